#include "quadCutter.H"
#include "syncTools.H"
#include "emptyPolyPatch.H"
#include "wedgePolyPatch.H"
#include "processorPolyPatch.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
    defineTypeNameAndDebug(quadCutter, 0);
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::quadCutter::quadCutter(fvMesh& mesh)
:
    amrCutter(mesh),
    cellLevel_
    (
        IOobject
        (
            "cellLevel",
            mesh.facesInstance(),
            polyMesh::meshSubDir,
            mesh,
            IOobject::READ_IF_PRESENT,
            IOobject::NO_WRITE
        ),
        labelList(mesh.nCells(), Zero)
    ),
    pointLevel_
    (
        IOobject
        (
            "pointLevel",
            mesh.facesInstance(),
            polyMesh::meshSubDir,
            mesh,
            IOobject::READ_IF_PRESENT,
            IOobject::NO_WRITE
        ),
        labelList(mesh.nPoints(), Zero)
    ),
    normal_(Zero)
{
    if
    (
        cellLevel_.size() != mesh.nCells()
     || pointLevel_.size() != mesh.nPoints()
    )
    {
        FatalErrorInFunction
            << "The refinement levels read with the mesh ("
            << cellLevel_.objectPath() << ": " << cellLevel_.size()
            << " cells, " << pointLevel_.size() << " points) are not the"
            << " mesh's (" << mesh.nCells() << " cells, " << mesh.nPoints()
            << " points): they belong to another mesh; delete them or"
            << " write them with this one" << exit(FatalError);
    }
    checkMesh();
    analyse();

    const label nProtected = returnReduce(protected_.count(), sumOp<label>());
    if (nProtected > 0)
    {
        Info<< "Refinement: " << nProtected << " cells are not"
            << " quadrilaterals that can be split: they stay as they are"
            << endl;
    }
}


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

void Foam::quadCutter::checkMesh()
{
    // One direction across: the empty or wedge direction
    label nAcross = 0;
    for (direction d = 0; d < vector::nComponents; ++d)
    {
        if (mesh_.solutionD()[d] < 0 || mesh_.geometricD()[d] < 0)
        {
            normal_ = Zero;
            normal_[d] = 1;
            ++nAcross;
        }
    }
    if (nAcross != 1)
    {
        FatalErrorInFunction
            << "Refinement asked for on a mesh with " << nAcross
            << " directions across which nothing varies (solutionD "
            << mesh_.solutionD() << "): a planar or axisymmetric mesh has"
            << " one, a 3-D mesh none. A 1-D mesh is not refined: make it"
            << " a planar strip (several cells across, symmetry planes at"
            << " its sides)" << exit(FatalError);
    }

    for (const polyPatch& pp : mesh_.boundaryMesh())
    {
        if (pp.coupled() && !isA<processorPolyPatch>(pp))
        {
            FatalErrorInFunction
                << "Refinement of a planar or axisymmetric mesh does not"
                << " take the coupled patch " << pp.name() << " (type "
                << pp.type() << "): only processor patches"
                << exit(FatalError);
        }
    }
    if (mesh_.faceZones().size() || mesh_.pointZones().size())
    {
        FatalErrorInFunction
            << "Refinement of a planar or axisymmetric mesh rebuilds its"
            << " faces and does not keep face or point zones; the mesh has "
            << mesh_.faceZones().size() << " face zones and "
            << mesh_.pointZones().size() << " point zones" << exit(FatalError);
    }
}


