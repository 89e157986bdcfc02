/*---------------------------------------------------------------------------*\
  Unit tests of the stiffened-gas equation of state (docs/validation.md V7, V9)
\*---------------------------------------------------------------------------*/

#include <gtest/gtest.h>
#include "stiffenedGas.H"
#include "IStringStream.H"

using namespace Foam;

namespace
{

autoPtr<equationOfState> eosFrom(const char* text)
{
    IStringStream is(text);
    const dictionary dict(is);
    return equationOfState::New("testPhase", dict);
}

} // End anonymous namespace


TEST(stiffenedGas, pressureEnergyRoundTrip)
{
    auto eos = eosFrom("type stiffenedGas; gamma 4.22; pInf 3.42e10;");
    for (const scalar rho : {7000.0, 8900.0, 11000.0})
    {
        for (const scalar p : {-1e10, 1e5, 1e9, 5e10})
        {
            const scalar e = eos->e(rho, p);
            EXPECT_NEAR(eos->p(rho, e), p, 1e-14*(mag(p) + 4.22*3.42e10));
        }
    }
}


TEST(stiffenedGas, soundSpeedIsIsentropicDerivative)
{
    // c^2 = dp/drho at constant entropy: de = p/rho^2 drho
    auto eos = eosFrom("type stiffenedGas; gamma 4.4; pInf 6e8;");
    const scalar rho = 1000, p = 1e9, drho = 1e-3;
    const scalar e = eos->e(rho, p);
    const scalar pPlus = eos->p(rho + drho, e + p/(rho*rho)*drho);
    const scalar pMinus = eos->p(rho - drho, e - p/(rho*rho)*drho);
    EXPECT_NEAR((pPlus - pMinus)/(2*drho), eos->c2(rho, p), 1e-6*eos->c2(rho, p));
}


TEST(stiffenedGas, badInputStopsWithMessage)
{
    try
    {
        eosFrom("type stiffenedGas; gamma 0.9; pInf 0;");
        FAIL() << "gamma < 1 accepted";
    }
    catch (const Foam::error& err)
    {
        EXPECT_NE(err.message().find("gamma"), std::string::npos);
        EXPECT_NE(err.message().find("testPhase"), std::string::npos);
    }
    EXPECT_THROW(eosFrom("type perfectFluid; gamma 1.4; pInf 0;"), Foam::error);
    EXPECT_THROW(eosFrom("type stiffenedGas; gamma 1.4;"), Foam::error);
}


TEST(stiffenedGas, isentropicRelaxationFollowsTheIsentrope)
{
    // vIsentropic integrates de = -p dv from (rho0, e0) to p*: check the
    // end state against a fine numerical integration of the isentrope,
    // and the derivative against a central difference
    auto eos = eosFrom("type stiffenedGas; gamma 1.4; pInf 0;");
    const scalar rho0 = 1.2, p0 = 1e5;
    const scalar e0 = eos->e(rho0, p0);
    for (const scalar pStar : {1e3, 3e4, 1e6, 5e8})
    {
        const scalar v = eos->vIsentropic(pStar, rho0, e0);

        // Integrate de/dv = -p(1/v, e) from 1/rho0 to v (RK4, in log v)
        const label n = 20000;
        const scalar s0 = std::log(1/rho0), s1 = std::log(v);
        const scalar ds = (s1 - s0)/n;
        scalar e = e0, s = s0;
        const auto dedS = [&](const scalar ss, const scalar ee)
        {
            const scalar vv = std::exp(ss);
            return -eos->p(1/vv, ee)*vv;
        };
        for (label i = 0; i < n; ++i)
        {
            const scalar k1 = dedS(s, e);
            const scalar k2 = dedS(s + 0.5*ds, e + 0.5*ds*k1);
            const scalar k3 = dedS(s + 0.5*ds, e + 0.5*ds*k2);
            const scalar k4 = dedS(s + ds, e + ds*k3);
            e += ds/6*(k1 + 2*k2 + 2*k3 + k4);
            s += ds;
        }
        EXPECT_NEAR(eos->p(1/v, e), pStar, 1e-9*pStar) << "p* " << pStar;
        EXPECT_NEAR(eos->eIsentropic(1/v, rho0, e0), e, 1e-9*mag(e));

        const scalar dp = 1e-6*pStar;
        const scalar fd =
            (eos->vIsentropic(pStar + dp, rho0, e0)
           - eos->vIsentropic(pStar - dp, rho0, e0))/(2*dp);
        EXPECT_NEAR(eos->dvIsentropicdp(pStar, rho0, e0), fd, 1e-6*mag(fd));
    }
}


TEST(stiffenedGas, fundamentalDerivativeGivesTheShockSpeed)
{
    // Weak shocks: the Rankine-Hugoniot shock speed relative to the
    // upstream state is c (1 + Gamma/2 (p2 - p1)/(rho c^2)) to first order
    auto eos = eosFrom("type stiffenedGas; gamma 4.4; pInf 6e8;");
    const scalar rho1 = 1000, p1 = 1e5;
    const scalar e1 = eos->e(rho1, p1);
    const scalar c2 = eos->c2(rho1, p1);
    const scalar G = eos->fundamentalDerivative(rho1, p1);
    const scalar p2 = p1 + 1e-4*rho1*c2;

    // Hugoniot: e2 - e1 = (p1 + p2)/2 (v1 - v2), solved for v2 by Newton
    scalar v2 = 1/rho1;
    for (int i = 0; i < 50; ++i)
    {
        const scalar f = eos->e(1/v2, p2) - e1 - 0.5*(p1 + p2)*(1/rho1 - v2);
        const scalar h = 1e-9*v2;
        const scalar df =
            (eos->e(1/(v2 + h), p2) - eos->e(1/(v2 - h), p2))/(2*h)
          + 0.5*(p1 + p2);
        v2 -= f/df;
    }
    // Mass flux j^2 = (p2 - p1)/(v1 - v2); shock speed W = j v1
    const scalar W = std::sqrt((p2 - p1)/(1/rho1 - v2))/rho1;
    const scalar predicted =
        std::sqrt(c2)*(1 + 0.5*G*(p2 - p1)/(rho1*c2));
    // Second-order remainder ~ (1e-4)^2
    EXPECT_NEAR(W, predicted, 1e-7*std::sqrt(c2));
}
