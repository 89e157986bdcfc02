#!/usr/bin/env python3
"""Markdown report of a bench/Allrun run: reads run/<config>/summary.<r>.json
(written by timeSteps.py summary) and, when present, the perf reports in
run/profile/<config>/; prints the report and writes it to --output."""

import argparse
import json
import os
import re
import sys

# (directory, case, solver, order) in table order
CONFIGS = [
    ("gas2D-order1", "gas2D", "impactFoam", "1"),
    ("gas2D-order2", "gas2D", "impactFoam", "2"),
    ("gas2D-rhoCentralFoam", "gas2D", "rhoCentralFoam", "2 (KT, van Leer)"),
    ("copperAir2D-order2", "copperAir2D", "impactFoam", "2"),
]
REFERENCE = "gas2D-rhoCentralFoam"
PERF_LINE = re.compile(r"^\s+([0-9.]+)%\s+(?:\[\.\]|\[k\])?\s*(.+?)\s*$")


def readSummaries(runDir, name, repeats):
    out = []
    for r in range(1, repeats + 1):
        path = os.path.join(runDir, name, "summary.%d.json" % r)
        with open(path) as f:
            out.append(json.load(f))
    return out


def best(values):
    values = [v for v in values if v is not None]
    return min(values) if values else None


def fmt(x, spec="%.0f"):
    return "n/a" if x is None else spec % x


def perfTop(path, count):
    """The first count (percent, name) rows of a perf report --stdio"""
    rows = []
    if not os.path.isfile(path):
        return rows
    with open(path) as f:
        for line in f:
            if line.startswith("#"):
                continue
            m = PERF_LINE.match(line)
            if m:
                name = re.sub(r"\s+-\s+-\s*$", "", m.group(2)).strip()
                rows.append((float(m.group(1)), name))
                if len(rows) == count:
                    break
    return rows


def readScalarField(path):
    """internalField of an ascii volScalarField as a list, None if uniform"""
    with open(path) as f:
        text = f.read()
    m = re.search(r"internalField\s+nonuniform\s+List<scalar>\s*(\d+)\s*\(", text)
    if not m:
        return None
    n = int(m.group(1))
    return [float(v) for v in text[m.end():].split(None, n)[:n]]


def latestTime(caseDir):
    times = []
    for d in os.listdir(caseDir):
        try:
            t = float(d)
        except ValueError:
            continue
        if t > 0 and os.path.isdir(os.path.join(caseDir, d)):
            times.append((t, d))
    return max(times) if times else None


def fieldDifference(runDir, field):
    """(time name, [(order, relative L1 difference)]) of impactFoam's gas
    runs against rhoCentralFoam's at their common last time, or None"""
    ref = latestTime(os.path.join(runDir, REFERENCE))
    if ref is None:
        return None
    try:
        b = readScalarField(os.path.join(runDir, REFERENCE, ref[1], field))
        out = []
        for name, order in (("gas2D-order1", "1"), ("gas2D-order2", "2")):
            t = latestTime(os.path.join(runDir, name))
            if t is None or abs(t[0] - ref[0]) > 1e-9*ref[0]:
                continue
            x = readScalarField(os.path.join(runDir, name, t[1], field))
            if x is None or b is None or len(x) != len(b):
                continue
            out.append((order, sum(abs(u - v) for u, v in zip(x, b))
                        / sum(abs(v) for v in b)))
    except (OSError, ValueError):
        return None
    return (ref[1], out) if out else None


