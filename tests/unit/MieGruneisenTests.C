/*---------------------------------------------------------------------------*\
  Unit tests of the Mie-Grueneisen equation of state (docs/model.md section
  10.1, docs/validation.md): the facts of that section (continuity at
  eta = 0 with c^2(rho0, 0) = c0^2, the model's own Hugoniot from rest is
  Us = c0 + s up, round trips, Gamma = rho0 Gamma0/rho, the temperature),
  the admissible range (rhoMax, pMin), the closed-form helpers against the
  generic ones, and the generic relaxation services against their direct
  definitions.
\*---------------------------------------------------------------------------*/

#include <gtest/gtest.h>
#include "MieGruneisen.H"
#include "primitivesOnly.H"
#include "unitTestTools.H"

#include <cmath>
#include <limits>
#include <string>
#include <vector>

using namespace Foam;
using namespace unitTestTools;

namespace
{

// Copper of docs/materials.md (OFHCcopper, Steinberg's data) and of V11
const scalar rho0 = 8930, c0 = 3940, s = 1.489, Gamma0 = 2.02;
const scalar Cv = 383, T0 = 298;
const scalar K = rho0*c0*c0;

const std::string copperDict
(
    "type MieGruneisen; rho0 8930; c0 3940; s 1.489; Gamma0 2.02;"
    " Cv 383; T0 298;"
);

autoPtr<equationOfState> eosFrom(const std::string& text)
{
    return equationOfState::New("copper", dictFrom(text));
}

const equationsOfState::MieGruneisen& mg(const equationOfState& eos)
{
    return refCast<const equationsOfState::MieGruneisen>(eos);
}

//- Density at compression eta = 1 - rho0/rho
scalar rhoAt(const scalar eta)
{
    return rho0/(1 - eta);
}

//- Compressions from deep tension to near the pole eta = 1/s = 0.6716
const std::vector<scalar> etas
{
    -3.0, -1.0, -0.3, -0.05, -1e-4, 0.0, 1e-4, 0.05, 0.2, 0.4, 0.6, 0.67
};

//- Pressures above pMin at density rho: fractions of p_ref - pMin above
//  pMin, and the reference curve shifted by fixed amounts
std::vector<scalar> pressuresAt(const equationOfState& eos, const scalar rho)
{
    const scalar pr = mg(eos).pRef(rho);
    const scalar pm = eos.pMin(rho);
    std::vector<scalar> ps;
    for (const scalar f : {0.01, 0.5, 1.0, 2.0, 5.0})
    {
        ps.push_back(pm + f*(pr - pm));
    }
    for (const scalar dp : {1e5, 1e9, 2e10})
    {
        ps.push_back(pr + dp);
    }
    return ps;
}



//- Counts the evaluations of p that the generic services make
class countingPrimitives
:
    public primitivesOnly
{
public:

    mutable label nP = 0;

    explicit countingPrimitives(const equationOfState& eos)
    :
        primitivesOnly(eos)
    {}

    scalar p(const scalar rho, const scalar e) const
    {
        ++nP;
        return primitivesOnly::p(rho, e);
    }
};

} // End anonymous namespace


TEST(MieGruneisen, referenceStateAndContinuityAtEtaZero)
{
    auto eos = eosFrom(copperDict);
    EXPECT_EQ(eos->type(), "MieGruneisen");
    EXPECT_EQ(eos->referenceDensity(), rho0);

    // At rest: p = e = 0, c^2 = c0^2
    EXPECT_EQ(eos->p(rho0, 0), 0);
    EXPECT_EQ(eos->e(rho0, 0), 0);
    EXPECT_TRUE(relClose(eos->c2(rho0, 0), c0*c0, 1e-15));

    // p and c^2 continuous across eta = 0 (compression and tension
    // branches): the jumps over rho0 (1 -+ d) are O(d), no step
    for (const scalar p : {-1e9, 0.0, 1e5, 1e9})
    {
        const scalar e = eos->e(rho0, p);
        for (const scalar d : {1e-6, 1e-9, 1e-12})
        {
            const scalar rhoL = rho0*(1 - d), rhoR = rho0*(1 + d);
            EXPECT_LE
            (
                mag(eos->p(rhoR, e) - eos->p(rhoL, e)),
                4*d*K + 1e-15*K
            ) << "p = " << p << ", d = " << d;
            EXPECT_LE
            (
                mag(eos->c2(rhoR, p) - eos->c2(rhoL, p)),
                20*d*c0*c0 + 1e-15*c0*c0
            ) << "p = " << p << ", d = " << d;
        }
    }
}


