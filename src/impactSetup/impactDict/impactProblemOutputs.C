#include "impactProblem.H"
#include "keywordCheck.H"
#include "wallPolyPatch.H"
#include "IFstream.H"
#include "IStringStream.H"
#include "primitiveEntry.H"

// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * * //

namespace
{

using namespace Foam;

// The output types of impactDict's outputs and their entries
const wordList outputTypes
({
    "penetration", "motion", "wallForce", "energy", "probes"
});

wordList outputKeywords(const word& type)
{
    if (type == "penetration")
    {
        return wordList({"type", "body", "into", "point", "direction"});
    }
    if (type == "motion")
    {
        return wordList({"type", "body", "fragmentAlpha"});
    }
    if (type == "wallForce")
    {
        return wordList({"type", "patches"});
    }
    if (type == "probes")
    {
        return wordList({"type", "points", "fields"});
    }
    return wordList({"type"});
}


// A function object's dictionary: its type and the library that has it
dictionary functionObjectDict(const word& type, const word& lib)
{
    dictionary fo;
    fo.add("type", type);
    fo.add(new primitiveEntry("libs", IStringStream("(" + lib + ");")()));
    return fo;
}

} // End anonymous namespace


// * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * * //

Foam::label Foam::impactProblem::outputBody
(
    const dictionary& od,
    const word& key,
    const string& owner
) const
{
    if (!od.found(key, keyType::LITERAL))
    {
        FatalIOErrorInFunction(od)
            << owner.c_str() << ": missing entry " << key
            << " (the name of a body)" << exit(FatalIOError);
    }
    const word name(od.get<word>(key));
    wordList names(bodies_.size());
    forAll(bodies_, i)
    {
        names[i] = bodies_[i].name();
        if (names[i] == name)
        {
            return i;
        }
    }
    FatalIOErrorInFunction(od)
        << owner.c_str() << ": entry " << key << " names " << name
        << ", which is not a body; did you mean "
        << nearestKeyword(name, names) << "?" << nl
        << "The bodies: " << names << exit(FatalIOError);
    return -1;
}


Foam::scalar Foam::impactProblem::lineEntry
(
    const point& start,
    const vector& d,
    const impactBody& target
) const
{
    // March along the line by the target's signed distance (never more
    // than the true distance, so the surface is not stepped over) until
    // the line is inside it, or has gone past every body
    boundBox all;
    for (const impactBody& b : bodies_)
    {
        if (b.shape().bounded())
        {
            all.add(b.bounds());
        }
    }
    all.add(start);
    const scalar size = all.mag();
    const scalar tol = 1e-9*size;
    scalar s = 0;
    for (label step = 0; step < 100000 && s < 2*size; ++step)
    {
        const scalar dist = target.effectiveDistance(start + s*d);
        if (dist <= tol)
        {
            return s;
        }
        s += max(dist, tol);
    }
    return -1;
}


