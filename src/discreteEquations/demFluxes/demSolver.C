#include "demSolver.H"
#include "faceFrame.H"
#include "HLLC.H"
#include "contactFractions.H"
#include "fvc.H"
#include "emptyFvPatch.H"
#include "wedgeFvPatch.H"
#include "wedgePolyPatch.H"
#include "symmetryPlaneFvPatch.H"
#include "symmetryFvPatch.H"
#include "processorPolyPatch.H"
#include "slipFvPatchFields.H"
#include "noSlipFvPatchVectorField.H"

namespace
{

typedef Eigen::Matrix<double, 3, 3, Eigen::RowMajor> rowMatrix;

inline Foam::cobasis::matrix toEigen(const Foam::tensor& T)
{
    return Eigen::Map<const rowMatrix>(T.v_);
}

inline Foam::cobasis::vector toEigen(const Foam::vector& v)
{
    return Foam::cobasis::vector(v.x(), v.y(), v.z());
}

} // End anonymous namespace


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::demSolver::demSolver
(
    phaseSystem& phases,
    const dictionary& schemeDict
)
:
    phases_(phases),
    mesh_(phases.mesh()),
    nPhases_(phases.size()),
    reconstructU_(schemeDict.getOrDefault<bool>("reconstructVelocity", true)),
    patchKinds_(mesh_.boundary().size(), patchKind::value),
    coupledLeft_(mesh_.boundary().size(), true),
    magSf_(mag(mesh_.faceAreas())),
    frames_(mesh_.nFaces()),
    E_(nPhases_),
    a_(nPhases_),
    sigma_(nPhases_),
    gradU_(mesh_.nCells(), Zero),
    dAlpha_(nPhases_),
    dMass_(nPhases_),
    dMomentum_(nPhases_),
    dEnergy_(nPhases_),
    L_(nPhases_),
    advection_(nPhases_),
    sideL_(nPhases_),
    sideR_(nPhases_),
    faceResult_(nPhases_)
{
    const word solverName
    (
        schemeDict.getOrDefault<word>("riemannSolver", "HLLC")
    );
    if (solverName != "HLLC")
    {
        FatalIOErrorInFunction(schemeDict)
            << "Unknown riemannSolver " << solverName
            << "; valid: (HLLC)" << exit(FatalIOError);
    }

    const label nCells = mesh_.nCells();
    for (label k = 0; k < nPhases_; ++k)
    {
        E_[k].resize(nCells);
        a_[k].resize(nCells);
        sigma_[k].resize(nCells);
        dAlpha_[k].resize(nCells);
        dMass_[k].resize(nCells);
        dMomentum_[k].resize(nCells);
        dEnergy_[k].resize(nCells);
        L_[k].resize(nCells);
        advection_[k].resize(nCells);
    }

    const vectorField& Sf = mesh_.faceAreas();
    const scalarField& magSf = magSf_;
    forAll(Sf, facei)
    {
        frames_[facei] = faceFrame::rotation(toEigen(Sf[facei]/magSf[facei]));
    }

    classifyPatches();
}


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

void Foam::demSolver::classifyPatches()
{
    const volVectorField& U = phases_.U();

    forAll(mesh_.boundary(), patchi)
    {
        const fvPatch& patch = mesh_.boundary()[patchi];
        const fvPatchVectorField& Up = U.boundaryField()[patchi];

        if (isA<emptyFvPatch>(patch))
        {
            patchKinds_[patchi] = patchKind::empty;
        }
        else if (patch.coupled())
        {
            patchKinds_[patchi] = patchKind::coupled;
            const polyPatch& pp = patch.patch();
            if (isA<processorPolyPatch>(pp))
            {
                coupledLeft_[patchi] =
                    refCast<const processorPolyPatch>(pp).owner();
            }
            else
            {
                FatalErrorInFunction
                    << "Patch " << patch.name() << " of type " << pp.type()
                    << ": only processor coupling is supported"
                    << exit(FatalError);
            }
        }
        else if (isA<wedgeFvPatch>(patch))
        {
            patchKinds_[patchi] = patchKind::wedge;
        }
        else if
        (
            isA<symmetryPlaneFvPatch>(patch)
         || isA<symmetryFvPatch>(patch)
         || isA<slipFvPatchVectorField>(Up)
        )
        {
            patchKinds_[patchi] = patchKind::mirror;
        }
        else if (isA<noSlipFvPatchVectorField>(Up))
        {
            patchKinds_[patchi] = patchKind::noSlip;
        }
        else
        {
            patchKinds_[patchi] = patchKind::value;
        }
    }
}


