/*---------------------------------------------------------------------------*\
  Unit tests of bad material input (docs/validation.md V9, library part): every
  invalid phase or plasticity dictionary stops with a FatalError (thrown as
  Foam::error here) whose message names the problem.
\*---------------------------------------------------------------------------*/

#include <gtest/gtest.h>
#include "hyperelasticPhase.H"
#include "plasticModel.H"
#include "unitTestTools.H"

#include <functional>
#include <utility>
#include <string>
#include <vector>

using namespace Foam;
using namespace unitTestTools;

namespace
{

const std::string copperEos
(
    "equationOfState { type stiffenedGas; gamma 4.22; pInf 3.42e10; }"
);

//- A phase dictionary: type, equation of state, elasticity entry
std::string phaseText
(
    const std::string& type,
    const std::string& elasticity,
    const std::string& eos = copperEos
)
{
    std::string text("type " + type + "; " + eos);
    if (!elasticity.empty())
    {
        text += " elasticity { " + elasticity + " }";
    }
    return text;
}

//- Call fun, expect a Foam::error whose message contains every key word
void expectError
(
    const std::function<void()>& fun,
    const std::vector<std::string>& keyWords,
    const std::string& what
)
{
    try
    {
        fun();
        ADD_FAILURE() << "accepted: " << what;
    }
    catch (const Foam::error& err)
    {
        const std::string msg(err.message());
        for (const std::string& key : keyWords)
        {
            EXPECT_NE(msg.find(key), std::string::npos)
                << what << ": message does not contain '" << key << "':\n"
                << msg;
        }
    }
}

void expectPhaseError
(
    const std::string& name,
    const std::string& text,
    const std::vector<std::string>& keyWords
)
{
    expectError
    (
        [&]() { hyperelasticPhase phase(name, dictFrom(text)); },
        keyWords,
        "phase " + name + " { " + text + " }"
    );
}

void expectPlasticityError
(
    const std::string& text,
    const std::vector<std::string>& keyWords
)
{
    expectError
    (
        [&]() { plasticModel::New("copper", dictFrom(text)); },
        keyWords,
        "plasticity { " + text + " }"
    );
}

} // End anonymous namespace


TEST(badInput, validInputIsAccepted)
{
    // The reference dictionaries the other tests spoil one entry at a time
    EXPECT_NO_THROW
    (
        hyperelasticPhase
        (
            "copper",
            dictFrom(phaseText("solid", "type separable; rho0 8900; mu 4.5e10; a 0.5;"))
        )
    );
    EXPECT_NO_THROW(hyperelasticPhase("water", dictFrom(phaseText("fluid", ""))));
    for (const char* a : {"-1", "0.5", "0"})
    {
        EXPECT_NO_THROW
        (
            hyperelasticPhase
            (
                "copper",
                dictFrom
                (
                    phaseText
                    (
                        "solid",
                        std::string("type separable; rho0 8900; mu 4.5e10; a ")
                      + a + ";"
                    )
                )
            )
        ) << "a = " << a;
    }
    EXPECT_NO_THROW(plasticModel::New("copper", dictFrom("type vonMises; sigmaY 4e8; tau 0;")));
    EXPECT_NO_THROW
    (
        plasticModel::New
        (
            "copper",
            dictFrom("type vonMises; sigmaY0 4e8; H 1e8; tau 1e-6; n 2;")
        )
    );
    EXPECT_NO_THROW
    (
        plasticModel::New
        (
            "copper",
            dictFrom
            (
                "type vonMises; yieldStress { type constant; sigmaY 4e8; }"
                " tau 0;"
            )
        )
    );
    EXPECT_NO_THROW
    (
        plasticModel::New
        (
            "copper",
            dictFrom
            (
                "type vonMises;"
                " yieldStress { type linear; sigmaY0 4e8; H 0; }"
                " tau 1e-6; n 2;"
            )
        )
    );
    EXPECT_NO_THROW(plasticModel::New("copper", dictFrom("type none;")));
}


