#include "stepLedger.H"
#include "IFstream.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
    defineTypeNameAndDebug(stepLedger, 0);
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::stepLedger::stepLedger(const phaseSystem& phases)
:
    regIOobject
    (
        IOobject
        (
            typeName,
            phases.mesh().time().timeName(),
            "uniform",
            phases.mesh(),
            IOobject::NO_READ,
            IOobject::AUTO_WRITE,
            true
        )
    ),
    phases_(phases),
    timeIndex_(-1),
    deltaT_(0),
    patchForces_(phases.mesh().boundary().size(), Zero),
    patchImpulses_(phases.mesh().boundary().size(), Zero),
    unpaidEnergy_(0),
    frictionalHeat_(0)
{
    readRestart();
}


// * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

void Foam::stepLedger::readRestart()
{
    // (at construction this object's own path is the start time's)
    const fvMesh& mesh = phases_.mesh();
    const fileName file(objectPath());
    if (!isFile(file))
    {
        return;
    }
    IFstream is(file);
    const dictionary dict(is);
    unpaidEnergy_ = dict.get<scalar>("unpaidEnergy");
    frictionalHeat_ = dict.get<scalar>("frictionalHeat");

    // The impulses are the whole domain's: held by the master alone (the
    // function objects sum them over the processors)
    const dictionary& impulses = dict.subDict("patchImpulses");
    const polyBoundaryMesh& pbm = mesh.boundaryMesh();
    for (label patchi = 0; patchi < pbm.nNonProcessor(); ++patchi)
    {
        vector I(Zero);
        impulses.readIfPresent(pbm[patchi].name(), I);
        patchImpulses_[patchi] = Pstream::master() ? I : vector::zero;
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::stepLedger::accept
(
    const scalar deltaT,
    const vectorField& patchForces,
    const scalar unpaidEnergy,
    const scalar frictionalHeat
)
{
    timeIndex_ = phases_.mesh().time().timeIndex();
    deltaT_ = deltaT;
    patchForces_ = patchForces;
    forAll(patchImpulses_, patchi)
    {
        patchImpulses_[patchi] += deltaT*patchForces[patchi];
    }
    unpaidEnergy_ = unpaidEnergy;
    frictionalHeat_ = frictionalHeat;
}


bool Foam::stepLedger::writeData(Ostream& os) const
{
    const polyBoundaryMesh& pbm = phases_.mesh().boundaryMesh();
    const label n = pbm.nNonProcessor();
    vectorField impulses(SubField<vector>(patchImpulses_, n));
    Pstream::listCombineGather(impulses, plusEqOp<vector>());
    Pstream::listCombineScatter(impulses);

    os.writeEntry("unpaidEnergy", unpaidEnergy_);
    os.writeEntry("frictionalHeat", frictionalHeat_);
    os.beginBlock("patchImpulses");
    for (label patchi = 0; patchi < n; ++patchi)
    {
        os.writeEntry(pbm[patchi].name(), impulses[patchi]);
    }
    os.endBlock();
    return os.good();
}


// ************************************************************************* //
