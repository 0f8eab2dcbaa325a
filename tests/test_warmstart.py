"""Warm starts (issue 28, item 2): the start state taken from a neighbour's final state."""

import numpy as np
import xarray as xr

from hsbearing.case import load_case
from hsbearing.dynamics import build_model
from hsbearing.warmstart import nearest, warm_state


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
