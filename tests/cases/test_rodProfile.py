#!/usr/bin/python3
"""rodProfile's radius at the impact face (faceRadius) against a body of
known outline (docs/validation.md W1, "the radius at the impact face").

A Lagrangian code reads a Taylor bar's mushroom radius at the nodes of the
impact face (z = 0). The first cell row of an Eulerian mesh reads the
outline at its centres, z = h/2; where the outline slopes, dr/dz = -s,
that reading (maxRadius) is s h/2 short of the face's radius. faceRadius
extends the outline of the first two rows linearly to the face.

Case: the taylorBar tutorial's mesh at 0.4 mm (wedge, the wall at x = 0),
no solver run: the copper volume fraction is written at t = 0 as a
diffuse body of revolution, alpha = 1/2 (1 - tanh((r - R(z))/w)) times
1/2 (1 - tanh((z - L)/w)), w = 1.5 h, L = 20 mm, so that alpha falls
through 1/2 at r = R(z) in every row (rodProfile reads the crossing
linearly between cell centres: up to 0.014 h off for this profile).

Checks
  rodProfile_faceRadius_cone   a foot with R(z) = 7 mm - 0.5 z (down to
                               the bar's 3.2 mm): faceRadius within 0.05 h
                               of 7 mm; maxRadius within 0.05 h of
                               R(h/2) = 7 mm - 0.1 mm, i.e. short of the
                               face by s h/2 = 0.25 h (what the
                               extension removes)
  rodProfile_faceRadius_cylinder  a straight bar, R = 3.2 mm: faceRadius
                               equals maxRadius (no slope, no extension)
"""
import os
import sys

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "lib"))
import foamcase as fc                         # noqa: E402
import fieldWriter as fw                      # noqa: E402
import meshGeometry as mg                     # noqa: E402
from checks import Checks                     # noqa: E402

checks = Checks()

H = 0.4e-3          # the tutorial's default cell size (m)
W = 1.5 * H         # interface width of the written alpha
LENGTH = 20e-3      # the body's length
R_FACE = 7e-3       # radius at the face of the cone-shaped foot
SLOPE = 0.5         # -dR/dz of the foot
R_BAR = 3.2e-3
TOL = 0.05 * H


def measure(case, m, outline):
    """Write alpha of the body whose radius is outline(z) and read
    rodProfile's row at t = 0."""
    z = m.C[:, 0]
    r = np.hypot(m.C[:, 1], m.C[:, 2])
    alpha = 0.25 * (1 - np.tanh((r - outline(z)) / W)) \
        * (1 - np.tanh((z - LENGTH) / W))
    fw.write_field(case, "0", "alpha.copper", alpha, m)
    fw.write_field(case, "0", "alpha.air", 1 - alpha, m)
    fc.run(case, ["rodProfile", "-phase", "copper", "-R0", str(R_BAR),
                  "-withZero"])
    tab = np.genfromtxt(os.path.join(case, "postProcessing", "rodProfile",
                                     "copper.csv"), delimiter=",",
                        names=True)
    return float(np.atleast_1d(tab["maxRadius"])[0]), \
        float(np.atleast_1d(tab["faceRadius"])[0])


def main():
    missing = fc.require_apps("impactSetup", "rodProfile")
    if missing:
        checks.fail("rodProfile_faceRadius_cone", "missing " + str(missing))
        checks.exit()
    case = fc.copy_tutorial("taylorBar", "rodProfile_faceRadius")
    fc.set_entry(case, "system/controlDict", "writeFormat", "ascii")
    fc.run(case, ["impactSetup"])
    m = mg.read_polymesh(case)
    h = m.C[:, 0].min() * 2
    if abs(h - H) > 1e-9:
        checks.fail("rodProfile_faceRadius_cone",
                    "the tutorial's first row is at %g m, not h/2 = %g m"
                    % (h / 2, H / 2))
        checks.exit()

    maxR, faceR = measure(
        case, m, lambda z: np.maximum(R_FACE - SLOPE * z, R_BAR))
    atCentre = R_FACE - SLOPE * H / 2
    checks.check(
        "rodProfile_faceRadius_cone",
        abs(faceR - R_FACE) <= TOL and abs(maxR - atCentre) <= TOL,
        "foot R = %.1f mm - %.1f z: faceRadius %.5f mm (%+.4f h from the "
        "face's %.1f mm), maxRadius %.5f mm (%+.4f h from R(h/2) = %.2f "
        "mm, %+.4f h from the face); bound 0.05 h"
        % (R_FACE * 1e3, SLOPE, faceR * 1e3, (faceR - R_FACE) / H,
           R_FACE * 1e3, maxR * 1e3, (maxR - atCentre) / H, atCentre * 1e3,
           (maxR - R_FACE) / H))

    maxR, faceR = measure(case, m, lambda z: np.full_like(z, R_BAR))
    checks.check(
        "rodProfile_faceRadius_cylinder",
        abs(faceR - maxR) <= 1e-12 and abs(faceR - R_BAR) <= TOL,
        "straight bar of %.1f mm: faceRadius %.6f mm, maxRadius %.6f mm "
        "(equal to 1e-12 m; within 0.05 h of the radius)"
        % (R_BAR * 1e3, faceR * 1e3, maxR * 1e3))
    checks.exit()


if __name__ == "__main__":
    main()
