"""The thermal, part-filled cage films in the quasi-static power loss (rating._film_corrections).

* the kernel's guide-land and pocket film powers at the quasi-static state are linear in the film viscosity (the
  premise of applying the thermal film as a factor eta_eff / eta_film): rebuilt with eta_film x 0.5, x 2;
* thermal_films = off gives the kernel's films exactly; on gives kernel x eta_eff / eta_film with eta_eff from
  films.thermal_couette_film at the film's speed, clearance and walls; the fill band brackets the value;
* the walls of the film (--thermal) move the film viscosity the right way.
"""

from __future__ import annotations

import math

import pytest

from hsbearing.case import load_case
from hsbearing.models.ball_bearing import films
from hsbearing.models.ball_bearing import kernel_io as kio
from hsbearing.systems.angular_contact import cage_films, rating
from hsbearing.systems.angular_contact.balances import power_variables
from hsbearing.systems.angular_contact.dynamics import build_model
from hsbearing.systems.angular_contact.oil_properties import viscosity_at as _viscosity


@pytest.fixture(scope="module")
def case():
    return load_case("zhang2016").with_overrides(**{"operating.inner_speed": "30000 rpm"})


def _films(m):
    aux, gaux = m.outputs(m.y0)
    pv = power_variables(aux[None], gaux[None])
    return float(pv["power_loss_guide_land"][0]), float(pv["power_loss_pocket_film"][0])


def test_kernel_films_are_linear_in_the_film_viscosity(case):
    m = build_model(case)
    land, pocket = _films(m)
    assert land > 0 and pocket > 0
    eta = kio.get(m.P, "eta_film")
    for f in (0.5, 2.0):
        kio.set_value(m.P, "eta_film", eta * f)
        l2, p2 = _films(m)
        assert l2 == pytest.approx(f * land, rel=1e-9)
        assert p2 == pytest.approx(f * pocket, rel=1e-9)
    kio.set_value(m.P, "eta_film", eta)


def test_off_is_the_kernel_and_on_is_the_thermal_factor(case):
    off = rating.quasi_static_power_loss(case.with_overrides(**{"friction.thermal_films": "off"}))
    on = rating.quasi_static_power_loss(case)
    m = build_model(case)
    land, pocket = _films(m)
    assert off["guide_land"] == land and off["pocket_film"] == pocket
    inp = cage_films.film_inputs(case, m)
    k = cage_films.oil_conductivity(case)
    eta_film = m.info["oil_viscosity"]
    for src, key, iso in (("guide_land", "land", land), ("pocket_film", "pocket", pocket)):
        U, h, Ta, Tb = inp[key]
        r = films.thermal_couette_film(lambda T: _viscosity(case, T), U, h, k, Ta, Tb)
        assert on[src] == pytest.approx(iso * r["eta_eff"] / eta_film, rel=1e-12)
        assert on[src] < iso
        assert on[f"{src}_band_low"] <= on[src] == on[f"{src}_band_high"]
        assert on[f"{src}_band_low"] == pytest.approx(m.info["cavity_oil_fraction"] * on[src], rel=1e-12)
    delta = (on["guide_land"] - land) + (on["pocket_film"] - pocket)
    assert on["power_loss"] == pytest.approx(off["power_loss"] + delta, rel=1e-12)


def test_hotter_walls_thin_the_films(case):
    T0 = case.lubricant.temperature
    cold = rating.quasi_static_power_loss(case)
    hot = rating.quasi_static_power_loss(case, walls={"outer_ring": T0 + 20, "cage": T0 + 20, "balls": T0 + 20})
    assert hot["land_film_wall_temperatures"] == (T0 + 20, T0 + 20)
    assert hot["guide_land"] < cold["guide_land"] and hot["pocket_film"] < cold["pocket_film"]
    assert math.isclose(hot["land_film_speed"], cold["land_film_speed"])


