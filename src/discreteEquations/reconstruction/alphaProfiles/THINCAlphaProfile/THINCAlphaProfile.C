#include "THINCAlphaProfile.H"
#include "inputDefaults.H"
#include "foamEigen.H"
#include "readOption.H"
#include "keywordCheck.H"
#include "addToRunTimeSelectionTable.H"

using Foam::foamEigen::toEigen;

namespace Foam
{
    defineTypeNameAndDebug(THINCAlphaProfile, 0);
    addToRunTimeSelectionTable(alphaProfile, THINCAlphaProfile, dictionary);
}

namespace
{
    // discreteEquations THINCCoeffs range
    enum class profileRange { neighbours, full };
    const Foam::Enum<profileRange> profileRangeNames
    ({
        {profileRange::neighbours, "neighbours"},
        {profileRange::full, "full"}
    });
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::THINCAlphaProfile::THINCAlphaProfile
(
    const phaseSystem& phases,
    const dictionary& dict
)
:
    alphaProfile(phases, true),
    fullRange_(readRange(dict)),
    thinc_(readBeta(dict)),
    profiles_(phases.size()),
    slot_(phases.size(), labelList(mesh_.nCells(), -1))
{
    if (dict.isDict("THINCCoeffs"))
    {
        checkKeywords
        (
            dict.subDict("THINCCoeffs"),
            {"range", "beta"},
            "discreteEquations THINCCoeffs"
        );
    }
}


Foam::wordList Foam::THINCAlphaProfile::keywords() const
{
    wordList valid(alphaProfile::keywords());
    valid.append("THINCCoeffs");
    return valid;
}


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

bool Foam::THINCAlphaProfile::readRange(const dictionary& dict)
{
    const scalar compression = readCompression(dict);
    if (compression != 1)
    {
        FatalIOErrorInFunction(dict)
            << "discreteEquations: alphaCompression " << compression
            << " steepens linear volume fraction slopes; with"
            << " alphaReconstruction THINC leave it out (or 1)"
            << exit(FatalIOError);
    }

    return
        readOption
        (
            dict.optionalSubDict("THINCCoeffs"),
            "range",
            profileRangeNames,
            profileRange::neighbours,
            "discreteEquations THINCCoeffs"
        )
     == profileRange::full;
}


Foam::scalar Foam::THINCAlphaProfile::readBeta(const dictionary& dict)
{
    const scalar beta =
        inputDefaults::get<scalar>
        (
            dict.optionalSubDict("THINCCoeffs"),
            "beta",
            2.5,
            "discreteEquations THINCCoeffs"
        );
    if (!(beta >= 0.5 && beta <= 10))
    {
        FatalIOErrorInFunction(dict)
            << "discreteEquations THINCCoeffs beta " << beta
            << " is not in [0.5, 10]" << exit(FatalIOError);
    }
    return beta;
}


void Foam::THINCAlphaProfile::extentAlong
(
    const labelUList& pointLabels,
    const vector& n,
    scalar& lo,
    scalar& hi
) const
{
    const pointField& pts = mesh_.points();
    lo = GREAT;
    hi = -GREAT;
    for (const label pi : pointLabels)
    {
        const scalar x = n & pts[pi];
        lo = min(lo, x);
        hi = max(hi, x);
    }
}


// * * * * * * * * * * * * Protected Member Functions  * * * * * * * * * * * //

bool Foam::THINCAlphaProfile::setInterface
(
    const label k,
    const label c,
    const scalar alpha,
    const scalar aMin,
    const scalar aMax,
    const vector& g,
    const vector& U,
    const scalar halfDt,
    alphaSlope& s
)
{
    const scalar aRange = aMax - aMin;
    const scalar magG = mag(g);
    if
    (
        phases_.regimes().thin(alpha)
     || aRange < phases_.regimes().alphaMinor()
     || magG < VSMALL
    )
    {
        return false;
    }
    // Normalised value: an interface cell lies strictly within the range
    const scalar aBar = (alpha - aMin)/aRange;
    if (!(aBar > 1e-4 && aBar < 1 - 1e-4))
    {
        return false;
    }

    const vector n(g/magG);
    scalar lo, hi;
    // Over the points of the cell's faces (a point shared by faces is
    // seen again: min and max do not mind). The mesh's cellPoints would
    // build its point-cell addressing for the whole mesh, 110-160 bytes
    // per cell kept for the run, for the few interface cells
    lo = GREAT;
    hi = -GREAT;
    for (const label facei : mesh_.cells()[c])
    {
        scalar fLo, fHi;
        extentAlong(mesh_.faces()[facei], n, fLo, fHi);
        lo = min(lo, fLo);
        hi = max(hi, fHi);
    }

    slot_[k][c] = profiles_[k].size();
    profiles_[k].emplace_back();
    profile& pr = profiles_[k].back();
    pr.nAlpha = toEigen(n);
    pr.xLow = lo;
    pr.h = hi - lo;
    pr.xiShift = (U & n)*halfDt/pr.h;
    if (fullRange_)
    {
        // The whole step from 0 to 1 (Xiao et al.'s profile): the cell
        // mean alone places the jump
        pr.xiJ = thinc_.jump(min(max(alpha, 1e-4), 1 - 1e-4));
        pr.aLow = 0;
        pr.aRange = 1;
    }
    else
    {
        pr.xiJ = thinc_.jump(aBar);
        pr.aLow = aMin;
        pr.aRange = aRange;
    }

    // The time-centred cell value: the mean of the profile moved by half
    // a step
    s.dt =
        pr.aLow + pr.aRange*thinc_.mean(-pr.xiShift, 1 - pr.xiShift, pr.xiJ)
      - alpha;

    return true;
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::THINCAlphaProfile::beginPhase(const label k)
{
    // The storage is kept from step to step: clear keeps the capacity
    profiles_[k].clear();
}


Foam::scalar Foam::THINCAlphaProfile::profileFaceAlpha
(
    const label k,
    const label c,
    const label facei,
    const vector& d
) const
{
    const profile& pr = profiles_[k][slot_[k][c]];

    // The face's spread along n from its points, its centre from d (on a
    // wedge face d is the centre turned into the cell's plane)
    const vector n(pr.nAlpha(0), pr.nAlpha(1), pr.nAlpha(2));
    scalar lo, hi;
    extentAlong(mesh_.faces()[facei], n, lo, hi);
    const scalar xiC =
        ((n & (mesh_.cellCentres()[c] + d)) - pr.xLow)/pr.h - pr.xiShift;
    const scalar halfW = 0.5*(hi - lo)/pr.h;
    return
        pr.aLow
      + pr.aRange*thinc_.mean(xiC - halfW, xiC + halfW, pr.xiJ);
}


void Foam::THINCAlphaProfile::describe(Ostream& os) const
{
    os  << ", THINC volume fractions (beta " << thinc_.beta()
        << (fullRange_ ? ", range full" : ", range neighbours")
        << ")";
}


// ************************************************************************* //
