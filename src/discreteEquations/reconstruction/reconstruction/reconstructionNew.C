#include "reconstruction.H"

Foam::autoPtr<Foam::reconstruction> Foam::reconstruction::New
(
    const phaseSystem& phases,
    const cellStates& cells,
    const dictionary& dict
)
{
    const label order(dict.getOrDefault<label>("order", 2));
    if (order != 1 && order != 2)
    {
        FatalIOErrorInFunction(dict)
            << "discreteEquations order " << order << " is not 1 or 2"
            << exit(FatalIOError);
    }
    const word modelType
    (
        dict.getOrDefault<word>
        (
            "reconstruction",
            order == 1 ? "firstOrder" : "MUSCLHancock"
        )
    );

    auto cstrIter = dictionaryConstructorTablePtr_->cfind(modelType);

    if (!cstrIter.found())
    {
        FatalIOErrorInFunction(dict)
            << "Unknown reconstruction " << modelType << nl << nl
            << "Valid reconstructions are :" << nl
            << dictionaryConstructorTablePtr_->sortedToc()
            << exit(FatalIOError);
    }

    return cstrIter()(phases, cells, dict);
}
