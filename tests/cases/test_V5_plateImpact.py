#!/usr/bin/python3
"""V5 (docs/validation.md): symmetric copper plate impact, 1-D, 2 x 200 m/s,
ideal Von Mises plasticity with sigma_Y = 0.3 GPa.

The tutorial copperPlateImpact is run unchanged (./Allrun): one copper
phase (rho0 8900, stiffened gas 4.22 / 3.42e10, separable a = 1/2,
mu 4.5e10, vonMises sigmaY 3e8 tau 0) on [0, 1] m, 4000 cells, u = +200 m/s
for x < 0.5 and -200 m/s for x > 0.5, p = 1e5 Pa, t = 6.5e-5 s. From the
impact plane an elastic precursor and, behind it, a plastic shock run into
each plate; the central region is at rest.

References
- Precursor (docs/validation.md): sigma_xx = -(K + 4 mu/3) sigma_Y / (2 mu),
  K = gamma (p0 + pInf). Printed as well: the exact precursor of the model
  (elastic uniaxial compression up to the yield surface, on the Hugoniot
  of the initial state), from tests/lib/elasticPlasticHugoniot.py.
- Plastic plateau: u = 0 and sigma_xx = -p - 2/3 sigma_Y with p from the
  stiffened gas at the state on the shock Hugoniot through the precursor
  state where the material is at rest (elasticPlasticHugoniot.py: for a
  trial density rho2 the unimodular stretch is the uniaxial one on the
  yield surface, the Hugoniot energy relation
  e2 - e1 = -(sigma_1 + sigma_2)/2 (1/rho1 - 1/rho2) gives e2 and so p2,
  and the velocity jump of the Rayleigh line
  u2 - u1 = -sqrt((sigma_2 - sigma_1)(1/rho2 - 1/rho1)) must bring u2 to 0;
  bisection in rho2). The front positions of both shocks follow from the
  same solution.

How the precursor plateau is located, in each half (the left half
mirrored, x -> 1 - x), from the impact plane outwards:
- plastic front x_p: first crossing of sigma_xx = sigma_c / 2, where
  sigma_c is the median of sigma_xx over |x - 0.5| < 0.1 (the central
  plateau, about -7.75 GPa);
- elastic front x_e: last crossing (from the undisturbed plate inwards) of
  sigma_xx = sigma_0 + s_lin / 2, half the expected precursor jump above
  the undisturbed stress sigma_0 (the value at the domain end);
- plateau: the cells in the middle half of [x_p, x_e], away from both
  smeared fronts; its mean is the measured amplitude (min, max and the
  number of cells are printed).
Central plateau: the cells with |x - 0.5| < 0.8 (x_p - 0.5).

Checks: precursor within 2 % of the linear formula (each half); central
sigma_xx within 1 % of the Hugoniot value in every cell of the central
plateau, |u| <= 0.5 % of the impact speed there; front positions within
2 % of the distance run; sigmaEq <= sigma_Y (1 + 1e-6) in every cell.

Two runs, the same checks: the tutorial as shipped (V5_*: the default
numerics, second order) and the tutorial with discreteEquations order 1
(V5_order1_*, the scheme of the prototype the docs/validation.md numbers come
from). Figures: tests/run/V5_copperPlateImpact*/plateImpact*.png.
"""
import os
import sys
import time

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "lib"))
import foamcase as fc                         # noqa: E402
from checks import Checks                     # noqa: E402
import plots                                  # noqa: E402
import elasticPlasticHugoniot as eph          # noqa: E402

TUTORIAL = "copperPlateImpact"
NAME = "V5_copperPlateImpact"
RUN_TIMEOUT = 900
T_END = 6.5e-5
X_IMPACT = 0.5
U_IMPACT = 200.0
P0 = 1e5
COPPER = dict(rho0=8900.0, gamma=4.22, pInf=3.42e10, mu=4.5e10, a=0.5,
              sigmaY=3e8)
