/*---------------------------------------------------------------------------*\
  Unit tests of the plastic relaxation (docs/validation.md V7): the Von Mises
  return lands on the yield surface, keeps det A (density), leaves the
  yielded A without rotation (A = G^(1/2), symmetric positive definite: the
  rotation carries no stress, and a rotation field that varies from cell to
  cell is strained by the numerical diffusion of the Eulerian transport) and
  an elastic A untouched, moves g radially in log-strain, never increases e_e and returns the
  released shear energy as heat; hardening, visco-plasticity and 'none'.
  Copper (a = 1/2) and a soft clay (a = -1).
\*---------------------------------------------------------------------------*/

#include <gtest/gtest.h>
#include "plasticModel.H"
#include "elasticModel.H"
#include "unitTestTools.H"

#include <cstdio>
#include <iomanip>
#include <sstream>
#include <vector>

using namespace Foam;
using namespace unitTestTools;

namespace
{

struct material
{
    const char* name;
    const char* elasticity;
    scalar sigmaY;
    scalar H;           // hardening modulus for the hardening test
};

const material materials[] =
{
    {
        "copper",
        "type separable; rho0 8900; mu 4.5e10; a 0.5;",
        4e8,
        1e8
    },
    {
        "clay",
        "type separable; rho0 1800; mu 1e6; a -1;",
        5e4,
        2e4
    }
};


autoPtr<plasticModel> plasticFrom(const material& m, const std::string& text)
{
    return plasticModel::New(m.name, dictFrom(text));
}

std::string vonMisesText(const scalar sigmaY, const scalar tau)
{
    std::ostringstream os;
    os  << std::setprecision(17)
        << "type vonMises; sigmaY " << sigmaY << "; tau " << tau << ";";
    return os.str();
}


//- Von Mises equivalent stress sqrt(3/2)|S|
scalar vonMisesStress(const elasticModel& elastic, const matrix& A)
{
    return std::sqrt(1.5)*elastic.SofA(A).norm();
}


//- The principal log-strains of g(Anew) in the principal frame of g(Aold):
//  checks that the two are coaxial and returns s with ln g_new = s ln g_old
scalar returnFraction(const matrix& Aold, const matrix& Anew)
{
    Eigen::SelfAdjointEigenSolver<matrix> eig(cobasis::g(Aold));
    const vector h(eig.eigenvalues().array().log());
    const matrix gNew
    (
        eig.eigenvectors().transpose()*cobasis::g(Anew)*eig.eigenvectors()
    );
    // Off-diagonal part vanishes when coaxial
    const matrix off(gNew - matrix(gNew.diagonal().asDiagonal()));
    EXPECT_LE(maxAbs(off), 1e-12*maxAbs(gNew));
    const vector hNew(gNew.diagonal().array().log());
    const scalar s = hNew.dot(h)/h.squaredNorm();
    EXPECT_LE((hNew - s*h).norm(), 1e-10*h.norm());
    return s;
}


//- Worst relative errors, printed at the end of each test
struct worstErrors
{
    scalar yield = 0, det = 0, detg = 0, rotation = 0, heat = 0, epsP = 0;
};

} // End anonymous namespace


TEST(vonMises, stressAndEnergyGrowAlongReturnPath)
{
    // The return path g(s) = Q diag(l_i^s) Q^T, s in [0, 1], on which the
    // algorithm searches for the yield surface: |S| and e_e grow with s
    // (docs/model.md), so the root is unique. Unimodular stretches up to 10.
    std::mt19937 gen(71);
    std::uniform_real_distribution<double> U(-std::log(10.0), std::log(10.0));
    for (const material& m : materials)
    {
        auto elastic = elasticModel::New(m.name, dictFrom(m.elasticity));
        for (int sample = 0; sample < 500; ++sample)
        {
            const scalar h1 = U(gen), h2 = U(gen);
            const vector h(h1, h2, -h1 - h2);
            const matrix Q(randomRotation(gen));
            scalar Sprev = 0, ePrev = 0;
            for (int k = 1; k <= 50; ++k)
            {
                const vector l((k/50.0*h).array().exp());
                const matrix g(Q*l.asDiagonal()*Q.transpose());
                const scalar Sn = elastic->S(g, 1).norm();
                const scalar e = elastic->energy(g);
                EXPECT_GT(Sn, Sprev) << m.name << ", h = " << h.transpose();
                EXPECT_GT(e, ePrev) << m.name << ", h = " << h.transpose();
                Sprev = Sn;
                ePrev = e;
            }
        }
    }
}


