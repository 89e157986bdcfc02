#include "failureModel.H"
#include "inputDefaults.H"

namespace Foam
{
    defineTypeNameAndDebug(failureModel, 0);
    defineRunTimeSelectionTable(failureModel, dictionary);
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::failureModel::failureModel
(
    const word& phaseName,
    const dictionary& dict
)
:
    phaseName_(phaseName),
    sigmaSpall_(0),
    pCavitation_(readOptional(dict, "cavitationPressure", 0)),
    spallTime_(readOptional(dict, "spallTime", 0))
{
    if (dict.found("sigmaSpall"))
    {
        sigmaSpall_ = dict.get<scalar>("sigmaSpall");
        if (!(sigmaSpall_ > 0))
        {
            badEntry(dict, "sigmaSpall", sigmaSpall_, "> 0");
        }
    }
    if (!(pCavitation_ > -GREAT && pCavitation_ < GREAT))
    {
        badEntry(dict, "cavitationPressure", pCavitation_, "finite");
    }
    if (!(spallTime_ >= 0))
    {
        badEntry(dict, "spallTime", spallTime_, ">= 0");
    }
    if (spallTime_ > 0 && !(sigmaSpall_ > 0))
    {
        FatalIOErrorInFunction(dict)
            << "Phase " << phaseName_ << ": failure entry spallTime needs"
            << " sigmaSpall" << exit(FatalIOError);
    }
    if (sigmaSpall_ > 0 && !(pCavitation_ > -sigmaSpall_))
    {
        badEntry(dict, "cavitationPressure", pCavitation_, "> -sigmaSpall");
    }
}


Foam::wordList Foam::failureModel::keywords() const
{
    return {"type", "sigmaSpall", "cavitationPressure", "spallTime"};
}


// * * * * * * * * * * * * Protected Member Functions  * * * * * * * * * * * //

Foam::scalar Foam::failureModel::readOptional
(
    const dictionary& dict,
    const word& name,
    const scalar deflt
) const
{
    // A default is noted where a failure model acts (not type none)
    if (dict.getOrDefault<word>("type", "none") == "none")
    {
        return dict.getOrDefault<scalar>(name, deflt);
    }
    return
        inputDefaults::get<scalar>
        (
            dict, name, deflt, "Phase " + phaseName_ + ", failure"
        );
}


Foam::scalar Foam::failureModel::read
(
    const dictionary& dict,
    const word& name
) const
{
    if (!dict.found(name))
    {
        FatalIOErrorInFunction(dict)
            << "Phase " << phaseName_ << ": failure "
            << dict.getOrDefault<word>("type", "") << " needs the entry "
            << name << exit(FatalIOError);
    }
    return dict.get<scalar>(name);
}


void Foam::failureModel::badEntry
(
    const dictionary& dict,
    const word& name,
    const scalar value,
    const char* what
) const
{
    FatalIOErrorInFunction(dict)
        << "Phase " << phaseName_ << ": failure "
        << dict.getOrDefault<word>("type", "") << " entry " << name
        << " = " << value << ", must be " << what << exit(FatalIOError);
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //



Foam::scalar Foam::failureModel::damage
(
    const scalar D,
    const scalar dEpsP,
    const scalar epsPDot,
    const scalar p,
    const scalar sigmaEq,
    const scalar T
) const
{
    if
    (
        failed(D)
     || (sigmaSpall_ > 0 && spallTime_ == 0 && p < -sigmaSpall_)
    )
    {
        return 1;
    }
    const scalar dD =
        dEpsP > 0 ? damageIncrement(dEpsP, epsPDot, p, sigmaEq, T) : 0;
    return min(D + dD, scalar(1));
}


Foam::scalar Foam::failureModel::spall
(
    const scalar D,
    const scalar p,
    const scalar dt
) const
{
    if (failed(D))
    {
        return 1;
    }
    if (!(sigmaSpall_ > 0))
    {
        return D;
    }
    if (spallTime_ == 0)
    {
        return p < -sigmaSpall_ ? 1 : D;
    }
    // Growing while the tension exceeds the spall strength it holds
    if (p < -sigmaSpall_)
    {
        return min(D + dt/spallTime_, scalar(1));
    }
    return D;
}


// ************************************************************************* //
