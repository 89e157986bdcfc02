#include "linearYieldStress.H"
#include "addToRunTimeSelectionTable.H"

namespace Foam
{
namespace yieldStresses
{
    defineTypeNameAndDebug(linear, 0);
    addToRunTimeSelectionTable(yieldStress, linear, dictionary);
}
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::yieldStresses::linear::linear
(
    const word& phaseName,
    const dictionary& dict
)
:
    yieldStress(phaseName),
    sigmaY0_(readPositive(dict, "sigmaY0")),
    H_(readNonNegative(dict, "H"))
{}


Foam::wordList Foam::yieldStresses::linear::keywords() const
{
    return {"type", "sigmaY0", "H"};
}


Foam::yieldStresses::linear::linear
(
    const word& phaseName,
    const scalar sigmaY0,
    const scalar H
)
:
    yieldStress(phaseName),
    sigmaY0_(sigmaY0),
    H_(H)
{}
