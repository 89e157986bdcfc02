#include "hexCutter.H"
#include "polyTopoChange.H"
#include "mapPolyMesh.H"
#include "syncTools.H"
#include "emptyPolyPatch.H"
#include "wedgePolyPatch.H"

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::hexCutter::hexCutter(fvMesh& mesh)
:
    amrCutter(mesh),
    cutter_(mesh, true),
    protected_(mesh.nCells())
{
    checkMesh();
    findProtected();
}


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

void Foam::hexCutter::checkMesh() const
{
    for (const polyPatch& pp : mesh_.boundaryMesh())
    {
        if (isA<emptyPolyPatch>(pp) || isA<wedgePolyPatch>(pp))
        {
            FatalErrorInFunction
                << "Refinement asked for, but the mesh has the " << pp.type()
                << " patch " << pp.name() << ": refinement is for 3-D meshes"
                << " (hexRef8 would split the cells across the plane of a"
                << " planar or axisymmetric mesh)" << exit(FatalError);
        }
    }
}


void Foam::hexCutter::findProtected()
{
    // A cell hexRef8 can split is a hexahedron whose eight corners are
    // its anchor points (points of a level at most the cell's) and whose
    // faces have four anchors each at their level
    const labelList& cellLevel = cutter_.cellLevel();
    const labelList& pointLevel = cutter_.pointLevel();
    protected_.reset();
    protected_.resize(mesh_.nCells());

    labelList nAnchors(mesh_.nCells(), Zero);
    forAll(pointLevel, pointi)
    {
        for (const label c : mesh_.pointCells(pointi))
        {
            if (pointLevel[pointi] <= cellLevel[c])
            {
                ++nAnchors[c];
            }
        }
    }
    forAll(nAnchors, c)
    {
        if (nAnchors[c] != 8 || mesh_.cells()[c].size() < 6)
        {
            protected_.set(c);
        }
    }

    // Faces: the level of the finer side (across processors too)
    const label nInternal = mesh_.nInternalFaces();
    labelList nbrLevel(mesh_.nFaces() - nInternal);
    for (label f = nInternal; f < mesh_.nFaces(); ++f)
    {
        nbrLevel[f - nInternal] = cellLevel[mesh_.faceOwner()[f]];
    }
    syncTools::swapBoundaryFaceList(mesh_, nbrLevel);

    forAll(mesh_.faces(), f)
    {
        const label o = mesh_.faceOwner()[f];
        const label level =
            f < nInternal
          ? max(cellLevel[o], cellLevel[mesh_.faceNeighbour()[f]])
          : max(cellLevel[o], nbrLevel[f - nInternal]);
        label n = 0;
        for (const label pointi : mesh_.faces()[f])
        {
            if (pointLevel[pointi] <= level)
            {
                ++n;
            }
        }
        if (n != 4)
        {
            protected_.set(o);
            if (f < nInternal)
            {
                protected_.set(mesh_.faceNeighbour()[f]);
            }
        }
    }

    const label nProtected = returnReduce(protected_.count(), sumOp<label>());
    if (nProtected > 0)
    {
        Info<< "Refinement: " << nProtected << " cells are not hexahedra"
            << " that can be split: they stay as they are" << endl;
    }
}


Foam::autoPtr<Foam::mapPolyMesh> Foam::hexCutter::change
(
    polyTopoChange& meshMod,
    listener* l
)
{
    if (l)
    {
        l->beforeChange();
    }
    autoPtr<mapPolyMesh> map = meshMod.changeMesh(mesh_, false);
    mesh_.updateMesh(map());
    cutter_.updateMesh(map());
    findProtected();
    changed();
    if (l)
    {
        l->afterChange(map());
    }
    return map;
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

bool Foam::hexCutter::refine
(
    bitSet& marked,
    const label maxLevel,
    const label maxCells,
    listener* l
)
{
    // The marked cells below the finest level, the coarsest first while
    // the cell budget lasts (each split adds seven cells)
    const labelList& cellLevel = cutter_.cellLevel();
    DynamicList<label> candidates;
    label budget = (maxCells - mesh_.globalData().nTotalCells())/7;
    for (label level = 0; level < maxLevel && budget > 0; ++level)
    {
        const label n0 = candidates.size();
        for (const label c : marked)
        {
            if (cellLevel[c] == level && !protected_.test(c))
            {
                candidates.append(c);
            }
        }
        budget -= returnReduce(candidates.size() - n0, sumOp<label>());
    }
    const labelList cells(cutter_.consistentRefinement(candidates, true));
    if (returnReduce(cells.size(), sumOp<label>()) == 0)
    {
        return false;
    }

    polyTopoChange meshMod(mesh_);
    cutter_.setRefinement(cells, meshMod);
    autoPtr<mapPolyMesh> map = change(meshMod, l);

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


bool Foam::hexCutter::unrefine(const bitSet& marked, listener* l)
{
    const labelList points(cutter_.getSplitPoints());
    DynamicList<label> quiet(points.size());
    for (const label pointi : points)
    {
        bool keep = false;
        for (const label c : mesh_.pointCells(pointi))
        {
            if (marked.test(c) || protected_.test(c))
            {
                keep = true;
                break;
            }
        }
        if (!keep)
        {
            quiet.append(pointi);
        }
    }
    const labelList splitPoints(cutter_.consistentUnrefinement(quiet, false));
    if (returnReduce(splitPoints.size(), sumOp<label>()) == 0)
    {
        return false;
    }

    polyTopoChange meshMod(mesh_);
    cutter_.setUnrefinement(splitPoints, meshMod);
    change(meshMod, l);
    return true;
}


Foam::labelList Foam::hexCutter::families() const
{
    // The history's root of each cell, or the cell itself if never split
    const refinementHistory& history = cutter_.history();
    const labelList& visible = history.visibleCells();
    const DynamicList<refinementHistory::splitCell8>& split =
        history.splitCells();

    labelList family(mesh_.nCells(), -1);
    Map<label> rootFamily;
    label n = 0;
    forAll(family, c)
    {
        label s = visible.size() ? visible[c] : -1;
        if (s < 0)
        {
            family[c] = n++;
            continue;
        }
        while (split[s].parent_ >= 0)
        {
            s = split[s].parent_;
        }
        const auto iter = rootFamily.cfind(s);
        if (iter.found())
        {
            family[c] = iter.val();
        }
        else
        {
            rootFamily.insert(s, n);
            family[c] = n++;
        }
    }
    return family;
}


void Foam::hexCutter::distribute(const mapDistributePolyMesh& map)
{
    cutter_.distribute(map);
    findProtected();
    changed();
}


void Foam::hexCutter::setLevelsInstance(const fileName& instance)
{
    cutter_.setInstance(instance);
}


void Foam::hexCutter::writeLevels()
{
    cutter_.write();
}


// ************************************************************************* //
