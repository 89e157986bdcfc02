#include "phaseModel.H"
#include "correctBoundaryConditionsInPlace.H"
#include "keywordCheck.H"
#include "inputDefaults.H"
#include "readOption.H"

// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

void Foam::phaseModel::initCobasis(const bool readA)
{
    tensorField& A = A_->primitiveFieldRef();
    const scalarField& rho = rho_.primitiveField();

    const scalar rho0 = law_.rho0();
    forAll(A, celli)
    {
        if (!readA)
        {
            A[celli] = cbrt(rho[celli]/rho0)*tensor::I;
            continue;
        }
        const scalar detA = det(A[celli]);
        if (!(detA > 0))
        {
            FatalErrorInFunction
                << "A." << name() << " has det = " << detA
                << " <= 0 in cell " << celli << exit(FatalError);
        }
        A[celli] *= cbrt(rho[celli]/(rho0*detA));
    }
}


void Foam::phaseModel::checkInitialState() const
{
    const equationOfState& eos = law_.eos();
    const scalarField& rho = rho_.primitiveField();
    const scalarField& pk = p_->primitiveField();
    forAll(rho, celli)
    {
        if (!eos.admissible(rho[celli], pk[celli]))
        {
            FatalErrorInFunction
                << "Phase " << name() << " starts in cell " << celli
                << " with rho = " << rho[celli] << ", p = " << pk[celli]
                << ": need 0 < rho < " << eos.rhoMax() << " and p > "
                << eos.pMin(rho[celli]) << exit(FatalError);
        }
    }
}


bool Foam::phaseModel::readWriteTemperature(const dictionary& dict) const
{
    const bool needed = needsTemperature();
    const bool write =
        inputDefaults::get<Switch>
        (
            dict, "writeTemperature", Switch(needed), "Phase " + name()
        );
    if (write && !law_.eos().hasTemperature())
    {
        FatalIOErrorInFunction(dict)
            << "Phase " << name() << ": writeTemperature needs a"
            << " temperature, and its equationOfState "
            << law_.eos().type() << " gives none: add Cv to"
            << " equationOfState" << exit(FatalIOError);
    }
    return write;
}


// * * * * * * * * * * * * * * * Static Data * * * * * * * * * * * * * * * //