TEST(vonMises, idealReturnLandsOnYieldSurface)
{
    std::mt19937 gen(47);
    worstErrors w;
    for (const material& m : materials)
    {
        auto elastic = elasticModel::New(m.name, dictFrom(m.elasticity));
        auto plastic = plasticFrom(m, vonMisesText(m.sigmaY, 0));
        EXPECT_TRUE(plastic->plastic());
        EXPECT_EQ(plastic->sigmaY(0.7, 0, 0), m.sigmaY);

        int nYield = 0, nElastic = 0;
        for (int sample = 0; sample < 2000; ++sample)
        {
            const matrix A0(randomState(gen));
            matrix A(A0);
            const scalar epsP0 = 0.1*(sample % 5);
            scalar epsP = epsP0;
            const scalar f0 = vonMisesStress(*elastic, A0);
            const scalar e0 = elastic->energy(cobasis::g(A0));

            const scalar heat = plastic->correct(A, epsP, *elastic, 0, 0);

            if (f0 <= m.sigmaY)
            {
                // Inside the yield surface: untouched, bit for bit
                ++nElastic;
                EXPECT_TRUE((A.array() == A0.array()).all());
                EXPECT_EQ(epsP, epsP0);
                EXPECT_EQ(heat, 0);
                continue;
            }
            ++nYield;

            // On the yield surface
            const scalar errY = relErr(vonMisesStress(*elastic, A), m.sigmaY);
            w.yield = max(w.yield, errY);
            EXPECT_LT(errY, 1e-10) << m.name << ", A0 =\n" << A0;

            // Density kept: det A, and det g = 1
            const scalar errDet = mag(A.determinant()/A0.determinant() - 1);
            const scalar errDetg = mag(cobasis::g(A).determinant() - 1);
            w.det = max(w.det, errDet);
            w.detg = max(w.detg, errDetg);
            EXPECT_LT(errDet, 1e-12) << m.name;
            EXPECT_LT(errDetg, 1e-12) << m.name;

            // Rotation of A discarded: A = (A^T A)^(1/2)
            const scalar errR =
                maxAbs(cobasis::rotation(A) - matrix::Identity());
            w.rotation = max(w.rotation, errR);
            EXPECT_LT(errR, 1e-12) << m.name;

            // Shear energy released as heat, nothing created or lost
            const scalar e1 = elastic->energy(cobasis::g(A));
            EXPECT_LT(e1, e0) << m.name;
            EXPECT_GT(heat, 0) << m.name;
            const scalar errHeat = mag(heat - (e0 - e1))/e0;
            w.heat = max(w.heat, errHeat);
            EXPECT_LT(errHeat, 1e-12) << m.name;

            // Radial return in log-strain; plastic strain grows by
            // sqrt(2/3) times the plastic Hencky strain (1 - s)/2 |ln g|
            const scalar s = returnFraction(A0, A);
            EXPECT_GE(s, 0);
            EXPECT_LT(s, 1);
            const scalar hNorm =
                Eigen::SelfAdjointEigenSolver<matrix>(cobasis::g(A0))
               .eigenvalues().array().log().matrix().norm();
            const scalar dEpsP = std::sqrt(2.0/3.0)*0.5*(1 - s)*hNorm;
            EXPECT_GT(epsP, epsP0);
            const scalar errEps = relErr(epsP - epsP0, dEpsP);
            w.epsP = max(w.epsP, errEps);
            EXPECT_LT(errEps, 1e-9) << m.name;

            // A second call changes nothing (already on the surface)
            matrix A2(A);
            scalar epsP2 = epsP;
            const scalar heat2 = plastic->correct(A2, epsP2, *elastic, 0, 0);
            EXPECT_LE(maxAbs(A2 - A), 1e-12*maxAbs(A));
            // heat2 is e_e(A) - e_e(A2): round-off of the energy, whose
            // terms are of order mu/rho0 (a difference of O(1) invariants)
            EXPECT_LE(mag(heat2), 1e-14*elastic->mu()/elastic->rho0());
        }
        EXPECT_GT(nYield, 200) << m.name;
        EXPECT_GT(nElastic, 100) << m.name;
        std::printf
        (
            "[ measured ] %s: %d yielding, %d elastic states\n",
            m.name, nYield, nElastic
        );
    }
    std::printf
    (
        "[ measured ] ideal return, worst: yield %.2e, det A %.2e,"
        " det g %.2e, rotation %.2e, heat %.2e, epsP %.2e\n",
        w.yield, w.det, w.detg, w.rotation, w.heat, w.epsP
    );
}


