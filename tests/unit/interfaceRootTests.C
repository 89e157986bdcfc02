/*---------------------------------------------------------------------------*\
  Unit tests of the pressure relaxation's root finder (interfaceRoot.H,
  docs/numerics.md section 9.5): the root of a volume function like a
  stiffened gas's, and the cells that have none (every phase held at its
  floor or at its largest volume, so F is flat). With floating-point traps
  on, as in impactFoam (FOAM_SIGFPE), none of these may raise a signal:
  a cell without a root returns false and takes the path of every failed
  state check.
\*---------------------------------------------------------------------------*/

#include <gtest/gtest.h>
#include "interfaceRoot.H"

#include <cfenv>
#include <cmath>

using namespace Foam;

namespace
{

//- Floating-point traps on for the scope of a test (as FOAM_SIGFPE sets
//  them in the solver), off again after it
struct trapsOn
{
    static constexpr int traps = FE_DIVBYZERO | FE_INVALID | FE_OVERFLOW;

    trapsOn()
    {
        std::feclearexcept(FE_ALL_EXCEPT);
        feenableexcept(traps);
    }

    ~trapsOn()
    {
        fedisableexcept(traps);
    }
};

} // End anonymous namespace


// A stiffened gas on its constant-pressure path at fixed (p + pInf) v
// takes v = c/(p + pInf): F = m c/(p + pInf) - 1 has the root
// p = m c - pInf, above the lowest pressure -pInf
TEST(interfaceRoot, stiffenedGasLikeRoot)
{
    trapsOn guard;
    const scalar m = 8900, c = 4.0e6/8900, pInf = 3.42e10;
    const auto F = [&](const scalar p, scalar& dF)
    {
        dF = -m*c/sqr(p + pInf);
        return m*c/(p + pInf) - 1;
    };
    scalar p = 1e9;
    ASSERT_TRUE(interfaceRoot(F, -pInf, pInf, 1e-12, p));
    EXPECT_NEAR(p, m*c - pInf, 1e-9*pInf);
}


// A phase capped at its largest volume below some pressure (a metal at
// half its reference density) and one that still responds: F is flat
// below the cap's pressure, and the root above it is found
TEST(interfaceRoot, rootAboveAFlatBranch)
{
    trapsOn guard;
    const scalar K = 7.4e10, vMax = 0.3;
    const auto F = [&](const scalar p, scalar& dF)
    {
        // phase 1: v = 0.4 (1 - p/K), at most vMax... held at vMax below
        // p = K/4; phase 2: v = 0.6 (1 - p/(2K))
        scalar v1 = 0.4*(1 - p/K), dv1 = -0.4/K;
        if (v1 > vMax) { v1 = vMax; dv1 = 0; }
        const scalar v2 = 0.6*(1 - p/(2*K)), dv2 = -0.6/(2*K);
        dF = dv1 + dv2;
        return v1 + v2 - 0.95;
    };
    scalar p = 0;
    ASSERT_TRUE(interfaceRoot(F, -GREAT, K, 1e-12, p));
    scalar dF;
    EXPECT_LT(std::abs(F(p, dF)), 1e-12);
}


// Every phase held: F flat and positive (the phases need more volume than
// the cell has at any pressure): no root, no trap, false
TEST(interfaceRoot, flatAbove)
{
    trapsOn guard;
    const auto F = [](const scalar, scalar& dF)
    {
        dF = 0;
        return 0.03;
    };
    scalar p = -5e9;
    EXPECT_FALSE(interfaceRoot(F, -GREAT, 1e11, 1e-12, p));
}


// Every phase held: F flat and negative (a failed metal that gave up
// volume nothing can take): no root, no trap, and no false root at the
// lower bound
TEST(interfaceRoot, flatBelow)
{
    trapsOn guard;
    const auto F = [](const scalar, scalar& dF)
    {
        dF = 0;
        return -0.03;
    };
    scalar p = -5e9;
    EXPECT_FALSE(interfaceRoot(F, -GREAT, 1e11, 1e-12, p));
    p = 1e5;
    EXPECT_FALSE(interfaceRoot(F, 0, 1e11, 1e-12, p));
}


// The guess outside the bracket and no guess at all (no phase with a
// volume fraction): started just above the lower bound
TEST(interfaceRoot, guessBelowTheBound)
{
    trapsOn guard;
    const auto F = [](const scalar p, scalar& dF)
    {
        // An ideal gas, (p v) fixed: v = 1e5/p
        dF = -1e5/sqr(p);
        return 1e5/p - 2;
    };
    scalar p = -1;
    ASSERT_TRUE(interfaceRoot(F, 0, 1e5, 1e-12, p));
    EXPECT_NEAR(p, 5e4, 1e-9*5e4);
}


// ************************************************************************* //
