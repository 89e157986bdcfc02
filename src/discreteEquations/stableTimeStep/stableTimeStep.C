#include "stableTimeStep.H"
#include "surfaceFields.H"

Foam::stableTimeStep::stableTimeStep(const phaseSystem& phases)
:
    phases_(phases),
    mesh_(phases.mesh()),
    limitingCell_(-1),
    limitingSpeed_(0),
    aMax_(mesh_.nCells()),
    sumLambda_(mesh_.nCells())
{}


void Foam::stableTimeStep::updateMesh()
{
    // (a cell label of the old mesh)
    limitingCell_ = -1;
    limitingSpeed_ = 0;
    aMax_.setSize(mesh_.nCells());
    sumLambda_.setSize(mesh_.nCells());
}


Foam::scalar Foam::stableTimeStep::deltaT(const cellStates& cells) const
{
    const label nCells = mesh_.nCells();
    const labelUList& own = mesh_.owner();
    const labelUList& nei = mesh_.neighbour();
    const vectorField& Sf = mesh_.faceAreas();
    const scalarField& magSf = mesh_.magSf();
    const vectorField& U = phases_.U().primitiveField();

    // Largest longitudinal speed among the phases that are not minor
    // (phaseSystem::minor)
    const scalarField& rhoMix = phases_.rhoMixture().primitiveField();
    scalarField& aMax = aMax_;
    aMax = 0;
    for (label k = 0; k < phases_.size(); ++k)
    {
        const scalarField& alpha = phases_.alpha(k).primitiveField();
        const scalarField& rho = phases_.rho(k).primitiveField();
        for (label celli = 0; celli < nCells; ++celli)
        {
            if
            (
                !phases_.regimes().unresolved
                (
                    k, alpha[celli], alpha[celli]*rho[celli], rhoMix[celli]
                )
            )
            {
                aMax[celli] = max(aMax[celli], cells.a(k, celli));
            }
        }
    }

    scalarField& sumLambda = sumLambda_;
    sumLambda = 0;
    forAll(nei, facei)
    {
        const scalar magS = magSf[facei];
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
        if (phases_.boundary().passive(patchi))
        {
            continue;
        }
        const fvPatch& patch = mesh_.boundary()[patchi];
        const labelUList& fc = patch.faceCells();
        const vectorField& pSf = patch.Sf();
        const scalarField& pMagSf = patch.magSf();
        forAll(fc, i)
        {
            sumLambda[fc[i]] +=
                mag(U[fc[i]] & pSf[i]) + aMax[fc[i]]*pMagSf[i];
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


