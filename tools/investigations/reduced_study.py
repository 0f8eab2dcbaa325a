"""Wall and CPU time of a reduced Zhang et al. 2016 study with the public API, for before/after runs.

    .venv/bin/python tools/investigations/reduced_study.py [--tables table5] [--duration 0.1s] [-j 1]

Runs ``hsbearing.workflows.study.run_study("zhang2016", ...)`` restricted to ``--tables`` with ``--duration`` simulated per
run (every run does the study's whole per-point work: quasi-static start, integration, outputs, analysis,
archive) after a 2 ms warm-up of the dynamic model, and prints wall and CPU seconds.  It uses only public
functions, so it runs unchanged in an older checkout (``PYTHONPATH=<checkout>``) for a comparison in one
sitting; on a loaded machine compare CPU seconds.
"""

from __future__ import annotations

import argparse
import os
import tempfile
import time


def main(argv=None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--tables", default="table5")
    ap.add_argument("--duration", default="0.1s")
    ap.add_argument("-j", "--jobs", type=int, default=1)
    a = ap.parse_args(argv)
    import hsbearing
    from hsbearing.workflows.study import run_study

    hsbearing.simulate(hsbearing.load_case("zhang2016"), 0.002)  # compile / cache load outside the timing
    print(f"{hsbearing.__file__}: load average at start {' '.join(f'{x:.2f}' for x in os.getloadavg())}; "
          f"{time.strftime('%Y-%m-%d %H:%M UTC', time.gmtime())}")
    with tempfile.TemporaryDirectory(prefix="reduced_study_") as d:
        c0, w0 = time.process_time(), time.perf_counter()
        res = run_study("zhang2016", d, jobs=a.jobs, duration=a.duration, progress=False, tables=a.tables.split(","))
        wall, cpu = time.perf_counter() - w0, time.process_time() - c0
    print(f"study {a.tables} x {a.duration} per run (-j {a.jobs}): wall {wall:.1f} s, CPU {cpu:.1f} s (this process; "
          f"with -j > 1 the workers' CPU is not counted); tables {[(k, dict(v.sizes)) for k, v in res['tables'].items()]}")
    print(f"load average at end {' '.join(f'{x:.2f}' for x in os.getloadavg())}")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
