#include "equationOfState.H"

#include <cmath>
#include <limits>

namespace Foam
{
    defineTypeNameAndDebug(equationOfState, 0);
    defineRunTimeSelectionTable(equationOfState, dictionary);
}

const Foam::scalar Foam::equationOfState::tolerance = 1e-14;


Foam::equationOfState::equationOfState
(
    const word& phaseName,
    const dictionary& dict
)
:
    phaseName_(phaseName)
{}


Foam::wordList Foam::equationOfState::keywords() const
{
    return {"type"};
}


Foam::scalar Foam::equationOfState::fundamentalDerivative
(
    const scalar rho,
    const scalar p
) const
{
    // G = 1 + (rho/(2 c2)) dc2/drho along the isentrope, whose tangent in
    // the (rho, p) plane is (1, c2). Central difference along the tangent:
    // the isentrope's curvature puts both ends off it by the same
    // c2''(rho) d^2/2 in p, which cancels in the difference, so the error
    // is O(d^2); d = eps^(1/3) rho balances it with round-off (about 1e-10
    // relative, ample for a wave-speed estimate)
    static const scalar h =
        std::cbrt(std::numeric_limits<scalar>::epsilon());
    const scalar d = h*rho;
    const scalar cc = c2(rho, p);
    const scalar dc2 = (c2(rho + d, p + cc*d) - c2(rho - d, p - cc*d))/(2*d);
    return 1 + 0.5*rho*dc2/cc;
}


Foam::scalar Foam::equationOfState::pScale
(
    const scalar rho,
    const scalar p
) const
{
    const scalar eh = e(rho, p);
    return mag(p) + rho*mag(Gamma(rho, eh)*eh);
}
