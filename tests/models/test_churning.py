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
    from scipy.linalg import solve_banded

    r = np.linspace(r_i, r_o, n)
    h = r[1] - r[0]
    rp, rm = (r[1:-1] + 0.5 * h) ** 3, (r[1:-1] - 0.5 * h) ** 3
    ab = np.zeros((3, n))  # tridiagonal: super, main, sub diagonal
    b = np.zeros(n)
    ab[1, 0] = ab[1, -1] = 1.0
    b[0], b[-1] = omega_i, omega_o
    ab[0, 2:], ab[1, 1:-1], ab[2, :-2] = rp, -(rm + rp), rm
    return r, solve_banded((1, 1), ab, b)


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


# --- the cavity mixture's angular-momentum balance (mixture_momentum_balance) -------------------------------------

def _von_karman_H_inf():
    """-H(inf) of the von Karman disc (the axial inflow per face over pi R^2 (nu omega)^1/2), solved here."""
    def f(z, y):
        F, Fp, G, Gp, H = y
        return np.vstack([Fp, F * F - G * G + H * Fp, Gp, 2 * F * G + H * Gp, -2 * F])

    def bc(ya, yb):
        return np.array([ya[0], ya[2] - 1.0, ya[4], yb[0], yb[2]])

    z = 20.0 * np.linspace(0, 1, 400) ** 2
    y0 = np.vstack([0.5 * z * np.exp(-z), 0.5 * np.exp(-z) * (1 - z), np.exp(-z), -np.exp(-z), -0.9 * (1 - np.exp(-z))])
    sol = solve_bvp(f, bc, z, y0, tol=1e-8, max_nodes=200000)
    assert sol.success
    return -float(sol.sol(20.0)[4])


def test_free_disc_pumped_flow_laminar_against_von_karman_solution():
    H = _von_karman_H_inf()
    assert H == pytest.approx(0.8845, abs=2e-4)  # Cochran 1934 (recalled: 0.8845)
    nu, R = 1e-3, 0.02
    for omega in (5.0, -5.0):  # Re = omega R^2 / nu = 2: laminar
        assert churning.free_disc_pumped_flow(omega, R, nu) == pytest.approx(H * math.pi * R * R * math.sqrt(nu * 5.0), rel=3e-3)
    nu_air = 2.1e-5 / 1.1
    Re = 7540.0 * 0.0205**2 / nu_air  # ~1.7e5: turbulent branch
    assert churning.free_disc_pumped_flow(7540.0, 0.0205, nu_air) == pytest.approx(0.219 * nu_air * 0.0205 * Re**0.8, rel=1e-12)
    assert churning.free_disc_pumped_flow(0.0, 0.0205, nu_air) == 0.0


@pytest.mark.parametrize("d_omega", [2.0, -2.0, 0.3])
@pytest.mark.parametrize("r1,r2", [(0.02, 0.02325), (0.02325, 0.0265), (1.0, 1.5)])
def test_gap_moment_laminar_against_finite_differences(d_omega, r1, r2):
    """The laminar moment against mu r^3 d omega/dr x 2 pi L of the finite-difference Couette profile (constant in r)."""
    mu, L, rho = 0.5, 0.013, 1.0  # Re = |d_omega| r1 s / nu <= 2 < 64: the laminar law alone
    r, w = _couette_fd(d_omega, 0.0, r1, r2)
    h = r[1] - r[0]
    rh = 0.5 * (r[1:] + r[:-1])
    M_fd = -2 * math.pi * mu * L * rh**3 * np.diff(w) / h
    assert np.ptp(M_fd) < 1e-6 * abs(M_fd).max()
    assert churning.taylor_couette_gap_moment(d_omega, r1, r2, L, rho, mu) == pytest.approx(M_fd.mean(), rel=1e-6)


