#include "stepControl.H"
#include "stepLedger.H"
#include "landingDeltaT.H"
#include "inputDefaults.H"

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::stepControl::stepControl
(
    Time& runTime,
    phaseSystem& phases,
    demSolver& dem,
    mechanicalRelaxation& relaxation,
    const bodyForces& forces
)
:
    runTime_(runTime),
    phases_(phases),
    dem_(dem),
    relaxation_(relaxation),
    forces_(forces),
    maxCo_
    (
        // Default: 0.6 at second order, 0.4 at first (0.8 of its limit
        // 0.5); docs/numerics.md 6.1
        inputDefaults::get<scalar>
        (
            runTime.controlDict(), "maxCo",
            min(scalar(0.6), 0.8*dem.maxCourant()), "controlDict"
        )
    ),
    maxDeltaT_
    (
        inputDefaults::get<scalar>
        (
            runTime.controlDict(), "maxDeltaT", GREAT, "controlDict"
        )
    ),
    dtFactor_(1),
    minDtFactor_
    (
        inputDefaults::get<scalar>
        (
            runTime.controlDict(), "minDeltaTFactor", 1.0/64, "controlDict"
        )
    ),
    debugDeltaT_
    (
        inputDefaults::get<bool>
        (
            runTime.controlDict(), "debugDeltaT", false, "controlDict"
        )
    ),
    pendingWrite_(-1),
    oldTime_(runTime.value()),
    oldIndex_(runTime.timeIndex()),
    dtStable_(GREAT),
    refinement_(nullptr)
{
    if (!(maxCo_ > 0 && maxCo_ <= 1))
    {
        FatalIOErrorInFunction(runTime.controlDict())
            << "maxCo = " << maxCo_ << " must be in (0, 1]"
            << exit(FatalIOError);
    }
    if (maxCo_ > dem.maxCourant())
    {
        // The first-order scheme (discreteEquations order 1) is stable up
        // to 0.5 (docs/numerics.md 6.1); the tutorials' 0.6 is for the
        // second-order scheme
        WarningInFunction
            << "maxCo " << maxCo_ << " in " << runTime.controlDict().name()
            << " is above " << dem.maxCourant() << ", the stability limit"
            << " of this scheme (discreteEquations order): the time step"
            << " uses " << dem.maxCourant() << endl;
        maxCo_ = dem.maxCourant();
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::scalar Foam::stepControl::advance()
{
    dtStable_ = dem_.stableDeltaT();
    scalar dt = min(dtFactor_*maxCo_*dtStable_, maxDeltaT_);

    // Land exactly on the next write time (adjustable write control) and
    // on endTime, with steps no longer than the stable one
    dt = landingDeltaT(runTime_, dt);
    runTime_.setDeltaT(dt, false);
    dt = runTime_.deltaTValue();

    oldTime_ = runTime_.value();
    oldIndex_ = runTime_.timeIndex();

    // Keep the state of the last good step, to write it if this one fails
    phases_.saveState();

    ++runTime_;

    Info<< "Time = " << runTime_.timeName()
        << "  deltaT = " << dt
        << "  Courant Number max = " << dt/dtStable_ << endl;
    if (debugDeltaT_ && dem_.limitingCell() >= 0)
    {
        const fvMesh& mesh = phases_.mesh();
        Pout<< "    deltaT limited by cell " << dem_.limitingCell()
            << " at " << mesh.C()[dem_.limitingCell()]
            << ", wave speed " << dem_.limitingSpeed() << endl;
    }

    return dt;
}


bool Foam::stepControl::take(const scalar dt)
{
    // Cells whose update fails the state checks are taken at first order
    // (their faces with HLL) and the step repeated, before any cut of the
    // time step (docs/numerics.md section 8.3)
    firstOrderFallback& fallback = dem_.fallback();
    fallback.clear();
    mechanicalRelaxation::stateError err;
    bool failed = false;
    for (label round = 0; ; ++round)
    {
        dem_.hyperbolicStep(dt, q_);
        forces_.addSources(dt, q_);
        err = relaxation_.correct(q_, dt);
        failed = returnReduce(err.failed, orOp<bool>());
        if
        (
            !failed
         || round == fallback.maxRounds()
         || !fallback.add(relaxation_.badCells())
        )
        {
            break;
        }
        phases_.restoreState();
    }

    return accept(err, failed);
}


bool Foam::stepControl::accept
(
    const mechanicalRelaxation::stateError& err,
    const bool failedAnywhere
)
{
    if (!failedAnywhere)
    {
        // A good step: let a reduced time step grow back
        dtFactor_ = min(2*dtFactor_, scalar(1));
        return true;
    }

    const fvMesh& mesh = phases_.mesh();
    if (err.failed)
    {
        Perr<< "impactFoam: unphysical state at time " << runTime_.value()
            << ": phase " << phases_.names()[err.phase]
            << ", cell " << err.cell
            << " (centre " << mesh.C()[err.cell] << "): "
            << err.quantity << " = " << err.value << endl;
    }

    const scalar failedTime = runTime_.value();

    if (dtFactor_ > minDtFactor_)
    {
        // Retry the step with half the time step. A rejected step to a
        // write time has used up OpenFOAM's write index for it: the write
        // is made when the retries reach that time
        if (runTime_.writeTime())
        {
            pendingWrite_ = runTime_.value();
        }
        phases_.restoreState();
        runTime_.setTime(oldTime_, oldIndex_);
        dtFactor_ *= 0.5;
        Info<< "    Step rejected; retrying with " << dtFactor_
            << " of the stable time step" << endl;
        return false;
    }

    phases_.restoreState();
    runTime_.setTime(oldTime_, oldIndex_);
    writeTime(true);

    // Every processor has written before any of them stops the run (a
    // fatal error on one aborts the others, mid-write)
    returnReduce(true, andOp<bool>());

    OStringStream where;
    if (err.failed)
    {
        where
            << " in phase " << phases_.names()[err.phase]
            << ", cell " << err.cell << ": "
            << err.quantity << " = " << err.value;
    }
    else
    {
        where << " on another processor";
    }

    FatalErrorInFunction
        << "Unphysical state at time " << failedTime << where.str().c_str()
        << nl << "    The last good fields were written at time "
        << runTime_.timeName()
        << (err.failed ? advice(err).c_str() : "") << exit(FatalError);

    return false;
}


std::string Foam::stepControl::advice
(
    const mechanicalRelaxation::stateError& err
) const
{
    const phaseModel& phase = phases_[err.phase];
    const word& name = phases_.names()[err.phase];
    const bool solid = phase.law().solid();
    OStringStream os;
    os  << nl << "    The state of every phase in that cell at that time is in"
        << " the written fields (alpha.<phase>, rho.<phase>, p.<phase>, U)."
        << nl << "    What may help:";
    if (solid && err.quantity == "p" && err.value < 0)
    {
        if (!phase.inelastic().limitsTension())
        {
            os  << nl << "    - phase " << name << " holds any tension: give it"
                << " a failure model (failure { type spall; sigmaSpall ...; }"
                << " in its material or in impactDict's phaseProperties,"
                << " docs/model.md section 11)";
        }
        os  << nl << "    - a finer mesh where the bodies meet (impactDict's"
            << " cellSize, or ./Allrun -h): the tension comes from cells"
            << " that mix " << name << " with another material";
    }
    else if (err.quantity.find("rhoMax") != std::string::npos)
    {
        os  << nl << "    - a smaller maxCo in system/controlDict (0.3): "
            << name << " was compressed beyond the pole of its equation of"
            << " state within one step";
    }
    else if (err.quantity.find("interface pressure") != std::string::npos)
    {
        os  << nl << "    - a finer mesh where the bodies meet: the phases of"
            << " that cell could not be brought to one pressure";
    }
    else
    {
        os  << nl << "    - a smaller maxCo in system/controlDict (0.3)";
    }
    os  << nl << "    - fallbackRounds (discreteEquations in system/fvSchemes,"
        << " default 3) and minDeltaTFactor (system/controlDict, default"
        << " 1/64): more first-order rounds and retries before the run"
        << " stops (docs/numerics.md section 8.3)";
    return std::string(os.str());
}


bool Foam::stepControl::outputsReadEveryStep() const
{
    const functionObjectList& functions = runTime_.functionObjects();
    if (functions.empty())
    {
        return false;
    }
    if (runTime_.runTimeModifiable())
    {
        // The list may be read again, a name kept for another type
        return true;
    }
    const stepLedger& ledger =
        phases_.mesh().lookupObject<stepLedger>(stepLedger::typeName);
    forAll(functions, i)
    {
        if (!ledger.isHistory(functions[i].name()))
        {
            return true;
        }
    }
    return false;
}


void Foam::stepControl::write()
{
    const bool pendingNow =
        pendingWrite_ > 0
     && runTime_.value() >= pendingWrite_ - 1e-6*runTime_.deltaTValue();

    // The output mixture fields (p, sigma, sigmaEq) when they are written,
    // and every step if function objects may read them
    if (runTime_.writeTime() || pendingNow || outputsReadEveryStep())
    {
        phases_.correctOutputs();
    }

    writeTime(false);
    if (pendingNow)
    {
        if (!runTime_.writeTime())
        {
            writeTime(true);
        }
        pendingWrite_ = -1;
    }
}


void Foam::stepControl::writeTime(const bool now)
{
    if (refinement_)
    {
        refinement_->setInstance();
    }
    if (now)
    {
        runTime_.writeNow();
    }
    else
    {
        runTime_.write();
    }
    if (refinement_)
    {
        refinement_->write();
    }
}


void Foam::stepControl::updateMesh()
{
    q_ = conservedState();
}
