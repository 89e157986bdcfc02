#!/usr/bin/python3
"""The plate's crater and the rod's motion in the obliqueRodImpact3D
tutorial, at every write time.

Reads alpha.steel, alpha.copper, rho.copper and U of each time directory
(ascii, reconstructed) on the single block of system/blockMeshDict: x in
[-8, 14] mm, y in [0, 8] mm (the symmetry plane y = 0), z in [-12, 12] mm,
nx x ny x nz cells from system/meshSize, x fastest. A refined mesh (./Allrun
-refine: cells of the block split into eight, 2^refine times at most) is
read with each time's cell centres and volumes (C and V, which Allrun
writes with postProcess) and sampled on the finest cells: each cell's
values fill the finest cells it covers, so that the measures below are
those of a uniform mesh of the finest cells holding the same values. The
plate's top face is x = 0. At each time it measures:
  depth   the crater's depth below x = 0: in every column of cells along x,
          scanning down from x = 0 to where alpha.steel rises through 1/2
          (linear between cell centres); the deepest column;
  copper  the rod's mass (for the half domain), its centre of mass and mean
          velocity (mass-weighted), split into the component along the
          plate's normal (x) and along the plate (z).
Writes penetration.dat and penetration.png, and prints the total energy
the solver logged at the first and the last write.
"""
import os
import re
import sys

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
LO = np.array([-8.0, 0.0, -12.0])       # mm
HI = np.array([14.0, 8.0, 12.0])


def entry(path, key):
    m = re.search(r"^%s\s+([^;]+);" % key, open(path).read(), re.M)
    return float(m.group(1))


def field(path, n, width=1):
    """internalField of an ascii volScalarField (width 1) or volVectorField
    (width 3) with n cells, uniform or not."""
    text = open(path).read()
    kind = "scalar" if width == 1 else "vector"
    m = re.search(r"internalField\s+nonuniform\s+List<%s>\s*(\d+)\s*\(" % kind,
                  text)
    if n is None:
        n = int(m.group(1))
    if m is None:
        v = re.search(r"internalField\s+uniform\s+([^;]+);", text).group(1)
        values = np.array(v.strip("() ").split(), float)
        return np.tile(values, (n, 1)).reshape(n, width).squeeze()
    body = text[m.end():]
    if width == 1:
        return np.array(body.split(")")[0].split(), float)
    values = re.findall(r"\(([^()]*)\)", body[:body.index("\n)")])
    return np.array([v.split() for v in values[:n]], float)


def refine_levels():
    """Allrun's -refine (0: the block's cells)"""
    path = os.path.join(HERE, "constant", "refinementProperties")
    return int(entry(path, "maxRefinement")) if os.path.exists(path) else 0


def sample(d, names, n, h):
    """The fields names (name, width) of time directory d on a refined mesh
    (its C and V) as arrays on the finest uniform grid n (cells of size h,
    x fastest): each cell fills the finest cells it covers"""
    V = field(os.path.join(d, "V"), None)
    count = len(V)
    C = field(os.path.join(d, "C"), count, 3) * 1e3          # mm
    side = np.cbrt(V) * 1e3
    k = np.rint(side / h[0]).astype(int)                     # cells per side
    start = np.rint((C - 0.5 * side[:, None] - LO) / h).astype(int)
    out = {}
    values = {name: field(os.path.join(d, name), count, width)
              for name, width in names}
    for name, width in names:
        out[name] = np.zeros((n[2], n[1], n[0]) + ((width,) if width > 1
                                                   else ()))
    for size in np.unique(k):
        cells = np.nonzero(k == size)[0]
        for di in range(size):
            for dj in range(size):
                for dk in range(size):
                    ix = start[cells, 0] + di
                    iy = start[cells, 1] + dj
                    iz = start[cells, 2] + dk
                    for name, _ in names:
                        out[name][iz, iy, ix] = values[name][cells]
    return out


def crater_depth(steel, x):
    """Deepest crossing of alpha.steel through 1/2 below x = 0, over the
    columns steel[..., i] (i along x); 0 where the steel is intact."""
    below = np.where(x < 0)[0][::-1]       # from the face downwards
    column = steel[:, :, below]            # (nz, ny, n below)
    depth = 0.0
    for a in column.reshape(-1, len(below)):
        if a[0] >= 0.5:
            continue
        above = np.nonzero(a >= 0.5)[0]
        if len(above) == 0:
            return -x[below[-1]]           # through the plate
        i = above[0]
        f = (0.5 - a[i - 1]) / (a[i] - a[i - 1])
        xc = x[below[i - 1]] + f * (x[below[i]] - x[below[i - 1]])
        depth = max(depth, -xc)
    return depth


