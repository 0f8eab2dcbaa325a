"""Independent numerical thermal-inlet solution of a rolling/sliding line contact (test reference).

The classical thermal inlet analysis of Murch & Wilson (1975) [1], extended to sliding by Wilson & Sheu (1983)
[2] (the numerical basis of the inlet-heating factor of Gupta et al. 1992 that ``hsbearing.models.ehl`` uses),
solved here from scratch.  Nothing of hsbearing is imported: this module checks that code.

Model (what was read and what was recalled: docs/power_loss.md, "Inlet heating: proof against our own thermal
inlet"; the papers themselves were not reachable, the model below is written from their recalled statement and
from first principles):

* line contact, inlet x < -b of the Hertz contact; the gap outside the contact is the Hertz gap
  h(x) = h0 + (b^2 / 2R) [X sqrt(X^2 - 1) - acosh X], X = |x| / b (``gap="hertz"``, the Ertel-Grubin inlet), or
  the rigid parabola h = h0 + (x^2 - b^2) / (2R) (``gap="rigid"``; with b = 0 the rigid Grubin/Martin inlet that
  has a closed form, :func:`rigid_isothermal_h0`);
* surfaces at u1 = u (1 + s/2), u2 = u (1 - s/2) (u the entrainment speed, s the slide-roll ratio); the film
  inside the contact is parallel at h0 and carries the flux Q = u h0 (both walls at the inlet temperature: the
  temperature profile is symmetric across the film, so the mean velocity is u whatever the profile);
* viscosity eta(p, T) = eta0 exp(alpha p - beta (T - T0)) (Barus in p, the oil's own exponential slope beta in T);
* Reynolds' thin-film momentum d tau / dz = dp/dx with the viscosity varying across the film (the generalised
  Reynolds equation), written for the reduced pressure q = (1 - exp(-alpha p)) / alpha and the reduced stress
  tau~ = tau exp(-alpha p): d tau~/dz = dq/dx, du/dz = tau~ / (eta0 theta(z)), theta = exp(-beta (T - T0));
* the temperature across the film from the energy equation with conduction only (convection along x neglected,
  as Murch & Wilson did [1]): k d^2T/dz^2 = -D, both surfaces held at the inlet temperature T0.  The dissipation
  D = tau~^2 / (eta0 theta) is the reduced one (``dissipation="reduced"``): the Murch-Wilson form whose result
  depends on the thermal loading L = beta eta0 u^2 / k and the slide-roll ratio but not on alpha (their
  published curve phi_T = 3.94 / (3.94 + L^0.62) has no alpha).  In the inlet the source is the reverse
  Poiseuille flow (pure rolling) plus the Couette shear of the sliding;
* inlet condition (Grubin / Ertel-Grubin): the reduced pressure, integrated from far upstream (q = 0), reaches
  1 / alpha at the contact edge x = -b; h0 by bisection on q(-b) = 1/alpha.
* variant :func:`full_dissipation_ratio`: the dissipation of the real viscosity, e^(alpha p) tau~^2 / (eta0 theta),
  i.e. the local problem at L e^(alpha p) = L / (1 - alpha q), marched along x with q; inlet condition at the
  finite edge pressure p_h (alpha q = 1 - e^(-alpha p_h)).  This reading reproduces the published Murch-Wilson
  curve in pure rolling (docs/power_loss.md); which of the two the papers used was not read.

Dimensionless local problem (at each x; z in units of h, velocities of u, phi = beta (T - T0)):
  phi'' = -L sigma^2 e^phi,  phi(0) = phi(1) = 0,  sigma = sigma0 + Gb z,
  int_0^1 sigma e^phi dz = s,   (1 - s/2) + int_0^1 (1 - z) sigma e^phi dz = r = h0 / h,
with Gb = (dq/dx) h^2 / (eta0 u).  Isothermally Gb = 12 (1 - r); the local thermal factor is
Phi(r; L, s) = Gb / (12 (1 - r)).  Solved by Newton's method on a uniform grid (second-order finite differences,
trapezoid quadrature), continuation in L from the isothermal solution.  Then

  q(-b) = (12 eta0 u / h0) int_0^1 (1 - r) Phi(r) / g'(x(r)) dr,  g = h - h0,

(the substitution r = h0 / h(x)), by Gauss-Legendre quadrature in v (r = sin^2(pi v / 2)) with Phi interpolated in r.

References
----------
[1] Murch L. E., Wilson W. R. D., "A thermal elastohydrodynamic inlet zone analysis", ASME J. Lubr. Technol. 97
    (1975) 212-216: phi_T = 3.94 / (3.94 + L^0.62), L = (-d eta/dT) u^2 / k (recalled, not read).
[2] Wilson W. R. D., Sheu S., "Effect of inlet shear heating due to sliding on elastohydrodynamic film
    thickness", ASME J. Lubr. Technol. 105 (1983) 187-188 (recalled, not read).
[3] Grubin A. N., 1949; as given by Dowson D., Higginson G. R., *Elasto-hydrodynamic Lubrication*, 1966/1977,
    Ch. 5: h0 / R = 1.95 (G U)^(8/11) W^(-1/11) for the Ertel-Grubin inlet (U = eta0 u / (E' R), G = alpha E',
    W = w / (E' R), u the entrainment speed, w the load per unit length).
"""

