#include "impactProblem.H"
#include "solidContacts.H"
#include "cutCellFractions.H"
#include "volFields.H"
#include "wallPolyPatch.H"
#include "emptyPolyPatch.H"
#include "wedgePolyPatch.H"
#include "phaseMaterial.H"
#include "clockTime.H"

// * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * * //

Foam::word Foam::impactProblem::patchFieldType
(
    const polyPatch& pp,
    const bool velocity
) const
{
    if (polyPatch::constraintType(pp.type()))
    {
        return pp.type();
    }
    if (velocity && isA<wallPolyPatch>(pp))
    {
        return "slip";
    }
    return "zeroGradient";
}


template<class Type>
void Foam::impactProblem::writeField
(
    const fvMesh& mesh,
    const word& name,
    const dimensionSet& dims,
    const Field<Type>& values
)
{
    const bool velocity = pTraits<Type>::nComponents == 3;
    wordList types(mesh.boundaryMesh().size());
    forAll(types, patchi)
    {
        types[patchi] = patchFieldType(mesh.boundaryMesh()[patchi], velocity);
    }

    GeometricField<Type, fvPatchField, volMesh> field
    (
        IOobject
        (
            name,
            runTime_.timeName(),
            mesh,
            IOobject::NO_READ,
            IOobject::NO_WRITE
        ),
        mesh,
        dimensioned<Type>(dims, Zero),
        types
    );
    field.primitiveFieldRef() = values;
    field.correctBoundaryConditions();

    autoPtr<OFstream> os(files_.open(field.objectPath()));
    os().precision(15);
    field.writeHeader(os());
    field.writeData(os());
    IOobject::writeEndDivider(os());
}


Foam::List<Foam::scalarField> Foam::impactProblem::bodyFractions
(
    const cutCellFractions& cut
) const
{
    List<scalarField> alpha(bodies_.size());
    forAll(bodies_, i)
    {
        const impactBody& b = bodies_[i];
        List<vector> n;
        scalarList d;
        if (b.polyhedron(n, d))
        {
            alpha[i] = cut.fractions(n, d);
        }
        else
        {
            alpha[i] = cut.fractions
            (
                [&b](const point& x) { return b.effectiveDistance(x); }
            );
        }
    }
    return alpha;
}


