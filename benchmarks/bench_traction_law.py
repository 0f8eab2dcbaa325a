"""A short dynamic run of the default case with a chosen traction law: CPU, wall, steps, rhs and Jacobian evaluations.

Usage (run it in each checkout to compare, in one sitting)::

    .venv/bin/python benchmarks/bench_traction_law.py [--law eyring] [--span 0.005] [--repeat 2]

A 1 ms warm-up run first (numba compile/cache load), then ``--repeat`` runs of ``--span`` simulated seconds of the
bundled default case (zhang2016) with ``lubricant.traction_law`` = ``--law`` (default: the case's own law).  Uses
only ``load_case`` and ``simulate``, so it runs unchanged on older checkouts.  Prints the solver counters of the
archive (``solver_steps``, ``solver_rhs_evals``, ``solver_jac_evals``) and the load average beside the times.
"""

from __future__ import annotations

import argparse
import os
import time


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--law", default=None)
    ap.add_argument("--span", type=float, default=0.005)
    ap.add_argument("--repeat", type=int, default=2)
    a = ap.parse_args(argv)
    import hsbearing
    from hsbearing.systems.angular_contact.dynamics import simulate

    case = hsbearing.load_case("zhang2016", **({"lubricant.traction_law": a.law} if a.law else {}))
    print(f"hsbearing from {os.path.dirname(hsbearing.__file__)}; law {a.law or 'the case default'}; "
          "load average at start: %.2f %.2f %.2f" % os.getloadavg())
    simulate(case, 0.001)
    for k in range(a.repeat):
        t0, w0 = time.process_time(), time.perf_counter()
        ds = simulate(case, a.span)
        at = ds.attrs
        print(f"{a.span:g} s run {k}: CPU {time.process_time() - t0:.2f} s, wall {time.perf_counter() - w0:.2f} s, "
              f"steps {at.get('solver_steps')}, rhs {at.get('solver_rhs_evals')}, "
              f"Jacobians {at.get('solver_jac_evals')}, status {at.get('status')}", flush=True)
    print("load average at end: %.2f %.2f %.2f" % os.getloadavg())
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
