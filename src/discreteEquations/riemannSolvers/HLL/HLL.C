#include "HLL.H"
#include "HLLC.H"
#include "addToRunTimeSelectionTable.H"
#include <algorithm>
#include <cmath>

namespace Foam
{
namespace riemannSolvers
{
    defineTypeNameAndDebug(HLL, 0);
    addToRunTimeSelectionTable(riemannSolver, HLL, dictionary);
}
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::riemannSolvers::HLL::HLL(const dictionary& dict)
:
    riemannSolver(dict)
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::riemannSolution Foam::riemannSolvers::HLL::solve
(
    const riemannState& L,
    const riemannState& R,
    const bool sameMaterial,
    const contactLaw* contact
) const
{
    const double uL = L.v(0);
    const double uR = R.v(0);

    // Einfeldt's bounds from the square-root-density averages
    const double rL = std::sqrt(L.rho);
    const double rR = std::sqrt(R.rho);
    const double w = 1/guard(rL + rR);
    const double uBar = (rL*uL + rR*uR)*w;
    const double aBar = std::sqrt
    (
        (rL*L.a*L.a + rR*R.a*R.a)*w + 0.5*rL*rR*w*w*(uR - uL)*(uR - uL)
    );
    const double SL = std::min(uL - L.a, uBar - aBar);
    const double SR = std::max(uR + R.a, uBar + aBar);

    // The contact (HLLC's for these bounds): u*, t*, v*; and, between two
    // materials, the flux of the upwind side's star state
    riemannSolution sol(HLLC::starSolution(L, R, SL, SR, contact));
    if (!sameMaterial)
    {
        return sol;
    }

    // One phase: the HLL flux of the state at x/t = 0
    double mL, mR, eL, eR;
    cobasis::vector pL, pR;
    physicalFlux(L, mL, pL, eL);
    physicalFlux(R, mR, pR, eR);

    if (SL >= 0)
    {
        sol.massFlux = mL;
        sol.momentumFlux = pL;
        sol.energyFlux = eL;
    }
    else if (SR <= 0)
    {
        sol.massFlux = mR;
        sol.momentumFlux = pR;
        sol.energyFlux = eR;
    }
    else
    {
        const double dS = guard(SR - SL);
        sol.massFlux = (SR*mL - SL*mR + SL*SR*(R.rho - L.rho))/dS;
        sol.momentumFlux =
            (SR*pL - SL*pR + SL*SR*(R.rho*R.v - L.rho*L.v))/dS;
        sol.energyFlux =
            (SR*eL - SL*eR + SL*SR*(R.rho*R.E - L.rho*L.E))/dS;
    }

    // The contact velocity carries that mass flux with the HLL density, so
    // that the DEM's upwind side (the sign of u*) is where the mass comes
    // from
    const double rhoStar =
        (SR*R.rho - SL*L.rho - (mR - mL))/guard(SR - SL);
    sol.uStar = sol.massFlux/guard(rhoStar);
    sol.vStarL(0) = sol.uStar;
    sol.vStarR(0) = sol.uStar;

    return sol;
}
