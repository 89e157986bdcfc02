#include "demSolver.H"
#include "faceFrame.H"
#include "HLLC.H"
#include "contactFractions.H"
#include "alphaClosure.H"
#include "fvc.H"
#include "gaussGrad.H"
#include "linear.H"
#include "emptyFvPatch.H"
#include "wedgeFvPatch.H"
#include "wedgePolyPatch.H"
#include "symmetryPlaneFvPatch.H"
#include "symmetryFvPatch.H"
#include "processorPolyPatch.H"
#include "slipFvPatchFields.H"
#include "noSlipFvPatchVectorField.H"
#include "PstreamBuffers.H"
#include "foamEigen.H"

using Foam::foamEigen::toEigen;


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
    order_(schemeDict.getOrDefault<label>("order", 2)),
    waveSpeeds_(HLLC::waveSpeeds::Davis),
    reconstructU_(schemeDict.getOrDefault<bool>("reconstructVelocity", true)),
    alphaCompression_(schemeDict.getOrDefault<scalar>("alphaCompression", 1)),
    patchKinds_(mesh_.boundary().size(), patchKind::value),
    coupledLeft_(mesh_.boundary().size(), true),
    magSf_(mag(mesh_.faceAreas())),
    frames_(mesh_.nFaces()),
    E_(nPhases_),
    a_(nPhases_),
    sigma_(nPhases_),
    gradU_(),
    acceleration_(nullptr),
    limitingCell_(-1),
    limitingSpeed_(0),
    slopes_(nPhases_),
    nbrStates_(mesh_.boundary().size()),
    dAlpha_(nPhases_),
    dMass_(nPhases_),
    dMomentum_(nPhases_),
    dEnergy_(nPhases_),
    dMassEpsP_(nPhases_),
    dMassWP_(nPhases_),
    L_(nPhases_),
    advection_(nPhases_),
    centre_(nPhases_),
    cellFace_(nPhases_),
    ghost_(nPhases_),
    alphaScratch_(nPhases_),
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
    const word speedsName
    (
        schemeDict.getOrDefault<word>("waveSpeeds", "Davis")
    );
    if (speedsName == "pressureBased")
    {
        waveSpeeds_ = HLLC::waveSpeeds::pressureBased;
    }
    else if (speedsName != "Davis")
    {
        FatalIOErrorInFunction(schemeDict)
            << "Unknown waveSpeeds " << speedsName
            << "; valid: (pressureBased Davis)" << exit(FatalIOError);
    }
    if (!(alphaCompression_ >= 1 && alphaCompression_ <= 4))
    {
        FatalIOErrorInFunction(schemeDict)
            << "discreteEquations alphaCompression " << alphaCompression_
            << " is not in [1, 4]" << exit(FatalIOError);
    }
    if (order_ != 1 && order_ != 2)
    {
        FatalIOErrorInFunction(schemeDict)
            << "discreteEquations order " << order_ << " is not 1 or 2"
            << exit(FatalIOError);
    }

    const label nCells = mesh_.nCells();
    for (label k = 0; k < nPhases_; ++k)
    {
        E_[k].resize(nCells);
        a_[k].resize(nCells);
        sigma_[k].resize(nCells);
        if (order_ == 2)
        {
            slopes_[k].resize(nCells);
        }
        dAlpha_[k].resize(nCells);
        dMass_[k].resize(nCells);
        dMomentum_[k].resize(nCells);
        dEnergy_[k].resize(nCells);
        dMassEpsP_[k].resize(nCells);
        dMassWP_[k].resize(nCells);
        L_[k].resize(nCells);
        advection_[k].resize(nCells);
    }

    const vectorField& Sf = mesh_.faceAreas();
    forAll(Sf, facei)
    {
        frames_[facei] =
            faceFrame::rotation(toEigen(Sf[facei]/magSf_[facei]));
    }

    classifyPatches();

    // A switch between two words: true for the first (the default)
    const auto readSwitch =
        [&schemeDict](const word& key, const word& on, const word& off)
    {
        const word value(schemeDict.getOrDefault<word>(key, on));
        if (value != on && value != off)
        {
            FatalIOErrorInFunction(schemeDict)
                << "Unknown " << key << " " << value
                << "; valid: (" << on << ' ' << off << ")"
                << exit(FatalIOError);
        }
        return value == on;
    };
    keepCobasisRotation_ = !readSwitch("cobasisRotation", "discard", "keep");
    const bool limitU = readSwitch("velocityLimiter", "cellLimited", "none");
    const bool limitA = readSwitch("cobasisLimiter", "cellLimited", "none");

    // Neighbours for the velocity gradient (a no-slip wall: its zero value
    // at the face) and for the cobasis limiter (a wall's ghost is the
    // cell's mirror image, NUMERICS.md section 7)
    List<cellLimiter::neighbour> kindsU(patchKinds_.size());
    List<cellLimiter::neighbour> kindsA(patchKinds_.size());
    forAll(patchKinds_, patchi)
    {
        using nb = cellLimiter::neighbour;
        switch (patchKinds_[patchi])
        {
            case patchKind::empty:
                kindsU[patchi] = kindsA[patchi] = nb::none; break;
            case patchKind::coupled:
                kindsU[patchi] = kindsA[patchi] = nb::coupled; break;
            case patchKind::mirror:
                kindsU[patchi] = kindsA[patchi] = nb::mirror; break;
            case patchKind::noSlip:
                kindsU[patchi] = nb::value;
                kindsA[patchi] = nb::mirror;
                break;
            case patchKind::wedge:
                kindsU[patchi] = kindsA[patchi] = nb::wedge; break;
            default:
                kindsU[patchi] = kindsA[patchi] = nb::value; break;
        }
    }
    if (limitA)
    {
        cobasisLimiter_.reset(new cellLimiter(mesh_, kindsA));
    }
    gradUCalc_.reset
    (
        new linearVelocityGradient(mesh_, kindsU, limitU)
    );

    Info<< "Discrete equations: order " << order_ << ", Riemann solver "
        << solverName << ", velocity limiter "
        << (limitU ? "cellLimited" : "none") << ", cobasis rotation "
        << (keepCobasisRotation_ ? "keep" : "discard");
    if (order_ == 1)
    {
        Info<< ", face velocity reconstruction "
            << (reconstructU_ ? "on" : "off");
    }
    else
    {
        Info<< ", cobasis limiter " << (limitA ? "cellLimited" : "none");
        if (alphaCompression_ > 1)
        {
            Info<< ", volume fraction slopes steepened by "
                << alphaCompression_;
        }
    }
    Info<< nl << endl;
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
            const polyPatch& pp = patch.patch();
            if (!isA<processorPolyPatch>(pp))
            {
                FatalErrorInFunction
                    << "Patch " << patch.name() << " of type " << pp.type()
                    << ": of the coupled patches only processor patches"
                    << " are supported" << exit(FatalError);
            }
            patchKinds_[patchi] = patchKind::coupled;
            coupledLeft_[patchi] =
                refCast<const processorPolyPatch>(pp).owner();
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
    s.cT = std::sqrt(ph.cT2());
    s.sigma = ph.sigma(s.p, s.A);
    s.E = ph.e(s.rho, s.p, s.A) + 0.5*s.U.squaredNorm();
}


