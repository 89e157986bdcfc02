#include "riemannSolver.H"
#include "inputDefaults.H"

Foam::autoPtr<Foam::riemannSolver> Foam::riemannSolver::New
(
    const dictionary& dict
)
{
    const word modelType(inputDefaults::get<word>
        (
            dict, "riemannSolver", "HLLC", "discreteEquations"
        ));

    auto cstrIter = dictionaryConstructorTablePtr_->cfind(modelType);

    if (!cstrIter.found())
    {
        FatalIOErrorInFunction(dict)
            << "Unknown riemannSolver " << modelType << nl << nl
            << "Valid riemannSolvers are :" << nl
            << dictionaryConstructorTablePtr_->sortedToc()
            << exit(FatalIOError);
    }

    return cstrIter()(dict);
}
