#include "halfSpaceShape.H"
#include "addToRunTimeSelectionTable.H"
#include "mathematicalConstants.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace bodyShapes
{
    defineTypeNameAndDebug(halfSpace, 0);
    addToRunTimeSelectionTable(bodyShape, halfSpace, dictionary);
}
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::bodyShapes::halfSpace::halfSpace
(
    const dictionary& dict,
    const string& owner,
    const wordList& bodyKeys,
    const Time&
)
:
    bodyShape(owner),
    point_
    (
        (
            checkEntries(dict, {"point", "normal"}, bodyKeys, owner),
            required<point>(dict, "point", owner)
        )
    ),
    normal_(unitVector(dict, "normal", owner))
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::scalar Foam::bodyShapes::halfSpace::distance(const point& p) const
{
    return (p - point_) & normal_;
}


Foam::boundBox Foam::bodyShapes::halfSpace::bounds() const
{
    return boundBox::greatBox;
}


Foam::point Foam::bodyShapes::halfSpace::referencePoint() const
{
    return point_;
}


bool Foam::bodyShapes::halfSpace::polyhedron
(
    List<vector>& n,
    scalarList& d
) const
{
    n = List<vector>(1, normal_);
    d = scalarList(1, normal_ & point_);
    return true;
}


Foam::scalar Foam::bodyShapes::halfSpace::volume
(
    const word&,
    const scalar
) const
{
    return -1;
}


// ************************************************************************* //