void Foam::demSolver::markMinor(std::vector<phaseSide>& s) const
{
    double rhoMix = 0;
    for (label k = 0; k < nPhases_; ++k)
    {
        rhoMix += s[k].alpha*s[k].rho;
    }
    const double Ymin = phases_.massFractionMinor();
    for (label k = 0; k < nPhases_; ++k)
    {
        s[k].minor =
            s[k].alpha < phases_.alphaMinor()
         || s[k].alpha*s[k].rho < Ymin*rhoMix;
    }
}


void Foam::demSolver::centreSides
(
    const label celli,
    std::vector<phaseSide>& s
) const
{
    const vector& Uc = phases_.U()[celli];

    for (label k = 0; k < nPhases_; ++k)
    {
        phaseSide& sk = s[k];
        sk.alpha = phases_.alpha(k)[celli];
        sk.rho = phases_.rho(k)[celli];
        sk.p = phases_.p(k)[celli];
        sk.U = toEigen(Uc);
        sk.A = toEigen(phases_.A(k)[celli]);
        sk.a = a_[k][celli];
        sk.epsP = phases_.epsilonP(k)[celli];
        sk.wP = phases_.plasticWork(k)[celli];

        if (order_ == 1)
        {
            const hyperelasticPhase& ph = phases_.phase(k);
            sk.solid = ph.solid();
            sk.trace = sk.alpha < phases_.alphaTrace();
            sk.cT = std::sqrt(ph.cT2());
            sk.sigma = sigma_[k][celli];
            sk.E = E_[k][celli];
            continue;
        }

        const cellSlopes& sl = slopes_[k][celli];
        if (sk.alpha >= phases_.alphaMinor())
        {
            sk.alpha = min(max(sk.alpha + sl.dtAlpha, 0.0), 1.0);
        }

        const double rho = sk.rho + sl.dtRho;
        const double p = sk.p + sl.dtP;
        const cobasis::matrix A(sk.A + sl.dtA);
        const hyperelasticPhase& ph = phases_.phase(k);
        if
        (
            rho > 0 && p > ph.eos().pMin(rho)
         && (!ph.solid() || A.determinant() > 0)
        )
        {
            sk.rho = rho;
            sk.p = p;
            sk.U += sl.dtU;
            sk.A = A;
        }
        completeSide(k, sk);
    }

    if (order_ == 2)
    {
        // The cell's largest phase closes the sum
        floorAndClose
        (
            nPhases_,
            0.0,
            [&s](const label k) -> double& { return s[k].alpha; }
        );
    }
    markMinor(s);
}


