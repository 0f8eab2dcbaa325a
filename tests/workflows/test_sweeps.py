"""Sweeps: product/zip grids, combined dataset, local processes vs dask LocalCluster, resume,
failing and crashing points, interrupted sweeps.

The point computations here are small module-level functions (``point_fn``)
so the tests exercise the sweep machinery, not the physics: they are
picklable by reference, so spawned workers and dask workers import this module.
"""

from __future__ import annotations

import math
import os
import re
import signal
import subprocess
import sys
import textwrap
import time
from pathlib import Path

import numpy as np
import pytest
import xarray as xr

import hsbearing
from hsbearing.case import CaseError
from hsbearing.errors import SolverError
from hsbearing.results import make_dataset, open_run, standard_attrs
from hsbearing.workflows import sweeps

HERE = Path(__file__).resolve().parent
REPO = Path(__file__).resolve().parents[2]


# ----------------------------------------------------------------------------- point functions


def fake_qs(case, duration):
    """A cheap, deterministic stand-in for a quasi-static result: Q = Fa / (Z sin alpha0) + Fr-dependent term."""
    Z = case.bearing.ball_count
    Fa, Fr = case.operating.axial_load, case.operating.radial_load
    psi = 2 * np.pi * np.arange(Z) / Z
    qi = Fa / (Z * np.sin(case.bearing.contact_angle)) + 2.0 * Fr / Z * np.cos(psi)
    qo = qi * 1.1 + case.lubricant.temperature * 0.0 + (0.5 if case.lubricant.oil == "4050" else 0.0)
    _log_call(case)
    return make_dataset(
        {"inner_contact_load": qi, "outer_contact_load": qo, "cage_speed": 600.0 + case.operating.axial_load / 1000.0,
         "inner_ring_axial_displacement": 1e-8 * Fa},
        coords={"ball": np.arange(Z)},
        attrs=standard_attrs(case, status="ok"),
    )


def _log_call(case):
    log = os.environ.get("HSB_TEST_CALL_LOG")
    if log:
        with open(log, "a") as fh:
            fh.write(f"{case.operating.axial_load} {case.lubricant.oil} {os.getpid()}\n")


def failing_qs(case, duration):
    """Fails numerically above 2 kN (with a partial dataset), like a solver that does not converge;
    above 5 kN without a partial."""
    ds = fake_qs(case, duration)
    if case.operating.axial_load > 5000.0:
        raise SolverError("step size too small (test)")
    if case.operating.axial_load > 2000.0:
        ds.attrs["status"] = "failed: residual 3e-2 N after 50 iterations"
        raise SolverError("did not converge (test)", partial=ds)
    if case.operating.axial_load == 1500.0:
        raise ZeroDivisionError("a bug in a point (test)")
    return ds


def crashing_qs(case, duration):
    """Kills its own worker process at 500 N (a segfault stand-in)."""
    if case.operating.axial_load == 500.0:
        os.kill(os.getpid(), signal.SIGKILL)
    return fake_qs(case, duration)


def sleepy_qs(case, duration):
    time.sleep(0.25)
    return fake_qs(case, duration)


# ----------------------------------------------------------------------------- values


@pytest.mark.parametrize(
    "key, spec, values, coords",
    [
        ("axial_load", "100,500,1000N", ["100 N", "500 N", "1000 N"], [100.0, 500.0, 1000.0]),
        ("operating.axial_load", "1,2.5kN", ["1 kN", "2.5 kN"], [1000.0, 2500.0]),
        ("axial_load", "500 N, 1 kN", ["500 N", "1 kN"], [500.0, 1000.0]),
        ("axial_load", ["100 N", "0.2 kN"], ["100 N", "0.2 kN"], [100.0, 200.0]),
        ("oil", "4109,4106,4050", ["4109", "4106", "4050"], ["4109", "4106", "4050"]),
        ("temperature", "27,130degC", ["27 degC", "130 degC"], [300.15, 403.15]),
        ("inner_conformity", "0.52,0.53", [0.52, 0.53], [0.52, 0.53]),
        ("ball_count", "11,12", [11, 12], [11, 12]),
    ],
)
def test_parse_values(key, spec, values, coords):
    v, c = sweeps.parse_values(key, spec)
    assert v == values
    assert c == pytest.approx(coords) if isinstance(coords[0], float) else c == coords


