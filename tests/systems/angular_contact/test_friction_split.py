"""hsbearing friction: both totals split into the SKF terms, the SKF validity warning."""

import math

import numpy as np
import pytest

from hsbearing.case import load_case
from hsbearing.systems.angular_contact import rating


def test_split_sums_to_totals_and_validity():
    case = load_case("zhang2016")
    w = np.array([14000.0, 30000.0]) * math.pi / 30
    ds = rating.friction_angular_contact(case, w)
    ours = sum(ds[f"qs_power_as_skf_{t}"].values for t in ("rolling", "sliding", "drag", "seal"))
    np.testing.assert_allclose(ours, ds.qs_power_loss.values, rtol=1e-12)
    skf = sum(ds[f"skf_power_{t}"].values for t in ("rolling", "sliding", "drag", "seal"))
    np.testing.assert_allclose(skf, ds.skf_total_torque.values * w, rtol=1e-12)
    # every source is in exactly one SKF term
    from hsbearing.systems.angular_contact.balances import SOURCES

    grouped = [s for v in rating.OURS_AS_SKF.values() for s in v]
    assert sorted(grouped) == sorted(tuple(SOURCES) + rating.CAVITY_SOURCES)
    # 30000 r/min x 46 mm = 1.38e6 mm r/min: outside the SKF model's speed range
    assert "SKF 2004 model likely outside its range" in ds.attrs["warnings"] and "speed ratings" in ds.attrs["warnings"]
    assert (ds.cavity_oil_fraction.values == 0.05).all()
    # ball Re in the droplet-laden air: 2.7e5 at 14 000 and 6.2e5 at 30 000 r/min (Re ~ rho_e v D / mu_e; the orbit
    # speed v grows ~6 % faster than n here as the centrifugal load turns the contact angles)
    Re = ds.drag_reynolds_number.values
    assert (1e5 < Re).all() and (Re < 1e6).all() and Re[1] / Re[0] == pytest.approx(30000 / 14000, rel=0.1)


def test_no_speed_warning_at_default():
    case = load_case("zhang2016")
    assert rating.skf_validity_warnings(case, np.array([14000.0])) == []
    assert rating.skf_validity_warnings(case.with_overrides(**{"lubricant.lubrication": "dry"}), np.array([1000.0]))


def test_parker_reaches_the_dynamic_model():
    from hsbearing.models.ball_bearing import drag
    from hsbearing.systems.angular_contact.dynamics import build_model

    case = load_case("zhang2016")
    free = case.with_overrides(**{"lubricant.oil_flow_rate": "1 L/min"})
    # remove the explicit override: Parker's correlation takes over
    raw = free.raw_text_base.replace("oil_volume_fraction = 0.05", "# oil_volume_fraction removed")
    from hsbearing.case import loads_case

    parker = loads_case(raw)
    assert parker.lubricant.oil_volume_fraction is None
    X = drag.parker_cavity_oil_fraction(1e-3 / 60, 14000 * math.pi / 30, 0.046)
    m = build_model(parker)
    assert m.info["cavity_oil_fraction"] == pytest.approx(X, rel=1e-12)
    assert m.info["drag_density"] == pytest.approx(drag.mixture_density(960.0, X))
    r1 = rating.quasi_static_power_loss(case)
    r2 = rating.quasi_static_power_loss(parker)
    # the drag is linear in C_D x mixture density (same state, same orbital speed); C_D follows the Reynolds number
    # of each mixture (the standard drag curve)
    assert r2["drag"] / r1["drag"] == pytest.approx(drag.mixture_density(960.0, X) * r2["drag_coefficient"]
                                                    / (drag.mixture_density(960.0, 0.05) * r1["drag_coefficient"]), rel=1e-6)
    assert r1["drag_coefficient"] != r2["drag_coefficient"]