def test_gap_moment_turbulent_branch():
    r1, r2, L, rho, mu = 0.02045, 0.02325, 0.013, 23.0, 2.2e-5
    s = r2 - r1
    for dw, (c, e) in ((3000.0, (0.065, -0.2)), (-3000.0, (0.065, -0.2)), (30.0, (1.03, -0.5)),
                         (3.0, (2.0, -0.6))):
        Re = rho * abs(dw) * r1 * s / mu
        M = churning.taylor_couette_gap_moment(dw, r1, r2, L, rho, mu)
        M_lam = churning.taylor_couette_gap_moment(dw, r1, r2, L, rho, mu, turbulent=False)
        M_bb = 0.5 * c * (s / r1) ** 0.3 * Re**e * math.pi * rho * dw * dw * r1**4 * L  # Bilgen & Boulos, recalled
        assert M == pytest.approx(math.copysign(max(M_bb, abs(M_lam)), dw), rel=1e-12)
        assert abs(M) >= abs(M_lam)
    assert abs(churning.taylor_couette_gap_moment(3000.0, r1, r2, L, rho, mu)) > 10 * abs(
        churning.taylor_couette_gap_moment(3000.0, r1, r2, L, rho, mu, turbulent=False))  # Re ~ 8e4: turbulent


def _bearing(sign=1.0, **kw):
    """35-mm TP-2275-like numbers at 72 000 r/min (X 0.024): a complete set of balance inputs."""
    w_i = sign * 7540.0
    gam = 0.14
    args = dict(Z=16, D=7.14e-3, r_m=0.02325, r_i=0.02045, r_o=0.0256, length=0.013, omega_i=w_i, omega_o=0.0,
                omega_c=0.5 * w_i * (1 - gam), rho_e=23.2, mu_e=2.2e-5, drag_coefficient=lambda w: 0.47,
                mass_flow=920.0 * 760e-6 / 60.0)
    args.update(kw)
    return args


def _torques(u, a, side, cage=None):
    """The moments on the mixture written out here (no churning call): balls, inner and outer wall layer (laminar:
    Couette across the wall .. r_m; turbulent: Bilgen & Boulos's full gap at the full-gap jump of the layer; the
    larger), side openings (free-disc law), throughflow."""
    r_m, rho, mu, L = a["r_m"], a["rho_e"], a["mu_e"], a["length"]
    w_f = u / r_m
    v = a["omega_c"] * r_m
    A = 0.25 * math.pi * a["D"] ** 2

    def gap(dw, r1, r2):
        s = r2 - r1
        lam = 4 * math.pi * mu * L * r1**2 * r2**2 * abs(dw) / (r2**2 - r1**2)
        Re = rho * abs(dw) * r1 * s / mu
        if Re < 64:
            turb = 0.0
        elif Re < 500:
            turb = 2.0 * (s / r1) ** 0.3 * Re**-0.6
        elif Re < 1e4:
            turb = 1.03 * (s / r1) ** 0.3 * Re**-0.5
        else:
            turb = 0.065 * (s / r1) ** 0.3 * Re**-0.2
        return math.copysign(max(lam, 0.5 * turb * math.pi * rho * dw * dw * r1**4 * L), dw)

    def wall(dw, r_w, r_x):  # a wall layer: laminar across the wall .. r_m, turbulent the full gap at its full jump
        r1, r2 = min(r_w, r_m), max(r_w, r_m)
        lam = 4 * math.pi * mu * L * r1**2 * r2**2 * abs(dw) / (r2**2 - r1**2)
        a_, b_ = min(r_w, r_x), max(r_w, r_x)
        turb = abs(gap(abs(dw) * (1.0 + (r_w / r_x) ** (19.0 / 9.0)), a_, b_))
        return math.copysign(max(lam, turb), dw)

    def wall_at(dw, r_w, r_x, length):  # the same law over another length, the core at mid gap if r_m is not in it
        r_c = r_m if min(r_w, r_x) < r_m < max(r_w, r_x) else 0.5 * (r_w + r_x)
        r1, r2 = min(r_w, r_c), max(r_w, r_c)
        lam = 4 * math.pi * mu * length * r1**2 * r2**2 * abs(dw) / (r2**2 - r1**2)
        a_, b_ = min(r_w, r_x), max(r_w, r_x)
        turb = abs(gap(abs(dw) * (1.0 + (r_w / r_x) ** (19.0 / 9.0)), a_, b_)) * length / L
        return math.copysign(max(lam, turb), dw)

    M = a["Z"] * 0.5 * a["drag_coefficient"](abs(v - u)) * rho * A * (v - u) * abs(v - u) * r_m
    if cage is None:
        M += wall(a["omega_i"] - w_f, a["r_i"], a["r_o"]) + wall(a["omega_o"] - w_f, a["r_o"], a["r_i"])
    else:  # beside the cage ring faces ring; over its width each ring faces the cage (guided side: a film, left out)
        w_c, rb, ro_c, wd = a["omega_c"], cage["r_bore"], cage["r_outside"], cage["width"]
        M += wall_at(a["omega_i"] - w_f, a["r_i"], a["r_o"], L - wd) + wall_at(a["omega_o"] - w_f, a["r_o"], a["r_i"], L - wd)
        if cage["guidance"] != "inner_ring":
            M += wall_at(a["omega_i"] - w_f, a["r_i"], rb, wd) + wall_at(w_c - w_f, rb, a["r_i"], wd)
        if cage["guidance"] != "outer_ring":
            M += wall_at(a["omega_o"] - w_f, a["r_o"], ro_c, wd) + wall_at(w_c - w_f, ro_c, a["r_o"], wd)
        nu, dc = mu / rho, w_c - w_f  # the two side faces: free-disc law at the cage's speed relative to the core
        lam = 0.5 * 3.87 * rho * math.sqrt(nu) * abs(dc) ** 1.5 * (ro_c**4 - rb**4)
        turb = 0.5 * 0.146 * rho * nu**0.2 * abs(dc) ** 1.8 * (ro_c**4.6 - rb**4.6)
        M += math.copysign(max(lam, turb), dc)
    if side:  # the side openings as stationary walls: Boedewadt laminar (G'(0) 0.7729), free-disc turbulent
        nu = mu / rho
        lam = math.pi * 0.7729 * rho * math.sqrt(nu) * abs(w_f) ** 1.5 * (a["r_o"] ** 4 - a["r_i"] ** 4)
        turb = 0.5 * 0.146 * rho * nu**0.2 * abs(w_f) ** 1.8 * (a["r_o"] ** 4.6 - a["r_i"] ** 4.6)
        M -= math.copysign(max(lam, turb), w_f)
    return M - a["mass_flow"] * u * r_m


