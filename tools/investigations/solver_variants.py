"""Cage statistics and solver counts of CVODE variants on the default case (benchmarks/RESULTS.md, issue 18).

    .venv/bin/python tools/investigations/solver_variants.py [--span 0.1]

Integrates the default case with the grid of ``simulate`` under: the default settings, a start perturbed in
the last digits (initial cage velocity + 1e-9), LAPACK dense LU, ``CVodeSetLSetupFrequency(50)`` and rtol 1e-6,
and prints steps, LU setups, error-test failures and statistics of the cage motion over the second half of the
span.  The cage motion is chaotic in phase: any change of the arithmetic moves the trajectory beyond the
tolerance within about a millisecond, so solver variants are compared by these statistics, and the spread of
the perturbed start shows how much of a difference is chaos alone.  CPU seconds are printed for orientation
only (one run each; the step count itself moves by ~15 % with the last bit of the trajectory).
"""

from __future__ import annotations

import argparse
import os
import time

import numpy as np


def main(argv=None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--span", type=float, default=0.1)
    a = ap.parse_args(argv)

    import hsbearing as h
    from hsbearing.solvers.cvode import integrate
    from hsbearing.systems.angular_contact import dynamics as dy

    case = h.load_case("zhang2016")
    m = dy.build_model(case)
    L = m.layout
    t_eval = dy._time_grid(a.span, min(case.simulation.output_interval, a.span))
    atol = L.atol(case.simulation.atol)
    rtol = case.simulation.rtol
    y0p = m.y0.copy()
    i = L.cage("ydot_c")
    y0p[i] += 1e-9 * max(1.0, abs(y0p[i]))
    variants = {
        "default": {},
        "start perturbed (ydot_c + 1e-9)": {"y0": y0p},
        "linsolver lapackdense": {"linsolver": "lapackdense"},
        "LSetupFrequency 50": {"cvode_settings": {"LSetupFrequency": 50}},
        "rtol 1e-6": {"rtol": 1e-6},
    }
    integrate(m.rhs, m.y0, t_eval[:3], rtol=rtol, atol=atol, jacfn=m.jac)  # warm-up (compile / cache load)
    integrate(m.rhs, m.y0, t_eval[:3], rtol=rtol, atol=atol, jacfn=m.jac, linsolver="lapackdense")
    print(f"load average {' '.join(f'{x:.2f}' for x in os.getloadavg())}; {a.span * 1e3:g} ms simulated; "
          f"statistics over the second half")
    for name, kw in variants.items():
        kw = dict(kw)
        y0 = kw.pop("y0", m.y0)
        r_tol = kw.pop("rtol", rtol)
        c0 = time.process_time()
        r = integrate(m.rhs, y0, t_eval, rtol=r_tol, atol=atol, jacfn=m.jac, **kw)
        cpu = time.process_time() - c0
        Y = r.y
        half = r.t >= r.t[-1] / 2
        yc, zc = Y[half, L.cage("y_c")], Y[half, L.cage("z_c")]
        rad = np.hypot(yc, zc)
        s = r.stats
        print(f"{name:32s} {r.status}; CPU {cpu:5.2f} s, steps {s['steps']:6d}, LU {s['linear_solver_setups']:5d}, "
              f"error-test failures {s['error_test_failures']:4d} | cage speed {np.mean(Y[half, L.cage('phidot_c')]):.3f} "
              f"rad/s, whirl radius {np.mean(rad) * 1e6:.2f} +- {np.std(rad) * 1e6:.2f} um, cage y sd "
              f"{np.std(yc) * 1e6:.2f} um", flush=True)
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