void Foam::demSolver::faceSides
(
    const label celli,
    const vector& d,
    std::vector<phaseSide>& s
)
{
    const vector& Uc = phases_.U()[celli];

    if (order_ == 1)
    {
        cobasis::vector U(toEigen(Uc));
        double dKe = 0;
        if (reconstructU_)
        {
            U += toEigen(d & gradU_[celli]);
            dKe = 0.5*(U.squaredNorm() - magSqr(Uc));
        }
        for (label k = 0; k < nPhases_; ++k)
        {
            phaseSide& sk = s[k];
            const hyperelasticPhase& ph = phases_.phase(k);
            sk.alpha = phases_.alpha(k)[celli];
            sk.rho = phases_.rho(k)[celli];
            sk.p = phases_.p(k)[celli];
            sk.U = U;
            sk.A = toEigen(phases_.A(k)[celli]);
            sk.epsP = phases_.epsilonP(k)[celli];
            sk.wP = phases_.plasticWork(k)[celli];
            sk.sigma = sigma_[k][celli];
            sk.E = E_[k][celli] + dKe;
            sk.a = a_[k][celli];
            sk.cT = std::sqrt(ph.cT2());
            sk.solid = ph.solid();
            sk.trace = sk.alpha < phases_.alphaTrace();
        }
        markMinor(s);
        return;
    }

    // Second order: alpha of every phase but the cell's largest, which
    // closes the sum; a minor phase (below alphaMinor in the cell) keeps
    // its cell value, so it never offers the faces more than it holds
    const cobasis::vector de(toEigen(d));
    const scalar alphaMin = phases_.alphaMin();
    label main = 0;
    for (label k = 1; k < nPhases_; ++k)
    {
        if (phases_.alpha(k)[celli] > phases_.alpha(main)[celli]) main = k;
    }
    scalar sumAlpha = 0;
    for (label k = 0; k < nPhases_; ++k)
    {
        if (k == main) continue;
        const scalar ac = phases_.alpha(k)[celli];
        const cellSlopes& sl = slopes_[k][celli];
        alphaScratch_[k] =
            ac < phases_.alphaMinor()
          ? ac
          : min(max(ac + sl.gAlpha.dot(de) + sl.dtAlpha, alphaMin), 1 - alphaMin);
        sumAlpha += alphaScratch_[k];
    }
    if (sumAlpha > 1 - alphaMin)
    {
        for (label k = 0; k < nPhases_; ++k)
        {
            if (k != main) alphaScratch_[k] *= (1 - alphaMin)/sumAlpha;
        }
        sumAlpha = 1 - alphaMin;
    }
    alphaScratch_[main] = 1 - sumAlpha;

    for (label k = 0; k < nPhases_; ++k)
    {
        const cellSlopes& sl = slopes_[k][celli];
        const hyperelasticPhase& ph = phases_.phase(k);
        phaseSide& sk = s[k];

        const double rhoc = phases_.rho(k)[celli];
        const double pc = phases_.p(k)[celli];
        const cobasis::matrix Ac(toEigen(phases_.A(k)[celli]));

        sk.alpha = alphaScratch_[k];
        sk.epsP = phases_.epsilonP(k)[celli];
        sk.wP = phases_.plasticWork(k)[celli];
        sk.rho = rhoc + sl.gRho.dot(de) + sl.dtRho;
        sk.p = pc + sl.gP.dot(de) + sl.dtP;
        sk.U = toEigen(Uc) + sl.gU.transpose()*de + sl.dtU;
        sk.A = Ac + de(0)*sl.gA[0] + de(1)*sl.gA[1] + de(2)*sl.gA[2] + sl.dtA;

        if
        (
            !(sk.rho > 0) || !(sk.p > ph.eos().pMin(sk.rho))
         || (ph.solid() && !(sk.A.determinant() > 0))
        )
        {
            // An inadmissible predicted state: the cell value
            sk.rho = rhoc;
            sk.p = pc;
            sk.U = toEigen(Uc);
            sk.A = Ac;
        }
        completeSide(k, sk);

        // a_f^2 = c_h^2(face) + (a_cell^2 - c_h^2(cell)), >= a_cell^2/4
        const double ac2 = sqr(a_[k][celli]);
        const double a2 =
            ph.eos().c2(sk.rho, sk.p) + ac2 - ph.eos().c2(rhoc, pc);
        sk.a = std::sqrt(max(a2, 0.25*ac2));
    }
    markMinor(s);
}


