#include "historySummary.H"

// * * * * * * * * * * * * * * * * Destructor  * * * * * * * * * * * * * * * //

Foam::historySummary::~historySummary()
{}


// ************************************************************************* //
