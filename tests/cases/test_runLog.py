#!/usr/bin/python3
"""What a run tells its user (docs/numerics.md 10.9): progress lines at a
wall-clock interval, a summary at the end, the terminal of ./Allrun, and a
strict controlDict and function objects.

The projectileOnPlate template on 1 mm cells (axisymmetric), to 3 us.

Checks
  runLog_progress   with progressInterval 1e-9 (a line after every step):
                    one Progress line per step, the simulated times rising
                    to "100 % of 3 us" at the last, steps/s and the time
                    left on each
  runLog_summary    the summary's mass and mean axial velocity of each
                    phase equal those of the written fields at the end
                    (sum alpha rho V times 2 pi/sin(theta) of the wedge;
                    to the 6 printed digits: 6e-6), it names the time
                    histories' directory, and it gives each time
                    history's last row as its table has it (6 digits)
  runLog_defaults   progressInterval, not given, is listed with its default
                    (controlDict: progressInterval 10) among the defaults
                    printed at start-up
  runLog_terminal   ./Allrun's own output (the terminal) shows Progress
                    lines while the solver runs and the summary at its end
  runLog_restart    a run killed after its 1 us write (its 2 us time removed,
                    its tables left with rows to 2 us) and resumed from the
                    latest time (./Allrun -resume): each table is one file,
                    postProcessing/<name>/0/<name>.dat, with strictly rising
                    times, and equals the table of a run straight to 2 us:
                    the same rows, every column within 1e-9 of its largest
                    (fields written with 17 digits, the energy rebuilt from
                    p: round-off; the impulse carries on through
                    uniform/stepLedger, and the start row is the first
                    run's, with its last step's force; the traces' fractions
                    below alphaMin are read as written, not floored)
  runLog_profiling  OpenFOAM's own controlDict entry profiling passes the
                    strict check, and its table (uniform/profiling) times
                    the function objects
  runLog_error_<what>  the run stops before its first step, naming the entry
                    and the nearest keyword: maxCO in the controlDict,
                    adjustTimeStep no, piont in a function object, a
                    negative progressInterval
About 30 s.
"""
import os
import re
import shutil
import sys

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "lib"))
import foamcase as fc                         # noqa: E402
import meshGeometry as mg                     # noqa: E402
from checks import Checks                     # noqa: E402

checks = Checks()
RUN = os.path.join(HERE, "..", "run", "runLog")
TEMPLATE = "templates/projectileOnPlate"
END = 3e-6


def new_case(name, control=None):
    """The template set up on 1 mm cells; control: text put before the
    controlDict's functions entry"""
    case = fc.copy_tutorial(TEMPLATE, name, run_dir=RUN)
    if control:
        path = os.path.join(case, "system", "controlDict")
        with open(path) as f:
            text = f.read()
        i = text.index("functions")
        with open(path, "w") as f:
            f.write(text[:i] + control + "\n" + text[i:])
    fc.run(case, ["impactSetup", "-cellSize", "1e-3"])
    return case


