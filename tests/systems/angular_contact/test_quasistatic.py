"""Quasi-static Jones-Harris model: literature values, invariants, cross-checks, CLI.

Tiers (docs/design.md habit 7):
- literature: Harris' closed-form static axial solution; the Sjovall load
  integrals J_r, J_a at epsilon = 0.5 (Harris & Kotzalas Vol. 1 Table 7.1,
  reprinted in NSK Technical Report E728, Sec. 5.1, Table 1); the race-control
  kinematics of Harris & Kotzalas Vol. 1 Ch. 8 (tan beta, cage and ball speed).
- invariants: symmetry, equilibrium recomputed from the output Dataset,
  zero speed == static, stiffness = derivative of the load.
- regression (our own numbers, NOT validation): the 7206-type check of
  docs/validation/quasistatic.md.
"""

from __future__ import annotations

import math
import subprocess
import sys

import numpy as np
import pytest
from scipy.optimize import brentq

from hsbearing.case import CaseError, load_case, loads_case
from hsbearing.errors import SolverError
from hsbearing.models import hertz
from hsbearing.models.ball_bearing import quasistatic as qp
from hsbearing.models.geometry import curvature_radii
from hsbearing.systems.angular_contact import quasistatic as qs

RPM = math.pi / 30.0
DEG = math.pi / 180.0

# the 7206-type bearing of issue 3 (these are also the zhang2016 case values; set explicitly)
B7206 = {
    "bearing.ball_count": "11",
    "bearing.ball_diameter": "9.525 mm",
    "bearing.pitch_diameter": "46 mm",
    "bearing.inner_conformity": "0.52",
    "bearing.outer_conformity": "0.53",
    "bearing.contact_angle": "25 deg",
    "materials.ball.elastic_modulus": "208 GPa",
    "materials.races.elastic_modulus": "208 GPa",
    "materials.ball.poisson_ratio": "0.3",
    "materials.races.poisson_ratio": "0.3",
    "operating.axial_load": "1000 N",
}


@pytest.fixture(scope="module")
def case7206():
    return load_case("zhang2016", **B7206)


@pytest.fixture(scope="module")
def static7206(case7206):
    return qs.solve_case(case7206, inner_speed=0.0)


@pytest.fixture(scope="module")
def fast7206(case7206):
    return qs.solve_case(case7206, inner_speed=14000 * RPM)


def dgbb_case(**over):
    """Deep-groove variant of the zhang2016 bearing (0 deg, 10 um diametral clearance)."""
    ov = {"case.system": "deep_groove", "bearing.contact_angle": "0 deg", "bearing.diametral_clearance": "10 um"}
    ov.update(over)
    return load_case("zhang2016", **ov)


def _K_exact(case, alpha):
    b = case.bearing
    Rxi, Ryi, Rxo, Ryo = curvature_radii(b.ball_diameter, b.pitch_diameter, alpha, b.inner_conformity, b.outer_conformity)
    m = case.materials
    args = (m.ball.elastic_modulus, m.ball.poisson_ratio, m.races.elastic_modulus, m.races.poisson_ratio)
    return hertz.point_contact(Rxi, Ryi, 1.0, *args).K, hertz.point_contact(Rxo, Ryo, 1.0, *args).K


# ----------------------------------------------------------------------------- physics pieces


def test_contact_stiffness_table_matches_exact_hertz(case7206):
    P = qs.build_problem(case7206)
    alpha = np.linspace(0.0, 85.0, 171) * DEG
    Ki, Ko = P.stiffness.K(np.cos(alpha), np.cos(alpha))
    Ki_x, Ko_x = _K_exact(case7206, alpha)
    assert np.max(np.abs(Ki / Ki_x - 1)) < 1e-10
    assert np.max(np.abs(Ko / Ko_x - 1)) < 1e-10


def test_race_control_kinematics_reproduce_harris_formulas():
    """Harris & Kotzalas Vol. 1 Ch. 8: outer raceway control, outer ring fixed.

    tan beta = sin a_o / (cos a_o + g) (Eq. 8.40), and the orbital and ball
    speeds of the same chapter, with g = D / d_m.
    """
    D, dm, wi = 0.01, 0.06, 1000.0
    ai, ao = np.array([0.45, 0.3]), np.array([0.35, 0.3])
    wm, wx, wy = qp.race_control_kinematics(wi, 0.0, 0.5 * dm, D, np.sin(ai), np.cos(ai), np.sin(ao), np.cos(ao))
    g = D / dm
    tb = np.sin(ao) / (np.cos(ao) + g)
    beta = np.arctan(tb)
    co_, ci_ = np.cos(ao) + tb * np.sin(ao), np.cos(ai) + tb * np.sin(ai)
    wm_h = wi * (1 - g * np.cos(ai)) * co_ / ((1 + g * np.cos(ao)) * ci_ + (1 - g * np.cos(ai)) * co_)
    wR_h = -wi / ((co_ / (1 + g * np.cos(ao)) + ci_ / (1 - g * np.cos(ai))) * g * np.cos(beta))
    np.testing.assert_allclose(np.arctan2(-wy, wx) - np.pi * np.sign(np.arctan2(-wy, wx)), beta, rtol=1e-12)
    np.testing.assert_allclose(wm, wm_h, rtol=1e-12)
    np.testing.assert_allclose(-np.hypot(wx, wy), wR_h, rtol=1e-12)
    # equal contact angles: cage speed of Eq. 8.21, omega_m = omega_i (1 - g cos a) / 2
    np.testing.assert_allclose(wm[1], 0.5 * wi * (1 - g * np.cos(0.3)), rtol=1e-12)
    # no spin at the controlling (outer) contact
    si, ri, so, ro = qp.contact_spin_roll(wx, wy, wm, wi, 0.0, np.sin(ai), np.cos(ai), np.sin(ao), np.cos(ao))
    np.testing.assert_allclose(so, 0.0, atol=1e-9 * wi)
    assert np.all(np.abs(si) > 0.01 * wi)


