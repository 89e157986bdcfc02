/*---------------------------------------------------------------------------*\
  Unit tests of the flow stress laws sigma_Y(epsP, epsPDot, T) and of the
  shared plastic return onto them (docs/model.md section 10.3): for every law
  (constant, linear and a rate- and temperature-dependent law defined here,
  registered in the yieldStress table like any user law) the return lands
  on sigma_Y(epsP + dEpsP, dEpsP/dt, T), keeps det A, never increases the
  shear energy, releases it as heat >= 0 and leaves a state inside the
  surface untouched, also for small plastic increments at high rates
  (where the rate term is steepest) and visco-plastically; a law with no
  strength takes the stress to zero; a rate- and temperature-independent
  law ignores dt and T; the original keywords and the yieldStress
  sub-dictionary give the same returns, bit for bit. Copper (a = 1/2) and
  a soft clay (a = -1).
\*---------------------------------------------------------------------------*/

#include <gtest/gtest.h>
#include "plasticModel.H"
#include "yieldStress.H"
#include "vonMisesReturn.H"
#include "elasticModel.H"
#include "addToRunTimeSelectionTable.H"
#include "unitTestTools.H"

#include <cstdio>
#include <iomanip>
#include <sstream>
#include <string>
#include <vector>

using namespace Foam;
using namespace unitTestTools;


// * * * * * * * * * * * * * A test-only flow stress law  * * * * * * * * * * //

namespace Foam
{
namespace yieldStresses
{

//- sigma_Y = (A + B epsP) (1 + C ln(max(epsPDot, 1))) (1 - T/Tm): hardening,
//  rate hardening and thermal softening, the three dependencies of a
//  Johnson-Cook law in their simplest form. Written as a user would write a
//  new law: one class and its addToRunTimeSelectionTable line
class rateTemperatureTest
:
    public yieldStress
{
    const scalar A_, B_, C_, Tm_;

public:

    TypeName("rateTemperatureTest");

    rateTemperatureTest(const word& phaseName, const dictionary& dict)
    :
        yieldStress(phaseName),
        A_(readPositive(dict, "A")),
        B_(readNonNegative(dict, "B")),
        C_(readNonNegative(dict, "C")),
        Tm_(readPositive(dict, "Tm"))
    {}

    //- A model declares the entries it reads (strict input)
    virtual wordList keywords() const
    {
        return {"type", "A", "B", "C", "Tm"};
    }

    virtual scalar sigmaY
    (
        const scalar epsP,
        const scalar epsPDot,
        const scalar T
    ) const
    {
        return
            (A_ + B_*epsP)
           *(1 + C_*std::log(max(epsPDot, scalar(1))))
           *(1 - T/Tm_);
    }

    virtual bool needsTemperature() const
    {
        return true;
    }
};

defineTypeNameAndDebug(rateTemperatureTest, 0);
addToRunTimeSelectionTable(yieldStress, rateTemperatureTest, dictionary);

} // End namespace yieldStresses
} // End namespace Foam


namespace
{

struct material
{
    const char* name;
    const char* elasticity;
    scalar sigmaY;      // yield stress scale
    scalar Tm;          // melting temperature of the test law
};

const material materials[] =
{
    {"copper", "type separable; rho0 8900; mu 4.5e10; a 0.5;", 4e8, 1356},
    {"clay", "type separable; rho0 1800; mu 1e6; a -1;", 5e4, 400}
};


std::string str(const scalar x)
{
    std::ostringstream os;
    os  << std::setprecision(17) << x;
    return os.str();
}

//- The yieldStress sub-dictionaries of the three laws for a material
std::vector<std::string> lawTexts(const material& m)
{
    return
    {
        "type constant; sigmaY " + str(m.sigmaY) + ";",
        "type linear; sigmaY0 " + str(m.sigmaY) + "; H "
      + str(0.25*m.sigmaY) + ";",
        "type rateTemperatureTest; A " + str(m.sigmaY) + "; B "
      + str(0.5*m.sigmaY) + "; C 0.05; Tm " + str(m.Tm) + ";"
    };
}

autoPtr<plasticModel> plasticFrom(const material& m, const std::string& text)
{
    return plasticModel::New(m.name, dictFrom(text));
}

//- vonMises with the law given as a yieldStress sub-dictionary
std::string vonMisesText(const std::string& law, const scalar tau = 0)
{
    return
        "type vonMises; yieldStress { " + law + " } tau " + str(tau) + ";";
}

//- Von Mises equivalent stress sqrt(3/2)|S|
scalar vonMisesStress(const elasticModel& elastic, const matrix& A)
{
    return std::sqrt(1.5)*elastic.SofA(A).norm();
}

bool sameBits(const matrix& A, const matrix& B)
{
    return (A.array() == B.array()).all();
}

} // End anonymous namespace


