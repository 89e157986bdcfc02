#include "phaseSystem.H"
#include "alphaClosure.H"
#include "foamEigen.H"
#include "polyPatch.H"
#include "zeroGradientFvPatchFields.H"
#include "OSspecific.H"

// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

Foam::wordList Foam::phaseSystem::derivedPatchTypes() const
{
    wordList types
    (
        mesh_.boundary().size(),
        zeroGradientFvPatchScalarField::typeName
    );
    forAll(mesh_.boundary(), patchi)
    {
        const word& pType = mesh_.boundaryMesh()[patchi].type();
        if (polyPatch::constraintType(pType))
        {
            types[patchi] = pType;
        }
    }
    return types;
}


Foam::wordList Foam::phaseSystem::mirrorPatchTypes() const
{
    // As derivedPatchTypes, and slip where U is slip: the cobasis of the
    // mirrored state is M A M (M = I - 2 n n), and its component gradients
    // must see that (zeroGradient gave the off-diagonal rows of A at a slip
    // wall the wrong sign)
    wordList types(derivedPatchTypes());
    forAll(mesh_.boundary(), patchi)
    {
        if (U_.boundaryField()[patchi].type() == "slip")
        {
            types[patchi] = "slip";
        }
    }
    return types;
}


void Foam::phaseSystem::checkFieldNames() const
{
    const fileName dir(mesh_.time().timePath());
    const fileNameList files(readDir(dir, fileName::FILE));

    for (const word prefix : {"alpha.", "rho.", "A.", "p.", "epsilonP."})
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
    forAll(phases_, k)
    {
        const scalarField& a = alpha_[k].primitiveField();
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
            sum += alpha_[k][celli];
        }
        if (mag(sum - 1) > 1e-6)
        {
            FatalErrorInFunction
                << "The volume fractions alpha.<phase> of " << phaseNames_
                << " sum to " << sum << " in cell " << celli
                << " (centre " << mesh_.C()[celli] << "), not 1 within 1e-6"
                << exit(FatalError);
        }

        // Floor, and close the sum exactly with the largest phase
        floorAndClose
        (
            phases_.size(),
            alphaMin_,
            [&](const label k) -> scalar& { return alpha_[k][celli]; }
        );
    }
}


