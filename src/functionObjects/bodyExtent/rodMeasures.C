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

    // Every cell's (z, r, alpha), gathered on the master
    List<List<vector>> cells(Pstream::nProcs());
    List<vector>& own = cells[Pstream::myProcNo()];
    own.setSize(C.size());
    forAll(C, celli)
    {
        const vector d(C[celli] - origin);
        const scalar zc = d & axis;
        own[celli] = vector(zc, mag(d - zc*axis), alpha[celli]);
    }
    Pstream::gatherList(cells);

    List<scalar> result(4, Zero);
    if (Pstream::master())
    {
        // Slices of equal axial coordinate
        std::map<long long, scalar> axisA, axisR, zOf;
        std::map<long long, std::vector<std::pair<scalar, scalar>>> rows;
        const scalar zScale = 1e-9*max(mag(mesh.bounds().span()), SMALL);
        for (const List<vector>& list : cells)
        {
            for (const vector& c : list)
            {
                const scalar zc = c.x(), r = c.y(), a = c.z();
                const long long key = std::llround(zc/zScale);
                zOf[key] = zc;
                rows[key].push_back({r, a});
                auto it = axisR.find(key);
                if (it == axisR.end() || r < it->second)
                {
                    axisR[key] = r;
                    axisA[key] = a;
                }
            }
        }

        const label n = zOf.size();
        z.setSize(n);
        dz.setSize(n);
        radius.setSize(n);
        axisAlpha.setSize(n);
        label i = 0;
        for (const auto& kv : zOf)
        {
            z[i++] = kv.second;
        }

        // Slice thickness from the spacing of the slices
        i = 0;
        for (const auto& kv : zOf)
        {
            const long long key = kv.first;
            if (n < 2) dz[i] = 1;
            else if (i == 0) dz[i] = z[1] - z[0];
            else if (i + 1 == n) dz[i] = z[i] - z[i - 1];
            else dz[i] = 0.5*(z[i + 1] - z[i - 1]);

            radius[i] = edgeRadius(rows[key]);
            axisAlpha[i] = axisA[key];
            length += axisAlpha[i]*dz[i];
            if (zMin == GREAT && axisAlpha[i] > 1e-3)
            {
                // The body fills the top of its first slice
                zMin = z[i] + 0.5*dz[i] - axisAlpha[i]*dz[i];
            }
            maxRadius = max(maxRadius, radius[i]);
            ++i;
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
