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
    m_(nPhases_),
    v0_(nPhases_),
    eh0_(nPhases_),
    alpha_(nPhases_),
    ee_(nPhases_, 0),
    trace_(nPhases_),
    isentropic_(nPhases_, false),
    failed_(nPhases_, false),
    held_(nPhases_, false),
    pHeld_(nPhases_, 0),
    pinned_(nPhases_, false),
    nVacuum_(0),
    nUnpaid_(0),
    unpaidEnergy_(0),
    err_(),
    nActive_(0),
    traceVolume_(0)
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


Foam::scalar Foam::mechanicalRelaxation::relaxedVolume
(
    const label k,
    const scalar pStar,
    scalar& dvdp
) const
{
    const equationOfState& eos = phases_.phase(k).eos();
    if (isentropic_[k])
    {
        // Along the isentrope, held at the cavitation pressure below it
        const Pair<scalar> s0(isentropeStart(k));
        const scalar pc = phases_.cavitationPressure(k);
        dvdp =
            pStar > pc
          ? eos.dvIsentropicdp(pStar, s0.first(), s0.second())
          : 0;
        return eos.vIsentropic(max(pStar, pc), s0.first(), s0.second());
    }
    if (pinned_[k])
    {
        // Failing material in tension keeps its own state, down to its
        // floor: it does not relax toward the fluids of the cell
        dvdp = 0;
        return
            eos.p(1/v0_[k], eh0_[k]) > pHeld_[k]
          ? v0_[k]
          : eos.vRelaxed(pHeld_[k], 1/v0_[k], eh0_[k]);
    }
    if (held_[k] && pStar < pHeld_[k])
    {
        // Damaged material holds no tension below its floor
        dvdp = 0;
        return eos.vRelaxed(pHeld_[k], 1/v0_[k], eh0_[k]);
    }
    dvdp = eos.dvRelaxeddp(pStar, 1/v0_[k], eh0_[k]);
    return eos.vRelaxed(pStar, 1/v0_[k], eh0_[k]);
}


Foam::Pair<Foam::scalar> Foam::mechanicalRelaxation::isentropeStart
(
    const label k
) const
{
    const Pair<scalar>& ref = phases_.referenceIsentrope(k);
    return ref.first() > 0 ? ref : Pair<scalar>(1/v0_[k], eh0_[k]);
}


bool Foam::mechanicalRelaxation::interfacePressure
(
    const scalar volume,
    scalar& p
) const
{
    // F(p) = sum m_k v_k(p) - volume decreases from +inf at the largest
    // of the lowest pressures the phases' paths reach (every active phase
    // is admissible there) to sum alpha_k (gamma-1)/gamma - volume < 0
    // (stiffened gases): one root
    scalar lo = -GREAT;
    scalar pScale = 0;
    scalar pGuess = 0, wGuess = 0;
    for (label k = 0; k < nPhases_; ++k)
    {
        if (trace_[k]) continue;
        const equationOfState& eos = phases_.phase(k).eos();
        const scalar pk = eos.p(1/v0_[k], eh0_[k]);
        const Pair<scalar> s0(isentropeStart(k));
        const scalar pPath =
            isentropic_[k]
          ? eos.pIsentropicMin(s0.first(), s0.second())
          : eos.pRelaxedMin(1/v0_[k], eh0_[k]);
        const bool held =
            (isentropic_[k] && phases_.cavitationPressure(k) > pPath)
         || (held_[k] && pHeld_[k] > pPath);
        if (!held)
        {
            // v_k(p) grows without bound as p -> pPath
            lo = max(lo, pPath);
        }
        pScale = max(pScale, eos.pScale(1/v0_[k], pk));
        pGuess += alpha_[k]*pk;
        wGuess += alpha_[k];
    }
    scalar hi = GREAT;

    const auto F = [&](const scalar pp, scalar& dF)
    {
        scalar f = -volume;
        dF = 0;
        for (label k = 0; k < nPhases_; ++k)
        {
            if (trace_[k]) continue;
            scalar dvdp;
            f += m_[k]*relaxedVolume(k, pp, dvdp);
            dF += m_[k]*dvdp;
        }
        return f;
    };

    p = pGuess/wGuess;
    if (!(p > lo)) p = lo + 1e-6*max(pScale, scalar(1));

    // Newton steps that do not shrink (a zigzag about the kink of a fluid
    // held at its cavitation pressure) give way to bisection
    scalar stepOld = GREAT;
    for (int iter = 0; iter < 300; ++iter)
    {
        scalar dF;
        const scalar f = F(p, dF);
        if (f == 0)
        {
            return true;
        }
        if (f > 0) lo = p; else hi = p;

        scalar pNew = p - f/dF;
        const bool stalled = mag(pNew - p) > 0.5*stepOld && hi < GREAT;
        stepOld = mag(pNew - p);
        if (!(pNew > lo && pNew < hi) || stalled)
        {
            // Bisect, or expand when no upper bound is known yet
            pNew =
                (hi < GREAT)
              ? 0.5*(lo + hi)
              : p + 2*max(mag(p - lo), scalar(1));
        }
        // Converged in p, and in the volume unless p is resolved to
        // round-off: a nearly empty gas next to failed or cavitating
        // material takes its volume at p* near 0, where a pressure
        // tolerance relative to the metal's scale would leave the volume
        // wrong by percent (and the closing of the volumes would hand
        // that to the metal as a tension of GPa)
        if
        (
            mag(pNew - p) <= 1e-15*(mag(pNew) + pScale)
         && (mag(f) <= 1e-12*volume || mag(pNew - p) <= 1e-15*mag(pNew))
        )
        {
            p = pNew;
            return true;
        }
        p = pNew;
    }
    return false;
}


