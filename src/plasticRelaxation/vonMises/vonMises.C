#include "vonMises.H"
#include "addToRunTimeSelectionTable.H"

namespace Foam
{
namespace plasticModels
{
    defineTypeNameAndDebug(vonMises, 0);
    addToRunTimeSelectionTable(plasticModel, vonMises, dictionary);
}
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::plasticModels::vonMises::vonMises
(
    const word& phaseName,
    const dictionary& dict
)
:
    plasticModel(phaseName, dict),
    sigmaY0_(0),
    H_(dict.getOrDefault<scalar>("H", 0)),
    tau_(dict.get<scalar>("tau")),
    n_(dict.getOrDefault<scalar>("n", 0))
{
    const bool hasY = dict.found("sigmaY");
    const bool hasY0 = dict.found("sigmaY0");
    if (hasY == hasY0)
    {
        FatalIOErrorInFunction(dict)
            << "Phase " << phaseName << ": plasticity needs exactly one of"
            << " sigmaY (yield stress) or sigmaY0 (initial yield stress)"
            << exit(FatalIOError);
    }
    sigmaY0_ = dict.get<scalar>(hasY ? "sigmaY" : "sigmaY0");

    if (!(sigmaY0_ > 0))
    {
        FatalIOErrorInFunction(dict)
            << "Phase " << phaseName << ": plasticity "
            << (hasY ? "sigmaY" : "sigmaY0") << " = " << sigmaY0_
            << " must be positive" << exit(FatalIOError);
    }
    if (!(H_ >= 0))
    {
        FatalIOErrorInFunction(dict)
            << "Phase " << phaseName << ": plasticity H = " << H_
            << " must be non-negative" << exit(FatalIOError);
    }
    if (!(tau_ >= 0))
    {
        FatalIOErrorInFunction(dict)
            << "Phase " << phaseName << ": plasticity tau = " << tau_
            << " must be non-negative (0 for ideal plasticity)"
            << exit(FatalIOError);
    }
    if (!(n_ >= 0))
    {
        FatalIOErrorInFunction(dict)
            << "Phase " << phaseName << ": plasticity n = " << n_
            << " must be non-negative" << exit(FatalIOError);
    }
}


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

Foam::scalar Foam::plasticModels::vonMises::f
(
    const scalar s,
    const cobasis::vector& h,
    const scalar rhoByRho0,
    const scalar epsP,
    const elasticModel& elastic
) const
{
    const cobasis::vector x((s*h).array().exp());
    const cobasis::matrix S(elastic.S(x.asDiagonal().toDenseMatrix(), rhoByRho0));
    const scalar dEpsP = sqrt(2.0/3.0)*0.5*(1 - s)*h.norm();
    return sqrt(1.5)*S.norm() - sigmaY(epsP + dEpsP);
}


template<class Function>
Foam::scalar Foam::plasticModels::vonMises::increasingRoot
(
    const Function& fun,
    scalar s0,
    scalar s1,
    scalar f0,
    scalar f1,
    const scalar tol
)
{
    // Illinois regula falsi, kept inside the bracket [s0, s1]
    int side = 0;
    for (int iter = 0; iter < 200; ++iter)
    {
        scalar s = (s0*f1 - s1*f0)/(f1 - f0);
        if (!(s > s0 && s < s1))
        {
            s = 0.5*(s0 + s1);
        }
        const scalar fs = fun(s);

        if (mag(fs) <= tol || s1 - s0 <= 4*SMALL)
        {
            return s;
        }
        if (fs > 0)
        {
            s1 = s;
            f1 = fs;
            if (side == 1) f0 *= 0.5;
            side = 1;
        }
        else
        {
            s0 = s;
            f0 = fs;
            if (side == -1) f1 *= 0.5;
            side = -1;
        }
    }
    return 0.5*(s0 + s1);
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::scalar Foam::plasticModels::vonMises::correct
(
    cobasis::matrix& A,
    scalar& epsP,
    const elasticModel& elastic,
    const scalar dt
) const
{
    const scalar rhoByRho0 = A.determinant();
    const cobasis::matrix g(cobasis::g(A));

    Eigen::SelfAdjointEigenSolver<cobasis::matrix> eig(g);
    const cobasis::vector h(eig.eigenvalues().array().log());

    const auto fOfs = [&](const scalar s)
    {
        return f(s, h, rhoByRho0, epsP, elastic);
    };

    const scalar f1 = fOfs(1);
    if (f1 <= 0)
    {
        return 0;
    }

    // Ideal return: the point of the path on the yield surface
    const scalar tol = 1e-13*sigmaY(epsP);
    scalar s = increasingRoot(fOfs, 0, 1, fOfs(0), f1, tol);

    if (tau_ > 0)
    {
        // Visco-plastic: backward Euler of ds/dt = -s/tau(f), s >= sY
        const scalar sY = s;
        const auto phi = [&](const scalar t)
        {
            const scalar ft = max(fOfs(t), scalar(0));
            const scalar rate = pow(ft/sigmaY(epsP), n_)/tau_;
            return t*(1 + dt*(ft > 0 ? rate : 0)) - 1;
        };
        const scalar phiY = phi(sY);
        const scalar phi1 = phi(1);
        s =
            phiY >= 0 ? sY
          : phi1 > 0 ? increasingRoot(phi, sY, 1, phiY, phi1, 1e-14)
          : 1;
    }

    if (!(s < 1))
    {
        // No plastic flow (visco-plastic with dt = 0): A untouched
        return 0;
    }

    const scalar eOld = elastic.energy(g);

    // The yielded cobasis is the stretch G_new^(1/2): its rotation carries no
    // stress (the energy depends on G = A^T A only), and an Eulerian cobasis
    // whose rotation varies from cell to cell (the accumulated spin of the
    // plastic flow) is strained by the numerical diffusion of its transport
    // alone: energy taken from the hydrodynamic part and then dissipated
    // (eigenvalues of G: det(A)^(2/3) exp(s h) on the return path)
    const cobasis::vector stretch
    (
        std::cbrt(rhoByRho0)*(s/2*h).array().exp()
    );
    A = eig.eigenvectors()*stretch.asDiagonal()*eig.eigenvectors().transpose();

    epsP += sqrt(2.0/3.0)*0.5*(1 - s)*h.norm();

    return eOld - elastic.energy(cobasis::g(A));
}