def test_inner_race_control_has_no_inner_spin(case7206):
    c = case7206.with_overrides(**{"simulation.kinematics": "inner_race_control"})
    ds = qs.solve_case(c)
    np.testing.assert_allclose(ds.inner_spin_to_roll.values, 0.0, atol=1e-12)
    assert np.all(np.abs(ds.outer_spin_to_roll.values) > 0.05)
    assert ds.attrs["kinematics"] == "inner_race_control"


# ----------------------------------------------------------------------------- literature


def test_pure_axial_static_matches_closed_form(case7206, static7206):
    """Harris & Kotzalas Vol. 1, Eq. 7.13: Fa = Z K_n (B D)^1.5 sin a (cos a0/cos a - 1)^1.5.

    Solved here independently with the exact Hertz constant (elliptic
    integrals, no interpolation table) by Brent's method.
    """
    b = case7206.bearing
    Z, D, Fa, a0 = b.ball_count, b.ball_diameter, 1000.0, 25 * DEG
    BD = (b.inner_conformity + b.outer_conformity - 1) * D

    def f(a):
        Ki, Ko = _K_exact(case7206, a)
        Kn = (Ki ** (-2 / 3) + Ko ** (-2 / 3)) ** -1.5
        return Z * Kn * (BD * (math.cos(a0) / math.cos(a) - 1)) ** 1.5 * math.sin(a) - Fa

    a = brentq(f, a0 + 1e-9, 60 * DEG, xtol=1e-15)
    Q = Fa / (Z * math.sin(a))
    ds = static7206
    np.testing.assert_allclose(ds.inner_contact_angle.values, a, rtol=0, atol=1e-10)
    np.testing.assert_allclose(ds.outer_contact_angle.values, a, rtol=0, atol=1e-10)
    np.testing.assert_allclose(ds.inner_contact_load.values, Q, rtol=1e-9)
    np.testing.assert_allclose(ds.outer_contact_load.values, Q, rtol=1e-9)
    # axial displacement: A1 = B D cos a0 tan a = B D sin a0 + delta_x
    np.testing.assert_allclose(float(ds.inner_ring_axial_displacement), BD * math.cos(a0) * math.tan(a) - BD * math.sin(a0),
                               rtol=1e-8)


# Rings and cage around a 250 mm pitch circle (the 7206's 30/62 mm rings cannot hold it: refused since
# issue 13, item 7), lands and cage at the 7206's offsets from the pitch circle (inner land d_m - 7.5 mm,
# outer land d_m + 6.4 mm, cage 1.6 mm inside and 6.0 mm outside); a static solution at 0 rpm does not
# depend on them.
RINGS_250 = {"bearing.bore_diameter": "200 mm", "bearing.outside_diameter": "300 mm",
             "bearing.inner_land_diameter": "242.5 mm", "bearing.outer_land_diameter": "256.4 mm",
             "cage.bore_diameter": "248.4 mm", "cage.outside_diameter": "256 mm"}


@pytest.mark.parametrize("kind", ["angular", "deep_groove"])
def test_sjovall_integrals_epsilon_half(kind):
    """Load-zone integrals at epsilon = 0.5 (half the raceway loaded), point contact.

    Harris & Kotzalas Vol. 1 Table 7.1 (Sjovall), reprinted in NSK Technical
    Report E728 Sec. 5.1 Table 1: J_r(0.5) = 0.2288, J_a(0.5) = 0.2782, i.e.
    Q_max = 4.37 F_r / (Z cos a) and F_a = 1.216 F_r tan a.  The table assumes
    many balls, a constant contact angle and no ring tilt: here Z = 60, a very
    light load and fixed tilt.  Tolerance 0.5 % (discrete balls; measured 0.2 %).
    """
    text = load_case("zhang2016").to_toml()
    over = {"bearing.ball_count": "60", "bearing.pitch_diameter": "250 mm", "operating.inner_speed": "0 rpm", **RINGS_250}
    if kind == "angular":
        a0 = 30 * DEG
        Fr = 30.0
        Fa = 1.216 * Fr * math.tan(a0)
        over |= {"bearing.contact_angle": "30 deg", "operating.radial_load": f"{Fr} N", "operating.axial_load": f"{Fa} N"}
    else:
        a0 = 0.0
        Fr = 30.0
        over |= {"case.system": "deep_groove", "bearing.contact_angle": "0 deg",
                 "operating.radial_load": f"{Fr} N", "operating.axial_load": "0 N"}
    case = loads_case(text, **over)
    P = qs.build_problem(case, fixed_tilt=True)
    sol = qs.solve(P)
    ds = qs.to_dataset(sol, case)
    Q = ds.inner_contact_load.values
    Z = 60
    ratio = Q.max() * Z * math.cos(a0) / Fr
    assert ratio == pytest.approx(1 / 0.2288, rel=0.005)  # Table 7.1: 1/J_r(0.5) = 4.37
    # half the raceway loaded: the balls beyond +/-90 deg carry (almost) nothing
    psi = ds.ball_azimuth.values
    back = np.abs(np.cos(psi)) > 0.2
    assert np.all(Q[back & (np.cos(psi) < 0)] < 1e-3 * Q.max())
    assert np.all(Q[back & (np.cos(psi) > 0)] > 0)
    if kind == "angular":
        # total axial reaction = Z J_a Q_max sin a  (Table 7.1: J_a(0.5) = 0.2782)
        Ja = (Q * np.sin(ds.inner_contact_angle.values)).sum() / (Z * Q.max() * math.sin(a0))
        assert Ja == pytest.approx(0.2782, rel=0.005)


