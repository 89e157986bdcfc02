#!/usr/bin/python3
"""Temperature and plastic heat through the solver (docs/validation.md,
other tests, test_temperature; docs/model.md sections 10.1 and 10.3): one step
of the small 1-D copper/air case of V9 (tests/cases/badInput/copperAir,
50 cells) with both phases at rest and the copper cobasis strained beyond
the yield surface (0/A.copper = diag(1.02, 1/1.02, 1), uniform): the
interior copper cells stay uniform, at fixed density, and only the plastic
return acts. One step of exactly 1e-7 s (maxDeltaT = endTime = 1e-7).

Variants (copper: stiffenedGas gamma 4.22, pInf 3.42e10, Cv 383):
  melted    Johnson-Cook OFHC (Tr 298, Tm 1356). At rest the stiffened
            gas's temperature (p + pInf)/((gamma - 1) rho Cv) is 3116 K,
            above Tm: no strength, the return takes the deviatoric stress
            to zero.
  strength  Johnson-Cook OFHC with Tr 3000, Tm 4500 (the same law moved to
            the stiffened gas's temperature scale, Th = 0.077); air with
            Cv 718 and writeTemperature yes.

Checks in the interior copper cells (5..19, away from the interface and
the open ends; every state there is uniform):
  - T.copper is written (the law needs T) and equals
    (p + pInf)/((gamma - 1) rho Cv) of the written rho.copper, p.copper
    (1e-10);
  - the density did not change (1e-12) and T rose by plasticWork/Cv:
    |T - T0 - plasticWork/Cv| <= 1e-6 (T - T0) (all the plastic work is
    heat, Taylor-Quinney 1);
  - melted: sigmaEq <= 1e-6 of its trial value and epsilonP is the whole
    equivalent log-strain sqrt(2/3)|ln g|/2;
  - strength: sigmaEq = alpha.copper sigma_Y(epsP, epsP/dt, T0) of the
    Johnson-Cook formula (1e-8: the return lands on the law at the end of
    the step, T from the state before it);
  - T.air: not written in 'melted' (air's models use no T and it did not
    ask), written in 'strength' and equal to p/((gamma - 1) rho Cv) of the
    air (1e-10).
"""
import math
import os
import shutil
import sys

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "lib"))
import foamcase as fc                         # noqa: E402
from checks import Checks                     # noqa: E402
import fieldWriter as fw                      # noqa: E402
import meshGeometry as mg                     # noqa: E402

BASE = os.path.join(HERE, "badInput", "copperAir")
PP = "constant/phaseProperties"
GAMMA, P_INF, CV = 4.22, 3.42e10, 383.0
GAMMA_AIR, CV_AIR = 1.4, 718.0
STRETCH = 1.02
DT = 1e-7
INTERIOR = slice(5, 20)

JC = ("yieldStress { type JohnsonCook; A 9e7; B 2.92e8; n 0.31; C 0.025; "
      "m 1.09; Tr %g; Tm %g; }")
VARIANTS = {
    "melted": dict(Tr=298.0, Tm=1356.0, air_T=False),
    "strength": dict(Tr=3000.0, Tm=4500.0, air_T=True),
}

checks = Checks()


def edit(case, rel, old, new):
    path = os.path.join(case, rel)
    with open(path) as f:
        text = f.read()
    if old not in text:
        raise fc.FoamError("%s: '%s' not found" % (path, old))
    with open(path, "w") as f:
        f.write(text.replace(old, new, 1))


def jc_sigma_y(eps, rate, T, Tr, Tm):
    th = min(max((T - Tr) / (Tm - Tr), 0.0), 1.0)
    return ((9e7 + 2.92e8 * eps ** 0.31)
            * (1 + 0.025 * math.log(max(rate, 1.0)))
            * (1 - th ** 1.09))


def T_sg(rho, p, gamma, p_inf, cv):
    return (p + p_inf) / ((gamma - 1) * rho * cv)


def prepare(name, v):
    case = fc.copy_tutorial(BASE, "T_" + name)
    edit(case, "system/setFieldsDict",
         "volVectorFieldValue U               (10 0 0)",
         "volVectorFieldValue U               (0 0 0)")
    fc.set_entry(case, "system/controlDict", "endTime", "%g" % DT)
    fc.set_entry(case, "system/controlDict", "writeInterval", "%g" % DT)
    fc.set_entry(case, "system/controlDict", "maxDeltaT", "%g" % DT)
    fc.set_entry(case, "system/controlDict", "writePrecision", "17")
    edit(case, PP, "sigmaY 3e8;", JC % (v["Tr"], v["Tm"]))
    edit(case, PP, "pInf 3.42e10; }", "pInf 3.42e10; Cv %g; }" % CV)
    if v["air_T"]:
        edit(case, PP, "type stiffenedGas; gamma 1.4; pInf 0; }",
             "type stiffenedGas; gamma 1.4; pInf 0; Cv %g; }\n"
             "    writeTemperature yes;" % CV_AIR)
    fc.run(case, ["blockMesh"])
    shutil.copytree(os.path.join(case, "0.orig"), os.path.join(case, "0"))
    fc.run(case, ["setFields"])
    mesh = mg.read_polymesh(case)
    A = np.diag([STRETCH, 1 / STRETCH, 1.0]).ravel()
    fw.write_field(case, "0", "A.copper", A, mesh)
    return case