TEST(MieGruneisen, soundSpeedAndGrueneisenFromPressure)
{
    // c^2 = (dp/drho)_e + (p/rho^2) dp/de and Gamma = (1/rho) dp/de, by
    // central differences of p(rho, e), on both branches
    auto eos = eosFrom(copperDict);
    for (const scalar eta : etas)
    {
        if (eta == 0) continue;     // the one-sided branches meet there
        const scalar rho = rhoAt(eta);
        for (const scalar p : pressuresAt(eos(), rho))
        {
            const scalar e = eos->e(rho, p);
            const scalar h = 1e-5*rho*min(mag(eta), scalar(1));
            const scalar de = 1e-4*(mag(e) + c0*c0);
            const scalar dpdrho = (eos->p(rho + h, e) - eos->p(rho - h, e))/(2*h);
            const scalar dpde = (eos->p(rho, e + de) - eos->p(rho, e - de))/(2*de);
            const scalar c2 = eos->c2(rho, p);

            EXPECT_EQ(eos->Gamma(rho, e), rho0*Gamma0/rho);
            EXPECT_TRUE(relClose(dpde/rho, eos->Gamma(rho, e), 1e-8))
                << "eta " << eta << " p " << p;
            EXPECT_NEAR
            (
                dpdrho + p/(rho*rho)*dpde, c2,
                1e-6*(mag(c2) + eos->pScale(rho, p)/rho)
            ) << "eta " << eta << " p " << p;
        }
    }
}


TEST(MieGruneisen, hugoniotFromRestIsLinearUsUp)
{
    // The Rankine-Hugoniot jump from rest (rho0, p = 0, e = 0, u = 0) to a
    // particle speed up: Us = up/eta (mass), p = rho0 Us up (momentum),
    // e = p eta/(2 rho0) = up^2/2 (energy). The state at compression eta
    // solves g(eta) = p_eos(rho(eta), up^2/2) - rho0 up^2/eta = 0, using the
    // equation of state's p only; its shock speed must be c0 + s up
    auto eos = eosFrom(copperDict);
    for (const scalar up : {1.0, 20.0, 100.0, 500.0, 1000.0, 2000.0, 4000.0})
    {
        const auto g = [&](const scalar eta)
        {
            return eos->p(rhoAt(eta), 0.5*up*up) - rho0*up*up/eta;
        };
        // g < 0 for small eta (the Rayleigh line is steep), > 0 near the
        // pole of p_ref: bisection to the last bit
        scalar lo = 1e-12, hi = (1 - 1e-15)/s;
        ASSERT_LT(g(lo), 0);
        ASSERT_GT(g(hi), 0);
        for (int i = 0; i < 200 && hi - lo > 0; ++i)
        {
            const scalar mid = 0.5*(lo + hi);
            if (mid <= lo || mid >= hi) break;
            (g(mid) < 0 ? lo : hi) = mid;
        }
        const scalar eta = 0.5*(lo + hi);
        const scalar Us = up/eta;
        EXPECT_TRUE(relClose(Us, c0 + s*up, 1e-12))
            << "up " << up << ": Us " << Us << ", c0 + s up " << c0 + s*up;

        // The Hugoniot state is on the reference curve: T = T0
        EXPECT_NEAR(eos->T(rhoAt(eta), 0.5*up*up), T0, 1e-9*T0);
    }
}


