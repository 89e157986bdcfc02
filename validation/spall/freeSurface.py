#!/usr/bin/python3
"""Free-surface velocity history of a 1-D plate impact and its spall
estimate (docs/validation.md V12).

Reads every time directory of a 1-D case along x (the spallPlate tutorial):
the free-surface velocity is the mass-weighted velocity U_x of the
outermost 0.1 mm of the phase (its mass at rho0, counted from the right:
the diffuse interface spans a few cells, and the outermost, nearly empty
ones lag behind the surface).
Writes the history (t [s], u [m/s]) and prints the pull-back estimate:
u rises to its first plateau u_peak; after spall it falls to the first
minimum u_min of the pull-back signal; dU = u_peak - u_min, and the
acoustic estimate of the spall strength is sigma = rho0 c_b dU / 2.

    freeSurface.py <case> [--phase copper] [--rho0 8930] [--cb 3940]
                   [--output freeSurfaceVelocity.dat]
"""
import argparse
import os
import sys

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "..", "tests", "lib"))
import foamcase as fc   # noqa: E402


def history(case, phase, rho0=8930.0, layer=1e-4):
    """Times and free-surface velocities of every time directory but 0:
    the mass-weighted velocity of the outermost layer of the phase (the
    mass of `layer` metres at rho0; the diffuse interface spans a few
    cells, whose outermost, nearly empty ones lag behind the surface)."""
    x = fc.cell_centres(case)[:, 0]
    order = np.argsort(x)
    xs = x[order]
    dx = np.gradient(xs)
    ts, us = [], []
    for t, name in fc.time_dirs(case):
        if t <= 0:
            continue
        alpha = fc.read_field(case, name, "alpha." + phase)[order]
        rho = fc.read_field(case, name, "rho." + phase)[order]
        U = fc.read_field(case, name, "U")[order, 0]
        # The surface layer: the outermost copper holding the mass of a
        # layer `layer` thick at rho0, from the right
        m = alpha*rho*dx
        cum = np.cumsum(m[::-1])
        n = np.searchsorted(cum, rho0*layer) + 1
        if cum[-1] < rho0*layer:
            continue
        mm, uu = m[::-1][:n], U[::-1][:n]
        ts.append(t)
        us.append(np.sum(mm*uu)/np.sum(mm))
    return np.array(ts), np.array(us)


def pull_back(t, u):
    """(u_peak, u_min, t_peak, t_min): the plateau the free surface first
    reaches, and the first minimum after it falls below it by more than
    a tenth of the rise."""
    if len(u) < 3 or u.max() <= 0:
        return None
    umax = u.max()
    rise = np.nonzero(u > 0.9*umax)[0][0]
    # The plateau: the largest velocity before the first fall of 10 %
    i = rise
    peak = rise
    while i < len(u) and u[i] > u[peak] - 0.1*umax:
        if u[i] > u[peak]:
            peak = i
        i += 1
    if i >= len(u):
        return (u[peak], None, t[peak], None)
    # The first minimum after the fall
    j = i
    while j + 1 < len(u) and u[j + 1] <= u[j]:
        j += 1
    return (u[peak], u[j], t[peak], t[j])


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("case")
    ap.add_argument("--phase", default="copper")
    ap.add_argument("--rho0", type=float, default=8930)
    ap.add_argument("--cb", type=float, default=3940,
                    help="bulk sound speed [m/s]")
    ap.add_argument("--output", default="freeSurfaceVelocity.dat")
    args = ap.parse_args()

    t, u = history(args.case, args.phase, args.rho0)
    out = os.path.join(args.case, args.output)
    np.savetxt(out, np.column_stack([t, u]), header="t [s]  u [m/s]")
    print("Free-surface velocity history: %s (%d times)" % (out, len(t)))
    pb = pull_back(t, u)
    if pb is None or pb[1] is None:
        print("No pull-back signal")
        return 0
    dU = pb[0] - pb[1]
    print("Peak %.2f m/s at %.3g s, pull-back minimum %.2f m/s at %.3g s:"
          " dU = %.2f m/s, spall estimate rho0 c_b dU/2 = %.4g Pa"
          % (pb[0], pb[2], pb[1], pb[3], dU, 0.5*args.rho0*args.cb*dU))
    return 0


if __name__ == "__main__":
    sys.exit(main())
