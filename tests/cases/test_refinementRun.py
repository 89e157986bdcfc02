#!/usr/bin/python3
"""impactFoam running with adaptive refinement (docs/numerics.md section 11):
conservation through many refine and unrefine changes, a resumed run equal
to a straight one, serial equal to 2 processes, and the time step of the
finest cells.

The case: the projectileOnPlate template in 3-D, a quarter (symmetry planes
y = 0 and z = 0, as in test_refinement) closed on every other side (xMin,
xMax, yMax, zMax walls: nothing enters or leaves), 2 mm base cells (720),
fields every 1 us with 17 digits, constant/refinementProperties: two
levels, every 5 steps, one buffer layer, interfaces and shocks. Run to
3 us: refined at the start to 10324 cells, then about 46 changes up to
about 19000 cells, the count falling at some (merges) and rising at others.

Checks
  refinementRun_changes       the log has changes that add cells and
                              changes that remove them (merges)
  refinementRun_conservation  from the "Initial totals" line (after the
                              start's refinement) to every "totals" line:
                              mass within 2e-13 relative, E - E0 - unpaid
                              within 2e-12 of E0 (measured: mass 5.4e-14,
                              energy 7.2e-13; merges where a phase is a
                              trace charge the trace's energy to the
                              heaviest phase, phaseRemap)
  refinementRun_uniform       the same case without refinement (720 cells):
                              the same bounds (measured: mass 1.6e-14,
                              energy 6.5e-14)
  refinementRun_restart       a run stopped at its 2 us write (step 149,
                              after 31 changes; its 3 us time removed, its
                              tables cut at 2 us) and resumed (startFrom
                              latestTime) to 3 us: every column of every
                              time history equal to the straight run's
                              within 1e-9 of the column's largest
                              magnitude (a vector's components: of the
                              largest of the three; a wall force's: of the
                              table's largest force), the changes from
                              2 us on the same (cells before, after, per
                              level), the same cells at 3 us. Measured:
                              1.2e-12, 17 changes the same, 19088 cells
  refinementRun_restartAtChange  the same with the run written every 20
                              steps (timePrecision 17, so that the time
                              names are exact) to 1 us, stopped at step 40:
                              a step whose change of the mesh comes
                              before the step, after the write: the
                              resumed run makes it too. Measured 1.6e-10,
                              7 changes the same, 14622 cells at 1 us
  refinementRun_parallel      2 processes (decomposePar, simple along x)
                              to 3 us: the same changes (cells before and
                              after, cells per level) as the serial run's,
                              one by one, and the initial and write totals
                              within 5e-13 relative (mass) and 2e-12
                              (energy) of the serial run's; the cells
                              shared out again (loadBalancer, maxImbalance
                              0.1) at least once, the largest process
                              within 1.1 times the mean at the end.
                              Measured: the 48 changes the same, mass
                              1.2e-13, energy 5.2e-13; 6 balances (the
                              first from 1.30 times the mean), 1.019 at
                              the end
  refinementRun_deltaT        the first 3 steps with refinement against a
                              uniform 0.5 mm mesh's (the finest level; a
                              run towards 1 us stopped after 3 steps, so
                              that its steps land on the write time as the
                              refined run's do): ratio of the mean steps
                              within 20 %. Measured: 1.596e-8 and
                              1.657e-8 s, ratio 0.963; the 2 mm mesh's
                              6.25e-8 s, 3.9 times the refined run's
  refinementRun_wedge*        the same on the template as it is, an
                              axisymmetric wedge closed by walls (1 mm
                              cells, two levels: quadCutter):
                              conservation with changes both ways (same
                              bounds), checkMesh on the last mesh, resumed
                              at 2 us, 2 processes
  refinementRun_wedgeSliding  the wedge with Coulomb friction (mu 0.1)
                              between rod and plate, refined by impactSetup
                              (its refinement entry: exact fractions on the
                              refined mesh), to 3 us (numerics.md 9.3a: the
                              band's per-cell storage follows the start's
                              change): changes both ways, mass and energy
                              within the bounds above, and the heat of
                              friction within 2 % of the uniform 0.25 mm
                              mesh's. Measured: 5.3906e-4 against
                              5.3878e-4 J (5e-4). A run that refines at
                              its start from the 1 mm fractions instead
                              smears the rod's front over 1 mm: its mixed
                              cells melt and hold no friction (0 J)
About 230 s on 2 cores.
"""
import os
import re
import shutil
import sys
import time

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "lib"))

