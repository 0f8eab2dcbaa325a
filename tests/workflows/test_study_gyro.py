"""Sweeps of the gyro ribbon-cage model (Jiang et al. 2014) through hsbearing.workflows.sweeps: what the sweep summary records.

Short runs (<= 0.15 s simulated per point, two points): the physics is tested in tests/systems/gyro/test_gyro.py; here only
that a gyro sweep writes its own summary (SFMC / SFMO / RFMC and their statistics) and none of the
rolling-element dynamics fields (classification, whirl, contact loads), which do not apply to it.
"""

from __future__ import annotations

import math

import numpy as np
import pytest
import xarray as xr

import hsbearing
from hsbearing import cli
from hsbearing.results import open_run
from hsbearing.systems.gyro import model as gyro
from hsbearing.workflows import sweeps
from hsbearing.workflows.study import gyro as studies

# Fields of the rolling-element dynamics summary (hsbearing.analysis.summary) that are meaningless for the gyro model.
_DYNAMICS_ONLY = ("classification", "classification_confidence", "mean_cage_slip_ratio", "whirl_amplitude",
                  "whirl_frequency", "mean_inner_contact_load", "max_outer_contact_load", "n_poincare_points")


def test_gyro_sweep_over_thickness_cli(tmp_path, capsys):
    """``hsbearing sweep jiang2014_gyro --vary cage.thickness=...`` (oscillation with a short period so that a
    0.15 s run holds two reversal windows): sweep.nc has finite sfmc, sfmo, rfmc per point and no dynamics fields."""
    out = tmp_path / "s"
    rc = cli.main(["sweep", "jiang2014_gyro", "--vary", "cage.thickness=0.15,0.3mm",
                   "--set", "operating.mode=oscillation", "--set", "operating.oscillation_period=0.05s",
                   "--duration", "0.15s", "-j", "1", "-o", str(out)])
    assert rc == 0
    printed = capsys.readouterr().out
    assert "sfmc=" in printed and "classification" not in printed
    with xr.open_dataset(out / "sweep.nc") as ds:
        ds = ds.load()
    assert ds["thickness"].values == pytest.approx([0.15e-3, 0.30e-3])
    for name in ("sfmc", "sfmo", "rfmc", "sfmo_stderr", "pocket_clearance", "cage_mass"):
        assert name in ds and np.all(np.isfinite(ds[name].values)), name
        assert ds[name].attrs["units"], name  # declared by the gyro module (units survive the sweep)
    for name in _DYNAMICS_ONLY:
        assert name not in ds, name
    assert list(ds["status"].values) == ["ok", "ok"]
    # RFMC does not depend on the cage (static sources, Jiang et al. 2014 Eq. 1) and matches the model directly
    rf = ds["rfmc"].values
    assert rf[0] == rf[1] == pytest.approx(gyro.static_friction(hsbearing.load_case("jiang2014_gyro")).rfmc)
    assert ds["cage_mass"].values[1] == pytest.approx(2 * ds["cage_mass"].values[0])  # m_c proportional to s
    assert ds["reversal_windows"].values.tolist() == [2.0, 2.0]
    # the summary is the archive's own numbers, and the model's summary of it
    for i in range(2):
        run = open_run(out / ds["archive"].values[i])
        assert float(run["sfmc"]) == ds["sfmc"].values[i] and float(run["sfmo"]) == ds["sfmo"].values[i]
        assert gyro.summary(run)["sfmc"] == ds["sfmc"].values[i]
    # resume: the same command computes nothing and gives the same table
    rc = cli.main(["sweep", "jiang2014_gyro", "--vary", "cage.thickness=0.15,0.3mm",
                   "--set", "operating.mode=oscillation", "--set", "operating.oscillation_period=0.05s",
                   "--duration", "0.15s", "-j", "1", "-o", str(out)])
    assert rc == 0
    with xr.open_dataset(out / "sweep.nc") as ds2:
        assert ds2["resumed"].values.tolist() == [1, 1]
        assert np.array_equal(ds2["sfmc"].values, ds["sfmc"].values)


def test_gyro_summary_constant_mode_and_clearance(tmp_path):
    """Constant-rate points: sfmc and rfmc only (no sfmo); a sweep over the pocket depth k records A = k - D_w/2."""
    ds = hsbearing.sweep("jiang2014_gyro", {"cage.pocket_depth": "0.66,0.68mm"}, jobs=1, out_dir=tmp_path,
                         duration="0.05 s", progress=False)
    assert ds["pocket_clearance"].values == pytest.approx([0.01e-3, 0.03e-3])
    assert np.all(np.isfinite(ds["sfmc"].values)) and np.all(np.isfinite(ds["rfmc"].values))
    for name in ("sfmo", "sfmo_stderr", "reversal_windows") + _DYNAMICS_ONLY:
        assert name not in ds, name


def test_summary_statistics():
    """sfmo_sd is the sample standard deviation (n - 1) of the reversal-window maxima and sfmo_stderr = sd/sqrt(n)."""
    wm = np.array([4.0, 7.0, 9.0, 8.0])  # window 0 (start) then three reversals
    ds = xr.Dataset({"sfmc": 4.0, "sfmo": wm[1:].mean(), "rfmc": 2.0, "window_max_moment": ("window", wm)},
                    attrs={"model": "gyro_ribbon_cage"})
    s = sweeps.dynamic_summary(ds)
    assert s["reversal_windows"] == 3
    assert s["sfmo_sd"] == pytest.approx(1.0)  # sample sd of 7, 9, 8
    assert s["sfmo_stderr"] == pytest.approx(1.0 / math.sqrt(3))
    assert set(s) == {"sfmc", "sfmo", "rfmc", "reversal_windows", "sfmo_sd", "sfmo_stderr"}


def test_study_goes_through_the_sweep_and_matches_simulate(tmp_path):
    """gyro.study runs its points through hsbearing.workflows.sweeps (archives in out_dir) and gives exactly the run of
    simulate(override(case, key=value)) -- same case text, so the same (chaotic) trajectory."""
    c = hsbearing.load_case("jiang2014_gyro")
    res = studies.study(c, "pocket_clearance", [0.02e-3], duration=0.03, out_dir=tmp_path)
    assert (tmp_path / "sweep.nc").exists() and len(list(tmp_path.glob("jiang2014_gyro-*.nc"))) == 1
    # A = 0.02 mm is k = 0.67 mm, written as in the case file (bit-identical k, hence the same trajectory)
    direct = gyro.simulate(gyro.override(c, **{"cage.pocket_depth": "0.67 mm"}), duration=0.03)
    assert np.array_equal(res[0.02e-3]["friction_moment_total"].values, direct["friction_moment_total"].values)
    assert float(res[0.02e-3]["sfmc"]) == float(direct["sfmc"])
