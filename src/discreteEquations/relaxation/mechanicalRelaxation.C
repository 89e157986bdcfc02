#include "mechanicalRelaxation.H"

namespace
{

typedef Eigen::Matrix<double, 3, 3, Eigen::RowMajor> rowMatrix;

inline Foam::tensor toTensor(const Foam::cobasis::matrix& M)
{
    Foam::tensor T;
    Eigen::Map<rowMatrix>(T.v_) = M;
    return T;
}

} // End anonymous namespace


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


Foam::scalar Foam::mechanicalRelaxation::interfacePressure
(
    const label celli,
    const scalar volume
) const
{
    // F(p) = sum m_k v_k(p) - volume decreases from +inf at the largest
    // pMin to sum alpha_k (gamma-1)/gamma - volume < 0
    scalar lo = -GREAT;
    scalar pGuess = 0, wGuess = 0;
    for (label k = 0; k < nPhases_; ++k)
    {
        if (trace_[k]) continue;
        const equationOfState& eos = phases_.phase(k).eos();
        lo = max(lo, eos.pMin());
        pGuess += alpha_[k]*eos.p(1/v0_[k], eh0_[k]);
        wGuess += alpha_[k];
    }
    scalar hi = GREAT;

    const auto F = [&](const scalar p, scalar& dF)
    {
        scalar f = -volume;
        dF = 0;
        for (label k = 0; k < nPhases_; ++k)
        {
            if (trace_[k]) continue;
            const equationOfState& eos = phases_.phase(k).eos();
            f += m_[k]*eos.vRelaxed(p, 1/v0_[k], eh0_[k]);
            dF += m_[k]*eos.dvRelaxeddp(p, 1/v0_[k], eh0_[k]);
        }
        return f;
    };

    scalar p = pGuess/wGuess;
    if (!(p > lo)) p = lo + max(mag(lo), scalar(1))*1e-3;

    for (int iter = 0; iter < 200; ++iter)
    {
        scalar dF;
        const scalar f = F(p, dF);
        if (f > 0) lo = p; else hi = p;

        scalar pNew = p - f/dF;
        if (!(pNew > lo && pNew < hi))
        {
            // Bisect, or expand when no upper bound is known yet
            pNew = (hi < GREAT) ? 0.5*(lo + hi) : p + 2*max(mag(p - lo), scalar(1));
        }
        if (mag(pNew - p) <= 1e-15*(mag(pNew) + mag(lo)) || f == 0)
        {
            return pNew;
        }
        p = pNew;
    }

    FatalErrorInFunction
        << "Pressure relaxation did not converge in cell " << celli
        << " (bracket " << lo << " " << hi << ")" << exit(FatalError);
    return p;
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
        // 1. Floor and normalisation of alpha; compatibility of A
        scalar sumAlpha = 0;
        label main = 0;
        for (label k = 0; k < nPhases_; ++k)
        {
            scalar& a = q.alpha[k][c];
            if (!(a >= alphaMin))
            {
                if (!(a > -1e-3))
                {
                    fail(c, k, "alpha", a);
                }
                a = alphaMin;
            }
            sumAlpha += a;
            if (a > q.alpha[main][c]) main = k;
        }

        cobasis::vector mom(cobasis::vector::Zero());
        scalar mass = 0;
        for (label k = 0; k < nPhases_; ++k)
        {
            q.alpha[k][c] /= sumAlpha;
            alpha_[k] = q.alpha[k][c];
            trace_[k] = alpha_[k] < alphaTrace;

            if (!(q.mass[k][c] > 0))
            {
                if (!trace_[k])
                {
                    fail(c, k, "mass", q.mass[k][c]);
                }
                // A trace that lost all its mass keeps its last density
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
            pStar = interfacePressure(c, 1 - traceVolume);

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
            if (ph.solid())
            {
                q.A[k][c] = cobasis::unstrained(rho, ph.rho0());
            }
            const scalar eNew = ph.eos().e(rho, pk);
            eh0_[main] -= m_[k]*(eNew - eh0_[k])/m_[main];
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
                eh0_[k] += phases_.plastic(k).correct
                (
                    A, phases_.epsilonP(k)[c], ph.elastic(), dt
                );
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
