/*---------------------------------------------------------------------------*\
  Unit tests of the contact laws between different solids (contactLaw.H,
  solidContacts.H; docs/model.md section 7.5, docs/numerics.md section
  3.4): the selection and its errors, each law's shear limit (the traction
  cap, no tension), the table of pairs, and the face Riemann problem of
  two elastic half-spaces pressed together and sliding, against the exact
  interface traction: welded Z1 Z2 V/(Z1 + Z2), frictionless 0, Coulomb
  min(mu p0, welded), with non-negative slip work.
\*---------------------------------------------------------------------------*/

#include <gtest/gtest.h>
#include "contactLaw.H"
#include "solidContacts.H"
#include "riemannSolver.H"
#include "unitTestTools.H"

using namespace Foam;
using unitTestTools::dictFrom;

namespace
{

autoPtr<contactLaw> lawFrom(const std::string& text)
{
    const dictionary dict(dictFrom("law " + text));
    return contactLaw::New(*dict.findEntry("law"), "test");
}


//- An elastic half-space in the face frame: stiffened-gas pressure p0
//  (no deviatoric traction), tangential velocity vt along the first
//  tangent
riemannState halfSpace
(
    const double rho,
    const double gamma,
    const double pInf,
    const double cT,
    const double p0,
    const double vt
)
{
    riemannState K;
    K.rho = rho;
    K.v = cobasis::vector(0, vt, 0);
    K.s = cobasis::vector(-p0, 0, 0);
    const double e = (p0 + gamma*pInf)/((gamma - 1)*rho);
    K.E = e + 0.5*vt*vt;
    K.a = std::sqrt(gamma*(p0 + pInf)/rho + 4.0/3.0*cT*cT);
    K.cT = cT;
    K.G = 0.5*(gamma + 1);
    K.strength = GREAT;
    K.solid = true;
    return K;
}

// Aluminium 6061-T6 and steel 4340, stiffened-gas fits (shear speeds from
// their shear moduli 26 and 77.5 GPa)
const double p0 = 1e8;
const double V = 20;

riemannState aluminium(const double vt)
{
    return halfSpace(2703, 3.4, 2.15e10, std::sqrt(26e9/2703), p0, vt);
}

riemannState steel(const double vt)
{
    return halfSpace(7830, 4.4, 3.6e10, std::sqrt(77.5e9/7830), p0, vt);
}

double weldedTraction()
{
    const double Z1 = 2703*std::sqrt(26e9/2703);
    const double Z2 = 7830*std::sqrt(77.5e9/7830);
    return Z1*Z2*V/(Z1 + Z2);
}

} // End anonymous namespace


TEST(contactLaw, selectsByNameOrDictionaryAndChecksEntries)
{
    EXPECT_EQ(lawFrom("welded;")->type(), "welded");
    EXPECT_EQ(lawFrom("frictionless;")->type(), "frictionless");
    EXPECT_EQ(lawFrom("{ type coulomb; mu 0.3; }")->type(), "coulomb");

    const std::vector<std::pair<std::string, std::string>> bad
    {
        {"sticky;", "sticky"},                       // unknown law
        {"{ mu 0.3; }", "no type"},                  // no type
        {"{ type coulomb; }", "mu"},                 // coulomb needs mu
        {"{ type coulomb; mu -0.1; }", "-0.1"},      // negative mu
        {"{ type coulomb; mu 0.1; muu 2; }", "muu"}, // unknown entry
        {"coulomb 0.1;", "more than one word"}
    };
    for (const auto& b : bad)
    {
        try
        {
            lawFrom(b.first);
            FAIL() << "accepted: " << b.first;
        }
        catch (const Foam::error& err)
        {
            EXPECT_NE(err.message().find(b.second), std::string::npos)
                << b.first << ": " << err.message();
        }
    }
}


TEST(contactLaw, shearLimitOfEachLaw)
{
    const double strength = 2e8;
    EXPECT_TRUE(lawFrom("welded;")->sticks());
    EXPECT_TRUE(std::isinf(lawFrom("welded;")->shearLimit(-1e9, strength)));

    const autoPtr<contactLaw> none(lawFrom("frictionless;"));
    EXPECT_FALSE(none->sticks());
    EXPECT_EQ(none->shearLimit(-1e9, strength), 0);

    const autoPtr<contactLaw> c(lawFrom("{ type coulomb; mu 0.25; }"));
    EXPECT_FALSE(c->sticks());
    EXPECT_DOUBLE_EQ(c->shearLimit(-4e8, strength), 1e8);  // mu p
    EXPECT_DOUBLE_EQ(c->shearLimit(-4e9, strength), 2e8);  // strength cap
    EXPECT_EQ(c->shearLimit(+1e8, strength), 0);           // tension
    EXPECT_EQ(lawFrom("{ type coulomb; mu 0; }")->shearLimit(-1e9, 1e9), 0);

    // The cap on a traction vector keeps its normal part and direction
    cobasis::vector t(-4e8, 3e8, -4e8);
    const double f = c->limitShear(t, strength);
    EXPECT_DOUBLE_EQ(f, 1e8/5e8);
    EXPECT_DOUBLE_EQ(t(0), -4e8);
    EXPECT_DOUBLE_EQ(t(1), 0.6e8);
    EXPECT_DOUBLE_EQ(t(2), -0.8e8);
    cobasis::vector small(-4e8, 3e7, 0);
    EXPECT_EQ(c->limitShear(small, strength), 1);
    EXPECT_EQ(small(1), 3e7);
}


