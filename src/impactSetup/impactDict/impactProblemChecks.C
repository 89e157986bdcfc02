#include "impactProblem.H"
#include "cutCellFractions.H"

// * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * * //

void Foam::impactProblem::checkInside
(
    const fvMesh& mesh,
    const List<scalarField>& alpha
) const
{
    const boundBox meshBounds(mesh.bounds());

    forAll(bodies_, i)
    {
        const impactBody& b = bodies_[i];
        if (max(alpha[i]) <= 0)
        {
            FatalIOErrorInFunction(dict_.subDict("bodies").subDict(b.name()))
                << b.owner().c_str() << " lies wholly outside the domain"
                << " (or is cut away by later bodies): no cell holds any of"
                << " it. Its bounds " << b.bounds() << ", the mesh's "
                << meshBounds << exit(FatalIOError);
        }
        if (!b.shape().bounded())
        {
            continue;
        }

        // A boundary face of an outer patch (not a symmetry, wedge, empty
        // or coupled one) with the body on it: the body crosses it
        const pointField& pts = mesh.points();
        for (const polyPatch& pp : mesh.boundaryMesh())
        {
            if (polyPatch::constraintType(pp.type()))
            {
                continue;
            }
            forAll(pp, facei)
            {
                const face& f = pp[facei];
                point q(Zero);
                for (const label pointi : f)
                {
                    const point& p = pts[pointi];
                    q +=
                        geometry_ == "axisymmetric"
                      ? point(p.x(), Foam::sqrt(sqr(p.y()) + sqr(p.z())), 0)
                      : geometry_ == "planar"
                      ? point(p.x(), p.y(), 0)
                      : p;
                }
                q /= f.size();
                const scalar size = Foam::sqrt(pp.magFaceAreas()[facei]);
                if (b.effectiveDistance(q) < -1e-6*size)
                {
                    FatalIOErrorInFunction
                    (
                        dict_.subDict("bodies").subDict(b.name())
                    )   << b.owner().c_str()
                        << " lies partly outside the domain:"
                        << " it crosses patch " << pp.name() << " at " << q
                        << ". Its bounds " << b.bounds() << ", the mesh's "
                        << meshBounds << exit(FatalIOError);
                }
            }
        }
    }
}


void Foam::impactProblem::checkOverlaps
(
    const cutCellFractions& cut,
    const List<scalarField>& alpha
) const
{
    const scalarField& V = cut.revolvedVolume();
    forAll(bodies_, i)
    {
        for (label j = i + 1; j < bodies_.size(); ++j)
        {
            bool shared = false;
            forAll(V, celli)
            {
                if (alpha[i][celli] > 0 && alpha[j][celli] > 0)
                {
                    shared = true;
                    break;
                }
            }
            if (!shared)
            {
                continue;
            }
            const impactBody& a = bodies_[i];
            const impactBody& b = bodies_[j];
            const scalarField both
            (
                cut.fractions
                (
                    [&a, &b](const point& x)
                    {
                        return max
                        (
                            a.effectiveDistance(x),
                            b.effectiveDistance(x)
                        );
                    }
                )
            );
            const scalar Vboth = sum(both*V);
            const scalar Va = sum(alpha[i]*V), Vb = sum(alpha[j]*V);
            if (Vboth > 1e-6*min(Va, Vb))
            {
                FatalIOErrorInFunction
                (
                    dict_.subDict("bodies").subDict(b.name())
                )   << b.owner().c_str() << " overlaps body " << a.name()
                    << ": volume " << Vboth << " in common ("
                    << 100*Vboth/Va << " % of " << a.name() << "). Move them"
                    << " apart, or give " << b.name() << " the entry cuts ("
                    << a.name() << "); to replace " << a.name()
                    << " where they overlap" << exit(FatalIOError);
            }
        }
    }
}


// ************************************************************************* //