TOL_PRECURSOR = 0.02
TOL_PLATEAU = 0.01
TOL_U = 0.005 * U_IMPACT
TOL_FRONT = 0.02
TOL_YIELD = 1e-6

checks = Checks()


def crossing(x, s, level, start, step):
    """Linearly interpolated position where s crosses level, scanning from
    index start in direction step (+1/-1); None if it never does."""
    i = start
    n = x.size
    while 0 <= i + step < n:
        j = i + step
        if (s[i] - level) * (s[j] - level) <= 0 and s[i] != s[j]:
            f = (level - s[i]) / (s[j] - s[i])
            return x[i] + f * (x[j] - x[i])
        i = j
    return None


def analyse_half(xh, sh, sigma_c, s_lin):
    """xh: distance from the impact plane (ascending), sh: sigma_xx.
    Returns dict with the fronts and the precursor plateau."""
    sigma_0 = sh[-1]
    x_p = crossing(xh, sh, 0.5 * sigma_c, 0, +1)
    x_e = crossing(xh, sh, sigma_0 + 0.5 * (s_lin - sigma_0), xh.size - 1,
                   -1)
    if x_p is None or x_e is None or x_e <= x_p:
        return {"x_p": x_p, "x_e": x_e, "n": 0}
    width = x_e - x_p
    window = (xh > x_p + 0.25 * width) & (xh < x_e - 0.25 * width)
    plateau = sh[window]
    return {"x_p": x_p, "x_e": x_e, "n": int(window.sum()),
            "mean": plateau.mean() if plateau.size else np.nan,
            "min": plateau.min() if plateau.size else np.nan,
            "max": plateau.max() if plateau.size else np.nan,
            "lo": x_p + 0.25 * width, "hi": x_e - 0.25 * width}


