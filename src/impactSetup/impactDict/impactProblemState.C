#include "impactProblem.H"
#include "phaseMaterial.H"
#include "equationOfState.H"
#include "inputDefaults.H"
#include "keywordCheck.H"
#include "Time.H"
#include "OSspecific.H"

// * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * * //

void Foam::impactProblem::resolveMaterials()
{
    // Each phase's material: the first body's (or the ambient's); another
    // material in the same phase stops
    HashTable<string> firstOwner;
    auto claim = [&](const word& phase, const word& material,
                     const string& owner, const dictionary& dict)
    {
        if (!phaseMaterials_.found(phase))
        {
            phaseMaterials_.set(phase, material);
            firstOwner.set(phase, owner);
        }
        else if (phaseMaterials_[phase] != material)
        {
            FatalIOErrorInFunction(dict)
                << owner.c_str() << ": phase " << phase << " has material "
                << material << ", but " << firstOwner[phase].c_str()
                << " gives it material " << phaseMaterials_[phase]
                << ": one phase, one material"
                << " (give the bodies different phase names)"
                << exit(FatalIOError);
        }
    };
    const dictionary& bd = dict_.subDict("bodies");
    for (const impactBody& b : bodies_)
    {
        claim(b.phase, b.material, b.owner(), bd.subDict(b.name()));
    }
    claim
    (
        ambient_.phase, ambient_.material, "impactDict ambient",
        dict_.subDict("ambient")
    );

    // Resolve: the library's entry, the phaseProperties entries on top
    for (const word& phase : phases_)
    {
        const word& material = phaseMaterials_[phase];
        const fileNameList places
        (
            phaseMaterial::searchPath(material, runTime_)
        );
        bool found = false;
        for (const fileName& f : places)
        {
            found = found || isFile(f);
        }
        if (!found)
        {
            // Name the body (or the ambient) and list what is available
            wordList available;
            for (const fileName& f : places)
            {
                for (const fileName& e : readDir(f.path(), fileName::FILE))
                {
                    if (!available.found(e))
                    {
                        available.append(e);
                    }
                }
            }
            Foam::sort(available);
            const dictionary& where =
                firstOwner[phase] == "impactDict ambient"
              ? dict_.subDict("ambient")
              : bd.subDict(word(firstOwner[phase].substr(5)));
            FatalIOErrorInFunction(where)
                << firstOwner[phase].c_str() << ": unknown material "
                << material << " (entry material): no file " << material
                << " in" << nl << "    " << places[0].path() << nl
                << "    " << places[1].path() << nl
                << "Available materials: " << available
                << " (docs/materials.md)" << exit(FatalIOError);
        }

        dictionary phaseDict;
        phaseDict.name() = dict_.name() + "/phaseProperties/" + phase;
        phaseDict.add("material", material);
        if (phaseProperties_.isDict(phase))
        {
            phaseMaterial::mergeOnto
            (
                phaseDict,
                phaseProperties_.subDict(phase)
            );
        }
        phaseDicts_.set
        (
            phase,
            phaseMaterial::phaseDict(phase, phaseDict, runTime_)
        );
    }

    // The densities
    for (impactBody& b : bodies_)
    {
        b.rho = density(bd.subDict(b.name()), b.owner(), b.phase, b.T);
    }
    ambient_.rho = density
    (
        dict_.subDict("ambient"), "impactDict ambient", ambient_.phase,
        ambient_.T
    );
}