@pytest.mark.parametrize(
    "key, spec, msg",
    [
        ("axial_load", "100,500", "needs a unit"),
        ("axial_load", "100,500mm", "not a force"),
        ("axial_lod", "100N", "unknown key"),
        ("axial_load", "100N,,200N", "empty item"),
        ("axial_load", "100,100N", "repeated"),
        ("density", "1,2kg/m^3", "ambiguous"),
    ],
)
def test_parse_values_errors(key, spec, msg):
    with pytest.raises(CaseError, match=msg):
        sweeps.parse_values(key, spec)


def test_point_hash_depends_on_full_case_kind_and_duration():
    c1 = hsbearing.load_case("zhang2016", axial_load="1 kN")
    c2 = hsbearing.load_case("zhang2016", axial_load="2 kN")
    h = sweeps.point_hash
    assert h(c1, "run", 0.01) == h(hsbearing.load_case("zhang2016", axial_load="1 kN"), "run", 0.01)
    assert len({h(c1, "run", 0.01), h(c2, "run", 0.01), h(c1, "run", 0.02), h(c1, "quasistatic", 0.01),
                h(c1, "run", 0.01, fake_qs)}) == 5


# ----------------------------------------------------------------------------- product / zip


def _qs_sweep(tmp_path, vary, **kw):
    kw.setdefault("jobs", 1)
    kw.setdefault("progress", False)
    return hsbearing.sweep("zhang2016", vary, out_dir=tmp_path, kind="quasistatic", point_fn=kw.pop("fn", fake_qs), **kw)


def test_product_sweep_dims_values_and_archives(tmp_path):
    ds = _qs_sweep(tmp_path, {"axial_load": "100,500,1000N", "oil": "4109,4050"})
    assert ds["status"].dims == ("axial_load", "oil")
    assert ds.sizes == {"axial_load": 3, "oil": 2}
    assert list(ds["axial_load"].values) == [100.0, 500.0, 1000.0]
    assert ds["axial_load"].attrs["units"] == "N" and ds["axial_load"].attrs["case_key"] == "operating.axial_load"
    assert list(ds["oil"].values) == ["4109", "4050"]
    assert list(ds["axial_load_label"].values) == ["100 N", "500 N", "1000 N"]
    assert (ds["status"] == "ok").all()
    # the values are those of each point's own case: Q = Fa / (Z sin 25 deg)
    expect = np.array([100.0, 500.0, 1000.0]) / (11 * math.sin(math.radians(25)))
    np.testing.assert_allclose(ds["mean_inner_contact_load"].sel(oil="4109"), expect, rtol=1e-12)
    np.testing.assert_allclose(ds["mean_outer_contact_load"].sel(oil="4050") - ds["mean_outer_contact_load"].sel(oil="4109"), 0.5, rtol=1e-9)
    assert ds["mean_inner_contact_load"].attrs["units"] == "N"
    assert ds["wall_time"].attrs["units"] == "s" and (ds["wall_time"] >= 0).all()
    # every point has its own archive, named by the hash, holding that point's case
    names = set(ds["archive"].values.ravel())
    assert len(names) == 6 and all((tmp_path / n).is_file() for n in names)
    one = open_run(tmp_path / str(ds["archive"].sel(axial_load=500.0, oil="4050").item()))
    case = hsbearing.case.loads_case(one.attrs["case_toml"])
    assert case.operating.axial_load == 500.0 and case.lubricant.oil == "4050"
    # sweep.nc on disk is the returned dataset
    disk = open_run(tmp_path / "sweep.nc")
    xr.testing.assert_identical(disk[["mean_inner_contact_load", "status"]], ds[["mean_inner_contact_load", "status"]])
    assert disk.attrs["sweep_mode"] == "product" and disk.attrs["sweep_points"] == 6


