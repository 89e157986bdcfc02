#include "none.H"
#include "addToRunTimeSelectionTable.H"

namespace Foam
{
namespace plasticModels
{
    defineTypeNameAndDebug(none, 0);
    addToRunTimeSelectionTable(plasticModel, none, dictionary);
}
}
