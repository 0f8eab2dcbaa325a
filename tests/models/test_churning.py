"""The churning laws of models/ball_bearing/churning.py against our own independent solutions.

* mixture co-rotation: a finite-difference solution of the azimuthal Stokes equation d/dr (r^3 d omega/dr) = 0
  between the raceways, inner or outer ring turning, both senses;
* ball drag power: quadrature of F . v over one orbit with the vector velocities of ball and mixture (2-D), both
  orbit directions, co-rotation 0..1; power = wake share + mixture share; k = 0 equals the kernel's drag law;
* jet-oil acceleration: an oil parcel picked up by a moving wall, integrated in time (two drag laws): the wall's
  work is m v^2 whatever the law, half of it dissipated;
* cage windage: the laminar free-disc moment against our own solution of von Karman's similarity equations.
"""

from __future__ import annotations

import math

import numpy as np
import pytest
from scipy.integrate import quad, solve_bvp, solve_ivp

from hsbearing.models.ball_bearing import churning
from hsbearing.models.ball_bearing.drag import ball_drag_force


def _couette_fd(omega_i, omega_o, r_i, r_o, n=4001):
    """omega(r) from d/dr (r^3 d omega/dr) = 0 by second-order finite differences (flux form)."""
    r = np.linspace(r_i, r_o, n)
    h = r[1] - r[0]
    rp, rm = (r[1:-1] + 0.5 * h) ** 3, (r[1:-1] - 0.5 * h) ** 3
    A = np.zeros((n, n))
    b = np.zeros(n)
    A[0, 0] = A[-1, -1] = 1.0
    b[0], b[-1] = omega_i, omega_o
    idx = np.arange(1, n - 1)
    A[idx, idx - 1], A[idx, idx], A[idx, idx + 1] = rm, -(rm + rp), rp
    return r, np.linalg.solve(A, b)


@pytest.mark.parametrize("omega_i,omega_o", [(1.0, 0.0), (-1.0, 0.0), (0.0, 1.0), (0.0, -2.0), (3.0, 1.0)])
@pytest.mark.parametrize("gamma", [0.05, 0.14, 0.3])
def test_couette_against_finite_differences(omega_i, omega_o, gamma):
    r, w = _couette_fd(omega_i, omega_o, 1.0 - gamma, 1.0 + gamma)
    w_m = np.interp(1.0, r, w)
    assert churning.couette_mixture_angular_velocity(omega_i, omega_o, 1 - gamma, 1 + gamma, 1.0) == pytest.approx(w_m, rel=1e-6, abs=1e-9)
    w_c = 0.5 * (omega_i * (1 - gamma) + omega_o * (1 + gamma))
    assert churning.couette_corotation_fraction(gamma, omega_i, omega_o) == pytest.approx(w_m / w_c, rel=1e-6)


def test_couette_fraction_closed_form_inner_ring():
    for gamma in (0.05, 0.14, 0.3):
        assert churning.couette_corotation_fraction(gamma) == pytest.approx(1 - gamma / 2 - gamma**2 / 2, rel=1e-13)
    assert math.isnan(churning.couette_corotation_fraction(0.2, 1.0, -(0.8 / 1.2)))  # the cage stands still
    with pytest.raises(ValueError):
        churning.couette_corotation_fraction(0.0)


def _orbit_power(Omega, k, R, D, rho, C_D):
    """Mean of F . v over one orbit of a ball at radius R turning at Omega in a mixture turning at k Omega,
    from the 2-D vectors (the ball's velocity, the mixture's velocity at the ball) by adaptive quadrature."""
    c = 0.5 * C_D * rho * 0.25 * math.pi * D * D

    def p(t):
        th = Omega * t
        e_t = np.array([-math.sin(th), math.cos(th)])
        v = Omega * R * e_t
        u = k * Omega * R * e_t
        w = v - u
        F = -c * np.linalg.norm(w) * w
        return -float(F @ v)

    T = 2 * math.pi / abs(Omega)
    return quad(p, 0.0, T, limit=200)[0] / T


@pytest.mark.parametrize("Omega", [3000.0, -3000.0, 50.0, -1.0])
@pytest.mark.parametrize("k", [0.0, 0.3, 0.889, 1.0])
def test_drag_power_against_orbit_quadrature(Omega, k):
    R, D, rho, C_D = 0.02325, 7.14e-3, 23.0, 0.47
    v = Omega * R
    F, P, P_w, P_m = churning.ball_drag_power(v, k * v, D, rho, C_D)
    assert P == pytest.approx(_orbit_power(Omega, k, R, D, rho, C_D), rel=1e-10, abs=1e-300)
    assert P >= 0.0 and P_w >= 0.0 and P_m >= 0.0          # a loss in both orbit directions
    assert P_w + P_m == pytest.approx(P, rel=1e-12, abs=1e-300)  # the balance: wake + mixture = what the ball spends
    assert F * v <= 0.0                                   # the force opposes the motion relative to the mixture
    assert P == pytest.approx(0.5 * C_D * rho * 0.25 * math.pi * D * D * (1 - k) ** 2 * abs(v) ** 3, rel=1e-12, abs=1e-300)


def test_drag_power_at_rest_mixture_is_the_kernel_law():
    D, rho, C_D = 7.14e-3, 23.0, 0.47
    for v in (-80.0, -3.0, 0.5, 75.4):
        F, P, _, P_m = churning.ball_drag_power(v, 0.0, D, rho, C_D)
        assert F == pytest.approx(ball_drag_force(v, D, rho, C_D, 0.0), rel=1e-14)
        assert P_m == 0.0


