#include "mechanicalRelaxation.H"
#include "alphaClosure.H"
#include "foamEigen.H"

#include <cmath>

using Foam::foamEigen::toTensor;


Foam::mechanicalRelaxation::mechanicalRelaxation(phaseSystem& phases)
:
    phases_(phases),
    nPhases_(phases.size()),
    rhoRef_(nPhases_),
    rhoCompressed_(nPhases_),
    rhoVacuum_(nPhases_, 0),
    cell_(nPhases_),
    pressure_(phases),
    ledger_(phases.mesh().V()),
    checks_(),
    uSlide_(nPhases_),
    slideHeat_(nPhases_, 0)
{
    for (label k = 0; k < nPhases_; ++k)
    {
        // A metal at twice its reference density is beyond any state of
        // the impacts the code is for (copper on copper at 6 km/s: 1.6 rho0
        // on its Hugoniot). A minor phase or a trace there is what the
        // transport left (copper at 3 rho0, beside the pole of its
        // Hugoniot, as a trace in an air cell next to an oblique impact):
        // in the internal contacts of the next step its pressure, 1e13 Pa
        // for a per-cent change of density, handed 2.7e8 J/m^3 to the
        // steel beside it
        const equationOfState& eos = phases_.phase(k).eos();
        rhoRef_[k] = eos.referenceDensity();
        rhoCompressed_[k] =
            rhoRef_[k] > 0 ? min(2*rhoRef_[k], eos.rhoMax()) : eos.rhoMax();
        if (rhoRef_[k] > 0)
        {
            cell_.vMax[k] = 2/rhoRef_[k];
        }

        // A gas at the edge of a vacuum (behind a body faster than its
        // escape speed, or among debris) holds next to no mass, and its
        // specific energy, a small difference of large numbers, can take
        // any value: air at 2e-12 kg/m^3 and 300 Pa (the library copper
        // at 6 km/s, 25 us) has a sound speed of 1.5e7 m/s, and the time
        // step collapsed. Below the density at which its reference
        // isentrope falls to the floor pMin + pVacuum (3.3e-4 kg/m^3 for
        // air from 1.2 kg/m^3 and 1e5 Pa) it is held at most on that
        // isentrope, where its sound speed falls with its density
        const Pair<scalar>& ref = phases_.referenceIsentrope(k);
        if (phases_.regimes().vacuumFloor() && ref.first() > 0)
        {
            const scalar pFloor =
                eos.pMin(ref.first()) + phases_.regimes().pVacuum();
            if (pFloor > eos.pIsentropicMin(ref.first(), ref.second()))
            {
                rhoVacuum_[k] =
                    1/eos.vIsentropic(pFloor, ref.first(), ref.second());
            }
        }
    }
}


void Foam::mechanicalRelaxation::relaxVelocity
(
    const label c,
    conservedState& q,
    const cobasis::vector& u,
    const scalar dt
)
{
    const bool slid = slideVelocities(c, q, u, dt);
    for (label k = 0; k < nPhases_; ++k)
    {
        const hyperelasticPhase& ph = phases_.phase(k);
        cell_.v[k] = cell_.alpha[k]/cell_.m[k];

        // A solid trace is reset unstrained by relaxTraces, which pays the
        // change of its whole energy: its cobasis is not made compatible
        // and no elastic energy is split off here (the same payment up to
        // round-off)
        const bool reset = ph.solid() && cell_.trace[k];
        cell_.ee[k] = 0;
        if (ph.solid() && !reset)
        {
            cobasis::matrix& A = q.A[k][c];
            const scalar detA = A.determinant();
            if (!(detA > 0))
            {
                // A minor solid's cobasis that the transport inverted is
                // reset (its elastic energy, if any, becomes heat)
                if (!cell_.trace[k] && !phases_.regimes().thin(cell_.alpha[k]))
                {
                    checks_.fail(c, k, "det(A)", detA);
                }
                A = cobasis::unstrained(1/cell_.v[k], ph.rho0());
            }
            else
            {
                A *= std::cbrt(1/(cell_.v[k]*ph.rho0()*detA));
            }
            cell_.ee[k] = ph.elasticEnergy(A);
        }
        // Own kinetic energy out, the share of the dissipated kinetic
        // energy 1/2 |u_k - u|^2 in: e_k never decreases
        const cobasis::vector uk(q.momentum[k][c]/cell_.m[k]);
        if (slid)
        {
            cell_.e[k] =
                q.energy[k][c]/cell_.m[k] - 0.5*uk.squaredNorm()
              + slideHeat_[k] - cell_.ee[k];
        }
        else
        {
            cell_.e[k] =
                q.energy[k][c]/cell_.m[k] - 0.5*uk.squaredNorm()
              + 0.5*(uk - u).squaredNorm() - cell_.ee[k];
        }

        // The slip velocity kept (phaseModel::slip; the relaxation's
        // store writes it with the other carried variables)
        const label iSlip = phases_[k].slipIndex();
        if (iSlip >= 0)
        {
            for (int d = 0; d < 3; ++d)
            {
                q.carried[k][iSlip + d][c] = slid ? uSlide_[k](d) - u(d) : 0;
            }
        }
    }
}