TEST(vonMises, linearHardening)
{
    std::mt19937 gen(53);
    scalar worst = 0;
    for (const material& m : materials)
    {
        auto elastic = elasticModel::New(m.name, dictFrom(m.elasticity));
        std::ostringstream os;
        os  << std::setprecision(17) << "type vonMises; sigmaY0 " << m.sigmaY
            << "; H " << m.H << "; tau 0;";
        auto plastic = plasticFrom(m, os.str());
        auto ideal = plasticFrom(m, vonMisesText(m.sigmaY, 0));
        EXPECT_EQ(plastic->sigmaY(0.5, 0, 0), m.sigmaY + 0.5*m.H);

        int nYield = 0;
        for (int sample = 0; sample < 500; ++sample)
        {
            const matrix A0(randomState(gen));
            const scalar epsP0 = 0.2*(sample % 4);
            if (vonMisesStress(*elastic, A0) <= plastic->sigmaY(epsP0, 0, 0))
            {
                continue;
            }
            ++nYield;
            matrix A(A0);
            scalar epsP = epsP0;
            plastic->correct(A, epsP, *elastic, 0, 0);

            EXPECT_GT(epsP, epsP0);
            const scalar err =
                relErr(vonMisesStress(*elastic, A), m.sigmaY + m.H*epsP);
            worst = max(worst, err);
            EXPECT_LT(err, 1e-10) << m.name << ", A0 =\n" << A0;
            EXPECT_LT(mag(A.determinant()/A0.determinant() - 1), 1e-12);

            // Hardening stops the return earlier than ideal plasticity
            // from the same (unhardened) state
            if (epsP0 == 0)
            {
                matrix Ai(A0);
                scalar epsPi = 0;
                ideal->correct(Ai, epsPi, *elastic, 0, 0);
                EXPECT_GT(vonMisesStress(*elastic, A), m.sigmaY);
                EXPECT_LT(epsP, epsPi);
            }
        }
        EXPECT_GT(nYield, 100) << m.name;
    }
    std::printf
    (
        "[ measured ] hardening: worst |sqrt(3/2)|S| - sigmaY(epsP)|/sigmaY"
        " %.2e\n", worst
    );
}


TEST(vonMises, viscoPlasticRelaxation)
{
    // tau > 0, n = 0: backward Euler of ds/dt = -s/tau gives
    // s = max(sY, 1/(1 + dt/tau)), sY the ideal return
    std::mt19937 gen(59);
    const scalar tau = 1e-6;
    const std::vector<scalar> ratios
        {1e-3, 1e-2, 0.1, 0.5, 1, 3, 10, 100, 1e3, 1e5, 1e9};
    scalar worstS = 0, worstIdeal = 0;

    for (const material& m : materials)
    {
        auto elastic = elasticModel::New(m.name, dictFrom(m.elasticity));
        auto visco = plasticFrom(m, vonMisesText(m.sigmaY, tau));
        auto ideal = plasticFrom(m, vonMisesText(m.sigmaY, 0));

        int nYield = 0;
        for (int sample = 0; sample < 300; ++sample)
        {
            const matrix A0(randomState(gen));
            const scalar f0 = vonMisesStress(*elastic, A0);
            if (f0 <= m.sigmaY) continue;
            ++nYield;

            matrix Ai(A0);
            scalar epsPi = 0;
            ideal->correct(Ai, epsPi, *elastic, 0, 0);
            const scalar sY = returnFraction(A0, Ai);

            scalar fPrev = f0, sPrev = 1, epsPPrev = 0;
            for (const scalar r : ratios)
            {
                matrix A(A0);
                scalar epsP = 0;
                const scalar e0 = elastic->energy(cobasis::g(A0));
                const scalar heat = visco->correct(A, epsP, *elastic, r*tau, 0);
                const scalar f = vonMisesStress(*elastic, A);
                const scalar s = returnFraction(A0, A);

                // On or above the yield surface, below the trial stress,
                // decreasing toward the surface as dt/tau grows
                EXPECT_GE(f, m.sigmaY*(1 - 1e-10)) << m.name << " dt/tau " << r;
                EXPECT_LE(f, fPrev*(1 + 1e-12)) << m.name << " dt/tau " << r;
                EXPECT_LE(s, sPrev + 1e-12);
                EXPECT_GE(epsP, epsPPrev*(1 - 1e-12));
                if (1/(1 + r) > sY + 1e-6)
                {
                    EXPECT_LT(f, fPrev) << m.name << " dt/tau " << r;
                    EXPECT_GT(f, m.sigmaY) << m.name << " dt/tau " << r;
                }

                // The discrete relaxation law
                const scalar sExpected = max(sY, 1/(1 + r));
                const scalar errS = mag(s - sExpected);
                worstS = max(worstS, errS);
                EXPECT_LT(errS, 1e-10) << m.name << " dt/tau " << r;

                // Density, rotation and energy as for the ideal return
                EXPECT_LT(mag(A.determinant()/A0.determinant() - 1), 1e-12);
                EXPECT_LT
                (
                    maxAbs(cobasis::rotation(A) - matrix::Identity()),
                    1e-12
                );
                const scalar e1 = elastic->energy(cobasis::g(A));
                EXPECT_LE(e1, e0);
                EXPECT_LT(mag(heat - (e0 - e1)), 1e-12*e0);

                fPrev = f;
                sPrev = s;
                epsPPrev = epsP;
            }

            // dt = 0: no relaxation
            {
                matrix A(A0);
                scalar epsP = 0;
                visco->correct(A, epsP, *elastic, 0, 0);
                EXPECT_LE(maxAbs(A - A0), 1e-12*maxAbs(A0)) << m.name;
                EXPECT_LE(epsP, 1e-12) << m.name;
            }

            // dt/tau -> infinity: the ideal return
            const scalar errIdeal = mag(fPrev - m.sigmaY)/m.sigmaY;
            worstIdeal = max(worstIdeal, errIdeal);
            EXPECT_LT(errIdeal, 1e-10) << m.name;
        }
        EXPECT_GT(nYield, 50) << m.name;
    }
    std::printf
    (
        "[ measured ] visco-plastic: worst |s - max(sY, 1/(1+dt/tau))| %.2e,"
        " dt/tau = 1e9 vs yield %.2e\n", worstS, worstIdeal
    );
}


