#include "alphaProfile.H"
#include "inputDefaults.H"

namespace Foam
{
    defineTypeNameAndDebug(alphaProfile, 0);
    defineRunTimeSelectionTable(alphaProfile, dictionary);
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::alphaProfile::alphaProfile
(
    const phaseSystem& phases,
    const bool sharpens
)
:
    phases_(phases),
    mesh_(phases.mesh()),
    sharpens_(sharpens)
{}


Foam::wordList Foam::alphaProfile::keywords() const
{
    return {"alphaReconstruction", "alphaCompression"};
}


// * * * * * * * * * * * * * Protected Member Functions  * * * * * * * * * * //

Foam::scalar Foam::alphaProfile::readCompression(const dictionary& dict)
{
    const scalar C =
        inputDefaults::get<scalar>
        (
            dict, "alphaCompression", 1, "discreteEquations"
        );
    if (!(C >= 1 && C <= 4))
    {
        FatalIOErrorInFunction(dict)
            << "discreteEquations alphaCompression " << C
            << " is not in [1, 4]" << exit(FatalIOError);
    }
    return C;
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::scalar Foam::alphaProfile::profileFaceAlpha
(
    const label,
    const label,
    const label,
    const vector&
) const
{
    FatalErrorInFunction
        << type() << " profile has only linear slopes" << abort(FatalError);
    return 0;
}


// ************************************************************************* //
