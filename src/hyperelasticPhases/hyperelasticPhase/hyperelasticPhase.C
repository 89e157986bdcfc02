#include "hyperelasticPhase.H"

// * * * * * * * * * * * * * * * Static Data * * * * * * * * * * * * * * * //

const Foam::wordList Foam::hyperelasticPhase::keywords
(
    {"type", "equationOfState", "elasticity"}
);


Foam::hyperelasticPhase::hyperelasticPhase
(
    const word& name,
    const dictionary& dict
)
:
    name_(name),
    solid_(false),
    eos_(),
    elastic_()
{
    const word phaseType(dict.get<word>("type"));

    if (phaseType == "solid")
    {
        solid_ = true;
    }
    else if (phaseType != "fluid")
    {
        FatalIOErrorInFunction(dict)
            << "Phase " << name << ": type " << phaseType
            << " is neither solid nor fluid" << exit(FatalIOError);
    }

    eos_ = equationOfState::New(name, dict.subDict("equationOfState"));

    if (solid_)
    {
        elastic_ = elasticModel::New(name, dict.subDict("elasticity"));

        // An equation of state with its own reference density
        // (MieGruneisen) and the shear energy describe one unstrained
        // state: their rho0 must agree (docs/model.md section 10.1)
        const scalar rho0Eos = eos_->referenceDensity();
        const scalar rho0El = elastic_->rho0();
        if (rho0Eos > 0 && mag(rho0Eos - rho0El) > 1e-12*rho0El)
        {
            FatalIOErrorInFunction(dict)
                << "Phase " << name << ": equationOfState rho0 = " << rho0Eos
                << " and elasticity rho0 = " << rho0El << " differ; both"
                << " describe the unstrained state at rest and must be"
                << " equal" << exit(FatalIOError);
        }
    }
    else if (dict.found("elasticity"))
    {
        FatalIOErrorInFunction(dict)
            << "Phase " << name << " is a fluid but has an elasticity entry;"
            << " make it type solid or remove the entry" << exit(FatalIOError);
    }
}


const Foam::elasticModel& Foam::hyperelasticPhase::elastic() const
{
    if (!solid_)
    {
        FatalErrorInFunction
            << "Phase " << name_ << " is a fluid: it has no elasticity"
            << abort(FatalError);
    }
    return *elastic_;
}


Foam::cobasis::matrix Foam::hyperelasticPhase::acousticTensor
(
    const scalar rho,
    const scalar p,
    const cobasis::matrix& A,
    const cobasis::vector& n
) const
{
    cobasis::matrix Q = eos_->c2(rho, p)*(n*n.transpose());
    if (solid_)
    {
        Q += elastic_->Qe(A, n)/rho;
    }
    return Q;
}


Foam::cobasis::vector Foam::hyperelasticPhase::waveSpeeds2
(
    const scalar rho,
    const scalar p,
    const cobasis::matrix& A,
    const cobasis::vector& n
) const
{
    Eigen::SelfAdjointEigenSolver<cobasis::matrix> eig
    (
        acousticTensor(rho, p, A, n),
        Eigen::EigenvaluesOnly
    );
    return eig.eigenvalues();
}


Foam::scalar Foam::hyperelasticPhase::a2Max
(
    const scalar rho,
    const scalar p,
    const cobasis::matrix& A
) const
{
    if (!solid_)
    {
        return eos_->c2(rho, p);
    }

    scalar a2 = 0;
    if (!elastic_->isotropic())
    {
        Eigen::SelfAdjointEigenSolver<cobasis::matrix> eig(A.transpose()*A);
        const cobasis::matrix& V = eig.eigenvectors();
        for (int d = 0; d < 3; ++d)
        {
            a2 = max(a2, waveSpeeds2(rho, p, A, V.col(d))(2));
        }
        return a2;
    }

    // Along principal direction d the acoustic tensor is
    // c_h^2 e_d (x) e_d + Qe(e_d)/rho, diagonal in G's eigenbasis: its
    // eigenvalues need only G's eigenvalues (elasticModel::principalQe)
    // (the closed-form eigenvalues: absolute error of order eps |G|)
    Eigen::SelfAdjointEigenSolver<cobasis::matrix> eig;
    eig.computeDirect(A.transpose()*A, Eigen::EigenvaluesOnly);
    const cobasis::matrix Qp
    (
        elastic_->principalQe(eig.eigenvalues(), A.determinant())
    );
    const scalar c2 = eos_->c2(rho, p);
    for (int d = 0; d < 3; ++d)
    {
        for (int j = 0; j < 3; ++j)
        {
            a2 = max(a2, (j == d ? c2 : 0) + Qp(j, d)/rho);
        }
    }
    return a2;
}
