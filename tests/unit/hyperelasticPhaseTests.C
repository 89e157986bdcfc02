/*---------------------------------------------------------------------------*\
  Unit tests of hyperelasticPhase (docs/validation.md V7): wave speeds at rest
  (c_T^2 = mu/rho0, c_L^2 = c_h^2 + 4/3 mu/rho0), the acoustic tensor of a
  strained solid against isentropic finite differences of the Cauchy
  stress, energy/pressure round trip, and the fluid case.
\*---------------------------------------------------------------------------*/

#include <gtest/gtest.h>
#include "hyperelasticPhase.H"
#include "unitTestTools.H"

#include <cstdio>
#include <sstream>
#include <vector>
#include <iomanip>

using namespace Foam;
using namespace unitTestTools;

namespace
{

// Copper, stiffened-gas fit (docs/model.md)
const scalar rho0Cu = 8900;
const scalar gammaCu = 4.22;
const scalar pInfCu = 3.42e10;
const scalar muCu = 4.5e10;

std::string copperText(const scalar a)
{
    std::ostringstream os;
    os  << std::setprecision(17)
        << "type solid;"
        << "equationOfState { type stiffenedGas; gamma " << gammaCu
        << "; pInf " << pInfCu << "; }"
        << "elasticity { type separable; rho0 " << rho0Cu << "; mu " << muCu
        << "; a " << a << "; }";
    return os.str();
}

hyperelasticPhase copper(const scalar a)
{
    return hyperelasticPhase("copper", dictFrom(copperText(a)));
}

//- Every elastic law of the library on copper's equation of state: the
//  separable family (a = -1, 0, 1/2), metal and neo-Hookean, mu = muCu
std::vector<std::string> everyElasticLaw()
{
    const std::string eos =
        "equationOfState { type stiffenedGas; gamma 4.22; pInf 3.42e10; }";
    return
    {
        copperText(-1), copperText(0), copperText(0.5),
        "type solid;" + eos
      + "elasticity { type metal; rho0 8900; mu 4.5e10; }",
        "type solid;" + eos
      + "elasticity { type neoHookean; rho0 8900; mu 4.5e10; }"
    };
}

} // End anonymous namespace


TEST(hyperelasticPhase, waveSpeedsAtRest)
{
    std::mt19937 gen(29);
    scalar worst = 0;
    for (const scalar a : {-1.0, 0.0, 0.5})
    {
        const hyperelasticPhase phase(copper(a));
        ASSERT_TRUE(phase.solid());
        EXPECT_EQ(phase.mu(), muCu);
        EXPECT_EQ(phase.rho0(), rho0Cu);
        EXPECT_NEAR(phase.cT2(), muCu/rho0Cu, 1e-15*muCu/rho0Cu);

        for (const scalar p : {1e5, 1e9, -1e10})
        {
            const scalar ch2 = gammaCu*(p + pInfCu)/rho0Cu;
            const scalar cT2 = muCu/rho0Cu;
            const scalar cL2 = ch2 + 4.0/3.0*muCu/rho0Cu;

            // Unstrained and rigidly rotated states are both at rest
            const matrix rest[] =
                {matrix::Identity(), randomRotation(gen)};
            for (const matrix& A : rest)
            {
                for (int sample = 0; sample < 20; ++sample)
                {
                    const vector n(randomUnit(gen));
                    const vector w(phase.waveSpeeds2(rho0Cu, p, A, n));
                    const scalar errs[] =
                        {relErr(w(0), cT2), relErr(w(1), cT2), relErr(w(2), cL2)};
                    for (const scalar e : errs)
                    {
                        worst = max(worst, e);
                        EXPECT_LT(e, 1e-10)
                            << "a = " << a << ", p = " << p << ", w = "
                            << w.transpose();
                    }
                }
                const scalar errA = relErr(phase.a2Max(rho0Cu, p, A), cL2);
                worst = max(worst, errA);
                EXPECT_LT(errA, 1e-10) << "a = " << a << ", p = " << p;
            }
        }
    }
    std::printf("[ measured ] wave speeds at rest: worst rel. error %.2e\n", worst);
}


