#!/usr/bin/python3
"""The crater of the hypervelocityImpact tutorial, at every write time.

Reads alpha.aluminium of each time directory (ascii) and the cell centres
0/C (postProcess -func writeCellCentres) of the wedge mesh (x in
[-20, 12] mm, the target's face at x = 0), and measures, below the
target's original face:
  depth     along the row of cells next to the axis, from x = 0 down to
            where alpha.aluminium rises through 1/2 (linear between cell
            centres);
  diameter  twice the radius, along the first row of cells below x = 0,
            out from the axis to where alpha.aluminium rises through 1/2.
Writes crater.dat (t [s], depth [mm], diameter [mm]) and crater.png, and
prints the total energy the solver logged at the first and last write.
"""
import os
import re
import sys

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
X_MIN = -20.0


def entry(path, key):
    m = re.search(r"^%s\s+([^;]+);" % key, open(path).read(), re.M)
    return float(m.group(1))


def field(path, n):
    text = open(path).read()
    m = re.search(r"internalField\s+nonuniform\s+List<scalar>\s*(\d+)\s*\(",
                  text)
    if m is None:
        v = re.search(r"internalField\s+uniform\s+(\S+);", text)
        return np.full(n, float(v.group(1)))
    return np.array(text[m.end():].split(")")[0].split(), float)


def crossing(values, positions, start):
    """Where values first rise through 1/2, scanning in order from start
    (linear between cell centres): start if the first value is already
    above 1/2 (no crater there), the last position if none is."""
    if values[0] >= 0.5:
        return start
    for i in range(1, len(values)):
        if values[i] >= 0.5:
            f = (0.5 - values[i - 1]) / (values[i] - values[i - 1])
            return positions[i - 1] + f * (positions[i] - positions[i - 1])
    return positions[-1]


def centres(path):
    """The cell centres of 0/C [mm]"""
    text = open(path).read()
    m = re.search(r"internalField\s+nonuniform\s+List<vector>\s*(\d+)\s*\(",
                  text)
    body = text[m.end():]
    values = re.findall(r"\(([^()]*)\)", body[:body.index("\n)")])
    return 1e3 * np.array([v.split() for v in values], float)


def main():
    C = centres(os.path.join(HERE, "0", "C"))
    n = len(C)
    x, r = C[:, 0], np.hypot(C[:, 1], C[:, 2])
    # The row next to the axis below the face, downwards; the first row
    # below the face, outwards
    axis = np.isclose(r, r.min(), rtol=1e-6, atol=1e-9)
    below = np.where(axis & (x < 0))[0]
    below = below[np.argsort(-x[below])]
    top = x[x < 0].max()
    row = np.where(np.isclose(x, top, rtol=0, atol=1e-9))[0]
    row = row[np.argsort(r[row])]
    times = sorted((d for d in os.listdir(HERE)
                    if re.match(r"^[0-9.eE+-]+$", d) and float(d) > 0),
                   key=float)
    rows = []
    for t in times:
        path = os.path.join(HERE, t, "alpha.aluminium")
        if not os.path.exists(path):
            continue
        a = field(path, n)
        depth = max(0.0, -crossing(a[below], x[below], 0.0))
        radius = crossing(a[row], r[row], 0.0)
        rows.append((float(t), depth, 2 * radius))
    rows = np.array(rows)
    np.savetxt(os.path.join(HERE, "crater.dat"), rows, fmt="%.6g",
               header="t [s], depth [mm], diameter [mm] (below x = 0)")
    for t, d, w in rows:
        print("t = %8.3g s: crater depth %6.3f mm, diameter %6.3f mm"
              % (t, d, w))

    log = os.path.join(HERE, "log.impactFoam")
    if os.path.exists(log):
        text = open(log).read()
        e0 = re.search(r"Initial totals: mass \S+ kg, energy (\S+) J", text)
        last = re.findall(r"totals: mass \S+ kg, energy (\S+) J, energy "
                          r"added without a payer (\S+) J", text)
        if e0 and last:
            E0, E1, added = float(e0.group(1)), float(last[-1][0]), \
                float(last[-1][1])
            print("total energy (2-degree wedge) %.10g J -> %.10g J: drift "
                  "%.2e, of which %.3g J added without a payer (vacuum "
                  "floor, trace resets)" % (E0, E1, E1 / E0 - 1, added))

    try:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
    except ImportError:
        print("no matplotlib: crater.png not written", file=sys.stderr)
        return 0
    fig, ax = plt.subplots(figsize=(6, 4))
    ax.plot(1e6 * rows[:, 0], rows[:, 1], "o-", label="depth")
    ax.plot(1e6 * rows[:, 0], rows[:, 2], "s-", label="diameter")
    ax.set_xlabel("t [us]")
    ax.set_ylabel("crater [mm]")
    ax.set_title("Aluminium sphere 6.35 mm on aluminium")
    ax.grid(True, alpha=0.3)
    ax.legend()
    fig.tight_layout()
    fig.savefig(os.path.join(HERE, "crater.png"), dpi=120)
    return 0


if __name__ == "__main__":
    sys.exit(main())
