#include "bodyMotion.H"
#include "regionSplit.H"
#include "syncTools.H"
#include "wedgeRevolution.H"
#include "addToRunTimeSelectionTable.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace functionObjects
{
    defineTypeNameAndDebug(bodyMotion, 0);
    addToRunTimeSelectionTable(functionObject, bodyMotion, dictionary);
}
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::functionObjects::bodyMotion::bodyMotion
(
    const word& name,
    const Time& runTime,
    const dictionary& dict
)
:
    impactTimeHistory(name, runTime, dict),
    phase_(-1),
    fragmentAlpha_(0.5),
    axis_(Zero),
    toFull_(0)
{
    bodyMotion::read(dict);
    toFull_ = wedgeToFull(mesh_, axis_);
    start();
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

bool Foam::functionObjects::bodyMotion::read(const dictionary& dict)
{
    impactTimeHistory::read(dict);
    phase_ = phaseIndex(dict, dict.get<word>("phase"));
    fragmentAlpha_ = dict.getOrDefault<scalar>("fragmentAlpha", 0.5);
    if (!(fragmentAlpha_ > 0 && fragmentAlpha_ <= 1))
    {
        FatalIOErrorInFunction(dict)
            << "fragmentAlpha " << fragmentAlpha_ << " in function object "
            << name() << ": must lie in (0, 1]" << exit(FatalIOError);
    }
    return true;
}


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

Foam::vector Foam::functionObjects::bodyMotion::full(const vector& U) const
{
    return toFull_ > 0 ? (U & axis_)*axis_ : U;
}


// * * * * * * * * * * * * * Protected Member Functions  * * * * * * * * * * //

Foam::wordList Foam::functionObjects::bodyMotion::columns() const
{
    return wordList
    ({
        "mass", "Ux", "Uy", "Uz", "fragments",
        "fragmentMass", "fragmentUx", "fragmentUy", "fragmentUz"
    });
}


Foam::wordList Foam::functionObjects::bodyMotion::units() const
{
    return wordList
    ({
        "[kg]", "[m/s]", "[m/s]", "[m/s]", "[-]",
        "[kg]", "[m/s]", "[m/s]", "[m/s]"
    });
}


void Foam::functionObjects::bodyMotion::values(DynamicList<scalar>& row)
{
    const phaseSystem& phases = this->phases();
    const phaseModel& ph = phases[phase_];
    const scalarField& V = mesh_.V();
    const vectorField& U = phases.U().primitiveField();
    const scalarField& alpha = phases.alpha(phase_).primitiveField();
    const scalarField& rho = phases.rho(phase_).primitiveField();

    // The fragments: the cells that hold enough of the phase, split where
    // a face parts such a cell from one that does not
    boolList inBody(mesh_.nCells());
    forAll(inBody, c)
    {
        inBody[c] = alpha[c] >= fragmentAlpha_;
    }
    boolList nbrInBody;
    syncTools::swapBoundaryCellList(mesh_, inBody, nbrInBody);
    const labelList& own = mesh_.faceOwner();
    const labelList& nei = mesh_.faceNeighbour();
    boolList blocked(mesh_.nFaces(), false);
    forAll(nei, f)
    {
        blocked[f] = inBody[own[f]] != inBody[nei[f]];
    }
    for (label f = mesh_.nInternalFaces(); f < mesh_.nFaces(); ++f)
    {
        const label b = f - mesh_.nInternalFaces();
        blocked[f] = inBody[own[f]] != nbrInBody[b];
    }
    const regionSplit regions(mesh_, blocked);

    // The whole body, and each region's share (0 for the regions of cells
    // outside the body)
    scalar mass = 0;
    vector momentum(Zero);
    scalarField regionMass(regions.nRegions(), Zero);
    vectorField regionMomentum(regions.nRegions(), Zero);
    forAll(V, c)
    {
        const scalar m = alpha[c]*rho[c]*V[c];
        const vector mU(m*ph.velocity(U[c], c));
        mass += m;
        momentum += mU;
        if (inBody[c])
        {
            regionMass[regions[c]] += m;
            regionMomentum[regions[c]] += mU;
        }
    }
    reduce(mass, sumOp<scalar>());
    reduce(momentum, sumOp<vector>());
    Pstream::listCombineGather(regionMass, plusEqOp<scalar>());
    Pstream::listCombineScatter(regionMass);
    Pstream::listCombineGather(regionMomentum, plusEqOp<vector>());
    Pstream::listCombineScatter(regionMomentum);

    label nFragments = 0;
    label largest = -1;
    forAll(regionMass, r)
    {
        if (regionMass[r] > 0)
        {
            ++nFragments;
            if (largest < 0 || regionMass[r] > regionMass[largest])
            {
                largest = r;
            }
        }
    }

    const scalar toMass = toFull_ > 0 ? toFull_ : 1;
    const vector meanU(mass > 0 ? full(momentum/mass) : vector::zero);
    row.append(toMass*mass);
    for (direction d = 0; d < vector::nComponents; ++d)
    {
        // (+ 0: no negative zero from the projection)
        row.append(meanU[d] + 0.0);
    }
    row.append(nFragments);
    const scalar fragmentMass = largest < 0 ? 0 : regionMass[largest];
    const vector fragmentU
    (
        largest < 0
      ? vector::zero
      : full(regionMomentum[largest]/regionMass[largest])
    );
    row.append(toMass*fragmentMass);
    for (direction d = 0; d < vector::nComponents; ++d)
    {
        row.append(fragmentU[d] + 0.0);
    }
}


// ************************************************************************* //
