/*---------------------------------------------------------------------------*\
  impactFoam: Eulerian multiphase elastic-plastic impact solver for OpenFOAM
\*---------------------------------------------------------------------------*/

#include "contactLaw.H"

namespace Foam
{
    defineTypeNameAndDebug(contactLaw, 0);
    defineRunTimeSelectionTable(contactLaw, dictionary);
}


Foam::wordList Foam::contactLaw::keywords() const
{
    return {"type"};
}


// ************************************************************************* //
