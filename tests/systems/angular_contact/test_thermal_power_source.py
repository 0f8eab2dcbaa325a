"""``thermal.power_source``: the thermal network is heated by the power loss the user chose, the choice (default
quasistatic) said in the output and kept in the archive (docs/power_loss.md, "Quasi-static, dynamic and SKF")."""

from __future__ import annotations

import numpy as np
import pytest

import hsbearing
from hsbearing.systems.angular_contact.dynamics import simulate
from hsbearing.systems.angular_contact.thermal import heat_by_body, thermal_equilibrium, thermal_lines

#: short dynamic runs keep the test in the default tier (the ball spin settles in ~10 ms; the cage whirl, ~2 W of
#: guide-land loss, needs ~40 ms and is not what is tested here)
# the cage films' film-temperature factor (friction.thermal_films) scales both sources alike; off here, so that the
# heat is the run's own means to rounding
SETS = {"thermal.dynamic_duration": "0.02 s", "thermal.tolerance": 0.05, "friction.thermal_films": "off"}


def test_default_is_quasistatic_and_said_in_the_output():
    case = hsbearing.load_case("zhang2016")
    assert case.thermal.power_source == "quasistatic"
    ds = thermal_equilibrium(case)
    assert ds.attrs["power_source"] == "quasistatic"
    text = "\n".join(thermal_lines(ds))
    assert "power source: quasistatic (thermal.power_source: quasistatic (default) or dynamic)" in text


def test_dynamic_source_heats_the_network_with_the_run_means():
    """At a fixed lubricant temperature the heat of ``power_source = dynamic`` is the mean over the second half of a
    dynamic run (computed here with ``simulate`` directly) and exceeds the quasi-static heat (measured 55.6 vs 45.8 W
    with 20 ms runs); the equilibrium it reaches is hotter than the quasi-static one."""
    case_d = hsbearing.load_case("zhang2016", **SETS, **{"thermal.power_source": "dynamic"})
    case_q = hsbearing.load_case("zhang2016", **SETS)
    src_d, heat_d, _ = heat_by_body(case_d)
    src_q, heat_q, _ = heat_by_body(case_q)
    ds = simulate(case_d, duration=0.02, annotate=False)
    t = ds["time"].values
    late = ds.isel(time=slice(int(np.searchsorted(t, 0.5 * t[-1])), None))
    assert sum(src_d.values()) == pytest.approx(float(late.power_loss.mean()), rel=1e-9)
    assert src_d["race_traction_inner"] + src_d["race_traction_outer"] == pytest.approx(
        float(late.power_loss_race_traction.mean()), rel=1e-9)
    assert sum(heat_d.values()) == pytest.approx(sum(src_d.values()), rel=1e-12)  # every watt goes to a node
    assert sum(src_d.values()) > sum(src_q.values()) + 5.0
    th_d = thermal_equilibrium(case_d)
    th_q = thermal_equilibrium(case_q)
    assert th_d.attrs["status"] == "ok" and th_d.attrs["power_source"] == "dynamic"
    assert float(th_d.heat_generated) > float(th_q.heat_generated)
    assert float(th_d.ball_temperature) > float(th_q.ball_temperature)
    assert "power source: dynamic" in "\n".join(thermal_lines(th_d))
