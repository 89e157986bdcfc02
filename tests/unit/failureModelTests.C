/*---------------------------------------------------------------------------*\
  Unit tests of the failure models (docs/model.md section 11): the damage
  each model's activity, the Johnson-Cook damage increment against its
  formula, the tensile cutoff, the bounds of D, and bad input (every entry
  missing or out of range stops with a FatalIOError naming phase and entry).
\*---------------------------------------------------------------------------*/

#include <gtest/gtest.h>
#include "failureModel.H"
#include "JohnsonCookFailure.H"
#include "unitTestTools.H"

#include <cmath>
#include <string>
#include <vector>

using namespace Foam;
using namespace unitTestTools;

namespace
{

//- The failure model of a phase dictionary text
autoPtr<failureModel> failureFrom(const std::string& phaseText)
{
    return failureModel::New("copper", dictFrom(phaseText));
}

const std::string jcCopper
(
    "failure { type JohnsonCook; D1 0.54; D2 4.89; D3 -3.03; D4 0.014;"
    " D5 1.12; Tr 298; Tm 1356; }"
);

//- Expect a Foam::error whose message holds every key word
void expectFailureError
(
    const std::string& text,
    const std::vector<std::string>& keyWords
)
{
    try
    {
        failureFrom(text);
        ADD_FAILURE() << "accepted: " << text;
    }
    catch (const Foam::error& err)
    {
        const std::string msg(err.message());
        for (const std::string& key : keyWords)
        {
            EXPECT_NE(msg.find(key), std::string::npos)
                << text << ": message does not contain '" << key << "':\n"
                << msg;
        }
    }
}

} // End anonymous namespace


TEST(failureModel, noneIsTheDefault)
{
    EXPECT_FALSE(failureFrom("")->active());
    EXPECT_FALSE(failureFrom("failure { type none; }")->active());
    for
    (
        const std::string& text
      : {std::string("failure { type spall; sigmaSpall 1.3e9; }"), jcCopper}
    )
    {
        const auto f = failureFrom(text);
        EXPECT_TRUE(f->active()) << text;
        EXPECT_EQ(f->cavitationPressure(), 0);
    }
}


TEST(failureModel, spallIsATensilePressureCutoff)
{
    const auto f = failureFrom("failure { type spall; sigmaSpall 1.3e9; }");
    // Plastic strain does not damage; tension beyond the cutoff fails
    EXPECT_EQ(f->damage(0, 0.5, 1e4, -1.29e9, 1e8, 300), 0);
    EXPECT_EQ(f->damage(0.3, 0, 0, -1.31e9, 0, 300), 1);
    // Failed material stays failed
    EXPECT_EQ(f->damage(1, 0, 0, 1e9, 0, 300), 1);
    EXPECT_TRUE(failureModel::failed(1 - 1e-9));
    EXPECT_FALSE(failureModel::failed(0.99));
}


TEST(failureModel, spallTimeHoldsTheStrength)
{
    const auto f = failureFrom
    (
        "failure { type spall; sigmaSpall 1.3e9; spallTime 1e-7; }"
    );
    // Below the cutoff D starts to grow by dt/tau and the plastic step
    // leaves it alone; while failing the material holds -sigmaSpall, once
    // failed the cavitation pressure
    const double dt = 1e-9;
    EXPECT_EQ(f->spall(0, -1.2e9, dt), 0);
    EXPECT_NEAR(f->spall(0, -1.31e9, dt), 0.01, 1e-15);
    EXPECT_EQ(f->damage(0, 0, 0, -1.31e9, 0, 300), 0);
    EXPECT_EQ(f->pFloor(0), -GREAT);
    EXPECT_EQ(f->pFloor(0.25), -1.3e9);
    EXPECT_EQ(f->pFloor(0.99), -1.3e9);
    EXPECT_EQ(f->pFloor(1), 0);
    // It grows only while the tension exceeds the strength, whatever D
    EXPECT_EQ(f->spall(0.5, -1.29e9, dt), 0.5);
    EXPECT_NEAR(f->spall(0.5, -1.31e9, dt), 0.51, 1e-15);
    EXPECT_EQ(f->spall(0.999, -1.31e9, 0.1), 1);
    // Without spallTime: failed at once, no floor before
    const auto g = failureFrom("failure { type spall; sigmaSpall 1.3e9; }");
    EXPECT_EQ(g->spall(0, -1.31e9, dt), 1);
    EXPECT_EQ(g->spall(0, -1.29e9, dt), 0);
    EXPECT_EQ(g->pFloor(0.5), -GREAT);
    EXPECT_EQ(g->pFloor(1), 0);
}