def main():
    size = os.path.join(HERE, "system", "meshSize")
    levels = refine_levels()
    n = np.array([int(entry(size, k)) for k in ("nx", "ny", "nz")]) \
        * 2 ** levels
    h = (HI - LO) / n
    centres = [LO[d] + (np.arange(n[d]) + 0.5) * h[d] for d in range(3)]
    x = centres[0]
    nCells = int(np.prod(n))
    vol = np.prod(h) * 1e-9                # m^3
    X, Y, Z = np.meshgrid(*centres, indexing="ij")
    # OpenFOAM's blockMesh order: x fastest, then y, then z
    pos = np.stack([a.transpose(2, 1, 0).ravel() for a in (X, Y, Z)], axis=1)

    times = sorted((d for d in os.listdir(HERE)
                    if re.match(r"^[0-9.eE+-]+$", d) and float(d) > 0),
                   key=float)
    rows = []
    for t in times:
        d = os.path.join(HERE, t)
        if not os.path.exists(os.path.join(d, "alpha.steel")):
            continue
        if levels:
            f = sample(d, [("alpha.steel", 1), ("alpha.copper", 1),
                           ("rho.copper", 1), ("U", 3)], n, h)
            steel = f["alpha.steel"].ravel()
            mass = f["alpha.copper"].ravel() * f["rho.copper"].ravel() * vol
            U = f["U"].reshape(-1, 3)
        else:
            steel = field(os.path.join(d, "alpha.steel"), nCells)
            mass = (field(os.path.join(d, "alpha.copper"), nCells)
                    * field(os.path.join(d, "rho.copper"), nCells) * vol)
            U = field(os.path.join(d, "U"), nCells, 3)
        m = mass.sum()
        centre = (mass[:, None] * pos).sum(axis=0) / m
        u = (mass[:, None] * U).sum(axis=0) / m
        depth = crater_depth(steel.reshape(n[2], n[1], n[0]), x)
        rows.append((float(t), depth, m, centre[0], centre[2], u[0], u[2]))
    if not rows:
        print("no written times with fields found in %s" % HERE,
              file=sys.stderr)
        return 1
    rows = np.array(rows)
    np.savetxt(os.path.join(HERE, "penetration.dat"), rows, fmt="%.6g",
               header="t [s], crater depth [mm], copper mass (half) [kg], "
               "copper centre x, z [mm], copper velocity u_x, u_z [m/s]")
    for t, depth, m, cx, cz, ux, uz in rows:
        print("t = %8.3g s: crater depth %6.3f mm; copper centre (%6.2f, "
              "%6.2f) mm, velocity normal %7.1f, along %7.1f m/s"
              % (t, depth, cx, cz, ux, uz))

    log = os.path.join(HERE, "log.impactFoam")
    if os.path.exists(log):
        text = open(log).read()
        e0 = re.search(r"Initial totals: mass \S+ kg, energy (\S+) J", text)
        last = re.findall(r"totals: mass \S+ kg, energy (\S+) J, energy "
                          r"added without a payer (\S+) J", text)
        if e0 and last:
            E0, E1, added = float(e0.group(1)), float(last[-1][0]), \
                float(last[-1][1])
            print("total energy (half domain) %.10g J -> %.10g J: drift "
                  "%.2e, of which %.3g J added without a payer (vacuum "
                  "floor, trace resets)" % (E0, E1, E1 / E0 - 1, added))

    try:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
    except ImportError:
        print("no matplotlib: penetration.png not written", file=sys.stderr)
        return 0
    fig, (a1, a2) = plt.subplots(1, 2, figsize=(10, 4))
    t_us = 1e6 * rows[:, 0]
    a1.plot(t_us, rows[:, 1], "o-")
    a1.set_xlabel("t [us]")
    a1.set_ylabel("crater depth [mm]")
    a1.grid(True, alpha=0.3)
    a2.plot(t_us, rows[:, 5], "o-", label="normal (x)")
    a2.plot(t_us, rows[:, 6], "s-", label="along the plate (z)")
    a2.set_xlabel("t [us]")
    a2.set_ylabel("copper mean velocity [m/s]")
    a2.grid(True, alpha=0.3)
    a2.legend()
    fig.suptitle("Copper rod on a steel plate, oblique")
    fig.tight_layout()
    fig.savefig(os.path.join(HERE, "penetration.png"), dpi=120)
    return 0


if __name__ == "__main__":
    sys.exit(main())
