/*---------------------------------------------------------------------------*\
  impactFoam: Eulerian multiphase elastic-plastic impact solver for OpenFOAM
\*---------------------------------------------------------------------------*/

#include "slidingInterfaces.H"
#include "surfaceFields.H"
#include "volPointInterpolation.H"

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::slidingInterfaces::slidingInterfaces
(
    const fvMesh& mesh,
    const solidContacts& contacts,
    const phaseRegimes& regimes,
    const label nPhases
)
:
    mesh_(mesh),
    contacts_(contacts),
    regimes_(regimes),
    nBand_(0)
{
    for (label k = 0; k < nPhases; ++k)
    {
        for (label j = k + 1; j < nPhases; ++j)
        {
            if (contacts.law(k, j))
            {
                pairs_.emplace_back(k, j);
            }
        }
    }
    updateMesh();
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::slidingInterfaces::update
(
    const UPtrList<const volScalarField>& alpha
)
{
    const label nCells = mesh_.nCells();
    const labelUList& own = mesh_.owner();
    const labelUList& nei = mesh_.neighbour();
    const vectorField& Sf = mesh_.Sf();

    std::fill(k_.begin(), k_.end(), -1);
    std::fill(score_.begin(), score_.end(), 0);
    nBand_ = 0;

    for (label pairi = 0; pairi < label(pairs_.size()); ++pairi)
    {
        const auto& pair = pairs_[pairi];
        const scalarField& ak = alpha[pair.first].primitiveField();
        const scalarField& aj = alpha[pair.second].primitiveField();

        for (label c = 0; c < nCells; ++c)
        {
            grad_[c] = vector::zero;
            hoodK_[c] = ak[c];
            hoodJ_[c] = aj[c];
        }

        // The neighbourhoods: the largest fraction of each phase in the
        // cell and its face neighbours (across coupled patches too)
        forAll(nei, facei)
        {
            const label o = own[facei];
            const label n = nei[facei];
            hoodK_[o] = max(hoodK_[o], ak[n]);
            hoodK_[n] = max(hoodK_[n], ak[o]);
            hoodJ_[o] = max(hoodJ_[o], aj[n]);
            hoodJ_[n] = max(hoodJ_[n], aj[o]);
        }
        forAll(mesh_.boundary(), patchi)
        {
            const fvPatch& patch = mesh_.boundary()[patchi];
            if (!patch.coupled())
            {
                continue;
            }
            const scalarField nbrK
            (
                alpha[pair.first].boundaryField()[patchi].patchNeighbourField()
            );
            const scalarField nbrJ
            (
                alpha[pair.second].boundaryField()[patchi].patchNeighbourField()
            );
            const labelUList& fc = patch.faceCells();
            forAll(fc, i)
            {
                hoodK_[fc[i]] = max(hoodK_[fc[i]], nbrK[i]);
                hoodJ_[fc[i]] = max(hoodJ_[fc[i]], nbrJ[i]);
            }
        }

        // The normal: Green-Gauss of d = alpha_k - alpha_j with the face
        // value the mean of d at the face's points, d at a point the
        // inverse-distance mean of the cells around it (volPointInterpolation,
        // across processors). The point values bring in the cells that
        // share only an edge or a corner (Youngs' stencil, the 3 x 3 cells
        // of a square mesh): with the face values from the two cells of a
        // face alone, an interface at 30 degrees to a square mesh reads
        // at 42
        volScalarField d(scratchField("d", alpha[pair.first]));
        d.primitiveFieldRef() = ak - aj;
        d.correctBoundaryConditions();
        for (label pass = 0; pass < nSmooth_; ++pass)
        {
            smooth(d);
        }
        const tmp<pointScalarField> tdp
        (
            volPointInterpolation::New(mesh_).interpolate(d)
        );
        const scalarField& dp = tdp().primitiveField();
        const faceList& faces = mesh_.faces();
        const auto faceValue = [&faces, &dp](const label facei)
        {
            const face& f = faces[facei];
            scalar sum = 0;
            forAll(f, i)
            {
                sum += dp[f[i]];
            }
            return sum/f.size();
        };
        forAll(nei, facei)
        {
            const label o = own[facei];
            const label n = nei[facei];
            const scalar df = faceValue(facei);
            grad_[o] += (df - d[o])*Sf[facei];
            grad_[n] -= (df - d[n])*Sf[facei];
        }
        forAll(mesh_.boundary(), patchi)
        {
            // (the patches that are not coupled hold d_f = d_c: a wall,
            // a wedge's sides)
            const fvPatch& patch = mesh_.boundary()[patchi];
            if (!patch.coupled())
            {
                continue;
            }
            const labelUList& fc = patch.faceCells();
            const vectorField& pSf = patch.Sf();
            const label start = patch.start();
            forAll(fc, i)
            {
                const label c = fc[i];
                grad_[c] += (faceValue(start + i) - d[c])*pSf[i];
            }
        }

        for (label c = 0; c < nCells; ++c)
        {
            const bool here = !regimes_.trace(ak[c]) || !regimes_.trace(aj[c]);
            const scalar score = min(hoodK_[c], hoodJ_[c]);
            const scalar magGrad = mag(grad_[c]);
            if
            (
                here
             && !regimes_.trace(score)
             && magGrad > 0
             && score > score_[c]
            )
            {
                if (k_[c] < 0) ++nBand_;
                score_[c] = score;
                k_[c] = pair.first;
                j_[c] = pair.second;
                normal_[c] = grad_[c]/magGrad;
                active_[c] =
                    (ak[c] >= alphaInterface_ && aj[c] >= alphaInterface_)
                  ? pairi + 1
                  : 0;
            }
        }
    }

    shareArea(alpha);
}


void Foam::slidingInterfaces::smooth(volScalarField& d) const
{
    // d <- d/2 + (the face-area weighted mean of the face neighbours)/2,
    // across coupled patches (the other patches take no part)
    const labelUList& own = mesh_.owner();
    const labelUList& nei = mesh_.neighbour();
    const scalarField& magSf = mesh_.magSf();
    scalarField& dc = d.primitiveFieldRef();
    const label nCells = mesh_.nCells();
    for (label c = 0; c < nCells; ++c)
    {
        sum_[c] = 0;
        weight_[c] = 0;
    }
    forAll(nei, facei)
    {
        const label o = own[facei];
        const label n = nei[facei];
        sum_[o] += magSf[facei]*dc[n];
        sum_[n] += magSf[facei]*dc[o];
        weight_[o] += magSf[facei];
        weight_[n] += magSf[facei];
    }
    forAll(mesh_.boundary(), patchi)
    {
        const fvPatch& patch = mesh_.boundary()[patchi];
        if (!patch.coupled())
        {
            continue;
        }
        const scalarField nbr
        (
            d.boundaryField()[patchi].patchNeighbourField()
        );
        const labelUList& fc = patch.faceCells();
        const scalarField& pMagSf = patch.magSf();
        forAll(fc, i)
        {
            sum_[fc[i]] += pMagSf[i]*nbr[i];
            weight_[fc[i]] += pMagSf[i];
        }
    }
    for (label c = 0; c < nCells; ++c)
    {
        if (weight_[c] > 0)
        {
            dc[c] = 0.5*(dc[c] + sum_[c]/weight_[c]);
        }
    }
    d.correctBoundaryConditions();
}


Foam::volScalarField Foam::slidingInterfaces::scratchField
(
    const word& name,
    const volScalarField& like
) const
{
    return volScalarField
    (
        IOobject
        (
            "slidingInterfaces:" + name,
            mesh_.time().timeName(),
            mesh_,
            IOobject::NO_READ,
            IOobject::NO_WRITE,
            false
        ),
        mesh_,
        dimensionedScalar(dimless, Zero),
        like.boundaryField().types()
    );
}


void Foam::slidingInterfaces::shareArea
(
    const UPtrList<const volScalarField>& alpha
)
{
    const label nCells = mesh_.nCells();
    const labelUList& own = mesh_.owner();
    const labelUList& nei = mesh_.neighbour();
    const vectorField& Sf = mesh_.Sf();
    const scalarField& V = mesh_.V();

    // Each cell's pair, numbered from 1, where it holds the pair's
    // interface (0 elsewhere): a neighbour holding the same pair's
    // interface shares a face's area, across coupled patches too
    volScalarField holding(scratchField("holding", alpha[0]));
    scalarField& h = holding.primitiveFieldRef();
    for (label c = 0; c < nCells; ++c)
    {
        h[c] = holdsInterface(c) ? active_[c] : 0;
        area_[c] = 0;
    }
    holding.correctBoundaryConditions();

    // A face's part of the interface: half the jump of d = alpha_k -
    // alpha_j across it times its area across n, (d_nbr - d_c) S_f.n/2 with
    // S_f out of c (summed over the faces, the Green-Gauss integral of
    // grad d . n, whose jump across the interface is 2); all of it to a
    // cell that holds the interface beside one that does not, half to
    // each of two that both hold it
    const auto addFace = [this, &alpha, &h]
    (
        const label c,
        const scalar dOther,
        const scalar otherHolds,
        const vector& SfOut
    )
    {
        const scalar dC = alpha[k_[c]][c] - alpha[j_[c]][c];
        const scalar w = otherHolds == h[c] ? 0.25 : 0.5;
        area_[c] += w*(dOther - dC)*(SfOut & normal_[c]);
    };

    forAll(nei, facei)
    {
        const label o = own[facei];
        const label n = nei[facei];
        if (h[o] > 0)
        {
            addFace(o, alpha[k_[o]][n] - alpha[j_[o]][n], h[n], Sf[facei]);
        }
        if (h[n] > 0)
        {
            addFace(n, alpha[k_[n]][o] - alpha[j_[n]][o], h[o], -Sf[facei]);
        }
    }
    forAll(mesh_.boundary(), patchi)
    {
        const fvPatch& patch = mesh_.boundary()[patchi];
        if (!patch.coupled())
        {
            continue;
        }
        const labelUList& fc = patch.faceCells();
        bool holds = false;
        forAll(fc, i)
        {
            holds = holds || h[fc[i]] > 0;
        }
        if (!holds)
        {
            continue;
        }
        const vectorField& pSf = patch.Sf();
        const scalarField nbrHolds
        (
            holding.boundaryField()[patchi].patchNeighbourField()
        );
        PtrList<scalarField> nbrAlpha(alpha.size());
        forAll(alpha, k)
        {
            nbrAlpha.set
            (
                k, alpha[k].boundaryField()[patchi].patchNeighbourField()
            );
        }
        forAll(fc, i)
        {
            const label c = fc[i];
            if (h[c] > 0)
            {
                const scalar dOther =
                    nbrAlpha[k_[c]][i] - nbrAlpha[j_[c]][i];
                addFace(c, dOther, nbrHolds[i], pSf[i]);
            }
        }
    }

    for (label c = 0; c < nCells; ++c)
    {
        area_[c] = max(area_[c], scalar(0))/V[c];
    }
}


void Foam::slidingInterfaces::updateMesh()
{
    const label nCells = mesh_.nCells();
    k_.assign(nCells, -1);
    j_.assign(nCells, -1);
    normal_.assign(nCells, vector::zero);
    area_.assign(nCells, 0);
    active_.assign(nCells, 0);
    score_.assign(nCells, 0);
    grad_.resize(nCells);
    hoodK_.resize(nCells);
    hoodJ_.resize(nCells);
    sum_.resize(nCells);
    weight_.resize(nCells);
}

// ************************************************************************* //
