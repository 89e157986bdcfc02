#!/usr/bin/python3
"""V4 (docs/validation.md): speeds of small longitudinal and shear pulses in
copper against the model's acoustic speeds at rest (docs/model.md):

    c_L = sqrt(c_h^2 + 4 mu / (3 rho0)),  c_h^2 = gamma (p + pInf) / rho0
    c_T = sqrt(mu / rho0)

The tutorial copperPulses is run unchanged (./Allrun): elastic copper
(rho0 8900, stiffened gas 4.22 / 3.42e10, separable a = 1/2, mu 4.5e10,
no plasticity) at rest at p = 1e5 Pa on [0, 1] m, 2000 cells, with the
initial velocity U = 0.1 exp(-((x - 0.5)/0.02)^2) (1, 1, 0) m/s. Each bump
splits into a left- and a right-going pulse of half its amplitude: the
u_x pulses are longitudinal, the u_y pulses transverse; at 0.1 m/s (strain
2e-5) the two families do not interact to within 1e-8.

Measurement: the centroid X = sum x u / sum u of the right-going pulse,
summed over the cells x > x0 = 0.5 (half-way between the two halves, which
are separated by 2 c t, more than 10 pulse widths at both times), at
t1 = 4e-5 s and t2 = 8e-5 s. Numerical diffusion spreads a pulse
symmetrically about its centroid, so the centroid of a first-order upwind
solution moves at the exact speed; the decisive speed is
c = (X(t2) - X(t1)) / (t2 - t1). Also reported and checked:
(X(t2) - x0) / t2 (speed from the start, which includes the start-up of the
scheme), and printed: the peak position with sub-cell (parabolic)
interpolation, and the pulse area (half the initial one: a conservation
check).

Checks: both speeds within 0.5 % of c_L and c_T; the right pulse carries
half the initial u-area within 1 %; no NaN.
"""
import os
import sys

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "lib"))
import foamcase as fc                         # noqa: E402
from checks import Checks                     # noqa: E402
import plots                                  # noqa: E402

TUTORIAL = "copperPulses"
NAME = "V4_copperPulses"
RUN_TIMEOUT = 600
X0 = 0.5
T1, T2 = 4e-5, 8e-5
TOL = 0.005

# Copper of the tutorial (constant/phaseProperties)
RHO0, GAMMA, PINF, MU, P0 = 8900.0, 4.22, 3.42e10, 4.5e10, 1e5
C_H2 = GAMMA * (P0 + PINF) / RHO0
C_L = np.sqrt(C_H2 + 4.0 * MU / (3.0 * RHO0))
C_T = np.sqrt(MU / RHO0)

checks = Checks()


def centroid(x, u, mask):
    w = u[mask]
    return np.sum(x[mask] * w) / np.sum(w), np.sum(w)


def peak(x, u, mask):
    """Position of the maximum of u over the cells in mask, refined by the
    parabola through the largest value and its two neighbours (uniform
    mesh)."""
    idx = np.flatnonzero(mask)
    i = idx[np.argmax(u[idx])]
    if i == 0 or i == x.size - 1:
        return x[i]
    um, u0, up = u[i - 1], u[i], u[i + 1]
    den = um - 2 * u0 + up
    shift = 0.5 * (um - up) / den if den != 0 else 0.0
    return x[i] + shift * 0.5 * (x[i + 1] - x[i - 1])