from __future__ import annotations

import functools
import math

import numpy as np
from scipy import interpolate

__all__ = [
    "local_factor",
    "local_factor_table",
    "inlet_h0",
    "thermal_ratio",
    "rigid_isothermal_h0",
    "grubin_h0",
    "murch_wilson_curve",
    "full_dissipation_ratio",
]


def _grid(n):
    z = np.linspace(0.0, 1.0, n + 1)
    w = np.full(n + 1, 1.0 / n)
    w[0] = w[-1] = 0.5 / n
    return z, w


def _newton(r, L, s, n, phi, sig0, Gb, tol=1e-12, maxit=60):
    """Newton on (phi interior, sigma0, Gb) for a batch of r at one L.  Arrays: r (m,), phi (m, n+1)."""
    z, w = _grid(n)
    dz2 = 1.0 / n**2
    m = r.size
    ni = n - 1  # interior unknowns
    size = ni + 2
    A = (np.diag(-2.0 * np.ones(ni)) + np.diag(np.ones(ni - 1), 1) + np.diag(np.ones(ni - 1), -1)) / dz2
    zi = z[1:-1]
    u2 = 1.0 - 0.5 * s

    def residual(phi, sig0, Gb):
        sig = sig0[:, None] + Gb[:, None] * z[None, :]
        e = np.exp(phi)
        Rin = phi[:, 1:-1] @ A.T + L * sig[:, 1:-1] ** 2 * e[:, 1:-1]
        # boundary nodes are zero, so A @ interior is the full Laplacian
        c1 = (w * sig * e).sum(axis=1) - s
        c2 = u2 + (w * (1.0 - z) * sig * e).sum(axis=1) - r
        return np.concatenate([Rin, c1[:, None], c2[:, None]], axis=1), sig, e

    R, sig, e = residual(phi, sig0, Gb)
    for _ in range(maxit):
        J = np.zeros((m, size, size))
        J[:, :ni, :ni] = A[None] + np.einsum("mi,ij->mij", L * sig[:, 1:-1] ** 2 * e[:, 1:-1], np.eye(ni))
        J[:, :ni, ni] = 2.0 * L * sig[:, 1:-1] * e[:, 1:-1]
        J[:, :ni, ni + 1] = 2.0 * L * sig[:, 1:-1] * e[:, 1:-1] * zi[None, :]
        we = (w * sig * e)[:, 1:-1]
        J[:, ni, :ni] = we
        J[:, ni, ni] = (w * e).sum(axis=1)
        J[:, ni, ni + 1] = (w * z * e).sum(axis=1)
        J[:, ni + 1, :ni] = we * (1.0 - zi)[None, :]
        J[:, ni + 1, ni] = (w * (1.0 - z) * e).sum(axis=1)
        J[:, ni + 1, ni + 1] = (w * (1.0 - z) * z * e).sum(axis=1)
        d = np.linalg.solve(J, -R[..., None])[..., 0]
        norm0 = np.abs(R).max(axis=1)
        lam = np.ones(m)
        for _ls in range(30):  # backtracking per batch member
            phin = phi.copy()
            phin[:, 1:-1] = phi[:, 1:-1] + lam[:, None] * d[:, :ni]
            s0n = sig0 + lam * d[:, ni]
            Gn = Gb + lam * d[:, ni + 1]
            Rn, sign, en = residual(phin, s0n, Gn)
            bad = ~(np.abs(Rn).max(axis=1) <= (1.0 - 1e-4 * lam) * norm0) & (norm0 > tol)
            if not bad.any():
                break
            lam = np.where(bad, 0.5 * lam, lam)
        phi, sig0, Gb, R, sig, e = phin, s0n, Gn, Rn, sign, en
        scale = np.maximum(1.0, np.abs(Gb))
        if (np.abs(d[:, ni + 1]) <= tol * scale).all() and (np.abs(R[:, ni:]).max() <= 1e-12):
            break
    else:
        raise RuntimeError(f"thermal inlet: Newton did not converge at L={L:g}, s={s:g}")
    return phi, sig0, Gb


