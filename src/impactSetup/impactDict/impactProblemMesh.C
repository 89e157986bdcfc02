#include "impactProblem.H"
#include "Time.H"
#include "OSspecific.H"
#include "wedgePolyPatch.H"
#include "mathematicalConstants.H"

// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * * //

namespace
{

using namespace Foam;

// The blockMesh patch type of a patch kind
word patchType(const word& kind)
{
    return
        kind == "wall" ? word("wall")
      : kind == "symmetry" ? word("symmetryPlane")
      : word("patch");
}

// Cells along an extent: the cell size rounded to fit
label nCells(const scalar extent, const scalar h)
{
    return max(label(1), label(extent/h + 0.5));
}

void writeVertex(Ostream& os, const point& p)
{
    os  << "    (" << p.x() << " " << p.y() << " " << p.z() << ")" << nl;
}

}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::impactProblem::guardMesh() const
{
    const fileName meshDir(runTime_.path()/runTime_.constant()/"polyMesh");
    const fileName blockMeshDict
    (
        runTime_.path()/runTime_.system()/"blockMeshDict"
    );
    if
    (
        isFile(meshDir/"faces")
     && (!isFile(blockMeshDict) || generatedFiles::foreign(blockMeshDict))
    )
    {
        FatalErrorInFunction
            << "impactDict has a domain, and " << meshDir << " holds a mesh"
            << " that impactSetup did not make (system/blockMeshDict is not"
            << " impactSetup's): impactSetup does not overwrite it. Remove"
            << " the domain entry to use that mesh, or move the mesh away."
            << exit(FatalError);
    }
}


