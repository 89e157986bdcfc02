/*---------------------------------------------------------------------------*\
  impactFoam: Eulerian multiphase elastic-plastic impact solver for OpenFOAM
-------------------------------------------------------------------------------
Description
    The relaxation services of equationOfState, built on its primitives
    p(rho, e), e(rho, p), c2(rho, p), Gamma(rho, e), pMin(rho), rhoMax()
    only, so that they serve every equation of state. A model with closed
    forms (stiffenedGas) overrides them.

    Two paths take a phase from its state (vOld, eOld) to an interface
    pressure p*:
    - the constant-pressure path de = -p* dv, a straight line in (v, e),
      ending where p = p*. Its end state solves one scalar equation;
      differentiating it (with dp/drho at constant e = c2 - p Gamma/rho and
      dp/de at constant rho = rho Gamma) gives the slope dv/dp*;
    - the isentrope de = -p dv, the integral curve of dp/drho = c2(rho, p)
      in the (rho, p) plane: integrated to round-off by scalarODE.H, its
      slope dv/dp = -1/(rho^2 c2) is exact.

\*---------------------------------------------------------------------------*/

#include "equationOfState.H"
#include "scalarODE.H"

#include <cmath>
#include <limits>

// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * //

namespace
{

// Maximum iterations of the Newton solves and bisections
const Foam::label maxIter = 200;

// Number of fourfold expansions when looking for the lowest pressure of a
// path (v up to 4^40 ~ 1e24 times its start)
const Foam::label nExpansions = 40;

const Foam::scalar NaN = std::numeric_limits<Foam::scalar>::quiet_NaN();

} // End anonymous namespace


// * * * * * * * * * * * * Protected Member Functions  * * * * * * * * * * //

bool Foam::equationOfState::isentropePressure
(
    const scalar rhoRef,
    const scalar pRef,
    const scalar rho,
    scalar& p
) const
{
    // dp/ds = rho c2(rho, p) in s = ln(rho/rhoRef); outside the admissible
    // range the right-hand side is not finite and the integrator stops
    const auto dpds = [this, rhoRef](const scalar s, const scalar pp)
    {
        const scalar r = rhoRef*std::exp(s);
        const scalar cc = c2(r, pp);
        return
            (r < rhoMax() && pp > pMin(r) && cc > 0)
          ? r*cc
          : NaN;
    };
    const auto scale = [this, rhoRef](const scalar s, const scalar pp)
    {
        return pScale(rhoRef*std::exp(s), pp);
    };
    return scalarODE::integrate
    (
        dpds, scale, 0, pRef, std::log(rho/rhoRef), tolerance, p
    );
}


