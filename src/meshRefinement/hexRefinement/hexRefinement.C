#include "hexRefinement.H"
#include "polyTopoChange.H"
#include "mapPolyMesh.H"
#include "syncTools.H"
#include "emptyPolyPatch.H"
#include "wedgePolyPatch.H"
#include "keywordCheck.H"
#include "inputDefaults.H"

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::hexRefinement::hexRefinement
(
    fvMesh& mesh,
    phaseSystem& phases,
    const dictionary& dict
)
:
    mesh_(mesh),
    phases_(phases),
    maxRefinement_(dict.get<label>("maxRefinement")),
    refineInterval_(inputDefaults::get<label>(dict, "refineInterval", 10, "refinement")),
    maxCells_(inputDefaults::get<label>(dict, "maxCells", labelMax, "refinement")),
    nBufferLayers_(inputDefaults::get<label>(dict, "nBufferLayers", 2, "refinement")),
    unrefine_(inputDefaults::get<bool>(dict, "unrefine", true, "refinement")),
    cutter_(mesh, true),
    protected_(mesh.nCells()),
    indicator_(phases, dict),
    remap_(phases),
    changedSinceWrite_(false),
    heat_(0)
{
    if (maxRefinement_ < 1 || refineInterval_ < 1 || nBufferLayers_ < 0)
    {
        FatalIOErrorInFunction(dict)
            << "Need maxRefinement >= 1 (" << maxRefinement_
            << "), refineInterval >= 1 (" << refineInterval_
            << ") and nBufferLayers >= 0 (" << nBufferLayers_ << ")"
            << exit(FatalIOError);
    }
    if (maxCells_ < 1)
    {
        FatalIOErrorInFunction(dict)
            << "Need maxCells >= 1, not " << maxCells_ << exit(FatalIOError);
    }

    checkMesh();
    findProtected();

    Info<< "Refinement: up to " << maxRefinement_ << " levels every "
        << refineInterval_ << " steps, " << nBufferLayers_
        << " buffer layers" << (unrefine_ ? ", unrefined where quiet" : "")
        << "; " << mesh_.globalData().nTotalCells() << " cells" << nl << endl;
}


// * * * * * * * * * * * * * * * * Selectors * * * * * * * * * * * * * * * * //

Foam::autoPtr<Foam::hexRefinement> Foam::hexRefinement::New
(
    fvMesh& mesh,
    phaseSystem& phases
)
{
    IOobject io
    (
        "refinementProperties",
        mesh.time().constant(),
        mesh,
        IOobject::MUST_READ,
        IOobject::NO_WRITE,
        false
    );
    if (!io.typeHeaderOk<IOdictionary>(true))
    {
        return nullptr;
    }
    const IOdictionary dict(io);

    // Every entry known before any is read
    wordList valid
    ({
        "maxRefinement", "refineInterval", "maxCells", "nBufferLayers",
        "unrefine"
    });
    valid.append(refinementIndicator::keywords);
    checkKeywords(dict, valid, "refinement");

    return autoPtr<hexRefinement>::New(mesh, phases, dict);
}


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

void Foam::hexRefinement::checkMesh() const
{
    for (const polyPatch& pp : mesh_.boundaryMesh())
    {
        if (isA<emptyPolyPatch>(pp) || isA<wedgePolyPatch>(pp))
        {
            FatalErrorInFunction
                << "constant/refinementProperties asks for refinement, but"
                << " the mesh has the " << pp.type() << " patch " << pp.name()
                << ": refinement is for 3-D meshes (hexRef8 would split the"
                << " cells across the plane of a planar or axisymmetric"
                << " mesh)" << exit(FatalError);
        }
    }
}


