/*---------------------------------------------------------------------------*\
  impactFoam: Eulerian multiphase elastic-plastic impact solver for OpenFOAM
\*---------------------------------------------------------------------------*/

#include "slidingInterfaces.H"
#include "surfaceFields.H"

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
    const label nCells = mesh.nCells();
    k_.assign(nCells, -1);
    j_.assign(nCells, -1);
    normal_.assign(nCells, vector::zero);
    area_.assign(nCells, 0);
    active_.assign(nCells, 0);
    score_.assign(nCells, 0);
    grad_.resize(nCells);
    hoodK_.resize(nCells);
    hoodJ_.resize(nCells);
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
    const scalarField& V = mesh_.V();

    std::fill(k_.begin(), k_.end(), -1);
    std::fill(score_.begin(), score_.end(), 0);
    nBand_ = 0;

    for (const auto& pair : pairs_)
    {
        const scalarField& ak = alpha[pair.first].primitiveField();
        const scalarField& aj = alpha[pair.second].primitiveField();

        for (label c = 0; c < nCells; ++c)
        {
            grad_[c] = vector::zero;
            hoodK_[c] = ak[c];
            hoodJ_[c] = aj[c];
        }

        // Green-Gauss of d = alpha_k - alpha_j with the face value the
        // mean of its two cells: (d_f - d_c) S_f out of each cell
        forAll(nei, facei)
        {
            const label o = own[facei];
            const label n = nei[facei];
            const vector g(0.5*((ak[n] - aj[n]) - (ak[o] - aj[o]))*Sf[facei]);
            grad_[o] += g;
            grad_[n] += g;
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
            const vectorField& pSf = patch.Sf();
            forAll(fc, i)
            {
                const label c = fc[i];
                grad_[c] +=
                    0.5*((nbrK[i] - nbrJ[i]) - (ak[c] - aj[c]))*pSf[i];
                hoodK_[c] = max(hoodK_[c], nbrK[i]);
                hoodJ_[c] = max(hoodJ_[c], nbrJ[i]);
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
                    (!regimes_.trace(ak[c]) && !regimes_.trace(aj[c]))
                  ? magGrad/V[c]
                  : 0;
            }
        }
    }

    shareArea(alpha[0]);
}


void Foam::slidingInterfaces::shareArea(const volScalarField& like)
{
    // The cells where both solids of the pair are present hold the
    // interface: each takes the interface's area across the cell, its
    // width along n (sum |S_f.n|/(2V) for a box, the area per unit volume
    // of a plane through the middle), in the share of the gradient it
    // holds among itself and its neighbours that hold the interface too
    // (a sharp interface in one row of cells: all of it; spread over two
    // rows: half each)
    const label nCells = mesh_.nCells();
    const labelUList& own = mesh_.owner();
    const labelUList& nei = mesh_.neighbour();
    const vectorField& Sf = mesh_.Sf();
    const scalarField& V = mesh_.V();

    volScalarField activeField
    (
        IOobject
        (
            "slidingInterfaces:active",
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
    scalarField& a = activeField.primitiveFieldRef();
    for (label c = 0; c < nCells; ++c)
    {
        a[c] = k_[c] >= 0 ? active_[c] : 0;
        grad_[c] = vector::zero;
        hoodK_[c] = a[c];
        hoodJ_[c] = 0;
    }
    activeField.correctBoundaryConditions();

    // hoodK_: the sum of the gradients of the cell and its neighbours of
    // the same pair, each weighted by |n.n_f| (across the interface);
    // hoodJ_: sum |S_f.n|
    forAll(nei, facei)
    {
        const label o = own[facei];
        const label n = nei[facei];
        if (a[o] > 0 && a[n] > 0 && k_[o] == k_[n] && j_[o] == j_[n])
        {
            // Neighbours across the interface count, those along it not
            const vector nf(Sf[facei]/mag(Sf[facei]));
            hoodK_[o] += a[n]*mag(nf & normal_[o]);
            hoodK_[n] += a[o]*mag(nf & normal_[n]);
        }
        if (a[o] > 0) hoodJ_[o] += mag(Sf[facei] & normal_[o]);
        if (a[n] > 0) hoodJ_[n] += mag(Sf[facei] & normal_[n]);
    }
    forAll(mesh_.boundary(), patchi)
    {
        const fvPatch& patch = mesh_.boundary()[patchi];
        const labelUList& fc = patch.faceCells();
        const vectorField& pSf = patch.Sf();
        const scalarField nbr
        (
            patch.coupled()
          ? activeField.boundaryField()[patchi].patchNeighbourField()()
          : scalarField(fc.size(), 0)
        );
        forAll(fc, i)
        {
            const label c = fc[i];
            if (a[c] > 0)
            {
                hoodK_[c] += nbr[i]*mag(pSf[i] & normal_[c])/mag(pSf[i]);
                hoodJ_[c] += mag(pSf[i] & normal_[c]);
            }
        }
    }

    for (label c = 0; c < nCells; ++c)
    {
        area_[c] =
            a[c] > 0 ? 0.5*hoodJ_[c]/V[c]*a[c]/hoodK_[c] : 0;
    }
}


// ************************************************************************* //