def _sjovall(eps):
    """Sjovall load integrals J_r(eps), J_a(eps), point contact (Harris & Kotzalas Vol. 1, Ch. 7).

    J_r = 1/(2 pi) int [1 - (1 - cos psi)/(2 eps)]^1.5 cos psi dpsi, J_a the same without cos psi,
    over the loaded arc -- evaluated here by quadrature (the source of Table 7.1).
    """
    psi = np.linspace(-np.pi, np.pi, 200001)
    f = np.clip(1 - (1 - np.cos(psi)) / (2 * eps), 0, None) ** 1.5
    return np.trapezoid(f * np.cos(psi), psi) / (2 * np.pi), np.trapezoid(f, psi) / (2 * np.pi)


@pytest.mark.parametrize("eps", [0.3, 0.8, 1.0, 2.5, 5.0])
def test_load_zone_follows_sjovall_integrals(eps):
    """Combined radial + axial static load over the whole range of load zones 0.3 <= epsilon <= 5.

    With F_a / (F_r tan a) = J_a/J_r(eps), the model must give Q_max = F_r / (Z J_r cos a), the same
    load zone eps (fitted to the deflection pattern delta(psi) = delta_max [1 - (1 - cos psi)/(2 eps)])
    and F_a = Z J_a Q_max sin a.  60 balls, very light load (constant contact angle), fixed tilt.
    """
    assert _sjovall(0.5)[0] == pytest.approx(0.2288, abs=1e-4)  # the quadrature reproduces Table 7.1
    Jr, Ja = _sjovall(eps)
    a0 = 30 * DEG
    Fr = 3.0
    Fa = Fr * math.tan(a0) * Ja / Jr
    case = loads_case(load_case("zhang2016").to_toml(), **{
        "bearing.ball_count": "60", "bearing.pitch_diameter": "250 mm", "bearing.contact_angle": "30 deg",
        "operating.inner_speed": "0 rpm", "operating.radial_load": f"{Fr} N", "operating.axial_load": f"{Fa} N",
        **RINGS_250})
    ds = qs.to_dataset(qs.solve(qs.build_problem(case, fixed_tilt=True)), case)
    Q = ds.inner_contact_load.values
    d = ds.inner_contact_deflection.values + ds.outer_contact_deflection.values
    psi = ds.ball_azimuth.values
    c0, c1 = np.linalg.lstsq(np.c_[np.ones_like(psi), np.cos(psi)], d, rcond=None)[0]
    assert (c0 + c1) / (2 * c1) == pytest.approx(eps, rel=0.01)
    assert Fr / (60 * Q.max() * math.cos(a0)) == pytest.approx(Jr, rel=0.005)
    assert Fa / (60 * Q.max() * math.sin(a0)) == pytest.approx(Ja, rel=0.005)


# ----------------------------------------------------------------------------- invariants


def test_pure_axial_symmetry_at_speed(fast7206):
    ds = fast7206
    for name in ("inner_contact_load", "outer_contact_load", "inner_contact_angle", "outer_contact_angle",
                 "ball_orbit_speed", "ball_spin_speed", "ball_center_radial", "ball_center_axial"):
        v = ds[name].values
        assert np.ptp(v) <= 1e-9 * np.abs(v).max(), name
    K = ds.stiffness.values
    assert abs(float(ds.inner_ring_radial_displacement_y)) < 1e-12
    assert abs(float(ds.inner_ring_tilt_z)) < 1e-10
    assert K[1, 1] == pytest.approx(K[2, 2], rel=1e-6)
    # inner-ring axial equilibrium: the Z inner contacts carry F_a = 1000 N (B7206)
    Fa = 1000.0
    Qi, ai = ds.inner_contact_load.values, ds.inner_contact_angle.values
    assert (Qi * np.sin(ai)).sum() == pytest.approx(Fa, rel=1e-8)


def test_high_speed_trends(static7206, fast7206):
    s, f = static7206, fast7206
    a_static = float(s.inner_contact_angle[0])
    assert float(f.inner_contact_angle[0]) > a_static + 1 * DEG
    assert float(f.outer_contact_angle[0]) < a_static - 1 * DEG
    assert np.all(f.outer_contact_load.values > f.inner_contact_load.values)
    assert np.all(f.ball_centrifugal_force.values > 0)
    # cage speed between the epicyclic values of the two contact angles
    g = 9.525 / 46
    wi = 14000 * RPM
    assert 0.5 * wi * (1 - g) < float(f.cage_speed) < 0.5 * wi


