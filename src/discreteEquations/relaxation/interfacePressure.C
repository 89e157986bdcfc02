/*---------------------------------------------------------------------------*\
  impactFoam: Eulerian multiphase elastic-plastic impact solver for OpenFOAM
\*---------------------------------------------------------------------------*/

#include "interfacePressure.H"
#include "interfaceRoot.H"

#include <cmath>

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
    // In tension a metal expands no further than its lowest density (half
    // its reference density, mechanicalRelaxation::compactMetals), or its
    // volume at p = 0 where that is larger (a hot metal): it takes no more
    // volume and no more work from a tension of the cell. A phase already
    // beyond it (the cell's largest, which compactMetals leaves alone, or
    // one it brings back over several steps) is not compressed to it. At
    // or below the lowest pressure of its path (where v grows without
    // bound) it is at the cap
    //
    // The phase's own path, unless it needs a payer it has not got (then
    // the constant-pressure one); constantPressure's v is eos.vRelaxed
    const pressureRelaxationPath& path = phases_.relaxationPath(k);
    const scalar rho = 1/cell.v[k];
    const scalar vMax = max(cell.vMax[k], cell.v[k]);
    const bool capped = vMax < VGREAT && cell.pLowest[k] < 0;
    const scalar v =
        capped && !(pStar > cell.pLowest[k])
      ? VGREAT
      : path.needsPayer()
      ? eos.vRelaxed(pStar, rho, cell.e[k], dvdp)
      : path.v(pStar, rho, cell.e[k], dvdp);
    if (capped && pStar < 0 && v > vMax)
    {
        scalar dv0;
        const scalar vCap = max(vMax, eos.vRelaxed(0, rho, cell.e[k], dv0));
        if (v > vCap)
        {
            dvdp = 0;
            return vCap;
        }
    }
    return v;
}

bool Foam::interfacePressure::solve
(
    relaxationCell& cell,
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
        // A phase outside its equation of state's range has no path (its
        // primitives give NaN, and comparing a NaN traps under
        // FOAM_SIGFPE): no root, the check fails
        const scalar rhoK = 1/cell.v[k];
        if (!(rhoK > 0 && rhoK < eos.rhoMax()))
        {
            return false;
        }
        const scalar pk = eos.p(rhoK, cell.e[k]);
        if (!std::isfinite(pk))
        {
            return false;
        }
        const pressureRelaxationPath& path = phases_.relaxationPath(k);
        const scalar pPath =
            cell.isentropic[k]
          ? path.pLowest(1/cell.v[k], cell.e[k])
          : eos.pRelaxedMin(1/cell.v[k], cell.e[k]);
        cell.pLowest[k] = pPath;
        const bool held =
            (cell.isentropic[k] && path.cavitationPressure() > pPath)
         || (cell.held[k] && cell.pHeld[k] > pPath)
         || (cell.vMax[k] < VGREAT && pPath < 0);
        if (!held)
        {
            // v_k(p) grows without bound as p -> pPath
            lo = max(lo, pPath);
        }
        pScale = max(pScale, eos.pScale(1/cell.v[k], pk));
        pGuess += cell.alpha[k]*pk;
        wGuess += cell.alpha[k];
    }
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

    p = wGuess > 0 ? pGuess/wGuess : lo;
    return interfaceRoot(F, lo, pScale, 1e-12*volume, p);
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
            // (a path that needs no payer ends at the constant-pressure
            // energy: pressureRelaxationPath::needsPayer)
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
