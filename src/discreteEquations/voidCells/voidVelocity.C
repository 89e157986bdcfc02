#include "voidVelocity.H"

Foam::voidVelocity::voidVelocity(phaseSystem& phases)
:
    phases_(phases),
    isVoid_(phases.mesh().nCells(), false),
    lo_(phases.mesh().nCells()),
    hi_(phases.mesh().nCells()),
    nCells_(0),
    energy_(0)
{}


void Foam::voidVelocity::correct()
{
    nCells_ = 0;
    energy_ = 0;

    const fvMesh& mesh = phases_.mesh();
    const label nCells = mesh.nCells();
    const label nPhases = phases_.size();
    const phaseRegimes& regimes = phases_.regimes();

    // Void cells of the new state: no phase counts by volume and mass
    boolList& isVoid = isVoid_;
    bool any = false;
    for (label c = 0; c < nCells; ++c)
    {
        scalar mix = 0;
        for (label k = 0; k < nPhases; ++k)
        {
            mix += phases_.alpha(k)[c]*phases_.rho(k)[c];
        }
        bool counts = false;
        for (label k = 0; k < nPhases && !counts; ++k)
        {
            const scalar alpha = phases_.alpha(k)[c];
            counts = !regimes.negligible(alpha, alpha*phases_.rho(k)[c], mix);
        }
        isVoid[c] = !counts;
        any = any || !counts;
    }
    if (!any)
    {
        return;
    }

    // Bounds from the face neighbours' velocities of the last good state
    const vectorField& U0 = phases_.savedU();
    const labelUList& own = mesh.owner();
    const labelUList& nei = mesh.neighbour();
    lo_ = vector::uniform(GREAT);
    hi_ = vector::uniform(-GREAT);
    const auto widen = [this](const label c, const vector& u)
    {
        lo_[c] = min(lo_[c], u);
        hi_[c] = max(hi_[c], u);
    };
    forAll(nei, facei)
    {
        if (isVoid[own[facei]]) widen(own[facei], U0[nei[facei]]);
        if (isVoid[nei[facei]]) widen(nei[facei], U0[own[facei]]);
    }
    const volVectorField& U = phases_.U();
    forAll(mesh.boundary(), patchi)
    {
        if (phases_.boundary()[patchi] != boundaryKinds::kind::coupled)
        {
            continue;
        }
        // A processor patch's values are the cells across (those of the
        // step's start: the boundary values are updated after this)
        const labelUList& fc = mesh.boundary()[patchi].faceCells();
        const fvPatchVectorField& Up = U.boundaryField()[patchi];
        forAll(fc, i)
        {
            if (isVoid[fc[i]]) widen(fc[i], Up[i]);
        }
    }

    // Hold the velocity in the bounds; book the kinetic energy change
    vectorField& u = phases_.U().primitiveFieldRef();
    const scalarField& V = mesh.V();
    for (label c = 0; c < nCells; ++c)
    {
        if (!isVoid[c] || !(lo_[c].x() <= hi_[c].x()))
        {
            continue;
        }
        const vector uNew(max(min(u[c], hi_[c]), lo_[c]));
        if (uNew != u[c])
        {
            scalar m = 0;
            for (label k = 0; k < nPhases; ++k)
            {
                m += phases_.alpha(k)[c]*phases_.rho(k)[c];
            }
            energy_ += 0.5*m*V[c]*(magSqr(uNew) - magSqr(u[c]));
            u[c] = uNew;
            ++nCells_;
        }
    }
}