def test_equilibrium_recomputed_from_dataset(case7206):
    """Ring and ball force balances rebuilt from the output variables only (outer control: lambda = 0, 2)."""
    c = case7206.with_overrides(**{"operating.radial_load": "800 N", "operating.radial_load_z": "-300 N",
                                   "operating.moment_y": "2 N*m"})
    ds = qs.solve_case(c)
    D = c.bearing.ball_diameter
    Qi, Qo = ds.inner_contact_load.values, ds.outer_contact_load.values
    ai, ao = ds.inner_contact_angle.values, ds.outer_contact_angle.values
    psi = ds.ball_azimuth.values
    Fc, Mg = ds.ball_centrifugal_force.values, ds.ball_gyroscopic_moment.values
    Fo = -2 * Mg / D  # friction force at the outer contact along (cos a_o, -sin a_o)
    ball_ax = Qi * np.sin(ai) - Qo * np.sin(ao) + Fo * np.cos(ao)
    ball_rad = Qi * np.cos(ai) - Qo * np.cos(ao) - Fo * np.sin(ao) + Fc
    scale = 1000.0
    assert np.max(np.abs(ball_ax)) < 1e-8 * scale
    assert np.max(np.abs(ball_rad)) < 1e-8 * scale
    # ring: sum of inner contact forces = applied loads (lambda_i = 0: no friction on the inner ring)
    assert (Qi * np.sin(ai)).sum() == pytest.approx(1000.0, rel=1e-8)
    assert (Qi * np.cos(ai) * np.cos(psi)).sum() == pytest.approx(800.0, rel=1e-8)
    assert (Qi * np.cos(ai) * np.sin(psi)).sum() == pytest.approx(-300.0, rel=1e-8)
    # moment about Y of the inner contact forces; arms of the undisplaced ring (Harris Vol. 2 Eq. 3.23:
    # the normal force passes through the inner groove curvature centre at (x_i0, R_i))
    fi = c.bearing.inner_conformity
    x_i0 = (fi - 0.5) * D * math.sin(25 * DEG)
    R_i = 0.5 * c.bearing.pitch_diameter + (fi - 0.5) * D * math.cos(25 * DEG)
    fx, fz = -Qi * np.sin(ai), -Qi * np.cos(ai) * np.sin(psi)
    My = (R_i * np.sin(psi) * fx - x_i0 * fz).sum()
    assert My == pytest.approx(-2.0, rel=1e-7)
    assert float(ds.residual_norm) < 1e-10
    assert abs(float(ds.inner_ring_tilt_y)) > 0


def test_ball_equations_in_harris_form(case7206, fast7206):
    """Harris & Kotzalas Vol. 2 Eqs. 3.14-3.15 with Harris' signed quantities.

    Harris writes Q_i sin a_i - Q_o sin a_o - (M_g/D)(lambda_i cos a_i - lambda_o cos a_o) = 0 and
    Q_i cos a_i - Q_o cos a_o + (M_g/D)(lambda_i sin a_i - lambda_o sin a_o) + F_c = 0 with
    M_g = J omega_R omega_m sin beta and omega_R < 0 from his Ch. 8 speed ratio (inner ring turning
    forward).  Our M_g = dH/dt . e_t is the same torque with the opposite sign convention.
    """
    ds = fast7206
    D = case7206.bearing.ball_diameter
    m = case7206.materials.ball.density * math.pi * D**3 / 6
    J = 0.1 * m * D**2
    wR = -ds.ball_spin_speed.values  # Harris' omega_R is negative for a forward-turning inner ring
    Mg_h = J * wR * ds.ball_orbit_speed.values * np.sin(ds.ball_pitch_angle.values)
    np.testing.assert_allclose(Mg_h, -ds.ball_gyroscopic_moment.values, rtol=1e-9)
    Qi, Qo = ds.inner_contact_load.values, ds.outer_contact_load.values
    ai, ao = ds.inner_contact_angle.values, ds.outer_contact_angle.values
    li, lo = 0.0, 2.0
    Fc = m * ds.ball_center_radial.values * ds.ball_orbit_speed.values ** 2
    e1 = Qi * np.sin(ai) - Qo * np.sin(ao) - Mg_h / D * (li * np.cos(ai) - lo * np.cos(ao))
    e2 = Qi * np.cos(ai) - Qo * np.cos(ao) + Mg_h / D * (li * np.sin(ai) - lo * np.sin(ao)) + Fc
    assert np.max(np.abs(e1)) < 1e-8 * 1000 and np.max(np.abs(e2)) < 1e-8 * 1000
    # and the gyroscopic moment matters: its friction force is a few N against ~200 N contact loads
    assert 1.0 < np.max(np.abs(2 * Mg_h / D)) < 20.0


def test_monolithic_solve_agrees_with_nested_solver(case7206):
    """Independent numerics: all 5 + 2Z unknowns at once with scipy's hybrid method, from a perturbed start."""
    from scipy.optimize import root

    c = case7206.with_overrides(**{"operating.radial_load": "1500 N", "operating.moment_z": "3 N*m"})
    P = qs.build_problem(c)
    ref = qs.solve(P)
    Z = P.Z
    xs = np.r_[np.full(3, 1e-6), np.full(2, 1e-4), np.full(2 * Z, 1e-6)]

    def F(z):
        u = z * xs
        q, X1, X2 = u[:5], u[5:5 + Z], u[5 + Z:]
        st = qs._ball_state(P, X1, X2, q)
        R = P.loads + qs._ring_contributions(P, st, q).sum(axis=1)
        return np.r_[R[:3] / 1000, R[3:] / 20, st["res"].ravel() / 1000]

    u0 = np.r_[ref.q * 1.02, ref.X1 * (1 + 2e-4), ref.X2 * (1 - 2e-4)]
    sol = root(F, u0 / xs, method="hybr", options={"xtol": 1e-14, "maxfev": 20000})
    u = sol.x * xs
    assert np.max(np.abs(F(sol.x))) < 1e-9
    np.testing.assert_allclose(u[:3], ref.q[:3], rtol=0, atol=1e-12)
    np.testing.assert_allclose(u[3:5], ref.q[3:], rtol=0, atol=1e-10)
    np.testing.assert_allclose(u[5:5 + Z], ref.X1, rtol=0, atol=1e-12)


