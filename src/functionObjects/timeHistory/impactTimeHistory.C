#include "impactTimeHistory.H"
#include "OStringStream.H"
#include "keywordCheck.H"
#include "IFstream.H"
#include "IStringStream.H"
#include "OSspecific.H"

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::functionObjects::impactTimeHistory::impactTimeHistory
(
    const word& name,
    const Time& runTime,
    const dictionary& dict
)
:
    fvMeshFunctionObject(name, runTime, dict),
    lastIndex_(-1),
    writePrecision_(15),
    writtenHeader_(false),
    dict_(dict),
    lastTime_(0)
{
    impactTimeHistory::read(dict);

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
        "writePrecision"
    });
    valid.append(keywords());
    checkKeywords(dict_, valid, "Function object " + name());

    openFile();
    write();
}


// * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

Foam::string Foam::functionObjects::impactTimeHistory::header() const
{
    // The names, then the units
    string h("# Time");
    for (const word& c : columns())
    {
        h += "\t" + c;
    }
    h += "\n# [s]";
    for (const word& u : units())
    {
        h += "\t" + u;
    }
    return h;
}


void Foam::functionObjects::impactTimeHistory::openFile()
{
    // (the master decides for all: write() is collective)
    bool startWritten = Pstream::master() && openTable();
    Pstream::scatter(startWritten);
    if (startWritten)
    {
        lastIndex_ = time_.timeIndex();
    }
}


bool Foam::functionObjects::impactTimeHistory::openTable()
{
    const fileName base
    (
        time_.globalPath()/functionObject::outputPrefix/name()
    );
    const fileName table(name() + ".dat");
    const scalar t0 = time_.value();
    const scalar tol = 1e-12*max(mag(t0), SMALL);

    // The table of the earliest start of this case at or before t0
    fileName earlier;
    scalar tEarlier = GREAT;
    for (const fileName& d : readDir(base, fileName::DIRECTORY))
    {
        scalar t = 0;
        if
        (
            readScalar(d, t) && t < tEarlier
         && t <= t0 + tol && isFile(base/d/table)
        )
        {
            earlier = base/d/table;
            tEarlier = t;
        }
    }

    if (!earlier.empty())
    {
        // Its rows up to t0, if its header is this one's: the rows after
        // t0 are written again by this run
        const string h(header());
        DynamicList<string> keep;
        bool sameHeader = false;
        bool startWritten = false;
        {
            IFstream is(earlier);
            string line, head;
            while (is.good() && !is.getLine(line).bad() && is.good())
            {
                if (line.empty())
                {
                    continue;
                }
                if (line[0] == '#')
                {
                    head += (head.empty() ? "" : "\n") + line;
                    continue;
                }
                if (head != h)
                {
                    break;
                }
                IStringStream ls(line);
                scalar t = 0;
                ls >> t;
                if (t < t0 + tol)
                {
                    keep.append(line);
                    startWritten = t > t0 - tol;
                }
            }
            sameHeader = head == h;
            if (!sameHeader)
            {
                keep.clear();
                startWritten = false;
            }
        }
        {
            OFstream os(earlier);
            if (sameHeader)
            {
                os  << h.c_str() << nl;
            }
            for (const string& line : keep)
            {
                os  << line.c_str() << nl;
            }
        }
        file_.reset
        (
            new OFstream
            (
                earlier,
                IOstream::ASCII,
                IOstream::currentVersion,
                IOstream::UNCOMPRESSED,
                true
            )
        );
        writtenHeader_ = sameHeader;

        // The row of the start time, written by the run that wrote that
        // time, stays: it holds that run's last step (this one's start has
        // no step yet: no force)
        return startWritten;
    }

    mkDir(base/time_.timeName());
    file_.reset(new OFstream(base/time_.timeName()/table));
    writtenHeader_ = false;
    return false;
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

bool Foam::functionObjects::impactTimeHistory::read(const dictionary& dict)
{
    fvMeshFunctionObject::read(dict);
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
    lastTime_ = time_.value();
    lastRow_ = row;

    if (!file_.valid())
    {
        return true;
    }
    OFstream& os = file_();
    os.precision(writePrecision_);
    if (!writtenHeader_)
    {
        os  << header().c_str() << nl;
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


Foam::string Foam::functionObjects::impactTimeHistory::summaryLine() const
{
    if (lastRow_.empty())
    {
        return string();
    }
    const wordList names(columns());
    const wordList unit(units());
    const wordList shown(summaryColumns());
    OStringStream os;
    os.precision(6);
    os  << name().c_str() << " at " << lastTime_ << " s:";
    label n = 0;
    forAll(names, i)
    {
        if (shown.found(names[i]) && i < lastRow_.size())
        {
            // (units without their brackets)
            string u(unit[i]);
            u.replaceAll("[", "");
            u.replaceAll("]", "");
            os  << (n++ ? ", " : " ") << names[i].c_str() << " "
                << lastRow_[i] << (u == "-" ? "" : " " + u).c_str();
        }
    }
    return os.str();
}


// ************************************************************************* //
