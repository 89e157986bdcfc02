/*---------------------------------------------------------------------------*\
  Unit tests of the regime rules (phaseRegimes, docs/numerics.md section
  8.1): each rule on the states of one cell or face side (a trace, a heavy
  metal film, a hot gas pocket, metal dust, a gas film along a solid's free
  surface, debris) gives the regime the table says; the thresholds' defaults
  and bounds.
\*---------------------------------------------------------------------------*/

#include <gtest/gtest.h>
#include "phaseRegimes.H"
#include "unitTestTools.H"

#include <string>

using namespace Foam;
using unitTestTools::dictFrom;

namespace
{

// Two phases: 0 copper (a solid, rho0 8930), 1 air
const scalar rho0Cu = 8930;

phaseRegimes regimes(const std::string& text)
{
    phaseRegimes r(dictFrom(text));
    r.setReferenceDensities(List<scalar>({rho0Cu, 0}));
    return r;
}

void expectError(const std::string& text, const std::string& key)
{
    try
    {
        regimes(text);
        ADD_FAILURE() << "accepted: " << text;
    }
    catch (const Foam::error& err)
    {
        const std::string msg(err.message());
        EXPECT_NE(msg.find(key), std::string::npos) << msg;
    }
}

} // End anonymous namespace


TEST(phaseRegimes, defaults)
{
    const phaseRegimes r(regimes(""));
    EXPECT_EQ(r.alphaMin(), 1e-8);
    EXPECT_EQ(r.alphaTrace(), 1e-6);
    EXPECT_EQ(r.alphaMinor(), 1e-3);
    EXPECT_EQ(r.pVacuum(), 1);
    EXPECT_TRUE(r.vacuumFloor());
    EXPECT_TRUE(r.gasTraces());
    EXPECT_EQ(phaseRegimes::keywords.size(), 7);
}


TEST(phaseRegimes, trace)
{
    const phaseRegimes r(regimes(""));
    EXPECT_TRUE(r.trace(5e-7));
    EXPECT_FALSE(r.trace(2e-6));
    // A trace is unresolved whatever its mass (it has no state of its own)
    EXPECT_TRUE(r.unresolved(0, 5e-7, 5e-7*rho0Cu, 1.2));
}


TEST(phaseRegimes, heavyMetalFilmIsResolved)
{
    // Copper at alpha 5e-4 and rho0 in air at 1.2 kg/m^3: 4.465 of 5.66
    // kg/m^3, most of the cell's mass; thin (no slopes) but resolved
    const phaseRegimes r(regimes("dustDensityRatio 0;"));
    const scalar aCu = 5e-4, mCu = aCu*rho0Cu, mAir = (1 - aCu)*1.2;
    EXPECT_TRUE(r.thin(aCu));
    EXPECT_FALSE(r.unresolved(0, aCu, mCu, mCu + mAir));
    // The air of that cell is not minor either
    EXPECT_FALSE(r.unresolved(1, 1 - aCu, mAir, mCu + mAir));
    // A light copper film (below alphaMinor of the mass too) is
    const scalar aLight = 1e-7*1.2/rho0Cu*1e4;
    EXPECT_TRUE
    (
        r.unresolved(0, aLight, aLight*rho0Cu, aLight*rho0Cu + 1.2)
    );
}


TEST(phaseRegimes, hotGasPocketIsUnresolved)
{
    // Air at alpha 0.01 and 1e-4 kg/m^3 in copper: a mass fraction of
    // 1e-7, below massFractionMinor, whatever its volume
    const phaseRegimes r(regimes(""));
    const scalar mAir = 0.01*1e-4, mCu = 0.99*rho0Cu;
    EXPECT_FALSE(r.thin(0.01));
    EXPECT_TRUE(r.unresolved(1, 0.01, mAir, mAir + mCu));
    EXPECT_TRUE(r.negligible(0.01, mAir, mAir + mCu));
    EXPECT_TRUE(r.lightGas(mAir, mAir + mCu));
}


TEST(phaseRegimes, metalDust)
{
    // Copper at alpha 2e-5 and 0.2 rho0 in air thinned to 0.5 kg/m^3: 6.7 %
    // of the cell's mass, so not minor by mass; dust below 0.5 rho0
    const scalar a = 2e-5, m = a*0.2*rho0Cu, mMix = m + 0.5;
    EXPECT_GT(m, 1e-3*mMix);
    EXPECT_TRUE(regimes("dustDensityRatio 0.5;").unresolved(0, a, m, mMix));
    EXPECT_FALSE(regimes("dustDensityRatio 0;").unresolved(0, a, m, mMix));
    // The same copper at rho0 is a film, not dust
    const scalar mDense = a*rho0Cu;
    EXPECT_FALSE
    (
        regimes("dustDensityRatio 0.5;")
       .unresolved(0, a, mDense, mDense + 0.5)
    );
    // The default ratio, 0.8: copper at 0.75 rho0 is dust, at 0.85 rho0 not
    const phaseRegimes byDefault(regimes(""));
    EXPECT_TRUE(byDefault.unresolved(0, a, a*0.75*rho0Cu, a*0.75*rho0Cu + 0.5));
    EXPECT_FALSE
    (
        byDefault.unresolved(0, a, a*0.85*rho0Cu, a*0.85*rho0Cu + 0.5)
    );
    // A fluid is never dust (its dust density is 0)
    EXPECT_FALSE
    (
        regimes("dustDensityRatio 0.5;").unresolved(1, 5e-4, 5e-4*1.2, 0.5)
    );
}


TEST(phaseRegimes, gasFilmAlongAFreeSurface)
{
    const phaseRegimes r(regimes(""));
    // Copper at alpha 0.7 near rho0: air holding less volume is a trace
    const scalar bound = r.gasTraceAlpha(0.7, 0.7*0.98*rho0Cu, rho0Cu);
    EXPECT_EQ(bound, 0.7);
    EXPECT_TRUE(0.3 < bound);
    // Debris below half its rho0 is no free surface
    EXPECT_EQ(r.gasTraceAlpha(0.7, 0.7*0.4*rho0Cu, rho0Cu), 0);
    // gasTraceRatio 0: off
    const phaseRegimes off(regimes("gasTraceRatio 0;"));
    EXPECT_FALSE(off.gasTraces());
    EXPECT_EQ(off.gasTraceAlpha(0.7, 0.7*rho0Cu, rho0Cu), 0);
}


TEST(phaseRegimes, negligibleAndVoid)
{
    const phaseRegimes r(regimes(""));
    EXPECT_TRUE(r.negligible(5e-4, 5e-4*rho0Cu, 10));
    EXPECT_FALSE(r.negligible(0.5, 0.6, 10));
    EXPECT_TRUE(r.negligible(0.5, 5e-6, 10));
    EXPECT_FALSE(regimes("pVacuum -1;").vacuumFloor());
    EXPECT_TRUE(r.mixed(0.5));
    EXPECT_FALSE(r.mixed(5e-4));
    EXPECT_FALSE(r.mixed(1 - 5e-4));
}


TEST(phaseRegimes, badValues)
{
    expectError("alphaTrace 1e-2;", "alphaTrace");
    expectError("massFractionMinor 2;", "massFractionMinor (2)");
    expectError("gasTraceRatio -1;", "gasTraceRatio >= 0, not -1");
    expectError("dustDensityRatio 1.5;", "dustDensityRatio < 1, not 1.5");
    // A removed entry warns and is ignored
    EXPECT_NO_THROW(regimes("massFractionTrace 1e-5;"));
}
