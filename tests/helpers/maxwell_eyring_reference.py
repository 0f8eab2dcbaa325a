"""Independent reference for the viscoelastic build-up of the traction law "physical": the Maxwell-Eyring equation
integrated along the streamlines of the Hertz ellipse.

The law's first build-up (hsbearing.models.traction.thermal.local_stress, the same closed form as the kernel law
"eyring"; since replaced in "physical" by a cell-by-cell march of the equation below, thermal.maxwell_eyring_march,
which this reference checks) takes the stress at every point in closed form,

    tau = tau_f (1 - exp(-tel / tau_f)),   tel = G_eff |S| (x - x_in) / h,

tau_f the steady flow stress of the point (Eyring flow, smooth minimum with the limiting shear Lambda p).  That is the
exact solution of the *linear* Maxwell equation for a viscosity that does not change along the path.  In a Hertz
contact the viscosity changes by orders of magnitude along the path and the flow is non-linear, so the closed form is
an approximation of the constitutive model it stands for: the Maxwell-Eyring fluid of Johnson & Tevaarwerk [1],

    gdot = (1 / G) dtau/dt + gdot_v(tau),       d/dt = U d/dx,   tau = 0 where the strip starts (x_in = -b_u),

with gdot = |S| U / h the imposed shear rate and gdot_v(tau) the viscous (steady) flow rate at the stress tau.  Here
gdot_v is the inverse of the law's own steady flow curve, so the rheology is the same and only the treatment of the
history differs: tau_f(gdot) = (tau_v^-4 + tau_L^-4)^(-1/4) with tau_v = tau0 asinh(eta gdot / tau0) (the law's smooth
minimum, written symmetrically) gives

    tau_v(tau) = (tau^-4 - tau_L^-4)^(-1/4),   gdot_v(tau) = (tau0 / eta(p)) sinh(tau_v / tau0)   (tau < tau_L).

This module integrates that equation numerically, isothermally (the law with ``thermal = False``), on each of n_y
strips y = a sin(phi) (Gauss-Legendre in phi, not the law's strips or weights), along x = b_u sin(theta) with theta
uniform (n_x steps, fine at both edges where the pressure changes fastest), by backward Euler (L-stable: the
relaxation length eta U / G is far below a step where the viscosity is low), the implicit equation of every step solved
by bisection on [0, min(tau_n + dx G gdot / U, tau_L)) (gdot_v rises monotonically to infinity at tau_L, so the root
is bracketed and unique), Richardson-extrapolated from n_x and n_x / 2 steps.  mu = sum_y w int tau dx /
sum_y w int p dx (trapezoid in x).  It shares with the law only the
rheology (thermal.roelands_viscosity or barus_viscosity, tau0, Lambda, G_eff) and the contact's parameters
(thermal.contact_parameters).

References
----------
[1] Johnson K. L., Tevaarwerk J. L., Shear behaviour of elastohydrodynamic oil films, Proc. R. Soc. Lond. A 356
    (1977) 215-236 (the Maxwell model with a non-linear (sinh) viscous element; read as an abstract only, the
    equation as it is reproduced throughout the EHL traction literature, e.g. Evans & Johnson 1986).
"""

from __future__ import annotations

import math

import numpy as np

from hsbearing.models.traction import thermal as th


def viscous_rate(tau, eta, tau0, tauL):
    """Steady viscous flow rate at the stress tau [1/s]: the inverse of the law's flow curve (module docstring).
    0 at tau <= 0; +inf at tau >= tau_L.  Vectorised."""
    tau, eta, tau0, tauL = np.broadcast_arrays(*(np.asarray(v, dtype=float) for v in (tau, eta, tau0, tauL)))
    out = np.zeros(tau.shape)
    ok = (tau > 0.0) & (tau < tauL)
    tv = (tau[ok] ** -4 - tauL[ok] ** -4) ** -0.25
    out[ok] = tau0[ok] / eta[ok] * np.sinh(np.minimum(tv / tau0[ok], 700.0))
    out[tau >= tauL] = np.inf
    return out


