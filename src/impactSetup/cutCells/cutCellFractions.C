#include "cutCellFractions.H"
#include "wedgePolyPatch.H"
#include "mathematicalConstants.H"
#include "cutCellGeometry.H"

using namespace Foam::cutCellGeometry;

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

const Foam::scalar Foam::cutCellFractions::tolerance_ = 1e-3;

const Foam::scalar Foam::cutCellFractions::snapFraction_ = 1e-4;


// * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * * //

Foam::scalar Foam::cutCellFractions::tetClip
(
    const FixedList<point, 4>& x,
    const FixedList<scalar, 4>& fIn,
    const scalar snap
)
{
    // Values within snap of zero are on the surface (mesh points written
    // to a finite precision do not put a node exactly on it)
    FixedList<scalar, 4> f;
    for (label i = 0; i < 4; ++i)
    {
        f[i] = mag(fIn[i]) <= snap ? 0 : fIn[i];
    }

    label neg[4], pos[4];
    label nNeg = 0, nPos = 0;
    for (label i = 0; i < 4; ++i)
    {
        if (f[i] < 0)
        {
            neg[nNeg++] = i;
        }
        else
        {
            pos[nPos++] = i;
        }
    }

    const scalar V = tetVolume(x[0], x[1], x[2], x[3]);

    if (nNeg == 0)
    {
        return 0;
    }
    if (nNeg == 4)
    {
        return V;
    }
    if (nNeg == 1 || nNeg == 3)
    {
        // The corner tetrahedron at the lone vertex
        const label i = nNeg == 1 ? neg[0] : pos[0];
        scalar frac = 1;
        for (label j = 0; j < 4; ++j)
        {
            if (j != i)
            {
                frac *= f[i]/(f[i] - f[j]);
            }
        }
        return nNeg == 1 ? frac*V : V - frac*V;
    }

    // Two on each side: the prism between the negative edge (a, b) and
    // the four crossings
    const label a = neg[0], b = neg[1], c = pos[0], d = pos[1];
    const point ac(crossing(x[a], x[c], f[a], f[c]));
    const point ad(crossing(x[a], x[d], f[a], f[d]));
    const point bc(crossing(x[b], x[c], f[b], f[c]));
    const point bd(crossing(x[b], x[d], f[b], f[d]));

    // Prism (x[a], ac, ad | x[b], bc, bd) as three tetrahedra
    return
        tetVolume(x[a], ac, ad, bd)
      + tetVolume(x[a], ac, bc, bd)
      + tetVolume(x[a], x[b], bc, bd);
}


Foam::scalar Foam::cutCellFractions::tetInside
(
    const distanceFunction& phi,
    const FixedList<point, 4>& x,
    const FixedList<scalar, 4>& f,
    const label level,
    const scalar tol
)
{
    scalar diam2 = 0;
    for (label i = 0; i < 4; ++i)
    {
        for (label j = i + 1; j < 4; ++j)
        {
            diam2 = max(diam2, magSqr(x[i] - x[j]));
        }
    }
    const scalar diam = Foam::sqrt(diam2);
    for (label i = 0; i < 4; ++i)
    {
        // |phi| never exceeds the distance to the surface: no surface
        // within diam of this vertex
        if (f[i] >= diam)
        {
            return 0;
        }
        if (f[i] <= -diam)
        {
            return tetVolume(x[0], x[1], x[2], x[3]);
        }
    }

    // Edge midpoints: 01 02 03 12 13 23
    static const label e[6][2] =
        {{0, 1}, {0, 2}, {0, 3}, {1, 2}, {1, 3}, {2, 3}};
    FixedList<point, 6> m;
    FixedList<scalar, 6> fm;
    scalar departure = 0;
    for (label k = 0; k < 6; ++k)
    {
        m[k] = 0.5*(x[e[k][0]] + x[e[k][1]]);
        fm[k] = phi(m[k]);
        departure =
            max(departure, mag(fm[k] - 0.5*(f[e[k][0]] + f[e[k][1]])));
    }

    // The eight children: four corners and the octahedron split along the
    // diagonal m02-m13 (indices 1 and 4)
    static const label child[8][4] =
    {
        {0, 4, 5, 6},       // 0 m01 m02 m03   (points 0-3, midpoints 4-9)
        {4, 1, 7, 8},       // m01 1 m12 m13
        {5, 7, 2, 9},       // m02 m12 2 m23
        {6, 8, 9, 3},       // m03 m13 m23 3
        {5, 8, 4, 6},       // m02 m13 m01 m03
        {5, 8, 6, 9},       // m02 m13 m03 m23
        {5, 8, 9, 7},       // m02 m13 m23 m12
        {5, 8, 7, 4}        // m02 m13 m12 m01
    };

    const bool leaf = level >= maxLevel3D_ || departure <= tol;

    scalar inside = 0;
    for (label c = 0; c < 8; ++c)
    {
        FixedList<point, 4> xc;
        FixedList<scalar, 4> fc;
        for (label k = 0; k < 4; ++k)
        {
            const label v = child[c][k];
            xc[k] = v < 4 ? x[v] : m[v - 4];
            fc[k] = v < 4 ? f[v] : fm[v - 4];
        }
        inside +=
            leaf
          ? tetClip(xc, fc, snapFraction_*tol)
          : tetInside(phi, xc, fc, level + 1, tol);
    }
    return inside;
}


