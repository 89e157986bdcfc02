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


Foam::wordList Foam::elasticModels::separable::keywords() const
{
    wordList valid(elasticModel::keywords());
    valid.append("a");
    return valid;
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


Foam::cobasis::vector Foam::elasticModels::separable::principalS
(
    const cobasis::vector& x,
    const scalar rhoByRho0
) const
{
    const cobasis::vector x2(x.cwiseProduct(x));
    const scalar j1 = x.sum();
    const scalar j2 = x2.sum();
    const cobasis::vector one(cobasis::vector::Ones());
    return
        (-mu_*rhoByRho0)
       *(
            ((1 - 2*a_)/3*j1)*(x - (j1/3.0)*one)
          + a_*(x2 - (j2/3.0)*one)
        );
}


Foam::cobasis::matrix Foam::elasticModels::separable::dS
(
    const cobasis::matrix& A,
    const cobasis::matrix& dA
) const
{
    // S = -mu r B(g), r = det A, g = s G, G = A^T A, s = (det A)^(-2/3),
    // B = c1 j1 (g - j1/3 I) + a (g^2 - j2/3 I), c1 = (1 - 2a)/3.
    // With t = tr(A^-1 dA) (so d det A = t det A):
    //   dG = dA^T A + A^T dA,   dg = s (dG - 2/3 t G),   dr = t r,
    //   dj1 = tr dg,   dj2 = 2 tr(g dg),
    //   dB = c1 (dj1 (g - j1/3 I) + j1 (dg - dj1/3 I))
    //      + a (dg g + g dg - dj2/3 I),
    //   dS = -mu (dr B + r dB)
    typedef cobasis::matrix M;
    const M I = M::Identity();
    const scalar r = A.determinant();
    const scalar t = (A.inverse()*dA).trace();
    const scalar s = std::cbrt(1/(r*r));
    const M G = A.transpose()*A;
    const M g = s*G;
    const M dg = s*(dA.transpose()*A + A.transpose()*dA - (2.0/3.0*t)*G);
    const M gdg = g*dg;
    const scalar j1 = g.trace();
    const scalar j2 = (g*g).trace();
    const scalar dj1 = dg.trace();
    const scalar dj2 = 2*gdg.trace();
    const scalar c1 = (1 - 2*a_)/3;
    const M B = (c1*j1)*(g - (j1/3)*I) + a_*(g*g - (j2/3)*I);
    const M dB =
        c1*(dj1*(g - (j1/3)*I) + j1*(dg - (dj1/3)*I))
      + a_*(dg*g + gdg - (dj2/3)*I);
    return (-mu_)*((t*r)*B + r*dB);
}


void Foam::elasticModels::separable::addDivS
(
    const cobasis::matrix& A,
    const cobasis::matrix dAdx[3],
    cobasis::vector& divS
) const
{
    // dS above, term for term, with the parts that do not depend on dA
    // evaluated once for the three directions
    typedef cobasis::matrix M;
    const M I = M::Identity();
    const scalar r = A.determinant();
    const M Ainv(A.inverse());
    const scalar s = std::cbrt(1/(r*r));
    const M G = A.transpose()*A;
    const M g = s*G;
    const scalar j1 = g.trace();
    const scalar j2 = (g*g).trace();
    const scalar c1 = (1 - 2*a_)/3;
    const M B = (c1*j1)*(g - (j1/3)*I) + a_*(g*g - (j2/3)*I);
    for (int j = 0; j < 3; ++j)
    {
        const M& dA = dAdx[j];
        const scalar t = (Ainv*dA).trace();
        const M dg = s*(dA.transpose()*A + A.transpose()*dA - (2.0/3.0*t)*G);
        const M gdg = g*dg;
        const scalar dj1 = dg.trace();
        const scalar dj2 = 2*gdg.trace();
        const M dB =
            c1*(dj1*(g - (j1/3)*I) + j1*(dg - (dj1/3)*I))
          + a_*(dg*g + gdg - (dj2/3)*I);
        divS += ((-mu_)*((t*r)*B + r*dB)).col(j);
    }
}


Foam::cobasis::matrix Foam::elasticModels::separable::Qe
(
    const cobasis::matrix& A,
    const cobasis::vector& n
) const
{
    // Column k is dS[dA_k] n with dA_k = -(A e_k) (x) n (dS above): then
    // t = tr(A^-1 dA_k) = -n_k and dG = -(n (x) G_k + G_k (x) n), G_k the
    // k-th column of G, so every term of dS[dA_k] n is a vector:
    //   dg v  = s (-(n (G_k . v) + G_k (n . v)) - 2/3 t G v),
    //   dj1   = s (-2 G_k . n - 2/3 t tr G),
    //   dj2   = 2 s (-2 G_k . (g n) - 2/3 t tr(g G)),
    //   dB n  = c1 (dj1 (g n - j1/3 n) + j1 (dg n - dj1/3 n))
    //         + a (dg (g n) + g (dg n) - dj2/3 n),
    //   dS n  = -mu r (t B n + dB n)
    typedef cobasis::matrix M;
    typedef cobasis::vector V;
    const scalar r = A.determinant();
    const scalar s = std::cbrt(1/(r*r));
    const M G = A.transpose()*A;
    const M g = s*G;
    const scalar j1 = g.trace();
    const scalar j2 = g.cwiseProduct(g).sum();
    const scalar trG = G.trace();
    const scalar trgG = g.cwiseProduct(G).sum();
    const scalar c1 = (1 - 2*a_)/3;
    const V gn = g*n;
    const V Gn = G*n;
    const V Ggn = G*gn;
    const scalar nn = n.squaredNorm();
    const scalar ngn = n.dot(gn);
    // B n, B = c1 j1 (g - j1/3 I) + a (g^2 - j2/3 I)
    const V Bn = (c1*j1)*(gn - (j1/3)*n) + a_*(g*gn - (j2/3)*n);

    M Q;
    for (int k = 0; k < 3; ++k)
    {
        const scalar t = -n(k);
        const V Gk = G.col(k);
        const scalar Gkn = Gk.dot(n);
        const scalar Gkgn = Gk.dot(gn);
        const V dgn = s*(-(Gkn*n + nn*Gk) - (2.0/3.0*t)*Gn);
        const V dggn = s*(-(Gkgn*n + ngn*Gk) - (2.0/3.0*t)*Ggn);
        const scalar dj1 = s*(-2*Gkn - 2.0/3.0*t*trG);
        const scalar dj2 = 2*s*(-2*Gkgn - 2.0/3.0*t*trgG);
        const V dBn =
            c1*(dj1*(gn - (j1/3)*n) + j1*(dgn - (dj1/3)*n))
          + a_*(dggn + g*dgn - (dj2/3)*n);
        Q.col(k) = (-mu_*r)*(t*Bn + dBn);
    }
    return 0.5*(Q + Q.transpose());
}


Foam::cobasis::matrix Foam::elasticModels::separable::principalQe
(
    const cobasis::vector& Lambda,
    const scalar detA
) const
{
    // Qe above with G = diag(Lambda), n = e_d: every vector is along a
    // basis vector, so Q is diagonal. With g_i = s Lambda_i,
    // j1 = sum g_i, j2 = sum g_i^2, r = det A:
    //   k != d:  Q_kk = mu r g_k (c1 j1 + a (g_d + g_k))
    //   k == d:  Q_dd = -mu r (-beta_d + dB_d), with
    //     beta_d = c1 j1 (g_d - j1/3) + a (g_d^2 - j2/3)   (B n = beta_d n)
    //     dj1 = -2 g_d + 2/3 j1,   dj2 = -4 g_d^2 + 4/3 j2,
    //     dB_d = c1 (dj1 (g_d - j1/3) + j1 (-4/3 g_d - dj1/3))
    //          + a (-8/3 g_d^2 - dj2/3)
    const scalar r = detA;
    const scalar s = std::cbrt(1/(r*r));
    const cobasis::vector g(s*Lambda);
    const scalar j1 = g.sum();
    const scalar j2 = g.squaredNorm();
    const scalar c1 = (1 - 2*a_)/3;
    const scalar muR = mu_*r;

    cobasis::matrix Qp;
    for (int d = 0; d < 3; ++d)
    {
        const scalar gd = g(d);
        for (int k = 0; k < 3; ++k)
        {
            if (k != d)
            {
                Qp(k, d) = muR*g(k)*(c1*j1 + a_*(gd + g(k)));
            }
        }
        const scalar beta = c1*j1*(gd - j1/3) + a_*(gd*gd - j2/3);
        const scalar dj1 = -2*gd + 2.0/3.0*j1;
        const scalar dj2 = -4*gd*gd + 4.0/3.0*j2;
        const scalar dB =
            c1*(dj1*(gd - j1/3) + j1*(-4.0/3.0*gd - dj1/3))
          + a_*(-8.0/3.0*gd*gd - dj2/3);
        Qp(d, d) = -muR*(dB - beta);
    }
    return Qp;
}


Foam::cobasis::matrix Foam::elasticModels::separable::dSComplexStep
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