Foam::scalar Foam::impactProblem::density
(
    const dictionary& dict,
    const string& owner,
    const word& phase,
    scalar& T
) const
{
    const dictionary& pd = phaseDicts_[phase];
    if (!pd.isDict("equationOfState"))
    {
        FatalIOErrorInFunction(pd)
            << owner.c_str() << ": the material " << phaseMaterials_[phase]
            << " of phase " << phase << " has no equationOfState"
            << exit(FatalIOError);
    }
    autoPtr<equationOfState> eos
    (
        equationOfState::New(phase, pd.subDict("equationOfState"))
    );
    const bool solid = pd.getOrDefault<word>("type", "fluid") == "solid";

    // p: the body's own or the ambient's
    const scalar p = dict.getOrDefault<scalar>("p", ambient_.p);

    if (dict.found("rho", keyType::LITERAL))
    {
        if (dict.found("T", keyType::LITERAL))
        {
            FatalIOErrorInFunction(dict)
                << owner.c_str() << ": give rho or T, not both"
                << exit(FatalIOError);
        }
        const scalar rho = dict.get<scalar>("rho");
        if (!eos->admissible(rho, p))
        {
            FatalIOErrorInFunction(dict)
                << owner.c_str() << ": rho " << rho << " at p " << p
                << " is outside the equation of state's range (material "
                << phaseMaterials_[phase] << ")" << exit(FatalIOError);
        }
        T = eos->hasTemperature() ? eos->T(rho, eos->e(rho, p)) : -1;
        return rho;
    }

    if (!eos->hasTemperature())
    {
        if (dict.found("T", keyType::LITERAL))
        {
            FatalIOErrorInFunction(dict)
                << owner.c_str()
                << ": entry T, but the equation of state of material "
                << phaseMaterials_[phase] << " has no temperature (no Cv):"
                << " give rho"
                << (solid ? " (or nothing: the elastic rho0)" : "")
                << exit(FatalIOError);
        }
        if (solid && pd.isDict("elasticity")
         && pd.subDict("elasticity").found("rho0"))
        {
            T = -1;
            return pd.subDict("elasticity").get<scalar>("rho0");
        }
        FatalIOErrorInFunction(dict)
            << owner.c_str()
            << ": no rho, and the equation of state of material "
            << phaseMaterials_[phase] << " has no temperature to find it"
            << " from p and T: give rho" << exit(FatalIOError);
    }

    // From p and T: T(rho, e(rho, p)) = T, bisection on log(rho)
    const scalar ambientT =
        dict_.subDict("ambient").getOrDefault<scalar>("T", 293);
    T = inputDefaults::get<scalar>(dict, "T", ambientT, owner);
    if (!(T > 0))
    {
        FatalIOErrorInFunction(dict)
            << owner.c_str() << ": T " << T << " must be positive"
            << exit(FatalIOError);
    }

    const scalar rhoRef = eos->referenceDensity();
    scalar lo = rhoRef > 0 ? 0.3*rhoRef : 1e-8;
    scalar hi = rhoRef > 0 ? min(3*rhoRef, 0.999*eos->rhoMax()) : 1e6;
    auto g = [&](const scalar rho)
    {
        const scalar e = eos->e(rho, p);
        return eos->T(rho, e) - T;
    };
    const scalar gLo = g(lo), gHi = g(hi);
    if (!(gLo*gHi < 0))
    {
        FatalIOErrorInFunction(dict)
            << owner.c_str() << ": no density between " << lo << " and " << hi
            << " gives T " << T << " at p " << p << " with the equation of"
            << " state of material " << phaseMaterials_[phase]
            << " (T there: " << gLo + T << ", " << gHi + T << "): give rho"
            << exit(FatalIOError);
    }
    for (label iter = 0; iter < 200 && hi - lo > 1e-14*hi; ++iter)
    {
        const scalar mid = Foam::sqrt(lo*hi);
        if ((g(mid) < 0) == (gLo < 0))
        {
            lo = mid;
        }
        else
        {
            hi = mid;
        }
    }
    return 0.5*(lo + hi);
}


void Foam::impactProblem::placeBodies()
{
    const dictionary& bd = dict_.subDict("bodies");
    forAll(bodies_, i)
    {
        impactBody& b = bodies_[i];
        const dictionary& d = bd.subDict(b.name());
        if (!d.found("gap", keyType::LITERAL))
        {
            continue;
        }
        if (!d.isDict("gap"))
        {
            FatalIOErrorInFunction(d)
                << b.owner().c_str() << ": entry gap must be a dictionary"
                << " { to <body>; distance <m>; }" << exit(FatalIOError);
        }
        const dictionary& gd = d.subDict("gap");
        checkKeywords(gd, {"to", "distance"}, b.owner() + ", gap");
        if (!gd.found("to") || !gd.found("distance"))
        {
            FatalIOErrorInFunction(gd)
                << b.owner().c_str()
                << ", gap: needs the entries to and distance"
                << exit(FatalIOError);
        }
        const word to(gd.get<word>("to"));
        label j = -1;
        forAll(bodies_, k)
        {
            if (k != i && bodies_[k].name() == to)
            {
                j = k;
            }
        }
        if (j < 0)
        {
            wordList others;
            forAll(bodies_, k)
            {
                if (k != i)
                {
                    others.append(bodies_[k].name());
                }
            }
            FatalIOErrorInFunction(gd)
                << b.owner().c_str() << ", gap: unknown body " << to
                << " (entry to); the other bodies are " << others
                << exit(FatalIOError);
        }
        if (j > i && bodies_[j].shape().bounded()
         && bd.subDict(to).found("gap", keyType::LITERAL))
        {
            FatalIOErrorInFunction(gd)
                << b.owner().c_str() << ", gap: body " << to
                << " is placed by a gap"
                << " itself later on: put the gap on one of the two"
                << exit(FatalIOError);
        }
        const scalar distance(gd.get<scalar>("distance"));
        b.shift(gapShift(b, bodies_[j], distance, gd));
    }
}


