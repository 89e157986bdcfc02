/*---------------------------------------------------------------------------*\
  impactFoam: Eulerian multiphase elastic-plastic impact solver for OpenFOAM
-------------------------------------------------------------------------------
Description
    quadCutter: the changed mesh built from the cells' corners and the
    hanging points, and played into the mesh.

\*---------------------------------------------------------------------------*/

#include "quadCutter.H"
#include "mapPolyMesh.H"

// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

Foam::labelList Foam::quadCutter::polygon
(
    const labelList& corners,
    const EdgeMap<label>& midPoint,
    const bitSet& removed
)
{
    DynamicList<label> poly(2*corners.size());
    forAll(corners, i)
    {
        poly.append(corners[i]);
        const auto iter =
            midPoint.cfind(edge(corners[i], corners[corners.fcIndex(i)]));
        if (iter.found() && !removed.test(iter.val()))
        {
            poly.append(iter.val());
        }
    }
    return labelList(std::move(poly));
}


Foam::label Foam::quadCutter::addMidPoint(change& ch, const edge& side) const
{
    const auto iter = ch.midPoint.cfind(side);
    if (iter.found())
    {
        return iter.val();
    }

    const pointField& points = mesh_.points();
    const label p = side.first();
    const label q = side.second();
    const label level = max(pointLevel_[p], pointLevel_[q]) + 1;
    const label nOld = mesh_.nPoints();

    const label m = nOld + ch.addedPoints.size();
    ch.addedPoints.append(0.5*(points[p] + points[q]));
    ch.addedLevel.append(level);
    if (ch.partner[p] == p && ch.partner[q] == q)
    {
        // On a collapsed axis: on both planes
        ch.partner.append(m);
    }
    else
    {
        ch.partner.append(m + 1);
        ch.addedPoints.append
        (
            0.5*(points[ch.partner[p]] + points[ch.partner[q]])
        );
        ch.addedLevel.append(level);
        ch.partner.append(-1);
    }
    ch.midPoint.set(side, m);
    ch.splitSide.set(m, side);
    return m;
}


Foam::label Foam::quadCutter::masterFace
(
    const change& ch,
    const label p,
    const label q
) const
{
    // An old segment
    const edge pq(p, q);
    if (sideFace_.found(pq))
    {
        return sideFace_[pq];
    }

    // Half of an old segment
    for (const label m : {p, q})
    {
        const auto iter = ch.splitSide.cfind(m);
        if (iter.found() && iter.val().found(pq.otherVertex(m)))
        {
            return sideFace_.lookup(iter.val(), -1);
        }
    }

    // Two old segments merged: the first
    const auto iter = ch.mergedSide.cfind(pq);
    if (iter.found())
    {
        return sideFace_.lookup(edge(p, iter.val()), -1);
    }

    // Inside a split cell
    return -1;
}


