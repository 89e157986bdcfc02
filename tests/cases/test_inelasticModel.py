#!/usr/bin/python3
"""A variable that an inelastic model declares and updates, with no edit
outside the model's own class (src/plasticRelaxation/inelasticModels).

The model is materialAge (tests/models): copper's plasticity as usual plus
an age [s] carried with copper's mass and grown by dt in each relaxation of
copper, built into a test-only library and loaded with libs (...) in
controlDict. Case: the closed box of V6 (tutorials/impactFoam/closedBox,
copper disc and aluminium block colliding in air, slip walls, second order,
150 steps of 3e-7 s), copper's initial age random in [0, 1e-5] s per cell.

Checks:
  - conserved with the mass: in a closed box the copper mass M is constant,
    and the age's mass integral I = sum(alpha rho age V) grows by dt times
    the mass relaxed in each step, which is M but for copper's traces
    (alpha < alphaTrace: left to the cell, not relaxed). So
    0 <= T M - (I(T) - I(0)) <= T M_trace, with M_trace the largest trace
    mass written (the fields every 7.5 us), to 1e-12 of T M;
  - serial = parallel: age.copper to 1e-10 of its largest value where
    copper is not a trace (the variable crosses processor faces in the
    exchanged face states); its written values on processor0's processor
    patch are those of processor1's cells beside it (1e-12), not the
    decomposition's;
  - restart = run: stopped at 22.5 us and restarted from the written
    fields, age.copper at the end within 1e-12 of its largest value of the
    straight run (the state, age included, is in the 17-digit fields);
  - passive for the mechanics: alpha, rho, p of copper and U equal to a run
    with copper's plain plasticityAndFailure to 1e-12;
  - the solver's log lists copper's carried variables: epsilonP,
    plasticWork (plasticityAndFailure's) and age.
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
import solverRun                              # noqa: E402
sys.path.insert(0, HERE)
import test_V6_conservation as v6             # noqa: E402

AGE0 = 1e-5
T_MID = 2.25e-5
ALPHA_TRACE = 1e-6

checks = Checks()


def phase_block(text, name):
    m = re.search(r"(^|\n)%s\s*\{" % name, text)
    if not m:
        raise fc.FoamError("no %s sub-dictionary in phaseProperties" % name)
    return m


def with_age(case):
    """copper's inelastic model materialAge, its library, a random age"""
    path = os.path.join(case, "constant", "phaseProperties")
    text = open(path).read()
    m = phase_block(text, "copper")
    text = (text[:m.end()] + "\n    inelastic { type materialAge; }"
            + text[m.end():])
    open(path, "w").write(text)
    cd = os.path.join(case, "system", "controlDict")
    open(cd, "a").write('\nlibs ("libimpactTestModels.so");\n')
    fc.set_entry(case, "system/controlDict", "writeInterval", 7.5e-6)
    mesh = mg.read_polymesh(case)
    rng = np.random.default_rng(11)
    fw.write_field(case, "0", "age.copper",
                   rng.uniform(0, AGE0, mesh.nCells), mesh,
                   dimensions="[0 0 1 0 0 0 0]")


def restart_leg(case):
    """Run on from the latest written time to the tutorial's end"""
    t_end = 4.5e-5
    fc.set_entry(case, "system/controlDict", "startFrom", "latestTime")
    fc.set_entry(case, "system/controlDict", "endTime", t_end)
    solverRun.run_capped(case, "impactFoam", 400, log="log.impactFoam.2",
                         timeout=v6.RUN_TIMEOUT)


