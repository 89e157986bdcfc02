#include "boxShape.H"
#include "addToRunTimeSelectionTable.H"
#include "mathematicalConstants.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace bodyShapes
{
    defineTypeNameAndDebug(box, 0);
    addToRunTimeSelectionTable(bodyShape, box, dictionary);
}
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::bodyShapes::box::box
(
    const dictionary& dict,
    const string& owner,
    const wordList& bodyKeys,
    const Time&
)
:
    bodyShape(owner),
    min_
    (
        (
            checkEntries(dict, {"min", "max"}, bodyKeys, owner),
            required<point>(dict, "min", owner)
        )
    ),
    max_(required<point>(dict, "max", owner))
{
    for (direction i = 0; i < vector::nComponents; ++i)
    {
        if (!(max_[i] > min_[i]))
        {
            FatalIOErrorInFunction(dict)
                << owner.c_str() << ": box min " << min_ << " max " << max_
                << " is empty in direction " << label(i)
                << " (need max > min)" << exit(FatalIOError);
        }
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::scalar Foam::bodyShapes::box::distance(const point& p) const
{
    const point c(0.5*(min_ + max_));
    const vector half(0.5*(max_ - min_));
    vector q;
    for (direction i = 0; i < vector::nComponents; ++i)
    {
        q[i] = mag(p[i] - c[i]) - half[i];
    }
    const vector out(max(q.x(), 0.0), max(q.y(), 0.0), max(q.z(), 0.0));
    return mag(out) + min(cmptMax(q), 0.0);
}


Foam::boundBox Foam::bodyShapes::box::bounds() const
{
    return boundBox(min_, max_);
}


Foam::point Foam::bodyShapes::box::referencePoint() const
{
    return 0.5*(min_ + max_);
}


bool Foam::bodyShapes::box::polyhedron(List<vector>& n, scalarList& d) const
{
    n.setSize(6);
    d.setSize(6);
    for (direction i = 0; i < vector::nComponents; ++i)
    {
        vector e(Zero);
        e[i] = 1;
        n[2*i] = e;
        d[2*i] = max_[i];
        n[2*i + 1] = -e;
        d[2*i + 1] = -min_[i];
    }
    return true;
}


Foam::scalar Foam::bodyShapes::box::volume
(
    const word& geometry,
    const scalar depth
) const
{
    const vector d(max_ - min_);
    if (geometry == "threeD")
    {
        return d.x()*d.y()*d.z();
    }
    if (geometry == "axisymmetric")
    {
        // The ring swept by the section's part at y >= 0
        const scalar r0 = max(min_.y(), 0.0), r1 = max(max_.y(), 0.0);
        return constant::mathematical::pi*(sqr(r1) - sqr(r0))*d.x();
    }
    return (min_.z() <= 0 && max_.z() >= 0) ? d.x()*d.y()*depth : -1;
}


// ************************************************************************* //
