#include "loadBalancer.H"
#include "fvMeshDistribute.H"
#include "simpleGeomDecomp.H"
#include "labelVector.H"

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::loadBalancer::loadBalancer(fvMesh& mesh, const scalar maxImbalance)
:
    mesh_(mesh),
    maxImbalance_(maxImbalance),
    nBalances_(0)
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::scalar Foam::loadBalancer::imbalance() const
{
    const scalar n = mesh_.nCells();
    const scalar mean = returnReduce(n, sumOp<scalar>())/Pstream::nProcs();
    return returnReduce(n, maxOp<scalar>())/max(mean, scalar(1)) - 1;
}


Foam::autoPtr<Foam::mapDistributePolyMesh> Foam::loadBalancer::balance
(
    const labelList& families
)
{
    if (!Pstream::parRun() || maxImbalance_ <= 0)
    {
        return nullptr;
    }
    const scalar before = imbalance();
    if (before <= maxImbalance_)
    {
        return nullptr;
    }

    // Slabs along the longest direction of the mesh in the plane of the
    // solution
    const boundBox bb(mesh_.points(), true);
    vector span(bb.span());
    for (direction d = 0; d < vector::nComponents; ++d)
    {
        if (mesh_.solutionD()[d] < 0 || mesh_.geometricD()[d] < 0)
        {
            span[d] = 0;
        }
    }
    const direction longest = findMax(span);
    labelVector n(1, 1, 1);
    n[longest] = Pstream::nProcs();

    dictionary coeffs;
    coeffs.add("n", n);
    dictionary decomposeDict;
    decomposeDict.add("numberOfSubdomains", Pstream::nProcs());
    decomposeDict.add("method", "simple");
    decomposeDict.add("simpleCoeffs", coeffs);
    simpleGeomDecomp method(decomposeDict);

    // Each family at its cells' centroid, weighed by its cells
    const label nFamilies = families.size() ? max(families) + 1 : 0;
    pointField centres(nFamilies, Zero);
    scalarField volumes(nFamilies, Zero);
    scalarField weights(nFamilies, Zero);
    forAll(families, c)
    {
        const label f = families[c];
        centres[f] += mesh_.V()[c]*mesh_.C()[c];
        volumes[f] += mesh_.V()[c];
        weights[f] += 1;
    }
    centres /= volumes;
    const decompositionMethod& decomposer = method;
    const labelList distribution
    (
        decomposer.decompose(mesh_, families, centres, weights)
    );

    fvMeshDistribute distributor(mesh_, 1e-6*bb.mag());
    autoPtr<mapDistributePolyMesh> map = distributor.distribute(distribution);
    ++nBalances_;

    Info<< "Load balance: the largest process held " << 1 + before
        << " times the mean number of cells, now " << 1 + imbalance()
        << endl;
    return map;
}


// ************************************************************************* //
