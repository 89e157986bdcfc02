"""Geometry of an ascii constant/polyMesh, computed with numpy the way
OpenFOAM does it (face centres and area vectors from a triangle fan about
the face's mean point, cell volumes and centres from pyramids on the faces
about the mean of the face centres), so that no postProcess run is needed.

    import meshGeometry as mg
    m = mg.read_polymesh(case)
    m.V, m.C             # (nCells,), (nCells, 3)
    m.Sf, m.Cf           # (nFaces, 3) area vectors and face centres
    m.patches            # [(name, type, start, nFaces)]
    mg.stable_step(m, speed)   # min over cells of 2 V / sum_f |S_f| speed
"""
import math
import os
import re

import numpy as np

import foamcase as fc


def _body(path):
    text = fc.strip_comments(fc._read_text(path))
    if "FoamFile" in text:
        text = text[text.find("}", text.find("FoamFile")) + 1:]
    return text


def _read_points(path):
    text = _body(path)
    start = text.find("(")
    nums = re.sub(r"[()]", " ", text[start:text.rfind(")") + 1]).split()
    return np.array(nums, dtype=float).reshape(-1, 3)


def _read_labels(path):
    text = _body(path)
    start = text.find("(")
    if start < 0:  # compact "N{value}" or empty
        m = re.search(r"(\d+)\s*\{\s*(-?\d+)\s*\}", text)
        return np.full(int(m.group(1)), int(m.group(2)), dtype=int) \
            if m else np.zeros(0, dtype=int)
    return np.array(text[start + 1:text.rfind(")")].split(), dtype=int)


def _read_faces(path):
    text = _body(path)
    text = text[text.find("(") + 1:text.rfind(")")]
    return [np.array(m.group(2).split(), dtype=int)
            for m in re.finditer(r"(\d+)\s*\(([^)]*)\)", text)]


def _read_boundary(path):
    text = _body(path)
    out = []
    for m in re.finditer(r"(\w+)\s*\{([^}]*)\}", text):
        entries = dict(re.findall(r"(\w+)\s+([^;]*);", m.group(2)))
        out.append((m.group(1), entries.get("type", "patch"),
                    int(entries["startFace"]), int(entries["nFaces"])))
    return out


class PolyMesh(object):
    pass


def read_polymesh(case, region=""):
    """Read case/constant[/region]/polyMesh and compute its geometry."""
    poly = os.path.join(case, "constant", region, "polyMesh")
    m = PolyMesh()
    m.points = _read_points(os.path.join(poly, "points"))
    m.faces = _read_faces(os.path.join(poly, "faces"))
    m.owner = _read_labels(os.path.join(poly, "owner"))
    m.neighbour = _read_labels(os.path.join(poly, "neighbour"))
    m.patches = _read_boundary(os.path.join(poly, "boundary"))
    m.nFaces = len(m.faces)
    m.nInternalFaces = len(m.neighbour)
    m.nCells = int(m.owner.max()) + 1

    # faces: triangle fan about the mean point
    Cf = np.zeros((m.nFaces, 3))
    Sf = np.zeros((m.nFaces, 3))
    for n in sorted({len(f) for f in m.faces}):
        idx = np.array([i for i, f in enumerate(m.faces) if len(f) == n])
        verts = np.array([m.faces[i] for i in idx])
        p = m.points[verts]                       # (F, n, 3)
        if n == 3:
            Cf[idx] = p.mean(axis=1)
            Sf[idx] = 0.5 * np.cross(p[:, 1] - p[:, 0], p[:, 2] - p[:, 0])
            continue
        mid = p.mean(axis=1)[:, None, :]
        q = np.roll(p, -1, axis=1)
        s = 0.5 * np.cross(p - mid, q - mid)      # (F, n, 3)
        c = (p + q + mid) / 3.0
        S = s.sum(axis=1)
        nhat = S / np.linalg.norm(S, axis=1)[:, None]
        a = np.einsum("fij,fj->fi", s, nhat)
        Cf[idx] = (c * a[:, :, None]).sum(axis=1) / a.sum(axis=1)[:, None]
        Sf[idx] = S
    m.Cf, m.Sf = Cf, Sf
    m.magSf = np.linalg.norm(Sf, axis=1)

    # cells: pyramids about the mean of the face centres
    own, nei, ni = m.owner, m.neighbour, m.nInternalFaces
    count = np.bincount(own, minlength=m.nCells) + \
        np.bincount(nei, minlength=m.nCells)
    cEst = np.zeros((m.nCells, 3))
    np.add.at(cEst, own, Cf)
    np.add.at(cEst, nei, Cf[:ni])
    cEst /= count[:, None]
    V = np.zeros(m.nCells)
    VC = np.zeros((m.nCells, 3))
    pv = np.einsum("ij,ij->i", Sf, Cf - cEst[own])
    np.add.at(V, own, pv)
    np.add.at(VC, own, pv[:, None] * (0.75 * Cf + 0.25 * cEst[own]))
    pv = np.einsum("ij,ij->i", Sf[:ni], cEst[nei] - Cf[:ni])
    np.add.at(V, nei, pv)
    np.add.at(VC, nei, pv[:, None] * (0.75 * Cf[:ni] + 0.25 * cEst[nei]))
    m.C = VC / V[:, None]
    m.V = V / 3.0
    return m


