/*---------------------------------------------------------------------------*\
  impactFoam: Eulerian multiphase elastic-plastic impact solver for OpenFOAM
\*---------------------------------------------------------------------------*/

#include "plasticityAndFailure.H"
#include "addToRunTimeSelectionTable.H"

namespace Foam
{
namespace inelasticModels
{
    defineTypeNameAndDebug(plasticityAndFailure, 0);
    addToRunTimeSelectionTable
    (
        inelasticModel,
        plasticityAndFailure,
        dictionary
    );
}
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::inelasticModels::plasticityAndFailure::plasticityAndFailure
(
    const hyperelasticPhase& law,
    const dictionary& phaseDict
)
:
    inelasticModel(law),
    needsT_(false),
    iEps_(-1),
    iWork_(-1),
    iDamage_(-1)
{
    const word& name = law.name();
    if (law.solid())
    {
        plastic_ = plasticModel::New(name, phaseDict.subDict("plasticity"));
        failure_ = failureModel::New(name, phaseDict);
    }
    else
    {
        if (phaseDict.found("failure"))
        {
            FatalIOErrorInFunction(phaseDict)
                << "Phase " << name << ": failure is for solids only"
                << exit(FatalIOError);
        }
        dictionary noneDict;
        noneDict.add("type", "none");
        plastic_ = plasticModel::New(name, noneDict);
        failure_ = failureModel::New(name, dictionary());
    }

    const char* needsT =
        plastic_->needsTemperature() ? "plasticity"
      : failure_->needsTemperature() ? "failure"
      : nullptr;
    if (needsT && !law.eos().hasTemperature())
    {
        FatalIOErrorInFunction(phaseDict)
            << "Phase " << name << ": its " << needsT << " needs a"
            << " temperature, and its equationOfState " << law.eos().type()
            << " gives none: add Cv to equationOfState"
            << exit(FatalIOError);
    }
    needsT_ = needsT != nullptr;

    label n = 0;
    if (plastic_->plastic())
    {
        iEps_ = n++;
        iWork_ = n++;
    }
    if (failure_->active())
    {
        iDamage_ = n++;
    }
}


Foam::wordList
Foam::inelasticModels::plasticityAndFailure::phaseKeywords() const
{
    wordList valid(inelasticModel::phaseKeywords());
    if (law_.solid())
    {
        valid.append(wordList({"plasticity", "failure"}));
    }
    return valid;
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::carriedVariableList
Foam::inelasticModels::plasticityAndFailure::carriedVariables() const
{
    carriedVariableList vars;
    if (iEps_ >= 0)
    {
        vars.append(carriedVariable("epsilonP", dimless, 0, 0));
        vars.append(carriedVariable("plasticWork", dimEnergy/dimMass, 0, 0));
    }
    if (iDamage_ >= 0)
    {
        vars.append(carriedVariable("damage", dimless, 0, 0, 1));
    }
    return vars;
}


void Foam::inelasticModels::plasticityAndFailure::describe(Ostream& os) const
{
    os  << "plasticity " << plastic_->type();
    if (failure_->active())
    {
        os  << ", failure " << failure_->type();
    }
}


Foam::scalar Foam::inelasticModels::plasticityAndFailure::tension
(
    scalar* carried,
    const scalar p,
    const scalar dt
) const
{
    if (iDamage_ < 0)
    {
        return -GREAT;
    }
    // The cutoff acts within the step that passes it (at once, or over
    // spallTime), also on a cell whose damage the transport mixed below 1
    scalar& D = carried[iDamage_];
    D = failure_->spall(D, p, dt);
    if (failureModel::failed(D))
    {
        D = 1;
    }
    return failure_->pFloor(D);
}


Foam::scalar Foam::inelasticModels::plasticityAndFailure::relax
(
    cobasis::matrix& A,
    scalar* carried,
    const scalar rho,
    scalar& e,
    const scalar dt
) const
{
    if (iEps_ < 0 && iDamage_ < 0)
    {
        return 0;
    }

    // The temperature before the step (the constructor made sure the
    // equation of state has one where it is needed)
    const equationOfState& eos = law_.eos();
    const scalar T = needsT_ ? eos.T(rho, e) : 0;

    scalar heat = 0;
    scalar dEpsP = 0;
    scalar epsP = 0;
    if (iEps_ >= 0)
    {
        epsP = carried[iEps_];
        const scalar epsPOld = epsP;
        heat = plastic_->correct(A, epsP, law_.elastic(), dt, T);
        e += heat;
        carried[iEps_] = epsP;
        carried[iWork_] += heat;
        dEpsP = epsP - epsPOld;
    }

    if (iDamage_ >= 0)
    {
        const scalar p = eos.p(rho, e);
        const scalar epsPDot = dt > 0 ? dEpsP/dt : 0;

        // On the yield surface after a plastic step, the Von Mises stress
        // is the flow stress
        const scalar sigmaEq =
            dEpsP > 0 ? plastic_->sigmaY(epsP, epsPDot, T) : 0;

        scalar& D = carried[iDamage_];
        D = failure_->damage(D, dEpsP, epsPDot, p, sigmaEq, T);
        if (failureModel::failed(D))
        {
            D = 1;
        }
    }
    return heat;
}


Foam::scalar Foam::inelasticModels::plasticityAndFailure::shearStrength
(
    const scalar* carried,
    const scalar rho,
    const scalar p
) const
{
    if (failed(carried))
    {
        return 0;
    }
    if (iEps_ < 0)
    {
        return GREAT;
    }
    const equationOfState& eos = law_.eos();
    const scalar T = needsT_ ? eos.T(rho, eos.e(rho, p)) : 0;
    return plastic_->sigmaY(carried[iEps_], 0, T)/std::sqrt(3.0);
}


bool Foam::inelasticModels::plasticityAndFailure::predict
(
    cobasis::matrix& A,
    const scalar* carried,
    const scalar rho,
    const scalar p,
    const scalar dt
) const
{
    if (failed(carried))
    {
        // A failed phase carries no shear (the relaxation takes it out)
        A = cobasis::rotation(A)*std::cbrt(A.determinant());
        return true;
    }
    if (!plastic_->plastic())
    {
        return false;
    }
    scalar epsP = iEps_ >= 0 ? carried[iEps_] : 0;
    const equationOfState& eos = law_.eos();
    const scalar T =
        plastic_->needsTemperature() ? eos.T(rho, eos.e(rho, p)) : 0;
    cobasis::matrix U(A);
    plastic_->correct(U, epsP, law_.elastic(), dt, T);
    if (U == A)
    {
        // Within the yield surface (the return leaves A bit for bit)
        return false;
    }
    // The return gives the stretch; the prediction keeps its rotation
    A = cobasis::rotation(A)*U;
    return true;
}


// ************************************************************************* //