TEST(badInput, aOutsideHyperbolicRange)
{
    expectPhaseError
    (
        "copper",
        phaseText("solid", "type separable; rho0 8900; mu 4.5e10; a 0.7;"),
        {"a = 0.7", "copper", "[-1, 1/2]"}
    );
    expectPhaseError
    (
        "jelly",
        phaseText("solid", "type separable; rho0 1000; mu 1e4; a -1.2;"),
        {"a = -1.2", "jelly", "[-1, 1/2]"}
    );
    // Just outside the closed interval
    expectPhaseError
    (
        "copper",
        phaseText("solid", "type separable; rho0 8900; mu 4.5e10; a 0.5000001;"),
        {"a = ", "copper"}
    );
    expectPhaseError
    (
        "copper",
        phaseText("solid", "type separable; rho0 8900; mu 4.5e10; a -1.0000001;"),
        {"a = ", "copper"}
    );
    // A preset contradicted by its own dictionary
    expectPhaseError
    (
        "copper",
        phaseText("solid", "type metal; rho0 8900; mu 4.5e10; a 0.3;"),
        {"a = ", "copper", "metal"}
    );
    expectPhaseError
    (
        "clay",
        phaseText("solid", "type neoHookean; rho0 1800; mu 1e6; a 0;"),
        {"a = ", "clay", "neoHookean"}
    );
}


TEST(badInput, nonPhysicalElasticConstants)
{
    expectPhaseError
    (
        "copper",
        phaseText("solid", "type separable; rho0 8900; mu -4.5e10; a 0.5;"),
        {"mu", "copper"}
    );
    expectPhaseError
    (
        "clay",
        phaseText("solid", "type neoHookean; rho0 1800; mu -1;"),
        {"mu", "clay"}
    );
    expectPhaseError
    (
        "copper",
        phaseText("solid", "type metal; rho0 0; mu 4.5e10;"),
        {"rho0", "copper"}
    );
    expectPhaseError
    (
        "copper",
        phaseText("solid", "type metal; rho0 -8900; mu 4.5e10;"),
        {"rho0", "copper"}
    );
    // Equation of state of a solid phase
    expectPhaseError
    (
        "copper",
        phaseText
        (
            "solid",
            "type metal; rho0 8900; mu 4.5e10;",
            "equationOfState { type stiffenedGas; gamma 1; pInf 3.42e10; }"
        ),
        {"gamma", "copper"}
    );
}


TEST(badInput, missingKeywords)
{
    // OpenFOAM's own message: "Entry 'rho0' not found in dictionary ..."
    expectPhaseError
    (
        "copper",
        phaseText("solid", "type separable; mu 4.5e10; a 0.5;"),
        {"rho0"}
    );
    expectPhaseError
    (
        "copper",
        phaseText("solid", "type separable; rho0 8900; a 0.5;"),
        {"mu"}
    );
    expectPhaseError
    (
        "copper",
        phaseText("solid", "type separable; rho0 8900; mu 4.5e10;"),
        {"'a'"}
    );
    expectPhaseError
    (
        "copper",
        phaseText("solid", "rho0 8900; mu 4.5e10; a 0.5;"),
        {"type"}
    );
    // Solid without elasticity, phase without equation of state or type
    expectPhaseError("copper", phaseText("solid", ""), {"elasticity"});
    expectPhaseError
    (
        "copper",
        "type solid; elasticity { type metal; rho0 8900; mu 4.5e10; }",
        {"equationOfState"}
    );
    expectPhaseError
    (
        "copper",
        copperEos + " elasticity { type metal; rho0 8900; mu 4.5e10; }",
        {"type"}
    );

    // Plasticity
    expectPlasticityError("type vonMises; sigmaY 4e8;", {"tau"});
    expectPlasticityError("type vonMises; tau 0;", {"sigmaY", "copper"});
    expectPlasticityError("sigmaY 4e8; tau 0;", {"type"});
}


