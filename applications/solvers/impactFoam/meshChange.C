#include "meshChange.H"
#include "inputDefaults.H"

// * * * * * * * * * * * * * * * Global Functions  * * * * * * * * * * * * * //

void Foam::updateSolverParts
(
    phaseSystem& phases,
    demSolver& dem,
    mechanicalRelaxation& relaxation,
    voidVelocity& voidCells,
    bodyForces& forces,
    stepControl& step
)
{
    // The phases first: their boundary values, mixture and saved state are
    // what the others read (the sliding band is found again at the next
    // step's start, demSolver::prepare)
    phases.updateMesh();
    dem.updateMesh();
    relaxation.updateMesh();
    voidCells.updateMesh();
    forces.updateMesh();
    step.updateMesh();
}


Foam::label Foam::rebuildSolverPartsInterval(const Time& runTime)
{
    const label interval
    (
        inputDefaults::get<label>
        (
            runTime.controlDict(), "rebuildSolverParts", 0, "controlDict"
        )
    );
    if (interval < 0)
    {
        FatalIOErrorInFunction(runTime.controlDict())
            << "rebuildSolverParts " << interval << " in "
            << runTime.controlDict().name() << ": give the number of"
            << " accepted steps between rebuilds of the solver's parts, or"
            << " 0 for none" << exit(FatalIOError);
    }
    return interval;
}


// ************************************************************************* //
