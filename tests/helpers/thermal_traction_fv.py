"""Independent reference for the thermal traction law: finite-volume solution of the energy equation of one strip.

The law (hsbearing.models.traction.thermal) takes the surface temperatures from Jaeger's band-source kernel in
closed form, splits the heat between the surfaces by Blok's partition and takes the film at its mean temperature
tau dU h / (12 K) above the surfaces.  None of that is used here.  This solver discretises, for one strip of the
Hertz ellipse (x along the rolling direction):

* each solid as a moving half-space, steady advection-diffusion u dT/dx = kappa (d2T/dx2 + d2T/dz2) on a 2-D
  finite-volume grid (second-order upwind advection, central diffusion; inflow and depth at the inlet temperature,
  outflow with no diffusive flux), each at its own surface speed u1 = U (1 + S/2), u2 = U (1 - S/2);
* the film at every contact cell as n_film cells across its thickness h, conduction only (K d2T/dz2 = -w),
  its two walls joined to the two solids' surface cells through the series conductance of the half cells;
* the heat w(z) = tau gdot(z): the shear stress tau is uniform across the film, the local Eyring flow rate
  gdot(z) = (tau0(T)/eta(p, T)) sinh(tau/tau0(T)) varies with the film temperature T(z), and the viscous flow
  stress tau_v solves mean(gdot) = dU / h (bisection); the limiting shear acts on it as in the law (the same
  rheology: thermal.roelands_viscosity, thermal.eyring_stress_at, the smooth minimum with Lambda p); the heat
  tau dU per area is distributed across the film as gdot(z);
* the viscoelastic build-up by its own integration of Johnson & Tevaarwerk's Maxwell-Eyring equation
  gdot = (U / G) dtau/dx + gdot_v(tau) along the strip (:func:`march_film`): gdot_v(tau) is the film's *mean*
  viscous rate over its n_film cells at their own temperatures (tau_v(tau) = (tau^-4 - tau_L^-4)^(-1/4), the
  inverse of the smooth minimum), not Nahme's factor; backward Euler with ``n_sub`` sub-steps on each of the n_x
  uniform cells (the law: one step on each of 16 cells uniform in theta), the implicit step solved by Newton
  safeguarded by its bracket.  (Before, this reference took the law's closed form tau_f (1 - exp(-tel / tau_f)) and
  could not see that it was 11-25 % low at the elastic-plastic knee; docs/traction.md.)

one sparse linear system for all temperatures (factorised once), and a relaxed fixed point between the
temperatures and the stress.  mu = sum tau dx / sum p dx on a uniform grid of n_x cells.

``couette_film`` is the film part alone between isothermal walls (checked against Nahme's closed form).
"""

from __future__ import annotations

import math

import numpy as np
import scipy.sparse as sp
import scipy.sparse.linalg as spla

from hsbearing.models.traction import thermal as th


def _geometric(first, total, growth=1.15):
    """Cell sizes starting at ``first``, growing by ``growth``, summing to at least ``total``."""
    out, s = [], 0.0
    d = first
    while s < total:
        out.append(d)
        s += d
        d *= growth
    return np.array(out)


def _tau_v(Tf, p, gdot, eta_fn, tau0_fn, iters=80):
    """Viscous flow stress uniform across the film with mean(gdot(z)) = gdot: bisection per contact cell.
    Tf (nc, nf) film temperatures [K]; p (nc,) [Pa]; returns (tau_v (nc,), rate (nc, nf) at tau_v)."""
    eta = eta_fn(p[:, None], Tf)
    t0 = tau0_fn(Tf)
    tiso = t0 * np.arcsinh(np.minimum(eta * gdot / t0, 1e300))
    lo, hi = tiso.min(axis=1), tiso.max(axis=1) * (1.0 + 1e-12) + 1e-300

    def rate(tau):
        return (t0 / eta) * np.sinh(np.minimum(tau[:, None] / t0, 700.0))

    for _ in range(iters):
        mid = 0.5 * (lo + hi)
        big = rate(mid).mean(axis=1) > gdot
        hi = np.where(big, mid, hi)
        lo = np.where(big, lo, mid)
    tv = 0.5 * (lo + hi)
    return tv, rate(tv)


