#include "bodyExtent.H"
#include "rodMeasures.H"
#include "addToRunTimeSelectionTable.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace functionObjects
{
    defineTypeNameAndDebug(bodyExtent, 0);
    addToRunTimeSelectionTable(functionObject, bodyExtent, dictionary);
}
}


// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * * //

namespace
{

// The unit vector of entry key (stops the run on a zero vector)
Foam::vector unitVector
(
    const Foam::dictionary& dict,
    const Foam::word& key,
    const Foam::vector& deflt
)
{
    using namespace Foam;
    const vector v(dict.getOrDefault<vector>(key, deflt));
    if (mag(v) < VSMALL)
    {
        FatalIOErrorInFunction(dict)
            << key << " " << v << " in " << dict.name()
            << ": a direction cannot be zero" << exit(FatalIOError);
    }
    return v/mag(v);
}

} // End anonymous namespace


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::functionObjects::bodyExtent::bodyExtent
(
    const word& name,
    const Time& runTime,
    const dictionary& dict
)
:
    impactTimeHistory(name, runTime, dict),
    phase_(-1),
    axis_(1, 0, 0),
    origin_(Zero),
    direction_(-1, 0, 0),
    point_(Zero)
{
    bodyExtent::read(dict);
    start();
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

bool Foam::functionObjects::bodyExtent::read(const dictionary& dict)
{
    impactTimeHistory::read(dict);
    phase_ = phaseIndex(dict, dict.get<word>("phase"));
    axis_ = unitVector(dict, "axis", vector(1, 0, 0));
    origin_ = dict.getOrDefault<point>("origin", Zero);
    direction_ = unitVector(dict, "direction", -axis_);
    point_ = dict.getOrDefault<point>("point", origin_);
    return true;
}


// * * * * * * * * * * * * * Protected Member Functions  * * * * * * * * * * //

Foam::wordList Foam::functionObjects::bodyExtent::columns() const
{
    return wordList
    ({
        "length", "maxRadius", "faceRadius", "zMin", "penetration"
    });
}


Foam::wordList Foam::functionObjects::bodyExtent::units() const
{
    return wordList({"[m]", "[m]", "[m]", "[m]", "[m]"});
}


void Foam::functionObjects::bodyExtent::values(DynamicList<scalar>& row)
{
    const scalarField& alpha = phases().alpha(phase_).primitiveField();
    const rodMeasures rod(mesh_, alpha, axis_, origin_);

    const vectorField& C = mesh_.C().primitiveField();
    scalar penetration = -GREAT;
    forAll(C, celli)
    {
        if (alpha[celli] >= 0.5)
        {
            penetration =
                max(penetration, (C[celli] - point_) & direction_);
        }
    }
    reduce(penetration, maxOp<scalar>());

    row.append(rod.length);
    row.append(rod.maxRadius);
    row.append(rod.faceRadius);
    row.append(rod.zMin);
    row.append(penetration > -GREAT ? penetration : 0);
}


// ************************************************************************* //
