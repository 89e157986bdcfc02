#include "JohnsonCookFailure.H"
#include "inputDefaults.H"
#include "addToRunTimeSelectionTable.H"

namespace Foam
{
namespace failureModels
{
    defineTypeNameAndDebug(JohnsonCook, 0);
    addToRunTimeSelectionTable(failureModel, JohnsonCook, dictionary);
}
}


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

Foam::scalar Foam::failureModels::JohnsonCook::readShared
(
    const dictionary& dict,
    const dictionary& phaseDict,
    const word& name,
    const scalar deflt
) const
{
    if (dict.found(name))
    {
        return dict.get<scalar>(name);
    }
    const dictionary* plasticity = phaseDict.findDict("plasticity");
    const dictionary* law =
        plasticity ? plasticity->findDict("yieldStress") : nullptr;
    if (law && law->found(name))
    {
        return law->get<scalar>(name);
    }
    if (deflt >= 0)
    {
        inputDefaults::note
        (
            "Phase " + phaseName_ + ", failure", name, Foam::name(deflt)
        );
    }
    else
    {
        FatalIOErrorInFunction(dict)
            << "Phase " << phaseName_ << ": failure JohnsonCook with D5 = "
            << D5_ << " needs the entry " << name << " (in failure, or in"
            << " a Johnson-Cook plasticity yieldStress)" << exit(FatalIOError);
    }
    return deflt;
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::failureModels::JohnsonCook::JohnsonCook
(
    const word& phaseName,
    const dictionary& dict,
    const dictionary& phaseDict
)
:
    failureModel(phaseName, dict),
    D1_(read(dict, "D1")),
    D2_(read(dict, "D2")),
    D3_(read(dict, "D3")),
    D4_(readOptional(dict, "D4", 0)),
    D5_(readOptional(dict, "D5", 0)),
    epsDot0_(readShared(dict, phaseDict, "epsDot0", 1)),
    rEpsDot0_(1),
    Tr_(0),
    Tm_(1)
{
    // epsF > 0 for every triaxiality, rate >= epsDot0 and Th in [0, 1]
    if (!(D1_ >= 0)) badEntry(dict, "D1", D1_, ">= 0");
    if (!(D2_ >= 0)) badEntry(dict, "D2", D2_, ">= 0");
    if (!(D1_ + D2_ > 0)) badEntry(dict, "D1 + D2", D1_ + D2_, "> 0");
    if (!(mag(D3_) < GREAT)) badEntry(dict, "D3", D3_, "finite");
    if (!(D4_ >= 0)) badEntry(dict, "D4", D4_, ">= 0");
    if (!(D5_ > -1)) badEntry(dict, "D5", D5_, "> -1");
    if (!(epsDot0_ > 0)) badEntry(dict, "epsDot0", epsDot0_, "> 0");
    rEpsDot0_ = 1/epsDot0_;
    if (spallTime_ > 0)
    {
        FatalIOErrorInFunction(dict)
            << "Phase " << phaseName << ": spallTime is for failure type"
            << " spall (a partial Johnson-Cook damage is no softening)"
            << exit(FatalIOError);
    }

    if (D5_ != 0)
    {
        Tr_ = readShared(dict, phaseDict, "Tr", -1);
        Tm_ = readShared(dict, phaseDict, "Tm", -1);
        if (!(Tm_ > Tr_)) badEntry(dict, "Tm - Tr", Tm_ - Tr_, "> 0");
    }
}


Foam::wordList Foam::failureModels::JohnsonCook::keywords() const
{
    wordList valid(failureModel::keywords());
    valid.append
    (
        wordList({"D1", "D2", "D3", "D4", "D5", "epsDot0", "Tr", "Tm"})
    );
    return valid;
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::scalar Foam::failureModels::JohnsonCook::epsF
(
    const scalar sigmaStar,
    const scalar epsPDot,
    const scalar T
) const
{
    // The exponent is clamped: sigmaStar is unbounded where the Von Mises
    // stress vanishes
    const scalar x = min(max(D3_*sigmaStar, scalar(-700)), scalar(700));
    scalar e = D1_ + D2_*exp(x);
    if (D4_ != 0 && epsPDot > epsDot0_)
    {
        e *= 1 + D4_*log(epsPDot*rEpsDot0_);
    }
    if (D5_ != 0)
    {
        const scalar Th = min(max((T - Tr_)/(Tm_ - Tr_), scalar(0)), scalar(1));
        e *= 1 + D5_*Th;
    }
    return e;
}


Foam::scalar Foam::failureModels::JohnsonCook::damageIncrement
(
    const scalar dEpsP,
    const scalar epsPDot,
    const scalar p,
    const scalar sigmaEq,
    const scalar T
) const
{
    const scalar sigmaStar =
        sigmaEq > 0 ? -p/sigmaEq : (p < 0 ? GREAT : p > 0 ? -GREAT : 0);
    return dEpsP/max(epsF(sigmaStar, epsPDot, T), VSMALL);
}


// ************************************************************************* //
