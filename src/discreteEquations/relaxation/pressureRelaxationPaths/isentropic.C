/*---------------------------------------------------------------------------*\
  impactFoam: Eulerian multiphase elastic-plastic impact solver for OpenFOAM
\*---------------------------------------------------------------------------*/

#include "isentropic.H"
#include "addToRunTimeSelectionTable.H"

namespace Foam
{
namespace pressureRelaxationPaths
{
    defineTypeNameAndDebug(isentropic, 0);
    addToRunTimeSelectionTable(pressureRelaxationPath, isentropic, dictionary);
}
}


Foam::pressureRelaxationPaths::isentropic::isentropic
(
    const hyperelasticPhase& law,
    const dictionary& dict
)
:
    pressureRelaxationPath(law)
{
    const word& name = law.name();
    if (law.solid())
    {
        FatalIOErrorInFunction(dict)
            << "Phase " << name << ": pressureRelaxation isentropic is"
            << " for fluids only" << exit(FatalIOError);
    }
    if (dict.found("cavitationPressure"))
    {
        pCavitation_ = dict.get<scalar>("cavitationPressure");
        // Held there, the fluid may expand to a vanishing density
        if (!(pCavitation_ > eos_.pMin(SMALL)))
        {
            FatalIOErrorInFunction(dict)
                << "Phase " << name << ": cavitationPressure "
                << pCavitation_ << " needs pressureRelaxation"
                << " isentropic and a value above "
                << eos_.pMin(SMALL) << exit(FatalIOError);
        }
    }
    if (dict.found("referenceIsentrope"))
    {
        const Pair<scalar> ref(dict.get<Pair<scalar>>("referenceIsentrope"));
        if (!eos_.admissible(ref.first(), ref.second()))
        {
            FatalIOErrorInFunction(dict)
                << "Phase " << name << ": referenceIsentrope " << ref
                << " needs pressureRelaxation isentropic, 0 < rho < "
                << eos_.rhoMax() << " and p > " << eos_.pMin(ref.first())
                << exit(FatalIOError);
        }
        isentrope_ =
            Pair<scalar>(ref.first(), eos_.e(ref.first(), ref.second()));
    }
}


Foam::wordList Foam::pressureRelaxationPaths::isentropic::keywords() const
{
    wordList valid(pressureRelaxationPath::keywords());
    valid.append(wordList({"cavitationPressure", "referenceIsentrope"}));
    return valid;
}


// ************************************************************************* //
