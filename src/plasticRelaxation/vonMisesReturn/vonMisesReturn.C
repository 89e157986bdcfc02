#include "vonMisesReturn.H"

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::vonMisesReturn::vonMisesReturn(const scalar tau, const scalar n)
:
    tau_(tau),
    n_(n)
{}


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

Foam::scalar Foam::vonMisesReturn::f
(
    const scalar s,
    const scalar q,
    const cobasis::vector& h,
    const scalar rhoByRho0,
    const scalar epsP,
    const elasticModel& elastic,
    const yieldStress& law,
    const scalar dt,
    const scalar T
)
{
    // g(s) in its eigenbasis is diag(exp(s h)), where S is diagonal too
    const cobasis::vector x((s*h).array().exp());
    const scalar magS = elastic.principalS(x, rhoByRho0).norm();
    const scalar dEps = dEpsP(q, h);
    return sqrt(1.5)*magS - law.sigmaY(epsP + dEps, rate(dEps, dt), T);
}


template<class Function>
bool Foam::vonMisesReturn::increasingRoot
(
    const Function& fun,
    scalar& s,
    scalar& s0,
    scalar& s1,
    scalar f0,
    scalar f1,
    const scalar tol,
    const scalar minWidth
)
{
    // Illinois regula falsi, kept inside the bracket [s0, s1]
    int side = 0;
    for (int iter = 0; iter < 200; ++iter)
    {
        s = (s0*f1 - s1*f0)/(f1 - f0);
        if (!(s > s0 && s < s1))
        {
            s = 0.5*(s0 + s1);
        }
        const scalar fs = fun(s);

        if (mag(fs) <= tol)
        {
            return true;
        }
        if (s1 - s0 <= minWidth)
        {
            // The bracket closed first: leave the tightest one
            (fs > 0 ? s1 : s0) = s;
            return false;
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
    s = 0.5*(s0 + s1);
    return false;
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::vonMisesReturn::result Foam::vonMisesReturn::correct
(
    cobasis::matrix& A,
    const scalar epsP,
    const elasticModel& elastic,
    const yieldStress& law,
    const scalar dt,
    const scalar T
) const
{
    const scalar rhoByRho0 = A.determinant();
    const cobasis::matrix g(cobasis::g(A));

    // Well inside the yield surface: f(1) <= 0 below as well, so no
    // eigenproblem. |S| is a function of the invariants of g (the elastic
    // laws are isotropic), so |S(g)| equals the |S| of g's eigenvalues
    // that f(1) takes to round-off (1e-15), far inside the margin; a
    // state within the margin takes the full test below
    if
    (
        sqrt(1.5)*elastic.S(g, rhoByRho0).norm()
      < (1 - 1e-9)*law.sigmaY(epsP, 0, T)
    )
    {
        return {0, 0};
    }

    Eigen::SelfAdjointEigenSolver<cobasis::matrix> eig(g);
    const cobasis::vector h(eig.eigenvalues().array().log());

    const auto fOfs = [&](const scalar s)
    {
        return f(s, 1 - s, h, rhoByRho0, epsP, elastic, law, dt, T);
    };

    const scalar f1 = fOfs(1);
    if (f1 <= 0)
    {
        return {0, 0};
    }

    // f(0) = sqrt(3/2)|S(I)| - sigmaY(epsP + dEpsP(0), ...): the flow
    // stress at the largest plastic increment. f(0) >= 0 is a phase with
    // no strength (sigmaY = 0 along the whole path, e.g. Johnson-Cook at
    // or above melting): the stress goes to zero, s = 0
    const scalar fAt0 = fOfs(0);
    const bool noStrength = !(fAt0 < 0);

    // The flow stress of the state before the step: the scale of the
    // tolerance and of the visco-plastic rate. Where it is 0 (a law with
    // no initial yield stress, Johnson-Cook with A = 0 at epsP = 0) the
    // flow stress at the largest plastic increment, -f(0) > 0, takes its
    // place (and 0 stays 0 for a phase with no strength)
    scalar sigmaY = law.sigmaY(epsP, 0, T);
    if (!(sigmaY > 0) && !noStrength)
    {
        sigmaY = max(-fAt0, scalar(0));
    }

    // Ideal return: the point of the path on the yield surface
    const scalar tol = 1e-13*sigmaY;
    scalar s = 0, s0 = 0, s1 = 1;
    const bool converged =
        noStrength
     || increasingRoot(fOfs, s, s0, s1, fAt0, f1, tol, 4*SMALL);

    // The plastic fraction of the log-strain
    scalar q = 1 - s;

    if (!converged)
    {
        // The bracket closed before |f| reached the tolerance. Where the
        // flow stress changes by more than the tolerance across it, the
        // law is what s does not resolve (a rate-dependent law near
        // s = 1, vonMisesReturn.H): refine in q = 1 - s, and keep the
        // result if it meets the tolerance. Otherwise f is at the
        // round-off of the stress (a tolerance below it: sigmaY/mu below
        // about 1e-3) and s is kept as it is
        scalar q0 = 1 - s1, q1 = 1 - s0;
        const scalar dEps0 = dEpsP(q0, h);
        const scalar dEps1 = dEpsP(q1, h);
        const scalar lawChange =
            law.sigmaY(epsP + dEps1, rate(dEps1, dt), T)
          - law.sigmaY(epsP + dEps0, rate(dEps0, dt), T);

        if (mag(lawChange) > tol)
        {
            const auto fOfq = [&](const scalar x)
            {
                return -f(1 - x, x, h, rhoByRho0, epsP, elastic, law, dt, T);
            };
            const scalar fq0 = fOfq(q0);
            const scalar fq1 = fOfq(q1);
            scalar qr = q;
            if
            (
                fq0 <= 0 && fq1 > 0
             && increasingRoot(fOfq, qr, q0, q1, fq0, fq1, tol, 4*SMALL*q1)
            )
            {
                q = qr;
                s = 1 - q;
            }
        }
    }

    // With no strength the visco-plastic rate (f/sigmaY)^n/tau is
    // unbounded for n > 0: the return is instantaneous (s = 0, the limit
    // as sigmaY goes to 0); for n = 0 it is 1/tau, as for any strength
    if (tau_ > 0 && !(noStrength && n_ > 0))
    {
        // Visco-plastic: backward Euler of ds/dt = -s/tau(f), s >= sY
        const scalar sY = s;
        const auto phi = [&](const scalar t)
        {
            const scalar ft = max(fOfs(t), scalar(0));
            const scalar relaxRate =
                (n_ > 0 ? pow(ft/sigmaY, n_) : scalar(1))/tau_;
            return t*(1 + dt*(ft > 0 ? relaxRate : 0)) - 1;
        };
        const scalar phiY = phi(sY);
        const scalar phi1 = phi(1);
        if (!(phiY >= 0))
        {
            s = 1;
            scalar t0 = sY, t1 = 1;
            if (phi1 > 0)
            {
                increasingRoot(phi, s, t0, t1, phiY, phi1, 1e-14, 4*SMALL);
            }
            q = 1 - s;
        }
    }

    if (!(q > 0))
    {
        // No plastic flow (visco-plastic with dt = 0): A untouched
        return {0, 0};
    }

    const scalar eOld = elastic.energy(g);

    // The yielded cobasis is the stretch G_new^(1/2), without the rotation
    // (vonMisesReturn.H says why); eigenvalues of G on the return path:
    // det(A)^(2/3) exp(s h)
    const cobasis::vector stretch
    (
        std::cbrt(rhoByRho0)*(s/2*h).array().exp()
    );
    A = eig.eigenvectors()*stretch.asDiagonal()*eig.eigenvectors().transpose();

    return {dEpsP(q, h), eOld - elastic.energy(cobasis::g(A))};
}
