#include "failureModel.H"
#include "keywordCheck.H"

Foam::autoPtr<Foam::failureModel> Foam::failureModel::New
(
    const word& phaseName,
    const dictionary& phaseDict
)
{
    const dictionary* dictPtr = phaseDict.findDict("failure");
    const dictionary noneDict;
    const dictionary& dict = dictPtr ? *dictPtr : noneDict;

    const word modelType(dict.getOrDefault<word>("type", "none"));

    auto cstrIter = dictionaryConstructorTablePtr_->cfind(modelType);

    if (!cstrIter.found())
    {
        FatalIOErrorInFunction(dict)
            << "Phase " << phaseName << ": unknown failure type "
            << modelType << nl << nl
            << "Valid types are :" << nl
            << dictionaryConstructorTablePtr_->sortedToc()
            << exit(FatalIOError);
    }

    autoPtr<failureModel> model(cstrIter()(phaseName, dict, phaseDict));

    // Each model lists the entries it reads
    if (dictPtr)
    {
        checkKeywords
        (
            dict, model->keywords(), "Phase " + phaseName + ", failure"
        );
    }
    return model;
}


// ************************************************************************* //
