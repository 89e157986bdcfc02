"""Shared pieces of the copper rod validations (docs/validation.md W1, W2, W4):
running a tutorial copy at a cell size, reading rodProfile's tables,
reference numbers, Taylor's estimate, plots and the markdown report.

Standard library plus numpy and matplotlib (Debian's /usr/bin/python3).
"""
import csv
import math
import os
import subprocess
import sys
import time

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.normpath(os.path.join(HERE, "..", ".."))
sys.path.insert(0, os.path.join(ROOT, "tests", "lib"))
import foamcase as fc  # noqa: E402

# W1 (docs/validation.md): the copper bar and its reference band
L0 = 32.4e-3          # m
R0 = 3.2e-3           # m
V0 = 227.0            # m/s
RHO = 8930.0          # kg/m^3
SIGMA_Y = 4e8         # Pa (initial yield; hardening 1e8 Pa)
# The converged Lagrangian finite-element results (docs/validation.md W1:
# Foulk et al. 2021 Q1/P0 7.22 mm; Sierra/SM composite tetrahedra
# extrapolated to h = 0: 7.226 mm, 21.43 mm)
L_BAND = (21.42e-3, 21.43e-3)
R_BAND = (7.22e-3, 7.23e-3)
L_TOL = 0.01          # within 1 % of the band on the 0.2 mm mesh
R_TOL = 0.01
FINE_TOL = 0.005      # within 0.5 % on the finest mesh
W2_TOL = 0.01         # rod-on-rod within 1 % of the Taylor bar
# The history of the finite-element run behind the band (Sierra/SM
# composite tetrahedra, h = 0.19 mm; source in the file's header): compared
# with the runs' L(t), R(t) as a diagnostic, not a decision
REF_HISTORY = os.path.join(ROOT, "validation", "taylorBar", "reference",
                           "sierra-ct-h0.19-history.csv")
REF_LABEL = "FE (Sierra/SM, h = 0.19 mm)"
W4_TOL = 0.20         # Taylor's apparent yield within 20 % of sigma_Y
# The mushroom radius compared with the FE: rodProfile's faceRadius, the
# outline extended from the first two cell rows to the impact face, where
# the FE reads its face nodes (docs/validation.md W1). maxRadius, the
# largest radius read at the rows' cell centres (z = h/2 for the first
# row), is shown beside it; it is first-order short where the foot slopes.
FACE_RADIUS = "faceRadius"
ROW_RADIUS = "maxRadius"


def band_error(value, band):
    """Relative distance of value from the band [lo, hi] (0 inside)."""
    lo, hi = band
    if value < lo:
        return (value - lo) / lo
    if value > hi:
        return (value - hi) / hi
    return 0.0


def taylor_yield(L1, X, V=V0, rho=RHO, L=L0):
    """Taylor's rigid-plastic estimate of the dynamic yield stress:
    sigma/(rho V^2) = (L0 - X)/(2 (L0 - L1) ln(L0/X))."""
    return rho * V * V * (L - X) / (2.0 * (L - L1) * math.log(L / X))


def progress(msg):
    sys.stdout.write(msg + "\n")
    sys.stdout.flush()


def copy_case(tutorial, dest):
    """A clean copy of a tutorial at dest (tests/lib/foamcase's
    copy_tutorial: no mesh, time directories or logs)."""
    return fc.copy_tutorial(tutorial, os.path.basename(dest),
                            os.path.dirname(dest))


def finished_run(case, h_mm, end=None):
    """Wall time (s, from log.impactFoam's ExecutionTime; 0 when absent) of
    a run of case at cell size h_mm that reached its end time (80 us
    unless given), else None: --reuse takes it instead of running again."""
    try:
        # impactSetup logs "Cell size <m> m (option -cellSize)"
        with open(os.path.join(case, "log.impactSetup")) as f:
            h = [1e3 * float(ln.split()[2]) for ln in f
                 if ln.startswith("Cell size ")]
        tab = read_table(case)
    except (OSError, IndexError, KeyError, ValueError):
        return None
    # run_case hands Allrun the cell size as "%g" (0.133333 for 2/15 mm)
    if not h or abs(h[0] - float("%g" % h_mm)) > 1e-9 \
            or tab["t"][-1] < (end or 80e-6) * (1 - 1e-6):
        return None
    wall = 0.0
    try:
        with open(os.path.join(case, "log.impactFoam")) as f:
            for line in f:
                if line.startswith("ExecutionTime"):
                    wall = float(line.split()[6])
    except (OSError, IndexError, ValueError):
        pass
    return wall


