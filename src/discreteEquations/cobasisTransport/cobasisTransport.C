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
    L_(nPhases_),
    advection_(nPhases_),
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

    const label nCells = phases.mesh().nCells();
    for (label k = 0; k < nPhases_; ++k)
    {
        if (phases.phase(k).solid())
        {
            L_[k].resize(nCells);
            advection_[k].resize(nCells);
        }
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::cobasisTransport::reset(const reconstruction& rec)
{
    rec_ = &rec;
    for (label k = 0; k < nPhases_; ++k)
    {
        for (cobasis::matrix& L : L_[k])
        {
            L.setZero();
        }
        for (cobasis::matrix& a : advection_[k])
        {
            a.setZero();
        }
        if (phases_.phase(k).solid())
        {
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

        const cobasis::vector vStar
        (
            Q ? (*Q*assembly.vStar(k)).eval() : assembly.vStar(k)
        );
        L_[k][c] += vStar*SfOut.transpose();

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
            advection_[k][c] += flux*(up.A*Q->transpose() - Ac);
        }
        else
        {
            advection_[k][c] += flux*(up.A - Ac);
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
    const scalar dtByV = dt/V;
    cobasis::matrix Anew
    (
        A - dtByV*advection_[k][c] - dt*(Ahalf(k, c)*L_[k][c])/V
    );

    // Stored without rotation (an inverted cobasis is left for the
    // relaxation's det(A) check)
    if (!keepRotation_ && Anew.determinant() > 0)
    {
        Anew = cobasis::stretch(Anew);
    }
    return Anew;
}
