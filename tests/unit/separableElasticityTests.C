/*---------------------------------------------------------------------------*\
  Unit tests of the separable shear energies (docs/validation.md V7):
  stress = -2 rho G de/dG = rho (de/dF) F^T at large strains, small-shear
  modulus, stress-free rest and rigid rotations, frame indifference, named
  presets, and the acoustic tensor: symmetry, analytic derivative against
  the complex step and finite differences, positive for -1 <= a <= 1/2 and
  not outside.
\*---------------------------------------------------------------------------*/

#include <gtest/gtest.h>
#include "separable.H"
#include "unitTestTools.H"

#include <cstdio>
#include <sstream>
#include <iomanip>

using namespace Foam;
using namespace unitTestTools;

namespace
{

const scalar rho0Cu = 8900;
const scalar muCu = 4.5e10;

autoPtr<elasticModel> modelFrom(const std::string& text)
{
    return elasticModel::New("testSolid", dictFrom(text));
}

autoPtr<elasticModel> separableWith(const scalar a)
{
    std::ostringstream os;
    os  << std::setprecision(17)
        << "type separable; rho0 " << rho0Cu << "; mu " << muCu
        << "; a " << a << ";";
    return modelFrom(os.str());
}


//- The separable family with any a: the dictionary rejects a outside
//  [-1, 1/2], so the test sets the protected parameter after construction.
//  Energy, stress and the acoustic tensor are the library's.
class anyASeparable
:
    public elasticModels::separable
{
public:

    explicit anyASeparable(const scalar a)
    :
        separable
        (
            "testSolid",
            dictFrom("type separable; rho0 8900; mu 4.5e10; a 0;")
        )
    {
        a_ = a;
    }
};


//- dE/dG of E(G) = e_e(G/det(G)^(1/3)) over symmetric G:
//  E(G + dG) = E(G) + D:dG + ... for symmetric dG
matrix dEdG(const elasticModel& model, const matrix& G)
{
    const scalar h =
        2e-3*Eigen::SelfAdjointEigenSolver<matrix>(G).eigenvalues()(0);
    matrix D;
    for (int i = 0; i < 3; ++i)
    {
        for (int j = i; j < 3; ++j)
        {
            matrix dG(matrix::Zero());
            dG(i, j) += 1;
            dG(j, i) += 1;
            const auto E = [&](const scalar t)
            {
                const matrix Gt(G + t*dG);
                return model.energy(Gt*std::pow(Gt.determinant(), -1.0/3.0));
            };
            const scalar d = derivative6(E, h);
            // D:dG = 2 D_ij for i != j, 2 D_ii for i == j
            D(i, j) = D(j, i) = d/2;
        }
    }
    return D;
}


//- de/dF of e(F) = e_e(g(F^-1)), all nine entries
matrix dEdF(const elasticModel& model, const matrix& F)
{
    const scalar h = 2e-3*std::sqrt
    (
        Eigen::SelfAdjointEigenSolver<matrix>
        (
            F.transpose()*F, Eigen::EigenvaluesOnly
        ).eigenvalues()(0)
    );
    matrix P;
    for (int i = 0; i < 3; ++i)
    {
        for (int j = 0; j < 3; ++j)
        {
            matrix dF(matrix::Zero());
            dF(i, j) = 1;
            const auto E = [&](const scalar t)
            {
                const matrix At((F + t*dF).inverse());
                return model.energy(cobasis::g(At));
            };
            P(i, j) = derivative6(E, h);
        }
    }
    return P;
}


//- Acoustic tensor column by column from 4th-order differences of SofA,
//  not symmetrised: column k is dS[-(A e_k) (x) n] n
// Acoustic tensor from the base class's finite-difference derivative of S,
// whatever dS the model overrides it with
matrix QeFiniteDifference
(
    const elasticModel& model,
    const matrix& A,
    const vector& n
)
{
    matrix Q;
    for (int k = 0; k < 3; ++k)
    {
        Q.col(k) = model.elasticModel::dS(A, -(A.col(k))*n.transpose())*n;
    }
    return 0.5*(Q + Q.transpose());
}


matrix QeRaw(const elasticModel& model, const matrix& A, const vector& n)
{
    matrix Q;
    for (int k = 0; k < 3; ++k)
    {
        const matrix dA(-(A.col(k))*n.transpose());
        for (int i = 0; i < 3; ++i)
        {
            const auto Si = [&](const scalar t)
            {
                return (model.SofA(A + t*dA)*n)(i);
            };
            Q(i, k) = derivative4(Si, 1e-4);
        }
    }
    return Q;
}


scalar minEigenvalue(const matrix& Q)
{
    return Eigen::SelfAdjointEigenSolver<matrix>
    (
        0.5*(Q + Q.transpose()),
        Eigen::EigenvaluesOnly
    ).eigenvalues()(0);
}

} // End anonymous namespace


