/*---------------------------------------------------------------------------*\
  impactFoam: Eulerian multiphase elastic-plastic impact solver for OpenFOAM
\*---------------------------------------------------------------------------*/

#include "welded.H"
#include "addToRunTimeSelectionTable.H"

namespace Foam
{
namespace contactLaws
{
    defineTypeNameAndDebug(welded, 0);
    addToRunTimeSelectionTable(contactLaw, welded, dictionary);
}
}


Foam::contactLaws::welded::welded(const dictionary&, const word&)
:
    contactLaw()
{}


// ************************************************************************* //
