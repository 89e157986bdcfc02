#include "bodyForces.H"
#include "uniformDimensionedFields.H"
#include "IOdictionary.H"
#include "IFstream.H"
#include "keywordCheck.H"

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::bodyForces::bodyForces(const fvMesh& mesh)
:
    mesh_(mesh),
    accelerations_(),
    acceleration_()
{
    const Time& runTime = mesh.time();

    IOobject gIO
    (
        "g",
        runTime.constant(),
        mesh,
        IOobject::MUST_READ,
        IOobject::NO_WRITE
    );
    if (gIO.typeHeaderOk<uniformDimensionedVectorField>(true))
    {
        const uniformDimensionedVectorField g(gIO);

        // Its entries, as for the other input (the field reads these two)
        IFstream gStream(typeFilePath<uniformDimensionedVectorField>(gIO));
        checkKeywords(dictionary(gStream), {"dimensions", "value"}, "g");
        dictionary gDict;
        gDict.add("type", "uniform");
        gDict.add("value", g.value());
        accelerations_.append(bodyAcceleration::New("g", gDict));
    }

    IOobject accIO
    (
        "bodyAccelerations",
        runTime.constant(),
        runTime,
        IOobject::MUST_READ,
        IOobject::NO_WRITE
    );
    if (accIO.typeHeaderOk<IOdictionary>(true))
    {
        const IOdictionary accDict(accIO);

        // Every entry is an acceleration's sub-dictionary
        wordList valid;
        for (const entry& e : accDict)
        {
            if (e.isDict())
            {
                valid.append(e.keyword());
            }
        }
        checkKeywords(accDict, valid, "bodyAccelerations");

        for (const entry& e : accDict)
        {
            if (e.isDict())
            {
                accelerations_.append
                (
                    bodyAcceleration::New(e.keyword(), e.dict())
                );
            }
        }
    }
    for (const bodyAcceleration& acc : accelerations_)
    {
        Info<< "Body acceleration " << acc.name() << " ("
            << acc.type() << ")" << nl;
    }

    // Per cell only when there are accelerations
    if (active())
    {
        acceleration_.setSize(mesh.nCells(), Zero);
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

const Foam::vectorField& Foam::bodyForces::update(const scalar t)
{
    const vectorField& C = mesh_.C().primitiveField();
    acceleration_ = Zero;
    for (const bodyAcceleration& acc : accelerations_)
    {
        forAll(acceleration_, celli)
        {
            acceleration_[celli] += acc.value(C[celli], t);
        }
    }
    return acceleration_;
}


void Foam::bodyForces::addSources(const scalar dt, conservedState& q) const
{
    if (!active())
    {
        return;
    }
    forAll(acceleration_, celli)
    {
        const cobasis::vector a
        (
            acceleration_[celli].x(),
            acceleration_[celli].y(),
            acceleration_[celli].z()
        );
        for (size_t k = 0; k < q.mass.size(); ++k)
        {
            const cobasis::vector mom0(q.momentum[k][celli]);
            q.momentum[k][celli] += q.mass[k][celli]*dt*a;
            q.energy[k][celli] += 0.5*(mom0 + q.momentum[k][celli]).dot(a)*dt;
        }
    }
}


void Foam::bodyForces::updateMesh()
{
    if (active())
    {
        // (the same field: the solver holds it)
        acceleration_.setSize(mesh_.nCells());
        acceleration_ = Zero;
    }
}