Foam::scalar Foam::cutCellFractions::rIntegral
(
    const vector2D& a,
    const vector2D& b,
    const vector2D& c
)
{
    return triArea(a, b, c)*(a.y() + b.y() + c.y())/3;
}


Foam::scalar Foam::cutCellFractions::triClip
(
    const FixedList<vector2D, 3>& x,
    const FixedList<scalar, 3>& fIn,
    const scalar snap
)
{
    FixedList<scalar, 3> f;
    for (label i = 0; i < 3; ++i)
    {
        f[i] = mag(fIn[i]) <= snap ? 0 : fIn[i];
    }

    // Sutherland-Hodgman against the linear interpolant: the polygon of
    // the triangle where f < 0 (at most four vertices)
    vector2D poly[4];
    label n = 0;
    for (label i = 0; i < 3; ++i)
    {
        const label j = (i + 1) % 3;
        if (f[i] < 0)
        {
            poly[n++] = x[i];
        }
        if ((f[i] < 0) != (f[j] < 0))
        {
            poly[n++] = crossing(x[i], x[j], f[i], f[j]);
        }
    }
    scalar I = 0;
    for (label k = 1; k + 1 < n; ++k)
    {
        I += rIntegral(poly[0], poly[k], poly[k + 1]);
    }
    return I;
}


Foam::scalar Foam::cutCellFractions::triInside
(
    const std::function<scalar(const vector2D&)>& phi,
    const FixedList<vector2D, 3>& x,
    const FixedList<scalar, 3>& f,
    const label level,
    const scalar tol
)
{
    const scalar diam = Foam::sqrt
    (
        max
        (
            max(magSqr(x[0] - x[1]), magSqr(x[1] - x[2])),
            magSqr(x[2] - x[0])
        )
    );
    for (label i = 0; i < 3; ++i)
    {
        if (f[i] >= diam)
        {
            return 0;
        }
        if (f[i] <= -diam)
        {
            return rIntegral(x[0], x[1], x[2]);
        }
    }

    // Midpoints 01 12 20
    FixedList<vector2D, 3> m;
    FixedList<scalar, 3> fm;
    scalar departure = 0;
    for (label k = 0; k < 3; ++k)
    {
        const label j = (k + 1) % 3;
        m[k] = 0.5*(x[k] + x[j]);
        fm[k] = phi(m[k]);
        departure = max(departure, mag(fm[k] - 0.5*(f[k] + f[j])));
    }

    const bool leaf = level >= maxLevel2D_ || departure <= tol;

    // Children: three corners and the middle (points 0-2, midpoints 3-5)
    static const label child[4][3] =
        {{0, 3, 5}, {3, 1, 4}, {5, 4, 2}, {3, 4, 5}};

    scalar I = 0;
    for (label c = 0; c < 4; ++c)
    {
        FixedList<vector2D, 3> xc;
        FixedList<scalar, 3> fc;
        for (label k = 0; k < 3; ++k)
        {
            const label v = child[c][k];
            xc[k] = v < 3 ? x[v] : m[v - 3];
            fc[k] = v < 3 ? f[v] : fm[v - 3];
        }
        I +=
            leaf
          ? triClip(xc, fc, snapFraction_*tol)
          : triInside(phi, xc, fc, level + 1, tol);
    }
    return I;
}


Foam::scalar Foam::cutCellFractions::cellFraction3D
(
    const distanceFunction& phi,
    const label celli
) const
{
    const point& C = mesh_.cellCentres()[celli];
    const scalar fC = phi(C);
    if (fC >= radius_[celli])
    {
        return 0;
    }
    if (fC <= -radius_[celli])
    {
        return 1;
    }

    const pointField& pts = mesh_.points();
    const faceList& faces = mesh_.faces();
    const scalar tol = tolerance_*radius_[celli];

    scalar inside = 0, total = 0;
    for (const label facei : mesh_.cells()[celli])
    {
        const face& fc = faces[facei];
        const point& F = mesh_.faceCentres()[facei];
        const scalar fF = phi(F);
        forAll(fc, k)
        {
            const point& a = pts[fc[k]];
            const point& b = pts[fc.nextLabel(k)];
            const FixedList<point, 4> x({C, F, a, b});
            const FixedList<scalar, 4> f({fC, fF, phi(a), phi(b)});
            total += tetVolume(C, F, a, b);
            inside += tetInside(phi, x, f, 0, tol);
        }
    }
    return total > 0 ? roundOff(inside/total) : 0;
}


