"""`hsbearing map`: a two-key cage-stability map (class map + instability indicator), end to end on a 2 x 2 grid
of real 5 ms dynamic runs, locally (-j 2, through the CLI) and through a real dask LocalCluster on loopback;
resume, per-point wall times, bad input.

5 ms runs are far too short for a meaningful class (the classifier says "undetermined", too few section points, and
the map extends each point to 6 x 5 ms by default: the real continuation in the workers): these tests check the
machinery, not the physics of the map.
"""

from __future__ import annotations

import os
import subprocess
import sys
from pathlib import Path

import numpy as np
import pytest
import xarray as xr

from hsbearing.results import open_run
from hsbearing.workflows.maps import INDICATOR, run_map

X = "bearing.outer_land_diameter=52.3,52.5mm"  # guide clearance 0.15 / 0.25 mm to the 52 mm cage
Y = "cage.pocket_diameter=9.6,9.7mm"  # pocket clearance 37.5 / 87.5 um on the 9.525 mm ball
DUR = "5ms"


def _cli(*args, cwd=None):
    env = dict(os.environ, PYTHONUNBUFFERED="1")
    return subprocess.run([sys.executable, "-m", "hsbearing.cli", *args], capture_output=True, text=True, env=env,
                          cwd=cwd, timeout=900)


@pytest.fixture(scope="module")
def local_map(tmp_path_factory):
    out = tmp_path_factory.mktemp("map") / "local"
    r = _cli("map", "zhang2016", "--x", X, "--y", Y, "--duration", DUR, "-j", "2", "-o", str(out))
    return out, r


def test_map_cli_local_writes_map_nc_png_and_wall_times(local_map):
    out, r = local_map
    assert r.returncode == 0, r.stderr[-2000:]
    ds = open_run(out / "map.nc")
    assert ds["status"].dims == ("pocket_diameter", "outer_land_diameter")
    assert ds.sizes == {"pocket_diameter": 2, "outer_land_diameter": 2}
    np.testing.assert_allclose(ds["outer_land_diameter"].values, [52.3e-3, 52.5e-3])
    assert (ds["status"] == "ok").all()
    assert ds.attrs["map_x"] == "bearing.outer_land_diameter" and ds.attrs["map_y"] == "cage.pocket_diameter"
    assert ds.attrs["map_indicator"] == INDICATOR and "Ghaisas" in ds.attrs["map_indicator_definition"]
    # every run carries the indicator and the sub-label field; the per-point and total wall times are recorded
    assert np.isfinite(ds[INDICATOR].values).all() and (ds[INDICATOR].values >= 0).all()
    assert "classification_detail" in ds and "classification" in ds
    wt = ds["wall_time"].values
    assert np.isfinite(wt).all() and (wt > 0).all()
    assert ds.attrs["map_points_computed"] == 4
    assert ds.attrs["map_point_wall_time_sum"] == pytest.approx(float(wt.sum()))
    assert ds.attrs["map_wall_time"] > ds.attrs["map_point_wall_time_max"]
    # different guide clearances are really different cases (not four copies of one run)
    assert len({a for a in ds["archive"].values.ravel()}) == 4
    a = open_run(out / ds["archive"].values[0, 0])
    assert a.attrs["guide_clearance"] == pytest.approx(0.15e-3, rel=1e-6)
    assert INDICATOR in a  # the archive of each run carries the indicator too
    assert ds[INDICATOR].attrs["units"] == "1" and "Ghaisas" in ds[INDICATOR].attrs["long_name"]  # CLI process too
    png = (out / "map.png").read_bytes()
    assert png[:8] == b"\x89PNG\r\n\x1a\n"
    # printed: one line per point with its wall time, and the totals; progress bar on stderr
    lines = [ln for ln in r.stdout.splitlines() if "wall_time=" in ln]
    assert len(lines) == 4 and all(" s" in ln for ln in lines)
    assert "4 point(s) computed" in r.stdout and "map: " in r.stdout
    assert "sweep" in r.stderr and "4/4" in r.stderr


