#include "linearAlphaProfile.H"
#include "addToRunTimeSelectionTable.H"

namespace Foam
{
    defineTypeNameAndDebug(linearAlphaProfile, 0);
    addToRunTimeSelectionTable(alphaProfile, linearAlphaProfile, dictionary);
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::linearAlphaProfile::linearAlphaProfile
(
    const phaseSystem& phases,
    const dictionary& dict
)
:
    alphaProfile(phases, false),
    compression_(readCompression(dict))
{}


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

void Foam::linearAlphaProfile::compress
(
    const volScalarField& alpha,
    const scalarField& aMin,
    const scalarField& aMax,
    vectorField& g
) const
{
    const label nCells = mesh_.nCells();
    const labelUList& own = mesh_.owner();
    const labelUList& nei = mesh_.neighbour();
    const vectorField& Cf = mesh_.faceCentres();
    const vectorField& C = mesh_.cellCentres();

    // Largest factor of g that keeps every face value in range
    scalarField factor(nCells, compression_);
    const auto limit = [&](const label c, const vector& d)
    {
        const scalar delta = g[c] & d;
        if (delta > VSMALL)
        {
            factor[c] = min(factor[c], (aMax[c] - alpha[c])/delta);
        }
        else if (delta < -VSMALL)
        {
            factor[c] = min(factor[c], (aMin[c] - alpha[c])/delta);
        }
    };
    forAll(nei, facei)
    {
        limit(own[facei], Cf[facei] - C[own[facei]]);
        limit(nei[facei], Cf[facei] - C[nei[facei]]);
    }
    forAll(mesh_.boundary(), patchi)
    {
        if (phases_.boundary().passive(patchi)) continue;
        const fvPatch& patch = mesh_.boundary()[patchi];
        const labelUList& fc = patch.faceCells();
        forAll(fc, i)
        {
            limit(fc[i], Cf[patch.start() + i] - C[fc[i]]);
        }
    }

    forAll(g, c)
    {
        g[c] *= max(factor[c], scalar(0));
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::linearAlphaProfile::correctSlopes
(
    const volScalarField& alpha,
    const scalarField& aMin,
    const scalarField& aMax,
    vectorField& g
) const
{
    // A single phase has alpha = 1 and no slope
    if (compression_ > 1 && phases_.size() > 1)
    {
        compress(alpha, aMin, aMax, g);
    }
}


void Foam::linearAlphaProfile::describe(Ostream& os) const
{
    if (compression_ > 1)
    {
        os  << ", volume fraction slopes steepened by " << compression_;
    }
}


// ************************************************************************* //
