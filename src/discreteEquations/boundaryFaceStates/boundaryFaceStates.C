#include "boundaryFaceStates.H"
#include "foamEigen.H"
#include "processorPolyPatch.H"
#include "PstreamBuffers.H"

using Foam::foamEigen::toEigen;


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::boundaryFaceStates::boundaryFaceStates(const phaseSystem& phases)
:
    phases_(phases),
    mesh_(phases.mesh()),
    nPhases_(phases.size()),
    nExchangeSlide_(phases.sliding() ? 3 : 0),
    exchangeSize_(0),
    exchangeOffset_(nPhases_),
    coupledOwn_(mesh_.boundary().size()),
    nbrStates_(mesh_.boundary().size())
{
    for (label k = 0; k < nPhases_; ++k)
    {
        exchangeOffset_[k] = exchangeSize_;
        exchangeSize_ +=
            nExchangeState + nExchangeSlide_ + phases[k].nCarried();
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::boundaryFaceStates::update
(
    const reconstruction& rec,
    const boolList* fallbackFaces
)
{
    if (!Pstream::parRun())
    {
        return;
    }

    const vectorField& Cf = mesh_.faceCentres();
    const vectorField& C = mesh_.cellCentres();

    const boundaryKinds& kinds = phases_.boundary();
    PstreamBuffers pBufs(Pstream::commsTypes::nonBlocking);

    forAll(mesh_.boundary(), patchi)
    {
        if (kinds[patchi] != boundaryKinds::kind::coupled) continue;

        const fvPatch& patch = mesh_.boundary()[patchi];
        const labelUList& fc = patch.faceCells();
        scalarList send(fc.size()*exchangeSize_);

        // The face states of this side, kept for the face loop
        std::vector<std::vector<phaseSide>>& own = coupledOwn_[patchi];
        own.resize(fc.size(), std::vector<phaseSide>(nPhases_));

        label i = 0;
        forAll(fc, facei)
        {
            // First order on a fall-back face (demSolver)
            const label meshFacei = patch.start() + facei;
            if (fallbackFaces && (*fallbackFaces)[meshFacei])
            {
                rec.cellMeanState(fc[facei], own[facei]);
            }
            else
            {
                const vector d(Cf[meshFacei] - C[fc[facei]]);
                rec.faceState(fc[facei], meshFacei, d, own[facei]);
            }
            for (label k = 0; k < nPhases_; ++k)
            {
                const phaseSide& s = own[facei][k];
                send[i++] = s.alpha;
                send[i++] = s.rho;
                send[i++] = s.p;
                send[i++] = s.a;
                for (int j = 0; j < 3; ++j) send[i++] = s.U(j);
                for (int j = 0; j < 9; ++j) send[i++] = s.A(j/3, j%3);
                for (int j = 0; j < nExchangeSlide_; ++j) send[i++] = s.nSlide(j);
                for (int j = 0; j < s.nCarried; ++j) send[i++] = s.carried[j];
            }
        }

        const processorPolyPatch& pp =
            refCast<const processorPolyPatch>(patch.patch());
        UOPstream toNbr(pp.neighbProcNo(), pBufs);
        toNbr << send;
    }

    pBufs.finishedSends();

    forAll(mesh_.boundary(), patchi)
    {
        if (kinds[patchi] != boundaryKinds::kind::coupled) continue;
        const processorPolyPatch& pp =
            refCast<const processorPolyPatch>
            (
                mesh_.boundary()[patchi].patch()
            );
        UIPstream fromNbr(pp.neighbProcNo(), pBufs);
        fromNbr >> nbrStates_[patchi];
    }
}



void Foam::boundaryFaceStates::ghost
(
    const label patchi,
    const label patchFacei,
    const cobasis::vector& n,
    const std::vector<phaseSide>& cell,
    std::vector<phaseSide>& ghost,
    const reconstruction& rec
) const
{
    const boundaryKinds::kind kind = phases_.boundary()[patchi];

    for (label k = 0; k < nPhases_; ++k)
    {
        const phaseSide& c = cell[k];
        phaseSide& g = ghost[k];

        switch (kind)
        {
            case boundaryKinds::kind::mirror:
            case boundaryKinds::kind::noSlip:
            {
                const cobasis::matrix M
                (
                    cobasis::matrix::Identity() - 2*n*n.transpose()
                );
                g = c;
                g.U =
                    (kind == boundaryKinds::kind::mirror)
                  ? (M*c.U).eval()
                  : (-c.U).eval();
                g.A = c.A*M;
                g.sigma = M*c.sigma*M;
                g.nSlide = M*c.nSlide;
                break;
            }

            case boundaryKinds::kind::wedge:
            {
                // The cell side is already rotated into the face plane
                g = c;
                break;
            }

            case boundaryKinds::kind::coupled:
            {
                const scalar* s =
                    &nbrStates_[patchi]
                    [
                        patchFacei*exchangeSize_ + exchangeOffset_[k]
                    ];
                g.alpha = s[0];
                g.rho = s[1];
                g.p = s[2];
                g.a = s[3];
                g.U = cobasis::vector(s[4], s[5], s[6]);
                for (int j = 0; j < 9; ++j) g.A(j/3, j%3) = s[7 + j];
                g.nSlide.setZero();
                for (int j = 0; j < nExchangeSlide_; ++j)
                {
                    g.nSlide(j) = s[nExchangeState + j];
                }
                g.nCarried = phases_[k].nCarried();
                for (int j = 0; j < g.nCarried; ++j)
                {
                    g.carried[j] = s[nExchangeState + nExchangeSlide_ + j];
                }
                rec.completeSide(k, g);
                break;
            }

            default:
            {
                const hyperelasticPhase& ph = phases_.phase(k);
                g.alpha = phases_.alpha(k).boundaryField()[patchi][patchFacei];
                g.rho = phases_.rho(k).boundaryField()[patchi][patchFacei];
                g.p = phases_.p(k).boundaryField()[patchi][patchFacei];
                g.U = toEigen(phases_.U().boundaryField()[patchi][patchFacei]);
                g.A = c.A*std::cbrt(g.rho/c.rho);
                g.nSlide = c.nSlide;
                g.nCarried = c.nCarried;
                for (int j = 0; j < c.nCarried; ++j)
                {
                    g.carried[j] = c.carried[j];
                }
                rec.completeSide(k, g);
                g.a = std::sqrt(ph.a2Max(g.rho, g.p, g.A));
                break;
            }
        }
    }
    rec.markMinor(ghost);
}



void Foam::boundaryFaceStates::updateMesh()
{
    coupledOwn_ = List<std::vector<std::vector<phaseSide>>>
    (
        mesh_.boundary().size()
    );
    nbrStates_ = List<scalarList>(mesh_.boundary().size());
}