void Foam::impactProblem::readOutputs()
{
    // Without an outputs entry: the defaults that follow the bodies
    dictionary od;
    const bool given = dict_.found("outputs", keyType::LITERAL);
    if (given)
    {
        if (!dict_.isDict("outputs"))
        {
            FatalIOErrorInFunction(dict_)
                << "impactDict: outputs must be a dictionary of tables"
                << " (name { type ...; })" << exit(FatalIOError);
        }
        od = dict_.subDict("outputs");
    }
    else
    {
        od.add("energy", dictionary());
        od.subDict("energy").add("type", "energy");
        forAll(bodies_, i)
        {
            const impactBody& b = bodies_[i];
            if (b.radial || mag(b.U) < VSMALL)
            {
                continue;
            }
            dictionary motion;
            motion.add("type", "motion");
            motion.add("body", b.name());
            od.add(word(b.name() + "Motion"), motion);

            // The first body its velocity's line meets
            vector d(b.U/mag(b.U));
            const point start(lineStart(b, d));
            label target = -1;
            scalar sTarget = GREAT;
            forAll(bodies_, j)
            {
                if (j != i)
                {
                    const scalar s = lineEntry(start, d, bodies_[j]);
                    if (s >= 0 && s < sTarget)
                    {
                        target = j;
                        sTarget = s;
                    }
                }
            }
            if (target >= 0)
            {
                dictionary pen;
                pen.add("type", "penetration");
                pen.add("body", b.name());
                pen.add("into", bodies_[target].name());
                od.add(word(b.name() + "Penetration"), pen);
            }
        }
        od.add("wallForce", dictionary());
        od.subDict("wallForce").add("type", "wallForce");
    }

    const string owner("impactDict outputs");
    interval_ = 0;
    if (od.found("interval", keyType::LITERAL))
    {
        interval_ = od.get<scalar>("interval");
        if (!(interval_ > 0))
        {
            FatalIOErrorInFunction(od)
                << owner.c_str() << ": interval " << interval_
                << " must be positive (leave it out for a row every step)"
                << exit(FatalIOError);
        }
    }

    outputs_.clear();
    for (const entry& e : od)
    {
        const word name(e.keyword());
        if (name == "interval")
        {
            continue;
        }
        const string entryOwner(owner + ", " + name);
        if (!e.isDict())
        {
            FatalIOErrorInFunction(od)
                << owner.c_str() << ": entry " << name << " is not a table"
                << " (name { type ...; }) nor interval" << exit(FatalIOError);
        }
        const dictionary& d = e.dict();
        if (!d.found("type", keyType::LITERAL))
        {
            FatalIOErrorInFunction(d)
                << entryOwner.c_str() << ": missing entry type; the types: "
                << outputTypes << exit(FatalIOError);
        }
        const word type(d.get<word>("type"));
        if (!outputTypes.found(type))
        {
            FatalIOErrorInFunction(d)
                << entryOwner.c_str() << ": unknown type " << type
                << "; did you mean " << nearestKeyword(type, outputTypes)
                << "?" << nl << "The types: " << outputTypes
                << exit(FatalIOError);
        }
        checkKeywords(d, outputKeywords(type), entryOwner);

        // The function object
        const word impactLib("impactFoamFunctionObjects");
        dictionary fo;
        if (type == "energy")
        {
            fo = functionObjectDict("energyBudget", impactLib);
        }
        else if (type == "motion")
        {
            const impactBody& b = bodies_[outputBody(d, "body", entryOwner)];
            fo = functionObjectDict("bodyMotion", impactLib);
            fo.add("phase", b.phase);
            if (d.found("fragmentAlpha", keyType::LITERAL))
            {
                fo.add("fragmentAlpha", d.get<scalar>("fragmentAlpha"));
            }
        }
        else if (type == "penetration")
        {
            fo = penetrationOutput(d, entryOwner);
        }
        else if (type == "wallForce")
        {
            fo = functionObjectDict("wallForce", impactLib);
            if (d.found("patches", keyType::LITERAL))
            {
                fo.add("patches", d.get<wordList>("patches"));
            }
        }
        else if (type == "probes")
        {
            for (const char* key : {"points", "fields"})
            {
                if (!d.found(key, keyType::LITERAL))
                {
                    FatalIOErrorInFunction(d)
                        << entryOwner.c_str() << ": missing entry " << key
                        << exit(FatalIOError);
                }
            }
            fo = functionObjectDict("probes", "sampling");
            fo.add("fields", d.get<wordList>("fields"));
            fo.add("probeLocations", d.get<List<point>>("points"));
        }
        if (interval_ > 0)
        {
            fo.add("writeControl", "runTime");
            fo.add("writeInterval", interval_);
        }
        outputs_.add(name, fo);
    }
}


