"""Each race's contacts at their own inlet temperature (docs/power_loss.md, "Temperatures at the contacts").

The kernel takes the inner race contacts' inlet oil from the record's ``lubricant``/``traction`` fields and the outer
race's from its ``outer_oil`` fields (kernel_io); ``build_model(case, race_temperatures=(T_i, T_o))`` fills them at
each race's temperature.  Proven here:

* equal temperatures change nothing, bit for bit (every default build has both races at lubricant.temperature; the
  regression archives in tests/regression compare the whole outputs with main's);
* with two temperatures, each race's outputs equal -- exactly -- those of an independent assembly: the default model
  of the case at that race's temperature (one temperature for everything), evaluated at the same state; the other
  race's outputs differ;
* ``hsbearing friction --thermal`` archives both inlet temperatures, their mean and the rule, and uses them.
"""

from __future__ import annotations

import numpy as np
import pytest

from hsbearing.case import load_case
from hsbearing.models.ball_bearing import kernel as K
from hsbearing.models.ball_bearing import kernel_io as kio
from hsbearing.systems.angular_contact import rating
from hsbearing.systems.angular_contact.dynamics import build_model

INNER = [K.AUX_INDEX[c] for c in ("T_roll_i", "T_trans_i", "S_i", "U_i", "F_R_i", "spin_roll_i", "P_trac_i", "P_ehl_i")]
OUTER = [K.AUX_INDEX[c] for c in ("T_roll_o", "T_trans_o", "S_o", "U_o", "F_R_o", "spin_roll_o", "P_trac_o", "P_ehl_o")]
OIL_FIELDS = ("eta_in", "alpha", "beta_T", "T_K", "tau0", "Lambda", "G")


def _at(case, T):
    return case.with_overrides(**{"lubricant.temperature": f"{float(T)!r} K"})


def _states(m):
    """The quasi-static state and a perturbed one (ball speeds and positions moved both ways: slip of both signs)."""
    y = m.y0.copy()
    y1 = y + 1e-6 * np.sin(np.arange(y.size)) * np.maximum(np.abs(y), 1.0)
    return (y, y1)


@pytest.fixture(scope="module", params=["seed", "eyring"])
def case(request):
    """zhang2016 at 40000 r/min with its seed law, or the physical (eyring) model with the inlet-heating factor on
    (every oil-temperature input of the race contact in use: T_K; eta_in, alpha, beta_T, tau0, Lambda, G)."""
    c = load_case("zhang2016").with_overrides(**{"operating.inner_speed": "40000 rpm"})
    if request.param == "eyring":
        c = c.with_overrides(**{"lubricant.traction_law": "eyring", "friction.inlet_heating": "on"})
    return c


def test_equal_race_temperatures_are_bit_identical(case):
    base = build_model(case)
    same = build_model(case, race_temperatures=(case.lubricant.temperature, case.lubricant.temperature))
    for f in OIL_FIELDS:  # the default build: the outer race's fields are the inner race's values
        assert kio.get(base.P, f + "_o") == kio.get(base.P, f)
    assert base.P.tobytes() == same.P.tobytes()
    for y in _states(base):
        a0, g0 = base.outputs(y)
        a1, g1 = same.outputs(y)
        assert np.array_equal(a0, a1) and np.array_equal(g0, g1)
        assert np.array_equal(base.f(y), same.f(y))


@pytest.mark.parametrize("dT_i,dT_o", [(25.0, -15.0), (-20.0, 30.0)])
def test_each_race_equals_the_model_at_its_own_temperature(case, dT_i, dT_o):
    T0 = case.lubricant.temperature
    Ti, To = T0 + dT_i, T0 + dT_o
    m = build_model(case, race_temperatures=(Ti, To))
    mi, mo = build_model(_at(case, Ti)), build_model(_at(case, To))  # independent: one temperature for everything
    for f in OIL_FIELDS:
        assert kio.get(m.P, f) == kio.get(mi.P, f)
        assert kio.get(m.P, f + "_o") == kio.get(mo.P, f)
    loaded = 0
    for y in _states(m):
        a = m.outputs(y)[0]
        ai, ao = mi.outputs(y)[0], mo.outputs(y)[0]
        assert np.array_equal(a[:, INNER], ai[:, INNER])  # inner contacts: the run at T_i
        assert np.array_equal(a[:, OUTER], ao[:, OUTER])  # outer contacts: the run at T_o
        loaded += int(np.count_nonzero(a[:, K.AUX_INDEX["P_trac_i"]]) + np.count_nonzero(a[:, K.AUX_INDEX["P_trac_o"]]))
        # and the temperature matters: the outer contacts of the run at T_i are not those at T_o
        assert not np.allclose(ai[:, OUTER], ao[:, OUTER], rtol=1e-6, atol=0.0)
    assert loaded > 0


def test_race_inlet_temperatures_rule():
    Ti, To = rating.race_inlet_temperatures(400.0, 380.0, 410.0)
    assert (Ti, To) == (405.0, 395.0)
    assert 0.5 * (Ti + To) == pytest.approx((400.0 + 380.0 + 2 * 410.0) / 4, rel=1e-15)