TEST(vonMises, viscoPlasticExponent)
{
    // 1/tau(f) = (1/tau) (f/sigmaY)^n: backward Euler
    // s (1 + dt/tau (f(s)/sigmaY)^n) = 1 whenever s is above the ideal return
    std::mt19937 gen(61);
    const scalar tau = 1e-6;
    scalar worst = 0;
    for (const material& m : materials)
    {
        auto elastic = elasticModel::New(m.name, dictFrom(m.elasticity));
        std::ostringstream os;
        os  << std::setprecision(17) << "type vonMises; sigmaY " << m.sigmaY
            << "; tau " << tau << "; n 2;";
        auto visco = plasticFrom(m, os.str());
        auto ideal = plasticFrom(m, vonMisesText(m.sigmaY, 0));

        for (int sample = 0; sample < 200; ++sample)
        {
            const matrix A0(randomState(gen));
            if (vonMisesStress(*elastic, A0) <= m.sigmaY) continue;

            matrix Ai(A0);
            scalar epsPi = 0;
            ideal->correct(Ai, epsPi, *elastic, 0, 0);
            const scalar sY = returnFraction(A0, Ai);

            for (const scalar r : {1e-3, 0.1, 10.0})
            {
                matrix A(A0);
                scalar epsP = 0;
                visco->correct(A, epsP, *elastic, r*tau, 0);
                const scalar s = returnFraction(A0, A);
                const scalar f = vonMisesStress(*elastic, A) - m.sigmaY;
                EXPECT_GE(f, -1e-10*m.sigmaY);
                EXPECT_GE(s, sY - 1e-12);
                if (s > sY + 1e-8)
                {
                    const scalar residual =
                        s*(1 + r*std::pow(f/m.sigmaY, 2)) - 1;
                    worst = max(worst, mag(residual));
                    EXPECT_LT(mag(residual), 1e-10) << m.name << " dt/tau " << r;
                }
            }
        }
    }
    std::printf
    (
        "[ measured ] visco-plastic n = 2: worst backward-Euler residual %.2e\n",
        worst
    );
}


TEST(vonMises, noneLeavesCobasisUnchanged)
{
    std::mt19937 gen(67);
    for (const material& m : materials)
    {
        auto elastic = elasticModel::New(m.name, dictFrom(m.elasticity));
        auto none = plasticFrom(m, "type none;");
        EXPECT_FALSE(none->plastic());
        for (int sample = 0; sample < 50; ++sample)
        {
            const matrix A0(randomCobasis(gen, 3));
            matrix A(A0);
            scalar epsP = 0.25;
            EXPECT_EQ(none->correct(A, epsP, *elastic, 1e-6, 0), 0);
            EXPECT_TRUE((A.array() == A0.array()).all());
            EXPECT_EQ(epsP, 0.25);
        }
    }
}
