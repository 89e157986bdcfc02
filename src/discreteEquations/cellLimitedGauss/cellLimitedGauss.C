#include "cellLimitedGauss.H"
#include "boundaryFaceTable.H"
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
) const
{
    const labelUList& own = mesh_.owner();
    const labelUList& nei = mesh_.neighbour();
    const vectorField& Sf = mesh_.Sf().primitiveField();
    const scalarField& w = mesh_.weights().primitiveField();
    const vectorField& C = mesh_.C().primitiveField();
    const scalarField& V = mesh_.V();
    const label nCells = mesh_.nCells();
    const label nPatches = mesh_.boundary().size();

    const scalarField* v[N];
    List<scalarField> nbr[N];
    for (int i = 0; i < N; ++i)
    {
        v[i] = &vf[i]->primitiveField();
        g[i]->setSize(nCells);
        *g[i] = Zero;

        // The neighbouring processors' values
        nbr[i].setSize(nPatches);
        for (label patchi = 0; patchi < nPatches; ++patchi)
        {
            const fvPatchScalarField& pv = vf[i]->boundaryField()[patchi];
            if (pv.coupled())
            {
                nbr[i][patchi] = pv.patchNeighbourField();
            }
        }
    }

    // Only the cells that read their slope need it
    const auto skip = [active](const label c)
    {
        return active && !(*active)[c];
    };

    // Gauss sums, internal faces
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
            const vector Sv
            (
                Sf[facei]*(w[facei]*(vi[o] - vi[n]) + vi[n])
            );
            gi[o] += Sv;
            gi[n] -= Sv;
        }
    }

    // Boundary faces (an empty patch has no faces here)
    for (label patchi = 0; patchi < nPatches; ++patchi)
    {
        const fvPatch& patch = mesh_.boundary()[patchi];
        const labelUList& fc = patch.faceCells();
        const vectorField& pSf = mesh_.Sf().boundaryField()[patchi];

        for (int i = 0; i < N; ++i)
        {
            const fvPatchScalarField& pv = vf[i]->boundaryField()[patchi];
            vectorField& gi = *g[i];
            if (pv.coupled())
            {
                const scalarField& pw =
                    mesh_.weights().boundaryField()[patchi];
                const scalarField& vn = nbr[i][patchi];
                forAll(patch, j)
                {
                    const scalar vc = (*v[i])[fc[j]];
                    gi[fc[j]] += pSf[j]*(pw[j]*vc + (1.0 - pw[j])*vn[j]);
                }
            }
            else
            {
                forAll(patch, j)
                {
                    gi[fc[j]] += pSf[j]*pv[j];
                }
            }
        }
    }

    // Cell by cell: the range over the cell, its face neighbours and its
    // boundary values, then the Barth-Jespersen factor (minmod of r, as
    // cellLimitedGrad) over its faces, applied to the slope
    const cellList& cells = mesh_.cells();
    const vectorField& xf = mesh_.faceCentres();
    const label nInternal = mesh_.nInternalFaces();
    const boundaryFaceTable boundaryFace(mesh_);

    // Per field and patch, the neighbour values a boundary face gives:
    // the processor neighbour's, or the patch value
    List<const scalarField*> bv[N];
    for (int i = 0; i < N; ++i)
    {
        bv[i].setSize(nPatches);
        for (label patchi = 0; patchi < nPatches; ++patchi)
        {
            const fvPatchScalarField& pv = vf[i]->boundaryField()[patchi];
            bv[i][patchi] = pv.coupled() ? &nbr[i][patchi] : &pv;
        }
    }

    for (label c = 0; c < nCells; ++c)
    {
        if (skip(c))
        {
            for (int i = 0; i < N; ++i)
            {
                (*g[i])[c] = Zero;
            }
            continue;
        }
        const labelList& cFaces = cells[c];

        scalar vMax[N], vMin[N];
        for (int i = 0; i < N; ++i)
        {
            (*g[i])[c] /= V[c];
            vMax[i] = vMin[i] = (*v[i])[c];
        }
        for (const label facei : cFaces)
        {
            if (facei < nInternal)
            {
                const label n = own[facei] == c ? nei[facei] : own[facei];
                for (int i = 0; i < N; ++i)
                {
                    vMax[i] = max(vMax[i], (*v[i])[n]);
                    vMin[i] = min(vMin[i], (*v[i])[n]);
                }
                continue;
            }
            label patchi, j;
            if (!boundaryFace(facei, patchi, j)) continue;
            for (int i = 0; i < N; ++i)
            {
                const scalar vn = (*bv[i][patchi])[j];
                vMax[i] = max(vMax[i], vn);
                vMin[i] = min(vMin[i], vn);
            }
        }
        scalar l[N];
        for (int i = 0; i < N; ++i)
        {
            vMax[i] -= (*v[i])[c];
            vMin[i] -= (*v[i])[c];
            l[i] = 1;
        }

        for (const label facei : cFaces)
        {
            label patchi, j;
            if (facei >= nInternal && !boundaryFace(facei, patchi, j))
            {
                continue;
            }
            const vector dx(xf[facei] - C[c]);
            for (int i = 0; i < N; ++i)
            {
                const scalar extrapolate = dx & (*g[i])[c];
                scalar r;
                if (extrapolate > SMALL)
                {
                    r = vMax[i]/extrapolate;
                }
                else if (extrapolate < -SMALL)
                {
                    r = vMin[i]/extrapolate;
                }
                else
                {
                    continue;
                }
                l[i] = min(l[i], min(r, scalar(1)));
            }
        }
        for (int i = 0; i < N; ++i)
        {
            (*g[i])[c] *= l[i];
        }
    }
}


void Foam::cellLimitedGauss::grad
(
    const volScalarField& vf,
    vectorField& g,
    const boolList* active
) const
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
) const
{
    const volScalarField* const f[2] = {&vf1, &vf2};
    vectorField* const gs[2] = {&g1, &g2};
    gradFields<2>(f, gs, active);
}


// ************************************************************************* //
