#include "surfaceVelocity.H"
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
    impactTimeHistory(name, runTime, dict),
    phase_(-1),
    point_(Zero),
    direction_(1, 0, 0)
{
    surfaceVelocity::read(dict);
    start();
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

    // The row of cells nearest to the line
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
    DynamicList<label> cells;
    forAll(C, celli)
    {
        if (dist[celli] <= nearest + tol)
        {
            cells.append(celli);
        }
    }
    cells_ = cells;
    return true;
}


// * * * * * * * * * * * * * Protected Member Functions  * * * * * * * * * * //

Foam::wordList Foam::functionObjects::surfaceVelocity::columns() const
{
    return wordList({"position", "velocity", "Ux", "Uy", "Uz"});
}


void Foam::functionObjects::surfaceVelocity::values(DynamicList<scalar>& row)
{
    const scalarField& alpha = phases().alpha(phase_).primitiveField();
    const vectorField& U = phases().U().primitiveField();
    const vectorField& C = mesh_.C().primitiveField();

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
            const vector Ui(line[i][2], line[i][3], line[i][4]);
            const vector Uj(line[j][2], line[j][3], line[j][4]);
            const vector Us(Ui + w*(Uj - Ui));
            result[1] = Us & direction_;
            result[2] = Us.x();
            result[3] = Us.y();
            result[4] = Us.z();
            break;
        }
    }
    Pstream::scatter(result);
    row.append(result);
}


// ************************************************************************* //