TEST(yieldStress, returnLandsOnTheFlowStress)
{
    // Random strained states, plastic strains, time steps (rates from
    // about 1 to 1e9 /s) and temperatures below melting
    std::mt19937 gen(83);
    std::uniform_real_distribution<double> logDt
    (
        std::log(1e-9), std::log(1e-5)
    );
    std::uniform_real_distribution<double> U01(0, 1);
    const vonMisesReturn ideal;
    scalar worstYield = 0, worstDet = 0, worstHeat = 0;

    for (const material& m : materials)
    {
        auto elastic = elasticModel::New(m.name, dictFrom(m.elasticity));
        for (const std::string& lawText : lawTexts(m))
        {
            auto law = yieldStress::New(m.name, dictFrom(lawText));
            auto plastic = plasticFrom(m, vonMisesText(lawText));

            int nYield = 0, nElastic = 0;
            for (int sample = 0; sample < 1500; ++sample)
            {
                const matrix A0(randomState(gen));
                const scalar epsP0 = 0.1*(sample % 5);
                const scalar dt = std::exp(logDt(gen));
                const scalar T = 0.9*m.Tm*U01(gen);
                const scalar trial = vonMisesStress(*elastic, A0);
                const scalar e0 = elastic->energy(cobasis::g(A0));

                matrix A(A0);
                const vonMisesReturn::result r =
                    ideal.correct(A, epsP0, *elastic, *law, dt, T);

                // The plastic model is this return and this law
                matrix Ap(A0);
                scalar epsPp = epsP0;
                const scalar heatp =
                    plastic->correct(Ap, epsPp, *elastic, dt, T);
                EXPECT_TRUE(sameBits(Ap, A)) << m.name << ": " << lawText;
                EXPECT_EQ(epsPp, epsP0 + r.dEpsP);
                EXPECT_EQ(heatp, r.heat);

                if (trial <= law->sigmaY(epsP0, 0, T))
                {
                    // Inside the surface: untouched, bit for bit
                    ++nElastic;
                    EXPECT_TRUE(sameBits(A, A0)) << m.name << ": " << lawText;
                    EXPECT_EQ(r.dEpsP, 0);
                    EXPECT_EQ(r.heat, 0);
                    continue;
                }
                ++nYield;

                // On the law at the end of the step: plastic strain
                // epsP + dEpsP, rate dEpsP/dt, temperature before the step
                EXPECT_GT(r.dEpsP, 0);
                const scalar sigmaY =
                    law->sigmaY(epsP0 + r.dEpsP, r.dEpsP/dt, T);
                const scalar errY = relErr(vonMisesStress(*elastic, A), sigmaY);
                worstYield = max(worstYield, errY);
                EXPECT_LT(errY, 1e-10)
                    << m.name << ": " << lawText << ", A0 =\n" << A0;

                // det A kept
                const scalar errDet = mag(A.determinant()/A0.determinant() - 1);
                worstDet = max(worstDet, errDet);
                EXPECT_LT(errDet, 1e-12) << m.name << ": " << lawText;

                // Shear energy never increased, released as heat >= 0
                const scalar e1 = elastic->energy(cobasis::g(A));
                EXPECT_LE(e1, e0) << m.name << ": " << lawText;
                EXPECT_GE(r.heat, 0) << m.name << ": " << lawText;
                const scalar errHeat = mag(r.heat - (e0 - e1))/e0;
                worstHeat = max(worstHeat, errHeat);
                EXPECT_LT(errHeat, 1e-12) << m.name << ": " << lawText;
            }
            EXPECT_GT(nYield, 300) << m.name << ": " << lawText;
            EXPECT_GT(nElastic, 100) << m.name << ": " << lawText;
        }
    }
    std::printf
    (
        "[ measured ] worst: |sqrt(3/2)|S| - sigmaY(epsP + dEpsP, dEpsP/dt, T)|"
        "/sigmaY %.2e, det A %.2e, heat %.2e\n",
        worstYield, worstDet, worstHeat
    );
}