TEST(badInput, nonPhysicalPlasticity)
{
    expectPlasticityError
    (
        "type vonMises; sigmaY 0; tau 0;", {"sigmaY", "copper"}
    );
    expectPlasticityError
    (
        "type vonMises; sigmaY -4e8; tau 0;", {"sigmaY", "copper"}
    );
    expectPlasticityError
    (
        "type vonMises; sigmaY0 0; H 1e8; tau 0;", {"sigmaY0", "copper"}
    );
    expectPlasticityError
    (
        "type vonMises; sigmaY 4e8; sigmaY0 4e8; tau 0;",
        {"sigmaY", "sigmaY0", "copper"}
    );
    expectPlasticityError
    (
        "type vonMises; sigmaY 4e8; tau -1e-6;", {"tau", "copper"}
    );
    expectPlasticityError
    (
        "type vonMises; sigmaY0 4e8; H -1e8; tau 0;", {"H", "copper"}
    );
    expectPlasticityError
    (
        "type vonMises; sigmaY 4e8; tau 1e-6; n -1;", {"n = ", "copper"}
    );
}


TEST(badInput, unknownTypeNames)
{
    expectPhaseError
    (
        "copper",
        phaseText("solid", "type hookean; rho0 8900; mu 4.5e10; a 0.5;"),
        {"hookean", "elasticity", "copper", "separable"}
    );
    expectPhaseError
    (
        "copper",
        phaseText("gel", "type metal; rho0 8900; mu 4.5e10;"),
        {"gel", "copper", "solid", "fluid"}
    );
    expectPhaseError
    (
        "copper",
        phaseText
        (
            "solid",
            "type metal; rho0 8900; mu 4.5e10;",
            "equationOfState { type mieGruneisen; gamma 2; pInf 0; }"
        ),
        {"mieGruneisen", "equationOfState", "copper"}
    );
    expectPlasticityError
    (
        "type johnsonCook; sigmaY 4e8; tau 0;",
        {"johnsonCook", "plasticity", "copper", "vonMises"}
    );
}


TEST(badInput, fluidWithElasticity)
{
    expectPhaseError
    (
        "water",
        phaseText("fluid", "type separable; rho0 1000; mu 1e6; a 0;"),
        {"water", "fluid", "elasticity"}
    );
}


TEST(badInput, yieldStress)
{
    // The yieldStress sub-dictionary: every message names the phase and
    // the entry
    expectPlasticityError
    (
        "type vonMises; yieldStress { type johnsonCook; A 9e7; } tau 0;",
        {"johnsonCook", "yieldStress", "copper", "constant", "linear"}
    );
    expectPlasticityError
    (
        "type vonMises; yieldStress { sigmaY 4e8; } tau 0;",
        {"yieldStress", "type", "copper", "constant", "linear"}
    );
    expectPlasticityError
    (
        "type vonMises; yieldStress { type constant; } tau 0;",
        {"yieldStress", "constant", "sigmaY", "copper"}
    );
    expectPlasticityError
    (
        "type vonMises; yieldStress { type constant; sigmaY 0; } tau 0;",
        {"yieldStress", "sigmaY = 0", "positive", "copper"}
    );
    expectPlasticityError
    (
        "type vonMises; yieldStress { type constant; sigmaY -4e8; } tau 0;",
        {"yieldStress", "sigmaY = -4e+08", "copper"}
    );
    expectPlasticityError
    (
        "type vonMises; yieldStress { type linear; sigmaY0 4e8; } tau 0;",
        {"yieldStress", "linear", "H", "copper"}
    );
    expectPlasticityError
    (
        "type vonMises; yieldStress { type linear; H 1e8; } tau 0;",
        {"yieldStress", "linear", "sigmaY0", "copper"}
    );
    expectPlasticityError
    (
        "type vonMises; yieldStress { type linear; sigmaY0 0; H 1e8; } tau 0;",
        {"yieldStress", "sigmaY0 = 0", "positive", "copper"}
    );
    expectPlasticityError
    (
        "type vonMises; yieldStress { type linear; sigmaY0 4e8; H -1e8; }"
        " tau 0;",
        {"yieldStress", "H = -1e+08", "non-negative", "copper"}
    );

    // Not a sub-dictionary
    expectPlasticityError
    (
        "type vonMises; yieldStress 4e8; tau 0;",
        {"yieldStress", "sub-dictionary", "copper"}
    );

    // The flow stress given twice
    for (const std::string entry : {"sigmaY 4e8;", "sigmaY0 4e8;", "H 1e8;"})
    {
        expectPlasticityError
        (
            "type vonMises; yieldStress { type constant; sigmaY 4e8; } "
          + entry + " tau 0;",
            {"yieldStress", entry.substr(0, entry.find(' ')), "copper"}
        );
    }

    // The relaxation rate stays an entry of vonMises
    expectPlasticityError
    (
        "type vonMises; yieldStress { type constant; sigmaY 4e8; }",
        {"tau"}
    );
    expectPlasticityError
    (
        "type vonMises; yieldStress { type constant; sigmaY 4e8; } tau -1;",
        {"tau", "copper"}
    );

    // Neither the original entries nor the sub-dictionary: the message
    // points at both
    expectPlasticityError
    (
        "type vonMises; tau 0;", {"sigmaY", "sigmaY0", "yieldStress", "copper"}
    );
}


