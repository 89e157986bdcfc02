#include "energyBudget.H"
#include "foamEigen.H"
#include "wedgeRevolution.H"
#include "addToRunTimeSelectionTable.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace functionObjects
{
    defineTypeNameAndDebug(energyBudget, 0);
    addToRunTimeSelectionTable(functionObject, energyBudget, dictionary);
}
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::functionObjects::energyBudget::energyBudget
(
    const word& name,
    const Time& runTime,
    const dictionary& dict
)
:
    impactTimeHistory(name, runTime, dict),
    toFull_(1)
{
    vector axis;
    const scalar toFull = wedgeToFull(mesh_, axis);
    toFull_ = toFull > 0 ? toFull : 1;
    start();
}


// * * * * * * * * * * * * * Protected Member Functions  * * * * * * * * * * //

Foam::wordList Foam::functionObjects::energyBudget::columns() const
{
    DynamicList<word> c;
    for (const word& p : phases().names())
    {
        c.append("kinetic." + p);
        c.append("internal." + p);
        c.append("elastic." + p);
        c.append("plasticWork." + p);
    }
    c.append("mass");
    c.append("kinetic");
    c.append("internal");
    c.append("elastic");
    c.append("plasticWork");
    c.append("total");
    c.append("unpaid");
    if (phases().sliding())
    {
        c.append("frictionHeat");
    }
    return wordList(c);
}


Foam::wordList Foam::functionObjects::energyBudget::units() const
{
    // Per phase four energies; then the mass and the energies
    wordList u(4*phases().size() + 7, word("[J]"));
    u[4*phases().size()] = "[kg]";
    if (phases().sliding())
    {
        u.append(word("[J]"));
    }
    return u;
}


Foam::wordList Foam::functionObjects::energyBudget::summaryColumns() const
{
    return wordList({"kinetic", "plasticWork", "total", "unpaid"});
}


void Foam::functionObjects::energyBudget::values(DynamicList<scalar>& row)
{
    const phaseSystem& phases = this->phases();
    const scalarField& V = mesh_.V();
    const vectorField& U = phases.U().primitiveField();
    const label nPhases = phases.size();

    // Per phase: kinetic, internal, elastic, plastic work; and the mass
    // and energy as the solver sums them (phaseSystem::totals, its totals
    // line: the same terms in the same order, so equal to the digit),
    // from the same evaluation of each cell's energies
    List<scalar> sums(4*nPhases, Zero);
    scalar mass = 0;
    scalar energy = 0;
    scalar carried[phaseModel::maxCarried];
    for (label k = 0; k < nPhases; ++k)
    {
        const hyperelasticPhase& ph = phases.phase(k);
        const scalarField& alpha = phases.alpha(k).primitiveField();
        const scalarField& rho = phases.rho(k).primitiveField();
        const scalarField& p = phases.p(k).primitiveField();
        const bool solid = ph.solid();
        const tensorField* A = phases.cellCobasis(k);
        const inelasticModel& inelastic = phases[k].inelastic();
        scalar* s = &sums[4*k];
        forAll(V, c)
        {
            const scalar m = alpha[c]*rho[c]*V[c];
            const scalar u2 = magSqr(phases[k].velocity(U[c], c));
            const scalar eh = ph.eos().e(rho[c], p[c]);
            const scalar ee =
                solid ? ph.elasticEnergy(foamEigen::toEigen((*A)[c])) : 0;
            mass += m;
            energy += m*((eh + ee) + 0.5*u2);
            s[0] += 0.5*m*u2;
            s[1] += m*eh;
            if (solid)
            {
                s[2] += m*ee;
                phases[k].inelasticState(c, carried);
                s[3] += m*inelastic.plasticWork(carried);
            }
        }
    }
    Pstream::listCombineGather(sums, plusEqOp<scalar>());
    Pstream::listCombineScatter(sums);
    reduce(mass, sumOp<scalar>());
    reduce(energy, sumOp<scalar>());

    // (the full body: every figure times toFull_)
    scalar total[4] = {0, 0, 0, 0};
    for (label k = 0; k < nPhases; ++k)
    {
        for (label i = 0; i < 4; ++i)
        {
            row.append(toFull_*sums[4*k + i]);
            total[i] += sums[4*k + i];
        }
    }

    row.append(toFull_*mass);
    for (label i = 0; i < 4; ++i)
    {
        row.append(toFull_*total[i]);
    }
    row.append(toFull_*energy);
    row.append(toFull_*ledger().unpaidEnergy());
    if (phases.sliding())
    {
        row.append(toFull_*ledger().frictionalHeat());
    }
}


// ************************************************************************* //
