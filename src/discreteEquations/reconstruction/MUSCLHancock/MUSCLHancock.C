#include "MUSCLHancock.H"
#include "alphaClosure.H"
#include "foamEigen.H"
#include "fvc.H"
#include "addToRunTimeSelectionTable.H"
#include "readOption.H"

using Foam::foamEigen::toEigen;

namespace Foam
{
namespace reconstructions
{
    defineTypeNameAndDebug(MUSCLHancock, 0);
    addToRunTimeSelectionTable(reconstruction, MUSCLHancock, dictionary);
}
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::reconstructions::MUSCLHancock::MUSCLHancock
(
    const phaseSystem& phases,
    const cellStates& cells,
    const dictionary& dict
)
:
    reconstruction(phases, cells, dict),
    predictor_(phases, dict),
    alphaProfile_(alphaProfile::New(phases, dict)),
    cobasisGradient_
    (
        mesh_,
        // A wall's ghost is the cell's mirror image (docs/numerics.md
        // section 7)
        phases.boundary().limiterNeighbours(false),
        readOption
        (
            dict, "cobasisLimiter", limiterNames, limiter::cellLimited,
            "discreteEquations"
        )
     == limiter::cellLimited
    ),
    slopes_(nPhases_),
    solidSlopes_(nPhases_),
    alphaScratch_(nPhases_),
    slopeCells_(mesh_.nCells(), false),
    alphaCells_(mesh_.nCells(), false),
    gauss_(mesh_)
{
    for (label k = 0; k < nPhases_; ++k)
    {
        slopes_[k].resize(mesh_.nCells());
        if (phases.phase(k).solid())
        {
            solidSlopes_[k].resize(mesh_.nCells());
        }
    }
}


Foam::wordList Foam::reconstructions::MUSCLHancock::keywords() const
{
    wordList valid(reconstruction::keywords());
    valid.append("cobasisLimiter");
    valid.append(hancockPredictor::keywords);
    valid.append(alphaProfile_->keywords());
    return valid;
}


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

void Foam::reconstructions::MUSCLHancock::alphaRange
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
        if (phases_.boundary()[patchi] != boundaryKinds::kind::coupled) continue;
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


void Foam::reconstructions::MUSCLHancock::markSlopeCells(const label k)
{
    // The cells that take slopes of rho, p and A: not minor, not first
    // order (update zeroes the others). The cells that read the alpha
    // slope: at or above alphaMinor in the cell, not first order (below,
    // a phase keeps its cell value at the faces and in the time-centred
    // state, and takes no profile but the linear one)
    const volScalarField& alpha = phases_.alpha(k);
    forAll(slopeCells_, c)
    {
        const bool first = firstOrderCell(c);
        slopeCells_[c] = !phases_.regimes().thin(minAlpha_[c]) && !first;
        alphaCells_[c] = !phases_.regimes().thin(alpha[c]) && !first;
    }
}


void Foam::reconstructions::MUSCLHancock::slopes
(
    const volScalarField& vf,
    vectorField& g,
    const boolList* active
)
{
    if (cellLimitedGauss::matches(mesh_, vf.name()))
    {
        gauss_.grad(vf, g, active);
    }
    else
    {
        g = fvc::grad(vf)().primitiveField();
    }
}


void Foam::reconstructions::MUSCLHancock::scalarSlopes(const label k)
{
    // fvSchemes' gradSchemes; the tutorials' "cellLimited Gauss linear 1"
    // by cellLimitedGauss, the same values without temporary fields,
    // computed and limited only where read (zero elsewhere). A single
    // phase has alpha = 1: no slope
    if (nPhases_ > 1)
    {
        slopes(phases_.alpha(k), gAlpha_, &alphaCells_);
    }
    else
    {
        gAlpha_.setSize(mesh_.nCells());
        gAlpha_ = Zero;
    }

    const volScalarField& rho = phases_.rho(k);
    const volScalarField& p = phases_.p(k);
    if
    (
        cellLimitedGauss::matches(mesh_, rho.name())
     && cellLimitedGauss::matches(mesh_, p.name())
    )
    {
        // Both in one pass over the faces (the same values)
        gauss_.grad(rho, p, gRho_, gP_, &slopeCells_);
    }
    else
    {
        slopes(rho, gRho_, &slopeCells_);
        slopes(p, gP_, &slopeCells_);
    }
}


void Foam::reconstructions::MUSCLHancock::setCellSlopes
(
    const label k,
    const scalar halfDt,
    const vectorField* acceleration
)
{
    const bool solid = phases_.phase(k).solid();
    const scalarField& alpha = phases_.alpha(k).primitiveField();
    const scalarField& rho = phases_.rho(k).primitiveField();
    const scalarField& p = phases_.p(k).primitiveField();
    const vectorField& U = phases_.U().primitiveField();
    const tensorField* A = phases_.cellCobasis(k);

    alphaProfile_->beginPhase(k);
    forAll(alpha, c)
    {
        phaseSlopes& sl = slopes_[k][c];
        solidSlopes* so = solid ? solidSlopes_[k].find(c) : nullptr;
        const vector* a = acceleration ? &(*acceleration)[c] : nullptr;

        // A cell the step takes at first order (the a posteriori
        // fall-back) keeps only the velocity gradient, as the firstOrder
        // reconstruction does
        const bool first = firstOrderCell(c);
        sl.minor = phases_.regimes().thin(minAlpha_[c]);
        sl.sharp =
            alphaProfile_->setProfile
            (
                k, c, first, alpha[c], minAlpha_[c], maxAlpha_[c],
                gAlpha_[c], U[c], halfDt, sl.alpha
            );

        if (sl.minor || first)
        {
            // A first-order cell's faces read the velocity slope, gradU_,
            // and the zero slopes of the others; a minor phase's face
            // states are its cell state (faceState). A solid has no
            // record here (zero cobasis slopes and increment). The
            // time-centred states read the zero increments
            sl.gRho.setZero();
            sl.gP.setZero();
            hancockPredictor::withoutSlopes(halfDt, a, sl, so);
            continue;
        }

        // A solid's cobasis slopes are in place (cobasisGradient)
        sl.gRho = toEigen(gRho_[c]);
        sl.gP = toEigen(gP_[c]);
        predictor_.predict
        (
            k, c, halfDt, rho[c], p[c], U[c], A ? (*A)[c] : tensor::I,
            gradU(k, c), a, sl, so
        );
    }
}


void Foam::reconstructions::MUSCLHancock::closeCentreAlphas()
{
    const label nCells = mesh_.nCells();
    centreAlpha_.resize(nCells*nPhases_);
    for (label c = 0; c < nCells; ++c)
    {
        double* alpha = &centreAlpha_[c*nPhases_];
        scalar sumAlpha = 0;
        label main = 0;
        for (label k = 0; k < nPhases_; ++k)
        {
            const scalar a = phases_.alpha(k)[c];
            alpha[k] =
                !phases_.regimes().thin(a)
              ? min(max(a + slopes_[k][c].alpha.dt, 0.0), 1.0)
              : a;
            if (alpha[k] > alpha[main]) main = k;
        }
        for (label k = 0; k < nPhases_; ++k)
        {
            if (k != main) sumAlpha += alpha[k];
        }
        alpha[main] = 1 - sumAlpha;
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::reconstructions::MUSCLHancock::update
(
    const scalar dt,
    const vectorField* acceleration
)
{
    velocityGradient();

    for (label k = 0; k < nPhases_; ++k)
    {
        const volScalarField& alpha = phases_.alpha(k);

        // The minor-phase rule (below alphaMinor in the cell or any
        // neighbour) and the cells whose slopes are read
        alphaRange(alpha, minAlpha_, maxAlpha_);
        markSlopeCells(k);
        if (phases_.phase(k).solid())
        {
            solidSlopes_[k].assign(slopeCells_);
        }

        // The limited slopes: alpha (as its profile takes it), rho, p and
        // a solid's cobasis
        scalarSlopes(k);
        alphaProfile_->correctSlopes(alpha, minAlpha_, maxAlpha_, gAlpha_);
        if (phases_.phase(k).solid())
        {
            cobasisGradient_.calculate
            (
                phases_.A(k), slopeCells_, solidSlopes_[k]
            );
        }

        // Per cell: alpha's profile, the slopes, the half-step increments
        setCellSlopes(k, 0.5*dt, acceleration);
    }

    closeCentreAlphas();
}


void Foam::reconstructions::MUSCLHancock::centreAlphas
(
    const label c,
    std::vector<double>& alpha
) const
{
    // Computed once per cell and step by update
    const double* a = &centreAlpha_[c*nPhases_];
    for (label k = 0; k < nPhases_; ++k)
    {
        alpha[k] = a[k];
    }
}


void Foam::reconstructions::MUSCLHancock::describe(Ostream& os) const
{
    os  << "MUSCL-Hancock, velocity limiter "
        << (gradUCalc_.limited() ? "cellLimited" : "none")
        << ", cobasis limiter "
        << (cobasisGradient_.limited() ? "cellLimited" : "none");
    predictor_.describe(os);
    alphaProfile_->describe(os);
}


void Foam::reconstructions::MUSCLHancock::faceState
(
    const label celli,
    const label facei,
    const vector& d,
    std::vector<phaseSide>& s
) const
{
    const vector& Uc = phases_.U()[celli];

    // Second order: alpha of every phase but the cell's largest, which
    // closes the sum; a minor phase (below alphaMinor in the cell) keeps
    // its cell value, so it never offers the faces more than it holds
    const cobasis::vector de(toEigen(d));
    const scalar alphaMin = phases_.regimes().alphaMin();
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
        const phaseSlopes& sl = slopes_[k][celli];
        const scalar af =
            sl.sharp
          ? alphaProfile_->profileFaceAlpha(k, celli, facei, d)
          : sl.alpha.face(ac, de);
        alphaScratch_[k] =
            phases_.regimes().thin(ac)
          ? ac
          : min(max(af, alphaMin), 1 - alphaMin);
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

    const bool first = firstOrderCell(celli);
    for (label k = 0; k < nPhases_; ++k)
    {
        const phaseSlopes& sl = slopes_[k][celli];
        phaseSide& sk = s[k];
        sk.alpha = alphaScratch_[k];

        if (sl.minor && !first)
        {
            // No slopes: the cell state, moved by the body acceleration
            // only; its stress, energy and wave speed are the cell's. But
            // a phase that slides in the band keeps its own velocity
            // slope: beside a cell it does not hold, its faces would
            // otherwise take its cell velocity while its next cell's
            // faces take the slope, and its shear waves would answer the
            // jump (a rotation's omega h/2) with a traction that drags it
            cobasis::vector U(toEigen(Uc) + sl.dtU);
            if (ownVelocityGradient(k, celli))
            {
                U += toEigen(phaseGradU_[k][celli]).transpose()*de;
            }
            cellSide(k, celli, U, sk);
            continue;
        }

        const hyperelasticPhase& ph = phases_.phase(k);
        const double rhoc = phases_.rho(k)[celli];
        const double pc = phases_.p(k)[celli];
        // The phase's own velocity where solids slide (phaseModel::slip)
        const cobasis::vector Uk(toEigen(phases_[k].velocity(Uc, celli)));
        cellCarried(k, celli, sk);
        sk.rho = rhoc + sl.gRho.dot(de) + sl.dtRho;
        sk.p = pc + sl.gP.dot(de) + sl.dtP;
        sk.U = Uk + toEigen(gradU(k, celli)).transpose()*de + sl.dtU;
        if (ph.solid())
        {
            // (a cell without a record: zero slopes and increment)
            const solidSlopes* so = solidSlopes_[k].find(celli);
            if (so)
            {
                sk.A =
                    toEigen(phases_.A(k)[celli])
                  + de(0)*so->gA[0] + de(1)*so->gA[1] + de(2)*so->gA[2]
                  + so->dtA;
            }
            else
            {
                sk.A = toEigen(phases_.A(k)[celli]);
            }
        }
        else
        {
            // A fluid has no cobasis (its stress is -p I; phaseModel): its
            // side takes the identity, unused
            sk.A.setIdentity();
        }

        if
        (
            !ph.eos().admissible(sk.rho, sk.p)
         || (ph.solid() && !(sk.A.determinant() > 0))
        )
        {
            // An inadmissible predicted state: the cell value
            sk.rho = rhoc;
            sk.p = pc;
            sk.U = Uk;
            sk.A = cobasisOrIdentity(k, celli);
        }
        completeSide(k, sk);

        // a_f^2 = c_h^2(face) + (a_cell^2 - c_h^2(cell)), >= a_cell^2/4
        const double ac2 = sqr(cells_.a(k, celli));
        const double a2 =
            ph.eos().c2(sk.rho, sk.p) + ac2 - cells_.c2h(k, celli);
        sk.a = std::sqrt(max(a2, 0.25*ac2));
    }
    markMinor(s);
    setSlideNormal(celli, s);
}


void Foam::reconstructions::MUSCLHancock::centreState
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
        sk.U = toEigen(phases_[k].velocity(Uc, celli));
        sk.A = cobasisOrIdentity(k, celli);
        sk.a = cells_.a(k, celli);
        cellCarried(k, celli, sk);

        const phaseSlopes& sl = slopes_[k][celli];
        if (!phases_.regimes().thin(sk.alpha))
        {
            sk.alpha = min(max(sk.alpha + sl.alpha.dt, 0.0), 1.0);
        }

        const hyperelasticPhase& ph = phases_.phase(k);
        const double rho = sk.rho + sl.dtRho;
        const double p = sk.p + sl.dtP;
        const solidSlopes* so =
            ph.solid() ? solidSlopes_[k].find(celli) : nullptr;
        const cobasis::matrix A(so ? (sk.A + so->dtA).eval() : sk.A);
        if
        (
            ph.eos().admissible(rho, p)
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

    // The cell's largest phase closes the sum
    floorAndClose
    (
        nPhases_,
        0.0,
        [&s](const label k) -> double& { return s[k].alpha; }
    );
    markMinor(s);
    setSlideNormal(celli, s);
}


