#include "JohnsonCookYieldStress.H"
#include "addToRunTimeSelectionTable.H"

namespace Foam
{
namespace yieldStresses
{
    defineTypeNameAndDebug(JohnsonCook, 0);
    addToRunTimeSelectionTable(yieldStress, JohnsonCook, dictionary);
}
}


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

void Foam::yieldStresses::JohnsonCook::check(const dictionary& dict) const
{
    if (!(Tm_ > Tr_))
    {
        FatalIOErrorInFunction(dict)
            << "Phase " << phaseName_ << ": yieldStress JohnsonCook Tm = "
            << Tm_ << " must be above Tr = " << Tr_
            << " (melting above the reference temperature)"
            << exit(FatalIOError);
    }
    if (!(A_ + B_ > 0))
    {
        FatalIOErrorInFunction(dict)
            << "Phase " << phaseName_ << ": yieldStress JohnsonCook A = "
            << A_ << " and B = " << B_ << " give no strength at any plastic"
            << " strain; A + B must be positive" << exit(FatalIOError);
    }
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::yieldStresses::JohnsonCook::JohnsonCook
(
    const word& phaseName,
    const dictionary& dict
)
:
    yieldStress(phaseName),
    A_(readNonNegative(dict, "A")),
    B_(readNonNegative(dict, "B")),
    n_(readPositive(dict, "n")),
    C_(readNonNegative(dict, "C", 0)),
    m_(readPositive(dict, "m")),
    Tr_(readNonNegative(dict, "Tr")),
    Tm_(read(dict, "Tm")),
    epsDot0_(readPositive(dict, "epsDot0", 1)),
    rDeltaT_(0),
    rEpsDot0_(1/epsDot0_),
    lastT_(Tr_),
    lastThermal_(1)
{
    check(dict);
    rDeltaT_ = 1/(Tm_ - Tr_);
}


Foam::wordList Foam::yieldStresses::JohnsonCook::keywords() const
{
    return {"type", "A", "B", "n", "C", "m", "Tr", "Tm", "epsDot0"};
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::scalar Foam::yieldStresses::JohnsonCook::sigmaY
(
    const scalar epsP,
    const scalar epsPDot,
    const scalar T
) const
{
    // Thermal factor 1 - Th^m, 0 at and above melting (that of the last
    // T if T has not changed)
    if (T != lastT_)
    {
        const scalar Th = (T - Tr_)*rDeltaT_;
        lastThermal_ =
            !(Th > 0) ? 1
          : !(Th < 1) ? 0
          : 1 - (m_ == 1 ? Th : std::pow(Th, m_));
        lastT_ = T;
    }
    const scalar thermal = lastThermal_;
    if (thermal == 0)
    {
        return 0;
    }

    // Strain hardening A + B epsP^n (epsP >= 0; 0^n = 0 for n > 0)
    scalar hardening = A_;
    if (epsP > 0 && B_ > 0)
    {
        hardening += B_*(n_ == 1 ? epsP : std::pow(epsP, n_));
    }

    // Rate factor, 1 below the reference rate
    scalar rateFactor = 1;
    if (C_ > 0)
    {
        const scalar x = epsPDot*rEpsDot0_;
        if (x > 1)
        {
            rateFactor += C_*std::log(x);
        }
    }

    return hardening*rateFactor*thermal;
}
