#include "firstOrder.H"
#include "addToRunTimeSelectionTable.H"


namespace Foam
{
namespace reconstructions
{
    defineTypeNameAndDebug(firstOrder, 0);
    addToRunTimeSelectionTable(reconstruction, firstOrder, dictionary);
}
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::reconstructions::firstOrder::firstOrder
(
    const phaseSystem& phases,
    const cellStates& cells,
    const dictionary& dict
)
:
    reconstruction(phases, cells, dict)
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::reconstructions::firstOrder::update
(
    const scalar,
    const vectorField*
)
{
    velocityGradient();
}


void Foam::reconstructions::firstOrder::faceState
(
    const label celli,
    const label,
    const vector& d,
    std::vector<phaseSide>& s
) const
{
    cellFaceState(celli, d, s);
}


void Foam::reconstructions::firstOrder::describe(Ostream& os) const
{
    os  << "first order, face velocity reconstruction with velocity limiter "
        << (gradUCalc_.limited() ? "cellLimited" : "none");
}
