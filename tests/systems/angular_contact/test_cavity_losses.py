"""hsbearing friction with the churning terms: off reproduces the drag-only numbers, on adds exactly the new sources,
the mixture co-rotation scales the drag as (1 - k)^2 (C_D at the relative Reynolds number)."""

import math
from pathlib import Path

import numpy as np
import pytest
import xarray as xr

from hsbearing.case import load_case
from hsbearing.models.ball_bearing.drag import ball_drag_coefficient
from hsbearing.systems.angular_contact import rating
from hsbearing.systems.angular_contact.balances import SOURCES
from hsbearing.systems.angular_contact.dynamics import build_model

ARCHIVE = "tests/data/regression/zhang2016_friction.nc"


@pytest.fixture(scope="module")
def default_case():
    return load_case("zhang2016")


def test_options_off_reproduce_the_drag_only_numbers(default_case):
    """friction.cavity_losses = off, thermal_films = off and mixture_corotation = 0: every source and the total as
    before the churning terms (the regression archive holds the new default; its kernel sources other than the two
    thermal films are unchanged and equal these; the films: tests/systems/angular_contact/test_thermal_films.py)."""
    off = default_case.with_overrides(**{"friction.cavity_losses": "off", "friction.thermal_films": "off"})
    r = rating.quasi_static_power_loss(off)
    m = build_model(off)
    from hsbearing.systems.angular_contact.balances import power_variables

    aux, gaux = m.outputs(m.y0)
    pv = power_variables(aux[None], gaux[None])
    for s in SOURCES:
        assert r[s] == float(pv[f"power_loss_{s}"][0])
    assert r["power_loss"] == float(pv["power_loss"][0])
    assert r["jet_oil_acceleration"] == 0.0 and r["cage_windage"] == 0.0 and r["drag_mixture_share"] == 0.0
    with xr.open_dataset(ARCHIVE) as ds:
        films = ("guide_land", "pocket_film")
        for s in SOURCES:
            if s not in films:
                assert r[s] == pytest.approx(float(ds[f"qs_power_loss_{s}"].values[0]), rel=1e-12, abs=1e-12)
        extra = float(ds["qs_power_loss_jet_oil_acceleration"].values[0] + ds["qs_power_loss_cage_windage"].values[0])
        extra += sum(float(ds[f"qs_power_loss_{s}"].values[0]) - r[s] for s in films)
        assert r["power_loss"] + extra == pytest.approx(float(ds["qs_power_loss"].values[0]), rel=1e-12)


def test_on_adds_exactly_the_new_sources(default_case):
    r = rating.quasi_static_power_loss(default_case)
    off = rating.quasi_static_power_loss(default_case.with_overrides(**{"friction.cavity_losses": "off"}))
    assert r["power_loss"] == pytest.approx(off["power_loss"] + r["jet_oil_acceleration"] + r["cage_windage"], rel=1e-12)
    m = build_model(default_case)
    v = m.info["drag_orbital_speed"]
    lub = default_case.lubricant
    # independent: m_dot v^2 with the case's flow and density, v = cage speed x d_m / 2 of the quasi-static state
    assert r["jet_oil_acceleration"] == pytest.approx(lub.density * lub.oil_flow_rate * v * v, rel=1e-12)
    assert r["cage_windage"] > 0.0 and r["jet_oil_acceleration"] > 0.0


@pytest.mark.parametrize("k", [0.3, 0.9])
def test_corotation_scales_the_drag(default_case, k):
    r0 = rating.quasi_static_power_loss(default_case)
    rk = rating.quasi_static_power_loss(default_case.with_overrides(**{"friction.mixture_corotation": str(k)}))
    m = build_model(default_case)
    v, rho, mu = (m.info[x] for x in ("drag_orbital_speed", "drag_density", "drag_viscosity"))
    D = default_case.bearing.ball_diameter
    C_k = ball_drag_coefficient(rho, mu, (1 - k) * v, D)[0]
    # kernel drag at k = 0 uses |v| regularised by v0 = 0.01 m/s: relative 1e-8 at these speeds
    assert rk["drag"] == pytest.approx(r0["drag"] * (1 - k) ** 2 * C_k / r0["drag_coefficient"], rel=1e-6)
    assert rk["drag_mixture_share"] == pytest.approx(rk["drag"] * k, rel=1e-12)  # F u / F v = k
    assert rk["cage_windage"] < r0["cage_windage"]
    for s in ("race_traction", "ehl_rolling", "guide_land"):
        assert rk[s] == r0[s]
    if k <= r0["mixture_corotation_couette"]:  # 0.889 here: k = 0.9 lies beyond the band's co-rotation range
        assert r0["drag_band_low"] <= rk["drag"] <= r0["drag_band_high"] * (1 + 1e-12)
    else:
        assert rk["drag"] < r0["drag_band_low"]