TEST(yieldStress, smallIncrementsAtHighRates)
{
    // States just beyond the quasi-static surface, short steps: the
    // plastic increment is tiny (1 - s down to 1e-9) and its rate of order
    // 1 to 1e3 /s, where the rate term varies like ln(1 - s) faster than s
    // resolves near 1; the return still lands on the law to 1e-10
    std::mt19937 gen(109);
    std::uniform_real_distribution<double> U(-1, 1);
    const vonMisesReturn ideal;
    scalar worst = 0;
    for (const material& m : materials)
    {
        auto elastic = elasticModel::New(m.name, dictFrom(m.elasticity));
        auto law = yieldStress::New(m.name, dictFrom(lawTexts(m)[2]));
        for (int sample = 0; sample < 200; ++sample)
        {
            // Random deviatoric direction u, volume change, rotation
            const scalar u1 = U(gen), u2 = U(gen);
            const vector u(vector(u1, u2, -u1 - u2).normalized());
            const matrix Q(randomRotation(gen));
            const scalar J = 1 + 0.01*U(gen);
            const auto cobasisAt = [&](const scalar k)
            {
                const vector l(std::cbrt(J)*(k*u).array().exp());
                return matrix(Q*l.asDiagonal()*Q.transpose());
            };

            const scalar epsP0 = 0.1*(sample % 4);
            const scalar T = 0.5*m.Tm*(1 + U(gen));
            const scalar delta = std::pow(10.0, -4 + 3*(0.5 + 0.5*U(gen)));
            const scalar target = (1 + delta)*law->sigmaY(epsP0, 0, T);

            // Log-strain magnitude k with the trial stress on the target
            scalar k0 = 0, k1 = 1;
            for (int i = 0; i < 200 && k1 - k0 > 1e-15*k1; ++i)
            {
                const scalar k = 0.5*(k0 + k1);
                (vonMisesStress(*elastic, cobasisAt(k)) < target ? k0 : k1) = k;
            }
            const matrix A0(cobasisAt(k1));

            for (const scalar dt : {1e-11, 1e-10, 1e-9, 1e-8})
            {
                matrix A(A0);
                const vonMisesReturn::result r =
                    ideal.correct(A, epsP0, *elastic, *law, dt, T);
                ASSERT_GT(r.dEpsP, 0) << m.name;
                const scalar err = relErr
                (
                    vonMisesStress(*elastic, A),
                    law->sigmaY(epsP0 + r.dEpsP, r.dEpsP/dt, T)
                );
                worst = max(worst, err);
                EXPECT_LT(err, 1e-10)
                    << m.name << " delta " << delta << " dt " << dt
                    << " dEpsP " << r.dEpsP;
            }
        }
    }
    std::printf
    (
        "[ measured ] small increments at high rates: worst landing %.2e\n",
        worst
    );
}


TEST(yieldStress, rateAndTemperatureMoveTheSurface)
{
    // The test law through vonMises: a faster step (smaller dt, larger
    // rate) stops the return on a higher stress with less plastic strain,
    // a hotter one on a lower stress with more (equal where the rate stays
    // below 1/s: to the root tolerance, 1e-13 sigmaY)
    std::mt19937 gen(89);
    for (const material& m : materials)
    {
        auto elastic = elasticModel::New(m.name, dictFrom(m.elasticity));
        auto plastic = plasticFrom(m, vonMisesText(lawTexts(m)[2]));
        EXPECT_TRUE(plastic->needsTemperature());

        int nYield = 0;
        for (int sample = 0; sample < 300; ++sample)
        {
            const matrix A0(randomState(gen));
            if (vonMisesStress(*elastic, A0) <= plastic->sigmaY(0, 0, 0))
            {
                continue;
            }
            ++nYield;

            scalar stressPrev = 0, epsPPrev = GREAT;
            for (const scalar dt : {1e-3, 1e-5, 1e-7, 1e-9})
            {
                matrix A(A0);
                scalar epsP = 0;
                plastic->correct(A, epsP, *elastic, dt, 0);
                const scalar stress = vonMisesStress(*elastic, A);
                EXPECT_GE(stress, stressPrev*(1 - 1e-12)) << m.name;
                EXPECT_LE(epsP, epsPPrev + 1e-12) << m.name;
                stressPrev = stress;
                epsPPrev = epsP;
            }

            stressPrev = GREAT;
            epsPPrev = 0;
            for (const scalar TbyTm : {0.0, 0.3, 0.6, 0.9})
            {
                matrix A(A0);
                scalar epsP = 0;
                plastic->correct(A, epsP, *elastic, 1e-6, TbyTm*m.Tm);
                const scalar stress = vonMisesStress(*elastic, A);
                EXPECT_LE(stress, stressPrev*(1 + 1e-12)) << m.name;
                EXPECT_GE(epsP, epsPPrev - 1e-12) << m.name;
                stressPrev = stress;
                epsPPrev = epsP;
            }
        }
        EXPECT_GT(nYield, 100) << m.name;
    }
}


