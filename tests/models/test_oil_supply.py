"""Oil supply and the cavity oil fraction of the drag: Parker's correlation (NASA TP-2275)."""

import math

import pytest

from hsbearing.case import load_case
from hsbearing.models.ball_bearing import drag


def _parker_by_hand(W_cm3_min, n_rpm, dm_mm):
    # X = 1e5 W^0.37 / (n d_m^1.7), W [cm^3/min], n [r/min], d_m [mm] (Parker 1984, NASA TP-2275, as reproduced)
    return 1e5 * W_cm3_min**0.37 / (n_rpm * dm_mm**1.7)


@pytest.mark.parametrize("W, n, dm", [(1000.0, 14000.0, 46.0), (1500.0, 25000.0, 150.0), (500.0, 72000.0, 48.5),
                                      (4000.0, 10000.0, 150.0)])
def test_parker_against_published_form(W, n, dm):
    flow = W * 1e-6 / 60.0  # cm^3/min -> m^3/s
    w = n * math.pi / 30.0
    assert drag.parker_cavity_oil_fraction(flow, w, dm * 1e-3) == pytest.approx(_parker_by_hand(W, n, dm), rel=1e-12)


def test_parker_hand_values():
    # 1 L/min, 14000 r/min, d_m 46 mm: 1e5 * 1000^0.37 / (14000 * 46^1.7) = 0.13715 (computed by hand: 12.882 / 93 926)
    assert drag.parker_cavity_oil_fraction(1e-3 / 60, 14000 * math.pi / 30, 0.046) == pytest.approx(0.13715, rel=1e-4)


def test_parker_limits():
    assert drag.parker_cavity_oil_fraction(0.0, 1000.0, 0.05) == 0.0  # no flow: air only
    assert drag.parker_cavity_oil_fraction(1e-4, 0.0, 0.05) == 1.0  # oil flowing, shaft at rest: flooded
    assert drag.parker_cavity_oil_fraction(1.0, 1.0, 0.01) == 1.0  # capped
    with pytest.raises(ValueError):
        drag.parker_cavity_oil_fraction(-1.0, 1.0, 0.05)
    # speed exponent -1: doubling the speed halves X
    a = drag.parker_cavity_oil_fraction(1e-5, 1000.0, 0.05)
    assert drag.parker_cavity_oil_fraction(1e-5, 2000.0, 0.05) == pytest.approx(a / 2)


def test_cavity_fraction_precedence():
    f, src = drag.cavity_oil_fraction(0.2, 1e-5, 1000.0, 0.05, "oil_jet")
    assert f == 0.2 and "override" not in src and src == "lubricant.oil_volume_fraction"
    f, src = drag.cavity_oil_fraction(None, 1e-5, 1000.0, 0.05, "oil_jet")
    assert f == pytest.approx(drag.parker_cavity_oil_fraction(1e-5, 1000.0, 0.05)) and "Parker" in src
    f, _ = drag.cavity_oil_fraction(None, 1e-5, 1000.0, 0.05, "oil_air")
    assert f == pytest.approx(drag.parker_cavity_oil_fraction(1e-5, 1000.0, 0.05))
    assert drag.cavity_oil_fraction(None, 0.0, 1000.0, 0.05, "oil_jet")[0] == 0.0
    assert drag.cavity_oil_fraction(None, None, 1000.0, 0.05, "oil_jet")[0] == drag.DEFAULT_OIL_FRACTION
    assert drag.cavity_oil_fraction(None, 1e-5, 1000.0, 0.05, "oil_bath")[0] == drag.DEFAULT_OIL_FRACTION
    assert drag.cavity_oil_fraction(None, 1e-5, 1000.0, 0.05, "dry")[0] == 0.0


def test_case_keys():
    c = load_case("zhang2016")
    assert c.lubricant.oil_flow_rate == pytest.approx(1e-3 / 60)
    assert c.lubricant.oil_volume_fraction == 0.05  # explicit override kept in the bundled case
    c2 = load_case("zhang2016", **{"lubricant.oil_flow_rate": "1.5 L/min"})
    assert c2.lubricant.oil_flow_rate == pytest.approx(1.5e-3 / 60)


def test_reynolds_in_newton_regime():
    # the default case: mixture 0.05 of an ester oil (~3e-3 Pa s) at 130 degC, ball 9.525 mm, orbit ~14 m/s
    rho = drag.mixture_density(960.0, 0.05)
    mu = drag.mixture_viscosity(3e-3, 0.05)
    Re = drag.ball_reynolds_number(rho, 14.0, 9.525e-3, mu)
    # Newton regime (C_D ~ 0.4-0.5) below the smooth sphere's crisis: ~2.6e5 with the droplet-in-air viscosity
    assert 1e3 < Re < drag.RE_SUBCRITICAL_MAX