void Foam::quadCutter::analyse()
{
    const faceList& faces = mesh_.faces();
    const vectorField& Sf = mesh_.faceAreas();
    const labelList& own = mesh_.faceOwner();
    const label nCells = mesh_.nCells();

    // The faces on the two planes
    frontFace_.setSize(nCells);
    frontFace_ = -1;
    backFace_.setSize(nCells);
    backFace_ = -1;
    bitSet isFront(mesh_.nPoints());
    bitSet isBack(mesh_.nPoints());
    bitSet planeFace(mesh_.nFaces());
    for (const polyPatch& pp : mesh_.boundaryMesh())
    {
        if (!isA<emptyPolyPatch>(pp) && !isA<wedgePolyPatch>(pp))
        {
            continue;
        }
        forAll(pp, i)
        {
            const label f = pp.start() + i;
            const scalar cosine = (Sf[f] & normal_)/mag(Sf[f]);
            labelList& side = cosine > 0 ? frontFace_ : backFace_;
            if (mag(cosine) < 0.5 || side[own[f]] >= 0)
            {
                FatalErrorInFunction
                    << "Cell " << own[f] << " at "
                    << mesh_.cellCentres()[own[f]] << " has a face on "
                    << pp.type() << " patch " << pp.name() << " that is not"
                    << " its one face on the "
                    << (cosine > 0 ? "front" : "back")
                    << " plane (normal " << Sf[f]/mag(Sf[f]) << "): not a"
                    << " mesh one cell thick across " << normal_
                    << exit(FatalError);
            }
            side[own[f]] = f;
            planeFace.set(f);
            (cosine > 0 ? isFront : isBack).set(faces[f]);
        }
    }
    for (label c = 0; c < nCells; ++c)
    {
        if (frontFace_[c] < 0 || backFace_[c] < 0)
        {
            FatalErrorInFunction
                << "Cell " << c << " at " << mesh_.cellCentres()[c]
                << " has no face on the "
                << (frontFace_[c] < 0 ? "front" : "back")
                << " plane: not a mesh one cell thick across " << normal_
                << exit(FatalError);
        }
    }

    // Each front point's partner on the back plane: the other end of the
    // edges across, which are the side faces' edges from a point of the
    // front plane only to one of the back plane only
    partner_.setSize(mesh_.nPoints());
    partner_ = -1;
    for (const label p : isFront)
    {
        if (isBack.test(p))
        {
            partner_[p] = p;
        }
    }
    forAll(faces, f)
    {
        if (planeFace.test(f))
        {
            continue;
        }
        const face& sf = faces[f];
        forAll(sf, i)
        {
            const label u = sf[i];
            const label v = sf.nextLabel(i);
            const bool uFront = isFront.test(u) && !isBack.test(u);
            const bool vFront = isFront.test(v) && !isBack.test(v);
            const bool uBack = isBack.test(u) && !isFront.test(u);
            const bool vBack = isBack.test(v) && !isFront.test(v);
            if ((uFront && vBack) || (vFront && uBack))
            {
                const label p = uFront ? u : v;
                const label q = uFront ? v : u;
                if (partner_[p] >= 0 && partner_[p] != q)
                {
                    FatalErrorInFunction
                        << "Point " << p << " at " << mesh_.points()[p]
                        << " on the front plane has two edges across the"
                        << " planes: not an extruded mesh" << exit(FatalError);
                }
                partner_[p] = q;
            }
        }
    }
    for (const label p : isFront)
    {
        if (partner_[p] < 0)
        {
            FatalErrorInFunction
                << "Point " << p << " at " << mesh_.points()[p]
                << " on the front plane has no edge across the planes"
                << exit(FatalError);
        }
    }

    // The side faces by their segments
    sideFace_.clear();
    sideFace_.resize(2*mesh_.nFaces());
    forAll(faces, f)
    {
        if (planeFace.test(f))
        {
            continue;
        }
        label ends[2] = {-1, -1};
        label n = 0;
        for (const label p : faces[f])
        {
            if (isFront.test(p))
            {
                if (n < 2)
                {
                    ends[n] = p;
                }
                ++n;
            }
        }
        if (n != 2)
        {
            FatalErrorInFunction
                << "Face " << f << " at " << mesh_.faceCentres()[f]
                << " is neither on a plane nor a side between two points of"
                << " the front plane (" << n << " points on it): not an"
                << " extruded mesh" << exit(FatalError);
        }
        sideFace_.set(edge(ends[0], ends[1]), f);
    }

    // Corners and hanging points; the back face must be the front one's
    // partners
    corners_.setSize(nCells);
    midPoint_.clear();
    midPoint_.resize(2*nCells);
    protected_.reset();
    protected_.resize(nCells);
    for (label c = 0; c < nCells; ++c)
    {
        const face& ff = faces[frontFace_[c]];
        const face& bf = faces[backFace_[c]];
        bool extruded = (ff.size() == bf.size());
        for (const label p : ff)
        {
            extruded = extruded && bf.found(partner_[p]);
        }
        if (!extruded)
        {
            FatalErrorInFunction
                << "Cell " << c << " at " << mesh_.cellCentres()[c]
                << ": its back face " << bf << " is not its front face "
                << ff << " across the planes: not an extruded mesh"
                << exit(FatalError);
        }

        DynamicList<label> at(ff.size());
        forAll(ff, i)
        {
            if (pointLevel_[ff[i]] <= cellLevel_[c])
            {
                at.append(i);
            }
        }
        labelList& corners = corners_[c];
        corners.setSize(at.size());
        forAll(at, k)
        {
            corners[k] = ff[at[k]];
        }
        if (at.size() != 4)
        {
            protected_.set(c);
        }
        forAll(at, k)
        {
            const label i0 = at[k];
            const label i1 = at[(k + 1) % at.size()];
            const label nBetween = (i1 - i0 - 1 + ff.size()) % ff.size();
            if (nBetween == 1)
            {
                midPoint_.set
                (
                    edge(ff[i0], ff[i1]),
                    ff[(i0 + 1) % ff.size()]
                );
            }
            else if (nBetween > 1)
            {
                FatalErrorInFunction
                    << "Cell " << c << " at " << mesh_.cellCentres()[c]
                    << " of level " << cellLevel_[c] << " has "
                    << nBetween << " points between two of its corners: the"
                    << " levels read with the mesh do not describe it"
                    << exit(FatalError);
            }
        }
    }
}


