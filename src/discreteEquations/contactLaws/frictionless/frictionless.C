/*---------------------------------------------------------------------------*\
  impactFoam: Eulerian multiphase elastic-plastic impact solver for OpenFOAM
\*---------------------------------------------------------------------------*/

#include "frictionless.H"
#include "addToRunTimeSelectionTable.H"

namespace Foam
{
namespace contactLaws
{
    defineTypeNameAndDebug(frictionless, 0);
    addToRunTimeSelectionTable(contactLaw, frictionless, dictionary);
}
}


Foam::contactLaws::frictionless::frictionless(const dictionary&, const word&)
:
    contactLaw()
{}


// ************************************************************************* //