def test_friction_thermal_archives_both_races(tmp_path, capsys):
    from hsbearing import cli
    from hsbearing.results import open_run
    from hsbearing.systems.angular_contact.thermal import thermal_equilibrium

    out = tmp_path / "f.nc"
    assert cli.main(["friction", "zhang2016", "--speeds", "14000rpm", "--thermal", "-o", str(out)]) == 0
    printed = capsys.readouterr().out
    assert "contact inlet temperature inner/outer race" in printed
    ds = open_run(out)
    th = thermal_equilibrium(load_case("zhang2016"))
    Tir, Tor, Tb = float(th.inner_ring_temperature), float(th.outer_ring_temperature), float(th.ball_temperature)
    Ti, To = float(ds.inner_contact_inlet_temperature[0]), float(ds.outer_contact_inlet_temperature[0])
    assert Ti == pytest.approx(0.5 * (Tir + Tb), rel=1e-12)
    assert To == pytest.approx(0.5 * (Tor + Tb), rel=1e-12)
    assert float(ds.contact_inlet_temperature[0]) == pytest.approx(0.5 * (Ti + To), rel=1e-12)
    assert "mean" in ds.contact_inlet_temperature.attrs["long_name"]
    for v in ("inner_contact_inlet_temperature", "outer_contact_inlet_temperature"):
        assert ds[v].attrs["units"] == "K"
    rule = ds.attrs["contact_temperatures"]
    assert "(T_inner_ring + T_balls)/2" in rule and "(T_outer_ring + T_balls)/2" in rule
    # the archive's power is the one of the two race temperatures (not of one common temperature)
    cw = load_case("zhang2016", **{"operating.inner_speed": "14000 rpm"})
    walls = {"inner_ring": Tir, "outer_ring": Tor, "balls": Tb, "cage": float(th.cage_temperature)}
    T_lub = float(th.lubricant_temperature)
    r = rating.quasi_static_power_loss(_at(cw, T_lub), walls=walls, race_temperatures=(Ti, To))
    assert float(ds.qs_power_loss[0]) == pytest.approx(r["power_loss"], rel=1e-9)
    assert float(ds.qs_power_loss_race_traction[0]) == pytest.approx(r["race_traction"], rel=1e-9)


def test_run_thermal_and_its_continuation_run_each_race_at_its_temperature(monkeypatch, tmp_path, capsys):
    """hsbearing run --thermal builds the model with both inlet temperatures, records them, and a --continue of the
    archive builds it with the same two."""
    from hsbearing import cli
    from hsbearing.results import open_run
    from hsbearing.systems.angular_contact import dynamics
    from hsbearing.systems.angular_contact.thermal import thermal_equilibrium

    seen = []
    real = dynamics.build_model

    def spy(case, **kw):
        seen.append(kw.get("race_temperatures"))
        return real(case, **kw)

    th = thermal_equilibrium(load_case("zhang2016"))
    Tb = float(th.ball_temperature)
    want = (0.5 * (float(th.inner_ring_temperature) + Tb), 0.5 * (float(th.outer_ring_temperature) + Tb))
    monkeypatch.setattr(dynamics, "build_model", spy)
    out, out2 = tmp_path / "r.nc", tmp_path / "c.nc"
    assert cli.main(["run", "zhang2016", "--thermal", "--duration", "0.1ms", "-o", str(out), "-q", "--no-figure"]) == 0
    assert "contact inlet temperatures: inner race" in capsys.readouterr().out
    assert seen[-1] == pytest.approx(want, rel=1e-12)  # the run's model (the network's own evaluations come first)
    ds = open_run(out)
    assert (ds.attrs["thermal_inner_contact_inlet_temperature"],
            ds.attrs["thermal_outer_contact_inlet_temperature"]) == pytest.approx(want, rel=1e-12)
    assert "(T_inner_ring + T_balls)/2" in ds.attrs["contact_temperatures"]
    seen.clear()
    assert cli.main(["run", "--continue", str(out), "--duration", "0.1ms", "-o", str(out2), "-q", "--no-figure"]) == 0
    assert seen and seen[-1] == pytest.approx(want, rel=1e-12)


def test_api_simulate_thermal_hands_both_races_and_the_cage_film_factors_to_the_model(monkeypatch):
    import xarray as xr

    import hsbearing
    from hsbearing import systems
    from hsbearing.systems.angular_contact.thermal import thermal_equilibrium

    seen = {}

    def fake(case, **kw):
        seen.update(kw)
        return xr.Dataset(attrs={"status": "ok"})

    monkeypatch.setattr(systems, "simulate", fake)
    ds = hsbearing.simulate("zhang2016", duration="0.1 ms", thermal=True)
    th = thermal_equilibrium(load_case("zhang2016"))
    Tb = float(th.ball_temperature)
    want = (0.5 * (float(th.inner_ring_temperature) + Tb), 0.5 * (float(th.outer_ring_temperature) + Tb))
    assert seen["race_temperatures"] == pytest.approx(want, rel=1e-12)
    assert ds.attrs["thermal_inner_contact_inlet_temperature"] == pytest.approx(want[0], rel=1e-12)
    assert ds.attrs["thermal_outer_contact_inlet_temperature"] == pytest.approx(want[1], rel=1e-12)
    from hsbearing import _thermal_start

    _, _, films = _thermal_start(load_case("zhang2016"))  # the factors friction --thermal applies (kernel films)
    factors = (films["land"]["factor"], films["pocket"]["factor"])
    assert seen["cage_film_factors"] == factors
    assert (ds.attrs["thermal_guide_land_film_factor"], ds.attrs["thermal_pocket_film_factor"]) == factors
    assert "frozen at that state" in ds.attrs["thermal_cage_film_rule"]
