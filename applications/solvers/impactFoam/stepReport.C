#include "stepReport.H"
#include "OStringStream.H"
#include "wedgeRevolution.H"

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::stepReport::stepReport
(
    const phaseSystem& phases,
    const mechanicalRelaxation& relaxation,
    demSolver& dem,
    const voidVelocity& voidCells
)
:
    phases_(phases),
    relaxation_(relaxation),
    dem_(dem),
    voidCells_(voidCells),
    unpaidTotal_(0),
    frictionTotal_(0),
    ledger_(phases)
{
    // A restarted run carries on the tallies of the run before it
    unpaidTotal_ = ledger_.unpaidEnergy();
    frictionTotal_ = ledger_.frictionalHeat();
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::stepReport::counts::reduce()
{
    List<scalar> all(9);
    all[0] = vacuumCells;
    all[1] = unpaidCells;
    all[2] = unpaidEnergy;
    all[3] = fallbackCells;
    all[4] = fallbackFaces;
    all[5] = voidCells;
    all[6] = voidEnergy;
    all[7] = untransportedCells;
    all[8] = frictionalHeat;
    Pstream::listCombineGather(all, plusEqOp<scalar>());
    Pstream::listCombineScatter(all);
    vacuumCells = all[0];
    unpaidCells = all[1];
    unpaidEnergy = all[2];
    fallbackCells = all[3];
    fallbackFaces = all[4];
    voidCells = all[5];
    voidEnergy = all[6];
    untransportedCells = all[7];
    frictionalHeat = all[8];
}


void Foam::stepReport::step(const scalar deltaT)
{
    counts n;
    n.vacuumCells = relaxation_.nVacuum();
    n.unpaidCells = relaxation_.nUnpaid();
    n.unpaidEnergy = relaxation_.unpaidEnergy();
    n.fallbackCells = dem_.fallback().nCells();
    n.fallbackFaces = dem_.fallback().nFaces();
    n.voidCells = voidCells_.nCells();
    n.voidEnergy = voidCells_.energy();
    n.untransportedCells = dem_.cobasis().missedCells();
    n.frictionalHeat = relaxation_.frictionalHeat();
    n.reduce();
    frictionTotal_ += n.frictionalHeat;

    dem_.fallback().countStep(n.fallbackCells, n.fallbackFaces);
    if (n.vacuumCells > 0)
    {
        Info<< "    vacuum floor (pVacuum) in " << n.vacuumCells << " cells"
            << nl;
    }
    if (n.untransportedCells > 0)
    {
        Info<< "    cobasis not transported (a solid arrived without sums) in "
            << n.untransportedCells << " cells" << nl;
    }
    if (n.unpaidCells > 0)
    {
        unpaidTotal_ += n.unpaidEnergy;
        Info<< "    set without a payer (vacuum floor, trace reset) in "
            << n.unpaidCells << " cells: energy added " << n.unpaidEnergy
            << " J" << nl;
    }
    if (n.voidCells > 0)
    {
        unpaidTotal_ += n.voidEnergy;
        Info<< "    void cells: velocity held in " << n.voidCells
            << " cells: energy added " << n.voidEnergy << " J" << nl;
    }

    ledger_.accept(deltaT, dem_.patchForces(), unpaidTotal_, frictionTotal_);
}


void Foam::stepReport::logTotals(const bool initial) const
{
    const Pair<scalar> totals(phases_.totals());
    OStringStream os;
    os.precision(15);
    if (initial)
    {
        os  << "Initial totals: mass " << totals.first() << " kg, energy "
            << totals.second() << " J";
        vector axis;
        const scalar toFull = wedgeToFull(phases_.mesh(), axis);
        if (toFull > 0)
        {
            os  << nl << "    (this log's masses and energies are the "
                << "wedge's; the full body of revolution, as in the time "
                << "histories and the summary, is " << toFull
                << " times them)";
        }
    }
    else
    {
        os  << "    totals: mass " << totals.first() << " kg, energy "
            << totals.second() << " J, energy added without a payer "
            << unpaidTotal_ << " J";
        if (phases_.sliding())
        {
            os  << ", heat of friction between sliding solids "
                << frictionTotal_ << " J";
        }
    }
    Info<< os.str().c_str() << nl;
}


// ************************************************************************* //