def test_zip_sweep_one_point_dim(tmp_path):
    ds = _qs_sweep(tmp_path, {"axial_load": "100,500,1000N", "radial_load": "0,50,200N"}, zip=True)
    assert ds["status"].dims == ("point",) and ds.sizes["point"] == 3
    assert list(ds["axial_load"].values) == [100.0, 500.0, 1000.0]
    assert list(ds["radial_load"].values) == [0.0, 50.0, 200.0]
    assert ds.attrs["sweep_mode"] == "zip"
    # a duration does not change a quasi-static point: same archives, resumed
    again = _qs_sweep(tmp_path, {"axial_load": "100,500,1000N", "radial_load": "0,50,200N"}, zip=True, duration="1 s")
    assert (again["resumed"] == 1).all()
    assert np.isclose(ds["max_inner_contact_load"].values[2] - ds["mean_inner_contact_load"].values[2], 2 * 200.0 / 11)
    # zipped lists may repeat a value; identical points are refused
    ds = _qs_sweep(tmp_path / "rep", {"axial_load": "500,500,1000N", "oil": "4109,4050,4050"}, zip=True)
    assert list(ds["oil"].values) == ["4109", "4050", "4050"] and (ds["status"] == "ok").all()
    with pytest.raises(CaseError, match="are the same"):
        _qs_sweep(tmp_path / "rep", {"axial_load": "500,500N", "oil": "4109,4109"}, zip=True)
    with pytest.raises(CaseError, match="equal length"):
        _qs_sweep(tmp_path, {"axial_load": "100,500N", "oil": "4109,4106,4050"}, zip=True)


def test_same_leaf_name_uses_full_key(tmp_path):
    ds = _qs_sweep(tmp_path, {"materials.ball.density": ["7800 kg/m^3", "7900 kg/m^3"],
                              "materials.races.density": ["7800 kg/m^3", "7900 kg/m^3"]})
    assert ds["status"].dims == ("materials.ball.density", "materials.races.density")


# ----------------------------------------------------------------------------- resume


def test_resume_does_no_work(tmp_path, monkeypatch):
    log = tmp_path / "calls.log"
    monkeypatch.setenv("HSB_TEST_CALL_LOG", str(log))
    out = tmp_path / "out"
    first = _qs_sweep(out, {"axial_load": "100,500,1000N", "oil": "4109,4106"}, jobs=2)
    assert len(log.read_text().splitlines()) == 6
    mtimes = {p.name: p.stat().st_mtime_ns for p in out.glob("zhang2016-*.nc")}
    assert len(mtimes) == 6
    second = _qs_sweep(out, {"axial_load": "100,500,1000N", "oil": "4109,4106"}, jobs=2)
    assert len(log.read_text().splitlines()) == 6  # no point computed again
    assert {p.name: p.stat().st_mtime_ns for p in out.glob("zhang2016-*.nc")} == mtimes
    assert (second["resumed"] == 1).all() and (first["resumed"] == 0).all()
    assert second.attrs["sweep_points_resumed"] == 6
    for v in ("mean_inner_contact_load", "status", "archive", "wall_time"):
        xr.testing.assert_equal(first[v], second[v])
    # an extended sweep computes only the new points
    third = _qs_sweep(out, {"axial_load": "100,500,1000,2000N", "oil": "4109,4106"}, jobs=1)
    assert len(log.read_text().splitlines()) == 8
    assert int(third["resumed"].sum()) == 6


def test_incomplete_archive_is_recomputed_and_temporaries_cleaned(tmp_path, monkeypatch):
    log = tmp_path / "calls.log"
    monkeypatch.setenv("HSB_TEST_CALL_LOG", str(log))
    ds = _qs_sweep(tmp_path, {"axial_load": "100,500N"})
    victim = tmp_path / str(ds["archive"].values[0])
    victim.write_bytes(victim.read_bytes()[:200])  # truncated: not a complete archive
    stale = tmp_path / f".{ds['archive'].values[1]}.abc123.tmp"
    stale.write_bytes(b"half a file")
    unrelated = tmp_path / ".someone-else.nc.xyz.tmp"
    unrelated.write_bytes(b"")
    again = _qs_sweep(tmp_path, {"axial_load": "100,500N"})
    assert list(again["resumed"].values) == [0, 1]
    assert len(log.read_text().splitlines()) == 3
    assert sweeps.archive_is_complete(victim)
    assert not stale.exists() and unrelated.exists()  # only this sweep's temporaries are removed


# ----------------------------------------------------------------------------- failures


