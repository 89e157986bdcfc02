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
    err_()
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


void Foam::mechanicalRelaxation::vacuumCap(const label c, const label k)
{
    const Pair<scalar>& ref = phases_.referenceIsentrope(k);
    const scalar eIs = phases_.phase(k).eos().eIsentropic
    (
        1/cell_.v[k], ref.first(), ref.second()
    );
    if (cell_.e[k] > eIs)
    {
        ledger_.pay(cell_, c, cell_.heaviestActive(k), cell_.m[k]*(eIs - cell_.e[k]));
        cell_.e[k] = eIs;
        ledger_.countVacuum();
    }
}


bool Foam::mechanicalRelaxation::vacuumFloor(const label c, const label k)
{
    // The fluid k is set to pMin + pVacuum at its density, or colder: to
    // the isentrope through its state before the step if that is lower (a
    // gas expanding into a vacuum follows its isentrope; at the floor's
    // constant pressure its sound speed, sqrt(gamma p/rho) for a gas, would
    // grow without bound as the density falls, and the time step would
    // collapse with it). The energy this takes comes from the heaviest
    // other phase that is not a trace, if any
    const equationOfState& eos = phases_.phase(k).eos();
    const scalar rho = 1/cell_.v[k];
    const scalar pMin = eos.pMin(rho);
    scalar eFloor = eos.e(rho, pMin + phases_.regimes().pVacuum());

    const scalar rhoOld = phases_.rho(k)[c];
    const scalar pOld = phases_.p(k)[c];
    if (rhoOld > 0 && eos.admissible(rhoOld, pOld))
    {
        const scalar eIs = eos.eIsentropic(rho, rhoOld, eos.e(rhoOld, pOld));
        if (eIs < eFloor && eos.p(rho, eIs) > pMin)
        {
            eFloor = eIs;
        }
    }

    // Alone (the other phases traces), the fluid's floor adds at most
    // alpha pVacuum/(gamma - 1) per unit volume, counted
    ledger_.pay(cell_, c, cell_.heaviestActive(k), cell_.m[k]*(eFloor - cell_.e[k]));
    cell_.e[k] = eFloor;
    ledger_.countVacuum();
    return true;
}


void Foam::mechanicalRelaxation::fail
(
    const label c,
    const label k,
    const char* what,
    const scalar value
)
{
    // Cells are relaxed one after the other
    if (badCells_.empty() || badCells_.last() != c)
    {
        badCells_.append(c);
    }
    if (!err_.failed)
    {
        err_.failed = true;
        err_.cell = c;
        err_.phase = k;
        err_.quantity = what;
        err_.value = value;
    }
}


Foam::label Foam::mechanicalRelaxation::floorVolumeFractions
(
    const label c,
    conservedState& q
)
{
    for (label k = 0; k < nPhases_; ++k)
    {
        if (!(q.alpha[k][c] > -1e-3))
        {
            fail(c, k, "alpha", q.alpha[k][c]);
        }
    }
    return floorAndClose
    (
        nPhases_,
        phases_.regimes().alphaMin(),
        [&](const label k) -> scalar& { return q.alpha[k][c]; }
    );
}


