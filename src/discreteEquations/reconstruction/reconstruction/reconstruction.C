#include "reconstruction.H"
#include "foamEigen.H"
#include "readOption.H"

using Foam::foamEigen::toEigen;

namespace Foam
{
    defineTypeNameAndDebug(reconstruction, 0);
    defineRunTimeSelectionTable(reconstruction, dictionary);
}


// * * * * * * * * * * * * * * * Static Data  * * * * * * * * * * * * * * * //

const Foam::Enum<Foam::reconstruction::limiter>
Foam::reconstruction::limiterNames
({
    {limiter::cellLimited, "cellLimited"},
    {limiter::none, "none"}
});


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
    phaseU_(phases.size()),
    phaseGradU_(phases.size()),
    firstOrderCells_(nullptr)
{
    forAll(phaseU_, k)
    {
        if (phases[k].carriesSlip())
        {
            phaseU_.set
            (
                k,
                new volVectorField
                (
                    IOobject
                    (
                        "U." + phases.phase(k).name() + ".own",
                        mesh_.time().timeName(),
                        mesh_,
                        IOobject::NO_READ,
                        IOobject::NO_WRITE,
                        false
                    ),
                    phases.U()
                )
            );
            phaseGradU_[k].setSize(mesh_.nCells(), Zero);
        }
    }
}


Foam::wordList Foam::reconstruction::keywords() const
{
    return {"order", "reconstruction", "velocityLimiter"};
}


// * * * * * * * * * * * * * Protected Member Functions  * * * * * * * * * * //

bool Foam::reconstruction::limitVelocity(const dictionary& dict)
{
    return
        readOption
        (
            dict, "velocityLimiter", limiterNames, limiter::cellLimited,
            "discreteEquations"
        )
     == limiter::cellLimited;
}


void Foam::reconstruction::completeSide(const label k, phaseSide& s) const
{
    const hyperelasticPhase& ph = phases_.phase(k);
    s.solid = ph.solid();
    s.trace = phases_.regimes().trace(s.alpha);
    s.cT = std::sqrt(ph.cT2());
    double e;
    ph.sigmaAndE(s.rho, s.p, s.A, s.sigma, e);
    s.E = e + 0.5*s.U.squaredNorm();
}


void Foam::reconstruction::cellSide
(
    const label k,
    const label celli,
    const cobasis::vector& U,
    phaseSide& s
) const
{
    const hyperelasticPhase& ph = phases_.phase(k);
    s.rho = phases_.rho(k)[celli];
    s.p = phases_.p(k)[celli];
    s.U = U;
    s.A = cobasisOrIdentity(k, celli);
    cellCarried(k, celli, s);
    if (ph.solid())
    {
        s.sigma = cells_.sigma(k, celli);
    }
    else
    {
        s.sigma = -s.p*cobasis::matrix::Identity();
    }
    if (phases_[k].carriesSlip())
    {
        // The phase's own velocity where solids slide (phaseModel::slip)
        const cobasis::vector w(toEigen(phases_[k].slip(celli)));
        s.U += w;
        s.E =
            cells_.E(k, celli)
          + 0.5
           *(
                s.U.squaredNorm()
              - (toEigen(phases_.U()[celli]) + w).squaredNorm()
            );
    }
    else
    {
        s.E =
            cells_.E(k, celli)
          + 0.5*(U.squaredNorm() - magSqr(phases_.U()[celli]));
    }
    s.a = cells_.a(k, celli);
    s.cT = std::sqrt(ph.cT2());
    s.solid = ph.solid();
    s.trace = phases_.regimes().trace(s.alpha);
}


void Foam::reconstruction::velocityGradient()
{
    gradUCalc_.calculate(phases_.U(), gradU_);

    // Where solids may slide on each other (the band of slidingInterfaces)
    // the cell velocity jumps across the interface by the pair's slip:
    // the derivative of the tangential velocity along the interface's
    // normal is left out, or it would read the slip as shear and carry
    // one solid's velocity into the other's faces (each phase's own
    // velocity there is U + its slip, phaseModel::velocity)
    const slidingInterfaces* sliding = phases_.sliding();
    if (!sliding)
    {
        return;
    }
    forAll(gradU_, c)
    {
        if (sliding->inBand(c))
        {
            const vector& n = sliding->normal(c);
            const vector dUdn(n & gradU_[c]);
            gradU_[c] -= n*(dUdn - (dUdn & n)*n);
        }
    }

    // Each sliding phase's own velocity and, in the band's cells that hold
    // it, its gradient from the neighbours that hold it: the mixture's
    // velocity changes with the fractions across the band, and its
    // gradient, read with one phase's velocity, puts velocity jumps on the
    // faces between a phase's cells that its elastic waves answer with
    // shear tractions of the order of rho c dU
    const volVectorField& U = phases_.U();
    forAll(phaseU_, k)
    {
        if (!phaseU_.set(k))
        {
            continue;
        }
        const phaseModel& phase = phases_[k];
        const volScalarField& alpha = phases_.alpha(k);
        volVectorField& Uk = phaseU_[k];
        vectorField& uk = Uk.primitiveFieldRef();
        phaseCells_.clear();
        forAll(uk, c)
        {
            uk[c] = phase.velocity(U[c], c);
            if (sliding->inBand(c) && !phases_.regimes().thin(alpha[c]))
            {
                phaseCells_.append(c);
            }
        }
        Uk.correctBoundaryConditions();
        gradUCalc_.calculatePresent
        (
            Uk, alpha, phases_.regimes().alphaMinor(), phaseCells_,
            phaseGradU_[k]
        );
    }
}


void Foam::reconstruction::setSlideNormal
(
    const label c,
    std::vector<phaseSide>& s
) const
{
    const slidingInterfaces* sliding = phases_.sliding();
    const cobasis::vector n
    (
        sliding && sliding->holdsInterface(c)
      ? toEigen(sliding->normal(c))
      : cobasis::vector::Zero()
    );
    for (phaseSide& side : s)
    {
        side.nSlide = n;
    }
}


void Foam::reconstruction::markMinor(std::vector<phaseSide>& s) const
{
    double rhoMix = 0;
    for (label k = 0; k < nPhases_; ++k)
    {
        rhoMix += s[k].alpha*s[k].rho;
    }
    for (label k = 0; k < nPhases_; ++k)
    {
        s[k].minor =
            phases_.regimes().unresolved
            (
                k, s[k].alpha, s[k].alpha*s[k].rho, rhoMix
            );
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
    cobasis::vector U(toEigen(phases_.U()[celli]));
    U += toEigen(d & gradU_[celli]);
    cellSides(celli, U, s);

    // A sliding phase's own velocity gradient in the band
    for (label k = 0; k < nPhases_; ++k)
    {
        if (ownVelocityGradient(k, celli))
        {
            const double ke = s[k].U.squaredNorm();
            s[k].U += toEigen(d & (phaseGradU_[k][celli] - gradU_[celli]));
            s[k].E += 0.5*(s[k].U.squaredNorm() - ke);
        }
    }
}


void Foam::reconstruction::cellMeanState
(
    const label celli,
    std::vector<phaseSide>& s
) const
{
    cellSides(celli, toEigen(phases_.U()[celli]), s);
}


void Foam::reconstruction::cellSides
(
    const label celli,
    const cobasis::vector& U,
    std::vector<phaseSide>& s
) const
{
    for (label k = 0; k < nPhases_; ++k)
    {
        s[k].alpha = phases_.alpha(k)[celli];
        cellSide(k, celli, U, s[k]);
    }
    markMinor(s);
    setSlideNormal(celli, s);
}


// ************************************************************************* //
