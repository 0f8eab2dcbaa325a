"""Independent numerical reference solutions for the elements of the steady thermal network (hsbearing/systems/angular_contact/thermal.py).

Nothing here uses hsbearing: each function solves the governing equations of one element on its own
(a boundary-value ODE, a finite-volume or boundary-element discretisation), so that the closed forms of
hsbearing.systems.angular_contact.thermal can be checked against something that is not themselves.  Used by tools/investigations/thermal_review.py
(fine grids, the numbers of docs/thermal.md "Review") and by tests/validation/test_thermal_reference.py (coarse grids).

* :func:`rotating_disk` -- von Karman's rotating disk in a fluid at rest (Cochran's similarity variables),
  momentum and energy as a two-point boundary-value problem (scipy solve_bvp), with a quadrature cross-check
  of the energy equation;
* :func:`halfspace_disk_fv` -- steady axisymmetric conduction into a half space from a disk (isothermal or
  uniform flux), finite volumes on a stretched grid, far boundary extrapolated to infinity;
* :func:`ellipse_bem` -- isothermal elliptic contact on a half space, collocation boundary elements with the
  half-space Green function 1 / (2 pi k r);
* :func:`ring_fv` -- axisymmetric conduction through a ring section (r, z) heated over a band of its race;
* :func:`fin_fd` -- 1-D pin fin with an adiabatic tip, second-order finite differences.
"""

from __future__ import annotations

import math

import numpy as np


# ----------------------------------------------------------------------------- rotating disk
def rotating_disk(prandtl, zmax: float = 20.0, n_energy: int = 400, tol: float = 1e-8):
    """Von Karman rotating disk (laminar, fluid at rest far away), Cochran's variables zeta = z sqrt(omega / nu):
    u = r omega F, v = r omega G, w = sqrt(nu omega) H,
    F'' = F^2 - G^2 + H F',  G'' = 2 F G + H G',  H' = -2 F,  F(0) = H(0) = 0, G(0) = 1, F, G -> 0;
    energy theta'' = Pr H theta', theta(0) = 1, theta -> 0.  h = -theta'(0) k sqrt(omega / nu).

    Returns dict F0p = F'(0), G0p = G'(0), Hinf = H(zmax), and nu_bvp / nu_quad: -theta'(0) per Prandtl number
    from the energy BVP and from its quadrature 1 / int_0^inf exp(Pr int_0^z H) dz."""
    from scipy.integrate import cumulative_trapezoid, solve_bvp

    z = zmax * np.linspace(0.0, 1.0, 400) ** 2.5

    def f(_z, y):
        F, Fp, G, Gp, H = y
        return np.vstack([Fp, F * F - G * G + H * Fp, Gp, 2 * F * G + H * Gp, -2 * F])

    def bc(ya, yb):
        return np.array([ya[0], ya[2] - 1.0, ya[4], yb[0], yb[2]])

    y0 = np.zeros((5, z.size))
    y0[2], y0[3], y0[4] = np.exp(-z), -np.exp(-z), -0.88 * (1.0 - np.exp(-z))
    sol = solve_bvp(f, bc, z, y0, tol=tol, max_nodes=200000)
    if not sol.success:
        raise RuntimeError(f"rotating disk momentum BVP: {sol.message}")
    F0p = float(sol.y[1, 0])
    zq = np.linspace(0.0, zmax, 100001)
    I = cumulative_trapezoid(sol.sol(zq)[4], zq, initial=0.0)
    out_bvp, out_q = [], []
    for Pr in np.atleast_1d(prandtl):
        ze = min(zmax, 12.0 * (3.0 / (Pr * F0p)) ** (1.0 / 3.0))  # ~ 10 thermal layer thicknesses
        zt = ze * np.linspace(0.0, 1.0, n_energy) ** 1.5
        c = Pr ** (1.0 / 3.0)
        se = solve_bvp(lambda zz, y, Pr=Pr: np.vstack([y[1], Pr * sol.sol(zz)[4] * y[1]]),
                       lambda ya, yb: np.array([ya[0] - 1.0, yb[0]]), zt,
                       np.vstack([np.exp(-c * zt), -c * np.exp(-c * zt)]), tol=tol * 10, max_nodes=400000)
        if not se.success:
            raise RuntimeError(f"rotating disk energy BVP at Pr {Pr}: {se.message}")
        out_bvp.append(float(-se.y[1, 0]))
        out_q.append(float(1.0 / np.trapezoid(np.exp(Pr * I), zq)))
    return {"F0p": F0p, "G0p": float(sol.y[3, 0]), "Hinf": float(sol.y[4, -1]),
            "nu_bvp": np.array(out_bvp), "nu_quad": np.array(out_q)}