@pytest.mark.parametrize("sign", [1.0, -1.0])
@pytest.mark.parametrize("side,air", [(False, 0.0), (True, 2.9e-3)])
def test_balance_against_spin_up_integration(sign, side, air):
    """The mixture spun up in time, I d omega_f/dt = sum of the moments (written out in _torques), from rest and from
    above the cage speed: both reach the balance's steady swirl, both rotation senses."""
    a = _bearing(sign, mass_flow=920.0 * 760e-6 / 60.0 + air)
    bal = churning.mixture_momentum_balance(side_walls=side, **a)
    I = a["rho_e"] * math.pi * (a["r_o"] ** 2 - a["r_i"] ** 2) * a["length"] * a["r_m"] ** 2
    for u0 in (0.0, 1.3 * a["omega_c"] * a["r_m"]):
        sol = solve_ivp(lambda t, y: [_torques(y[0] * a["r_m"], a, side) / I], (0.0, 0.05), [u0 / a["r_m"]],
                        method="LSODA", rtol=1e-10, atol=1e-10)
        u_end = sol.y[0, -1] * a["r_m"]
        assert u_end == pytest.approx(bal["u"], rel=1e-6)
    assert sign * bal["u"] > 0 and 0.0 < bal["k"] < 1.0
    # torque balance of the returned moments
    Ms = [bal[k] for k in ("M_balls", "M_inner", "M_outer", "M_side", "M_flow")]
    assert abs(sum(Ms)) < 1e-9 * max(abs(x) for x in Ms)


@pytest.mark.parametrize("sign", [1.0, -1.0])
@pytest.mark.parametrize("side", [False, True])
def test_balance_power_balance(sign, side):
    """What the balls and the ring surfaces give the mixture = wake + wall layers + pick-up mixing + outflow kinetic
    energy (the torque balance times omega_f, term by term)."""
    bal = churning.mixture_momentum_balance(side_walls=side, **_bearing(sign))
    given = bal["P_balls"] + bal["P_inner"] + bal["P_outer"]
    spent = bal["P_wake"] + bal["P_walls"] + bal["P_outflow_ke"] + bal["P_mixing"]
    assert given == pytest.approx(spent, rel=1e-9)
    assert min(bal["P_balls"], bal["P_wake"], bal["P_walls"], bal["P_inner"]) > 0.0 and bal["P_outer"] == 0.0


