"""Benchmark of the dynamic model: rhs and Jacobian cost, CVODE vs scipy BDF on the same rhs.

Usage::

    .venv/bin/python benchmarks/bench_dynamics.py [--spans 0.02,0.1] [--repeat 1] [--no-scipy] [--no-onestep]

Prints, for the bundled Zhang et al. 2016 case (default case, rtol/atol and output interval of the case file), in
one run:
- microseconds per right-hand-side call (Python wrapper as CVODE calls it, and the bare kernel) and per
  compiled arrowhead Jacobian;
- for every span (default 20 ms and 100 ms simulated):
  * CVODE BDF in normal mode (one C call per output interval) with ``dynamics.SOLVER_SETTINGS`` (what
    ``simulate`` runs), and the same with CVODE's own defaults ("defaults"): steps, rhs and
    Jacobian evaluations, error-test and convergence failures, LU setups, wall and CPU seconds, microseconds
    per step, simulated ms per wall second, and the per-step cost beyond rhs + Jacobian as a fraction of
    their cost;
  * the same in one-step mode (the previous path, one Python round trip per internal step);
  * ``scipy.integrate.solve_ivp(method="BDF")`` on the same rhs and tolerances, with scipy's own
    finite-difference Jacobian and with our compiled Jacobian, and the ratio to CVODE.

Every path is warmed up first (numba specialises the kernel for scikit-sundae's read-only arrays and for
scipy's arrays on first use: a first call can cost seconds of compilation).  Timings on a shared machine
are inflated by the other processes: the load average is printed; CPU seconds are less sensitive than wall
seconds; ``--repeat N`` keeps the best of N.  The cage motion is chaotic, so two paths whose arithmetic
differs in the last bit (scipy vs CVODE) do not share trajectories; they are compared by the cage speed
averaged over the span, which is not chaotic.
"""

from __future__ import annotations

import argparse
import os
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


def _best(fn, repeat):
    """Run ``fn`` (returning (result, wall, cpu)) ``repeat`` times; keep the run with the least CPU time."""
    best = None
    for _ in range(repeat):
        r = fn()
        if best is None or r[2] < best[2]:
            best = r
    return best


def _load():
    return " ".join(f"{x:.2f}" for x in os.getloadavg())


