#!/usr/bin/python3
"""Unstructured meshes without gmsh: triangular-prism (2-D) and tetrahedral
(3-D) meshes written straight into constant/polyMesh.

Debian's OpenFOAM has no gmsh and blockMesh makes hexahedra only, so the
tests that need triangles or tets build them here (numpy only):

    import triMesh
    pts, cells = triMesh.triangle_prisms(32, 32, jitter=0.2, seed=1)
    triMesh.write_polymesh(case, pts, cells, triMesh.box_patches_2d)

or from the shell (the tutorials' Allrun):

    python3 triMesh.py triangles <case> [n] [jitter]
    python3 triMesh.py tets <case> [n] [jitter]

write_polymesh takes any cells given as lists of faces (lists of point
labels, in any orientation) and writes what OpenFOAM requires:
  - internal faces first, owner < neighbour, in upper-triangular order
    (sorted by owner, then neighbour);
  - every face oriented so that its right-handed normal points out of its
    owner (towards the neighbour; out of the domain on boundary faces);
  - boundary faces grouped by patch, patches in the order given.
Cells must be convex (the orientation test uses the cell centroid).
checkMesh reports "Mesh OK" on the meshes of this module.
"""
import os
import sys

import numpy as np

HEADER = """/*--------------------------------*- C++ -*----------------------------------*\\
  written by tests/lib/triMesh.py
\\*---------------------------------------------------------------------------*/
FoamFile
{
    version     2.0;
    format      ascii;
    class       %(cls)s;
%(note)s    location    "constant/polyMesh";
    object      %(obj)s;
}
// * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * //

"""


# --------------------------------------------------------------------------
# Generators
# --------------------------------------------------------------------------

def _jittered_grid(nx, ny, x0, x1, y0, y1, jitter, rng):
    """(nx+1) x (ny+1) grid points; interior points moved at random by up
    to jitter times the spacing (boundary points stay on the boundary)."""
    x = np.linspace(x0, x1, nx + 1)
    y = np.linspace(y0, y1, ny + 1)
    X, Y = np.meshgrid(x, y, indexing="ij")
    hx, hy = (x1 - x0) / nx, (y1 - y0) / ny
    if jitter > 0:
        dX = rng.uniform(-jitter, jitter, X.shape) * hx
        dY = rng.uniform(-jitter, jitter, Y.shape) * hy
        dX[0, :] = dX[-1, :] = 0
        dY[:, 0] = dY[:, -1] = 0
        # points on the left/right edges slide along y only, and
        # bottom/top along x only
        X = X + dX
        Y = Y + dY
    return X, Y


def triangle_prisms(nx, ny, x0=0.0, x1=1.0, y0=0.0, y1=1.0, dz=0.02,
                    jitter=0.2, seed=1):
    """Triangular prisms, one cell thick in z (0 to dz): an nx x ny grid of
    jittered quadrilaterals, each cut into two triangles along a diagonal
    whose direction alternates (no preferred direction). Returns
    (points (P, 3), cells: list of faces)."""
    rng = np.random.RandomState(seed)
    X, Y = _jittered_grid(nx, ny, x0, x1, y0, y1, jitter, rng)
    n2 = (nx + 1) * (ny + 1)
    pts2 = np.column_stack([X.ravel(), Y.ravel()])
    points = np.vstack([np.column_stack([pts2, np.zeros(n2)]),
                        np.column_stack([pts2, np.full(n2, dz)])])

    def pid(i, j):
        return i * (ny + 1) + j

    tris = []
    for i in range(nx):
        for j in range(ny):
            a, b = pid(i, j), pid(i + 1, j)
            c, d = pid(i + 1, j + 1), pid(i, j + 1)
            if (i + j) % 2 == 0:
                tris += [(a, b, c), (a, c, d)]
            else:
                tris += [(a, b, d), (b, c, d)]
    cells = []
    for (a, b, c) in tris:
        A, B, C = a + n2, b + n2, c + n2
        cells.append([(a, b, c), (A, B, C), (a, b, B, A), (b, c, C, B),
                      (c, a, A, C)])
    return points, cells


# The six tetrahedra of a cube along its main diagonal (Kuhn): for each
# permutation of the axes, the path 0 -> e_i -> e_i + e_j -> (1,1,1).
_KUHN = [(0, 1, 2), (0, 2, 1), (1, 0, 2), (1, 2, 0), (2, 0, 1), (2, 1, 0)]


