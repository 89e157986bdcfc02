#include "impactBody.H"
#include "mathematicalConstants.H"
#include "transform.H"

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::impactBody::impactBody
(
    const word& name,
    const dictionary& dict,
    const wordList& bodyKeys,
    const Time& runTime
)
:
    name_(name),
    owner_("Body " + name),
    shape_(bodyShape::New(dict, owner_, bodyKeys, runTime)),
    R_(tensor::I),
    centre_(shape_->referencePoint()),
    rotated_(false),
    shift_(Zero),
    phase(),
    material(),
    U(Zero),
    radial(false),
    radialCentre(Zero),
    radialU(0),
    radialRadius(1),
    radialExponent(0),
    p(0),
    rho(0),
    T(-1)
{
    const scalar angle =
        dict.getOrDefault<scalar>("angle", 0, keyType::LITERAL);
    if (angle != 0)
    {
        vector axis(0, 0, 1);
        dict.readIfPresent("rotationAxis", axis, keyType::LITERAL);
        if (!(mag(axis) > VSMALL))
        {
            FatalIOErrorInFunction(dict)
                << owner_.c_str() << ": entry rotationAxis " << axis
                << " must be a non-zero vector" << exit(FatalIOError);
        }
        axis /= mag(axis);
        const scalar a = angle*constant::mathematical::pi/180;
        const scalar c = Foam::cos(a), s = Foam::sin(a);

        // Rodrigues: R = c I + s [axis]x + (1 - c) axis axis
        const tensor K
        (
            0, -axis.z(), axis.y(),
            axis.z(), 0, -axis.x(),
            -axis.y(), axis.x(), 0
        );
        R_ = c*tensor::I + s*K + (1 - c)*(axis*axis);
        rotated_ = true;
    }
    else if
    (
        dict.found("rotationAxis", keyType::LITERAL)
     && !dict.found("angle", keyType::LITERAL)
    )
    {
        FatalIOErrorInFunction(dict)
            << owner_.c_str() << ": entry rotationAxis without angle"
            << exit(FatalIOError);
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::scalar Foam::impactBody::distance(const point& x) const
{
    if (!rotated_)
    {
        return shape_->distance(x - shift_);
    }
    // Back to the shape's frame: undo the shift, then the rotation
    return shape_->distance(centre_ + (R_.T() & (x - shift_ - centre_)));
}


Foam::scalar Foam::impactBody::effectiveDistance(const point& x) const
{
    scalar d = distance(x);
    for (const impactBody* cutter : cutters_)
    {
        d = max(d, -cutter->distance(x));
    }
    return d;
}


bool Foam::impactBody::polyhedron(List<vector>& n, scalarList& d) const
{
    if (!cutters_.empty() || !shape_->polyhedron(n, d))
    {
        return false;
    }
    // n.p_local < d with p_local = centre + R^T (p - shift - centre):
    // (R n).p < d - n.centre + (R n).(shift + centre)
    forAll(n, i)
    {
        const vector Rn(R_ & n[i]);
        d[i] += (Rn & (shift_ + centre_)) - (n[i] & centre_);
        n[i] = Rn;
    }
    return true;
}


Foam::boundBox Foam::impactBody::bounds() const
{
    const boundBox bb(shape_->bounds());
    if (!rotated_)
    {
        return boundBox(bb.min() + shift_, bb.max() + shift_);
    }
    const pointField corners(bb.points());
    boundBox result;
    for (const point& c : corners)
    {
        result.add(centre_ + (R_ & (c - centre_)) + shift_);
    }
    return result;
}


Foam::scalar Foam::impactBody::exactVolume
(
    const word& geometry,
    const scalar depth
) const
{
    if (!rotated_ && mag(shift_) == 0)
    {
        return shape_->volume(geometry, depth);
    }
    if (geometry == "threeD")
    {
        return shape_->volume(geometry, depth);
    }
    // A shift along x keeps an axisymmetric or planar body's volume, and a
    // rotation about z a planar one's; otherwise there is no closed form
    const bool axialShift = mag(shift_.y()) + mag(shift_.z()) == 0;
    if (geometry == "axisymmetric" && !rotated_ && axialShift)
    {
        return shape_->volume(geometry, depth);
    }
    if
    (
        geometry == "planar"
     && shift_.z() == 0
     && (!rotated_ || mag(R_ & vector(0, 0, 1)) - (R_ & vector(0, 0, 1)).z()
          < 1e-12)
    )
    {
        return shape_->volume(geometry, depth);
    }
    return -1;
}


Foam::vector Foam::impactBody::velocity(const point& x) const
{
    if (!radial)
    {
        return U;
    }
    const vector d(x - radialCentre);
    const scalar r = mag(d);
    if (r < VSMALL)
    {
        return Zero;
    }
    return radialU*Foam::pow(r/radialRadius, radialExponent)*d/r;
}


// ************************************************************************* //
