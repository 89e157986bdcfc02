#include "linearVelocityGradient.H"

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::linearVelocityGradient::linearVelocityGradient
(
    const fvMesh& mesh,
    const List<cellLimiter::neighbour>& kinds,
    const bool limit
)
:
    mesh_(mesh),
    stencil_(mesh, kinds),
    limit_(limit),
    invG_(mesh.nCells(), Zero)
{
    const labelUList& own = mesh_.owner();
    const labelUList& nei = mesh_.neighbour();
    const vectorField& C = mesh_.cellCentres();

    symmTensorField G(mesh_.nCells(), Zero);
    forAll(nei, facei)
    {
        const vector d(C[nei[facei]] - C[own[facei]]);
        const symmTensor wdd(sqr(d)/magSqr(d));
        G[own[facei]] += wdd;
        G[nei[facei]] += wdd;
    }

    const volVectorField& Cv = mesh_.C();
    forAll(mesh_.boundary(), patchi)
    {
        if (stencil_.kind(patchi) == cellLimiter::neighbour::none) continue;
        const labelUList& fc = mesh_.boundary()[patchi].faceCells();
        vectorField nbrC;
        if (stencil_.kind(patchi) == cellLimiter::neighbour::coupled)
        {
            nbrC = Cv.boundaryField()[patchi].patchNeighbourField();
        }
        forAll(fc, i)
        {
            const vector d(stencil_.offset(patchi, i, nbrC));
            G[fc[i]] += sqr(d)/magSqr(d);
        }
    }

    // Directions without extent (empty): unit diagonal, zero gradient there
    const Vector<label>& geomD = mesh_.geometricD();
    forAll(G, celli)
    {
        symmTensor Gc(G[celli]);
        const scalar scale = tr(Gc)/3;
        for (direction dir = 0; dir < vector::nComponents; ++dir)
        {
            if (geomD[dir] < 0)
            {
                vector e(Zero);
                e[dir] = 1;
                Gc += scale*sqr(e);
            }
        }
        const tensor invGc(inv(tensor(Gc)));
        invG_[celli] = symmTensor
        (
            invGc.xx(), invGc.xy(), invGc.xz(),
            invGc.yy(), invGc.yz(),
            invGc.zz()
        );
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::linearVelocityGradient::calculate
(
    const volVectorField& U,
    tensorField& gradU
) const
{
    const labelUList& own = mesh_.owner();
    const labelUList& nei = mesh_.neighbour();
    const vectorField& C = mesh_.cellCentres();
    const volVectorField& Cv = mesh_.C();

    gradU.setSize(mesh_.nCells());
    gradU = Zero;

    forAll(nei, facei)
    {
        const vector d(C[nei[facei]] - C[own[facei]]);
        const vector dU(U[nei[facei]] - U[own[facei]]);
        const tensor wddU((d/magSqr(d))*dU);
        gradU[own[facei]] += wddU;
        gradU[nei[facei]] += wddU;
    }
    forAll(mesh_.boundary(), patchi)
    {
        if (stencil_.kind(patchi) == cellLimiter::neighbour::none) continue;
        const labelUList& fc = mesh_.boundary()[patchi].faceCells();
        vectorField nbrC, nbrU;
        if (stencil_.kind(patchi) == cellLimiter::neighbour::coupled)
        {
            nbrC = Cv.boundaryField()[patchi].patchNeighbourField();
            nbrU = U.boundaryField()[patchi].patchNeighbourField();
        }
        forAll(fc, i)
        {
            const vector d(stencil_.offset(patchi, i, nbrC));
            const vector dU(stencil_.value(patchi, i, U, nbrU) - U[fc[i]]);
            gradU[fc[i]] += (d/magSqr(d))*dU;
        }
    }
    forAll(gradU, celli)
    {
        gradU[celli] = invG_[celli] & gradU[celli];
    }

    if (!limit_)
    {
        return;
    }

    // Barth-Jespersen, component by component; column j of grad(U) is
    // the gradient of component j
    stencil_.limit
    (
        U,
        [&gradU](const label celli, const vector& dx)
        {
            return vector(dx & gradU[celli]);
        },
        [&gradU](const label celli, const vector& l)
        {
            tensor& g = gradU[celli];
            g.xx() *= l.x(); g.yx() *= l.x(); g.zx() *= l.x();
            g.xy() *= l.y(); g.yy() *= l.y(); g.zy() *= l.y();
            g.xz() *= l.z(); g.yz() *= l.z(); g.zz() *= l.z();
        }
    );
}


// ************************************************************************* //
