#include "phaseSystem.H"
#include "stepLedger.H"
#include "correctBoundaryConditionsInPlace.H"
#include "keywordCheck.H"
#include "phaseMaterial.H"
#include "alphaClosure.H"
#include "foamEigen.H"
#include "polyPatch.H"
#include "zeroGradientFvPatchFields.H"
#include "OSspecific.H"

using Foam::foamEigen::toEigen;

// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

void Foam::phaseSystem::checkFieldNames(const wordList& prefixes) const
{
    const fileName dir(mesh_.time().timePath());
    const fileNameList files(readDir(dir, fileName::FILE));

    for (const word& prefix : prefixes)
    {
        for (const fileName& f : files)
        {
            const word name(f.name());
            if (name.size() > prefix.size() && name.startsWith(prefix))
            {
                word phaseName(name.substr(prefix.size()));
                if (phaseName.hasExt("gz")) phaseName = phaseName.lessExt();
                if (!phaseNames_.found(phaseName))
                {
                    FatalErrorInFunction
                        << "Field file " << dir/name << " names the phase "
                        << phaseName << ", which is not in the phases "
                        << phaseNames_ << " of " << dict_.objectPath()
                        << exit(FatalError);
                }
            }
        }
    }
}


void Foam::phaseSystem::checkAlpha()
{
    const label nCells = mesh_.nCells();
    const bool restart = isFile
    (
        IOobject
        (
            stepLedger::typeName,
            mesh_.time().timeName(),
            "uniform",
            mesh_
        ).objectPath()
    );
    forAll(phases_, k)
    {
        const scalarField& a = phases_[k].alpha().primitiveField();
        forAll(a, celli)
        {
            if (!(a[celli] >= 0 && a[celli] <= 1))
            {
                FatalErrorInFunction
                    << "alpha." << phaseNames_[k] << " = " << a[celli]
                    << " in cell " << celli << " is outside [0, 1]"
                    << exit(FatalError);
            }
        }
    }

    for (label celli = 0; celli < nCells; ++celli)
    {
        scalar sum = 0;
        forAll(phases_, k)
        {
            sum += phases_[k].alpha()[celli];
        }
        if (mag(sum - 1) > 1e-6)
        {
            FatalErrorInFunction
                << "The volume fractions alpha.<phase> of " << phaseNames_
                << " sum to " << sum << " in cell " << celli
                << " (centre " << mesh_.C()[celli] << "), not 1 within 1e-6"
                << exit(FatalError);
        }

        // Floor, and close the sum exactly with the largest phase; not at
        // a time the solver wrote (its ledger is there): those fractions
        // are its state, traces below alphaMin after the pressure
        // relaxation's rescaling (numerics.md 9.5) included, and a restart
        // takes them as they are, so that it continues the run exactly
        if (!restart)
        {
            floorAndClose
            (
                phases_.size(),
                regimes_.alphaMin(),
                [&](const label k) -> scalar& { return alpha(k)[celli]; }
            );
        }
    }
}