void Foam::equationOfState::isentropeFailed
(
    const char* function,
    const scalar rhoRef,
    const scalar eRef,
    const char* what,
    const scalar value
) const
{
    FatalErrorInFunction
        << "Phase " << phaseName_ << ": equationOfState::" << function
        << ": the isentrope through rho = " << rhoRef << ", e = " << eRef
        << " (p = " << p(rhoRef, eRef) << ") leaves the admissible range"
        << " of the equation of state before " << what << " = " << value
        << exit(FatalError);
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * //

Foam::scalar Foam::equationOfState::vRelaxed
(
    const scalar pStar,
    const scalar rhoOld,
    const scalar eOld
) const
{
    // h(rho) = p(rho, e(rho)) - pStar along e(rho) = eOld - pStar (1/rho -
    // vOld): dh/drho = c2 - (p - pStar) Gamma/rho, which is c2 > 0 at the
    // root. Newton's method in rho (exact in one step for a stiffened gas,
    // where h is linear in rho), kept inside the bracket [rhoLo, rhoHi]
    // where h changes sign, bisection when it leaves it
    const scalar vOld = 1/rhoOld;
    scalar rhoLo = 0;
    scalar rhoHi = rhoMax();
    scalar rho = rhoOld;

    for (label iter = 0; iter < maxIter; ++iter)
    {
        const scalar eh = eOld - pStar*(1/rho - vOld);
        const scalar pp = p(rho, eh);
        const scalar h = pp - pStar;
        if (h == 0)
        {
            break;
        }
        if (h < 0)
        {
            rhoLo = rho;
        }
        else
        {
            rhoHi = rho;
        }

        const scalar dh = c2(rho, pp) - h*Gamma(rho, eh)/rho;
        scalar rhoNew = rho - h/dh;
        if (!(rhoNew > rhoLo && rhoNew < rhoHi))
        {
            // Bisect, or expand while no upper bound is known: fourfold,
            // but never beyond the admissible range (halfway to rhoMax
            // at most, where the model has a finite one: MieGruneisen)
            rhoNew =
                rhoHi < rhoMax()
              ? 0.5*(rhoLo + rhoHi)
              : min(4*rho, 0.5*(rho + rhoMax()));
        }
        // Quadratic convergence: a step below tolerance leaves an error
        // far below round-off
        const bool converged = mag(rhoNew - rho) <= tolerance*rho;
        rho = rhoNew;
        if (converged)
        {
            break;
        }
    }

    return 1/rho;
}


Foam::scalar Foam::equationOfState::dvRelaxeddpAt
(
    const scalar v,
    const scalar pStar,
    const scalar rhoOld,
    const scalar eOld
) const
{
    // G(v, pStar) = p(1/v, eOld - pStar (v - vOld)) - pStar = 0 at the end
    // state. With p_rho = dp/drho|e = c2 - p Gamma/rho, p_e = rho Gamma
    // and p = pStar there:
    //   dG/dv = -rho^2 p_rho - pStar rho Gamma = -rho^2 c2,
    //   dG/dpStar = -rho Gamma (v - vOld) - 1,
    // so dv/dpStar = -N/(rho^2 c2), N = 1 + Gamma (1 - rho vOld)
    const scalar rho = 1/v;
    const scalar eh = eOld - pStar*(v - 1/rhoOld);
    const scalar G = Gamma(rho, eh);
    scalar N = 1 + G*(1 - rho/rhoOld);

    // In a strong compression N is small: its two terms nearly cancel and
    // the rounding of v is amplified by about Gamma/N. A form without the
    // cancellation: with eOld - e = pStar (v - vOld) and p(rho, e) = pStar,
    //   pStar N = pStar + rho Gamma (eOld - e) = p(rho, eOld) - R,
    //   R = rho int_e^eOld (Gamma(rho, e') - Gamma(rho, e)) de',
    // where R = 0 when p is linear in e at constant rho (stiffened gas,
    // Mie-Grueneisen). It is used when its round-off relative to N,
    // pScale/|pStar| (in machine epsilons), is below that of the first
    // form, 1 + Gamma rho vOld
    const scalar pOldEnergy = p(rho, eOld);
    const scalar sAlt = pScale(rho, pOldEnergy);
    if (sAlt < (1 + mag(G)*rho/rhoOld)*mag(pStar))
    {
        // R vanishes where p is linear in e: no integral to take
        scalar R = 0;
        const auto dRde = [this, rho, G](const scalar e1, const scalar)
        {
            return rho*(Gamma(rho, e1) - G);
        };
        const auto scale = [sAlt](const scalar, const scalar)
        {
            return sAlt;
        };
        if
        (
            pLinearInEnergy()
         || scalarODE::integrate(dRde, scale, eh, 0, eOld, tolerance, R)
        )
        {
            N = (pOldEnergy - R)/pStar;
        }
    }

    return -N/(rho*rho*c2(rho, pStar));
}


Foam::scalar Foam::equationOfState::pRelaxedMin
(
    const scalar rhoOld,
    const scalar eOld
) const
{
    // The path ending at v belongs to the interface pressure q(v) that
    // solves phi(q) = p(1/v, eOld - q (v - vOld)) - q = 0, with
    // dphi/dq = -Gamma (1 - vOld/v) - 1 < 0: q falls as v grows (dv/dp* < 0).
    // Follow q out to v = 4^nExpansions vOld, stopping when it no longer
    // changes, or, where the end state leaves the admissible range, at the
    // edge of the range (bisection in ln v)
    const scalar vOld = 1/rhoOld;
    const scalar pOld = p(rhoOld, eOld);
    const scalar s = pScale(rhoOld, pOld);

    // q(v) by Newton's method from qStart (explicit where p is linear in
    // e: p(rho, eOld) - rho Gamma q (v - vOld) = q); false if it does not
    // converge or the end state is not admissible
    const bool linear = pLinearInEnergy();
    const auto admissibleEnd = [this](const scalar rho, const scalar q)
    {
        return rho < rhoMax() && q > pMin(rho) && c2(rho, q) > 0;
    };
    const auto endPressure =
        [&](const scalar v, const scalar qStart, scalar& q)
    {
        const scalar rho = 1/v;
        if (linear)
        {
            q = p(rho, eOld)/(1 + Gamma(rho, eOld)*(1 - vOld/v));
            return std::isfinite(q) && admissibleEnd(rho, q);
        }
        q = qStart;
        for (label iter = 0; iter < maxIter; ++iter)
        {
            const scalar eh = eOld - q*(v - vOld);
            const scalar phi = p(rho, eh) - q;
            const scalar dphi = -Gamma(rho, eh)*(1 - vOld/v) - 1;
            const scalar dq = -phi/dphi;
            if (!std::isfinite(dq))
            {
                return false;
            }
            q += dq;
            // Relative to |q| as well: q grows far beyond the start's
            // scale on a long expansion (a Mie-Grueneisen solid holds any
            // tension, q ~ -rho0^2 c0^2 v/2), and its round-off with it
            if (mag(dq) <= tolerance*(s + mag(q)))
            {
                return admissibleEnd(rho, q);
            }
        }
        return false;
    };

    scalar v = vOld;
    scalar q = pOld;
    for (label i = 0; i < nExpansions; ++i)
    {
        scalar qNew;
        if (!endPressure(4*v, q, qNew))
        {
            // The edge of the admissible range lies in (v, 4 v)
            scalar vB = 4*v;
            for
            (
                label iter = 0;
                iter < maxIter && vB > (1 + tolerance)*v;
                ++iter
            )
            {
                const scalar vM = std::sqrt(v*vB);
                scalar qM;
                if (endPressure(vM, q, qM))
                {
                    v = vM;
                    q = qM;
                }
                else
                {
                    vB = vM;
                }
            }
            return q;
        }
        const bool converged = mag(qNew - q) <= tolerance*s;
        v *= 4;
        q = qNew;
        if (converged)
        {
            break;
        }
    }
    return q;
}


Foam::scalar Foam::equationOfState::vIsentropic
(
    const scalar pStar,
    const scalar rhoOld,
    const scalar eOld
) const
{
    // d(ln rho)/dp = 1/(rho c2) from the old pressure to pStar, in
    // y = ln(rho/rhoOld) (error relative to 1 in y: relative in v)
    const scalar pOld = p(rhoOld, eOld);
    const auto dydp = [this, rhoOld](const scalar pp, const scalar y)
    {
        const scalar r = rhoOld*std::exp(y);
        const scalar cc = c2(r, pp);
        return
            (r < rhoMax() && pp > pMin(r) && cc > 0)
          ? 1/(r*cc)
          : NaN;
    };
    const auto scale = [](const scalar, const scalar y)
    {
        return max(mag(y), scalar(1));
    };
    scalar y;
    if (!scalarODE::integrate(dydp, scale, pOld, 0, pStar, tolerance, y))
    {
        isentropeFailed("vIsentropic", rhoOld, eOld, "p", pStar);
    }
    return std::exp(-y)/rhoOld;
}


Foam::scalar Foam::equationOfState::eIsentropic
(
    const scalar rho,
    const scalar rhoRef,
    const scalar eRef
) const
{
    scalar pp;
    if (!isentropePressure(rhoRef, p(rhoRef, eRef), rho, pp))
    {
        isentropeFailed("eIsentropic", rhoRef, eRef, "rho", rho);
    }
    return e(rho, pp);
}


Foam::scalar Foam::equationOfState::dvIsentropicdp
(
    const scalar pStar,
    const scalar rhoOld,
    const scalar eOld
) const
{
    // dv/dp = -1/(rho^2 c2) on the isentrope, at its end state
    const scalar v = vIsentropic(pStar, rhoOld, eOld);
    return -v*v/c2(1/v, pStar);
}


Foam::scalar Foam::equationOfState::pIsentropicMin
(
    const scalar rhoRef,
    const scalar eRef
) const
{
    // Follow the isentrope to lower densities, fourfold expansions to
    // 4^-nExpansions rhoRef, stopping when p no longer changes, or, where
    // it leaves the admissible range, at the edge of the range (bisection
    // in ln rho)
    const scalar pRef = p(rhoRef, eRef);
    const scalar s = pScale(rhoRef, pRef);

    scalar rho = rhoRef;
    scalar pp = pRef;
    for (label i = 0; i < nExpansions; ++i)
    {
        scalar pNew;
        if (!isentropePressure(rho, pp, 0.25*rho, pNew))
        {
            // The edge of the admissible range lies in (rho/4, rho)
            scalar rhoB = 0.25*rho;
            for
            (
                label iter = 0;
                iter < maxIter && rho > (1 + tolerance)*rhoB;
                ++iter
            )
            {
                const scalar rhoM = std::sqrt(rho*rhoB);
                scalar pM;
                if (isentropePressure(rho, pp, rhoM, pM))
                {
                    rho = rhoM;
                    pp = pM;
                }
                else
                {
                    rhoB = rhoM;
                }
            }
            return pp;
        }
        const bool converged = mag(pNew - pp) <= tolerance*s;
        rho *= 0.25;
        pp = pNew;
        if (converged)
        {
            break;
        }
    }
    return pp;
}


// ************************************************************************* //
