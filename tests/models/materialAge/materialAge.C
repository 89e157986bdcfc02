/*---------------------------------------------------------------------------*\
  impactFoam tests: an inelastic model defined outside the libraries
\*---------------------------------------------------------------------------*/

#include "materialAge.H"
#include "addToRunTimeSelectionTable.H"

namespace Foam
{
namespace inelasticModels
{
    defineTypeNameAndDebug(materialAge, 0);
    addToRunTimeSelectionTable(inelasticModel, materialAge, dictionary);
}
}


Foam::inelasticModels::materialAge::materialAge
(
    const hyperelasticPhase& law,
    const dictionary& phaseDict
)
:
    plasticityAndFailure(law, phaseDict),
    iAge_(plasticityAndFailure::carriedVariables().size())
{}


Foam::carriedVariableList
Foam::inelasticModels::materialAge::carriedVariables() const
{
    carriedVariableList vars(plasticityAndFailure::carriedVariables());
    vars.append(carriedVariable("age", dimTime, 0, 0));
    return vars;
}


void Foam::inelasticModels::materialAge::describe(Ostream& os) const
{
    plasticityAndFailure::describe(os);
    os  << ", age";
}


Foam::scalar Foam::inelasticModels::materialAge::relax
(
    cobasis::matrix& A,
    scalar* carried,
    const scalar rho,
    scalar& e,
    const scalar dt
) const
{
    const scalar heat = plasticityAndFailure::relax(A, carried, rho, e, dt);
    carried[iAge_] += dt;
    return heat;
}


// ************************************************************************* //