void Foam::phaseSystem::initCobasis(const label k, const bool readA)
{
    const hyperelasticPhase& ph = phases_[k];
    tensorField& A = A_[k].primitiveFieldRef();
    const scalarField& rho = rho_[k].primitiveField();

    if (!ph.solid())
    {
        A = tensor::I;
        return;
    }

    const scalar rho0 = ph.rho0();
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
                << "A." << ph.name() << " has det = " << detA
                << " <= 0 in cell " << celli << exit(FatalError);
        }
        A[celli] *= cbrt(rho[celli]/(rho0*detA));
    }
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
    alphaMin_(dict_.getOrDefault<scalar>("alphaMin", 1e-8)),
    alphaTrace_(dict_.getOrDefault<scalar>("alphaTrace", 1e-6)),
    alphaMinor_(dict_.getOrDefault<scalar>("alphaMinor", 1e-3)),
    massFractionMinor_
    (
        dict_.getOrDefault<scalar>("massFractionMinor", 1e-6)
    ),
    pVacuum_(dict_.getOrDefault<scalar>("pVacuum", -1)),
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
        derivedPatchTypes()
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
        derivedPatchTypes()
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
        derivedPatchTypes()
    )
{
    if (phaseNames_.empty())
    {
        FatalIOErrorInFunction(dict_)
            << "No phases listed in " << dict_.objectPath()
            << exit(FatalIOError);
    }
    if
    (
        !(
            alphaMin_ > 0 && alphaMin_ < alphaTrace_
         && alphaTrace_ <= alphaMinor_ && alphaMinor_ < 0.5
        )
    )
    {
        FatalIOErrorInFunction(dict_)
            << "Need 0 < alphaMin (" << alphaMin_ << ") < alphaTrace ("
            << alphaTrace_ << ") <= alphaMinor (" << alphaMinor_
            << ") < 0.5" << exit(FatalIOError);
    }

    checkFieldNames();

    const label N = phaseNames_.size();
    phases_.setSize(N);
    plastic_.setSize(N);
    isentropicRelaxation_.setSize(N, false);
    isentrope_.setSize(N);
    pCavitation_.setSize(N);
    alpha_.setSize(N);
    rho_.setSize(N);
    p_.setSize(N);
    A_.setSize(N);
    epsilonP_.setSize(N);
    plasticWork_.setSize(N);

    const word timeName(mesh.time().timeName());

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
        const dictionary& phaseDict = dict_.subDict(name);

        phases_.set(k, new hyperelasticPhase(name, phaseDict));

        const word path
        (
            phaseDict.getOrDefault<word>
            (
                "pressureRelaxation", "constantPressure"
            )
        );
        if (path != "constantPressure" && path != "isentropic")
        {
            FatalIOErrorInFunction(phaseDict)
                << "Phase " << name << ": unknown pressureRelaxation "
                << path << "; valid: (constantPressure isentropic)"
                << exit(FatalIOError);
        }
        if (path == "isentropic" && phases_[k].solid())
        {
            FatalIOErrorInFunction(phaseDict)
                << "Phase " << name << ": pressureRelaxation isentropic is"
                << " for fluids only" << exit(FatalIOError);
        }
        isentropicRelaxation_[k] = (path == "isentropic");
        isentrope_[k] = Pair<scalar>(-1, 0);
        pCavitation_[k] = -GREAT;
        if (phaseDict.found("cavitationPressure"))
        {
            pCavitation_[k] = phaseDict.get<scalar>("cavitationPressure");
            // Held there, the fluid may expand to a vanishing density
            if
            (
                !isentropicRelaxation_[k]
             || !(pCavitation_[k] > phases_[k].eos().pMin(SMALL))
            )
            {
                FatalIOErrorInFunction(phaseDict)
                    << "Phase " << name << ": cavitationPressure "
                    << pCavitation_[k] << " needs pressureRelaxation"
                    << " isentropic and a value above "
                    << phases_[k].eos().pMin(SMALL) << exit(FatalIOError);
            }
        }
        if (phaseDict.found("referenceIsentrope"))
        {
            const Pair<scalar> ref
            (
                phaseDict.get<Pair<scalar>>("referenceIsentrope")
            );
            if
            (
                !isentropicRelaxation_[k] || !(ref.first() > 0)
             || !(ref.second() > phases_[k].eos().pMin(ref.first()))
            )
            {
                FatalIOErrorInFunction(phaseDict)
                    << "Phase " << name << ": referenceIsentrope " << ref
                    << " needs pressureRelaxation isentropic, rho > 0 and"
                    << " p > " << phases_[k].eos().pMin(ref.first())
                    << exit(FatalIOError);
            }
            isentrope_[k] = Pair<scalar>
            (
                ref.first(),
                phases_[k].eos().e(ref.first(), ref.second())
            );
        }

        if (phases_[k].solid())
        {
            plastic_.set
            (
                k,
                plasticModel::New(name, phaseDict.subDict("plasticity"))
            );
        }
        else
        {
            dictionary noneDict;
            noneDict.add("type", "none");
            plastic_.set(k, plasticModel::New(name, noneDict));
        }

        alpha_.set
        (
            k,
            new volScalarField
            (
                IOobject
                (
                    "alpha." + name,
                    timeName,
                    mesh,
                    IOobject::MUST_READ,
                    IOobject::AUTO_WRITE
                ),
                mesh
            )
        );

        rho_.set
        (
            k,
            new volScalarField
            (
                IOobject
                (
                    "rho." + name,
                    timeName,
                    mesh,
                    IOobject::MUST_READ,
                    IOobject::AUTO_WRITE
                ),
                mesh
            )
        );

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
            p_.set(k, new volScalarField(pIO, mesh));
        }
        else
        {
            pIO.readOpt() = IOobject::NO_READ;
            p_.set(k, new volScalarField(pIO, pMixture_));
        }

        IOobject AIO
        (
            "A." + name,
            timeName,
            mesh,
            IOobject::MUST_READ,
            phases_[k].solid() ? IOobject::AUTO_WRITE : IOobject::NO_WRITE
        );
        const bool readA =
            phases_[k].solid() && AIO.typeHeaderOk<volTensorField>(true);
        if (readA)
        {
            A_.set(k, new volTensorField(AIO, mesh));
        }
        else
        {
            AIO.readOpt() = IOobject::NO_READ;
            A_.set
            (
                k,
                new volTensorField
                (
                    AIO,
                    mesh,
                    dimensionedTensor("I", dimless, tensor::I),
                    mirrorPatchTypes()
                )
            );
        }

        IOobject epsIO
        (
            "epsilonP." + name,
            timeName,
            mesh,
            IOobject::READ_IF_PRESENT,
            phases_[k].solid() ? IOobject::AUTO_WRITE : IOobject::NO_WRITE
        );
        epsilonP_.set
        (
            k,
            new volScalarField
            (
                epsIO,
                mesh,
                dimensionedScalar(dimless, Zero),
                derivedPatchTypes()
            )
        );
        if (epsIO.typeHeaderOk<volScalarField>(true))
        {
            epsilonP_[k].primitiveFieldRef() =
                volScalarField(epsIO, mesh).primitiveField();
        }

        IOobject wIO
        (
            "plasticWork." + name,
            timeName,
            mesh,
            IOobject::READ_IF_PRESENT,
            phases_[k].solid() ? IOobject::AUTO_WRITE : IOobject::NO_WRITE
        );
        plasticWork_.set
        (
            k,
            new volScalarField
            (
                wIO,
                mesh,
                dimensionedScalar(dimEnergy/dimMass, Zero),
                derivedPatchTypes()
            )
        );
        if (wIO.typeHeaderOk<volScalarField>(true))
        {
            plasticWork_[k].primitiveFieldRef() =
                volScalarField(wIO, mesh).primitiveField();
        }

        // Admissible initial state
        const equationOfState& eos = phases_[k].eos();
        const scalarField& rho = rho_[k].primitiveField();
        const scalarField& pk = p_[k].primitiveField();
        forAll(rho, celli)
        {
            if (!(rho[celli] > 0) || !(pk[celli] > eos.pMin(rho[celli])))
            {
                FatalErrorInFunction
                    << "Phase " << name << " starts in cell " << celli
                    << " with rho = " << rho[celli] << ", p = " << pk[celli]
                    << ": need rho > 0 and p > " << eos.pMin(rho[celli])
                    << exit(FatalError);
            }
        }

        initCobasis(k, readA);
    }

    checkAlpha();
    correctBoundaryConditions();
    correctMixture();

    Info<< "Phases:" << nl;
    forAll(phases_, k)
    {
        Info<< "    " << phaseNames_[k] << ": "
            << (phases_[k].solid() ? "solid" : "fluid")
            << ", equationOfState " << phases_[k].eos().type();
        if (phases_[k].solid())
        {
            Info<< ", elasticity " << phases_[k].elastic().type()
                << " (rho0 " << phases_[k].rho0()
                << ", mu " << phases_[k].mu() << ")"
                << ", plasticity " << plastic_[k].type();
        }
        Info<< nl;
    }
    Info<< endl;
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::phaseSystem::correctBoundaryConditions()
{
    forAll(phases_, k)
    {
        alpha_[k].correctBoundaryConditions();
        rho_[k].correctBoundaryConditions();
        p_[k].correctBoundaryConditions();
        A_[k].correctBoundaryConditions();
    }
    U_.correctBoundaryConditions();
}


