"""Warm starts: the start state taken from a neighbour's final state."""

import numpy as np
import xarray as xr

from hsbearing.case import load_case
from hsbearing.systems.angular_contact.dynamics import build_model
from hsbearing.workflows.warmstart import nearest, warm_state


def test_warm_state_scales_the_rotational_states_with_the_inner_speed():
    slow = load_case("zhang2016", **{"operating.inner_speed": "7000 rpm"})
    fast = load_case("zhang2016")
    m = build_model(fast, initial="nominal")
    ms = build_model(slow, initial="nominal")
    y = ms.y0.copy()
    y[m.layout.cage("phi_c")] = 123.0
    nb = xr.Dataset({"final_state": ("state", y)}, coords={"state": np.array(ms.state_names, dtype=object)},
                    attrs={"case_toml": slow.to_toml()})
    y1 = warm_state(nb, fast, m)
    L = m.layout
    np.testing.assert_allclose(y1[L.ball("thetadot_b")], 2.0 * y[L.ball("thetadot_b")])
    assert y1[L.cage("phidot_c")] == 2.0 * y[L.cage("phidot_c")]
    assert y1[L.cage("phi_c")] == 0.0
    np.testing.assert_array_equal(y1[L.ball("x_b")], y[L.ball("x_b")])  # positions kept


def test_nearest_neighbour_on_the_grid():
    assert nearest([(0, 0), (2, 2), (0, 3)], (1, 2)) == (2, 2)
    assert nearest([], (0, 0)) is None


def test_warm_map_waves_seeds_cold_others_from_their_nearest_seed(tmp_path, monkeypatch):
    """run_map(warm_start=True) in-process with the dynamics replaced: who starts from whom, and the cold sample."""
    from hsbearing.results import standard_attrs
    from hsbearing.workflows import maps, warmstart

    calls = []

    def fake_cold(case, duration=None):
        calls.append(("cold", case.operating.axial_load, case.operating.radial_load))
        return xr.Dataset({"final_state": ("state", np.zeros(3))}, attrs=standard_attrs(case, "ok"))

    def fake_warm(case, nb, duration=None):
        calls.append(("warm", case.operating.axial_load, case.operating.radial_load))
        return xr.Dataset({"final_state": ("state", np.zeros(3))}, attrs=standard_attrs(case, "ok"))

    monkeypatch.setattr("hsbearing.systems.simulate", fake_cold)
    monkeypatch.setattr(warmstart, "simulate_warm", fake_warm)
    ds = maps.run_map("zhang2016", "axial_load=500,1000,1500N", "radial_load=0,100,200N", out_dir=tmp_path,
                      jobs=1, progress=False, figure=False, warm_start=True, cold_sample=2)
    cold = {(a, r) for k, a, r in calls if k == "cold"}
    warm = {(a, r) for k, a, r in calls if k == "warm"}
    assert len(warm) == 9 - 4  # seeds: indices 0 and 2 of each axis
    assert {(500.0, 0.0), (1500.0, 200.0), (500.0, 200.0), (1500.0, 0.0)} <= cold
    assert "2/2" in ds.attrs["warm_start_agreement"] and ds.attrs["warm_start_differences"] == "none"
