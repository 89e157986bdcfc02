/*---------------------------------------------------------------------------*\
  impactFoam: Eulerian multiphase elastic-plastic impact solver for OpenFOAM
-------------------------------------------------------------------------------
Application
    impactSetup

Description
    Sets up an impact problem from one dictionary, system/impactDict
    (docs/impactSetup.md): the bodies as shapes of materials with a
    velocity and a temperature (or density) in an ambient material.

    With a domain entry it writes system/blockMeshDict and runs blockMesh
    (its output in log.blockMesh); without one it uses the case's mesh in
    constant/polyMesh. It then writes the exact volume fractions and the
    initial fields (0/alpha.<phase>, 0/rho.<phase>, 0/U, 0/p) and
    constant/phaseProperties, and prints a summary of the bodies. Every file
    it writes starts with a line marking it as generated; a file without
    that line is never overwritten.

Usage
    impactSetup [-case <dir>] [-cellSize <m>]

    -cellSize replaces the cellSize of the domain entry (a mesh study
    without editing impactDict).

\*---------------------------------------------------------------------------*/

#include "fvCFD.H"
#include "impactProblem.H"
#include "inputDefaults.H"
#include "IFstream.H"

// * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * //

int main(int argc, char *argv[])
{
    argList::addNote
    (
        "Set up an impact problem (mesh, volume fractions, initial fields,"
        " phaseProperties) from system/impactDict"
    );
    argList::noParallel();
    argList::addOption
    (
        "cellSize",
        "m",
        "the domain's cell size instead of impactDict's domain/cellSize"
    );

    #include "setRootCase.H"
    #include "createTime.H"

    // The fields are the initial ones: at the controlDict's startTime
    const scalar startTime =
        runTime.controlDict().getOrDefault<scalar>("startTime", 0);
    runTime.setTime(startTime, 0);
    {
        const instantList times(runTime.times());
        for (const instant& t : times)
        {
            if (t.value() > startTime)
            {
                WarningInFunction
                    << "The case holds later times (" << t.name() << " ...):"
                    << " a solver starting from latestTime starts there, not"
                    << " from the fields written now in "
                    << runTime.timeName() << nl << endl;
                break;
            }
        }
    }

    // system/impactDict (a FoamFile header is optional)
    const fileName dictFile(runTime.path()/runTime.system()/"impactDict");
    if (!isFile(dictFile))
    {
        FatalErrorInFunction
            << "No " << dictFile << ": impactSetup reads the problem from it"
            << " (docs/impactSetup.md)" << exit(FatalError);
    }
    IFstream dictStream(dictFile);
    dictionary impactDict(dictStream);
    impactDict.remove("FoamFile");

    // Variables: a top-level entry the file uses as $name has done its work
    // once the dictionary is read (an entry nobody uses still stops the
    // reader as unknown)
    {
        IFstream is(dictFile);
        string text, line;
        while (is.good())
        {
            is.getLine(line);
            // (comments do not count as uses)
            text += line.substr(0, line.find("//")) + "\n";
        }
        const wordList keys(impactDict.toc());
        for (const word& key : keys)
        {
            if (impactProblem::keywords.found(key))
            {
                continue;
            }
            const string use("$" + key);
            auto pos = text.find(use);
            while (pos != string::npos)
            {
                const auto end = pos + use.size();
                const bool whole =
                    end == text.size()
                 || !(isalnum(text[end]) || text[end] == '_');
                if (whole)
                {
                    impactDict.remove(key);
                    break;
                }
                pos = text.find(use, end);
            }
        }
    }

    scalar cellSize = 0;
    if (args.readIfPresent("cellSize", cellSize))
    {
        if (!impactDict.isDict("domain"))
        {
            FatalErrorInFunction
                << "-cellSize " << cellSize << ": impactDict has no domain"
                << " entry (the case's own mesh is used)" << exit(FatalError);
        }
        impactDict.subDict("domain").set("cellSize", cellSize);
        Info<< "Cell size " << cellSize << " m (option -cellSize)" << nl
            << endl;
    }

    impactProblem problem(runTime, impactDict);

    if (problem.hasDomain())
    {
        problem.guardMesh();
        problem.writeBlockMeshDict();
        const string command
        (
            "blockMesh -case '" + runTime.path() + "' > '"
          + runTime.path()/"log.blockMesh" + "' 2>&1"
        );
        Info<< "Running blockMesh (output in log.blockMesh)" << nl << endl;
        if (Foam::system(command) != 0)
        {
            FatalErrorInFunction
                << "blockMesh failed on the generated system/blockMeshDict:"
                << " see " << runTime.path()/"log.blockMesh"
                << exit(FatalError);
        }

        // The refinement levels of an earlier refined mesh do not belong
        // to blockMesh's
        const fileName meshDir(runTime.path()/runTime.constant()/"polyMesh");
        for
        (
            const word f
          : {"cellLevel", "pointLevel", "level0Edge", "refinementHistory"}
        )
        {
            rm(meshDir/f);
        }
    }
    else if (!isFile(runTime.path()/runTime.constant()/"polyMesh"/"faces"))
    {
        FatalIOErrorInFunction(impactDict)
            << "impactDict has no domain entry and the case has no mesh in "
            << runTime.path()/runTime.constant()/"polyMesh"
            << ": give a domain or make a mesh first" << exit(FatalIOError);
    }

    Info<< "Reading the mesh" << nl << endl;
    fvMesh mesh
    (
        IOobject
        (
            fvMesh::defaultRegion,
            runTime.timeName(),
            runTime,
            IOobject::MUST_READ
        )
    );

    problem.refineMesh(mesh);
    problem.setFields(mesh);
    problem.writeOutputs(mesh);

    inputDefaults::print(Info);
    problem.files().list(Info);
    const fileNameList stale
    (
        problem.files().removeStale(runTime.path()/runTime.timeName())
    );
    if (stale.size())
    {
        Info<< "Removed (written by an earlier run of impactSetup, not by"
            << " this one):" << nl;
        for (const fileName& f : stale)
        {
            Info<< "    " << f.c_str() << nl;
        }
        Info<< endl;
    }

    Info<< "End" << nl << endl;

    return 0;
}


// ************************************************************************* //