void Foam::phaseSystem::correctMixture()
{
    scalarField& rhoM = rhoMixture_.primitiveFieldRef();
    scalarField& pM = pMixture_.primitiveFieldRef();
    symmTensorField& sigma = sigma_.primitiveFieldRef();

    rhoM = 0;
    pM = 0;
    sigma = symmTensor::zero;

    forAll(phases_, k)
    {
        const hyperelasticPhase& ph = phases_[k];
        const scalarField& a = alpha_[k].primitiveField();
        const scalarField& rho = rho_[k].primitiveField();
        const scalarField& p = p_[k].primitiveField();
        const tensorField& A = A_[k].primitiveField();

        forAll(a, celli)
        {
            rhoM[celli] += a[celli]*rho[celli];
            pM[celli] += a[celli]*p[celli];
            sigma[celli] -= a[celli]*p[celli]*symmTensor::I;
            if (ph.solid())
            {
                const cobasis::matrix S(ph.S(foamEigen::toEigen(A[celli])));
                sigma[celli] += a[celli]*symmTensor
                (
                    S(0, 0), S(0, 1), S(0, 2),
                    S(1, 1), S(1, 2),
                    S(2, 2)
                );
            }
        }
    }

    sigmaEq_.primitiveFieldRef() = sqrt(1.5)*mag(dev(sigma));

    rhoMixture_.correctBoundaryConditions();
    pMixture_.correctBoundaryConditions();
    sigma_.correctBoundaryConditions();
    sigmaEq_.correctBoundaryConditions();
}
