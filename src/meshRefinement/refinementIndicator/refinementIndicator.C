#include "refinementIndicator.H"
#include "keywordCheck.H"
#include "inputDefaults.H"
#include "syncTools.H"

// * * * * * * * * * * * * * * * * Static Data * * * * * * * * * * * * * * * //

const Foam::wordList Foam::refinementIndicator::keywords
({
    "interfaces", "shocks", "plasticFlow"
});


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::refinementIndicator::refinementIndicator
(
    const phaseSystem& phases,
    const dictionary& dict
)
:
    phases_(phases),
    interfaces_(dict.found("interfaces")),
    alphaLower_(1e-3),
    alphaUpper_(0.999),
    shocks_(dict.found("shocks")),
    jump_(0.1),
    pRef_(1e5),
    plastic_(dict.found("plasticFlow")),
    rate_(1e3),
    epsilonPIndex_(phases.size(), -1),
    epsilonP0_(phases.size()),
    t0_(phases.mesh().time().value())
{
    const string owner("refinement");
    if (interfaces_)
    {
        const dictionary& d = dict.subDict("interfaces");
        alphaLower_ = inputDefaults::get(d, "lower", alphaLower_, owner);
        alphaUpper_ = inputDefaults::get(d, "upper", alphaUpper_, owner);
    }
    if (shocks_)
    {
        const dictionary& d = dict.subDict("shocks");
        jump_ = inputDefaults::get(d, "jump", jump_, owner);
        pRef_ = inputDefaults::get(d, "pRef", pRef_, owner);
    }
    if (plastic_)
    {
        const dictionary& d = dict.subDict("plasticFlow");
        rate_ = inputDefaults::get(d, "rate", rate_, owner);
        bool any = false;
        for (label k = 0; k < phases.size(); ++k)
        {
            epsilonPIndex_[k] = phases[k].carriedIndex("epsilonP");
            any = any || epsilonPIndex_[k] >= 0;
        }
        if (!any)
        {
            FatalIOErrorInFunction(d)
                << "plasticFlow asks for refinement where solids flow, but"
                << " no phase of " << phases.names() << " carries a plastic"
                << " strain epsilonP" << exit(FatalIOError);
        }
    }
    store();
}


// * * * * * * * * * * * * * Static Member Functions * * * * * * * * * * * //

void Foam::refinementIndicator::checkSettings(const dictionary& dict)
{
    const string owner("refinement");
    for (const word& key : keywords)
    {
        if (dict.found(key, keyType::LITERAL) && !dict.isDict(key))
        {
            FatalIOErrorInFunction(dict)
                << "refinement: " << key << " must be a dictionary of its"
                << " settings, e.g. " << key << " {}" << exit(FatalIOError);
        }
    }
    if (dict.isDict("interfaces"))
    {
        const dictionary& d = dict.subDict("interfaces");
        checkKeywords(d, {"lower", "upper"}, owner + " interfaces");
        const scalar lower = d.getOrDefault<scalar>("lower", 1e-3);
        const scalar upper = d.getOrDefault<scalar>("upper", 0.999);
        if (!(0 < lower && lower < upper && upper < 1))
        {
            FatalIOErrorInFunction(d)
                << "Need 0 < lower (" << lower << ") < upper (" << upper
                << ") < 1" << exit(FatalIOError);
        }
    }
    if (dict.isDict("shocks"))
    {
        const dictionary& d = dict.subDict("shocks");
        checkKeywords(d, {"jump", "pRef"}, owner + " shocks");
        const scalar jump = d.getOrDefault<scalar>("jump", 0.1);
        const scalar pRef = d.getOrDefault<scalar>("pRef", 1e5);
        if (!(jump > 0) || !(pRef >= 0))
        {
            FatalIOErrorInFunction(d)
                << "Need jump > 0 (" << jump << ") and pRef >= 0 (" << pRef
                << ")" << exit(FatalIOError);
        }
    }
    if (dict.isDict("plasticFlow"))
    {
        const dictionary& d = dict.subDict("plasticFlow");
        checkKeywords(d, {"rate"}, owner + " plasticFlow");
        const scalar rate = d.getOrDefault<scalar>("rate", 1e3);
        if (!(rate > 0))
        {
            FatalIOErrorInFunction(d)
                << "Need rate > 0, not " << rate << exit(FatalIOError);
        }
    }
    if
    (
        !dict.found("interfaces") && !dict.found("shocks")
     && !dict.found("plasticFlow")
    )
    {
        FatalIOErrorInFunction(dict)
            << "No criterion for refinement: give at least one of "
            << keywords << exit(FatalIOError);
    }
}


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

