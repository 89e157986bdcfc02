/*---------------------------------------------------------------------------*\
  impactFoam: Eulerian multiphase elastic-plastic impact solver for OpenFOAM
-------------------------------------------------------------------------------
Description
    impactDict's refinement: the mesh refined at the bodies' surfaces
    before the volume fractions are computed on it, and
    constant/refinementProperties for the solver (docs/impactSetup.md).

\*---------------------------------------------------------------------------*/

#include "impactProblem.H"
#include "adaptiveRefinement.H"
#include "amrCutter.H"

// * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * * //

void Foam::impactProblem::readRefinement()
{
    if (!dict_.found("refinement", keyType::LITERAL))
    {
        return;
    }
    if (!dict_.isDict("refinement"))
    {
        FatalIOErrorInFunction(dict_)
            << "impactDict: refinement must be a dictionary (maxRefinement"
            << " and the criteria; docs/impactSetup.md)" << exit(FatalIOError);
    }
    refinement_ = dict_.subDict("refinement");
    if (!hasDomain_)
    {
        FatalIOErrorInFunction(dict_.subDict("refinement"))
            << "impactDict: refinement refines the mesh impactSetup makes"
            << " from the domain entry, and there is none. For the case's own"
            << " mesh, write constant/refinementProperties (the same entries):"
            << " the solver refines it at the start" << exit(FatalIOError);
    }
    adaptiveRefinement::checkSettings(dict_.subDict("refinement"));
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::impactProblem::refineMesh(fvMesh& mesh)
{
    const fileName props
    (
        runTime_.path()/runTime_.constant()/"refinementProperties"
    );

    if (refinement_.empty())
    {
        // No refinement: a refinementProperties impactSetup wrote before
        // goes, the user's own stays
        if (isFile(props) && !generatedFiles::foreign(props))
        {
            rm(props);
            Info<< "Removed " << props << " (no refinement in impactDict)"
                << nl << endl;
        }
        return;
    }

    const label maxLevel = refinement_.get<label>("maxRefinement");
    const label maxCells = refinement_.getOrDefault<label>("maxCells", labelMax);
    const label nLayers = refinement_.getOrDefault<label>("nBufferLayers", 2);
    scalar lower = 1e-3;
    scalar upper = 0.999;
    if (refinement_.isDict("interfaces"))
    {
        const dictionary& d = refinement_.subDict("interfaces");
        lower = d.getOrDefault<scalar>("lower", lower);
        upper = d.getOrDefault<scalar>("upper", upper);
    }

    // Refine where a body's surface is, the exact fractions computed anew
    // on each refined mesh
    autoPtr<amrCutter> cutter(amrCutter::New(mesh));
    for (label level = 0; level < maxLevel; ++level)
    {
        const cutCellFractions cut(mesh, geometry_);
        const List<scalarField> alpha(bodyFractions(cut));
        bitSet marked(mesh.nCells());
        for (const scalarField& a : alpha)
        {
            forAll(a, c)
            {
                if (a[c] > lower && a[c] < upper)
                {
                    marked.set(c);
                }
            }
        }
        cutter->extend(marked, nLayers);
        if (!cutter->refine(marked, maxLevel, maxCells, nullptr))
        {
            break;
        }
        Info<< "Refined at the bodies' surfaces: "
            << mesh.globalData().nTotalCells() << " cells, per level "
            << cutter->perLevel(maxLevel) << nl << endl;
    }

    // The refined mesh and its levels replace blockMesh's
    cutter->setInstance(runTime_.constant());
    mesh.write();
    cutter->write(true);

    // The settings for the solver
    autoPtr<OFstream> os(files_.open(props));
    IOobject io("refinementProperties", runTime_.constant(), runTime_);
    io.writeHeader(os(), "dictionary");
    os() << "// impactDict's refinement (docs/numerics.md section 11)" << nl;
    refinement_.write(os(), false);
    IOobject::writeEndDivider(os());
}


// ************************************************************************* //