TEST(MieGruneisen, roundTrips)
{
    // p -> e -> p and e -> p -> e to 1e-12, relative to the largest term
    // (|p| and |p_ref|; |e| and |e_ref|): at a density away from rho0
    // p = p_ref + rho0 Gamma0 (e - e_ref) cannot do better than the
    // rounding of p_ref when p itself is small
    auto eos = eosFrom(copperDict);
    const auto& m = mg(eos());
    for (const scalar eta : etas)
    {
        const scalar rho = rhoAt(eta);
        for (const scalar p : pressuresAt(eos(), rho))
        {
            const scalar e = eos->e(rho, p);
            EXPECT_LE
            (
                mag(eos->p(rho, e) - p),
                1e-12*max(mag(p), mag(m.pRef(rho)))
            ) << "eta " << eta << " p " << p;
            EXPECT_LE
            (
                mag(eos->e(rho, eos->p(rho, e)) - e),
                1e-12*max(mag(e), mag(m.eRef(rho)))
            ) << "eta " << eta << " e " << e;
            // The round-off scale bounds the error of the round trip
            EXPECT_GE(eos->pScale(rho, p), mag(p));
            EXPECT_LE
            (
                mag(eos->p(rho, e) - p),
                64*std::numeric_limits<scalar>::epsilon()*eos->pScale(rho, p)
            ) << "eta " << eta << " p " << p;
        }
    }
}


TEST(MieGruneisen, temperature)
{
    auto eos = eosFrom(copperDict);
    const auto& m = mg(eos());
    ASSERT_TRUE(eos->hasTemperature());
    EXPECT_EQ(eos->Cv(), Cv);
    for (const scalar eta : etas)
    {
        const scalar rho = rhoAt(eta);
        const scalar eRef = m.eRef(rho);
        // On the reference curve: T0
        EXPECT_NEAR(eos->T(rho, eRef), T0, 1e-12*(T0 + mag(eRef)/Cv))
            << "eta " << eta;
        // Heat dE above it at fixed density: T0 + dE/Cv
        for (const scalar dE : {1e3, 1e5, 3e6})
        {
            EXPECT_NEAR
            (
                eos->T(rho, eRef + dE), T0 + dE/Cv,
                1e-12*(T0 + (mag(eRef) + dE)/Cv)
            ) << "eta " << eta << " dE " << dE;
        }
    }
    // Through the generic forwarder
    const primitivesOnly generic(eos());
    EXPECT_EQ(generic.T(9500, 4e4), eos->T(9500, 4e4));
}


TEST(MieGruneisen, admissibleRange)
{
    auto eos = eosFrom(copperDict);
    const auto& m = mg(eos());
    const scalar inf = std::numeric_limits<scalar>::infinity();

    // rhoMax at eta = 1/s (Gamma0 = 2.02 <= 2 s = 2.978)
    const scalar rhoMax = rho0/(1 - 1/s);
    EXPECT_TRUE(relClose(eos->rhoMax(), rhoMax, 1e-15));

    // At and beyond rhoMax (and at rho <= 0): no state
    for (const scalar rho : {rhoMax, eos->rhoMax(), 1.0001*rhoMax, 3*rhoMax, 0.0, -1.0})
    {
        EXPECT_TRUE(std::isnan(eos->p(rho, 0))) << rho;
        EXPECT_TRUE(std::isnan(eos->e(rho, 1e9))) << rho;
        EXPECT_TRUE(std::isnan(eos->c2(rho, 1e9))) << rho;
        EXPECT_TRUE(std::isnan(eos->T(rho, 1e5))) << rho;
        EXPECT_EQ(eos->pMin(rho), inf) << rho;
        EXPECT_FALSE(eos->admissible(rho, 1e12)) << rho;
    }
    // Just below: finite, large
    const scalar rhoBelow = rhoMax*(1 - 1e-9);
    EXPECT_TRUE(std::isfinite(eos->p(rhoBelow, 0)));
    EXPECT_GT(m.pRef(rhoBelow), 1e20);
    EXPECT_TRUE(eos->admissible(rhoBelow, m.pRef(rhoBelow)));

    // pMin is where c^2 vanishes; c^2 > 0 above it; the reference curve
    // is above it at every admissible density (densely sampled, up to the
    // pole), by K/Gamma0 in tension
    for (label i = 0; i <= 2000; ++i)
    {
        const scalar eta = -5 + (5 + (1 - 1e-6)/s)*i/2000.0;
        const scalar rho = rhoAt(eta);
        const scalar pm = eos->pMin(rho);
        const scalar pr = m.pRef(rho);
        const scalar scale = eos->pScale(rho, pm);
        EXPECT_NEAR(eos->c2(rho, pm), 0, 1e-13*scale/rho) << "eta " << eta;
        EXPECT_GT(eos->c2(rho, pm + 1e-9*scale), 0) << "eta " << eta;
        EXPECT_LT(pm, pr) << "eta " << eta;
        EXPECT_TRUE(eos->admissible(rho, pr)) << "eta " << eta;
        if (eta < 0)
        {
            EXPECT_NEAR(pr - pm, K/Gamma0, 1e-12*scale) << "eta " << eta;
        }
    }

    // Deep tension: both fall without bound, the model holds any tension
    EXPECT_LT(eos->pMin(rho0/1e6), -1e16);
    EXPECT_LT(m.pRef(rho0/1e6), -1e16);

    // The reference curve meets pMin at the pole exactly when
    // Gamma0 = 2 s: p_ref - pMin = K (1 + s eta (1 - Gamma0 eta))/(Gamma0
    // (1 - s eta)^3) > 0 up to the pole needs 2 - Gamma0/s > 0 (Gamma0 >= 2 s
    // is rejected at input, badInput.MieGruneisen)
    const scalar etaNear = (1 - 1e-6)/s;
    EXPECT_GT
    (
        m.pRef(rhoAt(etaNear)) - eos->pMin(rhoAt(etaNear)),
        0.9*K*(2 - Gamma0/s)/(Gamma0*std::pow(1e-6, 3))
    );
}


