#include "mechanicalRelaxation.H"
#include "alphaClosure.H"
#include "foamEigen.H"

using Foam::foamEigen::toTensor;


Foam::mechanicalRelaxation::mechanicalRelaxation(phaseSystem& phases)
:
    phases_(phases),
    nPhases_(phases.size()),
    m_(nPhases_),
    v0_(nPhases_),
    eh0_(nPhases_),
    alpha_(nPhases_),
    trace_(nPhases_)
{}


bool Foam::mechanicalRelaxation::interfacePressure
(
    const scalar volume,
    scalar& p
) const
{
    // F(p) = sum m_k v_k(p) - volume decreases from +inf at the largest
    // pMin (every active phase is admissible there) to
    // sum alpha_k (gamma-1)/gamma - volume < 0: one root
    scalar lo = -GREAT;
    scalar pScale = 0;
    scalar pGuess = 0, wGuess = 0;
    for (label k = 0; k < nPhases_; ++k)
    {
        if (trace_[k]) continue;
        const equationOfState& eos = phases_.phase(k).eos();
        const scalar pk = eos.p(1/v0_[k], eh0_[k]);
        lo = max(lo, eos.pMin());
        pScale = max(pScale, eos.pScale(pk));
        pGuess += alpha_[k]*pk;
        wGuess += alpha_[k];
    }
    scalar hi = GREAT;

    const auto F = [&](const scalar pp, scalar& dF)
    {
        scalar f = -volume;
        dF = 0;
        for (label k = 0; k < nPhases_; ++k)
        {
            if (trace_[k]) continue;
            const equationOfState& eos = phases_.phase(k).eos();
            f += m_[k]*eos.vRelaxed(pp, 1/v0_[k], eh0_[k]);
            dF += m_[k]*eos.dvRelaxeddp(pp, 1/v0_[k], eh0_[k]);
        }
        return f;
    };

    p = pGuess/wGuess;
    if (!(p > lo)) p = lo + 1e-6*max(pScale, scalar(1));

    for (int iter = 0; iter < 300; ++iter)
    {
        scalar dF;
        const scalar f = F(p, dF);
        if (f == 0)
        {
            return true;
        }
        if (f > 0) lo = p; else hi = p;

        scalar pNew = p - f/dF;
        if (!(pNew > lo && pNew < hi))
        {
            // Bisect, or expand when no upper bound is known yet
            pNew =
                (hi < GREAT)
              ? 0.5*(lo + hi)
              : p + 2*max(mag(p - lo), scalar(1));
        }
        if (mag(pNew - p) <= 1e-15*(mag(pNew) + pScale))
        {
            p = pNew;
            return true;
        }
        p = pNew;
    }
    return false;
}


