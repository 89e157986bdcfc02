#include "impactProblem.H"
#include "keywordCheck.H"
#include "inputDefaults.H"
#include "phaseRegimes.H"
#include "OStringStream.H"

// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * * //

namespace
{

using namespace Foam;

// A required sub-dictionary or entry, with a message naming the owner
void require(const dictionary& dict, const word& key, const string& owner)
{
    if (!dict.found(key, keyType::LITERAL))
    {
        FatalIOErrorInFunction(dict)
            << owner.c_str() << ": missing entry " << key << " in "
            << dict.name()
            << exit(FatalIOError);
    }
}

const dictionary& subDict
(
    const dictionary& dict,
    const word& key,
    const string& owner
)
{
    require(dict, key, owner);
    if (!dict.isDict(key, keyType::LITERAL))
    {
        FatalIOErrorInFunction(dict)
            << owner.c_str() << ": entry " << key
            << " must be a dictionary { ... }"
            << exit(FatalIOError);
    }
    return dict.subDict(key);
}

}


// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

const Foam::wordList Foam::impactProblem::keywords
({
    "geometry", "domain", "ambient", "bodies", "phaseProperties",
    "contacts", "outputs", "refinement"
});


// * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * * //

void Foam::impactProblem::readDomain()
{
    const wordList geometries({"threeD", "axisymmetric", "planar"});
    require(dict_, "geometry", "impactDict");
    geometry_ = dict_.get<word>("geometry");
    if (!geometries.found(geometry_))
    {
        FatalIOErrorInFunction(dict_)
            << "impactDict: unknown geometry " << geometry_
            << " (entry geometry); did you mean "
            << nearestKeyword(geometry_, geometries) << "?" << nl
            << "Valid geometries: " << geometries << exit(FatalIOError);
    }

    hasDomain_ = dict_.found("domain", keyType::LITERAL);
    if (!hasDomain_)
    {
        return;
    }

    const dictionary& dd = subDict(dict_, "domain", "impactDict");
    checkKeywords
    (
        dd,
        {"min", "max", "cellSize", "patches"},
        "impactDict domain"
    );
    require(dd, "min", "impactDict domain");
    require(dd, "max", "impactDict domain");
    require(dd, "cellSize", "impactDict domain");
    min_ = dd.get<point>("min");
    max_ = dd.get<point>("max");
    cellSize_ = dd.get<scalar>("cellSize");
    if (!(cellSize_ > 0))
    {
        FatalIOErrorInFunction(dd)
            << "impactDict domain: entry cellSize " << cellSize_
            << " must be positive" << exit(FatalIOError);
    }
    const label nDir = geometry_ == "threeD" ? 3 : 2;
    for (label i = 0; i < nDir; ++i)
    {
        if (!(max_[i] > min_[i]))
        {
            FatalIOErrorInFunction(dd)
                << "impactDict domain: min " << min_ << " max " << max_
                << " is empty in direction " << i << " (need max > min)"
                << exit(FatalIOError);
        }
    }
    if (geometry_ == "axisymmetric" && min_.y() != 0)
    {
        FatalIOErrorInFunction(dd)
            << "impactDict domain: geometry axisymmetric has the axis at"
            << " y = 0: min y must be 0 (min " << min_ << ")"
            << exit(FatalIOError);
    }

    // The outer patches the geometry has
    wordList patches({"xMin", "xMax", "yMin", "yMax", "zMin", "zMax"});
    if (geometry_ == "axisymmetric")
    {
        patches = wordList({"xMin", "xMax", "yMax"});
    }
    else if (geometry_ == "planar")
    {
        patches = wordList({"xMin", "xMax", "yMin", "yMax"});
    }
    const dictionary& pd =
        dd.found("patches", keyType::LITERAL)
      ? subDict(dd, "patches", "impactDict domain")
      : dictionary::null;
    checkKeywords
    (
        pd,
        patches,
        "impactDict domain, patches (geometry " + geometry_ + ")"
    );
    const wordList kinds({"wall", "open", "symmetry"});
    for (const word& patch : patches)
    {
        const word kind
        (
            inputDefaults::get<word>
            (
                pd, patch, "wall", "impactDict domain, patches"
            )
        );
        if (!kinds.found(kind))
        {
            FatalIOErrorInFunction(pd)
                << "impactDict domain, patches: unknown kind " << kind
                << " of patch " << patch << "; did you mean "
                << nearestKeyword(kind, kinds) << "?" << nl
                << "Valid kinds: " << kinds << exit(FatalIOError);
        }
        patchKinds_.set(patch, kind);
    }
}


void Foam::impactProblem::readAmbient()
{
    const dictionary& ad = subDict(dict_, "ambient", "impactDict");
    checkKeywords
    (
        ad,
        {"material", "phase", "p", "T", "rho", "U"},
        "impactDict ambient"
    );
    require(ad, "material", "impactDict ambient");
    ambient_.material = ad.get<word>("material");
    ambient_.phase = ad.getOrDefault<word>("phase", ambient_.material);
    ambient_.p = inputDefaults::get<scalar>(ad, "p", 1e5, "impactDict ambient");
    ambient_.U = ad.getOrDefault<vector>("U", Zero);
    ambient_.rho = 0;
    ambient_.T = -1;
}


