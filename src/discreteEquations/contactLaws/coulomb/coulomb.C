/*---------------------------------------------------------------------------*\
  impactFoam: Eulerian multiphase elastic-plastic impact solver for OpenFOAM
\*---------------------------------------------------------------------------*/

#include "coulomb.H"
#include "addToRunTimeSelectionTable.H"

namespace Foam
{
namespace contactLaws
{
    defineTypeNameAndDebug(coulomb, 0);
    addToRunTimeSelectionTable(contactLaw, coulomb, dictionary);
}
}


namespace Foam
{

static double readMu(const dictionary& dict, const word& owner)
{
    if (!dict.found("mu"))
    {
        FatalIOErrorInFunction(dict)
            << owner << ": coulomb needs its friction coefficient mu"
            << exit(FatalIOError);
    }
    const double mu = dict.get<scalar>("mu");
    if (!(mu >= 0))
    {
        FatalIOErrorInFunction(dict)
            << owner << ": coulomb's mu = " << mu << " must be >= 0"
            << exit(FatalIOError);
    }
    return mu;
}

} // End namespace Foam


Foam::contactLaws::coulomb::coulomb
(
    const dictionary& dict,
    const word& owner
)
:
    contactLaw(),
    mu_(readMu(dict, owner))
{}


Foam::wordList Foam::contactLaws::coulomb::keywords() const
{
    wordList valid(contactLaw::keywords());
    valid.append("mu");
    return valid;
}


// ************************************************************************* //
