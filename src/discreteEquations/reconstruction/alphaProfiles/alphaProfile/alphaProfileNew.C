#include "alphaProfile.H"
#include "inputDefaults.H"
#include <algorithm>
#include <cctype>

Foam::autoPtr<Foam::alphaProfile> Foam::alphaProfile::New
(
    const phaseSystem& phases,
    const dictionary& dict
)
{
    // alphaCompression's range is checked before the profile is looked up,
    // whichever profile reads it, so that a bad value is reported first
    readCompression(dict);

    // As readOption does for an enumeration: the literal entry, and an
    // unknown word reported with the entry and the valid words
    const entry* eptr = dict.findEntry("alphaReconstruction", keyType::LITERAL);
    const word profileType(eptr ? eptr->get<word>() : word("linear"));
    if (!eptr)
    {
        inputDefaults::note
        (
            "discreteEquations", "alphaReconstruction", profileType
        );
    }

    auto cstrIter = dictionaryConstructorTablePtr_->cfind(profileType);

    if (!cstrIter.found())
    {
        // The valid words in alphabetical order, case aside (linear THINC)
        wordList valid(dictionaryConstructorTablePtr_->toc());
        std::sort
        (
            valid.begin(),
            valid.end(),
            [](const word& a, const word& b)
            {
                return std::lexicographical_compare
                (
                    a.begin(), a.end(), b.begin(), b.end(),
                    [](const char x, const char y)
                    {
                        return std::tolower(x) < std::tolower(y);
                    }
                );
            }
        );

        FatalIOErrorInFunction(dict)
            << "discreteEquations: unknown alphaReconstruction "
            << profileType << "; valid: (";
        forAll(valid, i)
        {
            FatalIOError << (i ? " " : "") << valid[i];
        }
        FatalIOError << ')' << exit(FatalIOError);
    }

    return cstrIter()(phases, dict);
}


// ************************************************************************* //
