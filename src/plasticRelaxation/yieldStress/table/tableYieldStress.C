#include "tableYieldStress.H"
#include "Tuple2.H"
#include "addToRunTimeSelectionTable.H"

namespace Foam
{
namespace yieldStresses
{
    defineTypeNameAndDebug(table, 0);
    addToRunTimeSelectionTable(yieldStress, table, dictionary);
}
}


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

void Foam::yieldStresses::table::readValues(const dictionary& dict)
{
    if (!dict.found("values"))
    {
        FatalIOErrorInFunction(dict)
            << "Phase " << phaseName_ << ": yieldStress table needs the"
            << " entry values, the pairs (epsP sigmaY) from epsP = 0, e.g."
            << " values ((0 9e7) (0.1 2.2e8) (0.5 3.3e8));"
            << exit(FatalIOError);
    }

    const List<Tuple2<scalar, scalar>> values
    (
        dict.get<List<Tuple2<scalar, scalar>>>("values")
    );
    const label n = values.size();

    if (n < 1)
    {
        FatalIOErrorInFunction(dict)
            << "Phase " << phaseName_ << ": yieldStress table values is"
            << " empty; it needs at least one pair (epsP sigmaY)"
            << exit(FatalIOError);
    }

    epsP_.setSize(n);
    sigma_.setSize(n);
    forAll(values, i)
    {
        epsP_[i] = values[i].first();
        sigma_[i] = values[i].second();
    }

    if (!(epsP_[0] == 0))
    {
        FatalIOErrorInFunction(dict)
            << "Phase " << phaseName_ << ": yieldStress table values starts"
            << " at epsP = " << epsP_[0] << "; the first pair must be at"
            << " epsP = 0 (the initial yield stress)" << exit(FatalIOError);
    }
    if (!(sigma_[0] > 0) || !std::isfinite(sigma_[0]))
    {
        FatalIOErrorInFunction(dict)
            << "Phase " << phaseName_ << ": yieldStress table values: the"
            << " first stress (initial yield stress) sigmaY = " << sigma_[0]
            << " must be positive" << exit(FatalIOError);
    }
    for (label i = 1; i < n; ++i)
    {
        if (!(epsP_[i] > epsP_[i-1]) || !std::isfinite(epsP_[i]))
        {
            FatalIOErrorInFunction(dict)
                << "Phase " << phaseName_ << ": yieldStress table values:"
                << " epsP must be strictly increasing; pair " << i
                << " has epsP = " << epsP_[i] << " after " << epsP_[i-1]
                << exit(FatalIOError);
        }
        if (!(sigma_[i] >= 0) || !std::isfinite(sigma_[i]))
        {
            FatalIOErrorInFunction(dict)
                << "Phase " << phaseName_ << ": yieldStress table values:"
                << " pair " << i << " has the negative (or not finite)"
                << " stress sigmaY = " << sigma_[i] << exit(FatalIOError);
        }
    }
    slope_.setSize(n - 1);
    forAll(slope_, i)
    {
        slope_[i] = (sigma_[i+1] - sigma_[i])/(epsP_[i+1] - epsP_[i]);
    }
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::yieldStresses::table::table
(
    const word& phaseName,
    const dictionary& dict
)
:
    yieldStress(phaseName)
{
    readValues(dict);
}


Foam::wordList Foam::yieldStresses::table::keywords() const
{
    return {"type", "values"};
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::scalar Foam::yieldStresses::table::sigmaY
(
    const scalar epsP,
    const scalar,
    const scalar
) const
{
    const label last = epsP_.size() - 1;

    // Past the last pair: constant. Below the first (epsP < 0, which a
    // carried epsP never is): the initial yield stress
    if (!(epsP < epsP_[last]))
    {
        return sigma_[last];
    }
    if (!(epsP > 0))
    {
        return sigma_[0];
    }

    // The interval i with epsP_[i] <= epsP < epsP_[i+1]: binary search,
    // epsP_[lo] <= epsP < epsP_[hi] throughout
    label lo = 0, hi = last;
    while (hi - lo > 1)
    {
        const label mid = (lo + hi)/2;
        if (epsP < epsP_[mid])
        {
            hi = mid;
        }
        else
        {
            lo = mid;
        }
    }

    return sigma_[lo] + slope_[lo]*(epsP - epsP_[lo]);
}
