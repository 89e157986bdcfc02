#include "linearVelocityGradient.H"
#include "boundaryFaceTable.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * //

const Foam::scalar Foam::linearVelocityGradient::marginFraction_ = 3e-2;


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

    forAll(G, celli)
    {
        symmTensor Gc(G[celli]);
        completeEmptyDirections(Gc);
        const tensor invGc(inv(tensor(Gc)));
        invG_[celli] = symmTensor
        (
            invGc.xx(), invGc.xy(), invGc.xz(),
            invGc.yy(), invGc.yz(),
            invGc.zz()
        );
    }
}


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

void Foam::linearVelocityGradient::completeEmptyDirections
(
    symmTensor& G
) const
{
    // The empty direction of a planar mesh, not a wedge's normal
    // (geometricD's): the wedge images give that direction its extent, and
    // completing it as well would halve d u_z/d z, the hoop rate u_r/r that
    // the Hancock predictor reads (div u, A L)
    const Vector<label>& solD = mesh_.solutionD();
    const scalar scale = tr(G)/3;
    for (direction dir = 0; dir < vector::nComponents; ++dir)
    {
        if (solD[dir] < 0)
        {
            vector e(Zero);
            e[dir] = 1;
            G += scale*sqr(e);
        }
    }
}


void Foam::linearVelocityGradient::scaleColumns(tensor& g, const vector& l)
{
    g.xx() *= l.x(); g.yx() *= l.x(); g.zx() *= l.x();
    g.xy() *= l.y(); g.yy() *= l.y(); g.zy() *= l.y();
    g.xz() *= l.z(); g.yz() *= l.z(); g.zz() *= l.z();
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
            scaleColumns(gradU[celli], l);
        }
    );
}

void Foam::linearVelocityGradient::calculatePresent
(
    const volVectorField& Uk,
    const volScalarField& alpha,
    const scalar alphaMin,
    const labelUList& cells,
    tensorField& gradUk
) const
{
    const labelUList& own = mesh_.owner();
    const labelUList& nei = mesh_.neighbour();
    const vectorField& C = mesh_.cellCentres();
    const vectorField& Cf = mesh_.faceCentres();
    const volVectorField& Cv = mesh_.C();
    const cellList& meshCells = mesh_.cells();
    const label nInternal = mesh_.nInternalFaces();
    const boundaryFaceTable boundaryFace(mesh_);

    // The neighbouring processors' centres, velocities and fractions
    const label nPatches = mesh_.boundary().size();
    List<vectorField> nbrC(nPatches);
    List<vectorField> nbrU(nPatches);
    List<scalarField> nbrAlpha(nPatches);
    forAll(mesh_.boundary(), patchi)
    {
        if (stencil_.kind(patchi) == cellLimiter::neighbour::coupled)
        {
            nbrC[patchi] = Cv.boundaryField()[patchi].patchNeighbourField();
            nbrU[patchi] = Uk.boundaryField()[patchi].patchNeighbourField();
            nbrAlpha[patchi] =
                alpha.boundaryField()[patchi].patchNeighbourField();
        }
    }

    // The neighbour across a face of a cell, where it holds the phase: its
    // offset from the cell centre and its value
    const auto neighbour = [&]
    (
        const label celli,
        const label facei,
        vector& d,
        vector& vn
    )
    {
        if (facei < nInternal)
        {
            const label nb = own[facei] == celli ? nei[facei] : own[facei];
            if (alpha[nb] < alphaMin) return false;
            d = C[nb] - C[celli];
            vn = Uk[nb];
            return true;
        }
        label patchi, i;
        if (!boundaryFace(facei, patchi, i)) return false;
        const cellLimiter::neighbour kind = stencil_.kind(patchi);
        if
        (
            kind == cellLimiter::neighbour::none
         || (
                kind == cellLimiter::neighbour::coupled
             && nbrAlpha[patchi][i] < alphaMin
            )
        )
        {
            return false;
        }
        d = stencil_.offset(patchi, i, nbrC[patchi]);
        vn = stencil_.value(patchi, i, Uk, nbrU[patchi]);
        return true;
    };

    for (const label celli : cells)
    {
        const vector& uc = Uk[celli];
        symmTensor G(Zero);
        tensor b(Zero);
        vector vMax(uc);
        vector vMin(uc);
        for (const label facei : meshCells[celli])
        {
            vector d, vn;
            if (!neighbour(celli, facei, d, vn)) continue;
            G += sqr(d)/magSqr(d);
            b += (d/magSqr(d))*(vn - uc);
            vMax = max(vMax, vn);
            vMin = min(vMin, vn);
        }

        // Directions without extent: unit diagonal (zero gradient there);
        // too few neighbours for a full gradient (the phase's corner): a
        // small multiple of the identity, the least gradient that fits
        const scalar scale = tr(G)/3;
        if (!(scale > 0))
        {
            gradUk[celli] = Zero;
            continue;
        }
        completeEmptyDirections(G);
        if (det(G) < 1e-6*pow3(scale))
        {
            G += 1e-3*scale*symmTensor(I);
        }
        tensor g(inv(tensor(G)) & b);

        if (limit_)
        {
            // Barth-Jespersen, component by component, at the centres of
            // the faces whose neighbour holds the phase (not wedges: the
            // image lies next to the centre), within their range widened
            // on each side by a margin: marginFraction_ of the largest of
            // the components' ranges, the local variation of the velocity.
            // Across the other faces the phase meets another, so the range
            // is often one-sided here (at the phase's edge the cell's own
            // value bounds it), and a component that hardly varies (the
            // normal velocity along a sliding interface) would have its
            // whole gradient cut by its smallest wiggle. The factor would
            // then follow the wiggles and feed them: the serial and the
            // parallel run of V15a's closed box part by 4e-1 without the
            // margin, by 1e-8 with it. Overshoots within the margin are
            // left alone
            const scalar margin =
                marginFraction_*cmptMax(vMax - vMin) + VSMALL;
            vector l(vector::one);
            for (const label facei : meshCells[celli])
            {
                vector d, vn;
                if (!neighbour(celli, facei, d, vn)) continue;
                label patchi, i;
                if
                (
                    facei >= nInternal
                 && boundaryFace(facei, patchi, i)
                 && stencil_.kind(patchi) == cellLimiter::neighbour::wedge
                )
                {
                    continue;
                }
                const vector dv((Cf[facei] - C[celli]) & g);
                for (direction cmpt = 0; cmpt < vector::nComponents; ++cmpt)
                {
                    const scalar up = vMax[cmpt] - uc[cmpt] + margin;
                    const scalar down = vMin[cmpt] - uc[cmpt] - margin;
                    if (dv[cmpt] > up)
                    {
                        l[cmpt] = min(l[cmpt], up/dv[cmpt]);
                    }
                    else if (dv[cmpt] < down)
                    {
                        l[cmpt] = min(l[cmpt], down/dv[cmpt]);
                    }
                }
            }
            scaleColumns(g, l);
        }
        gradUk[celli] = g;
    }
}


// ************************************************************************* //
