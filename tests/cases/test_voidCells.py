#!/usr/bin/python3
"""Void cells keep a velocity in their neighbours' range (docs/numerics.md
9.11).

The case tests/cases/voidCells: 1-D, 100 cells of 1 mm between two walls,
the Taylor bar's copper and air, air at rest (1.2 kg/m3, 1e5 Pa) with a
copper floor (alpha 1e-8). Three cells, x in (49, 52) mm, are void: a
copper trace (alpha 1e-6, 8.9e-3 kg/m3) in near-vacuum air (1e-11 kg/m3),
so that no phase counts (each below alphaMinor 1e-3 by volume or below
massFractionMinor 1e-6 of the cell's mass). They move at 300, 1e5 and
-100 m/s; the middle one's 1e5 m/s is the state the transport left on the
axis behind the 0.2 mm rod-on-rod at 2000 m/s, where such cells reached
3.5e4 m/s and the time step collapsed. The run writes every step to 0.1 us.

Checks:
- the run reaches its end time with finite fields;
- at every step, the velocity of every void cell of the new state lies
  in the range of its face neighbours' velocities before the step (to
  1e-12 of the largest speed); the middle cell is void after the first
  step, so its 1e5 m/s falls to the largest of its neighbours', 300 m/s
  (the build before this rule: 8e4 m/s after the first step);
- the domain is closed: the total energy at each write equals the initial
  one plus what the solver logs as added without a payer (the void cells'
  kinetic energy among it), to 1e-10 relative;
- serial = parallel: on two processes split at x = 50 mm, between the
  first void cell and the fast one (the bound of 300 m/s then comes
  through the processor patch), the fields at the end equal the serial ones to 1e-12
  of each field's largest magnitude.
"""
import os
import re
import shutil
import sys

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "lib"))
import foamcase as fc                         # noqa: E402
from checks import Checks                     # noqa: E402

CASE = os.path.join(HERE, "voidCells")
RUN_TIMEOUT = 300
T_END = 1e-7
ALPHA_MINOR = 1e-3                # phaseSystem defaults
MASS_FRACTION_MINOR = 1e-6
PHASES = ("copper", "air")
BOUND_TOL = 1e-12
ENERGY_TOL = 1e-10
PARALLEL_TOL = 1e-12
FIELDS = ("U", "alpha.copper", "alpha.air", "rho.copper", "rho.air",
          "p.copper", "p.air")

checks = Checks()


def void_cells(case, t):
    alpha = [fc.read_field(case, t, "alpha." + k) for k in PHASES]
    rho = [fc.read_field(case, t, "rho." + k) for k in PHASES]
    mix = sum(a * r for a, r in zip(alpha, rho))
    counts = np.zeros(mix.shape, dtype=bool)
    for a, r in zip(alpha, rho):
        counts |= (a >= ALPHA_MINOR) & (a * r >= MASS_FRACTION_MINOR * mix)
    return ~counts