void Foam::demSolver::completeSide(const label k, phaseSide& s) const
{
    const hyperelasticPhase& ph = phases_.phase(k);
    s.solid = ph.solid();
    s.trace = s.alpha < phases_.alphaTrace();
    s.sigma = ph.sigma(s.p, s.A);
    s.E = ph.e(s.rho, s.p, s.A) + 0.5*s.U.squaredNorm();
    s.a = std::sqrt(ph.a2Max(s.rho, s.p, s.A));
    s.cT = std::sqrt(ph.cT2());
}


void Foam::demSolver::cellSide
(
    const label k,
    const label celli,
    phaseSide& s
) const
{
    const hyperelasticPhase& ph = phases_.phase(k);
    s.alpha = phases_.alpha(k)[celli];
    s.rho = phases_.rho(k)[celli];
    s.p = phases_.p(k)[celli];
    s.U = toEigen(phases_.U()[celli]);
    s.A = toEigen(phases_.A(k)[celli]);
    s.sigma = sigma_[k][celli];
    s.E = E_[k][celli];
    s.a = a_[k][celli];
    s.cT = std::sqrt(ph.cT2());
    s.solid = ph.solid();
    s.trace = s.alpha < phases_.alphaTrace();
}


void Foam::demSolver::ghostSides
(
    const label patchi,
    const label patchFacei,
    const label celli,
    const cobasis::vector& n,
    std::vector<phaseSide>& cell,
    std::vector<phaseSide>& ghost
) const
{
    const patchKind kind = patchKinds_[patchi];

    for (label k = 0; k < nPhases_; ++k)
    {
        phaseSide& c = cell[k];
        phaseSide& g = ghost[k];
        cellSide(k, celli, c);

        // Face-centroid velocity of the cell
        if (reconstructU_)
        {
            const vector d
            (
                mesh_.Cf().boundaryField()[patchi][patchFacei]
              - mesh_.C()[celli]
            );
            c.U += toEigen(d & gradU_[celli]);
            c.E = c.E - 0.5*toEigen(phases_.U()[celli]).squaredNorm()
              + 0.5*c.U.squaredNorm();
        }

        switch (kind)
        {
            case patchKind::mirror:
            case patchKind::noSlip:
            {
                const cobasis::matrix M
                (
                    cobasis::matrix::Identity() - 2*n*n.transpose()
                );
                g = c;
                if (kind == patchKind::mirror)
                {
                    g.U = M*c.U;
                }
                else
                {
                    g.U = -c.U;
                }
                g.A = c.A*M;
                g.sigma = M*c.sigma*M;
                break;
            }

            case patchKind::wedge:
            {
                const wedgePolyPatch& wpp =
                    refCast<const wedgePolyPatch>
                    (
                        mesh_.boundaryMesh()[patchi]
                    );
                const cobasis::matrix T(toEigen(wpp.faceT()));
                c.U = T*c.U;
                c.A = c.A*T.transpose();
                c.sigma = T*c.sigma*T.transpose();
                g = c;
                break;
            }

            case patchKind::coupled:
            {
                g.alpha =
                    phases_.alpha(k).boundaryField()[patchi]
                   .patchNeighbourField()()[patchFacei];
                g.rho =
                    phases_.rho(k).boundaryField()[patchi]
                   .patchNeighbourField()()[patchFacei];
                g.p =
                    phases_.p(k).boundaryField()[patchi]
                   .patchNeighbourField()()[patchFacei];
                g.U = toEigen
                (
                    phases_.U().boundaryField()[patchi]
                   .patchNeighbourField()()[patchFacei]
                );
                g.A = toEigen
                (
                    phases_.A(k).boundaryField()[patchi]
                   .patchNeighbourField()()[patchFacei]
                );
                completeSide(k, g);
                break;
            }

            default:
            {
                g.alpha = phases_.alpha(k).boundaryField()[patchi][patchFacei];
                g.rho = phases_.rho(k).boundaryField()[patchi][patchFacei];
                g.p = phases_.p(k).boundaryField()[patchi][patchFacei];
                g.U = toEigen(phases_.U().boundaryField()[patchi][patchFacei]);
                g.A = c.A*std::cbrt(g.rho/c.rho);
                completeSide(k, g);
                break;
            }
        }
    }
}


