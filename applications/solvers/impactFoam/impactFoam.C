/*---------------------------------------------------------------------------*\
  impactFoam: Eulerian multiphase elastic-plastic impact solver for OpenFOAM
-------------------------------------------------------------------------------
Application
    impactFoam

Description
    Explicit solver for impacts between several compressible elastic-plastic
    solids and fluids on one Eulerian mesh: the diffuse-interface model of
    Hank, Gavrilyuk, Favrie & Massoni (Int. J. Impact Eng. 2017) discretised
    by the discrete equations method.

    Each step (docs/numerics.md): the derived cell states and the stable
    time step; the hyperbolic step of the discrete equations method (face
    Riemann problems between the phases in contact); the body forces; the
    relaxation (velocity, pressure, traces, plasticity) with its state
    checks; a step that fails them is repeated with the failing cells at
    first order (the a posteriori fall-back of demSolver), then, if that
    is not enough, retried with a shorter step (stepControl).

    Dictionaries: constant/phaseProperties (phases and their models),
    system/fvSchemes discreteEquations { riemannSolver HLLC; } and
    gradSchemes (limited gradients), system/controlDict maxCo (default 0.6
    at second order, 0.4 at first) and maxDeltaT; optional constant/g (gravity) and constant/bodyAccelerations
    (e.g. the centripetal acceleration of a rigid rotation).

\*---------------------------------------------------------------------------*/

#include "fvCFD.H"
#include "phaseSystem.H"
#include "demSolver.H"
#include "mechanicalRelaxation.H"
#include "voidVelocity.H"
#include "bodyForces.H"
#include "stepControl.H"
#include "stepReport.H"
#include "progressLog.H"
#include "adaptiveRefinement.H"
#include "controlDictCheck.H"
#include "meshChange.H"
#include "inputDefaults.H"
#ifdef __GLIBC__
#include <malloc.h>
#endif

int main(int argc, char *argv[])
{
    argList::addNote
    (
        "Eulerian multiphase elastic-plastic impact solver"
        " (discrete equations method)"
    );

    argList::addOption
    (
        "endTime",
        "time",
        "stop at this time instead of the controlDict's endTime"
    );

    #ifdef __GLIBC__
    // Keep the memory the step's temporary fields free inside the process:
    // returned to the system (the default trims the heap top and maps large
    // blocks anew), it is faulted in again at every step (single-phase gas,
    // 40,000 cells: five times as many page faults, 1.6 times the run time)
    mallopt(M_MMAP_THRESHOLD, 32*1024*1024);
    mallopt(M_TRIM_THRESHOLD, 1024*1024*1024);
    mallopt(M_TOP_PAD, 64*1024*1024);
    #endif

    #include "setRootCase.H"
    #include "createTime.H"

    scalar endTimeOption;
    if (args.readIfPresent("endTime", endTimeOption))
    {
        if (!(endTimeOption > runTime.startTime().value()))
        {
            FatalErrorInFunction
                << "-endTime " << endTimeOption << " is not after the start"
                << " time " << runTime.startTime().value() << exit(FatalError);
        }
        runTime.setEndTime(endTimeOption);
    }
    // A misspelled entry stops here, before the mesh is read
    checkControlDict(runTime);

    #include "createMesh.H"

    phaseSystem phases(mesh);

    // Adaptive refinement (constant/refinementProperties; docs/numerics.md
    // 11): at the start of a run the mesh is refined where the criteria
    // mark cells, before the solver's parts are built on it
    autoPtr<adaptiveRefinement> refinement
    (
        adaptiveRefinement::New(mesh, phases)
    );
    if (refinement && runTime.startTimeIndex() == 0)
    {
        if (refinement->initialise())
        {
            // The phase system's per-cell storage (the sliding interfaces'
            // band) follows the refined mesh; the other parts are built on
            // it below
            phases.updateMesh();
        }
    }

    demSolver dem(phases, mesh.schemesDict().subOrEmptyDict("discreteEquations"));
    mechanicalRelaxation relaxation(phases);
    voidVelocity voidCells(phases);
    bodyForces forces(mesh);
    stepControl step(runTime, phases, dem, relaxation, forces);
    stepReport report(phases, relaxation, dem, voidCells);
    progressLog progress(runTime, phases);
    step.setRefinement(refinement.get());

    // A topology change of the mesh reaches the parts above through
    // updateSolverParts only (meshChange.H); rebuildSolverParts N: through
    // it after every N-th accepted step on the unchanged mesh (a test)
    const label rebuildInterval(rebuildSolverPartsInterval(runTime));

    // The defaults the models took for entries not given, in one block
    inputDefaults::print(Info);

    report.logTotals(true);

    Info<< "\nStarting time loop\n" << endl;

    // The changes of the mesh and the time they took (choosing the cells,
    // changing the mesh, carrying the state, rebuilding the parts)
    label nMeshChanges = 0;
    scalar refinementTime = 0;

    while (runTime.run())
    {
        // Every refineInterval steps, before the step: the mesh refined
        // and unrefined, the phase state carried over, the parts brought
        // to the new mesh. (Before the step, not after the write: a run
        // resumed from a written time then changes the mesh where a
        // straight run does)
        if (refinement)
        {
            const scalar t0 = runTime.elapsedCpuTime();
            if (refinement->update())
            {
                updateSolverParts
                (
                    phases, dem, relaxation, voidCells, forces, step
                );
                ++nMeshChanges;
            }
            refinementTime += runTime.elapsedCpuTime() - t0;
        }

        // The hyperbolic step and the relaxation, repeated with the failing
        // cells at first order; rejected (false): retried from the same
        // state with a shorter time step. The retries stay inside this
        // loop: the function objects (runTime.run()) see accepted steps
        // only, and nothing is written at the time a rejected step left
        scalar dt = 0;
        do
        {
            dem.prepare();
            dt = step.advance();

            if (forces.active())
            {
                dem.setAcceleration(forces.update(runTime.value() - 0.5*dt));
            }
        } while (!step.take(dt));

        // Void cells (no phase counts) keep a velocity in their neighbours'
        // range (docs/numerics.md 9.11)
        voidCells.correct();

        // What the step did beyond the scheme (vacuum floors, phases set
        // without a payer, cells at first order, void cells), logged; the
        // step recorded for function objects (stepLedger)
        report.step(dt);

        phases.correctBoundaryConditions();
        phases.correctDensity();
        step.write();
        if (runTime.writeTime())
        {
            report.logTotals(false);
        }
        progress.step();

        if
        (
            rebuildInterval > 0
         && (runTime.timeIndex() - runTime.startTimeIndex())
           % rebuildInterval == 0
        )
        {
            updateSolverParts(phases, dem, relaxation, voidCells, forces, step);
        }
    }

    // The final state, also when endTime is not a write time
    if (!runTime.writeTime() && runTime.timeIndex() != runTime.startTimeIndex())
    {
        phases.correctOutputs();
        step.writeNow();
    }

    dem.fallback().report();
    if (refinement)
    {
        Info<< "Refinement: " << nMeshChanges << " changes of the mesh, "
            << mesh.globalData().nTotalCells() << " cells at the end; "
            << refinementTime << " s of the run's " << runTime.elapsedCpuTime()
            << " s CPU time in the changes";
        if (Pstream::parRun())
        {
            Info<< "; " << refinement->nBalances() << " load balances, the"
                << " largest process's cells over the mean "
                << 1 + refinement->imbalance() << " at the end";
        }
        Info<< nl << endl;
    }
    progress.summary(report.unpaidEnergy());
    runTime.printExecutionTime(Info);

    Info<< "End\n" << endl;

    return 0;
}