TEST(yieldStress, viscoPlasticReturnStaysOnOrAboveTheSurface)
{
    // tau > 0 with the rate- and temperature-dependent law: the stress
    // relaxes toward the surface sigma_Y(epsP + dEpsP, dEpsP/dt, T), never
    // past it, and not above the trial stress
    std::mt19937 gen(97);
    const scalar tau = 1e-6;
    for (const material& m : materials)
    {
        auto elastic = elasticModel::New(m.name, dictFrom(m.elasticity));
        auto law = yieldStress::New(m.name, dictFrom(lawTexts(m)[2]));
        const vonMisesReturn visco(tau, 2);

        for (int sample = 0; sample < 200; ++sample)
        {
            const matrix A0(randomState(gen));
            const scalar T = 0.5*m.Tm;
            const scalar trial = vonMisesStress(*elastic, A0);
            if (trial <= law->sigmaY(0, 0, T))
            {
                continue;
            }
            for (const scalar r : {1e-3, 0.1, 10.0, 1e3})
            {
                matrix A(A0);
                const scalar dt = r*tau;
                const vonMisesReturn::result res =
                    visco.correct(A, 0, *elastic, *law, dt, T);
                const scalar stress = vonMisesStress(*elastic, A);
                EXPECT_GE
                (
                    stress,
                    law->sigmaY(res.dEpsP, res.dEpsP/dt, T)*(1 - 1e-10)
                ) << m.name << " dt/tau " << r;
                EXPECT_LE(stress, trial*(1 + 1e-12)) << m.name;
                EXPECT_GE(res.heat, 0) << m.name;
                EXPECT_LT(mag(A.determinant()/A0.determinant() - 1), 1e-12);
            }
        }
    }
}


TEST(yieldStress, noStrengthTakesTheStressToZero)
{
    // At T = Tm the test law has no strength: the return takes the whole
    // log-strain as plastic strain and the stress to round-off
    std::mt19937 gen(101);
    for (const material& m : materials)
    {
        auto elastic = elasticModel::New(m.name, dictFrom(m.elasticity));
        auto plastic = plasticFrom(m, vonMisesText(lawTexts(m)[2]));
        EXPECT_EQ(plastic->sigmaY(0.3, 1e4, m.Tm), 0);
        for (int sample = 0; sample < 100; ++sample)
        {
            const matrix A0(randomState(gen));
            matrix A(A0);
            scalar epsP = 0;
            const scalar heat = plastic->correct(A, epsP, *elastic, 1e-6, m.Tm);
            EXPECT_LE
            (
                vonMisesStress(*elastic, A), 1e-10*vonMisesStress(*elastic, A0)
            ) << m.name;

            // All the shear energy released, to the round-off of the
            // energy (terms of order mu/rho0)
            const scalar e0 = elastic->energy(cobasis::g(A0));
            const scalar eTol = 1e-10*e0 + 1e-14*elastic->mu()/elastic->rho0();
            EXPECT_LE(elastic->energy(cobasis::g(A)), eTol) << m.name;
            EXPECT_LE(mag(heat - e0), eTol) << m.name;
            const scalar hNorm =
                Eigen::SelfAdjointEigenSolver<matrix>(cobasis::g(A0))
               .eigenvalues().array().log().matrix().norm();
            EXPECT_LT(relErr(epsP, std::sqrt(2.0/3.0)*0.5*hNorm), 1e-10)
                << m.name;
        }
    }
}