TEST(separableElasticity, stressIsMinusTwoRhoGdEdG)
{
    std::mt19937 gen(20170101);
    scalar worst = 0;
    for (const scalar a : {-1.0, 0.0, 0.5})
    {
        auto model = separableWith(a);
        for (int sample = 0; sample < 200; ++sample)
        {
            const matrix A(randomCobasis(gen, 3));
            const matrix G(cobasis::G(A));
            const scalar rho = rho0Cu*A.determinant();

            const matrix Sfd(-2*rho*G*dEdG(*model, G));
            const matrix S(model->SofA(A));
            const matrix Sg(model->S(cobasis::g(A), A.determinant()));

            const scalar err = maxAbs(Sfd - S)/maxAbs(S);
            worst = max(worst, err);
            EXPECT_LT(err, 1e-9) << "a = " << a << ", A =\n" << A;
            EXPECT_LE(maxAbs(Sg - S), 1e-15*maxAbs(S));
            EXPECT_GE(model->energy(cobasis::g(A)), 0) << "a = " << a;
        }
    }
    std::printf("[ measured ] S vs -2 rho G de/dG: worst rel. error %.2e\n", worst);
}


TEST(separableElasticity, stressIsRhoDeDFFt)
{
    std::mt19937 gen(7);
    scalar worst = 0;
    for (const scalar a : {-1.0, 0.0, 0.5})
    {
        auto model = separableWith(a);
        for (int sample = 0; sample < 200; ++sample)
        {
            const matrix A(randomCobasis(gen, 3));
            const matrix F(A.inverse());
            const scalar rho = rho0Cu/F.determinant();

            const matrix Sfd(rho*dEdF(*model, F)*F.transpose());
            const matrix S(model->SofA(A));

            const scalar err = maxAbs(Sfd - S)/maxAbs(S);
            worst = max(worst, err);
            EXPECT_LT(err, 1e-9) << "a = " << a << ", A =\n" << A;
        }
    }
    std::printf("[ measured ] S vs rho de/dF F^T: worst rel. error %.2e\n", worst);
}


TEST(separableElasticity, smallSimpleShearGivesShearModulus)
{
    // x1 = X1 + gamma X2: F = I + gamma e1 e2^T, A = F^-1 = I - gamma e1 e2^T.
    // Exactly, S_12 = mu gamma (1 + gamma^2 (1 + a)/3) for this family.
    scalar worst = 0;
    for (const scalar a : {-1.0, -0.5, 0.0, 0.25, 0.5})
    {
        auto model = separableWith(a);
        for (const scalar gamma : {1e-2, 1e-3, 1e-4})
        {
            matrix A(matrix::Identity());
            A(0, 1) = -gamma;
            const matrix S(model->SofA(A));
            const scalar tau = muCu*gamma;

            const scalar err = mag(S(0, 1)/tau - 1);
            worst = max(worst, err/gamma);
            EXPECT_LE(err, gamma) << "a = " << a << ", gamma = " << gamma;
            EXPECT_NEAR
            (
                S(0, 1), tau*(1 + gamma*gamma*(1 + a)/3), 1e-13*tau
            ) << "a = " << a << ", gamma = " << gamma;
            EXPECT_NEAR(S(1, 0), S(0, 1), 1e-15*tau);
            EXPECT_NEAR(S(0, 2), 0, 1e-15*tau);
            EXPECT_NEAR(S(1, 2), 0, 1e-15*tau);
            for (int i = 0; i < 3; ++i)
            {
                EXPECT_LE(mag(S(i, i)), muCu*gamma*gamma);
            }
        }
    }
    std::printf
    (
        "[ measured ] simple shear: worst |S12/(mu gamma) - 1|/gamma %.2e\n",
        worst
    );
}


