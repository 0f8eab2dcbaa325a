"""EHL film thickness: a published worked problem, the radius convention, physical trends."""

import math

import numpy as np
import pytest

from hsbearing.models import ehl, hertz, traction
from hsbearing.models.geometry import curvature_radii


def _stachowiak_problem(distance):
    """Stachowiak & Batchelor, *Engineering Tribology*, Ch. 7 problem: a steel ball (d = 30 mm, E = 210 GPa,
    nu = 0.3, rho = 7800 kg/m^3) rolls without sliding from rest down a 45-degree oiled steel plate
    (eta0 = 50 cP, alpha = 2.2e-8 1/Pa).  Published answer: h_min = 0.059 um after 1 cm, 0.281 um after 1 m."""
    r, E, nu, rho, g = 15e-3, 2.1e11, 0.3, 7800.0, 9.81
    m = rho * 4.0 / 3.0 * math.pi * r**3
    W = m * g * math.cos(math.pi / 4)  # normal load on the plate
    v = math.sqrt(2 * (5.0 / 7.0) * g * math.sin(math.pi / 4) * distance)  # rolling sphere: a = 5/7 g sin(theta)
    Ep = float(hertz.reduced_modulus(E, nu, E, nu))
    # The book's U = (U_A + U_B)/2 with the plate at rest and the ball surface at v: U = v/2.  Its formulae use the
    # reduced radius R' (1/R' = 1/Rx + 1/Ry = 2/r) - our radius="reduced"; k = 1.0339 for the circular contact.
    return ehl.film_thickness(W, v / 2, r, r, Ep, 0.05, 2.2e-8, radius="reduced")


@pytest.mark.parametrize("distance, h_min_published", [(0.01, 0.059e-6), (1.0, 0.281e-6)])
def test_stachowiak_batchelor_worked_problem(distance, h_min_published):
    h_c, h_min = _stachowiak_problem(distance)
    # published answers carry 2-3 significant digits: 1 % tolerance
    assert float(h_min) == pytest.approx(h_min_published, rel=0.01)
    assert 1.5 < float(h_c / h_min) < 2.0  # central film thicker than the minimum (side lobes)


def test_radius_convention_matters_for_a_ball_on_flat_not_for_a_raceway():
    """h ~ R^0.46 at fixed physical inputs: Rx vs R' differ by 28 % on a ball-on-flat (R' = Rx/2), by ~1.4 %
    on the default case's inner raceway (Ry/Rx = 32)."""
    args = dict(Ep=2.3e11, eta0=0.01, alpha=2e-8)
    h_rx = ehl.film_thickness(100.0, 10.0, 5e-3, 5e-3, radius="Rx", **args)[1]
    h_red = ehl.film_thickness(100.0, 10.0, 5e-3, 5e-3, radius="reduced", **args)[1]
    assert float(h_red / h_rx) == pytest.approx(0.5 ** (1 - 0.68 + 2 * 0.073), rel=1e-12)
    Rx, Ry, _, _ = curvature_radii(9.525e-3, 46e-3, math.radians(25.0), 0.52, 0.53)
    h_rx = ehl.film_thickness(500.0, 16.0, Rx, Ry, radius="Rx", **args)[1]
    h_red = ehl.film_thickness(500.0, 16.0, Rx, Ry, radius="reduced", **args)[1]
    assert 0.98 < float(h_red / h_rx) < 0.995


def test_dimensionless_groups_definitions():
    U, G, W = ehl.dimensionless_groups(0.04, 5.0, 2e-8, 2.2e11, 4e-3, 800.0)
    assert U == pytest.approx(0.04 * 5.0 / (2.2e11 * 4e-3))
    assert G == pytest.approx(2e-8 * 2.2e11)
    assert W == pytest.approx(800.0 / (2.2e11 * 16e-6))


def test_exponents_of_speed_load_and_ellipticity():
    base = dict(Q=500.0, u=10.0, Rx=4e-3, Ry=0.1, Ep=2.3e11, eta0=0.01, alpha=2e-8)
    h_c0, h_m0 = ehl.film_thickness(**base)
    h_c1, h_m1 = ehl.film_thickness(**{**base, "u": 20.0})
    assert float(h_c1 / h_c0) == pytest.approx(2**0.67, rel=1e-12)
    assert float(h_m1 / h_m0) == pytest.approx(2**0.68, rel=1e-12)
    h_c2, h_m2 = ehl.film_thickness(**{**base, "Q": 1000.0})
    assert float(h_m2 / h_m0) == pytest.approx(2**-0.073, rel=1e-12)
    # wider contacts (larger k) give thicker films
    h_k = [float(ehl.film_thickness(**base, k=k)[1]) for k in (1.0, 3.0, 8.0)]
    assert h_k[0] < h_k[1] < h_k[2]


