/*---------------------------------------------------------------------------*\
  impactFoam: Eulerian multiphase elastic-plastic impact solver for OpenFOAM
-------------------------------------------------------------------------------
Application
    rodProfile

Description
    Measures a rod (one solid phase) from its volume fraction, at every
    selected time of an impactFoam case, and the energy budget:

      postProcessing/rodProfile/<phase>.csv, one row per time:
        t, length, maxRadius, faceRadius, undeformedLength, zMin,
        axialVelocity, kinetic, elastic, plasticWork, internal, total
        (energies in J; on a wedge mesh, of the full body of revolution)
      maxRadius is the largest radius of the slices, read at the slices'
      cell centres; faceRadius the radius at the impact face (the body's
      lowest end), where a Lagrangian code reads its face nodes: the
      outline of the first two slices that hold the body, extended
      linearly from their centres to the face (docs/validation.md W1).
      zMin is the lowest axial position of the body along the axis row
      (alpha integrated from the first slice holding it), axialVelocity
      the body's mass-averaged velocity along the axis.
      postProcessing/rodProfile/<time>/profile_<phase>.csv:
        z, radius (the rod's profile r(z))

    The rod lies along -axis (default (1 0 0)) through -origin (default
    (0 0 0)). The slices lie between the cells' axial faces (the rows of
    a structured mesh, the finest rows of a refined one); in each slice
    the radius is where alpha falls
    through 1/2 going out from the axis (linear between cell centres), so
    traces and mist of the phase in the air do not count. The length
    integrates alpha along the row of cells next to the axis; the undeformed length is the part of the rod
    whose radius is within -tolerance (default 0.01) of the initial radius
    (-R0, default: the largest radius at the first time processed).
    The length, radii and zMin are measured by rodMeasures, the code of
    the bodyExtent function object (src/functionObjects).

Usage
    rodProfile -phase copper [-axis '(1 0 0)'] [-origin '(0 0 0)']
               [-R0 0.0032] [-tolerance 0.01] [-time ...]

\*---------------------------------------------------------------------------*/

#include "fvCFD.H"
#include "phaseSystem.H"
#include "rodMeasures.H"
#include "wedgeRevolution.H"
#include "OFstream.H"
#include "foamEigen.H"