TEST(separableElasticity, restAndRigidRotationsAreStressFree)
{
    std::mt19937 gen(3);
    for (const scalar a : {-1.0, 0.0, 0.5})
    {
        auto model = separableWith(a);
        const scalar eScale = muCu/rho0Cu;

        EXPECT_NEAR(model->energy(matrix::Identity()), 0, 1e-14*eScale);
        for (const scalar rByR0 : {0.7, 1.0, 1.4})
        {
            EXPECT_LE(maxAbs(model->S(matrix::Identity(), rByR0)), 0);
        }
        for (int sample = 0; sample < 20; ++sample)
        {
            const scalar rho = rho0Cu*(0.6 + 0.8*sample/20.0);
            const matrix A
            (
                randomRotation(gen)*cobasis::unstrained(rho, rho0Cu)
            );
            EXPECT_NEAR(A.determinant(), rho/rho0Cu, 1e-14);
            EXPECT_LE(maxAbs(model->SofA(A)), 1e-14*muCu);
            EXPECT_NEAR(model->energy(cobasis::g(A)), 0, 1e-14*eScale);
        }
    }
}


TEST(separableElasticity, stretchKeepsFingerTensorAndStress)
{
    // cobasis::stretch(A) = (A^T A)^(1/2), what the solver stores after each
    // step (cobasisRotation discard): symmetric positive definite, the same
    // G = A^T A, A = R U with R = cobasis::rotation(A) orthogonal, and so the
    // same stress and energy
    std::mt19937 gen(11);
    std::uniform_real_distribution<double> U(-1, 1);
    auto model = separableWith(0.5);
    scalar worstG = 0, worstRU = 0, worstS = 0;
    for (int sample = 0; sample < 500; ++sample)
    {
        const scalar m = 0.5*(1 + U(gen));
        const vector l
        (
            std::exp(m*U(gen)), std::exp(m*U(gen)), std::exp(m*U(gen))
        );
        const matrix A
        (
            randomRotation(gen)*l.asDiagonal()*randomRotation(gen).transpose()
        );
        const matrix Us(cobasis::stretch(A));
        EXPECT_LE(maxAbs(Us - Us.transpose()), 1e-14*maxAbs(Us));
        EXPECT_GT(Eigen::SelfAdjointEigenSolver<matrix>(Us).eigenvalues()(0), 0);
        worstG = max
        (
            worstG,
            maxAbs(Us.transpose()*Us - A.transpose()*A)/maxAbs(A.transpose()*A)
        );
        const matrix R(cobasis::rotation(A));
        EXPECT_LE(maxAbs(R.transpose()*R - matrix::Identity()), 1e-13);
        worstRU = max(worstRU, maxAbs(R*Us - A)/maxAbs(A));
        worstS = max
        (
            worstS,
            maxAbs(model->SofA(Us) - model->SofA(A))
           /(muCu*(1 + maxAbs(A.transpose()*A)))
        );
        // A pure stretch is its own stretch
        EXPECT_LE(maxAbs(cobasis::stretch(Us) - Us), 1e-13*maxAbs(Us));
    }
    EXPECT_LT(worstG, 1e-13);
    EXPECT_LT(worstRU, 1e-13);
    EXPECT_LT(worstS, 1e-12);
    std::printf
    (
        "[ measured ] stretch: worst |U^T U - A^T A| %.2e, |R U - A| %.2e,"
        " |S(U) - S(A)|/mu %.2e (relative)\n", worstG, worstRU, worstS
    );
}


