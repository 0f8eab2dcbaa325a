"""A distributed sweep losing a machine (slow tier): on a real dask.distributed cluster of two worker processes on
loopback, a worker SIGKILLed from outside mid-sweep (and mid-map) costs nothing: every point exactly once, none
marked ``crashed``, each point's archive equal to a run without the fault; a scheduler that dies stops the command
with one clear line, and the same command resumes."""

from __future__ import annotations

import os
import signal
import socket
import subprocess
import sys
import threading
import time
from pathlib import Path

import numpy as np
import pytest

import hsbearing
from hsbearing import open_run

HERE = Path(__file__).resolve().parent
ROOT = HERE.parents[1]
sys.path.insert(0, str(HERE))

import test_sweeps  # noqa: E402 - the point functions the workers unpickle by module name

LOADS = ",".join(str(x) for x in range(100, 1300, 100)) + "N"  # 12 points of 0.25 s on 2 workers: ~1.5 s


def _kill_one_worker_after(client, out: Path, n_archives: int, killed: list):
    pids = client.run(os.getpid)  # worker address -> pid (worker processes under their nannies)
    deadline = time.time() + 120
    while time.time() < deadline and len(list(out.glob("zhang2016-*.nc"))) < n_archives:
        time.sleep(0.01)
    pid = sorted(pids.values())[0]
    os.kill(pid, signal.SIGKILL)
    killed.append(pid)


@pytest.mark.slow
@pytest.mark.parametrize("what", ["sweep", "map"])
def test_worker_killed_from_outside_costs_nothing(tmp_path, what):
    import distributed  # a hard dependency (dask[distributed])

    ref = hsbearing.sweep("zhang2016", {"axial_load": LOADS}, out_dir=tmp_path / "ref", kind="quasistatic",
                          point_fn=test_sweeps.fake_qs, jobs=1, progress=False)
    out = tmp_path / "out"
    with distributed.LocalCluster(n_workers=2, threads_per_worker=1, processes=True, host="127.0.0.1",
                                  dashboard_address=None) as cluster, distributed.Client(cluster) as client:
        client.run(sys.path.insert, 0, str(HERE))
        killed: list = []
        t = threading.Thread(target=_kill_one_worker_after, args=(client, out, 2, killed), daemon=True)
        t.start()
        if what == "sweep":
            ds = hsbearing.sweep("zhang2016", {"axial_load": LOADS}, out_dir=out, kind="quasistatic",
                                 point_fn=test_sweeps.sleepy_qs, scheduler=cluster.scheduler_address, progress=False)
        else:
            from hsbearing.workflows.maps import run_map

            ds = run_map("zhang2016", x=("axial_load", "100,200,300,400N"), y=("radial_load", "0,100,200N"),
                         out_dir=out, point_fn=test_sweeps.sleepy_qs, scheduler=cluster.scheduler_address,
                         figure=False, progress=False)
        t.join(timeout=30)
    assert killed, "no worker was killed: the fault was not injected"
    statuses = list(np.ravel(ds["status"].values))
    assert statuses == ["ok"] * len(statuses), (statuses, list(np.ravel(ds["error"].values)))
    names = list(np.ravel(ds["archive"].values))
    assert len(set(names)) == len(names) == len(list(out.glob("zhang2016-*.nc")))  # every point exactly once
    if what == "sweep":
        for a, b in zip(names, ref["archive"].values):
            x, y = open_run(out / a), open_run(tmp_path / "ref" / b)
            np.testing.assert_array_equal(x["inner_contact_load"].values, y["inner_contact_load"].values)
            assert x.attrs["case_toml"] == y.attrs["case_toml"]


def _free_port() -> int:
    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        return s.getsockname()[1]


def _cluster(port: int, env):
    sched = subprocess.Popen([sys.executable, "-m", "distributed.cli.dask_scheduler", "--host", "127.0.0.1",
                              "--port", str(port), "--dashboard-address", ":0", "--no-dashboard"],
                             stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL, env=env)
    work = subprocess.Popen([sys.executable, "-m", "distributed.cli.dask_worker", f"tcp://127.0.0.1:{port}",
                             "--nworkers", "2", "--nthreads", "1", "--no-dashboard", "--host", "127.0.0.1"],
                            stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL, env=env)
    return sched, work


def _stop(*procs):
    for p in procs:
        if p.poll() is None:
            p.terminate()
    for p in procs:
        try:
            p.wait(timeout=20)
        except subprocess.TimeoutExpired:
            p.kill()
            p.wait()


@pytest.mark.slow
def test_scheduler_killed_stops_with_one_line_and_the_same_command_resumes(tmp_path):
    env = dict(os.environ, PYTHONPATH=str(ROOT))
    port = _free_port()
    out = tmp_path / "out"
    loads = ",".join(str(x) for x in range(200, 6200, 200)) + "N"  # 30 real quasi-static points
    cmd = [sys.executable, "-m", "hsbearing.cli", "sweep", "zhang2016", "--vary", f"axial_load={loads}", "--kind",
           "quasistatic", "--scheduler", f"tcp://127.0.0.1:{port}", "-o", str(out)]
    sched, work = _cluster(port, env)
    try:
        proc = subprocess.Popen(cmd, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True, env=env)
        deadline = time.time() + 180
        while time.time() < deadline and len(list(out.glob("zhang2016-*.nc"))) < 2 and proc.poll() is None:
            time.sleep(0.01)
        sched.kill()
        sched.wait()
        t0 = time.time()
        _, err = proc.communicate(timeout=120)
        stop_time = time.time() - t0
    finally:
        _stop(work, sched)
        if proc.poll() is None:
            proc.kill()
            proc.wait()
    kept = sorted(out.glob("zhang2016-*.nc"))
    lines = [ln for ln in err.splitlines() if ln.startswith("hsbearing:")]
    assert proc.returncode == 1 and len(lines) == 1, (proc.returncode, err[-1500:])
    assert "dask scheduler" in lines[0] and "lost" in lines[0] and "resume" in lines[0], lines
    assert "Traceback" not in err, err[-1500:]
    assert stop_time < 60, stop_time
    assert 2 <= len(kept) < 30 and not (out / "sweep.nc").exists()
    # the same command, a scheduler back on the same address: resumes from the kept points
    sched, work = _cluster(port, env)
    try:
        res = subprocess.run(cmd, capture_output=True, text=True, env=env, timeout=300)
    finally:
        _stop(work, sched)
    assert res.returncode == 0, res.stderr[-1500:]
    ds = open_run(out / "sweep.nc")
    assert (ds["status"] == "ok").all() and int(ds["resumed"].sum()) >= len(kept)
