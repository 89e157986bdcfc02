#include "phaseRemap.H"
#include "foamEigen.H"

using Foam::foamEigen::toEigen;


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::phaseRemap::phaseRemap(phaseSystem& phases)
:
    phases_(phases),
    alpha_(phases.size()),
    rho_(phases.size()),
    p_(phases.size()),
    A_(phases.size()),
    carried_(phases.size())
{}


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

Foam::scalar Foam::phaseRemap::e(const label k, const label o) const
{
    const hyperelasticPhase& law = phases_.phase(k);
    return
        law.solid()
      ? law.e(rho_[k][o], p_[k][o], toEigen(A_[k][o]))
      : law.eos().e(rho_[k][o], p_[k][o]);
}


Foam::vector Foam::phaseRemap::velocity(const label k, const label o) const
{
    const label i = phases_[k].slipIndex();
    return
        i < 0
      ? U_[o]
      : U_[o]
      + vector(carried_[k][i][o], carried_[k][i + 1][o], carried_[k][i + 2][o]);
}


void Foam::phaseRemap::copy(const label c, const label o)
{
    phases_.U().primitiveFieldRef()[c] = U_[o];
    for (label k = 0; k < phases_.size(); ++k)
    {
        phaseModel& phase = phases_[k];
        phase.alpha().primitiveFieldRef()[c] = alpha_[k][o];
        phase.rho().primitiveFieldRef()[c] = rho_[k][o];
        phase.p().primitiveFieldRef()[c] = p_[k][o];
        if (phase.solid())
        {
            phase.A().primitiveFieldRef()[c] = A_[k][o];
        }
        forAll(carried_[k], i)
        {
            phase.carried(i).primitiveFieldRef()[c] = carried_[k][i][o];
        }
    }
}


