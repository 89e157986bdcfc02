#include "vonMises.H"
#include "inputDefaults.H"
#include "constantYieldStress.H"
#include "linearYieldStress.H"
#include "addToRunTimeSelectionTable.H"

namespace Foam
{
namespace plasticModels
{
    defineTypeNameAndDebug(vonMises, 0);
    addToRunTimeSelectionTable(plasticModel, vonMises, dictionary);
}
}


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

Foam::autoPtr<Foam::yieldStress>
Foam::plasticModels::vonMises::newYieldStress
(
    const word& phaseName,
    const dictionary& dict
)
{
    if (dict.found("yieldStress"))
    {
        if (!dict.isDict("yieldStress"))
        {
            FatalIOErrorInFunction(dict)
                << "Phase " << phaseName << ": plasticity yieldStress must be"
                << " a sub-dictionary, e.g."
                << " yieldStress { type linear; sigmaY0 4e8; H 1e8; }"
                << exit(FatalIOError);
        }
        for (const char* key : {"sigmaY", "sigmaY0", "H"})
        {
            if (dict.found(key))
            {
                FatalIOErrorInFunction(dict)
                    << "Phase " << phaseName << ": plasticity has both a"
                    << " yieldStress sub-dictionary and the entry " << key
                    << "; give the flow stress in one place"
                    << exit(FatalIOError);
            }
        }
        return yieldStress::New(phaseName, dict.subDict("yieldStress"));
    }

    // The original keywords
    const bool hasY = dict.found("sigmaY");
    const bool hasY0 = dict.found("sigmaY0");
    if (hasY == hasY0)
    {
        FatalIOErrorInFunction(dict)
            << "Phase " << phaseName << ": plasticity needs exactly one of"
            << " sigmaY (yield stress) or sigmaY0 (initial yield stress)"
            << (
                   hasY ? ""
                 : "\nor a yieldStress sub-dictionary, e.g."
                   " yieldStress { type linear; sigmaY0 4e8; H 1e8; }"
               )
            << exit(FatalIOError);
    }
    const scalar sigmaY0 = dict.get<scalar>(hasY ? "sigmaY" : "sigmaY0");

    if (!(sigmaY0 > 0))
    {
        FatalIOErrorInFunction(dict)
            << "Phase " << phaseName << ": plasticity "
            << (hasY ? "sigmaY" : "sigmaY0") << " = " << sigmaY0
            << " must be positive" << exit(FatalIOError);
    }

    if (!dict.found("H"))
    {
        return autoPtr<yieldStress>
        (
            new yieldStresses::constant(phaseName, sigmaY0)
        );
    }

    const scalar H = dict.get<scalar>("H");
    if (!(H >= 0))
    {
        FatalIOErrorInFunction(dict)
            << "Phase " << phaseName << ": plasticity H = " << H
            << " must be non-negative" << exit(FatalIOError);
    }
    return autoPtr<yieldStress>
    (
        new yieldStresses::linear(phaseName, sigmaY0, H)
    );
}


Foam::vonMisesReturn Foam::plasticModels::vonMises::newReturn
(
    const word& phaseName,
    const dictionary& dict
)
{
    const scalar tau = dict.get<scalar>("tau");
    const scalar n =
        inputDefaults::get<scalar>
        (
            dict, "n", 0, "Phase " + phaseName + ", plasticity"
        );

    if (!(tau >= 0))
    {
        FatalIOErrorInFunction(dict)
            << "Phase " << phaseName << ": plasticity tau = " << tau
            << " must be non-negative (0 for ideal plasticity)"
            << exit(FatalIOError);
    }
    if (!(n >= 0))
    {
        FatalIOErrorInFunction(dict)
            << "Phase " << phaseName << ": plasticity n = " << n
            << " must be non-negative" << exit(FatalIOError);
    }

    return vonMisesReturn(tau, n);
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::plasticModels::vonMises::vonMises
(
    const word& phaseName,
    const dictionary& dict
)
:
    plasticModel(phaseName, dict),
    yieldStress_(newYieldStress(phaseName, dict)),
    return_(newReturn(phaseName, dict))
{}


Foam::wordList Foam::plasticModels::vonMises::keywords() const
{
    return {"type", "tau", "n", "yieldStress", "sigmaY", "sigmaY0", "H"};
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::scalar Foam::plasticModels::vonMises::correct
(
    cobasis::matrix& A,
    scalar& epsP,
    const elasticModel& elastic,
    const scalar dt,
    const scalar T
) const
{
    const vonMisesReturn::result r =
        return_.correct(A, epsP, elastic, yieldStress_(), dt, T);

    epsP += r.dEpsP;

    return r.heat;
}
