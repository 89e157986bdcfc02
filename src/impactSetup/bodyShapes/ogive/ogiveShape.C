#include "ogiveShape.H"
#include "addToRunTimeSelectionTable.H"
#include "mathematicalConstants.H"
#include "vector2D.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace bodyShapes
{
    defineTypeNameAndDebug(ogive, 0);
    addToRunTimeSelectionTable(bodyShape, ogive, dictionary);
}
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::bodyShapes::ogive::ogive
(
    const dictionary& dict,
    const string& owner,
    const wordList& bodyKeys,
    const Time&
)
:
    bodyShape(owner),
    base_
    (
        (
            checkEntries
            (
                dict, {"base", "axis", "radius", "crh"}, bodyKeys, owner
            ),
            required<point>(dict, "base", owner)
        )
    ),
    axis_(unitVector(dict, "axis", owner)),
    radius_(positive(dict, "radius", owner)),
    crh_(positive(dict, "crh", owner)),
    arcRadius_(2*crh_*radius_),
    length_(0)
{
    if (crh_ < 0.5)
    {
        FatalIOErrorInFunction(dict)
            << owner.c_str() << ": entry crh " << crh_
            << " must be at least 0.5 (0.5: a hemisphere), for the arc"
            << " to meet the shank tangentially" << exit(FatalIOError);
    }
    const scalar c = arcRadius_ - radius_;
    length_ = Foam::sqrt(max(sqr(arcRadius_) - sqr(c), scalar(0)));
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::scalar Foam::bodyShapes::ogive::distance(const point& p) const
{
    const vector d(p - base_);
    const scalar s = d & axis_;
    const scalar rho = mag(d - s*axis_);
    const vector2D q(s, rho);

    // The arc: centre C = (0, a - S), from the rim (0, a) at 90 degrees
    // down to the tip (l, 0)
    const scalar S = arcRadius_;
    const vector2D C(0, radius_ - S);
    const vector2D rim(0, radius_), tip(length_, 0);
    const vector2D qc(q - C);
    const scalar r = mag(qc);
    scalar toArc;
    // Within the arc's angles: between the rays from C through the rim
    // (along +rho) and through the tip
    const vector2D toTip(tip - C);
    const bool withinArc =
        qc.x() >= 0 && (toTip.x()*qc.y() - toTip.y()*qc.x()) >= 0;
    if (withinArc)
    {
        toArc = mag(r - S);
    }
    else
    {
        toArc = min(mag(q - rim), mag(q - tip));
    }

    // The base: the segment s = 0, 0 <= rho <= a
    const scalar toBase =
        rho <= radius_ ? mag(s) : mag(q - rim);

    const scalar dist = min(toArc, toBase);
    const bool inside = s > 0 && r < S;
    return inside ? -dist : dist;
}


Foam::boundBox Foam::bodyShapes::ogive::bounds() const
{
    // The base disc: its centre +- a sqrt(1 - a_i^2) in direction i; and
    // the tip
    const vector ext(discExtent(axis_));
    boundBox bb(base_ - radius_*ext, base_ + radius_*ext);
    bb.add(base_ + length_*axis_);
    return bb;
}


Foam::scalar Foam::bodyShapes::ogive::volume
(
    const word& geometry,
    const scalar depth
) const
{
    // With c = S - a, rho(s) = sqrt(S^2 - s^2) - c on [0, l], sqrt(S^2 -
    // l^2) = c:
    //     solid   pi int rho^2 ds = pi (S^2 l - l^3/3 - c S^2 asin(l/S))
    //     section 2 int rho ds    = S^2 asin(l/S) - c l
    const scalar S = arcRadius_, l = length_, c = arcRadius_ - radius_;
    const scalar arc = sqr(S)*Foam::asin(min(l/S, scalar(1)));
    const scalar solid =
        constant::mathematical::pi*(sqr(S)*l - pow3(l)/3 - c*arc);

    if (geometry == "threeD")
    {
        return solid;
    }
    if (geometry == "axisymmetric")
    {
        return onXAxis(base_, axis_, l) ? solid : -1;
    }
    if (mag(axis_.z()) < 1e-12 && mag(base_.z()) < 1e-12*l)
    {
        return (arc - c*l)*depth;
    }
    return -1;
}


// ************************************************************************* //
