#include "centripetal.H"
#include "addToRunTimeSelectionTable.H"

namespace Foam
{
namespace bodyAccelerations
{
    defineTypeNameAndDebug(centripetal, 0);
    addToRunTimeSelectionTable(bodyAcceleration, centripetal, dictionary);
}
}

Foam::bodyAccelerations::centripetal::centripetal
(
    const word& name,
    const dictionary& dict
)
:
    bodyAcceleration(name, dict),
    omega_(dict.get<scalar>("omega")),
    axis_(dict.get<vector>("axis")),
    origin_(dict.get<point>("origin"))
{
    if (mag(axis_) < VSMALL)
    {
        FatalIOErrorInFunction(dict)
            << "bodyAcceleration " << name << ": axis is zero"
            << exit(FatalIOError);
    }
    axis_ /= mag(axis_);
}


Foam::wordList Foam::bodyAccelerations::centripetal::keywords() const
{
    return {"type", "omega", "axis", "origin"};
}