# ----------------------------------------------------------------------------- conduction, finite volumes
def _edges(n_fine, fine_to, L, growth):
    e = list(np.linspace(0.0, fine_to, n_fine + 1))
    d = fine_to / n_fine
    while e[-1] < L:
        d *= growth
        e.append(e[-1] + d)
    return np.array(e)


def _axisym_matrix(re, ze, k):
    """Finite-volume conduction matrix on an (r, z) grid of edges re, ze (no boundary terms: adiabatic)."""
    import scipy.sparse as sp

    rc, zc = 0.5 * (re[1:] + re[:-1]), 0.5 * (ze[1:] + ze[:-1])
    nr, nz = rc.size, zc.size
    I, J = np.meshgrid(np.arange(nr), np.arange(nz), indexing="ij")
    p = I * nz + J
    rows, cols, vals = [], [], []
    diag = np.zeros(nr * nz)
    # radial faces between (i, j) and (i+1, j): area 2 pi r dz
    g = k * 2 * math.pi * re[1:-1, None] * np.diff(ze)[None, :] / np.diff(rc)[:, None]
    a, b = p[:-1, :].ravel(), p[1:, :].ravel()
    rows += [a, b]
    cols += [b, a]
    vals += [-g.ravel(), -g.ravel()]
    np.add.at(diag, a, g.ravel())
    np.add.at(diag, b, g.ravel())
    # axial faces: area pi (r_{i+1}^2 - r_i^2)
    g = k * math.pi * (re[1:] ** 2 - re[:-1] ** 2)[:, None] / np.diff(zc)[None, :]
    a, b = p[:, :-1].ravel(), p[:, 1:].ravel()
    rows += [a, b]
    cols += [b, a]
    vals += [-g.ravel(), -g.ravel()]
    np.add.at(diag, a, g.ravel())
    np.add.at(diag, b, g.ravel())
    A = sp.csr_matrix((np.concatenate(vals), (np.concatenate(rows), np.concatenate(cols))), shape=(nr * nz,) * 2)
    return A, diag, rc, zc


