"""Cost of a cage-stability map point, and the projected wall time of a large map on a cluster.

    .venv/bin/python benchmarks/bench_map.py                                  # 2 x 2 maps of 5 and 20 ms runs, -j 2
    .venv/bin/python benchmarks/bench_map.py --durations 5ms,50ms --target 0.6s --runs 4000 --cores 16

What it does
------------
1. Runs a tiny map (``hsbearing.workflows.maps.run_map``: guide clearance x pocket clearance of the default case,
   2 x 2 points, fresh temporary directory each, so nothing is resumed) once per simulated duration
   in ``--durations``, with ``-j`` local worker processes, and records each point's wall time
   (``wall_time`` of map.nc: the time spent computing the point in its worker, from case build to the
   annotated Dataset) and the map's total wall time.  The first point of each worker also pays the one-time
   import and numba-cache load: the ``-j`` largest point times of each map are set apart as such.
2. Fits the per-point cost as a straight line in the simulated duration d,
   ``t_point(d) = a + b d`` (least squares over every point of every map): a [s] is the fixed cost of
   a point (case build, quasi-static initial state, analysis), b [s per simulated s] the integration
   cost.  With one duration only, a = 0 (pure proportionality, an upper bound for longer runs).
3. Projects ``--runs`` points of ``--target`` simulated time each on ``--cores`` cores:

       T = ceil(N / cores) * t_point(target) + T_first + T_start

   Assumptions (printed with the result): one single-threaded worker process per core (the model and
   CVODE are single-threaded; this is how ``hsbearing map --scheduler`` uses a dask cluster with
   ``--nthreads 1``); each cluster core as fast as one core of this machine *under the load measured
   here* (the machine is shared, so the measured cost is inflated and the projection is conservative
   for a dedicated cluster); per-point cost independent of the map point (the class changes the step
   count: the spread of the measured points is printed, and the projection is also given with the
   slowest measured point's cost); dask scheduling and result transfer (~10 ms and ~1-5 MB per point)
   negligible against minutes per point; T_first = the measured extra cost of a worker's first point
   and T_start = the measured start-up of the worker pool, both paid once (in parallel on every worker).
"""

from __future__ import annotations

import argparse
import json
import math
import os
import tempfile
import time


def _parse_durations(text: str) -> list[str]:
    return [s.strip() for s in text.split(",") if s.strip()]


def measure(duration: str, jobs: int, x: str, y: str) -> dict:
    import numpy as np

    from hsbearing.case import parse_quantity
    from hsbearing.workflows.maps import run_map

    d = parse_quantity(duration, "time", source="--durations", key="duration")
    with tempfile.TemporaryDirectory(prefix="bench_map_") as tmp:
        t0 = time.perf_counter()
        ds = run_map("zhang2016", x, y, out_dir=tmp, jobs=jobs, duration=duration, progress=True, figure=False)
        wall = time.perf_counter() - t0
    wt = np.asarray(ds["wall_time"].values, float).ravel()
    return {"duration": d, "duration_text": duration, "points": int(wt.size),
            "ok": int(ds.attrs["sweep_points_ok"]), "point_wall_times": [float(v) for v in wt],
            "map_wall_time": wall, "classes": [str(v) for v in np.asarray(ds["classification"].values).ravel()]}


def split_warmup(r: dict, jobs: int) -> tuple[list[float], list[float]]:
    """(steady points, first points): the ``jobs`` largest wall times of a map are the first point of each worker.

    A worker's first point also pays the one-time import of hsbearing and the load of the numba cache of the
    kernel (measured 7-12 s here, against 1.6-4.5 s for a 5-20 ms point); the fit uses the other points.
    """
    t = sorted(r["point_wall_times"])
    if len(t) <= jobs:
        return t, []
    return t[: len(t) - jobs], t[len(t) - jobs:]


def fit(results: list[dict], jobs: int) -> tuple[float, float, float]:
    """Least-squares ``t = a + b d`` over the steady points; and the mean extra cost of a worker's first point."""
    import numpy as np

    d, t, extra = [], [], []
    for r in results:
        steady, first = split_warmup(r, jobs)
        d += [r["duration"]] * len(steady)
        t += steady
        if first and steady:
            extra.append(float(np.mean(first) - np.mean(steady)))
    d, t = np.asarray(d), np.asarray(t)
    warm = float(np.mean(extra)) if extra else 0.0
    if len(set(d.tolist())) < 2:
        return 0.0, float(np.mean(t) / d[0]), warm
    b, a = np.polyfit(d, t, 1)
    return float(a), float(b), warm


def main(argv=None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--durations", default="5ms,20ms", help="simulated time per run of each tiny map (comma list)")
    ap.add_argument("-j", "--jobs", type=int, default=2, help="local worker processes")
    ap.add_argument("--x", default="bearing.outer_land_diameter=52.3,52.5mm")
    ap.add_argument("--y", default="cage.pocket_diameter=9.6,9.7mm")
    ap.add_argument("--target", default="0.6s", help="simulated time per run of the projected map (study default)")
    ap.add_argument("--runs", type=int, default=4000, help="points of the projected map")
    ap.add_argument("--cores", type=int, default=16, help="cores of the projected cluster (one worker each)")
    ap.add_argument("--json", default=None, help="write the measurements and the projection to this file")
    args = ap.parse_args(argv)

    from hsbearing.case import parse_quantity

    load0 = os.getloadavg()[0]
    results = [measure(dur, args.jobs, args.x, args.y) for dur in _parse_durations(args.durations)]
    load1 = os.getloadavg()[0]
    a, b, warm = fit(results, args.jobs)
    target = parse_quantity(args.target, "time", source="--target", key="target")
    t_point = a + b * target
    slowest = max(max(split_warmup(r, args.jobs)[0]) / (a + b * r["duration"]) for r in results)
    # pool start-up (spawn + imports before the first point starts), from the map whose points are all known
    start = max(0.0, min(r["map_wall_time"] - sum(r["point_wall_times"]) / args.jobs for r in results))
    waves = math.ceil(args.runs / args.cores)
    T = waves * t_point + warm + start
    T_slow = waves * t_point * slowest + warm + start
    print(f"load average {load0:.1f} -> {load1:.1f} on {os.cpu_count()} cores (shared machine: inflated)")
    for r in results:
        pts = ", ".join(f"{v:.2f}" for v in r["point_wall_times"])
        print(f"map {r['points']} points x {r['duration_text']} (-j {args.jobs}): total {r['map_wall_time']:.1f} s; "
              f"per point [{pts}] s; classes {r['classes']}")
    print(f"fit t_point(d) = {a:.2f} s + {b:.1f} s/s x d   (fixed cost a, integration cost b per simulated second; "
          f"steady points only); first point of a worker: +{warm:.1f} s (import + numba cache load, once per worker)")
    print(f"projection: {args.runs} runs x {args.target} on {args.cores} cores: t_point = {t_point:.1f} s, "
          f"{waves} waves -> {T / 3600:.1f} h ({T_slow / 3600:.1f} h if every point cost like the slowest measured, "
          f"x{slowest:.2f}); start-up {start:.1f} s + first-point extra {warm:.1f} s, once")
    print(f"for comparison, this machine (-j {args.jobs}): {math.ceil(args.runs / args.jobs) * t_point / 3600:.0f} h")
    if args.json:
        with open(args.json, "w") as fh:
            json.dump({"results": results, "a": a, "b": b, "first_point_extra": warm, "target": target, "t_point": t_point, "runs": args.runs,
                       "cores": args.cores, "projected_s": T, "projected_slowest_s": T_slow, "load": [load0, load1]},
                      fh, indent=1)
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
