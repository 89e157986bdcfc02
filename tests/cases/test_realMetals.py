#!/usr/bin/python3
"""The real-metal models in a 3-phase impact, serial and parallel
(docs/model.md sections 10-11).

Case: the closed box of V6 (tutorials/impactFoam/closedBox: copper disc
and aluminium block colliding in air, slip walls, random velocities, 150
fixed steps of 3e-7 s), order 2, with the copper made OFHC-like:
Mie-Grueneisen (rho0 8900 as its elasticity, c0 3940, s 1.489, Gamma0
2.02, Cv 383, T0 298), Johnson-Cook flow stress (A 9e7, B 2.92e8, n 0.31,
C 0.025, m 1.09, Tr 298, Tm 1356) and Johnson-Cook damage with a strain to
fracture of 0.01 and a 0.1 GPa cutoff (so that some copper fails). Run
serially and on 2 processes.
Checks:
  - the run completes with the fixed steps; some copper yields and fails;
    T.copper is written and finite;
  - the mass of each phase and the total energy (Mie-Grueneisen e_h of
    the copper from its written rho and p, shear energies, kinetic energy)
    are conserved to 1e-12 relative;
  - serial and parallel fields agree to 1e-10 of their largest magnitude
    (alpha, rho, p of copper, U, epsilonP, damage and T of copper).
"""
import os
import re
import sys

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "lib"))
import foamcase as fc                         # noqa: E402
from checks import Checks                     # noqa: E402
import meshGeometry as mg                     # noqa: E402
sys.path.insert(0, HERE)
import test_V6_conservation as v6             # noqa: E402

MG = dict(rho0=8900.0, c0=3940.0, s=1.489, Gamma0=2.02)
COPPER = """    equationOfState { type MieGruneisen; rho0 8900; c0 3940; s 1.489; Gamma0 2.02; Cv 383; T0 298; }
    elasticity      { type separable; rho0 8900; mu 4.5e10; a 0.5; }
    plasticity
    {
        type vonMises;
        yieldStress { type JohnsonCook; A 9e7; B 2.92e8; n 0.31; C 0.025; m 1.09; Tr 298; Tm 1356; }
        tau 0;
    }
    failure { type JohnsonCook; D1 0.01; D2 0; D3 0; sigmaSpall 1e8; }"""
checks = Checks()


def real_copper(case):
    path = os.path.join(case, "constant", "phaseProperties")
    with open(path) as f:
        text = f.read()
    m = re.search(r"\ncopper\s*\{(.*?)\n\}", text, re.S)
    text = (text[:m.start(1)] + "\n    type            solid;\n" + COPPER
            + text[m.end(1):])
    with open(path, "w") as f:
        f.write(text)


def e_mie_gruneisen(rho, p):
    """e_h(rho, p) of docs/model.md section 10.1."""
    eta = 1 - MG["rho0"] / rho
    K = MG["rho0"] * MG["c0"] ** 2
    pref = np.where(eta >= 0, K * eta / (1 - MG["s"] * eta) ** 2, K * eta)
    eref = pref * eta / (2 * MG["rho0"])
    return eref + (p - pref) / (MG["rho0"] * MG["Gamma0"])


def totals(case, time, phases, V, n):
    s = v6.state(case, time, phases, n)
    mass, energy = {}, 0.0
    for name, ph in phases:
        alpha, rho, p, A = s["phases"][name]
        m = alpha * rho
        mass[name] = np.sum(m * V)
        if name == "copper":
            e = e_mie_gruneisen(rho, p)
        else:
            e = (p + ph["gamma"] * ph["pInf"]) / ((ph["gamma"] - 1) * rho)
        if ph["solid"]:
            e = e + v6.elastic_energy(A, ph)
        energy += np.sum(m * e * V)
    U = s["U"]
    energy += np.sum(0.5 * s["rho"] * np.sum(U * U, axis=1) * V)
    return mass, energy


def phases_of(case):
    """v6.read_phases with the copper's stiffened-gas entries stubbed (its
    energy is Mie-Grueneisen's here)."""
    path = os.path.join(case, "constant", "phaseProperties")
    text = open(path).read()
    tmp = text.replace(
        "equationOfState { type MieGruneisen; rho0 8900; c0 3940; s 1.489; "
        "Gamma0 2.02; Cv 383; T0 298; }",
        "equationOfState { type stiffenedGas; gamma 0; pInf 0; }")
    open(path, "w").write(tmp)
    try:
        return v6.read_phases(case)
    finally:
        open(path, "w").write(text)


def main():
    missing = fc.require_apps("impactFoam", "blockMesh", "setFields",
                              "decomposePar", "reconstructPar", "mpirun")
    if missing:
        checks.fail("realMetals_run", "%s not found on PATH" % " ".join(missing))
        checks.exit()
    runs = {}
    for par in (False, True):
        tag = "realMetals_%s" % ("parallel" if par else "serial")
        try:
            runs[par] = v6.run_tutorial(tag, 2, par, before_run=real_copper)
        except fc.FoamError as e:
            checks.fail(tag + "_run", e.summary)
            checks.note(str(e))
            checks.exit()
    serial, parallel = runs[False], runs[True]
    mesh = mg.read_polymesh(serial)
    n, V = mesh.nCells, mesh.V
    t = fc.latest_time(serial)
    t_end = float(fc.get_entry(serial, "system/controlDict", "endTime"))
    eps = fc.read_field(serial, t, "epsilonP.copper", n)
    D = fc.read_field(serial, t, "damage.copper", n)
    a = fc.read_field(serial, t, "alpha.copper", n)
    T = fc.read_field(serial, t, "T.copper", n)
    nFailed = int(np.sum((D >= 1 - 1e-6) & (a > 1e-3)))
    checks.check("realMetals_run",
                 abs(float(t) - t_end) <= 1e-9 * t_end and eps.max() > 0
                 and nFailed > 0 and np.all(np.isfinite(T)),
                 "t = %s (end %g); max epsilonP %.4g; %d cells of failed "
                 "copper; T.copper %.1f-%.1f K"
                 % (t, t_end, eps.max(), nFailed, T[a > 1e-3].min(),
                    T[a > 1e-3].max()))

    phases = phases_of(serial)
    m0, E0 = totals(serial, "0", phases, V, n)
    m1, E1 = totals(serial, t, phases, V, n)
    worst = max(abs(m1[k] - m0[k]) / m0[k] for k in m0)
    dE = abs(E1 - E0) / abs(E0)
    checks.check("realMetals_conservation", worst <= 1e-12 and dE <= 1e-12,
                 "largest relative change of a phase mass %.3e, of the "
                 "total energy %.3e (bound 1e-12)" % (worst, dE))

    worstRel, worstName = 0.0, ""
    for name in ("alpha.copper", "rho.copper", "p.copper", "U",
                 "epsilonP.copper", "damage.copper", "T.copper"):
        fs = fc.read_field(serial, t, name, n)
        fp = fc.read_field(parallel, t, name, n)
        scale = max(np.max(np.abs(fs)), 1e-300)
        rel = np.max(np.abs(fs - fp)) / scale
        if rel >= worstRel:
            worstRel, worstName = rel, name
    checks.check("realMetals_serialParallel", worstRel <= 1e-10,
                 "largest difference serial - 2 processes %.3e of the "
                 "field's magnitude (%s; bound 1e-10)" % (worstRel, worstName))
    checks.exit()


if __name__ == "__main__":
    main()
