#include "demSolver.H"
#include "faceFrame.H"
#include "surfaceFields.H"
#include "wedgePolyPatch.H"
#include "foamEigen.H"
#include "keywordCheck.H"

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
    schemeDict_(schemeDict),
    cells_(phases),
    timeStep_(phases),
    reconstruction_(reconstruction::New(phases, cells_, schemeDict)),
    boundaryStates_(phases),
    assembly_(phases, schemeDict),
    cobasis_(phases, schemeDict),
    acceleration_(nullptr),
    faceO_(nPhases_),
    faceN_(nPhases_),
    ghost_(nPhases_),
    fallback_(phases, schemeDict),
    wedges_(mesh_, phases.boundary(), schemeDict),
    patchForces_(mesh_.boundary().size(), Zero)
{
    reconstruction_->setFirstOrderCells(&fallback_.cells());

    // Each part lists the entries it reads
    wordList valid(reconstruction_->keywords());
    valid.append(assembly_.riemann().keywords());
    valid.append(cobasisTransport::keywords);
    valid.append(firstOrderFallback::keywords);
    valid.append(wedgeImages::keywords);
    checkKeywords(schemeDict, valid, "discreteEquations");

    Info<< "Discrete equations: Riemann solver " << assembly_.riemann().type()
        << ", reconstruction ";
    reconstruction_->describe(Info);
    Info<< ", cobasis rotation "
        << (cobasis_.keepRotation() ? "keep" : "discard") << nl << endl;
}


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

void Foam::demSolver::internalFaces()
{
    const labelUList& own = mesh_.owner();
    const labelUList& nei = mesh_.neighbour();
    const vectorField& Sf = mesh_.faceAreas();
    const scalarField& magSf = mesh_.magSf();
    const vectorField& Cf = mesh_.faceCentres();
    const vectorField& C = mesh_.cellCentres();
    const reconstruction& rec = reconstruction_();
    const bool centred = rec.timeCentred();

    forAll(nei, facei)
    {
        const label o = own[facei];
        const label nb = nei[facei];

        const bool fallback = fallback_.firstOrderFace(facei);
        if (fallback)
        {
            rec.cellMeanState(o, faceO_);
            rec.cellMeanState(nb, faceN_);
        }
        else
        {
            // The offsets of the face centre from the cell centres
            rec.faceState(o, facei, Cf[facei] - C[o], faceO_);
            rec.faceState(nb, facei, Cf[facei] - C[nb], faceN_);
        }

        assembly_.solveFace
        (
            faceO_, faceN_, frame(facei, magSf[facei]), fallback
        );

        const cobasis::vector S(toEigen(Sf[facei]));
        assembly_.addToCell(o, 0, magSf[facei]);
        assembly_.addToCell(nb, 1, magSf[facei]);
        cobasis_.addFace(o, S, faceO_, faceN_, assembly_);
        cobasis_.addFace(nb, -S, faceN_, faceO_, assembly_);

        if (centred)
        {
            const cobasis::vector n(S/magSf[facei]);
            assembly_.internalContacts(o, n, magSf[facei], faceO_, rec);
            assembly_.internalContacts(nb, -n, magSf[facei], faceN_, rec);
        }
    }
}