TEST(solidContacts, tableOfPairsAndItsErrors)
{
    const wordList names({"rod", "plate", "air", "liner"});
    const boolList solid({true, true, false, true});

    {
        const solidContacts none(dictFrom(""), names, solid);
        EXPECT_FALSE(none.any());
        EXPECT_EQ(none.law(0, 1), nullptr);
    }
    {
        const solidContacts c
        (
            dictFrom
            (
                "contacts { default frictionless;"
                " plate.rod { type coulomb; mu 0.1; } liner.plate welded; }"
            ),
            names, solid
        );
        EXPECT_TRUE(c.any());
        EXPECT_TRUE(c.usesStrength());
        ASSERT_NE(c.law(0, 1), nullptr);
        EXPECT_EQ(c.law(0, 1), c.law(1, 0));
        EXPECT_EQ(c.law(0, 1)->type(), "coulomb");
        EXPECT_EQ(c.law(0, 3)->type(), "frictionless");   // the default
        EXPECT_EQ(c.law(1, 3), nullptr);                  // welded
        EXPECT_EQ(c.law(0, 2), nullptr);                  // a fluid
        EXPECT_EQ(c.law(0, 0), nullptr);                  // itself
    }

    const std::vector<std::pair<std::string, std::string>> bad
    {
        {"contacts { rod.plat frictionless; }", "plate"},   // nearest
        {"contacts { rod.air frictionless; }", "fluid"},
        {"contacts { rod.rod frictionless; }", "two different"},
        {"contacts { rodplate frictionless; }", "pair of phases"},
        {"contacts { rod.plate welded; plate.rod frictionless; }", "twice"},
        {"contacts { default { type coulomb; } }", "mu"}
    };
    for (const auto& b : bad)
    {
        try
        {
            solidContacts(dictFrom(b.first), names, solid);
            FAIL() << "accepted: " << b.first;
        }
        catch (const Foam::error& err)
        {
            EXPECT_NE(err.message().find(b.second), std::string::npos)
                << b.first << ": " << err.message();
        }
    }
}


TEST(contactLaw, slidingHalfSpacesGiveTheExactInterfaceTraction)
{
    const autoPtr<contactLaw> frictionless(lawFrom("frictionless;"));
    const autoPtr<contactLaw> weak(lawFrom("{ type coulomb; mu 0.05; }"));
    const autoPtr<contactLaw> strong(lawFrom("{ type coulomb; mu 5; }"));
    const double welded = weldedTraction();
    ASSERT_LT(0.05*p0, welded);
    ASSERT_GT(5*p0, welded);

    for (const char* name : {"HLLC", "HLL"})
    {
        const autoPtr<riemannSolver> solver
        (
            riemannSolver::New(dictFrom(std::string("riemannSolver ") + name + ";"))
        );
        // Aluminium left moving +V/2, steel right moving -V/2; the
        // traction on the interface opposes the relative motion
        const riemannState L(aluminium(0.5*V));
        const riemannState R(steel(-0.5*V));

        const struct { const contactLaw* law; double expected; } cases[] =
        {
            {nullptr, welded},
            {frictionless.get(), 0},
            {weak.get(), 0.05*p0},
            {strong.get(), welded}
        };
        for (const auto& c : cases)
        {
            const riemannSolution sol = solver->solve(L, R, false, c.law);
            SCOPED_TRACE(std::string(name) + " " + (c.law ? c.law->type() : "welded"));

            // Normal part untouched: u* = 0, t*_n = -p0
            EXPECT_NEAR(sol.uStar, 0, 1e-12);
            EXPECT_NEAR(sol.tStar(0), -p0, 1e-6*p0);
            EXPECT_NEAR(-sol.tStar(1), c.expected, 1e-9*welded);
            EXPECT_EQ(sol.tStar(2), 0);

            // Each side's star velocity from its own shear impedance;
            // the slip work t.(v*_R - v*_L) is never negative, zero
            // when welded
            const double slipWork =
                sol.tStar(1)*(sol.vStarR(1) - sol.vStarL(1));
            EXPECT_GE(slipWork, -1e-9*welded*V);
            if (c.expected == welded)
            {
                EXPECT_NEAR(sol.vStarL(1), sol.vStarR(1), 1e-9*V);
            }
            if (c.law == frictionless.get())
            {
                EXPECT_NEAR(sol.vStarL(1), 0.5*V, 1e-12*V);
                EXPECT_NEAR(sol.vStarR(1), -0.5*V, 1e-12*V);
            }
        }
    }
}


// ************************************************************************* //
