/*---------------------------------------------------------------------------*\
  Unit tests of the face Riemann solvers (docs/numerics.md section 3): the
  contract of riemannSolver.H for every model in the run-time selection
  table: consistency F(U, U), the symmetric impact, a contact at rest,
  the upwind owner of the flux, and the selection itself.
\*---------------------------------------------------------------------------*/

#include <gtest/gtest.h>
#include "riemannSolver.H"
#include "HLLC.H"
#include "unitTestTools.H"

using namespace Foam;
using unitTestTools::dictFrom;

namespace
{

//- Every model, and HLLC with each wave speed estimate
std::vector<std::string> solverDicts()
{
    return
    {
        "riemannSolver HLLC; waveSpeeds Davis;",
        "riemannSolver HLLC; waveSpeeds pressureBased;",
        "riemannSolver HLL;"
    };
}


//- A stiffened-gas state: rho, velocity v, pressure p plus a deviatoric
//  traction st (solids), longitudinal speed a
riemannState makeState
(
    const double rho,
    const cobasis::vector& v,
    const double p,
    const cobasis::vector& st,
    const double gamma,
    const double pInf,
    const bool solid,
    const double cT
)
{
    riemannState K;
    K.rho = rho;
    K.v = v;
    K.s = st - p*cobasis::vector::UnitX();
    const double e = (p + gamma*pInf)/((gamma - 1)*rho);
    K.E = e + 0.5*v.squaredNorm();
    K.a = std::sqrt(gamma*(p + pInf)/rho + (solid ? 4.0/3.0*cT*cT : 0));
    K.cT = solid ? cT : 0;
    K.G = 0.5*(gamma + 1);
    K.solid = solid;
    return K;
}


riemannState copper(const cobasis::vector& v, const double p)
{
    return makeState
    (
        8930, v, p, cobasis::vector(2e7, 1e8, -5e7), 4.22, 3.08e10,
        true, 2200
    );
}


riemannState air(const cobasis::vector& v, const double p)
{
    return makeState
    (
        1.2, v, p, cobasis::vector::Zero(), 1.4, 0, false, 0
    );
}

} // End anonymous namespace


TEST(riemannSolver, selectsEveryModelAndRejectsUnknown)
{
    EXPECT_EQ(riemannSolver::New(dictFrom(""))->type(), "HLLC");
    EXPECT_EQ(riemannSolver::New(dictFrom("riemannSolver HLL;"))->type(), "HLL");
    try
    {
        riemannSolver::New(dictFrom("riemannSolver Roe;"));
        FAIL() << "unknown riemannSolver accepted";
    }
    catch (const Foam::error& err)
    {
        EXPECT_NE(err.message().find("Roe"), std::string::npos);
        EXPECT_NE(err.message().find("HLL"), std::string::npos);
    }
    try
    {
        riemannSolver::New(dictFrom("riemannSolver HLLC; waveSpeeds fast;"));
        FAIL() << "unknown waveSpeeds accepted";
    }
    catch (const Foam::error& err)
    {
        EXPECT_NE(err.message().find("waveSpeeds"), std::string::npos);
    }
}


TEST(riemannSolver, consistencyEqualStatesGiveThePhysicalFlux)
{
    for (const std::string& d : solverDicts())
    {
        const autoPtr<riemannSolver> solver(riemannSolver::New(dictFrom(d)));
        for (const double un : {-300.0, -1e-3, 0.0, 250.0})
        {
            const cobasis::vector v(un, 40, -70);
            for (const riemannState& K : {copper(v, 2e9), air(v, 1e5)})
            {
                const riemannSolution sol = solver->solve(K, K, true);
                double m;
                cobasis::vector mom;
                double E;
                riemannSolver::physicalFlux(K, m, mom, E);

                SCOPED_TRACE(d + " un " + std::to_string(un));
                const double vScale = K.a + std::abs(un);
                EXPECT_NEAR(sol.uStar, un, 1e-12*vScale);
                EXPECT_LE((sol.tStar - K.s).norm(), 1e-12*K.s.norm());
                EXPECT_LE((sol.vStarL - K.v).norm(), 1e-12*vScale);
                EXPECT_LE((sol.vStarR - K.v).norm(), 1e-12*vScale);
                EXPECT_NEAR(sol.massFlux, m, 1e-12*K.rho*vScale);
                EXPECT_LE
                (
                    (sol.momentumFlux - mom).norm(),
                    1e-12*(K.rho*vScale*vScale + K.s.norm())
                );
                EXPECT_NEAR
                (
                    sol.energyFlux, E,
                    1e-12*(K.rho*K.E + K.s.norm())*vScale
                );
            }
        }
    }
}


