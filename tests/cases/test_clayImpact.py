#!/usr/bin/python3
"""Elastic jelly ball on a rigid wall (docs/validation.md W3), coarse setting.

tutorials/impactFoam/clayImpact as it is (./Allrun: elastic jelly ball,
R = 10 mm, 2 m/s, neo-Hookean mu = 1 MPa, 0.5 mm above a rigid frictionless
wall in air; axisymmetric wedge, closed box of slip walls, square cells of
1 mm, 1.8 ms, about 5000 steps), copied to tests/run/clayImpact_coarse.
rodProfile's table (postProcessing/rodProfile/ball.csv) gives the ball's
mass-averaged axial velocity V(t) and the energy budget at every written
time (every 20 us).

Checks:
  clayImpact_rebound   the ball bounces: V goes from -v through 0 to a
                       maximum of at least 0.5 v (a "sizeable fraction" of
                       the impact speed; Hertz: 1; the coarse run gives
                       about 0.66: the wall keeps the ball's diffuse edge
                       in tension as it leaves)
  clayImpact_energy    total energy (kinetic + elastic + internal, all
                       phases; nothing crosses the closed box) conserved:
                       max |E(t) - E(0)| <= 1 % of the ball's initial
                       kinetic energy (E itself is 4 orders larger, the
                       stiffened-gas internal energy, and would hide any
                       error)
Reported as a note (decided by validation/clayImpact/validate on finer
meshes): the contact time and compression against Hertz.
"""
import os
import sys

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "lib"))
import foamcase as fc                         # noqa: E402
from checks import Checks                     # noqa: E402

V_IMPACT = 2.0          # m/s (tutorial's setFieldsDict)
REBOUND_MIN = 0.5       # max rebound velocity / impact velocity
ENERGY_TOL = 0.01       # of the initial kinetic energy

checks = Checks()


def main():
    missing = fc.require_apps("impactFoam", "rodProfile", "blockMesh",
                              "setAlphaField", "setFields", "foamDictionary")
    if missing:
        checks.fail("clayImpact_run", "%s not found on PATH (not built or "
                    "environment not sourced: . etc/bashrc)"
                    % " ".join(missing))
        checks.exit()

    case = fc.copy_tutorial("clayImpact", "clayImpact_coarse")
    try:
        fc.run(case, "./Allrun", log="log.Allrun", timeout=900)
        for log in ("log.impactFoam", "log.rodProfile"):
            text = fc.tail(os.path.join(case, log), 400)
            if "FOAM FATAL" in text:
                raise fc.FoamError("%s: %s" % (log, fc.log_summary(text)))
    except fc.FoamError as e:
        checks.fail("clayImpact_run", e.summary)
        checks.note(str(e))
        checks.exit()

    path = os.path.join(case, "postProcessing", "rodProfile", "ball.csv")
    try:
        d = np.atleast_1d(np.genfromtxt(path, delimiter=",", names=True))
        t, V = d["t"], d["axialVelocity"]
        E, K = d["total"], d["kinetic"]
    except (OSError, ValueError) as e:
        checks.fail("clayImpact_run", "cannot read %s: %s" % (path, e))
        checks.exit()
    if len(t) < 10:
        checks.fail("clayImpact_run", "only %d rows in %s" % (len(t), path))
        checks.exit()

    # Rebound
    up = np.where((V[:-1] < 0) & (V[1:] >= 0))[0]
    if len(up) == 0:
        checks.fail("clayImpact_rebound",
                    "the axial velocity never changes sign: V from %.3f to "
                    "%.3f m/s, max %.3f m/s at t = %.3g s"
                    % (V[0], V[-1], V.max(), t[np.argmax(V)]))
    else:
        i0 = up[0]
        t0 = t[i0] - V[i0] * (t[i0 + 1] - t[i0]) / (V[i0 + 1] - V[i0])
        k = i0 + int(np.argmax(V[i0:]))
        e = V[k] / V_IMPACT
        checks.check("clayImpact_rebound", e >= REBOUND_MIN,
                     "V(0) = %.4f m/s; V = 0 (maximal compression) at t = "
                     "%.4g s; then max V = %.4f m/s at t = %.4g s: rebound "
                     "ratio %.3f (bound >= %.2f); V at the end %.4f m/s"
                     % (V[0], t0, V[k], t[k], e, REBOUND_MIN, V[-1]))

    # Energy
    dE = E - E[0]
    i = int(np.argmax(np.abs(dE)))
    drift = abs(dE[i]) / K[0]
    checks.check("clayImpact_energy", drift <= ENERGY_TOL,
                 "total energy %.9g J at t = 0, initial kinetic energy "
                 "%.4e J; max |E - E0| = %.3e J at t = %.4g s = %.3e of the "
                 "kinetic energy (bound %.0e), %.1e of E0; final drift "
                 "%.3e of the kinetic energy"
                 % (E[0], K[0], abs(dE[i]), t[i], drift, ENERGY_TOL,
                    abs(dE[i]) / abs(E[0]), dE[-1] / K[0]))

    # Hertz, as information (coarse mesh: not decided here)
    try:
        import importlib.machinery
        import importlib.util
        loader = importlib.machinery.SourceFileLoader(
            "clayValidate", os.path.join(fc.PROJECT_DIR, "validation",
                                         "clayImpact", "validate"))
        spec = importlib.util.spec_from_loader("clayValidate", loader)
        cv = importlib.util.module_from_spec(spec)
        loader.exec_module(cv)
        s = cv.setup(case, "jelly")
        H, ref, ref_c = cv.hertz_reference(s)
        tab = cv.read_table(case)
        r = cv.evaluate_jelly(tab, s, H, ref_c)
        checks.note("Hertz (not decided on this coarse mesh; see "
                    "validation/clayImpact): t_c %.4f ms against %.4f ms, "
                    "delta_max %.4f mm against %.4f mm"
                    % (r.get("tc", float("nan")) * 1e3, H["tc"] * 1e3,
                       r.get("dmax", float("nan")) * 1e3, H["dmax"] * 1e3))
    except Exception as e:  # information only
        checks.note("Hertz comparison not made: %s" % e)

    checks.exit()


if __name__ == "__main__":
    main()
