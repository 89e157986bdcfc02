#!/usr/bin/python3
"""Self-check of tests/lib/exactRiemann.py, the exact stiffened-gas Riemann
solver the V2 test compares impactFoam with.

Checks
  - ideal-gas problems with published star states (Toro, "Riemann Solvers
    and Numerical Methods for Fluid Dynamics", 3rd ed., table 4.3): Sod
    (p* 0.30313, u* 0.92745, rho*L 0.42632, rho*R 0.26557) and tests 3-5;
  - water (SG 4.4 / 6e8, rho 1000, p 1e9) against air (1.4, rho 50,
    p 1e5), the V2 problem, and a second problem with a stiffened gas on
    both sides, a left shock and a right rarefaction: Rankine-Hugoniot
    relations across each shock, Riemann invariants and isentropy in each
    fan, continuity of u and p at the contact, and conservation of mass,
    momentum and energy of the whole sampled solution against the boundary
    fluxes.
"""
import os
import sys

import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)),
                                "..", "lib"))
from exactRiemann import RiemannProblem, VacuumError, VacuumProblem  # noqa: E402,E501

failures = 0


def check(name, ok, msg):
    global failures
    print("%s %s: %s" % ("PASS" if ok else "FAIL", name, msg))
    if not ok:
        failures += 1


def rel(a, b):
    return abs(a - b) / max(abs(b), 1e-300)


# --------------------------------------------------------------------------
# 1. Ideal gas: Toro's table 4.3 (5 significant digits published)
# --------------------------------------------------------------------------
toro = [
    # name, left (rho u p), right (rho u p), p*, u*, rho*L, rho*R
    ("sod", (1.0, 0.0, 1.0), (0.125, 0.0, 0.1),
     0.30313, 0.92745, 0.42632, 0.26557),
    ("toro3", (1.0, 0.0, 1000.0), (1.0, 0.0, 0.01),
     460.894, 19.5975, 0.57506, 5.99924),
    ("toro4", (1.0, 0.0, 0.01), (1.0, 0.0, 100.0),
     46.0950, -6.19633, 5.99242, 0.57511),
    ("toro5", (5.99924, 19.5975, 460.894), (5.99242, -6.19633, 46.0950),
     1691.64, 8.68975, 14.2823, 31.0426),
]
for name, l, r, ps, us, rl, rr in toro:
    rp = RiemannProblem(l + (1.4, 0.0), r + (1.4, 0.0))
    # published values carry 5-6 digits: allow half a unit in the last one
    errs = [rel(rp.p_star, ps), abs(rp.u_star - us) / max(abs(us), 1.0),
            rel(rp.rho_star_L, rl), rel(rp.rho_star_R, rr)]
    check("ideal_%s_star" % name, max(errs) < 5e-5,
          "p* %.6g (ref %g) u* %.6g (ref %g) rho*L %.6g (ref %g) "
          "rho*R %.6g (ref %g); max rel diff %.2e"
          % (rp.p_star, ps, rp.u_star, us, rp.rho_star_L, rl,
             rp.rho_star_R, rr, max(errs)))

# The 123 problem (two strong rarefactions, near vacuum): p* = 0.00189, u* = 0
rp = RiemannProblem((1.0, -2.0, 0.4, 1.4, 0.0), (1.0, 2.0, 0.4, 1.4, 0.0))
check("ideal_toro2_star", abs(rp.p_star - 0.00189) < 5e-6
      and abs(rp.u_star) < 1e-12,
      "p* %.6g (ref 0.00189) u* %.2e (ref 0)" % (rp.p_star, rp.u_star))

# Vacuum generation is detected, not returned as a wrong state
try:
    RiemannProblem((1.0, -20.0, 0.4, 1.4, 0.0), (1.0, 20.0, 0.4, 1.4, 0.0))
    check("ideal_vacuum_detected", False, "no VacuumError")
except VacuumError as e:
    check("ideal_vacuum_detected", True, "VacuumError raised (%s)" % e)


