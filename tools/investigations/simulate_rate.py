"""Simulated-time rate of the whole user call ``simulate(case, span)``, warmed up.

Usage (run it in each checkout to compare, in one sitting)::

    .venv/bin/python tools/investigations/simulate_rate.py [--span 0.1] [--repeat 2]

A 2 ms warm-up run first (numba compile/cache load and the specialisation for the solver's arrays), then
``--repeat`` timed runs of ``--span`` simulated seconds of the bundled default case: CPU and wall seconds and
the solver steps.  Uses only ``load_case`` and ``simulate``, so it runs unchanged on older checkouts (e.g.
main at 7229e2e, whose ``bench_dynamics.py`` times its CVODE run without that warm-up).
"""

from __future__ import annotations

import argparse
import os
import time


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--span", type=float, default=0.1)
    ap.add_argument("--repeat", type=int, default=2)
    a = ap.parse_args(argv)
    import hsbearing
    from hsbearing.systems.angular_contact.dynamics import simulate

    case = hsbearing.load_case("zhang2016")
    print("load average at start: %.2f %.2f %.2f" % os.getloadavg())
    t0, w0 = time.process_time(), time.perf_counter()
    simulate(case, 0.002)
    print("warm-up 2 ms run: CPU %.2f s, wall %.2f s" % (time.process_time() - t0, time.perf_counter() - w0))
    for k in range(a.repeat):
        t0, w0 = time.process_time(), time.perf_counter()
        ds = simulate(case, a.span)
        print("%g s run %d: CPU %.2f s, wall %.2f s, steps %s" % (a.span, k, time.process_time() - t0,
                                                             time.perf_counter() - w0, ds.attrs.get("solver_steps")),
              flush=True)
    print("load average at end: %.2f %.2f %.2f" % os.getloadavg())
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
