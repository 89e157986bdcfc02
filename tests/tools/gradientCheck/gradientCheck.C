/*---------------------------------------------------------------------------*\
  impactFoam: Eulerian multiphase elastic-plastic impact solver for OpenFOAM
-------------------------------------------------------------------------------
Application
    gradientCheck

Description
    Test tool: cellLimitedGauss (the reconstruction's slopes of alpha, rho
    and p) against OpenFOAM's fvc::grad with fvSchemes' gradSchemes, on the
    case's mesh (serial or -parallel), for a field with kinks and jumps:
        v = sin(300 x) cos(500 y) + sin(700 z) + (x > x0 ? 1 : 0) + |y - y0|/L
    (x0, y0 the middle of the mesh's bounding box, L its size), its patches
    of the types a zeroGradient field takes on each patch (wedge, empty,
    symmetry and processor patches keep their constraint types).

    Prints, one item per line:
        matches <0|1>       cellLimitedGauss::matches for grad(v)
        cells <n>           over all processors
        maxAbsGradient <g>  largest |fvc::grad(v)|
        maxDifference <d>   largest |fvc::grad(v) - cellLimitedGauss|
        maxDifferenceMasked <d>  the same with every other cell masked,
                            over the masked cells
        maskedNonZero <n>   unmasked cells whose masked gradient is not
                            zero (they must get zero)
        maxDifferencePair <d>  the two-field pass (v and a second field
                            w) against two masked single passes, over all
                            cells
        limitedCells <n>    cells whose limited gradient differs from the
                            plain Gauss gradient (the limiter was active)
        phaseCells <n>      cells holding a phase on one side of a plane
                            (alpha 1; 0 beyond, where the velocity is a
                            far-off constant the phase must not read)
        phaseMaxError <e>   linearVelocityGradient::calculatePresent of
                            the phase's linear velocity u = a x + b e x x
                            (equivariant under the mesh's mirrors and
                            wedges; b = 0 with wedges) over those cells,
                            largest |grad u - exact|/|exact| in the
                            directions with extent, unlimited
        phaseMaxErrorLimited <e>  the same, limited
        mixtureMaxError <e> the same of linearVelocityGradient::calculate
                            over the same cells, the velocity linear in
                            every cell (the bound: on a wedge mesh neither
                            is exact in the cells on the axis)
        phaseUntouched <0|1>  the other cells keep what they held

Usage
    gradientCheck [-parallel] [-case dir]

\*---------------------------------------------------------------------------*/

#include "fvCFD.H"
#include "cellLimitedGauss.H"
#include "linearVelocityGradient.H"
#include "wedgeFvPatch.H"
#include "symmetryPlaneFvPatch.H"
#include "symmetryFvPatch.H"
#include "emptyFvPatch.H"

using namespace Foam;

