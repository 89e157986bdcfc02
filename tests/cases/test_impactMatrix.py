#!/usr/bin/python3
"""R1's matrix at a coarse resolution (docs/validation.md R1): the library's
solids against each other, heavy projectiles into light plates first.

validation/impactSpeeds/matrix's set-up (a sphere of radius 5 mm or a rod
of radius 2.5 mm and length 20 mm into an 8 mm plate, axisymmetric, in
air, closed domain, library materials with their failure models, the
projectileOnPlate template's numerics) on 1 mm cells, each run to the
time the projectile has crossed the plate, (L + T + gap)/v:
  - steel4340 sphere into aluminium6061T6 at 3, 6 and 10 km/s (on 0.5 mm
    cells they stopped at 2.6, 1.9 and 0.5 us with p = -5e13, -1.3e12 and
    -6e11 Pa in the sphere, numerics.md 9.3b and 9.8);
  - the same at 3 km/s with the plate given `failure { type spall;
    sigmaSpall 1.2e9; }` (it stopped with a floating-point signal in the
    interface-pressure solve, numerics.md 9.5);
  - a tungstenAlloy rod into aluminium6061T6 at 4 km/s (stopped at 1.4 us,
    p = -1.8e11 Pa in the rod);
  - an aluminium6061T6 sphere into steel4340 at 6 km/s, and a
    tungstenAlloy rod into steel4340 at 1 km/s.
Checks per run: the end time reached; the energy added without a payer
below 1e-4 of the projectile's initial kinetic energy; the total energy's
change beyond it below 1e-6 of that; the total mass unchanged to 1e-9 (the
domain is closed). Full matrix, two meshes: validation/impactSpeeds/matrix.
"""
import importlib.machinery
import importlib.util
import os
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(os.path.dirname(HERE))
sys.path.insert(0, os.path.join(HERE, "..", "lib"))
import foamcase as fc                         # noqa: E402
from checks import Checks                     # noqa: E402


def load_matrix():
    path = os.path.join(ROOT, "validation", "impactSpeeds", "matrix")
    loader = importlib.machinery.SourceFileLoader("impactMatrix", path)
    spec = importlib.util.spec_from_loader("impactMatrix", loader)
    module = importlib.util.module_from_spec(spec)
    loader.exec_module(module)
    return module


H = 1.0
SPALL = "phaseProperties { plate { failure { type spall; " \
        "sigmaSpall 1.2e9; } } }\n"
RUNS = [
    ("steel4340:aluminium6061T6", "sphere", 3000, ""),
    ("steel4340:aluminium6061T6", "sphere", 6000, ""),
    ("steel4340:aluminium6061T6", "sphere", 10000, ""),
    ("steel4340:aluminium6061T6", "sphere", 3000, SPALL),
    ("tungstenAlloy:aluminium6061T6", "rod", 4000, ""),
    ("aluminium6061T6:steel4340", "sphere", 6000, ""),
    ("tungstenAlloy:steel4340", "rod", 1000, ""),
]
RUN_TIMEOUT = 600

checks = Checks()


def main():
    missing = fc.require_apps("impactFoam", "impactSetup", "blockMesh")
    if missing:
        checks.fail("R1matrix_run", "%s not found on PATH (impactFoam not "
                    "built or environment not sourced: . etc/bashrc)"
                    % " ".join(missing))
        checks.exit()
    matrix = load_matrix()
    run_dir = os.path.join(ROOT, "tests", "run")
    for pair, shape, v, extra in RUNS:
        name = "R1matrix_" + matrix.tag(pair, shape, v, H) \
            + ("_spall" if extra else "")
        r = matrix.run(pair, shape, v, H, RUN_TIMEOUT, run_dir=run_dir,
                       extra=extra, name=name)
        checks.check(name + "_end", r["reached"],
                     "%s: reached %.4g us of %.4g us in %.0f s, %d steps, "
                     "%d retried %s" % (matrix.describe(r).split()[0],
                                       1e6 * r["t_last"],
                                       1e6 * r["t_end"], r["wall"],
                                       r["steps"], r["retried"],
                                       r["message"]))
        checks.check(name + "_unpaid", r["unpaid_ke"] < matrix.UNPAID_OF_KE,
                     "energy added without a payer %.2e of the projectile's "
                     "kinetic energy (bound %g)"
                     % (r["unpaid_ke"], matrix.UNPAID_OF_KE))
        checks.check(name + "_energy", abs(r["drift"]) < matrix.DRIFT,
                     "total energy's change beyond it %.2e of the kinetic "
                     "energy (bound %g)" % (r["drift"], matrix.DRIFT))
        checks.check(name + "_mass", abs(r["mass"]) < matrix.MASS,
                     "total mass change %.2e (bound %g)"
                     % (r["mass"], matrix.MASS))
    checks.exit()


if __name__ == "__main__":
    main()