def main(argv=None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--case", default="zhang2016")
    ap.add_argument("--spans", default="0.02,0.1", help="simulated seconds, comma-separated (default 0.02,0.1)")
    ap.add_argument("--repeat", type=int, default=1, help="best of N for every timed integration")
    ap.add_argument("--no-scipy", action="store_true", help="skip scipy solve_ivp")
    ap.add_argument("--no-onestep", action="store_true", help="skip CVODE one-step mode (the previous path)")
    ap.add_argument("--linsolver", default="dense",
                    help="CVODE linear solver: dense, lapackdense, arrowhead (block LU + Schur complement; "
                         "benchmarks/bench_linsolver.py compares it with dense in one sitting)")
    args = ap.parse_args(argv)
    spans = [float(s) for s in args.spans.split(",")]

    import hsbearing as h
    from hsbearing.models.ball_bearing import kernel as K
    from hsbearing.solvers.cvode import counters_available, integrate
    from hsbearing.systems.angular_contact import dynamics as dy

    settings = dict(dy.SOLVER_SETTINGS) if counters_available() else {}
    print(f"load average at start: {_load()} ({os.cpu_count()} cores); {time.strftime('%Y-%m-%d %H:%M UTC', time.gmtime())}")
    t0 = time.perf_counter()
    case = h.load_case(args.case)
    m = dy.build_model(case)
    y = m.y0.copy()
    yd = np.empty_like(y)
    m.rhs(0.0, y, yd)
    JJ = np.zeros((y.size, y.size))
    m.jac(0.0, y, yd, JJ)
    rtol = case.simulation.rtol
    atol = m.layout.atol(case.simulation.atol)
    dt = case.simulation.output_interval
    L = m.layout
    structure = dy.arrowhead_structure(L) if args.linsolver == "arrowhead" else None

    def f(t, yy):  # scipy's calling convention; scipy may pass non-contiguous columns
        out = np.empty(yy.size)
        m.rhs(t, np.ascontiguousarray(yy), out)
        return out

    def jac(t, yy):
        J = np.empty((yy.size, yy.size))
        m.jac(t, np.ascontiguousarray(yy), None, J)
        return J

    from scipy.integrate import solve_ivp

    # warm-up: every array specialisation the timed runs will use
    integrate(m.rhs, m.y0, np.linspace(0, 1e-4, 3), rtol=rtol, atol=atol, jacfn=m.jac, linsolver=args.linsolver,
              structure=structure)
    if not args.no_scipy:
        for jj in (None, jac):
            solve_ivp(f, (0.0, 2e-6), m.y0, method="BDF", rtol=rtol, atol=atol, **({"jac": jj} if jj else {}))
    print(f"CVODE settings of simulate(): {settings or 'CVODE defaults'}; 'defaults' rows: CVODE's own")
    print(f"case {case.name}: {L.Z} balls, {y.size} states, rtol {rtol:g}, output every {dt * 1e6:g} us; "
          f"build + compile/cache load + warm-up {time.perf_counter() - t0:.1f} s")

    t_rhs = _timeit(lambda: m.rhs(0.0, y, yd), 20000)
    t_ker = _timeit(lambda: K.rhs_kernel(y, m.P, m.qu, m.qw, yd, m._contrib, m._aux, False, m._csum, m._gaux), 20000)
    t_jac = _timeit(lambda: m.jac(0.0, y, yd, JJ), 200)
    print(f"rhs: {t_rhs[0] * 1e6:.2f} us wall / {t_rhs[1] * 1e6:.2f} us CPU per call (Python wrapper), "
          f"{t_ker[0] * 1e6:.2f} / {t_ker[1] * 1e6:.2f} us (bare kernel); "
          f"Jacobian: {t_jac[0] * 1e6:.0f} / {t_jac[1] * 1e6:.0f} us per call ({t_jac[1] / t_ker[1]:.0f} kernel-equivalents)")
    rhs_us, jac_us = t_rhs[1] * 1e6, t_jac[1] * 1e6  # CPU per call, the least load-sensitive figure
    # the physical traction model on the same case and state: its cost in the rhs
    m_ey = dy.build_model(h.load_case(args.case, **{"lubricant.traction_law": "eyring"}))
    yd_ey = np.empty_like(y)
    m_ey.rhs(0.0, m_ey.y0, yd_ey)
    t_ey = _timeit(lambda: m_ey.rhs(0.0, m_ey.y0, yd_ey), 5000)
    print(f"rhs with the physical traction model (traction_law = eyring): {t_ey[1] * 1e6:.2f} us CPU per call "
          f"({t_ey[1] / t_rhs[1]:.2f}x the case's own law)")

    def cvode_run(span, stepping, settings):
        t_eval = dy._time_grid(span, min(dt, span))

        def go():
            c0, w0 = time.process_time(), time.perf_counter()
            r = integrate(m.rhs, m.y0, t_eval, rtol=rtol, atol=atol, jacfn=m.jac, stepping=stepping,
                          linsolver=args.linsolver, cvode_settings=settings, structure=structure)
            return r, time.perf_counter() - w0, time.process_time() - c0

        return _best(go, args.repeat)

    def scipy_run(span, jj):
        def go():
            c0, w0 = time.process_time(), time.perf_counter()
            s = solve_ivp(f, (0.0, span), m.y0, method="BDF", rtol=rtol, atol=atol, **({"jac": jj} if jj else {}))
            return s, time.perf_counter() - w0, time.process_time() - c0

        return _best(go, args.repeat)

    def mean_cage_speed(t, Y):
        phi = Y[:, L.cage("phi_c")]
        return (phi[-1] - phi[0]) / (t[-1] - t[0])

    summary = []
    for span in spans:
        print(f"\n== {span * 1e3:g} ms simulated (load {_load()})")
        # "normal": what simulate() runs (normal mode + dynamics.SOLVER_SETTINGS); "defaults": the same with
        # CVODE's own msbp/msbj; "onestep": the previous path with simulate's settings (bit-identical check)
        modes = {"normal": ("normal", settings), "defaults": ("normal", {})}
        if not args.no_onestep:
            modes["onestep"] = ("onestep", settings)
        cv = {}
        for mode, (stepping, sets) in modes.items():
            r, wall, cpu = cvode_run(span, stepping, sets)
            cv[mode] = (r, wall, cpu)
            st = r.stats
            n = max(st["steps"], 1)
            work_us = (st["rhs_evals"] * rhs_us + st["jac_evals"] * jac_us) / n  # rhs + Jacobian per step
            over = cpu * 1e6 / n - work_us
            print(f"CVODE BDF {mode:8s}: {r.status}; steps {st['steps']}, rhs {st['rhs_evals']}, Jacobians "
                  f"{st['jac_evals']}, error-test failures {st.get('error_test_failures', '-')}, convergence "
                  f"failures {st.get('nonlinear_convergence_failures', '-')}, LU setups {st.get('linear_solver_setups', '-')}")
            print(f"    wall {wall:.2f} s, CPU {cpu:.2f} s -> {span / wall * 1e3:.1f} simulated ms per wall second "
                  f"({span / cpu * 1e3:.1f} per CPU second); {wall / n * 1e6:.1f} us wall / {cpu / n * 1e6:.1f} us CPU "
                  f"per step, of which rhs + Jacobian {work_us:.1f} us -> overhead {over / work_us * 100:.0f} % of "
                  f"their cost; mean cage speed {mean_cage_speed(r.t, r.y):.2f} rad/s")
        print(f"    simulate()'s settings vs CVODE defaults: {cv['defaults'][2] / cv['normal'][2]:.2f}x CPU "
              f"(one trajectory each: the step count moves +-15 % with the last bit, see solver_settings_ensemble.py)")
        if "onestep" in cv:
            a, b = cv["onestep"][0], cv["normal"][0]
            same = a.y.shape == b.y.shape and np.array_equal(a.y, b.y)
            print(f"    normal vs one-step: trajectory bit-identical {same}, steps {b.stats['steps']} vs "
                  f"{a.stats['python_counted_steps'] if 'python_counted_steps' in a.stats else a.stats['steps']} "
                  f"(counted in Python); speed-up {cv['onestep'][1] / cv['normal'][1]:.2f}x wall, "
                  f"{cv['onestep'][2] / cv['normal'][2]:.2f}x CPU")
        r_cv, w_cv, c_cv = cv["normal"]
        summary.append((span, w_cv, c_cv))
        if args.no_scipy:
            continue
        for label, jj in (("scipy's FD Jacobian", None), ("our compiled Jacobian", jac)):
            s, w_sp, c_sp = scipy_run(span, jj)
            steps = s.t.size - 1
            print(f"scipy solve_ivp BDF, {label}: status {s.status}, {steps} steps, {s.nfev} rhs, {s.njev} Jacobians, "
                  f"{s.nlu} LU; wall {w_sp:.2f} s, CPU {c_sp:.2f} s ({c_sp / max(steps, 1) * 1e6:.0f} us CPU per step) "
                  f"-> CVODE is {w_sp / w_cv:.1f}x faster (wall), {c_sp / c_cv:.1f}x (CPU); mean cage speed "
                  f"{mean_cage_speed(s.t, s.y.T):.2f} rad/s")
    print(f"\nload average at end: {_load()}")
    for span, w, c in summary:
        print(f"summary: {span * 1e3:g} ms simulated, CVODE normal mode: {span / w * 1e3:.1f} simulated ms per wall "
              f"second ({span / c * 1e3:.1f} per CPU second); issue-18 target >= 150 per wall second on a quiet machine")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
