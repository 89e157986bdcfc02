#include "cobasisTransport.H"
#include "foamEigen.H"
#include "readOption.H"

using Foam::foamEigen::toEigen;

// * * * * * * * * * * * * * * * Static Data * * * * * * * * * * * * * * * //

const Foam::wordList Foam::cobasisTransport::keywords
(
    {"cobasisRotation"}
);


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::cobasisTransport::cobasisTransport
(
    const phaseSystem& phases,
    const dictionary& dict
)
:
    phases_(phases),
    nPhases_(phases.size()),
    keepRotation_(false),
    slot_(nPhases_),
    sums_(nPhases_),
    near_(phases.mesh().nCells(), false),
    missed_(0),
    A_(nPhases_, nullptr),
    rec_(nullptr)
{
    enum class rotation { discard, keep };
    static const Enum<rotation> names
    ({
        {rotation::discard, "discard"},
        {rotation::keep, "keep"}
    });
    keepRotation_ =
        readOption
        (
            dict, "cobasisRotation", names, rotation::discard,
            "discreteEquations"
        )
     == rotation::keep;

    updateMesh();
}


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

void Foam::cobasisTransport::assignSums(const label k)
{
    const fvMesh& mesh = phases_.mesh();
    const phaseRegimes& regimes = phases_.regimes();
    const volScalarField& alpha = phases_.alpha(k);
    const scalarField& a = alpha.primitiveField();
    const labelUList& own = mesh.owner();
    const labelUList& nei = mesh.neighbour();

    forAll(near_, c)
    {
        near_[c] = !regimes.trace(a[c]);
    }
    forAll(nei, facei)
    {
        const label o = own[facei];
        const label n = nei[facei];
        if (!regimes.trace(a[n])) near_[o] = true;
        if (!regimes.trace(a[o])) near_[n] = true;
    }
    forAll(mesh.boundary(), patchi)
    {
        if (phases_.boundary()[patchi] != boundaryKinds::kind::coupled)
        {
            continue;
        }
        const scalarField nbr
        (
            alpha.boundaryField()[patchi].patchNeighbourField()
        );
        const labelUList& fc = mesh.boundary()[patchi].faceCells();
        forAll(fc, i)
        {
            if (!regimes.trace(nbr[i])) near_[fc[i]] = true;
        }
    }

    std::vector<label>& slot = slot_[k];
    label n = 0;
    forAll(near_, c)
    {
        slot[c] = near_[c] ? n++ : -1;
    }
    std::vector<sums>& s = sums_[k];
    if (n > label(s.size()))
    {
        s.resize(n);
    }
    for (label i = 0; i < n; ++i)
    {
        s[i].L.setZero();
        s[i].advection.setZero();
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::cobasisTransport::updateMesh()
{
    const label nCells = phases_.mesh().nCells();
    near_.setSize(nCells);
    near_ = false;
    for (label k = 0; k < nPhases_; ++k)
    {
        if (phases_.phase(k).solid())
        {
            slot_[k].assign(nCells, -1);
        }
        A_[k] = nullptr;
    }
    rec_ = nullptr;
}


void Foam::cobasisTransport::reset(const reconstruction& rec)
{
    rec_ = &rec;
    missed_ = 0;
    for (label k = 0; k < nPhases_; ++k)
    {
        if (phases_.phase(k).solid())
        {
            assignSums(k);
            A_[k] = &phases_.A(k).primitiveField();
        }
    }
}


void Foam::cobasisTransport::addFace
(
    const label c,
    const cobasis::vector& SfOut,
    const std::vector<phaseSide>& own,
    const std::vector<phaseSide>& across,
    const demFaceAssembly& assembly,
    const cobasis::matrix* Q
)
{
    for (label k = 0; k < nPhases_; ++k)
    {
        if (!phases_.phase(k).solid()) continue;
        const label slot = slot_[k][c];
        if (slot < 0) continue;
        sums& sc = sums_[k][slot];

        const cobasis::vector vStar
        (
            Q ? (*Q*assembly.vStar(k)).eval() : assembly.vStar(k)
        );
        sc.L += vStar*SfOut.transpose();

        const double flux = vStar.dot(SfOut);

        // Upwind face value; a trace upwind leaves the cell's own value
        const phaseSide& up = (flux < 0) ? across[k] : own[k];
        if (up.trace)
        {
            continue;
        }
        const cobasis::matrix Ac(Ahalf(k, c));
        if (Q)
        {
            sc.advection += flux*(up.A*Q->transpose() - Ac);
        }
        else
        {
            sc.advection += flux*(up.A - Ac);
        }
    }
}


Foam::cobasis::matrix Foam::cobasisTransport::update
(
    const label k,
    const label c,
    const scalar dt,
    const scalar V,
    const cobasis::matrix& A
) const
{
    const label slot = slot_[k][c];
    if (slot < 0)
    {
        ++missed_;
        return A;
    }
    const sums& sc = sums_[k][slot];
    const scalar dtByV = dt/V;
    cobasis::matrix Anew
    (
        A - dtByV*sc.advection - dt*(Ahalf(k, c)*sc.L)/V
    );

    // Stored without rotation (an inverted cobasis is left for the
    // relaxation's det(A) check)
    if (!keepRotation_ && Anew.determinant() > 0)
    {
        Anew = cobasis::stretch(Anew);
    }
    return Anew;
}
