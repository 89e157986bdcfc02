#include "noFailure.H"
#include "addToRunTimeSelectionTable.H"

namespace Foam
{
namespace failureModels
{
    defineTypeNameAndDebug(none, 0);
    addToRunTimeSelectionTable(failureModel, none, dictionary);
}
}


Foam::failureModels::none::none
(
    const word& phaseName,
    const dictionary& dict,
    const dictionary& phaseDict
)
:
    failureModel(phaseName, dict)
{
    if (sigmaSpall_ > 0)
    {
        FatalIOErrorInFunction(dict)
            << "Phase " << phaseName << ": failure none takes no sigmaSpall"
            << " (type spall does)" << exit(FatalIOError);
    }
}


// ************************************************************************* //
