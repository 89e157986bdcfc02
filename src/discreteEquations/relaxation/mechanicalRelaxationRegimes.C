/*---------------------------------------------------------------------------*\
  impactFoam: Eulerian multiphase elastic-plastic impact solver for OpenFOAM
-------------------------------------------------------------------------------
Description
    mechanicalRelaxation: the cell's phases sorted by regime (phaseRegimes)
    before the relaxation: floored volume fractions, masses, traces, compacted
    metals; and the traces reset to the cell's state after it.
\*---------------------------------------------------------------------------*/

#include "mechanicalRelaxation.H"
#include "alphaClosure.H"

#include <cmath>

// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

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
            checks_.fail(c, k, "alpha", q.alpha[k][c]);
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
                checks_.fail(c, k, "mass", q.mass[k][c]);
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



namespace
{
    //- The largest share of the main phase's volume one compaction hands
    //  it: the compaction repairs what the transport left, a little at
    //  each step. At once, the hot aluminium vapour that fills 0.4 of a
    //  cell in a tungsten sphere's crater at 10 km/s (at 0.23 of its
    //  reference density, 2e8 J/kg) expanded the tungsten beside it by a
    //  half, to -1.6e11 Pa, and the run stopped
    const Foam::scalar compactionLimit = 0.01;
}


void Foam::mechanicalRelaxation::compactMetals
(
    const label c,
    conservedState& q,
    const label main
)
{
    for (label k = 0; k < nPhases_; ++k)
    {
        const scalar vMax = cell_.vMax[k];
        if (k == main || !(cell_.v[k] > vMax))
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
        // metal takes its lowest density, half the reference density (at
        // most compactionLimit of the main phase's volume at a step), the
        // volume going to the cell's largest phase, exchanged at that
        // phase's pressure: each phase does the work -p dv, so the
        // energy is conserved and neither phase gains by the exchange.
        // At fixed energies instead, a minor metal under a tension of the
        // cell, compacted here and expanded again by the pressure
        // relaxation (which hands it the work of the expansion), pumped
        // energy from the main phase step after step (a tungsten rod's
        // nose cooled below absolute zero and stretched to -1.8e11 Pa,
        // the aluminium sliver beside it at 1e11 J/kg)
        const scalar pMain =
            phases_.phase(main).eos().p(1/cell_.v[main], cell_.e[main]);
        if (!std::isfinite(pMain))
        {
            continue;
        }
        const scalar dAlpha =
            max
            (
                cell_.m[k]*vMax - cell_.alpha[k],
                -compactionLimit*cell_.alpha[main]
            );
        const scalar vMain = (cell_.alpha[main] - dAlpha)/cell_.m[main];
        const scalar vK = (cell_.alpha[k] + dAlpha)/cell_.m[k];
        cell_.e[k] -= pMain*(vK - cell_.v[k]);
        cell_.e[main] -= pMain*(vMain - cell_.v[main]);
        for (const label j : {k, main})
        {
            const scalar vNew = j == k ? vK : vMain;
            if (phases_.phase(j).solid())
            {
                // The unimodular part (and the elastic energy) kept
                q.A[j][c] *= std::cbrt(cell_.v[j]/vNew);
            }
            cell_.v[j] = vNew;
        }
        cell_.alpha[k] += dAlpha;
        cell_.alpha[main] -= dAlpha;
    }
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
            checks_.fail(c, k, "rho>=rhoMax", rho);
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


// ************************************************************************* //
