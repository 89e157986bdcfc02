/*---------------------------------------------------------------------------*\
  impactFoam: Eulerian multiphase elastic-plastic impact solver for OpenFOAM
\*---------------------------------------------------------------------------*/

#include "interfacePressure.H"

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::interfacePressure::interfacePressure(const phaseSystem& phases)
:
    phases_(phases)
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::scalar Foam::interfacePressure::relaxedVolume
(
    const relaxationCell& cell,
    const label k,
    const scalar pStar,
    scalar& dvdp
) const
{
    const equationOfState& eos = phases_.phase(k).eos();
    if (cell.isentropic[k])
    {
        // Along its own path (an isentrope, held at the cavitation
        // pressure below it)
        return phases_.relaxationPath(k).v
        (
            pStar, 1/cell.v[k], cell.e[k], dvdp
        );
    }
    if (cell.pinned[k])
    {
        // Failing material in tension keeps its own state, down to its
        // floor: it does not relax toward the fluids of the cell
        dvdp = 0;
        return
            eos.p(1/cell.v[k], cell.e[k]) > cell.pHeld[k]
          ? cell.v[k]
          : eos.vRelaxed(cell.pHeld[k], 1/cell.v[k], cell.e[k]);
    }
    if (cell.held[k] && pStar < cell.pHeld[k])
    {
        // Damaged material holds no tension below its floor
        dvdp = 0;
        return eos.vRelaxed(cell.pHeld[k], 1/cell.v[k], cell.e[k]);
    }
    return eos.vRelaxed(pStar, 1/cell.v[k], cell.e[k], dvdp);
}

bool Foam::interfacePressure::solve
(
    const relaxationCell& cell,
    const scalar volume,
    scalar& p
) const
{
    // F(p) = sum m_k v_k(p) - volume decreases from +inf at the largest
    // of the lowest pressures the phases' paths reach (every active phase
    // is admissible there) to sum alpha_k (gamma-1)/gamma - volume < 0
    // (stiffened gases): one root
    scalar lo = -GREAT;
    scalar pScale = 0;
    scalar pGuess = 0, wGuess = 0;
    for (label k = 0; k < cell.size(); ++k)
    {
        if (cell.trace[k]) continue;
        const equationOfState& eos = phases_.phase(k).eos();
        const scalar pk = eos.p(1/cell.v[k], cell.e[k]);
        const pressureRelaxationPath& path = phases_.relaxationPath(k);
        const scalar pPath =
            cell.isentropic[k]
          ? path.pLowest(1/cell.v[k], cell.e[k])
          : eos.pRelaxedMin(1/cell.v[k], cell.e[k]);
        const bool held =
            (cell.isentropic[k] && path.cavitationPressure() > pPath)
         || (cell.held[k] && cell.pHeld[k] > pPath);
        if (!held)
        {
            // v_k(p) grows without bound as p -> pPath
            lo = max(lo, pPath);
        }
        pScale = max(pScale, eos.pScale(1/cell.v[k], pk));
        pGuess += cell.alpha[k]*pk;
        wGuess += cell.alpha[k];
    }
    scalar hi = GREAT;

    const auto F = [&](const scalar pp, scalar& dF)
    {
        scalar f = -volume;
        dF = 0;
        for (label k = 0; k < cell.size(); ++k)
        {
            if (cell.trace[k]) continue;
            scalar dvdp;
            f += cell.m[k]*relaxedVolume(cell, k, pp, dvdp);
            dF += cell.m[k]*dvdp;
        }
        return f;
    };

    p = pGuess/wGuess;
    if (!(p > lo)) p = lo + 1e-6*max(pScale, scalar(1));

    // Newton steps that do not shrink (a zigzag about the kink of a fluid
    // held at its cavitation pressure) give way to bisection
    scalar stepOld = GREAT;
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
        const bool stalled = mag(pNew - p) > 0.5*stepOld && hi < GREAT;
        stepOld = mag(pNew - p);
        if (!(pNew > lo && pNew < hi) || stalled)
        {
            // Bisect, or expand when no upper bound is known yet
            pNew =
                (hi < GREAT)
              ? 0.5*(lo + hi)
              : p + 2*max(mag(p - lo), scalar(1));
        }
        // Converged in p, and in the volume unless p is resolved to
        // round-off: a nearly empty gas next to failed or cavitating
        // material takes its volume at p* near 0, where a pressure
        // tolerance relative to the metal's scale would leave the volume
        // wrong by percent (and the closing of the volumes would hand
        // that to the metal as a tension of GPa)
        if
        (
            mag(pNew - p) <= 1e-15*(mag(pNew) + pScale)
         && (mag(f) <= 1e-12*volume || mag(pNew - p) <= 1e-15*mag(pNew))
        )
        {
            p = pNew;
            return true;
        }
        p = pNew;
    }
    return false;
}

bool Foam::interfacePressure::relax
(
    relaxationCell& cell,
    conservedState& q,
    const label c,
    scalar& pStar
) const
{
    // Fluids on their isentrope, when a phase on the default path
    // (the heaviest such, the payer) takes the energy difference and
    // outweighs them
    label payer = -1;
    for (label k = 0; k < cell.size(); ++k)
    {
        if
        (
            !cell.trace[k] && !phases_.relaxationPath(k).needsPayer()
         && (payer < 0 || cell.m[k] > cell.m[payer])
        )
        {
            payer = k;
        }
    }
    // The payer must outweigh the fluids it pays for: where the fluid is
    // the heavier (air with a few metal fragments) the energy difference
    // would overheat or freeze the light payer, and the default path is
    // used
    scalar mIsentropic = 0;
    for (label k = 0; k < cell.size(); ++k)
    {
        if (!cell.trace[k] && phases_.relaxationPath(k).needsPayer())
        {
            mIsentropic += cell.m[k];
        }
    }
    const bool useIsentropes = payer >= 0 && cell.m[payer] > mIsentropic;
    for (label k = 0; k < cell.size(); ++k)
    {
        cell.isentropic[k] =
            useIsentropes && !cell.trace[k]
         && phases_.relaxationPath(k).needsPayer();
    }

    if (!solve(cell, 1 - cell.traceVolume, pStar))
    {
        return false;
    }

    scalar sumActive = 0;
    for (label k = 0; k < cell.size(); ++k)
    {
        if (cell.trace[k]) continue;
        scalar dvdp;
        cell.alpha[k] = cell.m[k]*relaxedVolume(cell, k, pStar, dvdp);
        sumActive += cell.alpha[k];
    }
    scalar toPayer = 0;
    for (label k = 0; k < cell.size(); ++k)
    {
        if (cell.trace[k]) continue;
        cell.alpha[k] *= (1 - cell.traceVolume)/sumActive;
        const scalar v = cell.alpha[k]/cell.m[k];
        const scalar eConstantP = cell.e[k] - pStar*(v - cell.v[k]);
        if (cell.isentropic[k])
        {
            cell.e[k] = phases_.relaxationPath(k).e(v, pStar, eConstantP);
            toPayer += cell.m[k]*(eConstantP - cell.e[k]);
        }
        else
        {
            cell.e[k] = eConstantP;
        }
        if (phases_.phase(k).solid())
        {
            q.A[k][c] *= std::cbrt(cell.v[k]/v);
        }
        cell.v[k] = v;
    }
    if (payer >= 0)
    {
        cell.e[payer] += toPayer/cell.m[payer];
    }
    return true;
}


// ************************************************************************* //
