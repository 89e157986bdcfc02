#!/usr/bin/python3
"""A variable carried with a phase's mass (the phase model's list of carried
variables, src/hyperelasticPhases/carriedVariable): a passive tracer
declared in constant/phaseProperties (passiveScalars (dye);) is transported
like epsilonP and plasticWork, by every part of the step that loops over
the list (face states, DEM mass fluxes, processor exchange, conservative
sums, field I/O).

Case: the closed box of V6 (tutorials/impactFoam/closedBox: copper disc and
aluminium block colliding in air, slip walls, random velocities, 150 fixed
steps of 3e-7 s), second order, with `passiveScalars (dye);` in copper and
in air, the initial dye.copper and dye.air random in [0.2, 0.9] per cell.
Run serially and on 2 processes.

Checks:
  - the dye mass sum(alpha_k rho_k dye_k V) of each phase is conserved to
    1e-12 relative (the dye travels with the phase's mass only);
  - dye stays within its initial bounds [0.2, 0.9] (to 1e-12) wherever the
    phase is not a trace (alpha > 1e-6): the upwind transport is a convex
    combination;
  - serial and parallel dye fields agree to 1e-10 (the carried variables
    cross the processor faces in the exchanged face states);
  - the other fields are those of a run without the dye to round-off (the
    tracer is passive): alpha, rho, p of copper, U at the end, 1e-12.
"""
import os
import re
import sys

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "lib"))
import foamcase as fc                         # noqa: E402
from checks import Checks                     # noqa: E402
import fieldWriter as fw                      # noqa: E402
import meshGeometry as mg                     # noqa: E402
sys.path.insert(0, HERE)
import test_V6_conservation as v6             # noqa: E402

DYE_PHASES = ("copper", "air")
LO, HI = 0.2, 0.9

checks = Checks()


def add_dye(case):
    path = os.path.join(case, "constant", "phaseProperties")
    with open(path) as f:
        text = f.read()
    for name in DYE_PHASES:
        m = re.search(r"(^|\n)%s\s*\{" % name, text)
        if not m:
            raise fc.FoamError("no %s sub-dictionary in %s" % (name, path))
        text = text[:m.end()] + "\n    passiveScalars (dye);" + text[m.end():]
    with open(path, "w") as f:
        f.write(text)


def write_dye(case):
    """passiveScalars (dye) in the dye phases, random initial dye fields"""
    add_dye(case)
    mesh = mg.read_polymesh(case)
    rng = np.random.default_rng(7)
    for phase in DYE_PHASES:
        fw.write_field(case, "0", "dye." + phase,
                       rng.uniform(LO, HI, mesh.nCells), mesh,
                       dimensions="[0 0 0 0 0 0 0]")


def run(name, dye, parallel):
    """V6's closed box at second order (test_V6_conservation.run_tutorial)"""
    return v6.run_tutorial(name, 2, parallel,
                           before_run=write_dye if dye else None)


def main():
    missing = fc.require_apps("impactFoam", "blockMesh", "setFields",
                              "decomposePar", "reconstructPar", "mpirun")
    if missing:
        checks.fail("carried_run", "%s not found on PATH" % " ".join(missing))
        checks.exit()
    try:
        serial = run("carried_dye_serial", True, False)
        parallel = run("carried_dye_parallel", True, True)
        plain = run("carried_plain_serial", False, False)
    except fc.FoamError as e:
        checks.fail("carried_run", str(e))
        checks.exit()

    n = fc.mesh_n_cells(serial)
    V = mg.read_polymesh(serial).V
    t_end = fc.latest_time(serial)
    for phase in DYE_PHASES:
        def dye_mass(case, time):
            a = fc.read_field(case, time, "alpha." + phase, n)
            r = fc.read_field(case, time, "rho." + phase, n)
            d = fc.read_field(case, time, "dye." + phase, n)
            return np.sum(a * r * d * V), a, d
        m0, _, _ = dye_mass(serial, "0")
        m1, a1, d1 = dye_mass(serial, t_end)
        rel = abs(m1 - m0) / abs(m0)
        checks.check("carried_%s_conserved" % phase, rel <= 1e-12,
                     "dye mass %.15e -> %.15e, relative change %.2e "
                     "(bound 1e-12)" % (m0, m1, rel))
        live = a1 > 1e-6
        lo, hi = d1[live].min(), d1[live].max()
        ok = lo >= LO - 1e-12 and hi <= HI + 1e-12
        checks.check("carried_%s_bounded" % phase, ok,
                     "dye in [%.15f, %.15f] where alpha > 1e-6 (initial "
                     "[%g, %g])" % (lo, hi, LO, HI))
        dp = fc.read_field(parallel, fc.latest_time(parallel),
                           "dye." + phase, n)
        diff = np.max(np.abs(dp - d1)[live])
        checks.check("carried_%s_serial_parallel" % phase, diff <= 1e-10,
                     "max |serial - parallel| %.2e where alpha > 1e-6 "
                     "(bound 1e-10)" % diff)

    worst = 0.0
    for field in ("alpha.copper", "rho.copper", "p.copper", "U"):
        a = fc.read_field(serial, t_end, field, n)
        b = fc.read_field(plain, fc.latest_time(plain), field, n)
        worst = max(worst, np.max(np.abs(a - b)) / np.max(np.abs(b)))
    checks.check("carried_passive", worst <= 1e-12,
                 "fields with and without the dye differ by %.2e relative "
                 "(bound 1e-12)" % worst)
    checks.exit()


if __name__ == "__main__":
    main()
