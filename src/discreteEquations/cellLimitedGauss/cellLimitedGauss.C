#include "cellLimitedGauss.H"
#include "surfaceFields.H"

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::cellLimitedGauss::cellLimitedGauss(const fvMesh& mesh)
:
    mesh_(mesh)
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

bool Foam::cellLimitedGauss::matches
(
    const fvMesh& mesh,
    const word& fieldName
)
{
    // An ITstream is its list of tokens
    const tokenList& tokens = mesh.gradScheme("grad(" + fieldName + ')');
    return
        tokens.size() == 4
     && tokens[0].isWord() && tokens[0].wordToken() == "cellLimited"
     && tokens[1].isWord() && tokens[1].wordToken() == "Gauss"
     && tokens[2].isWord() && tokens[2].wordToken() == "linear"
     && tokens[3].isNumber() && tokens[3].number() == 1;
}


template<int N>
void Foam::cellLimitedGauss::gradFields
(
    const volScalarField* const vf[N],
    vectorField* const g[N],
    const boolList* active
)
{
    const labelUList& own = mesh_.owner();
    const labelUList& nei = mesh_.neighbour();
    const vectorField& Sf = mesh_.Sf().primitiveField();
    const scalarField& w = mesh_.weights().primitiveField();
    const vectorField& C = mesh_.C().primitiveField();
    const vectorField& Cf = mesh_.Cf().primitiveField();
    const scalarField& V = mesh_.V();
    const label nCells = mesh_.nCells();

    const scalarField* v[N];
    for (int i = 0; i < N; ++i)
    {
        v[i] = &vf[i]->primitiveField();
        g[i]->setSize(nCells);
        *g[i] = Zero;
        vMax_[i] = *v[i];
        vMin_[i] = *v[i];
    }

    // Only the cells that read their slope need it
    const auto skip = [active](const label c)
    {
        return active && !(*active)[c];
    };

    // Gauss sums and the neighbours' range, internal faces
    forAll(nei, facei)
    {
        const label o = own[facei];
        const label n = nei[facei];
        if (skip(o) && skip(n))
        {
            continue;
        }
        for (int i = 0; i < N; ++i)
        {
            const scalarField& vi = *v[i];
            vectorField& gi = *g[i];
            scalarField& vMax = vMax_[i];
            scalarField& vMin = vMin_[i];
            const vector Sv
            (
                Sf[facei]*(w[facei]*(vi[o] - vi[n]) + vi[n])
            );
            gi[o] += Sv;
            gi[n] -= Sv;

            vMax[o] = max(vMax[o], vi[n]);
            vMin[o] = min(vMin[o], vi[n]);
            vMax[n] = max(vMax[n], vi[o]);
            vMin[n] = min(vMin[n], vi[o]);
        }
    }

    // Boundary faces (an empty patch has no faces here)
    forAll(mesh_.boundary(), patchi)
    {
        const fvPatch& patch = mesh_.boundary()[patchi];
        const labelUList& fc = patch.faceCells();
        const vectorField& pSf = mesh_.Sf().boundaryField()[patchi];

        for (int i = 0; i < N; ++i)
        {
            const fvPatchScalarField& pv = vf[i]->boundaryField()[patchi];
            vectorField& gi = *g[i];
            scalarField& vMax = vMax_[i];
            scalarField& vMin = vMin_[i];
            if (pv.coupled())
            {
                const scalarField& pw =
                    mesh_.weights().boundaryField()[patchi];
                const scalarField vi(pv.patchInternalField());
                const scalarField vn(pv.patchNeighbourField());
                forAll(patch, j)
                {
                    gi[fc[j]] += pSf[j]*(pw[j]*vi[j] + (1.0 - pw[j])*vn[j]);
                    vMax[fc[j]] = max(vMax[fc[j]], vn[j]);
                    vMin[fc[j]] = min(vMin[fc[j]], vn[j]);
                }
            }
            else
            {
                forAll(patch, j)
                {
                    gi[fc[j]] += pSf[j]*pv[j];
                    vMax[fc[j]] = max(vMax[fc[j]], pv[j]);
                    vMin[fc[j]] = min(vMin[fc[j]], pv[j]);
                }
            }
        }
    }

    for (label c = 0; c < nCells; ++c)
    {
        for (int i = 0; i < N; ++i)
        {
            if (skip(c))
            {
                (*g[i])[c] = Zero;
                continue;
            }
            (*g[i])[c] /= V[c];
            vMax_[i][c] -= (*v[i])[c];
            vMin_[i][c] -= (*v[i])[c];
        }
    }

    // The Barth-Jespersen factors (minmod of r, as cellLimitedGrad)
    for (int i = 0; i < N; ++i)
    {
        limiter_[i].setSize(nCells);
        limiter_[i] = 1;
    }
    const auto limitFace = [&](const label c, const vector& dx)
    {
        if (skip(c))
        {
            return;
        }
        for (int i = 0; i < N; ++i)
        {
            const scalar extrapolate = dx & (*g[i])[c];
            scalar r;
            if (extrapolate > SMALL)
            {
                r = vMax_[i][c]/extrapolate;
            }
            else if (extrapolate < -SMALL)
            {
                r = vMin_[i][c]/extrapolate;
            }
            else
            {
                continue;
            }
            limiter_[i][c] = min(limiter_[i][c], min(r, scalar(1)));
        }
    };
    forAll(nei, facei)
    {
        limitFace(own[facei], Cf[facei] - C[own[facei]]);
        limitFace(nei[facei], Cf[facei] - C[nei[facei]]);
    }
    forAll(mesh_.boundary(), patchi)
    {
        const fvPatch& patch = mesh_.boundary()[patchi];
        const labelUList& fc = patch.faceCells();
        const vectorField& pCf = mesh_.Cf().boundaryField()[patchi];
        forAll(patch, j)
        {
            limitFace(fc[j], pCf[j] - C[fc[j]]);
        }
    }

    for (int i = 0; i < N; ++i)
    {
        vectorField& gi = *g[i];
        const scalarField& l = limiter_[i];
        for (label c = 0; c < nCells; ++c)
        {
            gi[c] *= l[c];
        }
    }
}


void Foam::cellLimitedGauss::grad
(
    const volScalarField& vf,
    vectorField& g,
    const boolList* active
)
{
    const volScalarField* const f[1] = {&vf};
    vectorField* const gs[1] = {&g};
    gradFields<1>(f, gs, active);
}


void Foam::cellLimitedGauss::grad
(
    const volScalarField& vf1,
    const volScalarField& vf2,
    vectorField& g1,
    vectorField& g2,
    const boolList* active
)
{
    const volScalarField* const f[2] = {&vf1, &vf2};
    vectorField* const gs[2] = {&g1, &g2};
    gradFields<2>(f, gs, active);
}


// ************************************************************************* //
