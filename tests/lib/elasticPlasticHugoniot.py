"""Shock (Rankine-Hugoniot) states of the elastic-plastic model of
docs/model.md in uniaxial strain: an equation of state (stiffened gas or
Mie-Grueneisen, or any object with pressure(rho, e_h), e_h(rho, p) and
c2(rho, p)) plus the separable shear energy
e_e(g) = mu/(4 rho0) ((1 - 2a)/3 j1^2 + a j2 + 3(a - 1)), ideal Von Mises
plasticity, no hardening. Standard library only.

In uniaxial strain along x the unimodular Finger tensor is diagonal,
g = diag(l, l^-1/2, l^-1/2) (l > 1 in compression: G = A^T A with
A = F^-1), and the deviatoric stress is S = diag(S_xx, -S_xx/2, -S_xx/2),
so sqrt(3/2)|S| = 3/2 |S_xx|.

    elastic compression from the unstrained state:  l = (rho/rho0)^(4/3)
    on the yield surface (compression):             S_xx = -2/3 sigma_Y

The shock relations (m = rho (u - D) the mass flux through a shock of
speed D, sigma_xx = -p + S_xx, e = e_h + e_e the specific internal energy)

    m^2 = (sigma_1 - sigma_0) / (v_1 - v_0),   v = 1/rho
    u_1 - u_0 = (sigma_1 - sigma_0) / m
    e_1 - e_0 = -(sigma_0 + sigma_1)/2 (v_0 - v_1)   (Hugoniot)

give, for a given density, one equation for e_1 (linear in e_1 when p is
linear in e_h at fixed density, as for both equations of state here; it
is solved by secant steps, exact in one step then), so every state below
is a one-dimensional root find (bisection) in the density.

    import elasticPlasticHugoniot as eph
    m = eph.Material(rho0=8900, gamma=4.22, pInf=3.42e10, mu=4.5e10,
                     a=0.5, sigmaY=3e8)
    sol = eph.symmetric_impact(m, u_impact=200.0, p0=1e5)
    sol["precursor"]["sigma_xx"], sol["plastic"]["sigma_xx"], ...

    cu = eph.Material(rho0=8930, mu=8930 * 2244.0**2, a=0.5, sigmaY=9e7,
                      eos=eph.MieGruneisen(rho0=8930, c0=3939, s=1.5,
                                           Gamma0=2))
    sol = eph.piston(cu, u_piston=20.0, p0=1e5)
"""
import math


class StiffenedGas(object):
    """p = (gamma - 1) rho e_h - gamma pInf (docs/model.md section 4.1)."""

    def __init__(self, gamma, pInf):
        self.gamma = float(gamma)
        self.pInf = float(pInf)

    def pressure(self, rho, e_h):
        return (self.gamma - 1) * rho * e_h - self.gamma * self.pInf

    def e_h(self, rho, p):
        return (p + self.gamma * self.pInf) / ((self.gamma - 1) * rho)

    def c2(self, rho, p):
        return self.gamma * (p + self.pInf) / rho


class MieGruneisen(object):
    """Mie-Grueneisen with the linear Us-up Hugoniot from rest as reference
    curve and rho Gamma = rho0 Gamma0, as in docs/model.md section 10.1 and
    src/equationsOfState/MieGruneisen (eta = 1 - rho0/rho):
      p_ref = rho0 c0^2 eta/(1 - s eta)^2 (eta >= 0), rho0 c0^2 eta (eta < 0)
      e_ref = p_ref eta/(2 rho0)
      p = p_ref + rho0 Gamma0 (e_h - e_ref)"""

    def __init__(self, rho0, c0, s, Gamma0):
        self.rho0 = float(rho0)
        self.c0 = float(c0)
        self.s = float(s)
        self.Gamma0 = float(Gamma0)

    def reference(self, rho):
        eta = 1.0 - self.rho0 / rho
        K = self.rho0 * self.c0 ** 2
        if eta >= 0:
            if self.s * eta >= 1:
                raise ValueError("rho = %g beyond the Hugoniot's pole "
                                 "eta = 1/s" % rho)
            p_ref = K * eta / (1 - self.s * eta) ** 2
        else:
            p_ref = K * eta
        return p_ref, p_ref * eta / (2 * self.rho0)

    def pressure(self, rho, e_h):
        p_ref, e_ref = self.reference(rho)
        return p_ref + self.rho0 * self.Gamma0 * (e_h - e_ref)

    def e_h(self, rho, p):
        p_ref, e_ref = self.reference(rho)
        return e_ref + (p - p_ref) / (self.rho0 * self.Gamma0)

    def c2(self, rho, p):
        """dp/drho at constant entropy, (dp/drho)_e + p/rho^2 (dp/de)_rho,
        by a central difference of the pressure (a reference value
        independent of the C++ closed form)."""
        h = 1e-6 * rho
        e = self.e_h(rho, p)
        dpdrho = (self.pressure(rho + h, e) - self.pressure(rho - h, e)) \
            / (2 * h)
        return dpdrho + p / rho ** 2 * self.rho0 * self.Gamma0