void Foam::demSolver::computeSlopes(const scalar dt)
{
    const label nCells = mesh_.nCells();
    const volVectorField& Ufield = phases_.U();
    const vectorField& U = Ufield.primitiveField();
    gradUCalc_->calculate(Ufield, gradU_);
    const tensorField& gradU = gradU_;
    const scalar halfDt = 0.5*dt;

    scalarField minAlpha(nCells);
    scalarField maxAlpha(nCells);
    tensorField limiterA;

    for (label k = 0; k < nPhases_; ++k)
    {
        const hyperelasticPhase& ph = phases_.phase(k);
        const volScalarField& alpha = phases_.alpha(k);
        const scalarField& rho = phases_.rho(k).primitiveField();
        const scalarField& p = phases_.p(k).primitiveField();
        const volTensorField& A = phases_.A(k);

        // Minor-phase rule: below alphaMinor in the cell or any neighbour
        alphaRange(alpha, minAlpha, maxAlpha);

        // A single phase has alpha = 1 everywhere: no slope to compute
        const tmp<volVectorField> tgAlpha
        (
            nPhases_ > 1
          ? fvc::grad(alpha)
          : tmp<volVectorField>
            (
                new volVectorField
                (
                    IOobject("gradAlpha", mesh_.time().timeName(), mesh_),
                    mesh_,
                    dimensionedVector(dimless/dimLength, Zero)
                )
            )
        );
        const tmp<volVectorField> tgRho(fvc::grad(phases_.rho(k)));
        const tmp<volVectorField> tgP(fvc::grad(phases_.p(k)));
        vectorField gAlpha(tgAlpha().primitiveField());
        if (alphaCompression_ > 1 && nPhases_ > 1)
        {
            compressAlphaSlopes(alpha, minAlpha, maxAlpha, gAlpha);
        }
        const vectorField& gRho = tgRho().primitiveField();
        const vectorField& gP = tgP().primitiveField();

        // Cobasis slopes: Gauss linear (the face values of A's boundary
        // conditions), limited with mirror neighbours
        PtrList<volVectorField> gA(ph.solid() ? 9 : 0);
        forAll(gA, cmpt)
        {
            gA.set
            (
                cmpt,
                fv::gaussGrad<scalar>::gradf
                (
                    linearInterpolate(A.component(cmpt)()),
                    "gradA"
                ).ptr()
            );
        }
        if (ph.solid() && cobasisLimiter_.valid())
        {
            cobasisLimiter_->factors
            (
                A,
                [&gA](const label celli, const vector& dx)
                {
                    tensor dA;
                    for (direction cmpt = 0; cmpt < 9; ++cmpt)
                    {
                        dA[cmpt] = dx & gA[cmpt][celli];
                    }
                    return dA;
                },
                limiterA
            );
            forAll(gA, cmpt)
            {
                vectorField& g = gA[cmpt].primitiveFieldRef();
                forAll(g, celli)
                {
                    g[celli] *= limiterA[celli][cmpt];
                }
            }
        }

        for (label c = 0; c < nCells; ++c)
        {
            cellSlopes& sl = slopes_[k][c];
            const cobasis::vector u(toEigen(U[c]));

            sl.gAlpha = toEigen(gAlpha[c]);
            sl.dtAlpha = -halfDt*u.dot(sl.gAlpha);
            sl.minor = minAlpha[c] < phases_.alphaMinor();

            if (sl.minor)
            {
                sl.gRho.setZero();
                sl.gP.setZero();
                sl.gU.setZero();
                for (int i = 0; i < 3; ++i) sl.gA[i].setZero();
                sl.dtRho = 0;
                sl.dtP = 0;
                sl.dtU.setZero();
                if (acceleration_)
                {
                    sl.dtU = halfDt*toEigen((*acceleration_)[c]);
                }
                sl.dtA.setZero();
                continue;
            }

            sl.gRho = toEigen(gRho[c]);
            sl.gP = toEigen(gP[c]);
            sl.gU = toEigen(gradU[c]);
            for (int i = 0; i < 3; ++i)
            {
                if (ph.solid())
                {
                    for (int cmpt = 0; cmpt < 9; ++cmpt)
                    {
                        sl.gA[i](cmpt/3, cmpt%3) = gA[cmpt][c][i];
                    }
                }
                else
                {
                    sl.gA[i].setZero();
                }
            }
            // Primitive equations, with L_ij = du_i/dx_j = gU(j, i)
            const cobasis::matrix L(sl.gU.transpose());
            const double divU = L.trace();
            const cobasis::matrix Ac(toEigen(A[c]));

            cobasis::vector divSigma(-sl.gP);
            if (ph.solid())
            {
                for (int j = 0; j < 3; ++j)
                {
                    divSigma += ph.elastic().dS(Ac, sl.gA[j]).col(j);
                }
            }

            sl.dtRho = -halfDt*(u.dot(sl.gRho) + rho[c]*divU);
            sl.dtP =
                -halfDt
               *(u.dot(sl.gP) + rho[c]*ph.eos().c2(rho[c], p[c])*divU);
            sl.dtU = -halfDt*(L*u - divSigma/rho[c]);
            if (acceleration_)
            {
                sl.dtU += halfDt*toEigen((*acceleration_)[c]);
            }
            if (ph.solid())
            {
                sl.dtA =
                    -halfDt
                   *(
                        u(0)*sl.gA[0] + u(1)*sl.gA[1] + u(2)*sl.gA[2]
                      + Ac*L
                    );
            }
            else
            {
                sl.dtA.setZero();
            }
        }
    }
}


void Foam::demSolver::alphaRange
(
    const volScalarField& alpha,
    scalarField& aMin,
    scalarField& aMax
) const
{
    const labelUList& own = mesh_.owner();
    const labelUList& nei = mesh_.neighbour();

    aMin = alpha.primitiveField();
    aMax = alpha.primitiveField();
    forAll(nei, facei)
    {
        const label o = own[facei];
        const label n = nei[facei];
        aMin[o] = min(aMin[o], alpha[n]);
        aMax[o] = max(aMax[o], alpha[n]);
        aMin[n] = min(aMin[n], alpha[o]);
        aMax[n] = max(aMax[n], alpha[o]);
    }
    forAll(mesh_.boundary(), patchi)
    {
        if (patchKinds_[patchi] != patchKind::coupled) continue;
        const scalarField nbr
        (
            alpha.boundaryField()[patchi].patchNeighbourField()
        );
        const labelUList& fc = mesh_.boundary()[patchi].faceCells();
        forAll(fc, i)
        {
            aMin[fc[i]] = min(aMin[fc[i]], nbr[i]);
            aMax[fc[i]] = max(aMax[fc[i]], nbr[i]);
        }
    }
}


