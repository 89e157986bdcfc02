#include "linearVelocityGradient.H"
#include "wedgePolyPatch.H"

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::linearVelocityGradient::linearVelocityGradient
(
    const fvMesh& mesh,
    const List<neighbour>& kinds,
    const bool limit
)
:
    mesh_(mesh),
    kinds_(kinds),
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
    const volVectorField zero
    (
        IOobject("zeroU", mesh_.time().timeName(), mesh_),
        mesh_,
        dimensionedVector(dimVelocity, Zero)
    );
    forAll(mesh_.boundary(), patchi)
    {
        if (kinds_[patchi] == neighbour::none) continue;
        const labelUList& fc = mesh_.boundary()[patchi].faceCells();
        vectorField nbrC(fc.size(), Zero);
        if (kinds_[patchi] == neighbour::coupled)
        {
            nbrC = Cv.boundaryField()[patchi].patchNeighbourField();
        }
        forAll(fc, i)
        {
            vector d, dU;
            boundaryNeighbour(patchi, i, zero, nbrC, nbrC, d, dU);
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
        invG_[celli] = inv(tensor(Gc));
    }
}


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

void Foam::linearVelocityGradient::boundaryNeighbour
(
    const label patchi,
    const label i,
    const volVectorField& U,
    const vectorField& nbrC,
    const vectorField& nbrU,
    vector& d,
    vector& dU
) const
{
    const fvPatch& patch = mesh_.boundary()[patchi];
    const label celli = patch.faceCells()[i];
    const vector& Cc = mesh_.C()[celli];
    const vector& Uc = U[celli];

    switch (kinds_[patchi])
    {
        case neighbour::mirror:
        {
            const vector& Sf = mesh_.faceAreas()[patch.start() + i];
            const vector n(Sf/mag(Sf));
            d = 2*((patch.Cf()[i] - Cc) & n)*n;
            dU = (Uc - 2*(Uc & n)*n) - Uc;
            break;
        }
        case neighbour::wedge:
        {
            const tensor& T =
                refCast<const wedgePolyPatch>(patch.patch()).cellT();
            d = (T & Cc) - Cc;
            dU = (T & Uc) - Uc;
            break;
        }
        case neighbour::coupled:
        {
            d = nbrC[i] - Cc;
            dU = nbrU[i] - Uc;
            break;
        }
        default:
        {
            d = patch.Cf()[i] - Cc;
            dU = U.boundaryField()[patchi][i] - Uc;
            break;
        }
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
    const vectorField& Cf = mesh_.faceCentres();
    const volVectorField& Cv = mesh_.C();

    gradU.setSize(mesh_.nCells());
    gradU = Zero;

    // Range of the neighbours' velocities, for the limiter, gathered in the
    // same passes as the gradient
    vectorField maxU(limit_ ? U.primitiveField() : vectorField());
    vectorField minU(limit_ ? U.primitiveField() : vectorField());
    const auto range = [&](const label celli, const vector& Unb)
    {
        maxU[celli] = max(maxU[celli], Unb);
        minU[celli] = min(minU[celli], Unb);
    };

    forAll(nei, facei)
    {
        const vector d(C[nei[facei]] - C[own[facei]]);
        const vector dU(U[nei[facei]] - U[own[facei]]);
        const tensor wddU((d/magSqr(d))*dU);
        gradU[own[facei]] += wddU;
        gradU[nei[facei]] += wddU;
        if (limit_)
        {
            range(own[facei], U[nei[facei]]);
            range(nei[facei], U[own[facei]]);
        }
    }

    forAll(mesh_.boundary(), patchi)
    {
        if (kinds_[patchi] == neighbour::none) continue;
        const labelUList& fc = mesh_.boundary()[patchi].faceCells();
        vectorField nbrC, nbrU;
        if (kinds_[patchi] == neighbour::coupled)
        {
            nbrC = Cv.boundaryField()[patchi].patchNeighbourField();
            nbrU = U.boundaryField()[patchi].patchNeighbourField();
        }
        forAll(fc, i)
        {
            vector d, dU;
            boundaryNeighbour(patchi, i, U, nbrC, nbrU, d, dU);
            gradU[fc[i]] += (d/magSqr(d))*dU;
            if (limit_)
            {
                range(fc[i], U[fc[i]] + dU);
            }
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

    // Barth-Jespersen: face-centroid extrapolations within the neighbours'
    // range, component by component
    vectorField limiter(mesh_.nCells(), vector::one);

    const auto limitFace = [&](const label celli, const vector& dx)
    {
        const vector dU(dx & gradU[celli]);
        for (direction cmpt = 0; cmpt < vector::nComponents; ++cmpt)
        {
            const scalar u = U[celli][cmpt];
            scalar r = 1;
            if (dU[cmpt] > VSMALL)
            {
                r = (maxU[celli][cmpt] - u)/dU[cmpt];
            }
            else if (dU[cmpt] < -VSMALL)
            {
                r = (minU[celli][cmpt] - u)/dU[cmpt];
            }
            limiter[celli][cmpt] = min(limiter[celli][cmpt], r);
        }
    };

    forAll(nei, facei)
    {
        limitFace(own[facei], Cf[facei] - C[own[facei]]);
        limitFace(nei[facei], Cf[facei] - C[nei[facei]]);
    }
    forAll(mesh_.boundary(), patchi)
    {
        // A wedge face is reconstructed at its image in the cell's plane,
        // next to the cell centre: nothing to limit there
        if
        (
            kinds_[patchi] == neighbour::none
         || kinds_[patchi] == neighbour::wedge
        )
        {
            continue;
        }
        const fvPatch& patch = mesh_.boundary()[patchi];
        const labelUList& fc = patch.faceCells();
        forAll(fc, i)
        {
            limitFace(fc[i], patch.Cf()[i] - C[fc[i]]);
        }
    }

    forAll(gradU, celli)
    {
        const vector& l = limiter[celli];
        tensor& g = gradU[celli];
        // Column j of grad(U) is the gradient of component j
        g.xx() *= l.x(); g.yx() *= l.x(); g.zx() *= l.x();
        g.xy() *= l.y(); g.yy() *= l.y(); g.zy() *= l.y();
        g.xz() *= l.z(); g.yz() *= l.z(); g.zz() *= l.z();
    }
}