def tetrahedra(nx, ny, nz, x0=0.0, x1=1.0, y0=0.0, y1=1.0, z0=0.0,
               z1=0.25, jitter=0.15, seed=1):
    """Tetrahedra: an nx x ny x nz grid of cubes, each cut into six tets
    along its main diagonal (a conforming mesh), interior points jittered
    by up to jitter times the spacing. Returns (points, cells)."""
    rng = np.random.RandomState(seed)
    xs = np.linspace(x0, x1, nx + 1)
    ys = np.linspace(y0, y1, ny + 1)
    zs = np.linspace(z0, z1, nz + 1)
    X, Y, Z = np.meshgrid(xs, ys, zs, indexing="ij")
    h = np.array([(x1 - x0) / nx, (y1 - y0) / ny, (z1 - z0) / nz])
    P = np.stack([X, Y, Z], axis=-1)
    if jitter > 0:
        d = rng.uniform(-jitter, jitter, P.shape) * h
        d[0, :, :, 0] = d[-1, :, :, 0] = 0
        d[:, 0, :, 1] = d[:, -1, :, 1] = 0
        d[:, :, 0, 2] = d[:, :, -1, 2] = 0
        P = P + d
    points = P.reshape(-1, 3)

    def pid(i, j, k):
        return (i * (ny + 1) + j) * (nz + 1) + k

    cells = []
    for i in range(nx):
        for j in range(ny):
            for k in range(nz):
                for perm in _KUHN:
                    idx = [i, j, k]
                    verts = [pid(*idx)]
                    for axis in perm:
                        idx[axis] += 1
                        verts.append(pid(*idx))
                    a, b, c, d = verts
                    cells.append([(a, b, c), (a, b, d), (a, c, d),
                                  (b, c, d)])
    return points, cells


# --------------------------------------------------------------------------
# Patch classifiers: (face centre, unit outward normal) -> patch name
# --------------------------------------------------------------------------

BOX_2D_PATCHES = [("sides", "patch"), ("frontAndBack", "empty")]
BOX_3D_PATCHES = [("sides", "patch")]


def box_patches_2d(centre, normal):
    """Faces normal to z are 'frontAndBack' (empty), the rest 'sides'."""
    return "frontAndBack" if abs(normal[2]) > 0.5 else "sides"


def box_patches_3d(centre, normal):
    return "sides"


# --------------------------------------------------------------------------
# Writer
# --------------------------------------------------------------------------

def _face_geometry(points, face):
    """Centre and area vector of a (planar or nearly planar) polygon: the
    triangle fan about the mean point, as OpenFOAM does."""
    p = points[list(face)]
    if len(face) == 3:
        return p.mean(axis=0), 0.5 * np.cross(p[1] - p[0], p[2] - p[0])
    m = p.mean(axis=0)
    q = np.roll(p, -1, axis=0)
    tri_s = 0.5 * np.cross(p - m, q - m)
    tri_c = (p + q + m) / 3.0
    mag = np.linalg.norm(tri_s, axis=1)
    S = tri_s.sum(axis=0)
    c = (tri_c * mag[:, None]).sum(axis=0) / mag.sum()
    return c, S


def _write(path, cls, obj, body, note=None):
    with open(path, "w") as f:
        f.write(HEADER % {"cls": cls, "obj": obj,
                          "note": ('    note        "%s";\n' % note
                                   if note else "")})
        f.write(body)
        f.write("\n// ****************************************"
                "********************************* //\n")


def _label_list(values):
    out = ["%d" % len(values), "("]
    out += ["%d" % v for v in values]
    out.append(")")
    return "\n".join(out) + "\n"


