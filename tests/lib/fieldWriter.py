#!/usr/bin/python3
"""Write ascii OpenFOAM vol fields with nonuniform internal and patch
values straight from numpy (no setFields/setExprFields run, full double
precision), and the linear velocity fields u = u0 + L0 (x - origin) of the
rigid-rotation and expanding-ring tests.

    import fieldWriter as fw
    import meshGeometry as mg
    m = mg.read_polymesh(case)
    fw.write_field(case, "0", "p", np.full(m.nCells, 1e5), m,
                   default_patch={"type": "zeroGradient"})
    fw.write_linear_velocity(case, m, L0, origin=(0, 0, 0))

From the shell (the tutorials' Allrun):

    python3 fieldWriter.py rotation <case> <omega> [x0 y0 z0]
        U = omega e_z x (x - origin) in 0/U: nonuniform internal field at
        the cell centres and fixedValue at the face centres of every patch
        that is not a constraint patch (empty, wedge, symmetry...)
    python3 fieldWriter.py linear <case> '(xx xy xz yx yy yz zx zy zz)'
        U = L0 x, the same way

Cell and face centres come from tests/lib/meshGeometry.py, which computes
them as OpenFOAM does, so a linear field written here is linear at the
points where the solver evaluates it.
"""
import os
import sys

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
if HERE not in sys.path:
    sys.path.insert(0, HERE)
import meshGeometry as mg        # noqa: E402

# patch types whose field type must equal the patch type
CONSTRAINT_TYPES = ("empty", "wedge", "symmetryPlane", "symmetry",
                    "cyclic", "cyclicAMI", "processor")

_CLASS = {1: "volScalarField", 3: "volVectorField", 9: "volTensorField",
          6: "volSymmTensorField"}
_LIST = {1: "scalar", 3: "vector", 9: "tensor", 6: "symmTensor"}

DIMENSIONS = {
    "U": "[0 1 -1 0 0 0 0]",
    "p": "[1 -1 -2 0 0 0 0]",
    "rho": "[1 -3 0 0 0 0 0]",
    "alpha": "[0 0 0 0 0 0 0]",
    "A": "[0 0 0 0 0 0 0]",
}

HEADER = """/*--------------------------------*- C++ -*----------------------------------*\\
  written by tests/lib/fieldWriter.py
\\*---------------------------------------------------------------------------*/
FoamFile
{
    version     2.0;
    format      ascii;
    class       %s;
    location    "%s";
    object      %s;
}
// * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * //

"""


def _fmt(v):
    v = np.atleast_1d(np.asarray(v, dtype=float))
    if v.size == 1:
        return "%.17g" % v[0]
    return "(" + " ".join("%.17g" % x for x in v) + ")"


def _values(vals, ncomp, label):
    """'uniform x' or 'nonuniform List<type> N(...)' for an entry."""
    vals = np.asarray(vals, dtype=float)
    if vals.ndim == (0 if ncomp == 1 else 1):
        return "uniform %s" % _fmt(vals)
    vals = vals.reshape(len(vals), -1) if ncomp > 1 else vals.ravel()
    lines = ["nonuniform List<%s> %d" % (_LIST[ncomp], len(vals)), "("]
    lines += [_fmt(v) for v in vals]
    lines.append(")")
    return "\n".join(lines)


def dimensions_of(name):
    base = name.split(".")[0]
    return DIMENSIONS.get(base, "[0 0 0 0 0 0 0]")


