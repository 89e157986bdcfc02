#!/usr/bin/python3
"""Coarse setting of tutorials/impactFoam/copperRodImpact3D: the
3-D rod-on-rod impact on a snappyHexMesh mesh refined about the rods' STL
surfaces, a quarter of the domain (symmetry planes y = 0, z = 0).

Runs the tutorial's Allrun (blockMesh, snappyHexMesh, checkMesh, setFields
from the STL surfaces, impactFoam) to 4 us with fields every 1 us, then
writeCellVolumes/writeCellCentres.

Checks
  rod3D_mesh        checkMesh reports "Mesh OK." and the mesh holds
                    refined (h/2) cells: snappyHexMesh refined it
  rod3D_setFields   the copper volume from the STL surfaces (cell centres
                    inside) is within 5 % of the quarter rods' volume
                    pi R0^2 L0 / 2 (a staircase of h/2 cubes)
  rod3D_rodsMove    the rods' rear ends (the last cell with alpha > 1/2
                    along the axis row) moved inwards by u0 t within 1.5
                    cells: no wave reaches them before 6.8 us
  rod3D_symmetry    the run is symmetric about the impact plane x = 0:
                    alpha.copper, p and U_x at mirrored cell centres agree
                    (max |d alpha|, max |dp|/max|p|, max |dU_x + U_x'|/u0
                    below 1e-6)
  rod3D_energy      total energy (kinetic + elastic + internal, from
                    rodProfile) constant within 1 % of the initial kinetic
                    energy (closed box)
"""
import os
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "lib"))

import numpy as np  # noqa: E402

import foamcase as fc  # noqa: E402
from checks import Checks  # noqa: E402

END = 4e-6
U0 = 227.0
R0, L0 = 3.2e-3, 32.4e-3
H = 1e-3          # background cube of the tutorial; h/2 near the rods

checks = Checks()


def main():
    missing = fc.require_apps("impactFoam", "blockMesh", "snappyHexMesh",
                              "setFields", "checkMesh", "rodProfile")
    if missing:
        checks.fail("rod3D_run", "%s not found on PATH" % " ".join(missing))
        checks.exit()
    case = fc.copy_tutorial("copperRodImpact3D", name="copperRodImpact3D")
    fc.set_entry(case, "system/controlDict", "writeInterval", 1e-6)
    fc.set_entry(case, "system/controlDict", "writeFormat", "ascii")
    try:
        fc.run(case, ["./Allrun", "-end", str(END)], log="log.Allrun",
               timeout=900)
        fc.run(case, ["postProcess", "-func", "writeCellVolumes",
                      "-time", "0"], log="log.writeCellVolumes")
        fc.run(case, ["postProcess", "-func", "writeCellCentres",
                      "-time", "0"], log="log.writeCellCentres")
        fc.run(case, ["rodProfile", "-phase", "copper", "-R0", str(R0),
                      "-withZero"], log="log.rodProfile")
        t = fc.find_time(case, END)
        V = fc.read_field(case, "0", "V")
        C = fc.read_field(case, "0", "C")
        a0 = fc.read_field(case, "0", "alpha.copper")
        f = {k: fc.read_field(case, t, k) for k in ("alpha.copper", "p", "U")}
    except fc.FoamError as e:
        checks.fail("rod3D_run", e.summary)
        checks.note(str(e))
        checks.exit()

    with open(os.path.join(case, "log.checkMesh")) as fh:
        ok_mesh = "Mesh OK." in fh.read()
    fine = int(np.sum(np.abs(V - (H / 2) ** 3) < 1e-3 * (H / 2) ** 3))
    checks.check("rod3D_mesh", ok_mesh and fine > 0,
                 "checkMesh: %s; %d cells, %d of them refined cubes of "
                 "%.2g mm" % ("Mesh OK" if ok_mesh else "FAILED", len(V),
                              fine, H / 2 * 1e3))

    vol = np.sum(a0 * V)
    exact = np.pi * R0 ** 2 * L0 / 2
    checks.check("rod3D_setFields", abs(vol / exact - 1) <= 0.05,
                 "copper volume %.4g mm3, quarter rods %.4g mm3: %+.2f %% "
                 "(bound 5 %%)" % (vol * 1e9, exact * 1e9,
                                   100 * (vol / exact - 1)))

    # rear ends along the axis row (the cells next to y = z = 0)
    axis = (C[:, 1] < H / 2) & (C[:, 2] < H / 2)
    xs = C[axis, 0]

    def ends(alpha):
        inside = xs[alpha[axis] > 0.5]
        return inside.min(), inside.max()

    (l0, r0), (l1, r1) = ends(a0), ends(f["alpha.copper"])
    moved = 0.5 * ((r0 - r1) + (l1 - l0))
    want = U0 * float(t)
    checks.check("rod3D_rodsMove", abs(moved - want) <= 1.5 * H / 2,
                 "rear ends moved in by %.3f mm (left %.3f, right %.3f), "
                 "u0 t = %.3f mm (bound 1.5 cells = %.2f mm)"
                 % (moved * 1e3, (l1 - l0) * 1e3, (r0 - r1) * 1e3,
                    want * 1e3, 1.5 * H / 2 * 1e3))

    # symmetry about x = 0: match each cell with its mirror image
    key = {tuple(np.round(c * 1e7).astype(np.int64)): i
           for i, c in enumerate(C)}
    mirror = np.array([key.get((-k[0], k[1], k[2]), -1) for k in
                       (tuple(np.round(c * 1e7).astype(np.int64))
                        for c in C)])
    paired = mirror >= 0
    i, j = np.nonzero(paired)[0], mirror[paired]
    da = np.max(np.abs(f["alpha.copper"][i] - f["alpha.copper"][j]))
    dp = np.max(np.abs(f["p"][i] - f["p"][j])) / np.max(np.abs(f["p"]))
    du = np.max(np.abs(f["U"][i, 0] + f["U"][j, 0])) / U0
    good = paired.all() and max(da, dp, du) <= 1e-6
    checks.check("rod3D_symmetry", good,
                 "%d of %d cells have a mirror cell; max |d alpha| %.2e, "
                 "max |dp|/max|p| %.2e, max |U_x + U_x'|/u0 %.2e (bound 1e-6)"
                 % (paired.sum(), len(C), da, dp, du))

    tab = np.genfromtxt(os.path.join(case, "postProcessing", "rodProfile",
                                     "copper.csv"), delimiter=",",
                        names=True)
    drift = np.max(np.abs(tab["total"] - tab["total"][0])) / tab["kinetic"][0]
    checks.check("rod3D_energy", drift <= 0.01,
                 "max |E(t) - E(0)| / K(0) = %.3e over %d writes to %.3g us "
                 "(bound 0.01)" % (drift, len(tab), tab["t"][-1] * 1e6))
    checks.exit()


if __name__ == "__main__":
    main()