TEST(riemannSolver, symmetricImpactHasAContactAtRest)
{
    // Two equal copper rods meeting at +/- 227 m/s: by symmetry u* = 0 and
    // no mass crosses; the contact is compressed, no tangential traction
    const double w = 227, p = 1e5;
    for (const std::string& d : solverDicts())
    {
        SCOPED_TRACE(d);
        const autoPtr<riemannSolver> solver(riemannSolver::New(dictFrom(d)));
        riemannState L =
            makeState(8930, cobasis::vector(w, 0, 0), p,
                      cobasis::vector::Zero(), 4.22, 3.08e10, true, 2200);
        riemannState R = L;
        R.v(0) = -w;

        const riemannSolution sol = solver->solve(L, R, true);
        EXPECT_NEAR(sol.uStar, 0, 1e-12*L.a);
        EXPECT_NEAR(sol.massFlux, 0, 1e-12*L.rho*L.a);
        EXPECT_NEAR(sol.tStar(1), 0, 1e-6);
        EXPECT_NEAR(sol.tStar(2), 0, 1e-6);

        // Compression of the order of the acoustic value rho a w
        const double pStar = -sol.tStar(0);
        EXPECT_GT(pStar - p, 0.8*L.rho*L.a*w);
        EXPECT_LT(pStar - p, 1.5*L.rho*L.a*w);

        if (d.find("Davis") != std::string::npos)
        {
            // HLLC with Davis speeds S = +/-(w + a): p* = p + rho (2w + a) w
            EXPECT_NEAR(pStar, p + L.rho*(2*w + L.a)*w, 1e-12*pStar);
        }

        // Mirror: the same problem seen from the other side
        riemannState Lm = R, Rm = L;
        Lm.v(0) = -R.v(0);
        Rm.v(0) = -L.v(0);
        const riemannSolution mir = solver->solve(Lm, Rm, true);
        EXPECT_NEAR(mir.tStar(0), sol.tStar(0), 1e-12*pStar);
    }
}


TEST(riemannSolver, contactAtRestBetweenCopperAndAir)
{
    // A material interface in equilibrium: u = 0 and the same normal
    // traction on both sides (the copper's deviatoric normal traction 0)
    const double p = 1e5;
    for (const std::string& d : solverDicts())
    {
        SCOPED_TRACE(d);
        const autoPtr<riemannSolver> solver(riemannSolver::New(dictFrom(d)));
        riemannState Cu =
            makeState(8930, cobasis::vector::Zero(), p,
                      cobasis::vector(0, 3e7, 0), 4.22, 3.08e10, true, 2200);
        const riemannState Air = air(cobasis::vector::Zero(), p);

        for (const bool copperLeft : {true, false})
        {
            const riemannSolution sol =
                copperLeft
              ? solver->solve(Cu, Air, false)
              : solver->solve(Air, Cu, false);
            EXPECT_NEAR(sol.uStar, 0, 1e-12);
            EXPECT_NEAR(sol.massFlux, 0, 1e-12);
            EXPECT_NEAR(sol.tStar(0), -p, 1e-12*p);
            // No shear across a fluid contact
            EXPECT_EQ(sol.tStar(1), 0);
            EXPECT_EQ(sol.tStar(2), 0);
            EXPECT_NEAR(sol.momentumFlux(0), p, 1e-12*p);
            EXPECT_NEAR(sol.energyFlux, 0, 1e-12*p);
        }
    }
}


TEST(riemannSolver, materialContactInUniformMotionIsPreserved)
{
    // Copper and air (and copper against copper at another density) in
    // uniform normal velocity and pressure: u* = u and t*_n = -p in any
    // frame, the basis of Abgrall's criterion in the DEM
    const double p = 1e5;
    for (const std::string& d : solverDicts())
    {
        SCOPED_TRACE(d);
        const autoPtr<riemannSolver> solver(riemannSolver::New(dictFrom(d)));
        for (const double u : {-100.0, 3.0, 100.0, 2000.0})
        {
            const cobasis::vector v(u, 20, 0);
            riemannState Cu =
                makeState(8930, v, p, cobasis::vector(0, 3e7, 0),
                          4.22, 3.08e10, true, 2200);
            const riemannState Air = air(v, p);
            riemannState dense = Cu;
            dense.rho = 9500;

            for (const auto& pair :
                {std::make_pair(Cu, Air), std::make_pair(Air, Cu),
                 std::make_pair(Cu, dense)})
            {
                const riemannSolution sol =
                    solver->solve(pair.first, pair.second, false);
                EXPECT_NEAR(sol.uStar, u, 1e-12*(std::abs(u) + Cu.a));
                EXPECT_NEAR(sol.tStar(0), -p, 1e-9*p);
            }
        }
    }
}


TEST(riemannSolver, fluxBelongsToTheUpwindSide)
{
    // Copper moving into air at 100 m/s: u* > 0 and the flux is copper's
    // (mass flux rho_copper-like); moving away, u* < 0 and it is air's
    for (const std::string& d : solverDicts())
    {
        SCOPED_TRACE(d);
        const autoPtr<riemannSolver> solver(riemannSolver::New(dictFrom(d)));
        for (const double u : {100.0, -100.0})
        {
            const cobasis::vector v(u, 0, 0);
            const riemannState Cu = copper(v, 1e5);
            const riemannState Air = air(v, 1e5);
            const riemannSolution sol = solver->solve(Cu, Air, false);
            EXPECT_EQ(sol.uStar > 0, u > 0);
            const double rhoUp = sol.massFlux/sol.uStar;
            if (u > 0)
            {
                EXPECT_GT(rhoUp, 1000);
            }
            else
            {
                EXPECT_LT(rhoUp, 100);
            }
        }
    }
}