Foam::vector Foam::impactProblem::gapShift
(
    const impactBody& body,
    const impactBody& target,
    const scalar gap,
    const dictionary& dict
) const
{
    if (!(mag(body.U) > 0))
    {
        FatalIOErrorInFunction(dict)
            << body.owner().c_str()
            << ", gap: the body is moved along its velocity,"
            << " and its U is zero" << exit(FatalIOError);
    }
    if (!body.shape().bounded())
    {
        FatalIOErrorInFunction(dict)
            << body.owner().c_str()
            << ", gap: an unbounded shape cannot be placed"
            << " by a gap (place the other body)" << exit(FatalIOError);
    }
    const vector d(body.U/mag(body.U));

    // Points on the body's surface: a grid over its bounds, the points
    // near the surface projected onto it (a step along the gradient)
    const boundBox bb(body.bounds());
    const label n = 64;
    const vector delta(bb.span()/n);
    const scalar near = mag(delta);
    const scalar eps = 1e-6*bb.mag();
    DynamicList<point> surface;
    for (label i = 0; i <= n; ++i)
    {
        for (label j = 0; j <= n; ++j)
        {
            for (label k = 0; k <= n; ++k)
            {
                point x
                (
                    bb.min()
                  + vector(i*delta.x(), j*delta.y(), k*delta.z())
                );
                scalar f = body.distance(x);
                if (mag(f) > near)
                {
                    continue;
                }
                for (label iter = 0; iter < 3; ++iter)
                {
                    vector grad;
                    for (direction c = 0; c < 3; ++c)
                    {
                        vector h(Zero);
                        h[c] = eps;
                        grad[c] =
                            (body.distance(x + h) - body.distance(x - h))
                           /(2*eps);
                    }
                    if (mag(grad) < SMALL)
                    {
                        break;
                    }
                    x -= f*grad/magSqr(grad);
                    f = body.distance(x);
                }
                surface.append(x);
            }
        }
    }

    // The gap at a shift s along -d: the nearest surface point's distance
    // to the target; it grows with s
    auto gapAt = [&](const scalar s)
    {
        scalar g = GREAT;
        for (const point& x : surface)
        {
            g = min(g, target.distance(x - s*d));
        }
        return g;
    };

    const scalar size = bb.mag();
    scalar lo = 0, hi = 0;
    scalar g0 = gapAt(0);
    scalar step = size;
    if (g0 < gap)
    {
        hi = step;
        while (gapAt(hi) < gap && hi < 1e3*size)
        {
            lo = hi;
            hi *= 2;
        }
    }
    else
    {
        lo = -step;
        while (gapAt(lo) > gap && lo > -1e3*size)
        {
            hi = lo;
            lo *= 2;
        }
    }
    if (!(gapAt(lo) <= gap && gapAt(hi) >= gap))
    {
        FatalIOErrorInFunction(dict)
            << body.owner().c_str() << ", gap: moving along its velocity "
            << body.U
            << " the body does not reach distance " << gap << " from "
            << target.name() << exit(FatalIOError);
    }
    for (label iter = 0; iter < 100 && hi - lo > 1e-12*size; ++iter)
    {
        const scalar mid = 0.5*(lo + hi);
        if (gapAt(mid) < gap)
        {
            lo = mid;
        }
        else
        {
            hi = mid;
        }
    }
    const scalar s = 0.5*(lo + hi);
    Info<< body.owner().c_str() << ": moved by " << -s*d << " to lie "
        << gap << " from " << target.name() << endl;
    return -s*d;
}


// ************************************************************************* //
