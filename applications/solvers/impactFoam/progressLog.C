#include "progressLog.H"
#include "inputDefaults.H"
#include "wedgeRevolution.H"
#include "historySummary.H"
#include "OStringStream.H"
#include "OSspecific.H"

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::progressLog::progressLog
(
    const Time& runTime,
    const phaseSystem& phases
)
:
    runTime_(runTime),
    phases_(phases),
    interval_
    (
        inputDefaults::get<scalar>
        (
            runTime.controlDict(), "progressInterval", 10, "controlDict"
        )
    ),
    clock_(),
    lastLine_(0),
    startTime_(runTime.value()),
    startIndex_(runTime.timeIndex()),
    kinetic0_(kineticEnergy())
{
    if (interval_ < 0)
    {
        FatalIOErrorInFunction(runTime.controlDict())
            << "progressInterval " << interval_ << " in "
            << runTime.controlDict().name() << ": give the wall-clock"
            << " seconds between progress lines, or 0 for none"
            << exit(FatalIOError);
    }
}


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

Foam::scalar Foam::progressLog::kineticEnergy() const
{
    scalar K = 0;
    forAll(phases_, k)
    {
        scalar mass, kinetic;
        vector momentum;
        phases_.phaseMotion(k, mass, momentum, kinetic);
        K += kinetic;
    }
    return K;
}


Foam::string Foam::progressLog::micro(const scalar t)
{
    OStringStream os;
    os.precision(3);
    os << t*1e6 << " us";
    return os.str();
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::progressLog::step()
{
    const scalar wall = clock_.elapsedTime();
    if (interval_ <= 0 || wall - lastLine_ < interval_)
    {
        return;
    }
    lastLine_ = wall;

    const scalar t = runTime_.value();
    const scalar tEnd = runTime_.endTime().value();
    const label steps = runTime_.timeIndex() - startIndex_;
    const scalar done = (t - startTime_)/max(tEnd - startTime_, VSMALL);
    const scalar rate = (t - startTime_)/max(wall, VSMALL);

    OStringStream os;
    os.precision(3);
    os  << "Progress: t = " << micro(t).c_str() << ", "
        << label(100*min(done, 1.0)) << " % of " << micro(tEnd).c_str()
        << "; " << steps << " steps, " << steps/max(wall, VSMALL)
        << " steps/s; " << wall << " s elapsed";
    if (rate > 0)
    {
        os  << ", about " << max(tEnd - t, 0.0)/rate << " s left";
    }
    Info<< os.str().c_str() << endl;
}


void Foam::progressLog::summary(const scalar unpaid) const
{
    const fvMesh& mesh = phases_.mesh();
    vector axis;
    const scalar toFull = wedgeToFull(mesh, axis);
    const scalar factor = toFull > 0 ? toFull : 1;

    const label n = phases_.size();
    List<scalar> mass(n, Zero);
    List<vector> momentum(n, Zero);
    forAll(phases_, k)
    {
        scalar kinetic;
        phases_.phaseMotion(k, mass[k], momentum[k], kinetic);
    }

    OStringStream os;
    os.precision(6);
    os  << nl << "Summary at t = " << runTime_.value() << " s ("
        << runTime_.timeIndex() - startIndex_ << " steps, "
        << clock_.elapsedTime() << " s)"
        << (toFull > 0 ? "; the full body of revolution" : "") << nl;
    forAll(phases_, k)
    {
        vector p(factor*momentum[k]);
        if (toFull > 0)
        {
            // Around the circle only the axial part is left (+ 0: no
            // negative zero)
            p = (p & axis)*axis + vector::zero;
        }
        const scalar m = factor*mass[k];
        os  << "    " << phases_.names()[k].c_str() << ": mass " << m
            << " kg, momentum " << p << " kg m/s, mean velocity "
            << (m > 0 ? p/m : vector::zero) << " m/s" << nl;
    }
    // (not the totals line's wording, which scripts read: stepReport)
    os  << "    unpaid energy " << factor*unpaid << " J";
    if (kinetic0_ > 0)
    {
        os  << " (" << unpaid/kinetic0_ << " of the initial kinetic energy)";
    }
    os  << nl;

    // The last row of each time history (penetration, residual velocity,
    // impulse: the outputs of impactDict), by their historySummary
    const functionObjectList& functions = runTime_.functionObjects();
    forAll(functions, i)
    {
        const historySummary* history =
            dynamic_cast<const historySummary*>(&functions[i]);
        if (history)
        {
            const string line(history->summaryLine());
            if (!line.empty())
            {
                os  << "    " << line.c_str() << nl;
            }
        }
    }

    // Where the results are (the case's directory, also in parallel)
    const fileName root(runTime_.globalPath());
    const fileName histories(root/"postProcessing");
    os  << "    fields: the time directories of " << root.c_str()
        << (Pstream::parRun() ? " (processor*; reconstructPar)" : "");
    if (isDir(histories))
    {
        os  << nl << "    time histories: " << histories.c_str() << " (";
        const fileNameList dirs(readDir(histories, fileName::DIRECTORY));
        forAll(dirs, i)
        {
            os  << (i ? " " : "") << dirs[i].c_str();
        }
        os  << ")";
    }
    Info<< os.str().c_str() << nl << endl;
}


// ************************************************************************* //
