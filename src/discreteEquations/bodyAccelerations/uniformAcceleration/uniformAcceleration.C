#include "uniformAcceleration.H"
#include "addToRunTimeSelectionTable.H"

namespace Foam
{
namespace bodyAccelerations
{
    defineTypeNameAndDebug(uniform, 0);
    addToRunTimeSelectionTable(bodyAcceleration, uniform, dictionary);
}
}