Foam::scalar Foam::cutCellFractions::cellFraction2D
(
    const distanceFunction& phi,
    const label celli
) const
{
    const List<vector2D>& prof = profile_[celli];
    vector2D C(Zero);
    for (const vector2D& p : prof)
    {
        C += p;
    }
    C /= prof.size();
    scalar R = 0;
    for (const vector2D& p : prof)
    {
        R = max(R, mag(p - C));
    }

    const std::function<scalar(const vector2D&)> phi2
    (
        [&phi](const vector2D& q) { return phi(point(q.x(), q.y(), 0)); }
    );

    const scalar fC = phi2(C);
    if (fC >= R)
    {
        return 0;
    }
    if (fC <= -R)
    {
        return 1;
    }

    const scalar tol = tolerance_*R;
    scalar inside = 0, total = 0;
    forAll(prof, k)
    {
        const vector2D& a = prof[k];
        const vector2D& b = prof[(k + 1) % prof.size()];
        const FixedList<vector2D, 3> x({C, a, b});
        const FixedList<scalar, 3> f({fC, phi2(a), phi2(b)});
        total += rIntegral(C, a, b);
        inside += triInside(phi2, x, f, 0, tol);
    }
    return total > 0 ? roundOff(inside/total) : 0;
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::cutCellFractions::cutCellFractions
(
    const polyMesh& mesh,
    const word& geometry
)
:
    mesh_(mesh),
    geometry_(geometry),
    radius_(mesh.nCells(), 0),
    volume_(mesh.cellVolumes())
{
    const pointField& pts = mesh.points();

    if (geometry_ != "axisymmetric")
    {
        const labelListList& cellPoints = mesh.cellPoints();
        forAll(cellPoints, celli)
        {
            const point& C = mesh.cellCentres()[celli];
            scalar r2 = 0;
            for (const label pointi : cellPoints[celli])
            {
                r2 = max(r2, magSqr(pts[pointi] - C));
            }
            radius_[celli] = Foam::sqrt(r2);
        }
        return;
    }

    // Axisymmetric: each cell's face on a wedge patch gives its profile
    profile_.setSize(mesh.nCells());
    boolList found(mesh.nCells(), false);
    for (const polyPatch& pp : mesh.boundaryMesh())
    {
        if (!isA<wedgePolyPatch>(pp))
        {
            continue;
        }
        forAll(pp, i)
        {
            const label celli = pp.faceCells()[i];
            if (found[celli])
            {
                continue;
            }
            const face& f = pp[i];
            List<vector2D>& prof = profile_[celli];
            prof.setSize(f.size());
            forAll(f, k)
            {
                const point& p = pts[f[k]];
                prof[k] = vector2D(p.x(), Foam::sqrt(sqr(p.y()) + sqr(p.z())));
            }
            found[celli] = true;
        }
    }

    forAll(found, celli)
    {
        if (!found[celli])
        {
            FatalErrorInFunction
                << "geometry axisymmetric: cell " << celli << " at "
                << mesh.cellCentres()[celli] << " has no face on a wedge"
                << " patch; an axisymmetric mesh is one cell thick between"
                << " two wedge patches" << exit(FatalError);
        }
        const List<vector2D>& prof = profile_[celli];
        vector2D C(Zero);
        for (const vector2D& p : prof)
        {
            C += p;
        }
        C /= prof.size();
        scalar I = 0;
        forAll(prof, k)
        {
            I += rIntegral(C, prof[k], prof[(k + 1) % prof.size()]);
        }
        volume_[celli] = 2*constant::mathematical::pi*I;
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::scalarField Foam::cutCellFractions::fractions
(
    const distanceFunction& phi
) const
{
    scalarField alpha(mesh_.nCells(), 0);

    if (geometry_ == "axisymmetric")
    {
        forAll(alpha, celli)
        {
            alpha[celli] = cellFraction2D(phi, celli);
        }
    }
    else if (geometry_ == "planar")
    {
        const distanceFunction phiPlane
        (
            [&phi](const point& p) { return phi(point(p.x(), p.y(), 0)); }
        );
        forAll(alpha, celli)
        {
            alpha[celli] = cellFraction3D(phiPlane, celli);
        }
    }
    else
    {
        forAll(alpha, celli)
        {
            alpha[celli] = cellFraction3D(phi, celli);
        }
    }
    return alpha;
}


// ************************************************************************* //