int main(int argc, char *argv[])
{
    #include "setRootCase.H"
    #include "createTime.H"
    #include "createMesh.H"

    const boundBox& bb = mesh.bounds();
    const point mid(bb.midpoint());
    const scalar L = bb.mag();

    // A field of the function f of the cell centres, with the patch types
    // a zeroGradient field takes
    const auto cellField = [&](const word& name, const auto& f)
    {
        tmp<volScalarField> tvf
        (
            new volScalarField
            (
                IOobject(name, runTime.timeName(), mesh),
                mesh,
                dimensionedScalar(dimless, Zero),
                "zeroGradient"
            )
        );
        volScalarField& vf = tvf.ref();
        forAll(vf, c)
        {
            vf[c] = f(mesh.C()[c]);
        }
        vf.correctBoundaryConditions();
        return tvf;
    };

    const volScalarField v
    (
        cellField
        (
            "v",
            [&](const point& x)
            {
                return
                    std::sin(300*x.x())*std::cos(500*x.y())
                  + std::sin(700*x.z())
                  + (x.x() > mid.x() ? 1 : 0) + mag(x.y() - mid.y())/L;
            }
        )
    );

    const vectorField gFoam(fvc::grad(v)().primitiveField());
    const vectorField gPlain(fv::gaussGrad<scalar>::gradf
    (
        linearInterpolate(v), "plain"
    )().primitiveField());

    cellLimitedGauss gauss(mesh);
    vectorField g;
    gauss.grad(v, g);

    boolList active(mesh.nCells(), false);
    forAll(active, c)
    {
        active[c] = (c % 2 == 0);
    }
    vectorField gMasked;
    gauss.grad(v, gMasked, &active);

    // A second field, and the two in one pass
    const volScalarField w
    (
        cellField
        (
            "w",
            [&](const point& x)
            {
                return
                    std::cos(400*x.x() + 200*x.y())
                  + (x.y() > mid.y() ? 2 : 0) + std::sin(900*x.z());
            }
        )
    );
    vectorField gwMasked, gPairV, gPairW;
    gauss.grad(w, gwMasked, &active);
    gauss.grad(v, w, gPairV, gPairW, &active);

    scalar maxG = 0, maxD = 0, maxDMasked = 0, maxDPair = 0;
    label nLimited = 0, nMaskedNonZero = 0;
    forAll(g, c)
    {
        maxG = max(maxG, mag(gFoam[c]));
        maxD = max(maxD, mag(gFoam[c] - g[c]));
        if (active[c])
        {
            maxDMasked = max(maxDMasked, mag(gFoam[c] - gMasked[c]));
        }
        else if (gMasked[c] != vector::zero || gPairW[c] != vector::zero)
        {
            ++nMaskedNonZero;
        }
        maxDPair = max
        (
            maxDPair,
            max(mag(gPairV[c] - gMasked[c]), mag(gPairW[c] - gwMasked[c]))
        );
        if (gFoam[c] != gPlain[c])
        {
            ++nLimited;
        }
    }
    reduce(maxG, maxOp<scalar>());
    reduce(maxD, maxOp<scalar>());
    reduce(maxDMasked, maxOp<scalar>());
    reduce(maxDPair, maxOp<scalar>());
    reduce(nLimited, sumOp<label>());
    reduce(nMaskedNonZero, sumOp<label>());

    // A phase's own velocity gradient where it is present
    List<cellLimiter::neighbour> kinds(mesh.boundary().size());
    bool wedges = false;
    forAll(mesh.boundary(), patchi)
    {
        const fvPatch& patch = mesh.boundary()[patchi];
        if (isA<wedgeFvPatch>(patch))
        {
            kinds[patchi] = cellLimiter::neighbour::wedge;
            wedges = true;
        }
        else if (isA<emptyFvPatch>(patch))
        {
            kinds[patchi] = cellLimiter::neighbour::none;
        }
        else if (patch.coupled())
        {
            kinds[patchi] = cellLimiter::neighbour::coupled;
        }
        else if
        (
            isA<symmetryPlaneFvPatch>(patch) || isA<symmetryFvPatch>(patch)
        )
        {
            kinds[patchi] = cellLimiter::neighbour::mirror;
        }
        else
        {
            kinds[patchi] = cellLimiter::neighbour::value;
        }
    }
    const scalar a = 1e3;
    const scalar b = wedges ? 0 : 2e3;
    const vector e(1, 0, 0);
    const tensor exact(a*tensor::I + b*tensor(0, 0, 0, 0, 0, 1, 0, -1, 0));
    const auto uExact = [&](const point& x) { return vector(a*x + b*(e ^ x)); };
    volScalarField alphaK
    (
        cellField("alphaK", [&](const point& x) { return scalar(x.x() < mid.x()); })
    );
    volVectorField uK
    (
        IOobject("uK", runTime.timeName(), mesh),
        mesh,
        dimensionedVector(dimVelocity, Zero),
        "zeroGradient"
    );
    DynamicList<label> present;
    forAll(uK, c)
    {
        uK[c] = alphaK[c] > 0.5 ? uExact(mesh.C()[c]) : vector(1e6, -1e6, 1e6);
        if (alphaK[c] > 0.5) present.append(c);
    }
    uK.correctBoundaryConditions();
    forAll(mesh.boundary(), patchi)
    {
        if (kinds[patchi] == cellLimiter::neighbour::value)
        {
            uK.boundaryFieldRef()[patchi] ==
                vectorField(mesh.boundary()[patchi].Cf().size(), Zero);
            forAll(mesh.boundary()[patchi], i)
            {
                uK.boundaryFieldRef()[patchi][i] =
                    uExact(mesh.boundary()[patchi].Cf()[i]);
            }
        }
    }
    // The derivatives along and of the directions with extent: on a planar
    // mesh those in its plane; on a wedge all three (the wedge images give
    // its normal extent: u = a x has the hoop rate u_r/r = a there)
    const Vector<label>& solD = mesh.solutionD();
    const auto withExtent = [&solD](tensor t)
    {
        for (direction i = 0; i < 3; ++i)
        {
            for (direction j = 0; j < 3; ++j)
            {
                if (solD[i] < 0 || solD[j] < 0) t(i, j) = 0;
            }
        }
        return t;
    };
    const tensor sentinel(tensor::one);
    scalar phaseErr[2] = {0, 0};
    bool untouched = true;
    for (int limited = 0; limited < 2; ++limited)
    {
        const linearVelocityGradient calc(mesh, kinds, limited);
        tensorField gK(mesh.nCells(), sentinel);
        calc.calculatePresent(uK, alphaK, 0.5, present, gK);
        forAll(gK, c)
        {
            if (alphaK[c] > 0.5)
            {
                phaseErr[limited] = max
                (
                    phaseErr[limited],
                    mag(withExtent(gK[c] - exact))/mag(withExtent(exact))
                );
            }
            else if (gK[c] != sentinel)
            {
                untouched = false;
            }
        }
        reduce(phaseErr[limited], maxOp<scalar>());
    }
    reduce(untouched, andOp<bool>());

    // The mixture's gradient of the same velocity, linear everywhere, over
    // the same cells: the bound of the phase's (on a wedge mesh the cells
    // on the axis are not exact in either)
    volVectorField uAll(uK);
    forAll(uAll, c)
    {
        uAll[c] = uExact(mesh.C()[c]);
    }
    uAll.correctBoundaryConditions();
    forAll(mesh.boundary(), patchi)
    {
        if (kinds[patchi] == cellLimiter::neighbour::value)
        {
            forAll(mesh.boundary()[patchi], i)
            {
                uAll.boundaryFieldRef()[patchi][i] =
                    uExact(mesh.boundary()[patchi].Cf()[i]);
            }
        }
    }
    tensorField gAll;
    linearVelocityGradient(mesh, kinds, false).calculate(uAll, gAll);
    scalar mixtureErr = 0;
    for (const label c : present)
    {
        mixtureErr = max
        (
            mixtureErr, mag(withExtent(gAll[c] - exact))/mag(withExtent(exact))
        );
    }
    reduce(mixtureErr, maxOp<scalar>());

    Info<< "matches " << cellLimitedGauss::matches(mesh, v.name()) << nl
        << "cells " << returnReduce(mesh.nCells(), sumOp<label>()) << nl
        << "maxAbsGradient " << maxG << nl
        << "maxDifference " << maxD << nl
        << "maxDifferenceMasked " << maxDMasked << nl
        << "maskedNonZero " << nMaskedNonZero << nl
        << "maxDifferencePair " << maxDPair << nl
        << "limitedCells " << nLimited << nl
        << "phaseCells " << returnReduce(present.size(), sumOp<label>()) << nl
        << "phaseMaxError " << phaseErr[0] << nl
        << "phaseMaxErrorLimited " << phaseErr[1] << nl
        << "phaseUntouched " << untouched << nl
        << "mixtureMaxError " << mixtureErr << endl;

    return 0;
}


// ************************************************************************* //
