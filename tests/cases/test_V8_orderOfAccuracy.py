#!/usr/bin/python3
"""V8 (docs/validation.md): observed order of accuracy on smooth elastic waves.

Case: tutorials/impactFoam/smoothWave. Copper (rho0 8900, SG 4.22 /
3.42e10 Pa, mu 4.5e10 Pa, a = 1/2, elastic), 1-D on [0, 1] m, transmissive
(zeroGradient) ends. At t = 0 a Gaussian pulse f(x) = exp(-((x - 0.25)/
0.04)^2) of u_x (longitudinal) and one of u_y (transverse), amplitude 1e-3
m/s each, on their right-going characteristics (density, pressure and
cobasis set consistently, tests/lib/acousticWave.py). The two waves are
linear and decoupled at this amplitude, so one run measures both. The exact
linear solution translates them: u_x = 1e-3 f(x - c_L t), u_y = 1e-3
f(x - c_T t), c_L = 4791.43 m/s, c_T = 2248.60 m/s (c_L^2 = c_h^2 +
4 mu/(3 rho0), c_h^2 = gamma (p + pInf)/rho0, c_T^2 = mu/rho0). At
t = 1e-4 s the pulses are centred at 0.729 m and 0.475 m; their tails
(< 1e-7 of the amplitude) never reach the ends.

Resolutions: N = 100, 200, 400, 800, 1600 cells on 1 m (the pulse's +-2 widths,
0.16 m, hold 16 to 256 cells), maxCo 0.4, at second order (the tutorial's
MUSCL-Hancock, cellLimited Gauss linear 1 = MC in 1-D) and at first order.
Error: relative L1 of each velocity component against the exact solution
at the cell centres, E = sum |u - u_exact| / sum |u_exact|. Observed
order between consecutive resolutions p = log2(E_N / E_2N).

Checks (on the finest pair 800 -> 1600, printed for every pair):
  V8_o2_longitudinal, V8_o2_shear     p >= 1.8
  V8_o1_longitudinal, V8_o1_shear     0.8 <= p <= 1.3
  V8_o2_better                        second order beats first order at 1600
                                      cells on both waves
"""
import os
import shutil
import sys

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "lib"))
import foamcase as fc                         # noqa: E402
from checks import Checks                     # noqa: E402
import acousticWave as aw                     # noqa: E402

TUTORIAL = "smoothWave"
T_END = 1e-4
RESOLUTIONS = [100, 200, 400, 800, 1600]
ORDERS = [2, 1]
BOUNDS = {2: (1.8, None), 1: (0.8, 1.3)}
RUN_TIMEOUT = 300

checks = Checks()
plot_data = {}


def run(order, n):
    case = fc.copy_tutorial(TUTORIAL, "V8_o%d_n%d" % (order, n))
    fc.set_entry(case, "system/blockMeshDict", "nx", n)
    fc.foam_dictionary(case, "system/fvSchemes", "discreteEquations/order",
                       order)
    fc.set_entry(case, "system/controlDict", "endTime", "%.10g" % T_END)
    fc.set_entry(case, "system/controlDict", "writeInterval", "%.10g" % T_END)
    fc.run(case, ["blockMesh"])
    shutil.rmtree(os.path.join(case, "0"), ignore_errors=True)
    shutil.copytree(os.path.join(case, "0.orig"), os.path.join(case, "0"))
    x = aw.write_initial(case)
    fc.run(case, ["impactFoam"], timeout=RUN_TIMEOUT)
    # the last time written; the exact solution is taken at that time (the
    # time loop may end a fraction of a step before endTime)
    t = fc.latest_time(case)
    if abs(float(t) - T_END) > 0.01 * T_END:
        raise fc.FoamError("%s: last time %s, endTime %g" % (case, t, T_END))
    U = fc.read_field(case, t, "U")
    ux, uy = aw.exact_velocity(x, float(t))
    errs = {}
    for name, num, ex in (("longitudinal", U[:, 0], ux),
                          ("shear", U[:, 1], uy)):
        errs[name] = np.sum(np.abs(num - ex)) / np.sum(np.abs(ex))
    plot_data[(order, n)] = (x, U[:, 0], U[:, 1], ux, uy)
    return errs


def main():
    missing = fc.require_apps("impactFoam", "blockMesh", "foamDictionary")
    if missing:
        checks.fail("V8_run", "%s not found on PATH (impactFoam not built "
                    "or environment not sourced: . etc/bashrc)"
                    % " ".join(missing))
        checks.exit()

    _, cL, cT = aw.speeds()
    checks.note("c_L = %.6g m/s, c_T = %.6g m/s, t = %g s"
                % (cL, cT, T_END))
    errors = {}
    for order in ORDERS:
        errors[order] = {}
        for n in RESOLUTIONS:
            try:
                errors[order][n] = run(order, n)
            except fc.FoamError as e:
                checks.fail("V8_o%d_n%d_run" % (order, n), e.summary)
                checks.note(str(e))
                errors[order][n] = None

    for order in ORDERS:
        lo, hi = BOUNDS[order]
        for wave in ("longitudinal", "shear"):
            E = [errors[order][n][wave] if errors[order][n] else np.nan
                 for n in RESOLUTIONS]
            p = [np.log2(E[i] / E[i + 1]) for i in range(len(E) - 1)]
            fit = -np.polyfit(np.log(RESOLUTIONS), np.log(E), 1)[0] \
                if np.all(np.isfinite(E)) else np.nan
            table = ", ".join("N=%d %.3e" % (n, e)
                              for n, e in zip(RESOLUTIONS, E))
            orders = " ".join("%.3f" % q for q in p)
            finest = p[-1]
            ok = np.isfinite(finest) and finest >= lo and \
                (hi is None or finest <= hi)
            bound = ">= %.1f" % lo if hi is None else \
                "in [%.1f, %.1f]" % (lo, hi)
            checks.check("V8_o%d_%s" % (order, wave), ok,
                         "L1 errors %s; observed orders %s (least-squares "
                         "fit %.3f); finest pair %.3f (bound %s)"
                         % (table, orders, fit, finest, bound))

    nmax = RESOLUTIONS[-1]
    if errors[2][nmax] and errors[1][nmax]:
        better = all(errors[2][nmax][w] < errors[1][nmax][w]
                     for w in ("longitudinal", "shear"))
        checks.check("V8_o2_better", better,
                     "at N=%d: order 2 L1 %.3e / %.3e against order 1 "
                     "%.3e / %.3e (longitudinal / shear)"
                     % (nmax, errors[2][nmax]["longitudinal"],
                        errors[2][nmax]["shear"],
                        errors[1][nmax]["longitudinal"],
                        errors[1][nmax]["shear"]))

    try:
        import plots
        if (2, 200) in plot_data and (1, 200) in plot_data:
            x, ux2, uy2, uxe, uye = plot_data[(2, 200)]
            _, ux1, uy1, _, _ = plot_data[(1, 200)]
            plots.compare_profiles(
                os.path.join(fc.RUN_DIR, "V8_profiles.png"),
                [("ux", "u_x [m/s]"), ("uy", "u_y [m/s]")],
                runs=[("order 2, 200 cells", x, {"ux": ux2, "uy": uy2}),
                      ("order 1, 200 cells", x, {"ux": ux1, "uy": uy1})],
                reference=("exact (linear)", x, {"ux": uxe, "uy": uye}),
                title="smooth waves in copper, t = 1e-4 s")
    except Exception as e:  # plotting never decides the test
        checks.note("plot skipped: %s" % e)

    checks.exit()


if __name__ == "__main__":
    main()
