#!/usr/bin/python3
"""V6 (docs/validation.md): conservation in a closed box, and serial = parallel.

tutorials/impactFoam/closedBox: a 2-D box [0, 1]^2 m (40 x 40 cells, slip
walls, empty front and back) with a copper disc and an aluminium block that
touch and collide (random rigid velocities of 50-200 m/s plus 2 m/s random
per cell), air with an independent random velocity in every cell, all with
z components; p 1e5 Pa; 150 steps of 3e-7 s (fixed: maxDeltaT is below the
stable step). Run serially and on 2 processes as the tutorial's Allrun
and Allrun -parallel do (decomposePar with method simple, mpirun -np 2
impactFoam -parallel, reconstructPar; the solver capped at twice the
expected number of steps), at first and at second order
(discreteEquations/order in system/fvSchemes), and once more at second
order with the air relaxed along its ambient isentrope (as in the copper
impact tutorials; tag V6_isentropicAir_o2), and once more at second order
with every mixed cell at first order and HLL at its faces in every step
(discreteEquations fallbackInterfaces yes, tag V6_o2_fallback): the a
posteriori fall-back's mixed faces keep conservation and serial =
parallel (docs/numerics.md 8.3).

Checks (VALIDATION V6), from the fields at t = 0 and at the end:
  - mass of each phase, sum(alpha_k rho_k V), conserved to 1e-12 relative;
  - total energy, sum over phases of alpha_k rho_k (e_h + e_e) V plus
    sum(1/2 rho |U|^2 V), conserved to 1e-12 relative, with
    e_h = (p_k + gamma pInf)/((gamma - 1) rho_k) and
    e_e = mu/(4 rho0) ((1 - 2a)/3 j1^2 + a j2 + 3(a - 1)) of the unimodular
    Finger tensor g of A_k (docs/model.md);
  - z-momentum sum(rho U_z V): no wall is normal to z, so it is conserved
    exactly; change <= 1e-12 of sum(rho |U| V). The x and y momenta change
    by the wall forces (printed);
  - sum of the volume fractions is 1 in every cell (to 1e-13);
  - serial and parallel fields at the end time agree to 1e-10 relative:
    the difference is divided by the field's largest magnitude (for
    pressures by max |p| + gamma pInf of the phase, of copper for the
    mixture p); phase fields (rho.k, p.k, A.k, epsilonP.k) are compared
    where alpha_k > 1e-6 (a trace's state is not physical and not
    conserved: its differences are printed over all cells too).
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
import solverRun                              # noqa: E402

TUTORIAL = "closedBox"
ORDERS = (1, 2)
CONSERVATION_TOL = 1e-12
PARALLEL_TOL = 1e-10
SUM_ALPHA_TOL = 1e-13
ALPHA_TRACE = 1e-6
RUN_TIMEOUT = 180       # seconds per solver run (normal: 2-10 s)

checks = Checks()


# --------------------------------------------------------------------------
# Materials (from constant/phaseProperties)
# --------------------------------------------------------------------------

def _sub_dict(text, name):
    """Text inside 'name { ... }' (braces matched), or None."""
    m = re.search(r"(^|[\s;{])%s\s*\{" % re.escape(name), text)
    if not m:
        return None
    i, depth = m.end(), 1
    while depth and i < len(text):
        depth += {"{": 1, "}": -1}.get(text[i], 0)
        i += 1
    return text[m.end():i - 1]


def _number(text, key):
    m = re.search(r"\b%s\s+([-+0-9.eE]+)\s*;" % key, text)
    return float(m.group(1)) if m else None


def read_phases(case):
    """[(name, dict)] with gamma, pInf and, for solids, rho0, mu, a."""
    with open(os.path.join(case, "constant", "phaseProperties")) as f:
        text = fc.strip_comments(f.read())
    names = re.search(r"\bphases\s*\(([^)]*)\)", text).group(1).split()
    out = []
    for name in names:
        d = _sub_dict(text, name)
        eos = _sub_dict(d, "equationOfState")
        ph = {"gamma": _number(eos, "gamma"), "pInf": _number(eos, "pInf"),
              "solid": re.search(r"\btype\s+solid\s*;", d) is not None}
        if ph["solid"]:
            el = _sub_dict(d, "elasticity")
            etype = re.search(r"\btype\s+(\w+)\s*;", el).group(1)
            a = {"neoHookean": -1.0, "metal": 0.5}.get(etype)
            if a is None:
                a = _number(el, "a")
            ph.update(rho0=_number(el, "rho0"), mu=_number(el, "mu"), a=a)
        out.append((name, ph))
    return out


def elastic_energy(A, ph):
    """e_e per unit mass for cobasis tensors A (N, 9), row-major."""
    A = A.reshape(-1, 3, 3)
    G = np.einsum("nki,nkj->nij", A, A)                 # A^T A
    detA = np.linalg.det(A)
    g = G * (detA ** 2)[:, None, None] ** (-1.0 / 3.0)
    j1 = np.trace(g, axis1=1, axis2=2)
    j2 = np.einsum("nij,nji->n", g, g)
    a = ph["a"]
    return ph["mu"] / (4 * ph["rho0"]) * ((1 - 2 * a) / 3 * j1 ** 2
                                          + a * j2 + 3 * (a - 1))


# --------------------------------------------------------------------------
# Totals
# --------------------------------------------------------------------------

def state(case, time, phases, n):
    """Per-phase alpha, rho, p, A and U, rho of a time directory; at t = 0
    (nothing but the inputs written) p.k = p and A.k = (rho/rho0)^(1/3) I
    as impactFoam starts."""
    s = {"U": fc.read_field(case, time, "U", n), "phases": {}}
    for name, ph in phases:
        alpha = fc.read_field(case, time, "alpha." + name, n)
        rho = fc.read_field(case, time, "rho." + name, n)
        pname = "p." + name if fc.has_field(case, time, "p." + name) else "p"
        p = fc.read_field(case, time, pname, n)
        A = None
        if ph["solid"]:
            if fc.has_field(case, time, "A." + name):
                A = fc.read_field(case, time, "A." + name, n)
            else:
                A = np.cbrt(rho / ph["rho0"])[:, None] \
                    * np.eye(3).ravel()[None, :]
        s["phases"][name] = (alpha, rho, p, A)
    s["rho_phases"] = sum(v[0] * v[1] for v in s["phases"].values())
    s["rho"] = fc.read_field(case, time, "rho", n) \
        if fc.has_field(case, time, "rho") else s["rho_phases"]
    return s


def totals(s, phases, V):
    out = {"mass": {}, "energy_phase": {}}
    internal = 0.0
    for name, ph in phases:
        alpha, rho, p, A = s["phases"][name]
        m = alpha * rho
        out["mass"][name] = np.sum(m * V)
        e = (p + ph["gamma"] * ph["pInf"]) / ((ph["gamma"] - 1) * rho)
        if ph["solid"]:
            e = e + elastic_energy(A, ph)
        out["energy_phase"][name] = np.sum(m * e * V)
        internal += out["energy_phase"][name]
    U = s["U"]
    kinetic = np.sum(0.5 * s["rho"] * np.sum(U * U, axis=1) * V)
    out["internal"] = internal
    out["kinetic"] = kinetic
    out["energy"] = internal + kinetic
    out["momentum"] = (s["rho"] * V) @ U
    out["momentum_scale"] = np.sum(s["rho"] * np.linalg.norm(U, axis=1) * V)
    return out


def box_residuals(case):
    """The closed box's conservation from t = 0 to its latest time:
    (phases, mesh, latest time name, largest relative change of a phase's
    mass, relative change of the total energy)"""
    phases = read_phases(case)
    mesh = mg.read_polymesh(case)
    tEnd = fc.latest_time(case)
    T0 = totals(state(case, "0", phases, mesh.nCells), phases, mesh.V)
    T1 = totals(state(case, tEnd, phases, mesh.nCells), phases, mesh.V)
    worst = max(abs(T1["mass"][n] - T0["mass"][n])/T0["mass"][n]
                for n, _ in phases)
    dE = abs(T1["energy"] - T0["energy"])/abs(T0["energy"])
    return phases, mesh, tEnd, worst, dE


def log_steps(log):
    """Number of steps and the set of time-step sizes in a solver log."""
    dts, courant = [], []
    with open(log) as f:
        for line in f:
            m = re.match(r"Time = \S+\s+deltaT = (\S+)\s+Courant Number max "
                         r"= (\S+)", line)
            if m:
                dts.append(float(m.group(1)))
                courant.append(float(m.group(2)))
    return len(dts), dts, courant


def steps_fixed(dts, max_dt, want):
    """The run took want steps of max_dt, up to the end: OpenFOAM may split
    the last one in two to land on the end time despite round-off."""
    return (want <= len(dts) <= want + 1
            and all(abs(dt - max_dt) <= 1e-9 * max_dt
                    for dt in dts[:want - 1])
            and abs(sum(dts[want - 1:]) - max_dt) <= 1e-9 * max_dt)


# --------------------------------------------------------------------------

def isentropic_air(case):
    """Air relaxed along the ambient isentrope (pressureRelaxation
    isentropic; referenceIsentrope (1.2 1e5);), as in the copper impact
    tutorials: the energy the air does not take goes to the heaviest phase,
    so the total must still be conserved."""
    path = os.path.join(case, "constant", "phaseProperties")
    with open(path) as f:
        text = f.read()
    m = re.search(r"(^|\n)air\s*\{", text)
    if not m:
        raise fc.FoamError("no air sub-dictionary in " + path)
    text = (text[:m.end()] + "\n    pressureRelaxation isentropic;"
            "\n    referenceIsentrope (1.2 1e5);" + text[m.end():])
    with open(path, "w") as f:
        f.write(text)


def run_tutorial(name, order, parallel, isentropic=False, before_run=None,
                 fallback=False):
    """The steps of the tutorial's Allrun [-parallel], with the solver run
    capped at twice the expected number of steps; before_run(case), if
    given, changes the case after its initial fields are set; fallback:
    every mixed cell at first order (discreteEquations
    fallbackInterfaces yes)."""
    case = fc.copy_tutorial(TUTORIAL, name)
    fc.set_entry(case, "system/fvSchemes", "order", order)
    if fallback:
        fc.set_entry(case, "system/fvSchemes",
                     "discreteEquations/fallbackInterfaces", "yes")
    if isentropic:
        isentropic_air(case)
    t_end = float(fc.get_entry(case, "system/controlDict", "endTime"))
    max_dt = float(fc.get_entry(case, "system/controlDict", "maxDeltaT"))
    max_steps = 2 * int(round(t_end / max_dt))
    fc.run(case, ["blockMesh"])
    shutil.rmtree(os.path.join(case, "0"), ignore_errors=True)
    shutil.copytree(os.path.join(case, "0.orig"), os.path.join(case, "0"))
    fc.run(case, ["setFields"])
    fc.run(case, [sys.executable, "randomVelocity.py", ".", "1"],
           log="log.randomVelocity")
    if before_run:
        before_run(case)
    if parallel:
        fc.write_decompose_dict(case, 2)
        fc.run(case, ["decomposePar"])
        solverRun.run_capped(case, "mpirun --oversubscribe -np 2 "
                             "impactFoam -parallel", max_steps,
                             log="log.mpirun",
                             timeout=RUN_TIMEOUT)
        fc.run(case, ["reconstructPar"])
    else:
        solverRun.run_capped(case, "impactFoam", max_steps,
                             timeout=RUN_TIMEOUT)
    return case


def check_order(order, isentropic=False, fallback=False):
    tag = ("V6_isentropicAir_o%d" if isentropic else "V6_o%d") % order
    if fallback:
        tag += "_fallback"
    try:
        serial = run_tutorial(tag + "_serial", order, False, isentropic,
                              fallback=fallback)
    except fc.FoamError as e:
        checks.fail("%s_serial_run" % tag, e.summary)
        checks.note(str(e))
        return

    t_end = float(fc.get_entry(serial, "system/controlDict", "endTime"))
    max_dt = float(fc.get_entry(serial, "system/controlDict", "maxDeltaT"))
    phases = read_phases(serial)
    mesh = mg.read_polymesh(serial)
    V, n = mesh.V, mesh.nCells
    steps, dts, courant = log_steps(os.path.join(serial, "log.impactFoam"))
    if fallback:
        text = open(os.path.join(serial, "log.impactFoam")).read()
        m = re.search(r"Fallback to first order: (\S+) of (\S+) cell updates",
                      text)
        share = float(m.group(1)) / float(m.group(2)) if m else 0.0
        checks.check("%s_fallbackActive" % tag, share > 0,
                     "fallbackInterfaces yes: %.3g of the cell updates at "
                     "first order" % share)
    want = int(round(t_end / max_dt))
    fixed = steps_fixed(dts, max_dt, want)
    try:
        t = fc.find_time(serial, t_end)
        s0 = state(serial, "0", phases, n)
        s1 = state(serial, t, phases, n)
    except fc.FoamError as e:
        checks.fail("%s_serial_run" % tag, e.summary)
        return
    finite = all(np.all(np.isfinite(x)) for v in s1["phases"].values()
                 for x in v if x is not None) and np.all(np.isfinite(s1["U"]))
    checks.check("%s_serial_run" % tag, fixed and finite,
                 "order %d, %d cells, %d steps (want %d), every step %g s "
                 "(but the last two may split one): %s, largest Courant "
                 "number %.3f, fields finite: %s"
                 % (order, n, steps, want, max_dt, fixed,
                    max(courant or [0]), finite))
    if not finite:
        return

    # activity: the solids really collided and yielded
    eps = {name: np.max(fc.read_field(serial, t, "epsilonP." + name, n))
           for name, ph in phases if ph["solid"]}
    checks.note("order %d, t = %g s: max equivalent plastic strain %s; max "
                "Von Mises stress %.4g Pa; max |U| %.4g m/s"
                % (order, float(t),
                   ", ".join("%s %.4g" % kv for kv in eps.items()),
                   np.max(fc.read_field(serial, t, "sigmaEq", n)),
                   np.max(np.linalg.norm(s1["U"], axis=1))))

    T0, T1 = totals(s0, phases, V), totals(s1, phases, V)

    for name, ph in phases:
        m0, m1 = T0["mass"][name], T1["mass"][name]
        rel = abs(m1 - m0) / m0
        checks.check("%s_mass_%s" % (tag, name), rel <= CONSERVATION_TOL,
                     "sum(alpha rho V) %.17g -> %.17g kg, relative change "
                     "%.3e (bound 1e-12)" % (m0, m1, rel))

    dE = T1["energy"] - T0["energy"]
    rel = abs(dE) / abs(T0["energy"])
    checks.check("%s_energy" % tag, rel <= CONSERVATION_TOL,
                 "total energy %.17g -> %.17g J, relative change %.3e "
                 "(bound 1e-12); change = %.3e of the initial kinetic "
                 "energy %.6g J (kinetic now %.6g J)"
                 % (T0["energy"], T1["energy"], rel, dE / T0["kinetic"],
                    T0["kinetic"], T1["kinetic"]))
    checks.note("internal energy change per phase: " + ", ".join(
        "%s %.6g J" % (name, T1["energy_phase"][name]
                       - T0["energy_phase"][name]) for name, _ in phases))

    P0, P1 = T0["momentum"], T1["momentum"]
    scale = T0["momentum_scale"]
    dPz = abs(P1[2] - P0[2])
    checks.check("%s_momentum_z" % tag, dPz <= CONSERVATION_TOL * scale,
                 "z-momentum %.17g -> %.17g kg m/s: change %.3e = %.3e of "
                 "sum(rho |U| V) = %.6g (bound 1e-12); x, y momenta (wall "
                 "forces) %.6g -> %.6g, %.6g -> %.6g"
                 % (P0[2], P1[2], dPz, dPz / scale, scale, P0[0], P1[0],
                    P0[1], P1[1]))
    mix = np.max(np.abs(s1["rho"] - s1["rho_phases"]) / s1["rho"])
    checks.note("mixture rho against sum(alpha_k rho_k): max relative "
                "difference %.3e" % mix)

    sum_alpha = sum(v[0] for v in s1["phases"].values())
    dev = np.max(np.abs(sum_alpha - 1))
    checks.check("%s_sum_alpha" % tag, dev <= SUM_ALPHA_TOL,
                 "max |sum alpha_k - 1| = %.3e (bound 1e-13)" % dev)

    # ------------------------------------------------------------------
    # serial against parallel
    try:
        par = run_tutorial(tag + "_parallel", order, True, isentropic,
                           fallback=fallback)
        tp = fc.find_time(par, t_end)
    except fc.FoamError as e:
        checks.fail("%s_parallel_run" % tag, e.summary)
        checks.note(str(e))
        return
    psteps, pdts, _ = log_steps(os.path.join(par, "log.mpirun"))
    pfixed = steps_fixed(pdts, max_dt, want)
    same = len(pdts) == len(dts) and all(a == b for a, b in zip(dts, pdts))
    checks.check("%s_parallel_run" % tag, pfixed and same,
                 "mpirun -np 2 impactFoam -parallel: %d steps (want %d), "
                 "every step %g s (but the last two may split one): %s; "
                 "the same steps as the serial run: %s"
                 % (psteps, want, max_dt, pfixed, same))

    gamma_pinf = {name: ph["gamma"] * ph["pInf"] for name, ph in phases}
    alpha_s = {name: s1["phases"][name][0] for name, _ in phases}
    worst, worst_field, rows = 0.0, "", []
    for fname in sorted(os.listdir(os.path.join(serial, t))):
        path = os.path.join(serial, t, fname)
        if not os.path.isfile(path) or fname in ("C", "V"):
            continue
        try:
            a = fc.read_field(serial, t, fname, n).reshape(n, -1)
            b = fc.read_field(par, tp, fname, n).reshape(n, -1)
        except fc.FoamError as e:
            checks.fail("%s_parallel_%s" % (tag, fname), e.summary)
            continue
        base, _, phase = fname.partition(".")
        diff = np.max(np.abs(a - b), axis=1)
        if base == "alpha":
            scale = 1.0
        elif base == "p":
            scale = np.max(np.abs(a)) + (gamma_pinf[phase] if phase
                                         else max(gamma_pinf.values()))
        else:
            scale = np.max(np.abs(a)) or 1.0
        rel_all = np.max(diff) / scale
        if phase and base != "alpha":
            mask = alpha_s[phase] > ALPHA_TRACE
            rel = np.max(diff[mask]) / scale if mask.any() else 0.0
            rows.append("%-20s %.3e (alpha > 1e-6), %.3e (all cells)"
                        % (fname, rel, rel_all))
        else:
            rel = rel_all
            rows.append("%-20s %.3e" % (fname, rel))
        if rel >= worst:
            worst, worst_field = rel, fname
    checks.note("order %d, serial - parallel, max |difference| / scale per "
                "field:\n" % order + "\n".join(rows))
    checks.check("%s_serial_parallel" % tag, worst <= PARALLEL_TOL,
                 "largest relative difference %.3e (%s) over %d fields "
                 "(bound 1e-10)" % (worst, worst_field, len(rows)))


def main():
    missing = fc.require_apps("impactFoam", "blockMesh", "setFields",
                              "decomposePar", "reconstructPar", "mpirun")
    if missing:
        checks.fail("V6_run", "%s not found on PATH (impactFoam not built "
                    "or environment not sourced: . etc/bashrc)"
                    % " ".join(missing))
        checks.exit()
    for order in ORDERS:
        check_order(order)
    check_order(2, isentropic=True)
    check_order(2, fallback=True)
    checks.exit()


if __name__ == "__main__":
    main()
