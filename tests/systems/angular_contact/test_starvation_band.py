"""The starvation band of the race contacts in the quasi-static power loss (rating._starvation_band): the high end is
today's EHL rolling loss, the low end each contact's kernel power times its own Grubin ratio, the totals fold it in,
and the flooded edge (cavity oil fraction 1) gives back the flooded value."""

import math

import numpy as np
import pytest

from hsbearing.case import load_case
from hsbearing.models.ball_bearing import starvation
from hsbearing.models.ball_bearing.kernel_io import AUX_INDEX
from hsbearing.models.geometry import curvature_radii, derive
from hsbearing.systems.angular_contact import rating
from hsbearing.systems.angular_contact.contact_state import quasi_static_contact_state
from hsbearing.systems.angular_contact.dynamics import build_model


@pytest.fixture(scope="module")
def case():
    return load_case("zhang2016")


def test_band_ends_per_contact(case):
    r = rating.quasi_static_power_loss(case)
    assert r["ehl_rolling_band_high"] == r["ehl_rolling"]
    assert 0.0 < r["ehl_rolling_band_low"] < r["ehl_rolling"]
    assert r["ehl_rolling_band_low_infinite_inlet"] <= r["ehl_rolling_band_low"]
    # independently assembled: each contact's kernel power x its own starvation ratio (b from a and p_max)
    m = build_model(case)
    aux, _ = m.outputs(m.y0)
    qs = m.info["quasistatic"]
    st = quasi_static_contact_state(case, qs)
    g = derive(case)
    X = float(m.info["cavity_oil_fraction"])
    low = 0.0
    for k, (side, col) in enumerate((("inner", "P_ehl_i"), ("outer", "P_ehl_o"))):
        al = qs[f"{side}_contact_angle"].values
        Rx = curvature_radii(g.D, g.dm, al, g.fi, g.fo)[2 * k]
        Q = qs[f"{side}_contact_load"].values
        a, p, hc = st[f"{side}_contact_semimajor"], st[f"{side}_contact_pressure"], st[f"{side}_film_thickness_central"]
        for j in range(g.Z):
            b = 3.0 * Q[j] / (2.0 * math.pi * a[j] * p[j])
            low += aux[j, AUX_INDEX[col]] * starvation.starvation_band(X, hc[j], Rx[j], b)["force"]
    assert r["ehl_rolling_band_low"] == pytest.approx(low, rel=1e-12)
    assert 0.0 < r["inner_starved_film_ratio_low"] < 1.0 and 0.0 < r["outer_starved_film_ratio_low"] < 1.0


def test_flooded_edge_and_totals(case):
    full = case.with_overrides(**{"lubricant.oil_volume_fraction": 1.0})
    r = rating.quasi_static_power_loss(full)
    assert r["ehl_rolling_band_low"] == pytest.approx(r["ehl_rolling"], rel=1e-12)
    assert r["inner_starved_film_ratio_low"] == 1.0 and r["outer_starved_film_ratio_low"] == 1.0
    ds = rating.friction_angular_contact(case, [case.operating.inner_speed])
    for end in ("low", "high"):
        folded = (ds.qs_power_loss - ds.qs_power_loss_drag + ds[f"qs_drag_band_{end}"]
                  - ds.qs_power_loss_guide_land - ds.qs_power_loss_pocket_film - ds.qs_power_loss_ehl_rolling
                  + ds[f"qs_guide_land_band_{end}"] + ds[f"qs_pocket_film_band_{end}"] + ds[f"qs_ehl_rolling_band_{end}"])
        np.testing.assert_allclose(ds[f"qs_total_band_{end}"].values, folded.values, rtol=1e-12)
    np.testing.assert_array_equal(ds.qs_ehl_rolling_band_high.values, ds.qs_power_loss_ehl_rolling.values)
    assert ds.qs_ehl_rolling_band_low.attrs["units"] == "W"


def test_without_bands_the_sources_are_the_same_and_no_band_is_half_built(case):
    """quasi_static_power_loss(bands=False), what a quasi-static sweep point reads: every source and total as with
    the bands, and no ``*_band_*`` key at all (the starvation band is not computed)."""
    full = rating.quasi_static_power_loss(case)
    lean = rating.quasi_static_power_loss(case, bands=False)
    assert not [k for k in lean if "_band_" in k]
    assert any("_band_" in k for k in full)
    for k, v in lean.items():
        assert full[k] == v, k