Foam::point Foam::impactProblem::lineStart
(
    const impactBody& b,
    vector& d
) const
{
    point c(b.bounds().centre());
    if (geometry_ == "axisymmetric")
    {
        // The line is the axis (the penetration's cells are those next to
        // it), in the direction of the velocity's axial part
        c = point(c.x(), 0, 0);
        d = vector(d.x() < 0 ? -1 : 1, 0, 0);
    }
    else if (geometry_ == "planar")
    {
        c.z() = 0;
    }
    return c;
}


Foam::dictionary Foam::impactProblem::penetrationOutput
(
    const dictionary& d,
    const string& owner
) const
{
    const impactBody& b = bodies_[outputBody(d, "body", owner)];
    vector dir(b.U);
    if (d.found("direction", keyType::LITERAL))
    {
        dir = d.get<vector>("direction");
    }
    if (mag(dir) < VSMALL)
    {
        FatalIOErrorInFunction(d)
            << owner.c_str() << ": body " << b.name() << " has no velocity"
            << " U to penetrate along: give a direction" << exit(FatalIOError);
    }
    dir /= mag(dir);
    point start(lineStart(b, dir));

    dictionary fo
    (
        functionObjectDict("penetration", "impactFoamFunctionObjects")
    );
    fo.add("phase", b.phase);
    if (d.found("point", keyType::LITERAL))
    {
        fo.add("point", d.get<point>("point"));
    }
    else
    {
        const impactBody& target = bodies_[outputBody(d, "into", owner)];
        const scalar s = lineEntry(start, dir, target);
        if (s < 0)
        {
            FatalIOErrorInFunction(d)
                << owner.c_str() << ": the line from body " << b.name()
                << "'s centre " << start << " along " << dir << " does not"
                << " meet body " << target.name() << ": give the point the"
                << " penetration is measured from" << exit(FatalIOError);
        }
        fo.add("point", start + s*dir);
    }
    fo.add("direction", dir);
    return fo;
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::impactProblem::writeOutputs(const fvMesh& mesh)
{
    const polyBoundaryMesh& pbm = mesh.boundaryMesh();
    wordList walls;
    for (const polyPatch& pp : pbm)
    {
        if (isA<wallPolyPatch>(pp))
        {
            walls.append(pp.name());
        }
    }

    dictionary functions;
    for (const entry& e : outputs_)
    {
        dictionary fo(e.dict());
        if (fo.get<word>("type") == "wallForce")
        {
            if (fo.found("patches"))
            {
                for (const word& p : fo.get<wordList>("patches"))
                {
                    if (pbm.findPatchID(p) < 0)
                    {
                        FatalIOErrorInFunction(dict_)
                            << "impactDict outputs, " << e.keyword()
                            << ": no patch " << p << "; the patches: "
                            << pbm.names() << exit(FatalIOError);
                    }
                }
            }
            else if (walls.empty())
            {
                // No wall: no table (a default output)
                continue;
            }
        }
        functions.add(e.keyword(), fo);
    }

    const fileName file(runTime_.path()/runTime_.system()/"impactOutputs");
    autoPtr<OFstream> os(files_.open(file));
    os().precision(15);
    os() << "// The time histories of impactDict's outputs (docs/impactSetup.md"
        << " section 7): function" << nl << "// objects, included by the"
        << " controlDict's functions { #includeIfPresent \"impactOutputs\" }"
        << nl << nl;
    functions.write(os(), false);

    // A controlDict that does not include the file
    const fileName controlDict(runTime_.path()/runTime_.system()/"controlDict");
    IFstream is(controlDict);
    string text;
    string line;
    while (is.good() && is.getLine(line))
    {
        text += line + "\n";
    }
    if (text.find("impactOutputs") == string::npos)
    {
        WarningInFunction
            << controlDict << " does not include impactOutputs: the tables of"
            << " impactDict's outputs are not written. Add" << nl
            << "    functions { #includeIfPresent \"impactOutputs\" }" << nl
            << endl;
    }
}


// ************************************************************************* //