TEST(separableElasticity, stretchClosedFormAtCoincidentEigenvalues)
{
    // cobasis::stretch (and rotation) is a closed form in G's eigenvalues:
    // against the eigenvector construction V diag(sqrt(lambda)) V^T where
    // eigenvalues coincide or nearly so (a rotation, a rotated isotropic
    // compression, strains from 1e-12 to 1e-2 and a uniaxial state)
    std::mt19937 gen(13);
    std::uniform_real_distribution<double> U(-1, 1);
    scalar worst = 0;
    for (int sample = 0; sample < 400; ++sample)
    {
        const scalar eps = std::pow(10.0, -12 + 10*(sample % 6)/5.0);
        matrix E;
        for (int i = 0; i < 9; ++i) E(i) = U(gen);
        E = 0.5*(E + E.transpose()).eval();
        if (sample % 4 == 0) E.setZero();
        if (sample % 4 == 1)
        {
            E.setZero();
            E(0, 0) = 1;
        }
        const scalar s = 0.8 + 0.4*(sample % 5)/4.0;
        const matrix A
        (
            randomRotation(gen)*(s*(matrix::Identity() + eps*E))
           *randomRotation(gen)
        );
        const Eigen::SelfAdjointEigenSolver<matrix> eig(A.transpose()*A);
        const matrix ref
        (
            eig.eigenvectors()*eig.eigenvalues().cwiseSqrt().asDiagonal()
           *eig.eigenvectors().transpose()
        );
        const scalar err = maxAbs(cobasis::stretch(A) - ref)/maxAbs(ref);
        worst = max(worst, err);
        EXPECT_LT(err, 1e-13) << "eps = " << eps << ", A =\n" << A;

        // The rotation A U^-1 (U^-1 from Cayley-Hamilton)
        const matrix R(cobasis::rotation(A));
        const scalar errR = max
        (
            maxAbs(R.transpose()*R - matrix::Identity()),
            maxAbs(R*ref - A)/maxAbs(A)
        );
        worst = max(worst, errR);
        EXPECT_LT(errR, 1e-13) << "eps = " << eps << ", A =\n" << A;
    }
    std::printf
    (
        "[ measured ] stretch closed form vs eigenvectors: %.2e (relative)\n",
        worst
    );
}


TEST(separableElasticity, frameIndifference)
{
    // Relabelling the reference (A -> R A) changes nothing; rotating the
    // current configuration (x -> Q x, A -> A Q^T) rotates S -> Q S Q^T
    std::mt19937 gen(11);
    for (const scalar a : {-1.0, 0.0, 0.5})
    {
        auto model = separableWith(a);
        for (int sample = 0; sample < 50; ++sample)
        {
            const matrix A(randomCobasis(gen, 3));
            const matrix R(randomRotation(gen));
            const matrix Q(randomRotation(gen));
            const matrix S(model->SofA(A));
            const scalar eps = 1e-13*maxAbs(S);

            EXPECT_LE(maxAbs(model->SofA(R*A) - S), eps);
            EXPECT_LE
            (
                maxAbs(model->SofA(A*Q.transpose()) - Q*S*Q.transpose()),
                eps
            );
            EXPECT_NEAR
            (
                model->energy(cobasis::g(matrix(A*Q.transpose()))),
                model->energy(cobasis::g(A)),
                1e-13*model->energy(cobasis::g(A))
            );
        }
    }
}


TEST(separableElasticity, presetsEqualSeparable)
{
    std::mt19937 gen(5);
    const std::string props("rho0 8900; mu 4.5e10;");
    const std::pair<std::string, scalar> presets[] =
        {{"neoHookean", -1.0}, {"metal", 0.5}};

    for (const auto& preset : presets)
    {
        auto named = modelFrom("type " + preset.first + "; " + props);
        auto sep = separableWith(preset.second);

        EXPECT_EQ(std::string(named->type()), preset.first);
        const auto* namedSep =
            dynamic_cast<const elasticModels::separable*>(named.get());
        ASSERT_NE(namedSep, nullptr);
        EXPECT_EQ(namedSep->a(), preset.second);
        EXPECT_EQ(named->rho0(), rho0Cu);
        EXPECT_EQ(named->mu(), muCu);

        // Giving the preset's own a is accepted
        std::ostringstream os;
        os << "type " << preset.first << "; " << props << " a " << preset.second << ";";
        EXPECT_NO_THROW(modelFrom(os.str()));

        for (int sample = 0; sample < 50; ++sample)
        {
            const matrix A(randomCobasis(gen, 3));
            const vector n(randomUnit(gen));
            const matrix g(cobasis::g(A));
            EXPECT_NEAR
            (
                named->energy(g), sep->energy(g), 1e-15*sep->energy(g)
            );
            EXPECT_LE
            (
                maxAbs(named->SofA(A) - sep->SofA(A)),
                1e-15*maxAbs(sep->SofA(A))
            );
            EXPECT_LE
            (
                maxAbs(named->Qe(A, n) - sep->Qe(A, n)),
                1e-15*maxAbs(sep->Qe(A, n))
            );
        }
    }

    // The closed forms of docs/model.md for the presets
    auto neo = modelFrom("type neoHookean; " + props);
    auto metal = modelFrom("type metal; " + props);
    for (int sample = 0; sample < 20; ++sample)
    {
        const matrix g(cobasis::g(randomCobasis(gen, 3)));
        const scalar j1 = g.trace(), j2 = (g*g).trace();
        const scalar eNeo = muCu/(4*rho0Cu)*(j1*j1 - j2 - 6);
        const scalar eMetal = muCu/(8*rho0Cu)*(j2 - 3);
        EXPECT_NEAR(neo->energy(g), eNeo, 1e-13*eNeo);
        EXPECT_NEAR(metal->energy(g), eMetal, 1e-13*eMetal);
    }
}


