/*---------------------------------------------------------------------------*\
  impactFoam: Eulerian multiphase elastic-plastic impact solver for OpenFOAM
-------------------------------------------------------------------------------
Description
    The velocity relaxation of a cell where two solids that may slide on
    each other meet (docs/numerics.md section 9.3a).

\*---------------------------------------------------------------------------*/

#include "mechanicalRelaxation.H"
#include "foamEigen.H"

using Foam::foamEigen::toEigen;

bool Foam::mechanicalRelaxation::slideVelocities
(
    const label c,
    const conservedState& q,
    const cobasis::vector& u,
    const scalar dt
)
{
    const slidingInterfaces* sliding = phases_.sliding();
    if (!sliding || !sliding->inBand(c))
    {
        return false;
    }
    const label a = sliding->k(c);
    const label b = sliding->j(c);
    if (cell_.trace[a] || cell_.trace[b] || !sliding->holdsInterface(c))
    {
        return false;
    }

    const cobasis::vector n(toEigen(sliding->normal(c)));
    const auto tangential = [&n](const cobasis::vector& v)
    {
        return (v - v.dot(n)*n).eval();
    };

    // The pair's tangential velocities after the step's Riemann problems
    const double mA = cell_.m[a];
    const double mB = cell_.m[b];
    const double mAB = mA + mB;
    const cobasis::vector tA(tangential(q.momentum[a][c]/mA));
    const cobasis::vector tB(tangential(q.momentum[b][c]/mB));

    // The pair's relative tangential velocity s, and the impulse per unit
    // volume that would stop it (welded); the law allows at most its
    // shear limit over the interface area in the cell, for dt
    const double reduced = mA*mB/mAB;
    const cobasis::vector s(tA - tB);
    const double jStick = reduced*s.norm();

    const contactLaw& law = sliding->law(c);
    double strength = GREAT;
    if (law.usesStrength())
    {
        for (const label k : {a, b})
        {
            scalar carried[phaseModel::maxCarried];
            phases_[k].inelasticState(c, carried);
            strength = min
            (
                strength,
                phases_[k].inelastic().shearStrength
                (
                    carried, phases_.rho(k)[c], phases_.p(k)[c]
                )
            );
        }
    }
    // The normal stress across the interface: the pair's pressure at the
    // start of the step (their deviatoric normal stress left out)
    const scalar alphaA = phases_.alpha(a)[c];
    const scalar alphaB = phases_.alpha(b)[c];
    const double sigmaNN =
        -(alphaA*phases_.p(a)[c] + alphaB*phases_.p(b)[c])
       /max(alphaA + alphaB, SMALL);
    const double jMax =
        law.shearLimit(sigmaNN, strength)*sliding->area(c)*dt;
    const double keep = jStick > jMax ? 1 - jMax/jStick : 0;

    const cobasis::vector sNew(keep*s);
    // The other phases (fluids, traces) take the cell's tangential
    // velocity, and the pair's centre of mass with them: a gas next to a
    // vacuum keeps no velocity of its own
    const cobasis::vector tMean(tangential(u));
    const double un = u.dot(n);

    // Kinetic energy lost, shared as heat in proportion to m |du|^2 (the
    // share of each phase is its own where the relaxation is a projection,
    // and the total is exact: momentum and energy kept)
    double lost = 0;
    double weight = 0;
    for (label k = 0; k < nPhases_; ++k)
    {
        const cobasis::vector t
        (
            k == a ? (tMean + (mB/mAB)*sNew).eval()
          : k == b ? (tMean - (mA/mAB)*sNew).eval()
          : tMean
        );
        uSlide_[k] = un*n + t;
        const cobasis::vector uk(q.momentum[k][c]/cell_.m[k]);
        const double m = cell_.m[k];
        lost += 0.5*m*(uk.squaredNorm() - uSlide_[k].squaredNorm());
        slideHeat_[k] = 0.5*(uk - uSlide_[k]).squaredNorm();
        weight += m*slideHeat_[k];
    }
    const double share = weight > 0 ? lost/weight : 0;
    for (label k = 0; k < nPhases_; ++k)
    {
        slideHeat_[k] *= share;
    }

    // The heat of friction: what the pair's relative sliding lost
    ledger_.countFriction(c, 0.5*reduced*(s.squaredNorm() - sNew.squaredNorm()));

    return true;
}


// ************************************************************************* //