@pytest.mark.parametrize("w_i,w_o", [(1.0, 0.0), (-1.0, 0.0), (0.0, 1.0), (2.0, -1.0)])
@pytest.mark.parametrize("radii", ["raceways", "lands"])
def test_balance_laminar_limit_is_couette(w_i, w_o, radii):
    """No balls, no throughflow, no side walls, laminar: the swirl at r_m is the circular Couette flow's (finite
    differences), and with the walls at the raceway contact radii the co-rotation is k_C of couette_corotation_fraction."""
    gam, r_m = 0.14, 0.02325
    r_i, r_o = (r_m * (1 - gam), r_m * (1 + gam)) if radii == "raceways" else (0.02045, 0.0256)
    w_c = 0.5 * (w_i * (1 - gam) + w_o * (1 + gam))
    bal = churning.mixture_momentum_balance(Z=16, D=7.14e-3, r_m=r_m, r_i=r_i, r_o=r_o, length=0.013, omega_i=w_i,
                                            omega_o=w_o, omega_c=w_c, rho_e=1.0, mu_e=1.0,
                                            drag_coefficient=lambda w: 0.47, mass_flow=0.0, balls=False)
    r, w = _couette_fd(w_i, w_o, r_i, r_o)
    assert bal["omega_f"] == pytest.approx(np.interp(r_m, r, w), rel=1e-6, abs=1e-9)
    if radii == "raceways":
        assert bal["k"] == pytest.approx(churning.couette_corotation_fraction(gam, w_i, w_o), rel=1e-9)
    # the wall dissipation is the viscous dissipation of the profile, int mu (r d omega/dr)^2 2 pi r L dr
    rh = 0.5 * (r[1:] + r[:-1])
    diss = float(np.sum(1.0 * (rh * np.diff(w) / (r[1] - r[0])) ** 2 * 2 * math.pi * rh * 0.013) * (r[1] - r[0]))
    assert bal["P_walls"] == pytest.approx(diss, rel=1e-5)


def test_balance_throughflow_dominates_stationary_walls():
    """Both rings at rest, balls orbiting: the throughflow holds the mixture back, k -> 0 as it grows; without
    balls nothing drives the mixture (k = 0 exactly)."""
    a = _bearing(omega_i=0.0)
    ks = [churning.mixture_momentum_balance(**{**a, "mass_flow": m}) for m in (0.01, 1.0, 100.0, 1e4)]
    k = [b["k"] for b in ks]
    assert all(x > y for x, y in zip(k, k[1:])) and k[-1] < 1e-2
    assert churning.mixture_momentum_balance(**{**a, "balls": False})["u"] == 0.0
    assert churning.mixture_momentum_balance(**{**a, "omega_c": 0.0, "balls": False})["u"] == 0.0
    with pytest.raises(ValueError):
        churning.mixture_momentum_balance(**{**a, "mass_flow": -1.0})
    with pytest.raises(ValueError):
        churning.mixture_momentum_balance(**{**a, "r_i": 0.03})


# ---- the wall layers of a turbulent gap against our own mixing-length solution --------------------------------------