void Foam::impactProblem::writeBlockMeshDict()
{
    const scalar h = cellSize_;
    const label nx = nCells(max_.x() - min_.x(), h);
    const label ny = nCells(max_.y() - min_.y(), h);
    const label nz = nCells(max_.z() - min_.z(), h);

    autoPtr<OFstream> osPtr
    (
        files_.open(runTime_.path()/runTime_.system()/"blockMeshDict")
    );
    OFstream& os = osPtr();
    os.precision(15);
    IOobject io("blockMeshDict", runTime_.system(), runTime_);
    io.writeHeader(os, "dictionary");
    os  << nl;

    const scalar x0 = min_.x(), x1 = max_.x();

    if (geometry_ == "axisymmetric")
    {
        // A 2-degree wedge about x: points at (x, r cos 1, -+r sin 1); the
        // axis a symmetry plane at a small radius; the nodes at multiples
        // of the radial cell size from r = 0 (the first cell from the
        // axis patch, the others in a second block)
        const scalar theta = constant::mathematical::pi/180;
        const scalar c = Foam::cos(theta), s = Foam::sin(theta);
        const scalar hr = max_.y()/ny;
        const scalar rAxis = min(1e-7, 1e-3*hr);
        const scalarList radii
        (
            ny > 1 ? scalarList({rAxis, hr, max_.y()})
                   : scalarList({rAxis, max_.y()})
        );

        os  << "// Axisymmetric wedge: axis x, radius y, angle 2 degrees;"
            << " the axis a symmetryPlane at r = " << rAxis << nl
            << "vertices" << nl << "(" << nl;
        // Vertex 4*k + (0: x0 front, 1: x1 front, 2: x1 back, 3: x0 back)
        // at radius k; the front wedge patch at -z, back at +z
        forAll(radii, k)
        {
            const scalar r = radii[k];
            writeVertex(os, point(x0, r*c, -r*s));
            writeVertex(os, point(x1, r*c, -r*s));
            writeVertex(os, point(x1, r*c, r*s));
            writeVertex(os, point(x0, r*c, r*s));
        }
        os  << ");" << nl << nl << "blocks" << nl << "(" << nl;
        for (label k = 0; k + 1 < radii.size(); ++k)
        {
            const label a = 4*k, b = 4*(k + 1);
            os  << "    hex (" << a << " " << a + 1 << " " << b + 1 << " "
                << b << " " << a + 3 << " " << a + 2 << " " << b + 2 << " "
                << b + 3 << ") (" << nx << " " << (k == 0 ? 1 : ny - 1)
                << " 1) simpleGrading (1 1 1)" << nl;
        }
        os  << ");" << nl << nl << "boundary" << nl << "(" << nl;

        auto patch = [&](const word& name, const word& type,
                         const List<labelList>& faces)
        {
            os  << "    " << name << nl << "    {" << nl
                << "        type " << type << ";" << nl
                << "        faces" << nl << "        (" << nl;
            for (const labelList& f : faces)
            {
                os  << "            (" << f[0] << " " << f[1] << " " << f[2]
                    << " " << f[3] << ")" << nl;
            }
            os  << "        );" << nl << "    }" << nl;
        };
        const label nb = radii.size() - 1;
        List<labelList> xMin(nb), xMax(nb), front(nb), back(nb);
        for (label k = 0; k < nb; ++k)
        {
            const label a = 4*k, b = 4*(k + 1);
            xMin[k] = labelList({a, a + 3, b + 3, b});
            xMax[k] = labelList({a + 1, b + 1, b + 2, a + 2});
            front[k] = labelList({a, b, b + 1, a + 1});
            back[k] = labelList({a + 3, a + 2, b + 2, b + 3});
        }
        const label t = 4*nb;
        patch("xMin", patchType(patchKinds_["xMin"]), xMin);
        patch("xMax", patchType(patchKinds_["xMax"]), xMax);
        patch
        (
            "yMax",
            patchType(patchKinds_["yMax"]),
            {{t, t + 3, t + 2, t + 1}}
        );
        patch("axis", "symmetryPlane", {{0, 1, 2, 3}});
        patch("front", "wedge", front);
        patch("back", "wedge", back);
        os  << ");" << nl;
    }
    else
    {
        point lo(min_), hi(max_);
        label nzCells = nz;
        if (geometry_ == "planar")
        {
            // One cell in z, of the x cell size, about z = 0
            const scalar dz = (x1 - x0)/nx;
            lo.z() = -0.5*dz;
            hi.z() = 0.5*dz;
            nzCells = 1;
        }
        os  << "vertices" << nl << "(" << nl;
        writeVertex(os, point(lo.x(), lo.y(), lo.z()));
        writeVertex(os, point(hi.x(), lo.y(), lo.z()));
        writeVertex(os, point(hi.x(), hi.y(), lo.z()));
        writeVertex(os, point(lo.x(), hi.y(), lo.z()));
        writeVertex(os, point(lo.x(), lo.y(), hi.z()));
        writeVertex(os, point(hi.x(), lo.y(), hi.z()));
        writeVertex(os, point(hi.x(), hi.y(), hi.z()));
        writeVertex(os, point(lo.x(), hi.y(), hi.z()));
        os  << ");" << nl << nl
            << "blocks" << nl << "(" << nl
            << "    hex (0 1 2 3 4 5 6 7) (" << nx << " " << ny << " "
            << nzCells << ") simpleGrading (1 1 1)" << nl
            << ");" << nl << nl << "boundary" << nl << "(" << nl;

        const wordList names({"xMin", "xMax", "yMin", "yMax", "zMin", "zMax"});
        const labelList faces[6] =
        {
            {0, 4, 7, 3}, {1, 2, 6, 5}, {0, 1, 5, 4},
            {3, 7, 6, 2}, {0, 3, 2, 1}, {4, 5, 6, 7}
        };
        for (label k = 0; k < 6; ++k)
        {
            word name(names[k]), type;
            if (geometry_ == "planar" && k >= 4)
            {
                name = k == 4 ? "front" : "back";
                type = "empty";
            }
            else
            {
                type = patchType(patchKinds_[name]);
            }
            const labelList& f = faces[k];
            os  << "    " << name << nl << "    {" << nl
                << "        type " << type << ";" << nl
                << "        faces ((" << f[0] << " " << f[1] << " " << f[2]
                << " " << f[3] << "));" << nl << "    }" << nl;
        }
        os  << ");" << nl;
    }
    IOobject::writeEndDivider(os);
}


void Foam::impactProblem::checkMesh(const fvMesh& mesh) const
{
    bool wedge = false;
    for (const polyPatch& pp : mesh.boundaryMesh())
    {
        wedge = wedge || isA<wedgePolyPatch>(pp);
    }
    const label nD = mesh.nGeometricD();
    const bool ok =
        geometry_ == "axisymmetric" ? wedge
      : geometry_ == "planar" ? (!wedge && nD == 2)
      : nD == 3;
    if (!ok)
    {
        FatalIOErrorInFunction(dict_)
            << "impactDict: geometry " << geometry_ << " does not fit the"
            << " mesh (" << nD << " geometric directions"
            << (wedge ? ", wedge patches" : ", no wedge patch") << "):"
            << " threeD needs a 3-D mesh, planar one cell in z between empty"
            << " patches, axisymmetric a wedge" << exit(FatalIOError);
    }
}


// ************************************************************************* //
