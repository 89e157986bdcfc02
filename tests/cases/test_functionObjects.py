#!/usr/bin/python3
"""The time-history function objects of impactFoamFunctionObjects
(src/functionObjects, docs/numerics.md section 10) against what they
must equal.

Case A: the taylorBar tutorial on its coarse mesh (0.4 mm, wedge), 4 us,
fields written every 1 us in ascii at 17 digits, with energyBudget (also a
second one written every 10 steps), wallForce on all the patches that are
not wedges, bodyExtent of the copper:
  fo_energyBudget_totals      the total energy and mass of each row at a
                              time the log prints ("Initial totals",
                              "totals:") equal the log's to 1e-12
                              relative; the unpaid column equals the log's
                              energy added without a payer
  fo_energyBudget_parts       kinetic + internal + elastic = total (1e-12)
  fo_energyBudget_interval    writeControl timeStep, writeInterval 10: a
                              row every 10 steps, equal to the every-step
                              rows at those times
  fo_wallForce_impulse        the sum of the patches' axial impulses from
                              1 to 4 us equals the axial momentum change
                              of the material (copper and air, from the
                              written fields, times 2 pi over the sine
                              of the wedge angle: the full circle) to 1e-11 of the
                              bar's momentum (2e-12 seen: the round-off
                              of the cells' updates over 120 steps)
  fo_wallForce_steps          each row's impulse change is its force times
                              its step (1e-9 of the impulse's range)
  fo_bodyExtent_rodProfile    length, maxRadius, faceRadius, zMin at the
                              written times equal rodProfile's (the same
                              code, rodMeasures; 1e-10 relative: the csv's
                              12 digits); penetration equals the furthest
                              cell centre with alpha >= 1/2 along -x
  fo_probes                   OpenFOAM's probes (libs (sampling)) on
                              alpha.copper, rho.copper, p.copper, p, U
                              and sigmaEq: at the written times the value
                              of the cell holding each probe (to 1e-15 of
                              the field's largest value)
  fo_resultsUnchanged         case A without function objects: every
                              field file of every written time
                              byte-identical (the ledger and the patch
                              forces change nothing)
Case A on two processors (decomposePar, simple 2 1 1):
  fo_parallel                 the serial rows at the last time: energy
                              total to 1e-12, the extent to 1e-12 m, the
                              impulses to 1e-9 of the bar's momentum (the
                              two runs' round-off differs and grows over
                              the steps: 1e-11 seen)
  fo_parallel_energyBudget_*, fo_parallel_wallForce_*: the checks above
                              on the parallel run (its log, its
                              reconstructed fields)
Bad input (taylorBar, one step):
  fo_badInput_phase           bodyExtent with phase nosuch: FatalIOError
                              naming the entry, the value, the valid phases
                              and the file
  fo_badInput_patches         wallForce with patches (nosuch): the same
                              with the valid patches
Rejected steps: V9's 1-D copper leaving air at 5000 m/s without the
vacuum floor (tests/cases/badInput/copperAir), which rejects steps and
retries them shorter until it stops, with energyBudget and wallForce on
its open ends:
  fo_rejectedSteps            one row per accepted step (and the start),
                              at increasing times; the unpaid column the
                              sum of the accepted steps' logged energy set
                              without a payer and in void cells; the impulse of the two ends
                              between the last writes equals the momentum
                              change to 1e-12 (4e-16 seen); every time
                              directory holds the fields (nothing, not
                              even the function objects' state, is
                              written at the time a rejected step left)
Case C: the taylorBar at 2000 m/s with dustDensityRatio 0, 4 us (cells
set without a payer and void cells from 2 us):
  fo_energyBudget_unpaid      the unpaid column equals the log's energy
                              added without a payer (not zero) and the
                              total the log's totals, to 1e-12 relative
Case B: the spallPlate tutorial at 25 um to 1.2 us (the target's free
surface moving), fields every 20 ns at 17 digits, with surfaceVelocity
along +x:
  fo_surfaceVelocity          position and velocity at every written time
                              equal the interpolation of the written
                              alpha.copper and U (the last fall of alpha
                              through 1/2 along x) to 1e-12
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

END_A = 4e-6
END_B = 1.2e-6
END_C = 4e-6

FUNCTIONS_A = """
functions
{
    energy
    {
        type            energyBudget;
        libs            (impactFoamFunctionObjects);
    }
    energy10
    {
        type            energyBudget;
        libs            (impactFoamFunctionObjects);
        writeControl    timeStep;
        writeInterval   10;
    }
    wallForce
    {
        type            wallForce;
        libs            (impactFoamFunctionObjects);
        patches         (xMin xMax yMax axis);
    }
    rod
    {
        type            bodyExtent;
        libs            (impactFoamFunctionObjects);
        phase           copper;
    }
    probes
    {
        type            probes;
        libs            (sampling);
        fields          (alpha.copper rho.copper p.copper p U sigmaEq);
        probeLocations  ((1.1e-3 1.1e-3 0) (5.1e-3 2.1e-3 0)
                         (20.1e-3 5.3e-3 0));
    }
}
"""

FUNCTIONS_REJECTED = """
functions
{
    energy
    {
        type            energyBudget;
        libs            (impactFoamFunctionObjects);
    }
    force
    {
        type            wallForce;
        libs            (impactFoamFunctionObjects);
        patches         (left right);
    }
}
"""

FUNCTIONS_UNPAID = """
functions
{
    energy
    {
        type            energyBudget;
        libs            (impactFoamFunctionObjects);
    }
}
"""

PROBES = [(1.1e-3, 1.1e-3), (5.1e-3, 2.1e-3), (20.1e-3, 5.3e-3)]
PROBED = ["alpha.copper", "rho.copper", "p.copper", "p", "U", "sigmaEq"]


def column(table, name):
    names, rows = table
    return rows[:, names.index(name)]


def row_at(table, t):
    names, rows = table
    i = int(np.argmin(np.abs(rows[:, 0] - t)))
    if abs(rows[i, 0] - t) > 1e-6 * max(abs(t), 1e-12):
        raise fc.FoamError("no row at t = %g" % t)
    return dict(zip(names, rows[i]))


def to_full(case, log="log.impactFoam"):
    """The factor from the log's sums to energyBudget's: the wedge's to the
    full body of revolution, which the log states on a wedge mesh (15
    digits), else 1. It is the mesh's to 1e-10 (meshGeometry.wedge_to_full,
    from one face of points written to 10 digits)."""
    with open(os.path.join(case, log)) as f:
        m = re.search(r"the full body of revolution, as in the time histories"
                      r" and the summary, is (\S+) times them", f.read())
    if not m:
        return 1.0
    factor = float(m.group(1))
    mesh = mg.read_polymesh(case)
    if abs(factor / mg.wedge_to_full(mesh) - 1) > 1e-10:
        raise fc.FoamError("the log's wedge factor %.15g is not the mesh's "
                           "%.15g" % (factor, mg.wedge_to_full(mesh)))
    return factor


def log_totals(case, log="log.impactFoam"):
    """(mass, energy, unpaid) of the log's totals lines, in order: the
    initial one, then one per write time; the full body's on a wedge mesh
    (the log prints the wedge's)"""
    f = to_full(case)
    return [(f * m, f * e, f * u) for m, e, u in log_totals_mesh(case, log)]


def log_totals_mesh(case, log="log.impactFoam"):
    """log_totals as the log prints them (the mesh's sums)"""
    out = []
    with open(os.path.join(case, log)) as f:
        for line in f:
            w = line.split()
            if line.startswith("Initial totals:"):
                out.append((float(w[3]), float(w[6]), 0.0))
            elif line.strip().startswith("totals:"):
                out.append((float(w[2]), float(w[5]), float(w[12])))
    return out


def prepare(case, functions, precision=17):
    """Fields in ascii at full precision; the tutorial's functions block
    replaced by functions"""
    fc.set_entry(case, "system/controlDict", "writeFormat", "ascii")
    fc.set_entry(case, "system/controlDict", "writePrecision",
                 str(precision))
    path = os.path.join(case, "system", "controlDict")
    with open(path) as f:
        text = f.read()
    start = text.find("\nfunctions")
    if start >= 0:
        depth, i = 0, text.index("{", start)
        while True:
            depth += {"{": 1, "}": -1}.get(text[i], 0)
            i += 1
            if depth == 0:
                break
        text = text[:start] + text[i:]
    with open(path, "w") as f:
        f.write(text + functions)


def momentum(case, m, time_name, phases):
    U = fc.read_field(case, time_name, "U")
    P = np.zeros(3)
    for ph in phases:
        a = fc.read_field(case, time_name, "alpha." + ph)
        r = fc.read_field(case, time_name, "rho." + ph)
        P += ((a * r * m.V)[:, None] * U).sum(axis=0)
    return P


def taylor_case(name, parallel=False):
    case = fc.copy_tutorial("taylorBar", name)
    prepare(case, FUNCTIONS_A)
    fc.set_entry(case, "system/controlDict", "writeInterval", "1e-6")
    fc.run(case, ["impactSetup"])
    if parallel:
        fc.write_decompose_dict(case, 2)
        fc.run(case, ["decomposePar", "-force"])
        fc.run(case, "mpirun --oversubscribe -np 2 impactFoam -parallel "
               "-endTime %g" % END_A, log="log.impactFoam")
        fc.run(case, ["reconstructPar"])
    else:
        fc.run(case, ["impactFoam", "-endTime", str(END_A)])
    return case


def check_energy(case, name="fo_energyBudget"):
    energy = fc.read_history(case, "energy")
    totals = log_totals(case)
    times = [t for t, _ in fc.time_dirs(case)]
    if len(totals) != len(times):
        checks.fail(name + "_totals", "%d totals lines for %d "
                    "written times" % (len(totals), len(times)))
        return
    worst = worstMass = worstUnpaid = 0.0
    for t, (mass, e, unpaid) in zip(times, totals):
        row = row_at(energy, t)
        worst = max(worst, abs(row["total"] / e - 1))
        worstMass = max(worstMass, abs(row["mass"] / mass - 1))
        worstUnpaid = max(worstUnpaid, abs(row["unpaid"] - unpaid) / e)
    checks.check(name + "_totals",
                 worst <= 1e-12 and worstMass <= 1e-12
                 and worstUnpaid <= 1e-12,
                 "%d times: total energy within %.2e, mass within %.2e "
                 "relative of the log's totals lines, unpaid within %.2e "
                 "of the energy (bound 1e-12)"
                 % (len(times), worst, worstMass, worstUnpaid))

    parts = column(energy, "kinetic") + column(energy, "internal") \
        + column(energy, "elastic")
    dev = np.max(np.abs(parts / column(energy, "total") - 1))
    names = energy[0]
    phases = sorted({n.split(".")[1] for n in names if "." in n})
    perPhase = max(np.max(np.abs(sum(column(energy, q + "." + p)
                                     for p in phases) - column(energy, q)))
                   for q in ("kinetic", "internal", "elastic",
                             "plasticWork"))
    checks.check(name + "_parts",
                 dev <= 1e-12 and perPhase <= 1e-12 * column(energy,
                                                             "total")[0],
                 "kinetic + internal + elastic = total within %.2e "
                 "relative over %d rows; the phases' columns add up to "
                 "the totals within %.2e J; plastic work of the copper at "
                 "the end %.4g J"
                 % (dev, len(parts), perPhase,
                    column(energy, "plasticWork.copper")[-1]))

    every10 = fc.read_history(case, "energy10")
    worst10 = 0.0
    for r in every10[1]:
        full = row_at(energy, r[0])
        worst10 = max(worst10, abs(full["total"] / r[every10[0].index(
            "total")] - 1))
    nSteps = len(energy[1]) - 1
    expected = nSteps // 10 + 1
    checks.check(name + "_interval",
                 len(every10[1]) == expected and worst10 <= 1e-15,
                 "writeInterval 10: %d rows for %d steps (expected %d), "
                 "totals equal to the every-step rows within %.2e"
                 % (len(every10[1]), nSteps, expected, worst10))


def check_wall_force(case, name="fo_wallForce"):
    m = mg.read_polymesh(case)
    toFull = mg.wedge_to_full(m)
    # From the first write after the start: the fields at 0 are the
    # setFields input, which the solver floors (alphaMin) before the first
    # step
    times = fc.time_dirs(case)
    P0 = momentum(case, m, times[1][1], ["copper", "air"])
    P1 = momentum(case, m, times[-1][1], ["copper", "air"])
    dPx = toFull * (P1[0] - P0[0])
    barP = toFull * abs(P0[0])
    force = fc.read_history(case, "wallForce")
    first = row_at(force, times[1][0])
    last = row_at(force, times[-1][0])
    patches = ["xMin", "xMax", "yMax", "axis"]
    impulse = sum(last[p + ".Ix"] - first[p + ".Ix"] for p in patches)
    err = abs(impulse - dPx) / barP
    checks.check(name + "_impulse", err <= 1e-11,
                 "axial impulse of the patches from %g to %g s %.12e N s, "
                 "momentum change of the material %.12e N s (full "
                 "circle, bar's momentum %.6g N s): difference %.2e of "
                 "the bar's momentum (bound 1e-11); the wall's impulse "
                 "since the start %.6g N s"
                 % (times[1][0], times[-1][0], impulse, dPx, barP, err,
                    last["xMin.Ix"]))

    t = column(force, "Time")
    worst = 0.0
    for p in patches:
        Fx = column(force, p + ".Fx")
        Ix = column(force, p + ".Ix")
        scale = max(np.max(np.abs(Ix)), 1e-300)
        dev = np.abs(np.diff(Ix) - Fx[1:] * np.diff(t)) / scale
        worst = max(worst, float(dev.max()))
    checks.check(name + "_steps", worst <= 1e-9,
                 "impulse change of each row = force times step within "
                 "%.2e of the impulse's range (bound 1e-9: the times' 15 "
                 "digits)" % worst)
    return last, barP


def check_extent(case):
    rp = os.path.join(case, "postProcessing", "rodProfile", "copper.csv")
    tab = np.genfromtxt(rp, delimiter=",", names=True)
    extent = fc.read_history(case, "rod")
    m = mg.read_polymesh(case)
    worst = 0.0
    worstPen = 0.0
    for r in np.atleast_1d(tab):
        row = row_at(extent, float(r["t"]))
        for q in ("length", "maxRadius", "faceRadius", "zMin"):
            worst = max(worst, abs(row[q] - r[q]) / max(abs(r[q]), 1e-3))
        alpha = fc.read_field(case, fc.find_time(case, float(r["t"])),
                              "alpha.copper")
        pen = float(np.max(-m.C[alpha >= 0.5, 0]))
        worstPen = max(worstPen, abs(row["penetration"] - pen))
    checks.check("fo_bodyExtent_rodProfile",
                 worst <= 1e-10 and worstPen <= 1e-12,
                 "%d times: length, maxRadius, faceRadius, zMin within "
                 "%.2e relative of rodProfile's (bound 1e-10); penetration "
                 "within %.2e m of the furthest cell centre with alpha >= "
                 "1/2 (bound 1e-12 m)" % (len(np.atleast_1d(tab)), worst,
                                          worstPen))


def check_unchanged(case):
    """The same run without function objects: every field file of every
    written time byte-identical"""
    plain = fc.copy_tutorial("taylorBar", "functionObjects_none")
    prepare(plain, "")
    fc.set_entry(plain, "system/controlDict", "writeInterval", "1e-6")
    fc.run(plain, ["impactSetup"])
    fc.run(plain, ["impactFoam", "-endTime", str(END_A)])
    compared = differ = 0
    for t, name in fc.time_dirs(plain):
        for f in sorted(os.listdir(os.path.join(plain, name))):
            a = os.path.join(plain, name, f)
            if not os.path.isfile(a):
                continue
            with open(a, "rb") as fa, \
                    open(os.path.join(case, name, f), "rb") as fb:
                differ += fa.read() != fb.read()
            compared += 1
    checks.check("fo_resultsUnchanged", compared > 40 and differ == 0,
                 "%d field files at %d times compared with a run without "
                 "function objects: %d differ"
                 % (compared, len(fc.time_dirs(plain)), differ))


def check_parallel(serial, serialLast, barP):
    try:
        case = taylor_case("functionObjects_parallel", parallel=True)
    except fc.FoamError as e:
        checks.fail("fo_parallel", e.summary)
        checks.note(str(e))
        return
    t = fc.time_dirs(serial)[-1][0]
    es = row_at(fc.read_history(serial, "energy"), t)
    ep = row_at(fc.read_history(case, "energy"), t)
    fp = row_at(fc.read_history(case, "wallForce"), t)
    xs = row_at(fc.read_history(serial, "rod"), t)
    xp = row_at(fc.read_history(case, "rod"), t)
    dE = abs(ep["total"] / es["total"] - 1)
    dI = max(abs(fp[p + ".Ix"] - serialLast[p + ".Ix"])
             for p in ("xMin", "xMax", "yMax", "axis")) / barP
    dX = max(abs(xp[q] - xs[q]) for q in ("length", "maxRadius",
                                          "faceRadius", "zMin",
                                          "penetration"))
    checks.check("fo_parallel", dE <= 1e-12 and dI <= 1e-9 and dX <= 1e-12,
                 "2 processors at t = %g: total energy within %.2e "
                 "relative (bound 1e-12), impulses within %.2e of the "
                 "bar's momentum (bound 1e-9: the runs' round-off, grown "
                 "over the steps), extent within %.2e m (bound 1e-12 m) "
                 "of the serial run" % (t, dE, dI, dX))
    check_energy(case, "fo_parallel_energyBudget")
    check_wall_force(case, "fo_parallel_wallForce")


def read_probes(case, field):
    """Times and values (rows: time, columns: probe[, component]) of
    OpenFOAM's probes file of field"""
    path = os.path.join(case, "postProcessing", "probes", "0", field)
    rows = []
    with open(path) as f:
        for line in f:
            if line.startswith("#") or not line.strip():
                continue
            rows.append([float(v) for v in
                         line.replace("(", " ").replace(")", " ").split()])
    rows = np.array(rows)
    return rows[:, 0], rows[:, 1:]


def check_probes(case):
    """OpenFOAM's probes on the phase fields and the output fields: the
    value of the cell holding the probe at every written time"""
    m = mg.read_polymesh(case)
    r = np.hypot(m.C[:, 1], m.C[:, 2])
    cells = [int(np.argmin((m.C[:, 0] - x)**2 + (r - y)**2))
             for x, y in PROBES]
    worst = 0.0
    compared = 0
    for field in PROBED:
        times, values = read_probes(case, field)
        for t, name in fc.time_dirs(case):
            if t <= 0:
                continue
            i = int(np.argmin(np.abs(times - t)))
            f = np.asarray(fc.read_field(case, name, field), dtype=float)
            expected = f[cells].reshape(-1)
            got = values[i]
            scale = max(np.max(np.abs(f)), 1e-300)
            worst = max(worst, float(np.max(np.abs(got - expected))) / scale)
            compared += 1
    checks.check("fo_probes", compared == len(PROBED) * 4 and worst <= 1e-15,
                 "probes of %s at %d probes: %d field-times compared, "
                 "largest difference %.2e of the field's largest value "
                 "(bound 1e-15)" % (" ".join(PROBED), len(PROBES), compared,
                                    worst))


def surface(x, alpha, U):
    """The last fall of alpha through 1/2 along x: (position, U_x)"""
    order = np.argsort(x)
    x, alpha, U = x[order], alpha[order], U[order]
    inside = np.nonzero(alpha >= 0.5)[0]
    if len(inside) == 0:
        return 0.0, 0.0
    i = inside[-1]
    if i + 1 == len(x):
        return x[i], U[i]
    w = (alpha[i] - 0.5) / (alpha[i] - alpha[i + 1])
    return x[i] + w * (x[i + 1] - x[i]), U[i] + w * (U[i + 1] - U[i])


def check_unpaid():
    """The 2000 m/s bar without the dust rule: cells set without a payer
    and void cells from 2 us; energyBudget's unpaid column against the
    log's"""
    case = fc.copy_tutorial("taylorBar", "functionObjects_unpaid")
    prepare(case, FUNCTIONS_UNPAID)
    fc.set_entry(case, "system/controlDict", "writeInterval", "1e-6")
    fc.impact_phase_properties(case, {"dustDensityRatio": "0"})
    with open(os.path.join(case, "system", "impact"), "w") as f:
        f.write("U (-2000 0 0);\n")
    fc.run(case, ["impactSetup"])
    fc.run(case, ["impactFoam", "-endTime", str(END_C)])
    energy = fc.read_history(case, "energy")
    totals = log_totals(case)
    times = [t for t, _ in fc.time_dirs(case)]
    worst = worstUnpaid = 0.0
    for t, (mass, e, unpaid) in zip(times, totals):
        row = row_at(energy, t)
        worst = max(worst, abs(row["total"] / e - 1))
        worstUnpaid = max(worstUnpaid,
                          abs(row["unpaid"] - unpaid) / max(unpaid, 1e-300))
    unpaid = totals[-1][2]
    checks.check("fo_energyBudget_unpaid",
                 len(totals) == len(times) and unpaid > 0
                 and worst <= 1e-12 and worstUnpaid <= 1e-12,
                 "2000 m/s to %g s: energy added without a payer %.6g J; "
                 "unpaid column within %.2e relative, total within %.2e "
                 "relative of the log's at %d times (bound 1e-12)"
                 % (END_C, unpaid, worstUnpaid, worst, len(times)))


def check_bad_input():
    """An unknown phase (bodyExtent) and an unknown patch (wallForce): the
    run stops with a FatalIOError naming the entry, the value and the
    valid ones"""
    bad = {
        "phase": ("bodyExtent", "phase           nosuch;",
                  ["FOAM FATAL IO ERROR", "phase nosuch", "valid phases",
                   "controlDict"]),
        "patches": ("wallForce", "patches         (nosuch);",
                    ["FOAM FATAL IO ERROR", "patches", "nosuch",
                     "valid patches", "controlDict"]),
    }
    for entry, (kind, line, words) in bad.items():
        case = fc.copy_tutorial("taylorBar", "functionObjects_bad_" + entry)
        prepare(case, """
functions
{
    bad
    {
        type            %s;
        libs            (impactFoamFunctionObjects);
        %s
    }
}
""" % (kind, line))
        fc.run(case, ["impactSetup"])
        log = fc.run(case, ["impactFoam", "-endTime", "1e-8"], check=False)
        with open(log) as f:
            text = f.read()
        missing = [w for w in words if w not in text]
        checks.check("fo_badInput_" + entry, not missing,
                     "%s with %s: the run stops naming %s%s"
                     % (kind, line, ", ".join(words),
                        "" if not missing else "; missing: %s" % missing))


def check_rejected_steps():
    """V9's copper leaving air at 5000 m/s without the vacuum floor: steps
    rejected and retried with shorter steps until the run stops. One row
    per accepted step; the impulse over the last writes equals the
    momentum change"""
    sys.path.insert(0, HERE)
    import test_V9_badInput as v9
    case = v9.prepare("functionObjects_rejected",
                      [v9.set_velocities(-5000.0, 0.0), v9.vacuum_off])
    fc.set_entry(case, "system/controlDict", "writePrecision", "17")
    with open(os.path.join(case, "system", "controlDict"), "a") as f:
        f.write(FUNCTIONS_REJECTED)
    log = fc.run(case, ["impactFoam"], check=False)
    with open(log) as f:
        text = f.read()
    attempts = len(re.findall(r"(?m)^Time = ", text))
    rejected = len(re.findall(r"Step rejected", text))
    stopped = "The last good fields were written" in text
    accepted = attempts - rejected - (1 if stopped else 0)
    force = fc.read_history(case, "force")
    energy = fc.read_history(case, "energy")
    t = column(force, "Time")
    unique = bool(np.all(np.diff(t) > 0))
    unpaidLog = to_full(case) * sum(float(e) for e in re.findall(
        r"(?:set without a payer|void cells).* energy added (\S+) J",
        text))
    unpaid = column(energy, "unpaid")[-1]

    m = mg.read_polymesh(case)
    times = fc.time_dirs(case)
    # Nothing is written at the time a rejected step left (the function
    # objects' state included): every time directory holds the fields
    bare = [name for _, name in times
            if not os.path.isfile(os.path.join(case, name, "U"))]
    (ta, na), (tb, nb) = times[-3], times[-1]
    Pa = momentum(case, m, na, ["copper", "air"])
    Pb = momentum(case, m, nb, ["copper", "air"])
    ra, rb = row_at(force, ta), row_at(force, tb)
    impulse = sum(rb[p + ".Ix"] - ra[p + ".Ix"] for p in ("left", "right"))
    err = abs(impulse - (Pb[0] - Pa[0])) / abs(Pa[0])
    checks.check("fo_rejectedSteps",
                 stopped and rejected > 0 and unique
                 and len(t) == accepted + 1 and len(energy[1]) == len(t)
                 and abs(unpaid - unpaidLog) <= 1e-12 * unpaidLog
                 and err <= 1e-12 and not bare,
                 "%d steps rejected, %d accepted, then the run stops: %d "
                 "rows at increasing times (expected %d); unpaid %.6g J, "
                 "the log's accepted steps %.6g J; impulse from %g to %g s "
                 "%.10g N s, momentum change %.10g N s: %.2e of the "
                 "momentum (bound 1e-12); time directories without the "
                 "fields: %s"
                 % (rejected, accepted, len(t), accepted + 1, unpaid,
                    unpaidLog, ta, tb, impulse, Pb[0] - Pa[0], err,
                    ", ".join(bare) or "none"))


def check_surface_velocity():
    case = fc.copy_tutorial("spallPlate", "functionObjects_spall")
    fc.set_entry(case, "system/controlDict", "writePrecision", "17")
    fc.run(case, ["./Allrun", "-h", "0.025", "-end", str(END_B)],
           log="log.Allrun")
    table = fc.read_history(case, "freeSurface")
    x = fc.cell_centres(case)[:, 0]
    worstX = worstU = 0.0
    n = 0
    uMax = 0.0
    for t, name in fc.time_dirs(case):
        row = row_at(table, t)
        alpha = fc.read_field(case, name, "alpha.copper")
        U = fc.read_field(case, name, "U")[:, 0]
        xs, us = surface(x, alpha, U)
        worstX = max(worstX, abs(row["position"] - xs))
        worstU = max(worstU, abs(row["velocity"] - us))
        uMax = max(uMax, abs(us))
        n += 1
    checks.check("fo_surfaceVelocity",
                 n > 10 and uMax > 50 and worstX <= 1e-15
                 and worstU <= 1e-12 * max(uMax, 1),
                 "%d written times (surface velocity up to %.2f m/s): "
                 "position within %.2e m, velocity within %.2e m/s of the "
                 "interpolated fields (bounds 1e-15 m, 1e-12 relative)"
                 % (n, uMax, worstX, worstU))


def main():
    missing = fc.require_apps("impactFoam", "impactSetup", "setFields",
                              "rodProfile")
    if missing:
        checks.fail("fo_run", "missing " + str(missing))
        checks.exit()
    try:
        case = taylor_case("functionObjects_taylorBar")
        fc.run(case, ["rodProfile", "-phase", "copper", "-withZero"])
    except fc.FoamError as e:
        checks.fail("fo_run", e.summary)
        checks.note(str(e))
        checks.exit()

    check_unchanged(case)
    check_energy(case)
    last, barP = check_wall_force(case)
    check_extent(case)
    check_probes(case)
    if shutil.which("mpirun") and shutil.which("decomposePar"):
        check_parallel(case, last, barP)
    else:
        checks.fail("fo_parallel", "mpirun or decomposePar not found")
    try:
        check_bad_input()
    except fc.FoamError as e:
        checks.fail("fo_badInput", e.summary)
    try:
        check_rejected_steps()
    except fc.FoamError as e:
        checks.fail("fo_rejectedSteps", e.summary)
    try:
        check_unpaid()
    except fc.FoamError as e:
        checks.fail("fo_energyBudget_unpaid", e.summary)
        checks.note(str(e))
    try:
        check_surface_velocity()
    except fc.FoamError as e:
        checks.fail("fo_surfaceVelocity", e.summary)
        checks.note(str(e))
    checks.exit()


if __name__ == "__main__":
    main()
