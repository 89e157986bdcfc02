#!/usr/bin/python3
"""The second Riemann solver of the run-time selection table, HLL with
Einfeldt's wave speeds (discreteEquations { riemannSolver HLL; },
docs/numerics.md section 3.6), in whole runs.

- Abgrall's criterion (V1 set-up, tests/cases/test_V1_interfaceAdvection.py):
  a copper slab in air, u = 100 m/s and p = 1e5 Pa everywhere, 500 steps,
  on the 1-D mesh, the skewed hex mesh (diagonal motion) and triangles
  (diagonal), and on the 1-D mesh with Mie-Grueneisen copper (V1's
  '_MieGruneisen' variant), first and second order: max |U - u0| <= 1e-10
  |u0| and max |p - p0| <= 1e-10 (p0 + gamma pInf) of copper, as V1 asks
  of HLLC.
  Between copper and air the solver's contact is HLLC's for Einfeldt's
  bounds; within each phase the HLL flux acts (the uniform states make
  both exact).
- V2's water-air shock tube (tests/cases/test_V2_waterAirShockTube.py) at
  100, 200, 400 cells, second order: the relative L1 errors of rho, u, p
  against the exact solution fall with resolution, and at 400 cells stay
  within V2's own bounds, 0.6 / 0.6 / 1 % (measured when the test was
  written: 0.36 / 0.43 / 0.69 %; the water-air contact is HLLC's, and at
  second order the extra diffusion of HLL at the shock and in the
  rarefaction costs little).
"""
import os
import sys

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
sys.path.insert(0, os.path.join(HERE, "..", "lib"))
import foamcase as fc                                 # noqa: E402
from checks import Checks                             # noqa: E402
import test_V1_interfaceAdvection as v1               # noqa: E402
import test_V2_waterAirShockTube as v2                # noqa: E402

checks = Checks()

V1_RUNS = [
    ("1D", "1D", (100.0, 0.0, 0.0)),
    ("skewed_diag", "skewed", (v1.DIAG, v1.DIAG, 0.0)),
    ("triangles_diag", "triangles", (v1.DIAG, v1.DIAG, 0.0)),
    ("1D_MieGruneisen", "1D", (100.0, 0.0, 0.0)),
]
V2_BOUNDS = v2.BOUNDS


def abgrall():
    for order in (1, 2):
        for name, kind, u0 in V1_RUNS:
            tag = "HLL_%s_o%d" % (name, order)
            u0 = np.array(u0)
            try:
                case, mesh, dt, t_end, steps = v1.run_case(
                    tag, kind, u0, order, riemann_solver="HLL")
                t = fc.find_time(case, t_end)
                U = fc.read_field(case, t, "U")
                p = {k: fc.read_field(case, t, k)
                     for k in ("p", "p.copper", "p.air")}
            except fc.FoamError as e:
                checks.fail("%s_run" % tag, e.summary)
                continue
            ok_steps = v1.N_STEPS <= steps <= v1.N_STEPS + 1
            du = np.max(np.abs(U - u0))
            checks.check("%s_u" % tag,
                         ok_steps and du <= v1.U_TOL * np.linalg.norm(u0),
                         "%d steps; max |U - u0| = %.3e |u0| (bound 1e-10)"
                         % (steps, du / np.linalg.norm(u0)))
            dp = max(np.max(np.abs(v - v1.P0)) for v in p.values())
            checks.check("%s_p" % tag, dp <= v1.P_TOL,
                         "max |p - p0| over p, p.copper, p.air = %.3e Pa "
                         "(bound %.3g Pa)" % (dp, v1.P_TOL))


def shock_tube():
    exact = v2.RiemannProblem(v2.WATER, v2.AIR)
    errors = {"rho": [], "u": [], "p": []}
    for n in v2.RESOLUTIONS:
        name = "HLL_V2_waterAir_n%d" % n
        try:
            case = fc.copy_tutorial(v2.TUTORIAL, name)
            fc.set_entry(case, "system/blockMeshDict", "nx", n)
            fc.set_entry(case, "system/fvSchemes",
                         "discreteEquations/riemannSolver", "HLL")
            fc.run(case, "./Allrun", log="log.Allrun",
                   timeout=v2.RUN_TIMEOUT)
            t = fc.find_time(case, v2.T_END)
            xc = fc.cell_centres(case, t)[:, 0]
            q = {"rho": fc.read_field(case, t, "rho"),
                 "u": fc.read_field(case, t, "U")[:, 0],
                 "p": fc.read_field(case, t, "p")}
        except fc.FoamError as e:
            checks.fail("HLL_V2_run_n%d" % n, e.summary)
            return
        order = np.argsort(xc)
        edges = v2.cell_edges(xc[order])
        dx = np.diff(edges)
        ref = dict(zip(("rho", "u", "p"),
                       exact.cell_averages(edges, v2.T_END, v2.X0)[:3]))
        for k in errors:
            errors[k].append(v2.rel_l1(q[k][order], ref[k], dx))
    for k in ("rho", "u", "p"):
        errs = errors[k]
        falls = all(errs[i + 1] < errs[i] for i in range(len(errs) - 1))
        checks.check("HLL_V2_%s_L1_falls" % k, falls,
                     "relative L1 %s at %s cells"
                     % (" / ".join("%.4f %%" % (100 * x) for x in errs),
                        "/".join(str(r) for r in v2.RESOLUTIONS)))
        checks.check("HLL_V2_%s_L1_n%d" % (k, v2.RESOLUTIONS[-1]),
                     errs[-1] < V2_BOUNDS[k],
                     "relative L1 %.4f %% (bound %.1f %%)"
                     % (100 * errs[-1], 100 * V2_BOUNDS[k]))


def main():
    missing = fc.require_apps("impactFoam", "blockMesh", "setFields",
                              "checkMesh", "postProcess")
    if missing:
        checks.fail("HLL_run", "%s not found on PATH" % " ".join(missing))
        checks.exit()
    abgrall()
    shock_tube()
    checks.exit()


if __name__ == "__main__":
    main()
