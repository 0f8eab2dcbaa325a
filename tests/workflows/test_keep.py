"""What a sweep / map / study point archive keeps (``keep="answer"`` by default, ``"full"`` on request):
the answer and its figures from the kept archive, resume and reclassification from it, ``--keep`` on the CLI.

The point function is a cheap stand-in for a dynamic run with the layout of the real one: a 0.5 s cage-centre
orbit (a circular whirl at 0.97 x the cage speed, 50 us output), per-ball contact loads over time and a
``final_state``.  The per-point size on a real run (docs/sweeps.md "What a point keeps") is measured by the
command given there, not here.
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
from hsbearing.case import CaseError
from hsbearing.results import standard_attrs, write_netcdf
from hsbearing.workflows import sweeps
from hsbearing.workflows.sweeps.archives import read_record
from hsbearing.workflows.sweeps.points import ORBIT_VARIABLES, keep_answer

W = 2 * math.pi * 96.0


def fake_run(case, duration):
    """A dynamic-run-like Dataset: orbit radius grows with the axial load (so points differ)."""
    dt = 50e-6
    t = np.arange(int(0.5 / dt) + 1) * dt
    r = 40e-6 + 1e-8 * case.operating.axial_load
    th = 0.97 * W * t
    rng = np.random.default_rng(int(case.operating.axial_load))
    Z = case.bearing.ball_count
    q = 200.0 + 5.0 * np.sin(11 * W * t)[:, None] + rng.standard_normal((t.size, Z))
    ds = xr.Dataset(
        {"cage_center_y": ("time", r * np.cos(th)), "cage_center_z": ("time", r * np.sin(th)),
         "cage_velocity_y": ("time", -r * 0.97 * W * np.sin(th)), "cage_velocity_z": ("time", r * 0.97 * W * np.cos(th)),
         "cage_angle": ("time", W * t), "cage_speed": ("time", np.full_like(t, W)),
         "inner_contact_load": (("time", "ball"), q), "outer_contact_load": (("time", "ball"), 1.1 * q),
         "ball_spin": (("time", "ball"), rng.standard_normal((t.size, Z))),
         "final_state": ("state", rng.standard_normal(40))},
        coords={"time": t, "ball": np.arange(Z), "state": [f"s{i}" for i in range(40)]},
        attrs=standard_attrs(case, status="ok"))
    ds.attrs["case_toml"] = case.to_toml()
    return annotate(ds, case)  # as simulate() returns a run


def _sweep(tmp_path, name, **kw):
    return sweeps.run_sweep("zhang2016", {"axial_load": "500,1000N"}, out_dir=tmp_path / name, point_fn=fake_run,
                            jobs=1, progress=False, **kw)


def test_keep_answer_reduces_and_keeps_what_the_answer_needs(tmp_path):
    a = _sweep(tmp_path, "answer")
    f = _sweep(tmp_path, "full", keep="full")
    for i in range(2):
        pa = tmp_path / "answer" / str(a["archive"].values[i])
        pf = tmp_path / "full" / str(f["archive"].values[i])
        assert pa.stat().st_size < pf.stat().st_size / 3, (pa.stat().st_size, pf.stat().st_size)
        with xr.open_dataset(pa) as ka, xr.open_dataset(pf) as kf:
            assert ka.attrs["keep"] == "answer" and "keep" not in kf.attrs
            for v in ORBIT_VARIABLES:  # the orbit whole, at every output
                np.testing.assert_array_equal(ka[v].values, kf[v].values)
            assert ka["inner_contact_load"].dims == ("time_decimated", "ball")
            assert ka.sizes["time_decimated"] <= sweeps.points.DECIMATED_SAMPLES + 1
            np.testing.assert_array_equal(ka["final_state"].values, kf["final_state"].values)
            assert ka.attrs["classification"] == kf.attrs["classification"]
            assert ka.attrs["classification_reason"] == kf.attrs["classification_reason"]
            np.testing.assert_array_equal(ka["poincare_y"].values, kf["poincare_y"].values)
    # the answer is the same either way
    for k in ("classification", "whirl_amplitude", "mean_inner_contact_load", "whirl_frequency"):
        np.testing.assert_array_equal(a[k].values, f[k].values)


def test_resume_from_kept_archives(tmp_path):
    _sweep(tmp_path, "answer")
    again = _sweep(tmp_path, "answer")
    assert again.attrs["sweep_points_resumed"] == 2


def test_keep_full_recomputes_a_reduced_archive(tmp_path):
    _sweep(tmp_path, "answer")
    full = _sweep(tmp_path, "answer", keep="full")
    assert full.attrs["sweep_points_resumed"] == 0
    with xr.open_dataset(tmp_path / "answer" / str(full["archive"].values[0])) as ds:
        assert "keep" not in ds.attrs and ds["inner_contact_load"].dims == ("time", "ball")
    assert _sweep(tmp_path, "answer").attrs["sweep_points_resumed"] == 2  # a full archive serves keep="answer"


def test_reclassification_from_a_kept_archive(tmp_path):
    """An archive classified by older rules is re-read from what it keeps: the same label, and contact-load means
    from the decimated histories within 0.5 % of the whole run's."""
    a = _sweep(tmp_path, "answer")
    f = _sweep(tmp_path, "full", keep="full")
    path = tmp_path / "answer" / str(a["archive"].values[1])
    with xr.open_dataset(path) as ds:
        ds = ds.load()
    ds.attrs["classifier_version"] = "older rules"
    old = tmp_path / "old.nc"
    write_netcdf(ds, old)
    rec = read_record(old)
    assert "summary_error" not in rec
    assert rec["summary"]["classification"] == str(f["classification"].values[1])
    assert rec["summary"]["mean_inner_contact_load"] == pytest.approx(float(f["mean_inner_contact_load"].values[1]),
                                                                      rel=5e-3)
    assert rec["summary"]["whirl_amplitude"] == pytest.approx(float(f["whirl_amplitude"].values[1]), rel=1e-12)


