/*---------------------------------------------------------------------------*\
  Unit tests of a phase's inelastic mechanics (inelasticModel,
  plasticityAndFailure): the variables each composition carries (none for a
  fluid or an elastic solid), relax() against the plasticity and failure
  models it is made of, the tensile cutoff and the floor it leaves, the
  predictor's step of failed material, and bad input.
\*---------------------------------------------------------------------------*/

#include <gtest/gtest.h>
#include "plasticityAndFailure.H"
#include "unitTestTools.H"

#include <cmath>
#include <string>

using namespace Foam;
using unitTestTools::dictFrom;
using Foam::cobasis::matrix;

namespace
{

const std::string copperLaw
(
    "type solid;"
    " equationOfState { type stiffenedGas; gamma 4.22; pInf 3.42e10; }"
    " elasticity { type separable; rho0 8900; mu 4.5e10; a 0.5; }"
);

const std::string vonMises("plasticity { type vonMises; sigmaY 3e8; tau 0; }");
const std::string elastic("plasticity { type none; }");
const std::string spall("failure { type spall; sigmaSpall 1.3e9; }");

struct phase
{
    dictionary dict;
    hyperelasticPhase law;
    autoPtr<inelasticModel> model;

    explicit phase(const std::string& text)
    :
        dict(dictFrom(text)),
        law("copper", dict),
        model(inelasticModel::New(law, dict))
    {}
};

//- Expect a Foam::error whose message holds key
void expectError(const std::string& text, const std::string& key)
{
    try
    {
        phase p(text);
        ADD_FAILURE() << "accepted: " << text;
    }
    catch (const Foam::error& err)
    {
        const std::string msg(err.message());
        EXPECT_NE(msg.find(key), std::string::npos) << msg;
    }
}

//- A volume-preserving stretch of 5 %: 2 GPa of shear in copper, far
//  beyond its 0.3 GPa flow stress
matrix strained()
{
    return cobasis::vector(1.05, 1, 1/1.05).asDiagonal();
}

} // End anonymous namespace


TEST(inelasticModel, carriesOnlyWhatItUses)
{
    const phase plastic(copperLaw + vonMises);
    const carriedVariableList v(plastic.model->carriedVariables());
    ASSERT_EQ(v.size(), 2);
    EXPECT_EQ(v[0].name, "epsilonP");
    EXPECT_EQ(v[1].name, "plasticWork");
    EXPECT_EQ(v[0].lower, 0);
    EXPECT_TRUE(plastic.model->plastic());
    EXPECT_FALSE(plastic.model->limitsTension());

    const phase failing(copperLaw + vonMises + spall);
    const carriedVariableList w(failing.model->carriedVariables());
    ASSERT_EQ(w.size(), 3);
    EXPECT_EQ(w[2].name, "damage");
    EXPECT_EQ(w[2].upper, 1);
    EXPECT_TRUE(failing.model->limitsTension());

    // An elastic solid and a fluid carry nothing and never relax
    const phase solid(copperLaw + elastic);
    EXPECT_EQ(solid.model->carriedVariables().size(), 0);
    EXPECT_FALSE(solid.model->plastic());
    matrix A(strained());
    scalar e = 1e4;
    EXPECT_EQ(solid.model->relax(A, nullptr, 8900, e, 1e-8), 0);
    EXPECT_EQ(A, strained());
    EXPECT_EQ(e, 1e4);

    const phase air
    (
        "type fluid; equationOfState { type stiffenedGas; gamma 1.4;"
        " pInf 0; }"
    );
    EXPECT_EQ(air.model->carriedVariables().size(), 0);
    EXPECT_FALSE(air.model->plastic());
    EXPECT_FALSE(air.model->limitsTension());
}


