/*---------------------------------------------------------------------------*\
  impactFoam: Eulerian multiphase elastic-plastic impact solver for OpenFOAM
-------------------------------------------------------------------------------
Description
    mechanicalRelaxation: the solids' inelastic mechanics in the relaxation
    (each phase's inelasticModel): the tensile cutoff and failed material
    before the pressure relaxation, the plastic return after it.
\*---------------------------------------------------------------------------*/

#include "mechanicalRelaxation.H"

// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

void Foam::mechanicalRelaxation::removeShear
(
    const label c,
    conservedState& q,
    const label k
)
{
    const hyperelasticPhase& ph = phases_.phase(k);
    cobasis::matrix& A = q.A[k][c];
    const scalar shearEnergy = ph.elasticEnergy(A);
    A = cobasis::unstrained(1/cell_.v[k], ph.rho0());
    cell_.e[k] += shearEnergy;
}


void Foam::mechanicalRelaxation::relaxFailed
(
    const label c,
    conservedState& q,
    const scalar dt
)
{
    bool open = false;
    for (label k = 0; k < nPhases_; ++k)
    {
        const phaseModel& phase = phases_[k];
        const inelasticModel& inelastic = phase.inelastic();
        cell_.failed[k] = false;
        cell_.held[k] = false;
        cell_.pinned[k] = false;
        if (!inelastic.limitsTension() || cell_.trace[k])
        {
            // A trace's state is the cell's business (relaxTraces)
            continue;
        }

        // The tensile cutoff of the step, and the floor it leaves
        const label nI = phase.nInelastic();
        scalar carried[phaseModel::maxCarried];
        for (label i = 0; i < nI; ++i)
        {
            carried[i] = q.carried[k][i][c];
        }
        const scalar pk = phase.eos().p(1/cell_.v[k], cell_.e[k]);
        const scalar floor = inelastic.tension(carried, pk, dt);
        for (label i = 0; i < nI; ++i)
        {
            q.carried[k][i][c] = carried[i];
        }
        if (!(floor > -GREAT))
        {
            continue;
        }
        cell_.held[k] = true;
        cell_.pHeld[k] = floor;

        const bool failed = inelastic.failed(carried);
        if (failed)
        {
            // No deviatoric stress: the shear energy becomes heat
            cell_.failed[k] = true;
            removeShear(c, q, k);
        }

        // Failing (over spallTime) and in tension, it holds its own state
        // down to -sigmaSpall: fluids that the opening let into the cell
        // take no tension from it before it has failed
        cell_.pinned[k] = !failed && pk < 0;

        // In tension below its floor (the whole solid, or a trace of it
        // next to a fluid) it opens up: the fluids of the cell take the
        // volume
        open = open || pk < floor || cell_.pinned[k];
    }
    if (open)
    {
        openUp(c);
    }
}


void Foam::mechanicalRelaxation::openUp(const label c)
{
    // Every fluid with mass takes part; a failed solid that is only a
    // trace stays one. A fluid the step left at the edge of its range (a
    // gas torn open in the gap) is floored first (pVacuum), or else stays
    // a trace
    bool fluid = false;
    for (label k = 0; k < nPhases_; ++k)
    {
        if (phases_.phase(k).solid() || !(cell_.m[k] > 0) || !cell_.trace[k])
        {
            fluid = fluid || (!phases_.phase(k).solid() && !cell_.trace[k]);
            continue;
        }
        const equationOfState& eos = phases_.phase(k).eos();
        const scalar rho = 1/cell_.v[k];
        if (!(eos.p(rho, cell_.e[k]) > eos.pMin(rho)))
        {
            if (!phases_.regimes().vacuumFloor())
            {
                continue;
            }
            cell_.trace[k] = false;
            vacuumFloor(c, k);
        }
        cell_.trace[k] = false;
        fluid = true;
    }
    if (!fluid)
    {
        // Nothing can take the volume: the damaged material keeps its
        // tension (a case without a fluid phase). A solid of the cell
        // that is not held would otherwise be stretched to fill whatever
        // volume the held one gives up (an aluminium sliver of 1e-6 of
        // the cell taken to 4 % of its density and -1e15 Pa)
        for (label k = 0; k < nPhases_; ++k)
        {
            cell_.held[k] = false;
            cell_.pinned[k] = false;
        }
    }
}


bool Foam::mechanicalRelaxation::relaxPlastic
(
    const label c,
    conservedState& q,
    const scalar dt
)
{
    bool heated = false;
    bool open = false;
    for (label k = 0; k < nPhases_; ++k)
    {
        phaseModel& phase = phases_[k];
        const hyperelasticPhase& ph = phase.law();
        for (label i = 0; i < phase.nCarried(); ++i)
        {
            phase.carried(i)[c] = q.carried[k][i][c];
        }
        if (ph.solid() && !cell_.trace[k] && !cell_.failed[k])
        {
            // The plastic return, its heat and the damage it does
            // (inelasticModel), on the phase's fields of this cell
            const inelasticModel& inelastic = phase.inelastic();
            const label nI = phase.nInelastic();
            scalar carried[phaseModel::maxCarried];
            phase.inelasticState(c, carried);
            const scalar heat =
                inelastic.relax(q.A[k][c], carried, 1/cell_.v[k], cell_.e[k], dt);
            for (label i = 0; i < nI; ++i)
            {
                phase.carried(i)[c] = carried[i];
            }
            heated = heated || heat > 0;
            if (inelastic.failed(carried))
            {
                removeShear(c, q, k);
                cell_.failed[k] = true;
                cell_.held[k] = true;
                cell_.pHeld[k] = inelastic.pFloor(carried);
                heated = true;
                open =
                    open
                 || ph.eos().p(1/cell_.v[k], cell_.e[k]) < cell_.pHeld[k];
            }
        }
    }
    if (open)
    {
        // Material that failed in this step while in tension opens up as
        // in relaxFailed: the fluids of the cell take the volume it gives
        // up, or, with none, it keeps its tension
        openUp(c);
    }
    return heated;
}


// ************************************************************************* //