template<class Jump>
void Foam::refinementIndicator::markJumps
(
    const scalarField& v,
    const Jump& jumps,
    bitSet& cells
) const
{
    const fvMesh& mesh = phases_.mesh();
    const labelUList& own = mesh.owner();
    const labelUList& nei = mesh.neighbour();
    forAll(nei, f)
    {
        if (jumps(v[own[f]], v[nei[f]]))
        {
            cells.set(own[f]);
            cells.set(nei[f]);
        }
    }

    // Across processor boundaries: the other side's values
    scalarField vNbr;
    syncTools::swapBoundaryCellList(mesh, v, vNbr);
    const label start = mesh.nInternalFaces();
    for (const polyPatch& pp : mesh.boundaryMesh())
    {
        if (!pp.coupled())
        {
            continue;
        }
        forAll(pp, i)
        {
            const label f = pp.start() + i;
            if (jumps(v[own[f]], vNbr[f - start]))
            {
                cells.set(own[f]);
            }
        }
    }
}


void Foam::refinementIndicator::markInterfaces(bitSet& cells) const
{
    // A sharp interface on a face: fractions of 0 and 1 on its sides, as
    // setFields writes them
    const auto sharp = [](const scalar a1, const scalar a2)
    {
        return mag(a1 - a2) > 0.5;
    };
    for (label k = 0; k < phases_.size(); ++k)
    {
        const scalarField& alpha = phases_.alpha(k).primitiveField();
        forAll(alpha, c)
        {
            if (alpha[c] > alphaLower_ && alpha[c] < alphaUpper_)
            {
                cells.set(c);
            }
        }
        markJumps(alpha, sharp, cells);
    }
}


void Foam::refinementIndicator::markShocks(bitSet& cells) const
{
    const label nCells = phases_.mesh().nCells();

    // The mixture's density and pressure
    scalarField rho(nCells, Zero);
    scalarField p(nCells, Zero);
    for (label k = 0; k < phases_.size(); ++k)
    {
        const scalarField& alpha = phases_.alpha(k).primitiveField();
        const scalarField& rhok = phases_.rho(k).primitiveField();
        const scalarField& pk = phases_.p(k).primitiveField();
        forAll(rho, c)
        {
            rho[c] += alpha[c]*rhok[c];
            p[c] += alpha[c]*pk[c];
        }
    }

    markJumps
    (
        rho,
        [this](const scalar r1, const scalar r2)
        {
            const scalar rMax = max(r1, r2);
            return rMax > 0 && mag(r1 - r2) > jump_*rMax;
        },
        cells
    );
    markJumps
    (
        p,
        [this](const scalar p1, const scalar p2)
        {
            return mag(p1 - p2) > jump_*(max(mag(p1), mag(p2)) + pRef_);
        },
        cells
    );
}


void Foam::refinementIndicator::markPlasticFlow(bitSet& cells) const
{
    const scalar dt = phases_.mesh().time().value() - t0_;
    if (!(dt > 0))
    {
        return;
    }
    for (label k = 0; k < phases_.size(); ++k)
    {
        const label i = epsilonPIndex_[k];
        if (i < 0)
        {
            continue;
        }
        const scalarField& eps = phases_[k].carried(i).primitiveField();
        const scalarField& eps0 = epsilonP0_[k];
        forAll(eps, c)
        {
            if (eps[c] - eps0[c] > rate_*dt)
            {
                cells.set(c);
            }
        }
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::refinementIndicator::mark(bitSet& cells) const
{
    if (interfaces_)
    {
        markInterfaces(cells);
    }
    if (shocks_)
    {
        markShocks(cells);
    }
    if (plastic_)
    {
        markPlasticFlow(cells);
    }
}


void Foam::refinementIndicator::store()
{
    if (!plastic_)
    {
        return;
    }
    for (label k = 0; k < phases_.size(); ++k)
    {
        if (epsilonPIndex_[k] >= 0)
        {
            epsilonP0_[k] =
                phases_[k].carried(epsilonPIndex_[k]).primitiveField();
        }
    }
    t0_ = phases_.mesh().time().value();
}


// ************************************************************************* //
