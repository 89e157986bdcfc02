#!/usr/bin/python3
"""Coarse Taylor test (tutorials/impactFoam/taylorTest, docs/validation.md):
the copper Taylor test 3 (L0 34.5 mm, D0 7.8 mm, 162 m/s, 298 K, library
OFHCcopper) on 0.8 mm cells to the tutorial's own end time (its stopping
estimate rho L0 v / sigma), in well under 90 s.

Checks:
    taylorTest_run      ./Allrun completes, the last written time is the end
                        time, the specimen's shape is printed
    taylorTest_shape    the specimen shortened and spread, within bounds from
                        physics:
                        - length: Wilkins & Guinan's rigid-plastic estimate
                          Lf/L0 = exp(-rho v^2 / (2 sigma)), with sigma between
                          the material's flow stress at (strain 0.1, 1/s, T0)
                          (a lower bound: the softest material) and at
                          (strain 2, 1e5/s, T0) (an upper bound: the hardest):
                          exp(-rho v^2/(2 sigma_lo)) < Lf/L0 < exp(-rho v^2/(2 sigma_hi));
                        - radius: Rf >= R0 sqrt(L0/Lf) (the volume is kept:
                          the largest radius is at least the mean one) and
                          Rf < 2.5 R0 (the mushroom stays in the domain);
                        - the length never grows by more than a cell over the
                          run and the specimen has stopped: the mean axial
                          velocity at the end is below 10 % of v
Usage: test_taylorTest.py [--material <name>] (default OFHCcopper)
"""
import math
import os
import subprocess
import sys
import time

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "lib"))
import foamcase as fc                         # noqa: E402
from checks import Checks                     # noqa: E402

TUTORIAL = "taylorTest"
L0, D0, V, T0, H = 34.5e-3, 7.8e-3, 162.0, 298.0, 0.8e-3
R0 = D0 / 2
TIMEOUT = 300

checks = Checks()


def main():
    material = "OFHCcopper"
    if "--material" in sys.argv:
        material = sys.argv[sys.argv.index("--material") + 1]
    missing = fc.require_apps("impactFoam", "blockMesh", "setFields",
                              "rodProfile")
    if missing:
        checks.fail("taylorTest_run", "%s not found on PATH (. etc/bashrc)"
                    % " ".join(missing))
        checks.exit()
    case = fc.copy_tutorial(TUTORIAL)
    sys.path.insert(0, case)
    import specimen as sp                     # noqa: E402 (the tutorial's)

    t0 = time.time()
    cmd = ["./Allrun", "-h", "%g" % (H * 1e3), "-material", material,
           "-L0", "%g" % (L0 * 1e3), "-D0", "%g" % (D0 * 1e3),
           "-v", "%g" % V, "-T0", "%g" % T0]
    try:
        proc = subprocess.run(cmd, cwd=case, stdout=subprocess.PIPE,
                              stderr=subprocess.STDOUT, text=True,
                              timeout=TIMEOUT)
        out, code = proc.stdout, proc.returncode
    except subprocess.TimeoutExpired:
        out, code = "", None
    wall = time.time() - t0
    end = float(fc.get_entry(case, "system/runTime", "endTime"))
    times = [t for t, _ in fc.time_dirs(case)]
    ok = code == 0 and times and abs(times[-1] - end) <= 1e-6 * end \
        and "foot radius Rf" in out
    checks.check("taylorTest_run", ok,
                 "%s: exit code %s in %.0f s, last time %s of end time %g s%s"
                 % (" ".join(cmd), code, wall,
                    "%g" % times[-1] if times else "none", end,
                    "" if ok else "; output: " + out[-1500:]))
    if not ok:
        checks.exit()

    ph = sp.phase_dict(case)
    rho, T = sp.rest_density(ph, 1e5, T0)
    s_lo = sp.flow_stress(ph, T, epsP=0.1, rate=1.0)
    s_hi = sp.flow_stress(ph, T, epsP=2.0, rate=1e5)
    q = rho * V * V / 2
    lo, hi = math.exp(-q / s_lo), math.exp(-q / s_hi)
    Lf, Rf, W, t = sp.shape(case)
    tab = sp.read_rod_table(case)
    growth = max(b - a for a, b in zip(tab["length"], tab["length"][1:]))
    u_end = tab["axialVelocity"][-1]
    r_min = R0 * math.sqrt(L0 / Lf)
    problems = []
    if not lo < Lf / L0 < hi:
        problems.append("Lf/L0 = %.3f outside (%.3f, %.3f)"
                        % (Lf / L0, lo, hi))
    if not r_min <= Rf < 2.5 * R0:
        problems.append("Rf = %.3f mm outside [%.3f, %.3f) mm"
                        % (Rf * 1e3, r_min * 1e3, 2.5 * R0 * 1e3))
    if growth > H:
        problems.append("the length grew by %.3f mm between two writes"
                        % (growth * 1e3))
    if abs(u_end) > 0.1 * V:
        problems.append("axial velocity %.1f m/s at the end" % u_end)
    checks.check("taylorTest_shape", not problems,
                 "%s, h = %g mm: Lf = %.2f mm (Lf/L0 = %.3f in (%.3f, %.3f) "
                 "from sigma %.0f-%.0f MPa), Rf = %.2f mm (>= %.2f, < %.2f), "
                 "largest length growth %.3f mm, final axial velocity "
                 "%.1f m/s%s"
                 % (material, H * 1e3, Lf * 1e3, Lf / L0, lo, hi,
                    s_lo * 1e-6, s_hi * 1e-6, Rf * 1e3, r_min * 1e3,
                    2.5 * R0 * 1e3, growth * 1e3, u_end,
                    ("; PROBLEMS: " + "; ".join(problems)) if problems
                    else ""))
    checks.exit()


if __name__ == "__main__":
    main()