def check_variant(name, v):
    tag = "temperature_" + name
    try:
        case = prepare(name, v)
        fc.run(case, ["impactFoam"], log="log.impactFoam")
    except fc.FoamError as e:
        checks.fail(tag, "run failed: %s" % e.summary)
        return
    times = fc.time_dirs(case)
    end = times[-1][1]
    if abs(times[-1][0] - DT) > 1e-6 * DT:
        checks.fail(tag, "last time %s is not %g" % (end, DT))
        return
    n = fc.mesh_n_cells(case)
    rd = lambda t, f: fc.read_field(case, t, f, n)[INTERIOR]   # noqa: E731

    rho0, p0 = rd("0", "rho.copper"), rd("0", "p")
    rho, p = rd(end, "rho.copper"), rd(end, "p.copper")
    alpha = rd(end, "alpha.copper")
    T0 = T_sg(rho0, p0, GAMMA, P_INF, CV)
    problems = []
    if not fc.has_field(case, end, "T.copper"):
        checks.fail(tag, "no T.copper written at %s" % end)
        return
    T = rd(end, "T.copper")
    W = rd(end, "plasticWork.copper")
    eps = rd(end, "epsilonP.copper")
    sig = rd(end, "sigmaEq")

    err_formula = np.max(np.abs(T / T_sg(rho, p, GAMMA, P_INF, CV) - 1))
    err_rho = np.max(np.abs(rho / rho0 - 1))
    rise = T - T0
    err_heat = np.max(np.abs(rise - W / CV) / np.abs(rise))
    if not err_formula <= 1e-10:
        problems.append("T.copper differs from T(rho, p) by %.2e"
                        % err_formula)
    if not err_rho <= 1e-12:
        problems.append("density changed by %.2e" % err_rho)
    if not (np.all(W > 0) and err_heat <= 1e-6):
        problems.append("T - T0 differs from plasticWork/Cv by %.2e"
                        % err_heat)

    # The trial state: isochoric diag(l, 1/l, 1), g = A^T A, h = ln eig g
    h = np.array([2 * math.log(STRETCH), -2 * math.log(STRETCH), 0.0])
    eps_full = math.sqrt(2.0 / 3.0) * 0.5 * np.linalg.norm(h)
    if name == "melted":
        mu = 4.5e10
        trial = mu * STRETCH ** 4   # a generous scale of the trial stress
        stress_info = "sigmaEq max %.3g Pa" % np.max(sig)
        if not np.max(sig) <= 1e-6 * trial:
            problems.append("sigmaEq %.3g not zero" % np.max(sig))
        err_eps = np.max(np.abs(eps / eps_full - 1))
        stress_info += ", epsilonP/full %.2e" % err_eps
        if not err_eps <= 1e-10:
            problems.append("epsilonP %.6g, not the whole %.6g"
                            % (eps[0], eps_full))
    else:
        ref = np.array([alpha[i] * jc_sigma_y(eps[i], eps[i] / DT, T0[i],
                                              v["Tr"], v["Tm"])
                        for i in range(len(eps))])
        err_sig = np.max(np.abs(sig / ref - 1))
        stress_info = ("sigmaEq %.6g Pa vs alpha sigma_Y(epsP, epsP/dt, T0)"
                       " %.6g Pa (%.2e), epsilonP %.4g"
                       % (sig[0], ref[0], err_sig, eps[0]))
        if not err_sig <= 1e-8:
            problems.append("sigmaEq off the Johnson-Cook law by %.2e"
                            % err_sig)

    has_air_T = fc.has_field(case, end, "T.air")
    air_info = "T.air %s" % ("written" if has_air_T else "not written")
    if has_air_T != v["air_T"]:
        problems.append("T.air %s written" % ("" if has_air_T else "not"))
    if has_air_T:
        Ta = fc.read_field(case, end, "T.air", n)
        ra = fc.read_field(case, end, "rho.air", n)
        pa = fc.read_field(case, end, "p.air", n)
        err_air = np.max(np.abs(Ta / T_sg(ra, pa, GAMMA_AIR, 0.0, CV_AIR)
                                - 1))
        air_info += " (against p/((gamma - 1) rho Cv): %.2e)" % err_air
        if not err_air <= 1e-10:
            problems.append("T.air off by %.2e" % err_air)

    checks.check(tag, not problems,
                 "T0 %.2f K, T %.4f K, rise %.4f K, |rise - W/Cv|/rise %.2e,"
                 " T against T(rho, p) %.2e, density change %.1e; %s; %s%s"
                 % (T0[0], T[0], rise[0], err_heat, err_formula, err_rho,
                    stress_info, air_info,
                    ("; PROBLEMS: " + "; ".join(problems)) if problems
                    else ""))


def main():
    missing = fc.require_apps("impactFoam", "blockMesh", "setFields")
    if missing:
        checks.fail("temperature_run", "%s not found on PATH" % " ".join(
            missing))
        checks.exit()
    for name, v in VARIANTS.items():
        check_variant(name, v)
    checks.exit()


if __name__ == "__main__":
    main()