void Foam::demSolver::compressAlphaSlopes
(
    const volScalarField& alpha,
    const scalarField& aMin,
    const scalarField& aMax,
    vectorField& g
) const
{
    const label nCells = mesh_.nCells();
    const labelUList& own = mesh_.owner();
    const labelUList& nei = mesh_.neighbour();
    const vectorField& Cf = mesh_.faceCentres();
    const vectorField& C = mesh_.cellCentres();

    // Largest factor of g that keeps every face value in range
    scalarField factor(nCells, alphaCompression_);
    const auto limit = [&](const label c, const vector& d)
    {
        const scalar delta = g[c] & d;
        if (delta > VSMALL)
        {
            factor[c] = min(factor[c], (aMax[c] - alpha[c])/delta);
        }
        else if (delta < -VSMALL)
        {
            factor[c] = min(factor[c], (aMin[c] - alpha[c])/delta);
        }
    };
    forAll(nei, facei)
    {
        limit(own[facei], Cf[facei] - C[own[facei]]);
        limit(nei[facei], Cf[facei] - C[nei[facei]]);
    }
    forAll(mesh_.boundary(), patchi)
    {
        const patchKind kind = patchKinds_[patchi];
        if (kind == patchKind::empty || kind == patchKind::wedge) continue;
        const fvPatch& patch = mesh_.boundary()[patchi];
        const labelUList& fc = patch.faceCells();
        forAll(fc, i)
        {
            limit(fc[i], Cf[patch.start() + i] - C[fc[i]]);
        }
    }

    forAll(g, c)
    {
        g[c] *= max(factor[c], scalar(0));
    }
}


void Foam::demSolver::exchangeCoupled()
{
    if (!Pstream::parRun())
    {
        return;
    }

    const vectorField& Cf = mesh_.faceCentres();
    const vectorField& C = mesh_.cellCentres();

    PstreamBuffers pBufs(Pstream::commsTypes::nonBlocking);

    forAll(mesh_.boundary(), patchi)
    {
        if (patchKinds_[patchi] != patchKind::coupled) continue;

        const fvPatch& patch = mesh_.boundary()[patchi];
        const labelUList& fc = patch.faceCells();
        scalarList send(fc.size()*nPhases_*nExchange);

        label i = 0;
        forAll(fc, facei)
        {
            faceSides
            (
                fc[facei],
                Cf[patch.start() + facei] - C[fc[facei]],
                cellFace_
            );
            for (label k = 0; k < nPhases_; ++k)
            {
                const phaseSide& s = cellFace_[k];
                send[i++] = s.alpha;
                send[i++] = s.rho;
                send[i++] = s.p;
                send[i++] = s.a;
                for (int j = 0; j < 3; ++j) send[i++] = s.U(j);
                for (int j = 0; j < 9; ++j) send[i++] = s.A(j/3, j%3);
                send[i++] = s.epsP;
                send[i++] = s.wP;
            }
        }

        const processorPolyPatch& pp =
            refCast<const processorPolyPatch>(patch.patch());
        UOPstream toNbr(pp.neighbProcNo(), pBufs);
        toNbr << send;
    }

    pBufs.finishedSends();

    forAll(mesh_.boundary(), patchi)
    {
        if (patchKinds_[patchi] != patchKind::coupled) continue;
        const processorPolyPatch& pp =
            refCast<const processorPolyPatch>
            (
                mesh_.boundary()[patchi].patch()
            );
        UIPstream fromNbr(pp.neighbProcNo(), pBufs);
        fromNbr >> nbrStates_[patchi];
    }
}


void Foam::demSolver::ghostSides
(
    const label patchi,
    const label patchFacei,
    const cobasis::vector& n,
    const std::vector<phaseSide>& cell,
    std::vector<phaseSide>& ghost
) const
{
    const patchKind kind = patchKinds_[patchi];

    for (label k = 0; k < nPhases_; ++k)
    {
        const phaseSide& c = cell[k];
        phaseSide& g = ghost[k];

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
                g.U = (kind == patchKind::mirror) ? (M*c.U).eval() : (-c.U).eval();
                g.A = c.A*M;
                g.sigma = M*c.sigma*M;
                break;
            }

            case patchKind::wedge:
            {
                // The cell side is already rotated into the face plane
                g = c;
                break;
            }

            case patchKind::coupled:
            {
                const scalar* s =
                    &nbrStates_[patchi][(patchFacei*nPhases_ + k)*nExchange];
                g.alpha = s[0];
                g.rho = s[1];
                g.p = s[2];
                g.a = s[3];
                g.U = cobasis::vector(s[4], s[5], s[6]);
                for (int j = 0; j < 9; ++j) g.A(j/3, j%3) = s[7 + j];
                g.epsP = s[16];
                g.wP = s[17];
                completeSide(k, g);
                break;
            }

            default:
            {
                const hyperelasticPhase& ph = phases_.phase(k);
                g.alpha = phases_.alpha(k).boundaryField()[patchi][patchFacei];
                g.rho = phases_.rho(k).boundaryField()[patchi][patchFacei];
                g.p = phases_.p(k).boundaryField()[patchi][patchFacei];
                g.U = toEigen(phases_.U().boundaryField()[patchi][patchFacei]);
                g.A = c.A*std::cbrt(g.rho/c.rho);
                g.epsP = c.epsP;
                g.wP = c.wP;
                completeSide(k, g);
                g.a = std::sqrt(ph.a2Max(g.rho, g.p, g.A));
                break;
            }
        }
    }
    markMinor(ghost);
}