def run_and_check(order, P, name, mat, sol):
    """Run the tutorial (order None: as shipped; else discreteEquations
    order set to it) and check it; check names start with P."""
    s_lin = sol["linear_precursor"]
    pre, pla = sol["precursor"], sol["plastic"]
    try:
        case = fc.copy_tutorial(TUTORIAL, name)
        if order is not None:
            fc.set_entry(case, "system/fvSchemes",
                         "discreteEquations/order", order)
        t0 = time.time()
        fc.run(case, "./Allrun", log="log.Allrun", timeout=RUN_TIMEOUT)
        elapsed = time.time() - t0
        t = fc.find_time(case, T_END)
        x = fc.cell_centres(case, t)[:, 0]
        sigma = fc.read_field(case, t, "sigma")
        u = fc.read_field(case, t, "U")[:, 0]
        sigma_eq = fc.read_field(case, t, "sigmaEq")
        rho = fc.read_field(case, t, "rho")
    except fc.FoamError as e:
        checks.fail(P + "run", e.summary)
        checks.note(str(e))
        return
    checks.note("%s: Allrun (blockMesh, setFields, impactFoam on %d "
                "cells) took %.1f s" % (name, x.size, elapsed))

    idx = np.argsort(x)
    x, sxx, u = x[idx], sigma[idx, 0], u[idx]
    sigma_eq, rho = sigma_eq[idx], rho[idx]
    if not checks.check(P + "finite",
                        np.all(np.isfinite(sigma)) and np.all(np.isfinite(u))
                        and np.all(np.isfinite(sigma_eq)),
                        "sigma, U, sigmaEq finite at t = %g" % T_END):
        return

    centre = np.abs(x - X_IMPACT) < 0.1
    sigma_c = np.median(sxx[centre])

    halves = {}
    right = x > X_IMPACT
    halves["right"] = analyse_half(x[right] - X_IMPACT, sxx[right], sigma_c,
                                   s_lin)
    left = x < X_IMPACT
    halves["left"] = analyse_half((X_IMPACT - x[left])[::-1],
                                  sxx[left][::-1], sigma_c, s_lin)

    # Elastic precursor
    d_e = pre["D"] * T_END      # lab-frame shock speeds (right plate)
    d_p = pla["D"] * T_END
    for side in ("right", "left"):
        h = halves[side]
        tag = P + "precursor_" + side
        if h["n"] < 5:
            checks.fail(tag, "precursor plateau not found (plastic front %s, "
                        "elastic front %s, %d cells between)"
                        % (h["x_p"], h["x_e"], h["n"]))
            continue
        err = h["mean"] / s_lin - 1
        checks.check(tag, abs(err) <= TOL_PRECURSOR,
                     "sigma_xx plateau %.6g Pa (mean of %d cells at %.4f.."
                     "%.4f m from the impact plane; min %.6g, max %.6g), "
                     "expected -(K + 4mu/3) sY/(2mu) = %.6g Pa, error "
                     "%+.3f %% (tolerance %.0f %%); exact precursor %.6g Pa "
                     "(%+.3f %%)"
                     % (h["mean"], h["n"], h["lo"], h["hi"], h["min"],
                        h["max"], s_lin, 100 * err, 100 * TOL_PRECURSOR,
                        pre["sigma_xx"],
                        100 * (h["mean"] / pre["sigma_xx"] - 1)))
        for front, dist, label in (("x_e", d_e, "elastic"),
                                   ("x_p", d_p, "plastic")):
            derr = h[front] / dist - 1
            checks.check(P + "%sFront_%s" % (label, side),
                         abs(derr) <= TOL_FRONT,
                         "%s front %.5f m from the impact plane, expected "
                         "%.5f m (shock speed %.2f m/s), error %+.3f %% "
                         "(tolerance %.0f %%)"
                         % (label, h[front], dist, dist / T_END, 100 * derr,
                            100 * TOL_FRONT))

    # Central plastic plateau
    x_p = [halves[s]["x_p"] for s in ("left", "right")]
    if None in x_p:
        checks.fail(P + "plastic", "plastic fronts not found")
    else:
        half = 0.8 * min(x_p)
        core = np.abs(x - X_IMPACT) < half
        dev = sxx[core] / pla["sigma_xx"] - 1
        imax = np.argmax(np.abs(dev))
        checks.check(P + "plastic_sigma", np.max(np.abs(dev)) <= TOL_PLATEAU,
                     "central sigma_xx (%d cells, |x - 0.5| < %.4f m): mean "
                     "%.6g Pa, worst %.6g Pa at x = %.4f; Hugoniot "
                     "-p - 2/3 sY = %.6g Pa; mean error %+.4f %%, worst "
                     "%+.4f %% (tolerance %.0f %%)"
                     % (core.sum(), half, sxx[core].mean(), sxx[core][imax],
                        x[core][imax], pla["sigma_xx"],
                        100 * (sxx[core].mean() / pla["sigma_xx"] - 1),
                        100 * dev[imax], 100 * TOL_PLATEAU))
        umax = np.max(np.abs(u[core]))
        checks.check(P + "plastic_u", umax <= TOL_U,
                     "max |u| in the central plateau %.4g m/s (tolerance "
                     "%.3g m/s = 0.5 %% of the impact speed)" % (umax, TOL_U))
        checks.note("central plateau: rho mean %.3f (min %.3f, max %.3f), "
                    "Hugoniot %.3f kg/m^3; sigmaEq mean %.4g Pa (yield "
                    "surface %.4g Pa)"
                    % (rho[core].mean(), rho[core].min(), rho[core].max(),
                       pla["rho"], sigma_eq[core].mean(), mat.sigmaY))

    # Yield surface everywhere
    worst = np.argmax(sigma_eq)
    checks.check(P + "yield", sigma_eq[worst] <= mat.sigmaY * (1 + TOL_YIELD),
                 "max sigmaEq %.9g Pa at x = %.4f, sigma_Y (1 + 1e-6) = "
                 "%.9g Pa" % (sigma_eq[worst], x[worst],
                              mat.sigmaY * (1 + TOL_YIELD)))

    # Figure
    ref_x = np.array([0.0, X_IMPACT - d_e, X_IMPACT - d_e, X_IMPACT - d_p,
                      X_IMPACT - d_p, X_IMPACT + d_p, X_IMPACT + d_p,
                      X_IMPACT + d_e, X_IMPACT + d_e, 1.0])
    s0 = -P0
    ref_s = np.array([s0, s0, pre["sigma_xx"], pre["sigma_xx"],
                      pla["sigma_xx"], pla["sigma_xx"], pre["sigma_xx"],
                      pre["sigma_xx"], s0, s0])
    ref_u = np.array([U_IMPACT, U_IMPACT, -pre["u"], -pre["u"], 0, 0,
                      pre["u"], pre["u"], -U_IMPACT, -U_IMPACT])
    plots.compare_profiles(
        os.path.join(case, "plateImpact.png"),
        [("sxx", "sigma_xx [Pa]"), ("u", "u [m/s]"),
         ("seq", "sigmaEq [Pa]")],
        [("impactFoam, %d cells" % x.size, x,
          {"sxx": sxx, "u": u, "seq": sigma_eq})],
        reference=("Rankine-Hugoniot", ref_x,
                   {"sxx": ref_s, "u": ref_u}),
        title="copper plate impact 2 x 200 m/s, sigma_Y 0.3 GPa, t = 65 us, "
        "%s" % name)
    plots.compare_profiles(
        os.path.join(case, "plateImpact_zoom.png"),
        [("sxx", "sigma_xx [Pa]"), ("seq", "sigmaEq [Pa]")],
        [("impactFoam, %d cells" % x.size, x,
          {"sxx": sxx, "seq": sigma_eq})],
        reference=("Rankine-Hugoniot", ref_x, {"sxx": ref_s}),
        title="precursor (right plate), %s" % name,
        xlim=(X_IMPACT + d_p - 0.02, X_IMPACT + d_e + 0.02))



