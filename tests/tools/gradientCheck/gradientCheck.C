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

Usage
    gradientCheck [-parallel] [-case dir]

\*---------------------------------------------------------------------------*/

#include "fvCFD.H"
#include "cellLimitedGauss.H"

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

    Info<< "matches " << cellLimitedGauss::matches(mesh, v.name()) << nl
        << "cells " << returnReduce(mesh.nCells(), sumOp<label>()) << nl
        << "maxAbsGradient " << maxG << nl
        << "maxDifference " << maxD << nl
        << "maxDifferenceMasked " << maxDMasked << nl
        << "maskedNonZero " << nMaskedNonZero << nl
        << "maxDifferencePair " << maxDPair << nl
        << "limitedCells " << nLimited << endl;

    return 0;
}


// ************************************************************************* //