import foamcase as fc  # noqa: E402
from checks import Checks  # noqa: E402

TEMPLATE = os.path.join("templates", "projectileOnPlate")
RUN = os.path.join(fc.RUN_DIR, "refinementRun")

END = 3e-6          # the straight run
STOP = 2e-6         # the first leg of the resumed run (a write time)
PARALLEL_END = END
STEPS_WRITE = 20    # the run written every 20 steps
STEPS_STOP = 40     # stopped at step 40, a step that changes the mesh
STEPS_END = 1e-6
UNIFORM_END = 1e-6  # the 0.5 mm mesh, stopped after its first steps

MASS_TOL = 2e-13
ENERGY_TOL = 2e-12
RESTART_TOL = 1e-9
PARALLEL_MASS_TOL = 5e-13
PARALLEL_ENERGY_TOL = 2e-12
DT_TOL = 0.2
FRICTION_TOL = 0.02  # the wedge's heat of friction against the finest mesh's
N_DT = 3

# The template as it is (axisymmetric), closed: walls at xMax and yMax
WEDGE = [
    ("cellSize    0.25e-3;", "cellSize    %g;"),
    ("        xMax    open;", "        xMax    wall;"),
    ("        yMax    open;", "        yMax    wall;"),
]
WEDGE_CELL = 1e-3

# A closed quarter: symmetry at y = 0 and z = 0, walls elsewhere
QUARTER = [
    ("geometry    axisymmetric;", "geometry    threeD;"),
    ("max         (60e-3 20e-3 0);", "max         (30e-3 12e-3 12e-3);"),
    ("cellSize    0.25e-3;", "cellSize    %g;"),
    ("        xMax    open;", "        xMax    wall;"),
    ("        yMax    open;", "        yMin    symmetry;\n        yMax    wall;"
     "\n        zMin    symmetry;\n        zMax    wall;"),
    ("length      40e-3;", "length      20e-3;"),
    ("min         (-10e-3 0 -1);", "min         (-10e-3 0 0);"),
    ("max         (0 15e-3 1);", "max         (0 12e-3 12e-3);"),
]

PROPERTIES = """FoamFile { version 2.0; format ascii; class dictionary;
           object refinementProperties; }
maxRefinement   2;
refineInterval  5;
nBufferLayers   1;
interfaces      { lower 1e-3; upper 0.999; }
shocks          { jump 0.1; }
"""

CHANGE = re.compile(r"^Refinement: (\d+) -> (\d+) cells, per level "
                    r"(\d+\([\d ]+\))", re.M)
INITIAL = re.compile(r"^Initial totals: mass (\S+) kg, energy (\S+) J", re.M)
TOTALS = re.compile(r"^    totals: mass (\S+) kg, energy (\S+) J, energy "
                    r"added without a payer (\S+) J", re.M)
FRICTION = re.compile(r"^    totals: .*, heat of friction between sliding "
                      r"solids (\S+) J", re.M)
STEP = re.compile(r"^Time = (\S+)  deltaT = (\S+)", re.M)

checks = Checks()


def make_case(name, cell_size, refine, changes=QUARTER, extra=""):
    """The closed quarter (or wedge) set up (impactSetup) on cells of
    cell_size, with or without constant/refinementProperties, extra
    entries added to the impactDict; fields with 17 digits"""
    case = fc.copy_tutorial(TEMPLATE, name, run_dir=RUN)
    path = os.path.join(case, "system", "impactDict")
    with open(path) as f:
        text = f.read()
    for old, new in changes:
        if old not in text:
            raise fc.FoamError("template impactDict: no %r" % old)
        text = text.replace(old, new % cell_size if "%g" in new else new, 1)
    with open(path, "w") as f:
        f.write(text + extra)
    fc.set_entry(case, "system/controlDict", "writePrecision", "17")
    fc.set_entry(case, "system/controlDict", "progressInterval", "0")
    fc.run(case, ["impactSetup"])
    if refine:
        with open(os.path.join(case, "constant", "refinementProperties"),
                  "w") as f:
            f.write(PROPERTIES)
    return case


def read_log(log):
    text = open(log).read()
    changes = [(int(a), int(b), lv) for a, b, lv in CHANGE.findall(text)]
    m = INITIAL.search(text)
    initial = (float(m.group(1)), float(m.group(2))) if m else None
    totals = [tuple(float(v) for v in t) for t in TOTALS.findall(text)]
    steps = [(float(t), float(dt)) for t, dt in STEP.findall(text)]
    # The changes with the time of the step they follow
    timed = []
    t = 0.0
    for line in text.splitlines():
        s = STEP.match(line)
        if s:
            t = float(s.group(1))
        c = CHANGE.match(line)
        if c:
            timed.append((t, int(c.group(1)), int(c.group(2)), c.group(3)))
    return {"changes": changes, "timed": timed, "initial": initial,
            "totals": totals, "steps": steps}


