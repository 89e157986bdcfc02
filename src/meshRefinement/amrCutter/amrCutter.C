#include "amrCutter.H"
#include "hexCutter.H"
#include "quadCutter.H"
#include "syncTools.H"
#include "emptyPolyPatch.H"
#include "wedgePolyPatch.H"

// * * * * * * * * * * * * * * * * Selectors * * * * * * * * * * * * * * * * //

Foam::autoPtr<Foam::amrCutter> Foam::amrCutter::New(fvMesh& mesh)
{
    if (planar(mesh))
    {
        return autoPtr<amrCutter>(new quadCutter(mesh));
    }
    return autoPtr<amrCutter>(new hexCutter(mesh));
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

bool Foam::amrCutter::planar(const polyMesh& mesh)
{
    for (const polyPatch& pp : mesh.boundaryMesh())
    {
        if (isA<emptyPolyPatch>(pp) || isA<wedgePolyPatch>(pp))
        {
            return true;
        }
    }
    return false;
}


Foam::labelList Foam::amrCutter::perLevel(const label maxLevel) const
{
    labelList n(maxLevel + 1, Zero);
    for (const label l : cellLevel())
    {
        ++n[min(l, maxLevel)];
    }
    Pstream::listCombineGather(n, plusEqOp<label>());
    Pstream::listCombineScatter(n);
    return n;
}


void Foam::amrCutter::extend(bitSet& marked, const label n) const
{
    for (label layer = 0; layer < n; ++layer)
    {
        bitSet faces(mesh_.nFaces());
        for (const label c : marked)
        {
            faces.set(mesh_.cells()[c]);
        }
        syncTools::syncFaceList(mesh_, faces, orEqOp<unsigned int>());
        for (const label f : faces)
        {
            marked.set(mesh_.faceOwner()[f]);
            if (f < mesh_.nInternalFaces())
            {
                marked.set(mesh_.faceNeighbour()[f]);
            }
        }
    }
}


void Foam::amrCutter::setInstance(const fileName& instance)
{
    if (changedSinceWrite_)
    {
        const fileName inst
        (
            instance.empty() ? fileName(mesh_.time().timeName()) : instance
        );
        mesh_.setInstance(inst);
        setLevelsInstance(inst);
    }
}


void Foam::amrCutter::write(const bool force)
{
    if (changedSinceWrite_ && (force || mesh_.time().writeTime()))
    {
        writeLevels();
        mesh_.setInstance(mesh_.facesInstance(), IOobject::NO_WRITE);
        changedSinceWrite_ = false;
    }
}


// ************************************************************************* //
