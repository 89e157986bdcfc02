/*---------------------------------------------------------------------------*\
  impactFoam: Eulerian multiphase elastic-plastic impact solver for OpenFOAM
-------------------------------------------------------------------------------
Application
    impactRefine

Description
    Refine a case's mesh where its fields mark cells, before a run
    (docs/numerics.md section 11.5): constant/refinementProperties'
    criteria, maxRefinement passes as the solver makes at the start, the
    phase state carried over (phaseRemap). The refined mesh with its
    levels and the fields are written at the start time, over the fields
    there. For a case set with setFields: run setFields, impactRefine, and
    setFields again, which then sets the bodies on the refined cells (its
    sharp 0/1 fractions at the finest cell size where the surfaces are).
    Cases made by impactSetup need none of this (impactDict's refinement).

Usage
    impactRefine [-case dir] [-parallel]

\*---------------------------------------------------------------------------*/

#include "fvCFD.H"
#include "phaseSystem.H"
#include "adaptiveRefinement.H"

using namespace Foam;

int main(int argc, char *argv[])
{
    argList::addNote
    (
        "Refine the mesh where constant/refinementProperties' criteria mark"
        " cells in the start time's fields; write mesh and fields there"
    );

    #include "setRootCase.H"
    #include "createTime.H"
    #include "createMesh.H"

    phaseSystem phases(mesh);
    autoPtr<adaptiveRefinement> refinement
    (
        adaptiveRefinement::New(mesh, phases)
    );
    if (!refinement)
    {
        FatalErrorInFunction
            << "No " << runTime.path()/runTime.constant()
            /"refinementProperties" << ": nothing says how to refine"
            << exit(FatalError);
    }

    refinement->initialise();

    // The refined mesh, its levels and the fields at the start time
    refinement->setInstance();
    phases.correctOutputs();
    runTime.writeNow();
    refinement->write();

    Info<< nl << "Written " << mesh.globalData().nTotalCells()
        << " cells at time " << runTime.timeName() << nl << endl;
    Info<< "End" << nl << endl;
    return 0;
}


// ************************************************************************* //