def test_zero_speed_is_the_static_case(case7206, static7206):
    """Speed 0 and 'centrifugal and gyroscopic off' give the same equilibrium."""
    off = qs.solve_case(case7206, inner_speed=14000 * RPM, centrifugal=False, gyroscopic=False)
    for name in ("inner_contact_load", "outer_contact_load", "inner_contact_angle", "outer_contact_angle",
                 "inner_ring_axial_displacement", "ball_center_axial", "ball_center_radial"):
        np.testing.assert_allclose(off[name].values, static7206[name].values, rtol=1e-13, atol=1e-18)
    # the kinematics are still there
    assert float(off.cage_speed) > 0 and float(static7206.cage_speed) == 0
    # static: the two contacts are collinear with equal loads
    np.testing.assert_allclose(static7206.inner_contact_load.values, static7206.outer_contact_load.values, rtol=1e-13)


def test_stiffness_is_the_load_derivative(case7206):
    """K_xx, K_yy from the implicit-function Jacobian vs finite differences of whole solves."""
    base = qs.build_problem(case7206, inner_speed=0.0)
    s0 = qs.solve(base)
    from dataclasses import replace

    dF = 1.0
    s1 = qs.solve(replace(base, loads=base.loads + np.array([dF, 0, 0, 0, 0])))
    s2 = qs.solve(replace(base, loads=base.loads + np.array([0, dF, 0, 0, 0])), initial=s0)
    Kxx_fd = dF / (s1.q[0] - s0.q[0])
    Kyy_fd = dF / (s2.q[1] - s0.q[1])
    # compliance matrix inverse: the radial push also moves the ring axially / tilts it
    C = np.linalg.inv(s0.stiffness)
    assert 1 / C[0, 0] == pytest.approx(Kxx_fd, rel=2e-3)
    assert 1 / C[1, 1] == pytest.approx(Kyy_fd, rel=2e-3)
    # static contact forces derive from a potential: symmetric stiffness
    K = s0.stiffness
    np.testing.assert_allclose(K, K.T, rtol=0, atol=1e-6 * np.abs(K).max())


def test_dgbb_combined_load_balls_lose_contact():
    case = dgbb_case(**{"operating.axial_load": "200 N", "operating.radial_load": "2000 N"})
    for w in (0.0, 14000 * RPM):
        ds = qs.solve_case(case, inner_speed=w)
        Qi = ds.inner_contact_load.values
        for name in ("inner_contact_load", "outer_contact_load", "inner_contact_angle", "outer_contact_angle",
                     "inner_contact_pressure", "inner_contact_semimajor", "ball_pitch_angle", "inner_spin_to_roll"):
            assert np.all(np.isfinite(ds[name].values)), name
        assert float(ds.residual_norm) < 1e-10
        assert (Qi * np.cos(ds.inner_contact_angle.values) * np.cos(ds.ball_azimuth.values)).sum() == pytest.approx(2000, rel=1e-8)
    # pure radial load on the deep-groove bearing with clearance: less than half the balls loaded
    ds = qs.solve_case(dgbb_case(**{"operating.axial_load": "0 N", "operating.radial_load": "2000 N"}), inner_speed=0.0)
    Qi = ds.inner_contact_load.values
    assert np.sum(Qi > 0) < 6 and np.sum(Qi == 0) >= 5
    np.testing.assert_array_equal(ds.inner_contact_pressure.values[Qi == 0], 0.0)
    assert abs(float(ds.inner_ring_axial_displacement)) < 1e-15  # symmetric: no axial shift, no tilt
    assert abs(float(ds.inner_ring_tilt_z)) < 1e-12
    # Stribeck: Q_max ~ 5 F_r / Z with clearance (4.37 at zero clearance)
    assert 4.37 < Qi.max() * 11 / 2000 < 5.5
    # at speed the unloaded balls ride on the outer race with Q_o = F_c
    ds = qs.solve_case(dgbb_case(**{"operating.axial_load": "0 N", "operating.radial_load": "2000 N"}))
    off = ds.inner_contact_load.values == 0
    assert off.sum() >= 5
    np.testing.assert_allclose(ds.outer_contact_load.values[off], ds.ball_centrifugal_force.values[off], rtol=1e-9)


@pytest.mark.parametrize("seed", [0, 1])
def test_robustness_random_combined_loads(seed):
    """Random feasible 5-DOF load combinations and speeds converge (deep groove and angular contact)."""
    rng = np.random.default_rng(seed)
    dg = {"case.system": "deep_groove", "bearing.contact_angle": "0 deg", "bearing.diametral_clearance": "15 um"}
    for k in range(6):
        kind = "dg" if k % 2 else "ac"
        Fa = float(rng.choice([0.0, 300.0, 2000.0])) if kind == "dg" else float(rng.choice([200.0, 1000.0, 5000.0]))
        Fy, Fz = float(rng.choice([0.0, 10.0, 800.0, 3000.0])), float(rng.choice([0.0, -500.0]))
        My = float(rng.choice([0.0, 0.5, -1.0])) * (1.0 if kind == "dg" else Fa / 1000)
        rpm = float(rng.choice([0.0, 3000.0, 14000.0, 25000.0]))
        case = load_case("zhang2016", **(dg if kind == "dg" else {}), **{
            "operating.axial_load": f"{Fa} N", "operating.radial_load": f"{Fy} N",
            "operating.radial_load_z": f"{Fz} N", "operating.moment_y": f"{My} N*m"})
        ds = qs.solve_case(case, inner_speed=rpm * RPM)
        assert float(ds.residual_norm) < 1e-10, (kind, Fa, Fy, Fz, My, rpm)
        assert np.all(np.isfinite(ds.inner_contact_load.values))


