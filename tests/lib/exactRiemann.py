"""Exact solution of the 1-D Riemann problem between two stiffened gases.

Each side K has its own material, p = (gamma_K - 1) rho e - gamma_K pInf_K,
c^2 = gamma_K (p + pInf_K) / rho. The materials meet at the contact; the
left (right) material fills everything left (right) of it. With
P = p + pInf_K the stiffened gas behaves as an ideal gas in P on each side,
so the classical construction applies (E. F. Toro, "Riemann Solvers and
Numerical Methods for Fluid Dynamics", ch. 4) with p replaced by p + pInf_K
in the wave relations of side K; the star pressure p* is common to both
sides, so P*_L = p* + pInf_L and P*_R = p* + pInf_R differ.

    from exactRiemann import RiemannProblem
    rp = RiemannProblem((1000, 0, 1e9, 4.4, 6e8), (50, 0, 1e5, 1.4, 0))
    rp.p_star, rp.u_star
    rho, u, p, side = rp.sample(xi)                  # xi = (x - x0) / t
    rho, u, p, side = rp.at(x, t, x0=0.7)
    rho, u, p = rp.cell_averages(edges, t, x0=0.7)   # exact cell means

side is 0 where the left material is, 1 where the right material is.
"""
import math

import numpy as np


class VacuumError(ValueError):
    """The data generate a vacuum (or a state with p + pInf <= 0)."""


class SideState(object):
    """State and material of one side."""

    def __init__(self, rho, u, p, gamma, pInf=0.0):
        self.rho = float(rho)
        self.u = float(u)
        self.p = float(p)
        self.gamma = float(gamma)
        self.pInf = float(pInf)
        if self.rho <= 0 or self.P <= 0 or self.gamma <= 1:
            raise ValueError("invalid state rho=%g p=%g gamma=%g pInf=%g"
                             % (rho, p, gamma, pInf))
        self.c = math.sqrt(self.gamma * self.P / self.rho)

    @property
    def P(self):
        return self.p + self.pInf

    def energy(self, rho, p):
        """Specific internal energy e(rho, p)."""
        return (p + self.gamma * self.pInf) / ((self.gamma - 1.0) * rho)

    def sound_speed(self, rho, p):
        return np.sqrt(self.gamma * (p + self.pInf) / rho)

    def fan(self, sgn, xi):
        """rho, u, p inside this side's rarefaction fan at similarity
        coordinate xi; sgn -1 for the left fan (u - c = xi,
        u + 2c/(g-1) = uL + 2cL/(g-1)), +1 for the right (u + c = xi,
        u - 2c/(g-1) = uR - 2cR/(g-1))."""
        g = self.gamma
        u = 2.0 / (g + 1.0) * (-sgn * self.c + 0.5 * (g - 1.0) * self.u + xi)
        c = 2.0 / (g + 1.0) * (self.c - sgn * 0.5 * (g - 1.0)
                               * (self.u - xi))
        rho = self.rho * (c / self.c) ** (2.0 / (g - 1.0))
        p = self.P * (c / self.c) ** (2.0 * g / (g - 1.0)) - self.pInf
        return rho, u, p

    def f_and_df(self, p):
        """Toro's f_K(p*) (velocity change across the K wave) and its
        derivative, for star pressure p."""
        g, PK, rho = self.gamma, self.P, self.rho
        P = p + self.pInf
        if P > PK:                                   # shock
            A = 2.0 / ((g + 1.0) * rho)
            B = (g - 1.0) / (g + 1.0) * PK
            q = math.sqrt(A / (P + B))
            return (P - PK) * q, q * (1.0 - 0.5 * (P - PK) / (P + B))
        # rarefaction (P > 0 is guaranteed by the caller)
        r = P / PK
        f = 2.0 * self.c / (g - 1.0) * (r ** ((g - 1.0) / (2.0 * g)) - 1.0)
        df = 1.0 / (rho * self.c) * r ** (-(g + 1.0) / (2.0 * g))
        return f, df


def _side(s):
    if isinstance(s, SideState):
        return s
    if isinstance(s, dict):
        return SideState(s["rho"], s["u"], s["p"], s["gamma"],
                         s.get("pInf", 0.0))
    return SideState(*s)


