#include "cellLimiter.H"
#include "wedgePolyPatch.H"
#include "transform.H"

// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

template<class Type>
Type Foam::cellLimiter::value
(
    const label patchi,
    const label i,
    const GeometricField<Type, fvPatchField, volMesh>& vf,
    const Field<Type>& nbr
) const
{
    const fvPatch& patch = mesh_.boundary()[patchi];
    const Type& vc = vf[patch.faceCells()[i]];

    switch (kinds_[patchi])
    {
        case neighbour::mirror:
        {
            const vector& Sf = mesh_.faceAreas()[patch.start() + i];
            const vector n(Sf/mag(Sf));
            return transform(I - 2*sqr(n), vc);
        }
        case neighbour::wedge:
        {
            return transform(wedgeT_[patchi], vc);
        }
        case neighbour::coupled:
        {
            return nbr[i];
        }
        default:
        {
            return vf.boundaryField()[patchi][i];
        }
    }
}


template<class Type, class Extrapolate, class Apply>
void Foam::cellLimiter::limit
(
    const GeometricField<Type, fvPatchField, volMesh>& vf,
    const Extrapolate& extrapolate,
    const Apply& apply,
    const boolList* active
) const
{
    const labelUList& own = mesh_.owner();
    const labelUList& nei = mesh_.neighbour();
    const vectorField& C = mesh_.cellCentres();
    const vectorField& Cf = mesh_.faceCentres();
    const cellList& cells = mesh_.cells();
    const label nInternal = mesh_.nInternalFaces();
    const Field<Type>& v = vf.primitiveField();
    const boundaryFaceTable boundaryFace(mesh_);

    // The neighbouring processors' values, patch by patch
    List<Field<Type>> nbr(kinds_.size());
    forAll(kinds_, patchi)
    {
        if (kinds_[patchi] == neighbour::coupled)
        {
            nbr[patchi] = vf.boundaryField()[patchi].patchNeighbourField();
        }
    }

    forAll(cells, celli)
    {
        if (active && !(*active)[celli])
        {
            continue;
        }
        const labelList& cFaces = cells[celli];
        const Type& vc = v[celli];

        // The range of the cell and its neighbours (the order of max and
        // min does not matter: the face loop's range, bit for bit)
        Type vMax(vc);
        Type vMin(vc);
        for (const label facei : cFaces)
        {
            if (facei < nInternal)
            {
                const Type& vn =
                    v[own[facei] == celli ? nei[facei] : own[facei]];
                vMax = max(vMax, vn);
                vMin = min(vMin, vn);
                continue;
            }
            label patchi, i;
            if
            (
                !boundaryFace(facei, patchi, i)
             || kinds_[patchi] == neighbour::none
            )
            {
                continue;
            }
            const Type vn(value(patchi, i, vf, nbr[patchi]));
            vMax = max(vMax, vn);
            vMin = min(vMin, vn);
        }

        // The largest factors that keep every face-centre extrapolation in
        // the range
        Type l(pTraits<Type>::one);
        for (const label facei : cFaces)
        {
            label patchi, i;
            if
            (
                facei >= nInternal
             && (
                    !boundaryFace(facei, patchi, i)
                 || kinds_[patchi] == neighbour::none
                 || kinds_[patchi] == neighbour::wedge
                )
            )
            {
                continue;
            }
            const Type dv(extrapolate(celli, Cf[facei] - C[celli]));
            for (direction cmpt = 0; cmpt < pTraits<Type>::nComponents; ++cmpt)
            {
                const scalar d = component(dv, cmpt);
                scalar r = 1;
                if (d > VSMALL)
                {
                    r = (component(vMax, cmpt) - component(vc, cmpt))/d;
                }
                else if (d < -VSMALL)
                {
                    r = (component(vMin, cmpt) - component(vc, cmpt))/d;
                }
                scalar& lc = setComponent(l, cmpt);
                lc = min(lc, r);
            }
        }

        apply(celli, l);
    }
}


// ************************************************************************* //