def directions(changes):
    """The number of changes that add cells and that remove cells"""
    return (sum(1 for a, b, lv in changes if b > a),
            sum(1 for a, b, lv in changes if b < a))


def drift(run):
    """Largest relative change of the mass and of E - unpaid from the
    initial totals over the totals lines"""
    m0, e0 = run["initial"]
    dm = max(abs(m - m0) / m0 for m, e, u in run["totals"])
    de = max(abs(e - e0 - u) / abs(e0) for m, e, u in run["totals"])
    return dm, de


def check_conservation(straight, uniform):
    changes = straight["changes"][2:]     # after the start's refinement
    up, down = directions(changes)
    checks.check("refinementRun_changes", up > 0 and down > 0,
                 "%d changes in the run after the start's %s: %d add "
                 "cells, %d remove cells; cells %d to %d"
                 % (len(changes), [(a, b) for a, b, lv in
                                   straight["changes"][:2]],
                    up, down, min(b for a, b, lv in changes),
                    max(b for a, b, lv in changes)))
    for name, run in (("conservation", straight), ("uniform", uniform)):
        if run["initial"] is None or not run["totals"]:
            checks.fail("refinementRun_" + name, "no totals in the log")
            continue
        dm, de = drift(run)
        last = run["totals"][-1]
        checks.check(
            "refinementRun_" + name, dm <= MASS_TOL and de <= ENERGY_TOL,
            "%s, %d totals lines to %g s: largest relative change of the "
            "mass %.2g (bound %g), of E - E0 - unpaid %.2g of E0 (bound "
            "%g); E0 %.15g J, at the end %.15g J, unpaid %g J"
            % ("with refinement" if name == "conservation"
               else "2 mm cells, no refinement", len(run["totals"]), END,
               dm, MASS_TOL, de, ENERGY_TOL, run["initial"][1], last[1],
               last[2]))


def history_names(case):
    return sorted(os.listdir(os.path.join(case, "postProcessing")))


def cut_tables(case, t_end):
    """Cut every time history after t_end (as a run stopped there left
    it)"""
    for name in history_names(case):
        path = os.path.join(case, "postProcessing", name, "0", name + ".dat")
        with open(path) as f:
            lines = f.readlines()
        keep = [l for l in lines if l.startswith("#")
                or float(l.split()[0]) <= t_end * (1 + 1e-9)]
        with open(path, "w") as f:
            f.writelines(keep)


def column_scales(cols, rows):
    """Each column's largest magnitude; a vector's components share the
    largest of the three (an axisymmetric body's radial velocity and a
    slip wall's tangential force are round-off, 1e-11 N against 1e4 N),
    and the wall forces share the table's largest force, the impulses its
    largest impulse (a wall nothing reaches has round-off alone)"""
    scale = np.abs(rows).max(axis=0)
    groups = {}
    for j, c in enumerate(cols):
        m = re.match(r"^(.*)[xyz]$", c)
        if m:
            w = re.match(r"^.*\.([FI])$", m.group(1))
            groups.setdefault(w.group(1) if w else m.group(1), []).append(j)
    for js in groups.values():
        scale[js] = scale[js].max()
    return np.maximum(scale, 1e-300)


def n_cells_at(case, t):
    """Cells of the fields at time t"""
    return len(fc.read_field(case, t, "alpha.rod"))


