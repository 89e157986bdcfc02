#include "surfaceVelocity.H"
#include "boundBox.H"
#include "mapPolyMesh.H"
#include "addToRunTimeSelectionTable.H"
#include <algorithm>
#include <vector>

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace functionObjects
{
    defineTypeNameAndDebug(surfaceVelocity, 0);
    addToRunTimeSelectionTable(functionObject, surfaceVelocity, dictionary);
}
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::functionObjects::surfaceVelocity::surfaceVelocity
(
    const word& name,
    const Time& runTime,
    const dictionary& dict
)
:
    surfaceVelocity(name, runTime, dict, true)
{}


Foam::functionObjects::surfaceVelocity::surfaceVelocity
(
    const word& name,
    const Time& runTime,
    const dictionary& dict,
    const bool writeStart
)
:
    impactTimeHistory(name, runTime, dict),
    phase_(-1),
    point_(Zero),
    direction_(1, 0, 0)
{
    surfaceVelocity::read(dict);
    if (writeStart)
    {
        start();
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

bool Foam::functionObjects::surfaceVelocity::read(const dictionary& dict)
{
    impactTimeHistory::read(dict);
    phase_ = phaseIndex(dict, dict.get<word>("phase"));
    point_ = dict.getOrDefault<point>("point", Zero);
    direction_ = dict.get<vector>("direction");
    if (mag(direction_) < VSMALL)
    {
        FatalIOErrorInFunction(dict)
            << "direction " << direction_ << " in " << dict.name()
            << ": a direction cannot be zero" << exit(FatalIOError);
    }
    direction_ /= mag(direction_);

    selectCells();
    return true;
}


void Foam::functionObjects::surfaceVelocity::selectCells()
{
    // The row of cells whose centres lie nearest to the line (on a wedge
    // the row next to the axis, which lies off it), and the cells whose
    // bounding box the line meets (within a tolerance): on a refined mesh
    // the cells the line runs through or along, of whatever size
    const vectorField& C = mesh_.C().primitiveField();
    scalarField dist(C.size());
    scalar nearest = GREAT;
    forAll(C, celli)
    {
        const vector d(C[celli] - point_);
        dist[celli] = mag(d - (d & direction_)*direction_);
        nearest = min(nearest, dist[celli]);
    }
    reduce(nearest, minOp<scalar>());
    const scalar tol = 1e-9*max(mag(mesh_.bounds().span()), SMALL);
    const pointField& points = mesh_.points();
    const labelListList& cellPoints = mesh_.cellPoints();
    DynamicList<label> cells;
    forAll(cellPoints, celli)
    {
        if (dist[celli] <= nearest + tol)
        {
            cells.append(celli);
            continue;
        }
        const boundBox bb(points, cellPoints[celli], false);
        scalar sMin = -GREAT;
        scalar sMax = GREAT;
        bool meets = true;
        for (Foam::direction i = 0; i < 3 && meets; ++i)
        {
            const scalar lo = bb.min()[i] - tol - point_[i];
            const scalar hi = bb.max()[i] + tol - point_[i];
            const scalar d = direction_[i];
            if (mag(d) < SMALL)
            {
                meets = lo <= 0 && hi >= 0;
            }
            else
            {
                sMin = max(sMin, min(lo/d, hi/d));
                sMax = min(sMax, max(lo/d, hi/d));
                meets = sMin <= sMax;
            }
        }
        if (meets)
        {
            cells.append(celli);
        }
    }
    cells_ = cells;
    stale_ = false;
}


void Foam::functionObjects::surfaceVelocity::updateMesh(const mapPolyMesh&)
{
    // Called inside the mesh's own update, before its geometry is: the
    // cells are selected again when next needed
    cells_.clear();
    stale_ = true;
}


// * * * * * * * * * * * * * Protected Member Functions  * * * * * * * * * * //

Foam::wordList Foam::functionObjects::surfaceVelocity::columns() const
{
    return wordList({"position", "velocity", "Ux", "Uy", "Uz"});
}


Foam::wordList Foam::functionObjects::surfaceVelocity::units() const
{
    return wordList({"[m]", "[m/s]", "[m/s]", "[m/s]", "[m/s]"});
}


Foam::functionObjects::surfaceVelocity::lineSurface
Foam::functionObjects::surfaceVelocity::surfaceOnLine() const
{
    const scalarField& alpha = phases().alpha(phase_).primitiveField();
    const vectorField& U = phases().U().primitiveField();
    const vectorField& C = mesh_.C().primitiveField();

    if (stale_)
    {
        const_cast<surfaceVelocity&>(*this).selectCells();
    }

    // The line's cells (s, alpha, U), gathered on the master
    List<List<scalar>> lines(Pstream::nProcs());
    List<scalar>& own = lines[Pstream::myProcNo()];
    own.setSize(5*cells_.size());
    forAll(cells_, i)
    {
        const label c = cells_[i];
        own[5*i] = (C[c] - point_) & direction_;
        own[5*i + 1] = alpha[c];
        own[5*i + 2] = U[c].x();
        own[5*i + 3] = U[c].y();
        own[5*i + 4] = U[c].z();
    }
    Pstream::gatherList(lines);

    // position, Ux, Uy, Uz, length
    List<scalar> result(5, Zero);
    if (Pstream::master())
    {
        std::vector<std::vector<scalar>> line;
        for (const List<scalar>& l : lines)
        {
            for (label i = 0; i < l.size(); i += 5)
            {
                line.push_back({l[i], l[i + 1], l[i + 2], l[i + 3], l[i + 4]});
            }
        }
        std::sort(line.begin(), line.end());

        const label n = line.size();

        // The phase's length on the line: alpha times each cell's share
        // of the line, half-way to its neighbours' centres
        for (label i = 0; i < n; ++i)
        {
            const scalar sLow = i > 0 ? line[i - 1][0] : line[i][0];
            const scalar sHigh = i + 1 < n ? line[i + 1][0] : line[i][0];
            scalar ds = 0.5*(sHigh - sLow);
            if (n > 1 && (i == 0 || i + 1 == n))
            {
                ds *= 2;
            }
            result[4] += line[i][1]*ds;
        }

        for (label i = n - 1; i >= 0; --i)
        {
            if (line[i][1] < 0.5)
            {
                continue;
            }
            // The last cell holding 1/2; the surface between it and the
            // next (or at its centre at the end of the line)
            scalar w = 0;
            label j = i;
            if (i + 1 < n)
            {
                j = i + 1;
                w = (line[i][1] - 0.5)/(line[i][1] - line[j][1]);
            }
            result[0] = line[i][0] + w*(line[j][0] - line[i][0]);
            for (label k = 0; k < 3; ++k)
            {
                result[1 + k] =
                    line[i][2 + k] + w*(line[j][2 + k] - line[i][2 + k]);
            }
            break;
        }
    }
    Pstream::scatter(result);

    lineSurface surface;
    surface.position = result[0];
    surface.U = vector(result[1], result[2], result[3]);
    surface.length = result[4];
    return surface;
}


void Foam::functionObjects::surfaceVelocity::values(DynamicList<scalar>& row)
{
    const lineSurface surface(surfaceOnLine());
    row.append(surface.position);
    row.append(surface.U & direction_);
    row.append(surface.U.x());
    row.append(surface.U.y());
    row.append(surface.U.z());
}


// ************************************************************************* //
