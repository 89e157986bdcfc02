/*---------------------------------------------------------------------------*\
  impactFoam: Eulerian multiphase elastic-plastic impact solver for OpenFOAM
\*---------------------------------------------------------------------------*/

#include "inelasticModel.H"
#include "keywordCheck.H"

// * * * * * * * * * * * * * * * * Selectors * * * * * * * * * * * * * * * //

Foam::autoPtr<Foam::inelasticModel> Foam::inelasticModel::New
(
    const hyperelasticPhase& law,
    const dictionary& phaseDict
)
{
    const dictionary* dictPtr = phaseDict.findDict("inelastic");
    const word modelType
    (
        dictPtr ? dictPtr->get<word>("type") : word("plasticityAndFailure")
    );

    auto cstrIter = dictionaryConstructorTablePtr_->cfind(modelType);
    if (!cstrIter.found())
    {
        FatalIOErrorInFunction(dictPtr ? *dictPtr : phaseDict)
            << "Phase " << law.name() << ": unknown inelastic type "
            << modelType << nl << nl
            << "Valid types are :" << nl
            << dictionaryConstructorTablePtr_->sortedToc()
            << exit(FatalIOError);
    }
    autoPtr<inelasticModel> model(cstrIter()(law, phaseDict));

    // Each model lists the entries of its sub-dictionary
    if (dictPtr)
    {
        checkKeywords
        (
            *dictPtr, model->keywords(), "Phase " + law.name() + ", inelastic"
        );
    }
    return model;
}


// ************************************************************************* //
