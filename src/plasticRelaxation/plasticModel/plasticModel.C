#include "plasticModel.H"

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


Foam::wordList Foam::plasticModel::keywords() const
{
    return {"type"};
}


