#include "sphereShape.H"
#include "addToRunTimeSelectionTable.H"
#include "mathematicalConstants.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace bodyShapes
{
    defineTypeNameAndDebug(sphere, 0);
    addToRunTimeSelectionTable(bodyShape, sphere, dictionary);
}
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::bodyShapes::sphere::sphere
(
    const dictionary& dict,
    const string& owner,
    const wordList& bodyKeys,
    const Time&
)
:
    bodyShape(owner),
    centre_
    (
        (
            checkEntries(dict, {"centre", "radius"}, bodyKeys, owner),
            required<point>(dict, "centre", owner)
        )
    ),
    radius_(positive(dict, "radius", owner))
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::scalar Foam::bodyShapes::sphere::distance(const point& p) const
{
    return mag(p - centre_) - radius_;
}


Foam::boundBox Foam::bodyShapes::sphere::bounds() const
{
    const vector r(radius_*vector::one);
    return boundBox(centre_ - r, centre_ + r);
}


Foam::point Foam::bodyShapes::sphere::referencePoint() const
{
    return centre_;
}


Foam::scalar Foam::bodyShapes::sphere::volume
(
    const word& geometry,
    const scalar depth
) const
{
    const scalar pi = constant::mathematical::pi;
    if (geometry == "threeD")
    {
        return 4*pi*pow3(radius_)/3;
    }
    if (geometry == "axisymmetric")
    {
        const bool onAxis =
            mag(centre_.y()) < 1e-12*radius_
         && mag(centre_.z()) < 1e-12*radius_;
        return onAxis ? 4*pi*pow3(radius_)/3 : -1;
    }
    return mag(centre_.z()) < 1e-12*radius_ ? pi*sqr(radius_)*depth : -1;
}


// ************************************************************************* //
