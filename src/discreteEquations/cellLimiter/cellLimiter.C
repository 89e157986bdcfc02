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
    kinds_(kinds),
    wedgeT_(kinds.size(), tensor::I)
{
    forAll(kinds_, patchi)
    {
        if (kinds_[patchi] == neighbour::wedge)
        {
            wedgeT_[patchi] =
                refCast<const wedgePolyPatch>
                (
                    mesh.boundary()[patchi].patch()
                ).cellT();
        }
    }
}


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
            return (wedgeT_[patchi] & Cc) - Cc;
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
