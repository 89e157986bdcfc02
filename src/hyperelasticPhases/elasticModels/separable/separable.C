#include "separable.H"
#include "addToRunTimeSelectionTable.H"

namespace Foam
{
namespace elasticModels
{
    defineTypeNameAndDebug(separable, 0);
    addToRunTimeSelectionTable(elasticModel, separable, dictionary);
}
}

void Foam::elasticModels::separable::checkA(const dictionary& dict) const
{
    if (!(a_ >= -1 && a_ <= 0.5))
    {
        FatalIOErrorInFunction(dict)
            << "Phase " << phaseName_ << ": elasticity a = " << a_
            << " is outside [-1, 1/2], where the model is hyperbolic"
            << exit(FatalIOError);
    }
}


Foam::elasticModels::separable::separable
(
    const word& phaseName,
    const dictionary& dict
)
:
    elasticModel(phaseName, dict),
    a_(dict.get<scalar>("a"))
{
    checkA(dict);
}


Foam::elasticModels::separable::separable
(
    const word& phaseName,
    const dictionary& dict,
    scalar a
)
:
    elasticModel(phaseName, dict),
    a_(a)
{
    scalar aGiven = a;
    if (dict.readIfPresent("a", aGiven) && aGiven != a)
    {
        FatalIOErrorInFunction(dict)
            << "Phase " << phaseName << ": elasticity type "
            << dict.get<word>("type") << " has a = " << a
            << " but the dictionary gives a = " << aGiven
            << exit(FatalIOError);
    }
    checkA(dict);
}


Foam::scalar Foam::elasticModels::separable::energy
(
    const cobasis::matrix& g
) const
{
    const scalar j1 = g.trace();
    const scalar j2 = (g*g).trace();
    return mu_/(4*rho0_)*((1 - 2*a_)/3*j1*j1 + a_*j2 + 3*(a_ - 1));
}


Foam::cobasis::matrix Foam::elasticModels::separable::S
(
    const cobasis::matrix& g,
    const scalar rhoByRho0
) const
{
    return ST(g, rhoByRho0);
}


Foam::cobasis::matrix Foam::elasticModels::separable::dS
(
    const cobasis::matrix& A,
    const cobasis::matrix& dA
) const
{
    typedef std::complex<double> cplx;

    const double h = 1e-30;
    const cobasis::matrixT<cplx> Ac =
        A.cast<cplx>() + cplx(0, h)*dA.cast<cplx>();
    return ST(cobasis::g(Ac), cplx(Ac.determinant())).imag()/h;
}