def main():
    missing = fc.require_apps("impactFoam", "blockMesh", "setFields",
                              "decomposePar", "reconstructPar", "mpirun")
    if missing:
        checks.fail("inelastic_run", "%s not found on PATH" % " ".join(missing))
        checks.exit()

    def two_legs(case):
        with_age(case)
        fc.set_entry(case, "system/controlDict", "endTime", T_MID)

    try:
        serial = v6.run_tutorial("inelastic_age_serial", 2, False,
                                 before_run=with_age)
        parallel = v6.run_tutorial("inelastic_age_parallel", 2, True,
                                   before_run=with_age)
        legs = v6.run_tutorial("inelastic_age_restart", 2, False,
                               before_run=two_legs)
        restart_leg(legs)
        plain = v6.run_tutorial("inelastic_plain_serial", 2, False)
    except fc.FoamError as e:
        checks.fail("inelastic_run", str(e))
        checks.exit()

    mesh = mg.read_polymesh(serial)
    n, V = mesh.nCells, mesh.V
    t_end = fc.latest_time(serial)
    T = float(t_end)

    def rd(case, t, field):
        return fc.read_field(case, t, field, n)

    # Conserved with the mass
    def integrals(t):
        a, r = rd(serial, t, "alpha.copper"), rd(serial, t, "rho.copper")
        m = a * r * V
        return (np.sum(m * rd(serial, t, "age.copper")), np.sum(m),
                np.sum(m[a < ALPHA_TRACE]))
    I0, M, _ = integrals("0")
    I1, M1, _ = integrals(t_end)
    traces = [integrals(name)[2] for _, name in fc.time_dirs(serial)]
    deficit = T * M - (I1 - I0)
    bound = T * max(traces)
    tol = 1e-12 * T * M
    checks.check("inelastic_age_conserved",
                 -tol <= deficit <= bound + tol,
                 "T M - (I(T) - I(0)) = %.3e kg s, in [0, T M_trace = %.3e] "
                 "(T M = %.6e kg s, copper mass %.15e -> %.15e kg)"
                 % (deficit, bound, T * M, M, M1))

    live = rd(serial, t_end, "alpha.copper") > ALPHA_TRACE
    age = rd(serial, t_end, "age.copper")
    scale = np.max(np.abs(age[live]))
    dp = np.max(np.abs(rd(parallel, fc.latest_time(parallel), "age.copper")
                       - age)[live]) / scale
    checks.check("inelastic_age_serial_parallel", dp <= 1e-10,
                 "max |serial - parallel| age.copper %.2e of its largest "
                 "value (bound 1e-10)" % dp)

    # The written boundary values of a carried variable are current: on a
    # processor patch, the cells on the other side
    diff, big = mg.processor_patch_difference(
        parallel, fc.latest_time(parallel), "age.copper")
    checks.check("inelastic_age_processorPatch", diff <= 1e-12 * big,
                 "age.copper written on processor0's processor patch at the "
                 "end against processor1's cells beside it: largest "
                 "difference %.2e of %.3e (bound 1e-12 of it)" % (diff, big))

    dr = np.max(np.abs(rd(legs, fc.latest_time(legs), "age.copper")
                       - age)) / scale
    checks.check("inelastic_age_restart", dr <= 1e-12,
                 "max |restarted - straight| age.copper %.2e of its largest "
                 "value (bound 1e-12)" % dr)

    worst = 0.0
    for field in ("alpha.copper", "rho.copper", "p.copper", "U"):
        a = rd(serial, t_end, field)
        b = rd(plain, fc.latest_time(plain), field)
        worst = max(worst, np.max(np.abs(a - b)) / np.max(np.abs(b)))
    checks.check("inelastic_age_passive", worst <= 1e-12,
                 "copper's fields with and without the age differ by %.2e "
                 "relative (bound 1e-12)" % worst)

    def carried(case, phase):
        text = open(os.path.join(case, "log.impactFoam")).read()
        m = re.search(r"^\s*%s: [^\n]*" % phase, text, re.M)
        line = m.group(0) if m else ""
        c = re.search(r"carried ([\w ]+)", line)
        return line, (c.group(1).split() if c else [])
    line, names = carried(serial, "copper")
    checks.check("inelastic_age_declared",
                 names == ["epsilonP", "plasticWork", "age"],
                 "log: %s" % line.strip())
    checks.exit()


if __name__ == "__main__":
    main()
