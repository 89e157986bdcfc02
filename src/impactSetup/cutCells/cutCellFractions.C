#include "cutCellFractions.H"
#include "wedgePolyPatch.H"
#include "mathematicalConstants.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

const Foam::scalar Foam::cutCellFractions::tolerance_ = 1e-3;

const Foam::scalar Foam::cutCellFractions::snapFraction_ = 1e-4;


// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * * //

namespace
{

using namespace Foam;

inline scalar tetVolume
(
    const point& a,
    const point& b,
    const point& c,
    const point& d
)
{
    return mag((b - a) & ((c - a) ^ (d - a)))/6;
}


inline scalar triArea(const vector2D& a, const vector2D& b, const vector2D& c)
{
    const vector2D u(b - a), v(c - a);
    return 0.5*mag(u.x()*v.y() - u.y()*v.x());
}


// A fraction within round-off of 0 or 1 is 0 or 1
inline scalar roundOff(const scalar a)
{
    return a < 1e-12 ? 0 : a > 1 - 1e-12 ? 1 : a;
}


// The point on edge a-b where the linear interpolant of (fa, fb) is zero
template<class Point>
inline Point crossing(const Point& a, const Point& b, scalar fa, scalar fb)
{
    const scalar t = fa/(fa - fb);
    return a + t*(b - a);
}

}


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


void Foam::cutCellFractions::clipTets
(
    DynamicList<FixedList<point, 4>>& tets,
    const vector& n,
    const scalar d,
    const scalar snap
)
{
    DynamicList<FixedList<point, 4>> result(tets.size());

    // A prism (A0 A1 A2 | B0 B1 B2) as three tetrahedra
    auto prism = [&result]
    (
        const point& A0, const point& A1, const point& A2,
        const point& B0, const point& B1, const point& B2
    )
    {
        result.append(FixedList<point, 4>({A0, A1, A2, B2}));
        result.append(FixedList<point, 4>({A0, A1, B1, B2}));
        result.append(FixedList<point, 4>({A0, B0, B1, B2}));
    };

    for (const FixedList<point, 4>& x : tets)
    {
        FixedList<scalar, 4> f;
        label neg[4], pos[4];
        label nNeg = 0, nPos = 0;
        for (label i = 0; i < 4; ++i)
        {
            f[i] = (n & x[i]) - d;
            if (mag(f[i]) <= snap)
            {
                f[i] = 0;
            }
            if (f[i] < 0)
            {
                neg[nNeg++] = i;
            }
            else
            {
                pos[nPos++] = i;
            }
        }
        if (nNeg == 4)
        {
            result.append(x);
        }
        else if (nNeg == 1)
        {
            const label i = neg[0];
            FixedList<point, 4> t;
            t[0] = x[i];
            for (label k = 0; k < 3; ++k)
            {
                const label j = pos[k];
                t[k + 1] = crossing(x[i], x[j], f[i], f[j]);
            }
            result.append(t);
        }
        else if (nNeg == 3)
        {
            // The tetrahedron less the corner at the lone outside vertex
            const label o = pos[0];
            const label a = neg[0], b = neg[1], c = neg[2];
            prism
            (
                x[a], x[b], x[c],
                crossing(x[a], x[o], f[a], f[o]),
                crossing(x[b], x[o], f[b], f[o]),
                crossing(x[c], x[o], f[c], f[o])
            );
        }
        else if (nNeg == 2)
        {
            const label a = neg[0], b = neg[1], c = pos[0], e = pos[1];
            prism
            (
                x[a],
                crossing(x[a], x[c], f[a], f[c]),
                crossing(x[a], x[e], f[a], f[e]),
                x[b],
                crossing(x[b], x[c], f[b], f[c]),
                crossing(x[b], x[e], f[b], f[e])
            );
        }
    }
    tets.transfer(result);
}


