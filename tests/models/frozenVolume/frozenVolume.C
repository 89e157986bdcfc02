#include "frozenVolume.H"
#include "addToRunTimeSelectionTable.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace pressureRelaxationPaths
{
    defineTypeNameAndDebug(frozenVolume, 0);
    addToRunTimeSelectionTable
    (
        pressureRelaxationPath,
        frozenVolume,
        dictionary
    );
}
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::pressureRelaxationPaths::frozenVolume::frozenVolume
(
    const hyperelasticPhase& law,
    const dictionary&
)
:
    pressureRelaxationPath(law)
{}


// ************************************************************************* //
