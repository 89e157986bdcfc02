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


void Foam::cellLimitedGauss::grad
(
    const volScalarField& vf,
    vectorField& g,
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
    const scalarField& v = vf.primitiveField();
    const label nCells = mesh_.nCells();

    g.setSize(nCells);
    g = Zero;
    vMax_ = v;
    vMin_ = v;

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
        const vector Sv
        (
            Sf[facei]*(w[facei]*(v[o] - v[n]) + v[n])
        );
        g[o] += Sv;
        g[n] -= Sv;

        vMax_[o] = max(vMax_[o], v[n]);
        vMin_[o] = min(vMin_[o], v[n]);
        vMax_[n] = max(vMax_[n], v[o]);
        vMin_[n] = min(vMin_[n], v[o]);
    }

    // Boundary faces (an empty patch has no faces here)
    const volScalarField::Boundary& bv = vf.boundaryField();
    forAll(mesh_.boundary(), patchi)
    {
        const fvPatch& patch = mesh_.boundary()[patchi];
        const labelUList& fc = patch.faceCells();
        const vectorField& pSf = mesh_.Sf().boundaryField()[patchi];
        const fvPatchScalarField& pv = bv[patchi];

        if (pv.coupled())
        {
            const scalarField& pw = mesh_.weights().boundaryField()[patchi];
            const scalarField vi(pv.patchInternalField());
            const scalarField vn(pv.patchNeighbourField());
            forAll(patch, i)
            {
                g[fc[i]] += pSf[i]*(pw[i]*vi[i] + (1.0 - pw[i])*vn[i]);
                vMax_[fc[i]] = max(vMax_[fc[i]], vn[i]);
                vMin_[fc[i]] = min(vMin_[fc[i]], vn[i]);
            }
        }
        else
        {
            forAll(patch, i)
            {
                g[fc[i]] += pSf[i]*pv[i];
                vMax_[fc[i]] = max(vMax_[fc[i]], pv[i]);
                vMin_[fc[i]] = min(vMin_[fc[i]], pv[i]);
            }
        }
    }

    for (label c = 0; c < nCells; ++c)
    {
        if (skip(c))
        {
            g[c] = Zero;
            continue;
        }
        g[c] /= V[c];
        vMax_[c] -= v[c];
        vMin_[c] -= v[c];
    }

    // The Barth-Jespersen factors (minmod of r, as cellLimitedGrad)
    limiter_.setSize(nCells);
    limiter_ = 1;
    const auto limitFace = [&](const label c, const vector& dx)
    {
        if (skip(c))
        {
            return;
        }
        const scalar extrapolate = dx & g[c];
        scalar r;
        if (extrapolate > SMALL)
        {
            r = vMax_[c]/extrapolate;
        }
        else if (extrapolate < -SMALL)
        {
            r = vMin_[c]/extrapolate;
        }
        else
        {
            return;
        }
        limiter_[c] = min(limiter_[c], min(r, scalar(1)));
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
        forAll(patch, i)
        {
            limitFace(fc[i], pCf[i] - C[fc[i]]);
        }
    }

    for (label c = 0; c < nCells; ++c)
    {
        g[c] *= limiter_[c];
    }
}


// ************************************************************************* //