def local_factor_table(r, L, s, n=128, steps_per_decade=4):
    """Local thermal factor Phi(r; L', s) = Gb / (12 (1 - r)) along a continuation path ending at L.

    Returns (Ls, Phi) with Ls the path (ascending, last = L) and Phi of shape (len(Ls), len(r)).
    """
    r = np.atleast_1d(np.asarray(r, dtype=float))
    s = abs(float(s))  # mirror symmetry: s -> -s swaps the walls (z -> 1 - z), same Gb
    z, _ = _grid(n)
    Gb = 12.0 * (1.0 - r)
    sig0 = s - 0.5 * Gb
    phi = np.zeros((r.size, n + 1))
    if L <= 0.0:
        return np.array([0.0]), np.ones((1, r.size))
    L0 = 1e-2
    k = max(1, int(math.ceil(steps_per_decade * math.log10(max(L / L0, 10.0)))))
    Ls = np.geomspace(min(L0, L), L, k + 1)
    out = []
    for Lk in Ls:
        phi, sig0, Gb = _newton(r, Lk, s, n, phi, sig0, Gb)
        out.append(Gb / (12.0 * (1.0 - r)))
    return Ls, np.array(out)


def local_factor(r, L, s, n=128):
    """Local thermal factor Phi(r; L, s) = (dq/dx)_thermal / (dq/dx)_isothermal at h0 / h = r [-]."""
    return local_factor_table(r, L, s, n=n)[1][-1]


def _gap(gap, b, R):
    """g(x) = h - h0 and g'(x) for |x| >= b, as functions of xi = |x| (m)."""
    if gap == "hertz":
        c = b * b / (2.0 * R)

        def g(xi):
            X = xi / b
            return c * (X * np.sqrt(X * X - 1.0) - np.arccosh(X))

        def dg(xi):
            X = xi / b
            return (b / R) * np.sqrt(X * X - 1.0)
    elif gap == "rigid":
        def g(xi):
            return (xi * xi - b * b) / (2.0 * R)

        def dg(xi):
            return xi / R
    else:
        raise ValueError(f"unknown gap {gap!r} (hertz, rigid)")
    return g, dg


def _invert(g, target, b, R):
    """xi >= b with g(xi) = target (vectorised bisection on a monotone g)."""
    lo = np.full_like(target, b)
    hi = np.maximum(b, 1e-12) + np.sqrt(2.0 * R * target) * 2.0 + 10.0 * max(b, 1e-9)
    while True:
        mask = g(hi) < target
        if not mask.any():
            break
        hi = np.where(mask, 2.0 * hi, hi)
    for _ in range(120):
        mid = 0.5 * (lo + hi)
        m = g(mid) < target
        lo = np.where(m, mid, lo)
        hi = np.where(m, hi, mid)
        if np.all(hi - lo <= 1e-15 * hi):
            break
    return 0.5 * (lo + hi)


@functools.lru_cache(maxsize=8)
def _r_nodes(nq):
    """Nodes r = sin^2(pi v / 2) and weights (Gauss-Legendre in v on (0, 1), times dr/dv)."""
    v, wv = np.polynomial.legendre.leggauss(nq)
    v = 0.5 * (v + 1.0)
    r = np.sin(0.5 * math.pi * v) ** 2
    return r, 0.5 * wv * 0.5 * math.pi * np.sin(math.pi * v)


