#include "wedgeRevolution.H"
#include "wedgePolyPatch.H"
#include "SubField.H"
#include "mathematicalConstants.H"

// * * * * * * * * * * * * * * * Global Functions  * * * * * * * * * * * * * //

Foam::scalar Foam::wedgeToFull(const polyMesh& mesh, vector& axis)
{
    // The axis of a wedge patch that has faces, and the angle between the
    // two wedge patches from their area-weighted normals summed over every
    // face on every processor: the same on any decomposition to round-off
    // (one face's normal, from points written to 10 digits, differs from
    // another's by 1e-11)
    const polyBoundaryMesh& patches = mesh.boundaryMesh();
    axis = Zero;
    // (the patches before the processor patches: the same on every
    // processor)
    List<vector> normals(patches.nNonProcessor(), Zero);
    forAll(normals, patchi)
    {
        const polyPatch& pp = patches[patchi];
        if (isA<wedgePolyPatch>(pp))
        {
            normals[patchi] = sum(pp.faceAreas());
            if (pp.size() && axis == vector::zero)
            {
                axis = refCast<const wedgePolyPatch>(pp).axis();
            }
        }
    }
    Pstream::listCombineGather(normals, plusEqOp<vector>());
    Pstream::listCombineScatter(normals);
    reduce(axis, maxMagSqrOp<vector>());

    DynamicList<vector> n;
    for (const vector& s : normals)
    {
        if (mag(s) > VSMALL)
        {
            n.append(s/mag(s));
        }
    }
    if (n.size() != 2)
    {
        return 0;
    }
    // (the two patches face away from each other: the wedge's angle is
    // that between n0 and -n1, by atan2 for full precision at small angles)
    const scalar angle = std::atan2(mag(n[0] ^ n[1]), -(n[0] & n[1]));
    axis /= mag(axis);
    return constant::mathematical::twoPi/std::sin(angle);
}


// ************************************************************************* //