void Foam::impactProblem::readBodies()
{
    const dictionary& bd = subDict(dict_, "bodies", "impactDict");
    const wordList bodyKeys
    ({
        "material", "phase", "U", "T", "rho", "p", "angle", "rotationAxis",
        "gap", "cuts", "radialVelocity"
    });

    label n = 0;
    for (const entry& e : bd)
    {
        if (e.isDict())
        {
            ++n;
        }
    }
    if (n == 0)
    {
        FatalIOErrorInFunction(bd)
            << "impactDict bodies: no body (each body is a dictionary:"
            << " name { shape ...; material ...; })" << exit(FatalIOError);
    }
    bodies_.setSize(n);

    label i = 0;
    for (const entry& e : bd)
    {
        if (!e.isDict())
        {
            FatalIOErrorInFunction(bd)
                << "impactDict bodies: entry " << e.keyword()
                << " is not a body (a dictionary name { shape ...; })"
                << exit(FatalIOError);
        }
        const word name(e.keyword());
        const dictionary& d = e.dict();
        bodies_.set(i, new impactBody(name, d, bodyKeys, runTime_));
        impactBody& b = bodies_[i];

        require(d, "material", b.owner());
        b.material = d.get<word>("material");
        b.phase = d.getOrDefault<word>("phase", b.material);
        b.U = d.getOrDefault<vector>("U", Zero);
        if (b.rotated())
        {
            b.U = b.rotation() & b.U;
        }
        if (d.found("radialVelocity", keyType::LITERAL))
        {
            readRadialVelocity(d, b);
        }
        b.p = d.getOrDefault<scalar>("p", ambient_.p);

        // The bodies this one cuts: earlier ones
        if (d.found("cuts", keyType::LITERAL))
        {
            for (const word& cut : d.get<wordList>("cuts"))
            {
                label j = 0;
                while (j < i && bodies_[j].name() != cut)
                {
                    ++j;
                }
                if (j == i)
                {
                    wordList earlier(i);
                    forAll(earlier, k)
                    {
                        earlier[k] = bodies_[k].name();
                    }
                    FatalIOErrorInFunction(d)
                        << b.owner().c_str() << ": entry cuts names " << cut
                        << ", which is not an earlier body; the earlier"
                        << " bodies are " << earlier << exit(FatalIOError);
                }
                bodies_[j].cutBy(b);
            }
        }
        ++i;
    }
}


void Foam::impactProblem::readRadialVelocity
(
    const dictionary& d,
    impactBody& b
) const
{
    const string owner(b.owner() + ", radialVelocity");
    if (d.found("U", keyType::LITERAL))
    {
        FatalIOErrorInFunction(d)
            << b.owner().c_str() << ": give either U or radialVelocity,"
            << " not both" << exit(FatalIOError);
    }
    if (d.found("gap", keyType::LITERAL))
    {
        FatalIOErrorInFunction(d)
            << b.owner().c_str() << ": a gap moves a body along its"
            << " velocity U, which a radialVelocity does not have"
            << exit(FatalIOError);
    }
    const dictionary& rd = subDict(d, "radialVelocity", b.owner());
    checkKeywords(rd, {"centre", "U", "radius", "exponent"}, owner);
    for (const word& key : {"centre", "U", "radius"})
    {
        require(rd, key, owner);
    }
    b.radial = true;
    b.radialCentre = rd.get<point>("centre");
    b.radialU = rd.get<scalar>("U");
    b.radialRadius = rd.get<scalar>("radius");
    b.radialExponent = rd.getOrDefault<scalar>("exponent", 0);
    if (!(b.radialRadius > 0))
    {
        FatalIOErrorInFunction(rd)
            << owner.c_str() << ": radius " << b.radialRadius
            << " must be positive" << exit(FatalIOError);
    }
}


void Foam::impactProblem::readPhaseProperties()
{
    if (!dict_.found("phaseProperties", keyType::LITERAL))
    {
        return;
    }
    phaseProperties_ =
        subDict(dict_, "phaseProperties", "impactDict");
    wordList valid(phaseRegimes::keywords);
    valid.append("contacts");
    valid.append(phases_);
    OStringStream owner;
    owner << "impactDict phaseProperties (the phases";
    for (const word& phase : phases_)
    {
        owner << " " << phase.c_str();
    }
    owner << " and phaseProperties entries)";
    checkKeywords(phaseProperties_, valid, owner.str());
    for (const word& key : phaseProperties_.toc())
    {
        if (phases_.found(key) && !phaseProperties_.isDict(key))
        {
            FatalIOErrorInFunction(phaseProperties_)
                << "impactDict phaseProperties: entry " << key
                << " names a phase: it must be a dictionary of that phase's"
                << " entries" << exit(FatalIOError);
        }
    }
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::impactProblem::impactProblem
(
    const Time& runTime,
    const dictionary& dict
)
:
    runTime_(runTime),
    dict_(dict),
    hasDomain_(false),
    min_(Zero),
    max_(Zero),
    cellSize_(0),
    interval_(0)
{
    checkKeywords(dict_, keywords, "impactDict");
    readDomain();
    readAmbient();
    readBodies();

    // The phases in order of appearance, the ambient's last
    DynamicList<word> phases;
    for (const impactBody& b : bodies_)
    {
        if (!phases.found(b.phase) && b.phase != ambient_.phase)
        {
            phases.append(b.phase);
        }
    }
    phases.append(ambient_.phase);
    phases_.transfer(phases);

    readPhaseProperties();
    resolveMaterials();
    placeBodies();
    readOutputs();
    readRefinement();
}


// ************************************************************************* //