TEST(hyperelasticPhase, waveSpeedsHydrostaticallyCompressed)
{
    // A = (rho/rho0)^(1/3) I: c_T^2 = mu/rho0 still, c_L^2 = c_h^2 + 4/3 mu/rho0
    std::mt19937 gen(31);
    const hyperelasticPhase phase(copper(0.5));
    for (const scalar rByR0 : {0.9, 1.1, 1.3})
    {
        const scalar rho = rByR0*rho0Cu, p = 2e9;
        const matrix A(cobasis::unstrained(rho, rho0Cu));
        const scalar ch2 = gammaCu*(p + pInfCu)/rho;
        for (int sample = 0; sample < 10; ++sample)
        {
            const vector w(phase.waveSpeeds2(rho, p, A, randomUnit(gen)));
            EXPECT_LT(relErr(w(0), muCu/rho0Cu), 1e-10);
            EXPECT_LT(relErr(w(1), muCu/rho0Cu), 1e-10);
            EXPECT_LT(relErr(w(2), ch2 + 4.0/3.0*muCu/rho0Cu), 1e-10);
        }
    }
}


TEST(hyperelasticPhase, acousticTensorIsIsentropicStressDerivative)
{
    // rho Q(n) d = d sigma[-(A d) (x) n] n along the isentrope
    // p + pInf ~ rho^gamma, for strained states
    std::mt19937 gen(37);
    scalar worst = 0;
    for (const scalar a : {-1.0, 0.0, 0.5})
    {
        const hyperelasticPhase phase(copper(a));
        for (int sample = 0; sample < 100; ++sample)
        {
            const matrix A(randomCobasis(gen, 1.5));
            const vector n(randomUnit(gen));
            const scalar rho = rho0Cu*A.determinant();
            const scalar p = 1e9;

            const auto sigma = [&](const matrix& At)
            {
                const scalar rhot = rho0Cu*At.determinant();
                const scalar pt =
                    (p + pInfCu)*std::pow(rhot/rho, gammaCu) - pInfCu;
                return phase.sigma(pt, At);
            };

            matrix Qfd;
            for (int k = 0; k < 3; ++k)
            {
                const matrix dA(-(A.col(k))*n.transpose());
                for (int i = 0; i < 3; ++i)
                {
                    const auto si = [&](const scalar t)
                    {
                        return (sigma(A + t*dA)*n)(i);
                    };
                    Qfd(i, k) = derivative4(si, 1e-4);
                }
            }

            const matrix Q(rho*phase.acousticTensor(rho, p, A, n));
            const scalar err = maxAbs(Q - Qfd)/maxAbs(Q);
            worst = max(worst, err);
            EXPECT_LT(err, 1e-9) << "a = " << a << ", A =\n" << A;

            // Eigenvalues: real wave speeds, ascending
            const vector w(phase.waveSpeeds2(rho, p, A, n));
            EXPECT_GT(w(0), 0);
            EXPECT_LE(w(0), w(1));
            EXPECT_LE(w(1), w(2));
        }
    }
    std::printf
    (
        "[ measured ] rho*acousticTensor vs isentropic FD of sigma: worst"
        " rel. error %.2e\n", worst
    );
}


TEST(hyperelasticPhase, a2MaxIsLargestEigenvalueOverPrincipalDirections)
{
    // a2Max takes the diagonal of the acoustic tensor in the principal
    // basis of G = A^T A (isotropic energies): it must equal the largest
    // eigenvalue of the acoustic tensor along each principal direction,
    // from the eigenproblem, for strained states of every elastic law
    std::mt19937 gen(43);
    scalar worst = 0;
    for (const std::string& law : everyElasticLaw())
    {
        const hyperelasticPhase phase("copper", dictFrom(law));
        for (int sample = 0; sample < 200; ++sample)
        {
            const matrix A(randomCobasis(gen, sample < 100 ? 1.1 : 1.8));
            const scalar rho = rho0Cu*A.determinant();
            const scalar p = 1e9;
            Eigen::SelfAdjointEigenSolver<matrix> eig(A.transpose()*A);
            scalar a2 = 0;
            for (int d = 0; d < 3; ++d)
            {
                a2 = max
                (
                    a2,
                    phase.waveSpeeds2(rho, p, A, eig.eigenvectors().col(d))(2)
                );
            }
            const scalar err = relErr(phase.a2Max(rho, p, A), a2);
            worst = max(worst, err);
            EXPECT_LT(err, 1e-12) << law << "\nA =\n" << A;
        }
    }
    std::printf
    (
        "[ measured ] a2Max against the eigenproblem: worst rel. error"
        " %.2e\n", worst
    );
}