def test_failing_points_are_recorded_and_the_rest_go_on(tmp_path):
    vary = {"axial_load": "500,1500,2500N", "inner_conformity": "0.49,0.52"}
    ds = _qs_sweep(tmp_path, vary, fn=failing_qs, jobs=1)
    st = ds["status"]
    # bad override (conformity <= 0.5): invalid, nothing computed, no archive
    assert (st.sel(inner_conformity=0.49) == "invalid").all()
    assert all("inner_conformity" in e and "0.5" in e for e in ds["error"].sel(inner_conformity=0.49).values)
    assert (ds["archive"].sel(inner_conformity=0.49) == "").all()
    good = ds.sel(inner_conformity=0.52)
    assert list(good["status"].values) == ["ok", "error", "failed"]
    assert "ZeroDivisionError" in good["error"].values[1]
    assert "did not converge" in good["error"].values[2]
    assert np.isfinite(good["mean_inner_contact_load"].values[[0, 2]]).all()  # partial result summarised
    assert np.isnan(good["mean_inner_contact_load"].values[1])
    part = open_run(tmp_path / str(good["archive"].values[2]))
    assert part.attrs["status"].startswith("failed") and "did not converge" in part.attrs["error"]
    assert good["archive"].values[1] == ""  # a bug is not archived: retried next time
    assert ds.attrs["status"].startswith("partial: 5 of 6")
    # a solver failure without a partial result: archived as an empty dataset carrying status and error
    nopart = _qs_sweep(tmp_path / "np", {"axial_load": "1000,6000N"}, fn=failing_qs)
    assert list(nopart["status"].values) == ["ok", "failed"] and np.isnan(nopart["mean_inner_contact_load"].values[1])
    empty = open_run(tmp_path / "np" / nopart["archive"].values[1])
    assert empty.attrs["status"] == "failed" and "step size" in empty.attrs["error"] and not empty.data_vars
    assert "operating" in empty.attrs["case_toml"]
    again = _qs_sweep(tmp_path / "np", {"axial_load": "1000,6000N"}, fn=failing_qs)
    assert list(again["resumed"].values) == [1, 1]  # deterministic failure: not recomputed ...
    retry = _qs_sweep(tmp_path / "np", {"axial_load": "1000,6000N"}, fn=failing_qs, retry_failed=True)
    assert list(retry["resumed"].values) == [1, 0]  # ... unless asked


def test_summary_failure_is_reported_and_recomputed_on_resume(tmp_path, monkeypatch):
    def broken(ds):
        raise KeyError("cage_center_y")

    real = sweeps.quasistatic_summary
    monkeypatch.setattr(sweeps.points, "quasistatic_summary", broken)
    ds = _qs_sweep(tmp_path, {"axial_load": "100,500N"})
    assert list(ds["status"].values) == ["ok", "ok"]  # the run itself is fine and archived
    assert all(e.startswith("summary failed: KeyError") for e in ds["error"].values)
    assert "mean_inner_contact_load" not in ds
    monkeypatch.setattr(sweeps.points, "quasistatic_summary", real)
    again = _qs_sweep(tmp_path, {"axial_load": "100,500N"})
    assert list(again["resumed"].values) == [1, 1] and list(again["error"].values) == ["", ""]
    assert np.isfinite(again["mean_inner_contact_load"].values).all()


@pytest.mark.slow
def test_unpicklable_point_function_is_an_error_not_a_crash(tmp_path):
    """Every point errors (the function cannot be sent to a worker): the sweep raises SolverError (issue 13:
    a sweep whose every point failed never returns quietly) and sweep.nc records why, point by point."""
    from hsbearing.errors import SolverError

    with pytest.raises(SolverError, match="pickle"):
        _qs_sweep(tmp_path, {"axial_load": "100,500N"}, fn=lambda case, duration: fake_qs(case, duration), jobs=2)
    ds = hsbearing.open_run(tmp_path / "sweep.nc")
    assert list(ds["status"].values) == ["error", "error"]
    assert all("pickle" in e.lower() for e in ds["error"].values)


def test_crashed_worker_is_isolated(tmp_path):
    ds = _qs_sweep(tmp_path, {"axial_load": "100,500,1000,2000N"}, fn=crashing_qs, jobs=2)
    assert list(ds["status"].values) == ["ok", "crashed", "ok", "ok"]
    assert "worker process died" in ds["error"].values[1]
    assert sorted(p.name for p in tmp_path.iterdir() if p.name.startswith(".") and p.name.endswith(".tmp")) == []


def test_cli_sweep_exit_codes(tmp_path):
    from hsbearing import cli

    assert cli.main(["sweep", "zhang2016", "--vary", "axial_load=100,500", "-o", str(tmp_path / "a")]) == 2
    assert not (tmp_path / "a" / "sweep.nc").exists()
    assert cli.main(["sweep", "zhang2016", "--vary", "oil=4109", "--kind", "quasistatic", "--duration", "-1 s",
                     "-o", str(tmp_path / "b")]) == 2


# ----------------------------------------------------------------------------- local processes vs dask


