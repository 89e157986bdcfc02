/*---------------------------------------------------------------------------*\
  impactFoam: Eulerian multiphase elastic-plastic impact solver for OpenFOAM
\*---------------------------------------------------------------------------*/

#include "phaseRegimes.H"
#include "inputDefaults.H"
#include "error.H"
#include "Pair.H"
#include <cmath>

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

const Foam::wordList Foam::phaseRegimes::keywords
({
    "alphaMin", "alphaTrace", "alphaMinor", "massFractionMinor",
    "gasTraceRatio", "dustDensityRatio", "pVacuum"
});


const Foam::List<Foam::Pair<Foam::word>> Foam::phaseRegimes::removedKeywords
({
    Pair<word>
    (
        "massFractionTrace",
        "a fluid on a reference isentrope is a trace below massFractionMinor"
        " of its cell's mass"
    )
});


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

namespace
{
    // An optional scalar of phaseProperties, its default noted
    Foam::scalar get
    (
        const Foam::dictionary& dict,
        const Foam::word& key,
        const Foam::scalar deflt
    )
    {
        return Foam::inputDefaults::get(dict, key, deflt, "phaseProperties");
    }
}


Foam::phaseRegimes::phaseRegimes(const dictionary& dict)
:
    alphaMin_(get(dict, "alphaMin", 1e-8)),
    alphaTrace_(get(dict, "alphaTrace", 1e-6)),
    alphaMinor_(get(dict, "alphaMinor", 1e-3)),
    massFractionMinor_(get(dict, "massFractionMinor", 1e-6)),
    gasTraceRatio_(get(dict, "gasTraceRatio", 1)),
    dustDensityRatio_(get(dict, "dustDensityRatio", 0.8)),
    pVacuum_(get(dict, "pVacuum", 1))
{
    for (const Pair<word>& removed : removedKeywords)
    {
        if (dict.found(removed.first()))
        {
            IOWarningInFunction(dict)
                << removed.first() << " is no longer read and is ignored: "
                << removed.second() << endl;
        }
    }

    if
    (
        !(
            alphaMin_ > 0 && alphaMin_ < alphaTrace_
         && alphaTrace_ <= alphaMinor_ && alphaMinor_ < 0.5
        )
    )
    {
        FatalIOErrorInFunction(dict)
            << "Need 0 < alphaMin (" << alphaMin_ << ") < alphaTrace ("
            << alphaTrace_ << ") <= alphaMinor (" << alphaMinor_
            << ") < 0.5" << exit(FatalIOError);
    }
    if (!(massFractionMinor_ >= 0 && massFractionMinor_ < 1))
    {
        FatalIOErrorInFunction(dict)
            << "Need 0 <= massFractionMinor (" << massFractionMinor_
            << ") < 1" << exit(FatalIOError);
    }
    if (!(gasTraceRatio_ >= 0 && std::isfinite(gasTraceRatio_)))
    {
        FatalIOErrorInFunction(dict)
            << "Need a finite gasTraceRatio >= 0, not " << gasTraceRatio_
            << exit(FatalIOError);
    }
    if (!(dustDensityRatio_ >= 0 && dustDensityRatio_ < 1))
    {
        FatalIOErrorInFunction(dict)
            << "Need 0 <= dustDensityRatio < 1, not " << dustDensityRatio_
            << exit(FatalIOError);
    }
    if (!std::isfinite(pVacuum_))
    {
        FatalIOErrorInFunction(dict)
            << "Need a finite pVacuum, not " << pVacuum_
            << exit(FatalIOError);
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::phaseRegimes::setReferenceDensities(const UList<scalar>& rho0Solid)
{
    dustDensity_.setSize(rho0Solid.size());
    forAll(rho0Solid, k)
    {
        dustDensity_[k] = dustDensityRatio_*rho0Solid[k];
    }
}


// ************************************************************************* //