TEST(failureModel, JohnsonCookIncrementIsThePlasticStrainOverEpsF)
{
    const auto f = failureFrom(jcCopper);
    EXPECT_TRUE(f->needsTemperature());
    const auto& jc = dynamic_cast<const failureModels::JohnsonCook&>(f());

    const double D1 = 0.54, D2 = 4.89, D3 = -3.03, D4 = 0.014, D5 = 1.12;
    const double Tr = 298, Tm = 1356;
    for (const double p : {-2e9, -3e8, 0.0, 4e8, 3e9})
    {
        for (const double rate : {0.1, 1.0, 1e3, 1e6})
        {
            for (const double T : {200.0, 298.0, 600.0, 1500.0})
            {
                const double sigmaEq = 3e8;
                const double dEpsP = 1e-3;
                const double sStar = -p/sigmaEq;
                const double Th =
                    std::min(std::max((T - Tr)/(Tm - Tr), 0.0), 1.0);
                const double epsF =
                    (D1 + D2*std::exp(D3*sStar))
                   *(1 + D4*std::log(std::max(rate, 1.0)))
                   *(1 + D5*Th);
                EXPECT_NEAR
                (
                    jc.epsF(sStar, rate, T), epsF, 1e-13*epsF
                );
                const double D0 = 0.2;
                EXPECT_NEAR
                (
                    f->damage(D0, dEpsP, rate, p, sigmaEq, T),
                    D0 + dEpsP/epsF, 1e-13
                ) << "p " << p << " rate " << rate << " T " << T;
            }
        }
    }
    // Damage is at most 1; no plastic strain, no damage
    EXPECT_EQ(f->damage(0.99, 10, 1, -1e9, 3e8, 300), 1);
    EXPECT_EQ(f->damage(0.5, 0, 1, -1e9, 3e8, 300), 0.5);
    // Without a Von Mises stress (all pressure): finite, no NaN
    const double Dh = f->damage(0, 1e-3, 1, -1e9, 0, 300);
    EXPECT_TRUE(std::isfinite(Dh));
    EXPECT_GE(Dh, 0);
    EXPECT_LE(Dh, 1);
}


TEST(failureModel, JohnsonCookTakesTemperaturesFromTheFlowStress)
{
    // D5 != 0 without Tr, Tm of its own: the Johnson-Cook flow stress's
    const auto f = failureFrom
    (
        "plasticity { type vonMises; yieldStress { type JohnsonCook;"
        " A 9e7; B 2.92e8; n 0.31; C 0.025; m 1.09; Tr 298; Tm 1356; } }"
        " failure { type JohnsonCook; D1 0.54; D2 4.89; D3 -3.03;"
        " D4 0.014; D5 1.12; }"
    );
    const auto g = failureFrom(jcCopper);
    EXPECT_EQ(f->damage(0, 1e-3, 10, -1e8, 2e8, 800), g->damage(0, 1e-3, 10, -1e8, 2e8, 800));
    // D5 = 0: no temperature needed
    EXPECT_FALSE
    (
        failureFrom("failure { type JohnsonCook; D1 0.54; D2 4.89; D3 -3.03; }")
       ->needsTemperature()
    );
}


TEST(failureModel, badInputNamesPhaseAndEntry)
{
    const std::string jc("failure { type JohnsonCook; ");
    expectFailureError("failure { type spall; }", {"copper", "sigmaSpall"});
    expectFailureError
    (
        "failure { type spall; sigmaSpall -1e9; }", {"copper", "sigmaSpall"}
    );
    expectFailureError
    (
        "failure { type spall; sigmaSpall 0; }", {"copper", "sigmaSpall"}
    );
    expectFailureError("failure { type cracking; }", {"copper", "cracking"});
    expectFailureError
    (
        "failure { type none; sigmaSpall 1e9; }", {"copper", "sigmaSpall"}
    );
    expectFailureError(jc + "D2 4.89; D3 -3.03; }", {"copper", "D1"});
    expectFailureError(jc + "D1 0.54; D3 -3.03; }", {"copper", "D2"});
    expectFailureError(jc + "D1 0.54; D2 4.89; }", {"copper", "D3"});
    // Constants that make epsF <= 0 somewhere
    expectFailureError(jc + "D1 -0.1; D2 4.89; D3 -3.03; }", {"copper", "D1"});
    expectFailureError(jc + "D1 0.54; D2 -1; D3 -3.03; }", {"copper", "D2"});
    expectFailureError(jc + "D1 0; D2 0; D3 -3.03; }", {"copper", "D1 + D2"});
    expectFailureError
    (
        jc + "D1 0.54; D2 4.89; D3 -3.03; D4 -0.01; }", {"copper", "D4"}
    );
    expectFailureError
    (
        jc + "D1 0.54; D2 4.89; D3 -3.03; D5 -1; Tr 298; Tm 1356; }",
        {"copper", "D5"}
    );
    expectFailureError
    (
        jc + "D1 0.54; D2 4.89; D3 -3.03; epsDot0 0; }", {"copper", "epsDot0"}
    );
    expectFailureError
    (
        "failure { type spall; sigmaSpall 1e9; spallTime -1e-7; }",
        {"copper", "spallTime"}
    );
    expectFailureError
    (
        jc + "D1 0.54; D2 4.89; D3 -3.03; sigmaSpall 1e9; spallTime 1e-7; }",
        {"copper", "spallTime"}
    );
    expectFailureError
    (
        "failure { type spall; sigmaSpall 1e9; cavitationPressure -2e9; }",
        {"copper", "cavitationPressure"}
    );
    // Temperature dependence without temperatures
    expectFailureError
    (
        jc + "D1 0.54; D2 4.89; D3 -3.03; D5 1.12; }", {"copper", "Tr"}
    );
    expectFailureError
    (
        jc + "D1 0.54; D2 4.89; D3 -3.03; D5 1.12; Tr 1356; Tm 298; }",
        {"copper", "Tm"}
    );
}


// ************************************************************************* //
