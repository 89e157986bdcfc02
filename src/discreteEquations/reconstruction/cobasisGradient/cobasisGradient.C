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
    const boolList& active,
    solidSlopeRecords& slopes
) const
{
    const labelUList& own = mesh_.owner();
    const labelUList& nei = mesh_.neighbour();
    const vectorField& Sf = mesh_.Sf();
    const scalarField& w = mesh_.weights();
    const tensorField& Ai = A.primitiveField();

    // Only the marked cells are summed, divided and read
    const label nCells = mesh_.nCells();
    for (label c = 0; c < nCells; ++c)
    {
        if (!active[c]) continue;
        for (int i = 0; i < 3; ++i) slopes[c].gA[i].setZero();
    }

    // Adds S_i A_f to cell c's sum of direction i, component by component
    // (A_f row-major, gA(r, s) = dA_rs/dx_i)
    const auto add = [&slopes, &active]
    (
        const label c,
        const vector& S,
        const tensor& Af
    )
    {
        if (!active[c]) return;
        for (int i = 0; i < 3; ++i)
        {
            cobasis::matrix& g = slopes[c].gA[i];
            for (direction r = 0; r < 3; ++r)
            {
                for (direction s = 0; s < 3; ++s)
                {
                    g(r, s) += S[i]*Af[3*r + s];
                }
            }
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
    forAll(V, c)
    {
        if (!active[c]) continue;
        for (int i = 0; i < 3; ++i)
        {
            double* g = slopes[c].gA[i].data();
            for (direction cmpt = 0; cmpt < 9; ++cmpt)
            {
                g[cmpt] /= V[c];
            }
        }
    }
}


void Foam::cobasisGradient::limit
(
    const volTensorField& A,
    const boolList& active,
    solidSlopeRecords& slopes
) const
{
    // Tensor component 3 r + s is gA(r, s)
    limiter_->limit
    (
        A,
        [&slopes](const label celli, const vector& dx)
        {
            const cobasis::matrix* g = slopes[celli].gA;
            tensor dA;
            for (direction r = 0; r < 3; ++r)
            {
                for (direction s = 0; s < 3; ++s)
                {
                    dA[3*r + s] =
                        dx.x()*g[0](r, s)
                      + dx.y()*g[1](r, s)
                      + dx.z()*g[2](r, s);
                }
            }
            return dA;
        },
        [&slopes](const label celli, const tensor& l)
        {
            cobasis::matrix* g = slopes[celli].gA;
            for (int i = 0; i < 3; ++i)
            {
                for (direction r = 0; r < 3; ++r)
                {
                    for (direction s = 0; s < 3; ++s)
                    {
                        g[i](r, s) *= l[3*r + s];
                    }
                }
            }
        },
        &active
    );
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::cobasisGradient::calculate
(
    const volTensorField& A,
    const boolList& active,
    solidSlopeRecords& slopes
) const
{
    gaussSlopes(A, active, slopes);
    if (limiter_.valid())
    {
        limit(A, active, slopes);
    }
}


// ************************************************************************* //
