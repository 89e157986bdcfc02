#include "coneShape.H"
#include "addToRunTimeSelectionTable.H"
#include "mathematicalConstants.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace bodyShapes
{
    defineTypeNameAndDebug(cone, 0);
    addToRunTimeSelectionTable(bodyShape, cone, dictionary);
}
}


// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * * //

namespace
{

// Distance from q to the segment a-b in the plane
Foam::scalar segmentDistance
(
    const Foam::vector2D& q,
    const Foam::vector2D& a,
    const Foam::vector2D& b
)
{
    using namespace Foam;
    const vector2D ab(b - a);
    const scalar len2 = ab & ab;
    scalar t = len2 > VSMALL ? ((q - a) & ab)/len2 : 0;
    t = min(max(t, scalar(0)), scalar(1));
    return mag(q - a - t*ab);
}

}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::bodyShapes::cone::cone
(
    const dictionary& dict,
    const string& owner,
    const wordList& bodyKeys,
    const bool isCylinder
)
:
    bodyShape(owner),
    base_
    (
        (
            checkEntries
            (
                dict,
                isCylinder
              ? wordList({"base", "axis", "length", "radius"})
              : wordList({"base", "axis", "length", "radius", "topRadius"}),
                bodyKeys,
                owner
            ),
            required<point>(dict, "base", owner)
        )
    ),
    axis_(unitVector(dict, "axis", owner)),
    length_(positive(dict, "length", owner)),
    radius_(positive(dict, "radius", owner)),
    topRadius_
    (
        isCylinder
      ? radius_
      : dict.getOrDefault<scalar>("topRadius", 0, keyType::LITERAL)
    )
{
    if (topRadius_ < 0)
    {
        FatalIOErrorInFunction(dict)
            << owner.c_str() << ": entry topRadius " << topRadius_
            << " must not be negative" << exit(FatalIOError);
    }
}


Foam::bodyShapes::cone::cone
(
    const dictionary& dict,
    const string& owner,
    const wordList& bodyKeys,
    const Time&
)
:
    cone(dict, owner, bodyKeys, false)
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::scalar Foam::bodyShapes::cone::distance(const point& p) const
{
    const vector d(p - base_);
    const scalar s = d & axis_;
    const scalar rho = mag(d - s*axis_);
    const vector2D q(s, rho);

    // The section's upper half: the base, the side, the top
    const vector2D a(0, 0), b(0, radius_), c(length_, topRadius_),
        e(length_, 0);
    const scalar dist = min
    (
        min(segmentDistance(q, a, b), segmentDistance(q, b, c)),
        segmentDistance(q, c, e)
    );

    // Inside: between the ends and below the side
    const scalar side =
        (c.x() - b.x())*(q.y() - b.y()) - (c.y() - b.y())*(q.x() - b.x());
    const bool inside = s > 0 && s < length_ && side < 0;

    return inside ? -dist : dist;
}


Foam::boundBox Foam::bodyShapes::cone::bounds() const
{
    // Each end disc: the centre +- R sqrt(1 - a_i^2) in direction i
    const vector ext(discExtent(axis_));
    const point top(base_ + length_*axis_);
    boundBox bb(base_ - radius_*ext, base_ + radius_*ext);
    bb.add(top - topRadius_*ext);
    bb.add(top + topRadius_*ext);
    return bb;
}


Foam::scalar Foam::bodyShapes::cone::volume
(
    const word& geometry,
    const scalar depth
) const
{
    const scalar R0 = radius_, R1 = topRadius_;
    const scalar solid =
        constant::mathematical::pi*length_*(R0*R0 + R0*R1 + R1*R1)/3;

    if (geometry == "threeD")
    {
        return solid;
    }
    if (geometry == "axisymmetric")
    {
        // A solid of revolution about x when its axis lies on x
        return onXAxis(base_, axis_, length_) ? solid : -1;
    }
    // planar: the section z = 0 of a cone whose axis lies in that plane
    if (mag(axis_.z()) < 1e-12 && mag(base_.z()) < 1e-12*length_)
    {
        return (R0 + R1)*length_*depth;
    }
    return -1;
}


// ************************************************************************* //
