#include "neoHookean.H"
#include "addToRunTimeSelectionTable.H"

namespace Foam
{
namespace elasticModels
{
    defineTypeNameAndDebug(neoHookean, 0);
    addToRunTimeSelectionTable(elasticModel, neoHookean, dictionary);
}
}
