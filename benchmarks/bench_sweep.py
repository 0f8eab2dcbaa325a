"""Sweep wall time: a quasi-static sweep with -j 1 (in-process) vs -j 2 (two worker processes),
and optionally the bundled Zhang et al. 2016 study with -j 2.

    .venv/bin/python benchmarks/bench_sweep.py                      # quasi-static sweep, 48 points
    .venv/bin/python benchmarks/bench_sweep.py --loads 24 --speeds 4
    .venv/bin/python benchmarks/bench_sweep.py --study --duration 0.05s -j 2   # the full study (dynamics)

Each configuration runs in a fresh temporary directory (no resume), with
progress bars off.  The -j 2 time includes starting the worker processes
(spawn: a fresh interpreter importing numpy/xarray/hsbearing each, ~1-3 s),
which a quasi-static point (~0.05 s) does not amortise over a few dozen
points; dynamic points (minutes each) do.  Timings on a shared machine are
inflated by the other processes' load: the script prints the load average.
"""

from __future__ import annotations

import argparse
import os
import tempfile
import time


def quasistatic_sweep(jobs: int, n_loads: int, n_speeds: int) -> tuple[float, int, int]:
    import numpy as np

    from hsbearing import sweep

    loads = ",".join(f"{x:g}" for x in np.linspace(200, 6000, n_loads)) + "N"
    speeds = ",".join(f"{x:g}" for x in np.linspace(0, 20000, n_speeds)) + "rpm"
    with tempfile.TemporaryDirectory(prefix="bench_sweep_") as d:
        t0 = time.perf_counter()
        ds = sweep("zhang2016", {"axial_load": loads, "inner_speed": speeds}, kind="quasistatic", jobs=jobs,
                   out_dir=d, progress=False)
        wall = time.perf_counter() - t0
    return wall, int(ds.attrs["sweep_points"]), int(ds.attrs["sweep_points_ok"])


def study(jobs: int, duration: str | None, out: str | None, stop: str | None = None) -> dict:
    from hsbearing.workflows.study import run_study

    if out:
        return run_study("zhang2016", out, jobs=jobs, duration=duration, progress=True, stop=stop)
    with tempfile.TemporaryDirectory(prefix="bench_study_") as d:
        return run_study("zhang2016", d, jobs=jobs, duration=duration, progress=True, stop=stop)


def main() -> None:
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    p.add_argument("--loads", type=int, default=12, help="axial loads 200..6000 N")
    p.add_argument("--speeds", type=int, default=4, help="inner speeds 0..20000 rpm")
    p.add_argument("--study", action="store_true", help="time the zhang2016 study instead")
    p.add_argument("--duration", default=None, help="simulated time per study point, e.g. 0.05s")
    p.add_argument("-j", "--jobs", type=int, default=2)
    p.add_argument("-o", "--output", default=None, help="keep the study output here")
    p.add_argument("--stop", default="both", choices=("both", "duration", "converged"),
                   help="study: with the stop rule off (duration), on (converged) or both in one sitting (default)")
    a = p.parse_args()
    print(f"cores: {os.cpu_count()}, load average: {' '.join(f'{x:.2f}' for x in os.getloadavg())}")
    if a.study:
        for stop in (("duration", "converged") if a.stop == "both" else (a.stop,)):
            out = f"{a.output}-{stop}" if a.output else None
            res = study(a.jobs, a.duration, out, stop=stop)
            print(f"study zhang2016, stop {stop}: {res['n_unique_points']} points, {res['n_computed']} computed, "
                  f"wall time {res['wall_time']:.1f} s ({res['backend']}, duration {res['duration']}); load average "
                  f"{' '.join(f'{x:.2f}' for x in os.getloadavg())}")
        return
    for jobs in (1, 2):
        wall, n, ok = quasistatic_sweep(jobs, a.loads, a.speeds)
        print(f"quasi-static sweep, {n} points ({ok} ok), -j {jobs}: {wall:.2f} s  ({wall / n * 1e3:.0f} ms/point)")


if __name__ == "__main__":
    main()