def _mixing_length_gap(d_omega, r1, r2, L, rho, mu, n=8001):
    """Turbulent circular Couette flow across r1 .. r2 from a mixing-length model, our own solution: the moment
    G = 2 pi r^2 L tau is the same at every radius (steady, axisymmetric); at each radius the shear rate S = r d omega/dr
    follows from tau = (mu + rho l^2 |S|) |S| (solved exactly), l = Nikuradse's distribution over the half gap h,
    h (0.14 - 0.08 (1 - y/h)^2 - 0.06 (1 - y/h)^4), with van Driest's damping 1 - exp(-y u_tau / (26 nu)) of the
    nearer wall, y the distance to it; omega(r) by trapezoidal quadrature of S / r; G by root finding so that the
    walls differ by d_omega > 0.  Returns G, r and omega(r) - omega(r1)."""
    from scipy.optimize import brentq

    nu, h = mu / rho, 0.5 * (r2 - r1)
    r = np.linspace(r1, r2, n)
    y = np.minimum(r - r1, r2 - r)
    inner = (r - r1) <= (r2 - r)
    l_nik = h * (0.14 - 0.08 * (1 - y / h) ** 2 - 0.06 * (1 - y / h) ** 4)

    def omega(G):
        tau = G / (2 * math.pi * r * r * L)
        u_tau = np.where(inner, math.sqrt(G / (2 * math.pi * r1 * r1 * L * rho)), math.sqrt(G / (2 * math.pi * r2 * r2 * L * rho)))
        l = l_nik * (1 - np.exp(-y * u_tau / (26.0 * nu)))
        S = 2 * tau / (mu + np.sqrt(mu * mu + 4 * rho * l * l * tau))
        f = S / r
        return -np.concatenate([[0.0], np.cumsum(0.5 * (f[1:] + f[:-1]) * np.diff(r))])

    g_lam = 4 * math.pi * mu * L * r1**2 * r2**2 * d_omega / (r2**2 - r1**2)
    G = brentq(lambda G: -omega(G)[-1] - d_omega, g_lam, 1e4 * g_lam, rtol=1e-12)
    return G, r, omega(G)


@pytest.mark.parametrize("ratio", [1.01, 1.05, 1.25, 1.5])
@pytest.mark.parametrize("Re", [2e4, 1e5, 1e6])
@pytest.mark.parametrize("w_i,w_o", [(1.0, 0.0), (-1.0, 0.0), (0.0, 1.0), (0.5, -0.5)])
def test_wall_layers_against_mixing_length_gap(ratio, Re, w_i, w_o):
    """A gap with a core between two wall layers, no balls, no throughflow: (1) the two wall moments of the balance
    are equal and reproduce Bilgen & Boulos's full-gap moment (the derivation's identity, 1e-9); (2) the core's
    angular velocity matches our mixing-length solution's at mid gap within 0.05 of the jump (set after a first look:
    the mixing length gives d_in / d_out = (r2/r1)^1.7-1.8 where the wall law's split is (r2/r1)^2.11); (3) the
    mixing-length moment is 0.45..1.05 of the balance's (a plane-shear mixing length has no Taylor vortices, which
    Bilgen & Boulos's measured torques contain: 0.50-0.67 for gaps of 5-50 %, 0.9-1.0 at 1 %).  Gap ratio 1.01 ..
    1.5, Re = d_omega r1 s / nu 2e4 .. 1e6, inner or outer ring turning, both senses."""
    rho, mu, L, r1 = 22.8, 2.2e-5, 0.013, 0.02
    r2 = ratio * r1
    r_m = 0.5 * (r1 + r2)
    dw = Re * mu / (rho * r1 * (r2 - r1))
    W_i, W_o = w_i * dw, w_o * dw
    bal = churning.mixture_momentum_balance(Z=16, D=1e-3, r_m=r_m, r_i=r1, r_o=r2, length=L, omega_i=W_i, omega_o=W_o,
                                            omega_c=1.0, rho_e=rho, mu_e=mu, drag_coefficient=lambda w: 0.47,
                                            mass_flow=0.0, balls=False)
    G_bb = churning.taylor_couette_gap_moment(W_i - W_o, r1, r2, L, rho, mu)
    assert bal["M_inner"] == pytest.approx(G_bb, rel=1e-9) and -bal["M_outer"] == pytest.approx(G_bb, rel=1e-9)
    G_ml, r, om = _mixing_length_gap(abs(W_i - W_o), r1, r2, L, rho, mu)
    om_mid = W_i + math.copysign(1.0, W_i - W_o) * np.interp(r_m, r, om)
    assert abs(bal["omega_f"] - om_mid) < 0.05 * abs(W_i - W_o)
    assert 0.45 < G_ml / abs(G_bb) < 1.05