def test_local_processes_equal_serial(tmp_path):
    vary = {"axial_load": "100,700N", "temperature": "27,130degC"}
    a = _qs_sweep(tmp_path / "a", vary, jobs=1)
    b = _qs_sweep(tmp_path / "b", vary, jobs=2)
    for v in ("mean_inner_contact_load", "mean_outer_contact_load", "cage_speed", "status", "archive"):
        xr.testing.assert_identical(a[v], b[v])


def test_dask_local_cluster_equals_local(tmp_path):
    """The real quasi-static solver on a real dask scheduler + worker (loopback) equals local processes."""
    import distributed  # a hard dependency (dask[distributed]): missing is an error, not a skip
    vary = {"axial_load": "100,500,1000N", "inner_speed": "0,14000rpm"}
    local = _qs_sweep(tmp_path / "local", vary, jobs=2, fn=None)
    with distributed.LocalCluster(n_workers=1, threads_per_worker=1, processes=True, host="127.0.0.1",
                                  dashboard_address=None) as cluster:
        remote = _qs_sweep(tmp_path / "dask", vary, scheduler=cluster.scheduler_address, fn=None)
        assert remote.attrs["sweep_backend"].startswith("dask tcp://127.0.0.1")
    for v in ("mean_inner_contact_load", "mean_outer_contact_load", "max_inner_contact_load", "cage_speed",
              "inner_ring_axial_displacement", "status", "archive"):
        xr.testing.assert_identical(local[v], remote[v])
    # the point archives hold the same data (attrs differ: creation time, wall time)
    for name in local["archive"].values.ravel():
        xr.testing.assert_equal(open_run(tmp_path / "local" / name)[["inner_contact_load"]],
                                    open_run(tmp_path / "dask" / name)[["inner_contact_load"]])


def test_unreachable_scheduler_is_bad_input(tmp_path):
    with pytest.raises(CaseError, match="cannot connect"):
        sweeps.DaskBackend("tcp://127.0.0.1:9", timeout=1.0).__enter__()  # refused port


# ----------------------------------------------------------------------------- interruption


_DRIVER = textwrap.dedent(
    """
    import sys
    sys.path.insert(0, {tests!r})
    import hsbearing, test_sweeps
    hsbearing.sweep("zhang2016", {{"axial_load": "100,200,300,400,500,600,700,800,900,1000N"}},
                    out_dir={out!r}, kind="quasistatic", point_fn=test_sweeps.sleepy_qs, jobs=2, progress=False)
    """
)


def _children(pid: int) -> list[int]:
    out = []
    for d in Path("/proc").iterdir():
        if d.name.isdigit():
            try:
                stat = (d / "stat").read_text()
            except OSError:
                continue
            if int(stat.rpartition(")")[2].split()[1]) == pid:
                out.append(int(d.name))
    return out


def _alive(pid: int) -> bool:
    try:
        state = Path(f"/proc/{pid}/stat").read_text().rpartition(")")[2].split()[0]
    except OSError:
        return False
    return state != "Z"


@pytest.mark.skipif(not sys.platform.startswith("linux"), reason="uses /proc and PR_SET_PDEATHSIG")
@pytest.mark.parametrize("sig", [signal.SIGKILL, pytest.param(signal.SIGTERM, marks=pytest.mark.slow)])
def test_interrupted_sweep_leaves_only_complete_archives(tmp_path, sig):
    out = tmp_path / "out"
    proc = subprocess.Popen([sys.executable, "-c", _DRIVER.format(tests=str(HERE), out=str(out))],
                            stdout=subprocess.PIPE, stderr=subprocess.PIPE)
    try:
        deadline = time.time() + 60
        while time.time() < deadline and len(list(out.glob("zhang2016-*.nc"))) < 2:
            time.sleep(0.05)
        assert len(list(out.glob("zhang2016-*.nc"))) >= 2, proc.communicate(timeout=5)
        workers = _children(proc.pid)
        assert workers  # the worker processes (and the resource tracker)
        proc.send_signal(sig)
        proc.wait(timeout=30)
    finally:
        if proc.poll() is None:
            proc.kill()
            proc.wait()
    # no worker survives its sweep (Linux: PR_SET_PDEATHSIG in the worker initializer)
    deadline = time.time() + 10
    while time.time() < deadline and [p for p in workers if _alive(p)]:
        time.sleep(0.1)
    assert not [p for p in workers if _alive(p)], "orphaned worker processes"
    done = sorted(out.glob("zhang2016-*.nc"))
    assert 2 <= len(done) < 10 and not (out / "sweep.nc").exists()
    for p in done:
        assert sweeps.archive_is_complete(p), p
    leftovers = [p for p in out.iterdir() if p.name.endswith(".tmp")]
    # a kill exactly during a write could leave one hidden temporary; resume removes it
    assert all(p.name.startswith(".") for p in leftovers)
    # resume finishes the rest, recomputing none of the completed points
    ds = _qs_sweep(out, {"axial_load": "100,200,300,400,500,600,700,800,900,1000N"}, jobs=2, fn=sleepy_qs)
    assert (ds["status"] == "ok").all()
    assert int(ds["resumed"].sum()) == len(done)
    assert not [p for p in out.iterdir() if p.name.endswith(".tmp")]