TEST(yieldStress, rateAndTemperatureIndependentLawsIgnoreThem)
{
    // constant and linear: the rate (through dt) and T change nothing
    std::mt19937 gen(103);
    for (const material& m : materials)
    {
        auto elastic = elasticModel::New(m.name, dictFrom(m.elasticity));
        const std::vector<std::string> laws(lawTexts(m));
        for (int i = 0; i < 2; ++i)
        {
            auto plastic = plasticFrom(m, vonMisesText(laws[i]));
            EXPECT_FALSE(plastic->needsTemperature()) << laws[i];

            int nYield = 0;
            for (int sample = 0; sample < 300; ++sample)
            {
                const matrix A0(randomState(gen));
                const scalar epsP0 = 0.1*(sample % 3);
                matrix Aref(A0);
                scalar epsPref = epsP0;
                const scalar heatRef =
                    plastic->correct(Aref, epsPref, *elastic, 0, 0);
                nYield += epsPref > epsP0;

                for (const scalar dt : {0.0, 1e-12, 1e-6, 1.0})
                {
                    for (const scalar T : {0.0, 300.0, 1e4})
                    {
                        matrix A(A0);
                        scalar epsP = epsP0;
                        const scalar heat =
                            plastic->correct(A, epsP, *elastic, dt, T);
                        EXPECT_TRUE(sameBits(A, Aref)) << laws[i];
                        EXPECT_EQ(epsP, epsPref) << laws[i];
                        EXPECT_EQ(heat, heatRef) << laws[i];
                    }
                }
            }
            EXPECT_GT(nYield, 50) << laws[i];
        }
    }
}


TEST(yieldStress, originalKeywordsAndSubDictionaryAgree)
{
    // Each pair: the original entries of the plasticity dictionary and the
    // yieldStress sub-dictionary they stand for; same returns, bit for bit,
    // ideal and visco-plastic
    std::mt19937 gen(107);
    for (const material& m : materials)
    {
        auto elastic = elasticModel::New(m.name, dictFrom(m.elasticity));
        const std::string Y(str(m.sigmaY)), H(str(0.25*m.sigmaY));
        const std::vector<std::pair<std::string, std::string>> pairs
        {
            {
                "type vonMises; sigmaY " + Y + "; tau 0;",
                vonMisesText("type constant; sigmaY " + Y + ";")
            },
            {
                "type vonMises; sigmaY0 " + Y + "; tau 0;",
                vonMisesText("type constant; sigmaY " + Y + ";")
            },
            {
                "type vonMises; sigmaY0 " + Y + "; H " + H + "; tau 0;",
                vonMisesText("type linear; sigmaY0 " + Y + "; H " + H + ";")
            },
            {
                "type vonMises; sigmaY " + Y + "; H " + H + "; tau 0;",
                vonMisesText("type linear; sigmaY0 " + Y + "; H " + H + ";")
            },
            {
                "type vonMises; sigmaY " + Y + "; tau 1e-6;",
                vonMisesText("type constant; sigmaY " + Y + ";", 1e-6)
            },
            {
                "type vonMises; sigmaY0 " + Y + "; H " + H
              + "; tau 1e-6; n 2;",
                "type vonMises; yieldStress { type linear; sigmaY0 " + Y
              + "; H " + H + "; } tau 1e-6; n 2;"
            }
        };

        for (const auto& p : pairs)
        {
            auto original = plasticFrom(m, p.first);
            auto subDict = plasticFrom(m, p.second);
            EXPECT_EQ(original->sigmaY(0.3, 0, 0), subDict->sigmaY(0.3, 0, 0));

            int nYield = 0;
            for (int sample = 0; sample < 300; ++sample)
            {
                const matrix A0(randomState(gen));
                const scalar epsP0 = 0.1*(sample % 4);
                const scalar dt = sample % 3 == 0 ? 0 : 1e-7*(sample % 7);
                matrix A1(A0), A2(A0);
                scalar epsP1 = epsP0, epsP2 = epsP0;
                const scalar heat1 =
                    original->correct(A1, epsP1, *elastic, dt, 0);
                const scalar heat2 =
                    subDict->correct(A2, epsP2, *elastic, dt, 0);
                EXPECT_TRUE(sameBits(A1, A2)) << p.first << " | " << p.second;
                EXPECT_EQ(epsP1, epsP2) << p.first << " | " << p.second;
                EXPECT_EQ(heat1, heat2) << p.first << " | " << p.second;
                nYield += epsP1 > epsP0;
            }
            EXPECT_GT(nYield, 50) << p.first;
        }
    }
}