Foam::autoPtr<Foam::mapPolyMesh> Foam::quadCutter::apply
(
    const change& ch,
    listener* l
)
{
    const label nOldPoints = mesh_.nPoints();
    const label nOldCells = mesh_.nCells();
    const polyBoundaryMesh& patches = mesh_.boundaryMesh();
    const cellZoneMesh& cellZones = mesh_.cellZones();

    polyTopoChange meshMod(mesh_);

    // Points
    forAll(ch.addedPoints, i)
    {
        const label p = meshMod.addPoint(ch.addedPoints[i], -1, -1, true);
        if (p != nOldPoints + i)
        {
            FatalErrorInFunction
                << "Point added as " << p << ", not " << nOldPoints + i
                << abort(FatalError);
        }
    }
    for (const label p : ch.removed)
    {
        meshMod.removePoint(p, -1);
    }

    // Cells: merged into the first of their four, children added from
    // their parent
    forAll(ch.mergeInto, c)
    {
        if (ch.mergeInto[c] >= 0)
        {
            meshMod.removeCell(c, ch.mergeInto[c]);
        }
    }
    for (label c = nOldCells; c < ch.corners.size(); ++c)
    {
        const label o = ch.origin[c];
        const label added =
            meshMod.addCell(-1, -1, -1, o, cellZones.whichZone(o));
        if (added != c)
        {
            FatalErrorInFunction
                << "Cell added as " << added << ", not " << c
                << abort(FatalError);
        }
    }

    // Faces: every one built anew
    for (label f = 0; f < mesh_.nFaces(); ++f)
    {
        meshMod.removeFace(f, -1);
    }

    // The plane faces, and each segment of the cells' polygons with the
    // cells on either side (the first: the one it turns about normal_)
    struct segment
    {
        label p, q, first, second;
    };
    DynamicList<segment> segments(4*ch.corners.size());
    EdgeMap<label> segmentIndex(8*ch.corners.size());

    forAll(ch.corners, c)
    {
        if (ch.corners[c].empty())
        {
            continue;
        }
        const labelList poly(polygon(ch.corners[c], ch.midPoint, ch.removed));
        const label o = ch.origin[c];

        face front(poly);
        face back(poly.size());
        forAll(poly, i)
        {
            back[poly.size() - 1 - i] = ch.partner[poly[i]];
        }
        meshMod.addFace
        (
            front, c, -1, -1, -1, frontFace_[o], false,
            patches.whichPatch(frontFace_[o]), -1, false
        );
        meshMod.addFace
        (
            back, c, -1, -1, -1, backFace_[o], false,
            patches.whichPatch(backFace_[o]), -1, false
        );

        forAll(poly, i)
        {
            const label p = poly[i];
            const label q = poly[poly.fcIndex(i)];
            const edge e(p, q);
            const auto iter = segmentIndex.find(e);
            if (iter.found())
            {
                segments[iter.val()].second = c;
            }
            else
            {
                segmentIndex.insert(e, segments.size());
                segments.append({p, q, c, -1});
            }
        }
    }

    // The side faces: each segment swept across the planes, oriented out
    // of its owner
    for (const segment& s : segments)
    {
        // Out of the first cell: p, its partner, q's partner, q
        const label own =
            s.second < 0 ? s.first : min(s.first, s.second);
        const label nei =
            s.second < 0 ? -1 : max(s.first, s.second);
        const bool reversed = own != s.first;
        const label a = reversed ? s.q : s.p;
        const label b = reversed ? s.p : s.q;

        DynamicList<label> pts(4);
        for (const label x : {a, ch.partner[a], ch.partner[b], b})
        {
            if (pts.empty() || (pts.last() != x && pts.first() != x))
            {
                pts.append(x);
            }
        }
        if (pts.size() < 3)
        {
            // A segment on a collapsed axis: no face
            continue;
        }

        const label master = masterFace(ch, s.p, s.q);
        label patchi = -1;
        if (nei < 0)
        {
            patchi = master >= 0 ? patches.whichPatch(master) : -1;
            if (patchi < 0)
            {
                FatalErrorInFunction
                    << "A boundary segment from " << s.p << " to " << s.q
                    << " comes from no boundary face of the old mesh"
                    << abort(FatalError);
            }
        }
        meshMod.addFace
        (
            face(labelList(std::move(pts))), own, nei, -1, -1, master, false,
            patchi, -1, false
        );
    }

    // The change, the fields mapped by the listener around it
    if (l)
    {
        l->beforeChange();
    }
    autoPtr<mapPolyMesh> map = meshMod.changeMesh(mesh_, false);
    mesh_.updateMesh(map());

    // The levels: a cell's from the old cell it comes from (its children
    // and the cells merged into it have the level set in the change); the
    // points kept in order, then the added ones
    const labelList& cellMap = map().cellMap();
    labelList cellLevel(mesh_.nCells());
    forAll(cellMap, c)
    {
        cellLevel[c] = ch.level[cellMap[c]];
    }
    labelList pointLevel(mesh_.nPoints());
    label n = 0;
    for (label p = 0; p < nOldPoints; ++p)
    {
        if (!ch.removed.test(p))
        {
            pointLevel[n++] = pointLevel_[p];
        }
    }
    forAll(ch.addedPoints, i)
    {
        if (mag(mesh_.points()[n] - ch.addedPoints[i]) > SMALL)
        {
            FatalErrorInFunction
                << "Added point " << i << " at " << ch.addedPoints[i]
                << " is point " << n << " at " << mesh_.points()[n]
                << abort(FatalError);
        }
        pointLevel[n++] = ch.addedLevel[i];
    }
    cellLevel_.transfer(cellLevel);
    pointLevel_.transfer(pointLevel);

    analyse();
    changed();

    if (l)
    {
        l->afterChange(map());
    }
    return map;
}


// ************************************************************************* //
