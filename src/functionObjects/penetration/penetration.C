/*---------------------------------------------------------------------------*\
  impactFoam: Eulerian multiphase elastic-plastic impact solver for OpenFOAM
\*---------------------------------------------------------------------------*/

#include "penetration.H"
#include "addToRunTimeSelectionTable.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace functionObjects
{
    defineTypeNameAndDebug(penetration, 0);
    addToRunTimeSelectionTable(functionObject, penetration, dictionary);
}
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::functionObjects::penetration::penetration
(
    const word& name,
    const Time& runTime,
    const dictionary& dict
)
:
    surfaceVelocity(name, runTime, dict, false)
{
    start();
}


// * * * * * * * * * * * * * Protected Member Functions  * * * * * * * * * * //

Foam::wordList Foam::functionObjects::penetration::columns() const
{
    return wordList({"P", "rodLength", "u"});
}


Foam::wordList Foam::functionObjects::penetration::units() const
{
    return wordList({"[m]", "[m]", "[m/s]"});
}


void Foam::functionObjects::penetration::values(DynamicList<scalar>& row)
{
    const lineSurface surface(surfaceOnLine());
    row.append(surface.position);
    row.append(surface.length);
    row.append(surface.U & direction());
}


// ************************************************************************* //