def march_film(xc, p, gdot, U, G, tauL, rate_of, x_in, n_sub=2, guess=None):
    """Maxwell-Eyring stress along the strip's uniform cells [Pa]: backward Euler, ``n_sub`` sub-steps per cell.

    rate_of(i, tv) -> the mean viscous rate of cell i's film at the viscous stress tv and its derivative d/dtv
    (the film's own temperatures); tauL (nc,) the cap of each cell.  Each implicit step solves
    tau - tau_prev - ds G gdot / U + ds (G / U) gdot_v(tau) = 0 on (0, min(tau_prev + ds G gdot / U, tau_L)):
    increasing in tau, so Newton safeguarded by bisection.  The sub-steps of cell i run from the previous cell's
    centre (x_in for the first) to xc[i] with that cell's film."""
    out = np.zeros(len(xc))
    B = G / abs(U)
    tau, xp = 0.0, float(x_in)
    for i in range(len(xc)):
        tL = float(tauL[i])
        if p[i] <= 0.0 or tL <= 0.0:
            tau, xp = 0.0, float(xc[i])
            continue
        ds = (float(xc[i]) - xp) / n_sub
        xp = float(xc[i])
        for _ in range(n_sub):
            base = tau + ds * B * gdot
            lo, hi = 0.0, min(base, tL * (1.0 - 1e-12))
            t = float(guess[i]) if guess is not None and 0.0 < guess[i] < hi else 0.5 * hi
            for _ in range(200):
                q = 1.0 - (t / tL) ** 4
                tv = t * q ** -0.25  # (t^-4 - tL^-4)^(-1/4) without overflow at small t
                g, dg = rate_of(i, tv)
                f = t - base + ds * B * g
                if f > 0.0:
                    hi = t
                else:
                    lo = t
                tn = t - f / (1.0 + ds * B * dg * q ** -1.25)
                if not lo < tn < hi:
                    tn = 0.5 * (lo + hi)
                if abs(tn - t) <= 1e-12 * t or hi - lo <= 1e-13 * hi:
                    t = tn
                    break
                t = tn
            tau = t
        out[i] = tau
    return out


def _solid_block(xe, ze, u, k, kappa):
    """FV matrix of one moving solid (W per unit y-length per K), unknowns ordered (i, j) -> i * nz + j."""
    xc, zc = 0.5 * (xe[:-1] + xe[1:]), 0.5 * (ze[:-1] + ze[1:])
    dx, dz = np.diff(xe), np.diff(ze)
    nx, nz = len(xc), len(zc)
    rc = k / kappa  # rho c
    rows, cols, vals = [], [], []

    def add(r, c, v):
        rows.append(r)
        cols.append(c)
        vals.append(v)

    for i in range(nx):
        for j in range(nz):
            P = i * nz + j
            # diffusion in x
            if i > 0:
                g = k * dz[j] / (xc[i] - xc[i - 1])
                add(P, P, g)
                add(P, P - nz, -g)
            else:  # inflow face at the inlet temperature (rise 0)
                add(P, P, k * dz[j] / (0.5 * dx[i]))
            if i < nx - 1:
                g = k * dz[j] / (xc[i + 1] - xc[i])
                add(P, P, g)
                add(P, P + nz, -g)
            # diffusion in z (z depth; top face: interface or adiabatic, added by the caller)
            if j < nz - 1:
                g = k * dx[i] / (zc[j + 1] - zc[j])
                add(P, P, g)
                add(P, P + 1, -g)
            else:
                add(P, P, k * dx[i] / (0.5 * dz[j]))
            if j > 0:
                g = k * dx[i] / (zc[j] - zc[j - 1])
                add(P, P, g)
                add(P, P - 1, -g)
            # advection (u > 0), second-order upwind face values: out through east, in through west
            m = rc * u * dz[j]
            if i == nx - 1 or i == 0:
                add(P, P, m)  # east face value T_P (first order at the ends)
            else:
                f = (xe[i + 1] - xc[i]) / (xc[i] - xc[i - 1])
                add(P, P, m * (1.0 + f))
                add(P, P - nz, -m * f)
            if i >= 2:
                f = (xe[i] - xc[i - 1]) / (xc[i - 1] - xc[i - 2])
                add(P, P - nz, -m * (1.0 + f))
                add(P, P - 2 * nz, m * f)
            elif i == 1:
                add(P, P - nz, -m)
            # i == 0: inflow value 0
    return rows, cols, vals, nx * nz


