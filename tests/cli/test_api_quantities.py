"""The Python API takes what users hold: ``hsbearing.friction``, ``hsbearing.thermal`` and ``hsbearing.life``
(exported, explicit keywords) and the case overrides accept unit strings, pint Quantities or SI floats, all giving
the same case and the same answer; ``friction_angular_contact`` no longer crashes on "10000 rpm"."""

from __future__ import annotations

import math

import numpy as np
import pytest

import hsbearing
from hsbearing.systems.angular_contact.rating import friction_angular_contact
from hsbearing.units import _ureg


@pytest.mark.slow  # long: default tier kept under ~10 min (docs/testing.md)
def test_speed_as_unit_string_quantity_or_si_float_gives_one_answer():
    case = hsbearing.load_case("zhang2016")
    si = friction_angular_contact(case, np.array([10000 * math.pi / 30])).qs_power_loss.values
    for speeds in ("10000 rpm", ["10000 rpm"], _ureg().Quantity(10000, "rpm"), 10000 * math.pi / 30):
        got = friction_angular_contact(case, speeds).qs_power_loss.values
        assert got == pytest.approx(si, rel=1e-12), speeds


def test_overrides_as_unit_strings_quantities_or_si_floats_give_the_same_case():
    u = _ureg()
    a = hsbearing.load_case("zhang2016", inner_speed="10000 rpm", axial_load="2 kN", temperature="100 degC")
    b = hsbearing.load_case("zhang2016", inner_speed=10000 * math.pi / 30, axial_load=2000.0, temperature=373.15)
    c = hsbearing.load_case("zhang2016", inner_speed=u.Quantity(10000, "rpm"), axial_load=u.Quantity(2, "kN"),
                            temperature=u.Quantity(100, "degC"))
    for x in (b, c):
        assert x.operating.inner_speed == pytest.approx(a.operating.inner_speed, rel=1e-12)
        assert x.operating.axial_load == pytest.approx(a.operating.axial_load, rel=1e-12)
        assert x.lubricant.temperature == pytest.approx(a.lubricant.temperature, rel=1e-12)


def test_api_friction_thermal_life_equal_the_engines():
    from hsbearing.systems.angular_contact.rating import life
    from hsbearing.systems.angular_contact.thermal import thermal_equilibrium

    for name in ("friction", "thermal", "life"):
        assert name in hsbearing.__all__ and getattr(hsbearing, name).__doc__
    case = hsbearing.load_case("zhang2016", axial_load="2 kN")
    fr = hsbearing.friction("zhang2016", speeds="10000 rpm", axial_load=2000.0)
    assert fr.qs_power_loss.values == pytest.approx(friction_angular_contact(case, "10000 rpm").qs_power_loss.values,
                                                    rel=1e-12)
    th = hsbearing.thermal("zhang2016", axial_load=_ureg().Quantity(2, "kN"))
    assert float(th.lubricant_temperature) == pytest.approx(float(thermal_equilibrium(case).lubricant_temperature),
                                                           rel=1e-12)
    lf = hsbearing.life("zhang2016", axial_load="2 kN")
    assert float(lf.basic_rating_life) == pytest.approx(float(life(case).basic_rating_life), rel=1e-12)