def contact_mu(S, W, U, Ep, Rx, k, a, T, eta_in, alpha, beta_in, prm=None, *, n_y=16, n_x=400, h=None,
               return_strips=False):
    """mu of a whole contact by the Maxwell-Eyring equation integrated along x, isothermal [-] (odd in S).

    Arguments as thermal.contact_mu (K is not needed: no heat).  prm must have thermal = False.
    Vectorised in S (all slips march together).  Backward Euler is first order in the step: the result is the
    Richardson extrapolation 2 mu(n_x) - mu(n_x / 2) (measured: the plain n_x = 400 march is 1.1e-3 off the closed
    form of a constant-viscosity film, the extrapolated one 2.5e-5).
    """
    fine = _contact_mu(S, W, U, Ep, Rx, k, a, T, eta_in, alpha, beta_in, prm, n_y=n_y, n_x=n_x, h=h)
    coarse = _contact_mu(S, W, U, Ep, Rx, k, a, T, eta_in, alpha, beta_in, prm, n_y=n_y, n_x=n_x // 2, h=h)
    mu = 2.0 * fine[0] - coarse[0]
    return (mu, fine[1]) if return_strips else mu


def _contact_mu(S, W, U, Ep, Rx, k, a, T, eta_in, alpha, beta_in, prm, *, n_y, n_x, h):
    """One backward-Euler march (:func:`contact_mu`); returns (mu, parameters)."""
    prm = prm or th.PhysicalParameters(thermal=False)
    if prm.thermal:
        raise ValueError("the Maxwell-Eyring reference is isothermal: use PhysicalParameters(thermal=False)")
    b, p0, h, Ge, tau0 = th.contact_parameters(W, U, Ep, Rx, k, a, eta_in, alpha, prm, T, h)
    if prm.pressure_viscosity == "roelands":
        z, S0 = th.roelands_indices(eta_in, alpha, beta_in, T)
        if prm.z is not None:
            z = prm.z

        def eta_of(p):
            return th.roelands_viscosity(p, T, eta_in, T, z, S0)
    else:
        def eta_of(p):
            return th.barus_viscosity(p, T, eta_in, T, alpha, beta_in)
    Lam = float(prm.limiting_shear(T))
    t0 = float(th.eyring_stress_at(tau0, T, T, prm.eyring_temperature))
    Sa = np.asarray(S, dtype=float)
    s = np.abs(Sa.ravel())[:, None]                      # (nS, 1)
    A = Ge * s / h                                       # elastic stress rate per length, G gdot / U [Pa/m]
    B = Ge / abs(U)                                      # [Pa s / m]
    xg, wg = np.polynomial.legendre.leggauss(n_y)
    phi = 0.5 * math.pi * xg
    wy = 0.5 * math.pi * wg * np.cos(phi)                # dy = a cos(phi) dphi (a cancels)
    su = np.cos(phi)[None, :]                            # (1, n_y): sqrt(1 - u^2)
    p0u, bu = p0 * su, b * su
    theta = np.linspace(-0.5 * math.pi, 0.5 * math.pi, n_x + 1)
    tau = np.zeros((s.shape[0], n_y))
    integral = np.zeros_like(tau)
    x_prev = -bu
    for kk in range(1, n_x + 1):
        x = bu * math.sin(theta[kk])
        dx = x - x_prev
        p = p0u * math.cos(theta[kk])
        tauL = Lam * p
        hi = np.minimum(tau + dx * A, tauL * (1.0 - 1e-14))
        if np.all(p <= 0.0):
            new = np.zeros_like(tau)
        else:
            eta = eta_of(np.maximum(p, 1.0))
            lo = np.zeros_like(tau)
            base = tau + dx * A
            for _ in range(46):
                mid = 0.5 * (lo + hi)
                F = mid - base + dx * B * viscous_rate(mid, eta, t0, tauL)
                pos = F > 0.0
                hi = np.where(pos, mid, hi)
                lo = np.where(pos, lo, mid)
            new = 0.5 * (lo + hi)
        integral += 0.5 * (tau + new) * dx
        tau = new
        x_prev = x
    load = 0.5 * math.pi * bu * p0u                      # int p dx of each strip
    mu = np.sum(wy * integral, axis=1) / float(np.sum(wy * load))
    mu = np.copysign(mu, Sa.ravel()).reshape(Sa.shape)
    return mu, dict(b=b, p0=p0, h=h, Ge=Ge, tau0=t0, Lambda=Lam)