class Material(object):
    """Elastic-plastic material: an equation of state (eos; or gamma and
    pInf for a stiffened gas), the separable shear energy (rho0, mu, a)
    and a constant yield stress sigmaY."""

    def __init__(self, rho0, mu, a, sigmaY, gamma=None, pInf=None, eos=None):
        self.rho0 = float(rho0)
        if eos is None:
            eos = StiffenedGas(gamma, pInf)
        self.eos = eos
        if isinstance(eos, StiffenedGas):
            self.gamma = eos.gamma
            self.pInf = eos.pInf
        self.mu = float(mu)
        self.a = float(a)
        self.sigmaY = float(sigmaY)

    # ---- shear part, uniaxial g = diag(l, l^-1/2, l^-1/2) --------------
    def _invariants(self, l):
        t = l ** -0.5
        return l + 2 * t, l * l + 2 * t * t, t

    def e_elastic(self, l):
        """Shear energy per unit mass [J/kg]."""
        j1, j2, _ = self._invariants(l)
        a = self.a
        return self.mu / (4 * self.rho0) * ((1 - 2 * a) / 3 * j1 * j1
                                            + a * j2 + 3 * (a - 1))

    def S_xx(self, l, rho):
        """Deviatoric stress S_xx of docs/model.md for g = diag(l, t, t)."""
        j1, j2, t = self._invariants(l)
        a = self.a
        dg = l - j1 / 3.0                      # (g - j1/3 I)_xx
        dg2 = l * l - j2 / 3.0                 # (g^2 - j2/3 I)_xx
        return -self.mu * rho / self.rho0 * ((1 - 2 * a) / 3 * j1 * dg
                                             + a * dg2)

    def l_yield(self, rho):
        """l > 1 of the uniaxial-compression state on the yield surface
        (S_xx = -2/3 sigma_Y) at density rho."""
        target = -2.0 / 3.0 * self.sigmaY
        return bisect(lambda l: self.S_xx(l, rho) - target, 1.0, 2.0)

    # ---- hydrodynamic part ---------------------------------------------
    def pressure(self, rho, e_h):
        return self.eos.pressure(rho, e_h)

    def e_h(self, rho, p):
        return self.eos.e_h(rho, p)

    def bulk_modulus(self, rho, p):
        """rho c_h^2 (gamma (p + pInf) for a stiffened gas)."""
        return rho * self.eos.c2(rho, p)

    def state(self, rho, e, l):
        """Dict of a state of density rho, specific internal energy e and
        unimodular stretch l."""
        ee = self.e_elastic(l)
        p = self.pressure(rho, e - ee)
        Sxx = self.S_xx(l, rho)
        return {"rho": rho, "e": e, "l": l, "p": p, "S_xx": Sxx,
                "sigma_xx": -p + Sxx, "e_elastic": ee,
                "sigma_eq": 1.5 * abs(Sxx)}


def bisect(f, lo, hi, tol=1e-15, itmax=400):
    """Root of f in [lo, hi] (f(lo) f(hi) <= 0) by bisection."""
    flo, fhi = f(lo), f(hi)
    if flo * fhi > 0:
        raise ValueError("root not bracketed: f(%g) = %g, f(%g) = %g"
                         % (lo, flo, hi, fhi))
    for _ in range(itmax):
        mid = 0.5 * (lo + hi)
        fm = f(mid)
        if fm == 0 or (hi - lo) <= tol * abs(mid):
            return mid
        if (fm < 0) == (flo < 0):
            lo, flo = mid, fm
        else:
            hi = mid
    return 0.5 * (lo + hi)


def hugoniot_state(mat, s0, rho1, l_of_rho):
    """State of density rho1 on the Hugoniot centred at state s0 (a dict
    from Material.state), with unimodular stretch l_of_rho(rho1): the
    Hugoniot energy relation
        r(e1) = e1 - e0 + (sigma_0 + sigma_1(e1))/2 (v0 - v1) = 0,
    sigma_1(e1) = -p(rho1, e1 - e_e(l1)) + S_xx(l1, rho1), solved by secant
    steps (exact in the first when p is linear in e_h at fixed density)."""
    l1 = l_of_rho(rho1)
    dv = 1.0 / s0["rho"] - 1.0 / rho1
    ee1 = mat.e_elastic(l1)
    Sxx1 = mat.S_xx(l1, rho1)

    def r(e1):
        sigma1 = -mat.pressure(rho1, e1 - ee1) + Sxx1
        return e1 - s0["e"] + 0.5 * (s0["sigma_xx"] + sigma1) * dv

    ea = s0["e"] + ee1
    eb = ea + 1e3 + 1e-3 * abs(ea)
    ra, rb = r(ea), r(eb)
    for _ in range(50):
        if rb == ra:
            break
        ec = eb - rb * (eb - ea) / (rb - ra)
        ea, ra = eb, rb
        eb, rb = ec, r(ec)
        if abs(eb - ea) <= 1e-15 * (abs(eb) + 1.0):
            break
    return mat.state(rho1, eb, l1)


