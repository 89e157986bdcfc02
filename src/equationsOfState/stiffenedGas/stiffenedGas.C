#include "stiffenedGas.H"
#include "addToRunTimeSelectionTable.H"

namespace Foam
{
namespace equationsOfState
{
    defineTypeNameAndDebug(stiffenedGas, 0);
    addToRunTimeSelectionTable(equationOfState, stiffenedGas, dictionary);
}
}

Foam::equationsOfState::stiffenedGas::stiffenedGas
(
    const word& phaseName,
    const dictionary& dict
)
:
    equationOfState(phaseName, dict),
    gamma_(dict.get<scalar>("gamma")),
    pInf_(dict.get<scalar>("pInf")),
    Cv_(0)
{
    if (!(gamma_ > 1))
    {
        FatalIOErrorInFunction(dict)
            << "Phase " << phaseName << ": equationOfState gamma = " << gamma_
            << " must be greater than 1" << exit(FatalIOError);
    }
    if (!(pInf_ >= 0))
    {
        FatalIOErrorInFunction(dict)
            << "Phase " << phaseName << ": equationOfState pInf = " << pInf_
            << " must be non-negative" << exit(FatalIOError);
    }
    if (dict.found("Cv"))
    {
        Cv_ = dict.get<scalar>("Cv");
        if (!(Cv_ > 0))
        {
            FatalIOErrorInFunction(dict)
                << "Phase " << phaseName << ": equationOfState Cv = " << Cv_
                << " must be positive" << exit(FatalIOError);
        }
    }
}


Foam::wordList Foam::equationsOfState::stiffenedGas::keywords() const
{
    return {"type", "gamma", "pInf", "Cv"};
}


void Foam::equationsOfState::stiffenedGas::noTemperature
(
    const char* function
) const
{
    FatalErrorInFunction
        << "Phase " << phaseName_ << " has no temperature (" << function
        << " asked): the keyword Cv (heat capacity at constant volume,"
        << " J/(kg K)) is missing from its equationOfState"
        << exit(FatalError);
}


Foam::scalar Foam::equationsOfState::stiffenedGas::T
(
    const scalar rho,
    const scalar e
) const
{
    if (!(Cv_ > 0))
    {
        noTemperature("T");
    }
    return (p(rho, e) + pInf_)/((gamma_ - 1)*rho*Cv_);
}


Foam::scalar Foam::equationsOfState::stiffenedGas::Cv() const
{
    if (!(Cv_ > 0))
    {
        noTemperature("Cv");
    }
    return Cv_;
}
