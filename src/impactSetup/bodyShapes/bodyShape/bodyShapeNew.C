#include "bodyShape.H"
#include "keywordCheck.H"

// * * * * * * * * * * * * * * * * Selectors * * * * * * * * * * * * * * * * //

Foam::autoPtr<Foam::bodyShape> Foam::bodyShape::New
(
    const dictionary& dict,
    const string& owner,
    const wordList& bodyKeys,
    const Time& runTime
)
{
    if (!dict.found("shape", keyType::LITERAL))
    {
        FatalIOErrorInFunction(dict)
            << owner.c_str() << ": no entry shape in " << dict.name()
            << nl << "Valid shapes: "
            << dictionaryConstructorTablePtr_->sortedToc()
            << exit(FatalIOError);
    }
    const word shapeType(dict.get<word>("shape"));

    auto cstrIter = dictionaryConstructorTablePtr_->cfind(shapeType);

    if (!cstrIter.found())
    {
        const wordList valid(dictionaryConstructorTablePtr_->sortedToc());
        FatalIOErrorInFunction(dict)
            << owner.c_str() << ": unknown shape " << shapeType
            << " (entry shape); did you mean "
            << nearestKeyword(shapeType, valid) << "?"
            << nl << "Valid shapes: " << valid
            << exit(FatalIOError);
    }

    return cstrIter()(dict, owner, bodyKeys, runTime);
}


// ************************************************************************* //
