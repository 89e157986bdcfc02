#!/usr/bin/python3
"""Axisymmetric wedge (docs/numerics.md 7): the uniformly expanding ring and a
hydrostatic state at rest.

Meshes (blockMesh, written by this script into tests/run/): one cell thick
wedges of angle THETA about the x axis (OpenFOAM's convention: axis x,
radial direction y, the two 'wedge' patches at z = +-y tan(THETA/2)),
x in [0, 0.02] m:
    ring    annulus r in [0.01, 0.05] m, 8 x 20 cells, 2 and 5 degrees
    disc    r in [0, 0.05] m (cells on the axis are prisms), 8 x 20 cells,
            2 degrees
checkMesh must say "Mesh OK". Copper (rho0 8900, SG 4.22 / 3.42e10 Pa,
mu 4.5e10 Pa, a = 1/2, elastic), one phase, second order (default), unlimited
least-squares gradients.

1. Expanding ring: u = k (0, y, z), i.e. u_r = k r and no axial or swirl
   velocity, k = 1000 s^-1 (50 m/s at r = 0.05 m), written at the cell
   centres and as fixedValue at the face centres of the non-wedge patches
   (tests/lib/fieldWriter.py). Cell centres lie in the mid-plane z = 0,
   where e_r = e_y and e_theta = e_z, so the cobasis update must see
   L = k (I - e_x e_x) = k diag(0, 1, 1): L_yy = du_r/dr = k (radial),
   L_zz = u_r/r = k (hoop, from the wedge faces), L_xx = 0.
   tests/tools/cobasisRateCheck (one step of 1e-12 times the stable step)
   gives L per cell. Checks on the ring meshes (relative to k):
     wedge<angle>_hoop     max |L_zz/k - 1|
     wedge<angle>_radial   max |L_yy/k - 1|
     wedge<angle>_L        max |L - k diag(0,1,1)| / k over all cells
   Tolerance 1e-6 relative to k. Why that number: u = k (0, y, z) is a linear
   Cartesian field, and docs/numerics.md 4 requires the face velocities to be
   reconstructed exactly for linear fields; with exact face-centroid
   velocities the Green-Gauss identity sum_f x_f (x) S_f = V I (planar
   faces) makes L exact up to round-off (about 1e-16 r/(r sin(THETA/2))
   ~ 1e-13 here), so an exact-by-construction wedge treatment passes with
   a wide margin. The upper end comes from the stress budget of V10: an
   error e in L accumulates a spurious strain e times the flow's strain,
   O(1) in an impact, i.e. a spurious deviatoric stress ~ e mu; 1e-6 keeps
   it ten times below V10's 1e-5 mu. Geometric errors of the wedge
   treatment (the mirrored or fully rotated ghost of docs/numerics.md 7, O(THETA^2)
   ~ 1e-4 to 1e-3; cell-centre velocities on the faces, O(dr/r); a gradient
   not exact on wedges) are all caught. The disc mesh is reported as a note
   (its axis cells have degenerate faces).
   And one impactFoam step of 1e-10 s on the 2-degree ring:
     wedge2_massRate       (drho/dt)/(rho k) = -2 (rho div u, radial +
                           hoop) within 1e-6 in the cells off the inner,
                           outer and end patches (those are reported)
2. Hydrostatic state: p = 1e9 Pa uniform, u = 0, unstrained copper at
   rho 8900 on the ring and the disc (2 degrees), fixedValue U = 0 on the
   non-wedge patches, 50 steps of impactFoam. The wedge faces carry the
   pressure as traction on both sides; the sum over a closed cell vanishes,
   so the state must stay at rest:
     wedge<angle>_rest_<mesh>   max |u| < 1e-10 c_L = 4.79e-7 m/s,
                                and max |p - 1e9| <= 1e-10 (p + gamma pInf)
"""
import os
import re
import shutil
import sys

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "lib"))
import foamcase as fc                         # noqa: E402
from checks import Checks                     # noqa: E402
import meshGeometry as mg                     # noqa: E402
import fieldWriter as fw                      # noqa: E402