def prepare_run(tutorial, case, h_mm, np_, reuse, label, end=None,
                modify=None, speed=None):
    """Run tutorial at cell size h_mm (and speed, Allrun -v, when given) in
    case (a fresh copy, given to modify(case) first when given) and return
    the wall time; with reuse, a finished run already there is taken as
    is."""
    if reuse:
        wall = finished_run(case, h_mm, end)
        if wall is not None:
            progress("%s h = %g mm: reusing the finished run in %s"
                     % (label, h_mm, case))
            return wall
    copy_case(tutorial, case)
    if modify:
        modify(case)
    progress("%s h = %g mm: running in %s" % (label, h_mm, case))
    return run_case(case, h_mm, np_, end=end, label=label, speed=speed)


def run_case(case, h_mm, np_=1, end=None, label="", speed=None):
    """./Allrun -h h [-np N] [-end t] [-v speed] in case, with a progress
    line from the solver log every 20 s. Returns the wall time in s."""
    cmd = ["./Allrun", "-h", "%g" % h_mm]
    if speed is not None:
        cmd += ["-v", "%g" % speed]
    if np_ > 1:
        cmd += ["-np", str(np_)]
    if end:
        cmd += ["-end", "%g" % end]
    t0 = time.time()
    log = open(os.path.join(case, "log.Allrun"), "w")
    proc = subprocess.Popen(cmd, cwd=case, stdout=log,
                            stderr=subprocess.STDOUT)
    end_time = end or 80e-6
    last = 0
    while proc.poll() is None:
        time.sleep(2)
        if time.time() - last > 20:
            last = time.time()
            t = solver_time(case)
            if t is not None:
                progress("  %s h = %g mm: t = %5.1f us of %g us (%3.0f %%), "
                         "%4.0f s elapsed"
                         % (label, h_mm, t * 1e6, end_time * 1e6,
                            100 * t / end_time, time.time() - t0))
    log.close()
    if proc.returncode != 0:
        with open(os.path.join(case, "log.Allrun")) as f:
            tail = f.read()[-3000:]
        raise RuntimeError("Allrun failed in %s:\n%s" % (case, tail))
    return time.time() - t0


def solver_time(case):
    """Latest 'Time = ' of log.impactFoam, or None."""
    path = os.path.join(case, "log.impactFoam")
    try:
        with open(path, "rb") as f:
            f.seek(0, 2)
            size = f.tell()
            f.seek(max(0, size - 4000))
            tail = f.read().decode(errors="replace")
    except OSError:
        return None
    t = None
    for line in tail.splitlines():
        if line.startswith("Time = "):
            try:
                t = float(line.split()[2])
            except (IndexError, ValueError):
                pass
    return t


def read_table(case, phase="copper"):
    """rodProfile's table as a dict of lists (floats)."""
    path = os.path.join(case, "postProcessing", "rodProfile", phase + ".csv")
    with open(path) as f:
        rows = list(csv.DictReader(f))
    if FACE_RADIUS not in rows[0]:
        raise RuntimeError("%s has no %s column: measured by an older "
                           "rodProfile; run rodProfile -phase %s -R0 %g "
                           "-withZero in %s again"
                           % (path, FACE_RADIUS, phase, R0, case))
    return {k: [float(r[k]) for r in rows] for k in rows[0]}


def read_profile(case, time_name, phase="copper"):
    """z, r of the rod profile at a time directory name."""
    path = os.path.join(case, "postProcessing", "rodProfile", time_name,
                        "profile_" + phase + ".csv")
    z, r = [], []
    with open(path) as f:
        for row in csv.DictReader(f):
            z.append(float(row["z"]))
            r.append(float(row["radius"]))
    return z, r


def last_time_name(case):
    names = [n for n in os.listdir(os.path.join(case, "postProcessing",
                                                "rodProfile"))
             if n[0].isdigit()]
    return max(names, key=float)


def read_measured(path):
    """A user's measured profiles: CSV with columns t, length, diameter
    (SI units; header names containing 't', 'length', 'diam')."""
    with open(path) as f:
        rows = list(csv.reader(f))
    head = [h.strip().lower() for h in rows[0]]

    def col(key):
        for i, h in enumerate(head):
            if key in h:
                return i
        raise ValueError("%s: no column with '%s' in %s" % (path, key, head))
    it, il, idia = col("t"), col("length"), col("diam")
    data = [(float(r[it]), float(r[il]), float(r[idia])) for r in rows[1:]
            if r]
    return data


def read_reference_history(path=REF_HISTORY):
    """The reference history: dict of lists t, radius, length (SI), from
    a CSV whose comment lines start with '#'."""
    with open(path) as f:
        rows = list(csv.DictReader(ln for ln in f if not ln.startswith("#")))
    return {k: [float(r[k]) for r in rows] for k in ("t", "radius", "length")}


def interpolate(ts, ys, t):
    """ys(t) by linear interpolation in the increasing ts (None outside)."""
    if not ts or t < ts[0] or t > ts[-1]:
        return None
    import numpy as np
    return float(np.interp(t, ts, ys))