class RiemannProblem(object):
    """Exact Riemann problem; left and right are SideState, dicts with keys
    rho u p gamma pInf, or tuples (rho, u, p, gamma, pInf)."""

    def __init__(self, left, right, tol=1e-15, max_iter=200):
        self.L = _side(left)
        self.R = _side(right)
        self._solve_star(tol, max_iter)
        self._wave_speeds()

    # ---- star region -----------------------------------------------------

    def pressure_function(self, p):
        fL, dL = self.L.f_and_df(p)
        fR, dR = self.R.f_and_df(p)
        return fL + fR + (self.R.u - self.L.u), dL + dR

    def _solve_star(self, tol, max_iter):
        L, R = self.L, self.R
        # p + pInf_K > 0 on both sides
        p_lo = -min(L.pInf, R.pInf)
        scale = max(abs(L.p), abs(R.p), L.pInf, R.pInf, 1e-300)
        eps = 1e-14 * scale
        F_lo, _ = self.pressure_function(p_lo + eps)
        if F_lo >= 0.0:
            raise VacuumError("the rarefactions reach p + pInf = 0 "
                              "(vacuum/cavitation): F(p_min) = %g" % F_lo)
        # upper bracket
        p_hi = max(L.p, R.p, p_lo + eps)
        step = max(abs(p_hi), scale)
        while self.pressure_function(p_hi)[0] < 0.0:
            p_hi += step
            step *= 2.0
        lo, hi = p_lo + eps, p_hi
        # initial guess: linearised (acoustic) star pressure, kept in bracket
        zL, zR = L.rho * L.c, R.rho * R.c
        p = (zR * L.p + zL * R.p + zL * zR * (L.u - R.u)) / (zL + zR)
        if not lo < p < hi:
            p = 0.5 * (lo + hi)
        for it in range(max_iter):
            F, dF = self.pressure_function(p)
            if F < 0.0:
                lo = p
            else:
                hi = p
            p_new = p - F / dF if dF > 0 else 0.5 * (lo + hi)
            if not lo < p_new < hi:                  # Newton left the bracket
                p_new = 0.5 * (lo + hi)
            change = abs(p_new - p)
            p = p_new
            if change <= tol * (abs(p) + scale) or hi - lo <= tol * scale:
                break
        else:
            raise RuntimeError("star pressure did not converge")
        self.iterations = it + 1
        self.p_star = p
        fL, _ = L.f_and_df(p)
        fR, _ = R.f_and_df(p)
        self.u_star = 0.5 * (L.u + R.u) + 0.5 * (fR - fL)
        self.residual = self.pressure_function(p)[0]
        self.rho_star_L = self._star_density(L, p)
        self.rho_star_R = self._star_density(R, p)

    @staticmethod
    def _star_density(K, p):
        g, PK = K.gamma, K.P
        r = (p + K.pInf) / PK
        if r > 1.0:                                  # shock (Hugoniot)
            m = (g - 1.0) / (g + 1.0)
            return K.rho * (r + m) / (m * r + 1.0)
        return K.rho * r ** (1.0 / g)                # isentrope

    def _wave_speeds(self):
        """Speeds of the waves: for a shock 'shock' and its speed, for a
        rarefaction 'rarefaction' with head and tail speeds."""
        L, R, ps, us = self.L, self.R, self.p_star, self.u_star
        self.waves = {}
        for K, sgn, name in ((L, -1.0, "left"), (R, 1.0, "right")):
            g = K.gamma
            r = (ps + K.pInf) / K.P
            if r > 1.0:
                s = K.u + sgn * K.c * math.sqrt((g + 1.0) / (2.0 * g) * r
                                                + (g - 1.0) / (2.0 * g))
                self.waves[name] = ("shock", s, s)
            else:
                c_star = K.c * r ** ((g - 1.0) / (2.0 * g))
                head = K.u + sgn * K.c
                tail = us + sgn * c_star
                self.waves[name] = ("rarefaction", head, tail)
        self.waves["contact"] = ("contact", us, us)

    # ---- sampling ----------------------------------------------------------

    def sample(self, xi):
        """rho, u, p, side at similarity coordinate xi = (x - x0)/t
        (scalar or array). side: 0 left material, 1 right material."""
        xi = np.asarray(xi, dtype=float)
        rho = np.empty_like(xi)
        u = np.empty_like(xi)
        p = np.empty_like(xi)
        side = np.where(xi <= self.u_star, 0, 1)
        for K, sgn, name, rho_star, sel in (
                (self.L, -1.0, "left", self.rho_star_L, side == 0),
                (self.R, 1.0, "right", self.rho_star_R, side == 1)):
            kind, head, tail = self.waves[name]
            # distance from the contact measured outwards (positive towards
            # the undisturbed state of side K)
            outside = sel & (sgn * xi >= sgn * head)
            if kind == "shock":
                outside = sel & (sgn * xi > sgn * head)
            star = sel & ~outside & (sgn * xi <= sgn * tail)
            fan = sel & ~outside & ~star
            rho[outside], u[outside], p[outside] = K.rho, K.u, K.p
            rho[star], u[star], p[star] = rho_star, self.u_star, self.p_star
            if np.any(fan):
                rho[fan], u[fan], p[fan] = K.fan(sgn, xi[fan])
        if rho.ndim == 0:
            return float(rho), float(u), float(p), int(side)
        return rho, u, p, side

    def at(self, x, t, x0=0.0):
        """rho, u, p, side at positions x and time t > 0 (discontinuity
        initially at x0)."""
        x = np.asarray(x, dtype=float)
        return self.sample((x - x0) / t)

    def cell_averages(self, edges, t, x0=0.0, nsub=32):
        """Cell means of rho, u, p over cells [edges[i], edges[i+1]] at time
        t (midpoint rule on nsub sub-intervals per cell, so a
        discontinuity inside a cell is averaged, not point-sampled).
        Also returns the mean of side (the right material's fraction)."""
        edges = np.asarray(edges, dtype=float)
        n = edges.size - 1
        frac = (np.arange(nsub) + 0.5) / nsub
        x = edges[:-1, None] + (edges[1:] - edges[:-1])[:, None] * frac
        rho, u, p, side = self.at(x.ravel(), t, x0)
        mean = lambda q: q.reshape(n, nsub).mean(axis=1)
        return mean(rho), mean(u), mean(p), mean(side.astype(float))

    def energy(self, rho, p, side):
        """Specific internal energy of the local material."""
        side = np.asarray(side)
        return np.where(side == 0, self.L.energy(rho, p),
                        self.R.energy(rho, p))

    def summary(self):
        w = self.waves
        lines = ["p* = %.10g  u* = %.10g  rho*L = %.10g  rho*R = %.10g"
                 % (self.p_star, self.u_star, self.rho_star_L,
                    self.rho_star_R)]
        for name in ("left", "contact", "right"):
            kind, a, b = w[name]
            lines.append("%-7s %-11s speeds %.8g %.8g" % (name, kind, a, b))
        return "\n".join(lines)