void Foam::demSolver::boundaryFaces()
{
    const vectorField& Sf = mesh_.faceAreas();
    const vectorField& Cf = mesh_.faceCentres();
    const vectorField& C = mesh_.cellCentres();
    const reconstruction& rec = reconstruction_();
    const bool centred = rec.timeCentred();
    const boundaryKinds& kinds = phases_.boundary();

    // The cell's face state of a face that is not coupled
    std::vector<phaseSide> cellFace(nPhases_);

    patchForces_ = Zero;

    forAll(mesh_.boundary(), patchi)
    {
        const boundaryKinds::kind kind = kinds[patchi];
        if (kind == boundaryKinds::kind::empty || wedges_.isImage(patchi))
        {
            // (an image patch's faces are added with the imaged patch's)
            continue;
        }
        const bool coupled = (kind == boundaryKinds::kind::coupled);
        const bool wedge = (kind == boundaryKinds::kind::wedge);
        const bool imaged = wedges_.imaged(patchi);

        const fvPatch& patch = mesh_.boundary()[patchi];
        const labelUList& fc = patch.faceCells();
        const scalarField& pMagSf = patch.magSf();
        const label start = patch.start();
        const bool cellIsLeft = !coupled || kinds.coupledLeft(patchi);

        // Wedge faces: reconstruct at the image of the face centroid in
        // the cell's plane (Tinv Cf), then rotate into the face plane by
        // half the wedge angle: both sides take that state (section 7)
        cobasis::matrix T(cobasis::matrix::Identity());
        tensor Tinv(tensor::I);
        if (wedge)
        {
            const tensor& faceT =
                refCast<const wedgePolyPatch>(patch.patch()).faceT();
            T = toEigen(faceT);
            Tinv = faceT.T();
        }

        forAll(fc, i)
        {
            const label facei = start + i;
            const label celli = fc[i];
            const cobasis::vector S(toEigen(Sf[facei]));
            const scalar magS = pMagSf[i];
            const cobasis::vector n(S/magS);
            const bool fallback = fallback_.firstOrderFace(facei);

            if (!coupled && fallback)
            {
                rec.cellMeanState(celli, cellFace);
            }
            else if (!coupled)
            {
                // (the offset of the face centre, or of its image, from
                // the cell centre)
                rec.faceState
                (
                    celli, facei,
                    wedge
                  ? vector((Tinv & Cf[facei]) - C[celli])
                  : vector(Cf[facei] - C[celli]),
                    cellFace
                );
            }
            // (a wedge face is never coupled: its rotation below acts on
            // cellFace)
            const std::vector<phaseSide>& side =
                coupled ? boundaryStates_.coupledOwn(patchi, i) : cellFace;

            if (centred)
            {
                assembly_.internalContacts
                (
                    celli, n, magS, side, rec
                );
                if (imaged)
                {
                    wedges_.internalContacts(i, celli, side, rec, assembly_);
                }
            }

            if (wedge)
            {
                for (label k = 0; k < nPhases_; ++k)
                {
                    phaseSide& s = cellFace[k];
                    s.U = T*s.U;
                    if (s.solid)
                    {
                        // (a fluid's cobasis is not read)
                        s.A = s.A*T.transpose();
                    }
                    s.sigma = T*s.sigma*T.transpose();
                }
            }

            if (imaged)
            {
                // Both sides hold the rotated state (7.2): the consistent
                // solution, then the image face's
                assembly_.solveFace
                (
                    side, side, frame(facei, magS), fallback, true
                );
                assembly_.addToCell(celli, 0, magS);
                cobasis_.addFace(celli, S, side, side, assembly_);
                wedges_.addImage(i, celli, side, assembly_, cobasis_);
                continue;
            }

            boundaryStates_.ghost(patchi, i, n, side, ghost_, rec);

            if (cellIsLeft)
            {
                assembly_.solveFace
                (
                    side, ghost_, frame(facei, magS), fallback
                );
            }
            else
            {
                // Same orientation as on the neighbouring processor
                assembly_.solveFace
                (
                    ghost_, side, faceFrame::rotation(-n), fallback
                );
            }

            assembly_.addToCell(celli, cellIsLeft ? 0 : 1, magS);
            if (!coupled && !wedge)
            {
                // (the cell is the left side of a face that is not
                // coupled)
                const cobasis::vector m(assembly_.momentumToSide(0));
                patchForces_[patchi] +=
                    magS*vector(m(0), m(1), m(2));
            }
            cobasis_.addFace
            (
                celli, S, side, ghost_, assembly_
            );
        }
    }
}


