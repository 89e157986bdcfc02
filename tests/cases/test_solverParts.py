#!/usr/bin/python3
"""The solver's parts follow a topology change through one path
(updateSolverParts, applications/solvers/impactFoam/meshChange.H).

With `rebuildSolverParts 1` in system/controlDict the solver rebuilds every
part (per-cell and per-face storage, cached geometry: inverse matrices,
neighbour tables, wedge images, the reconstruction selected again) after
every accepted step on the unchanged mesh. A part that loses state in the
rebuild, or keeps storage or geometry the rebuild should have renewed,
changes the run. Each case runs twice, without and with the rebuild, and
must give the same run bit for bit.

The cases: the template tutorials/impactFoam/templates/projectileOnPlate
(a tungsten rod on a steel plate in air: two solids and a gas, the rod and
the plate sliding with Coulomb friction, mu 0.1, so that the sliding band,
the phases' own velocities and the friction heat take part) to 3 us,
  axisymmetric  the template's wedge at 0.5 mm (wedge images, axis)
  threeD        a quarter of it in 3-D at 1 mm (symmetry planes y = 0,
                z = 0), serial, with fallbackInterfaces yes (every mixed
                cell at first order: the fall-back's flags, which the
                reconstruction reads, take part; the friction heat is
                then zero, the axisymmetric case has it)
fields written with 17 digits every microsecond.

Checks, per case
  solverParts_<case>   every file the two runs wrote in their time
                       directories (fields, uniform/) is the same byte for
                       byte, and the logs' lines of every step (time,
                       deltaT, Courant number), the totals (mass, energy,
                       energy without a payer, heat of friction) and the
                       fall-back's run totals are equal
  solverParts_<case>_log  the rebuilding run logs the discrete equations'
                       banner once and the wedge faces' choice once (on
                       the wedge; never in 3-D), and does not list
                       rebuildSolverParts, which it gives, among the
                       defaults
"""
import filecmp
import os
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "lib"))

import foamcase as fc  # noqa: E402
from checks import Checks  # noqa: E402

TEMPLATE = "templates/projectileOnPlate"
END = "3e-06"

CONTACTS = """
contacts
{
    default     { type coulomb; mu 0.1; }
}
"""

# impactDict edits per case: (old, new)
EDITS = {
    "axisymmetric": [
        ("cellSize    0.25e-3;", "cellSize    0.5e-3;"),
    ],
    "threeD": [
        ("geometry    axisymmetric;", "geometry    threeD;"),
        ("min         (-10e-3 0 0);\n    max         (60e-3 20e-3 0);",
         "min         (-10e-3 0 0);\n    max         (50e-3 12e-3 12e-3);"),
        ("cellSize    0.25e-3;", "cellSize    1e-3;"),
        ("yMax    open;",
         "yMax    open;\n        yMin    symmetry;\n"
         "        zMin    symmetry;\n        zMax    open;"),
        ("min         (-10e-3 0 -1);\n        max         (0 15e-3 1);",
         "min         (-10e-3 0 0);\n        max         (0 10e-3 10e-3);"),
    ],
}

# Log lines that must be equal: every step's, the totals, the fall-back's
LOG_PREFIXES = ("Time = ", "Initial totals", "    totals", "Fallback to first",
                "    fallback:", "    Step rejected")

checks = Checks()


def prepare(case_name, name, rebuild):
    case = fc.copy_tutorial(TEMPLATE, name)
    path = os.path.join(case, "system", "impactDict")
    text = open(path).read()
    for old, new in EDITS[case_name]:
        if text.count(old) != 1:
            raise fc.FoamError("impactDict of %s: no single '%s'"
                               % (TEMPLATE, old.splitlines()[0]))
        text = text.replace(old, new)
    text = text.replace("\nbodies\n", CONTACTS + "\nbodies\n", 1)
    open(path, "w").write(text)
    if case_name == "threeD":
        # Every mixed cell at first order in every step: the fall-back's
        # flags, which the reconstruction reads, take part
        fc.set_entry(case, "system/fvSchemes",
                     "discreteEquations/fallbackInterfaces", "yes")
    fc.set_entry(case, "system/controlDict", "writePrecision", 17)
    fc.set_entry(case, "system/controlDict", "writeInterval", "1e-06")
    if rebuild:
        fc.set_entry(case, "system/controlDict", "rebuildSolverParts", 1)
    fc.run(case, ["impactSetup"])
    fc.run(case, ["impactFoam", "-endTime", END])
    return case


def written_files(case):
    """Relative paths of the files in the case's time directories but 0"""
    files = []
    for t, name in fc.time_dirs(case):
        if t == 0:
            continue
        for root, _, names in os.walk(os.path.join(case, name)):
            for n in names:
                files.append(os.path.relpath(os.path.join(root, n), case))
    return sorted(files)


def log_lines(case):
    text = open(os.path.join(case, "log.impactFoam")).read()
    return [l for l in text.splitlines() if l.startswith(LOG_PREFIXES)], text


def compare(case_name):
    tag = "solverParts_" + case_name
    try:
        plain = prepare(case_name, "solverParts_%s" % case_name, False)
        rebuilt = prepare(case_name, "solverParts_%s_rebuilt" % case_name,
                          True)
    except fc.FoamError as e:
        checks.fail(tag, e.summary)
        return

    files_a = written_files(plain)
    files_b = written_files(rebuilt)
    differ = [f for f in files_a if f in files_b
              and not filecmp.cmp(os.path.join(plain, f),
                                  os.path.join(rebuilt, f), shallow=False)]
    only = sorted(set(files_a) ^ set(files_b))
    lines_a, _ = log_lines(plain)
    lines_b, log_b = log_lines(rebuilt)
    steps = sum(1 for l in lines_a if l.startswith("Time = "))
    log_differ = [(a, b) for a, b in zip(lines_a, lines_b) if a != b]
    if len(lines_a) != len(lines_b):
        log_differ.append(("%d lines" % len(lines_a),
                           "%d lines" % len(lines_b)))
    totals = [l for l in lines_b if "totals" in l]
    checks.check(tag, files_a and not differ and not only and steps
                 and not log_differ,
                 "%d steps rebuilding every part after each: %d written "
                 "files compared, %d differ%s, %d in one run only; "
                 "%d log lines compared (steps, totals, fall-back), %d "
                 "differ%s; last totals: %s"
                 % (steps, len(files_a), len(differ),
                    " (%s)" % " ".join(differ[:4]) if differ else "",
                    len(only), len(lines_a), len(log_differ),
                    " (first: '%s' vs '%s')" % log_differ[0]
                    if log_differ else "",
                    totals[-1].strip() if totals else "none"))

    banner = log_b.count("Discrete equations: ")
    wedges = log_b.count("Wedge faces: ")
    want_wedges = 1 if case_name == "axisymmetric" else 0
    checks.check(tag + "_log", banner == 1 and wedges == want_wedges
                 and "controlDict: rebuildSolverParts" not in log_b,
                 "rebuilding run: the discrete equations' banner %d time(s) "
                 "(1), the wedge faces' choice %d time(s) (%d); "
                 "rebuildSolverParts %s the defaults"
                 % (banner, wedges, want_wedges,
                    "among" if "controlDict: rebuildSolverParts" in log_b
                    else "not among"))


def main():
    missing = fc.require_apps("impactFoam", "impactSetup")
    if missing:
        checks.fail("solverParts_run", "not found on PATH: %s"
                    % " ".join(missing))
        return checks.exit()
    for case_name in ("axisymmetric", "threeD"):
        compare(case_name)
    return checks.exit()


if __name__ == "__main__":
    main()