def test_vectorised_over_balls():
    Q = np.linspace(100.0, 1000.0, 11)
    h_c, h_min = ehl.film_thickness(Q, 16.0, 3.87e-3, 0.124, 2.29e11, 0.005, 1.3e-8)
    assert h_c.shape == (11,) and np.all(np.diff(h_min) < 0)


def test_hamrock_brewe_ellipticity_close_to_exact():
    """[2]: within 3.5 % of the exact elliptic-integral value for 1 <= Ry/Rx <= 32 (ball/race range)."""
    ratio = np.array([1.0, 2.0, 5.0, 10.0, 20.0, 32.0])
    exact = hertz.ellipticity(hertz.curvature_difference(1.0, ratio))
    np.testing.assert_allclose(ehl.ellipticity_hamrock_brewe(1.0, ratio), exact, rtol=0.035)


def test_viscosity_temperature_law():
    o = traction.OILS["4109"]
    assert ehl.viscosity_at_temperature(o.eta0, o.beta, ehl.REFERENCE_TEMPERATURE) == pytest.approx(o.eta0)
    eta = ehl.viscosity_at_temperature(o.eta0, o.beta, np.array([300.15, 353.15, 403.15, 453.15]))
    assert np.all(np.diff(eta) < 0)
    assert float(eta[2]) == pytest.approx(0.033 * math.exp(-0.0215 * 103.0), rel=1e-12)


def test_thermal_reduction_factor_limits_and_trends():
    assert float(ehl.thermal_reduction_factor(0.0, 1.5e9, 2.3e11)) == pytest.approx(1.0)
    L = np.array([0.01, 0.1, 1.0, 5.0])
    phi = ehl.thermal_reduction_factor(L, 1.5e9, 2.3e11)
    assert np.all(np.diff(phi) < 0) and np.all((phi > 0) & (phi <= 1))
    assert float(ehl.thermal_reduction_factor(1.0, 1.5e9, 2.3e11, slide_roll=0.2)) < float(phi[2])


def test_default_case_inner_contact_film_is_physical():
    """Oil 4109 at 130 degC, Q = 200 N, 14000 r/min: sub-micron film, thermal factor 0.8-1."""
    Rx, Ry, _, _ = curvature_radii(9.525e-3, 46e-3, math.radians(25.0), 0.52, 0.53)
    Ep = float(hertz.reduced_modulus(208e9, 0.3, 208e9, 0.3))
    o = traction.OILS["4109"]
    eta = ehl.viscosity_at_temperature(o.eta0, o.beta, 403.15)
    pc = hertz.point_contact(Rx, Ry, 200.0, 208e9, 0.3, 208e9, 0.3)
    u = 16.27
    h_c, h_min = ehl.film_thickness(200.0, u, Rx, Ry, Ep, eta, o.alpha)
    assert 0.05e-6 < float(h_min) < float(h_c) < 1e-6
    h_cT, _ = ehl.film_thickness(200.0, u, Rx, Ry, Ep, eta, o.alpha, thermal=True, beta=o.beta, K=o.K, p_max=pc.p_max)
    assert 0.8 < float(h_cT / h_c) < 1.0


def test_bad_radius_convention_and_missing_thermal_inputs():
    with pytest.raises(ValueError, match="radius"):
        ehl.film_thickness(1.0, 1.0, 1e-3, 1e-2, 2e11, 0.01, 2e-8, radius="Ry")
    with pytest.raises(ValueError, match="thermal"):
        ehl.film_thickness(1.0, 1.0, 1e-3, 1e-2, 2e11, 0.01, 2e-8, thermal=True)


def test_lubricant_parameters_from_case_and_overrides():
    from hsbearing.case import load_case

    c = load_case("zhang2016", **{"lubricant.viscosity_law": "table1"})  # default "walther": tests/models/test_viscosity.py
    p = ehl.lubricant_parameters(c)
    assert p["eta"] == pytest.approx(0.033 * math.exp(-0.0215 * (130.0 - 27.0)), rel=1e-12)
    assert p["alpha"] == 1.28e-8 and p["T"] == pytest.approx(403.15)
    p = ehl.lubricant_parameters(load_case("zhang2016", **{"lubricant.kinematic_viscosity": "5 mm^2/s"}))
    assert p["eta"] == pytest.approx(5e-6 * 960.0)
    p = ehl.lubricant_parameters(load_case("zhang2016", **{"lubricant.oil": "4050", "lubricant.temperature": "27 degC",
                                                           "lubricant.viscosity_law": "table1"}))
    assert p["eta"] == pytest.approx(0.060) and p["alpha"] == 2.02e-8