def _reduced_pressure(h0, eta0, u, b, R, Phi_of_r, gap, nq=200):
    """q(-b) = (12 eta0 u / h0) int_0^1 (1 - r) Phi(r) / g'(x(r)) dr [Pa].

    r = sin^2(pi v / 2) removes the endpoint singularities (integrand ~ sqrt(r) at r -> 0 and ~ (1 - r)^(2/3) at
    the Hertz edge r -> 1); nq-point Gauss-Legendre in v.
    """
    g, dg = _gap(gap, b, R)
    r, wr = _r_nodes(nq)
    xi = _invert(g, h0 * (1.0 / r - 1.0), b, R)
    val = np.sum(wr * (1.0 - r) * Phi_of_r(r) / dg(xi))
    return 12.0 * eta0 * u / h0 * val


def inlet_h0(eta0, alpha, u, R, b, *, Phi_of_r=None, gap="hertz", nq=200):
    """Film h0 [m] at which the reduced pressure reaches 1/alpha at the contact edge (bisection in log h0)."""
    if Phi_of_r is None:
        def Phi_of_r(r):
            return np.ones_like(r)
    target = 1.0 / alpha
    lo, hi = 1e-12, 1e-3
    for _ in range(80):
        mid = math.sqrt(lo * hi)
        if _reduced_pressure(mid, eta0, u, b, R, Phi_of_r, gap, nq) > target:
            lo = mid  # too much pressure: the film can be thicker
        else:
            hi = mid
        if hi / lo < 1.0 + 1e-10:
            break
    return math.sqrt(lo * hi)


def _phi_interpolant(L, s, n, nr=48):
    """Phi(r) on Chebyshev-Lobatto-like nodes of (0, 1) (ends excluded), cubic interpolation (PCHIP)."""
    t = (np.arange(nr) + 0.5) / nr
    r = 0.5 * (1.0 - np.cos(math.pi * t))
    Phi = local_factor(r, L, s, n=n)
    f = interpolate.PchipInterpolator(r, Phi, extrapolate=True)
    return f, r, Phi


def thermal_ratio(eta0, alpha, beta, k, u, s, R, b, *, gap="hertz", n=128, nr=48, nq=200):
    """h0_thermal / h0_isothermal of the inlet (and both films) [-], with L = beta eta0 u^2 / k.

    Returns dict(ratio, h_iso, h_thermal, L).
    """
    u = abs(float(u))
    L = beta * eta0 * u * u / k
    h_iso = inlet_h0(eta0, alpha, u, R, b, gap=gap, nq=nq)
    f, _r, _P = _phi_interpolant(L, s, n, nr)
    h_th = inlet_h0(eta0, alpha, u, R, b, Phi_of_r=f, gap=gap, nq=nq)
    return {"ratio": h_th / h_iso, "h_iso": h_iso, "h_thermal": h_th, "L": L}


def rigid_isothermal_h0(eta0, alpha, u, R):
    """Closed form of the rigid parabolic inlet h = h0 + x^2 / (2R) reaching q = 1/alpha at x = 0 [m].

    q(0) = 12 eta0 u int_{-inf}^0 (h - h0) / h^3 dx = (3 pi / 4) sqrt(2) eta0 u sqrt(R) h0^(-3/2) = 1 / alpha
    (int_0^inf t^2 / (1 + t^2)^3 dt = pi / 16).
    """
    return (0.75 * math.pi * math.sqrt(2.0) * alpha * eta0 * u * math.sqrt(R)) ** (2.0 / 3.0)


def grubin_h0(eta0, alpha, u, R, Ep, w):
    """Grubin's fit of the Ertel-Grubin inlet [3]: h0 = 1.95 R (G U)^(8/11) W^(-1/11) [m]."""
    U = eta0 * u / (Ep * R)
    G = alpha * Ep
    W = w / (Ep * R)
    return 1.95 * R * (G * U) ** (8.0 / 11.0) * W ** (-1.0 / 11.0)


def murch_wilson_curve(L):
    """Murch & Wilson's published curve fit phi_T = 3.94 / (3.94 + L^0.62) [1] (pure rolling) [-]."""
    L = np.asarray(L, dtype=float)
    return 3.94 / (3.94 + L**0.62)


# --- full dissipation: the heating with the pressure-dependent viscosity ---------------------------------------


