#include "cellLimiter.H"
#include "wedgePolyPatch.H"

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::cellLimiter::cellLimiter
(
    const fvMesh& mesh,
    const List<neighbour>& kinds
)
:
    mesh_(mesh),
    kinds_(kinds)
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::vector Foam::cellLimiter::offset
(
    const label patchi,
    const label i,
    const vectorField& nbrC
) const
{
    const fvPatch& patch = mesh_.boundary()[patchi];
    const vector& Cc = mesh_.C()[patch.faceCells()[i]];

    switch (kinds_[patchi])
    {
        case neighbour::mirror:
        {
            const vector& Sf = mesh_.faceAreas()[patch.start() + i];
            const vector n(Sf/mag(Sf));
            return 2*((patch.Cf()[i] - Cc) & n)*n;
        }
        case neighbour::wedge:
        {
            const tensor& T =
                refCast<const wedgePolyPatch>(patch.patch()).cellT();
            return (T & Cc) - Cc;
        }
        case neighbour::coupled:
        {
            return nbrC[i] - Cc;
        }
        default:
        {
            return patch.Cf()[i] - Cc;
        }
    }
}


// ************************************************************************* //
