#include "riemannSolver.H"

namespace Foam
{
    defineTypeNameAndDebug(riemannSolver, 0);
    defineRunTimeSelectionTable(riemannSolver, dictionary);
}


Foam::riemannSolver::riemannSolver(const dictionary&)
{}


Foam::wordList Foam::riemannSolver::keywords() const
{
    return {"riemannSolver"};
}