TEST(hyperelasticPhase, unstrainedCobasisHasNoShear)
{
    // sigmaAndE takes a cobasis s I (cobasis::isUnstrained) as stress free
    // with no elastic energy, without evaluating the law: the general path
    // must give the same to round-off for every law and density, and a
    // cobasis with the smallest shear must take the general path
    const scalar mu = muCu;
    scalar worstS = 0, worstE = 0;
    for (const std::string& law : everyElasticLaw())
    {
        const hyperelasticPhase phase("copper", dictFrom(law));
        for (const scalar s : {0.7, 0.93, 1.0, 1.04, 1.3})
        {
            const matrix A(s*matrix::Identity());
            ASSERT_TRUE(cobasis::isUnstrained(A));
            const scalar rho = rho0Cu*A.determinant();
            const scalar p = 2e9;
            matrix sigma;
            scalar e;
            phase.sigmaAndE(rho, p, A, sigma, e);
            EXPECT_EQ(sigma, (-p*matrix::Identity()).eval());
            EXPECT_EQ(e, phase.eos().e(rho, p));

            // The general path
            const matrix g(cobasis::g(A));
            const matrix S(phase.elastic().S(g, A.determinant()));
            const scalar ee = phase.elastic().energy(g);
            worstS = max(worstS, maxAbs(S)/mu);
            worstE = max(worstE, mag(ee)/(mu/rho0Cu));
            EXPECT_LT(maxAbs(S), 1e-13*mu) << law << " s = " << s;
            EXPECT_LT(mag(ee), 1e-13*mu/rho0Cu) << law << " s = " << s;

            // The smallest shear is not unstrained
            matrix As(A);
            As(0, 1) = 1e-3*s;
            EXPECT_FALSE(cobasis::isUnstrained(As));
            phase.sigmaAndE(rho, p, As, sigma, e);
            EXPECT_GT(mag(sigma(0, 1)), 1e-4*mu) << law;
        }
    }
    EXPECT_FALSE(cobasis::isUnstrained(matrix::Zero()));
    std::printf
    (
        "[ measured ] general path at A = s I: |S|/mu %.2e, e_e/(mu/rho0)"
        " %.2e\n", worstS, worstE
    );
}


TEST(hyperelasticPhase, energyPressureRoundTrip)
{
    std::mt19937 gen(41);
    const hyperelasticPhase phase(copper(0.5));
    for (int sample = 0; sample < 50; ++sample)
    {
        const matrix A(randomCobasis(gen, 1.2));
        const scalar rho = rho0Cu*A.determinant();
        for (const scalar p : {1e5, 3e9})
        {
            const scalar e = phase.e(rho, p, A);
            EXPECT_NEAR
            (
                e,
                phase.eos().e(rho, p) + phase.elastic().energy(cobasis::g(A)),
                1e-15*mag(e)
            );
            EXPECT_NEAR(phase.p(rho, e, A), p, 1e-13*(mag(p) + pInfCu));
        }
        EXPECT_LE
        (
            maxAbs(phase.sigma(1e9, A) + 1e9*matrix::Identity() - phase.S(A)),
            1e-15*1e9
        );
    }
}


TEST(hyperelasticPhase, fluid)
{
    std::mt19937 gen(43);
    const hyperelasticPhase water
    (
        "water",
        dictFrom
        (
            "type fluid; equationOfState { type stiffenedGas; gamma 4.4;"
            " pInf 6e8; }"
        )
    );
    EXPECT_FALSE(water.solid());
    EXPECT_EQ(water.mu(), 0);
    EXPECT_EQ(water.cT2(), 0);

    const scalar rho = 1000, p = 1e5;
    const scalar c2 = 4.4*(p + 6e8)/rho;
    const matrix A(randomCobasis(gen, 1.5));   // ignored for a fluid
    EXPECT_NEAR(water.a2Max(rho, p, A), c2, 1e-14*c2);
    EXPECT_EQ(water.elasticEnergy(A), 0);
    EXPECT_EQ(maxAbs(water.S(A)), 0);
    for (int sample = 0; sample < 10; ++sample)
    {
        const vector w(water.waveSpeeds2(rho, p, A, randomUnit(gen)));
        EXPECT_NEAR(w(0), 0, 1e-14*c2);
        EXPECT_NEAR(w(1), 0, 1e-14*c2);
        EXPECT_NEAR(w(2), c2, 1e-14*c2);
    }
    EXPECT_THROW(water.elastic(), Foam::error);
}