Foam::scalar Foam::mechanicalRelaxation::collectMasses
(
    const label c,
    conservedState& q,
    cobasis::vector& mom
)
{
    const phaseRegimes& regimes = phases_.regimes();
    mom.setZero();
    scalar mass = 0;
    for (label k = 0; k < nPhases_; ++k)
    {
        cell_.alpha[k] = q.alpha[k][c];
        cell_.trace[k] = regimes.trace(cell_.alpha[k]);

        if (!(q.mass[k][c] > 0))
        {
            // Minor after the step, or before it (by its mass fraction)
            scalar oldMix = 0;
            for (label j = 0; j < nPhases_; ++j)
            {
                oldMix += phases_.alpha(j)[c]*phases_.rho(j)[c];
            }
            if
            (
                !regimes.negligible
                (
                    cell_.alpha[k], phases_.alpha(k)[c]*phases_.rho(k)[c], oldMix
                )
            )
            {
                fail(c, k, "mass", q.mass[k][c]);
            }
            // A minor phase that lost all its mass keeps its last
            // density (the mass this adds is below alphaMinor rho, or
            // massFractionMinor of the cell's mass)
            q.mass[k][c] = cell_.alpha[k]*phases_.rho(k)[c];
        }
        cell_.m[k] = q.mass[k][c];
        mass += cell_.m[k];
        mom += q.momentum[k][c];
    }

    // A fluid on a reference isentrope holding less than
    // massFractionMinor of the cell's mass is a trace too, whatever its
    // volume: air inside a metal (numerical diffusion leaves such tails)
    // would otherwise take part in the pressure relaxation and cavitate
    // under the metal's tensile release waves, a gas holding no tension,
    // and the near-vacuum bubble would keep growing. As a trace it stays
    // on its isentrope (cold), see relaxTraces. A heavy minor phase (metal
    // debris in air) stays active: resetting it as a trace would hand its
    // energy to the light phase
    //
    // Such a fluid holding less volume than gasTraceRatio times the cell's
    // largest solid is a trace too (numerics 9.2). There it is a film along
    // the solid's free surface: the true condition there is a normal
    // traction equal to the gas's pressure, which the face Riemann problems
    // impose, while equal pressures would hold the solid's mean stress at
    // the gas's pressure. Every mixed cell of a metal's free surface would
    // then carry that wrong condition; at the lip of a Taylor bar it makes
    // the mushroom 1.7 % wider than the converged Lagrangian result, at
    // every mesh (docs/validation.md W1). The solid must also be near its
    // reference density (above half of it, the bound of compactMetals): a
    // solid expanded far below it is debris, not a free surface
    // (stiffened-gas copper at 1-4 % of its density in the wake of the
    // 4 km/s bar, where the rule left the air around it heated to 1e7 Pa
    // at 0.2 kg/m^3 and the time step halved)
    scalar alphaGasTrace = 0;
    if (regimes.gasTraces())
    {
        label kSolid = -1;
        for (label k = 0; k < nPhases_; ++k)
        {
            if
            (
                phases_.phase(k).solid()
             && (kSolid < 0 || cell_.alpha[k] > cell_.alpha[kSolid])
            )
            {
                kSolid = k;
            }
        }
        if (kSolid >= 0)
        {
            alphaGasTrace = regimes.gasTraceAlpha
            (
                cell_.alpha[kSolid], cell_.m[kSolid], phases_.phase(kSolid).rho0()
            );
        }
    }

    for (label k = 0; k < nPhases_; ++k)
    {
        if
        (
            phases_.referenceIsentrope(k).first() > 0
         && (
                regimes.lightGas(cell_.m[k], mass)
             || cell_.alpha[k] < alphaGasTrace
            )
        )
        {
            cell_.trace[k] = true;
        }

        // A minor metal pressed beyond rhoCompressed_ is a trace, and
        // relaxTraces gives it its reference density
        if
        (
            regimes.thin(cell_.alpha[k])
         && !(cell_.m[k] < rhoCompressed_[k]*cell_.alpha[k])
        )
        {
            cell_.trace[k] = true;
        }
    }
    return mass;
}


void Foam::mechanicalRelaxation::compactMetals
(
    const label c,
    const label main
)
{
    for (label k = 0; k < nPhases_; ++k)
    {
        const scalar rhoRef = rhoRef_[k];
        if (k == main || !(rhoRef > 0) || !(cell_.m[k] < 0.5*rhoRef*cell_.alpha[k]))
        {
            continue;
        }
        // A phase with a reference density (a metal) below half of it is
        // not a state of the material: a metal holds no more than a few
        // per cent of tension before it fails. The transport leaves such
        // states where it spreads a metal's volume fraction ahead of its
        // mass (steel at 0.07 rho0 and alpha 0.0075 in an air cell beside
        // an oblique impact, at -2e12 Pa, where its Mie-Grueneisen pressure
        // swings by 1e12 Pa for a one-per-mille change of density). The
        // metal takes its reference density at its specific energy, the
        // volume going to the cell's largest phase: only volumes change,
        // the energy is conserved
        const scalar dAlpha = cell_.m[k]/rhoRef - cell_.alpha[k];
        cell_.alpha[k] += dAlpha;
        cell_.alpha[main] -= dAlpha;
    }
}


