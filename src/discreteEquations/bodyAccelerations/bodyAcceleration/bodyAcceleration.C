#include "bodyAcceleration.H"
#include "keywordCheck.H"

namespace Foam
{
    defineTypeNameAndDebug(bodyAcceleration, 0);
    defineRunTimeSelectionTable(bodyAcceleration, dictionary);
}

Foam::bodyAcceleration::bodyAcceleration
(
    const word& name,
    const dictionary& dict
)
:
    name_(name)
{}


Foam::wordList Foam::bodyAcceleration::keywords() const
{
    return {"type"};
}


Foam::autoPtr<Foam::bodyAcceleration> Foam::bodyAcceleration::New
(
    const word& name,
    const dictionary& dict
)
{
    const word modelType(dict.get<word>("type"));

    auto cstrIter = dictionaryConstructorTablePtr_->cfind(modelType);

    if (!cstrIter.found())
    {
        FatalIOErrorInFunction(dict)
            << "Unknown bodyAcceleration type " << modelType
            << " for " << name << nl << nl
            << "Valid types are :" << nl
            << dictionaryConstructorTablePtr_->sortedToc()
            << exit(FatalIOError);
    }

    autoPtr<bodyAcceleration> model(cstrIter()(name, dict));

    // Each model lists the entries it reads
    checkKeywords(dict, model->keywords(), "bodyAcceleration " + name);
    return model;
}