Foam::label Foam::mechanicalRelaxation::countActive()
{
    cell_.nActive = 0;
    cell_.traceVolume = 0;
    for (label k = 0; k < nPhases_; ++k)
    {
        if (cell_.trace[k]) cell_.traceVolume += cell_.alpha[k];
        else ++cell_.nActive;
    }
    return cell_.nActive;
}


bool Foam::mechanicalRelaxation::relaxPressures
(
    const label c,
    conservedState& q,
    const label main,
    scalar& pStar
)
{
    if (countActive() > 1)
    {
        if (!pressure_.relax(cell_, q, c, pStar))
        {
            checks_.fail(c, main, "interface pressure (no convergence)", pStar);
            return false;
        }
    }
    else
    {
        pStar = phases_.phase(main).eos().p(1/cell_.v[main], cell_.e[main]);
    }
    return true;
}


void Foam::mechanicalRelaxation::checkAndStore
(
    const label c,
    const conservedState& q,
    const cobasis::vector& u
)
{
    phases_.U()[c] = vector(u(0), u(1), u(2));
    for (label k = 0; k < nPhases_; ++k)
    {
        const hyperelasticPhase& ph = phases_.phase(k);
        const scalar rho = 1/cell_.v[k];

        // No pressure outside the density range (a Mie-Grueneisen phase
        // beyond rhoMax gives NaN, and comparing a NaN traps under
        // FOAM_SIGFPE): the phase fails on rho and keeps its last
        // pressure (the step is retried or stopped). A trace there has
        // already failed (relaxTraces)
        const bool inRange = rho > 0 && rho < ph.eos().rhoMax();
        const scalar p =
            inRange ? ph.eos().p(rho, cell_.e[k]) : phases_.p(k)[c];

        if (!cell_.trace[k])
        {
            if (!(rho > 0)) checks_.fail(c, k, "rho", rho);
            if (!(rho < ph.eos().rhoMax())) checks_.fail(c, k, "rho>=rhoMax", rho);
            if (inRange && !(std::isfinite(p) && p > ph.eos().pMin(rho)))
            {
                checks_.fail(c, k, "p", p);
            }
            if (!(cell_.alpha[k] <= 1)) checks_.fail(c, k, "alpha", cell_.alpha[k]);
            if (ph.solid() && !(q.A[k][c].determinant() > 0))
            {
                checks_.fail(c, k, "det(A)", q.A[k][c].determinant());
            }
        }

        phases_.alpha(k)[c] = cell_.alpha[k];
        phases_.rho(k)[c] = rho;
        phases_.p(k)[c] = p;
        if (ph.solid())
        {
            phases_.A(k)[c] = toTensor(q.A[k][c]);
        }
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::mechanicalRelaxation::stateError Foam::mechanicalRelaxation::correct
(
    conservedState& q,
    const scalar dt
)
{
    checks_.reset();
    ledger_.reset();

    const label nCells = phases_.mesh().nCells();
    for (label c = 0; c < nCells; ++c)
    {
        // 1. Volume fractions floored, the sum closed by the largest phase;
        //    the masses and the trace phases
        const label main = floorVolumeFractions(c, q);
        cobasis::vector mom;
        const scalar mass = collectMasses(c, q, mom);

        // 2. One velocity; the cobasis made compatible with the density
        const cobasis::vector u(mom/mass);
        relaxVelocity(c, q, u, dt);

        // A minor metal below its lowest density compacted to it, the
        // volume exchanged with the main phase at its pressure
        compactMetals(c, q, main);

        // A minor phase whose energy the step left inadmissible is reset
        // as a trace, a torn gas floored (pVacuum); any other phase fails
        screenEnergies(c, mass);
        if (checks_.failed(c))
        {
            continue;
        }

        // Failed material: no shear stress; in tension, the fluids of the
        // cell take part in the pressure relaxation
        relaxFailed(c, q, dt);

        // 3. Pressure relaxation among the phases that are not traces
        scalar pStar;
        if (!relaxPressures(c, q, main, pStar))
        {
            continue;
        }

        // 4. Traces follow the cell: pressure p*, unstrained cobasis
        relaxTraces(c, q, main, pStar);

        // 5. Plastic relaxation. Its heat raises the pressure of the
        //    solid; in a mixed cell the pressures are relaxed once more, or
        //    the next step would start out of equilibrium and the solid
        //    would push the heat into its neighbours (a light gas next to
        //    a yielding metal took it all and reached 1e5 K)
        const bool heated = relaxPlastic(c, q, dt);
        if (heated && countActive() > 1)
        {
            // The traces' reset (4) is paid by the heaviest active phase:
            // a nearly empty gas that pays it (air in a crater, cold from
            // expanding, next to a dense metal trace) can be left below
            // its floor, and the relaxation needs admissible phases
            vacuumAfterRelaxation(c);
            if (!pressure_.relax(cell_, q, c, pStar))
            {
                checks_.fail(c, main, "interface pressure (no convergence)", pStar);
                continue;
            }
        }

        // A fluid that the pressure relaxation took to the edge of its
        // admissible range (a gas opened up by a solid in tension: p* at
        // pMin to round-off)
        vacuumAfterRelaxation(c);

        // 6. Checks; the phase fields
        checkAndStore(c, q, u);
    }

    return checks_.first();
}


void Foam::mechanicalRelaxation::updateMesh()
{
    ledger_.updateMesh(phases_.mesh().V());
    checks_.reset();
}