def check_restart(name, straight_case, straight, stop, end, what):
    """The straight run's case stopped at its write time stop (the later
    times removed, the tables cut there, as a run stopped there leaves
    them) and resumed to end; against the straight run"""
    case = os.path.join(RUN, name)
    if os.path.lexists(case):
        shutil.rmtree(case)
    shutil.copytree(straight_case, case)
    for value, tname in fc.time_dirs(case):
        if value > stop * (1 + 1e-9):
            shutil.rmtree(os.path.join(case, tname))
    for log in [f for f in os.listdir(case) if f.startswith("log.impactFoam")]:
        os.remove(os.path.join(case, log))
    cut_tables(case, stop)
    index = time_index(case, fc.find_time(case, stop))
    resumed = read_log(run_solver(case, end, "log.impactFoam.resumed"))

    worst, where, why = 0.0, None, []
    for table in history_names(straight_case):
        cols, a = fc.read_history(straight_case, table)
        cols2, b = fc.read_history(case, table)
        if cols2 != cols or b.shape != a.shape or \
                not np.all(np.diff(b[:, 0]) > 0):
            why.append("%s: %s rows against %s" % (table, b.shape, a.shape))
            continue
        d = np.abs(b - a) / column_scales(cols, a)
        if d.max() > worst:
            worst = float(d.max())
            i, j = np.unravel_index(np.argmax(d), d.shape)
            where = "%s %s at %.6g s" % (table, cols[j], a[i, 0])
    # The changes the resumed run must make: from the stop's step on (the
    # change at that step follows its write)
    after = [c[1:] for c in straight["timed"] if c[0] >= stop * (1 - 1e-9)]
    again = [c[1:] for c in resumed["timed"]]
    same_changes = after == again
    first_diff = next((i for i, (x, y) in enumerate(zip(after, again))
                       if x != y), None)
    n_a = n_cells_at(straight_case, end)
    n_b = n_cells_at(case, end)
    checks.check(
        "refinementRun_" + name,
        not why and worst <= RESTART_TOL and same_changes and n_a == n_b,
        "%s: stopped at %g s (step %d), resumed to %g s: %s; largest "
        "difference of a column from the straight run's, of its largest: "
        "%.2g (%s; bound %g); changes from %g s on: %d and %d, the same: "
        "%s%s; cells at %g s %d and %d; initial totals of the resumed run "
        "%s"
        % (what, stop, index, end, "; ".join(why) or "the same rows", worst,
           where, RESTART_TOL, stop, len(after), len(again), same_changes,
           "" if first_diff is None else
           " (change %d: %s -> %s against %s -> %s)"
           % (first_diff + 1, again[first_diff][0], again[first_diff][1],
              after[first_diff][0], after[first_diff][1]),
           end, n_a, n_b, resumed["initial"]))


def time_index(case, tname):
    """The step index written with a time"""
    text = open(os.path.join(case, tname, "uniform", "time")).read()
    return int(re.search(r"^index\s+(\d+);", text, re.M).group(1))


def check_parallel(setup_case, straight, run_fn, name="parallel"):
    case = os.path.join(RUN, name)
    if os.path.lexists(case):
        shutil.rmtree(case)
    shutil.copytree(setup_case, case)
    fc.write_decompose_dict(case, 2)
    fc.run(case, ["decomposePar", "-force"])
    par = read_log(run_fn(case, PARALLEL_END, "log.impactFoam.parallel",
                          parallel=True))
    serial = [c[1:] for c in straight["timed"]
              if c[0] <= PARALLEL_END * (1 + 1e-9)]
    pchanges = [c[1:] for c in par["timed"]]
    first_diff = next((i for i, (x, y) in enumerate(zip(serial, pchanges))
                       if x != y), None)
    same = serial == pchanges
    n = min(len(par["totals"]), len(straight["totals"]))
    dm, de = 0.0, 0.0
    pairs = [(straight["initial"], par["initial"])] + \
        list(zip(straight["totals"][:n], par["totals"][:n]))
    for s, p in pairs:
        if s is None or p is None:
            dm = de = float("inf")
            continue
        dm = max(dm, abs(p[0] - s[0]) / s[0])
        de = max(de, abs(p[1] - s[1]) / abs(s[1]))
    # The cells shared out again after changes (maxImbalance 0.1)
    m = re.search(r"(\d+) load balances, the largest process's cells over "
                  r"the mean (\S+) at the end",
                  open(os.path.join(case, "log.impactFoam.parallel")).read())
    balances = int(m.group(1)) if m else 0
    ratio = float(m.group(2)) if m else float("inf")
    ok = same and n >= 1 and dm <= PARALLEL_MASS_TOL and \
        de <= PARALLEL_ENERGY_TOL and balances > 0 and ratio <= 1.1
    checks.check(
        "refinementRun_" + name, ok,
        "2 processes to %g s: %d changes against the serial run's %d, the "
        "same cells before, after and per level: %s%s; initial and %d "
        "write totals: largest relative difference of the mass %.2g "
        "(bound %g), of the energy %.2g (bound %g); %d load balances "
        "(must be > 0), the largest process's cells over the mean %.3f at "
        "the end (bound 1.1)"
        % (PARALLEL_END, len(pchanges), len(serial), same,
           "" if first_diff is None else
           " (first differing change %d: %s against %s)"
           % (first_diff + 1, pchanges[first_diff], serial[first_diff]),
           n, dm, PARALLEL_MASS_TOL, de, PARALLEL_ENERGY_TOL, balances,
           ratio))


