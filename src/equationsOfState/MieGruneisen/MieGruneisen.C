#include "MieGruneisen.H"
#include "addToRunTimeSelectionTable.H"

#include <cmath>
#include <limits>

namespace Foam
{
namespace equationsOfState
{
    defineTypeNameAndDebug(MieGruneisen, 0);
    addToRunTimeSelectionTable(equationOfState, MieGruneisen, dictionary);
}
}


namespace
{
    const Foam::scalar NaN = std::numeric_limits<Foam::scalar>::quiet_NaN();
}


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

Foam::scalar Foam::equationsOfState::MieGruneisen::readPositive
(
    const word& phaseName,
    const dictionary& dict,
    const word& key,
    const char* meaning
)
{
    if (!dict.found(key))
    {
        FatalIOErrorInFunction(dict)
            << "Phase " << phaseName << ": equationOfState MieGruneisen"
            << " needs the keyword " << key << " (" << meaning << ")"
            << exit(FatalIOError);
    }
    const scalar value = dict.get<scalar>(key);
    if (!(value > 0))
    {
        FatalIOErrorInFunction(dict)
            << "Phase " << phaseName << ": equationOfState " << key
            << " = " << value << " must be positive (" << meaning << ")"
            << exit(FatalIOError);
    }
    return value;
}


void Foam::equationsOfState::MieGruneisen::reference
(
    const scalar eta,
    scalar& pRef,
    scalar& eRef
) const
{
    if (eta >= 0)
    {
        const scalar D = 1 - s_*eta;
        pRef = K_*eta/(D*D);
    }
    else
    {
        pRef = K_*eta;
    }
    eRef = pRef*eta/(2*rho0_);
}


Foam::scalar Foam::equationsOfState::MieGruneisen::F(const scalar eta) const
{
    if (eta >= 0)
    {
        const scalar D = 1 - s_*eta;
        return K_*(1 + (s_ - Gamma0_)*eta)/(D*D*D);
    }
    return K_*(1 - Gamma0_*eta);
}


Foam::scalar Foam::equationsOfState::MieGruneisen::dFdeta
(
    const scalar eta
) const
{
    if (eta >= 0)
    {
        const scalar D = 1 - s_*eta;
        return
            K_*(4*s_ - Gamma0_ + 2*s_*(s_ - Gamma0_)*eta)/((D*D)*(D*D));
    }
    return -K_*Gamma0_;
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::equationsOfState::MieGruneisen::MieGruneisen
(
    const word& phaseName,
    const dictionary& dict
)
:
    equationOfState(phaseName, dict),
    rho0_(readPositive(phaseName, dict, "rho0", "reference density, kg/m^3")),
    c0_(readPositive(phaseName, dict, "c0", "bulk sound speed at rest, m/s")),
    s_(readPositive(phaseName, dict, "s", "slope of the Us-up Hugoniot")),
    Gamma0_
    (
        readPositive(phaseName, dict, "Gamma0", "Grueneisen coefficient at rho0")
    ),
    Cv_
    (
        readPositive
        (
            phaseName, dict, "Cv", "heat capacity at constant volume, J/(kg K)"
        )
    ),
    T0_
    (
        readPositive
        (
            phaseName, dict, "T0", "temperature of the reference curve, K"
        )
    ),
    K_(rho0_*c0_*c0_),
    rhoGamma_(rho0_*Gamma0_),
    rhoMax_(rho0_/(1 - 1/s_))
{
    // The reference curve is admissible (p_ref > pMin) where
    // 1 + s eta (1 - Gamma0 eta) > 0, everywhere below the pole eta = 1/s
    // only when Gamma0 < 2 s; and the Hugoniot from rest
    // (p - p_ref)(1 - Gamma0 eta/2) = 0 is the reference curve alone only
    // when its limiting compression 2/Gamma0 lies beyond the pole
    if (!(Gamma0_ < 2*s_))
    {
        FatalIOErrorInFunction(dict)
            << "Phase " << phaseName << ": equationOfState Gamma0 = "
            << Gamma0_ << " must be below 2 s = " << 2*s_
            << " (else the Hugoniot from rest reaches its limiting"
            << " compression eta = 2/Gamma0 before the pole eta = 1/s and"
            << " the reference curve leaves the admissible range, c^2 <= 0)"
            << exit(FatalIOError);
    }
}


Foam::wordList Foam::equationsOfState::MieGruneisen::keywords() const
{
    return {"type", "rho0", "c0", "s", "Gamma0", "Cv", "T0"};
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::scalar Foam::equationsOfState::MieGruneisen::pRef
(
    const scalar rho
) const
{
    scalar pr, er;
    if (!referenceAt(rho, pr, er))
    {
        return NaN;
    }
    return pr;
}


Foam::scalar Foam::equationsOfState::MieGruneisen::eRef
(
    const scalar rho
) const
{
    scalar pr, er;
    if (!referenceAt(rho, pr, er))
    {
        return NaN;
    }
    return er;
}


Foam::scalar Foam::equationsOfState::MieGruneisen::p
(
    const scalar rho,
    const scalar e
) const
{
    scalar pr, er;
    if (!referenceAt(rho, pr, er))
    {
        return NaN;
    }
    return pr + rhoGamma_*(e - er);
}


Foam::scalar Foam::equationsOfState::MieGruneisen::e
(
    const scalar rho,
    const scalar p
) const
{
    scalar pr, er;
    if (!referenceAt(rho, pr, er))
    {
        return NaN;
    }
    return er + (p - pr)/rhoGamma_;
}


Foam::scalar Foam::equationsOfState::MieGruneisen::c2
(
    const scalar rho,
    const scalar p
) const
{
    if (!admissible(rho))
    {
        return NaN;
    }
    return rho0_/(rho*rho)*(F(eta(rho)) + Gamma0_*p);
}


Foam::scalar Foam::equationsOfState::MieGruneisen::pMin
(
    const scalar rho
) const
{
    if (!admissible(rho))
    {
        return std::numeric_limits<scalar>::infinity();
    }
    return -F(eta(rho))/Gamma0_;
}


Foam::scalar Foam::equationsOfState::MieGruneisen::T
(
    const scalar rho,
    const scalar e
) const
{
    return T0_ + (e - eRef(rho))/Cv_;
}


Foam::scalar Foam::equationsOfState::MieGruneisen::fundamentalDerivative
(
    const scalar rho,
    const scalar p
) const
{
    return
        sqr(rho0_)*dFdeta(eta(rho))/(2*rho*rho*rho*c2(rho, p))
      + rhoGamma_/(2*rho);
}


Foam::scalar Foam::equationsOfState::MieGruneisen::pScale
(
    const scalar rho,
    const scalar p
) const
{
    scalar pr, er;
    if (!referenceAt(rho, pr, er))
    {
        return NaN;
    }
    const scalar x = eta(rho);
    const scalar eh = er + (p - pr)/rhoGamma_;

    // d p_ref/d eta and d e_ref/d eta
    scalar dp, de;
    if (x >= 0)
    {
        const scalar D = 1 - s_*x;
        const scalar D3 = D*D*D;
        dp = K_*(1 + s_*x)/D3;
        de = c0_*c0_*x/D3;
    }
    else
    {
        dp = K_;
        de = c0_*c0_*x;
    }
    return
        mag(p) + mag(pr) + rhoGamma_*(mag(eh) + mag(er))
      + mag(dp) + rhoGamma_*mag(de);
}


// ************************************************************************* //
