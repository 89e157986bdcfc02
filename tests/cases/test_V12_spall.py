#!/usr/bin/python3
"""V12 (docs/validation.md), the parts the test suite decides: failure by a
tensile pressure cutoff (failure { type spall; }) in a 1-D copper
flyer-plate impact, and conservation through failure.

Case: tutorials/impactFoam/spallPlate at 25 um cells (400 cells, 4 us): a
2 mm OFHC copper flyer (Mie-Grueneisen, Johnson-Cook strength) at 200 m/s
on a 4 mm copper target, free surfaces in air, sigmaSpall 1.3 GPa. The release waves from the flyer's back and from the
target's free surface meet 2 mm inside the target (x = 5 mm at impact).
Checks:
  - the target's free surface first rises to the impact speed (2 %);
  - the target fails in a layer (damage >= 1/2: the transport mixes D)
    around the plane where the release waves meet, 5 +- 0.5 mm, and
    nowhere else at 1.7 us;
  - after failure the copper holds no tension beyond sigmaSpall: the
    lowest copper pressure over the run, in cells not failed, stays above
    -1.05 sigmaSpall (the cutoff acts in the step that reaches it), and
    failed copper that a fluid shares its cell with holds no tension
    beyond 1e-3 sigmaSpall;
  - the free-surface velocity shows the pull-back: it falls by more than
    10 m/s below its plateau and rises again (the spall signal), and the
    acoustic estimate rho0 c_b dU/2 is within 15 % of sigmaSpall (V12's
    criterion, here at 25 um; validation/spall/validate adds 10 um);
  - the tutorial fails over spallTime 0.1 us. Failing at once instead
    (spallTime 0): the copper holds no tension beyond sigmaSpall either,
    and the pull-back is smaller (a spike as narrow as the smeared
    release front);
  - one wave speed (the copper's shear modulus 1 MPa, no plasticity),
    where the acoustic estimate is exact for a plane that holds
    sigmaSpall while it opens: within 3 % (the spall plane transmits its
    strength; before the failing copper kept its own state in the
    relaxation it was 53 % low);
  - without failure (failure { type none; }), no damage is carried, the
    target holds a tension beyond 2 sigmaSpall, and the free surface
    falls by more than twice the pull-back of the spalled target.
Conservation through failure: the closed box of V6 (copper disc and
aluminium block colliding in air, 150 steps) with Johnson-Cook damage at a
strain to fracture of 0.01 and a cutoff of 0.1 GPa in the copper
(failure { type JohnsonCook; D1 0.01; D2 0; D3 0; sigmaSpall 1e8; }), and
with a 20 MPa spall cutoff over spallTime 1e-8 s (failing copper in
tension keeps its own state in the pressure relaxation): some copper
fails (counted at a write every 5 steps: afterwards the transport mixes a
failed cell's damage below 1), and mass of each phase and total energy are
conserved to 1e-12 relative.

The acoustic estimate of the spall strength from the pull-back (within
15 % in docs/validation.md V12) is decided by validation/spall/validate, not here.
"""
import os
import re
import sys

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "lib"))
sys.path.insert(0, os.path.join(HERE, "..", "..", "validation", "spall"))
import foamcase as fc                         # noqa: E402
from checks import Checks                     # noqa: E402
import freeSurface as fs                      # noqa: E402
sys.path.insert(0, HERE)
import test_V6_conservation as v6             # noqa: E402

SIGMA_SPALL = 1.3e9
checks = Checks()


def set_failure(case, text):
    path = os.path.join(case, "constant", "phaseProperties")
    with open(path) as f:
        src = f.read()
    src, n = re.subn(r"failure\s*\{[^}]*\}", text, src)
    if n != 1:
        raise fc.FoamError("no failure entry in %s" % path)
    with open(path, "w") as f:
        f.write(src)


def acoustic_estimate(dU):
    """rho0 c_b dU/2 of the tutorial's copper (c_b = c0)"""
    return 0.5*8930*3940*dU


def one_wave_speed(case):
    """The copper without strength: shear modulus 1 MPa, no plasticity"""
    path = os.path.join(case, "constant", "phaseProperties")
    with open(path) as f:
        src = f.read()
    src, n1 = re.subn(r"mu 4\.6e10;", "mu 1e6;", src)
    src, n2 = re.subn(r"plasticity\s*\{.*?\n    \}\n",
                      "plasticity { type none; }\n", src, flags=re.S)
    if n1 != 1 or n2 != 1:
        raise fc.FoamError("%s: copper's mu or plasticity not found" % path)
    with open(path, "w") as f:
        f.write(src)


