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
    if (cell_.trace[a] || cell_.trace[b])
    {
        return false;
    }

    const cobasis::vector n(toEigen(sliding->normal(c)));
    const auto tangential = [&n](const cobasis::vector& v)
    {
        return (v - v.dot(n)*n).eval();
    };

    // The phases' velocities after the step; the common tangential
    // velocity of the phases other than the pair
    const double mA = cell_.m[a];
    const double mB = cell_.m[b];
    const double mAB = mA + mB;
    double mOther = 0;
    for (label k = 0; k < nPhases_; ++k)
    {
        if (k != a && k != b)
        {
            mOther += cell_.m[k];
        }
    }

    // The tangential momentum the pair's contact tractions gave each of
    // the two, shared in proportion to their masses: a face sees the
    // interface along its own normal, and the split of a contact's
    // pressure between the phases of the receiving cell (by the sign of
    // u*) has a tangential part where the interface is oblique to the
    // faces (at 45 degrees, 0.6 p of spurious shear). The law's own
    // tangential exchange follows below
    cobasis::vector pA(q.momentum[a][c]);
    cobasis::vector pB(q.momentum[b][c]);
    if (!q.contactMomentum.empty())
    {
        const cobasis::vector xA(tangential(q.contactMomentum[a][c]));
        const cobasis::vector xB(tangential(q.contactMomentum[b][c]));
        const cobasis::vector shift(xA - (mA/mAB)*(xA + xB));
        pA -= shift;
        pB += shift;
    }
    const cobasis::vector tA(tangential(pA/mA));
    const cobasis::vector tB(tangential(pB/mB));

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

    cobasis::vector sNew(keep*s);
    // The other phases (fluids, traces) take the cell's tangential
    // velocity, and the pair's centre of mass with them: a gas next to a
    // vacuum keeps no velocity of its own
    const cobasis::vector tMean(tangential(u));
    const double un = u.dot(n);

    // The kinetic energy after the step's Riemann problems: the relaxation
    // gives out no more than that (taking the contact tractions' tangential
    // part off the pair can leave it with more relative motion than the
    // step paid for; the slip is then cut to what was paid)
    double keBefore = 0;
    for (label k = 0; k < nPhases_; ++k)
    {
        keBefore += 0.5*q.momentum[k][c].squaredNorm()/cell_.m[k];
    }
    const double keSlip = 0.5*reduced*sNew.squaredNorm();
    const double keRest = 0.5*(mAB + mOther)*u.squaredNorm();
    if (keRest + keSlip > keBefore && keSlip > 0)
    {
        sNew *= std::sqrt(max(keBefore - keRest, 0.0)/keSlip);
    }

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
