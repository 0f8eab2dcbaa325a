"""Run ``hsbearing map`` on a dask ``distributed.LocalCluster`` started here (the CLI only connects to one).

    python tools/investigations/run_map_dask.py --workers 2 -- zhang2016 --x operating.axial_load=... --y ... -o DIR

Everything after ``--`` is passed to ``hsbearing map`` unchanged, plus ``--scheduler ADDR`` of the cluster
started here: ``--workers`` worker processes with one thread each (the model and CVODE are single-threaded),
scheduler and workers on the loopback interface, no dashboard.  The cluster is closed when the map returns (or
fails); the exit code is the CLI's.  The wall time of the whole invocation (cluster start-up included) and the
load average at the end are printed on the last line.

The workers are spawned processes that import :mod:`hsbearing` from ``sys.path`` of this process: run the script
from the source tree you mean to run (``cd TREE && PYTHONPATH=TREE python tools/investigations/run_map_dask.py ...``), not from
a tree that is being edited.
"""

from __future__ import annotations

import argparse
import os
import sys
import time


def main(argv: list[str] | None = None) -> int:
    argv = list(sys.argv[1:] if argv is None else argv)
    if "--" in argv:
        cut = argv.index("--")
        own, rest = argv[:cut], argv[cut + 1:]
    else:
        own, rest = [], argv
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--workers", type=int, default=2, help="dask worker processes (one thread each), default 2")
    ap.add_argument("--memory-limit", default="auto", help="per-worker memory limit passed to LocalCluster")
    args = ap.parse_args(own)
    if args.workers < 1:
        print(f"run_map_dask.py: --workers must be >= 1, got {args.workers}", file=sys.stderr)
        return 2
    if any(a == "--scheduler" or a.startswith("--scheduler=") for a in rest):
        print("run_map_dask.py: --scheduler is set by this script (it starts the cluster)", file=sys.stderr)
        return 2

    import distributed

    from hsbearing.cli import main as hsbearing_main

    t0 = time.perf_counter()
    with distributed.LocalCluster(n_workers=args.workers, threads_per_worker=1, processes=True, host="127.0.0.1",
                                  dashboard_address=None, memory_limit=args.memory_limit) as cluster:
        print(f"run_map_dask.py: LocalCluster {cluster.scheduler_address}, {args.workers} worker process(es), "
              "1 thread each", file=sys.stderr, flush=True)
        rc = hsbearing_main(["map", *rest, "--scheduler", cluster.scheduler_address])
    wall = time.perf_counter() - t0
    load = os.getloadavg()
    print(f"run_map_dask.py: exit {rc}, wall time {wall:.1f} s including the cluster start-up; "
          f"load average {load[0]:.2f} {load[1]:.2f} {load[2]:.2f}")
    return rc


if __name__ == "__main__":
    sys.exit(main())