class VacuumProblem(RiemannProblem):
    """Two rarefactions moving apart faster than the escape speeds,
    u_R - u_L >= 2 c_L/(gamma_L - 1) + 2 c_R/(gamma_R - 1): a vacuum
    opens between them (Toro, ch. 4.6). Each fan ends at its escape front,
    u_L + 2 c_L/(gamma_L - 1) on the left, u_R - 2 c_R/(gamma_R - 1) on
    the right, with rho = 0 and p = -pInf; between the fronts rho = 0,
    p = -pInf of the nearer side and u is undefined (NaN). Same sampling
    interface as RiemannProblem."""

    def __init__(self, left, right):
        self.L = _side(left)
        self.R = _side(right)
        L, R = self.L, self.R
        self.front_L = L.u + 2.0 * L.c / (L.gamma - 1.0)
        self.front_R = R.u - 2.0 * R.c / (R.gamma - 1.0)
        if self.front_L > self.front_R:
            raise ValueError("no vacuum: u_R - u_L = %g below the escape "
                             "speeds %g" % (R.u - L.u, self.front_L - L.u
                                            + R.u - self.front_R))
        self.waves = {"left": ("rarefaction", L.u - L.c, self.front_L),
                      "right": ("rarefaction", R.u + R.c, self.front_R)}

    def sample(self, xi):
        xi = np.asarray(xi, dtype=float)
        rho = np.zeros_like(xi)
        u = np.full_like(xi, np.nan)
        mid = 0.5 * (self.front_L + self.front_R)
        side = np.where(xi <= mid, 0, 1)
        p = np.where(side == 0, -self.L.pInf, -self.R.pInf).astype(float)
        for K, sgn, name, sel in ((self.L, -1.0, "left", side == 0),
                                  (self.R, 1.0, "right", side == 1)):
            head, front = self.waves[name][1], self.waves[name][2]
            outside = sel & (sgn * xi >= sgn * head)
            fan = sel & ~outside & (sgn * xi > sgn * front)
            rho[outside], u[outside], p[outside] = K.rho, K.u, K.p
            rho[fan], u[fan], p[fan] = K.fan(sgn, xi[fan])
        if rho.ndim == 0:
            return float(rho), float(u), float(p), int(side)
        return rho, u, p, side


def solve(left, right):
    """Shorthand for RiemannProblem(left, right)."""
    return RiemannProblem(left, right)
