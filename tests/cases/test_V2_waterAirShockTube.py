#!/usr/bin/python3
"""V2 (docs/validation.md): water-air shock tube against the exact stiffened-gas
Riemann solution.

[0, 1] m, interface at 0.7, water (rho 1000, p 1e9, SG 4.4 / 6e8) left, air
(rho 50, p 1e5, gamma 1.4) right, t = 240 us. The tutorial
tutorials/impactFoam/waterAirShockTube is run unchanged (./Allrun) with 100,
200 and 400 cells. Errors are relative L1 norms of the mixture density
`rho`, the velocity U_x and the pressure `p`,

    e(q) = sum |q - q_exact| dx / sum |q_exact| dx,

with q_exact the exact cell averages (tests/lib/exactRiemann.py).

Checks: each error falls from 100 to 200 to 400 cells; at 400 cells
rho < 0.6 %, u < 0.6 %, p < 1 % (a first-order prototype: 1.3 / 1.6 / 5.2 %,
second order 0.41 / 0.29 / 0.69 %). Figures in tests/run/V2_waterAir_n*/.
"""
import os
import sys

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "lib"))
import foamcase as fc                         # noqa: E402
from checks import Checks                     # noqa: E402
from exactRiemann import RiemannProblem       # noqa: E402
import plots                                  # noqa: E402

TUTORIAL = "waterAirShockTube"
RESOLUTIONS = (100, 200, 400)
T_END = 240e-6
X0 = 0.7
WATER = (1000.0, 0.0, 1e9, 4.4, 6e8)          # rho, u, p, gamma, pInf
AIR = (50.0, 0.0, 1e5, 1.4, 0.0)
# At the finest resolution, second order (MUSCL-Hancock); the design's 1-D
# prototype reached 0.41/0.29/0.69 % there
BOUNDS = {"rho": 0.006, "u": 0.006, "p": 0.01}
RUN_TIMEOUT = 900                             # seconds per run

checks = Checks()


def cell_edges(xc, x_min=0.0, x_max=1.0):
    """Face positions of a 1-D mesh from its cell centres."""
    edges = np.empty(xc.size + 1)
    edges[0], edges[-1] = x_min, x_max
    edges[1:-1] = 0.5 * (xc[:-1] + xc[1:])
    return edges


def rel_l1(q, q_ref, dx):
    return np.sum(np.abs(q - q_ref) * dx) / np.sum(np.abs(q_ref) * dx)


def main():
    missing = fc.require_apps("impactFoam", "blockMesh", "setFields",
                              "postProcess")
    if missing:
        checks.fail("V2_run", "%s not found on PATH (impactFoam not built "
                    "or environment not sourced: . etc/bashrc)"
                    % " ".join(missing))
        checks.exit()

    exact = RiemannProblem(WATER, AIR)
    checks.note("exact solution: " + exact.summary())

    errors = {"rho": [], "u": [], "p": []}
    runs = []
    for n in RESOLUTIONS:
        name = "V2_waterAir_n%d" % n
        try:
            case = fc.copy_tutorial(TUTORIAL, name)
            fc.set_entry(case, "system/blockMeshDict", "nx", n)
            fc.run(case, "./Allrun", log="log.Allrun", timeout=RUN_TIMEOUT)
            t = fc.find_time(case, T_END)
            xc = fc.cell_centres(case, t)[:, 0]
            rho = fc.read_field(case, t, "rho")
            u = fc.read_field(case, t, "U")[:, 0]
            p = fc.read_field(case, t, "p")
        except fc.FoamError as e:
            text = str(e)
            checks.fail("V2_run_n%d" % n, e.summary)
            checks.note(text)
            checks.exit()
        if xc.size != n:
            checks.fail("V2_run_n%d" % n, "mesh has %d cells, expected %d"
                        % (xc.size, n))
            checks.exit()
        order = np.argsort(xc)
        xc, rho, u, p = xc[order], rho[order], u[order], p[order]
        edges = cell_edges(xc)
        dx = np.diff(edges)
        rho_e, u_e, p_e, _ = exact.cell_averages(edges, T_END, X0)
        finite = np.all(np.isfinite(rho)) and np.all(np.isfinite(u)) \
            and np.all(np.isfinite(p))
        if not finite:
            checks.fail("V2_run_n%d" % n, "non-finite values in rho, U or p")
            checks.exit()
        e = {"rho": rel_l1(rho, rho_e, dx), "u": rel_l1(u, u_e, dx),
             "p": rel_l1(p, p_e, dx)}
        for k in errors:
            errors[k].append(e[k])
        checks.note("%4d cells: relative L1 errors rho %.4f %%, u %.4f %%, "
                    "p %.4f %%" % (n, 100 * e["rho"], 100 * e["u"],
                                   100 * e["p"]))
        runs.append(("impactFoam, %d cells" % n, xc,
                     {"rho": rho, "u": u, "p": p}))

        # figure of this run against the exact solution
        xf = np.linspace(0.0, 1.0, 4001)
        rf, uf, pf, _ = exact.at(xf, T_END, X0)
        reference = ("exact", xf, {"rho": rf, "u": uf, "p": pf})
        quantities = [("rho", "rho [kg/m^3]"), ("u", "u [m/s]"),
                      ("p", "p [Pa]")]
        plots.compare_profiles(os.path.join(case, "profiles.png"),
                               quantities, runs[-1:], reference,
                               title="V2 water-air shock tube, %d cells, "
                               "t = 240 us" % n)

    # all resolutions together, and the convergence plot, in the finest case
    finest = os.path.join(fc.RUN_DIR, "V2_waterAir_n%d" % RESOLUTIONS[-1])
    plots.compare_profiles(os.path.join(finest, "profiles_all.png"),
                           quantities, runs, reference,
                           title="V2 water-air shock tube, t = 240 us")
    plots.convergence(os.path.join(finest, "convergence.png"),
                      list(RESOLUTIONS),
                      {k: v for k, v in errors.items()},
                      title="V2 water-air: relative L1 errors")

    for k in ("rho", "u", "p"):
        errs = errors[k]
        rates = [np.log(errs[i] / errs[i + 1]) / np.log(
            RESOLUTIONS[i + 1] / RESOLUTIONS[i]) for i in range(len(errs) - 1)]
        falls = all(errs[i + 1] < errs[i] for i in range(len(errs) - 1))
        checks.check(
            "V2_%s_L1_falls" % k, falls,
            "relative L1 %s at %s cells; observed orders %s"
            % (" / ".join("%.4f %%" % (100 * x) for x in errs),
               "/".join(str(r) for r in RESOLUTIONS),
               " ".join("%.2f" % r for r in rates)))
    for k in ("rho", "u", "p"):
        err = errors[k][-1]
        checks.check("V2_%s_L1_n%d" % (k, RESOLUTIONS[-1]), err < BOUNDS[k],
                     "relative L1 %.4f %% (bound %.1f %%)"
                     % (100 * err, 100 * BOUNDS[k]))
    checks.exit()


if __name__ == "__main__":
    main()
