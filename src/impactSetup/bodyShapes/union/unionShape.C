#include "unionShape.H"
#include "addToRunTimeSelectionTable.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace bodyShapes
{
    defineTypeNameAndDebug(shapeUnion, 0);
    addToRunTimeSelectionTable(bodyShape, shapeUnion, dictionary);
}
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::bodyShapes::shapeUnion::shapeUnion
(
    const dictionary& dict,
    const string& owner,
    const wordList& bodyKeys,
    const Time& runTime
)
:
    bodyShape(owner)
{
    checkEntries(dict, {"shapes"}, bodyKeys, owner);
    if (!dict.found("shapes", keyType::LITERAL))
    {
        missing(dict, "shapes", owner);
    }
    if (!dict.isDict("shapes"))
    {
        FatalIOErrorInFunction(dict)
            << owner.c_str() << ": entry shapes of a union must be a"
            << " dictionary of named shapes, shapes { a { shape ...; } ... }"
            << exit(FatalIOError);
    }
    const dictionary& shapes = dict.subDict("shapes");
    for (const entry& e : shapes)
    {
        if (!e.isDict())
        {
            FatalIOErrorInFunction(shapes)
                << owner.c_str() << ": entry " << e.keyword() << " of shapes"
                << " is not a shape (a dictionary name { shape ...; })"
                << exit(FatalIOError);
        }
        parts_.append
        (
            bodyShape::New
            (
                e.dict(),
                owner + ", shape " + e.keyword() + " of the union",
                wordList(),
                runTime
            )
        );
    }
    if (parts_.empty())
    {
        FatalIOErrorInFunction(dict)
            << owner.c_str() << ": entry shapes of a union is empty"
            << exit(FatalIOError);
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::scalar Foam::bodyShapes::shapeUnion::distance(const point& p) const
{
    scalar d = GREAT;
    for (const bodyShape& s : parts_)
    {
        d = min(d, s.distance(p));
    }
    return d;
}


bool Foam::bodyShapes::shapeUnion::bounded() const
{
    for (const bodyShape& s : parts_)
    {
        if (!s.bounded())
        {
            return false;
        }
    }
    return true;
}


Foam::boundBox Foam::bodyShapes::shapeUnion::bounds() const
{
    boundBox bb(parts_[0].bounds());
    for (const bodyShape& s : parts_)
    {
        bb.add(s.bounds());
    }
    return bb;
}


Foam::point Foam::bodyShapes::shapeUnion::referencePoint() const
{
    return parts_[0].referencePoint();
}


Foam::scalar Foam::bodyShapes::shapeUnion::volume
(
    const word& geometry,
    const scalar depth
) const
{
    scalar V = 0;
    for (const bodyShape& s : parts_)
    {
        const scalar v = s.volume(geometry, depth);
        if (v < 0)
        {
            return -1;
        }
        V += v;
    }
    return V;
}


// ************************************************************************* //