int main(int argc, char *argv[])
{
    argList::addNote("Rod length, radius, profile and energy budget");
    timeSelector::addOptions(true, true);
    argList::addOption("phase", "name", "the solid phase of the rod");
    argList::addOption("axis", "vector", "rod axis (default (1 0 0))");
    argList::addOption("origin", "point", "a point of the axis");
    argList::addOption("R0", "scalar", "initial rod radius");
    argList::addOption("tolerance", "scalar", "undeformed radius tolerance");

    #include "setRootCase.H"
    #include "createTime.H"

    const instantList timeDirs = timeSelector::select0(runTime, args);

    #include "createMesh.H"

    const word phaseName(args.get<word>("phase"));
    vector axis(args.getOrDefault<vector>("axis", vector(1, 0, 0)));
    axis /= mag(axis);
    const point origin(args.getOrDefault<point>("origin", Zero));
    scalar R0 = args.getOrDefault<scalar>("R0", -1);
    const scalar tolerance = args.getOrDefault<scalar>("tolerance", 0.01);

    vector wedgeAxis;
    scalar toFull = wedgeToFull(mesh, wedgeAxis);
    if (toFull == 0)
    {
        toFull = 1;
    }

    const fileName outDir(mesh.time().globalPath()/"postProcessing"/"rodProfile");
    mkDir(outDir);
    OFstream table(outDir/(phaseName + ".csv"));
    table.precision(12);
    table<< "t,length,maxRadius,faceRadius,undeformedLength,zMin,"
         << "axialVelocity,kinetic,elastic,plasticWork,internal,total" << nl;

    forAll(timeDirs, timei)
    {
        runTime.setTime(timeDirs[timei], timei);
        mesh.readUpdate();

        phaseSystem phases(mesh);
        const label k = phases.names().find(phaseName);
        if (k < 0)
        {
            FatalErrorInFunction
                << "No phase " << phaseName << " in " << phases.names()
                << exit(FatalError);
        }

        const scalarField& alpha = phases.alpha(k).primitiveField();
        const vectorField& C = mesh.C();
        const scalarField& V = mesh.V();

        // Length, radii and the slices (rodMeasures: the bodyExtent
        // function object's measures)
        const rodMeasures rod(mesh, alpha, axis, origin);
        const scalar length = rod.length;
        const scalar maxRadius = rod.maxRadius;
        const scalar faceRadius = rod.faceRadius;
        const scalar zMin = rod.zMin;
        const List<scalar>& zs = rod.z;
        const List<scalar>& dzs = rod.dz;
        const List<scalar>& radius = rod.radius;

        mkDir(outDir/runTime.timeName());
        OFstream profile
        (
            outDir/runTime.timeName()/("profile_" + phaseName + ".csv")
        );
        profile<< "z,radius" << nl;
        forAll(zs, i)
        {
            profile<< zs[i] << ',' << radius[i] << nl;
        }

        if (R0 < 0)
        {
            R0 = maxRadius;
            Info<< "Initial radius R0 = " << R0 << nl;
        }
        scalar undeformed = 0;
        forAll(zs, i)
        {
            if (rod.axisAlpha[i] > 0.5 && radius[i] < (1 + tolerance)*R0)
            {
                undeformed += dzs[i];
            }
        }

        // Energy budget
        scalar kinetic = 0, elastic = 0, plastic = 0, internal = 0;
        const vectorField& U = phases.U().primitiveField();
        const scalarField& rhoM = phases.rhoMixture().primitiveField();
        forAll(C, celli)
        {
            kinetic += 0.5*rhoM[celli]*magSqr(U[celli])*V[celli];
        }
        forAll(phases.names(), j)
        {
            const hyperelasticPhase& ph = phases.phase(j);
            const scalarField& a = phases.alpha(j).primitiveField();
            const scalarField& rho = phases.rho(j).primitiveField();
            const scalarField& p = phases.p(j).primitiveField();
            const tensorField* A = phases.cellCobasis(j);
            const inelasticModel& inelastic = phases[j].inelastic();
            scalar carried[phaseModel::maxCarried];
            forAll(C, celli)
            {
                const scalar m = a[celli]*rho[celli]*V[celli];
                internal += m*ph.eos().e(rho[celli], p[celli]);
                if (ph.solid())
                {
                    elastic +=
                        m*ph.elasticEnergy(foamEigen::toEigen((*A)[celli]));
                    phases[j].inelasticState(celli, carried);
                    plastic += m*inelastic.plasticWork(carried);
                }
            }
        }
        scalar bodyMass = 0, bodyMomentum = 0;
        {
            const scalarField& a = phases.alpha(k).primitiveField();
            const scalarField& rho = phases.rho(k).primitiveField();
            forAll(C, celli)
            {
                const scalar m = a[celli]*rho[celli]*V[celli];
                bodyMass += m;
                bodyMomentum += m*(U[celli] & axis);
            }
        }
        const scalar axialVelocity = bodyMomentum/max(bodyMass, VSMALL);

        kinetic *= toFull;
        elastic *= toFull;
        plastic *= toFull;
        internal *= toFull;

        table<< runTime.value() << ',' << length << ',' << maxRadius << ','
             << faceRadius << ',' << undeformed << ',' << zMin << ','
             << axialVelocity << ','
             << kinetic << ',' << elastic << ','
             << plastic << ',' << internal << ','
             << kinetic + elastic + internal << nl;

        Info<< "Time " << runTime.timeName() << ": length " << length
            << ", max radius " << maxRadius << ", face radius " << faceRadius
            << ", undeformed length "
            << undeformed << ", kinetic " << kinetic << " J, elastic "
            << elastic << " J, plastic work " << plastic << " J" << nl;
    }

    Info<< "Wrote " << outDir << nl << "End" << nl;
    return 0;
}