@pytest.mark.parametrize("d_omega", [1.0, -1.0])
def test_wall_moment_laminar_is_couette_to_the_core(d_omega):
    """Laminar (tiny Re): the wall moment is the exact Couette moment across the wall .. the core radius, either wall,
    and the former half-gap law is kept for comparison; bad radii raise."""
    r_i, r_m, r_o, L = 0.02, 0.021, 0.022, 0.01
    m_in = churning.taylor_couette_wall_moment(d_omega, r_i, r_o, r_m, L, 1.0, 1.0)
    m_out = churning.taylor_couette_wall_moment(d_omega, r_o, r_i, r_m, L, 1.0, 1.0)
    assert m_in == pytest.approx(4 * math.pi * L * r_i**2 * r_m**2 * d_omega / (r_m**2 - r_i**2), rel=1e-12)
    assert m_out == pytest.approx(4 * math.pi * L * r_m**2 * r_o**2 * d_omega / (r_o**2 - r_m**2), rel=1e-12)
    assert churning.taylor_couette_wall_moment(0.0, r_i, r_o, r_m, L, 1.0, 1.0) == 0.0
    for bad in ((r_i, r_i, r_m), (r_i, r_o, 0.03), (-r_i, r_o, r_m)):
        with pytest.raises(ValueError):
            churning.taylor_couette_wall_moment(d_omega, *bad, L, 1.0, 1.0)
    a = _bearing()
    old, new = (churning.mixture_momentum_balance(wall_law=w, **a) for w in ("half_gap", "full_gap"))
    assert abs(new["M_inner"]) > 2.0 * abs(old["M_inner"])  # the full-gap law: ~3.5x the half-gap moment of a layer
    with pytest.raises(ValueError):
        churning.mixture_momentum_balance(wall_law="log", **a)


_CAGE = {"r_bore": 0.02265, "r_outside": 0.0255, "width": 8.25e-3}


@pytest.mark.parametrize("sign", [1.0, -1.0])
@pytest.mark.parametrize("guidance", ["outer_ring", "inner_ring", "ball"])
@pytest.mark.parametrize("side,outer", [(False, False), (True, False), (False, True)])
def test_balance_with_cage_against_spin_up_and_power(sign, guidance, side, outer):
    """The cage's bore, outside surface and side faces in the balance: the mixture spun up in time with the moments
    written out in _torques (rings beside the cage, each ring against the cage over its width, the guided surface
    left out, the side faces by the free-disc law) reaches the balance's swirl from rest and from above the cage speed;
    the returned moments sum to 0; given (balls + ring surfaces + cage) = spent (wake + wall layers + outflow);
    the cage raises k unless it hides the driving inner ring's surface (inner-ring guidance); both senses, each
    guidance."""
    a = _bearing(sign)
    if outer:  # the outer ring turning, the inner ring at rest
        a.update(omega_i=0.0, omega_o=sign * 7540.0, omega_c=0.5 * sign * 7540.0 * 1.14)
    cage = {**_CAGE, "guidance": guidance}
    bal = churning.mixture_momentum_balance(cage=cage, side_walls=side, **a)
    I = a["rho_e"] * math.pi * (a["r_o"] ** 2 - a["r_i"] ** 2) * a["length"] * a["r_m"] ** 2
    for u0 in (0.0, 1.3 * a["omega_c"] * a["r_m"]):
        sol = solve_ivp(lambda t, y: [_torques(y[0] * a["r_m"], a, side, cage) / I], (0.0, 0.05), [u0 / a["r_m"]],
                        method="LSODA", rtol=1e-10, atol=1e-10)
        assert sol.y[0, -1] * a["r_m"] == pytest.approx(bal["u"], rel=1e-6)
    Ms = [bal[k] for k in ("M_balls", "M_inner", "M_outer", "M_cage", "M_side", "M_flow")]
    assert abs(sum(Ms)) < 1e-9 * max(abs(x) for x in Ms)
    given = bal["P_balls"] + bal["P_inner"] + bal["P_outer"] + bal["P_cage"]
    spent = bal["P_wake"] + bal["P_walls"] + bal["P_outflow_ke"] + bal["P_mixing"]
    assert given == pytest.approx(spent, rel=1e-9) and bal["P_cage"] > 0.0 and 0.0 < bal["k"] < 1.3
    if not (side or outer):
        k0 = churning.mixture_momentum_balance(**a)["k"]
        # outer-ring or ball guidance: the cage pulls the core towards its speed; an inner-ring-guided cage's land
        # hides the inner ring's surface under the cage (a film), which takes more drive away than the cage adds
        assert bal["k"] > k0 if guidance != "inner_ring" else bal["k"] < k0


