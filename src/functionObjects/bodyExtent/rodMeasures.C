#include "rodMeasures.H"
#include "mathematicalConstants.H"
#include <map>
#include <algorithm>
#include <vector>

// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * * //

namespace
{

// Radius of the body in one slice: where alpha falls through 1/2 going
// out from the axis (linear between cell centres); 0 if the axis cell is
// below 1/2
Foam::scalar edgeRadius
(
    std::vector<std::pair<Foam::scalar, Foam::scalar>>& row
)
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


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::rodMeasures::rodMeasures
(
    const fvMesh& mesh,
    const scalarField& alpha,
    const vector& axis,
    const point& origin
)
:
    length(0),
    maxRadius(0),
    faceRadius(0),
    zMin(GREAT)
{
    const vectorField& C = mesh.C().primitiveField();
    const pointField& points = mesh.points();

    // Every cell's axial extent, radius and alpha, gathered on the master
    List<List<FixedList<scalar, 4>>> cells(Pstream::nProcs());
    List<FixedList<scalar, 4>>& own = cells[Pstream::myProcNo()];
    own.setSize(C.size());
    forAll(C, celli)
    {
        const vector d(C[celli] - origin);
        const scalar zc = d & axis;
        scalar lo = GREAT;
        scalar hi = -GREAT;
        for (const label pointi : mesh.cellPoints()[celli])
        {
            const scalar zp = (points[pointi] - origin) & axis;
            lo = min(lo, zp);
            hi = max(hi, zp);
        }
        own[celli] = {lo, hi, mag(d - zc*axis), alpha[celli]};
    }
    Pstream::gatherList(cells);

    List<scalar> result(4, Zero);
    if (Pstream::master())
    {
        // Slices between the cells' axial faces (on a structured mesh the
        // rows of cells; on a refined one the finest rows, a coarser cell
        // in each slice it spans)
        const scalar zScale = 1e-9*max(mag(mesh.bounds().span()), SMALL);
        std::map<long long, scalar> faces;
        for (const List<FixedList<scalar, 4>>& list : cells)
        {
            for (const FixedList<scalar, 4>& c : list)
            {
                faces[std::llround(c[0]/zScale)] = c[0];
                faces[std::llround(c[1]/zScale)] = c[1];
            }
        }
        std::vector<scalar> zf;
        std::vector<long long> keys;
        for (const auto& kv : faces)
        {
            keys.push_back(kv.first);
            zf.push_back(kv.second);
        }
        const label n = max(label(zf.size()) - 1, label(0));
        std::vector<std::vector<std::pair<scalar, scalar>>> rows(n);
        List<scalar> axisR(n, GREAT);
        z.setSize(n);
        dz.setSize(n);
        radius.setSize(n);
        axisAlpha.setSize(n, Zero);
        for (label i = 0; i < n; ++i)
        {
            z[i] = 0.5*(zf[i] + zf[i + 1]);
            dz[i] = zf[i + 1] - zf[i];
        }
        for (const List<FixedList<scalar, 4>>& list : cells)
        {
            for (const FixedList<scalar, 4>& c : list)
            {
                const label first =
                    std::lower_bound
                    (
                        keys.begin(), keys.end(), std::llround(c[0]/zScale)
                    ) - keys.begin();
                const long long last = std::llround(c[1]/zScale);
                for (label i = first; i < n && keys[i] < last; ++i)
                {
                    rows[i].push_back({c[2], c[3]});
                    if (c[2] < axisR[i])
                    {
                        axisR[i] = c[2];
                        axisAlpha[i] = c[3];
                    }
                }
            }
        }

        for (label i = 0; i < n; ++i)
        {
            radius[i] = edgeRadius(rows[i]);
            length += axisAlpha[i]*dz[i];
            if (zMin == GREAT && axisAlpha[i] > 1e-3)
            {
                // The body fills the top of its first slice
                zMin = z[i] + 0.5*dz[i] - axisAlpha[i]*dz[i];
            }
            maxRadius = max(maxRadius, radius[i]);
        }

        // Radius at the impact face. The first slice holding the body
        // reads its radius half a slice above the face; with the next
        // slice's the outline is extended to the face (the body's lowest
        // position, or the slice's lower face if that is higher), which
        // removes the first-order offset of a sloping outline
        for (label j = 0; j < n; ++j)
        {
            if (radius[j] > 0)
            {
                faceRadius = radius[j];
                if (j + 1 < n && radius[j + 1] > 0)
                {
                    const scalar zFace = max(zMin, z[j] - 0.5*dz[j]);
                    faceRadius +=
                        (radius[j] - radius[j + 1])*(z[j] - zFace)
                       /(z[j + 1] - z[j]);
                }
                break;
            }
        }

        result[0] = length;
        result[1] = maxRadius;
        result[2] = faceRadius;
        result[3] = zMin;
    }
    Pstream::scatter(result);
    length = result[0];
    maxRadius = result[1];
    faceRadius = result[2];
    zMin = result[3];
}


// ************************************************************************* //