def main():
    missing = fc.require_apps("impactFoam", "blockMesh", "setFields",
                              "postProcess")
    if missing:
        checks.fail("V5_run", "%s not found on PATH (impactFoam not built "
                    "or environment not sourced: . etc/bashrc)"
                    % " ".join(missing))
        checks.exit()

    # Reference states
    mat = eph.Material(**COPPER)
    sol = eph.symmetric_impact(mat, U_IMPACT, P0)
    s_lin = sol["linear_precursor"]
    pre, pla = sol["precursor"], sol["plastic"]
    checks.note("reference (elasticPlasticHugoniot.py):")
    checks.note("  linear precursor -(K + 4mu/3) sY/(2mu) = %.6g Pa "
                "(K = gamma (p0 + pInf) = %.6g Pa)"
                % (s_lin, mat.gamma * (P0 + mat.pInf)))
    checks.note("  exact precursor: rho %.3f, p %.6g, S_xx %.6g, "
                "sigma_xx %.6g Pa, u %.3f m/s, shock speed %.2f m/s"
                % (pre["rho"], pre["p"], pre["S_xx"], pre["sigma_xx"],
                   pre["u"], pre["D"]))
    checks.note("  plastic state: rho %.3f, e %.3f J/kg, p %.6g, S_xx "
                "%.6g, sigma_xx = -p - 2/3 sY = %.6g Pa, u %.2g m/s, "
                "shock speed %.2f m/s"
                % (pla["rho"], pla["e"], pla["p"], pla["S_xx"],
                   pla["sigma_xx"], pla["u"], pla["D"]))

    run_and_check(None, "V5_", NAME, mat, sol)
    run_and_check(1, "V5_order1_", NAME + "_order1", mat, sol)

    checks.exit()


if __name__ == "__main__":
    main()