def check_run():
    case = new_case("progress", "progressInterval 1e-9;")
    log = fc.run(case, ["impactFoam", "-endTime", "%g" % END])
    with open(log) as f:
        text = f.read()

    steps = len(re.findall(r"^Time = ", text, re.M))
    lines = re.findall(r"^Progress: t = ([0-9.e+-]+) us, (\d+) % of "
                       r"([0-9.e+-]+) us; (\d+) steps, ([0-9.e+-]+) steps/s;"
                       r" ([0-9.e+-]+) s elapsed, about ([0-9.e+-]+) s left$",
                       text, re.M)
    times = [float(l[0]) for l in lines]
    ok = steps > 10 and len(lines) == steps and \
        all(b > a for a, b in zip(times, times[1:])) and \
        lines[-1][1] == "100" and abs(float(lines[-1][2]) - END * 1e6) \
        <= 1e-9 and int(lines[-1][3]) == steps
    checks.check("runLog_progress", ok,
                 "%d steps, %d Progress lines, the last: %s"
                 % (steps, len(lines), lines[-1] if lines else None))

    # The summary against the fields at the end
    m = mg.read_polymesh(case)
    toFull = mg.wedge_to_full(m)
    t = fc.latest_time(case)
    U = fc.read_field(case, t, "U")
    block = text[text.index("Summary at"):]
    worst = 0.0
    seen = []
    for ph in ("rod", "plate", "air"):
        a = fc.read_field(case, t, "alpha." + ph)
        rho = fc.read_field(case, t, "rho." + ph)
        mc = a * rho * m.V
        mass = toFull * mc.sum()
        Ux = (mc * U[:, 0]).sum() / mc.sum()
        r = re.search(r"^\s+%s: mass ([0-9.e+-]+) kg, momentum \(([^)]*)\) "
                      r"kg m/s, mean velocity \(([^)]*)\) m/s$" % ph, block,
                      re.M)
        if not r:
            worst = 1.0
            continue
        seen.append(ph)
        worst = max(worst, abs(float(r.group(1)) / mass - 1))
        ux = float(r.group(3).split()[0])
        worst = max(worst, abs(ux - Ux) / max(abs(Ux), 1.0))
    names = "time histories: " in block and "rodPenetration" in block
    # Each time history's last row, as its table has it (6 digits)
    rows = {}
    for name in ("rodPenetration", "rodMotion", "wallForce", "energy"):
        cols, table = fc.read_history(case, name)
        r = re.search(r"^\s+%s at (\S+) s: (.*)$" % name, block, re.M)
        if not r:
            rows[name] = None
            continue
        last = dict(zip(cols, table[-1]))
        got = dict((w.split()[0], float(w.split()[1]))
                   for w in r.group(2).split(", "))
        rows[name] = max([abs(float(r.group(1)) - last["Time"])
                          / last["Time"]]
                         + [abs(v - last[c]) / max(abs(last[c]), 1e-300)
                            if abs(last[c]) > 1e-12 else abs(v)
                            for c, v in got.items()])
    histories = all(v is not None and v <= 6e-6 for v in rows.values())
    checks.check("runLog_summary", worst <= 6e-6 and names and histories,
                 "phases %s; largest relative difference of the mass and "
                 "mean velocity from the fields %.1e (bound 6e-6: 6 "
                 "digits); names the time histories: %s; each history's "
                 "last row (relative difference from its table): %s"
                 % (seen, worst, names, rows))

    defaults = re.search(r"controlDict: progressInterval", text)
    case2 = new_case("defaults")
    log2 = fc.run(case2, ["impactFoam", "-endTime", "1e-7"])
    with open(log2) as f:
        text2 = f.read()
    noted = "controlDict: progressInterval 10" in text2
    checks.check("runLog_defaults", noted and not defaults,
                 "listed when not given: %s; not listed when given: %s"
                 % (noted, not defaults))


def read_tables(case):
    """{name: (header, rows)} of every table under postProcessing, and the
    directories holding them"""
    tables, dirs = {}, []
    base = os.path.join(case, "postProcessing")
    for name in sorted(os.listdir(base)):
        for d in sorted(os.listdir(os.path.join(base, name))):
            path = os.path.join(base, name, d, name + ".dat")
            if os.path.isfile(path):
                dirs.append("%s/%s" % (name, d))
                with open(path) as f:
                    header = f.readline()
                tables[name] = (header, np.atleast_2d(np.loadtxt(path)))
    return tables, dirs


def check_restart():
    control = "progressInterval 0;"
    straight = new_case("restart_straight", control)
    legs = new_case("restart_legs", control)
    for case in (straight, legs):
        fc.set_entry(case, "system/controlDict", "writePrecision", "17")
        fc.run(case, ["impactFoam", "-endTime", "2e-6"])
    # The kill: the 2 us write lost, the tables' rows kept
    shutil.rmtree(os.path.join(legs, "2e-06"))
    fc.run(legs, ["./Allrun", "-resume", "-end", "2e-6", "-noPlot"],
           log="log.Allrun.resume")

    a, _ = read_tables(straight)
    b, dirs = read_tables(legs)
    one = all(d.endswith("/0") for d in dirs) and len(dirs) == len(a)
    worst, worstWall, why = 0.0, 0.0, []
    for name, (header, rows) in a.items():
        if name not in b:
            why.append("no table %s" % name)
            continue
        h2, rows2 = b[name]
        t = rows2[:, 0]
        if h2 != header or rows2.shape != rows.shape or \
                not np.all(np.diff(t) > 0):
            why.append("%s: %s rows against %s, times rising: %s"
                       % (name, rows2.shape, rows.shape,
                          bool(np.all(np.diff(t) > 0))))
            continue
        scale = np.maximum(np.abs(rows).max(axis=0), 1e-300)
        d = float((np.abs(rows2 - rows) / scale).max())
        if name == "wallForce":
            worstWall = max(worstWall, d)
        else:
            worst = max(worst, d)
    impulse = a.get("wallForce", (None, np.zeros((1, 5))))[1][-1, 4]
    checks.check("runLog_restart",
                 one and not why and worstWall <= 1e-9 and worst <= 1e-9,
                 "tables %s; %s; largest difference from the straight run, "
                 "of a column's largest: wall force and impulse %.1e (bound "
                 "1e-9), the other tables %.1e (bound 1e-9); the wall's "
                 "impulse at 2 us %.6g N s"
                 % (dirs, "; ".join(why) or "same rows", worstWall, worst,
                    impulse))