Foam::scalar Foam::phaseRemap::merge(const label c, const labelUList& old)
{
    const label nPhases = phases_.size();
    const scalar Vc = phases_.mesh().V()[c];

    scalar Vold = 0;
    for (const label o : old)
    {
        Vold += V_[o];
    }

    // Per phase: the sums over the merged cells
    List<scalar> vol(nPhases, Zero);
    List<scalar> mass(nPhases, Zero);
    List<vector> mom(nPhases, Zero);
    List<scalar> energy(nPhases, Zero);
    List<scalar> pVol(nPhases, Zero);
    scalar kinetic = 0;
    for (label k = 0; k < nPhases; ++k)
    {
        for (const label o : old)
        {
            const scalar v = alpha_[k][o]*V_[o];
            const scalar m = v*rho_[k][o];
            const vector u(velocity(k, o));
            vol[k] += v;
            pVol[k] += v*p_[k][o];
            mass[k] += m;
            mom[k] += m*u;
            energy[k] += m*(e(k, o) + 0.5*magSqr(u));
            kinetic += 0.5*m*magSqr(u);
        }
    }

    // One velocity: the merged cells' centre of mass
    scalar M = 0;
    vector P(Zero);
    for (label k = 0; k < nPhases; ++k)
    {
        M += mass[k];
        P += mom[k];
    }
    const vector U(M > 0 ? P/M : U_[old[0]]);
    phases_.U().primitiveFieldRef()[c] = U;

    // The heaviest phase pays for the traces' states
    label heaviest = 0;
    for (label k = 1; k < nPhases; ++k)
    {
        if (mass[k] > mass[heaviest])
        {
            heaviest = k;
        }
    }

    const phaseRegimes& regimes = phases_.regimes();
    List<scalar> eNew(nPhases, Zero);
    scalar unpaid = 0;

    for (label k = 0; k < nPhases; ++k)
    {
        phaseModel& phase = phases_[k];
        const hyperelasticPhase& law = phases_.phase(k);
        const scalar alpha = vol[k]/Vold;
        phase.alpha().primitiveFieldRef()[c] = alpha;

        // Mass kept exactly on the new cell's volume
        scalar rho = 0;
        if (mass[k] > 0 && alpha > 0)
        {
            rho = mass[k]/(alpha*Vc);
        }
        else
        {
            // Absent from every merged cell: the first one's density
            rho = rho_[k][old[0]];
        }
        phase.rho().primitiveFieldRef()[c] = rho;

        // Carried variables: mass means (a phase without mass keeps the
        // first cell's); slip velocities are not carried
        forAll(carried_[k], i)
        {
            const bool slip =
                phase.carriesSlip()
             && i >= phase.slipIndex() && i < phase.slipIndex() + 3;
            scalar sum = 0;
            for (const label o : old)
            {
                sum += alpha_[k][o]*rho_[k][o]*V_[o]*carried_[k][i][o];
            }
            phase.carried(i).primitiveFieldRef()[c] =
                slip ? 0
              : mass[k] > 0 ? sum/mass[k]
              : carried_[k][i][old[0]];
        }

        const bool trace = regimes.trace(alpha) || !(mass[k] > 0);

        // Cobasis: the mass mean, made compatible with the density
        tensor A(Zero);
        if (law.solid())
        {
            if (!(mass[k] > 0))
            {
                A = A_[k][old[0]];
            }
            else
            {
                for (const label o : old)
                {
                    A += (alpha_[k][o]*rho_[k][o]*V_[o]/mass[k])*A_[k][o];
                }
                const scalar d = det(A);
                if (!(d > 0))
                {
                    // Cobases that cancel: the heaviest merged cell's
                    label big = old[0];
                    for (const label o : old)
                    {
                        if
                        (
                            alpha_[k][o]*rho_[k][o]*V_[o]
                          > alpha_[k][big]*rho_[k][big]*V_[big]
                        )
                        {
                            big = o;
                        }
                    }
                    A = A_[k][big];
                }
                A *= cbrt(rho/(law.rho0()*det(A)));
            }
            phase.A().primitiveFieldRef()[c] = A;
        }

        if (trace)
        {
            // The merged cells' mean pressure (the relaxation sets a
            // trace's); the energy it changes is paid by the heaviest
            // phase below
            const scalar p =
                vol[k] > 0 ? pVol[k]/vol[k] : p_[k][old[0]];
            phase.p().primitiveFieldRef()[c] = p;
            const scalar eTrace =
                law.solid() ? law.e(rho, p, toEigen(A)) : law.eos().e(rho, p);

            // Its share of the total as any phase's (below), less what
            // its state holds
            unpaid +=
                energy[k] - (mom[k] & U) + mass[k]*magSqr(U)
              - mass[k]*(eTrace + 0.5*magSqr(U));
        }
        else
        {
            // Total energy kept: the phase's own kinetic energy change to
            // the cell's velocity heats it, 1/2 |u_k - U|^2 per unit mass
            // (e_k = E_k/m_k - u_k.U + |U|^2/2)
            eNew[k] = energy[k]/mass[k] - (mom[k] & U)/mass[k] + 0.5*magSqr(U);
        }
    }

    // The traces' energy to the heaviest phase, then the pressures
    if (mass[heaviest] > 0)
    {
        eNew[heaviest] += unpaid/mass[heaviest];
    }
    for (label k = 0; k < nPhases; ++k)
    {
        phaseModel& phase = phases_[k];
        const scalar alpha = phase.alpha()[c];
        if (regimes.trace(alpha) || !(mass[k] > 0))
        {
            continue;
        }
        const hyperelasticPhase& law = phases_.phase(k);
        const scalar rho = phase.rho()[c];
        phase.p().primitiveFieldRef()[c] =
            law.solid()
          ? law.p(rho, eNew[k], toEigen(phase.A()[c]))
          : law.eos().p(rho, eNew[k]);
    }

    return kinetic - 0.5*M*magSqr(U);
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::phaseRemap::store()
{
    V_ = phases_.mesh().V();
    U_ = phases_.U().primitiveField();
    for (label k = 0; k < phases_.size(); ++k)
    {
        const phaseModel& phase = phases_[k];
        alpha_[k] = phase.alpha().primitiveField();
        rho_[k] = phase.rho().primitiveField();
        p_[k] = phase.p().primitiveField();
        if (phase.solid())
        {
            A_[k] = phase.A().primitiveField();
        }
        carried_[k].setSize(phase.nCarried());
        forAll(carried_[k], i)
        {
            carried_[k][i] = phase.carried(i).primitiveField();
        }
    }
}


Foam::scalar Foam::phaseRemap::apply(const mapPolyMesh& map)
{
    const label nCells = phases_.mesh().nCells();
    const labelList& cellMap = map.cellMap();

    // The cells merged into each new cell
    labelList mergedFrom(nCells, -1);
    const List<objectMap>& merged = map.cellsFromCellsMap();
    forAll(merged, i)
    {
        mergedFrom[merged[i].index()] = i;
    }

    scalar heat = 0;
    for (label c = 0; c < nCells; ++c)
    {
        if (mergedFrom[c] >= 0)
        {
            heat += merge(c, merged[mergedFrom[c]].masterObjects());
        }
        else if (cellMap[c] >= 0)
        {
            copy(c, cellMap[c]);
        }
        else
        {
            FatalErrorInFunction
                << "Cell " << c << " of the changed mesh comes from no cell"
                << " of the old one: a change the remap does not handle"
                << abort(FatalError);
        }
    }

    phases_.correctBoundaryConditions();
    phases_.correctMixture();

    return returnReduce(heat, sumOp<scalar>());
}


// ************************************************************************* //