def main():
    missing = fc.require_apps("impactFoam", "blockMesh", "setFields")
    if missing:
        checks.fail("voidCells_run", "%s not found on PATH (impactFoam not "
                    "built or environment not sourced: . etc/bashrc)"
                    % " ".join(missing))
        checks.exit()

    case = fc.copy_tutorial(CASE, "voidCells")
    try:
        fc.run(case, "./Allrun", log="log.Allrun", timeout=RUN_TIMEOUT)
    except fc.FoamError as e:
        checks.fail("voidCells_run", e.summary)
        checks.exit()

    times = [name for _, name in fc.time_dirs(case)]
    x = fc.cell_centres(case, times[0])[:, 0]
    order = np.argsort(x)
    U = {t: fc.read_field(case, t, "U")[order, 0] for t in times}
    finite = all(np.all(np.isfinite(u)) for u in U.values())
    reached = abs(float(times[-1]) - T_END) <= 1e-6 * T_END
    checks.check("voidCells_run", reached and finite and len(times) > 3,
                 "%d writes, last at %s s (end %g s), fields finite: %s"
                 % (len(times), times[-1], T_END, finite))

    # The maximum principle, step by step (1-D: neighbours c - 1, c + 1)
    worst, n_checked, first_middle = 0.0, 0, None
    middle = int(np.argmax(np.abs(U[times[0]])))
    for told, tnew in zip(times[:-1], times[1:]):
        is_void = void_cells(case, tnew)[order]
        uo, un = U[told], U[tnew]
        scale = max(np.max(np.abs(uo)), 1.0)
        for c in np.nonzero(is_void)[0]:
            nb = [j for j in (c - 1, c + 1) if 0 <= j < len(uo)]
            lo, hi = min(uo[j] for j in nb), max(uo[j] for j in nb)
            worst = max(worst, (max(un[c] - hi, lo - un[c], 0.0)) / scale)
            n_checked += 1
            if told == times[0] and c == middle:
                first_middle = un[c]
    checks.check("voidCells_bounds",
                 n_checked > 0 and first_middle is not None
                 and worst <= BOUND_TOL,
                 "%d void cell updates; largest excursion beyond the "
                 "neighbours' range %.3e of the largest speed (bound %g); "
                 "the 1e5 m/s cell after the first step: %s m/s"
                 % (n_checked, worst, BOUND_TOL,
                    "%.6g" % first_middle if first_middle is not None
                    else "not void"))

    # Energy of the closed domain against what the log books
    log = open(os.path.join(case, "log.impactFoam")).read()
    e0 = float(re.search(r"Initial totals: mass \S+ kg, energy (\S+) J",
                         log).group(1))
    totals = re.findall(r"totals: mass \S+ kg, energy (\S+) J, energy "
                        r"added without a payer (\S+) J", log)
    drift = max((abs(float(e) - e0 - float(a)) / e0 for e, a in totals),
                default=float("inf"))
    held = len(re.findall(r"void cells: velocity held", log))
    checks.check("voidCells_energy", drift <= ENERGY_TOL and held > 0,
                 "total energy at %d writes against the initial %.6g J plus "
                 "the logged energy added without a payer: largest "
                 "difference %.3e relative (bound %g); velocity held in %d "
                 "steps" % (len(totals), e0, drift, ENERGY_TOL, held))

    # Serial = parallel
    par = fc.copy_tutorial(CASE, "voidCells_parallel")
    try:
        fc.run(par, ["blockMesh"])
        shutil.copytree(os.path.join(par, "0.orig"), os.path.join(par, "0"))
        fc.run(par, ["setFields"])
        fc.run(par, ["decomposePar"])
        fc.run(par, "mpirun --oversubscribe -np 2 impactFoam -parallel",
               log="log.mpirun", timeout=RUN_TIMEOUT)
        fc.run(par, ["reconstructPar", "-latestTime"])
    except fc.FoamError as e:
        checks.fail("voidCells_parallel", e.summary)
        checks.exit()
    t = times[-1]
    diffs = {}
    for name in FIELDS:
        a = fc.read_field(case, t, name)
        b = fc.read_field(par, fc.latest_time(par), name)
        diffs[name] = np.max(np.abs(a - b)) / max(np.max(np.abs(a)), 1e-300)
    plog = open(os.path.join(par, "log.mpirun")).read()
    pheld = len(re.findall(r"void cells: velocity held", plog))
    checks.check("voidCells_parallel",
                 fc.latest_time(par) == t and pheld == held
                 and max(diffs.values()) <= PARALLEL_TOL,
                 "2 processes against serial at %s s: largest relative "
                 "difference %.3e (%s; bound %g); velocity held in %d steps "
                 "(serial %d)"
                 % (fc.latest_time(par), max(diffs.values()),
                    max(diffs, key=diffs.get), PARALLEL_TOL, pheld, held))
    checks.exit()


if __name__ == "__main__":
    main()