def test_drag_power_finite_difference_of_work():
    """P = dW/dt: the work F . dx done by the ball over a short arc, by differences of positions."""
    R, Omega, k, D, rho, C_D = 0.02325, 3300.0, 0.5, 7.14e-3, 23.0, 0.47
    v = R * Omega
    F = churning.ball_drag_power(v, k * v, D, rho, C_D)[0]
    dt = 1e-7
    x0, x1 = R * np.array([1.0, 0.0]), R * np.array([math.cos(Omega * dt), math.sin(Omega * dt)])
    Fvec = F * np.array([-math.sin(0.5 * Omega * dt), math.cos(0.5 * Omega * dt)])
    assert -float(Fvec @ (x1 - x0)) / dt == pytest.approx(churning.ball_drag_power(v, k * v, D, rho, C_D)[1], rel=1e-8)


@pytest.mark.parametrize("law", ["linear", "quadratic"])
@pytest.mark.parametrize("V", [29.3, -75.4])
def test_jet_oil_acceleration_against_a_parcel_picked_up_by_a_wall(law, V):
    """A unit mass of oil at rest dragged by a wall moving at V: the wall spends int F V dt = m V^2 (any law), the
    parcel gains 1/2 m V^2, the rest is dissipated."""
    c = 50.0

    def f(t, y):
        u = y[0]
        F = c * (V - u) if law == "linear" else c * (V - u) * abs(V - u)
        return [F, F * V, F * (V - u)]

    sol = solve_ivp(f, (0.0, 40.0 if law == "linear" else 400.0), [0.0, 0.0, 0.0], rtol=1e-11, atol=1e-12, method="LSODA")
    u, W, Q = sol.y[:, -1]
    P, P_diss = churning.jet_oil_acceleration_power(1.0, V)
    assert u == pytest.approx(V, rel=2e-3)
    assert W == pytest.approx(P, rel=3e-3)
    assert Q == pytest.approx(P_diss, rel=3e-3)
    assert P == pytest.approx(V * V, rel=1e-14) and P_diss == pytest.approx(0.5 * V * V, rel=1e-14)
    with pytest.raises(ValueError):
        churning.jet_oil_acceleration_power(-1.0, V)


def _von_karman_G0():
    """G'(0) of the von Karman rotating-disc similarity solution, solved here (solve_bvp on [0, 20])."""
    def f(z, y):  # y = F, F', G, G', H ; F'' = F^2 - G^2 + H F', G'' = 2 F G + H G', H' = -2 F
        F, Fp, G, Gp, H = y
        return np.vstack([Fp, F * F - G * G + H * Fp, Gp, 2 * F * G + H * Gp, -2 * F])

    def bc(ya, yb):
        return np.array([ya[0], ya[2] - 1.0, ya[4], yb[0], yb[2]])

    z = np.linspace(0, 20, 400)
    y0 = np.vstack([0.5 * z * np.exp(-z), 0.5 * np.exp(-z) * (1 - z), np.exp(-z), -np.exp(-z), -0.9 * (1 - np.exp(-z))])
    sol = solve_bvp(f, bc, z, y0, tol=1e-8, max_nodes=200000)
    assert sol.success
    return sol.sol(0.0)[3]


def test_windage_laminar_against_von_karman_solution():
    G0 = _von_karman_G0()
    assert G0 == pytest.approx(-0.6159, abs=2e-4)  # Cochran 1934
    rho, mu, omega, r1, r2 = 900.0, 0.5, 20.0, 0.02, 0.03  # Re = omega r2^2 / nu = 0.032: laminar
    nu = mu / rho
    # shear per face tau(r) = -G'(0) rho nu^1/2 omega^3/2 r; moment of both faces by quadrature
    M_quad = 2 * quad(lambda r: -G0 * rho * math.sqrt(nu) * omega**1.5 * r * 2 * math.pi * r * r, r1, r2)[0]
    for s in (1.0, -1.0):
        M = churning.rotating_annulus_windage_moment(s * omega, r1, r2, rho, mu)
        assert M == pytest.approx(-s * M_quad, rel=2e-3)
    assert churning.DISC_LAMINAR_CM == pytest.approx(-4 * math.pi * G0 / 2 * 2 / 2, rel=2e-3)


def test_windage_turbulent_branch_and_edges():
    rho, mu, r2 = 23.0, 3e-5, 0.0255
    nu = mu / rho
    omega = 3500.0  # Re = omega r2^2 / nu ~ 1.7e6: the turbulent law is the larger
    M = -churning.rotating_annulus_windage_moment(omega, 0.0, r2, rho, mu)
    Re = omega * r2 * r2 / nu
    assert M == pytest.approx(0.5 * churning.DISC_TURBULENT_CM * Re**-0.2 * 0.5 * rho * omega**2 * r2**5 * 2, rel=1e-12)
    assert churning.rotating_annulus_windage_moment(0.0, 0.01, r2, rho, mu) == 0.0
    # the annulus is the disc minus its hole, in each regime
    assert -churning.rotating_annulus_windage_moment(omega, 0.02, r2, rho, mu) == pytest.approx(
        M - (-churning.rotating_annulus_windage_moment(omega, 0.0, 0.02, rho, mu) * 0.0
             + 0.5 * churning.DISC_TURBULENT_CM * rho * nu**0.2 * omega**1.8 * 0.02**4.6), rel=1e-12)
    with pytest.raises(ValueError):
        churning.rotating_annulus_windage_moment(omega, 0.03, 0.02, rho, mu)


def test_drag_band_brackets_and_orders():
    b = churning.drag_band(16, 75.4, 7.14e-3, 23.0, 3e-5, 0.92)
    assert b["low"] <= b[(0.0, "subcritical")] <= b["high"]
    assert b[(0.92, "subcritical")] < b[(0.0, "subcritical")]
    assert b[(0.0, "crisis")] <= b[(0.0, "subcritical")] * 1.0000001
