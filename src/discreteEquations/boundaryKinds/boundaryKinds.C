#include "boundaryKinds.H"
#include "emptyFvPatch.H"
#include "wedgeFvPatch.H"
#include "symmetryPlaneFvPatch.H"
#include "symmetryFvPatch.H"
#include "processorPolyPatch.H"
#include "slipFvPatchFields.H"
#include "noSlipFvPatchVectorField.H"
#include "zeroGradientFvPatchFields.H"

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::boundaryKinds::boundaryKinds(const volVectorField& U)
:
    kinds_(U.mesh().boundary().size(), kind::value),
    coupledLeft_(U.mesh().boundary().size(), true)
{
    const fvMesh& mesh = U.mesh();

    forAll(mesh.boundary(), patchi)
    {
        const fvPatch& patch = mesh.boundary()[patchi];
        const fvPatchVectorField& Up = U.boundaryField()[patchi];

        if (isA<emptyFvPatch>(patch))
        {
            kinds_[patchi] = kind::empty;
        }
        else if (patch.coupled())
        {
            const polyPatch& pp = patch.patch();
            if (!isA<processorPolyPatch>(pp))
            {
                FatalErrorInFunction
                    << "Patch " << patch.name() << " of type " << pp.type()
                    << ": of the coupled patches only processor patches"
                    << " are supported" << exit(FatalError);
            }
            kinds_[patchi] = kind::coupled;
            coupledLeft_[patchi] =
                refCast<const processorPolyPatch>(pp).owner();
        }
        else if (isA<wedgeFvPatch>(patch))
        {
            kinds_[patchi] = kind::wedge;
        }
        else if
        (
            isA<symmetryPlaneFvPatch>(patch)
         || isA<symmetryFvPatch>(patch)
         || isA<slipFvPatchVectorField>(Up)
        )
        {
            kinds_[patchi] = kind::mirror;
        }
        else if (isA<noSlipFvPatchVectorField>(Up))
        {
            kinds_[patchi] = kind::noSlip;
        }
        else
        {
            kinds_[patchi] = kind::value;
        }
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::List<Foam::cellLimiter::neighbour>
Foam::boundaryKinds::limiterNeighbours(const bool forVelocity) const
{
    using nb = cellLimiter::neighbour;
    List<nb> nbrs(kinds_.size());
    forAll(kinds_, patchi)
    {
        switch (kinds_[patchi])
        {
            case kind::empty:
                nbrs[patchi] = nb::none; break;
            case kind::coupled:
                nbrs[patchi] = nb::coupled; break;
            case kind::mirror:
                nbrs[patchi] = nb::mirror; break;
            case kind::noSlip:
                nbrs[patchi] = forVelocity ? nb::value : nb::mirror; break;
            case kind::wedge:
                nbrs[patchi] = nb::wedge; break;
            default:
                nbrs[patchi] = nb::value; break;
        }
    }
    return nbrs;
}


Foam::wordList Foam::boundaryKinds::derivedPatchTypes(const fvMesh& mesh)
{
    wordList types
    (
        mesh.boundary().size(),
        zeroGradientFvPatchScalarField::typeName
    );
    forAll(mesh.boundary(), patchi)
    {
        const word& pType = mesh.boundaryMesh()[patchi].type();
        if (polyPatch::constraintType(pType))
        {
            types[patchi] = pType;
        }
    }
    return types;
}


Foam::wordList Foam::boundaryKinds::cobasisPatchTypes
(
    const fvMesh& mesh
) const
{
    wordList types(derivedPatchTypes(mesh));
    forAll(kinds_, patchi)
    {
        if
        (
            kinds_[patchi] == kind::mirror
         && !polyPatch::constraintType(mesh.boundaryMesh()[patchi].type())
        )
        {
            types[patchi] = "slip";
        }
    }
    return types;
}
