#include "equationOfState.H"
#include "keywordCheck.H"

Foam::autoPtr<Foam::equationOfState> Foam::equationOfState::New
(
    const word& phaseName,
    const dictionary& dict
)
{
    const word modelType(dict.get<word>("type"));

    auto cstrIter = dictionaryConstructorTablePtr_->cfind(modelType);

    if (!cstrIter.found())
    {
        FatalIOErrorInFunction(dict)
            << "Unknown equationOfState type " << modelType
            << " for phase " << phaseName << nl << nl
            << "Valid types are :" << nl
            << dictionaryConstructorTablePtr_->sortedToc()
            << exit(FatalIOError);
    }

    autoPtr<equationOfState> model(cstrIter()(phaseName, dict));

    // Each model lists the entries it reads
    checkKeywords
    (
        dict, model->keywords(), "Phase " + phaseName + ", equationOfState"
    );
    return model;
}
