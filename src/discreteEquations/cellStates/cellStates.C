#include "cellStates.H"
#include "foamEigen.H"

using Foam::foamEigen::toEigen;


Foam::cellStates::cellStates(const phaseSystem& phases)
:
    phases_(phases),
    E_(phases.size()),
    speeds_(phases.size()),
    sigma_(phases.size())
{
    updateMesh();
}


void Foam::cellStates::updateMesh()
{
    const label nCells = phases_.mesh().nCells();
    for (label k = 0; k < phases_.size(); ++k)
    {
        E_[k].resize(nCells);
        speeds_[k].resize(nCells);
        if (phases_.phase(k).solid())
        {
            sigma_[k].resize(nCells);
        }
    }
}


void Foam::cellStates::update()
{
    const label nCells = phases_.mesh().nCells();
    const vectorField& U = phases_.U().primitiveField();

    for (label k = 0; k < phases_.size(); ++k)
    {
        const phaseModel& phase = phases_[k];
        const hyperelasticPhase& ph = phase.law();
        const scalarField& rho = phase.rho().primitiveField();
        const scalarField& p = phase.p().primitiveField();
        const scalarField& alpha = phase.alpha().primitiveField();
        const phaseRegimes& regimes = phases_.regimes();
        const scalar cT2 = ph.cT2();
        const bool solid = ph.solid();
        const tensorField* A = phase.cellCobasis();

        for (label celli = 0; celli < nCells; ++celli)
        {
            // A fluid's stress is -p I (not stored), it has no cobasis
            // (phaseModel) and its wave speed is c_h
            cobasis::matrix Ac;
            double e;
            if (solid)
            {
                Ac = toEigen((*A)[celli]);
                ph.sigmaAndE(rho[celli], p[celli], Ac, sigma_[k][celli], e);
            }
            else
            {
                e = ph.eos().e(rho[celli], p[celli]);
            }
            // The phase's own velocity where solids slide (phaseModel::slip)
            E_[k][celli] = e + 0.5*magSqr(phase.velocity(U[celli], celli));

            // The acoustic eigenproblem for the phases that set the time
            // step; a minor phase (a trace is unstrained) takes the
            // small-strain speed c_h^2 + 4/3 mu/rho0, c_h^2 floored at 0
            // (a trace heavier than the cell's other phases keeps its own
            // energy, mechanicalRelaxation::relaxTraces, and may sit below
            // pMin: debris smeared into a vacuum)
            speeds& sc = speeds_[k][celli];
            sc.c2h = ph.eos().c2(rho[celli], p[celli]);
            scalar a2;
            if (regimes.thin(alpha[celli]))
            {
                a2 = max(sc.c2h, scalar(0)) + 4.0/3.0*cT2;
            }
            else if (solid)
            {
                a2 = ph.a2Max(rho[celli], p[celli], Ac);
            }
            else
            {
                a2 = sc.c2h;
            }
            sc.a = std::sqrt(a2);
        }
    }
}