const Foam::wordList Foam::phaseModel::keywords
(
    {"material", "writeTemperature", "passiveScalars"}
);


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::phaseModel::phaseModel
(
    const label index,
    const word& name,
    const dictionary& dict,
    const volScalarField& pMixture,
    const wordList& derivedTypes,
    const wordList& mirrorTypes,
    const bool carriesSlip
)
:
    index_(index),
    law_(name, dict),
    alpha_
    (
        IOobject
        (
            "alpha." + name,
            pMixture.time().timeName(),
            pMixture.mesh(),
            IOobject::MUST_READ,
            IOobject::AUTO_WRITE
        ),
        pMixture.mesh()
    ),
    rho_
    (
        IOobject
        (
            "rho." + name,
            pMixture.time().timeName(),
            pMixture.mesh(),
            IOobject::MUST_READ,
            IOobject::AUTO_WRITE
        ),
        pMixture.mesh()
    ),
    nInelastic_(0)
{
    const fvMesh& mesh = pMixture.mesh();
    const word timeName(mesh.time().timeName());

    relaxationPath_ = pressureRelaxationPath::New(law_, dict);

    // Stops on a model that needs a temperature the equation of state
    // does not give
    inelastic_ = inelasticModel::New(law_, dict);
    const bool writeT = readWriteTemperature(dict);

    // The phase's entries: its own and those its models read from it (an
    // entry from the material library file is reported in that file)
    wordList valid(keywords);
    valid.append(hyperelasticPhase::keywords);
    valid.append(relaxationPath_->keywords());
    valid.append(inelastic_->phaseKeywords());
    checkKeywords(dict, valid, "Phase " + name);

    IOobject pIO
    (
        "p." + name,
        timeName,
        mesh,
        IOobject::MUST_READ,
        IOobject::AUTO_WRITE
    );
    if (pIO.typeHeaderOk<volScalarField>(true))
    {
        p_.reset(new volScalarField(pIO, mesh));
    }
    else
    {
        pIO.readOpt() = IOobject::NO_READ;
        p_.reset(new volScalarField(pIO, pMixture));
    }

    if (writeT)
    {
        temperature_.reset
        (
            new phaseTemperature(name, law_.eos(), rho_, p_())
        );
    }

    // A fluid carries no cobasis (its stress is -p I)
    bool readA = false;
    if (law_.solid())
    {
        IOobject AIO
        (
            "A." + name,
            timeName,
            mesh,
            IOobject::MUST_READ,
            IOobject::AUTO_WRITE
        );
        readA = AIO.typeHeaderOk<volTensorField>(true);
        if (readA)
        {
            A_.reset(new volTensorField(AIO, mesh));
        }
        else
        {
            AIO.readOpt() = IOobject::NO_READ;
            A_.reset
            (
                new volTensorField
                (
                    AIO,
                    mesh,
                    dimensionedTensor("I", dimless, tensor::I),
                    mirrorTypes
                )
            );
        }
    }

    // Carried variables: those of the inelastic model, then the passive
    // tracers
    carriedInfo_.append(inelastic_->carriedVariables());
    nInelastic_ = carriedInfo_.size();
    for
    (
        const word& tracer
      : dict.getOrDefault<wordList>("passiveScalars", wordList())
    )
    {
        carriedInfo_.append(carriedVariable(tracer, dimless));
    }
    // The slip velocity of a case where solids slide on each other: every
    // phase's velocity less the cell's, set by the velocity relaxation
    // (carried so that the face states, the processor exchange, the
    // restart and the retried step have it)
    iSlip_ = -1;
    if (carriesSlip)
    {
        iSlip_ = carriedInfo_.size();
        for (const word& component : {"slipUx", "slipUy", "slipUz"})
        {
            carriedInfo_.append(carriedVariable(component, dimVelocity));
        }
    }
    if (carriedInfo_.size() > maxCarried)
    {
        FatalIOErrorInFunction(dict)
            << "Phase " << name << " carries " << carriedInfo_.size()
            << " variables with its mass; at most " << label(maxCarried)
            << exit(FatalIOError);
    }

    carried_.setSize(carriedInfo_.size());
    forAll(carriedInfo_, i)
    {
        const carriedVariable& var = carriedInfo_[i];
        if (carriedIndex(var.name) != i)
        {
            FatalIOErrorInFunction(dict)
                << "Phase " << name << ": the variable " << var.name
                << " is carried twice" << exit(FatalIOError);
        }

        // The boundary values of a carried variable are never used (faces
        // carry the upwind cell value): zeroGradient, whatever the file says
        IOobject io
        (
            var.name + "." + name,
            timeName,
            mesh,
            IOobject::READ_IF_PRESENT,
            IOobject::AUTO_WRITE
        );
        carried_.set
        (
            i,
            new volScalarField
            (
                io,
                mesh,
                dimensionedScalar(var.name, var.dimensions, var.initial),
                derivedTypes
            )
        );
        if (io.typeHeaderOk<volScalarField>(true))
        {
            carried_[i].primitiveFieldRef() =
                volScalarField(io, mesh).primitiveField();
        }
    }
    checkInitialState();
    if (law_.solid())
    {
        initCobasis(readA);
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::label Foam::phaseModel::carriedIndex(const word& name) const
{
    forAll(carriedInfo_, i)
    {
        if (carriedInfo_[i].name == name)
        {
            return i;
        }
    }
    return -1;
}


void Foam::phaseModel::correctBoundaryConditions()
{
    correctBoundaryConditionsInPlace(alpha_);
    correctBoundaryConditionsInPlace(rho_);
    correctBoundaryConditionsInPlace(p_());

    if (solid())
    {
        correctBoundaryConditionsInPlace(A_());
    }
}


void Foam::phaseModel::correctCarriedBoundaries()
{
    for (volScalarField& field : carried_)
    {
        correctBoundaryConditionsInPlace(field);
    }
}


void Foam::phaseModel::saveState()
{
    alphaSave_ = alpha_.primitiveField();
    rhoSave_ = rho_.primitiveField();
    pSave_ = p_->primitiveField();
    if (solid())
    {
        ASave_ = A_->primitiveField();
    }
    carriedSave_.setSize(carried_.size());
    forAll(carried_, i)
    {
        carriedSave_[i] = carried_[i].primitiveField();
    }
}


void Foam::phaseModel::restoreState()
{
    alpha_.primitiveFieldRef() = alphaSave_;
    rho_.primitiveFieldRef() = rhoSave_;
    p_->primitiveFieldRef() = pSave_;
    if (solid())
    {
        A_->primitiveFieldRef() = ASave_;
    }
    forAll(carried_, i)
    {
        carried_[i].primitiveFieldRef() = carriedSave_[i];
    }
}
