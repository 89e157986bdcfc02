#include "reconstruction.H"
#include "foamEigen.H"

using Foam::foamEigen::toEigen;

namespace Foam
{
    defineTypeNameAndDebug(reconstruction, 0);
    defineRunTimeSelectionTable(reconstruction, dictionary);
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::reconstruction::reconstruction
(
    const phaseSystem& phases,
    const cellStates& cells,
    const dictionary& dict
)
:
    phases_(phases),
    mesh_(phases.mesh()),
    nPhases_(phases.size()),
    cells_(cells),
    gradUCalc_
    (
        phases.mesh(),
        phases.boundary().limiterNeighbours(true),
        limitVelocity(dict)
    ),
    gradU_(),
    firstOrderCells_(nullptr)
{}


// * * * * * * * * * * * * * Protected Member Functions  * * * * * * * * * * //

bool Foam::reconstruction::limitVelocity(const dictionary& dict)
{
    const word value
    (
        dict.getOrDefault<word>("velocityLimiter", "cellLimited")
    );
    if (value != "cellLimited" && value != "none")
    {
        FatalIOErrorInFunction(dict)
            << "Unknown velocityLimiter " << value
            << "; valid: (cellLimited none)" << exit(FatalIOError);
    }
    return value == "cellLimited";
}


void Foam::reconstruction::completeSide(const label k, phaseSide& s) const
{
    const hyperelasticPhase& ph = phases_.phase(k);
    s.solid = ph.solid();
    s.trace = s.alpha < phases_.alphaTrace();
    s.cT = std::sqrt(ph.cT2());
    double e;
    ph.sigmaAndE(s.rho, s.p, s.A, s.sigma, e);
    s.E = e + 0.5*s.U.squaredNorm();
}


void Foam::reconstruction::markMinor(std::vector<phaseSide>& s) const
{
    double rhoMix = 0;
    for (label k = 0; k < nPhases_; ++k)
    {
        rhoMix += s[k].alpha*s[k].rho;
    }
    const double Ymin = phases_.massFractionMinor();
    for (label k = 0; k < nPhases_; ++k)
    {
        s[k].minor =
            s[k].alpha < phases_.alphaMinor()
         || s[k].alpha*s[k].rho < Ymin*rhoMix;
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::reconstruction::centreAlphas
(
    const label,
    std::vector<double>&
) const
{
    FatalErrorInFunction
        << type() << " has no time-centred state" << abort(FatalError);
}


void Foam::reconstruction::centreState
(
    const label,
    std::vector<phaseSide>&
) const
{
    FatalErrorInFunction
        << type() << " has no time-centred state" << abort(FatalError);
}


void Foam::reconstruction::cellFaceState
(
    const label celli,
    const vector& d,
    std::vector<phaseSide>& s
) const
{
    const vector& Uc = phases_.U()[celli];

    cobasis::vector U(toEigen(Uc));
    U += toEigen(d & gradU_[celli]);
    const double dKe = 0.5*(U.squaredNorm() - magSqr(Uc));

    for (label k = 0; k < nPhases_; ++k)
    {
        phaseSide& sk = s[k];
        const hyperelasticPhase& ph = phases_.phase(k);
        sk.alpha = phases_.alpha(k)[celli];
        sk.rho = phases_.rho(k)[celli];
        sk.p = phases_.p(k)[celli];
        sk.U = U;
        sk.A = toEigen(phases_.A(k)[celli]);
        cellCarried(k, celli, sk);
        sk.sigma = cells_.sigma(k, celli);
        sk.E = cells_.E(k, celli) + dKe;
        sk.a = cells_.a(k, celli);
        sk.cT = std::sqrt(ph.cT2());
        sk.solid = ph.solid();
        sk.trace = sk.alpha < phases_.alphaTrace();
    }
    markMinor(s);
}


// ************************************************************************* //
