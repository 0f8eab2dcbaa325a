"""``friction_angular_contact`` (the engine of ``hsbearing friction`` and of the API) takes the speeds as users
write them: a unit string, a pint Quantity or SI floats [rad/s], all giving the same answer (it crashed with a
numpy ValueError on "10000 rpm")."""

from __future__ import annotations

import math

import numpy as np
import pytest

import hsbearing
from hsbearing.systems.angular_contact.rating import friction_angular_contact
from hsbearing.units import _ureg


def test_speed_as_unit_string_quantity_or_si_float_gives_one_answer():
    case = hsbearing.load_case("zhang2016")
    si = friction_angular_contact(case, np.array([10000 * math.pi / 30])).qs_power_loss.values
    for speeds in ("10000 rpm", ["10000 rpm"], _ureg().Quantity(10000, "rpm"), 10000 * math.pi / 30):
        got = friction_angular_contact(case, speeds).qs_power_loss.values
        assert got == pytest.approx(si, rel=1e-12), speeds