TEST(badInput, tableYieldStress)
{
    // Every message names the phase and the entry (values) and says what
    // is wrong
    const auto table = [](const std::string& values)
    {
        return
            "type vonMises; yieldStress { type table; " + values
          + " } tau 0;";
    };
    expectPlasticityError(table(""), {"copper", "table", "values"});
    expectPlasticityError
    (
        table("values ();"), {"copper", "values", "at least one pair"}
    );
    expectPlasticityError
    (
        table("values ((0.01 9e7) (0.1 2.2e8));"),
        {"copper", "values", "epsP = 0.01", "epsP = 0"}
    );
    expectPlasticityError
    (
        table("values ((0 0) (0.1 2.2e8));"),
        {"copper", "values", "first stress", "positive"}
    );
    expectPlasticityError
    (
        table("values ((0 -9e7) (0.1 2.2e8));"),
        {"copper", "values", "first stress", "positive"}
    );
    expectPlasticityError
    (
        table("values ((0 9e7) (0.1 2.2e8) (0.1 3.3e8));"),
        {"copper", "values", "strictly increasing", "pair 2"}
    );
    expectPlasticityError
    (
        table("values ((0 9e7) (0.5 2.2e8) (0.1 3.3e8));"),
        {"copper", "values", "strictly increasing", "pair 2"}
    );
    expectPlasticityError
    (
        table("values ((0 9e7) (0.1 -2.2e8));"),
        {"copper", "values", "negative", "pair 1"}
    );
}


TEST(badInput, JohnsonCookYieldStress)
{
    // Each entry missing and each bad value: the message names the phase
    // and the entry
    const std::vector<std::pair<std::string, std::string>> entries
    {
        {"A", "9e7"}, {"B", "2.92e8"}, {"n", "0.31"}, {"C", "0.025"},
        {"m", "1.09"}, {"Tr", "298"}, {"Tm", "1356"}, {"epsDot0", "1"}
    };
    const auto jc = [&](const std::string& key, const std::string& value)
    {
        std::string text("type vonMises; yieldStress { type JohnsonCook;");
        for (const auto& e : entries)
        {
            if (e.first == key)
            {
                if (!value.empty())
                {
                    text += " " + key + " " + value + ";";
                }
            }
            else
            {
                text += " " + e.first + " " + e.second + ";";
            }
        }
        return text + " } tau 0;";
    };

    // The valid set is accepted, and so are the optional entries left out
    plasticModel::New("copper", dictFrom(jc("", "")));
    plasticModel::New("copper", dictFrom(jc("C", "")));
    plasticModel::New("copper", dictFrom(jc("epsDot0", "")));

    // Required entries missing
    for (const std::string key : {"A", "B", "n", "m", "Tr", "Tm"})
    {
        expectPlasticityError
        (
            jc(key, ""), {"copper", "JohnsonCook", "needs the entry " + key}
        );
    }

    // Bad values
    const std::vector<std::vector<std::string>> bad
    {
        {"A", "-1e7", "A = -1e+07", "non-negative"},
        {"B", "-2e8", "B = -2e+08", "non-negative"},
        {"n", "0", "n = 0", "positive"},
        {"n", "-0.3", "n = -0.3", "positive"},
        {"m", "0", "m = 0", "positive"},
        {"m", "-1", "m = -1", "positive"},
        {"C", "-0.01", "C = -0.01", "non-negative"},
        {"epsDot0", "0", "epsDot0 = 0", "positive"},
        {"epsDot0", "-1", "epsDot0 = -1", "positive"},
        {"Tm", "298", "Tm = 298", "Tr = 298"},
        {"Tm", "200", "Tm = 200", "Tr = 298"},
        {"Tr", "-1", "Tr = -1", "non-negative"}
    };
    for (const auto& b : bad)
    {
        expectPlasticityError(jc(b[0], b[1]), {"copper", b[2], b[3]});
    }

    // No strength at any strain
    std::string noStrength(jc("A", "0"));
    noStrength.replace(noStrength.find("B 2.92e8"), 8, "B 0");
    expectPlasticityError(noStrength, {"copper", "A = 0", "B = 0"});
}


