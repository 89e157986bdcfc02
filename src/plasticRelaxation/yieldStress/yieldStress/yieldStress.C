#include "yieldStress.H"
#include "inputDefaults.H"

namespace Foam
{
    defineTypeNameAndDebug(yieldStress, 0);
    defineRunTimeSelectionTable(yieldStress, dictionary);
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::yieldStress::yieldStress(const word& phaseName)
:
    phaseName_(phaseName)
{}


Foam::wordList Foam::yieldStress::keywords() const
{
    return {"type"};
}


// * * * * * * * * * * * * Protected Member Functions  * * * * * * * * * * * //

Foam::scalar Foam::yieldStress::read
(
    const dictionary& dict,
    const word& name
) const
{
    if (!dict.found(name))
    {
        FatalIOErrorInFunction(dict)
            << "Phase " << phaseName_ << ": yieldStress "
            << dict.getOrDefault<word>("type", "") << " needs the entry "
            << name << exit(FatalIOError);
    }
    return dict.get<scalar>(name);
}


Foam::scalar Foam::yieldStress::readPositive
(
    const dictionary& dict,
    const word& name
) const
{
    const scalar value = read(dict, name);
    if (!(value > 0))
    {
        FatalIOErrorInFunction(dict)
            << "Phase " << phaseName_ << ": yieldStress " << name << " = "
            << value << " must be positive" << exit(FatalIOError);
    }
    return value;
}


Foam::scalar Foam::yieldStress::readNonNegative
(
    const dictionary& dict,
    const word& name
) const
{
    const scalar value = read(dict, name);
    if (!(value >= 0))
    {
        FatalIOErrorInFunction(dict)
            << "Phase " << phaseName_ << ": yieldStress " << name << " = "
            << value << " must be non-negative" << exit(FatalIOError);
    }
    return value;
}


bool Foam::yieldStress::defaulted
(
    const dictionary& dict,
    const word& name,
    const scalar deflt
) const
{
    if (dict.found(name))
    {
        return false;
    }
    inputDefaults::note
    (
        "Phase " + phaseName_ + ", plasticity yieldStress",
        name,
        Foam::name(deflt)
    );
    return true;
}


Foam::scalar Foam::yieldStress::readPositive
(
    const dictionary& dict,
    const word& name,
    const scalar deflt
) const
{
    return defaulted(dict, name, deflt) ? deflt : readPositive(dict, name);
}


Foam::scalar Foam::yieldStress::readNonNegative
(
    const dictionary& dict,
    const word& name,
    const scalar deflt
) const
{
    return defaulted(dict, name, deflt) ? deflt : readNonNegative(dict, name);
}


// ************************************************************************* //