def check_terminal():
    case = fc.copy_tutorial(TEMPLATE, "terminal", run_dir=RUN)
    path = os.path.join(case, "system", "controlDict")
    with open(path) as f:
        text = f.read()
    i = text.index("functions")
    with open(path, "w") as f:
        f.write(text[:i] + "progressInterval 0.5;\n" + text[i:])
    log = fc.run(case, ["./Allrun", "-h", "0.5", "-end", "6e-6", "-noPlot"],
                 log="log.terminal")
    with open(log) as f:
        out = f.read()
    progress = re.findall(r"^    Progress: t = .*$", out, re.M)
    summary = re.search(r"^Summary at t = 6e-06 s", out, re.M)
    checks.check("runLog_terminal", progress and summary,
                 "%d Progress lines on the terminal (the last: %s); "
                 "summary shown: %s" % (len(progress), progress[-1].strip()
                                        if progress else None,
                                        bool(summary)))


ERRORS = [
    ("maxCO", "maxCO 0.5;", ["unknown entry maxCO", "did you mean maxCo"]),
    ("adjustTimeStep", "adjustTimeStep no;", ["adjustTimeStep no",
                                              "maxCo"]),
    ("progressInterval", "progressInterval -1;", ["progressInterval -1"]),
]


def check_errors():
    for what, entry, expect in ERRORS:
        case = new_case("error_" + what, entry)
        log = fc.run(case, ["impactFoam", "-endTime", "1e-7"], check=False)
        with open(log) as f:
            out = " ".join(f.read().split())
        missing = [e for e in expect if e not in out]
        ok = "FOAM FATAL" in out and not missing and "Time = " not in out
        checks.check("runLog_error_" + what, ok,
                     "missing %s; %s" % (missing, out[out.find("FOAM FATAL"):]
                                         [:240]))
    # A function object's misspelled entry
    case = new_case("error_functionObject")
    path = os.path.join(case, "system", "impactOutputs")
    with open(path) as f:
        text = f.read()
    text = text.replace("point ", "piont ", 1)
    with open(path, "w") as f:
        f.write(text)
    log = fc.run(case, ["impactFoam", "-endTime", "1e-7"], check=False)
    with open(log) as f:
        out = " ".join(f.read().split())
    expect = ["Function object rodPenetration", "unknown entry piont",
              "did you mean point"]
    missing = [e for e in expect if e not in out]
    checks.check("runLog_error_functionObject",
                 "FOAM FATAL" in out and not missing,
                 "missing %s; %s" % (missing, out[out.find("FOAM FATAL"):]
                                     [:240]))


def check_profiling():
    """OpenFOAM's own controlDict entries pass the strict check: profiling
    runs, and its table times each function object"""
    case = new_case("profiling", "profiling { active true; cpuInfo false; "
                    "memInfo false; sysInfo false; }")
    fc.run(case, ["impactFoam", "-endTime", "2e-7"])
    path = os.path.join(case, fc.latest_time(case), "uniform", "profiling")
    text = open(path).read() if os.path.isfile(path) else ""
    timed = sorted(set(re.findall(r"functionObject::(\w+)::execute", text)))
    checks.check("runLog_profiling", {"energy", "rodMotion"} <= set(timed),
                 "controlDict's profiling accepted; %s times the function "
                 "objects %s" % (os.path.relpath(path, case), timed))


def main():
    fc.require_apps("impactSetup", "impactFoam", "blockMesh")
    for step in (check_run, check_restart, check_terminal, check_errors,
                 check_profiling):
        try:
            step()
        except fc.FoamError as e:
            checks.fail("runLog_" + step.__name__[6:], e.summary or str(e))
    checks.exit()


if __name__ == "__main__":
    main()