void Foam::impactProblem::writePhaseProperties()
{
    dictionary out;
    for (const entry& e : phaseProperties_)
    {
        if (!phases_.found(e.keyword()))
        {
            out.add(e.clone(out).ptr());
        }
    }
    // The contact laws between the bodies' solids: impactDict's contacts
    // (or its phaseProperties'), checked against the phases here
    if (dict_.found("contacts", keyType::LITERAL))
    {
        if (out.found("contacts", keyType::LITERAL))
        {
            FatalIOErrorInFunction(dict_)
                << "impactDict: contacts given both at the top level and in"
                << " phaseProperties; keep one" << exit(FatalIOError);
        }
        if (!dict_.isDict("contacts"))
        {
            FatalIOErrorInFunction(dict_)
                << "impactDict: contacts must be a dictionary (a default"
                << " and <phase>.<phase> entries)" << exit(FatalIOError);
        }
        out.add("contacts", dict_.subDict("contacts"));
    }
    boolList solid(phases_.size());
    forAll(phases_, k)
    {
        const word& phase = phases_[k];
        dictionary pd;
        pd.add("material", phaseMaterials_[phase]);
        if (phaseProperties_.isDict(phase))
        {
            phaseMaterial::mergeOnto(pd, phaseProperties_.subDict(phase));
        }
        solid[k] =
            phaseMaterial::phaseDict(phase, pd, runTime_)
           .lookupOrDefault<word>("type", "fluid") == "solid";
        out.add(phase, pd);
    }
    solidContacts(out, phases_, solid);

    autoPtr<OFstream> os
    (
        files_.open(runTime_.path()/runTime_.constant()/"phaseProperties")
    );
    os().precision(15);
    IOobject io("phaseProperties", runTime_.constant(), runTime_);
    io.writeHeader(os(), "dictionary");
    os() << "// The phases of the bodies in order, the ambient's last; each"
        << " from its material" << nl << "// (docs/materials.md) with the"
        << " entries of impactDict's phaseProperties on top" << nl
        << "phases          (";
    forAll(phases_, i)
    {
        os() << (i ? " " : "") << phases_[i];
    }
    os() << ");" << nl << nl;
    out.write(os(), false);
    IOobject::writeEndDivider(os());
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::impactProblem::setFields(const fvMesh& mesh)
{
    checkMesh(mesh);
    clockTime clock;

    const cutCellFractions cut(mesh, geometry_);
    const scalarField& V = cut.revolvedVolume();
    const label nCells = mesh.nCells();

    // Each body's fractions
    List<scalarField> alpha(bodyFractions(cut));
    Info<< "Volume fractions of " << bodies_.size() << " bodies on "
        << nCells << " cells in " << clock.timeIncrement() << " s" << nl
        << endl;

    checkInside(mesh, alpha);
    checkOverlaps(cut, alpha);
    warnResolution();
    warnFailure();

    // The ambient fills the rest (bodies summing above 1 by round-off are
    // scaled back)
    scalarField alphaAmbient(nCells, 0);
    forAll(alphaAmbient, celli)
    {
        scalar s = 0;
        forAll(bodies_, i)
        {
            s += alpha[i][celli];
        }
        if (s > 1)
        {
            forAll(bodies_, i)
            {
                alpha[i][celli] /= s;
            }
            s = 1;
        }
        alphaAmbient[celli] = 1 - s;
    }

    // The members of each phase: body indices, -1 the ambient
    auto members = [&](const word& phase)
    {
        DynamicList<label> m;
        forAll(bodies_, i)
        {
            if (bodies_[i].phase == phase)
            {
                m.append(i);
            }
        }
        if (ambient_.phase == phase)
        {
            m.append(-1);
        }
        return labelList(m);
    };
    auto fractionOf = [&](const label k, const label celli)
    {
        return k < 0 ? alphaAmbient[celli] : alpha[k][celli];
    };
    auto rhoOf = [&](const label k)
    {
        return k < 0 ? ambient_.rho : bodies_[k].rho;
    };

    auto pOf = [&](const label k)
    {
        return k < 0 ? ambient_.p : bodies_[k].p;
    };

    // Pressures: one p where all bodies are at the ambient's; else each
    // phase's own p.<phase> too (volume-weighted over its bodies), so that
    // a cell holding bodies at different pressures starts with each at its
    // own, not at their mean
    bool uniformP = true;
    for (const impactBody& b : bodies_)
    {
        uniformP = uniformP && b.p == ambient_.p;
    }

    for (const word& phase : phases_)
    {
        const labelList m(members(phase));
        scalarField alphaPhase(nCells, 0), rhoPhase(nCells, rhoOf(m[0]));
        scalarField pPhase(nCells, pOf(m[0]));
        forAll(alphaPhase, celli)
        {
            scalar a = 0, mass = 0, pa = 0;
            for (const label k : m)
            {
                a += fractionOf(k, celli);
                mass += fractionOf(k, celli)*rhoOf(k);
                pa += fractionOf(k, celli)*pOf(k);
            }
            alphaPhase[celli] = a;
            if (a > 0)
            {
                rhoPhase[celli] = mass/a;
                pPhase[celli] = pa/a;
            }
        }
        writeField(mesh, "alpha." + phase, dimless, alphaPhase);
        writeField(mesh, "rho." + phase, dimDensity, rhoPhase);
        if (!uniformP)
        {
            writeField(mesh, "p." + phase, dimPressure, pPhase);
        }
    }

    // U: momentum-weighted; p: volume-weighted (uniform where all agree)
    vectorField U(nCells, Zero);
    scalarField p(nCells, ambient_.p);
    const vectorField& C = mesh.C().primitiveField();
    forAll(U, celli)
    {
        vector momentum(alphaAmbient[celli]*ambient_.rho*ambient_.U);
        scalar mass = alphaAmbient[celli]*ambient_.rho;
        scalar pa = alphaAmbient[celli]*ambient_.p;
        forAll(bodies_, i)
        {
            const impactBody& b = bodies_[i];
            momentum += alpha[i][celli]*b.rho*b.velocity(C[celli]);
            mass += alpha[i][celli]*b.rho;
            pa += alpha[i][celli]*b.p;
        }
        if (mass > 0)
        {
            U[celli] = momentum/mass;
        }
        if (!uniformP)
        {
            p[celli] = pa;
        }
    }
    writeField(mesh, "U", dimVelocity, U);
    writeField(mesh, "p", dimPressure, p);
    writePhaseProperties();

    // Summary
    scalar depth = 1;
    if (geometry_ == "planar")
    {
        depth = mesh.bounds().span().z();
    }
    Info<< nl << "impactSetup: " << nCells << " cells, geometry " << geometry_
        << (geometry_ == "axisymmetric" ? " (volumes and masses of the whole"
            " body of revolution)" : "") << nl
        << "Phases";
    for (const word& phase : phases_)
    {
        Info<< " " << phase;
    }
    Info<< " (ambient " << ambient_.phase
        << ": material " << ambient_.material << ", rho " << ambient_.rho
        << ", p " << ambient_.p;
    if (ambient_.T > 0)
    {
        Info<< ", T " << ambient_.T;
    }
    Info<< ")" << nl << nl;
    forAll(bodies_, i)
    {
        const impactBody& b = bodies_[i];
        const scalar Vmesh = sum(alpha[i]*V);
        const scalar Vexact = b.exactVolume(geometry_, depth);
        Info<< b.owner().c_str() << ": phase " << b.phase << ", material "
            << b.material << nl
            << "    volume on the mesh " << Vmesh;
        if (Vexact > 0)
        {
            Info<< ", exact " << Vexact << " (relative difference "
                << (Vmesh - Vexact)/Vexact << ")";
        }
        else
        {
            Info<< " (no closed form for the exact volume)";
        }
        Info<< nl << "    mass " << Vmesh*b.rho << ", U ";
        if (b.radial)
        {
            Info<< b.radialU << " (r/" << b.radialRadius << ")^"
                << b.radialExponent << " along r from " << b.radialCentre;
        }
        else
        {
            Info<< b.U;
        }
        Info<< ", rho " << b.rho << ", p " << b.p;
        if (b.T > 0)
        {
            Info<< ", T " << b.T;
        }
        if (mag(b.shiftVector()) > 0)
        {
            Info<< nl << "    moved by " << b.shiftVector() << " (gap)";
        }
        Info<< nl;
    }
    Info<< endl;
}


// ************************************************************************* //
