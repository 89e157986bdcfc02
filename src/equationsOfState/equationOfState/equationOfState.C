#include "equationOfState.H"

namespace Foam
{
    defineTypeNameAndDebug(equationOfState, 0);
    defineRunTimeSelectionTable(equationOfState, dictionary);
}

Foam::equationOfState::equationOfState
(
    const word& phaseName,
    const dictionary& dict
)
:
    phaseName_(phaseName)
{}
