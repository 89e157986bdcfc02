#include "adaptiveRefinement.H"
#include "keywordCheck.H"
#include "inputDefaults.H"

// * * * * * * * * * * * * * * * * Static Data * * * * * * * * * * * * * * * //

const Foam::wordList Foam::adaptiveRefinement::keywords
({
    "maxRefinement", "refineInterval", "maxCells", "nBufferLayers",
    "unrefine", "maxImbalance"
});


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::adaptiveRefinement::adaptiveRefinement
(
    fvMesh& mesh,
    phaseSystem& phases,
    const dictionary& dict
)
:
    mesh_(mesh),
    maxRefinement_(dict.get<label>("maxRefinement")),
    refineInterval_
    (
        inputDefaults::get<label>(dict, "refineInterval", 10, "refinement")
    ),
    maxCells_
    (
        inputDefaults::get<label>(dict, "maxCells", labelMax, "refinement")
    ),
    nBufferLayers_
    (
        inputDefaults::get<label>(dict, "nBufferLayers", 2, "refinement")
    ),
    unrefine_(inputDefaults::get<bool>(dict, "unrefine", true, "refinement")),
    cutter_(amrCutter::New(mesh)),
    indicator_(phases, dict),
    remap_(phases),
    balancer_
    (
        mesh,
        inputDefaults::get<scalar>(dict, "maxImbalance", 0.1, "refinement")
    ),
    heat_(0)
{
    Info<< "Refinement: up to " << maxRefinement_ << " levels every "
        << refineInterval_ << " steps, " << nBufferLayers_
        << " buffer layers" << (unrefine_ ? ", unrefined where quiet" : "")
        << "; " << mesh_.globalData().nTotalCells() << " cells" << nl << endl;
}


// * * * * * * * * * * * * * * * * Selectors * * * * * * * * * * * * * * * * //

Foam::autoPtr<Foam::adaptiveRefinement> Foam::adaptiveRefinement::New
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
    checkSettings(dict);
    return autoPtr<adaptiveRefinement>::New(mesh, phases, dict);
}


// * * * * * * * * * * * * * Static Member Functions * * * * * * * * * * * * //

void Foam::adaptiveRefinement::checkSettings(const dictionary& dict)
{
    // Every entry known before any is read
    wordList valid(keywords);
    valid.append(refinementIndicator::keywords);
    checkKeywords(dict, valid, "refinement");

    const label maxRefinement = dict.get<label>("maxRefinement");
    const label refineInterval = dict.getOrDefault<label>("refineInterval", 10);
    const label nBufferLayers = dict.getOrDefault<label>("nBufferLayers", 2);
    const label maxCells = dict.getOrDefault<label>("maxCells", labelMax);
    if (maxRefinement < 1 || refineInterval < 1 || nBufferLayers < 0)
    {
        FatalIOErrorInFunction(dict)
            << "Need maxRefinement >= 1 (" << maxRefinement
            << "), refineInterval >= 1 (" << refineInterval
            << ") and nBufferLayers >= 0 (" << nBufferLayers << ")"
            << exit(FatalIOError);
    }
    const scalar maxImbalance = dict.getOrDefault<scalar>("maxImbalance", 0.1);
    if (maxImbalance < 0)
    {
        FatalIOErrorInFunction(dict)
            << "Need maxImbalance >= 0 (0: no load balancing), not "
            << maxImbalance << exit(FatalIOError);
    }
    if (maxCells < 1)
    {
        FatalIOErrorInFunction(dict)
            << "Need maxCells >= 1, not " << maxCells << exit(FatalIOError);
    }
    refinementIndicator::checkSettings(dict);
}


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

void Foam::adaptiveRefinement::beforeChange()
{
    remap_.store();
}


void Foam::adaptiveRefinement::afterChange(const mapPolyMesh& map)
{
    heat_ += remap_.apply(map);
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

bool Foam::adaptiveRefinement::initialise()
{
    bool changed = false;
    for (label i = 0; i < maxRefinement_; ++i)
    {
        bitSet marked(mesh_.nCells());
        indicator_.mark(marked);
        if (!adapt(marked))
        {
            break;
        }
        changed = true;
    }
    return changed;
}


bool Foam::adaptiveRefinement::update()
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


bool Foam::adaptiveRefinement::adapt(bitSet marked)
{
    const label nOld = mesh_.globalData().nTotalCells();

    marked.resize(mesh_.nCells());
    cutter_->extend(marked, nBufferLayers_);
    const bool refined =
        cutter_->refine(marked, maxRefinement_, maxCells_, this);
    const bool unrefined = unrefine_ && cutter_->unrefine(marked, this);

    if (refined || unrefined)
    {
        autoPtr<mapDistributePolyMesh> map =
            balancer_.balance(cutter_->families());
        if (map)
        {
            cutter_->distribute(map());
        }
    }

    // The plastic strains of the current mesh and time, for the next
    // evaluation's rates
    indicator_.store();

    if (!refined && !unrefined)
    {
        return false;
    }

    Info<< "Refinement: " << nOld << " -> " << mesh_.globalData().nTotalCells()
        << " cells, per level " << cutter_->perLevel(maxRefinement_)
        << "; kinetic energy to heat in merged cells " << heat_ << " J"
        << endl;
    return true;
}


// ************************************************************************* //
