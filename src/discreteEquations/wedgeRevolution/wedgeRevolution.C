#include "wedgeRevolution.H"
#include "wedgePolyPatch.H"
#include "mathematicalConstants.H"

// * * * * * * * * * * * * * * * Global Functions  * * * * * * * * * * * * * //

Foam::scalar Foam::wedgeToFull(const polyMesh& mesh, vector& axis)
{
    // The axis and angle of a wedge patch that has faces
    axis = Zero;
    scalar angle = 0;
    for (const polyPatch& pp : mesh.boundaryMesh())
    {
        if (isA<wedgePolyPatch>(pp) && pp.size())
        {
            const wedgePolyPatch& w = refCast<const wedgePolyPatch>(pp);
            axis = w.axis();
            angle = 2*std::acos(min(max(w.cosAngle(), -1.0), 1.0));
            break;
        }
    }
    reduce(angle, maxOp<scalar>());
    reduce(axis, maxMagSqrOp<vector>());
    if (angle > 0)
    {
        axis /= mag(axis);
        return constant::mathematical::twoPi/std::sin(angle);
    }
    return 0;
}


// ************************************************************************* //
