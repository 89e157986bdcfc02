/*---------------------------------------------------------------------------*\
  impactFoam: Eulerian multiphase elastic-plastic impact solver for OpenFOAM
\*---------------------------------------------------------------------------*/

#include "solidContacts.H"
#include "keywordCheck.H"

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::solidContacts::solidContacts
(
    const dictionary& phaseProperties,
    const wordList& phaseNames,
    const boolList& solid
)
:
    nPhases_(phaseNames.size()),
    any_(false),
    usesStrength_(false)
{
    pair_.assign(nPhases_*nPhases_, nullptr);

    const dictionary* dictPtr = phaseProperties.findDict("contacts");
    if (!dictPtr)
    {
        return;
    }
    const dictionary& dict = *dictPtr;

    // The default law, then each named pair's
    const contactLaw* defaultLaw = nullptr;
    std::vector<label> named(nPhases_*nPhases_, 0);

    for (const entry& e : dict)
    {
        const word key(e.keyword());
        const word owner("phaseProperties contacts " + key);

        if (key == "default")
        {
            laws_.append(contactLaw::New(e, owner).ptr());
            defaultLaw = &laws_.last();
            continue;
        }

        // <phase>.<phase>
        const auto dot = key.find('.');
        if (dot == string::npos || key.find('.', dot + 1) != string::npos)
        {
            FatalIOErrorInFunction(dict)
                << "contacts in " << entryOrigin(e, dict) << ": entry "
                << key << " is neither default nor a pair of phases"
                << " <phase>.<phase> (phases " << phaseNames << ")"
                << exit(FatalIOError);
        }
        const word a(key.substr(0, dot));
        const word b(key.substr(dot + 1));
        label ka = -1, kb = -1;
        forAll(phaseNames, k)
        {
            if (phaseNames[k] == a) ka = k;
            if (phaseNames[k] == b) kb = k;
        }
        for (const label k : {ka, kb})
        {
            if (k < 0)
            {
                const word& missing = (ka < 0 ? a : b);
                FatalIOErrorInFunction(dict)
                    << "contacts in " << entryOrigin(e, dict) << ": entry "
                    << key << " names " << missing << ", which is not a"
                    << " phase (nearest: "
                    << nearestKeyword(missing, phaseNames) << "; phases "
                    << phaseNames << ")" << exit(FatalIOError);
            }
        }
        if (ka == kb || !solid[ka] || !solid[kb])
        {
            FatalIOErrorInFunction(dict)
                << "contacts in " << entryOrigin(e, dict) << ": entry "
                << key << " must name two different solid phases ("
                << a << (solid[ka] ? " solid" : " fluid") << ", "
                << b << (solid[kb] ? " solid" : " fluid") << ")"
                << exit(FatalIOError);
        }
        if (named[ka*nPhases_ + kb])
        {
            FatalIOErrorInFunction(dict)
                << "contacts in " << entryOrigin(e, dict) << ": the pair "
                << a << ", " << b << " is given twice"
                << exit(FatalIOError);
        }
        named[ka*nPhases_ + kb] = named[kb*nPhases_ + ka] = 1;

        laws_.append(contactLaw::New(e, owner).ptr());
        const contactLaw* law = &laws_.last();
        if (!law->sticks())
        {
            pair_[ka*nPhases_ + kb] = pair_[kb*nPhases_ + ka] = law;
        }
    }

    for (label k = 0; k < nPhases_; ++k)
    {
        for (label j = 0; j < nPhases_; ++j)
        {
            const label kj = k*nPhases_ + j;
            if
            (
                j != k && solid[k] && solid[j] && !named[kj]
             && defaultLaw && !defaultLaw->sticks()
            )
            {
                pair_[kj] = defaultLaw;
            }
            if (pair_[kj])
            {
                any_ = true;
                usesStrength_ = usesStrength_ || pair_[kj]->usesStrength();
            }
        }
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

bool Foam::solidContacts::slides(const dictionary& phaseProperties)
{
    const dictionary* dictPtr = phaseProperties.findDict("contacts");
    if (!dictPtr)
    {
        return false;
    }
    for (const entry& e : *dictPtr)
    {
        const word owner("phaseProperties contacts " + e.keyword());
        if (!contactLaw::New(e, owner)->sticks())
        {
            return true;
        }
    }
    return false;
}


void Foam::solidContacts::describe
(
    Ostream& os,
    const wordList& phaseNames
) const
{
    for (label k = 0; k < nPhases_; ++k)
    {
        for (label j = k + 1; j < nPhases_; ++j)
        {
            if (const contactLaw* law = this->law(k, j))
            {
                os  << "    contact " << phaseNames[k] << "."
                    << phaseNames[j] << ": ";
                law->describe(os);
                os  << nl;
            }
        }
    }
}


// ************************************************************************* //