def write_field(case, time, name, values, mesh, boundary=None,
                default_patch=None, dimensions=None):
    """Write <case>/<time>/<name>.

    values: (N,) scalars, (N, 3) vectors or (N, 9) tensors (xx xy .. zz),
    or one value (uniform). boundary: {patch: {"type": t, "value": v}}
    with v one value or one per face (optional for types that need none).
    Patches not in boundary get their constraint type (empty, wedge, ...)
    or default_patch (default zeroGradient)."""
    values = np.asarray(values, dtype=float)
    if values.ndim == 0:
        ncomp = 1
    elif values.ndim == 1 and len(values) in (3, 6, 9) \
            and len(values) != mesh.nCells:
        ncomp = len(values)
    elif values.ndim == 1:
        ncomp = 1
    else:
        ncomp = values.shape[1]
    boundary = boundary or {}
    default_patch = default_patch or {"type": "zeroGradient"}
    out = [HEADER % (_CLASS[ncomp], time, name)]
    out.append("dimensions      %s;\n\n" % (dimensions or
                                            dimensions_of(name)))
    out.append("internalField   %s;\n\n" % _values(values, ncomp, name))
    out.append("boundaryField\n{\n")
    for pname, ptype, start, n in mesh.patches:
        if pname in boundary:
            spec = boundary[pname]
        elif ptype in CONSTRAINT_TYPES:
            spec = {"type": ptype}
        else:
            spec = default_patch
        out.append("    %s\n    {\n        type            %s;\n"
                   % (pname, spec["type"]))
        if spec.get("value") is not None:
            out.append("        value           %s;\n"
                       % _values(spec["value"], ncomp, name))
        out.append("    }\n")
    out.append("}\n\n// ****************************************"
               "********************************* //\n")
    os.makedirs(os.path.join(case, time), exist_ok=True)
    with open(os.path.join(case, time, name), "w") as f:
        f.write("".join(out))


def linear_velocity(points, L0, u0=(0.0, 0.0, 0.0), origin=(0.0, 0.0, 0.0)):
    """u = u0 + L0 (x - origin) at the given points (P, 3)."""
    L0 = np.asarray(L0, dtype=float).reshape(3, 3)
    return np.asarray(u0, dtype=float) + \
        (np.asarray(points) - np.asarray(origin, dtype=float)) @ L0.T


def rotation_tensor(omega, axis=(0.0, 0.0, 1.0)):
    """L of the rigid rotation u = omega axis x r: L = omega [axis]_x."""
    a = np.asarray(axis, dtype=float)
    a = a / np.linalg.norm(a)
    return omega * np.array([[0.0, -a[2], a[1]],
                             [a[2], 0.0, -a[0]],
                             [-a[1], a[0], 0.0]])


def write_linear_velocity(case, mesh, L0, u0=(0.0, 0.0, 0.0),
                          origin=(0.0, 0.0, 0.0), time="0",
                          patch_type="fixedValue"):
    """0/U = u0 + L0 (x - origin): internal field at the cell centres;
    fixedValue (or patch_type with a value) at the face centres of every
    non-constraint patch, so the ghost states of the solver are exact."""
    boundary = {}
    for pname, ptype, start, n in mesh.patches:
        if ptype in CONSTRAINT_TYPES:
            continue
        boundary[pname] = {
            "type": patch_type,
            "value": linear_velocity(mesh.Cf[start:start + n], L0, u0,
                                     origin)}
    write_field(case, time, "U", linear_velocity(mesh.C, L0, u0, origin),
                mesh, boundary)


def main(argv):
    usage = ("usage: fieldWriter.py rotation <case> <omega> [x0 y0 z0]\n"
             "       fieldWriter.py linear <case> "
             "'(xx xy xz yx yy yz zx zy zz)'\n")
    if len(argv) < 3 or argv[0] not in ("rotation", "linear"):
        sys.stderr.write(usage)
        return 1
    case = argv[1]
    mesh = mg.read_polymesh(case)
    origin = (0.0, 0.0, 0.0)
    if argv[0] == "rotation":
        L0 = rotation_tensor(float(argv[2]))
        if len(argv) >= 6:
            origin = tuple(float(x) for x in argv[3:6])
    else:
        L0 = np.array(argv[2].replace("(", " ").replace(")", " ").split(),
                      dtype=float).reshape(3, 3)
    write_linear_velocity(case, mesh, L0, origin=origin)
    print("fieldWriter: wrote %s/0/U = L0 (x - origin) on %d cells, "
          "L0 = %s" % (case, mesh.nCells, " ".join("%g" % x
                                                 for x in L0.ravel())))
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