void Foam::demSolver::solveFace
(
    const std::vector<phaseSide>& sideL,
    const std::vector<phaseSide>& sideR,
    const cobasis::matrix& R
)
{
    for (label k = 0; k < nPhases_; ++k)
    {
        faceContribution& fc = faceResult_[k];
        fc.dAlpha[0] = fc.dAlpha[1] = 0;
        fc.dMass[0] = fc.dMass[1] = 0;
        fc.dMomentum[0].setZero();
        fc.dMomentum[1].setZero();
        fc.dEnergy[0] = fc.dEnergy[1] = 0;
        fc.dMassEpsP[0] = fc.dMassEpsP[1] = 0;
        fc.dMassWP[0] = fc.dMassWP[1] = 0;
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
                minorPairs_.push_back({k, j, S});
                return;
            }

            riemannState L, Rs;
            L.rho = sl.rho;
            L.v = R*sl.U;
            L.s = R*(sl.sigma*n);
            L.E = sl.E;
            L.a = sl.a;
            L.cT = sl.cT;
            L.G = phases_.phase(k).eos().fundamentalDerivative(sl.rho, sl.p);
            L.solid = sl.solid;

            Rs.rho = sr.rho;
            Rs.v = R*sr.U;
            Rs.s = R*(sr.sigma*n);
            Rs.E = sr.E;
            Rs.a = sr.a;
            Rs.cT = sr.cT;
            Rs.G = phases_.phase(j).eos().fundamentalDerivative(sr.rho, sr.p);
            Rs.solid = sr.solid;

            const riemannSolution sol = HLLC::solve(L, Rs, waveSpeeds_);

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
        dMassEpsP_[k][c] += magSf*fc.dMassEpsP[side];
        dMassWP_[k][c] += magSf*fc.dMassWP[side];
        if (phases_.phase(k).solid())
        {
            L_[k][c] += (fc.vStarSum/fc.vStarWeight)*SfOut.transpose();
        }
    }
}


void Foam::demSolver::addAdvection
(
    const label c,
    const cobasis::vector& SfOut,
    const std::vector<phaseSide>& own,
    const std::vector<phaseSide>& across
)
{
    for (label k = 0; k < nPhases_; ++k)
    {
        if (!phases_.phase(k).solid()) continue;

        const faceContribution& fc = faceResult_[k];
        const double flux = (fc.vStarSum/fc.vStarWeight).dot(SfOut);

        // Upwind face value; a trace upwind leaves the cell's own value
        const phaseSide& up = (flux < 0) ? across[k] : own[k];
        if (up.trace)
        {
            continue;
        }

        cobasis::matrix Ac(toEigen(phases_.A(k)[c]));
        if (order_ == 2)
        {
            Ac += slopes_[k][c].dtA;
        }
        advection_[k][c] += flux*(up.A - Ac);
    }
}


