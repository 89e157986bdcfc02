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
    (0 0 0)). Cells are grouped into slices of equal axial coordinate
    (structured meshes); in each slice the radius is where alpha falls
    through 1/2 going out from the axis (linear between cell centres), so
    traces and mist of the phase in the air do not count. The length integrates alpha along the row of
    cells next to the axis; the undeformed length is the part of the rod
    whose radius is within -tolerance (default 0.01) of the initial radius
    (-R0, default: the largest radius at the first time processed).

Usage
    rodProfile -phase copper [-axis '(1 0 0)'] [-origin '(0 0 0)']
               [-R0 0.0032] [-tolerance 0.01] [-time ...]

\*---------------------------------------------------------------------------*/

#include "fvCFD.H"
#include "phaseSystem.H"
#include "wedgePolyPatch.H"
#include "OFstream.H"
#include "foamEigen.H"
#include <map>
#include <algorithm>
#include <vector>

namespace
{

// Full angle of the wedge mesh (2 pi for a 3-D mesh)
Foam::scalar meshAngle(const Foam::fvMesh& mesh)
{
    using namespace Foam;
    for (const polyPatch& pp : mesh.boundaryMesh())
    {
        if (isA<wedgePolyPatch>(pp))
        {
            const scalar c = refCast<const wedgePolyPatch>(pp).cosAngle();
            return 2*std::acos(min(max(c, -1.0), 1.0));
        }
    }
    return constant::mathematical::twoPi;
}

// Radius of the body in one slice: where alpha falls through 1/2 going
// out from the axis (linear between cell centres), so that traces and
// mist of the phase further out do not count; 0 if the axis cell is
// below 1/2
Foam::scalar edgeRadius(std::vector<std::pair<Foam::scalar, Foam::scalar>>& row)
{
    std::sort(row.begin(), row.end());
    if (row.empty() || row[0].second < 0.5)
    {
        return 0;
    }
    for (size_t i = 1; i < row.size(); ++i)
    {
        if (row[i].second < 0.5)
        {
            const Foam::scalar r0 = row[i - 1].first, a0 = row[i - 1].second;
            const Foam::scalar r1 = row[i].first, a1 = row[i].second;
            return r0 + (a0 - 0.5)/(a0 - a1)*(r1 - r0);
        }
    }
    return row.back().first;
}

} // End anonymous namespace


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

    const scalar angle = meshAngle(mesh);
    const scalar toFull = constant::mathematical::twoPi/angle;

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

        // Slices of equal axial coordinate
        std::map<long long, scalar> solid, axisAlpha, axisR, zOf;
        std::map<long long, std::vector<std::pair<scalar, scalar>>> rows;
        const scalar zScale = 1e-9*max(mag(mesh.bounds().span()), SMALL);
        forAll(C, celli)
        {
            const vector d(C[celli] - origin);
            const scalar z = d & axis;
            const scalar r = mag(d - z*axis);
            const long long key = std::llround(z/zScale);
            zOf[key] = z;
            solid[key] += alpha[celli]*V[celli]*toFull;
            rows[key].push_back({r, alpha[celli]});
            auto it = axisR.find(key);
            if (it == axisR.end() || r < it->second)
            {
                axisR[key] = r;
                axisAlpha[key] = alpha[celli];
            }
        }

        // Slice thickness from the spacing of the slices
        std::vector<scalar> zs;
        for (const auto& kv : zOf) zs.push_back(kv.second);
        mkDir(outDir/runTime.timeName());
        OFstream profile
        (
            outDir/runTime.timeName()/("profile_" + phaseName + ".csv")
        );
        profile<< "z,radius" << nl;

        scalar length = 0, maxRadius = 0, zMin = GREAT;
        std::vector<scalar> radius(zs.size(), 0), dzs(zs.size(), 0);
        label i = 0;
        for (const auto& kv : zOf)
        {
            const long long key = kv.first;
            scalar dz;
            if (zs.size() < 2) dz = 1;
            else if (i == 0) dz = zs[1] - zs[0];
            else if (i + 1 == label(zs.size())) dz = zs[i] - zs[i - 1];
            else dz = 0.5*(zs[i + 1] - zs[i - 1]);

            dzs[i] = dz;
            radius[i] = edgeRadius(rows[key]);
            length += axisAlpha[key]*dz;
            if (zMin == GREAT && axisAlpha[key] > 1e-3)
            {
                // The body fills the top of its first slice
                zMin = zs[i] + 0.5*dz - axisAlpha[key]*dz;
            }
            maxRadius = max(maxRadius, radius[i]);
            profile<< zs[i] << ',' << radius[i] << nl;
            ++i;
        }

        // Radius at the impact face. The first slice holding the body reads
        // its radius half a slice above the face; with the next slice's the
        // outline is extended to the face (the body's lowest position, or
        // the slice's lower face if that is higher), which removes the
        // first-order offset of a sloping outline
        scalar faceRadius = 0;
        for (size_t j = 0; j < zs.size(); ++j)
        {
            if (radius[j] > 0)
            {
                faceRadius = radius[j];
                if (j + 1 < zs.size() && radius[j + 1] > 0)
                {
                    const scalar zFace = max(zMin, zs[j] - 0.5*dzs[j]);
                    faceRadius +=
                        (radius[j] - radius[j + 1])*(zs[j] - zFace)
                       /(zs[j + 1] - zs[j]);
                }
                break;
            }
        }

        if (R0 < 0)
        {
            R0 = maxRadius;
            Info<< "Initial radius R0 = " << R0 << nl;
        }
        scalar undeformed = 0;
        i = 0;
        for (const auto& kv : zOf)
        {
            if (axisAlpha[kv.first] > 0.5 && radius[i] < (1 + tolerance)*R0)
            {
                undeformed += dzs[i];
            }
            ++i;
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
            const tensorField& A = phases.A(j).primitiveField();
            const inelasticModel& inelastic = phases[j].inelastic();
            scalar carried[phaseModel::maxCarried];
            forAll(C, celli)
            {
                const scalar m = a[celli]*rho[celli]*V[celli];
                internal += m*ph.eos().e(rho[celli], p[celli]);
                if (ph.solid())
                {
                    elastic +=
                        m*ph.elasticEnergy(foamEigen::toEigen(A[celli]));
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
