#!/usr/bin/python3
"""Write 0/U of the closedBox tutorial: random velocities from a fixed seed.

  - Air: an independent random velocity in every cell, magnitude uniform in
    [50, 200] m/s, direction uniform on the sphere.
  - Each solid body (the cells where a solid phase is the main phase,
    after setFields): one random rigid velocity (magnitude 50-200 m/s,
    random direction, the x components chosen so that the copper disc and
    the aluminium block, which touch, collide) plus an independent random
    perturbation in every cell of up to 2 m/s. (Larger cell-to-cell jumps
    in the solids, 10 m/s and more, put them in a tension that stops
    impactFoam within 50 steps: the trace of air in the solid grows and
    cavitates.)

Every velocity has a z component: the 2-D box has no wall normal to z, so
the z-momentum is conserved exactly. Standard library only.

Usage: randomVelocity.py [case] [seed]     (defaults: . and 1)
"""
import math
import os
import random
import re
import sys

U_MIN, U_MAX = 50.0, 200.0
SOLID_JITTER = 2.0
SOLIDS = ("copper", "aluminium")


def read_scalar_list(path, n):
    """Internal field of an ascii volScalarField (uniform or nonuniform)."""
    with open(path) as f:
        text = f.read()
    m = re.search(r"^internalField\s+uniform\s+([^;\s]+)\s*;", text, re.M)
    if m:
        return [float(m.group(1))] * n
    m = re.search(r"^internalField\s+nonuniform\s+List<scalar>\s*(\d+)\s*"
                  r"\(([^)]*)\)", text, re.M)
    if not m or int(m.group(1)) != n:
        raise SystemExit("randomVelocity.py: cannot read %s" % path)
    return [float(v) for v in m.group(2).split()]


def n_cells(case):
    """Number of cells, from the note of constant/polyMesh/owner."""
    with open(os.path.join(case, "constant", "polyMesh", "owner")) as f:
        head = f.read(4000)
    m = re.search(r"nCells\s*:\s*(\d+)", head)
    if not m:
        raise SystemExit("randomVelocity.py: no nCells in "
                         "constant/polyMesh/owner (run blockMesh first)")
    return int(m.group(1))


def random_direction(rng):
    cos_t = rng.uniform(-1.0, 1.0)
    sin_t = math.sqrt(1.0 - cos_t * cos_t)
    phi = rng.uniform(0.0, 2.0 * math.pi)
    return (sin_t * math.cos(phi), sin_t * math.sin(phi), cos_t)


def random_velocity(rng, lo, hi):
    mag = rng.uniform(lo, hi)
    return tuple(mag * c for c in random_direction(rng))


def velocities(case, seed):
    n = n_cells(case)
    rng = random.Random(seed)
    alpha = {s: read_scalar_list(os.path.join(case, "0", "alpha." + s), n)
             for s in SOLIDS}
    body = {s: random_velocity(rng, U_MIN, U_MAX) for s in SOLIDS}
    # the copper disc (left) and the aluminium block (right) touch: make
    # them approach each other along x, so that they collide
    body["copper"] = (abs(body["copper"][0]),) + body["copper"][1:]
    body["aluminium"] = (-abs(body["aluminium"][0]),) + body["aluminium"][1:]
    out = []
    for i in range(n):
        solid = [s for s in SOLIDS if alpha[s][i] > 0.5]
        if solid:
            jitter = random_velocity(rng, 0.0, SOLID_JITTER)
            out.append(tuple(b + j for b, j in zip(body[solid[0]], jitter)))
        else:
            out.append(random_velocity(rng, U_MIN, U_MAX))
    return out, body


def main(argv):
    case = argv[0] if argv else "."
    seed = int(argv[1]) if len(argv) > 1 else 1
    path = os.path.join(case, "0", "U")
    with open(path) as f:
        text = f.read()
    U, body = velocities(case, seed)
    values = "\n".join("(%.17g %.17g %.17g)" % u for u in U)
    field = "internalField   nonuniform List<vector>\n%d\n(\n%s\n)\n;" \
        % (len(U), values)
    new, count = re.subn(r"^internalField\s[^;]*;", lambda m: field, text,
                         count=1, flags=re.M)
    if count != 1:
        raise SystemExit("randomVelocity.py: no internalField in %s" % path)
    with open(path, "w") as f:
        f.write(new)
    print("randomVelocity.py: %d random velocities (seed %d) written to %s"
          % (len(U), seed, path))
    for s in SOLIDS:
        print("    %s moves at (%.6g %.6g %.6g) m/s +- %g m/s"
              % ((s,) + body[s] + (SOLID_JITTER,)))


if __name__ == "__main__":
    main(sys.argv[1:])