def shock(s0, s1, u0, direction):
    """Mass flux, speed D and velocity behind a shock from s0 (ahead, at
    velocity u0) to s1; direction +1 for a shock moving to +x relative to
    the material, -1 for -x."""
    m2 = (s1["sigma_xx"] - s0["sigma_xx"]) / (1 / s1["rho"] - 1 / s0["rho"])
    m = -direction * math.sqrt(m2)          # m = rho (u - D)
    u1 = u0 + (s1["sigma_xx"] - s0["sigma_xx"]) / m
    D = u0 - m / s0["rho"]
    return m, D, u1


def symmetric_impact(mat, u_impact, p0=1e5):
    """Two half-spaces of mat at p0, unstrained, meeting at +/- u_impact.
    Solved for the right plate (moving at -u_impact; waves run to +x):

      0  unstrained plate:  rho0, e_h(rho0, p0), u = -u_impact
      1  elastic precursor: elastic uniaxial compression (l = (rho/rho0)^4/3)
         up to the yield surface, on the Hugoniot of state 0
      2  plastic state:     on the yield surface, on the Hugoniot of state 1,
         brought to rest (u = 0, the symmetry plane)

    Returns {"initial", "precursor", "plastic": state dicts (with "u", and
    "D" the lab speed of the shock that produced the state),
    "linear_precursor": -(K + 4 mu/3) sigma_Y/(2 mu), K = rho0 c_h^2 at the
    initial state (gamma (p0 + pInf) for a stiffened gas)}.
    If the impact is too weak to yield, "plastic" is None."""
    rho0 = mat.rho0
    s0 = mat.state(rho0, mat.e_h(rho0, p0), 1.0)
    u0 = -float(u_impact)

    def l_elastic(rho):
        return (rho / rho0) ** (4.0 / 3.0)

    # Density at which elastic uniaxial compression reaches the yield
    # surface: S_xx(l_elastic(rho), rho) = -2/3 sigma_Y
    rho1 = bisect(lambda r: mat.S_xx(l_elastic(r), r)
                  + 2.0 / 3.0 * mat.sigmaY, rho0, 1.5 * rho0)
    s1 = hugoniot_state(mat, s0, rho1, l_elastic)
    m1, D1, u1 = shock(s0, s1, u0, +1)
    s0.update(u=u0, D=None)
    s1.update(u=u1, D=D1, m=m1)

    K = mat.bulk_modulus(rho0, p0)
    out = {"initial": s0, "precursor": s1, "plastic": None,
           "linear_precursor":
               -(K + 4 * mat.mu / 3) * mat.sigmaY / (2 * mat.mu)}
    if u1 >= 0:
        return out

    # Plastic shock from s1 bringing the material to rest
    def residual(rho2):
        s2 = hugoniot_state(mat, s1, rho2, mat.l_yield)
        _, _, u2 = shock(s1, s2, u1, +1)
        return u2

    rho2 = bisect(residual, rho1 * (1 + 1e-12), 1.5 * rho0)
    s2 = hugoniot_state(mat, s1, rho2, mat.l_yield)
    m2, D2, u2 = shock(s1, s2, u1, +1)
    s2.update(u=u2, D=D2, m=m2)
    out["plastic"] = s2
    return out


def piston(mat, u_piston, p0=1e5):
    """Material at rest at p0, unstrained, driven by a piston at u_piston
    (waves running away from the piston). In the piston's frame this is
    the right plate of symmetric_impact(mat, u_piston, p0): the material
    arrives at -u_piston and is brought to rest by the elastic precursor
    and the plastic shock. Returned as symmetric_impact returns it (piston
    frame: add u_piston to velocities and shock speeds for the frame of
    the undisturbed material)."""
    return symmetric_impact(mat, u_piston, p0)


if __name__ == "__main__":
    copper = Material(rho0=8900, gamma=4.22, pInf=3.42e10, mu=4.5e10,
                      a=0.5, sigmaY=3e8)
    sol = symmetric_impact(copper, 200.0, 1e5)
    for key in ("initial", "precursor", "plastic"):
        print(key, sol[key])
    print("linear precursor", sol["linear_precursor"])