def main():
    p = argparse.ArgumentParser()
    p.add_argument("--run-dir", required=True)
    p.add_argument("--repeats", type=int, required=True)
    p.add_argument("--cells", type=int, required=True)
    p.add_argument("--n", type=int, required=True)
    p.add_argument("--warmup", type=int, required=True)
    p.add_argument("--gas-dt", required=True)
    p.add_argument("--date", required=True)
    p.add_argument("--nproc", required=True)
    p.add_argument("--cpu", required=True)
    p.add_argument("--commit", required=True)
    p.add_argument("--openfoam", required=True)
    p.add_argument("--load", required=True)
    p.add_argument("--default-malloc", action="store_true")
    p.add_argument("--seconds", required=True)
    p.add_argument("--profile-dir", required=True)
    p.add_argument("--output", required=True)
    a = p.parse_args()

    data = {}
    for name, case, solver, order in CONFIGS:
        s = readSummaries(a.run_dir, name, a.repeats)
        data[name] = {
            "wall": best(x["nsPerCellStep"] for x in s),
            "walls": [x["nsPerCellStep"] for x in s],
            "cpu": best(x["cpuNsPerCellStep"] for x in s),
            "median": best(x["medianNsPerCellStep"] for x in s),
            "timed": s[0]["timedSteps"],
            "steps": s[0]["steps"],
            "dtMin": min(x["dtMin"] for x in s),
            "dtMax": max(x["dtMax"] for x in s),
            "coMax": best(x["coMax"] for x in s),
            "start": best(x["startSeconds"] for x in s),
            "solverCpu": [x["cpuLoopSecondsSolver"] for x in s],
            "procCpu": [x["cpuLoopSecondsProc"] for x in s],
        }
    ref = data[REFERENCE]

    def ratio(name, key):
        if data[name][key] is None or ref[key] is None:
            return None
        return data[name][key]/ref[key]

    lines = []
    w = lines.append
    w("# impactFoam bench results")
    w("")
    w("- Date: %s" % a.date)
    w("- Machine: %s, nproc %s (all runs serial)" % (a.cpu, a.nproc))
    w("- impactFoam: %s; OpenFOAM %s (Debian's rhoCentralFoam)"
      % (a.commit, a.openfoam))
    w("- Mesh: %d x %d = %d cells on the unit square, 2-D (one cell thick)"
      % (a.n, a.n, a.cells))
    w("- Allocator: %s" % (
        "glibc's defaults for every run" if a.default_malloc else
        "rhoCentralFoam with glibc's malloc keeping what is freed"
        " (GLIBC_TUNABLES mmap_threshold 256 MB, trim_threshold 1 GB: its"
        " faster figure on this machine type), impactFoam with glibc's"
        " defaults (its faster one); bench/Allrun -d: defaults for both"))
    w("- Load average (1, 5, 15 min) before -> after the timed runs: %s;"
      " timed runs took %s s" % (a.load, a.seconds))
    w("- Each configuration ran %d times, interleaved; the table gives the"
      " fastest repeat. The time loop leaves out the first %d steps and the"
      " last one (it writes the fields): ns/cell/step = loop wall time /"
      " (cells x steps timed)." % (a.repeats, a.warmup))
    w("- CPU ns/cell/step: the same from the solver process's CPU time (what"
      " the wall figure would be on an idle core); ratio = ns/cell/step over"
      " rhoCentralFoam's on the gas case (below 1: faster than"
      " rhoCentralFoam).")
    w("")
    w("| case | solver | order | steps timed | step (s) | max Courant |"
      " wall ns/cell/step | (all repeats) | CPU ns/cell/step |"
      " ratio (wall) | ratio (CPU) |")
    w("|---|---|---|---:|---|---:|---:|---|---:|---:|---:|")
    for name, case, solver, order in CONFIGS:
        d = data[name]
        if abs(d["dtMax"] - d["dtMin"]) <= 1e-6*d["dtMax"]:
            step = "%.4g" % d["dtMax"]
        else:
            step = "%.4g-%.4g" % (d["dtMin"], d["dtMax"])
        w("| %s | %s | %s | %d | %s | %s | %s | %s | %s | %s | %s |" % (
            case, solver, order, d["timed"], step,
            fmt(d["coMax"], "%.2f"),
            fmt(d["wall"]),
            ", ".join("%.0f" % x for x in d["walls"]),
            fmt(d["cpu"]),
            fmt(ratio(name, "wall"), "%.2f"),
            fmt(ratio(name, "cpu"), "%.2f"),
        ))
    w("")

    w("Target: the gas case no slower than rhoCentralFoam per cell-step.")
    for name, order in (("gas2D-order2", "2"), ("gas2D-order1", "1")):
        rw, rc = ratio(name, "wall"), ratio(name, "cpu")

        def verdict(r):
            return "n/a" if r is None else ("met" if r <= 1.0 else "not met")
        w("- impactFoam order %s: %s x rhoCentralFoam by wall time (%s),"
          " %s x by CPU time (%s)" % (order, fmt(rw, "%.2f"), verdict(rw),
                                      fmt(rc, "%.2f"), verdict(rc)))
    cu, g2 = data["copperAir2D-order2"], data["gas2D-order2"]
    if cu["wall"] and g2["wall"] and cu["cpu"] and g2["cpu"]:
        w("- copper-air costs %.1f x (wall), %.1f x (CPU) the single-phase"
          " gas per cell-step (both order 2)."
          % (cu["wall"]/g2["wall"], cu["cpu"]/g2["cpu"]))
    # rhoCentralFoam reports its own CPU time each step: a check of the
    # outside clock
    pairs = [(x, y) for x, y in zip(ref["solverCpu"], ref["procCpu"])
             if x is not None and y is not None and y > 0]
    if pairs:
        w("- Check of the timing: over the timed window rhoCentralFoam's own"
          " ExecutionTime sums to %s s against %s s of process CPU time"
          " measured from outside." % (
              ", ".join("%.2f" % x for x, _ in pairs),
              ", ".join("%.2f" % y for _, y in pairs)))
    walls = [d["wall"]/d["cpu"] for d in data.values()
             if d["wall"] and d["cpu"]]
    if walls and max(walls) > 1.15:
        w("- The machine was busy (load above): wall time was up to %.1f x"
          " the solver's CPU time, so the wall figures and their ratios carry"
          " the noise of other work; the CPU columns compare the solvers"
          " themselves." % max(walls))
    diff = fieldDifference(a.run_dir, "p")
    if diff:
        w("- Same problem: at the end (t = %s s) the pressure of impactFoam"
          " differs from rhoCentralFoam's by %s (relative L1)." % (
              diff[0], ", ".join("%.2f %% at order %s" % (100*e, o)
                                 for o, e in diff[1])))
    w("")

    profiles = []
    for name, label in (("gas2D-order2", "gas2D, impactFoam order 2"),
                        ("copperAir2D-order2", "copperAir2D, impactFoam order 2")):
        top = perfTop(os.path.join(a.profile_dir, name, "perf.symbols"), 15)
        dsos = perfTop(os.path.join(a.profile_dir, name, "perf.dsos"), 6)
        if top:
            profiles.append((label, top, dsos))
    if profiles:
        w("## Profile")
        w("")
        w("perf record of a short run of impactFoam (40 gas steps, 20"
          " copper-air steps; start-up included, no field write); self time"
          " per function.")
        w("")
        for label, top, dsos in profiles:
            w("%s; by library: %s" % (label, ", ".join(
                "%s %.1f %%" % (n, pc) for pc, n in dsos)))
            w("")
            w("| self % | function |")
            w("|---:|---|")
            for pc, n in top:
                w("| %.1f | `%s` |" % (pc, n))
            w("")

    text = "\n".join(lines)
    print(text)
    if a.output != "-":
        with open(a.output, "w") as f:
            f.write(text)
        print("bench: wrote %s" % a.output)
    return 0


if __name__ == "__main__":
    sys.exit(main())
