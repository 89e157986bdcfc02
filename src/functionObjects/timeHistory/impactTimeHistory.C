#include "impactTimeHistory.H"
#include "keywordCheck.H"

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::functionObjects::impactTimeHistory::impactTimeHistory
(
    const word& name,
    const Time& runTime,
    const dictionary& dict
)
:
    fvMeshFunctionObject(name, runTime, dict),
    writeFile(mesh_, name, name, true),
    lastIndex_(-1),
    dict_(dict)
{
    impactTimeHistory::read(dict);
    resetFile(name);

    // Tell the solver that this function object does not read the output
    // mixture fields (without impactFoam, ledger() stops at first use)
    if (mesh_.foundObject<stepLedger>(stepLedger::typeName))
    {
        ledger().addHistory(name);
    }
}


// * * * * * * * * * * * * * Protected Member Functions  * * * * * * * * * * //

const Foam::stepLedger&
Foam::functionObjects::impactTimeHistory::ledger() const
{
    if (!mesh_.foundObject<stepLedger>(stepLedger::typeName))
    {
        FatalErrorInFunction
            << "Function object " << name() << " (" << type() << ") reads"
            << " the state of impactFoam: run it with impactFoam"
            << exit(FatalError);
    }
    return mesh_.lookupObject<stepLedger>(stepLedger::typeName);
}


Foam::label Foam::functionObjects::impactTimeHistory::phaseIndex
(
    const dictionary& dict,
    const word& name
) const
{
    const label k = phases().names().find(name);
    if (k < 0)
    {
        FatalIOErrorInFunction(dict)
            << "phase " << name << " in function object " << this->name()
            << ": no such phase; valid phases: " << phases().names()
            << exit(FatalIOError);
    }
    return k;
}


void Foam::functionObjects::impactTimeHistory::start()
{
    // Strict like every other dictionary: the entries OpenFOAM's function
    // objects read, and the derived class's
    wordList valid
    ({
        "type", "libs", "enabled", "log", "timeStart", "timeEnd",
        "executeControl", "executeInterval", "writeControl",
        "writeInterval", "outputControl", "outputInterval", "region",
        "writePrecision", "writeToFile", "useUserTime", "updateHeader"
    });
    valid.append(keywords());
    checkKeywords(dict_, valid, "Function object " + name());

    write();
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

bool Foam::functionObjects::impactTimeHistory::read(const dictionary& dict)
{
    fvMeshFunctionObject::read(dict);
    writeFile::read(dict);
    writePrecision_ = dict.getOrDefault<label>("writePrecision", 15);
    return true;
}


bool Foam::functionObjects::impactTimeHistory::execute()
{
    return true;
}


bool Foam::functionObjects::impactTimeHistory::write()
{
    if (time_.timeIndex() == lastIndex_)
    {
        return true;
    }
    lastIndex_ = time_.timeIndex();

    DynamicList<scalar> row;
    values(row);

    OFstream& os = file();
    os.precision(writePrecision_);
    if (!writtenHeader_)
    {
        os.width(0);
        os  << "# Time";
        for (const word& c : columns())
        {
            os  << tab << c;
        }
        os  << endl;
        writtenHeader_ = true;
    }
    os  << time_.value();
    for (const scalar v : row)
    {
        os  << tab << v;
    }
    os  << endl;

    return true;
}


// ************************************************************************* //