def check_delta_t(straight, uniform2):
    fine_case = make_case("uniform05", 0.5e-3, False)
    # Its first steps only: a run towards the first write time (the steps
    # land on it as in the refined run), stopped after N_DT steps
    log = fc.run(fine_case, "impactFoam -endTime %g 2>&1 | awk '{ print; "
                 "fflush() } /^Time = / { n++; if (n >= %d) exit }'"
                 % (UNIFORM_END, N_DT), log="log.impactFoam", check=False,
                 timeout=300)
    fine = read_log(log)
    if len(fine["steps"]) < N_DT or len(straight["steps"]) < N_DT:
        checks.fail("refinementRun_deltaT", "fewer than %d steps" % N_DT)
        return
    dt_ref = np.mean([dt for t, dt in straight["steps"][:N_DT]])
    dt_fine = np.mean([dt for t, dt in fine["steps"][:N_DT]])
    dt_coarse = np.mean([dt for t, dt in uniform2["steps"][:N_DT]])
    ratio = dt_ref / dt_fine
    checks.check(
        "refinementRun_deltaT", abs(ratio - 1) <= DT_TOL,
        "mean of the first %d steps: with refinement (%d cells, finest "
        "0.5 mm) %.4g s, uniform 0.5 mm (%d cells) %.4g s: ratio %.3f "
        "(bound 1 +- %g); uniform 2 mm %.4g s (%.2f times the refined "
        "run's)"
        % (N_DT, straight["changes"][1][1] if len(straight["changes"]) > 1
           else -1, dt_ref, fc.mesh_n_cells(fine_case) or -1, dt_fine,
           ratio, DT_TOL, dt_coarse, dt_coarse / dt_ref))


def run_solver(case, end, log="log.impactFoam", parallel=False):
    cmd = ["impactFoam", "-endTime", "%g" % end]
    if parallel:
        cmd = "mpirun -np 2 --oversubscribe impactFoam -parallel -endTime " \
            "%g" % end
    t0 = time.time()
    path = fc.run(case, cmd, log=log, timeout=600)
    checks.note("%s in %s: %.1f s" % (log, os.path.basename(case),
                                       time.time() - t0))
    return path


def wedge_run():
    """The same on the closed axisymmetric wedge (quadCutter): conservation,
    a resumed run, 2 processes, and a valid mesh at the end"""
    setup = make_case("wedgeSetup", WEDGE_CELL, True, WEDGE)
    case = os.path.join(RUN, "wedgeStraight")
    if os.path.lexists(case):
        shutil.rmtree(case)
    shutil.copytree(setup, case)
    run = read_log(run_solver(case, END))
    changes = run["changes"][2:]
    up, down = directions(changes)
    if run["initial"] is None or not run["totals"]:
        checks.fail("refinementRun_wedgeConservation", "no totals in the log")
    else:
        dm, de = drift(run)
        checks.check(
            "refinementRun_wedgeConservation",
            up > 0 and down > 0 and dm <= MASS_TOL and de <= ENERGY_TOL,
            "the wedge, 1 mm cells refined twice, to %g s: %d changes after "
            "the start's, %d adding cells, %d removing; largest relative "
            "change of the mass %.2g (bound %g), of E - E0 - unpaid %.2g "
            "of E0 (bound %g)"
            % (END, len(changes), up, down, dm, MASS_TOL, de, ENERGY_TOL))
    log = fc.run(case, ["checkMesh", "-latestTime"], log="log.checkMesh",
                 check=False)
    ok = "Mesh OK." in open(log).read()
    checks.check("refinementRun_wedgeMesh", ok,
                 "checkMesh on the wedge's last mesh: %s"
                 % ("Mesh OK" if ok else fc.tail(log)))
    check_restart("wedgeRestart", case, run, STOP, END,
                  "the wedge written every 1 us")
    check_parallel(setup, run, run_solver, "wedgeParallel")