void Foam::demSolver::internalContacts
(
    const label c,
    const cobasis::vector& nOut,
    const scalar magSf,
    const std::vector<phaseSide>& face
)
{
    // Time-centred alphas of the cell first: most cells hold the same
    // alphas at the centre and on the face, and need no contact
    scalar sumAlpha = 0;
    label main = 0;
    for (label k = 0; k < nPhases_; ++k)
    {
        const scalar a = phases_.alpha(k)[c];
        alphaScratch_[k] =
            a >= phases_.alphaMinor()
          ? min(max(a + slopes_[k][c].dtAlpha, 0.0), 1.0)
          : a;
        if (alphaScratch_[k] > alphaScratch_[main]) main = k;
    }
    for (label k = 0; k < nPhases_; ++k)
    {
        if (k != main) sumAlpha += alphaScratch_[k];
    }
    alphaScratch_[main] = 1 - sumAlpha;

    bool differ = false;
    for (label k = 0; k < nPhases_; ++k)
    {
        if (alphaScratch_[k] != face[k].alpha) differ = true;
    }
    if (!differ)
    {
        return;
    }

    centreSides(c, centre_);
    solveFace(centre_, face, faceFrame::rotation(nOut));

    // Both sides are cell c: the conservative parts cancel exactly, the
    // Lagrangian parts remain
    for (label k = 0; k < nPhases_; ++k)
    {
        const faceContribution& fc = faceResult_[k];
        dAlpha_[k][c] += magSf*(fc.dAlpha[0] + fc.dAlpha[1]);
        dMomentum_[k][c] += magSf*(fc.dMomentum[0] + fc.dMomentum[1]);
        dEnergy_[k][c] += magSf*(fc.dEnergy[0] + fc.dEnergy[1]);
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::demSolver::prepare()
{
    phases_.correctBoundaryConditions();

    const label nCells = mesh_.nCells();
    const vectorField& U = phases_.U().primitiveField();

    for (label k = 0; k < nPhases_; ++k)
    {
        const hyperelasticPhase& ph = phases_.phase(k);
        const scalarField& rho = phases_.rho(k).primitiveField();
        const scalarField& p = phases_.p(k).primitiveField();
        const tensorField& A = phases_.A(k).primitiveField();

        const scalarField& alpha = phases_.alpha(k).primitiveField();
        const scalar aMinor = phases_.alphaMinor();
        const scalar cT2 = ph.cT2();

        for (label celli = 0; celli < nCells; ++celli)
        {
            const cobasis::matrix Ac(toEigen(A[celli]));
            sigma_[k][celli] = ph.sigma(p[celli], Ac);
            E_[k][celli] =
                ph.e(rho[celli], p[celli], Ac) + 0.5*magSqr(U[celli]);

            // The acoustic eigenproblem for the phases that set the time
            // step; a minor phase (a trace is unstrained) takes the
            // small-strain speed c_h^2 + 4/3 mu/rho0
            a_[k][celli] = std::sqrt
            (
                alpha[celli] < aMinor
              ? ph.eos().c2(rho[celli], p[celli]) + 4.0/3.0*cT2
              : ph.a2Max(rho[celli], p[celli], Ac)
            );
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

    // Largest longitudinal speed among the phases that are not minor
    // (above alphaMinor and massFractionMinor)
    const scalarField& rhoMix = phases_.rhoMixture().primitiveField();
    const scalar Ymin = phases_.massFractionMinor();
    scalarField aMax(nCells, 0);
    for (label k = 0; k < nPhases_; ++k)
    {
        const scalarField& alpha = phases_.alpha(k).primitiveField();
        const scalarField& rho = phases_.rho(k).primitiveField();
        for (label celli = 0; celli < nCells; ++celli)
        {
            if
            (
                alpha[celli] >= phases_.alphaMinor()
             && alpha[celli]*rho[celli] >= Ymin*rhoMix[celli]
            )
            {
                aMax[celli] = max(aMax[celli], a_[k][celli]);
            }
        }
    }

    scalarField sumLambda(nCells, 0);
    forAll(nei, facei)
    {
        const scalar magS = magSf_[facei];
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
        // No wave crosses an empty or a wedge face (axisymmetry): counting
        // the wedge faces would cut the step by the wedge angle near the axis
        if
        (
            patchKinds_[patchi] == patchKind::empty
         || patchKinds_[patchi] == patchKind::wedge
        )
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
    limitingCell_ = -1;
    const scalarField& V = mesh_.V();
    forAll(V, celli)
    {
        if (sumLambda[celli] > 0 && 2*V[celli]/sumLambda[celli] < dt)
        {
            dt = 2*V[celli]/sumLambda[celli];
            limitingCell_ = celli;
        }
    }
    limitingSpeed_ = limitingCell_ >= 0 ? aMax[limitingCell_] : 0;
    return returnReduce(dt, minOp<scalar>());
}


void Foam::demSolver::hyperbolicStep(const scalar dt, conservedState& q)
{
    const label nCells = mesh_.nCells();
    const labelUList& own = mesh_.owner();
    const labelUList& nei = mesh_.neighbour();
    const vectorField& Sf = mesh_.faceAreas();
    const vectorField& Cf = mesh_.faceCentres();
    const vectorField& C = mesh_.cellCentres();
    const vectorField& U = phases_.U().primitiveField();

    if (order_ == 2)
    {
        computeSlopes(dt);
    }
    else if (reconstructU_)
    {
        gradUCalc_->calculate(phases_.U(), gradU_);
    }
    exchangeCoupled();

    for (label k = 0; k < nPhases_; ++k)
    {
        std::fill(dAlpha_[k].begin(), dAlpha_[k].end(), 0.0);
        std::fill(dMass_[k].begin(), dMass_[k].end(), 0.0);
        std::fill(dEnergy_[k].begin(), dEnergy_[k].end(), 0.0);
        std::fill(dMassEpsP_[k].begin(), dMassEpsP_[k].end(), 0.0);
        std::fill(dMassWP_[k].begin(), dMassWP_[k].end(), 0.0);
        for (label c = 0; c < nCells; ++c)
        {
            dMomentum_[k][c].setZero();
            L_[k][c].setZero();
            advection_[k][c].setZero();
        }
    }

    std::vector<phaseSide> faceO(nPhases_), faceN(nPhases_);

    // Internal faces
    forAll(nei, facei)
    {
        const label o = own[facei];
        const label nb = nei[facei];

        faceSides(o, Cf[facei] - C[o], faceO);
        faceSides(nb, Cf[facei] - C[nb], faceN);

        solveFace(faceO, faceN, frames_[facei]);

        const cobasis::vector S(toEigen(Sf[facei]));
        addToCell(o, 0, magSf_[facei], S);
        addToCell(nb, 1, magSf_[facei], -S);
        addAdvection(o, S, faceO, faceN);
        addAdvection(nb, -S, faceN, faceO);

        if (order_ == 2)
        {
            const cobasis::vector n(S/magSf_[facei]);
            internalContacts(o, n, magSf_[facei], faceO);
            internalContacts(nb, -n, magSf_[facei], faceN);
        }
    }

    // Boundary faces
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

        cobasis::matrix T(cobasis::matrix::Identity());
        if (kind == patchKind::wedge)
        {
            T = toEigen
            (
                refCast<const wedgePolyPatch>(patch.patch()).faceT()
            );
        }

        forAll(fc, i)
        {
            const label facei = start + i;
            const label celli = fc[i];
            const cobasis::vector S(toEigen(Sf[facei]));
            const cobasis::vector n(S/magSf_[facei]);

            // On a wedge face: reconstruct at the image of the face
            // centroid in the cell's plane, then rotate into the face
            const vector d
            (
                kind == patchKind::wedge
              ? vector
                (
                    (
                        refCast<const wedgePolyPatch>(patch.patch())
                       .faceT().T() & Cf[facei]
                    )
                  - C[celli]
                )
              : vector(Cf[facei] - C[celli])
            );
            faceSides(celli, d, cellFace_);

            if (order_ == 2)
            {
                internalContacts(celli, n, magSf_[facei], cellFace_);
            }

            if (kind == patchKind::wedge)
            {
                // Both sides: the cell state rotated by half the wedge
                // angle into the face plane (NUMERICS.md section 7)
                for (label k = 0; k < nPhases_; ++k)
                {
                    phaseSide& s = cellFace_[k];
                    s.U = T*s.U;
                    s.A = s.A*T.transpose();
                    s.sigma = T*s.sigma*T.transpose();
                }
            }

            ghostSides(patchi, i, n, cellFace_, ghost_);

            if (cellIsLeft)
            {
                solveFace(cellFace_, ghost_, frames_[facei]);
            }
            else
            {
                // Same orientation as on the neighbouring processor
                solveFace(ghost_, cellFace_, faceFrame::rotation(-n));
            }

            addToCell(celli, cellIsLeft ? 0 : 1, magSf_[facei], S);
            addAdvection(celli, S, cellFace_, ghost_);
        }
    }

    // New conservative state
    const scalarField& V = mesh_.V();
    q.alpha.resize(nPhases_);
    q.mass.resize(nPhases_);
    q.momentum.resize(nPhases_);
    q.energy.resize(nPhases_);
    q.A.resize(nPhases_);
    q.epsilonP.resize(nPhases_);
    q.plasticWork.resize(nPhases_);

    for (label k = 0; k < nPhases_; ++k)
    {
        q.alpha[k].resize(nCells);
        q.mass[k].resize(nCells);
        q.momentum[k].resize(nCells);
        q.energy[k].resize(nCells);
        q.A[k].resize(nCells);
        q.epsilonP[k].resize(nCells);
        q.plasticWork[k].resize(nCells);

        const bool solid = phases_.phase(k).solid();
        const scalarField& alpha = phases_.alpha(k).primitiveField();
        const scalarField& rho = phases_.rho(k).primitiveField();
        const tensorField& A = phases_.A(k).primitiveField();
        const scalarField& epsP = phases_.epsilonP(k).primitiveField();
        const scalarField& wP = phases_.plasticWork(k).primitiveField();

        for (label c = 0; c < nCells; ++c)
        {
            const scalar dtByV = dt/V[c];
            const scalar m = alpha[c]*rho[c];
            q.alpha[k][c] = alpha[c] + dtByV*dAlpha_[k][c];
            q.mass[k][c] = m + dtByV*dMass_[k][c];
            q.momentum[k][c] = m*toEigen(U[c]) + dtByV*dMomentum_[k][c];
            q.energy[k][c] = m*E_[k][c] + dtByV*dEnergy_[k][c];

            // Plastic strain and work per unit mass: the upwind values
            // carried by the mass fluxes (a phase left without mass keeps
            // its values; both stay non-negative)
            if (solid && q.mass[k][c] > 0)
            {
                q.epsilonP[k][c] = max
                (
                    (m*epsP[c] + dtByV*dMassEpsP_[k][c])/q.mass[k][c], 0.0
                );
                q.plasticWork[k][c] = max
                (
                    (m*wP[c] + dtByV*dMassWP_[k][c])/q.mass[k][c], 0.0
                );
            }
            else
            {
                q.epsilonP[k][c] = epsP[c];
                q.plasticWork[k][c] = wP[c];
            }

            const cobasis::matrix Ac(toEigen(A[c]));
            if (solid)
            {
                // Time-centred cobasis in the stretching term
                cobasis::matrix Ahalf(Ac);
                if (order_ == 2)
                {
                    Ahalf += slopes_[k][c].dtA;
                }
                q.A[k][c] =
                    Ac - dtByV*advection_[k][c] - dt*(Ahalf*L_[k][c])/V[c];

                // Stored without rotation (an inverted cobasis is left for
                // the relaxation's det(A) check)
                if (!keepCobasisRotation_ && q.A[k][c].determinant() > 0)
                {
                    q.A[k][c] = cobasis::stretch(q.A[k][c]);
                }
            }
            else
            {
                q.A[k][c] = Ac;
            }
        }
    }
}
