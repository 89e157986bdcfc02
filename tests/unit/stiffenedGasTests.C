/*---------------------------------------------------------------------------*\
  Unit tests of the stiffened-gas equation of state (VALIDATION.md V7, V9)
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