def run_spall(name, failure=None, modify=None):
    case = fc.copy_tutorial("spallPlate", name)
    if failure:
        set_failure(case, failure)
    if modify:
        modify(case)
    fc.run(case, ["./Allrun", "-h", "0.025"], log="log.Allrun")
    return case


def scan(case, failed_field=True):
    """Per time: (t, lowest p of copper not failed, lowest p of failed
    copper sharing its cell with air, failed x range)."""
    x = fc.cell_centres(case)[:, 0]
    out = []
    for t, name in fc.time_dirs(case):
        if t <= 0:
            continue
        p = fc.read_field(case, name, "p.copper")
        a = fc.read_field(case, name, "alpha.copper")
        inside = a > 1e-3
        if failed_field:
            D = fc.read_field(case, name, "damage.copper")
            failed = D >= 1 - 1e-6
        else:
            failed = np.zeros_like(p, dtype=bool)
        intact = inside & ~failed
        shared = inside & failed
        # The failed layer: mostly failed mass (the transport mixes D)
        layer = inside & (D >= 0.5) if failed_field else shared
        out.append((t,
                    p[intact].min() if intact.any() else 0.0,
                    p[shared].min() if shared.any() else 0.0,
                    (x[layer].min(), x[layer].max()) if layer.any()
                    else None))
    return out


