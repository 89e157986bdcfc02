#include "stlShape.H"
#include "addToRunTimeSelectionTable.H"
#include "Time.H"
#include "volumeType.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace bodyShapes
{
    defineTypeNameAndDebug(stl, 0);
    addToRunTimeSelectionTable(bodyShape, stl, dictionary);
}
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::bodyShapes::stl::stl
(
    const dictionary& dict,
    const string& owner,
    const wordList& bodyKeys,
    const Time& runTime
)
:
    bodyShape(owner),
    span_(0)
{
    checkEntries(dict, {"file", "scale"}, bodyKeys, owner);
    fileName file(required<fileName>(dict, "file", owner));
    file.expand();
    if (!file.isAbsolute())
    {
        file = runTime.globalPath()/file;
    }
    if (!isFile(file))
    {
        FatalIOErrorInFunction(dict)
            << owner.c_str() << ": entry file: no surface file " << file
            << exit(FatalIOError);
    }
    surface_.reset(new triSurface(file));
    const scalar scale =
        dict.getOrDefault<scalar>("scale", 1, keyType::LITERAL);
    if (scale != 1)
    {
        surface_->scalePoints(scale);
    }
    if (surface_->empty())
    {
        FatalIOErrorInFunction(dict)
            << owner.c_str() << ": surface " << file << " has no triangles"
            << exit(FatalIOError);
    }

    // Closed: every edge shared by exactly two triangles
    const labelListList& edgeFaces = surface_->edgeFaces();
    label open = 0;
    for (const labelList& ef : edgeFaces)
    {
        if (ef.size() != 2)
        {
            ++open;
        }
    }
    if (open)
    {
        FatalIOErrorInFunction(dict)
            << owner.c_str() << ": surface " << file << " is not closed: "
            << open
            << " of its " << edgeFaces.size() << " edges do not join two"
            << " triangles (inside and outside need a closed surface)"
            << exit(FatalIOError);
    }

    search_.reset(new triSurfaceSearch(surface_()));
    span_ = 2*boundBox(surface_->points(), false).mag() + 1;
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::scalar Foam::bodyShapes::stl::distance(const point& p) const
{
    const pointIndexHit hit(search_->nearest(p, vector::uniform(span_)));
    const scalar d = hit.hit() ? mag(hit.hitPoint() - p) : span_;
    const volumeType vt(search_->tree().getVolumeType(p));
    return vt == volumeType::INSIDE ? -d : d;
}


bool Foam::bodyShapes::stl::bounded() const
{
    return true;
}


Foam::boundBox Foam::bodyShapes::stl::bounds() const
{
    return boundBox(surface_->points(), false);
}


Foam::point Foam::bodyShapes::stl::referencePoint() const
{
    return bounds().centre();
}


Foam::scalar Foam::bodyShapes::stl::volume
(
    const word& geometry,
    const scalar
) const
{
    if (geometry != "threeD")
    {
        return -1;
    }
    const pointField& pts = surface_->points();
    scalar V = 0;
    for (const labelledTri& f : surface_())
    {
        V += (pts[f[0]] & (pts[f[1]] ^ pts[f[2]]))/6;
    }
    return mag(V);
}


// ************************************************************************* //