def halfspace_disk_fv(mode: str = "isothermal", n: int = 40, L: float = 50.0, growth: float = 1.08) -> float:
    """Constriction resistance x k a of a disk of radius a = 1 on a half space (k = 1), finite volumes.

    Domain 0 < r < L, 0 < z < L (stretched grid, n cells across the disk), T = 0 on r = L and z = L, the
    surface z = 0 adiabatic outside the disk; ``mode`` "isothermal": T = 1 on the disk, R = 1 / Q;
    "isoflux": uniform flux Q = 1, R = mean disk temperature.  The truncation error ~ c / L is removed by
    evaluating at L and 2 L: R = 2 R(2L) - R(L)."""
    import scipy.sparse as sp
    import scipy.sparse.linalg as spla

    def one(Lx):
        re, ze = _edges(n, 1.0, Lx, growth), _edges(max(n // 2, 2), 0.5, Lx, growth)
        A, diag, rc, zc = _axisym_matrix(re, ze, 1.0)
        nr, nz = rc.size, zc.size
        diag = diag.copy()
        b = np.zeros(nr * nz)
        outer = (nr - 1) * nz + np.arange(nz)
        diag[outer] += 2 * math.pi * re[-1] * np.diff(ze) / (re[-1] - rc[-1])
        top = np.arange(nr) * nz + nz - 1
        diag[top] += math.pi * (re[1:] ** 2 - re[:-1] ** 2) / (ze[-1] - zc[-1])
        disk = np.where(re[1:] <= 1.0 + 1e-12)[0]
        area = math.pi * (re[disk + 1] ** 2 - re[disk] ** 2)
        cells = disk * nz
        gs = area / (zc[0] - ze[0])
        if mode == "isothermal":
            diag[cells] += gs
            b[cells] += gs
        else:
            b[cells] += area / math.pi
        T = spla.spsolve((A + sp.diags(diag)).tocsc(), b)
        if mode == "isothermal":
            return 1.0 / float(np.sum(gs * (1.0 - T[cells])))
        Ts = T[cells] + (zc[0] - ze[0]) / math.pi
        return float(np.sum(Ts * area) / np.sum(area))

    return 2.0 * one(2.0 * L) - one(L)


def ellipse_bem(a: float, b: float, n: int, k: float = 1.0) -> float:
    """Constriction resistance [K/W] of an isothermal ellipse (semi-axes a >= b) on a half space of conductivity k:
    collocation on an n x m grid of rectangles covering the ellipse (staircase boundary), potential of a
    surface flux q: T(x) = int q / (2 pi k |x - x'|) dA' (half-space Green function), T = 1 on the contact,
    R = 1 / sum(q A).  The rectangle's own singular integral is exact: 4 [p ln((q + d)/p) + q ln((p + d)/q)]."""
    m = max(4, int(round(n * b / a)))
    dx, dy = 2 * a / n, 2 * b / m
    X, Y = np.meshgrid(-a + dx * (np.arange(n) + 0.5), -b + dy * (np.arange(m) + 0.5), indexing="ij")
    inside = (X / a) ** 2 + (Y / b) ** 2 <= 1.0
    x, y = X[inside], Y[inside]
    r = np.hypot(x[:, None] - x[None, :], y[:, None] - y[None, :])
    p, q = dx / 2, dy / 2
    d = math.hypot(p, q)
    own = 4 * (p * math.log((q + d) / p) + q * math.log((p + d) / q))
    with np.errstate(divide="ignore"):
        M = np.where(r > 0, dx * dy / np.where(r > 0, r, 1.0), own) / (2 * math.pi * k)
    qv = np.linalg.solve(M, np.ones(x.size))
    return 1.0 / float(qv.sum() * dx * dy)


def ring_fv(r1: float, r2: float, B: float, band: float, k: float, nr: int = 20, nz: int = 80,
            heat_at: str = "outer") -> tuple[float, float]:
    """Ring section r1 < r < r2, 0 < z < B of conductivity k, finite volumes: T = 0 on the cylinder opposite the
    heated one, heat Q = 1 W uniformly over the band |z - B/2| < band/2 of the heated cylinder (``heat_at``
    "outer": r2, the inner ring's race; "inner": r1, the outer ring's race), the other faces adiabatic.
    Returns (mean temperature of the band, mean temperature of the heated cylinder) [K/W]."""
    import scipy.sparse as sp
    import scipy.sparse.linalg as spla

    re, ze = np.linspace(r1, r2, nr + 1), np.linspace(0.0, B, nz + 1)
    A, diag, rc, zc = _axisym_matrix(re, ze, k)
    dz = np.diff(ze)
    diag = diag.copy()
    b = np.zeros(nr * nz)
    cold, hot = (0, nr - 1) if heat_at == "outer" else (nr - 1, 0)
    rcold, rhot = (re[0], re[-1]) if heat_at == "outer" else (re[-1], re[0])
    diag[cold * nz + np.arange(nz)] += k * 2 * math.pi * rcold * dz / abs(rc[cold] - rcold)
    inband = np.abs(zc - B / 2) < band / 2
    Aband = 2 * math.pi * rhot * dz[inband].sum()
    b[hot * nz + np.where(inband)[0]] += 2 * math.pi * rhot * dz[inband] / Aband
    T = spla.spsolve((A + sp.diags(diag)).tocsc(), b)
    Th = T[hot * nz + np.arange(nz)] + np.where(inband, 1.0 / Aband, 0.0) * abs(rhot - rc[hot]) / k
    return float(np.sum(Th[inband] * dz[inband]) / dz[inband].sum()), float(np.sum(Th * dz) / B)


def fin_fd(h: float, d: float, k: float, L: float, n: int = 400) -> float:
    """Conductance [W/K] of a pin fin (diameter d, length L, adiabatic tip) by second-order finite differences of
    k A T'' = h P (T - T_inf), T(0) = 1, T'(L) = 0 (ghost node): G = heat leaving the base k A (-dT/dx)(0), taken
    as the convective loss of the whole fin (trapezoidal over the nodes) so that it is second-order too."""
    A, P = math.pi * d * d / 4, math.pi * d
    m2 = h * P / (k * A)
    dx = L / n
    main = np.full(n + 1, -2.0 - m2 * dx * dx)
    lo, up = np.ones(n), np.ones(n)
    up[0] = 0.0
    main[0] = 1.0
    lo[-1] = 2.0  # ghost node of the adiabatic tip
    from scipy.linalg import solve_banded

    ab = np.zeros((3, n + 1))
    ab[0, 1:], ab[1], ab[2, :-1] = up, main, lo
    rhs = np.zeros(n + 1)
    rhs[0] = 1.0
    T = solve_banded((1, 1), ab, rhs)
    w = np.full(n + 1, dx)
    w[0] = w[-1] = dx / 2
    return float(h * P * np.sum(w * T))