K = 1000.0
L_TOL = 1e-6
GAMMA, PINF, RHO0, MU = 4.22, 3.42e10, 8900.0, 4.5e10
P_REST = 1e9
CL = np.sqrt(GAMMA * (1e5 + PINF) / RHO0 + 4.0 * MU / (3.0 * RHO0))
U_TOL = 1e-10 * CL
P_TOL = 1e-10 * (P_REST + GAMMA * PINF)
N_STEPS = 50
DT_STEP = 1e-10

checks = Checks()

HEADER = """/*--------------------------------*- C++ -*----------------------------------*\\
  written by tests/cases/test_wedgeRing.py
\\*---------------------------------------------------------------------------*/
FoamFile
{
    version     2.0;
    format      ascii;
    class       dictionary;
    location    "%s";
    object      %s;
}
// * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * //

"""

CONTROL = """application     impactFoam;
startFrom       startTime;
startTime       0;
stopAt          endTime;
endTime         %(endTime)s;
deltaT          1e-9;
writeControl    timeStep;
writeInterval   %(writeInterval)d;
purgeWrite      0;
writeFormat     ascii;
writePrecision  17;
writeCompression off;
timeFormat      general;
timePrecision   12;
runTimeModifiable false;
adjustTimeStep  yes;
maxCo           0.4;
"""

SCHEMES = """ddtSchemes { default Euler; }
gradSchemes { default leastSquares; }
divSchemes { default none; }
laplacianSchemes { default Gauss linear corrected; }
interpolationSchemes { default linear; }
snGradSchemes { default corrected; }
discreteEquations
{
    order           2;
    riemannSolver   HLLC;
}
"""

PHASES = """phases (copper);
copper
{
    type            solid;
    equationOfState { type stiffenedGas; gamma 4.22; pInf 3.42e10; }
    elasticity      { type separable; rho0 8900; mu 4.5e10; a 0.5; }
    plasticity      { type none; }
}
"""


def blockmesh_dict(theta_deg, r_in, r_out, length=0.02, nx=8, nr=20):
    """A wedge of angle theta about the x axis; r_in = 0 collapses the
    inner edge onto the axis (no 'inner' patch then)."""
    h = 0.5 * np.radians(theta_deg)
    c, s = np.cos(h), np.sin(h)
    v = []
    for z_sign in (-1.0, 1.0):
        for x, r in ((0.0, r_in), (length, r_in), (length, r_out),
                     (0.0, r_out)):
            v.append((x, r * c, z_sign * r * s))
    verts = "\n".join("    (%.17g %.17g %.17g)" % p for p in v)
    inner = "" if r_in == 0 else """    inner
    {
        type patch;
        faces ((0 1 5 4));
    }
"""
    return """scale 1;
vertices
(
%s
);
blocks
(
    hex (0 1 2 3 4 5 6 7) (%d %d 1) simpleGrading (1 1 1)
);
edges ();
boundary
(
%s    outer
    {
        type patch;
        faces ((3 7 6 2));
    }
    ends
    {
        type patch;
        faces ((0 4 7 3) (1 2 6 5));
    }
    front
    {
        type wedge;
        faces ((4 5 6 7));
    }
    back
    {
        type wedge;
        faces ((0 3 2 1));
    }
);
mergePatchPairs ();
""" % (verts, nx, nr, inner)


def write_dict(case, location, name, body):
    os.makedirs(os.path.join(case, location), exist_ok=True)
    with open(os.path.join(case, location, name), "w") as f:
        f.write(HEADER % (location, name) + body +
                "\n// ************************************"
                "************************************* //\n")


def make_case(name, theta, r_in, end_time="1", write_interval=1):
    case = os.path.join(fc.RUN_DIR, name)
    if os.path.lexists(case):
        shutil.rmtree(case)
    os.makedirs(case)
    write_dict(case, "system", "controlDict",
               CONTROL % {"endTime": end_time,
                          "writeInterval": write_interval})
    write_dict(case, "system", "fvSchemes", SCHEMES)
    write_dict(case, "system", "fvSolution", "solvers {}\n")
    write_dict(case, "system", "blockMeshDict",
               blockmesh_dict(theta, r_in, 0.05))
    write_dict(case, "constant", "phaseProperties", PHASES)
    fc.run(case, ["blockMesh"])
    log = fc.run(case, ["checkMesh"])
    with open(log) as f:
        text = f.read()
    ok = "Mesh OK." in text
    checks.check("wedge_%s_checkMesh" % name, ok,
                 "checkMesh on the %g-degree wedge (%s): %s"
                 % (theta, "ring" if r_in > 0 else "disc",
                    "Mesh OK" if ok else "FAILED (see %s)" % log))
    m = mg.read_polymesh(case)
    return case, m


