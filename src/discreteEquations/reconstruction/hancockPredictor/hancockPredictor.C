#include "hancockPredictor.H"
#include "inputDefaults.H"

using Foam::foamEigen::toEigen;

// * * * * * * * * * * * * * * * Static Data * * * * * * * * * * * * * * * //

const Foam::wordList Foam::hancockPredictor::keywords
(
    {"predictorRelaxation"}
);


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::hancockPredictor::hancockPredictor
(
    const phaseSystem& phases,
    const dictionary& dict
)
:
    phases_(phases),
    relax_
    (
        inputDefaults::get<Switch>
        (
            dict, "predictorRelaxation", Switch(true), "discreteEquations"
        )
    )
{}


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

void Foam::hancockPredictor::relaxPredicted
(
    const label k,
    const label c,
    const cobasis::matrix& Ac,
    const scalar rho,
    const scalar p,
    const scalar halfDt,
    cobasis::matrix& dtA
) const
{
    const phaseModel& phase = phases_[k];
    cobasis::matrix A(Ac + dtA);
    if (!(A.determinant() > 0))
    {
        // Inadmissible: the face states fall back to the cell's
        return;
    }

    // The phase's plastic step over the half step (inelasticModel)
    scalar carried[phaseModel::maxCarried];
    phase.inelasticState(c, carried);
    if (phase.inelastic().predict(A, carried, rho, p, halfDt))
    {
        dtA = A - Ac;
    }
}


void Foam::hancockPredictor::predictCobasis
(
    const label k,
    const label c,
    const scalar halfDt,
    const scalar rho,
    const scalar p,
    const cobasis::vector& u,
    const cobasis::matrix& L,
    const tensor& A,
    cobasis::vector& divSigma,
    solidSlopes& so
) const
{
    const cobasis::matrix Ac(toEigen(A));

    // The directional derivatives of S(A) along the cobasis slopes
    phases_.phase(k).elastic().addDivS(Ac, so.gA, divSigma);

    so.dtA =
        -halfDt
       *(
            u(0)*so.gA[0] + u(1)*so.gA[1] + u(2)*so.gA[2]
          + Ac*L
        );
    if (relax_)
    {
        relaxPredicted(k, c, Ac, rho, p, halfDt, so.dtA);
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::hancockPredictor::describe(Ostream& os) const
{
    if (relax_)
    {
        os  << ", plastic return in the predictor";
    }
}


// ************************************************************************* //