def stable_step(m, speed):
    """min over cells of 2 V / sum_f |S_f| speed over the faces that are
    not on empty patches (docs/numerics.md section 6, without maxCo), for one
    bound 'speed' >= |u.n| + a valid in every cell."""
    ni = m.nInternalFaces
    lam = m.magSf * speed
    total = np.zeros(m.nCells)
    np.add.at(total, m.owner[:ni], lam[:ni])
    np.add.at(total, m.neighbour, lam[:ni])
    for name, ptype, start, n in m.patches:
        if ptype == "empty" or n == 0:
            continue
        np.add.at(total, m.owner[start:start + n], lam[start:start + n])
    return float(np.min(2 * m.V / total))


def wedge_to_full(m):
    """2 pi over the sine of the wedge angle theta, from the two wedge
    patches' normals: a flat-faced wedge cell of angle theta holds
    sin(theta)/(2 pi) of its ring (numerics.md 10.3)"""
    normals = [m.Sf[start] / np.linalg.norm(m.Sf[start])
               for name, kind, start, size in m.patches if kind == "wedge"]
    angle = math.acos(min(1.0, max(-1.0, -float(np.dot(*normals)))))
    return 2 * math.pi / math.sin(angle)


def patch_values(path, patch):
    """The value list of patch in a volScalarField file"""
    with open(path) as f:
        text = f.read()
    i = text.index(patch, text.index("boundaryField"))
    m = re.search(r"value\s+(uniform\s+(\S+);|nonuniform\s+List<scalar>"
                  r"\s*(\d+)\s*\(([^)]*)\))", text[i:])
    if m.group(2) is not None:
        return np.array([float(m.group(2))])
    return np.array(m.group(4).split(), dtype=float)


def processor_patch_difference(case, time, field):
    """The largest difference between a decomposed case's written field on
    processor0's patch to processor1 and processor1's cells beside it (the
    faces of the two processor patches are in the same order), and the
    largest of those cells' values"""
    p0 = os.path.join(case, "processor0")
    p1 = os.path.join(case, "processor1")
    m1 = read_polymesh(p1)
    start, size = next((s, n) for name, kind, s, n in m1.patches
                       if name == "procBoundary1to0")
    inner = fc.read_field(p1, time, field)[m1.owner[start:start + size]]
    values = patch_values(os.path.join(p0, time, field), "procBoundary0to1")
    if values.size not in (1, inner.size):
        return float("inf"), float(np.abs(inner).max())
    return float(np.abs(values - inner).max()), float(np.abs(inner).max())
