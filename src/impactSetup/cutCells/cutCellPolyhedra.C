#include "cutCellFractions.H"
#include "cutCellGeometry.H"

using namespace Foam::cutCellGeometry;

// * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * * //

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


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

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
