#include "elasticModel.H"

namespace Foam
{
    defineTypeNameAndDebug(elasticModel, 0);
    defineRunTimeSelectionTable(elasticModel, dictionary);
}

Foam::elasticModel::elasticModel
(
    const word& phaseName,
    const dictionary& dict
)
:
    phaseName_(phaseName),
    rho0_(dict.get<scalar>("rho0")),
    mu_(dict.get<scalar>("mu"))
{
    if (!(rho0_ > 0))
    {
        FatalIOErrorInFunction(dict)
            << "Phase " << phaseName << ": elasticity rho0 = " << rho0_
            << " must be positive" << exit(FatalIOError);
    }
    if (!(mu_ >= 0))
    {
        FatalIOErrorInFunction(dict)
            << "Phase " << phaseName << ": elasticity mu = " << mu_
            << " must be non-negative (shear modulus)" << exit(FatalIOError);
    }
}


Foam::wordList Foam::elasticModel::keywords() const
{
    return {"type", "rho0", "mu"};
}


Foam::cobasis::matrix Foam::elasticModel::dS
(
    const cobasis::matrix& A,
    const cobasis::matrix& dA
) const
{
    const scalar h = 1e-6*max(A.norm(), SMALL)/max(dA.norm(), SMALL);
    return (SofA(A + h*dA) - SofA(A - h*dA))/(2*h);
}


Foam::cobasis::vector Foam::elasticModel::principalS
(
    const cobasis::vector& x,
    const scalar rhoByRho0
) const
{
    return S(x.asDiagonal().toDenseMatrix(), rhoByRho0).diagonal();
}


void Foam::elasticModel::addDivS
(
    const cobasis::matrix& A,
    const cobasis::matrix dAdx[3],
    cobasis::vector& divS
) const
{
    for (int j = 0; j < 3; ++j)
    {
        divS += dS(A, dAdx[j]).col(j);
    }
}


Foam::cobasis::matrix Foam::elasticModel::Qe
(
    const cobasis::matrix& A,
    const cobasis::vector& n
) const
{
    cobasis::matrix Q;
    for (int k = 0; k < 3; ++k)
    {
        Q.col(k) = dS(A, -(A.col(k))*n.transpose())*n;
    }
    return 0.5*(Q + Q.transpose());
}


Foam::cobasis::matrix Foam::elasticModel::principalQe
(
    const cobasis::vector& Lambda,
    const scalar
) const
{
    const cobasis::matrix U(Lambda.cwiseSqrt().asDiagonal());
    cobasis::matrix Qp;
    for (int d = 0; d < 3; ++d)
    {
        Qp.col(d) = Qe(U, cobasis::vector::Unit(d)).diagonal();
    }
    return Qp;
}