def test_second_sweep_in_same_directory_is_refused(tmp_path):
    with sweeps.dir_lock(tmp_path):
        with pytest.raises(CaseError, match="another hsbearing sweep"):
            _qs_sweep(tmp_path, {"axial_load": "100,500N"})


# ----------------------------------------------------------------------------- the real quasi-static solver


def test_quasistatic_sweep_equals_direct_solves(tmp_path, capsys):
    from hsbearing import cli

    rc = cli.main(["sweep", "zhang2016", "--vary", "axial_load=500,2000N", "--vary", "inner_speed=0,14000rpm",
                   "--kind", "quasistatic", "-j", "1", "-o", str(tmp_path)])
    assert rc == 0
    out = capsys.readouterr().out
    assert "4 of 4 points ok" in out and "axial_load=2000 N  inner_speed=14000 rpm  status=ok" in out
    ds = open_run(tmp_path / "sweep.nc")
    assert ds["status"].dims == ("axial_load", "inner_speed")
    np.testing.assert_allclose(ds["inner_speed"].values, [0.0, 14000 * 2 * np.pi / 60])
    for fa in ("500 N", "2000 N"):
        for n in ("0 rpm", "14000 rpm"):
            ref = hsbearing.quasi_static(hsbearing.load_case("zhang2016", axial_load=fa, inner_speed=n))
            pt = ds.sel(axial_load=float(fa.split()[0]), inner_speed=float(ds["inner_speed"].sel(
                inner_speed=0.0 if n == "0 rpm" else 14000 * 2 * np.pi / 60, method="nearest")))
            assert pt["mean_inner_contact_load"].item() == pytest.approx(float(ref["inner_contact_load"].mean()), rel=1e-9)
            assert pt["mean_outer_contact_load"].item() == pytest.approx(float(ref["outer_contact_load"].mean()), rel=1e-9)
            assert pt["inner_ring_axial_displacement"].item() == pytest.approx(float(ref["inner_ring_axial_displacement"]), rel=1e-9)
            # and the point archive is that solve, with its case
            arch = open_run(tmp_path / pt["archive"].item())
            np.testing.assert_allclose(arch["inner_contact_load"].values, ref["inner_contact_load"].values, rtol=1e-9)
    # physics sanity through the sweep: at speed the outer loads exceed the inner (centrifugal force)
    fast = ds.sel(inner_speed=ds["inner_speed"].values[1])
    assert (fast["mean_outer_contact_load"] > fast["mean_inner_contact_load"]).all()
    static = ds.sel(inner_speed=0.0)
    np.testing.assert_allclose(static["mean_outer_contact_load"], static["mean_inner_contact_load"], rtol=1e-6)


@pytest.mark.slow
def test_dask_crashed_worker_and_failures(tmp_path):
    """On dask a point that kills its worker ends as KilledWorker -> crashed; the others complete."""
    import dask
    import distributed  # a hard dependency (dask[distributed]): missing is an error, not a skip

    with dask.config.set({"distributed.scheduler.allowed-failures": 0}):
        with distributed.LocalCluster(n_workers=1, threads_per_worker=1, processes=True, host="127.0.0.1",
                                      dashboard_address=None) as cluster:
            ds = _qs_sweep(tmp_path, {"axial_load": "100,500,1000N"}, fn=crashing_qs, scheduler=cluster.scheduler_address)
            bad = _qs_sweep(tmp_path / "f", {"axial_load": "500,1500,2500N"}, fn=failing_qs,
                            scheduler=cluster.scheduler_address)
    assert list(ds["status"].values) == ["ok", "crashed", "ok"]
    assert "KilledWorker" in ds["error"].values[1]
    assert list(bad["status"].values) == ["ok", "error", "failed"]


