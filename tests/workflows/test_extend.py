"""``hsbearing run --extend``: an undetermined run is continued until its label is determined or the budget is spent
(hsbearing.systems.angular_contact.extend).  The continuation is a synthetic one here (a whirl whose radius grows
logistically and saturates, re-generated over the longer span and annotated like a real run), so the loop, the
steps and what the archive records are tested without the dynamic model; bad input of the CLI exits 2.
"""

from __future__ import annotations

import json
import math
import subprocess
import sys

import numpy as np
import pytest
import xarray as xr

from hsbearing.analysis import annotate
from hsbearing.systems.angular_contact.extend import MIN_STEP_FRACTION, extend_until_determined, next_step

W = 2 * math.pi * 96.0
DT = 50e-6


def _orbit(t_end, radius):
    t = np.arange(int(round(t_end / DT)) + 1) * DT
    r = radius(t)
    th = 0.97 * W * t
    dr = np.gradient(r, t)
    ds = xr.Dataset({"cage_speed": ("time", np.full_like(t, W)), "cage_angle": ("time", W * t),
                     "cage_center_y": ("time", r * np.cos(th)), "cage_center_z": ("time", r * np.sin(th)),
                     "cage_velocity_y": ("time", dr * np.cos(th) - r * 0.97 * W * np.sin(th)),
                     "cage_velocity_z": ("time", dr * np.sin(th) + r * 0.97 * W * np.cos(th))},
                    coords={"time": t}, attrs={"guide_clearance": 200e-6})
    return annotate(ds)


def logistic(t, sigma=8.0, r0=2e-6, rsat=100e-6):
    return rsat / (1 + (rsat / r0 - 1) * np.exp(-sigma * t))


def _continuation(radius, calls):
    def cont(ds, duration):
        calls.append(duration)
        return _orbit(float(ds["time"].values[-1]) + duration, radius)
    return cont


def test_growing_whirl_is_extended_until_it_saturates():
    ds = _orbit(0.3, logistic)
    assert ds.attrs["classification"] == "undetermined" and "growing" in ds.attrs["classification_reason"]
    step, why = next_step(ds)
    assert "growing" in why and step >= MIN_STEP_FRACTION * 0.3
    calls = []
    out = extend_until_determined(ds, 3.0, continue_fn=_continuation(logistic, calls))
    assert out.attrs["classification"] == "1 period", out.attrs["classification_reason"]
    assert out.attrs["extension_stop_reason"].startswith("determined: 1 period")
    ext = json.loads(out.attrs["extensions"])
    assert len(ext) == len(calls) >= 1
    assert ext[0]["label_before"] == "undetermined" and ext[0]["growth_rate"] > 0  # the growth rate is reported
    assert ext[-1]["label_after"] == "1 period"
    assert float(out["time"].values[-1]) <= 3.0 + 1e-9
    # the saturated orbit: the whirl amplitude is the saturation radius
    assert float(out["whirl_amplitude"]) == pytest.approx(100e-6, rel=0.03)


def test_budget_ends_a_whirl_that_keeps_growing():
    grow = lambda t: 1e-6 * np.exp(5.0 * t)  # noqa: E731 - e-folding 0.2 s, never saturates
    ds = _orbit(0.3, grow)
    calls = []
    out = extend_until_determined(ds, 1.0, continue_fn=_continuation(grow, calls))
    assert out.attrs["classification"] == "undetermined"
    assert out.attrs["extension_stop_reason"].startswith("budget: 1 s")
    assert float(out["time"].values[-1]) == pytest.approx(1.0, abs=DT)
    assert sum(calls) == pytest.approx(0.7, abs=DT)


def test_a_determined_run_is_not_extended():
    ds = _orbit(0.3, lambda t: np.full_like(t, 80e-6))
    out = extend_until_determined(ds, 3.0, continue_fn=lambda d, s: pytest.fail("extended a determined run"))
    assert out.attrs["extension_stop_reason"] == "determined: 1 period (no extension needed)"
    assert json.loads(out.attrs["extensions"]) == []


@pytest.mark.parametrize("extra,what", [(["--max-duration", "1s"], "only with --extend"),
                                        (["--extend", "--max-duration", "0.01s"], "at least the run's duration")])
def test_cli_extend_bad_input(tmp_path, extra, what):
    r = subprocess.run([sys.executable, "-m", "hsbearing.cli", "run", "zhang2016", "--duration", "0.05s",
                        "-o", str(tmp_path / "r.nc"), *extra], capture_output=True, text=True, timeout=300)
    assert r.returncode == 2 and what in r.stderr, r.stderr
    assert not list(tmp_path.iterdir())
