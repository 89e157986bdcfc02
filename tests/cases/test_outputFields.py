#!/usr/bin/python3
"""The output mixture fields (p, sigma, sigmaEq) are current wherever they
are read (phaseSystem::correctOutputs, stepControl::write).

The solver computes them, the stress of every solid in every cell, only
when they are written, or every step if the case has a function object
other than impactFoam's time histories (which read the phases, never these
fields) or may change its function objects at run time
(stepControl::outputsReadEveryStep). The case tests/cases/voidCells (1-D,
copper and air, a copper trace moving through near-vacuum air, 8 steps to
0.1 us: the trace is metal dust and does not set the time step,
docs/numerics.md 2.7) is run three times:

- A: written every step, no function objects (the fields on disk at every
  step are the reference);
- B: written only at the end time (writeInterval 1000 steps: the end time
  is not a write time, the solver's final write), with a fieldMinMax
  function object on p and sigmaEq every step beside an energyBudget, and
  runTimeModifiable off (the function objects are known from the start);
- C: as B with the energyBudget only: the fields are computed for the
  final write alone.

Checks:
- both runs reach their end time, A in more than 5 steps;
- at every step, B's function object reports the minimum and maximum of p
  and sigmaEq that A wrote at that time, to 1e-10 relative (the files
  hold 12 and 13 significant digits; with the fields computed only at
  write times, the function object would see the initial ones: p's
  largest value 4.4e6 Pa after the first step against 1e5 Pa at the
  start);
- B's and C's final p, sigma and sigmaEq equal A's at the end time to
  1e-12 of each field's largest magnitude.
"""
import os
import sys

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "lib"))
import foamcase as fc                         # noqa: E402
from checks import Checks                     # noqa: E402

CASE = os.path.join(HERE, "voidCells")
RUN_TIMEOUT = 300
T_END = 1e-7
TOL = 1e-12
PRINT_TOL = 1e-10                 # 12-13 significant digits in the files
FIELDS = ("p", "sigmaEq")

ENERGY = """
    energy
    {
        type            energyBudget;
        libs            (impactFoamFunctionObjects);
    }
"""

MIN_MAX = """
    minMax
    {
        type            fieldMinMax;
        libs            (fieldFunctionObjects);
        fields          (p sigmaEq);
        mode            magnitude;
        writeControl    timeStep;
        writeInterval   1;
    }
"""

checks = Checks()


def run(name, functions):
    case = fc.copy_tutorial(CASE, name)
    if functions:
        fc.set_entry(case, "system/controlDict", "writeInterval", "1000")
        fc.set_entry(case, "system/controlDict", "runTimeModifiable",
                     "false")
        with open(os.path.join(case, "system", "controlDict"), "a") as f:
            f.write("\nfunctions\n{\n%s}\n" % functions)
    fc.run(case, "./Allrun", log="log.Allrun", timeout=RUN_TIMEOUT)
    return case


def min_max_log(case):
    """{(time name, field): (min, max)} from the fieldMinMax file."""
    path = os.path.join(case, "postProcessing", "minMax", "0",
                        "fieldMinMax.dat")
    rows = {}
    for line in open(path):
        if line.startswith("#") or not line.strip():
            continue
        cols = line.split("\t")
        time, field = float(cols[0]), cols[1].strip()
        rows[(time, field)] = (float(cols[2]), float(cols[4]))
    return rows


def magnitude(values):
    return np.abs(values) if values.ndim == 1 else \
        np.sqrt(np.sum(values**2, axis=1))


def main():
    missing = fc.require_apps("impactFoam", "blockMesh", "setFields")
    if missing:
        checks.fail("outputFields_run", "%s not found on PATH (impactFoam "
                    "not built or environment not sourced: . etc/bashrc)"
                    % " ".join(missing))
        checks.exit()
    try:
        a = run("outputFields_written", functions="")
        b = run("outputFields_functionObject", functions=ENERGY + MIN_MAX)
        c = run("outputFields_histories", functions=ENERGY)
    except fc.FoamError as e:
        checks.fail("outputFields_run", e.summary)
        checks.exit()

    times_a = [name for _, name in fc.time_dirs(a)]
    times_b = [name for _, name in fc.time_dirs(b)]
    times_c = [name for _, name in fc.time_dirs(c)]
    reached = all(abs(float(t[-1]) - T_END) <= 1e-6 * T_END
                  for t in (times_a, times_b, times_c))
    checks.check("outputFields_run", reached and len(times_a) > 6,
                 "A wrote %d times, B %d, C %d; last at %s, %s and %s s "
                 "(end %g s)"
                 % (len(times_a), len(times_b), len(times_c), times_a[-1],
                    times_b[-1], times_c[-1], T_END))

    # B's function object against A's fields, step by step
    fo = min_max_log(b)
    worst, n, first_pmax = 0.0, 0, None
    for t in times_a[1:]:
        for field in FIELDS:
            key = min((k for k in fo if k[1] == field),
                      key=lambda k: abs(k[0] - float(t)))
            if abs(key[0] - float(t)) > 1e-6 * float(t):
                continue
            values = magnitude(fc.read_field(a, t, field))
            scale = max(np.max(values), 1e-300)
            lo, hi = fo[key]
            worst = max(worst, abs(lo - np.min(values)) / scale,
                        abs(hi - np.max(values)) / scale)
            n += 1
            if field == "p" and first_pmax is None:
                first_pmax = hi
    checks.check("outputFields_functionObject",
                 n >= 2 * (len(times_a) - 1) and worst <= PRINT_TOL,
                 "%d step-field pairs of B's fieldMinMax against A's written "
                 "fields: largest difference %.3e relative (bound %g); p's "
                 "largest value after the first step %s Pa"
                 % (n, worst, PRINT_TOL, "%.6g" % first_pmax
                    if first_pmax is not None else "-"))

    # The final writes of B and C (not write times) against A's
    for run_name, case, times in (("B", b, times_b), ("C", c, times_c)):
        diffs = {}
        for field in ("p", "sigma", "sigmaEq"):
            fa = fc.read_field(a, times_a[-1], field)
            fb = fc.read_field(case, times[-1], field)
            diffs[field] = (np.max(np.abs(fa - fb))
                            / max(np.max(np.abs(fa)), 1e-300))
        checks.check("outputFields_finalWrite%s" % run_name,
                     max(diffs.values()) <= TOL,
                     "%s's fields at the end time against A's: %s (bound %g)"
                     % (run_name, ", ".join("%s %.3e" % kv
                                            for kv in diffs.items()), TOL))
    checks.exit()


if __name__ == "__main__":
    main()
