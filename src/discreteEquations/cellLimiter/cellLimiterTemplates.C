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
            return transform
            (
                refCast<const wedgePolyPatch>(patch.patch()).cellT(),
                vc
            );
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


template<class Type, class Extrapolate>
void Foam::cellLimiter::factors
(
    const GeometricField<Type, fvPatchField, volMesh>& vf,
    const Extrapolate& extrapolate,
    Field<Type>& limiter,
    const boolList* active
) const
{
    const labelUList& own = mesh_.owner();
    const labelUList& nei = mesh_.neighbour();
    const vectorField& C = mesh_.cellCentres();
    const vectorField& Cf = mesh_.faceCentres();
    const Field<Type>& v = vf.primitiveField();

    // Range of the cell and its neighbours
    Field<Type>* scratch = range(static_cast<const Type*>(nullptr));
    Field<Type>& vMax = scratch[0];
    Field<Type>& vMin = scratch[1];
    vMax = v;
    vMin = v;
    forAll(nei, facei)
    {
        const label o = own[facei];
        const label n = nei[facei];
        if (active && !(*active)[o] && !(*active)[n])
        {
            continue;
        }
        vMax[o] = max(vMax[o], v[n]);
        vMin[o] = min(vMin[o], v[n]);
        vMax[n] = max(vMax[n], v[o]);
        vMin[n] = min(vMin[n], v[o]);
    }
    forAll(mesh_.boundary(), patchi)
    {
        if (kinds_[patchi] == neighbour::none) continue;
        const labelUList& fc = mesh_.boundary()[patchi].faceCells();
        Field<Type> nbr;
        if (kinds_[patchi] == neighbour::coupled)
        {
            nbr = vf.boundaryField()[patchi].patchNeighbourField();
        }
        forAll(fc, i)
        {
            if (active && !(*active)[fc[i]])
            {
                continue;
            }
            const Type vn(value(patchi, i, vf, nbr));
            vMax[fc[i]] = max(vMax[fc[i]], vn);
            vMin[fc[i]] = min(vMin[fc[i]], vn);
        }
    }

    limiter.setSize(v.size());
    limiter = pTraits<Type>::one;
    const auto limitFace = [&](const label celli, const vector& dx)
    {
        if (active && !(*active)[celli])
        {
            return;
        }
        const Type dv(extrapolate(celli, dx));
        for (direction cmpt = 0; cmpt < pTraits<Type>::nComponents; ++cmpt)
        {
            const scalar d = component(dv, cmpt);
            scalar r = 1;
            if (d > VSMALL)
            {
                r = (component(vMax[celli], cmpt) - component(v[celli], cmpt))/d;
            }
            else if (d < -VSMALL)
            {
                r = (component(vMin[celli], cmpt) - component(v[celli], cmpt))/d;
            }
            scalar& l = setComponent(limiter[celli], cmpt);
            l = min(l, r);
        }
    };
    forAll(nei, facei)
    {
        limitFace(own[facei], Cf[facei] - C[own[facei]]);
        limitFace(nei[facei], Cf[facei] - C[nei[facei]]);
    }
    forAll(mesh_.boundary(), patchi)
    {
        if
        (
            kinds_[patchi] == neighbour::none
         || kinds_[patchi] == neighbour::wedge
        )
        {
            continue;
        }
        const fvPatch& patch = mesh_.boundary()[patchi];
        const labelUList& fc = patch.faceCells();
        forAll(fc, i)
        {
            limitFace(fc[i], patch.Cf()[i] - C[fc[i]]);
        }
    }
}


// ************************************************************************* //
