#include "cobasisGradient.H"
#include "surfaceFields.H"

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::cobasisGradient::cobasisGradient
(
    const fvMesh& mesh,
    const List<cellLimiter::neighbour>& kinds,
    const bool limit
)
:
    mesh_(mesh),
    limiter_(limit ? new cellLimiter(mesh, kinds) : nullptr)
{}


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

void Foam::cobasisGradient::gaussSlopes
(
    const volTensorField& A,
    const boolList& active
)
{
    const labelUList& own = mesh_.owner();
    const labelUList& nei = mesh_.neighbour();
    const vectorField& Sf = mesh_.Sf();
    const scalarField& w = mesh_.weights();
    const tensorField& Ai = A.primitiveField();

    // Only the marked cells are summed, divided and read
    const label nCells = mesh_.nCells();
    for (int i = 0; i < 3; ++i)
    {
        dAdx_[i].resize(nCells);
        tensorField& g = dAdx_[i];
        for (label c = 0; c < nCells; ++c)
        {
            if (active[c]) g[c] = Zero;
        }
    }

    // Adds S_i A_f to cell c's sum of direction i
    const auto add = [this, &active]
    (
        const label c,
        const vector& S,
        const tensor& Af
    )
    {
        if (!active[c]) return;
        for (int i = 0; i < 3; ++i)
        {
            dAdx_[i][c] += S[i]*Af;
        }
    };

    // A face between two unmarked cells is skipped (each cell's sum keeps
    // its order)
    forAll(nei, facei)
    {
        if (!active[own[facei]] && !active[nei[facei]])
        {
            continue;
        }
        const tensor Af
        (
            w[facei]*(Ai[own[facei]] - Ai[nei[facei]]) + Ai[nei[facei]]
        );
        add(own[facei], Sf[facei], Af);
        add(nei[facei], -Sf[facei], Af);
    }

    forAll(mesh_.boundary(), patchi)
    {
        const fvPatch& patch = mesh_.boundary()[patchi];
        const labelUList& fc = patch.faceCells();
        const vectorField& pSf = mesh_.Sf().boundaryField()[patchi];
        const fvPatchTensorField& pA = A.boundaryField()[patchi];
        if (pA.coupled())
        {
            const scalarField& pw = mesh_.weights().boundaryField()[patchi];
            const tensorField nbr(pA.patchNeighbourField());
            forAll(fc, facei)
            {
                add
                (
                    fc[facei],
                    pSf[facei],
                    pw[facei]*Ai[fc[facei]] + (1 - pw[facei])*nbr[facei]
                );
            }
        }
        else
        {
            forAll(fc, facei)
            {
                add(fc[facei], pSf[facei], pA[facei]);
            }
        }
    }

    const scalarField& V = mesh_.V();
    for (int i = 0; i < 3; ++i)
    {
        forAll(V, c)
        {
            if (active[c]) dAdx_[i][c] /= V[c];
        }
    }
}


void Foam::cobasisGradient::limit
(
    const volTensorField& A,
    const boolList& active
)
{
    limiter_->factors
    (
        A,
        [this](const label celli, const vector& dx)
        {
            tensor dA;
            for (direction cmpt = 0; cmpt < 9; ++cmpt)
            {
                dA[cmpt] =
                    dx.x()*dAdx_[0][celli][cmpt]
                  + dx.y()*dAdx_[1][celli][cmpt]
                  + dx.z()*dAdx_[2][celli][cmpt];
            }
            return dA;
        },
        limiterA_,
        &active
    );
    for (int i = 0; i < 3; ++i)
    {
        tensorField& g = dAdx_[i];
        forAll(g, celli)
        {
            if (!active[celli]) continue;
            for (direction cmpt = 0; cmpt < 9; ++cmpt)
            {
                g[celli][cmpt] *= limiterA_[celli][cmpt];
            }
        }
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::cobasisGradient::calculate
(
    const volTensorField& A,
    const boolList& active
)
{
    gaussSlopes(A, active);
    if (limiter_.valid())
    {
        limit(A, active);
    }
}


// ************************************************************************* //