TEST(badInput, MieGruneisen)
{
    // The MieGruneisen keywords of docs/model.md section 10.1: each one
    // missing, zero or negative stops with a FatalIOError naming the phase
    // and the entry
    const std::vector<std::pair<std::string, std::string>> entries
    {
        {"rho0", "8930"}, {"c0", "3939"}, {"s", "1.5"}, {"Gamma0", "2"},
        {"Cv", "383"}, {"T0", "298"}
    };
    const auto eosText = [&](const std::string& skip, const std::string& value)
    {
        std::string text("equationOfState { type MieGruneisen;");
        for (const auto& kv : entries)
        {
            if (kv.first == skip)
            {
                if (!value.empty()) text += " " + kv.first + " " + value + ";";
            }
            else
            {
                text += " " + kv.first + " " + kv.second + ";";
            }
        }
        return text + " }";
    };
    const std::string metal("type metal; rho0 8930; mu 4.4967e10;");

    EXPECT_NO_THROW
    (
        hyperelasticPhase("copper", dictFrom(phaseText("solid", metal, eosText("", ""))))
    );
    EXPECT_NO_THROW
    (
        hyperelasticPhase("water", dictFrom(phaseText("fluid", "", eosText("", ""))))
    );

    for (const auto& kv : entries)
    {
        const std::string& key = kv.first;
        expectPhaseError
        (
            "copper", phaseText("solid", metal, eosText(key, "")),
            {"copper", "MieGruneisen", "keyword " + key}
        );
        for (const char* bad : {"0", "-1"})
        {
            expectPhaseError
            (
                "copper", phaseText("solid", metal, eosText(key, bad)),
                {"copper", "equationOfState " + key + " = " + bad, "positive"}
            );
        }
    }
    // A fluid phase too (no elasticity to stop it first)
    expectPhaseError
    (
        "water", phaseText("fluid", "", eosText("c0", "-1500")),
        {"water", "equationOfState c0 = -1500"}
    );

    // Gamma0 >= 2 s: the Hugoniot from rest would reach its limiting
    // compression 2/Gamma0 before the pole 1/s
    expectPhaseError
    (
        "copper",
        phaseText
        (
            "solid", metal,
            "equationOfState { type MieGruneisen; rho0 8930; c0 3939; s 1;"
            " Gamma0 2; Cv 383; T0 298; }"
        ),
        {"copper", "equationOfState Gamma0 = 2", "2 s = 2"}
    );

    // The shear energy's rho0 must be the equation of state's
    expectPhaseError
    (
        "copper",
        phaseText("solid", "type metal; rho0 8900; mu 4.4967e10;", eosText("", "")),
        {"copper", "equationOfState rho0 = 8930", "elasticity rho0 = 8900"}
    );
}