TEST(separableElasticity, acousticTensorAtRest)
{
    // Q_e(n) = (rho/rho0) mu (I + n n^T/3) for any a at A = (rho/rho0)^(1/3) I
    std::mt19937 gen(13);
    for (const scalar a : {-1.0, 0.0, 0.5})
    {
        auto model = separableWith(a);
        for (const scalar rByR0 : {1.0, 0.8, 1.25})
        {
            const matrix A(cobasis::unstrained(rByR0*rho0Cu, rho0Cu));
            for (int sample = 0; sample < 10; ++sample)
            {
                const vector n(randomUnit(gen));
                const matrix exact
                (
                    rByR0*muCu
                   *(matrix::Identity() + n*n.transpose()/3)
                );
                EXPECT_LE(maxAbs(model->Qe(A, n) - exact), 1e-14*muCu)
                    << "a = " << a << ", rho/rho0 = " << rByR0;
            }
        }
    }
}


TEST(separableElasticity, acousticTensorSymmetricAndConsistent)
{
    // The library returns the symmetric part: check that the unsymmetrised
    // derivative is itself symmetric and equal to it, and that the exact
    // (analytic dS) tensor matches the base class's finite differences
    std::mt19937 gen(17);
    scalar worstSym = 0, worstRaw = 0, worstFd = 0;
    for (const scalar a : {-1.0, -0.5, 0.0, 0.25, 0.5})
    {
        auto model = separableWith(a);
        for (int sample = 0; sample < 200; ++sample)
        {
            const matrix A(randomCobasis(gen, 3));
            const vector n(randomUnit(gen));

            const matrix Q(model->Qe(A, n));
            const matrix Qraw(QeRaw(*model, A, n));
            const matrix Qfd(QeFiniteDifference(*model, A, n));
            const scalar scale = maxAbs(Q);

            const scalar errSym = maxAbs(Qraw - Qraw.transpose())/scale;
            const scalar errRaw = maxAbs(Qraw - Q)/scale;
            const scalar errFd = maxAbs(Qfd - Q)/scale;
            worstSym = max(worstSym, errSym);
            worstRaw = max(worstRaw, errRaw);
            worstFd = max(worstFd, errFd);

            EXPECT_LT(errSym, 1e-9) << "a = " << a << ", A =\n" << A;
            EXPECT_LT(errRaw, 1e-9) << "a = " << a << ", A =\n" << A;
            EXPECT_LT(errFd, 1e-7) << "a = " << a << ", A =\n" << A;
        }
    }
    std::printf
    (
        "[ measured ] Qe: asymmetry %.2e, vs own 4th-order FD %.2e,"
        " closed form vs base-class FD %.2e (relative)\n",
        worstSym, worstRaw, worstFd
    );
}


TEST(separableElasticity, analyticDerivativeMatchesComplexStep)
{
    // dS is analytic (the hot path: the acoustic tensor and the Hancock
    // predictor's divergence of the stress); the complex step is exact to
    // round-off, so the two agree to a few ulps of the stress scale, for
    // any a, compressions and tensions, and directions dA of any kind
    std::mt19937 gen(23);
    std::uniform_real_distribution<scalar> u(-1, 1);
    scalar worst = 0, worstQ = 0;
    for (const scalar a : {-1.0, -0.5, 0.0, 0.25, 0.5})
    {
        const anyASeparable model(a);
        for (int sample = 0; sample < 500; ++sample)
        {
            const matrix A(randomCobasis(gen, 3));
            matrix dA;
            for (int i = 0; i < 9; ++i) dA(i) = u(gen);
            const matrix exact(model.dSComplexStep(A, dA));
            const scalar err =
                maxAbs(model.dS(A, dA) - exact)/maxAbs(exact);
            worst = max(worst, err);
            EXPECT_LT(err, 1e-13) << "a = " << a << ", A =\n" << A;

            // The closed-form acoustic tensor against the one built from
            // complex-step columns dS[-(A e_k) (x) n] n
            const vector n(randomUnit(gen));
            matrix Qc;
            for (int k = 0; k < 3; ++k)
            {
                Qc.col(k) =
                    model.dSComplexStep(A, -(A.col(k))*n.transpose())*n;
            }
            Qc = 0.5*(Qc + Qc.transpose()).eval();
            const scalar errQ = maxAbs(model.Qe(A, n) - Qc)/maxAbs(Qc);
            worstQ = max(worstQ, errQ);
            EXPECT_LT(errQ, 1e-13) << "a = " << a << ", A =\n" << A;
        }
    }
    std::printf
    (
        "[ measured ] dS analytic vs complex step: %.2e, Qe closed form vs"
        " complex-step columns: %.2e (relative)\n",
        worst, worstQ
    );
}


