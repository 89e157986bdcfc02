#include "spall.H"
#include "addToRunTimeSelectionTable.H"

namespace Foam
{
namespace failureModels
{
    defineTypeNameAndDebug(spall, 0);
    addToRunTimeSelectionTable(failureModel, spall, dictionary);
}
}


Foam::failureModels::spall::spall
(
    const word& phaseName,
    const dictionary& dict,
    const dictionary& phaseDict
)
:
    failureModel(phaseName, dict)
{
    // The base class read and checked it, if given
    read(dict, "sigmaSpall");
}


// ************************************************************************* //
