/*---------------------------------------------------------------------------*\
  impactFoam: Eulerian multiphase elastic-plastic impact solver for OpenFOAM
\*---------------------------------------------------------------------------*/

#include "inelasticModel.H"

namespace Foam
{
    defineTypeNameAndDebug(inelasticModel, 0);
    defineRunTimeSelectionTable(inelasticModel, dictionary);
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::inelasticModel::inelasticModel(const hyperelasticPhase& law)
:
    law_(law)
{}


Foam::wordList Foam::inelasticModel::keywords() const
{
    return {"type"};
}


Foam::wordList Foam::inelasticModel::phaseKeywords() const
{
    return {"inelastic"};
}


// ************************************************************************* //