def write_state(case, m, p, U_L0):
    n = m.nCells
    fw.write_field(case, "0", "alpha.copper", np.ones(n), m)
    fw.write_field(case, "0", "rho.copper", np.full(n, RHO0), m)
    fw.write_field(case, "0", "p", np.full(n, p), m)
    fw.write_linear_velocity(case, m, U_L0)


def expanding(theta, r_in, assert_it=True):
    name = "wedge%g_%s_expanding" % (theta, "ring" if r_in > 0 else "disc")
    case, m = make_case(name, theta, r_in)
    L0 = K * np.diag([0.0, 1.0, 1.0])
    write_state(case, m, 1e5, L0)
    arg = "(" + " ".join("%.17g" % x for x in L0.ravel()) + ")"
    log = fc.run(case, ["cobasisRateCheck", "-L0", arg])
    with open(log) as f:
        text = f.read()
    mm = re.search(r"^maxError\s+(\S+)", text, re.M)
    if not mm:
        raise fc.FoamError("no maxError line in %s" % log)
    L = fc.read_field(case, "0", "Lcobasis")
    zc = np.max(np.abs(m.C[:, 2]))
    hoop = np.max(np.abs(L[:, 8] / K - 1))
    radial = np.max(np.abs(L[:, 4] / K - 1))
    full = np.max(np.linalg.norm(L - L0.ravel(), axis=1)) / K
    worst = int(np.argmax(np.abs(L[:, 8] / K - 1)))
    msg = ("%g-degree %s, %d cells (max |z_c| %.1e m): max |L_zz/k - 1| "
           "(hoop) %.3e, max |L_yy/k - 1| (radial) %.3e, max |L - k "
           "diag(0,1,1)|/k %.3e (tool maxError/k %.3e); worst hoop cell "
           "at r = %.4f m: L = %s"
           % (theta, "ring" if r_in > 0 else "disc", m.nCells, zc, hoop,
              radial, full, float(mm.group(1)) / K,
              np.hypot(m.C[worst, 1], m.C[worst, 2]),
              " ".join("%.6g" % x for x in L[worst])))
    tag = "wedge%g" % theta
    if assert_it:
        checks.check(tag + "_hoop", hoop <= L_TOL,
                     "%s (bound 1e-6)" % msg)
        checks.check(tag + "_radial", radial <= L_TOL,
                     "max |L_yy/k - 1| = %.3e (bound 1e-6)" % radial)
        checks.check(tag + "_L", full <= L_TOL,
                     "max |L - k diag(0,1,1)|/k = %.3e (bound 1e-6)"
                     % full)
    else:
        checks.note("expanding, " + msg)


def mass_rate(theta, r_in):
    """One impactFoam step of DT_STEP on the expanding ring: the density
    must fall at rate rho div u = 2 k rho (to O(k dt) = 1e-7)."""
    name = "wedge%g_ring_step" % theta
    case, m = make_case(name, theta, r_in, end_time="%.6g" % DT_STEP)
    write_state(case, m, 1e5, K * np.diag([0.0, 1.0, 1.0]))
    fc.set_entry(case, "system/controlDict", "maxDeltaT", "%.6g" % DT_STEP)
    fc.set_entry(case, "system/controlDict", "deltaT", "%.6g" % DT_STEP)
    fc.run(case, ["impactFoam"], timeout=300)
    t = fc.latest_time(case)
    dt = float(t)
    if not 0.5 * DT_STEP <= dt <= DT_STEP * (1 + 1e-6):
        raise fc.FoamError("%s: one step of %g s expected, last time %s"
                           % (case, DT_STEP, t))
    rho = fc.read_field(case, t, "rho.copper")
    rate = (rho - RHO0) / (RHO0 * dt * K)        # exact: -2 (1 - k dt)
    exact = -2.0 * (1.0 - K * dt)
    rel = np.abs(rate / exact - 1.0)
    # cells with a face on the inner, outer or end patches (fixedValue U)
    bnd = np.zeros(m.nCells, bool)
    for pname, ptype, start, n in m.patches:
        if ptype not in ("wedge", "empty"):
            bnd[m.owner[start:start + n]] = True
    err = float(np.max(rel[~bnd]))
    checks.check("wedge%g_massRate" % theta, err <= L_TOL,
                 "expanding ring, one step of %g s: (drho/dt)/(rho k) in "
                 "[%.6f, %.6f], exact -2 (rho div u = 2 k rho): max "
                 "relative error %.3e over the %d cells off the inner, "
                 "outer and end patches (bound 1e-6); %.3e in the %d cells "
                 "on them" % (dt, rate.min(), rate.max(), err,
                              int((~bnd).sum()), float(np.max(rel[bnd])),
                              int(bnd.sum())))


