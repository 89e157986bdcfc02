#!/usr/bin/python3
"""impactStudy (docs/impactStudy.md): a case run over a list of values of
one of its Allrun's options, the time histories' final values tabulated.

The projectileOnPlate template on 2 mm cells for 1 us, over -v 1200 and
1800 (-- -h 2 -end 1e-6 -noPlot).

Checks
  impactStudy_speed  each run's rod starts at its speed: 0/U is -v in
                    the cells the rod fills, so -v reached impactSetup
                    through the template's speed variable
  impactStudy_table  study/v.dat has a row per value, the value first, and
                    each quantity equal to the last row of its run's table
                    (10 digits); a column per table column, its unit on
                    the second header line
  impactStudy_keep  run again: the finished runs are kept (log.impactFoam
                    untouched), the table the same; the case's own files
                    are unchanged by the study
  impactStudy_failed  a value Allrun fails with (-v abc): reported with the
                    run's log, its row nan, the others there, exit status 1
  impactStudy_error_<what>  an option the Allrun does not have, no values,
                    an Allrun that does not parse options (not run): a
                    message naming it, exit status 1, no traceback
About 15 s.
"""
import hashlib
import os
import subprocess
import sys

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "lib"))
import foamcase as fc                         # noqa: E402
from checks import Checks                     # noqa: E402

checks = Checks()
RUN = os.path.join(HERE, "..", "run", "impactStudy")
SCRIPT = os.path.join(HERE, "..", "..", "applications", "utilities",
                      "impactStudy", "impactStudy")
SPEEDS = ["1200", "1800"]
EXTRA = ["--", "-h", "2", "-end", "1e-6", "-noPlot"]


def study(case, *args):
    proc = subprocess.run(["/usr/bin/python3", SCRIPT] + list(args),
                          cwd=case, stdout=subprocess.PIPE,
                          stderr=subprocess.STDOUT, universal_newlines=True,
                          env=fc._case_env(case, None))
    return proc.returncode, proc.stdout


def read_table(path):
    with open(path) as f:
        names = f.readline()[1:].split()
        units = f.readline()[1:].split()
    rows = np.atleast_2d(np.genfromtxt(path, comments="#"))
    return names, units, rows


def last_rows(run):
    """{<table>.<column>: final value} of a run's histories"""
    out = {}
    for name in os.listdir(os.path.join(run, "postProcessing")):
        path = os.path.join(run, "postProcessing", name, "0", name + ".dat")
        if not os.path.isfile(path):
            continue
        cols, rows = fc.read_history(run, name)
        for c, v in zip(cols[1:], rows[-1, 1:]):
            out["%s.%s" % (name, c)] = v
    return out


def digest(case):
    """A hash of the case's own files (not the study's)"""
    h = hashlib.sha1()
    for root, dirs, files in os.walk(case):
        dirs[:] = sorted(d for d in dirs if d != "study")
        for f in sorted(files):
            p = os.path.join(root, f)
            h.update(p.encode())
            with open(p, "rb") as fh:
                h.update(fh.read())
    return h.hexdigest()


def main():
    case = fc.copy_tutorial("templates/projectileOnPlate", "template",
                            run_dir=RUN)
    before = digest(case)
    code, out = study(case, "v", *SPEEDS, *EXTRA)
    if code != 0:
        checks.fail("impactStudy_table", "exit status %d: %s"
                    % (code, out[-800:]))
        return
    runs = [os.path.join(case, "study", "v_" + v) for v in SPEEDS]

    errs = []
    for v, run in zip(SPEEDS, runs):
        U = fc.read_field(run, "0", "U")
        inside = fc.read_field(run, "0", "alpha.rod") > 0.999
        errs.append(np.abs(U[inside, 0] / -float(v) - 1).max()
                    if inside.any() else np.inf)
    checks.check("impactStudy_speed", max(errs) <= 1e-12,
                 "0/U in the cells the rod fills over -v: largest relative "
                 "errors %s" % ["%.1e" % e for e in errs])

    table = os.path.join(case, "study", "v.dat")
    names, units, rows = read_table(table)
    worst, missing = 0.0, []
    for i, run in enumerate(runs):
        for c, v in last_rows(run).items():
            if c not in names:
                missing.append(c)
                continue
            got = rows[i, names.index(c)]
            worst = max(worst, abs(got - v) / max(abs(v), 1e-300))
    ok = (rows.shape[0] == 2 and list(rows[:, 0]) == [1200, 1800]
          and not missing and worst <= 1e-9 and len(units) == len(names)
          and units[names.index("rodPenetration.P")] == "[m]")
    checks.check("impactStudy_table", ok,
                 "%d rows of %d columns, values %s; largest relative "
                 "difference from the runs' last rows %.1e; missing %s"
                 % (rows.shape[0], len(names), list(rows[:, 0]), worst,
                    missing[:3]))

    log = os.path.join(runs[0], "log.impactFoam")
    mtime = os.path.getmtime(log)
    with open(table) as f:
        first = f.read()
    code2, out2 = study(case, "v", *SPEEDS, *EXTRA)
    with open(table) as f:
        second = f.read()
    ok = (code2 == 0 and os.path.getmtime(log) == mtime and first == second
          and "done before, kept" in out2 and digest(case) == before)
    checks.check("impactStudy_keep", ok,
                 "second call: exit %d, log.impactFoam %s, table %s, case's "
                 "files %s" % (code2, "kept" if os.path.getmtime(log) == mtime
                               else "rewritten",
                               "same" if first == second else "changed",
                               "unchanged" if digest(case) == before
                               else "changed"))

    code3, out3 = study(case, "v", "1200", "abc", *EXTRA)
    names3, _, rows3 = read_table(table)
    ok = (code3 == 1 and "-v abc (2 of 2): failed" in out3
          and "study/v_abc/log.Allrun" in out3
          and np.isnan(rows3[1, 2:]).all() and np.isfinite(rows3[0, 2:]).all())
    checks.check("impactStudy_failed", ok,
                 "exit %d; %s" % (code3, " ".join(
                     l for l in out3.splitlines() if "abc" in l)[:200]))

    # A case whose Allrun does not parse options (it would run on -help)
    plain = os.path.join(RUN, "plainAllrun")
    os.makedirs(plain, exist_ok=True)
    with open(os.path.join(plain, "Allrun"), "w") as f:
        f.write("#!/bin/bash\ntouch ran\n")
    os.chmod(os.path.join(plain, "Allrun"), 0o755)
    if os.path.exists(os.path.join(plain, "ran")):
        os.remove(os.path.join(plain, "ran"))
    for what, where, args, expect in (
            ("option", case, ("speed", "1200"),
             ["no option -speed", "-v", "-np"]),
            ("noValues", case, ("v",), ["at least one value"]),
            ("plainAllrun", plain, ("v", "1"),
             ["does not declare its options", "impactParseOptions"])):
        code, out = study(where, *args)
        ok = code == 1 and all(e in out for e in expect) \
            and "Traceback" not in out \
            and not os.path.exists(os.path.join(plain, "ran"))
        checks.check("impactStudy_error_" + what, ok,
                     "exit %d: %s" % (code, out.strip()[:200]))


if __name__ == "__main__":
    try:
        main()
    except fc.FoamError as e:
        checks.fail("impactStudy", e.summary or str(e))
    checks.exit()