def full_dissipation_ratio(eta0, alpha, beta, k, u, s, R, b, p_edge, *, gap="hertz", n=64, nr=48, nv=400,
                           L_cap=1e4):
    """h0_thermal / h0_isothermal with the dissipation of the real viscosity, tau^2 / eta = e^(alpha p) tau~^2 /
    (eta0 theta): the local problem at L_eff = L e^(alpha p) = L / (1 - alpha q), coupled along x through q.

    Inlet condition at a finite pressure (the Ertel-Grubin equivalent): alpha q(-b) = 1 - exp(-alpha p_edge)
    (p_edge = p_h; with heating in a sliding inlet the reduced pressure may never reach 1/alpha, because the
    Couette heating grows as e^(alpha p)).  The local factor is tabulated on (r, log L_eff) along the
    continuation path up to min(L e^(alpha p_edge), L_cap) (beyond L_cap: the factor at L_cap, which
    underestimates the heating there; the returned ``capped`` says whether the cap was reached).  Along x: RK4 in
    v (r = sin^2(pi v / 2)), nv steps; h0 by bisection.  Returns dict(ratio, h_iso, h_thermal, L, capped).
    """
    u = abs(float(u))
    L = beta * eta0 * u * u / k
    target = -math.expm1(-alpha * p_edge)
    t = (np.arange(nr) + 0.5) / nr
    rn = 0.5 * (1.0 - np.cos(math.pi * t))
    Lmax = min(max(L, 1e-12) * math.exp(min(alpha * p_edge, 700.0)), L_cap)
    Ls, Phi = local_factor_table(rn, Lmax, s, n=n)
    if Ls.size < 2:
        Ls, Phi = np.array([0.0, 1.0]), np.ones((2, rn.size))
    lL = np.log(np.maximum(Ls, 1e-300))
    spline = interpolate.RectBivariateSpline(rn, lL, Phi.T, kx=3, ky=1)
    capped = {"hit": False}
    g, dg = _gap(gap, b, R)

    def Phi_at(r, y):
        Le = L / max(1.0 - y, 1e-300)
        if Le >= Ls[-1]:
            capped["hit"] = Le > Ls[-1] * (1 + 1e-9)
            Le = Ls[-1]
        if Le <= Ls[0]:
            return float(spline(r, lL[0])[0, 0]) if L > 0 else 1.0
        return float(spline(r, math.log(Le))[0, 0])

    vv = np.linspace(0.0, 1.0, 2 * nv + 1)[1:-1]  # RK4 nodes and midpoints, ends excluded (integrand 0 there)
    rr = np.sin(0.5 * math.pi * vv) ** 2
    jac = 0.5 * math.pi * np.sin(math.pi * vv)
    hstep = 1.0 / nv

    def shoot(h0, thermal):
        xi = _invert(g, h0 * (1.0 / rr - 1.0), b, R)
        base = np.concatenate([[0.0], 12.0 * eta0 * u * alpha / h0 * (1.0 - rr) / dg(xi) * jac, [0.0]])
        rfull = np.concatenate([[0.0], rr, [1.0]])

        def f(j, y):
            if base[j] == 0.0:
                return 0.0
            return base[j] * (Phi_at(rfull[j], y) if thermal else 1.0)

        y = 0.0
        for i in range(nv):
            j0, jm, j1 = 2 * i, 2 * i + 1, 2 * i + 2
            k1 = f(j0, y)
            k2 = f(jm, min(y + 0.5 * hstep * k1, target))
            k3 = f(jm, min(y + 0.5 * hstep * k2, target))
            k4 = f(j1, min(y + hstep * k3, target))
            y += hstep * (k1 + 2 * k2 + 2 * k3 + k4) / 6.0
            if y >= target:
                return True
        return False

    def solve(thermal, lo=1e-12, hi=1e-3):
        for _ in range(80):
            mid = math.sqrt(lo * hi)
            if shoot(mid, thermal):
                lo = mid
            else:
                hi = mid
            if hi / lo < 1.0 + 1e-7:
                break
        return math.sqrt(lo * hi)

    h_iso = solve(False)
    h_th = solve(True, 1e-3 * h_iso, h_iso * 1.0001)
    return {"ratio": h_th / h_iso, "h_iso": h_iso, "h_thermal": h_th, "L": L, "capped": capped["hit"]}