def test_reverse_rotation_is_a_loss(default_case):
    neg = default_case.with_overrides(**{"operating.inner_speed": "-14000 rpm", "friction.mixture_corotation": "0.5"})
    r = rating.quasi_static_power_loss(neg)
    assert r["drag"] > 0 and r["jet_oil_acceleration"] > 0 and r["cage_windage"] > 0 and r["drag_mixture_share"] > 0
    assert math.isfinite(r["mixture_corotation_couette"]) and 0.8 < r["mixture_corotation_couette"] < 1.0


def test_friction_dataset_has_units_and_long_names(default_case):
    ds = rating.friction_angular_contact(default_case, np.array([14000.0]) * math.pi / 30)
    for name in ("qs_power_loss_jet_oil_acceleration", "qs_power_loss_cage_windage", "qs_drag_mixture_share",
                 "qs_drag_band_low", "qs_drag_band_high", "mixture_corotation", "mixture_corotation_couette"):
        assert ds[name].attrs.get("units") and ds[name].attrs.get("long_name"), name


@pytest.mark.parametrize("speed", ["14000 rpm", "-14000 rpm"])
def test_balance_option_assembles_the_balance(default_case, speed):
    """friction.mixture_corotation_law = balance: the drag is the balls' drag power at the balance's swirl plus the
    ring surface's power, from mixture_momentum_balance called here with the case's inputs by hand; the jet-oil term
    is inside it (0); the other sources are unchanged; k lies in its band; both rotation senses."""
    from hsbearing.models.ball_bearing import churning

    case = default_case.with_overrides(**{"operating.inner_speed": speed})
    bal_case = case.with_overrides(**{"friction.mixture_corotation_law": "balance"})
    r0, rb = rating.quasi_static_power_loss(case), rating.quasi_static_power_loss(bal_case)
    m = build_model(case)
    v, rho, mu = (m.info[x] for x in ("drag_orbital_speed", "drag_density", "drag_viscosity"))
    b, lub, g = case.bearing, case.lubricant, case.bearing
    r_m = 0.5 * g.pitch_diameter
    by_hand = churning.mixture_momentum_balance(
        Z=b.ball_count, D=b.ball_diameter, r_m=r_m, r_i=0.5 * b.inner_land_diameter, r_o=0.5 * b.outer_land_diameter,
        length=b.width, omega_i=case.operating.inner_speed, omega_o=0.0, omega_c=v / r_m, rho_e=rho, mu_e=mu,
        drag_coefficient=lambda w: ball_drag_coefficient(rho, mu, w, b.ball_diameter)[0],
        mass_flow=lub.density * lub.oil_flow_rate,
        cage={"r_bore": 0.5 * case.cage.bore_diameter, "r_outside": 0.5 * case.cage.outside_diameter,
              "width": case.cage.width, "guidance": case.cage.guidance})
    geo = r0["drag"] / (b.ball_count * churning.ball_drag_power(v, 0.0, b.ball_diameter, rho, r0["drag_coefficient"])[1])
    assert abs(geo - 1.0) < 1e-2
    assert rb["mixture_corotation"] == pytest.approx(by_hand["k"], rel=1e-9) and 0.0 < rb["mixture_corotation"] < 1.0
    assert rb["drag"] == pytest.approx(geo * by_hand["P_balls"] + by_hand["P_inner"], rel=1e-9)
    assert rb["drag_ring_share"] == pytest.approx(by_hand["P_inner"], rel=1e-9)
    assert rb["jet_oil_acceleration"] == 0.0 and rb["drag"] < r0["drag"]
    assert rb["cage_windage"] == pytest.approx(by_hand["P_cage"], rel=1e-9) and by_hand["P_cage"] > 0.0
    assert rb["mixture_balance_cage"] == "cage surfaces in the balance: bore, side faces"
    assert rb["mixture_corotation_balance_low"] <= rb["mixture_corotation"] <= rb["mixture_corotation_balance_high"]
    assert rb["drag_balance_band_low"] <= rb["drag"] * (1 + 1e-12) <= rb["drag_balance_band_high"] * (1 + 1e-12)
    for s in ("race_traction", "ehl_rolling", "guide_land", "pocket_film"):
        assert rb[s] == r0[s]
    assert rb["power_loss"] == pytest.approx(r0["power_loss"] - r0["drag"] - r0["jet_oil_acceleration"] - r0["cage_windage"]
                                             + rb["drag"] + rb["cage_windage"], rel=1e-12)
    # the fixed-k default reports the balance's numbers without using them
    assert r0["mixture_corotation"] == 0.0 and r0["mixture_corotation_balance"] == pytest.approx(by_hand["k"], rel=1e-9)


