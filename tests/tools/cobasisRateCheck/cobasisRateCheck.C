/*---------------------------------------------------------------------------*\
  impactFoam: Eulerian multiphase elastic-plastic impact solver for OpenFOAM
-------------------------------------------------------------------------------
Application
    cobasisRateCheck

Description
    Test tool (VALIDATION V10 and the wedge ring test of docs/numerics.md 7):
    the velocity gradient L_ij = du_i/dx_j that the cobasis update of one
    hyperbolic step sees, compared with an expected tensor L0.

    Reads the case at its start time (phaseSystem, fvSchemes
    discreteEquations), calls demSolver::prepare() and one
    demSolver::hyperbolicStep() of length dt = dtFraction*stableDeltaT()
    (the fields are not changed), and compares cobasisTransport::velocityGradient
    of a solid phase (the first solid phase unless -phase is given) with L0
    in every cell. The error is the Frobenius norm |L - L0|.

    dt: at second order the Hancock predictor moves the face velocities by
    -dt/2 (u.grad)u, so L differs from grad u at the start of the step by
    O(dt |L0|^2); the default dtFraction 1e-12 makes that term negligible
    (< 1e-14 relative for any reasonable L0) and measures the spatial
    operator alone.

    Cells are classified as boundary cells if one of their faces lies on a
    patch that is not empty, wedge or coupled (symmetry and wall patches
    count as boundaries), and as interior cells otherwise.

    Output (stdout), one item per line:
        cells <n> interior <nInterior> boundary <nBoundary>
        dt <dt> stableDeltaT <dtStable>
        maxErrorInterior <abs> relative <abs/|L0|> cell <c> L <tensor>
        maxErrorBoundary <abs> relative <abs/|L0|> cell <c> L <tensor>
        maxRelError <max abs/|L0| over all cells>
        maxError <max abs over all cells>
    and writes the volTensorField Lcobasis and the volScalarField
    LcobasisError (|L - L0|) in the start time directory (not with
    -noWrite).

Usage
    cobasisRateCheck -L0 '(xx xy xz yx yy yz zx zy zz)'
        [-phase name] [-dtFraction 1e-12] [-noWrite] [-case dir]

\*---------------------------------------------------------------------------*/

#include "fvCFD.H"
#include "phaseSystem.H"
#include "demSolver.H"
#include "emptyFvPatch.H"
#include "wedgeFvPatch.H"

using namespace Foam;

namespace
{

tensor toTensor(const cobasis::matrix& M)
{
    return tensor
    (
        M(0, 0), M(0, 1), M(0, 2),
        M(1, 0), M(1, 1), M(1, 2),
        M(2, 0), M(2, 1), M(2, 2)
    );
}

} // End anonymous namespace