void Foam::hexRefinement::findProtected()
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
    labelList nbrLevel(mesh_.nFaces() - mesh_.nInternalFaces());
    for (label f = mesh_.nInternalFaces(); f < mesh_.nFaces(); ++f)
    {
        nbrLevel[f - mesh_.nInternalFaces()] = cellLevel[mesh_.faceOwner()[f]];
    }
    syncTools::swapBoundaryFaceList(mesh_, nbrLevel);

    forAll(mesh_.faces(), f)
    {
        const label o = mesh_.faceOwner()[f];
        const label level =
            f < mesh_.nInternalFaces()
          ? max(cellLevel[o], cellLevel[mesh_.faceNeighbour()[f]])
          : max(cellLevel[o], nbrLevel[f - mesh_.nInternalFaces()]);
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
            if (f < mesh_.nInternalFaces())
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


void Foam::hexRefinement::extend(bitSet& cells) const
{
    bitSet faces(mesh_.nFaces());
    for (const label c : cells)
    {
        faces.set(mesh_.cells()[c]);
    }
    syncTools::syncFaceList(mesh_, faces, orEqOp<unsigned int>());
    for (const label f : faces)
    {
        cells.set(mesh_.faceOwner()[f]);
        if (f < mesh_.nInternalFaces())
        {
            cells.set(mesh_.faceNeighbour()[f]);
        }
    }
}


void Foam::hexRefinement::changed(const mapPolyMesh& map)
{
    cutter_.updateMesh(map);
    heat_ += remap_.apply(map);
    findProtected();
    changedSinceWrite_ = true;
}


bool Foam::hexRefinement::refine(const labelList& cells, bitSet& marked)
{
    if (returnReduce(cells.size(), sumOp<label>()) == 0)
    {
        return false;
    }

    polyTopoChange meshMod(mesh_);
    cutter_.setRefinement(cells, meshMod);
    remap_.store();
    autoPtr<mapPolyMesh> map = meshMod.changeMesh(mesh_, false);
    mesh_.updateMesh(map());
    changed(map());

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


bool Foam::hexRefinement::unrefine(const labelList& splitPoints)
{
    if (returnReduce(splitPoints.size(), sumOp<label>()) == 0)
    {
        return false;
    }

    polyTopoChange meshMod(mesh_);
    cutter_.setUnrefinement(splitPoints, meshMod);
    remap_.store();
    autoPtr<mapPolyMesh> map = meshMod.changeMesh(mesh_, false);
    mesh_.updateMesh(map());
    changed(map());
    return true;
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::hexRefinement::initialise()
{
    for (label i = 0; i < maxRefinement_; ++i)
    {
        bitSet marked(mesh_.nCells());
        indicator_.mark(marked);
        if (!adapt(marked))
        {
            break;
        }
    }
}


bool Foam::hexRefinement::update()
{
    // Counted from the run's first step, also across a restart (the index
    // is written with each time), so that a resumed run changes the mesh
    // at the steps a straight one does
    const label index = mesh_.time().timeIndex();
    if (index <= 0 || index % refineInterval_ != 0)
    {
        return false;
    }

    bitSet marked(mesh_.nCells());
    indicator_.mark(marked);
    return adapt(marked);
}


bool Foam::hexRefinement::adapt(bitSet marked)
{
    const label nOld = mesh_.globalData().nTotalCells();

    // Where the mesh should be fine, with its buffer
    marked.resize(mesh_.nCells());
    for (label i = 0; i < nBufferLayers_; ++i)
    {
        extend(marked);
    }

    // Refine the marked cells below the finest level, the coarsest first
    // while the cell budget lasts (each split adds seven cells)
    const labelList& cellLevel = cutter_.cellLevel();
    DynamicList<label> candidates;
    label budget = (maxCells_ - nOld)/7;
    for (label level = 0; level < maxRefinement_ && budget > 0; ++level)
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
    const bool refined = refine(cells, marked);

    // Merge the split cells of which no child is marked
    bool unrefined = false;
    if (unrefine_)
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
        unrefined = unrefine(cutter_.consistentUnrefinement(quiet, false));
    }

    if (!refined && !unrefined)
    {
        indicator_.store();
        return false;
    }

    indicator_.store();
    const labelList& levels = cutter_.cellLevel();
    labelList perLevel(maxRefinement_ + 1, Zero);
    for (const label l : levels)
    {
        ++perLevel[min(l, maxRefinement_)];
    }
    Pstream::listCombineGather(perLevel, plusEqOp<label>());
    Pstream::listCombineScatter(perLevel);
    Info<< "Refinement: " << nOld << " -> " << mesh_.globalData().nTotalCells()
        << " cells, per level " << perLevel
        << "; kinetic energy to heat in merged cells " << heat_ << " J"
        << endl;
    return true;
}


void Foam::hexRefinement::setInstance()
{
    if (changedSinceWrite_)
    {
        mesh_.setInstance(mesh_.time().timeName());
        cutter_.setInstance(mesh_.time().timeName());
    }
}


void Foam::hexRefinement::write()
{
    if (changedSinceWrite_ && mesh_.time().writeTime())
    {
        cutter_.write();
        mesh_.setInstance(mesh_.time().timeName(), IOobject::NO_WRITE);
        changedSinceWrite_ = false;
    }
}


// ************************************************************************* //