def main():
    missing = fc.require_apps("impactFoam", "blockMesh", "setFields")
    if missing:
        checks.fail("V12_run", "%s not found on PATH" % " ".join(missing))
        checks.exit()

    try:
        case = run_spall("V12_spall")
        t, u = fs.history(case, "copper")
    except fc.FoamError as e:
        checks.fail("V12_spall_run", e.summary)
        checks.note(str(e))
        checks.exit()

    pb = fs.pull_back(t, u)
    checks.check("V12_freeSurfacePeak",
                 pb is not None and abs(pb[0] - 200) <= 4,
                 "free-surface plateau %.2f m/s (impact speed 200)"
                 % (pb[0] if pb else float("nan")))

    rows = scan(case)
    at = min(rows, key=lambda r: abs(r[0] - 1.7e-6))
    rng = at[3]
    checks.check("V12_spallPlane",
                 rng is not None and rng[0] >= 4.5e-3 and rng[1] <= 5.5e-3,
                 "failed copper at t = %.3g s in x = %s mm (expected within "
                 "5 +- 0.5 mm)" % (at[0], None if rng is None else
                                   "%.3f-%.3f" % (rng[0]*1e3, rng[1]*1e3)))
    pIntact = min(r[1] for r in rows)
    pFailed = min(r[2] for r in rows)
    checks.check("V12_noTensionBeyondCutoff",
                 pIntact >= -1.05*SIGMA_SPALL,
                 "lowest pressure of copper not failed %.4g Pa (bound "
                 "-1.05 sigmaSpall = %.4g)" % (pIntact, -1.05*SIGMA_SPALL))
    checks.note("lowest pressure of failed copper sharing its cell with "
                "air: %.4g Pa" % pFailed)
    dU = None
    if pb is not None and pb[1] is not None:
        dU = pb[0] - pb[1]
        later = u[t > pb[3]]
        rebound = later.max() - pb[1] if len(later) else 0
        checks.check("V12_pullBack", dU > 10 and rebound > 5,
                     "plateau %.2f, minimum %.2f m/s at %.3g s: dU = %.2f "
                     "m/s, then up by %.2f m/s"
                     % (pb[0], pb[1], pb[3], dU, rebound))
        estimate = acoustic_estimate(dU)
        checks.check("V12_acousticEstimate",
                     abs(estimate/SIGMA_SPALL - 1) <= 0.15,
                     "rho0 c_b dU/2 = %.4g Pa (c_b 3940 m/s): %+.1f %% from "
                     "sigmaSpall (bound 15 %%)"
                     % (estimate, 100*(estimate/SIGMA_SPALL - 1)))
    else:
        checks.fail("V12_pullBack", "no pull-back signal")

    # Failing at once (spallTime 0)
    try:
        once = run_spall("V12_atOnce", "failure { type spall; "
                         "sigmaSpall 1.3e9; }")
        to_, uo_ = fs.history(once, "copper")
    except fc.FoamError as e:
        checks.fail("V12_atOnce_run", e.summary)
        checks.exit()
    pbo = fs.pull_back(to_, uo_)
    pIntactO = min(r[1] for r in scan(once))
    dUo = pbo[0] - pbo[1] if pbo and pbo[1] is not None else float("nan")
    checks.check("V12_atOnce",
                 pIntactO >= -1.05*SIGMA_SPALL and dU is not None
                 and dUo < dU,
                 "spallTime 0: lowest pressure of copper not failed "
                 "%.4g Pa (bound %.4g); pull-back %.2f m/s (over 0.1 us: %s)"
                 % (pIntactO, -1.05*SIGMA_SPALL, dUo,
                    "%.2f" % dU if dU else None))

    # One wave speed: the acoustic estimate is exact
    try:
        hydro = run_spall("V12_oneWaveSpeed", modify=one_wave_speed)
        th, uh = fs.history(hydro, "copper")
    except fc.FoamError as e:
        checks.fail("V12_oneWaveSpeed_run", e.summary)
        checks.exit()
    pbh = fs.pull_back(th, uh)
    if pbh is not None and pbh[1] is not None:
        eh = acoustic_estimate(pbh[0] - pbh[1])
        checks.check("V12_oneWaveSpeed", abs(eh/SIGMA_SPALL - 1) <= 0.03,
                     "shear modulus 1 MPa, no plasticity: dU = %.2f m/s, "
                     "rho0 c_b dU/2 = %.4g Pa, %+.1f %% from sigmaSpall "
                     "(bound 3 %%)" % (pbh[0] - pbh[1], eh,
                                       100*(eh/SIGMA_SPALL - 1)))
    else:
        checks.fail("V12_oneWaveSpeed", "no pull-back signal")

    # Without failure
    try:
        none = run_spall("V12_noFailure", "failure { type none; }")
        tn, un = fs.history(none, "copper")
    except fc.FoamError as e:
        checks.fail("V12_noFailure_run", e.summary)
        checks.exit()
    hasD = any(fc.has_field(none, name, "damage.copper")
               for _, name in fc.time_dirs(none))
    pmin = min(r[1] for r in scan(none, failed_field=False))
    peak = un.max()
    after = un[np.argmax(un):]
    drop = peak - after.min()
    checks.check("V12_noFailure",
                 not hasD and pmin < -2*SIGMA_SPALL
                 and dU is not None and drop > 2*dU,
                 "no damage field: %s; lowest copper pressure %.4g Pa "
                 "(< -2 sigmaSpall); free surface falls by %.2f m/s after "
                 "its peak (spalled: %.2f)"
                 % (not hasD, pmin, drop, dU if dU else float("nan")))

    # Conservation through failure: V6's closed box, failing at once and
    # over spallTime (failing material in tension then keeps its own state
    # in the pressure relaxation)
    for tag, failure in (
            ("", "type JohnsonCook; D1 0.01; D2 0; D3 0; sigmaSpall 1e8;"),
            ("_spallTime", "type spall; sigmaSpall 2e7; spallTime 1e-8;")):
        def add_failure(case):
            path = os.path.join(case, "constant", "phaseProperties")
            with open(path) as f:
                text = f.read()
            m = re.search(r"(^|\n)copper\s*\{", text)
            text = (text[:m.end()] + "\n    failure { %s }" % failure
                    + text[m.end():])
            with open(path, "w") as f:
                f.write(text)
            # A write every 5 steps: failed cells are counted at each (the
            # transport mixes a failed cell's damage below 1 afterwards)
            fc.set_entry(case, "system/controlDict", "writeControl",
                         "timeStep")
            fc.set_entry(case, "system/controlDict", "writeInterval", 5)
        try:
            box = v6.run_tutorial("V12_closedBox" + tag, 2, False,
                                  before_run=add_failure)
        except fc.FoamError as e:
            checks.fail("V12_conservation%s_run" % tag, e.summary)
            continue
        phases, mesh, tEnd, worst, dE = v6.box_residuals(box)
        nFailed, nDamaged = 0, 0
        for _, n in fc.time_dirs(box):
            if n == "0":
                continue
            D = fc.read_field(box, n, "damage.copper", mesh.nCells)
            a = fc.read_field(box, n, "alpha.copper", mesh.nCells)
            nFailed = max(nFailed, int(np.sum((D >= 1 - 1e-6) & (a > 1e-3))))
            nDamaged = max(nDamaged, int(np.sum((D > 0) & (a > 1e-3))))
        checks.check("V12_conservation" + tag,
                     nFailed > 0 and worst <= 1e-12 and dE <= 1e-12,
                     "closed box, failure { %s }: at most %d cells of "
                     "failed copper (%d damaged) at the writes to t = %s; "
                     "largest relative mass change "
                     "%.3e, total energy %.3e (bound 1e-12)"
                     % (failure, nFailed, nDamaged, tEnd, worst, dE))
    checks.exit()


if __name__ == "__main__":
    main()
