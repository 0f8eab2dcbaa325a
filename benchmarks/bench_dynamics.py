"""Benchmark of the dynamic model (issue 4): rhs cost, CVODE statistics per cage revolution, scipy BDF ratio.

Usage::

    .venv/bin/python benchmarks/bench_dynamics.py [--span 0.1] [--scipy-span 0.001] [--case zhang2016]

Prints, for the case (default: the bundled seed 004 case):
- microseconds per right-hand-side call (Python wrapper as CVODE calls it, and the bare kernel),
  and per compiled arrowhead Jacobian;
- CVODE BDF over ``--span`` simulated seconds: steps, rhs and Jacobian evaluations per simulated
  cage revolution, wall and CPU seconds per cage revolution, simulated ms per wall second;
- the first ``--scipy-span`` seconds integrated by ``scipy.integrate.solve_ivp(method="BDF")`` on
  the same rhs, tolerances and Jacobian, and by CVODE, as a wall-time ratio.

Timings depend on the machine load: report them with the load they were measured under.
"""

from __future__ import annotations

import argparse
import math
import time

import numpy as np


def _timeit(fn, n):
    """(wall, CPU) seconds per call; CPU time is less sensitive to the load of other processes."""
    fn()
    t0 = time.perf_counter()
    c0 = time.process_time()
    for _ in range(n):
        fn()
    return (time.perf_counter() - t0) / n, (time.process_time() - c0) / n


def main(argv=None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--case", default="zhang2016")
    ap.add_argument("--span", type=float, default=0.1, help="simulated seconds for the CVODE run (default 0.1)")
    ap.add_argument("--scipy-span", type=float, default=1e-3, help="simulated seconds for the scipy comparison")
    args = ap.parse_args(argv)

    import hsbearing as h
    from hsbearing import dynamics as dy
    from hsbearing.models import kernel as K
    from hsbearing.solvers.cvode import integrate

    t0 = time.perf_counter()
    case = h.load_case(args.case)
    m = dy.build_model(case)
    y = m.y0.copy()
    yd = np.empty_like(y)
    m.rhs(0.0, y, yd)
    JJ = np.zeros((y.size, y.size))
    m.jac(0.0, y, yd, JJ)
    print(f"case {case.name}: {m.layout.Z} balls, {y.size} states; model build + compile/cache load {time.perf_counter() - t0:.2f} s")

    t_rhs = _timeit(lambda: m.rhs(0.0, y, yd), 20000)
    t_ker = _timeit(lambda: K.rhs_kernel(y, m.P, m.qu, m.qw, yd, m._contrib, m._aux, False, m._csum, m._gaux), 20000)
    t_jac = _timeit(lambda: m.jac(0.0, y, yd, JJ), 200)
    print(f"rhs: {t_rhs[0] * 1e6:.2f} us wall / {t_rhs[1] * 1e6:.2f} us CPU per call (Python wrapper), "
          f"{t_ker[0] * 1e6:.2f} / {t_ker[1] * 1e6:.2f} us (bare kernel); "
          f"Jacobian: {t_jac[0] * 1e6:.0f} / {t_jac[1] * 1e6:.0f} us per call ({t_jac[1] / t_ker[1]:.0f} kernel-equivalents)")

    atol = m.layout.atol(case.simulation.atol)
    rtol = case.simulation.rtol
    # CVODE over the span
    t_eval = np.linspace(0.0, args.span, max(int(round(args.span / case.simulation.output_interval)), 1) + 1)
    c0 = time.process_time()
    w0 = time.perf_counter()
    res = integrate(m.rhs, m.y0, t_eval, rtol=rtol, atol=atol, jacfn=m.jac)
    wall = time.perf_counter() - w0
    cpu = time.process_time() - c0
    L = m.layout
    phi = res.y[:, L.cage("phi_c")]
    revs = (phi[-1] - phi[0]) / (2 * math.pi)
    st = res.stats
    print(f"CVODE BDF, rtol {rtol:g}, {args.span * 1e3:g} ms simulated ({revs:.2f} cage revolutions), status {res.status}:")
    print(f"  steps {st['steps']}, rhs evals {st['rhs_evals']}, Jacobians {st['jac_evals']}; "
          f"median step {args.span / max(st['steps'], 1) * 1e6:.2f} us (mean)")
    if revs > 0:
        print(f"  per cage revolution: {st['steps'] / revs:.0f} steps, {st['rhs_evals'] / revs:.0f} rhs, "
              f"{st['jac_evals'] / revs:.1f} Jacobians, {wall / revs:.2f} s wall, {cpu / revs:.2f} s CPU")
    print(f"  wall {wall:.2f} s, CPU {cpu:.2f} s -> {args.span / wall * 1e3:.1f} simulated ms per wall second "
          f"({args.span / max(cpu, 1e-9) * 1e3:.1f} per CPU second)")
    print(f"  target 0.1 s simulated in < 10 s wall: {'met' if 0.1 / (args.span / wall) < 10 else 'NOT met'} "
          f"(extrapolated {0.1 / (args.span / wall):.1f} s)")

    # scipy BDF vs CVODE on the same short span, rhs, tolerances and Jacobian
    from scipy.integrate import solve_ivp

    def f(t, yy):
        out = np.empty_like(yy)
        m.rhs(t, yy, out)
        return out

    def jac(t, yy):
        J = np.empty((yy.size, yy.size))
        m.jac(t, yy, None, J)
        return J

    span = args.scipy_span
    w0 = time.perf_counter()
    r2 = integrate(m.rhs, m.y0, np.array([0.0, span]), rtol=rtol, atol=atol, jacfn=m.jac)
    w_cv = time.perf_counter() - w0
    w0 = time.perf_counter()
    r3 = integrate(m.rhs, m.y0, np.array([0.0, span]), rtol=rtol, atol=atol)
    w_cvfd = time.perf_counter() - w0
    print(f"first {span * 1e3:g} ms: CVODE + compiled arrowhead Jacobian {w_cv:.3f} s wall ({r2.stats['steps']} steps, "
          f"{r2.stats['jac_evals']} Jacobians); CVODE + its own FD Jacobian {w_cvfd:.3f} s ({r3.stats['steps']} steps, "
          f"{r3.stats['rhs_evals']} rhs)")
    for label, jj in (("scipy's FD Jacobian", None), ("the compiled Jacobian", jac)):
        w0 = time.perf_counter()
        sol = solve_ivp(f, (0.0, span), m.y0, method="BDF", rtol=rtol, atol=atol, **({"jac": jj} if jj else {}))
        w_sp = time.perf_counter() - w0
        dev = np.abs(sol.y[:, -1] - r2.y[-1]) / (atol + rtol * np.abs(r2.y[-1]))
        k = int(np.argmax(dev))
        print(f"  scipy solve_ivp BDF with {label}: {w_sp:.2f} s wall, {sol.nfev} rhs, {sol.njev} Jacobians, "
              f"status {sol.status} -> CVODE (arrowhead) is {w_sp / w_cv:.1f}x faster; end-state difference "
              f"max {dev[k]:.3g} x (atol + rtol |y|) at {m.state_names[k]}")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