void Foam::mechanicalRelaxation::relaxVelocity
(
    const label c,
    conservedState& q,
    const cobasis::vector& u
)
{
    for (label k = 0; k < nPhases_; ++k)
    {
        const hyperelasticPhase& ph = phases_.phase(k);
        cell_.v[k] = cell_.alpha[k]/cell_.m[k];
        cobasis::matrix& A = q.A[k][c];

        // A solid trace is reset unstrained by relaxTraces, which pays the
        // change of its whole energy: its cobasis is not made compatible
        // and no elastic energy is split off here (the same payment up to
        // round-off)
        const bool reset = ph.solid() && cell_.trace[k];
        if (ph.solid() && !reset)
        {
            const scalar detA = A.determinant();
            if (!(detA > 0))
            {
                // A minor solid's cobasis that the transport inverted is
                // reset (its elastic energy, if any, becomes heat)
                if (!cell_.trace[k] && !phases_.regimes().thin(cell_.alpha[k]))
                {
                    fail(c, k, "det(A)", detA);
                }
                A = cobasis::unstrained(1/cell_.v[k], ph.rho0());
            }
            else
            {
                A *= std::cbrt(1/(cell_.v[k]*ph.rho0()*detA));
            }
        }
        // Own kinetic energy out, the share of the dissipated kinetic
        // energy 1/2 |u_k - u|^2 in: e_k never decreases
        const cobasis::vector uk(q.momentum[k][c]/cell_.m[k]);
        cell_.ee[k] = reset ? 0 : ph.elasticEnergy(A);
        cell_.e[k] =
            q.energy[k][c]/cell_.m[k] - 0.5*uk.squaredNorm()
          + 0.5*(uk - u).squaredNorm() - cell_.ee[k];
    }
}


void Foam::mechanicalRelaxation::screenEnergies
(
    const label c,
    const scalar mass
)
{
    for (label k = 0; k < nPhases_; ++k)
    {
        if (cell_.trace[k]) continue;
        const equationOfState& eos = phases_.phase(k).eos();
        if (!(1/cell_.v[k] < eos.rhoMax()))
        {
            // Beyond the highest density of the equation of state (the
            // pole of a Mie-Grueneisen Hugoniot) there is no pressure
            fail(c, k, "rho>=rhoMax", 1/cell_.v[k]);
            continue;
        }
        const scalar pk = eos.p(1/cell_.v[k], cell_.e[k]);
        if (!(pk > eos.pMin(1/cell_.v[k])))
        {
            if
            (
                phases_.regimes().negligible(cell_.alpha[k], cell_.m[k], mass)
            )
            {
                cell_.trace[k] = true;
            }
            else if
            (
                phases_.regimes().vacuumFloor() && !phases_.phase(k).solid()
             && vacuumFloor(c, k)
            )
            {}
            else
            {
                fail(c, k, "p", pk);
            }
        }
        else if (1/cell_.v[k] < rhoVacuum_[k])
        {
            vacuumCap(c, k);
        }
    }
}


bool Foam::mechanicalRelaxation::relaxPressures
(
    const label c,
    conservedState& q,
    const label main,
    scalar& pStar
)
{
    cell_.nActive = 0;
    cell_.traceVolume = 0;
    for (label k = 0; k < nPhases_; ++k)
    {
        if (cell_.trace[k]) cell_.traceVolume += cell_.alpha[k];
        else ++cell_.nActive;
    }

    if (cell_.nActive > 1)
    {
        if (!pressure_.relax(cell_, q, c, pStar))
        {
            fail(c, main, "interface pressure (no convergence)", pStar);
            return false;
        }
    }
    else
    {
        pStar = phases_.phase(main).eos().p(1/cell_.v[main], cell_.e[main]);
    }
    return true;
}