def test_balance_cage_alone_and_bad_cage():
    """Rings at rest, no balls, no throughflow, the cage turning: the core turns between 0 and the cage's speed, in
    the cage's sense; a cage outside the ring walls or with a bad guidance raises."""
    a = _bearing(omega_i=0.0, mass_flow=0.0, balls=False)
    for sign in (1.0, -1.0):
        b = churning.mixture_momentum_balance(**{**a, "omega_c": sign * 3000.0}, cage={**_CAGE, "guidance": "ball"})
        assert 0.0 < b["k"] < 1.0 and sign * b["u"] > 0.0
    for bad in ({**_CAGE, "r_bore": 0.02, "guidance": "ball"}, {**_CAGE, "r_outside": 0.026, "guidance": "ball"},
                {**_CAGE, "guidance": "land"}):
        with pytest.raises(ValueError):
            churning.mixture_momentum_balance(**a, cage=bad)


def _boedewadt():
    """Our own solution of Boedewadt's similarity equations (a fluid rotating as a body over a stationary wall):
    F'' = F^2 - G^2 + H F' + 1, G'' = 2 F G + H G', H' = -2 F; F = G = H = 0 at the wall, F = 0, G = 1 at zeta = 30."""
    def rhs(z, y):
        F, Fp, G, Gp, H = y
        return np.vstack([Fp, F * F - G * G + H * Fp + 1.0, Gp, 2 * F * G + H * Gp, -2 * F])

    z = np.linspace(0.0, 30.0, 3001)
    e = np.exp(-z)
    y0 = np.vstack([-e * np.sin(z), -e * (np.cos(z) - np.sin(z)), 1 - e * np.cos(z), e * (np.cos(z) + np.sin(z)),
                    1.35 * (1 - e)])
    sol = solve_bvp(rhs, lambda a, b: np.array([a[0], a[2], a[4], b[0], b[2] - 1.0]), z, y0, tol=1e-8, max_nodes=100000)
    assert sol.status == 0
    return sol


def test_stationary_wall_laminar_against_boedewadt_solution():
    """Laminar: the wall shear constant is our Boedewadt solution's G'(0) (0.77289; Rogers & Lance's 0.7729, 1e-4),
    F'(0) -0.9420; the moment is the quadrature of the wall shear tau = G'(0) rho nu^1/2 omega^3/2 r over the two faces,
    25.5 % above the free disc's; both senses; the turbulent branch (the free disc's) takes over above Re ~ 1.2e5."""
    sol = _boedewadt()
    G0, F0 = float(sol.y[3, 0]), float(sol.y[1, 0])
    assert G0 == pytest.approx(churning.BOEDEWADT_G0, abs=1e-4) and F0 == pytest.approx(-0.9420, abs=1e-4)
    r1, r2, rho, mu = 0.02, 0.026, 1.2, 1.8e-5
    nu = mu / rho
    for om in (30.0, -30.0):  # Re = omega r2^2 / nu ~ 1.4e3: laminar
        quad_M = 2 * quad(lambda r: G0 * rho * math.sqrt(nu) * abs(om) ** 1.5 * r * 2 * math.pi * r * r, r1, r2)[0]
        M = churning.stationary_wall_moment(om, r1, r2, rho, mu)
        assert M == pytest.approx(-math.copysign(quad_M, om), rel=2e-4)
        free = churning.rotating_annulus_windage_moment(om, r1, r2, rho, mu)
        assert M / free == pytest.approx(0.7729 / 0.6159, rel=1e-3)
    hi = 3.0e5 * nu / r2**2  # Re 3e5: turbulent, the free disc's law
    assert churning.stationary_wall_moment(hi, r1, r2, rho, mu) == churning.rotating_annulus_windage_moment(hi, r1, r2, rho, mu)
    assert churning.stationary_wall_moment(0.0, r1, r2, rho, mu) == 0.0
    with pytest.raises(ValueError):
        churning.stationary_wall_moment(1.0, r2, r1, rho, mu)