def test_infeasible_load_fails_fast_with_a_hint(case7206):
    """A single angular-contact bearing cannot carry a 3 N m moment with 10 N of axial load."""
    c = case7206.with_overrides(**{"operating.axial_load": "10 N", "operating.moment_y": "-3 N*m",
                                   "operating.radial_load_z": "-200 N"})
    import time

    t = time.perf_counter()
    with pytest.raises(SolverError, match="no equilibrium"):
        qs.solve_case(c)
    assert time.perf_counter() - t < 20.0


def test_unloaded_bearing_at_speed():
    case = load_case("zhang2016", **{"operating.axial_load": "0 N"})
    ds = qs.solve_case(case)
    np.testing.assert_array_equal(ds.inner_contact_load.values, 0.0)
    np.testing.assert_allclose(ds.outer_contact_load.values, ds.ball_centrifugal_force.values, rtol=1e-9)
    assert np.all(ds.ball_centrifugal_force.values > 0)


def test_speed_sweep_continues_and_matches_single_solves(case7206):
    speeds = np.array([0.0, 5000.0, 10000.0, 14000.0]) * RPM
    sw = qs.speed_sweep(case7206, speeds)
    assert sw.sizes["inner_speed"] == 4
    single = qs.solve_case(case7206, inner_speed=speeds[2])
    np.testing.assert_allclose(sw.inner_contact_load.isel(inner_speed=2).values, single.inner_contact_load.values, rtol=1e-9)
    ai = sw.inner_contact_angle.isel(ball=0).values
    ao = sw.outer_contact_angle.isel(ball=0).values
    assert np.all(np.diff(ai) > 0) and np.all(np.diff(ao) < 0)
    # continuation from a Dataset (what the dynamics and sweeps pass) lands on the same state cheaply
    again = qs.solve_case(case7206, inner_speed=speeds[3], initial=sw.isel(inner_speed=2))
    np.testing.assert_allclose(again.inner_contact_load.values, sw.inner_contact_load.isel(inner_speed=3).values, rtol=1e-9)


def test_dataset_names_units_and_netcdf_roundtrip(fast7206, tmp_path):
    from hsbearing.results import open_run, write_netcdf

    ds = fast7206
    for name in ("inner_contact_load", "outer_contact_load", "inner_contact_angle", "outer_contact_angle",
                 "ball_orbit_speed", "ball_spin_speed", "inner_film_thickness_central", "outer_film_thickness_central",
                 "inner_contact_semimajor", "outer_contact_semiminor", "ball_angular_velocity_x"):
        assert ds[name].dims == ("ball",), name
        assert ds[name].attrs["units"]
    for name in ("cage_speed", "inner_ring_axial_displacement", "inner_ring_tilt_y", "residual_norm"):
        assert ds[name].dims == ()
    assert ds.stiffness.dims == ("dof", "dof2") and list(ds.dof.values) == list(qs.DOF_LABELS)
    assert ds.attrs["status"] == "ok" and "case_toml" in ds.attrs
    h = ds.inner_film_thickness_central.values
    assert np.all((h > 20e-9) & (h < 2e-6))  # EHL films of an oil-jet aero bearing: tens to hundreds of nm
    # absolute angular velocity = orbital + relative: x component of the ball equals omega_m + omega_x(rel)
    assert np.all(ds.ball_angular_velocity_x.values < 0)
    p = write_netcdf(ds, tmp_path / "qs.nc")
    back = open_run(p)
    np.testing.assert_allclose(back.inner_contact_load.values, ds.inner_contact_load.values)
    # a Dataset read back continues a solve
    case = load_case("zhang2016")
    again = qs.solve_case(case, initial=back)
    np.testing.assert_allclose(again.outer_contact_load.values, ds.outer_contact_load.values, rtol=1e-9)


def test_friction_kinematics_uses_jones_criterion_per_ball():
    """kinematics = "friction": Jones' raceway-control criterion chooses the controlling race of each ball.

    Static, equal loads: the inner contact (larger a) controls; at 14000 r/min the heavier outer contact
    controls; under a combined load the pattern is mixed and self-consistent.
    """
    c = load_case("zhang2016", **{"simulation.kinematics": "friction"})
    s = qs.solve_case(c, inner_speed=0.0)
    assert np.all(s.ball_outer_race_control.values == 0)
    f = qs.solve_case(c)
    assert np.all(f.ball_outer_race_control.values == 1)
    ref = qs.solve_case(load_case("zhang2016"))  # outer control everywhere -> the same solution
    np.testing.assert_allclose(f.inner_contact_load.values, ref.inner_contact_load.values, rtol=1e-9)
    m = qs.solve_case(c.with_overrides(**{"simulation.kinematics": "friction", "operating.radial_load": "2000 N"}))
    ctrl = m.ball_outer_race_control.values
    assert 0 < ctrl.sum() < ctrl.size
    np.testing.assert_array_equal(ctrl, m.ball_jones_outer_control.values)
    assert m.attrs["solver_race_control_converged"] == 1
    # zero spin at each ball's controlling contact
    sr = np.where(ctrl == 1, m.outer_spin_to_roll.values, m.inner_spin_to_roll.values)
    np.testing.assert_allclose(sr, 0.0, atol=1e-12)


def test_bad_input_is_a_case_error():
    with pytest.raises(CaseError, match="simulation.kinematics"):
        load_case("zhang2016", **{"simulation.kinematics": "rolling"})
    with pytest.raises(CaseError, match="case.system"):
        qs.solve_case(load_case("shan2010_wire_race"))


@pytest.mark.parametrize("name", ["dgbb_6206", "dgbb_6207", "dgbb_6208", "jiang2014_gyro"])
def test_bundled_cases_solve(name):
    """Every bundled rolling-bearing case gives a converged, finite equilibrium (outer-ring rotation included)."""
    case = load_case(name)  # a bundled case that does not load is a failure, never a skip
    ds = qs.solve_case(case)
    assert float(ds.residual_norm) < 1e-10
    assert np.all(np.isfinite(ds.inner_contact_load.values)) and ds.inner_contact_load.values.max() > 0
    if case.operating.outer_speed and not case.operating.inner_speed:
        assert float(ds.cage_speed) * case.operating.outer_speed > 0  # the cage follows the turning ring


