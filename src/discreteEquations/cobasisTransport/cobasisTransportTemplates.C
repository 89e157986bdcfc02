template<class CentredA>
void Foam::cobasisTransport::addFace
(
    const label c,
    const cobasis::vector& SfOut,
    const std::vector<phaseSide>& own,
    const std::vector<phaseSide>& across,
    const demFaceAssembly& assembly,
    const CentredA& Ac
)
{
    for (label k = 0; k < nPhases_; ++k)
    {
        if (!phases_.phase(k).solid()) continue;

        const cobasis::vector vStar(assembly.vStar(k));
        L_[k][c] += vStar*SfOut.transpose();

        const double flux = vStar.dot(SfOut);

        // Upwind face value; a trace upwind leaves the cell's own value
        const phaseSide& up = (flux < 0) ? across[k] : own[k];
        if (up.trace)
        {
            continue;
        }
        advection_[k][c] += flux*(up.A - Ac(k));
    }
}
