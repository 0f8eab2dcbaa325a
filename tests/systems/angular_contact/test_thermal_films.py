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
from hsbearing.systems.angular_contact import rating
from hsbearing.systems.angular_contact.balances import power_variables
from hsbearing.systems.angular_contact.dynamics import build_model
from hsbearing.systems.angular_contact.thermal import _viscosity


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
    inp = rating.film_inputs(case, m)
    k = rating.oil_conductivity(case)
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
