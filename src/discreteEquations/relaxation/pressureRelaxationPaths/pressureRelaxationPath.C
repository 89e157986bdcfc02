/*---------------------------------------------------------------------------*\
  impactFoam: Eulerian multiphase elastic-plastic impact solver for OpenFOAM
\*---------------------------------------------------------------------------*/

#include "pressureRelaxationPath.H"
#include "inputDefaults.H"

namespace Foam
{
    defineTypeNameAndDebug(pressureRelaxationPath, 0);
    defineRunTimeSelectionTable(pressureRelaxationPath, dictionary);
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::pressureRelaxationPath::pressureRelaxationPath
(
    const hyperelasticPhase& law
)
:
    eos_(law.eos()),
    isentrope_(-1, 0),
    pCavitation_(-GREAT)
{}


Foam::wordList Foam::pressureRelaxationPath::keywords() const
{
    return {"pressureRelaxation"};
}


// * * * * * * * * * * * * * * * * * Selector  * * * * * * * * * * * * * * * //

Foam::autoPtr<Foam::pressureRelaxationPath> Foam::pressureRelaxationPath::New
(
    const hyperelasticPhase& law,
    const dictionary& phaseDict
)
{
    const word pathType
    (
        inputDefaults::get<word>
        (
            phaseDict,
            "pressureRelaxation",
            "constantPressure",
            "Phase " + law.name()
        )
    );
    auto cstrIter = dictionaryConstructorTablePtr_->cfind(pathType);
    if (!cstrIter.found())
    {
        FatalIOErrorInFunction(phaseDict)
            << "Phase " << law.name() << ": unknown pressureRelaxation "
            << pathType << "; valid: (";
        const wordList valid(dictionaryConstructorTablePtr_->sortedToc());
        forAll(valid, i)
        {
            FatalIOError << (i ? " " : "") << valid[i];
        }
        FatalIOError << ")" << exit(FatalIOError);
    }
    return cstrIter()(law, phaseDict);
}


// ************************************************************************* //
