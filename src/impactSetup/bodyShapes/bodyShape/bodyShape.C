#include "bodyShape.H"
#include "keywordCheck.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
    defineTypeNameAndDebug(bodyShape, 0);
    defineRunTimeSelectionTable(bodyShape, dictionary);
}


// * * * * * * * * * * * * Protected Member Functions  * * * * * * * * * * * //

void Foam::bodyShape::checkEntries
(
    const dictionary& dict,
    const wordList& shapeKeys,
    const wordList& bodyKeys,
    const string& owner
)
{
    wordList valid(bodyKeys);
    valid.append("shape");
    valid.append(shapeKeys);
    checkKeywords(dict, valid, owner);
}


void Foam::bodyShape::missing
(
    const dictionary& dict,
    const word& key,
    const string& owner
)
{
    FatalIOErrorInFunction(dict)
        << owner.c_str() << ": shape " << dict.getOrDefault<word>("shape", "?")
        << " needs the entry " << key << " (missing in " << dict.name()
        << ")" << exit(FatalIOError);
}


Foam::scalar Foam::bodyShape::positive
(
    const dictionary& dict,
    const word& key,
    const string& owner
)
{
    const scalar value(required<scalar>(dict, key, owner));
    if (!(value > 0))
    {
        FatalIOErrorInFunction(dict)
            << owner.c_str() << ": entry " << key << " " << value
            << " must be positive" << exit(FatalIOError);
    }
    return value;
}


Foam::vector Foam::bodyShape::discExtent(const vector& axis)
{
    return vector
    (
        Foam::sqrt(max(1 - sqr(axis.x()), scalar(0))),
        Foam::sqrt(max(1 - sqr(axis.y()), scalar(0))),
        Foam::sqrt(max(1 - sqr(axis.z()), scalar(0)))
    );
}


bool Foam::bodyShape::onXAxis
(
    const point& base,
    const vector& axis,
    const scalar length
)
{
    return
        mag(axis ^ vector(1, 0, 0)) < 1e-12
     && mag(base.y()) < 1e-12*length && mag(base.z()) < 1e-12*length;
}


Foam::vector Foam::bodyShape::unitVector
(
    const dictionary& dict,
    const word& key,
    const string& owner
)
{
    const vector v(required<vector>(dict, key, owner));
    if (!(mag(v) > VSMALL))
    {
        FatalIOErrorInFunction(dict)
            << owner.c_str() << ": entry " << key << " " << v
            << " must be a non-zero vector" << exit(FatalIOError);
    }
    return v/mag(v);
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::bodyShape::bodyShape(const string& owner)
:
    owner_(owner)
{}


// ************************************************************************* //
