#include "stepLedger.H"

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
            phases.mesh(),
            IOobject::NO_READ,
            IOobject::NO_WRITE,
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
{}


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


// ************************************************************************* //