def strip_reference(S, U, p0u, b_u, h, T_in, oil, prm, *, Ge, tau0_in, n_x=120, n_film=12, n_sub=2, tol=1e-4,
                    max_iter=4000):
    """Reference mu of one strip and its fields (same arguments as thermal.strip_mu).  Returns (mu, fields)."""
    if S == 0.0:
        return 0.0, {}
    s, Ua = abs(S), abs(U)
    u1, u2 = Ua * (1.0 + 0.5 * S), Ua * (1.0 - 0.5 * S)
    k, kappa, K = prm.k_solid, prm.kappa_solid, oil["K"]
    # x grid: n_x uniform cells over the contact, geometric cells upstream and downstream
    dxc = 2.0 * b_u / n_x
    umin = min(u1, u2)
    up = _geometric(dxc, max(1.0 * b_u, 8.0 * kappa / umin))[::-1]
    dn = _geometric(dxc, 3.0 * b_u)
    dxs = np.concatenate([up, np.full(n_x, dxc), dn])
    xe = np.concatenate([[0.0], np.cumsum(dxs)]) - up.sum() - b_u
    i0 = len(up)  # first contact cell
    delta = math.sqrt(kappa * 2.0 * b_u / max(umin, 1e-9))
    dz0 = min(dxc, delta / 40.0, h * 50.0)
    ze = np.concatenate([[0.0], np.cumsum(_geometric(dz0, 3.0 * b_u + 6.0 * delta, 1.12))])
    nz = len(ze) - 1
    blocks = []
    offset = 0
    rows, cols, vals = [], [], []
    for uu in (u1, u2):
        r, c, v, n = _solid_block(xe, ze, uu, k, kappa)
        rows += [x + offset for x in r]
        cols += [x + offset for x in c]
        vals += v
        blocks.append(offset)
        offset += n
    nf = n_film
    dzf = h / nf
    film0 = offset
    nunk = offset + n_x * nf
    dz_top = ze[1] - ze[0]
    G = 1.0 / (0.5 * dzf / K + 0.5 * dz_top / k)  # film wall cell <-> solid surface cell, per area
    for ic in range(n_x):
        i = i0 + ic
        for m in range(nf):
            P = film0 + ic * nf + m
            if m > 0:
                g = K * dxc / dzf
                rows += [P, P]
                cols += [P, P - 1]
                vals += [g, -g]
            if m < nf - 1:
                g = K * dxc / dzf
                rows += [P, P]
                cols += [P, P + 1]
                vals += [g, -g]
        for m, b0 in ((0, blocks[0]), (nf - 1, blocks[1])):
            P = film0 + ic * nf + m
            Q = b0 + i * nz  # surface cell j = 0
            g = G * dxc
            rows += [P, P, Q, Q]
            cols += [P, Q, Q, P]
            vals += [g, -g, g, -g]
    A = sp.csc_matrix((vals, (rows, cols)), shape=(nunk, nunk))
    lu = spla.splu(A)
    xc = -b_u + dxc * (np.arange(n_x) + 0.5)
    p = p0u * np.sqrt(np.maximum(1.0 - (xc / b_u) ** 2, 0.0))
    dU = s * Ua
    gdot = dU / h
    eta_in, alpha, beta_in = oil["eta_in"], oil["alpha"], oil["beta_in"]
    if prm.pressure_viscosity == "roelands":
        z, S0 = th.roelands_indices(eta_in, alpha, beta_in, T_in)
        z = prm.z if prm.z is not None else z

        def eta_fn(pp, TT):
            return th.roelands_viscosity(pp, TT, eta_in, T_in, z, S0)
    else:
        def eta_fn(pp, TT):
            return th.barus_viscosity(pp, TT, eta_in, T_in, alpha, beta_in)

    def tau0_fn(TT):
        return th.eyring_stress_at(tau0_in, TT, T_in, prm.eyring_temperature)

    Tf = np.full((n_x, nf), float(T_in))
    tau_prev = None
    omega = 0.5
    last = np.inf
    it = 0
    for it in range(1, max_iter + 1):
        Tm = Tf.mean(axis=1)
        tauL = prm.limiting_shear(Tm) * p
        eta_z = eta_fn(p[:, None], Tf)
        t0_z = tau0_fn(Tf)
        c_z = (t0_z / eta_z).tolist()
        it0_z = (1.0 / t0_z).tolist()

        def rate_of(i, tv, c_z=c_z, it0_z=it0_z):
            g = dg = 0.0
            for cc, ii in zip(c_z[i], it0_z[i]):
                r = min(tv * ii, 700.0)
                g += cc * math.sinh(r)
                dg += cc * ii * math.cosh(r)
            return g / nf, dg / nf

        tau = march_film(xc, p, gdot, Ua, Ge, tauL, rate_of, -b_u, n_sub=n_sub, guess=tau_prev)
        tau_prev = tau
        if not prm.thermal:
            break
        tv_z = np.maximum(tau, 1e-300)[:, None]
        lsv = np.minimum(tv_z, tauL[:, None] * (1.0 - 1e-12))
        tvv = lsv * (1.0 - (lsv / tauL[:, None]) ** 4) ** -0.25  # viscous stress of each cell at its stress
        rate = (t0_z / eta_z) * np.sinh(np.minimum(tvv / t0_z, 700.0))
        share = rate / np.maximum(rate.sum(axis=1, keepdims=True), 1e-300)
        w = (tau * dU)[:, None] * share * dxc  # W per unit y-length in each film cell
        rhs = np.zeros(nunk)
        rhs[film0:] = w.ravel()
        sol = lu.solve(rhs)
        T_new = T_in + sol[film0:].reshape(n_x, nf)
        dT = T_new - Tf
        Tf = Tf + omega * dT
        change = np.max(np.abs(dT))
        if change < tol:
            break
        if change > last:  # oscillating: relax harder
            omega = max(0.5 * omega, 0.02)
        last = change
    else:
        raise RuntimeError("reference fixed point did not converge")
    mu = math.copysign(float(np.sum(tau) / np.sum(p)), S)
    return mu, dict(x=xc, p=p, tau=tau, T_film=Tf.mean(axis=1), T_max=Tf.max(axis=1), iterations=it)