def history_comparison(tab, ref, times_us=(5, 10, 20, 30, 40, 50, 60, 70,
                                           80), radius=FACE_RADIUS):
    """Rows (t [us], L, L_ref, R, R_ref) [m] at the given times, the run's
    table (its radius column) and the reference each interpolated linearly;
    times outside either record are left out."""
    rows = []
    for tu in times_us:
        t = tu * 1e-6
        L = interpolate(tab["t"], tab["length"], t)
        R = interpolate(tab["t"], tab[radius], t)
        Lr = interpolate(ref["t"], ref["length"], t)
        Rr = interpolate(ref["t"], ref["radius"], t)
        if None not in (L, R, Lr, Rr):
            rows.append((tu, L, Lr, R, Rr))
    return rows


def plot_histories(runs, png, title, measured=None, per_rod=1.0,
                   reference=None, radius=FACE_RADIUS):
    """L(t) and R(t) (the tables' radius column) of several runs
    [(label, table)] against the band (and a reference history dict t,
    radius, length when given)."""
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, ax = plt.subplots(1, 2, figsize=(11, 4.2))
    for label, tab in runs:
        t = [x * 1e6 for x in tab["t"]]
        ax[0].plot(t, [x * 1e3 / per_rod for x in tab["length"]], label=label)
        ax[1].plot(t, [x * 1e3 for x in tab[radius]], label=label)
    for a, band, name in ((ax[0], L_BAND, "length"),
                          (ax[1], R_BAND, "radius")):
        a.axhspan(band[0] * 1e3, band[1] * 1e3, color="0.8",
                  label="reference band (final)")
        a.set_xlabel("t [us]")
        a.set_ylabel("%s [mm]" % name)
        a.grid(True, alpha=0.3)
    if reference:
        t = [x * 1e6 for x in reference["t"]]
        ax[0].plot(t, [x * 1e3 for x in reference["length"]], "k--",
                   lw=1, label=REF_LABEL)
        ax[1].plot(t, [x * 1e3 for x in reference["radius"]], "k--",
                   lw=1, label=REF_LABEL)
    if measured:
        ax[0].plot([m[0] * 1e6 for m in measured],
                   [m[1] * 1e3 / per_rod for m in measured], "ko",
                   label="measured")
        ax[1].plot([m[0] * 1e6 for m in measured],
                   [m[2] * 0.5e3 for m in measured], "ko", label="measured")
    ax[0].set_title("rod length" + (" (per rod)" if per_rod != 1 else ""))
    ax[1].set_title("mushroom radius" + (" at the impact face"
                                         if radius == FACE_RADIUS else ""))
    ax[0].legend(fontsize=8)
    fig.suptitle(title)
    fig.tight_layout()
    fig.savefig(png, dpi=110)
    plt.close(fig)


def plot_profiles(profiles, png, title):
    """Final profiles r(z) [(label, z, r)]."""
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, ax = plt.subplots(figsize=(9, 3.2))
    for label, z, r in profiles:
        ax.plot([x * 1e3 for x in z], [x * 1e3 for x in r], label=label)
    ax.axhline(R0 * 1e3, color="0.6", ls=":", label="R0")
    ax.set_xlabel("z [mm]")
    ax.set_ylabel("r [mm]")
    ax.set_title(title)
    ax.set_ylim(0, 8)
    ax.grid(True, alpha=0.3)
    ax.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(png, dpi=110)
    plt.close(fig)


def plot_convergence(hs, Ls, Rs, png, title):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, ax = plt.subplots(1, 2, figsize=(10, 3.8))
    ax[0].plot(hs, [x * 1e3 for x in Ls], "o-")
    ax[0].axhspan(L_BAND[0] * 1e3, L_BAND[1] * 1e3, color="0.8")
    ax[0].set_ylabel("final length [mm]")
    ax[1].plot(hs, [x * 1e3 for x in Rs], "o-")
    ax[1].axhspan(R_BAND[0] * 1e3, R_BAND[1] * 1e3, color="0.8")
    ax[1].set_ylabel("mushroom radius at the impact face [mm]")
    for a in ax:
        a.set_xlabel("cell size h [mm]")
        a.invert_xaxis()
        a.grid(True, alpha=0.3)
    fig.suptitle(title)
    fig.tight_layout()
    fig.savefig(png, dpi=110)
    plt.close(fig)


def converging(values):
    """Mesh convergence of a sequence from coarse to fine: the changes
    between successive meshes shrink (or the last is below 0.5 %). None
    when fewer than three meshes were run."""
    if len(values) < 3:
        return None
    d1 = abs(values[-2] - values[-3])
    d2 = abs(values[-1] - values[-2])
    return d2 <= d1 or d2 <= 0.005 * abs(values[-1])