# Vacuum generation (Toro 4.6): the fans of VacuumProblem are continuous at
# their heads, end at the escape fronts with rho = p = 0, keep the Riemann
# invariant u + 2c/(g - 1) (left) and the isentrope p/rho^g of their side
vp = VacuumProblem((1.0, -20.0, 0.4, 1.4, 0.0), (0.5, 18.0, 0.3, 1.4, 0.0))
L_, R_ = vp.L, vp.R
xi_l = np.linspace(L_.u - L_.c, vp.front_L, 50)[1:-1]
xi_r = np.linspace(vp.front_R, R_.u + R_.c, 50)[1:-1]
rl, ul, pl, _ = vp.sample(xi_l)
rr, ur, pr, _ = vp.sample(xi_r)
cl, cr = np.sqrt(1.4 * pl / rl), np.sqrt(1.4 * pr / rr)
errs = [
    np.max(np.abs(ul + 5 * cl - (L_.u + 5 * L_.c))) / L_.c,
    np.max(np.abs(ur - 5 * cr - (R_.u - 5 * R_.c))) / R_.c,
    np.max(np.abs(pl / rl**1.4 - L_.p / L_.rho**1.4)) / (L_.p / L_.rho**1.4),
    np.max(np.abs(pr / rr**1.4 - R_.p / R_.rho**1.4)) / (R_.p / R_.rho**1.4),
    np.max(np.abs(ul - cl - xi_l)) / L_.c,
    np.max(np.abs(ur + cr - xi_r)) / R_.c,
]
head_l = vp.sample(L_.u - L_.c + 1e-9)
edge = vp.sample(vp.front_L - 1e-9)
inside = vp.sample(0.5 * (vp.front_L + vp.front_R))
check("ideal_vacuum_fans", max(errs) < 1e-12
      and abs(head_l[0] - L_.rho) < 1e-8 and edge[0] < 1e-12
      and inside[0] == 0 and inside[2] == 0,
      "invariants, isentropes and characteristic speeds in both fans: max "
      "rel error %.2e; rho at the left head %.9g (%.9g), at its escape front "
      "%.2e; vacuum between fronts %.4g and %.4g"
      % (max(errs), head_l[0], L_.rho, edge[0], vp.front_L, vp.front_R))

# --------------------------------------------------------------------------
# 2. Stiffened gases: Rankine-Hugoniot, Riemann invariants, conservation
# --------------------------------------------------------------------------

def flux_and_cons(rp, rho, u, p, side):
    e = rp.energy(rho, p, side)
    E = rho * (e + 0.5 * u * u)
    cons = np.array([rho, rho * u, E])
    flux = np.array([rho * u, rho * u * u + p, u * (E + p)])
    return cons, flux


def stiffened_checks(tag, rp, t=1.0):
    L, R = rp.L, rp.R
    print("  %s: %s" % (tag, rp.summary().replace("\n", "\n  " + " " * len(tag) + "  ")))

    # pressure function converged, u* agrees from both sides
    uL = L.u - L.f_and_df(rp.p_star)[0]
    uR = R.u + R.f_and_df(rp.p_star)[0]
    scale_u = max(abs(L.u), abs(R.u), L.c, R.c)
    check("%s_contact" % tag, abs(uL - uR) < 1e-10 * scale_u
          and abs(rp.u_star - uL) < 1e-10 * scale_u,
          "u* from left %.12g, from right %.12g (%d iterations)"
          % (uL, uR, rp.iterations))

    for K, sgn, name, rho_star in ((L, -1, "left", rp.rho_star_L),
                                   (R, 1, "right", rp.rho_star_R)):
        kind, head, tail = rp.waves[name]
        if kind == "shock":
            s = head
            # both states of the shock, sampled just around it
            d = 1e-9 * max(abs(s), 1.0)
            a = rp.sample(s + sgn * d)     # undisturbed side
            b = rp.sample(s - sgn * d)     # star side
            ca, fa = flux_and_cons(rp, *[np.atleast_1d(v) for v in a])
            cb, fb = flux_and_cons(rp, *[np.atleast_1d(v) for v in b])
            # F(b) - F(a) = s (U(b) - U(a)) for mass, momentum, energy
            res = (fb - fa - s * (cb - ca))[:, 0]
            scales = np.abs(fa[:, 0]) + np.abs(fb[:, 0]) \
                + abs(s) * (np.abs(ca[:, 0]) + np.abs(cb[:, 0]))
            worst = np.max(np.abs(res) / scales)
            ok = worst < 1e-12 and abs(b[0] - rho_star) < 1e-12 * rho_star \
                and abs(a[0] - K.rho) < 1e-12 * K.rho
            check("%s_%s_shock_RH" % (tag, name), ok,
                  "speed %.8g, rho %.8g -> %.8g, p %.6g -> %.6g; max "
                  "relative RH residual (mass, momentum, energy) %.2e"
                  % (s, K.rho, b[0], K.p, b[2], worst))
            # entropy condition: the shock is compressive (Lax)
            us_ = rp.u_star
            c_star = float(K.sound_speed(rho_star, rp.p_star))
            if sgn < 0:
                lax_ok = K.u - K.c > s > us_ - c_star
            else:
                lax_ok = K.u + K.c < s < us_ + c_star
            check("%s_%s_shock_Lax" % (tag, name), lax_ok,
                  "characteristics %.6g and %.6g enclose speed %.6g"
                  % (K.u + sgn * K.c, us_ + sgn * c_star, s))
        else:
            xi = np.linspace(head, tail, 201)[1:-1]
            rho, u, p, side = rp.sample(xi)
            g = K.gamma
            c = K.sound_speed(rho, p)
            inv = u - sgn * 2.0 * c / (g - 1.0)
            inv0 = K.u - sgn * 2.0 * K.c / (g - 1.0)
            ent = (p + K.pInf) / rho ** g
            ent0 = K.P / K.rho ** g
            charac = u + sgn * c - xi
            e1 = np.max(np.abs(inv - inv0)) / scale_u
            e2 = np.max(np.abs(ent / ent0 - 1.0))
            e3 = np.max(np.abs(charac)) / scale_u
            # the fan joins the star state continuously at its tail
            tail_state = rp.sample(tail - sgn * 1e-12 * scale_u)
            e4 = abs(tail_state[2] - rp.p_star) / (abs(rp.p_star) + K.pInf)
            check("%s_%s_fan_invariants" % (tag, name),
                  max(e1, e2, e3, e4) < 1e-10,
                  "head %.8g tail %.8g; max |Riemann invariant change|/c "
                  "%.2e, |entropy (p+pInf)/rho^g change| %.2e, "
                  "|u %s c - x/t|/c %.2e, p jump at tail %.2e"
                  % (head, tail, e1, e2, "-" if sgn < 0 else "+", e3, e4))

    # global conservation on [a, b] holding all waves:
    # int U(x, t) dx = int U(x, 0) dx + t (F(U_L) - F(U_R))
    speeds = [v for w in rp.waves.values() for v in w[1:]]
    a, b = min(speeds) * t * 1.2 - 1e-9, max(speeds) * t * 1.2 + 1e-9
    n = 200000
    edges = np.linspace(a, b, n + 1)
    # means of the conserved variables from finely sampled values
    frac = (np.arange(4) + 0.5) / 4
    xs = (edges[:-1, None] + np.diff(edges)[:, None] * frac).ravel()
    cons, _ = flux_and_cons(rp, *rp.at(xs, t))
    integral = cons.sum(axis=1) * (b - a) / xs.size
    cl, fl = flux_and_cons(rp, *[np.atleast_1d(v) for v in
                                 (L.rho, L.u, L.p, 0)])
    cr, fr = flux_and_cons(rp, *[np.atleast_1d(v) for v in
                                 (R.rho, R.u, R.p, 1)])
    expected = (-a * cl[:, 0] + b * cr[:, 0]) + t * (fl[:, 0] - fr[:, 0])
    scale = np.abs(-a * cl[:, 0]) + np.abs(b * cr[:, 0]) \
        + t * (np.abs(fl[:, 0]) + np.abs(fr[:, 0]))
    err = np.abs(integral - expected) / scale
    check("%s_conservation" % tag, np.max(err) < 1e-5,
          "relative error of integrated mass %.2e, momentum %.2e, "
          "energy %.2e (sampling with %d points)"
          % (err[0], err[1], err[2], xs.size))


