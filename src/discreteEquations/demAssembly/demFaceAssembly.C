#include "demFaceAssembly.H"
#include "faceFrame.H"
#include "contactFractions.H"
#include "primitiveEntry.H"

// * * * * * * * * * * * * * Static Member Functions * * * * * * * * * * * //

Foam::dictionary Foam::demFaceAssembly::fallbackDict()
{
    dictionary dict;
    dict.add("riemannSolver", word("HLL"));
    return dict;
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::demFaceAssembly::demFaceAssembly
(
    const phaseSystem& phases,
    const dictionary& dict
)
:
    phases_(phases),
    nPhases_(phases.size()),
    contacts_(phases.contacts()),
    frictionless_(contactLaw::New(primitiveEntry("frictionless", word("frictionless")), "demFaceAssembly")),
    riemann_(riemannSolver::New(dict)),
    fallbackRiemann_(riemannSolver::New(fallbackDict())),
    sums_(nPhases_),
    stride_(nPhases_),
    faceResult_(nPhases_),
    alphaScratch_(nPhases_),
    nCentres_(0),
    stamp_(0)
{
    const label nCells = phases.mesh().nCells();
    tensionLimit_.resize(nPhases_);
    for (label k = 0; k < nPhases_; ++k)
    {
        const inelasticModel& inelastic = phases[k].inelastic();
        tensionLimit_[k] =
            inelastic.limitsTension() ? &inelastic : nullptr;
        stride_[k] = iCarried + phases[k].nCarried();
        sums_[k].resize(nCells*stride_[k]);
    }
}


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

void Foam::demFaceAssembly::limitFailedTension
(
    const label k,
    const phaseSide& sl,
    const phaseSide& sr,
    riemannSolution& sol
) const
{
    const inelasticModel* inelastic = tensionLimit_[k];
    if (!inelastic)
    {
        return;
    }
    const double floor = max
    (
        inelastic->pFloor(sl.carried),
        inelastic->pFloor(sr.carried)
    );
    if (floor > -GREAT)
    {
        floorTension(floor, sol);
    }
}


void Foam::demFaceAssembly::floorTension
(
    const double pFloor,
    riemannSolution& sol
)
{
    // Normal traction t*_n = -p* in the face frame
    const double excess = pFloor + sol.tStar(0);
    if (excess > 0)
    {
        sol.tStar(0) -= excess;
        sol.momentumFlux(0) += excess;
        sol.energyFlux += excess*sol.uStar;
    }
}


void Foam::demFaceAssembly::slideApart
(
    const phaseSide& sl,
    const phaseSide& sr,
    const cobasis::matrix& R,
    riemannState& L,
    riemannState& R2,
    cobasis::vector& dL,
    cobasis::vector& dR
)
{
    // The interface's normal: the sides' band normals, of one sense
    cobasis::vector ni(sl.nSlide);
    ni += (ni.dot(sr.nSlide) < 0 ? -1.0 : 1.0)*sr.nSlide;
    const double magNi = ni.norm();
    if (!(magNi > 0))
    {
        return;
    }
    ni /= magNi;

    // Each side's velocity less its part of the relative motion along
    // the interface, in the face frame: both then share the mean tangential
    // velocity
    const cobasis::vector niF(R*ni);
    const cobasis::vector mean(0.5*(L.v + R2.v));
    const auto along = [&niF](const cobasis::vector& v)
    {
        return (v - v.dot(niF)*niF).eval();
    };
    dL = along(L.v - mean);
    dR = along(R2.v - mean);
    const double keL = L.v.squaredNorm();
    const double keR = R2.v.squaredNorm();
    L.v -= dL;
    R2.v -= dR;
    L.E += 0.5*(L.v.squaredNorm() - keL);
    R2.E += 0.5*(R2.v.squaredNorm() - keR);

    // Each side's traction less the part of its stress that is shear on
    // the interface's plane, tau (n_i (x) t + t (x) n_i) with tau t =
    // P sigma n_i: across a face oblique to the interface that shear would
    // reach the other solid as normal traction on the face (at 45 degrees
    // it is all normal traction), welding the two wherever the relaxation
    // lets them slide
    const cobasis::vector nF(R.row(0).transpose());
    const auto interfaceShear = [&](const phaseSide& side)
    {
        const cobasis::vector sn(side.sigma*ni);
        const cobasis::vector tau(sn - sn.dot(ni)*ni);
        return (R*(ni*tau.dot(nF) + tau*ni.dot(nF))).eval();
    };
    L.s -= interfaceShear(sl);
    R2.s -= interfaceShear(sr);
}


void Foam::demFaceAssembly::slideBack
(
    const cobasis::vector& dL,
    const cobasis::vector& dR,
    riemannSolution& sol
)
{
    // Each side's star velocity takes its own sliding back, whole (the
    // part along the face's normal too: the cobasis and the traction's work
    // see the phase move along the interface, not into the face); the
    // upwind state's flux carries its sliding, its kinetic energy and the
    // traction's work on it
    const bool left = sol.uStar >= 0;
    const cobasis::vector& d = left ? dL : dR;
    const cobasis::vector& vUp = left ? sol.vStarL : sol.vStarR;
    sol.momentumFlux += sol.massFlux*d;
    sol.energyFlux +=
        sol.massFlux*(vUp.dot(d) + 0.5*d.squaredNorm()) - sol.tStar.dot(d);
    sol.vStarL += dL;
    sol.vStarR += dR;
}


double Foam::demFaceAssembly::shearStrength
(
    const label k,
    const phaseSide& s
) const
{
    return phases_[k].inelastic().shearStrength(s.carried, s.rho, s.p);
}


Foam::riemannState Foam::demFaceAssembly::faceFrameState
(
    const label k,
    const phaseSide& s,
    const cobasis::matrix& R,
    const cobasis::vector& n,
    const bool withG
) const
{
    riemannState K;
    K.rho = s.rho;
    K.v = R*s.U;
    K.s = R*(s.sigma*n);
    K.E = s.E;
    K.a = s.a;
    K.cT = s.cT;
    K.G =
        withG
      ? phases_.phase(k).eos().fundamentalDerivative(s.rho, s.p)
      : 0;
    K.strength = GREAT;
    K.solid = s.solid;
    return K;
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::demFaceAssembly::updateMesh()
{
    const label nCells = phases_.mesh().nCells();
    for (label k = 0; k < nPhases_; ++k)
    {
        sums_[k].resize(nCells*stride_[k]);
    }

    // The time-centred states' slots, allocated again by reset() (the
    // pool of states is kept)
    centreSlot_.clear();
    centreStamp_.clear();
    nCentres_ = 0;
}


void Foam::demFaceAssembly::reset()
{
    const label nCells = phases_.mesh().nCells();
    for (label k = 0; k < nPhases_; ++k)
    {
        std::fill(sums_[k].begin(), sums_[k].end(), 0.0);
    }

    // The time-centred cell states of the last step are stale
    // (allocated for the cells that hold an internal contact only)
    if (centreStamp_.empty())
    {
        centreSlot_.resize(nCells, -1);
        centreStamp_.resize(nCells, -1);
    }
    nCentres_ = 0;
    ++stamp_;
}


void Foam::demFaceAssembly::solveFace
(
    const std::vector<phaseSide>& sideL,
    const std::vector<phaseSide>& sideR,
    const cobasis::matrix& R,
    const bool fallback,
    const bool identical
)
{
    const riemannSolver& solver = fallback ? fallbackRiemann_() : riemann_();
    const bool withG = solver.usesFundamentalDerivative();

    for (label k = 0; k < nPhases_; ++k)
    {
        faceContribution& fc = faceResult_[k];
        fc.dAlpha[0] = fc.dAlpha[1] = 0;
        fc.dMass[0] = fc.dMass[1] = 0;
        fc.dMomentum[0].setZero();
        fc.dMomentum[1].setZero();
        fc.dEnergy[0] = fc.dEnergy[1] = 0;
        for (label i = 0; i < phases_[k].nCarried(); ++i)
        {
            fc.dMassCarried[0][i] = fc.dMassCarried[1][i] = 0;
        }
        fc.vStarSum.setZero();
        fc.vStarWeight = 0;
    }

    const auto alphaL = [&sideL](const int k) { return sideL[k].alpha; };
    const auto alphaR = [&sideR](const int k) { return sideR[k].alpha; };

    const cobasis::vector n(R.row(0).transpose());

    // Pairs between two minor states (alpha < alphaMinor) are carried with
    // the face's contact velocity after the other pairs are solved: their
    // own waves (a trace of hot gas has a sound speed of tens of km/s) are
    // not resolved by the time step, and solving them would empty the
    // minor phase faster than it holds mass
    minorPairs_.clear();
    double uFace = 0, wFace = 0;

    contactFractions::forAllPairs
    (
        nPhases_, alphaL, alphaR,
        [&](const int k, const int j, const double S)
        {
            const phaseSide& sl = sideL[k];
            const phaseSide& sr = sideR[j];

            if (sl.minor && sr.minor)
            {
                // Field by field: a brace-initialised temporary was
                // written in three stores and read back in one (a
                // store-forwarding stall: 9 % of solveFace's samples in a
                // perf profile of the bar sat on that copy)
                minorPairs_.emplace_back();
                minorPair& mp = minorPairs_.back();
                mp.k = k;
                mp.j = j;
                mp.S = S;
                return;
            }

            riemannSolution sol;
            const contactLaw* contact =
                k != j ? contacts_.law(k, j) : nullptr;
            if (identical)
            {
                // Equal states (then k == j): the consistent solution
                riemannState K;
                K.rho = sl.rho;
                K.v = R*sl.U;
                K.s = R*(sl.sigma*n);
                K.E = sl.E;
                sol.uStar = K.v(0);
                sol.tStar = K.s;
                sol.vStarL = K.v;
                sol.vStarR = K.v;
                riemannSolver::physicalFlux
                (
                    K, sol.massFlux, sol.momentumFlux, sol.energyFlux
                );
            }
            else if (k == j)
            {
                sol = solver.solve
                (
                    faceFrameState(k, sl, R, n, withG),
                    faceFrameState(j, sr, R, n, withG),
                    true
                );
                limitFailedTension(k, sl, sr, sol);
            }
            else
            {
                // Two different solids that may slide: their contact law
                // caps the shear traction, and they hold no tension
                riemannState stL(faceFrameState(k, sl, R, n, withG));
                riemannState stR(faceFrameState(j, sr, R, n, withG));
                if (contact && contact->usesStrength())
                {
                    stL.strength = shearStrength(k, sl);
                    stR.strength = shearStrength(j, sr);
                }
                // Where a side's cell holds the interface (slidingInterfaces
                // gave it a normal)
                // the velocity relaxation there applies the law's
                // friction; the face then transmits none, or the two would
                // add up. And the pair slides along the interface, not
                // along the face: their relative velocity along the
                // interface is taken out of the problem (across an oblique
                // face it would read as the two moving into or away from
                // each other) and given back to each side's star velocity
                const bool inCell =
                    contact
                 && (sl.nSlide.squaredNorm() > 0 || sr.nSlide.squaredNorm() > 0);
                cobasis::vector dL(cobasis::vector::Zero());
                cobasis::vector dR(cobasis::vector::Zero());
                if (inCell)
                {
                    slideApart(sl, sr, R, stL, stR, dL, dR);
                }
                sol = solver.solve
                (
                    stL, stR, false, inCell ? frictionless_.get() : contact
                );
                if (inCell)
                {
                    slideBack(dL, dR, sol);
                }
                if (contact)
                {
                    floorTension(0, sol);
                }
            }

            uFace += S*sol.uStar;
            wFace += S;

            const cobasis::vector vStarL(R.transpose()*sol.vStarL);
            const cobasis::vector vStarR(R.transpose()*sol.vStarR);
            const cobasis::vector tStar(R.transpose()*sol.tStar);

            // Conservative and Lagrangian parts of the upwind side, with
            // weight w; the flux is in the face frame
            const auto apply = [&]
            (
                const bool fromLeft,
                const double w,
                const double massFlux,
                const cobasis::vector& momentumFlux,
                const double energyFlux
            )
            {
                const int up = fromLeft ? k : j;
                const double Sw = w*S;

                // Conservative part, for the upwind phase
                faceResult_[up].addFlux
                (
                    Sw, massFlux, R.transpose()*momentumFlux, energyFlux,
                    fromLeft ? sl : sr
                );

                if (k != j)
                {
                    // Lagrangian part in the receiving cell c
                    const int c = fromLeft ? 1 : 0;
                    const int invaded = fromLeft ? j : k;
                    const cobasis::vector tc
                    (
                        fromLeft ? (-tStar).eval() : tStar
                    );
                    const cobasis::vector& vStar = fromLeft ? vStarL : vStarR;
                    const double work = tc.dot(vStar);
                    const double du = std::abs(sol.uStar);

                    faceResult_[up].dAlpha[c] += Sw*du;
                    faceResult_[invaded].dAlpha[c] -= Sw*du;
                    faceResult_[up].dMomentum[c] -= Sw*tc;
                    faceResult_[invaded].dMomentum[c] += Sw*tc;
                    faceResult_[up].dEnergy[c] -= Sw*work;
                    faceResult_[invaded].dEnergy[c] += Sw*work;
                }
            };

            if (sol.uStar != 0 || k == j)
            {
                apply
                (
                    sol.uStar >= 0, 1,
                    sol.massFlux, sol.momentumFlux, sol.energyFlux
                );
            }
            else
            {
                // A contact at rest (the plane of a symmetric impact):
                // half of each side's star flux (no mass, the traction,
                // its work at that side's star velocity), so that the
                // face has no preferred side
                apply
                (
                    true, 0.5,
                    0, sol.momentumFlux, -sol.tStar.dot(sol.vStarL)
                );
                apply
                (
                    false, 0.5,
                    0, sol.momentumFlux, -sol.tStar.dot(sol.vStarR)
                );
            }

            // Star velocity seen by each phase, for the cobasis
            faceResult_[k].vStarSum += S*vStarL;
            faceResult_[k].vStarWeight += S;
            faceResult_[j].vStarSum += S*vStarR;
            faceResult_[j].vStarWeight += S;
        }
    );

    if (minorPairs_.empty())
    {
        return;
    }

    // Minor pairs: upwind transport at the contact velocity of the face
    // (the mean normal velocity of the sides where no pair was solved)
    if (wFace > 0)
    {
        uFace /= wFace;
    }
    else
    {
        uFace = 0.5*(sideL[0].U + sideR[0].U).dot(n);
    }

    for (const minorPair& tp : minorPairs_)
    {
        // Each side's traction (and its work) with half the weight, the
        // mass and what it carries from the upwind side: the flux is then
        // continuous in uFace (an upwind traction would jump as uFace
        // changes sign, e.g. at the plane of a symmetric impact)
        for (int side = 0; side < 2; ++side)
        {
            const bool fromLeft = (side == 0);
            const int up = fromLeft ? tp.k : tp.j;
            const phaseSide& K = fromLeft ? sideL[tp.k] : sideR[tp.j];
            const cobasis::vector s(K.sigma*n);

            faceResult_[up].addFlux(0.5*tp.S, 0, -s, -s.dot(K.U), K);

            if (uFace != 0 && fromLeft == (uFace > 0))
            {
                const double massFlux = K.rho*uFace;
                faceResult_[up].addFlux
                (
                    tp.S, massFlux, massFlux*K.U, massFlux*K.E, K
                );
            }
        }
        const double S = tp.S;

        const phaseSide& sl = sideL[tp.k];
        const phaseSide& sr = sideR[tp.j];
        faceResult_[tp.k].vStarSum += S*(sl.U + (uFace - sl.U.dot(n))*n);
        faceResult_[tp.k].vStarWeight += S;
        faceResult_[tp.j].vStarSum += S*(sr.U + (uFace - sr.U.dot(n))*n);
        faceResult_[tp.j].vStarWeight += S;
    }
}



void Foam::demFaceAssembly::addToCell
(
    const label c,
    const int side,
    const scalar magSf
)
{
    for (label k = 0; k < nPhases_; ++k)
    {
        const faceContribution& fc = faceResult_[k];
        double* s = sums(k, c);
        s[iAlpha] += magSf*fc.dAlpha[side];
        s[iMass] += magSf*fc.dMass[side];
        for (int j = 0; j < 3; ++j)
        {
            s[iMomentum + j] += magSf*fc.dMomentum[side](j);
        }
        s[iEnergy] += magSf*fc.dEnergy[side];
        for (int i = 0; i < stride_[k] - iCarried; ++i)
        {
            s[iCarried + i] += magSf*fc.dMassCarried[side][i];
        }
    }
}



void Foam::demFaceAssembly::addImageToCell
(
    const label c,
    const scalar magSf,
    const cobasis::matrix& Q
)
{
    for (label k = 0; k < nPhases_; ++k)
    {
        const faceContribution& fc = faceResult_[k];
        double* s = sums(k, c);
        const cobasis::vector m(magSf*(Q*fc.dMomentum[0]));
        s[iAlpha] -= magSf*fc.dAlpha[0];
        s[iMass] -= magSf*fc.dMass[0];
        for (int j = 0; j < 3; ++j)
        {
            s[iMomentum + j] -= m(j);
        }
        s[iEnergy] -= magSf*fc.dEnergy[0];
        for (int i = 0; i < stride_[k] - iCarried; ++i)
        {
            s[iCarried + i] -= magSf*fc.dMassCarried[0][i];
        }
    }
}


void Foam::demFaceAssembly::internalContacts
(
    const label c,
    const cobasis::vector& nOut,
    const scalar magSf,
    const std::vector<phaseSide>& face,
    const reconstruction& rec
)
{
    // A single phase has alpha = 1 at the centre and on every face
    if (nPhases_ == 1)
    {
        return;
    }

    // Time-centred alphas of the cell first: most cells hold the same
    // alphas at the centre and on the face, and need no contact
    rec.centreAlphas(c, alphaScratch_);

    bool differ = false;
    for (label k = 0; k < nPhases_; ++k)
    {
        if (alphaScratch_[k] != face[k].alpha) differ = true;
    }
    if (!differ)
    {
        return;
    }

    // The time-centred state, built once per cell and step
    if (centreStamp_[c] != stamp_)
    {
        centreStamp_[c] = stamp_;
        if (nCentres_ == label(centres_.size()))
        {
            centres_.emplace_back(nPhases_);
        }
        centreSlot_[c] = nCentres_++;
        rec.centreState(c, centres_[centreSlot_[c]]);
    }
    solveFace(centres_[centreSlot_[c]], face, faceFrame::rotation(nOut));

    // Both sides are cell c: the conservative parts cancel exactly, the
    // Lagrangian parts remain
    for (label k = 0; k < nPhases_; ++k)
    {
        const faceContribution& fc = faceResult_[k];
        double* s = sums(k, c);
        s[iAlpha] += magSf*(fc.dAlpha[0] + fc.dAlpha[1]);
        for (int j = 0; j < 3; ++j)
        {
            s[iMomentum + j] += magSf*(fc.dMomentum[0](j) + fc.dMomentum[1](j));
        }
        s[iEnergy] += magSf*(fc.dEnergy[0] + fc.dEnergy[1]);
    }
}