TEST(MieGruneisen, closedFormHelpersMatchGeneric)
{
    auto eos = eosFrom(copperDict);
    const primitivesOnly generic(eos());

    // At rest: G = 2 s (linear Us-up)
    EXPECT_TRUE(relClose(eos->fundamentalDerivative(rho0, 0), 2*s, 1e-14));

    for (const scalar eta : etas)
    {
        // The generic central difference straddles the kink of c^2 at
        // eta = 0; and near the pole its steps leave the range
        if (mag(eta) < 1e-3 || eta > 0.6) continue;
        const scalar rho = rhoAt(eta);
        for (const scalar p : pressuresAt(eos(), rho))
        {
            if (p < eos->pMin(rho) + 0.1*(mg(eos()).pRef(rho) - eos->pMin(rho)))
            {
                continue;   // c^2 -> 0: G is singular at pMin
            }
            // Absolute: G vanishes on the reference curve in tension
            // (and is negative below it), where a relative test means
            // nothing; the difference's error is about 1e-10
            const scalar G = eos->fundamentalDerivative(rho, p);
            EXPECT_NEAR
            (
                G, generic.fundamentalDerivative(rho, p), 1e-8*(1 + mag(G))
            ) << "eta " << eta << " p " << p;
            if (eta < 0 && p == mg(eos()).pRef(rho))
            {
                EXPECT_NEAR(G, 0, 1e-14) << "eta " << eta;
            }
        }
    }
}