def rest(theta, r_in):
    mesh = "ring" if r_in > 0 else "disc"
    name = "wedge%g_%s_rest" % (theta, mesh)
    # a step is about 0.4 * 1.2e-7 s on these meshes: endTime far away,
    # stop after N_STEPS with writeInterval = N_STEPS and stopAt writeNow
    case, m = make_case(name, theta, r_in, end_time="1",
                        write_interval=N_STEPS)
    write_state(case, m, P_REST, np.zeros((3, 3)))
    # exactly N_STEPS steps: endTime = N_STEPS maxDeltaT, with maxDeltaT
    # below the stable step (speed bound c_L)
    dt = 0.9 * 0.4 * mg.stable_step(m, CL)
    dt = float("%.6g" % dt)
    fc.set_entry(case, "system/controlDict", "maxDeltaT", "%.6g" % dt)
    fc.set_entry(case, "system/controlDict", "endTime",
                 "%.12g" % (N_STEPS * dt))
    fc.run(case, ["impactFoam"], timeout=300)
    t = fc.latest_time(case)
    with open(os.path.join(case, "log.impactFoam")) as f:
        steps = sum(1 for line in f if line.startswith("Time = "))
    U = fc.read_field(case, t, "U")
    p = fc.read_field(case, t, "p")
    du = float(np.max(np.linalg.norm(U, axis=1)))
    dp = float(np.max(np.abs(p - P_REST)))
    ok = steps >= N_STEPS and du < U_TOL and dp <= P_TOL \
        and np.all(np.isfinite(U))
    checks.check("wedge%g_rest_%s" % (theta, mesh), ok,
                 "p = 1e9 Pa at rest, %d cells, %d steps to t = %s s: "
                 "max |u| = %.3e m/s (bound 1e-10 c_L = %.3g m/s), "
                 "max |p - p0| = %.3e Pa (bound %.3g Pa)"
                 % (m.nCells, steps, t, du, U_TOL, dp, P_TOL))


def main():
    missing = fc.require_apps("impactFoam", "cobasisRateCheck", "blockMesh",
                              "checkMesh")
    if missing:
        checks.fail("wedge_run", "%s not found on PATH (not built or "
                    "environment not sourced: . etc/bashrc; "
                    "cobasisRateCheck is built by tests/Allwmake)"
                    % " ".join(missing))
        checks.exit()

    for theta, r_in, assert_it in ((2.0, 0.01, True), (5.0, 0.01, True),
                                   (2.0, 0.0, False)):
        try:
            expanding(theta, r_in, assert_it)
        except fc.FoamError as e:
            checks.fail("wedge%g_expanding_run" % theta, e.summary)
            checks.note(str(e))

    try:
        mass_rate(2.0, 0.01)
    except fc.FoamError as e:
        checks.fail("wedge2_massRate_run", e.summary)
        checks.note(str(e))

    for theta, r_in in ((2.0, 0.01), (2.0, 0.0)):
        try:
            rest(theta, r_in)
        except fc.FoamError as e:
            checks.fail("wedge%g_rest_run" % theta, e.summary)
            checks.note(str(e))

    checks.exit()


if __name__ == "__main__":
    main()