void Foam::phaseSystem::checkKeywords() const
{
    wordList valid(phaseRegimes::keywords);
    valid.append("phases");
    valid.append("contacts");
    valid.append(phaseNames_);
    for (const Pair<word>& removed : phaseRegimes::removedKeywords)
    {
        valid.append(removed.first());
    }
    Foam::checkKeywords(dict_, valid, "phaseProperties");
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::phaseSystem::phaseSystem(const fvMesh& mesh)
:
    mesh_(mesh),
    dict_
    (
        IOobject
        (
            "phaseProperties",
            mesh.time().constant(),
            mesh,
            IOobject::MUST_READ,
            IOobject::NO_WRITE
        )
    ),
    phaseNames_(dict_.get<wordList>("phases")),
    regimes_(dict_),
    U_
    (
        IOobject
        (
            "U",
            mesh.time().timeName(),
            mesh,
            IOobject::MUST_READ,
            IOobject::AUTO_WRITE
        ),
        mesh
    ),
    boundary_(U_),
    pMixture_
    (
        IOobject
        (
            "p",
            mesh.time().timeName(),
            mesh,
            IOobject::MUST_READ,
            IOobject::AUTO_WRITE
        ),
        mesh
    ),
    rhoMixture_
    (
        IOobject
        (
            "rho",
            mesh.time().timeName(),
            mesh,
            IOobject::NO_READ,
            IOobject::AUTO_WRITE
        ),
        mesh,
        dimensionedScalar(dimDensity, Zero),
        boundaryKinds::derivedPatchTypes(mesh)
    ),
    sigma_
    (
        IOobject
        (
            "sigma",
            mesh.time().timeName(),
            mesh,
            IOobject::NO_READ,
            IOobject::AUTO_WRITE
        ),
        mesh,
        dimensionedSymmTensor(dimPressure, Zero),
        boundaryKinds::derivedPatchTypes(mesh)
    ),
    sigmaEq_
    (
        IOobject
        (
            "sigmaEq",
            mesh.time().timeName(),
            mesh,
            IOobject::NO_READ,
            IOobject::AUTO_WRITE
        ),
        mesh,
        dimensionedScalar(dimPressure, Zero),
        boundaryKinds::derivedPatchTypes(mesh)
    )
{
    if (phaseNames_.empty())
    {
        FatalIOErrorInFunction(dict_)
            << "No phases listed in " << dict_.objectPath()
            << exit(FatalIOError);
    }
    checkKeywords();

    checkFieldNames({"alpha.", "rho.", "A.", "p."});

    const wordList derivedTypes(boundaryKinds::derivedPatchTypes(mesh));
    const wordList mirrorTypes(boundary_.cobasisPatchTypes(mesh));

    // Where solids may slide on each other, every phase carries a slip
    // velocity (phaseModel::slip)
    const bool carriesSlip = solidContacts::slides(dict_);

    phases_.setSize(phaseNames_.size());
    forAll(phaseNames_, k)
    {
        const word& name = phaseNames_[k];
        if (!dict_.isDict(name))
        {
            FatalIOErrorInFunction(dict_)
                << "Phase " << name << " listed in phases has no"
                << " sub-dictionary in " << dict_.objectPath()
                << exit(FatalIOError);
        }
        // The phase's dictionary with its `material <name>;` resolved
        // (phaseMaterial.H: the library entry, the phase's keywords on top)
        const dictionary phaseDict
        (
            phaseMaterial::phaseDict(name, dict_.subDict(name), mesh.time())
        );
        phases_.set
        (
            k,
            new phaseModel
            (
                k, name, phaseDict, pMixture_, derivedTypes, mirrorTypes,
                carriesSlip
            )
        );
    }

    {
        List<scalar> rho0Solid(phases_.size(), scalar(0));
        forAll(phases_, k)
        {
            if (phase(k).solid())
            {
                rho0Solid[k] = phase(k).rho0();
            }
        }
        regimes_.setReferenceDensities(rho0Solid);

        boolList solid(phases_.size());
        forAll(phases_, k)
        {
            solid[k] = phase(k).solid();
        }
        contacts_.reset(new solidContacts(dict_, phaseNames_, solid));
        if (contacts_->any())
        {
            sliding_.reset
            (
                new slidingInterfaces
                (
                    mesh, contacts_(), regimes_, phases_.size()
                )
            );
        }
    }

    // Field files of the carried variables that name no phase
    wordList carriedPrefixes;
    for (const phaseModel& phase : phases_)
    {
        for (const carriedVariable& var : phase.carriedInfo())
        {
            if (!carriedPrefixes.found(var.name + "."))
            {
                carriedPrefixes.append(var.name + ".");
            }
        }
    }
    checkFieldNames(carriedPrefixes);

    checkAlpha();
    correctBoundaryConditions();
    correctMixture();

    Info<< "Phases:" << nl;
    for (const phaseModel& phase : phases_)
    {
        const hyperelasticPhase& law = phase.law();
        Info<< "    " << phase.name() << ": "
            << (law.solid() ? "solid" : "fluid")
            << ", equationOfState " << law.eos().type();
        if (law.solid())
        {
            Info<< ", elasticity " << law.elastic().type()
                << " (rho0 " << law.rho0()
                << ", mu " << law.mu() << "), ";
            phase.inelastic().describe(Info);
        }
        if (phase.nCarried())
        {
            Info<< ", carried";
            for (const carriedVariable& var : phase.carriedInfo())
            {
                Info<< ' ' << var.name;
            }
        }
        Info<< nl;
    }
    contacts_->describe(Info, phaseNames_);
    Info<< endl;
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::phaseSystem::correctBoundaryConditions()
{
    for (phaseModel& phase : phases_)
    {
        phase.correctBoundaryConditions();
    }
    correctBoundaryConditionsInPlace(U_);
}


void Foam::phaseSystem::updateSliding()
{
    if (!sliding_.valid())
    {
        return;
    }
    UPtrList<const volScalarField> alphas(phases_.size());
    forAll(phases_, k)
    {
        alphas.set(k, &phases_[k].alpha());
    }
    sliding_->update(alphas);
}


void Foam::phaseSystem::correctDensity()
{
    scalarField& rhoM = rhoMixture_.primitiveFieldRef();
    rhoM = 0;
    forAll(phases_, k)
    {
        const scalarField& a = phases_[k].alpha().primitiveField();
        const scalarField& rho = phases_[k].rho().primitiveField();
        forAll(a, celli)
        {
            rhoM[celli] += a[celli]*rho[celli];
        }
    }
    rhoMixture_.correctBoundaryConditions();
}


void Foam::phaseSystem::correctOutputs()
{
    for (phaseModel& phase : phases_)
    {
        phase.correctCarriedBoundaries();
    }

    scalarField& pM = pMixture_.primitiveFieldRef();
    symmTensorField& sigma = sigma_.primitiveFieldRef();

    pM = 0;
    sigma = symmTensor::zero;

    forAll(phases_, k)
    {
        const hyperelasticPhase& ph = phases_[k].law();
        const scalarField& a = phases_[k].alpha().primitiveField();
        const scalarField& p = phases_[k].p().primitiveField();
        const tensorField* A = phases_[k].cellCobasis();

        forAll(a, celli)
        {
            pM[celli] += a[celli]*p[celli];
            sigma[celli] -= a[celli]*p[celli]*symmTensor::I;
            if (A)
            {
                const cobasis::matrix S(ph.S(foamEigen::toEigen((*A)[celli])));
                sigma[celli] += a[celli]*symmTensor
                (
                    S(0, 0), S(0, 1), S(0, 2),
                    S(1, 1), S(1, 2),
                    S(2, 2)
                );
            }
        }
    }

    // Per cell, without temporary fields
    scalarField& sigmaEq = sigmaEq_.primitiveFieldRef();
    forAll(sigma, celli)
    {
        sigmaEq[celli] = sqrt(1.5)*mag(dev(sigma[celli]));
    }

    pMixture_.correctBoundaryConditions();
    sigma_.correctBoundaryConditions();
    sigmaEq_.correctBoundaryConditions();
}


void Foam::phaseSystem::correctMixture()
{
    correctDensity();
    correctOutputs();
}


void Foam::phaseSystem::saveState()
{
    for (phaseModel& phase : phases_)
    {
        phase.saveState();
    }
    USave_ = U_.primitiveField();
}


Foam::Pair<Foam::scalar> Foam::phaseSystem::totals() const
{
    const scalarField& V = mesh_.V();
    const vectorField& U = U_.primitiveField();
    scalar mass = 0;
    scalar energy = 0;
    for (label k = 0; k < size(); ++k)
    {
        const hyperelasticPhase& ph = phase(k);
        const scalarField& alpha = this->alpha(k).primitiveField();
        const scalarField& rho = this->rho(k).primitiveField();
        const scalarField& p = this->p(k).primitiveField();
        const tensorField* A = cellCobasis(k);
        forAll(V, c)
        {
            const scalar m = alpha[c]*rho[c]*V[c];
            mass += m;
            const scalar e =
                A ? ph.e(rho[c], p[c], toEigen((*A)[c])) : ph.eos().e(rho[c], p[c]);
            energy += m*(e + 0.5*magSqr(phases_[k].velocity(U[c], c)));
        }
    }
    return Pair<scalar>
    (
        returnReduce(mass, sumOp<scalar>()),
        returnReduce(energy, sumOp<scalar>())
    );
}


void Foam::phaseSystem::phaseMotion
(
    const label k,
    scalar& mass,
    vector& momentum,
    scalar& kinetic
) const
{
    const scalarField& V = mesh_.V();
    const vectorField& U = U_.primitiveField();
    const scalarField& alpha = this->alpha(k).primitiveField();
    const scalarField& rho = this->rho(k).primitiveField();
    mass = 0;
    momentum = Zero;
    kinetic = 0;
    forAll(V, c)
    {
        const scalar m = alpha[c]*rho[c]*V[c];
        const vector u(phases_[k].velocity(U[c], c));
        mass += m;
        momentum += m*u;
        kinetic += 0.5*m*magSqr(u);
    }
    reduce(mass, sumOp<scalar>());
    reduce(momentum, sumOp<vector>());
    reduce(kinetic, sumOp<scalar>());
}


void Foam::phaseSystem::restoreState()
{
    for (phaseModel& phase : phases_)
    {
        phase.restoreState();
    }
    U_.primitiveFieldRef() = USave_;
    correctBoundaryConditions();
    correctMixture();
}


void Foam::phaseSystem::updateMesh()
{
    if (sliding_.valid())
    {
        sliding_->updateMesh();
    }
    correctBoundaryConditions();
    correctMixture();
    saveState();
}
