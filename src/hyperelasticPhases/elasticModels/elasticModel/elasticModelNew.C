#include "elasticModel.H"

Foam::autoPtr<Foam::elasticModel> Foam::elasticModel::New
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
            << "Unknown elasticity type " << modelType
            << " for phase " << phaseName << nl << nl
            << "Valid types are :" << nl
            << dictionaryConstructorTablePtr_->sortedToc()
            << exit(FatalIOError);
    }

    return cstrIter()(phaseName, dict);
}
