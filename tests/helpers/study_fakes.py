"""A synthetic dynamic run for study and sweep tests (the cage centre on a circle whose radius depends on the oil,
a constant cage speed, the classification already set): seconds instead of minutes, and no dependence on the
classifier.  A module of its own so that every test folder (and spawned sweep workers) can import it by name."""

from __future__ import annotations

import math

import numpy as np
import xarray as xr

from hsbearing.results import standard_attrs

FAKE_LABEL = {"4109": "quasi-periodic", "4106": "1 period", "4050": "4 periods"}


def fake_dynamics(case, duration):
    """A synthetic dynamic run: the cage centre on a circle (radius by oil), constant cage speed,
    scalar summaries and the classification already set (so the test does not depend on the classifier)."""
    n = 600
    dur = duration or 0.01
    t = np.linspace(0.0, dur, n)
    wc = 6000.0  # rad/s: ~10 cage revolutions in 10 ms, so the Poincare panels have points
    r = {"4109": 30e-6, "4106": 20e-6, "4050": 10e-6}[case.lubricant.oil]
    Z = case.bearing.ball_count
    q = case.operating.axial_load / (Z * math.sin(case.bearing.contact_angle))
    slip = 0.01 + 1e-5 * (case.lubricant.temperature - 273.15) + 2e-6 * case.operating.axial_load \
        + 1e-7 * case.operating.radial_load + {"4109": 0.0, "4106": 0.002, "4050": 0.004}[case.lubricant.oil]
    ds = xr.Dataset(
        {
            "cage_speed": ("time", np.full(n, wc)),
            "cage_center_y": ("time", r * np.cos(wc * t)),
            "cage_center_z": ("time", r * np.sin(wc * t)),
            "inner_contact_load": (("time", "ball"), np.full((n, Z), q)),
            "outer_contact_load": (("time", "ball"), np.full((n, Z), 1.1 * q)),
            "mean_cage_slip_ratio": ((), slip),
            "whirl_amplitude": ((), r),
        },
        coords={"time": t, "ball": np.arange(Z)},
        attrs=standard_attrs(case, status="ok", classification=FAKE_LABEL[case.lubricant.oil],
                             classification_confidence=0.9),
    )
    return ds