Foam::mechanicalRelaxation::stateError Foam::mechanicalRelaxation::correct
(
    demSolver::conservedState& q,
    const scalar dt
)
{
    stateError err;
    const auto fail = [&err](label c, label k, const char* what, scalar v)
    {
        if (!err.failed)
        {
            err.failed = true;
            err.cell = c;
            err.phase = k;
            err.quantity = what;
            err.value = v;
        }
    };

    const label nCells = phases_.mesh().nCells();
    const scalar alphaMin = phases_.alphaMin();
    const scalar alphaTrace = phases_.alphaTrace();
    vectorField& Ufield = phases_.U().primitiveFieldRef();

    for (label c = 0; c < nCells; ++c)
    {
        // 1. Floor of alpha, sum closed by the largest phase; compatibility
        //    of A
        for (label k = 0; k < nPhases_; ++k)
        {
            if (!(q.alpha[k][c] > -1e-3))
            {
                fail(c, k, "alpha", q.alpha[k][c]);
            }
        }
        const label main = floorAndClose
        (
            nPhases_,
            alphaMin,
            [&](const label k) -> scalar& { return q.alpha[k][c]; }
        );

        cobasis::vector mom(cobasis::vector::Zero());
        scalar mass = 0;
        for (label k = 0; k < nPhases_; ++k)
        {
            alpha_[k] = q.alpha[k][c];
            trace_[k] = alpha_[k] < alphaTrace;

            if (!(q.mass[k][c] > 0))
            {
                // Minor after the step, or before it (by its mass fraction)
                scalar oldMix = 0;
                for (label j = 0; j < nPhases_; ++j)
                {
                    oldMix += phases_.alpha(j)[c]*phases_.rho(j)[c];
                }
                const bool minor =
                    alpha_[k] < phases_.alphaMinor()
                 || phases_.alpha(k)[c]*phases_.rho(k)[c]
                  < phases_.massFractionMinor()*oldMix;
                if (!minor)
                {
                    fail(c, k, "mass", q.mass[k][c]);
                }
                // A minor phase that lost all its mass keeps its last
                // density (the mass this adds is below alphaMinor rho, or
                // massFractionMinor of the cell's mass)
                q.mass[k][c] = alpha_[k]*phases_.rho(k)[c];
            }
            m_[k] = q.mass[k][c];
            mass += m_[k];
            mom += q.momentum[k][c];
        }

        // 2. Velocity relaxation
        const cobasis::vector u(mom/mass);

        for (label k = 0; k < nPhases_; ++k)
        {
            const hyperelasticPhase& ph = phases_.phase(k);
            v0_[k] = alpha_[k]/m_[k];
            cobasis::matrix& A = q.A[k][c];
            if (ph.solid())
            {
                const scalar detA = A.determinant();
                if (!(detA > 0))
                {
                    if (!trace_[k]) fail(c, k, "det(A)", detA);
                    A = cobasis::unstrained(1/v0_[k], ph.rho0());
                }
                else
                {
                    A *= std::cbrt(1/(v0_[k]*ph.rho0()*detA));
                }
            }
            // Own kinetic energy out, the share of the dissipated kinetic
            // energy 1/2 |u_k - u|^2 in: e_k never decreases
            const cobasis::vector uk(q.momentum[k][c]/m_[k]);
            eh0_[k] =
                q.energy[k][c]/m_[k] - 0.5*uk.squaredNorm()
              + 0.5*(uk - u).squaredNorm() - ph.elasticEnergy(A);
        }

        // A minor phase whose energy the step left inadmissible (a gas
        // with e <= 0, say) is reset as a trace; any other phase fails
        for (label k = 0; k < nPhases_; ++k)
        {
            if (trace_[k]) continue;
            const equationOfState& eos = phases_.phase(k).eos();
            const scalar pk = eos.p(1/v0_[k], eh0_[k]);
            if (!(pk > eos.pMin()))
            {
                if
                (
                    alpha_[k] < phases_.alphaMinor()
                 || m_[k] < phases_.massFractionMinor()*mass
                )
                {
                    trace_[k] = true;
                }
                else
                {
                    fail(c, k, "p", pk);
                }
            }
        }
        if (err.failed && err.cell == c)
        {
            continue;
        }

        // 3. Pressure relaxation among the phases that are not traces
        label nActive = 0;
        scalar traceVolume = 0;
        for (label k = 0; k < nPhases_; ++k)
        {
            if (trace_[k]) traceVolume += alpha_[k];
            else ++nActive;
        }

        scalar pStar;
        if (nActive > 1)
        {
            if (!interfacePressure(1 - traceVolume, pStar))
            {
                fail(c, main, "interface pressure (no convergence)", pStar);
                continue;
            }

            scalar sumActive = 0;
            for (label k = 0; k < nPhases_; ++k)
            {
                if (trace_[k]) continue;
                alpha_[k] = m_[k]*phases_.phase(k).eos().vRelaxed
                (
                    pStar, 1/v0_[k], eh0_[k]
                );
                sumActive += alpha_[k];
            }
            for (label k = 0; k < nPhases_; ++k)
            {
                if (trace_[k]) continue;
                alpha_[k] *= (1 - traceVolume)/sumActive;
                const scalar v = alpha_[k]/m_[k];
                eh0_[k] -= pStar*(v - v0_[k]);
                if (phases_.phase(k).solid())
                {
                    q.A[k][c] *= std::cbrt(v0_[k]/v);
                }
                v0_[k] = v;
            }
        }
        else
        {
            pStar = phases_.phase(main).eos().p(1/v0_[main], eh0_[main]);
        }

        // 4. Traces follow the cell: pressure p*, unstrained cobasis
        for (label k = 0; k < nPhases_; ++k)
        {
            if (!trace_[k]) continue;
            const hyperelasticPhase& ph = phases_.phase(k);
            const scalar rho = 1/v0_[k];
            scalar pk = max(pStar, ph.eos().pMin() + 1);
            const scalar eeOld = ph.elasticEnergy(q.A[k][c]);
            if (ph.solid())
            {
                q.A[k][c] = cobasis::unstrained(rho, ph.rho0());
            }
            const scalar eNew = ph.eos().e(rho, pk);
            eh0_[main] -= m_[k]*(eNew - eh0_[k] - eeOld)/m_[main];
            eh0_[k] = eNew;
        }

        // 5. Plastic relaxation, 6. checks, store
        Ufield[c] = vector(u(0), u(1), u(2));
        for (label k = 0; k < nPhases_; ++k)
        {
            const hyperelasticPhase& ph = phases_.phase(k);
            cobasis::matrix& A = q.A[k][c];

            if (ph.solid() && !trace_[k])
            {
                const scalar heat = phases_.plastic(k).correct
                (
                    A, phases_.epsilonP(k)[c], ph.elastic(), dt
                );
                eh0_[k] += heat;
                phases_.plasticWork(k)[c] += heat;
            }

            const scalar rho = 1/v0_[k];
            const scalar p = ph.eos().p(rho, eh0_[k]);

            if (!trace_[k])
            {
                if (!(rho > 0)) fail(c, k, "rho", rho);
                if (!(p > ph.eos().pMin())) fail(c, k, "p", p);
                if (!(alpha_[k] <= 1)) fail(c, k, "alpha", alpha_[k]);
                if (ph.solid() && !(A.determinant() > 0))
                {
                    fail(c, k, "det(A)", A.determinant());
                }
            }

            phases_.alpha(k)[c] = alpha_[k];
            phases_.rho(k)[c] = rho;
            phases_.p(k)[c] = p;
            phases_.A(k)[c] = toTensor(A);
        }
    }

    return err;
}
