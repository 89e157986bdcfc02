#include "HLLC.H"
#include "addToRunTimeSelectionTable.H"
#include "readOption.H"
#include <algorithm>
#include <cmath>

namespace Foam
{
namespace riemannSolvers
{
    defineTypeNameAndDebug(HLLC, 0);
    addToRunTimeSelectionTable(riemannSolver, HLLC, dictionary);
}
}

const Foam::Enum<Foam::riemannSolvers::HLLC::waveSpeeds>
Foam::riemannSolvers::HLLC::waveSpeedsNames
({
    {waveSpeeds::pressureBased, "pressureBased"},
    {waveSpeeds::Davis, "Davis"}
});


namespace
{

using Foam::riemannSolver;


//- Contact speed S* of the HLLC solution for the given bounds
inline double contactSpeed
(
    const Foam::riemannState& L,
    const Foam::riemannState& R,
    const double SL,
    const double SR,
    double& mL,
    double& mR
)
{
    // Longitudinal impedances m_K = rho_K (u_K - S_K): mL > 0 > mR
    mL = L.rho*(L.v(0) - SL);
    mR = R.rho*(R.v(0) - SR);
    // S* = [s_Ln - s_Rn + rho_L u_L (S_L - u_L) - rho_R u_R (S_R - u_R)]
    //    / [rho_L (S_L - u_L) - rho_R (S_R - u_R)]
    return
        (L.s(0) - R.s(0) - mL*L.v(0) + mR*R.v(0))
       /riemannSolver::guard(mR - mL);
}

} // End anonymous namespace


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::riemannSolvers::HLLC::HLLC(const dictionary& dict)
:
    riemannSolver(dict),
    waveSpeeds_
    (
        readOption
        (
            dict, "waveSpeeds", waveSpeedsNames, waveSpeeds::Davis,
            "discreteEquations"
        )
    )
{}


Foam::riemannSolvers::HLLC::HLLC(const waveSpeeds estimate)
:
    riemannSolver(dictionary()),
    waveSpeeds_(estimate)
{}


Foam::wordList Foam::riemannSolvers::HLLC::keywords() const
{
    wordList valid(riemannSolver::keywords());
    valid.append("waveSpeeds");
    return valid;
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::riemannSolution Foam::riemannSolvers::HLLC::solve
(
    const riemannState& L,
    const riemannState& R,
    const bool,
    const contactLaw* contact
) const
{
    const double uL = L.v(0);
    const double uR = R.v(0);

    // Davis bounds
    double SL = std::min(uL - L.a, uR - R.a);
    double SR = std::max(uL + L.a, uR + R.a);

    if (waveSpeeds_ == waveSpeeds::pressureBased)
    {
        // Acoustic contact pressure between the two impedances (pressure
        // = minus the normal traction)
        const double ZL = L.rho*L.a, ZR = R.rho*R.a;
        const double pL = -L.s(0), pR = -R.s(0);
        const double pStar =
            (ZR*pL + ZL*pR + ZL*ZR*(uL - uR))/guard(ZL + ZR);
        // Where the fundamental derivative is negative (Mie-Grueneisen
        // below its reference curve in tension) a compression is no shock
        // and its fastest speed is the side's own: q = 1, and the root
        // stays real
        const double qL =
            pStar > pL
          ? std::sqrt(1 + std::max(L.G, 0.0)*(pStar - pL)/guard(ZL*L.a))
          : 1;
        const double qR =
            pStar > pR
          ? std::sqrt(1 + std::max(R.G, 0.0)*(pStar - pR)/guard(ZR*R.a))
          : 1;
        SL = uL - qL*L.a;
        SR = uR + qR*R.a;
    }

    return starSolution(L, R, SL, SR, contact);
}


Foam::riemannSolution Foam::riemannSolvers::HLLC::starSolution
(
    const riemannState& L,
    const riemannState& R,
    double SL,
    double SR,
    const contactLaw* contact
)
{
    const double uL = L.v(0);
    const double uR = R.v(0);

    // Davis bounds, the fall-back when S* is not between SL and SR
    const double SLDavis = std::min(uL - L.a, uR - R.a);
    const double SRDavis = std::max(uL + L.a, uR + R.a);

    double mL, mR;
    double Sstar = contactSpeed(L, R, SL, SR, mL, mR);
    if (!(SL < Sstar && Sstar < SR))
    {
        SL = std::min(SL, SLDavis);
        SR = std::max(SR, SRDavis);
        Sstar = contactSpeed(L, R, SL, SR, mL, mR);
    }

    riemannSolution sol;
    sol.uStar = Sstar;

    // Normal star traction
    sol.tStar(0) =
        (mR*L.s(0) - mL*R.s(0) + mL*mR*(uR - uL))/guard(mR - mL);

    // Tangential star traction and velocities
    double mtL = mL, mtR = mR;
    if (L.solid && R.solid)
    {
        // Welded contact; shear impedance rho c_T with the sign of u - S
        mtL = L.rho*L.cT;
        mtR = -R.rho*R.cT;
        for (int j = 1; j < 3; ++j)
        {
            sol.tStar(j) =
                (mtR*L.s(j) - mtL*R.s(j) + mtL*mtR*(R.v(j) - L.v(j)))
               /guard(mtR - mtL);
        }
        if (contact)
        {
            // Two solids that may slide: the shear traction capped at
            // the law's limit at this normal traction (each side's star
            // velocity follows from it)
            contact->limitShear
            (
                sol.tStar, L.strength < R.strength ? L.strength : R.strength
            );
        }
    }
    else
    {
        // A fluid holds no shear
        sol.tStar(1) = 0;
        sol.tStar(2) = 0;
        if (L.solid) mtL = L.rho*L.cT;
        if (R.solid) mtR = -R.rho*R.cT;
    }

    sol.vStarL(0) = Sstar;
    sol.vStarR(0) = Sstar;
    for (int j = 1; j < 3; ++j)
    {
        sol.vStarL(j) =
            L.solid ? L.v(j) + (sol.tStar(j) - L.s(j))/guard(mtL) : L.v(j);
        sol.vStarR(j) =
            R.solid ? R.v(j) + (sol.tStar(j) - R.s(j))/guard(mtR) : R.v(j);
    }

    // Flux of the state at x/t = 0, on the upwind side of the contact
    const bool left = (Sstar >= 0);
    const riemannState& K = left ? L : R;
    const double SK = left ? SL : SR;

    if ((left && SL >= 0) || (!left && SR < 0))
    {
        // Unperturbed state
        const double un = K.v(0);
        sol.massFlux = K.rho*un;
        sol.momentumFlux = K.rho*un*K.v - K.s;
        sol.energyFlux = K.rho*K.E*un - K.s.dot(K.v);
    }
    else
    {
        const cobasis::vector& vStar = left ? sol.vStarL : sol.vStarR;
        const double d = guard(SK - Sstar);
        const double rhoStar = K.rho*(SK - K.v(0))/d;
        const double rhoEStar =
            (K.rho*K.E*(SK - K.v(0)) + K.s.dot(K.v) - sol.tStar.dot(vStar))/d;

        sol.massFlux = rhoStar*Sstar;
        sol.momentumFlux = rhoStar*Sstar*vStar - sol.tStar;
        sol.energyFlux = rhoEStar*Sstar - sol.tStar.dot(vStar);
    }

    return sol;
}