def test_non_convergence_raises_solver_error_with_partial(case7206, monkeypatch):
    P = qs.build_problem(case7206)
    with pytest.raises(SolverError, match="residual") as exc:
        qs.solve(P, tol=1e-40)  # unattainable
    assert exc.value.partial is not None and exc.value.partial.attrs["status"] == "failed"


# ----------------------------------------------------------------------------- regression (our numbers)


def test_7206_regression_numbers(static7206, fast7206):
    """REGRESSION, not validation: the numbers recorded in docs/validation/quasistatic.md."""
    s, f = static7206, fast7206
    assert float(s.inner_contact_angle[0]) / DEG == pytest.approx(26.874, abs=5e-4)
    assert float(s.inner_contact_load[0]) == pytest.approx(201.110, abs=5e-3)
    assert float(s.inner_ring_axial_displacement) * 1e6 == pytest.approx(17.4635, abs=5e-4)
    assert float(f.inner_contact_angle[0]) / DEG == pytest.approx(29.970, abs=5e-3)
    assert float(f.outer_contact_angle[0]) / DEG == pytest.approx(24.539, abs=5e-3)
    assert float(f.inner_contact_load[0]) == pytest.approx(181.981, abs=5e-3)
    assert float(f.outer_contact_load[0]) == pytest.approx(208.116, abs=5e-3)
    assert float(f.cage_speed) / RPM == pytest.approx(5757.54, abs=0.05)


# ----------------------------------------------------------------------------- CLI


def _cli(*args, cwd=None):
    return subprocess.run([sys.executable, "-m", "hsbearing.cli", *args], capture_output=True, text=True, cwd=cwd)


def test_cli_quasistatic_7206_overrides(tmp_path):
    out = tmp_path / "qs.nc"
    sets = []
    for k, v in B7206.items():
        sets += ["--set", f"{k}={v}"]
    r = _cli("quasistatic", "zhang2016", *sets, "--set", "operating.inner_speed=14000 rpm", "-o", str(out))
    assert r.returncode == 0, r.stderr
    assert "status: ok" in r.stdout and "29.970" in r.stdout
    assert out.exists()
    r = _cli("quasistatic", "zhang2016", "--set", "operating.axial_lod=1 kN", "-o", str(tmp_path / "bad.nc"))
    assert r.returncode == 2 and "axial_lod" in r.stderr and len(r.stderr.strip().splitlines()) == 1
    assert not (tmp_path / "bad.nc").exists()


def test_cli_numerical_failure_exit_1(monkeypatch, capsys):
    from hsbearing import cli

    def boom(case, **kw):
        raise SolverError("quasi-static equilibrium did not converge: ring residual max|R|/F = 1e-3")

    monkeypatch.setattr(qs, "solve_case", boom)
    assert cli.main(["quasistatic", "zhang2016"]) == 1
    assert "residual" in capsys.readouterr().err


def test_contract_names_and_common_solver_attrs():
    """docs/design.md: the quasi-static dataset carries the dynamic names without `time` (incl. cage_slip_ratio) and
    the common solver_* statistics (review finding 4)."""
    import hsbearing

    ds = hsbearing.quasi_static("zhang2016")
    assert ds["cage_slip_ratio"].dims == () and abs(float(ds.cage_slip_ratio)) < 0.05
    for k in ("solver_steps", "solver_rhs_evals", "solver_jac_evals", "solver_wall_time"):
        assert k in ds.attrs
    assert math.isnan(float(hsbearing.quasi_static("zhang2016", inner_speed=0.0).cage_slip_ratio))


# ----------------------------------------------------------------------------- issue 16 item 5: independent codes


def test_race_control_closed_forms_both_races():
    """Cage speed and pitch angle of both race controls against closed forms derived independently.

    Rolling at both contact centres with omega_rel = W (cos b, -sin b) gives
    omega_m / omega_i = (1 - g c_i) cos(a_o - b) / [(1 + g c_o) cos(a_i - b) + (1 - g c_i) cos(a_o - b)]
    (g = D/d_m, ball centre on the pitch circle); with Harris & Kotzalas Vol. 1 Ch. 8
    tan b = sin a_o / (cos a_o + g) (outer control) this is (1 - g cos a_i) / (1 + cos(a_i - a_o)),
    with tan b = sin a_i / (cos a_i - g) (inner control) (cos(a_i - a_o) - g cos a_o) / (1 + cos(a_i - a_o))
    (derivation: docs/quasistatic.md, "Comparison with independent codes").  The solver solves a
    3x3 linear system instead; both races, angles 5-50 deg, the whole range of D/d_m in use.
    """
    rng = np.random.default_rng(16)
    n = 200
    ai, ao = rng.uniform(5, 50, n) * DEG, rng.uniform(5, 50, n) * DEG
    D, dm, wi = 0.01, rng.uniform(0.025, 0.2, n), 1500.0
    g = D / dm
    si, ci, so, co = np.sin(ai), np.cos(ai), np.sin(ao), np.cos(ao)
    cd = np.cos(ai - ao)
    for control, wm_ref, tb_ref in [
        ("outer_race_control", wi * (1 - g * ci) / (1 + cd), so / (co + g)),
        ("inner_race_control", wi * (cd - g * co) / (1 + cd), si / (ci - g)),
    ]:
        wm, wx, wy = qp.race_control_kinematics(wi, 0.0, 0.5 * dm, D, si, ci, so, co, control)
        np.testing.assert_allclose(wm, wm_ref, rtol=1e-12)
        np.testing.assert_allclose(-wy / wx, tb_ref, rtol=1e-11)


