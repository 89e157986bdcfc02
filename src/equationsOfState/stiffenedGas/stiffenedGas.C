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
    pInf_(dict.get<scalar>("pInf"))
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
}
