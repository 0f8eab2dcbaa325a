"""Derived geometry (Harris & Kotzalas 5th ed., Vol. 1, Ch. 2): independent identities."""

import math

import pytest

from hsbearing import load_case
from hsbearing.models.geometry import curvature_radii, derive


def test_free_contact_angle_and_clearance_are_inverse():
    c = load_case()
    g = derive(c)
    # H&K Eq. 2.10: cos(alpha0) = 1 - Pd / (2 A), A = (fi + fo - 1) D
    assert g.A == pytest.approx((0.52 + 0.53 - 1) * 9.525e-3)
    assert math.cos(g.alpha0) == pytest.approx(1 - g.Pd / (2 * g.A))
    g2 = derive(load_case("zhang2016", **{"bearing.diametral_clearance": f"{g.Pd * 1e6!r} um"}))
    assert g2.alpha0 == pytest.approx(g.alpha0, rel=1e-12)
    # free end play, H&K Eq. 2.13
    assert g.Pe == pytest.approx(2 * g.A * math.sin(g.alpha0))


def test_masses_and_inertias():
    g = derive(load_case())
    m = 7830 * math.pi * 9.525e-3**3 / 6
    assert g.ball_mass == pytest.approx(m)
    assert g.ball_inertia == pytest.approx(0.4 * m * (9.525e-3 / 2) ** 2)  # solid sphere 2/5 m r^2
    assert 0 < g.cage_mass < 0.02 and g.cage_axial_inertia > 0
    assert g.pocket_clearance == pytest.approx(0.05e-3)
    assert g.guide_clearance == pytest.approx(0.2e-3)


def test_curvature_radii_osculation():
    D, dm = 9.525e-3, 46e-3
    Rxi, Ryi, Rxo, Ryo = curvature_radii(D, dm, 0.0, 0.52, 0.53)
    gamma = D / dm
    # the ball radius combined with the race radius in the rolling plane: 1/Rx = 2/D +/- 2 gamma/(D (1 -/+ gamma))
    assert 1 / Rxi == pytest.approx(2 / D + 2 * gamma / (D * (1 - gamma)))
    assert 1 / Rxo == pytest.approx(2 / D - 2 * gamma / (D * (1 + gamma)))
    assert 1 / Ryi == pytest.approx(2 / D - 1 / (0.52 * D))
    assert 1 / Ryo == pytest.approx(2 / D - 1 / (0.53 * D))