def couette_film(dU, h, K, eta_of_T, tau0=1e15, n_film=200, T_wall=300.0, tol=1e-10, max_iter=2000):
    """Film alone between two walls at T_wall: uniform stress, rate gdot(z) = (tau0/eta(T)) sinh(tau/tau0)
    (tau0 -> infinity: Newtonian), heat tau gdot(z) conducted to the walls.  Returns (tau, T(z) - T_wall)."""
    nf = n_film
    dz = h / nf
    main = np.full(nf, 2.0)
    main[0] = main[-1] = 3.0  # half-cell distance to the wall
    A = sp.diags([main, -np.ones(nf - 1), -np.ones(nf - 1)], [0, -1, 1], format="csc") * (K / dz)
    lu = spla.splu(A)
    T = np.full(nf, float(T_wall))
    tau = 0.0
    for _ in range(max_iter):
        tv, rate = _tau_v(T[None, :], np.array([1.0]), dU / h, lambda pp, TT: eta_of_T(TT),
                          lambda TT: tau0 * np.ones_like(TT))
        tau = float(tv[0])
        T_new = T_wall + lu.solve(tau * rate[0] * dz)
        if np.max(np.abs(T_new - T)) < tol:
            T = T_new
            break
        T = 0.5 * (T + T_new)
    return tau, T - T_wall