def test_map_cli_resume_computes_nothing(local_map):
    out, r0 = local_map
    assert r0.returncode == 0
    mtimes = {p.name: p.stat().st_mtime_ns for p in out.glob("zhang2016-*.nc")}
    r = _cli("map", "zhang2016", "--x", X, "--y", Y, "--duration", DUR, "-j", "2", "-o", str(out), "--no-figure")
    assert r.returncode == 0, r.stderr[-2000:]
    ds = open_run(out / "map.nc")
    assert int(ds["resumed"].sum()) == 4 and ds.attrs["map_points_computed"] == 0
    assert {p.name: p.stat().st_mtime_ns for p in out.glob("zhang2016-*.nc")} == mtimes
    assert "(4 resumed)" in r.stdout


@pytest.mark.slow  # long: default tier kept under ~10 min (docs/testing.md)
def test_map_through_dask_localcluster_matches_local(local_map, tmp_path):
    import distributed  # a locked dependency (dask[distributed]): a missing one fails here, never skips
    out_local, r0 = local_map
    assert r0.returncode == 0
    local = open_run(out_local / "map.nc")
    with distributed.LocalCluster(n_workers=2, threads_per_worker=1, processes=True, host="127.0.0.1",
                                  dashboard_address=None) as cluster:
        ds = run_map("zhang2016", X, Y, out_dir=tmp_path / "dask", scheduler=cluster.scheduler_address,
                     duration=DUR, progress=False)
    assert ds.attrs["sweep_backend"].startswith("dask tcp://127.0.0.1")
    assert (ds["status"] == "ok").all() and ds.attrs["map_points_computed"] == 4
    assert (tmp_path / "dask" / "map.nc").exists() and (tmp_path / "dask" / "map.png").exists()
    # same cases, same deterministic solver: the same runs, whichever process computed them
    for v in ("classification", "classification_detail", INDICATOR, "mean_cage_slip_ratio", "archive"):
        xr.testing.assert_identical(local[v].reset_coords(drop=True), ds[v].reset_coords(drop=True))


def test_map_bad_input_exit_2_nothing_written(tmp_path, capsys):
    from hsbearing.cli import main

    out = tmp_path / "bad"

    def err(*argv):
        rc = main(["map", "zhang2016", *argv, "-o", str(out)])
        e = capsys.readouterr().err
        assert len(e.strip().splitlines()) == 1 and "Traceback" not in e, e
        return rc, e

    rc, e = err("--x", X, "--y", "bearing.outer_land_diameter=52.4mm")  # the same key twice
    assert rc == 2 and "bearing.outer_land_diameter" in e
    rc, e = err("--x", X, "--y", "cage.pocket_diameter=9.0,9.7mm")  # a pocket smaller than the ball
    assert rc == 2 and "pocket" in e
    rc, e = err("--x", "no_such_key=1,2", "--y", Y)
    assert rc == 2 and "no_such_key" in e
    rc, e = err("--x", X, "--y", "cage.pocket_diameter=9.6,9.7")  # no unit
    assert rc == 2 and "pocket_diameter" in e
    rc, e = err("--x", X, "--y", Y, "--duration=-5ms")
    assert rc == 2 and "duration" in e
    assert not out.exists()


def test_plot_map_marks_not_ok_points(tmp_path):
    """The figure of a map with a failed point: drawn, hatched cell, counts in the PNG text."""
    from hsbearing.plotting.maps import plot_map

    ds = xr.Dataset(
        {"status": (("a", "b"), np.array([["ok", "ok"], ["failed", "ok"]], dtype=object)),
         "classification": (("a", "b"), np.array([["1 period", "chaos"], ["", "3 periods"]], dtype=object)),
         "classification_detail": (("a", "b"), np.array([["still cage", ""], ["", ""]], dtype=object)),
         "classification_confidence": (("a", "b"), np.array([[0.9, 0.6], [np.nan, 0.8]])),
         INDICATOR: (("a", "b"), np.array([[0.0, 0.7], [np.nan, 0.1]]))},
        coords={"a": [1.0, 2.0], "b": [3.0, 4.0]},
        attrs={"map_y_dim": "a", "map_x_dim": "b", "case_name": "test"},
    )
    p = plot_map(ds, tmp_path / "m.png")
    from PIL import Image

    with Image.open(p) as im:
        assert "3 of 4 points ok" in im.info.get("Description", "")


