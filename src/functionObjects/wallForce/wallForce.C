#include "wallForce.H"
#include "wallPolyPatch.H"
#include "wedgeRevolution.H"
#include "addToRunTimeSelectionTable.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace functionObjects
{
    defineTypeNameAndDebug(wallForce, 0);
    addToRunTimeSelectionTable(functionObject, wallForce, dictionary);
}
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::functionObjects::wallForce::wallForce
(
    const word& name,
    const Time& runTime,
    const dictionary& dict
)
:
    impactTimeHistory(name, runTime, dict),
    axis_(Zero),
    toFull_(0)
{
    wallForce::read(dict);

    toFull_ = wedgeToFull(mesh_, axis_);

    start();
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

bool Foam::functionObjects::wallForce::read(const dictionary& dict)
{
    impactTimeHistory::read(dict);

    const polyBoundaryMesh& pbm = mesh_.boundaryMesh();
    DynamicList<label> patches;
    if (dict.found("patches"))
    {
        const wordRes names(dict.get<wordRes>("patches"));
        const labelHashSet set(pbm.patchSet(names, false, true));
        if (set.empty())
        {
            FatalIOErrorInFunction(dict)
                << "patches " << names << " in function object " << name()
                << ": no such patch; valid patches: " << pbm.names()
                << exit(FatalIOError);
        }
        patches = set.sortedToc();
    }
    else
    {
        forAll(pbm, patchi)
        {
            if (isA<wallPolyPatch>(pbm[patchi]))
            {
                patches.append(patchi);
            }
        }
    }
    patches_ = patches;
    return true;
}


// * * * * * * * * * * * * * Protected Member Functions  * * * * * * * * * * //

Foam::wordList Foam::functionObjects::wallForce::columns() const
{
    DynamicList<word> c;
    for (const label patchi : patches_)
    {
        const word& p = mesh_.boundaryMesh()[patchi].name();
        for (const char* q : {"Fx", "Fy", "Fz", "Ix", "Iy", "Iz"})
        {
            c.append(p + "." + word(q));
        }
    }
    return wordList(c);
}


Foam::wordList Foam::functionObjects::wallForce::units() const
{
    DynamicList<word> u;
    forAll(patches_, i)
    {
        for (const char* q : {"[N]", "[N]", "[N]", "[Ns]", "[Ns]", "[Ns]"})
        {
            u.append(word(q));
        }
    }
    return wordList(u);
}


void Foam::functionObjects::wallForce::values(DynamicList<scalar>& row)
{
    const stepLedger& ledger = this->ledger();

    // Force and impulse of every patch reported, summed over the
    // processors (the patches that are not processor patches have the
    // same index on all of them)
    List<vector> sums(2*patches_.size(), Zero);
    forAll(patches_, i)
    {
        sums[2*i] = ledger.patchForces()[patches_[i]];
        sums[2*i + 1] = ledger.patchImpulses()[patches_[i]];
    }
    Pstream::listCombineGather(sums, plusEqOp<vector>());
    Pstream::listCombineScatter(sums);

    for (vector& v : sums)
    {
        if (toFull_ > 0)
        {
            v = toFull_*(v & axis_)*axis_;
        }
        for (direction d = 0; d < vector::nComponents; ++d)
        {
            // (+ 0: no negative zero from the projection)
            row.append(v[d] + 0.0);
        }
    }
}


// ************************************************************************* //