TEST(MieGruneisen, relaxationServicesAgainstDefinitions)
{
    auto eos = eosFrom(copperDict);
    const auto& m = mg(eos());
    const countingPrimitives counter(eos());
    // Calls and evaluations of p: end states within 5 % of the start's
    // volume (a relaxation step), and the others
    label nCalls[2] = {0, 0}, nEvals[2] = {0, 0};

    for (const scalar etaOld : {-0.2, -0.01, 0.0, 0.05, 0.2, 0.4})
    {
        const scalar rhoOld = rhoAt(etaOld);
        const scalar vOld = 1/rhoOld;
        for (const scalar pOld : pressuresAt(eos(), rhoOld))
        {
            if (pOld < eos->pMin(rhoOld) + 0.4*(m.pRef(rhoOld) - eos->pMin(rhoOld)))
            {
                continue;
            }
            const scalar eOld = eos->e(rhoOld, pOld);

            // The constant-pressure path: at fixed density p is linear in
            // e, so the path's pressure at volume v is explicit,
            //   q(v) = (p_ref + rho0 Gamma0 (eOld - e_ref))
            //         /(1 + rho0 Gamma0 (v - vOld)),
            // and vRelaxed(q(v)) must give v back. Volumes from a
            // compression to a tenfold expansion
            for (const scalar f : {0.8, 0.95, 0.999, 1.0, 1.05, 1.5, 3.0, 10.0})
            {
                const scalar v = f*vOld;
                if (!(1/v < eos->rhoMax()) || 1 + rho0*Gamma0*(v - vOld) <= 0)
                {
                    continue;
                }
                const scalar q =
                    (m.pRef(1/v) + rho0*Gamma0*(eOld - m.eRef(1/v)))
                   /(1 + rho0*Gamma0*(v - vOld));
                if (!(q > eos->pMin(1/v))) continue;
                SCOPED_TRACE
                (
                    "etaOld " + std::to_string(etaOld) + " pOld "
                  + std::to_string(pOld) + " v/vOld " + std::to_string(f)
                );
                const label n0 = counter.nP;
                const scalar vR = counter.vRelaxed(q, rhoOld, eOld);
                const int far = mag(f - 1) > 0.05;
                nEvals[far] += counter.nP - n0;
                ++nCalls[far];
                EXPECT_TRUE(relClose(vR, v, 1e-12));

                // Its definition: p(1/v, eOld - p* (v - vOld)) = p*
                EXPECT_NEAR
                (
                    eos->p(1/vR, eOld - q*(vR - vOld)), q,
                    1e-12*eos->pScale(1/vR, q)
                );

                // dv/dp* = -(1 + rho0 Gamma0 (v - vOld))/(rho^2 c^2) (the
                // implicit derivative of the definition, Gamma = rho0
                // Gamma0/rho) and a central difference of vRelaxed (not
                // across the kink of c^2 at eta = 0)
                const scalar dvdp = eos->dvRelaxeddp(q, rhoOld, eOld);
                EXPECT_TRUE
                (
                    relClose
                    (
                        dvdp,
                        -(1 + rho0*Gamma0*(v - vOld))*v*v/eos->c2(1/v, q),
                        1e-10
                    )
                );
                if (mag(1 - rho0*v) > 1e-3)
                {
                    const scalar dq = 1e-5*eos->pScale(1/v, q);
                    const scalar dvNum =
                        (
                            eos->vRelaxed(q + dq, rhoOld, eOld)
                          - eos->vRelaxed(q - dq, rhoOld, eOld)
                        )/(2*dq);
                    EXPECT_TRUE(relClose(dvdp, dvNum, 1e-5));
                }
            }

            // The lowest pressure the path reaches lies below the path's
            // pressure at a hundredfold expansion
            {
                const scalar v = 100*vOld;
                const scalar q100 =
                    (m.pRef(1/v) + rho0*Gamma0*(eOld - m.eRef(1/v)))
                   /(1 + rho0*Gamma0*(v - vOld));
                EXPECT_LT(eos->pRelaxedMin(rhoOld, eOld), q100);
            }

            // The isentrope de = -p dv: eIsentropic against fourth-order
            // Runge-Kutta in v (4000 steps, error ~1e-12 relative). From
            // states on or above the reference curve: an isentrope far
            // below it in compression reaches c^2 = 0 on expansion (the
            // generic services then stop, naming the phase)
            if (pOld < m.pRef(rhoOld)) continue;
            for (const scalar f : {0.8, 0.95, 1.2, 2.0})
            {
                const scalar v1 = f*vOld;
                if (!(1/v1 < eos->rhoMax())) continue;
                const label nSteps = 4000;
                const scalar h = (v1 - vOld)/nSteps;
                scalar v = vOld, e = eOld;
                const auto dedv = [&](const scalar vv, const scalar ee)
                {
                    return -eos->p(1/vv, ee);
                };
                for (label i = 0; i < nSteps; ++i)
                {
                    const scalar k1 = dedv(v, e);
                    const scalar k2 = dedv(v + h/2, e + h/2*k1);
                    const scalar k3 = dedv(v + h/2, e + h/2*k2);
                    const scalar k4 = dedv(v + h, e + h*k3);
                    e += h/6*(k1 + 2*k2 + 2*k3 + k4);
                    v += h;
                }
                const scalar eI = eos->eIsentropic(1/v1, rhoOld, eOld);
                const scalar pI = eos->p(1/v1, eI);
                EXPECT_NEAR(pI, eos->p(1/v1, e), 1e-9*eos->pScale(1/v1, pI))
                    << "etaOld " << etaOld << " pOld " << pOld
                    << " v/vOld " << f;

                // vIsentropic is the inverse: the volume at that pressure
                // (1e-10: an isentrope across eta = 0, where the derivative
                // of c^2 jumps, is integrated to about 1e-11 only)
                EXPECT_TRUE
                (
                    relClose(eos->vIsentropic(pI, rhoOld, eOld), v1, 1e-10)
                ) << "etaOld " << etaOld << " pOld " << pOld;
                // and dv/dp = -1/(rho^2 c^2) there
                EXPECT_TRUE
                (
                    relClose
                    (
                        eos->dvIsentropicdp(pI, rhoOld, eOld),
                        -v1*v1/eos->c2(1/v1, pI),
                        1e-10
                    )
                );
            }
            EXPECT_LT
            (
                eos->pIsentropicMin(rhoOld, eOld),
                eos->p(0.01*rhoOld, eos->eIsentropic(0.01*rhoOld, rhoOld, eOld))
            );
        }
    }

    // Cost of the generic Newton on the density: evaluations of p per
    // vRelaxed (one per iteration), printed; a relaxation step (end state
    // near the start) takes a handful
    ASSERT_GT(nCalls[0], 0);
    ASSERT_GT(nCalls[1], 0);
    const scalar nearMean = scalar(nEvals[0])/nCalls[0];
    std::cout
        << "    MieGruneisen: generic vRelaxed, evaluations of p per call: "
        << nearMean << " (" << nCalls[0] << " calls within 5 % of vOld), "
        << scalar(nEvals[1])/nCalls[1] << " (" << nCalls[1]
        << " calls farther)" << std::endl;
    EXPECT_LE(nearMean, 8);
}


