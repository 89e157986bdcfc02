#include "phaseTemperature.H"

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::phaseTemperature::phaseTemperature
(
    const word& phaseName,
    const equationOfState& eos,
    const volScalarField& rho,
    const volScalarField& p
)
:
    regIOobject
    (
        IOobject
        (
            "T." + phaseName,
            rho.time().timeName(),
            rho.mesh(),
            IOobject::NO_READ,
            IOobject::AUTO_WRITE
        )
    ),
    eos_(eos),
    rho_(rho),
    p_(p)
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::tmp<Foam::volScalarField> Foam::phaseTemperature::T() const
{
    const fvMesh& mesh = rho_.mesh();
    tmp<volScalarField> tT
    (
        new volScalarField
        (
            IOobject
            (
                name(),
                mesh.time().timeName(),
                mesh,
                IOobject::NO_READ,
                IOobject::NO_WRITE,
                false
            ),
            mesh,
            dimensionedScalar(dimTemperature, Zero)
        )
    );
    volScalarField& T = tT.ref();

    const auto temperature = [this](const scalar rho, const scalar p)
    {
        return eos_.T(rho, eos_.e(rho, p));
    };

    scalarField& Ti = T.primitiveFieldRef();
    const scalarField& rhoi = rho_.primitiveField();
    const scalarField& pi = p_.primitiveField();
    forAll(Ti, celli)
    {
        Ti[celli] = temperature(rhoi[celli], pi[celli]);
    }

    // Boundary values from those of rho and p: no communication (a write
    // is not a place for it)
    volScalarField::Boundary& Tb = T.boundaryFieldRef();
    forAll(Tb, patchi)
    {
        const scalarField& rhop = rho_.boundaryField()[patchi];
        const scalarField& pp = p_.boundaryField()[patchi];
        scalarField Tp(Tb[patchi].size());
        forAll(Tp, facei)
        {
            Tp[facei] = temperature(rhop[facei], pp[facei]);
        }
        Tb[patchi] == Tp;
    }

    return tT;
}


bool Foam::phaseTemperature::writeObject
(
    IOstream::streamFormat fmt,
    IOstream::versionNumber ver,
    IOstream::compressionType cmp,
    const bool valid
) const
{
    return T()().writeObject(fmt, ver, cmp, valid);
}