void Foam::cutCellFractions::clipPolygon
(
    DynamicList<vector2D>& poly,
    const vector2D& n,
    const scalar d,
    const scalar snap
)
{
    DynamicList<vector2D> result(poly.size() + 1);
    forAll(poly, i)
    {
        const vector2D& a = poly[i];
        const vector2D& b = poly[(i + 1) % poly.size()];
        scalar fa = (n & a) - d, fb = (n & b) - d;
        fa = mag(fa) <= snap ? 0 : fa;
        fb = mag(fb) <= snap ? 0 : fb;
        if (fa < 0)
        {
            result.append(a);
        }
        if ((fa < 0) != (fb < 0))
        {
            result.append(crossing(a, b, fa, fb));
        }
    }
    poly.transfer(result);
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


Foam::scalarField Foam::cutCellFractions::fractions
(
    const List<vector>& nIn,
    const scalarList& dIn
) const
{
    scalarField alpha(mesh_.nCells(), 0);

    // threeD: the planes; planar and axisymmetric: the lines they cut from
    // z = 0 (a plane parallel to z = 0 holds all of it or none)
    DynamicList<vector> n;
    DynamicList<scalar> d;
    forAll(nIn, i)
    {
        vector ni(nIn[i]);
        scalar di = dIn[i];
        if (geometry_ != "threeD")
        {
            ni.z() = 0;
            const scalar m = mag(ni);
            if (m < 1e-12)
            {
                if (di <= 0)
                {
                    return alpha;
                }
                continue;
            }
            ni /= m;
            di /= m;
        }
        n.append(ni);
        d.append(di);
    }

    // A lower bound of the distance (outside) and of the depth (inside)
    auto phi = [&n, &d](const point& p)
    {
        scalar f = -GREAT;
        forAll(n, i)
        {
            f = max(f, (n[i] & p) - d[i]);
        }
        return f;
    };

    const pointField& pts = mesh_.points();
    const faceList& faces = mesh_.faces();

    forAll(alpha, celli)
    {
        if (geometry_ == "axisymmetric")
        {
            const List<vector2D>& prof = profile_[celli];
            vector2D C(Zero);
            for (const vector2D& q : prof)
            {
                C += q;
            }
            C /= prof.size();
            scalar R = 0;
            for (const vector2D& q : prof)
            {
                R = max(R, mag(q - C));
            }
            const scalar fC = phi(point(C.x(), C.y(), 0));
            if (fC >= R || fC <= -R)
            {
                alpha[celli] = fC <= -R ? 1 : 0;
                continue;
            }
            const scalar snap = snapFraction_*tolerance_*R;
            scalar inside = 0, total = 0;
            forAll(prof, k)
            {
                const vector2D& a = prof[k];
                const vector2D& b = prof[(k + 1) % prof.size()];
                total += rIntegral(C, a, b);
                DynamicList<vector2D> poly(4);
                poly.append(C);
                poly.append(a);
                poly.append(b);
                forAll(n, i)
                {
                    clipPolygon
                    (
                        poly, vector2D(n[i].x(), n[i].y()), d[i], snap
                    );
                }
                for (label j = 1; j + 1 < poly.size(); ++j)
                {
                    inside += rIntegral(poly[0], poly[j], poly[j + 1]);
                }
            }
            alpha[celli] = total > 0 ? roundOff(inside/total) : 0;
            continue;
        }

        const point& C = mesh_.cellCentres()[celli];
        const point C0(C.x(), C.y(), geometry_ == "planar" ? 0 : C.z());
        const scalar fC = phi(C0);
        if (fC >= radius_[celli] || fC <= -radius_[celli])
        {
            alpha[celli] = fC <= -radius_[celli] ? 1 : 0;
            continue;
        }
        const scalar snap = snapFraction_*tolerance_*radius_[celli];
        scalar inside = 0, total = 0;
        for (const label facei : mesh_.cells()[celli])
        {
            const face& fc = faces[facei];
            const point& F = mesh_.faceCentres()[facei];
            forAll(fc, k)
            {
                const point& a = pts[fc[k]];
                const point& b = pts[fc.nextLabel(k)];
                total += tetVolume(C, F, a, b);
                DynamicList<FixedList<point, 4>> tets(4);
                tets.append(FixedList<point, 4>({C, F, a, b}));
                forAll(n, i)
                {
                    clipTets(tets, n[i], d[i], snap);
                }
                for (const FixedList<point, 4>& t : tets)
                {
                    inside += tetVolume(t[0], t[1], t[2], t[3]);
                }
            }
        }
        alpha[celli] = total > 0 ? roundOff(inside/total) : 0;
    }
    return alpha;
}


// ************************************************************************* //