def test_ctrl_c_on_the_cli(tmp_path):
    """SIGINT (Ctrl-C) on `hsbearing sweep`: exit 130, workers stopped, only complete archives, resumable."""
    out = tmp_path / "out"
    # 30 quasi-static points (~0.03 s each): the SIGINT goes out within ~20 ms of the second archive, while the
    # remaining 28 points need ~0.4 s on 2 workers, so a sweep that completes ignored SIGINT (a failure, not a skip)
    loads = ",".join(str(x) for x in range(200, 6200, 200)) + "N"
    cmd = [sys.executable, "-m", "hsbearing.cli", "sweep", "zhang2016", "--vary", f"axial_load={loads}",
           "--kind", "quasistatic", "-j", "2", "-o", str(out)]
    # SIGINT back to default in the child: pytest-xdist workers may ignore it, and an ignored
    # SIGINT is inherited (Python then keeps ignoring it)
    proc = subprocess.Popen(cmd, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True,
                            preexec_fn=lambda: signal.signal(signal.SIGINT, signal.SIG_DFL))
    try:
        deadline = time.time() + 90
        while time.time() < deadline and len(list(out.glob("zhang2016-*.nc"))) < 2 and proc.poll() is None:
            time.sleep(0.02)
        proc.send_signal(signal.SIGINT)
        _, err = proc.communicate(timeout=30)
    finally:
        if proc.poll() is None:
            proc.kill()
            proc.wait()
    done = sorted(out.glob("zhang2016-*.nc"))
    assert proc.returncode == 130 and "interrupted" in err, (proc.returncode, err[-500:])
    # the newcomer's questions answered on that line: how many points were kept, and how to go on
    m = re.search(r"hsbearing: interrupted: (\d+) of 30 points kept in .*; the same command resumes from them", err)
    assert m and int(m.group(1)) == len(list(out.glob("zhang2016-*.nc"))), err[-500:]
    assert len(done) < 30 and not (out / "sweep.nc").exists()
    assert all(sweeps.archive_is_complete(p) for p in done)
    assert not [p for p in out.iterdir() if p.name.endswith(".tmp")]
    time.sleep(0.5)
    assert sorted(out.glob("zhang2016-*.nc")) == done  # no orphan worker went on writing


def test_base_case_overrides_are_kept_in_every_point(tmp_path):
    """A base case that already carries overrides (CLI --set) keeps them in every point's case."""
    base = hsbearing.load_case("zhang2016", radial_load="200 N", temperature="80 degC")
    ds = hsbearing.sweep(base, {"axial_load": "500,1000N"}, out_dir=tmp_path, kind="quasistatic", point_fn=fake_qs,
                         jobs=1, progress=False)
    for name in ds["archive"].values:
        case = hsbearing.case.loads_case(open_run(tmp_path / name).attrs["case_toml"])
        assert case.operating.radial_load == 200.0 and case.lubricant.temperature == pytest.approx(353.15)
    np.testing.assert_allclose(ds["max_inner_contact_load"] - ds["mean_inner_contact_load"], 2 * 200.0 / 11, rtol=1e-9)


@pytest.mark.slow
def test_dynamic_sweep_point_equals_direct_simulation(tmp_path):
    """Kind "run" end to end with the real dynamic model: a sweep point is the direct simulate() result."""
    ds = hsbearing.sweep("zhang2016", {"oil": "4109,4050"}, out_dir=tmp_path, duration="1 ms", jobs=2, progress=False)
    assert (ds["status"] == "ok").all() and "classification" in ds and "mean_cage_slip_ratio" in ds
    ref = hsbearing.simulate(hsbearing.load_case("zhang2016", oil="4050"), duration=1e-3)
    arch = open_run(tmp_path / ds["archive"].sel(oil="4050").item())
    np.testing.assert_allclose(arch["cage_center_y"].values, ref["cage_center_y"].values, rtol=1e-9, atol=1e-15)
    np.testing.assert_allclose(arch["inner_contact_load"].values, ref["inner_contact_load"].values, rtol=1e-9)


