/*---------------------------------------------------------------------------*\
  impactFoam: Eulerian multiphase elastic-plastic impact solver for OpenFOAM
-------------------------------------------------------------------------------
Description
    mechanicalRelaxation: fluids torn open (the vacuum floor pMin + pVacuum)
    and fluids below their vacuum density (held on their isentrope).
\*---------------------------------------------------------------------------*/

#include "mechanicalRelaxation.H"

// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

void Foam::mechanicalRelaxation::vacuumCap(const label c, const label k)
{
    const Pair<scalar>& ref = phases_.referenceIsentrope(k);
    const scalar eIs = phases_.phase(k).eos().eIsentropic
    (
        1/cell_.v[k], ref.first(), ref.second()
    );
    if (cell_.e[k] > eIs)
    {
        ledger_.pay(cell_, c, cell_.heaviestActive(k), cell_.m[k]*(eIs - cell_.e[k]));
        cell_.e[k] = eIs;
        ledger_.countVacuum();
    }
}



bool Foam::mechanicalRelaxation::vacuumFloor(const label c, const label k)
{
    // The fluid k is set to pMin + pVacuum at its density, or colder: to
    // the isentrope through its state before the step if that is lower (a
    // gas expanding into a vacuum follows its isentrope; at the floor's
    // constant pressure its sound speed, sqrt(gamma p/rho) for a gas, would
    // grow without bound as the density falls, and the time step would
    // collapse with it). The energy this takes comes from the heaviest
    // other phase that is not a trace, if any
    const equationOfState& eos = phases_.phase(k).eos();
    const scalar rho = 1/cell_.v[k];
    const scalar pMin = eos.pMin(rho);
    scalar eFloor = eos.e(rho, pMin + phases_.regimes().pVacuum());

    const scalar rhoOld = phases_.rho(k)[c];
    const scalar pOld = phases_.p(k)[c];
    if (rhoOld > 0 && eos.admissible(rhoOld, pOld))
    {
        const scalar eIs = eos.eIsentropic(rho, rhoOld, eos.e(rhoOld, pOld));
        if (eIs < eFloor && eos.p(rho, eIs) > pMin)
        {
            eFloor = eIs;
        }
    }

    // Alone (the other phases traces), the fluid's floor adds at most
    // alpha pVacuum/(gamma - 1) per unit volume, counted
    ledger_.pay(cell_, c, cell_.heaviestActive(k), cell_.m[k]*(eFloor - cell_.e[k]));
    cell_.e[k] = eFloor;
    ledger_.countVacuum();
    return true;
}



void Foam::mechanicalRelaxation::screenEnergies
(
    const label c,
    const scalar mass
)
{
    for (label k = 0; k < nPhases_; ++k)
    {
        if (cell_.trace[k]) continue;
        const equationOfState& eos = phases_.phase(k).eos();
        if (!(1/cell_.v[k] < eos.rhoMax()))
        {
            // Beyond the highest density of the equation of state (the
            // pole of a Mie-Grueneisen Hugoniot) there is no pressure
            checks_.fail(c, k, "rho>=rhoMax", 1/cell_.v[k]);
            continue;
        }
        const scalar pk = eos.p(1/cell_.v[k], cell_.e[k]);
        if (!(pk > eos.pMin(1/cell_.v[k])))
        {
            if
            (
                phases_.regimes().negligible(cell_.alpha[k], cell_.m[k], mass)
            )
            {
                cell_.trace[k] = true;
            }
            else if
            (
                phases_.regimes().vacuumFloor() && !phases_.phase(k).solid()
             && vacuumFloor(c, k)
            )
            {}
            else
            {
                checks_.fail(c, k, "p", pk);
            }
        }
        else if (1/cell_.v[k] < rhoVacuum_[k])
        {
            vacuumCap(c, k);
        }
    }
}



void Foam::mechanicalRelaxation::vacuumAfterRelaxation(const label c)
{
    for (label k = 0; k < nPhases_; ++k)
    {
        const equationOfState& eos = phases_.phase(k).eos();
        if
        (
            phases_.regimes().vacuumFloor() && !cell_.trace[k]
         && !phases_.phase(k).solid()
         && 1/cell_.v[k] < eos.rhoMax()
         && !(eos.p(1/cell_.v[k], cell_.e[k]) > eos.pMin(1/cell_.v[k]))
        )
        {
            vacuumFloor(c, k);
        }
    }
}


// ************************************************************************* //