void Foam::mechanicalRelaxation::vacuumCap(const label c, const label k)
{
    const Pair<scalar>& ref = phases_.referenceIsentrope(k);
    const scalar eIs = phases_.phase(k).eos().eIsentropic
    (
        1/v0_[k], ref.first(), ref.second()
    );
    if (eh0_[k] > eIs)
    {
        pay(c, heaviestActive(k), m_[k]*(eIs - eh0_[k]));
        eh0_[k] = eIs;
        ++nVacuum_;
    }
}


Foam::label Foam::mechanicalRelaxation::heaviestActive(const label k) const
{
    label heaviest = -1;
    for (label j = 0; j < nPhases_; ++j)
    {
        if (j != k && !trace_[j] && (heaviest < 0 || m_[j] > m_[heaviest]))
        {
            heaviest = j;
        }
    }
    return heaviest;
}


void Foam::mechanicalRelaxation::pay
(
    const label c,
    const label payer,
    const scalar dE
)
{
    if (payer >= 0)
    {
        eh0_[payer] -= dE/m_[payer];
    }
    else
    {
        unpaidEnergy_ += dE*phases_.mesh().V()[c];
        ++nUnpaid_;
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
    const scalar rho = 1/v0_[k];
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
    pay(c, heaviestActive(k), m_[k]*(eFloor - eh0_[k]));
    eh0_[k] = eFloor;
    ++nVacuum_;
    return true;
}


bool Foam::mechanicalRelaxation::relaxPressure
(
    const label c,
    conservedState& q,
    const scalar traceVolume,
    scalar& pStar
)
{
    // Fluids on their isentrope, when a phase on the default path
    // (the heaviest such, the payer) takes the energy difference and
    // outweighs them
    label payer = -1;
    for (label k = 0; k < nPhases_; ++k)
    {
        if
        (
            !trace_[k] && !phases_.isentropicRelaxation(k)
         && (payer < 0 || m_[k] > m_[payer])
        )
        {
            payer = k;
        }
    }
    // The payer must outweigh the fluids it pays for: where the fluid is
    // the heavier (air with a few metal fragments) the energy difference
    // would overheat or freeze the light payer, and the default path is
    // used
    scalar mIsentropic = 0;
    for (label k = 0; k < nPhases_; ++k)
    {
        if (!trace_[k] && phases_.isentropicRelaxation(k))
        {
            mIsentropic += m_[k];
        }
    }
    const bool useIsentropes = payer >= 0 && m_[payer] > mIsentropic;
    for (label k = 0; k < nPhases_; ++k)
    {
        isentropic_[k] =
            useIsentropes && !trace_[k]
         && phases_.isentropicRelaxation(k);
    }

    if (!interfacePressure(1 - traceVolume, pStar))
    {
        return false;
    }

    scalar sumActive = 0;
    for (label k = 0; k < nPhases_; ++k)
    {
        if (trace_[k]) continue;
        scalar dvdp;
        alpha_[k] = m_[k]*relaxedVolume(k, pStar, dvdp);
        sumActive += alpha_[k];
    }
    scalar toPayer = 0;
    for (label k = 0; k < nPhases_; ++k)
    {
        if (trace_[k]) continue;
        alpha_[k] *= (1 - traceVolume)/sumActive;
        const scalar v = alpha_[k]/m_[k];
        const scalar eConstantP = eh0_[k] - pStar*(v - v0_[k]);
        if (isentropic_[k])
        {
            eh0_[k] = phases_.phase(k).eos().e
            (
                1/v, max(pStar, phases_.cavitationPressure(k))
            );
            toPayer += m_[k]*(eConstantP - eh0_[k]);
        }
        else
        {
            eh0_[k] = eConstantP;
        }
        if (phases_.phase(k).solid())
        {
            q.A[k][c] *= std::cbrt(v0_[k]/v);
        }
        v0_[k] = v;
    }
    if (payer >= 0)
    {
        eh0_[payer] += toPayer/m_[payer];
    }
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
        alpha_[k] = q.alpha[k][c];
        trace_[k] = regimes.trace(alpha_[k]);

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
                    alpha_[k], phases_.alpha(k)[c]*phases_.rho(k)[c], oldMix
                )
            )
            {
                fail(c, k, "mass", q.mass[k][c]);
            }
            // A minor phase that lost all its mass keeps its last
            // density (the mass this adds is below alphaMinor rho, or
            // massFractionMinor of the cell's mass)
            q.mass[k][c] = alpha_[k]*phases_.rho(k)[c];
        }
        m_[k] = q.mass[k][c];
        mass += m_[k];
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
             && (kSolid < 0 || alpha_[k] > alpha_[kSolid])
            )
            {
                kSolid = k;
            }
        }
        if (kSolid >= 0)
        {
            alphaGasTrace = regimes.gasTraceAlpha
            (
                alpha_[kSolid], m_[kSolid], phases_.phase(kSolid).rho0()
            );
        }
    }

    for (label k = 0; k < nPhases_; ++k)
    {
        if
        (
            phases_.referenceIsentrope(k).first() > 0
         && (
                regimes.lightGas(m_[k], mass)
             || alpha_[k] < alphaGasTrace
            )
        )
        {
            trace_[k] = true;
        }

        // A minor metal pressed beyond rhoCompressed_ is a trace, and
        // relaxTraces gives it its reference density
        if
        (
            regimes.thin(alpha_[k])
         && !(m_[k] < rhoCompressed_[k]*alpha_[k])
        )
        {
            trace_[k] = true;
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
        if (k == main || !(rhoRef > 0) || !(m_[k] < 0.5*rhoRef*alpha_[k]))
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
        const scalar dAlpha = m_[k]/rhoRef - alpha_[k];
        alpha_[k] += dAlpha;
        alpha_[main] -= dAlpha;
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
        v0_[k] = alpha_[k]/m_[k];
        cobasis::matrix& A = q.A[k][c];

        // A solid trace is reset unstrained by relaxTraces, which pays the
        // change of its whole energy: its cobasis is not made compatible
        // and no elastic energy is split off here (the same payment up to
        // round-off)
        const bool reset = ph.solid() && trace_[k];
        if (ph.solid() && !reset)
        {
            const scalar detA = A.determinant();
            if (!(detA > 0))
            {
                // A minor solid's cobasis that the transport inverted is
                // reset (its elastic energy, if any, becomes heat)
                if (!trace_[k] && !phases_.regimes().thin(alpha_[k]))
                {
                    fail(c, k, "det(A)", detA);
                }
                A = cobasis::unstrained(1/v0_[k], ph.rho0());
            }
            else
            {
                A *= std::cbrt(1/(v0_[k]*ph.rho0()*detA));
            }
        }
        // Own kinetic energy out, the share of the dissipated kinetic
        // energy 1/2 |u_k - u|^2 in: e_k never decreases
        const cobasis::vector uk(q.momentum[k][c]/m_[k]);
        ee_[k] = reset ? 0 : ph.elasticEnergy(A);
        eh0_[k] =
            q.energy[k][c]/m_[k] - 0.5*uk.squaredNorm()
          + 0.5*(uk - u).squaredNorm() - ee_[k];
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
        if (trace_[k]) continue;
        const equationOfState& eos = phases_.phase(k).eos();
        if (!(1/v0_[k] < eos.rhoMax()))
        {
            // Beyond the highest density of the equation of state (the
            // pole of a Mie-Grueneisen Hugoniot) there is no pressure
            fail(c, k, "rho>=rhoMax", 1/v0_[k]);
            continue;
        }
        const scalar pk = eos.p(1/v0_[k], eh0_[k]);
        if (!(pk > eos.pMin(1/v0_[k])))
        {
            if
            (
                phases_.regimes().negligible(alpha_[k], m_[k], mass)
            )
            {
                trace_[k] = true;
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
        else if (1/v0_[k] < rhoVacuum_[k])
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
    nActive_ = 0;
    traceVolume_ = 0;
    for (label k = 0; k < nPhases_; ++k)
    {
        if (trace_[k]) traceVolume_ += alpha_[k];
        else ++nActive_;
    }

    if (nActive_ > 1)
    {
        if (!relaxPressure(c, q, traceVolume_, pStar))
        {
            fail(c, main, "interface pressure (no convergence)", pStar);
            return false;
        }
    }
    else
    {
        pStar = phases_.phase(main).eos().p(1/v0_[main], eh0_[main]);
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
    label payer = heaviestActive(-1);
    if (payer < 0) payer = main;

    for (label k = 0; k < nPhases_; ++k)
    {
        if (!trace_[k]) continue;
        const hyperelasticPhase& ph = phases_.phase(k);
        const equationOfState& eos = ph.eos();
        const scalar rhoRef = rhoRef_[k];
        const scalar rhoTrace = 1/v0_[k];
        if (k != main && !(rhoTrace < rhoCompressed_[k]))
        {
            // A trace that the transport left beyond rhoCompressed_ takes
            // its reference density (half rhoMax if it has none), the
            // volume exchanged with the cell's largest phase (below half
            // the reference density it was compacted, compactMetals)
            const scalar rhoNew = rhoRef > 0 ? rhoRef : 0.5*eos.rhoMax();
            const scalar dAlpha = m_[k]/rhoNew - alpha_[k];
            alpha_[k] += dAlpha;
            alpha_[main] -= dAlpha;
            v0_[k] = alpha_[k]/m_[k];
            v0_[main] = alpha_[main]/m_[main];
        }
        const scalar rho = 1/v0_[k];
        if (!(rho < ph.eos().rhoMax()))
        {
            // No state to be reset to
            fail(c, k, "rho>=rhoMax", rho);
            continue;
        }
        scalar pk = max(pStar, ph.eos().pMin(rho) + 1);
        // The elastic energy relaxVelocity split off (its A is unchanged
        // since)
        const scalar eeOld = ee_[k];
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
        pay
        (
            c,
            m_[k] < m_[payer] ? payer : -1,
            m_[k]*(eNew - eh0_[k] - eeOld)
        );
        eh0_[k] = eNew;
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
        if (ph.solid() && !trace_[k] && !failed_[k])
        {
            // The plastic return, its heat and the damage it does
            // (inelasticModel), on the phase's fields of this cell
            const inelasticModel& inelastic = phase.inelastic();
            const label nI = phase.nInelastic();
            scalar carried[phaseModel::maxCarried];
            phase.inelasticState(c, carried);
            const scalar heat =
                inelastic.relax(q.A[k][c], carried, 1/v0_[k], eh0_[k], dt);
            for (label i = 0; i < nI; ++i)
            {
                phase.carried(i)[c] = carried[i];
            }
            heated = heated || heat > 0;
            if (inelastic.failed(carried))
            {
                removeShear(c, q, k);
                failed_[k] = true;
                held_[k] = true;
                pHeld_[k] = inelastic.pFloor(carried);
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
            phases_.regimes().vacuumFloor() && !trace_[k]
         && !phases_.phase(k).solid()
         && 1/v0_[k] < eos.rhoMax()
         && !(eos.p(1/v0_[k], eh0_[k]) > eos.pMin(1/v0_[k]))
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

        const scalar rho = 1/v0_[k];

        // No pressure outside the density range (a Mie-Grueneisen phase
        // beyond rhoMax gives NaN, and comparing a NaN traps under
        // FOAM_SIGFPE): the phase fails on rho and keeps its last
        // pressure (the step is retried or stopped). A trace there has
        // already failed (relaxTraces)
        const bool inRange = rho > 0 && rho < ph.eos().rhoMax();
        const scalar p =
            inRange ? ph.eos().p(rho, eh0_[k]) : phases_.p(k)[c];

        if (!trace_[k])
        {
            if (!(rho > 0)) fail(c, k, "rho", rho);
            if (!(rho < ph.eos().rhoMax())) fail(c, k, "rho>=rhoMax", rho);
            if (inRange && !(std::isfinite(p) && p > ph.eos().pMin(rho)))
            {
                fail(c, k, "p", p);
            }
            if (!(alpha_[k] <= 1)) fail(c, k, "alpha", alpha_[k]);
            if (ph.solid() && !(A.determinant() > 0))
            {
                fail(c, k, "det(A)", A.determinant());
            }
        }

        phases_.alpha(k)[c] = alpha_[k];
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
    nVacuum_ = 0;
    nUnpaid_ = 0;
    unpaidEnergy_ = 0;

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
        if (heated && nActive_ > 1)
        {
            if (!relaxPressure(c, q, traceVolume_, pStar))
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