def test_balance_outputs_in_the_friction_dataset(default_case):
    ds = rating.friction_angular_contact(default_case.with_overrides(**{"friction.mixture_corotation_law": "balance"}),
                                         np.array([14000.0]) * math.pi / 30)
    for name in ("mixture_corotation_balance", "mixture_corotation_balance_low", "mixture_corotation_balance_high",
                 "qs_drag_balance_band_low", "qs_drag_balance_band_high", "qs_drag_ring_share"):
        assert ds[name].attrs.get("units") and ds[name].attrs.get("long_name"), name
    assert float(ds.mixture_corotation[0]) == float(ds.mixture_corotation_balance[0])


def test_bad_corotation_law_exits_2_naming_file_and_key(tmp_path, capsys):
    from hsbearing import cli
    from hsbearing.case import CaseError

    out = tmp_path / "x.nc"
    assert cli.main(["friction", "zhang2016", "--speeds", "14000rpm", "--set", "friction.mixture_corotation_law=dynamic",
                     "-o", str(out)]) == 2
    err = capsys.readouterr().err.strip()
    assert "friction.mixture_corotation_law" in err and len(err.splitlines()) == 1
    assert not out.exists()
    from hsbearing.case.load import case_path

    text = Path(case_path("zhang2016")).read_text()
    assert "[friction]" in text
    bad = tmp_path / "bad.toml"
    bad.write_text(text.replace("[friction]", '[friction]\nmixture_corotation_law = "sometimes"', 1))
    with pytest.raises(CaseError) as e:
        load_case(bad)
    assert "bad.toml" in str(e.value) and "friction.mixture_corotation_law" in str(e.value)


def test_balance_with_a_cage_outside_its_walls_leaves_the_cage_out(default_case):
    """A cage whose bore lies below the inner ring's land (the land raised above it): the balance runs without the
    cage's surfaces (nothing invented), the result says why, and the cage windage is the side-face estimate at (1 - k)
    of the cage speed, as with a fixed k.  (The angular-contact model requires cage.bore_diameter, outside_diameter
    and width, so the missing-key branch of the note cannot be reached from a valid case.)"""
    over = {"friction.mixture_corotation_law": "balance"}
    full = rating.quasi_static_power_loss(default_case.with_overrides(**over))
    r = rating.quasi_static_power_loss(default_case.with_overrides(**over, **{"bearing.inner_land_diameter": "45 mm"}))
    assert r["mixture_balance_cage"] == "cage surfaces left out: the cage does not lie between the ring walls of the balance"
    assert full["mixture_balance_cage"] == "cage surfaces in the balance: bore, side faces"
    assert 0.0 < r["mixture_corotation"] < 1.0 and r["cage_windage"] > 0.0
    assert r["cage_windage"] != full["cage_windage"]