def test_friction_thermal_feeds_the_network_temperatures(tmp_path, capsys):
    """hsbearing friction --thermal: per speed the thermal equilibrium's temperatures reach the contacts (each race's
    contacts at (T_ring + T_ball)/2, films between their walls' nodes); the archive holds the temperatures used."""
    from hsbearing import cli
    from hsbearing.results import open_run
    from hsbearing.systems.angular_contact.thermal import thermal_equilibrium

    out = tmp_path / "f.nc"
    assert cli.main(["friction", "zhang2016", "--speeds", "14000rpm", "--thermal", "-o", str(out)]) == 0
    assert "--thermal: contact inlet temperature" in capsys.readouterr().out
    ds = open_run(out)
    assert "thermal network" in ds.attrs["contact_temperatures"]
    case = load_case("zhang2016")
    th = thermal_equilibrium(case)
    T_lub = float(th.lubricant_temperature)
    T_mean = 0.25 * (float(th.inner_ring_temperature) + float(th.outer_ring_temperature) + 2 * float(th.ball_temperature))
    assert float(ds.contact_inlet_temperature[0]) == pytest.approx(T_mean, rel=1e-12)  # the mean of the two races
    assert float(ds.contact_inlet_temperature[0]) == pytest.approx(T_lub, abs=0.05)  # = the network's, to its tolerance
    assert float(ds.thermal_cage_temperature[0]) == pytest.approx(float(th.cage_temperature), rel=1e-12)
    assert float(ds.land_film_wall_temperature_a[0]) == pytest.approx(float(th.cage_temperature), rel=1e-12)
    assert float(ds.land_film_wall_temperature_b[0]) == pytest.approx(float(th.outer_ring_temperature), rel=1e-12)
    assert float(ds.pocket_film_wall_temperature_a[0]) == pytest.approx(float(th.ball_temperature), rel=1e-12)
    walls = {"inner_ring": float(th.inner_ring_temperature), "outer_ring": float(th.outer_ring_temperature),
             "balls": float(th.ball_temperature), "cage": float(th.cage_temperature)}
    T_races = rating.race_inlet_temperatures(walls["inner_ring"], walls["outer_ring"], walls["balls"])
    r = rating.quasi_static_power_loss(case.with_overrides(**{"lubricant.temperature": f"{T_lub} K"}), walls=walls,
                                       race_temperatures=T_races)
    assert float(ds.qs_power_loss[0]) == pytest.approx(r["power_loss"], rel=1e-9)
    plain = open_run(_plain(tmp_path))
    assert "contact_inlet_temperature" not in plain
    assert plain.attrs["contact_temperatures"].startswith("lubricant.temperature")


def _plain(tmp_path):
    from hsbearing import cli

    p = tmp_path / "plain.nc"
    assert cli.main(["friction", "zhang2016", "--speeds", "14000rpm", "-o", str(p)]) == 0
    return p


def test_friction_thermal_bad_input_exits_2_before_writing(tmp_path, capsys):
    from hsbearing import cli

    out = tmp_path / "x.nc"
    assert cli.main(["friction", "dgbb_6206", "--thermal", "-o", str(out)]) == 2
    assert "--thermal" in capsys.readouterr().err
    assert cli.main(["friction", "zhang2016", "--thermal", "--set", "lubricant.oil_flow_rate=0 L/min", "-o", str(out)]) == 2
    assert "oil_flow_rate" in capsys.readouterr().err
    assert not out.exists()


def test_run_thermal_records_the_temperatures_it_used(monkeypatch, tmp_path):
    """hsbearing run --thermal: the run's attrs say which temperatures the contacts used (the thermal network's)."""
    import xarray as xr

    import hsbearing
    from hsbearing import cli, systems
    from hsbearing.cli import commands

    seen = {}

    def fake_simulate(case, **kw):
        return xr.Dataset(attrs={"status": "ok"})

    def fake_finish(ds, out, args):
        seen["attrs"] = dict(ds.attrs)
        return 0

    monkeypatch.setattr(hsbearing, "simulate", fake_simulate)
    monkeypatch.setattr(systems, "simulate", fake_simulate)  # --thermal: each race's inlet temperature to the model
    monkeypatch.setattr(commands, "_finish_run", fake_finish)
    assert cli.main(["run", "zhang2016", "--thermal", "--duration", "1ms", "-o", str(tmp_path / "r.nc"), "-q",
                     "--no-figure"]) == 0
    a = seen["attrs"]
    assert "thermal network" in a["contact_temperatures"]
    for k in ("thermal_lubricant_temperature", "thermal_inner_ring_temperature", "thermal_outer_ring_temperature",
              "thermal_ball_temperature", "thermal_cage_temperature", "thermal_oil_outlet_temperature",
              "thermal_inner_contact_inlet_temperature", "thermal_outer_contact_inlet_temperature"):
        assert 273.15 < a[k] < 600.0
    T = a["thermal_lubricant_temperature"]
    assert T == pytest.approx(0.25 * (a["thermal_inner_ring_temperature"] + a["thermal_outer_ring_temperature"]
                                      + 2 * a["thermal_ball_temperature"]), abs=0.05)  # fixed point to its tolerance


def test_api_friction_thermal_is_the_engine():
    import hsbearing

    api = hsbearing.friction("zhang2016", speeds="14000 rpm", thermal=True)
    eng = rating.friction_angular_contact(load_case("zhang2016"), "14000 rpm", thermal=True)
    for v in ("qs_power_loss", "contact_inlet_temperature", "thermal_cage_temperature"):
        assert api[v].values == pytest.approx(eng[v].values, rel=1e-12)