void Foam::demSolver::newState(const scalar dt, conservedState& q) const
{
    const label nCells = mesh_.nCells();
    const vectorField& U = phases_.U().primitiveField();
    const scalarField& V = mesh_.V();
    q.alpha.resize(nPhases_);
    q.mass.resize(nPhases_);
    q.momentum.resize(nPhases_);
    q.energy.resize(nPhases_);
    q.A.resize(nPhases_);
    q.carried.resize(nPhases_);

    for (label k = 0; k < nPhases_; ++k)
    {
        q.alpha[k].resize(nCells);
        q.mass[k].resize(nCells);
        q.momentum[k].resize(nCells);
        q.energy[k].resize(nCells);
        q.carried[k].resize(phases_[k].nCarried());
        for (auto& v : q.carried[k])
        {
            v.resize(nCells);
        }

        // A fluid has no cobasis (phaseModel): its entry stays empty
        const bool solid = phases_.phase(k).solid();
        q.A[k].resize(solid ? nCells : 0);
        const phaseRegimes& regimes = phases_.regimes();
        const scalarField& alpha = phases_.alpha(k).primitiveField();
        const scalarField& rho = phases_.rho(k).primitiveField();
        const tensorField* A = phases_.cellCobasis(k);
        const phaseModel& phase = phases_[k];
        const label nCarried = phase.nCarried();

        for (label c = 0; c < nCells; ++c)
        {
            const scalar dtByV = dt/V[c];
            const scalar m = alpha[c]*rho[c];
            q.alpha[k][c] = alpha[c] + dtByV*assembly_.dAlpha(k, c);
            q.mass[k][c] = m + dtByV*assembly_.dMass(k, c);
            q.momentum[k][c] =
                m*toEigen(phase.velocity(U[c], c))
              + dtByV*assembly_.dMomentum(k, c);
            q.energy[k][c] = m*cells_.E(k, c) + dtByV*assembly_.dEnergy(k, c);

            // Carried variables per unit mass: the upwind values carried
            // by the mass fluxes, kept within their bounds (a phase left
            // without mass keeps its values)
            for (label i = 0; i < nCarried; ++i)
            {
                const scalar v = phase.carried(i)[c];
                if (q.mass[k][c] > 0)
                {
                    const carriedVariable& var = phase.carriedInfo()[i];
                    q.carried[k][i][c] = min
                    (
                        max
                        (
                            (m*v + dtByV*assembly_.dMassCarried(k, i, c))
                           /q.mass[k][c],
                            var.lower
                        ),
                        var.upper
                    );
                }
                else
                {
                    q.carried[k][i][c] = v;
                }
            }

            if (!solid)
            {
                continue;
            }
            const cobasis::matrix Ac(toEigen((*A)[c]));
            if (regimes.trace(q.alpha[k][c]))
            {
                // A trace after the step: the relaxation resets its cobasis
                // unstrained and pays its energy (mechanicalRelaxation::
                // relaxTraces), so it is not transported
                q.A[k][c] = Ac;
            }
            else
            {
                // (the time-centred cobasis in the stretching term is the
                // one the face loop advected against)
                q.A[k][c] = cobasis_.update(k, c, dt, V[c], Ac);
            }
        }
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::demSolver::prepare()
{
    // The phases' boundary values are current: the phase system corrects
    // them after every change of the fields (construction, end of a step,
    // restored state)
    cells_.update();

    // Where solids that may slide meet (their velocity relaxation)
    phases_.updateSliding();
}


void Foam::demSolver::updateMesh()
{
    cells_.updateMesh();
    timeStep_.updateMesh();

    // (its options read again: they are those read at the start; the
    // notes of the defaults it takes are not printed again)
    reconstruction_.reset
    (
        reconstruction::New(phases_, cells_, schemeDict_).ptr()
    );

    boundaryStates_.updateMesh();
    assembly_.updateMesh();
    cobasis_.updateMesh();
    fallback_.updateMesh();
    reconstruction_->setFirstOrderCells(&fallback_.cells());
    wedges_.updateMesh();
}


void Foam::demSolver::hyperbolicStep(const scalar dt, conservedState& q)
{
    reconstruction_->update(dt, acceleration_);
    boundaryStates_.update(reconstruction_(), fallback_.faces());
    assembly_.reset();
    cobasis_.reset(reconstruction_());

    internalFaces();
    boundaryFaces();

    newState(dt, q);
}


// ************************************************************************* //
