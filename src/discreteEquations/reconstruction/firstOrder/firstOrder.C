#include "firstOrder.H"
#include "foamEigen.H"
#include "addToRunTimeSelectionTable.H"

using Foam::foamEigen::toEigen;

namespace Foam
{
namespace reconstructions
{
    defineTypeNameAndDebug(firstOrder, 0);
    addToRunTimeSelectionTable(reconstruction, firstOrder, dictionary);
}
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::reconstructions::firstOrder::firstOrder
(
    const phaseSystem& phases,
    const cellStates& cells,
    const dictionary& dict
)
:
    reconstruction(phases, cells, dict)
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::reconstructions::firstOrder::update
(
    const scalar,
    const vectorField*
)
{
    gradUCalc_.calculate(phases_.U(), gradU_);
}


void Foam::reconstructions::firstOrder::faceState
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


void Foam::reconstructions::firstOrder::describe(Ostream& os) const
{
    os  << "first order, face velocity reconstruction with velocity limiter "
        << (gradUCalc_.limited() ? "cellLimited" : "none");
}
