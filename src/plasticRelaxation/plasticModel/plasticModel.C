#include "plasticModel.H"
#include "carriedVariable.H"

namespace Foam
{
    defineTypeNameAndDebug(plasticModel, 0);
    defineRunTimeSelectionTable(plasticModel, dictionary);
}

Foam::plasticModel::plasticModel
(
    const word& phaseName,
    const dictionary& dict
)
:
    phaseName_(phaseName)
{}


Foam::carriedVariableList Foam::plasticModel::carriedVariables() const
{
    carriedVariableList vars;
    vars.append(carriedVariable("epsilonP", dimless, 0, 0));
    vars.append(carriedVariable("plasticWork", dimEnergy/dimMass, 0, 0));
    return vars;
}