def test_map_stop_stats_tool_reads_a_finished_map(local_map):
    """tools/investigations/map_stop_stats.py on the 2 x 2 map of 5 ms runs: the stop rule's first check is at 0.4 s, so no
    point can have stopped early and every point ran to the 5 ms bound."""
    out, r0 = local_map
    assert r0.returncode == 0
    tool = Path(__file__).resolve().parents[2] / "tools" / "investigations" / "map_stop_stats.py"
    r = subprocess.run([sys.executable, str(tool), str(out)], capture_output=True, text=True, timeout=300)
    assert r.returncode == 0, r.stderr[-2000:]
    # the 5 ms points are undetermined (too few section points) and extended by default to 6 x 5 ms: the tool's
    # bound is the longest simulated time
    assert "4 points with archives; 0 stopped early by the stop rule, 4 ran to the 0.03 s bound" in r.stdout
    assert len([ln for ln in r.stdout.splitlines() if "stop bound" in ln]) == 4
    r = subprocess.run([sys.executable, str(tool), str(out / "nothing")], capture_output=True, text=True, timeout=300)
    assert r.returncode == 2 and "no map.nc" in r.stderr


def test_run_map_dask_tool_refuses_bad_input_before_starting_a_cluster(tmp_path):
    tool = Path(__file__).resolve().parents[2] / "tools" / "investigations" / "run_map_dask.py"
    common = ["zhang2016", "--x", X, "--y", Y, "-o", str(tmp_path / "m")]
    r = subprocess.run([sys.executable, str(tool), "--workers", "0", "--", *common], capture_output=True, text=True,
                       timeout=300)
    assert r.returncode == 2 and "--workers must be >= 1" in r.stderr
    r = subprocess.run([sys.executable, str(tool), "--", *common, "--scheduler", "tcp://127.0.0.1:1"],
                       capture_output=True, text=True, timeout=300)
    assert r.returncode == 2 and "--scheduler is set by this script" in r.stderr
    assert not (tmp_path / "m").exists()


@pytest.mark.slow  # a 4 ms point in a subprocess and in-process: two imports and cache loads (234 s at load 6)
def test_map_point_cost_tool_runs_the_maps_point(tmp_path):
    """tools/investigations/map_point_cost.py times the point the map computes: the same case (planned as the map plans
    it, stop rule "converged"), the same point function, so the same CVODE steps and rhs evaluations as the point
    computed here; its CPU inside CVODE is part of the point's CPU."""
    import json

    from hsbearing.case import load_case
    from hsbearing.workflows.sweeps import plan_sweep
    from hsbearing.workflows.sweeps.points import compute_point

    tool = Path(__file__).resolve().parents[2] / "tools" / "investigations" / "map_point_cost.py"
    r = subprocess.run([sys.executable, str(tool), "1000", "105", "--duration", "0.004", "--callback-timing"],
                       capture_output=True, text=True, timeout=900)
    assert r.returncode == 0, r.stderr[-2000:]
    got = json.loads(r.stdout.strip().splitlines()[-1])
    base = load_case("zhang2016").with_overrides(**{"simulation.stop": "converged"})
    plan = plan_sweep(base, {"lubricant.temperature": ["105degC"], "operating.axial_load": ["1000N"]}, duration=0.004)
    rec, ds = compute_point(plan.points[0].case, "run", 0.004, None, keep="answer", extend=None)
    assert (got["steps"], got["rhs"], got["jac"]) == (ds.attrs["solver_steps"], ds.attrs["solver_rhs_evals"],
                                                      ds.attrs["solver_jac_evals"])
    assert got["simulated_s"] == pytest.approx(0.004) and got["label"] == rec["summary"]["classification"]
    assert 0 < got["cpu_integrate_s"] <= got["cpu_point_s"] and got["cpu_outside_s"] >= 0
    assert 0 <= got["cpu_callback_s"] <= got["cpu_integrate_s"] and got["archive_MB"] > 0
    assert got["hsbearing"] == str(Path(__import__("hsbearing").__file__).parent)