void Foam::demSolver::solveFace(const cobasis::matrix& R)
{
    for (label k = 0; k < nPhases_; ++k)
    {
        faceContribution& fc = faceResult_[k];
        fc.dAlpha[0] = fc.dAlpha[1] = 0;
        fc.dMass[0] = fc.dMass[1] = 0;
        fc.dMomentum[0].setZero();
        fc.dMomentum[1].setZero();
        fc.dEnergy[0] = fc.dEnergy[1] = 0;
        fc.vStarSum.setZero();
        fc.vStarWeight = 0;
    }

    const auto alphaL = [this](const int k) { return sideL_[k].alpha; };
    const auto alphaR = [this](const int k) { return sideR_[k].alpha; };

    const cobasis::vector n(R.row(0).transpose());

    contactFractions::forAllPairs
    (
        nPhases_, alphaL, alphaR,
        [&](const int k, const int j, const double S)
        {
            const phaseSide& sl = sideL_[k];
            const phaseSide& sr = sideR_[j];

            riemannState L, Rs;
            L.rho = sl.rho;
            L.v = R*sl.U;
            L.s = R*(sl.sigma*n);
            L.E = sl.E;
            L.a = sl.a;
            L.cT = sl.cT;
            L.solid = sl.solid;

            Rs.rho = sr.rho;
            Rs.v = R*sr.U;
            Rs.s = R*(sr.sigma*n);
            Rs.E = sr.E;
            Rs.a = sr.a;
            Rs.cT = sr.cT;
            Rs.solid = sr.solid;

            const riemannSolution sol = HLLC::solve(L, Rs);

            // One rule for both parts, including u* = 0
            const bool fromLeft = (sol.uStar >= 0);
            const int up = fromLeft ? k : j;

            const cobasis::vector momFlux(R.transpose()*sol.momentumFlux);

            // Conservative part: out of L, into R, for the upwind phase
            faceResult_[up].dMass[0] -= S*sol.massFlux;
            faceResult_[up].dMass[1] += S*sol.massFlux;
            faceResult_[up].dMomentum[0] -= S*momFlux;
            faceResult_[up].dMomentum[1] += S*momFlux;
            faceResult_[up].dEnergy[0] -= S*sol.energyFlux;
            faceResult_[up].dEnergy[1] += S*sol.energyFlux;

            const cobasis::vector vStarL(R.transpose()*sol.vStarL);
            const cobasis::vector vStarR(R.transpose()*sol.vStarR);

            if (k != j)
            {
                // Lagrangian part in the receiving cell c
                const int c = fromLeft ? 1 : 0;
                const int invaded = fromLeft ? j : k;
                const cobasis::vector tStar(R.transpose()*sol.tStar);
                const cobasis::vector tc(fromLeft ? (-tStar).eval() : tStar);
                const cobasis::vector& vStar = fromLeft ? vStarL : vStarR;
                const double work = tc.dot(vStar);
                const double du = std::abs(sol.uStar);

                faceResult_[up].dAlpha[c] += S*du;
                faceResult_[invaded].dAlpha[c] -= S*du;
                faceResult_[up].dMomentum[c] -= S*tc;
                faceResult_[invaded].dMomentum[c] += S*tc;
                faceResult_[up].dEnergy[c] -= S*work;
                faceResult_[invaded].dEnergy[c] += S*work;
            }

            // Star velocity seen by each phase, for the cobasis
            faceResult_[k].vStarSum += S*vStarL;
            faceResult_[k].vStarWeight += S;
            faceResult_[j].vStarSum += S*vStarR;
            faceResult_[j].vStarWeight += S;
        }
    );
}


void Foam::demSolver::addToCell
(
    const label c,
    const int side,
    const scalar magSf,
    const cobasis::vector& SfOut
)
{
    for (label k = 0; k < nPhases_; ++k)
    {
        const faceContribution& fc = faceResult_[k];
        dAlpha_[k][c] += magSf*fc.dAlpha[side];
        dMass_[k][c] += magSf*fc.dMass[side];
        dMomentum_[k][c] += magSf*fc.dMomentum[side];
        dEnergy_[k][c] += magSf*fc.dEnergy[side];
        if (phases_.phase(k).solid())
        {
            L_[k][c] += (fc.vStarSum/fc.vStarWeight)*SfOut.transpose();
        }
    }
}


