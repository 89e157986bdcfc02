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


Foam::cobasis::matrix Foam::elasticModel::Qe
(
    const cobasis::matrix& A,
    const cobasis::vector& n
) const
{
    cobasis::matrix Q;
    const scalar h = 1e-6;
    for (int k = 0; k < 3; ++k)
    {
        const cobasis::matrix dA = -(A.col(k))*n.transpose();
        Q.col(k) = (SofA(A + h*dA) - SofA(A - h*dA))*n/(2*h);
    }
    return 0.5*(Q + Q.transpose());
}