def test_keep_answer_leaves_static_results_alone():
    ds = xr.Dataset({"inner_contact_load": ("ball", np.ones(3))})
    assert keep_answer(ds) is ds


def test_bad_keep_is_an_input_error(tmp_path):
    with pytest.raises(CaseError, match="keep"):
        _sweep(tmp_path, "bad", keep="most")
    assert not (tmp_path / "bad" / "sweep.nc").exists()


@pytest.mark.parametrize("command", ["sweep", "map", "study"])
def test_cli_keep_option(command):
    r = subprocess.run([sys.executable, "-m", "hsbearing.cli", command, "--help"], capture_output=True, text=True,
                       timeout=120)
    assert "--keep {answer,full}" in r.stdout
    bad = {"sweep": ["sweep", "zhang2016", "--vary", "axial_load=1,2kN", "-o", "x"],
           "map": ["map", "zhang2016", "--x", "axial_load=1,2kN", "--y", "inner_speed=1,2rpm", "-o", "x"],
           "study": ["study", "zhang2016", "-o", "x"]}[command]
    r = subprocess.run([sys.executable, "-m", "hsbearing.cli", *bad, "--keep", "most"], capture_output=True, text=True,
                       timeout=120)
    assert r.returncode == 2 and "--keep" in r.stderr


def test_keep_definition_is_stated(tmp_path):
    a = _sweep(tmp_path, "answer")
    with xr.open_dataset(tmp_path / "answer" / str(a["archive"].values[0])) as ds:
        text = ds.attrs["keep_definition"]
        rec = json.loads(ds.attrs["sweep_record"])
    assert "every one of the" in text and "--keep full" in text and rec["status"] == "ok"


def test_run_figure_from_a_kept_archive(tmp_path):
    """`hsbearing plot` of a kept archive: the orbit panels from the whole orbit, the slip panel from the decimated
    history on its own time."""
    from hsbearing import systems
    from hsbearing.results import open_run

    a = _sweep(tmp_path, "answer")
    ds = open_run(tmp_path / "answer" / str(a["archive"].values[0]))
    assert ds["cage_slip_ratio"].dims == ("time_decimated",)
    png = systems.plot_run(ds, tmp_path / "kept.png")
    assert png and png.stat().st_size > 10_000
