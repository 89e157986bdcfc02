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

    Each step: hyperbolic DEM step (face Riemann problems between the phases
    in contact), then velocity, pressure and plastic relaxation.

    Dictionaries: constant/phaseProperties (phases and their models),
    system/fvSchemes discreteEquations { riemannSolver HLLC; } and
    gradSchemes (limited gradients), system/controlDict maxCo (default 0.4)
    and maxDeltaT; optional constant/g (gravity) and constant/bodyAccelerations
    (e.g. the centripetal acceleration of a rigid rotation).

\*---------------------------------------------------------------------------*/

#include "fvCFD.H"
#include "phaseSystem.H"
#include "demSolver.H"
#include "mechanicalRelaxation.H"
#include "uniformDimensionedFields.H"
#include "bodyAcceleration.H"
#include "landingDeltaT.H"

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
    #include "createMesh.H"
    #include "createFields.H"

    Info<< "\nStarting time loop\n" << endl;

    while (runTime.run())
    {
        dem.prepare();

        const scalar dtStable = dem.stableDeltaT();
        scalar dt = min(dtFactor*maxCo*dtStable, maxDeltaT);

        // Land exactly on the next write time (adjustable write control)
        // and on endTime, with steps no longer than the stable one
        dt = landingDeltaT(runTime, dt);
        runTime.setDeltaT(dt, false);
        dt = runTime.deltaTValue();

        const scalar oldTime = runTime.value();
        const label oldIndex = runTime.timeIndex();

        #include "saveState.H"

        ++runTime;

        Info<< "Time = " << runTime.timeName()
            << "  deltaT = " << dt
            << "  Courant Number max = " << dt/dtStable << endl;
        if (debugDeltaT && dem.limitingCell() >= 0)
        {
            Pout<< "    deltaT limited by cell " << dem.limitingCell()
                << " at " << mesh.C()[dem.limitingCell()]
                << ", wave speed " << dem.limitingSpeed() << endl;
        }

        #include "bodyAccelerationField.H"

        dem.hyperbolicStep(dt, q);

        #include "bodyForces.H"

        const mechanicalRelaxation::stateError err = relaxation.correct(q, dt);

        #include "checkState.H"

        const label nVacuum = returnReduce(relaxation.nVacuum(), sumOp<label>());
        if (nVacuum)
        {
            Info<< "    vacuum floor (pVacuum) in " << nVacuum << " cells" << nl;
        }

        // A good step: let a reduced time step grow back
        dtFactor = min(2*dtFactor, scalar(1));

        phases.correctBoundaryConditions();
        phases.correctMixture();

        runTime.write();
        if
        (
            pendingWrite > 0
         && runTime.value() >= pendingWrite - 1e-6*runTime.deltaTValue()
        )
        {
            if (!runTime.writeTime())
            {
                runTime.writeNow();
            }
            pendingWrite = -1;
        }
    }

    // The final state, also when endTime is not a write time
    if (!runTime.writeTime() && runTime.timeIndex() != runTime.startTimeIndex())
    {
        runTime.writeNow();
    }

    runTime.printExecutionTime(Info);

    Info<< "End\n" << endl;

    return 0;
}
