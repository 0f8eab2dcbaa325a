"""Independent numerical Reynolds solutions of a journal-bearing film, for the guide-land tests (test-only).

Nothing here is derived from hsbearing.models.ball_bearing.cage: the film thickness comes from the geometry of two
circles in the inertial frame, h(Theta, t) = c - y(t) cos(Theta) - z(t) sin(Theta) (inner member = the
cage, displaced by (y, z) from the land centre), its time and angle derivatives are taken by central
differences, and the Reynolds equation

    d/dx (h^3 dp/dx) + d/dz (h^3 dp/dz) = 6 eta (U_1 + U_2) dh/dx + 12 eta dh/dt,   x = R Theta,

is solved with the Guembel condition p >= 0 (Hamrock, Schmid & Jacobson, *Fundamentals of Fluid Film
Lubrication*, 2004, Ch. 7 and 10; Reynolds-equation forms of San Andres, *Modern Lubrication Theory*,
Notes 4):

* :func:`short_bearing_forces` drops d/dx (h^3 dp/dx) (short width): p(Theta, z) is a parabola in z
  whose amplitude is computed on a fine Theta grid, clipped at 0 and integrated by the trapezoidal rule;
* :func:`finite_bearing_forces` keeps both terms: a 2-D finite-volume grid (Theta, z) solved by
  projected successive over-relaxation (PSOR, p <- max(0, p_SOR): Christopherson's method, the
  Swift-Stieber / Reynolds cavitation condition at convergence).

Forces are returned on the cage in the (r, t) frame of the guide_land_forces contract: r along the
offset (positive away from the land centre), t perpendicular, positive in the direction of rotation.
"""

from __future__ import annotations

import math

import numpy as np
from numba import njit


def _film(y, z, vy, vz, c, theta, dt=1e-7):
    """h(Theta) and dh/dt, dh/dTheta by central differences of the two-circle geometry [m, m/s, m]."""
    h = lambda yy, zz, th: c - yy * np.cos(th) - zz * np.sin(th)  # noqa: E731
    h0 = h(y, z, theta)
    ht = (h(y + vy * dt, z + vz * dt, theta) - h(y - vy * dt, z - vz * dt, theta)) / (2 * dt)
    d = 1e-6
    hth = (h(y, z, theta + d) - h(y, z, theta - d)) / (2 * d)
    return h0, ht, hth


def _state(eps, eps_dot, whirl, c):
    """A cage at offset e = eps c along Y, moving radially at eps' c and tangentially at e whirl."""
    e = eps * c
    return e, 0.0, eps_dot * c, e * whirl


def _to_rt(Fy, Fz, y, z):
    e = math.hypot(y, z)
    uy, uz = y / e, z / e
    return Fy * uy + Fz * uz, -Fy * uz + Fz * uy


def short_bearing_forces(eps, eps_dot, omega_sum, whirl, eta, R, L, c, n=8001):
    """Film force (F_r, F_t) [N] of the short-width Reynolds equation with p >= 0, by numerical quadrature."""
    y, z, vy, vz = _state(eps, eps_dot, whirl, c)
    th = np.linspace(-math.pi, math.pi, n)
    h, ht, hth = _film(y, z, vy, vz, c, th)
    rhs = 6.0 * eta * omega_sum * hth + 12.0 * eta * ht  # right side of the Reynolds equation [Pa m]
    # d/dz (h^3 dp/dz) = rhs, p(+-L/2) = 0  ->  p = rhs (z^2 - L^2/4) / (2 h^3); 3-point Gauss-Legendre
    # across the width (exact for the parabola)
    xg, wg = np.polynomial.legendre.leggauss(3)
    zz = 0.5 * L * xg
    p = rhs[:, None] * (zz[None, :] ** 2 - 0.25 * L * L) / (2.0 * h[:, None] ** 3)
    p = np.maximum(p, 0.0)  # Guembel
    w = p @ (0.5 * L * wg)  # [N/m]
    Fy = -np.trapezoid(w * np.cos(th), th) * R
    Fz = -np.trapezoid(w * np.sin(th), th) * R
    return _to_rt(Fy, Fz, y, z)


@njit(cache=True)
def _psor(P, A_e, A_w, A_n, A_s, A_p, S, omega, tol, maxit):
    """Projected SOR on a (Theta periodic, z Dirichlet 0) grid; returns the number of sweeps."""
    nt, nz = P.shape
    for it in range(maxit):
        dmax = 0.0
        pmax = 1e-300
        for i in range(nt):
            ie = (i + 1) % nt
            iw = (i - 1) % nt
            for j in range(1, nz - 1):
                g = (A_e[i] * P[ie, j] + A_w[i] * P[iw, j] + A_n[i] * (P[i, j + 1] + P[i, j - 1]) - S[i]) / A_p[i]
                new = P[i, j] + omega * (g - P[i, j])
                if new < 0.0:
                    new = 0.0
                d = abs(new - P[i, j])
                if d > dmax:
                    dmax = d
                if new > pmax:
                    pmax = new
                P[i, j] = new
        if dmax < tol * pmax:
            return it + 1
    return maxit


def finite_bearing_forces(eps, eps_dot, omega_sum, whirl, eta, R, L, c, nt=720, nz=41, omega=1.7,
                          tol=1e-10, maxit=200000):
    """Film force (F_r, F_t) [N] of the 2-D (finite-length) Reynolds equation with p >= 0 (PSOR).

    Finite volumes: cell faces at Theta_i +- dTheta/2 carry h^3 of the face; the z faces h^3 of the
    node.  Returns (F_r, F_t, sweeps).
    """
    y, z, vy, vz = _state(eps, eps_dot, whirl, c)
    dth = 2 * math.pi / nt
    th = np.arange(nt) * dth - math.pi
    h, ht, hth = _film(y, z, vy, vz, c, th)
    he, _, _ = _film(y, z, vy, vz, c, th + 0.5 * dth)
    hw, _, _ = _film(y, z, vy, vz, c, th - 0.5 * dth)
    dz = L / (nz - 1)
    dx = R * dth
    A_e = he**3 / dx**2
    A_w = hw**3 / dx**2
    A_n = h**3 / dz**2
    A_p = A_e + A_w + 2 * A_n
    # dh/dx = dh/dTheta / R;  6 eta (U1 + U2) dh/dx = 6 eta omega_sum dh/dTheta
    S = 6.0 * eta * omega_sum * hth + 12.0 * eta * ht
    P = np.zeros((nt, nz))
    sweeps = _psor(P, A_e, A_w, A_n, A_n, A_p, S, omega, tol, maxit)
    zz = np.linspace(-0.5 * L, 0.5 * L, nz)
    w = np.trapezoid(P, zz, axis=1)
    Fy = -np.sum(w * np.cos(th)) * dth * R  # periodic: the rectangle rule is the trapezoidal rule
    Fz = -np.sum(w * np.sin(th)) * dth * R
    Fr, Ft = _to_rt(Fy, Fz, y, z)
    return Fr, Ft, sweeps