TEST(separableElasticity, principalQeIsQeInTheEigenbasisOfG)
{
    // The closed form along G's principal directions (what a2Max reads)
    // against the general Qe rotated into G's eigenbasis: entry (j, d) is
    // v_j . Qe(A, v_d) v_j, and the off-diagonal entries of that matrix
    // vanish; also against the base class's default (Qe at the principal
    // stretch)
    std::mt19937 gen(29);
    scalar worst = 0, worstOff = 0, worstBase = 0;
    for (const scalar a : {-1.0, -0.5, 0.0, 0.25, 0.5})
    {
        const anyASeparable model(a);
        for (int sample = 0; sample < 200; ++sample)
        {
            const matrix A(randomCobasis(gen, sample < 100 ? 1.1 : 3));
            const Eigen::SelfAdjointEigenSolver<matrix> eig(A.transpose()*A);
            const matrix& V = eig.eigenvectors();
            const matrix Qp(model.principalQe(eig.eigenvalues(), A.determinant()));
            const matrix Qbase
            (
                model.elasticModel::principalQe
                (
                    eig.eigenvalues(), A.determinant()
                )
            );
            const scalar scale = maxAbs(Qp);
            for (int d = 0; d < 3; ++d)
            {
                const matrix Qd(V.transpose()*model.Qe(A, V.col(d))*V);
                for (int j = 0; j < 3; ++j)
                {
                    worst = max(worst, mag(Qd(j, j) - Qp(j, d))/scale);
                    for (int i = 0; i < 3; ++i)
                    {
                        if (i != j)
                        {
                            worstOff = max(worstOff, mag(Qd(i, j))/scale);
                        }
                    }
                }
            }
            worstBase = max(worstBase, maxAbs(Qbase - Qp)/scale);
        }
    }
    EXPECT_LT(worst, 1e-12);
    EXPECT_LT(worstOff, 1e-12);
    EXPECT_LT(worstBase, 1e-12);
    std::printf
    (
        "[ measured ] principalQe closed form vs Qe in G's eigenbasis %.2e"
        " (off-diagonal %.2e), vs the base class %.2e (relative)\n",
        worst, worstOff, worstBase
    );
}


TEST(separableElasticity, addDivSIsThreeDerivatives)
{
    // The predictor's divergence of S: the shared-work version equals the
    // base class's three calls of dS, column j of dS(A, dA/dx_j), to the
    // last bit (the same expressions)
    std::mt19937 gen(31);
    std::uniform_real_distribution<scalar> u(-1, 1);
    for (const scalar a : {-1.0, 0.0, 0.5})
    {
        const anyASeparable model(a);
        for (int sample = 0; sample < 100; ++sample)
        {
            const matrix A(randomCobasis(gen, 2));
            matrix dAdx[3];
            for (int j = 0; j < 3; ++j)
            {
                for (int i = 0; i < 9; ++i) dAdx[j](i) = 100*u(gen);
            }
            vector d1(1e9, -2e9, 3e9), d2(d1), d3(d1);
            model.addDivS(A, dAdx, d1);
            model.elasticModel::addDivS(A, dAdx, d2);
            for (int j = 0; j < 3; ++j)
            {
                d3 += model.dS(A, dAdx[j]).col(j);
            }
            EXPECT_EQ(d1, d2) << "a = " << a << ", A =\n" << A;
            EXPECT_EQ(d1, d3) << "a = " << a << ", A =\n" << A;
        }
    }
}