def main():
    missing = fc.require_apps("impactFoam", "blockMesh", "setExprFields",
                              "postProcess")
    if missing:
        checks.fail("V4_run", "%s not found on PATH (impactFoam not built "
                    "or environment not sourced: . etc/bashrc)"
                    % " ".join(missing))
        checks.exit()

    try:
        case = fc.copy_tutorial(TUTORIAL, NAME)
        fc.run(case, "./Allrun", log="log.Allrun", timeout=RUN_TIMEOUT)
        x = fc.cell_centres(case, "0")[:, 0]
        U = {t: fc.read_field(case, t, "U") for t in (0.0, T1, T2)}
    except fc.FoamError as e:
        checks.fail("V4_run", e.summary)
        checks.note(str(e))
        checks.exit()

    finite = all(np.all(np.isfinite(u)) for u in U.values())
    if not checks.check("V4_finite", finite, "U finite at t = 0, %g, %g"
                        % (T1, T2)):
        checks.exit()

    dx = np.median(np.diff(np.sort(x)))
    right = x > X0
    checks.note("c_L = %.3f m/s, c_T = %.3f m/s (c_h = %.3f m/s); %d cells"
                % (C_L, C_T, np.sqrt(C_H2), x.size))

    profiles = {}
    for label, comp, c_ref in (("longitudinal", 0, C_L),
                               ("transverse", 1, C_T)):
        tag = "V4_c%s" % label[0].upper()
        area0 = np.sum(U[0.0][:, comp]) * dx
        X, area, xpk = {}, {}, {}
        for t in (T1, T2):
            u = U[t][:, comp]
            X[t], s = centroid(x, u, right)
            area[t] = s * dx
            xpk[t] = peak(x, u, right)
        c_two = (X[T2] - X[T1]) / (T2 - T1)
        c_start = (X[T2] - X0) / T2
        c_peak = (xpk[T2] - xpk[T1]) / (T2 - T1)
        e_two = c_two / c_ref - 1
        e_start = c_start / c_ref - 1
        checks.note("%s: centroid X(%g) = %.6f m, X(%g) = %.6f m; peak "
                    "%.6f, %.6f m; peak speed %.3f m/s (%+.3f %%)"
                    % (label, T1, X[T1], T2, X[T2], xpk[T1], xpk[T2],
                       c_peak, 100 * (c_peak / c_ref - 1)))
        checks.check(tag, abs(e_two) <= TOL,
                     "centroid speed between t = %g and %g s: %.3f m/s, "
                     "expected %.3f m/s, error %+.4f %% (tolerance %.1f %%)"
                     % (T1, T2, c_two, c_ref, 100 * e_two, 100 * TOL))
        checks.check(tag + "_fromStart", abs(e_start) <= TOL,
                     "(X(%g) - x0)/t: %.3f m/s, expected %.3f m/s, error "
                     "%+.4f %% (tolerance %.1f %%)"
                     % (T2, c_start, c_ref, 100 * e_start, 100 * TOL))
        ratio = [area[t] / (0.5 * area0) for t in (T1, T2)]
        checks.check(tag + "_area",
                     all(abs(r - 1) <= 0.01 for r in ratio),
                     "area of the right-going u_%s pulse / half the initial "
                     "area: %.6f, %.6f (tolerance 1 %%)"
                     % ("xy"[comp], ratio[0], ratio[1]))
        profiles[label] = {"t1": U[T1][:, comp], "t2": U[T2][:, comp]}

    order = np.argsort(x)
    xs = x[order]
    runs = []
    for t, key in ((T1, "t1"), (T2, "t2")):
        runs.append(("t = %g s" % t, xs,
                     {"ux": profiles["longitudinal"][key][order],
                      "uy": profiles["transverse"][key][order]}))
    # Exact linear acoustics: half-amplitude Gaussians at x0 +/- c t (the
    # initial bump parameters of the tutorial)
    ref = {"ux": np.zeros_like(xs), "uy": np.zeros_like(xs)}
    for t in (T1, T2):
        for key, c in (("ux", C_L), ("uy", C_T)):
            for sgn in (-1, 1):
                ref[key] += 0.05 * np.exp(-((xs - X0 - sgn * c * t)
                                            / 0.02) ** 2)
    plots.compare_profiles(
        os.path.join(case, "pulses.png"),
        [("ux", "u_x [m/s]"), ("uy", "u_y [m/s]")], runs,
        reference=("linear acoustics (both times)", xs, ref),
        title="copper pulses: c_L = %.1f m/s, c_T = %.1f m/s" % (C_L, C_T))

    checks.exit()


if __name__ == "__main__":
    main()