int main(int argc, char *argv[])
{
    argList::addNote
    (
        "Compare the velocity gradient seen by the cobasis update of one"
        " hyperbolic step with an expected tensor L0"
    );
    argList::noParallel();
    argList::addOption
    (
        "L0",
        "tensor",
        "expected velocity gradient L_ij = du_i/dx_j, as"
        " '(xx xy xz yx yy yz zx zy zz)'"
    );
    argList::addOption
    (
        "phase",
        "name",
        "solid phase to check (default: the first solid phase)"
    );
    argList::addOption
    (
        "dtFraction",
        "scalar",
        "step length as a fraction of the stable step (default 1e-12)"
    );
    argList::addBoolOption
    (
        "noWrite",
        "do not write Lcobasis and LcobasisError"
    );

    #include "setRootCase.H"

    if (!args.found("L0"))
    {
        FatalErrorInFunction
            << "Give the expected velocity gradient with"
            << " -L0 '(xx xy xz yx yy yz zx zy zz)'" << exit(FatalError);
    }
    const tensor L0(args.get<tensor>("L0"));
    const scalar dtFraction = args.getOrDefault<scalar>("dtFraction", 1e-12);

    #include "createTime.H"
    #include "createMesh.H"

    phaseSystem phases(mesh);

    label phasei = -1;
    if (args.found("phase"))
    {
        const word name(args.get<word>("phase"));
        phasei = phases.names().find(name);
        if (phasei < 0 || !phases.phase(phasei).solid())
        {
            FatalErrorInFunction
                << "No solid phase " << name << " in " << phases.names()
                << exit(FatalError);
        }
    }
    else
    {
        forAll(phases.names(), k)
        {
            if (phases.phase(k).solid())
            {
                phasei = k;
                break;
            }
        }
        if (phasei < 0)
        {
            FatalErrorInFunction
                << "No solid phase among " << phases.names()
                << exit(FatalError);
        }
    }

    demSolver dem
    (
        phases,
        mesh.schemesDict().subOrEmptyDict("discreteEquations")
    );
    dem.prepare();
    const scalar dtStable = dem.stableDeltaT();
    const scalar dt = dtFraction*dtStable;

    conservedState q;
    dem.hyperbolicStep(dt, q);

    // Boundary cells: a face on a patch other than empty, wedge, coupled
    boolList boundaryCell(mesh.nCells(), false);
    forAll(mesh.boundary(), patchi)
    {
        const fvPatch& patch = mesh.boundary()[patchi];
        if
        (
            isA<emptyFvPatch>(patch)
         || isA<wedgeFvPatch>(patch)
         || patch.coupled()
        )
        {
            continue;
        }
        for (const label celli : patch.faceCells())
        {
            boundaryCell[celli] = true;
        }
    }

    volTensorField Lcobasis
    (
        IOobject
        (
            "Lcobasis",
            runTime.timeName(),
            mesh,
            IOobject::NO_READ,
            IOobject::NO_WRITE
        ),
        mesh,
        dimensionedTensor(dimless/dimTime, Zero),
        "zeroGradient"
    );
    volScalarField LcobasisError
    (
        IOobject
        (
            "LcobasisError",
            runTime.timeName(),
            mesh,
            IOobject::NO_READ,
            IOobject::NO_WRITE
        ),
        mesh,
        dimensionedScalar(dimless/dimTime, Zero),
        "zeroGradient"
    );

    const scalar magL0 = mag(L0);
    const scalar scale = (magL0 > VSMALL) ? magL0 : 1.0;

    scalar errInt = 0, errBnd = 0;
    label cellInt = -1, cellBnd = -1;
    label nInt = 0, nBnd = 0;

    forAll(mesh.C(), celli)
    {
        const tensor L
        (
            toTensor
            (
                dem.cobasis().velocityGradient
                (
                    phasei, celli, mesh.V()[celli]
                )
            )
        );
        const scalar err = mag(L - L0);
        Lcobasis[celli] = L;
        LcobasisError[celli] = err;

        if (boundaryCell[celli])
        {
            ++nBnd;
            if (cellBnd < 0 || err > errBnd)
            {
                errBnd = err;
                cellBnd = celli;
            }
        }
        else
        {
            ++nInt;
            if (cellInt < 0 || err > errInt)
            {
                errInt = err;
                cellInt = celli;
            }
        }
    }
    Lcobasis.correctBoundaryConditions();
    LcobasisError.correctBoundaryConditions();

    const scalar errMax = max(errInt, errBnd);

    Info<< nl << "phase " << phases.names()[phasei] << nl
        << "L0 " << L0 << nl
        << "cells " << mesh.nCells() << " interior " << nInt
        << " boundary " << nBnd << nl
        << "dt " << dt << " stableDeltaT " << dtStable << nl;

    Info<< "maxErrorInterior " << errInt << " relative " << errInt/scale;
    if (cellInt >= 0)
    {
        Info<< " cell " << cellInt << " L " << Lcobasis[cellInt];
    }
    Info<< nl;

    Info<< "maxErrorBoundary " << errBnd << " relative " << errBnd/scale;
    if (cellBnd >= 0)
    {
        Info<< " cell " << cellBnd << " L " << Lcobasis[cellBnd];
    }
    Info<< nl;

    Info<< "maxRelError " << errMax/scale << nl
        << "maxError " << errMax << nl << endl;

    if (!args.found("noWrite"))
    {
        Lcobasis.write();
        LcobasisError.write();
    }

    Info<< "End\n" << endl;

    return 0;
}


// ************************************************************************* //
