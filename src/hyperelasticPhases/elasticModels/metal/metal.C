#include "metal.H"
#include "addToRunTimeSelectionTable.H"

namespace Foam
{
namespace elasticModels
{
    defineTypeNameAndDebug(metal, 0);
    addToRunTimeSelectionTable(elasticModel, metal, dictionary);
}
}
