#include "cylinderShape.H"
#include "addToRunTimeSelectionTable.H"
#include "mathematicalConstants.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace bodyShapes
{
    defineTypeNameAndDebug(cylinder, 0);
    addToRunTimeSelectionTable(bodyShape, cylinder, dictionary);
}
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::bodyShapes::cylinder::cylinder
(
    const dictionary& dict,
    const string& owner,
    const wordList& bodyKeys,
    const Time&
)
:
    cone(dict, owner, bodyKeys, true)
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::scalar Foam::bodyShapes::cylinder::volume
(
    const word& geometry,
    const scalar depth
) const
{
    // planar, axis along z: the section is a disc
    if
    (
        geometry == "planar"
     && mag(axis_ ^ vector(0, 0, 1)) < 1e-12
    )
    {
        return constant::mathematical::pi*sqr(radius_)*depth;
    }
    return cone::volume(geometry, depth);
}


// ************************************************************************* //