Foam::bitSet Foam::quadCutter::consistentRefinement
(
    const bitSet& candidates,
    const label maxLevel
) const
{
    const label nCells = mesh_.nCells();
    const label nInternal = mesh_.nInternalFaces();
    const labelList& own = mesh_.faceOwner();
    const labelList& nei = mesh_.faceNeighbour();

    bitSet refine(candidates);
    bitSet blocked(protected_);
    labelList newLevel(cellLevel_);
    for (const label c : refine)
    {
        ++newLevel[c];
    }

    // Whether c could still be split to meet a neighbour's need
    auto canSplit = [&](const label c)
    {
        return
            !refine.test(c) && !blocked.test(c) && cellLevel_[c] < maxLevel;
    };

    // One level at most between c and a neighbour of level nbr after the
    // change: split c where it is two coarser, drop it where it is two
    // finer and the neighbour cannot be split
    label nChanged = 0;
    auto meet = [&](const label c, const label nbr, const bool nbrCanSplit)
    {
        if (newLevel[c] > nbr + 1 && !nbrCanSplit && refine.test(c))
        {
            refine.unset(c);
            blocked.set(c);
            --newLevel[c];
            ++nChanged;
        }
        else if (nbr > newLevel[c] + 1 && canSplit(c))
        {
            refine.set(c);
            ++newLevel[c];
            ++nChanged;
        }
    };

    const label nBoundary = mesh_.nFaces() - nInternal;
    for (label iter = 0; ; ++iter)
    {
        nChanged = 0;

        labelList nbrLevel(nBoundary);
        boolList nbrCanSplit(nBoundary);
        for (label f = nInternal; f < mesh_.nFaces(); ++f)
        {
            nbrLevel[f - nInternal] = newLevel[own[f]];
            nbrCanSplit[f - nInternal] = canSplit(own[f]);
        }
        syncTools::swapBoundaryFaceList(mesh_, nbrLevel);
        syncTools::swapBoundaryFaceList(mesh_, nbrCanSplit);

        for (label f = 0; f < nInternal; ++f)
        {
            meet(own[f], newLevel[nei[f]], canSplit(nei[f]));
            meet(nei[f], newLevel[own[f]], canSplit(own[f]));
        }
        for (const polyPatch& pp : mesh_.boundaryMesh())
        {
            if (!pp.coupled())
            {
                continue;
            }
            forAll(pp, i)
            {
                const label f = pp.start() + i;
                const label b = f - nInternal;
                meet(own[f], nbrLevel[b], nbrCanSplit[b]);
            }
        }

        if (returnReduce(nChanged, sumOp<label>()) == 0)
        {
            break;
        }
        if (iter > 100*(1 + nCells))
        {
            FatalErrorInFunction
                << "The one-level rule found no set of cells to split"
                << abort(FatalError);
        }
    }
    return refine;
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::quadCutter::change Foam::quadCutter::unchanged() const
{
    const label nCells = mesh_.nCells();
    change ch;
    ch.corners = corners_;
    ch.level = cellLevel_;
    ch.origin = identity(nCells);
    ch.mergeInto = labelList(nCells, -1);
    ch.partner = partner_;
    ch.midPoint = midPoint_;
    ch.removed.resize(mesh_.nPoints());
    return ch;
}


bool Foam::quadCutter::refine
(
    bitSet& marked,
    const label maxLevel,
    const label maxCells,
    listener* l
)
{
    // The marked cells below the finest level, the coarsest first while
    // the cell budget lasts (each split adds three cells)
    bitSet candidates(mesh_.nCells());
    label budget = (maxCells - mesh_.globalData().nTotalCells())/3;
    for (label level = 0; level < maxLevel && budget > 0; ++level)
    {
        label n = 0;
        for (const label c : marked)
        {
            if (cellLevel_[c] == level && !protected_.test(c))
            {
                candidates.set(c);
                ++n;
            }
        }
        budget -= returnReduce(n, sumOp<label>());
    }
    const bitSet split(consistentRefinement(candidates, maxLevel));
    if (returnReduce(split.count(), sumOp<label>()) == 0)
    {
        return false;
    }

    // The change: each split cell keeps its label for its first child
    change ch(unchanged());

    // The middles of the split cells' sides, shared with a neighbour
    // splitting too (across processors as well)
    for (const label c : split)
    {
        const labelList& a = corners_[c];
        forAll(a, i)
        {
            addMidPoint(ch, edge(a[i], a[(i + 1) % 4]));
        }
    }
    {
        const label nInternal = mesh_.nInternalFaces();
        boolList nbrSplits(mesh_.nFaces() - nInternal, false);
        List<edge> segment(mesh_.nFaces() - nInternal);
        forAllConstIters(sideFace_, iter)
        {
            const label f = iter.val();
            if (f >= nInternal)
            {
                segment[f - nInternal] = iter.key();
                nbrSplits[f - nInternal] = ch.midPoint.found(iter.key());
            }
        }
        syncTools::swapBoundaryFaceList(mesh_, nbrSplits);
        for (const polyPatch& pp : mesh_.boundaryMesh())
        {
            if (!pp.coupled())
            {
                continue;
            }
            forAll(pp, i)
            {
                const label b = pp.start() + i - nInternal;
                if (nbrSplits[b] && segment[b].valid())
                {
                    addMidPoint(ch, segment[b]);
                }
            }
        }
    }

    // The children: the parent's corner, the middle of the side after it,
    // the middle of the cell, the middle of the side before it
    for (const label c : split)
    {
        const labelList& a = corners_[c];
        point front(Zero);
        point back(Zero);
        for (const label p : a)
        {
            front += 0.25*mesh_.points()[p];
            back += 0.25*mesh_.points()[partner_[p]];
        }
        const label nOld = mesh_.nPoints();
        const label centre = nOld + ch.addedPoints.size();
        ch.addedPoints.append(front);
        ch.addedLevel.append(cellLevel_[c] + 1);
        ch.partner.append(nOld + ch.addedPoints.size());
        ch.addedPoints.append(back);
        ch.addedLevel.append(cellLevel_[c] + 1);
        ch.partner.append(-1);

        for (label i = 0; i < 4; ++i)
        {
            const labelList corners
            ({
                a[i],
                ch.midPoint[edge(a[i], a[(i + 1) % 4])],
                centre,
                ch.midPoint[edge(a[(i + 3) % 4], a[i])]
            });
            if (i == 0)
            {
                ch.corners[c] = corners;
                ++ch.level[c];
            }
            else
            {
                ch.corners.append(corners);
                ch.level.append(cellLevel_[c] + 1);
                ch.origin.append(c);
            }
        }
    }

    autoPtr<mapPolyMesh> map = apply(ch, l);

    // The children of marked cells are marked
    const labelList& cellMap = map().cellMap();
    bitSet newMarked(mesh_.nCells());
    forAll(cellMap, c)
    {
        if (cellMap[c] >= 0 && marked.test(cellMap[c]))
        {
            newMarked.set(c);
        }
    }
    marked.transfer(newMarked);
    return true;
}


void Foam::quadCutter::splitGroups
(
    const labelListList& corners,
    const labelUList& level,
    const bitSet& exclude,
    labelListList& pointCells,
    DynamicList<label>& centres,
    DynamicList<FixedList<label, 4>>& groups
) const
{
    // A point of level L > 0 that is a corner of four cells of level L
    // (then it hangs on no side: the four fill the angle about it), each
    // with its corner across (the parent's) coarser and the two beside it
    // of level L, is the middle of their parent
    invertManyToMany(mesh_.nPoints(), corners, pointCells);
    boolList grouped(corners.size(), false);
    forAll(pointCells, x)
    {
        const label L = pointLevel_[x];
        const labelList& pc = pointCells[x];
        if (L == 0 || pc.size() != 4 || partner_[x] < 0 || partner_[x] == x)
        {
            continue;
        }
        bool ok = true;
        for (const label c : pc)
        {
            const labelList& a = corners[c];
            const label k = a.find(x);
            ok = ok
             && level[c] == L && k >= 0 && a.size() == 4
             && !exclude.test(c) && !grouped[c]
             && pointLevel_[a[(k + 2) % 4]] < L
             && pointLevel_[a[(k + 1) % 4]] == L
             && pointLevel_[a[(k + 3) % 4]] == L;
        }
        if (!ok)
        {
            continue;
        }

        // The four in turn about the middle
        FixedList<label, 4> g;
        g[0] = pc[0];
        for (label i = 1; i < 4; ++i)
        {
            const labelList& a = corners[g[i - 1]];
            const label after = a[(a.find(x) + 3) % 4];
            g[i] = -1;
            for (const label c : pc)
            {
                const labelList& b = corners[c];
                if (b[(b.find(x) + 1) % 4] == after)
                {
                    g[i] = c;
                }
            }
            ok = ok && g[i] >= 0;
        }
        if (!ok)
        {
            continue;
        }
        for (const label c : g)
        {
            grouped[c] = true;
        }
        centres.append(x);
        groups.append(g);
    }
}


Foam::labelList Foam::quadCutter::families() const
{
    // Merge every split cell back in thought, finest first, and number
    // each cell by the base cell it is part of
    const label nCells = mesh_.nCells();
    labelListList corners(corners_);
    labelList level(cellLevel_);
    labelList root(identity(nCells));
    const label maxLevel = nCells ? max(cellLevel_) : 0;
    for (label L = maxLevel; L > 0; --L)
    {
        labelListList pointCells;
        DynamicList<label> centres;
        DynamicList<FixedList<label, 4>> groups;
        splitGroups
        (
            corners, level, bitSet(nCells), pointCells, centres, groups
        );
        forAll(groups, gi)
        {
            const FixedList<label, 4>& g = groups[gi];
            labelList parent(4);
            forAll(g, i)
            {
                const labelList& a = corners[g[i]];
                parent[i] = a[(a.find(centres[gi]) + 2) % 4];
            }
            for (label i = 1; i < 4; ++i)
            {
                corners[g[i]].clear();
                root[g[i]] = g[0];
            }
            corners[g[0]] = parent;
            level[g[0]] = L - 1;
        }
    }

    // Each cell's base cell, numbered from 0
    labelList family(nCells, -1);
    label n = 0;
    forAll(root, c)
    {
        label r = c;
        while (root[r] != r)
        {
            r = root[r];
        }
        if (family[r] < 0)
        {
            family[r] = n++;
        }
        family[c] = family[r];
    }
    return family;
}


bool Foam::quadCutter::unrefine(const bitSet& marked, listener* l)
{
    const label nCells = mesh_.nCells();

    // The split cells none of whose children is marked
    bitSet exclude(marked);
    exclude |= protected_;
    exclude.resize(nCells);
    labelListList pointCells;
    DynamicList<label> centres;
    DynamicList<FixedList<label, 4>> groups;
    splitGroups(corners_, cellLevel_, exclude, pointCells, centres, groups);
    labelList group(nCells, -1);
    forAll(groups, gi)
    {
        for (const label c : groups[gi])
        {
            group[c] = gi;
        }
    }

    // One level at most between the merged cell and its neighbours:
    // merges next to a cell that stays two finer are dropped
    labelList newLevel(cellLevel_);
    bitSet active(groups.size(), true);
    forAll(groups, gi)
    {
        for (const label c : groups[gi])
        {
            --newLevel[c];
        }
    }
    const label nInternal = mesh_.nInternalFaces();
    const labelList& own = mesh_.faceOwner();
    const labelList& nei = mesh_.faceNeighbour();
    labelList nbrLevel(mesh_.nFaces() - nInternal);
    bitSet coupled(mesh_.nFaces() - nInternal);
    for (const polyPatch& pp : mesh_.boundaryMesh())
    {
        if (pp.coupled())
        {
            coupled.set(identity(pp.size(), pp.start() - nInternal));
        }
    }
    for (;;)
    {
        for (label f = nInternal; f < mesh_.nFaces(); ++f)
        {
            nbrLevel[f - nInternal] = newLevel[own[f]];
        }
        syncTools::swapBoundaryFaceList(mesh_, nbrLevel);

        label nDropped = 0;
        forAll(groups, gi)
        {
            if (!active.test(gi))
            {
                continue;
            }
            const label L = cellLevel_[groups[gi][0]];
            bool ok = true;
            for (const label c : groups[gi])
            {
                for (const label f : mesh_.cells()[c])
                {
                    if (f < nInternal)
                    {
                        const label n = own[f] == c ? nei[f] : own[f];
                        ok = ok && (group[n] == gi || newLevel[n] <= L);
                    }
                    else if (coupled.test(f - nInternal))
                    {
                        ok = ok && nbrLevel[f - nInternal] <= L;
                    }
                }
            }
            if (!ok)
            {
                active.unset(gi);
                for (const label c : groups[gi])
                {
                    ++newLevel[c];
                }
                ++nDropped;
            }
        }
        if (returnReduce(nDropped, sumOp<label>()) == 0)
        {
            break;
        }
    }
    if (returnReduce(active.count(), sumOp<label>()) == 0)
    {
        return false;
    }

    // The change: the first of the four (lowest label) keeps the parent
    change ch(unchanged());

    // Whether a point is a corner of a cell (here or across a processor)
    // after the change
    bitSet nbrCorner(mesh_.nPoints());
    for (const polyPatch& pp : mesh_.boundaryMesh())
    {
        if (!pp.coupled())
        {
            continue;
        }
        forAll(pp, i)
        {
            const label f = pp.start() + i;
            for (const label p : mesh_.faces()[f])
            {
                if (pointLevel_[p] <= nbrLevel[f - nInternal])
                {
                    nbrCorner.set(p);
                }
            }
        }
    }
    auto staysCorner = [&](const label p)
    {
        if (nbrCorner.test(p))
        {
            return true;
        }
        for (const label c : pointCells[p])
        {
            if (pointLevel_[p] <= newLevel[c])
            {
                return true;
            }
        }
        return false;
    };

    for (const label gi : active)
    {
        const FixedList<label, 4>& g = groups[gi];
        const label x = centres[gi];
        label master = g[0];
        for (const label c : g)
        {
            master = min(master, c);
        }

        labelList parent(4);
        labelList middle(4);
        forAll(g, i)
        {
            const labelList& a = corners_[g[i]];
            const label k = a.find(x);
            parent[i] = a[(k + 2) % 4];
            middle[i] = a[(k + 3) % 4];
        }
        for (const label c : g)
        {
            if (c != master)
            {
                ch.corners[c].clear();
                ch.mergeInto[c] = master;
            }
        }
        ch.corners[master] = parent;
        ch.level[master] = cellLevel_[master] - 1;

        ch.removed.set(x);
        ch.removed.set(partner_[x]);
        forAll(middle, i)
        {
            const label m = middle[i];
            const edge side(parent[i], parent[(i + 1) % 4]);
            ch.mergedSide.set(side, m);
            if (staysCorner(m))
            {
                ch.midPoint.set(side, m);
            }
            else
            {
                ch.removed.set(m);
                ch.removed.set(partner_[m]);
            }
        }
    }

    // A point hanging on a processor boundary goes when the cells across
    // that had it as a corner merge
    for (const polyPatch& pp : mesh_.boundaryMesh())
    {
        if (!pp.coupled())
        {
            continue;
        }
        for (const label p : pp.meshPoints())
        {
            if
            (
                partner_[p] >= 0 && pointLevel_[p] > 0
             && !ch.removed.test(p) && !staysCorner(p)
            )
            {
                ch.removed.set(p);
                ch.removed.set(partner_[p]);
            }
        }
    }

    // The coarse sides whose middle goes: to it, for the faces' origin
    forAllConstIters(midPoint_, iter)
    {
        if (ch.removed.test(iter.val()))
        {
            ch.mergedSide.set(iter.key(), iter.val());
        }
    }

    apply(ch, l);
    return true;
}


void Foam::quadCutter::distribute(const mapDistributePolyMesh& map)
{
    map.distributeCellData(cellLevel_);
    map.distributePointData(pointLevel_);
    analyse();
    changed();
}


void Foam::quadCutter::setLevelsInstance(const fileName& instance)
{
    cellLevel_.instance() = instance;
    pointLevel_.instance() = instance;
}


void Foam::quadCutter::writeLevels()
{
    cellLevel_.write();
    pointLevel_.write();
}


// ************************************************************************* //