# V2: water left, air right (at rest)
water_air = RiemannProblem((1000.0, 0.0, 1e9, 4.4, 6e8),
                           (50.0, 0.0, 1e5, 1.4, 0.0))
stiffened_checks("waterAir", water_air, t=240e-6)
kinds = (water_air.waves["left"][0], water_air.waves["right"][0])
check("waterAir_wave_pattern", kinds == ("rarefaction", "shock")
      and water_air.u_star > 0 and 1e5 < water_air.p_star < 1e9,
      "left %s, right %s, p* %.6g Pa, u* %.6g m/s"
      % (kinds + (water_air.p_star, water_air.u_star)))

# Both stiffened, moving: air-like gas with pInf pushed into water
sg2 = RiemannProblem((800.0, 300.0, 2e8, 4.4, 6e8),
                     (1.2, 50.0, 1e5, 1.4, 1e4))
stiffened_checks("sgMoving", sg2, t=1e-4)
# Reverse: water on the right, strong left shock, right rarefaction
sg3 = RiemannProblem((50.0, 200.0, 5e8, 1.4, 0.0),
                     (1000.0, 0.0, 1e9, 4.4, 6e8))
stiffened_checks("airWater", sg3, t=1e-4)

# Consistency of the pInf shift: stiffened gas on both sides equals the
# ideal gas in P = p + pInf
a = RiemannProblem((2.0, 0.3, 5.0, 2.0, 3.0), (1.0, -0.1, 1.0, 2.0, 3.0))
b = RiemannProblem((2.0, 0.3, 8.0, 2.0, 0.0), (1.0, -0.1, 4.0, 2.0, 0.0))
xi = np.linspace(-5, 5, 1001)
ra, ua, pa, _ = a.sample(xi)
rb, ub, pb, _ = b.sample(xi)
d = max(np.max(np.abs(ra - rb)), np.max(np.abs(ua - ub)),
        np.max(np.abs(pa + 3.0 - pb)))
check("pInf_shift", d < 1e-12,
      "same pInf on both sides vs ideal gas in p + pInf: max diff %.2e" % d)

sys.exit(1 if failures else 0)
