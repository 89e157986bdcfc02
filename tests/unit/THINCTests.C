/*---------------------------------------------------------------------------*\
  Unit tests of the THINC profile (docs/numerics.md section 5.11): the jump
  position reproduces the cell's mean, the closed-form mean over an
  interval equals a quadrature of H, the face values lie within (0, 1) and
  grow towards the larger side, and the profile steepens with beta.
\*---------------------------------------------------------------------------*/

#include <gtest/gtest.h>
#include "THINC.H"
#include <cmath>

using namespace Foam;

namespace
{

//- Mean of H over [a, b] by the composite Simpson rule
double simpsonMean(const THINC& t, const double a, const double b,
                   const double xiJ)
{
    const int n = 2000;
    const double h = (b - a)/n;
    const auto H = [&](const double x)
    {
        return 0.5*(1 + std::tanh(t.beta()*(x - xiJ)));
    };
    double s = H(a) + H(b);
    for (int i = 1; i < n; ++i)
    {
        s += (i % 2 ? 4 : 2)*H(a + i*h);
    }
    return s*h/3/(b - a);
}

} // End anonymous namespace


TEST(THINC, jumpReproducesTheCellMean)
{
    for (const double beta : {0.5, 1.6, 2.5, 10.0})
    {
        const THINC t(beta);
        for (const double aBar : {1e-4, 0.01, 0.3, 0.5, 0.77, 0.999, 1 - 1e-4})
        {
            const double xiJ = t.jump(aBar);
            EXPECT_NEAR(t.mean(0, 1, xiJ), aBar, 1e-12)
                << "beta " << beta << " aBar " << aBar;
            EXPECT_NEAR(simpsonMean(t, 0, 1, xiJ), aBar, 1e-9)
                << "beta " << beta << " aBar " << aBar;
        }
        // Symmetry: 1 - aBar puts the jump at the mirror position
        EXPECT_NEAR(t.jump(0.3) + t.jump(0.7), 1, 1e-12);
    }
}


TEST(THINC, meanOverIntervalsMatchesQuadrature)
{
    const THINC t(2.5);
    const double xiJ = t.jump(0.35);
    const double intervals[][2] =
        {{0, 0.5}, {0.5, 1}, {-0.2, 0.8}, {0.9, 1.0}, {0.25, 1.25}};
    for (const auto& iv : intervals)
    {
        EXPECT_NEAR(t.mean(iv[0], iv[1], xiJ),
                    simpsonMean(t, iv[0], iv[1], xiJ), 1e-10)
            << "[" << iv[0] << ", " << iv[1] << "]";
    }
    // A point (zero width) takes the point value, and the mean is
    // continuous as the width shrinks to it
    const double point = 0.5*(1 + std::tanh(2.5*(0.7 - xiJ)));
    EXPECT_NEAR(t.mean(0.7, 0.7, xiJ), point, 1e-15);
    EXPECT_NEAR(t.mean(0.7 - 1e-5, 0.7 + 1e-5, xiJ), point, 1e-9);
}


TEST(THINC, faceValuesBoundedAndSteepening)
{
    // Face values at xi = 0 and 1 bracket the mean and stay in (0, 1);
    // a larger beta pushes them towards 0 and 1
    double lastSpread = 0;
    for (const double beta : {0.5, 1.6, 2.5, 4.0})
    {
        const THINC t(beta);
        const double xiJ = t.jump(0.5);
        const double left = t.mean(0, 0, xiJ);
        const double right = t.mean(1, 1, xiJ);
        EXPECT_GT(left, 0);
        EXPECT_LT(left, 0.5);
        EXPECT_GT(right, 0.5);
        EXPECT_LT(right, 1);
        EXPECT_GT(right - left, lastSpread) << "beta " << beta;
        lastSpread = right - left;
    }
    // beta 4 at aBar 0.5: the faces hold (1 -+ tanh 2)/2
    EXPECT_NEAR(lastSpread, std::tanh(2.0), 1e-14);
}


// ************************************************************************* //