def wedge_sliding_run():
    """The closed wedge with rod and plate sliding (Coulomb), refined by
    impactSetup (exact fractions on the refined mesh): the run goes through
    the start's change and those after it, conserving mass and energy, and
    releases the heat of friction of the uniform mesh of its finest cells"""
    contacts = "\ncontacts { default { type coulomb; mu 0.1; } }\n"
    # impactDict's refinement entry: PROPERTIES without its FoamFile header
    # (its first two lines)
    refinement = "refinement { %s }\n" % " ".join(
        line.strip() for line in PROPERTIES.splitlines()[2:])
    setup = make_case("wedgeSlidingSetup", WEDGE_CELL, False, WEDGE,
                      contacts + refinement)
    uniform = make_case("wedgeSlidingUniform", WEDGE_CELL/4, False, WEDGE,
                        contacts)
    try:
        log = run_solver(setup, END)
        uniform_log = run_solver(uniform, END)
    except fc.FoamError as e:
        checks.fail("refinementRun_wedgeSliding", e.summary)
        return
    run = read_log(log)
    friction = [float(v) for v in FRICTION.findall(open(log).read())]
    friction_uniform = [float(v) for v in
                        FRICTION.findall(open(uniform_log).read())]
    changes = run["changes"]
    up, down = directions(changes)
    if run["initial"] is None or not run["totals"] or not friction \
            or not friction_uniform:
        checks.fail("refinementRun_wedgeSliding",
                    "no totals in the logs: %s" % fc.tail(log))
        return
    dm, de = drift(run)
    heat, heat_uniform = friction[-1], friction_uniform[-1]
    diff = abs(heat - heat_uniform) / heat_uniform \
        if heat_uniform > 0 else float("inf")
    checks.check(
        "refinementRun_wedgeSliding",
        up > 0 and down > 0 and dm <= MASS_TOL and de <= ENERGY_TOL
        and diff <= FRICTION_TOL,
        "the wedge with Coulomb friction, 1 mm cells refined twice by "
        "impactSetup, to %g s: %d changes (the start's %d -> %d cells), %d "
        "adding cells, %d removing; largest relative change of the mass "
        "%.2g (bound %g), of E - E0 - unpaid %.2g of E0 (bound %g); heat of"
        " friction %.6g J against %.6g J on the uniform 0.25 mm mesh "
        "(difference %.2g, bound %g)"
        % (END, len(changes), changes[0][0] if changes else -1,
           changes[0][1] if changes else -1, up, down, dm, MASS_TOL, de,
           ENERGY_TOL, heat, heat_uniform, diff, FRICTION_TOL))


def main():
    missing = fc.require_apps("impactSetup", "impactFoam", "decomposePar",
                              "mpirun")
    if missing:
        checks.fail("refinementRun", "missing: %s" % ", ".join(missing))
        checks.exit()
    t0 = time.time()
    try:
        setup = make_case("setup", 2e-3, True)
        straight_case = os.path.join(RUN, "straight")
        if os.path.lexists(straight_case):
            shutil.rmtree(straight_case)
        shutil.copytree(setup, straight_case)
        straight = read_log(run_solver(straight_case, END))
        uniform_case = make_case("uniform2", 2e-3, False)
        uniform = read_log(run_solver(uniform_case, END))
        check_conservation(straight, uniform)
        check_delta_t(straight, uniform)
        check_restart("restart", straight_case, straight, STOP, END,
                      "written every 1 us")
        # Written every 20 steps: a write time whose step also changes the
        # mesh (after the write)
        steps_case = os.path.join(RUN, "straightSteps")
        if os.path.lexists(steps_case):
            shutil.rmtree(steps_case)
        shutil.copytree(setup, steps_case)
        fc.set_entry(steps_case, "system/controlDict", "writeControl",
                     "timeStep")
        fc.set_entry(steps_case, "system/controlDict", "writeInterval",
                     str(STEPS_WRITE))
        # Times named with every digit: a restart takes its time from the
        # directory's name (OpenFOAM), which timePrecision 6 would cut
        fc.set_entry(steps_case, "system/controlDict", "timePrecision",
                     "17")
        steps = read_log(run_solver(steps_case, STEPS_END))
        stop = [v for v, n in fc.time_dirs(steps_case)
                if v > 0 and time_index(steps_case, n) == STEPS_STOP]
        if not stop:
            raise fc.FoamError("no write at step %d in %s"
                               % (STEPS_STOP, steps_case))
        check_restart("restartAtChange", steps_case, steps, stop[0],
                      STEPS_END, "written every %d steps" % STEPS_WRITE)
        check_parallel(setup, straight, run_solver)
        wedge_run()
        wedge_sliding_run()
    except fc.FoamError as e:
        checks.fail("refinementRun", e.summary)
    checks.note("total %.0f s" % (time.time() - t0))
    checks.exit()


if __name__ == "__main__":
    main()
