#include "yieldStress.H"
#include "keywordCheck.H"

Foam::autoPtr<Foam::yieldStress> Foam::yieldStress::New
(
    const word& phaseName,
    const dictionary& dict
)
{
    if (!dict.found("type"))
    {
        FatalIOErrorInFunction(dict)
            << "Phase " << phaseName << ": yieldStress needs the entry type"
            << nl << nl << "Valid types are :" << nl
            << dictionaryConstructorTablePtr_->sortedToc()
            << exit(FatalIOError);
    }

    const word modelType(dict.get<word>("type"));

    auto cstrIter = dictionaryConstructorTablePtr_->cfind(modelType);

    if (!cstrIter.found())
    {
        FatalIOErrorInFunction(dict)
            << "Unknown yieldStress type " << modelType
            << " for phase " << phaseName << nl << nl
            << "Valid types are :" << nl
            << dictionaryConstructorTablePtr_->sortedToc()
            << exit(FatalIOError);
    }

    autoPtr<yieldStress> model(cstrIter()(phaseName, dict));

    // Each model lists the entries it reads
    checkKeywords
    (
        dict,
        model->keywords(),
        "Phase " + phaseName + ", plasticity yieldStress"
    );
    return model;
}
