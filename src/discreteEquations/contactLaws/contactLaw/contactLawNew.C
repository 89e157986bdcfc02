/*---------------------------------------------------------------------------*\
  impactFoam: Eulerian multiphase elastic-plastic impact solver for OpenFOAM
\*---------------------------------------------------------------------------*/

#include "contactLaw.H"
#include "keywordCheck.H"

Foam::autoPtr<Foam::contactLaw> Foam::contactLaw::New
(
    const entry& e,
    const word& owner
)
{
    // `default frictionless;` or `default { type coulomb; mu 0.1; }`
    dictionary dict;
    word lawType;
    if (e.isDict())
    {
        dict = e.dict();
        if (!dict.found("type"))
        {
            FatalIOErrorInFunction(e.dict())
                << owner << ": no type (valid: "
                << dictionaryConstructorTablePtr_->sortedToc() << ")"
                << exit(FatalIOError);
        }
        lawType = dict.get<word>("type");
    }
    else
    {
        ITstream& is = e.stream();
        is >> lawType;
        if (!is.eof())
        {
            FatalIOErrorInFunction(is)
                << owner << ": expected a contact law's name or a"
                << " dictionary, found more than one word"
                << exit(FatalIOError);
        }
        dict.add("type", lawType);
        dict.name() = e.name();
    }

    auto cstrIter = dictionaryConstructorTablePtr_->cfind(lawType);
    if (!cstrIter.found())
    {
        FatalIOErrorInFunction(dict)
            << owner << ": unknown contact law " << lawType << "; valid: "
            << dictionaryConstructorTablePtr_->sortedToc()
            << exit(FatalIOError);
    }

    autoPtr<contactLaw> law(cstrIter()(dict, owner));
    checkKeywords(dict, law->keywords(), owner);
    return law;
}


// ************************************************************************* //
