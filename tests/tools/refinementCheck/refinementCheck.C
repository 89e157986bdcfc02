/*---------------------------------------------------------------------------*\
  impactFoam: Eulerian multiphase elastic-plastic impact solver for OpenFOAM
-------------------------------------------------------------------------------
Application
    refinementCheck

Description
    Test tool: a refine / unrefine cycle of the case's mesh and phase state
    (adaptiveRefinement with constant/refinementProperties, phaseRemap), with no
    time step between. From the state at the start time:
    1. maxRefinement times: refine where the criteria mark cells;
    2. then, with no cell marked, unrefine until nothing changes;
    3. then once more refine where the criteria mark, and write the state
       at a new time (-write): mesh, fields and levels.
    After each change of the mesh it prints one line
        cells <n> mass <m_1 ... m_K> momentum <x y z> energy <E> heat <Q>
    (n over all processors; m_k each phase's mass, the momentum and the
    total energy of all phases, from phaseSystem's sums; Q the kinetic
    energy turned into heat so far), and after step 2 the largest
    difference of the state (U; each phase's alpha, rho, specific internal
    energy, cobasis and carried variables) from the start, relative to
    each field's largest magnitude (the energy to the phase's largest
    c^2), and the field's index in that list:
        roundTrip <d> (field <i>)
    (the children of a split cell copy it and the merged cell of eight
    copies is the cell again, so d is round-off).

Usage
    refinementCheck [-parallel] [-case dir] [-write]

\*---------------------------------------------------------------------------*/

#include "fvCFD.H"
#include "phaseSystem.H"
#include "adaptiveRefinement.H"
#include "foamEigen.H"
#include "Tuple2.H"

using namespace Foam;

namespace
{

void report(const phaseSystem& phases, const adaptiveRefinement& refinement)
{
    Info<< "cells " << phases.mesh().globalData().nTotalCells() << " mass";
    vector momentum(Zero);
    for (label k = 0; k < phases.size(); ++k)
    {
        scalar m = 0;
        vector P(Zero);
        scalar kinetic = 0;
        phases.phaseMotion(k, m, P, kinetic);
        Info<< ' ' << m;
        momentum += P;
    }
    Info<< " momentum " << momentum.x() << ' ' << momentum.y() << ' '
        << momentum.z() << " energy " << phases.totals().second()
        << " heat " << refinement.heat() << endl;
}


//- The state as one list per field and its scale, for the round trip
List<Tuple2<scalarField, scalar>> state(const phaseSystem& phases)
{
    List<Tuple2<scalarField, scalar>> s;
    const auto add = [&s](const scalarField& f, scalar scale = 0)
    {
        if (scale <= 0)
        {
            scale = max(gMax(mag(f)()), VSMALL);
        }
        s.append(Tuple2<scalarField, scalar>(f, scale));
    };
    for (direction d = 0; d < 3; ++d)
    {
        add(phases.U().primitiveField().component(d));
    }
    for (label k = 0; k < phases.size(); ++k)
    {
        add(phases.alpha(k).primitiveField());
        add(phases.rho(k).primitiveField());
        // The specific internal energy over the largest c^2 (the energy
        // scale of the equation of state), not the pressure: a metal's
        // pressure near zero is the difference of terms of the size of
        // its bulk modulus
        const hyperelasticPhase& law = phases.phase(k);
        scalarField e(phases.mesh().nCells());
        scalar c2 = 0;
        forAll(e, c)
        {
            const scalar rho = phases.rho(k)[c];
            const scalar p = phases.p(k)[c];
            e[c] =
                law.solid()
              ? law.e(rho, p, foamEigen::toEigen(phases.A(k)[c]))
              : law.eos().e(rho, p);
            c2 = max(c2, law.eos().c2(rho, p));
        }
        reduce(c2, maxOp<scalar>());
        add(e, c2);
        if (phases[k].solid())
        {
            for (direction d = 0; d < 9; ++d)
            {
                add(phases.A(k).primitiveField().component(d));
            }
        }
        for (label i = 0; i < phases[k].nCarried(); ++i)
        {
            add(phases[k].carried(i).primitiveField());
        }
    }
    return s;
}

} // End namespace


int main(int argc, char *argv[])
{
    argList::addBoolOption("write", "write the refined state at a new time");

    #include "setRootCase.H"
    #include "createTime.H"
    #include "createMesh.H"

    phaseSystem phases(mesh);
    autoPtr<adaptiveRefinement> refinement
    (
        adaptiveRefinement::New(mesh, phases)
    );
    if (!refinement)
    {
        FatalErrorInFunction
            << "No constant/refinementProperties" << exit(FatalError);
    }

    IOstream::defaultPrecision(16);
    Info().precision(16);
    const List<Tuple2<scalarField, scalar>> start(state(phases));
    report(phases, refinement());

    const label maxLevel =
        readLabel
        (
            IOdictionary
            (
                IOobject
                (
                    "refinementProperties",
                    runTime.constant(),
                    mesh,
                    IOobject::MUST_READ
                )
            ).lookup("maxRefinement")
        );

    for (label i = 0; i < maxLevel; ++i)
    {
        bitSet marked(mesh.nCells());
        refinement->mark(marked);
        if (refinement->adapt(marked))
        {
            report(phases, refinement());
        }
    }

    while (refinement->adapt(bitSet(mesh.nCells())))
    {
        report(phases, refinement());
    }

    const List<Tuple2<scalarField, scalar>> end(state(phases));
    scalar diff = 0;
    label worst = -1;
    if (end[0].first().size() != start[0].first().size())
    {
        diff = GREAT;
    }
    else
    {
        forAll(start, i)
        {
            const scalar d =
                gMax(mag(end[i].first() - start[i].first())())
               /start[i].second();
            if (d > diff)
            {
                diff = d;
                worst = i;
            }
        }
    }
    Info<< "roundTrip " << diff << " (field " << worst << ")" << endl;

    bitSet marked(mesh.nCells());
    refinement->mark(marked);
    if (refinement->adapt(marked))
    {
        report(phases, refinement());
    }

    if (args.found("write"))
    {
        runTime.setTime(runTime.value() + 1e-9, runTime.timeIndex() + 1);
        refinement->setInstance();
        phases.correctOutputs();
        runTime.writeNow();
        refinement->write();
        Info<< "written " << runTime.timeName() << endl;
    }

    Info<< "End" << endl;
    return 0;
}


// ************************************************************************* //