TEST(separableElasticity, principalSIsSOfDiagonalG)
{
    // The plastic return's yield function reads S at g = diag(x): the
    // vector formula against the dense S, whose off-diagonal entries vanish
    std::mt19937 gen(37);
    std::uniform_real_distribution<scalar> u(-1, 1);
    scalar worst = 0;
    for (const scalar a : {-1.0, -0.5, 0.0, 0.25, 0.5})
    {
        const anyASeparable model(a);
        for (int sample = 0; sample < 200; ++sample)
        {
            vector h(u(gen), u(gen), 0);
            h(2) = -h(0) - h(1);
            const vector x(h.array().exp());
            const scalar r = 1 + 0.3*u(gen);
            const matrix S(model.S(x.asDiagonal().toDenseMatrix(), r));
            const vector Sp(model.principalS(x, r));
            // The size of the terms that cancel in the deviator
            const scalar scale = muCu*r*sqr(x.maxCoeff());
            worst = max(worst, (S.diagonal() - Sp).cwiseAbs().maxCoeff()/scale);
            EXPECT_EQ(maxAbs(S - matrix(S.diagonal().asDiagonal())), 0);
            EXPECT_NEAR(S.norm(), Sp.norm(), 1e-14*scale);
        }
    }
    EXPECT_LT(worst, 1e-14);
    std::printf
    (
        "[ measured ] principalS vs dense S: %.2e (of mu r max(x)^2)\n", worst
    );
}


TEST(separableElasticity, hyperbolicOnlyForAInRange)
{
    // Isochoric strains, principal stretches in [1/3, 3], random n
    const int nSamples = 20000;
    std::printf("[ measured ] min eigenvalue of Qe/mu over %d states:", nSamples);

    for (const scalar a : {-1.0, -0.5, 0.0, 0.25, 0.5})
    {
        auto model = separableWith(a);
        std::mt19937 gen(19);
        scalar lMin = GREAT;
        for (int sample = 0; sample < nSamples; ++sample)
        {
            const matrix A(randomIsochoricCobasis(gen, 3));
            const vector n(randomUnit(gen));
            const scalar l = minEigenvalue(model->Qe(A, n))/muCu;
            lMin = min(lMin, l);
        }
        EXPECT_GT(lMin, 0) << "a = " << a;
        std::printf(" a=%g: %.3e", a, lMin);
    }

    // Outside the range. With isochoric stretches up to 3 the a = 0.55
    // tensor stays positive (minimum about 0.014 mu on a fine grid of
    // stretches and directions); negative eigenvalues need stretches above
    // about 3.3, so a = 0.55 is sampled with stretches up to 4.
    const std::pair<scalar, scalar> outside[] = {{-1.1, 3.0}, {0.55, 4.0}};
    for (const auto& aAndStretch : outside)
    {
        const scalar a = aAndStretch.first;
        const anyASeparable model(a);
        std::mt19937 gen(19);
        scalar lMin = GREAT;
        matrix Aworst;
        vector nWorst;
        int nNegative = 0;
        for (int sample = 0; sample < nSamples; ++sample)
        {
            const matrix A(randomIsochoricCobasis(gen, aAndStretch.second));
            const vector n(randomUnit(gen));
            const scalar l = minEigenvalue(model.Qe(A, n))/muCu;
            if (l < 0) ++nNegative;
            if (l < lMin)
            {
                lMin = l;
                Aworst = A;
                nWorst = n;
            }
        }
        EXPECT_LT(lMin, 0) << "a = " << a;
        // The base-class finite differences agree on the sign
        EXPECT_LT(minEigenvalue(QeFiniteDifference(model, Aworst, nWorst)), 0)
            << "a = " << a;
        std::printf
        (
            " a=%g (stretch <= %g): %.3e (%d negative)",
            a, aAndStretch.second, lMin, nNegative
        );
    }

    // Deterministic states: uniaxial-like isochoric stretch along e3 with
    // n = e1 (found by a grid search)
    {
        const anyASeparable model(0.55);
        const matrix A(vector(0.345478, 0.723635, 4.0).asDiagonal());
        EXPECT_LT(minEigenvalue(model.Qe(A, vector(1, 0, 0)))/muCu, -0.1);
    }
    {
        const anyASeparable model(-1.1);
        const matrix A(vector(1/std::sqrt(3.0), 1/std::sqrt(3.0), 3).asDiagonal());
        EXPECT_LT(minEigenvalue(model.Qe(A, vector(0, 0, 1)))/muCu, -3.0);
    }
    std::printf("\n");
}