TEST(MieGruneisen, combinedRelaxedVolumeAndLinearEnergyShortcut)
{
    // vRelaxed(p*, rhoOld, eOld, dvdp) gives the same end state and slope,
    // bit for bit, as vRelaxed and dvRelaxeddp called apart; and the slope
    // with the shortcut of a model linear in e (no correction integral R)
    // equals the generic one that integrates R = 0, bit for bit
    auto eos = eosFrom(copperDict);
    ASSERT_TRUE(eos->pLinearInEnergy());
    // The model's primitives and round-off scale, without the shortcut
    struct withoutShortcut : public primitivesOnly
    {
        const equationOfState& model;
        explicit withoutShortcut(const equationOfState& m)
        :
            primitivesOnly(m),
            model(m)
        {}
        scalar pScale(const scalar rho, const scalar p) const
        {
            return model.pScale(rho, p);
        }
    };
    const withoutShortcut generic(eos());
    ASSERT_FALSE(generic.pLinearInEnergy());
    label nCompared = 0;
    for (const scalar etaOld : {-0.2, -0.01, 0.0, 0.05, 0.2, 0.4})
    {
        const scalar rhoOld = rhoAt(etaOld);
        for (const scalar pOld : pressuresAt(eos(), rhoOld))
        {
            const scalar eOld = eos->e(rhoOld, pOld);
            for (const scalar f : {0.5, 0.9, 1.0, 1.1, 2.0})
            {
                const scalar pStar =
                    eos->pMin(rhoOld) + f*(pOld - eos->pMin(rhoOld));
                SCOPED_TRACE
                (
                    "etaOld " + std::to_string(etaOld) + " pOld "
                  + std::to_string(pOld) + " p* " + std::to_string(pStar)
                );
                scalar dvdp;
                const scalar v = eos->vRelaxed(pStar, rhoOld, eOld, dvdp);
                EXPECT_EQ(v, eos->vRelaxed(pStar, rhoOld, eOld));
                EXPECT_EQ(dvdp, eos->dvRelaxeddp(pStar, rhoOld, eOld));
                EXPECT_EQ(dvdp, generic.dvRelaxeddp(pStar, rhoOld, eOld));
                ++nCompared;
            }
        }
    }
    EXPECT_GT(nCompared, 100);

    // The stiffened gas: its closed forms, the same through both calls
    auto sg = eosFrom("type stiffenedGas; gamma 4.22; pInf 3.42e10;");
    EXPECT_TRUE(sg->pLinearInEnergy());
    for (const scalar pStar : {-1e10, 0.0, 1e9})
    {
        const scalar eOld = sg->e(8930, 1e5);
        scalar dvdp;
        EXPECT_EQ(sg->vRelaxed(pStar, 8930, eOld, dvdp), sg->vRelaxed(pStar, 8930, eOld));
        EXPECT_EQ(dvdp, sg->dvRelaxeddp(pStar, 8930, eOld));
    }
}