void Foam::demSolver::addAdvection
(
    const label k,
    const label c,
    const cobasis::vector& v,
    const cobasis::vector& SfOut,
    const phaseSide& own,
    const phaseSide& nb
)
{
    const double flux = v.dot(SfOut);
    if (flux < 0 && !nb.trace)
    {
        advection_[k][c] += flux*(nb.A - own.A);
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::demSolver::prepare()
{
    phases_.correctBoundaryConditions();

    if (reconstructU_)
    {
        gradU_ = fvc::grad(phases_.U())().primitiveField();
    }

    const label nCells = mesh_.nCells();
    const vectorField& U = phases_.U().primitiveField();

    for (label k = 0; k < nPhases_; ++k)
    {
        const hyperelasticPhase& ph = phases_.phase(k);
        const scalarField& rho = phases_.rho(k).primitiveField();
        const scalarField& p = phases_.p(k).primitiveField();
        const tensorField& A = phases_.A(k).primitiveField();

        for (label celli = 0; celli < nCells; ++celli)
        {
            const cobasis::matrix Ac(toEigen(A[celli]));
            sigma_[k][celli] = ph.sigma(p[celli], Ac);
            E_[k][celli] =
                ph.e(rho[celli], p[celli], Ac) + 0.5*magSqr(U[celli]);
            a_[k][celli] = std::sqrt(ph.a2Max(rho[celli], p[celli], Ac));
        }
    }
}


Foam::scalar Foam::demSolver::stableDeltaT() const
{
    const label nCells = mesh_.nCells();
    const labelUList& own = mesh_.owner();
    const labelUList& nei = mesh_.neighbour();
    const vectorField& Sf = mesh_.faceAreas();
    const vectorField& U = phases_.U().primitiveField();

    // Largest longitudinal speed among the phases with alpha > 1e-3
    scalarField aMax(nCells, 0);
    for (label k = 0; k < nPhases_; ++k)
    {
        const scalarField& alpha = phases_.alpha(k).primitiveField();
        for (label celli = 0; celli < nCells; ++celli)
        {
            if (alpha[celli] > 1e-3)
            {
                aMax[celli] = max(aMax[celli], a_[k][celli]);
            }
        }
    }

    scalarField sumLambda(nCells, 0);
    forAll(nei, facei)
    {
        const scalar magS = mag(Sf[facei]);
        const scalar lambda = max
        (
            mag(U[own[facei]] & Sf[facei]) + aMax[own[facei]]*magS,
            mag(U[nei[facei]] & Sf[facei]) + aMax[nei[facei]]*magS
        );
        sumLambda[own[facei]] += lambda;
        sumLambda[nei[facei]] += lambda;
    }
    forAll(mesh_.boundary(), patchi)
    {
        if (patchKinds_[patchi] == patchKind::empty)
        {
            continue;
        }
        const fvPatch& patch = mesh_.boundary()[patchi];
        const labelUList& fc = patch.faceCells();
        const vectorField& pSf = patch.Sf();
        forAll(fc, i)
        {
            sumLambda[fc[i]] +=
                mag(U[fc[i]] & pSf[i]) + aMax[fc[i]]*mag(pSf[i]);
        }
    }

    scalar dt = GREAT;
    const scalarField& V = mesh_.V();
    forAll(V, celli)
    {
        if (sumLambda[celli] > 0)
        {
            dt = min(dt, 2*V[celli]/sumLambda[celli]);
        }
    }
    return returnReduce(dt, minOp<scalar>());
}


void Foam::demSolver::hyperbolicStep(const scalar dt, conservedState& q)
{
    const label nCells = mesh_.nCells();
    const labelUList& own = mesh_.owner();
    const labelUList& nei = mesh_.neighbour();
    const vectorField& Sf = mesh_.faceAreas();
    const scalarField& magSf = magSf_;
    const vectorField& Cf = mesh_.faceCentres();
    const vectorField& C = mesh_.cellCentres();
    const vectorField& U = phases_.U().primitiveField();

    for (label k = 0; k < nPhases_; ++k)
    {
        std::fill(dAlpha_[k].begin(), dAlpha_[k].end(), 0.0);
        std::fill(dMass_[k].begin(), dMass_[k].end(), 0.0);
        std::fill(dEnergy_[k].begin(), dEnergy_[k].end(), 0.0);
        for (label c = 0; c < nCells; ++c)
        {
            dMomentum_[k][c].setZero();
            L_[k][c].setZero();
            advection_[k][c].setZero();
        }
    }

    // Internal faces
    forAll(nei, facei)
    {
        const label o = own[facei];
        const label nb = nei[facei];

        for (label k = 0; k < nPhases_; ++k)
        {
            cellSide(k, o, sideL_[k]);
            cellSide(k, nb, sideR_[k]);
        }
        if (reconstructU_)
        {
            const cobasis::vector dUL(toEigen((Cf[facei] - C[o]) & gradU_[o]));
            const cobasis::vector dUR(toEigen((Cf[facei] - C[nb]) & gradU_[nb]));
            const cobasis::vector UL(toEigen(U[o]) + dUL);
            const cobasis::vector UR(toEigen(U[nb]) + dUR);
            const double keL = 0.5*(UL.squaredNorm() - magSqr(U[o]));
            const double keR = 0.5*(UR.squaredNorm() - magSqr(U[nb]));
            for (label k = 0; k < nPhases_; ++k)
            {
                sideL_[k].U = UL;
                sideL_[k].E += keL;
                sideR_[k].U = UR;
                sideR_[k].E += keR;
            }
        }

        solveFace(frames_[facei]);

        const cobasis::vector S(toEigen(Sf[facei]));
        addToCell(o, 0, magSf[facei], S);
        addToCell(nb, 1, magSf[facei], -S);

        for (label k = 0; k < nPhases_; ++k)
        {
            if (!phases_.phase(k).solid()) continue;
            const faceContribution& fc = faceResult_[k];
            const cobasis::vector v(fc.vStarSum/fc.vStarWeight);
            addAdvection(k, o, v, S, sideL_[k], sideR_[k]);
            addAdvection(k, nb, v, -S, sideR_[k], sideL_[k]);
        }
    }

    // Boundary faces
    std::vector<phaseSide> cellStates(nPhases_), ghostStates(nPhases_);
    forAll(mesh_.boundary(), patchi)
    {
        const patchKind kind = patchKinds_[patchi];
        if (kind == patchKind::empty)
        {
            continue;
        }

        const fvPatch& patch = mesh_.boundary()[patchi];
        const labelUList& fc = patch.faceCells();
        const label start = patch.start();
        const bool cellIsLeft =
            kind != patchKind::coupled || coupledLeft_[patchi];

        forAll(fc, i)
        {
            const label facei = start + i;
            const label celli = fc[i];
            const cobasis::vector S(toEigen(Sf[facei]));
            const cobasis::vector n(S/magSf[facei]);

            ghostSides(patchi, i, celli, n, cellStates, ghostStates);

            if (cellIsLeft)
            {
                sideL_ = cellStates;
                sideR_ = ghostStates;
                solveFace(frames_[facei]);
            }
            else
            {
                // Same orientation as on the neighbouring processor
                sideL_ = ghostStates;
                sideR_ = cellStates;
                solveFace(faceFrame::rotation(-n));
            }

            addToCell(celli, cellIsLeft ? 0 : 1, magSf[facei], S);

            for (label k = 0; k < nPhases_; ++k)
            {
                if (!phases_.phase(k).solid()) continue;
                const faceContribution& fr = faceResult_[k];
                addAdvection
                (
                    k, celli, fr.vStarSum/fr.vStarWeight, S,
                    cellStates[k], ghostStates[k]
                );
            }
        }
    }

    // New conservative state
    const scalarField& V = mesh_.V();
    q.alpha.resize(nPhases_);
    q.mass.resize(nPhases_);
    q.momentum.resize(nPhases_);
    q.energy.resize(nPhases_);
    q.A.resize(nPhases_);

    for (label k = 0; k < nPhases_; ++k)
    {
        q.alpha[k].resize(nCells);
        q.mass[k].resize(nCells);
        q.momentum[k].resize(nCells);
        q.energy[k].resize(nCells);
        q.A[k].resize(nCells);

        const bool solid = phases_.phase(k).solid();
        const scalarField& alpha = phases_.alpha(k).primitiveField();
        const scalarField& rho = phases_.rho(k).primitiveField();
        const tensorField& A = phases_.A(k).primitiveField();

        for (label c = 0; c < nCells; ++c)
        {
            const scalar dtByV = dt/V[c];
            const scalar m = alpha[c]*rho[c];
            q.alpha[k][c] = alpha[c] + dtByV*dAlpha_[k][c];
            q.mass[k][c] = m + dtByV*dMass_[k][c];
            q.momentum[k][c] = m*toEigen(U[c]) + dtByV*dMomentum_[k][c];
            q.energy[k][c] = m*E_[k][c] + dtByV*dEnergy_[k][c];

            const cobasis::matrix Ac(toEigen(A[c]));
            if (solid)
            {
                q.A[k][c] =
                    Ac - dtByV*(advection_[k][c] + Ac*L_[k][c]);
            }
            else
            {
                q.A[k][c] = Ac;
            }
        }
    }
}
