#include "firstOrderFallback.H"
#include "inputDefaults.H"
#include "syncTools.H"

// * * * * * * * * * * * * * * * Static Data * * * * * * * * * * * * * * * //

const Foam::wordList Foam::firstOrderFallback::keywords
(
    {"fallbackRounds", "fallbackInterfaces"}
);


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::firstOrderFallback::firstOrderFallback
(
    const phaseSystem& phases,
    const dictionary& schemeDict
)
:
    phases_(phases),
    mesh_(phases.mesh()),
    maxRounds_
    (
        inputDefaults::get<label>
        (
            schemeDict, "fallbackRounds", 3, "discreteEquations"
        )
    ),
    interfaces_
    (
        inputDefaults::get<Switch>
        (
            schemeDict, "fallbackInterfaces", Switch(false), "discreteEquations"
        )
    ),
    cells_(mesh_.nCells(), false),
    faces_(mesh_.nFaces(), false),
    nFaces_(0),
    cellSteps_(0),
    faceSteps_(0),
    fallbackCellSteps_(0),
    fallbackFaceSteps_(0)
{
    if (maxRounds_ < 0)
    {
        FatalIOErrorInFunction(schemeDict)
            << "fallbackRounds " << maxRounds_ << " must be >= 0"
            << exit(FatalIOError);
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::firstOrderFallback::clear()
{
    for (const label c : flagged_)
    {
        cells_[c] = false;
    }
    flagged_.clear();
    if (nFaces_ > 0)
    {
        faces_ = false;
        nFaces_ = 0;
    }

    if (interfaces_)
    {
        const phaseRegimes& regimes = phases_.regimes();
        const label nPhases = phases_.size();
        DynamicList<label> mixed;
        for (label c = 0; c < mesh_.nCells(); ++c)
        {
            for (label k = 0; k < nPhases; ++k)
            {
                if (regimes.mixed(phases_.alpha(k)[c]))
                {
                    mixed.append(c);
                    break;
                }
            }
        }
        add(mixed);
    }
}


bool Foam::firstOrderFallback::add(const labelUList& cells)
{
    bool added = false;
    for (const label c : cells)
    {
        if (!cells_[c])
        {
            cells_[c] = true;
            flagged_.append(c);
            added = true;
        }
    }
    if (!returnReduce(added, orOp<bool>()))
    {
        return false;
    }

    // Every face of a flagged cell, also across processor boundaries
    boolList nbrCells;
    syncTools::swapBoundaryCellList(mesh_, cells_, nbrCells);

    const labelUList& own = mesh_.faceOwner();
    const labelUList& nei = mesh_.faceNeighbour();
    const label nInternal = mesh_.nInternalFaces();
    nFaces_ = 0;
    forAll(faces_, facei)
    {
        faces_[facei] =
            cells_[own[facei]]
         || (
                facei < nInternal
              ? cells_[nei[facei]]
              : nbrCells[facei - nInternal]
            );
        if (faces_[facei]) ++nFaces_;
    }
    return true;
}


void Foam::firstOrderFallback::countStep
(
    const scalar nCellsAll,
    const scalar nFacesAll
)
{
    cellSteps_ += mesh_.nCells();
    faceSteps_ += mesh_.nFaces();
    if (nCellsAll > 0)
    {
        fallbackCellSteps_ += flagged_.size();
        fallbackFaceSteps_ += nFaces_;
        Info<< "    fallback: " << nCellsAll << " cells, " << nFacesAll
            << " faces at first order (HLL)" << nl;
    }
}


void Foam::firstOrderFallback::updateMesh()
{
    // (the same lists: the reconstruction holds cells_)
    cells_.setSize(mesh_.nCells());
    cells_ = false;
    faces_.setSize(mesh_.nFaces());
    faces_ = false;
    flagged_.clear();
    nFaces_ = 0;
}


void Foam::firstOrderFallback::report() const
{
    const scalar cells = returnReduce(cellSteps_, sumOp<scalar>());
    const scalar faces = returnReduce(faceSteps_, sumOp<scalar>());
    const scalar fbCells = returnReduce(fallbackCellSteps_, sumOp<scalar>());
    const scalar fbFaces = returnReduce(fallbackFaceSteps_, sumOp<scalar>());
    Info<< "Fallback to first order: " << fbCells << " of " << cells
        << " cell updates (" << (cells > 0 ? fbCells/cells : 0) << "), "
        << fbFaces << " of " << faces << " face updates ("
        << (faces > 0 ? fbFaces/faces : 0) << ")" << nl;
}


// ************************************************************************* //
