#!/usr/bin/python3
"""Right-going small-amplitude elastic waves in an unstrained solid at rest
(1-D along x), for the order-of-accuracy test V8 and the smoothWave
tutorial.

A longitudinal pulse u_x = UL f(x) and a transverse pulse u_y = UT f(x),
f(x) = exp(-((x - x0)/width)^2), each set on its right-going
characteristic of linear elasticity about the rest state (rho0, p0, A = I):

    longitudinal:  rho = rho0 (1 + u_x/c_L),  A_xx = rho/rho0,
                   p = p0 + c_h^2 (rho - rho0)        (isentrope, linear)
                   -> sigma_xx = -p0 - rho0 c_L u_x
    transverse:    A_yx = u_y/c_T  (shear strain dv/dx = -u_y/c_T)
                   -> sigma_xy = -rho0 c_T u_y

with c_h^2 = gamma (p0 + pInf)/rho0, c_L^2 = c_h^2 + 4 mu/(3 rho0),
c_T^2 = mu/rho0 (docs/model.md). The exact linear solution translates each
pulse: u_x(x, t) = UL f(x - c_L t), u_y(x, t) = UT f(x - c_T t). The
neglected nonlinear terms are of relative size u/c (2e-7 at 1e-3 m/s).

    import acousticWave as aw
    aw.write_initial(case)                      # 0/U, rho.copper, p, A.copper
    ux, uy = aw.exact_velocity(x, t)

From the shell (the tutorial's Allrun):

    python3 acousticWave.py <case> [UL UT x0 width]
"""
import os
import sys

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
if HERE not in sys.path:
    sys.path.insert(0, HERE)
import meshGeometry as mg        # noqa: E402
import fieldWriter as fw         # noqa: E402

# Copper of the tutorials (docs/model.md) at rest
COPPER = {"rho0": 8900.0, "gamma": 4.22, "pInf": 3.42e10, "mu": 4.5e10,
          "p0": 1e5}

# Defaults of the smoothWave tutorial
UL = 1e-3
UT = 1e-3
X0 = 0.25
WIDTH = 0.04


def speeds(mat=COPPER):
    """(c_h, c_L, c_T) at rest."""
    ch2 = mat["gamma"] * (mat["p0"] + mat["pInf"]) / mat["rho0"]
    cT2 = mat["mu"] / mat["rho0"]
    return np.sqrt(ch2), np.sqrt(ch2 + 4.0 * cT2 / 3.0), np.sqrt(cT2)


def profile(x, x0=X0, width=WIDTH):
    return np.exp(-((np.asarray(x) - x0) / width) ** 2)


def initial_state(x, ul=UL, ut=UT, x0=X0, width=WIDTH, mat=COPPER):
    """Cell values at positions x (N,): dict of U (N, 3), rho (N,),
    p (N,), A (N, 9)."""
    ch, cL, cT = speeds(mat)
    f = profile(x, x0, width)
    ux, uy = ul * f, ut * f
    n = len(x)
    rho = mat["rho0"] * (1.0 + ux / cL)
    p = mat["p0"] + ch ** 2 * (rho - mat["rho0"])
    A = np.tile(np.eye(3).ravel(), (n, 1))
    A[:, 0] = rho / mat["rho0"]
    A[:, 3] = uy / cT
    U = np.column_stack([ux, uy, np.zeros(n)])
    return {"U": U, "rho": rho, "p": p, "A": A}


def exact_velocity(x, t, ul=UL, ut=UT, x0=X0, width=WIDTH, mat=COPPER):
    """(u_x, u_y) of the linear solution at positions x, time t."""
    _, cL, cT = speeds(mat)
    return ul * profile(x - cL * t, x0, width), \
        ut * profile(x - cT * t, x0, width)


def write_initial(case, ul=UL, ut=UT, x0=X0, width=WIDTH, mat=COPPER,
                  phase="copper"):
    """Write 0/U, 0/rho.<phase>, 0/p, 0/A.<phase> (and alpha.<phase> = 1)
    at the cell centres of the case's mesh; zeroGradient on the open
    patches. Returns the cell centres' x."""
    m = mg.read_polymesh(case)
    x = m.C[:, 0]
    s = initial_state(x, ul, ut, x0, width, mat)
    fw.write_field(case, "0", "U", s["U"], m)
    fw.write_field(case, "0", "rho." + phase, s["rho"], m)
    fw.write_field(case, "0", "p", s["p"], m)
    fw.write_field(case, "0", "A." + phase, s["A"], m)
    fw.write_field(case, "0", "alpha." + phase, np.ones(m.nCells), m)
    return x


def main(argv):
    if len(argv) < 1:
        sys.stderr.write("usage: acousticWave.py <case> [UL UT x0 width]\n")
        return 1
    vals = [float(v) for v in argv[1:5]]
    defaults = [UL, UT, X0, WIDTH]
    ul, ut, x0, width = vals + defaults[len(vals):]
    x = write_initial(argv[0], ul, ut, x0, width)
    ch, cL, cT = speeds()
    print("acousticWave: %d cells; pulses u_x %g m/s and u_y %g m/s at "
          "x0 = %g m, width %g m; c_L = %.6g m/s, c_T = %.6g m/s"
          % (len(x), ul, ut, x0, width, cL, cT))
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
