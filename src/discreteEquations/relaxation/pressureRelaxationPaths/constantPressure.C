/*---------------------------------------------------------------------------*\
  impactFoam: Eulerian multiphase elastic-plastic impact solver for OpenFOAM
\*---------------------------------------------------------------------------*/

#include "constantPressure.H"
#include "addToRunTimeSelectionTable.H"

namespace Foam
{
namespace pressureRelaxationPaths
{
    defineTypeNameAndDebug(constantPressure, 0);
    addToRunTimeSelectionTable
    (
        pressureRelaxationPath,
        constantPressure,
        dictionary
    );
}
}


Foam::pressureRelaxationPaths::constantPressure::constantPressure
(
    const hyperelasticPhase& law,
    const dictionary& dict
)
:
    pressureRelaxationPath(law)
{
    for (const word key : {"cavitationPressure", "referenceIsentrope"})
    {
        if (dict.found(key))
        {
            FatalIOErrorInFunction(dict)
                << "Phase " << law.name() << ": " << key
                << " needs pressureRelaxation isentropic"
                << exit(FatalIOError);
        }
    }
}


// ************************************************************************* //
