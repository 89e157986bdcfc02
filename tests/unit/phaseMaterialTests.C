/*---------------------------------------------------------------------------*\
  Unit tests of the material keyword's merge (phaseMaterial.H,
  docs/materials.md): the phase's keywords on top of the library entry.
  The search and the whole-case equality of a library entry with the same
  dictionary written inline are tests/cases/test_materialLibrary.py.
\*---------------------------------------------------------------------------*/

#include <gtest/gtest.h>
#include "phaseMaterial.H"
#include "unitTestTools.H"

using namespace Foam;
using namespace unitTestTools;

namespace
{

const std::string library
(
    "type solid;"
    "equationOfState { type MieGruneisen; rho0 8930; c0 3940; s 1.489;"
    "  Gamma0 2.02; Cv 383; T0 298; }"
    "elasticity { type metal; rho0 8930; mu 4.6e10; }"
    "plasticity { type vonMises; tau 0;"
    "  yieldStress { type JohnsonCook; A 9e7; B 2.92e8; n 0.31; C 0.025;"
    "  m 1.09; Tr 298; Tm 1356; epsDot0 1; } }"
);

dictionary merged(const std::string& top)
{
    dictionary base(dictFrom(library));
    phaseMaterial::mergeOnto(base, dictFrom(top));
    return base;
}

} // End anonymous namespace


// Nothing on top: the library entry as it is
TEST(phaseMaterial, emptyTopKeepsLibrary)
{
    const dictionary d(merged("material OFHCcopper;"));
    const dictionary lib(dictFrom(library));
    for (const entry& e : lib)
    {
        ASSERT_TRUE(d.found(e.keyword())) << e.keyword();
    }
    EXPECT_EQ(d.subDict("elasticity").get<scalar>("mu"), 4.6e10);
    EXPECT_EQ
    (
        d.subDict("plasticity").subDict("yieldStress").get<scalar>("B"),
        2.92e8
    );
}


// A keyword in a sub-dictionary of the same (or no) type: that keyword only
TEST(phaseMaterial, sameTypeMergesKeywords)
{
    const dictionary d
    (
        merged
        (
            "elasticity { mu 4.8e10; }"
            "plasticity { type vonMises; yieldStress { A 1e8; } }"
        )
    );
    const dictionary& el = d.subDict("elasticity");
    EXPECT_EQ(el.get<scalar>("mu"), 4.8e10);
    EXPECT_EQ(el.get<scalar>("rho0"), 8930);
    EXPECT_EQ(el.get<word>("type"), "metal");
    const dictionary& ys = d.subDict("plasticity").subDict("yieldStress");
    EXPECT_EQ(ys.get<scalar>("A"), 1e8);
    EXPECT_EQ(ys.get<scalar>("B"), 2.92e8);
    EXPECT_EQ(ys.get<word>("type"), "JohnsonCook");
    EXPECT_EQ(d.subDict("plasticity").get<scalar>("tau"), 0);
}


// A sub-dictionary of another type replaces the library's wholly
TEST(phaseMaterial, otherTypeReplaces)
{
    const dictionary d
    (
        merged
        (
            "equationOfState { type stiffenedGas; gamma 4.22; pInf 3.08e10; }"
            "plasticity { yieldStress { type linear; sigmaY0 4e8; H 1e8; } }"
        )
    );
    const dictionary& eos = d.subDict("equationOfState");
    EXPECT_EQ(eos.get<word>("type"), "stiffenedGas");
    EXPECT_FALSE(eos.found("c0"));
    EXPECT_FALSE(eos.found("rho0"));
    const dictionary& ys = d.subDict("plasticity").subDict("yieldStress");
    EXPECT_EQ(ys.get<word>("type"), "linear");
    EXPECT_FALSE(ys.found("B"));
    EXPECT_EQ(ys.get<scalar>("H"), 1e8);
    EXPECT_EQ(d.subDict("plasticity").get<word>("type"), "vonMises");
}


// Plain keywords replace; new keywords and sub-dictionaries are added
TEST(phaseMaterial, plainKeywordsAndAdditions)
{
    const dictionary d
    (
        merged
        (
            "type fluid; passiveScalars (dye);"
            "failure { type spall; sigmaSpall 1.3e9; }"
        )
    );
    EXPECT_EQ(d.get<word>("type"), "fluid");
    EXPECT_EQ(d.get<wordList>("passiveScalars").size(), 1);
    EXPECT_EQ(d.subDict("failure").get<scalar>("sigmaSpall"), 1.3e9);
}
