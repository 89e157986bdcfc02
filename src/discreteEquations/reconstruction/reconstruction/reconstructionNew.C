#include "reconstruction.H"
#include "inputDefaults.H"

Foam::autoPtr<Foam::reconstruction> Foam::reconstruction::New
(
    const phaseSystem& phases,
    const cellStates& cells,
    const dictionary& dict
)
{
    const label order
    (
        inputDefaults::get<label>(dict, "order", 2, "discreteEquations")
    );
    if (order != 1 && order != 2)
    {
        FatalIOErrorInFunction(dict)
            << "discreteEquations order " << order << " is not 1 or 2"
            << exit(FatalIOError);
    }
    const word modelType
    (
        inputDefaults::get<word>
        (
            dict,
            "reconstruction",
            order == 1 ? "firstOrder" : "MUSCLHancock",
            "discreteEquations"
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
