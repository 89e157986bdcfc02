#include "constantYieldStress.H"
#include "addToRunTimeSelectionTable.H"

namespace Foam
{
namespace yieldStresses
{
    defineTypeNameAndDebug(constant, 0);
    addToRunTimeSelectionTable(yieldStress, constant, dictionary);
}
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::yieldStresses::constant::constant
(
    const word& phaseName,
    const dictionary& dict
)
:
    yieldStress(phaseName),
    sigmaY_(readPositive(dict, "sigmaY"))
{}


Foam::wordList Foam::yieldStresses::constant::keywords() const
{
    return {"type", "sigmaY"};
}


Foam::yieldStresses::constant::constant
(
    const word& phaseName,
    const scalar sigmaY
)
:
    yieldStress(phaseName),
    sigmaY_(sigmaY)
{}
