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
            // An open (zero-gradient) patch copies the cell's state into
            // the face problem: a body within a cell of it draws its own
            // material in wherever it moves away from the patch
            const bool open =
                hasDomain_ && patchKinds_.found(pp.name())
             && patchKinds_[pp.name()] == "open";
            bool nearOpen = false;
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
                nearOpen =
                    nearOpen
                 || (open && b.effectiveDistance(q) < 1.5*cellSize_);
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
            if (nearOpen)
            {
                WarningInFunction
                    << b.owner().c_str() << " lies within a cell of the open"
                    << " patch " << pp.name() << ": a zero-gradient boundary"
                    << " copies the cell's state into the face problem, so"
                    << " wherever the body moves away from the patch its own"
                    << " material flows in and the body grows. Make the"
                    << " domain larger there, or the patch a wall, unless"
                    << " the body is meant to continue beyond it (a"
                    << " semi-infinite target)." << endl;
            }
        }
    }
}


void Foam::impactProblem::warnResolution() const
{
    if (!hasDomain_)
    {
        // A mesh of the user's own: no one cell size to judge by
        return;
    }
    forAll(bodies_, i)
    {
        const impactBody& b = bodies_[i];
        if (!b.shape().bounded())
        {
            continue;
        }
        // The smallest extent in the directions that are meshed (x and y
        // in the meridian or planar plane, z too in 3-D), within the domain
        const boundBox bb(b.bounds());
        const label nDir = geometry_ == "threeD" ? 3 : 2;
        scalar smallest = GREAT;
        for (label d = 0; d < nDir; ++d)
        {
            const scalar lo = max(bb.min()[d], min_[d]);
            const scalar hi = min(bb.max()[d], max_[d]);
            smallest = min(smallest, hi - lo);
        }
        // Refined at its surface: the finest cells
        const scalar h =
            refinement_.empty()
          ? cellSize_
          : cellSize_/pow(2.0, refinement_.get<label>("maxRefinement"));
        const scalar across = smallest/h;
        if (across < 3)
        {
            WarningInFunction
                << b.owner().c_str() << " is " << across << " cells across"
                << " its smallest extent (" << smallest << " m at cells of "
                << h << " m): fewer than 3, too few to resolve it."
                << " Lengths are in metres (cellSize 0.25 is 25 cm; 0.25 mm"
                << " is 0.25e-3)." << endl;
        }
    }
}


void Foam::impactProblem::warnFailure() const
{
    // The largest speed at which two bodies meet
    scalar speed = 0;
    forAll(bodies_, i)
    {
        forAll(bodies_, j)
        {
            speed = max(speed, mag(bodies_[i].U - bodies_[j].U));
        }
    }
    if (speed < 1000)
    {
        return;
    }
    for (const word& phase : phases_)
    {
        if (!phaseDicts_.found(phase))
        {
            continue;
        }
        dictionary pd(phaseDicts_[phase]);
        if (phaseProperties_.isDict(phase))
        {
            pd.merge(phaseProperties_.subDict(phase));
        }
        if (pd.getOrDefault<word>("type", "fluid") != "solid")
        {
            continue;
        }
        const bool failure =
            pd.isDict("failure")
         && pd.subDict("failure").getOrDefault<word>("type", "none") != "none";
        if (!failure)
        {
            WarningInFunction
                << "Phase " << phase << " (material " << phaseMaterials_[phase]
                << ") is a solid without a failure model, and bodies meet at "
                << speed << " m/s: it will hold any tension its cells reach,"
                << " where a real metal spalls. Give it one if it may fail"
                << " (phaseProperties { " << phase << " { failure { type"
                << " spall; sigmaSpall ...; } } } in impactDict;"
                << " docs/model.md section 11)." << endl;
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
