#include "voidVelocity.H"
#include "boundaryFaceTable.H"

Foam::voidVelocity::voidVelocity(phaseSystem& phases)
:
    phases_(phases),
    isVoid_(phases.mesh().nCells(), false),
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

    // Per void cell, over its faces: the bounds of the face neighbours'
    // velocities of the last good state (component by component; min and
    // max do not depend on the order of the faces). Processor neighbours:
    // U's patch values, those of the step's start (the boundary values are
    // updated after this)
    const vectorField& U0 = phases_.savedU();
    const labelUList& own = mesh.owner();
    const labelUList& nei = mesh.neighbour();
    const label nInternal = mesh.nInternalFaces();
    const cellList& cells = mesh.cells();
    const boundaryFaceTable boundaryFace(mesh);
    const volVectorField& U = phases_.U();
    vectorField& u = phases_.U().primitiveFieldRef();
    const scalarField& V = mesh.V();
    for (label c = 0; c < nCells; ++c)
    {
        if (!isVoid[c])
        {
            continue;
        }
        vector lo(vector::uniform(GREAT));
        vector hi(vector::uniform(-GREAT));
        for (const label facei : cells[c])
        {
            vector un;
            if (facei < nInternal)
            {
                un = U0[own[facei] == c ? nei[facei] : own[facei]];
            }
            else
            {
                label patchi, i;
                if
                (
                    !boundaryFace(facei, patchi, i)
                 || phases_.boundary()[patchi] != boundaryKinds::kind::coupled
                )
                {
                    continue;
                }
                un = U.boundaryField()[patchi][i];
            }
            lo = min(lo, un);
            hi = max(hi, un);
        }

        // Hold the velocity in the bounds; book the kinetic energy change
        if (!(lo.x() <= hi.x()))
        {
            continue;
        }
        const vector uNew(max(min(u[c], hi), lo));
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


void Foam::voidVelocity::updateMesh()
{
    isVoid_.setSize(phases_.mesh().nCells());
    isVoid_ = false;
}
