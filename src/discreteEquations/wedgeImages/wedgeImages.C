#include "wedgeImages.H"
#include "inputDefaults.H"
#include "wedgePolyPatch.H"
#include "surfaceFields.H"
#include "foamEigen.H"

using Foam::foamEigen::toEigen;


// * * * * * * * * * * * * * * * Static Data * * * * * * * * * * * * * * * //

const Foam::wordList Foam::wedgeImages::keywords
(
    {"wedgeImages"}
);


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::wedgeImages::wedgeImages
(
    const fvMesh& mesh,
    const boundaryKinds& kinds,
    const dictionary& schemeDict
)
:
    mesh_(mesh),
    kinds_(kinds),
    enabled_(true),
    patchA_(-1),
    patchB_(-1),
    Q_(cobasis::matrix::Identity())
{
    bool wedge = false;
    forAll(mesh_.boundary(), patchi)
    {
        wedge = wedge || kinds[patchi] == boundaryKinds::kind::wedge;
    }
    if (wedge)
    {
        enabled_ = inputDefaults::get<Switch>
        (
            schemeDict, "wedgeImages", Switch(true), "discreteEquations"
        );
    }
    pair(true);
}


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

void Foam::wedgeImages::pair(const bool report)
{
    const bool paired = patchA_ >= 0;
    patchA_ = -1;
    patchB_ = -1;
    image_.clear();
    Q_ = cobasis::matrix::Identity();

    labelList wedges;
    forAll(mesh_.boundary(), patchi)
    {
        if (kinds_[patchi] == boundaryKinds::kind::wedge)
        {
            wedges.append(patchi);
        }
    }
    if (wedges.empty())
    {
        return;
    }
    if (!enabled_)
    {
        if (report)
        {
            Info<< "Wedge faces: each solved (wedgeImages no)" << nl;
        }
        return;
    }

    // The second wedge face of every cell is the image of its first under
    // Q = T_B T_A^T, with the reversed orientation, if the mesh is a
    // one-cell-thick wedge: two wedge patches, each cell with one face in
    // each, reconstructed at the same point of the mid-plane (7.2)
    string reason;
    labelList image;
    cobasis::matrix Q(cobasis::matrix::Identity());
    if (wedges.size() != 2)
    {
        reason = "not two wedge patches";
    }
    else
    {
        const wedgePolyPatch& a =
            refCast<const wedgePolyPatch>(mesh_.boundaryMesh()[wedges[0]]);
        const wedgePolyPatch& b =
            refCast<const wedgePolyPatch>(mesh_.boundaryMesh()[wedges[1]]);
        Q = toEigen(b.faceT() & a.faceT().T());
        const vectorField& Sf = mesh_.faceAreas();
        const vectorField& Cf = mesh_.faceCentres();
        const scalarField& magSfA = mesh_.boundary()[wedges[0]].magSf();
        const scalarField& magSfB = mesh_.boundary()[wedges[1]].magSf();

        labelList faceB(mesh_.nCells(), -1);
        const labelUList& cellsB = b.faceCells();
        forAll(cellsB, i)
        {
            if (faceB[cellsB[i]] >= 0)
            {
                reason = "a cell with two faces on " + b.name();
            }
            faceB[cellsB[i]] = b.start() + i;
        }

        const labelUList& cellsA = a.faceCells();
        if (cellsA.size() != cellsB.size())
        {
            reason = a.name() + " and " + b.name() + " differ in size";
        }
        image.setSize(cellsA.size(), -1);
        forAll(cellsA, i)
        {
            if (!reason.empty()) break;

            const label fa = a.start() + i;
            const label fb = faceB[cellsA[i]];
            if (fb < 0)
            {
                reason = "a cell without a face on " + b.name();
                break;
            }
            const scalar magA = magSfA[i];
            const scalar magB = magSfB[fb - b.start()];
            const cobasis::vector nA(toEigen(Sf[fa]/magA));
            const cobasis::vector nB(toEigen(Sf[fb]/magB));
            const scalar length = sqrt(magA);
            const vector dImage
            (
                (a.faceT().T() & Cf[fa]) - (b.faceT().T() & Cf[fb])
            );
            if
            (
                (nB + Q*nA).norm() > 1e-9
             || mag(dImage) > 1e-9*length
             || mag(magB - magA) > 1e-9*magA
            )
            {
                reason = "faces of a cell not images of each other";
                break;
            }
            image[i] = fb;
        }
    }

    // The same choice on every processor
    if (!returnReduce(reason.empty(), andOp<bool>()))
    {
        if (reason.empty())
        {
            reason = "not on every processor";
        }
        if (report || paired)
        {
            Info<< "Wedge faces: each solved (" << reason << ")" << nl;
        }
        return;
    }
    patchA_ = wedges[0];
    patchB_ = wedges[1];
    image_.transfer(image);
    Q_ = Q;
    if (report)
    {
        Info<< "Wedge faces: " << mesh_.boundary()[patchB_].name()
            << " as the image of " << mesh_.boundary()[patchA_].name() << nl;
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::wedgeImages::internalContacts
(
    const label i,
    const label celli,
    const std::vector<phaseSide>& side,
    const reconstruction& rec,
    demFaceAssembly& assembly
) const
{
    const vectorField& Sf = mesh_.faceAreas();
    const label fb = image_[i];
    assembly.internalContacts
    (
        celli, toEigen(Sf[fb]/magSfB(fb)), magSfB(fb), side, rec
    );
}


void Foam::wedgeImages::addImage
(
    const label i,
    const label celli,
    const std::vector<phaseSide>& side,
    demFaceAssembly& assembly,
    cobasisTransport& cobasis
) const
{
    const vectorField& Sf = mesh_.faceAreas();
    const label fb = image_[i];
    assembly.addImageToCell(celli, magSfB(fb), Q_);
    cobasis.addFace(celli, toEigen(Sf[fb]), side, side, assembly, &Q_);
}


void Foam::wedgeImages::updateMesh()
{
    pair(false);
}


// ************************************************************************* //
