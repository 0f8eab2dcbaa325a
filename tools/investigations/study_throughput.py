"""Study throughput before/after normal-mode stepping: a reduced Zhang et al. 2016 study, in one sitting.

    .venv/bin/python tools/investigations/study_throughput.py [--tables table5] [--duration 0.05s] [--repeat 2]

Runs the bundled ``zhang2016`` study restricted to ``--tables`` with a short ``--duration`` per run, in this
process (``-j 1``, so that the stepping mode can be switched and CPU time measured), once with CVODE in
one-step mode (the previous path: one Python round trip per internal step) and once in normal mode (one C call
per output interval), alternating, best of ``--repeat``.  Every run does the whole per-point work of the study
(quasi-static start, integration, outputs, analysis, netCDF archive).

Projection to the full study (36 distinct runs of ``[study] duration`` = 1.2 s simulated): per run, the CPU
time outside the integration (fixed: build, quasi-static start, dataset, analysis, archive) plus the
integration CPU per simulated second times 1.2 s; the wall time on 2 otherwise idle cores is taken as half the
CPU total.  Assumption: the reduced runs' integration cost per simulated second holds over 1.2 s (the runs start
from the quasi-static equilibrium, so no start-up transient dominates).  On a loaded machine wall times are
inflated; CPU seconds are the comparable figure.
"""

from __future__ import annotations

import argparse
import os
import tempfile
import time


def main(argv=None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--tables", default="table5", help="comma-separated study table ids (default table5, 9 runs)")
    ap.add_argument("--duration", default="0.05s", help="simulated time per run (default 0.05s)")
    ap.add_argument("--repeat", type=int, default=2)
    ap.add_argument("--full-runs", type=int, default=36, help="distinct runs of the full study")
    ap.add_argument("--full-duration", type=float, default=1.2, help="simulated seconds per run of the full study")
    args = ap.parse_args(argv)

    import hsbearing.solvers.cvode as cv
    from hsbearing.case import parse_quantity
    from hsbearing.workflows.study import run_study

    dur = parse_quantity(args.duration, "time", source="--duration", key="duration")
    original = cv.integrate
    acc = {}

    def counting(*a, **kw):  # dynamics.simulate imports cv.integrate at call time
        kw.setdefault("stepping", acc["stepping"])
        c0, w0 = time.process_time(), time.perf_counter()
        r = original(*a, **kw)
        acc["cpu"] += time.process_time() - c0
        acc["wall"] += time.perf_counter() - w0
        acc["steps"] += r.stats["steps"]
        acc["runs"] += 1
        return r

    cv.integrate = counting
    tables = args.tables.split(",")
    print(f"load average at start: {' '.join(f'{x:.2f}' for x in os.getloadavg())}; "
          f"{time.strftime('%Y-%m-%d %H:%M UTC', time.gmtime())}; study tables {tables}, {dur:g} s per run, -j 1")
    best = {}
    for rep in range(args.repeat):
        for stepping in ("onestep", "normal"):
            acc.update(stepping=stepping, cpu=0.0, wall=0.0, steps=0, runs=0)
            with tempfile.TemporaryDirectory(prefix="bench_study_") as d:
                c0, w0 = time.process_time(), time.perf_counter()
                run_study("zhang2016", d, jobs=1, duration=dur, progress=False, tables=tables)
                wall, cpu = time.perf_counter() - w0, time.process_time() - c0
            rec = dict(acc, total_wall=wall, total_cpu=cpu)
            print(f"  [{rep + 1}] {stepping:8s}: {rec['runs']} runs, {rec['steps']} steps; whole study wall {wall:.1f} s, "
                  f"CPU {cpu:.1f} s; integration wall {rec['wall']:.1f} s, CPU {rec['cpu']:.1f} s", flush=True)
            if stepping not in best or cpu < best[stepping]["total_cpu"]:
                best[stepping] = rec
    print(f"load average at end: {' '.join(f'{x:.2f}' for x in os.getloadavg())}")
    proj = {}
    for stepping, r in best.items():
        n = max(r["runs"], 1)
        fixed = (r["total_cpu"] - r["cpu"]) / n
        per_sim_s = r["cpu"] / (n * dur)
        full_cpu = args.full_runs * (fixed + args.full_duration * per_sim_s)
        proj[stepping] = full_cpu
        print(f"{stepping:8s} (best CPU): per run {fixed:.2f} s CPU outside the integration + {per_sim_s:.1f} CPU s "
              f"per simulated second -> full study ({args.full_runs} runs x {args.full_duration:g} s) "
              f"{full_cpu:.0f} CPU s, about {full_cpu / 2:.0f} s wall on 2 idle cores")
    if len(proj) == 2:
        print(f"reduced study CPU: one-step / normal = {best['onestep']['total_cpu'] / best['normal']['total_cpu']:.2f}x; "
              f"integration only {best['onestep']['cpu'] / best['normal']['cpu']:.2f}x; projected full study "
              f"{proj['onestep'] / proj['normal']:.2f}x")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
