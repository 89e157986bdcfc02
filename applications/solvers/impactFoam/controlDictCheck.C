#include "controlDictCheck.H"
#include "keywordCheck.H"

// * * * * * * * * * * * * * * * Global Functions  * * * * * * * * * * * * * //

void Foam::checkControlDict(const Time& runTime)
{
    const dictionary& dict = runTime.controlDict();
    const wordList valid
    ({
        // OpenFOAM's Time and its function objects
        "application", "startFrom", "startTime", "stopAt", "endTime",
        "deltaT", "writeControl", "writeInterval", "purgeWrite",
        "writeFormat", "writePrecision", "writeCompression", "timeFormat",
        "timePrecision", "runTimeModifiable", "adjustTimeStep", "functions",
        "libs", "graphFormat", "cacheTemporaryObjects", "DebugSwitches",
        "InfoSwitches", "OptimisationSwitches", "DimensionedConstants",
        "DimensionSets", "fileModificationChecking", "fileHandler",
        "profiling", "printExecutionFormat", "writeFrequency",
        "writeVersion",
        // impactFoam's
        "maxCo", "maxDeltaT", "minDeltaTFactor", "debugDeltaT",
        "progressInterval", "rebuildSolverParts"
    });
    checkKeywords(dict, valid, "system/controlDict");

    if (!dict.getOrDefault<bool>("adjustTimeStep", true))
    {
        FatalIOErrorInFunction(dict)
            << "adjustTimeStep no in " << dict.name() << ": impactFoam"
            << " always sets its time step from maxCo (and maxDeltaT);"
            << " remove the entry or set it to yes" << exit(FatalIOError);
    }
}


// ************************************************************************* //
