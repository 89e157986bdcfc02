#include "phaseMaterial.H"
#include "Time.H"
#include "IFstream.H"
#include "OSspecific.H"

// * * * * * * * * * * * * * * * * Functions * * * * * * * * * * * * * * * * //

Foam::fileNameList Foam::phaseMaterial::searchPath
(
    const word& material,
    const Time& runTime
)
{
    fileNameList places;
    places.append
    (
        runTime.globalPath()/runTime.constant()/"materials"/material
    );
    const fileName root(getEnv("IMPACTFOAM_DIR"));
    places.append
    (
        root.empty()
      ? fileName("$IMPACTFOAM_DIR/etc/materials"/material)
      : root/"etc"/"materials"/material
    );
    return places;
}


void Foam::phaseMaterial::mergeOnto(dictionary& base, const dictionary& top)
{
    for (const entry& e : top)
    {
        entry* existing = base.findEntry(e.keyword(), keyType::LITERAL);

        if (existing && existing->isDict() && e.isDict())
        {
            const dictionary& topDict = e.dict();
            dictionary& baseDict = existing->dict();
            const bool sameType =
                !topDict.found("type", keyType::LITERAL)
             || (
                    baseDict.found("type", keyType::LITERAL)
                 && topDict.get<word>("type") == baseDict.get<word>("type")
                );
            if (sameType)
            {
                mergeOnto(baseDict, topDict);
                continue;
            }
        }
        // Adding renames an entry after its new dictionary; an entry keeps
        // the name of the file it came from, so that an error in it names
        // that file and its lines (a sub-dictionary: <file>.<keyword>, as
        // OpenFOAM names one)
        const fileName origin(e.name());
        entry* added = base.set(e.clone(base).ptr());
        if (added)
        {
            added->name() = origin;
        }
    }
}


Foam::dictionary Foam::phaseMaterial::phaseDict
(
    const word& phaseName,
    const dictionary& dict,
    const Time& runTime
)
{
    if (!dict.found("material", keyType::LITERAL))
    {
        return dictionary(dict.parent(), dict);
    }

    const word material(dict.get<word>("material"));
    const fileNameList places(searchPath(material, runTime));

    for (const fileName& file : places)
    {
        if (!isFile(file))
        {
            continue;
        }
        IFstream is(file);
        const dictionary library(is, false);

        // The library's entries under the phase's name (messages about a
        // keyword name the phase's dictionary), then the phase's on top
        dictionary result(dict.parent(), dictionary());
        result.name() = dict.name();
        mergeOnto(result, library);
        mergeOnto(result, dict);
        Info<< "Phase " << phaseName << ": material " << material
            << " from " << file << endl;
        return result;
    }

    fileNameList entries(readDir(places[1].path(), fileName::FILE));
    Foam::sort(entries);
    string library;
    for (const fileName& f : entries)
    {
        library += (library.empty() ? "" : " ") + f;
    }

    FatalIOErrorInFunction(dict)
        << "Phase " << phaseName << ": unknown material " << material
        << " (entry material): no file " << material << " in"
        << nl << "    " << places[0].path()
        << nl << "    " << places[1].path()
        << (getEnv("IMPACTFOAM_DIR").empty()
            ? " (IMPACTFOAM_DIR is not set: source etc/bashrc)" : "")
        << nl << "Searched in this order. The library has: (" << library.c_str()
        << ") (docs/materials.md)" << exit(FatalIOError);

    return dictionary::null;
}


// ************************************************************************* //