void Foam::mechanicalRelaxation::relaxTraces
(
    const label c,
    conservedState& q,
    const label main,
    const scalar pStar
)
{
    // The energy a trace's reset takes or gives is paid by the heaviest
    // phase that is not a trace (the cell's largest by volume if none)
    label payer = cell_.heaviestActive(-1);
    if (payer < 0) payer = main;

    for (label k = 0; k < nPhases_; ++k)
    {
        if (!cell_.trace[k]) continue;
        const hyperelasticPhase& ph = phases_.phase(k);
        const equationOfState& eos = ph.eos();
        const scalar rhoRef = rhoRef_[k];
        const scalar rhoTrace = 1/cell_.v[k];
        if (k != main && !(rhoTrace < rhoCompressed_[k]))
        {
            // A trace that the transport left beyond rhoCompressed_ takes
            // its reference density (half rhoMax if it has none), the
            // volume exchanged with the cell's largest phase (below half
            // the reference density it was compacted, compactMetals)
            const scalar rhoNew = rhoRef > 0 ? rhoRef : 0.5*eos.rhoMax();
            const scalar dAlpha = cell_.m[k]/rhoNew - cell_.alpha[k];
            cell_.alpha[k] += dAlpha;
            cell_.alpha[main] -= dAlpha;
            cell_.v[k] = cell_.alpha[k]/cell_.m[k];
            cell_.v[main] = cell_.alpha[main]/cell_.m[main];
        }
        const scalar rho = 1/cell_.v[k];
        if (!(rho < ph.eos().rhoMax()))
        {
            // No state to be reset to
            fail(c, k, "rho>=rhoMax", rho);
            continue;
        }
        scalar pk = max(pStar, ph.eos().pMin(rho) + 1);
        // The elastic energy relaxVelocity split off (its A is unchanged
        // since)
        const scalar eeOld = cell_.ee[k];
        if (ph.solid())
        {
            q.A[k][c] = cobasis::unstrained(rho, ph.rho0());
        }
        // A fluid with a reference isentrope stays on it (a trace of air
        // inside a metal at the metal's pressure, 1e8-1e9 Pa, and its own
        // tiny density would hold 1e12 J/kg, and the metal would pay for
        // it every step)
        const Pair<scalar>& ref = phases_.referenceIsentrope(k);
        const scalar eNew =
            ref.first() > 0
          ? ph.eos().eIsentropic(rho, ref.first(), ref.second())
          : ph.eos().e(rho, pk);
        // A trace heavier than every other phase of the cell (metal debris
        // in a vacuum: alpha 1e-7 next to a gas at rho 1e-11) is reset
        // without a payer: handing its energy change to a lighter phase
        // would heat that phase by the ratio of the masses (a gas at 1e11
        // Pa, the time step collapsing)
        ledger_.pay
        (
            cell_,
            c,
            cell_.m[k] < cell_.m[payer] ? payer : -1,
            cell_.m[k]*(eNew - cell_.e[k] - eeOld)
        );
        cell_.e[k] = eNew;
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
            }
        }
    }
    return heated;
}


void Foam::mechanicalRelaxation::vacuumAfterRelaxation(const label c)
{
    for (label k = 0; k < nPhases_; ++k)
    {
        const equationOfState& eos = phases_.phase(k).eos();
        if
        (
            phases_.regimes().vacuumFloor() && !cell_.trace[k]
         && !phases_.phase(k).solid()
         && 1/cell_.v[k] < eos.rhoMax()
         && !(eos.p(1/cell_.v[k], cell_.e[k]) > eos.pMin(1/cell_.v[k]))
        )
        {
            vacuumFloor(c, k);
        }
    }
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
        const cobasis::matrix& A = q.A[k][c];

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
            if (!(rho > 0)) fail(c, k, "rho", rho);
            if (!(rho < ph.eos().rhoMax())) fail(c, k, "rho>=rhoMax", rho);
            if (inRange && !(std::isfinite(p) && p > ph.eos().pMin(rho)))
            {
                fail(c, k, "p", p);
            }
            if (!(cell_.alpha[k] <= 1)) fail(c, k, "alpha", cell_.alpha[k]);
            if (ph.solid() && !(A.determinant() > 0))
            {
                fail(c, k, "det(A)", A.determinant());
            }
        }

        phases_.alpha(k)[c] = cell_.alpha[k];
        phases_.rho(k)[c] = rho;
        phases_.p(k)[c] = p;
        phases_.A(k)[c] = toTensor(A);
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::mechanicalRelaxation::stateError Foam::mechanicalRelaxation::correct
(
    conservedState& q,
    const scalar dt
)
{
    err_ = stateError();
    badCells_.clear();
    ledger_.reset();

    const label nCells = phases_.mesh().nCells();
    for (label c = 0; c < nCells; ++c)
    {
        // 1. Volume fractions floored, the sum closed by the largest phase;
        //    the masses and the trace phases
        const label main = floorVolumeFractions(c, q);
        cobasis::vector mom;
        const scalar mass = collectMasses(c, q, mom);
        compactMetals(c, main);

        // 2. One velocity; the cobasis made compatible with the density
        const cobasis::vector u(mom/mass);
        relaxVelocity(c, q, u);

        // A minor phase whose energy the step left inadmissible is reset
        // as a trace, a torn gas floored (pVacuum); any other phase fails
        screenEnergies(c, mass);
        if (err_.failed && err_.cell == c)
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
        if (heated && cell_.nActive > 1)
        {
            if (!pressure_.relax(cell_, q, c, pStar))
            {
                fail(c, main, "interface pressure (no convergence)", pStar);
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

    return err_;
}