TEST(inelasticModel, relaxIsTheReturnWithItsHeat)
{
    const phase p(copperLaw + vonMises);
    const auto& model =
        refCast<const inelasticModels::plasticityAndFailure>(p.model());

    // The plasticity alone on the same state
    matrix A0(strained());
    scalar eps0 = 0.1;
    const scalar heat0 =
        model.plasticity().correct(A0, eps0, p.law.elastic(), 1e-8, 0);
    ASSERT_GT(heat0, 0);

    matrix A(strained());
    scalar carried[2] = {0.1, 5e3};
    scalar e = 1e4;
    const scalar heat = model.relax(A, carried, 8900, e, 1e-8);
    EXPECT_EQ(heat, heat0);
    EXPECT_EQ(A, A0);
    EXPECT_EQ(carried[0], eps0);
    EXPECT_EQ(carried[1], 5e3 + heat0);
    EXPECT_EQ(e, 1e4 + heat0);
    EXPECT_EQ(model.plasticWork(carried), 5e3 + heat0);

    // The heat is the shear energy released
    EXPECT_NEAR
    (
        heat,
        p.law.elasticEnergy(strained()) - p.law.elasticEnergy(A),
        1e-9*heat
    );
}


TEST(inelasticModel, tensionCutoffAndFloor)
{
    const phase p
    (
        copperLaw + vonMises
      + "failure { type spall; sigmaSpall 1.3e9; cavitationPressure -1e5; }"
    );
    const inelasticModel& model = p.model();

    scalar carried[3] = {0, 0, 0};
    EXPECT_EQ(model.tension(carried, -1.2e9, 1e-9), -GREAT);
    EXPECT_FALSE(model.failed(carried));
    EXPECT_EQ(model.pFloor(carried), -GREAT);

    EXPECT_EQ(model.tension(carried, -1.4e9, 1e-9), -1e5);
    EXPECT_EQ(carried[2], 1);
    EXPECT_TRUE(model.failed(carried));
    EXPECT_EQ(model.pFloor(carried), -1e5);

    // Failed material relaxes no further and predicts no shear
    matrix A(strained()*1.01);
    EXPECT_TRUE(model.predict(A, carried, 8900, 1e9, 1e-8));
    EXPECT_NEAR(A.determinant(), std::pow(1.01, 3), 1e-14);
    EXPECT_NEAR(p.law.elasticEnergy(A), 0, 1e-9);

    // Damage transported below 1 but past the failed threshold fails
    scalar mixed[3] = {0, 0, 1 - 1e-7};
    EXPECT_TRUE(model.failed(mixed));
}


TEST(inelasticModel, predictKeepsTheRotation)
{
    const phase p(copperLaw + vonMises);
    scalar carried[2] = {0, 0};
    const matrix R(Eigen::AngleAxisd(0.3, cobasis::vector(0, 0, 1)).toRotationMatrix());
    matrix A(R*strained());
    ASSERT_TRUE(p.model->predict(A, carried, 8900, 1e5, 1e-8));
    // The relaxed stretch, turned by the same rotation
    matrix U(strained());
    scalar eps = 0;
    refCast<const inelasticModels::plasticityAndFailure>(p.model())
        .plasticity().correct(U, eps, p.law.elastic(), 1e-8, 0);
    EXPECT_LT((A - R*U).norm(), 1e-14);
    // A state inside the yield surface is left alone
    matrix small(cobasis::vector(1.0001, 1, 1/1.0001).asDiagonal());
    const matrix small0(small);
    EXPECT_FALSE(p.model->predict(small, carried, 8900, 1e5, 1e-8));
    EXPECT_EQ(small, small0);
}


TEST(inelasticModel, badInput)
{
    expectError(copperLaw + "inelastic { type backstress; }", "backstress");
    expectError(copperLaw + "inelastic { type backstress; }", "plasticityAndFailure");
    expectError
    (
        "type fluid; equationOfState { type stiffenedGas; gamma 1.4;"
        " pInf 0; }" + spall,
        "failure is for solids only"
    );
    expectError
    (
        copperLaw
      + "plasticity { type vonMises; tau 0; yieldStress { type JohnsonCook;"
        " A 9e7; B 2.92e8; n 0.31; C 0.025; m 1.09; Tr 298; Tm 1356; } }",
        "add Cv"
    );
}