def _variant(case, control, split=None, gyro=True, speed=14000 * RPM):
    from dataclasses import replace

    P = replace(qs.build_problem(case, inner_speed=speed, control=control, gyroscopic=gyro), gyro_split=split)
    sol = qs.solve(P)
    st = sol.state
    return (math.degrees(math.atan2(st["si"][0], st["ci"][0])), math.degrees(math.atan2(st["so"][0], st["co"][0])),
            float(st["wm"][0]), sol)


def test_independent_codes_difference_is_the_controlling_race(case7206):
    """Issue 16 item 5: which assumption moves the 14000 r/min solution as the two independent codes do.

    The codes' values are quoted in issue 16 only as differences to ours: inner contact angle "about 1 deg
    lower", outer "about 0.6 deg higher", cage speed "about 1.3 % lower" (static solutions equal to 0.01 deg).
    Varying one assumption at a time (tools/investigations/qs_code_comparison.py, table in docs/quasistatic.md):
    the lambda split under outer control, dropping the gyroscopic moment or reversing its sign move the
    angles but never the cage speed by more than 0.6 %; only inner-race-control kinematics lowers the cage
    speed by 1.0-1.4 %, and inner control with Harris' lambda_i = lambda_o = 1 reproduces all three
    differences.  Loose tolerances: the issue's numbers are rounded ("about").
    """
    ai0, ao0, wm0, _ = _variant(case7206, "outer_race_control")
    outer_variants = [_variant(case7206, "outer_race_control", split=(1.0, 1.0)),
                      _variant(case7206, "outer_race_control", gyro=False),
                      _variant(case7206, "outer_race_control", split=(0.0, -2.0))]  # sign of M_g reversed
    for ai, ao, wm, _ in outer_variants:
        assert abs(wm / wm0 - 1) < 0.006  # outer kinematics cannot give the codes' -1.3 %
    ai, ao, wm, sol = _variant(case7206, "inner_race_control")
    assert abs((ai - ai0) - (-1.0)) < 0.2  # issue 16: about 1 deg lower
    assert abs((ao - ao0) - 0.6) < 0.15  # about 0.6 deg higher
    assert abs(100 * (wm / wm0 - 1) - (-1.3)) < 0.15  # about 1.3 % lower
    # REGRESSION (our own numbers, docs/quasistatic.md table rows A, B, C, D, G)
    # (degrees, degrees, rad/s; tolerance 5e-4 deg / 5e-3 rad/s as test_7206_regression_numbers)
    tol = [5e-4, 5e-4, 5e-3]
    np.testing.assert_array_less(np.abs(np.subtract([ai0, ao0, wm0], [29.9703, 24.5385, 602.9279])), tol)
    np.testing.assert_array_less(np.abs(np.subtract([ai, ao, wm], [29.1069, 25.1860, 594.6810])), tol)
    for v, ref in zip(outer_variants, [[29.1404, 25.1924, 601.1953], [29.1169, 25.2600, 601.1319],
                                       [28.2525, 25.9566, 599.5843]]):
        np.testing.assert_array_less(np.abs(np.subtract(v[:3], ref)), tol)


def _jones_ratio(sol, method):
    P, st = sol.problem, sol.state
    Rxi, Ryi, Rxo, Ryo = qs._contact_radii(P, st)
    hi = hertz.point_contact(Rxi, Ryi, st["Qi"], P.E1, P.nu1, P.E2, P.nu2, method=method)
    ho = hertz.point_contact(Rxo, Ryo, st["Qo"], P.E1, P.nu1, P.E2, P.nu2, method=method)
    return float(qp.race_control_ratio(st["Qi"], hi.a, hi.second_kind, st["Qo"], ho.a, ho.second_kind,
                                       np.arctan2(st["si"], st["ci"]), np.arctan2(st["so"], st["co"]))[0])


def test_jones_criterion_switches_near_14000_rpm(case7206):
    """14000 r/min lies just above the speed where Jones' criterion hands control to the outer race.

    With the exact Hertz semi-axis and E(e) the criterion ratio
    Q_o a_o E_o cos(a_i - a_o) / (Q_i a_i E_i) crosses 1 between 13500 and 14000 r/min, on the
    outer- and on the inner-control solution alike (so at 14000 r/min only outer control is
    self-consistent); with the Hamrock-Brewe (1983) approximations of a and E it crosses between
    14000 and 14500 r/min, so a code using them chooses inner control at 14000 r/min.
    """
    r = {}
    for n in (13500, 14000, 14500):
        for control in ("outer_race_control", "inner_race_control"):
            sol = _variant(case7206, control, speed=n * RPM)[3]
            r[n, control] = (_jones_ratio(sol, "exact"), _jones_ratio(sol, "hamrock_brewe"))
    for control in ("outer_race_control", "inner_race_control"):
        assert r[13500, control][0] < 1.0 < r[14000, control][0]
        assert r[14000, control][1] < 1.0 < r[14500, control][1]
        assert abs(r[14000, control][0] - 1.0) < 0.01  # a marginal case: 0.4-0.5 % from the switch
    # the Dataset reports the same margin and the criterion flag follows it
    ds = qs.solve_case(case7206, inner_speed=14000 * RPM)
    np.testing.assert_allclose(ds.ball_race_control_ratio.values, r[14000, "outer_race_control"][0], rtol=1e-9)
    assert np.all(ds.ball_jones_outer_control.values == 1)