def write_polymesh(case, points, cells, classify, patches=None):
    """Write case/constant/polyMesh (points, faces, owner, neighbour,
    boundary) for cells given as lists of faces.

    classify(centre, outward unit normal) names the patch of a boundary
    face; patches is the list of (name, type) in the order to write (by
    default BOX_2D_PATCHES if 'frontAndBack' is used, else BOX_3D_PATCHES).
    Returns a dict with the mesh sizes."""
    points = np.asarray(points, dtype=float)
    centroids = np.array([points[sorted({v for f in c for v in f})]
                          .mean(axis=0) for c in cells])

    faces_of = {}
    for ci, cell in enumerate(cells):
        for face in cell:
            key = tuple(sorted(face))
            entry = faces_of.setdefault(key, [face, []])
            entry[1].append(ci)

    internal, boundary = [], {}
    for key, (face, owners) in faces_of.items():
        if len(owners) > 2:
            raise ValueError("face %s shared by %d cells" % (key, len(owners)))
        own = min(owners)
        centre, S = _face_geometry(points, face)
        if np.dot(S, centre - centroids[own]) < 0:
            face = tuple(reversed(face))
            S = -S
        if len(owners) == 2:
            internal.append((own, max(owners), face))
        else:
            name = classify(centre, S / np.linalg.norm(S))
            boundary.setdefault(name, []).append((own, face))

    if patches is None:
        patches = BOX_2D_PATCHES if "frontAndBack" in boundary \
            else BOX_3D_PATCHES
    unknown = set(boundary) - {n for n, _ in patches}
    if unknown:
        raise ValueError("faces classified into unknown patches %s"
                         % sorted(unknown))

    internal.sort(key=lambda t: (t[0], t[1]))
    faces, owner = [f for _, _, f in internal], [o for o, _, _ in internal]
    neighbour = [n for _, n, _ in internal]
    patch_ranges = []
    for name, ptype in patches:
        fl = sorted(boundary.get(name, []), key=lambda t: t[0])
        patch_ranges.append((name, ptype, len(faces), len(fl)))
        faces += [f for _, f in fl]
        owner += [o for o, _ in fl]

    poly = os.path.join(case, "constant", "polyMesh")
    os.makedirs(poly, exist_ok=True)
    for name in os.listdir(poly):
        os.remove(os.path.join(poly, name))

    body = ["%d" % len(points), "("]
    body += ["(%.17g %.17g %.17g)" % tuple(p) for p in points]
    body.append(")")
    _write(os.path.join(poly, "points"), "vectorField", "points",
           "\n".join(body) + "\n")

    body = ["%d" % len(faces), "("]
    body += ["%d(%s)" % (len(f), " ".join("%d" % v for v in f))
             for f in faces]
    body.append(")")
    _write(os.path.join(poly, "faces"), "faceList", "faces",
           "\n".join(body) + "\n")

    note = "nPoints:%d  nCells:%d  nFaces:%d  nInternalFaces:%d" \
        % (len(points), len(cells), len(faces), len(internal))
    _write(os.path.join(poly, "owner"), "labelList", "owner",
           _label_list(owner), note)
    _write(os.path.join(poly, "neighbour"), "labelList", "neighbour",
           _label_list(neighbour), note)

    body = ["%d" % len(patch_ranges), "("]
    for name, ptype, start, n in patch_ranges:
        body += ["    %s" % name, "    {",
                 "        type            %s;" % ptype]
        if ptype == "empty":
            body.append("        inGroups        List<word> 1(empty);")
        body += ["        nFaces          %d;" % n,
                 "        startFace       %d;" % start, "    }"]
    body.append(")")
    _write(os.path.join(poly, "boundary"), "polyBoundaryMesh", "boundary",
           "\n".join(body) + "\n")
    return {"points": len(points), "cells": len(cells), "faces": len(faces),
            "internalFaces": len(internal)}


# --------------------------------------------------------------------------
# Command line (for the tutorials' Allrun scripts)
# --------------------------------------------------------------------------

def main(argv):
    usage = ("usage: triMesh.py triangles <case> [n] [jitter]\n"
             "       triMesh.py tets <case> [n] [jitter]\n")
    if len(argv) < 2 or argv[0] not in ("triangles", "tets"):
        sys.stderr.write(usage)
        return 1
    kind, case = argv[0], argv[1]
    if kind == "triangles":
        n = int(argv[2]) if len(argv) > 2 else 32
        jitter = float(argv[3]) if len(argv) > 3 else 0.2
        pts, cells = triangle_prisms(n, n, jitter=jitter)
        info = write_polymesh(case, pts, cells, box_patches_2d)
    else:
        n = int(argv[2]) if len(argv) > 2 else 8
        jitter = float(argv[3]) if len(argv) > 3 else 0.15
        pts, cells = tetrahedra(n, n, n, z1=1.0, jitter=jitter)
        info = write_polymesh(case, pts, cells, box_patches_3d)
    print("triMesh: %s mesh with %d cells, %d faces (%d internal), "
          "%d points" % (kind, info["cells"], info["faces"],
                         info["internalFaces"], info["points"]))
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