def test_bad_backend_writes_nothing(tmp_path, monkeypatch):
    from hsbearing import cli

    monkeypatch.setattr(sweeps.DaskBackend, "CONNECT_TIMEOUT", 1.0)
    out = tmp_path / "x"
    assert cli.main(["sweep", "zhang2016", "--vary", "axial_load=1,2kN", "--kind", "quasistatic", "-j", "0",
                     "-o", str(out)]) == 2
    assert not out.exists()
    with pytest.raises(CaseError, match="cannot connect"):
        _qs_sweep(out, {"axial_load": "1,2kN"}, scheduler="tcp://127.0.0.1:9")
    assert not out.exists()


def test_cli_invalid_value_is_bad_input_unless_keep_going(tmp_path, capsys):
    from hsbearing import cli

    """Contract: bad input exits 2 and writes nothing (review finding 3); --keep-going records it instead."""
    out = tmp_path / "e"
    rc = cli.main(["sweep", "zhang2016", "--vary", "inner_conformity=0.49,0.52", "--kind", "quasistatic", "-j", "1",
                   "-o", str(out)])
    err = capsys.readouterr().err
    assert rc == 2 and "inner_conformity=0.49" in err and "--keep-going" in err
    assert not out.exists()
    rc = cli.main(["sweep", "zhang2016", "--vary", "inner_conformity=0.49,0.52", "--kind", "quasistatic", "-j", "1",
                   "--keep-going", "-o", str(out)])
    assert rc == 1 and (out / "sweep.nc").exists()


# ----------------------------------------------------------------------------- issue 27: resume trusts only this point's archive


def test_resume_recomputes_an_archive_of_another_point(tmp_path, monkeypatch):
    """Another load's archive copied over this point's name (a complete, readable archive): its own
    ``sweep_point_hash`` says it is not this point, so the point is recomputed and sweep.nc shows the right loads
    (before: '6 of 6 ok' and the wrong loads)."""
    import shutil

    log = tmp_path / "calls.log"
    monkeypatch.setenv("HSB_TEST_CALL_LOG", str(log))
    out = tmp_path / "out"
    first = _qs_sweep(out, {"axial_load": "100,500,1000N"}, jobs=1)
    names = [str(a) for a in first["archive"].values]
    shutil.copyfile(out / names[2], out / names[0])  # the 1000 N archive under the 100 N point's name
    again = _qs_sweep(out, {"axial_load": "100,500,1000N"}, jobs=1)
    assert list(again["resumed"].values) == [0, 1, 1]
    assert len(log.read_text().splitlines()) == 4  # 3 + the recomputed 100 N point
    np.testing.assert_allclose(again["mean_inner_contact_load"].values, first["mean_inner_contact_load"].values)
    assert open_run(out / names[0]).attrs["sweep_point_hash"] != open_run(out / names[2]).attrs["sweep_point_hash"]


def test_resume_recomputes_an_archive_without_point_identity(tmp_path, monkeypatch):
    """An archive with no ``sweep_point_hash`` (written by something else under this name) is not trusted."""
    log = tmp_path / "calls.log"
    monkeypatch.setenv("HSB_TEST_CALL_LOG", str(log))
    first = _qs_sweep(tmp_path, {"axial_load": "100,500N"}, jobs=1)
    victim = tmp_path / str(first["archive"].values[1])
    ds = open_run(victim)
    del ds.attrs["sweep_point_hash"]
    ds["inner_contact_load"] = ds["inner_contact_load"] * 3.0  # wrong numbers that must not be reused
    from hsbearing.results import write_netcdf

    write_netcdf(ds, victim)
    again = _qs_sweep(tmp_path, {"axial_load": "100,500N"}, jobs=1)
    assert list(again["resumed"].values) == [1, 0]
    np.testing.assert_allclose(again["mean_inner_contact_load"].values, first["mean_inner_contact_load"].values)


def test_resume_cleans_the_short_temporary_names(tmp_path):
    """Temporaries are now `.hsb-<hash of the name>-<random>.tmp` (a name that fits whenever the archive's fits);
    a resumed sweep removes its own leftovers of that form and leaves another output's alone."""
    from hsbearing.results import temp_prefix

    ds = _qs_sweep(tmp_path, {"axial_load": "100,500N"})
    mine = tmp_path / f"{temp_prefix(str(ds['archive'].values[0]))}abc123.tmp"
    other = tmp_path / f"{temp_prefix('someone-else.nc')}xyz.tmp"
    mine.write_bytes(b"half")
    other.write_bytes(b"")
    _qs_sweep(tmp_path, {"axial_load": "100,500N"})
    assert not mine.exists() and other.exists()
    assert len(temp_prefix("x" * 255)) < 20
