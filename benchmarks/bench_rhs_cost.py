"""Cost of the compiled right-hand side: best-of timings, per state, and the split by term.

Usage (run it in each checkout to compare, in one sitting)::

    .venv/bin/python benchmarks/bench_rhs_cost.py [--runs 200] [--calls 100] [--no-split] [--no-states] [--law eyring]
    .venv/bin/python benchmarks/bench_rhs_cost.py --ratio eyring     # the physical traction law's cost ratio
    .venv/bin/python benchmarks/bench_rhs_cost.py --ratio eyring --rounds 3   # best of 3 alternated passes
    .venv/bin/python benchmarks/bench_rhs_cost.py --ratio eyring --own-run 0.02  # at states of an eyring run

Prints, for the default case (zhang2016): the bare ``kernel.rhs_kernel`` and the Python wrapper
``DynamicModel.rhs`` at the initial state, microseconds per call as the best of ``--runs`` runs of ``--calls``
calls (short runs: on a loaded machine some of them run a whole time slice, so the minimum is stable where the
mean of one long run is not); over the regression trajectory states of tests/data/regression/kernel_rhs_states.npz
(median, min, max); and the split at the last of those states by variants of the parameter record: without the
pocket film (``eta_film`` = 0), without friction (no traction quadrature, no pocket friction), without both; and the
inlet-shear-heating branch off / on (``inlet_heating``).
The load average is printed beside the numbers.
"""

from __future__ import annotations

import argparse
import os
import time
from pathlib import Path

import numpy as np

STATES = Path(__file__).resolve().parents[1] / "tests" / "data" / "regression" / "kernel_rhs_states.npz"


def best_us(fn, runs: int, calls: int) -> float:
    """Best of ``runs`` runs of ``calls`` calls of ``fn``: microseconds per call."""
    fn()
    best = float("inf")
    for _ in range(runs):
        t0 = time.perf_counter()
        for _ in range(calls):
            fn()
        best = min(best, (time.perf_counter() - t0) / calls)
    return best * 1e6


def main(argv=None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--runs", type=int, default=200)
    ap.add_argument("--calls", type=int, default=100)
    ap.add_argument("--no-split", action="store_true")
    ap.add_argument("--no-states", action="store_true")
    ap.add_argument("--ratio", default=None, metavar="LAW",
                    help="only: the rhs cost of traction law LAW over the case's own law, both models in this process, "
                         "alternated state by state, CPU time (process_time) best-of: per state and median")
    ap.add_argument("--rounds", type=int, default=1,
                    help="with --ratio: passes over the states, each state's best kept per law (default 1)")
    ap.add_argument("--own-run", type=float, default=None, metavar="SPAN",
                    help="with --ratio: the states of a run of law LAW itself over SPAN s (every 80th of 4081, after "
                         "y0) instead of the regression states (a run of the case's own law)")
    ap.add_argument("--law", default=None,
                    help="lubricant.traction_law of the case (e.g. eyring: the physical model); default: the case's")
    a = ap.parse_args(argv)
    import hsbearing
    from hsbearing.models.ball_bearing import kernel as K
    from hsbearing.models.ball_bearing import kernel_io as kio
    from hsbearing.systems.angular_contact.dynamics import build_model

    print(f"hsbearing from {Path(hsbearing.__file__).parent}; load average at start: "
          + " ".join(f"{x:.2f}" for x in os.getloadavg()))
    if a.ratio:
        return _ratio(a, K, build_model, hsbearing)
    m = build_model(hsbearing.load_case("zhang2016", **({"lubricant.traction_law": a.law} if a.law else {})))
    print(f"traction law: {a.law or 'the case default'}")
    yd = np.empty(m.y0.size)

    def kernel(y, P):
        return lambda: K.rhs_kernel(y, P, m.qu, m.qw, yd, m._contrib, m._aux, False, m._csum, m._gaux)

    y0 = m.y0.copy()
    print(f"y0: bare kernel {best_us(kernel(y0, m.P), a.runs, a.calls):.2f} us, Python wrapper "
          f"{best_us(lambda: m.rhs(0.0, y0, yd), a.runs, a.calls):.2f} us per call")
    Y = np.load(STATES)["y_default"]
    if not a.no_states:
        ts = np.array([best_us(kernel(y, m.P), max(a.runs // 5, 1), max(a.calls // 2, 1)) for y in Y])
        print(f"{len(Y)} regression states: median {np.median(ts):.1f} us (min {ts.min():.1f}, max {ts.max():.1f})")
    if not a.no_split:
        y = Y[-1].copy()
        variants = {"full": {}, "no pocket film": {"eta_film": 0.0}, "no friction": {"friction": False},
                    "neither": {"eta_film": 0.0, "friction": False}}
        t = {}
        for name, over in variants.items():
            P = m.P.copy()
            for k, v in over.items():
                kio.set_value(P, k, v)
            t[name] = best_us(kernel(y, P), a.runs, a.calls)
        print(f"split at the last regression state: full {t['full']:.2f} us; pocket film "
              f"{t['full'] - t['no pocket film']:.2f}, friction (traction quadrature + pocket friction) "
              f"{t['full'] - t['no friction']:.2f}, the rest {t['neither']:.2f} us")
        # the inlet-shear-heating branch (friction.inlet_heating, default off): alternating off / on, best of each
        t_ih = {False: [], True: []}
        for _ in range(3):
            for flag in (False, True):
                P = m.P.copy()
                kio.set_value(P, "inlet_heating", flag)
                t_ih[flag].append(best_us(kernel(y, P), a.runs, a.calls))
        print(f"inlet heating at the last regression state: off {min(t_ih[False]):.2f} us, on {min(t_ih[True]):.2f} us "
              f"(best of three alternating repetitions each)")
    print("load average at end: " + " ".join(f"{x:.2f}" for x in os.getloadavg()))
    return 0


def best_cpu_us(fn, runs: int, calls: int) -> float:
    """Best of ``runs`` runs of ``calls`` calls of ``fn`` in CPU time (process_time): microseconds per call."""
    fn()
    best = float("inf")
    for _ in range(runs):
        t0 = time.process_time()
        for _ in range(calls):
            fn()
        best = min(best, (time.process_time() - t0) / calls)
    return best * 1e6


def _ratio(a, K, build_model, hsbearing) -> int:
    """rhs cost of law a.ratio over the case's own law: the same states, both models, alternated."""
    ms = {"own": build_model(hsbearing.load_case("zhang2016")),
          a.ratio: build_model(hsbearing.load_case("zhang2016", **{"lubricant.traction_law": a.ratio}))}
    print(f"traction laws: the case's own vs {a.ratio}")
    if a.own_run:
        from bench_eyring_rhs_strips import own_run_states  # the same run, one definition (this script's directory)

        Y = np.concatenate([ms["own"].y0[None, :], own_run_states(a.own_run, a.ratio)])
        print(f"states: y0 and 51 states of a {a.own_run:g} s run of {a.ratio}")
    else:
        Y = np.concatenate([ms["own"].y0[None, :], np.load(STATES)["y_default"]])
    runs, calls = max(a.runs // 10, 3), max(a.calls // 2, 10)
    best = np.full((len(Y), 2), np.inf)
    for _ in range(max(a.rounds, 1)):  # passes over all states: a busy spell of the machine hits one pass, not all
        for i, y in enumerate(Y):
            y = y.copy()
            for j, m in enumerate(ms.values()):
                yd = np.empty(m.y0.size)
                t = best_cpu_us(lambda m=m, yd=yd: K.rhs_kernel(y, m.P, m.qu, m.qw, yd, m._contrib, m._aux, False,
                                                                 m._csum, m._gaux), runs, calls)
                best[i, j] = min(best[i, j], t)
    r = best
    q = r[:, 1] / r[:, 0]
    print(f"rounds {max(a.rounds, 1)}; y0: own law {r[0, 0]:.2f} us, {a.ratio} {r[0, 1]:.2f} us CPU per call: ratio {q[0]:.2f}")
    print(f"{len(Y) - 1} {'run' if a.own_run else 'regression'} states: own law median {np.median(r[1:, 0]):.1f} us, {a.ratio} median "
          f"{np.median(r[1:, 1]):.1f} us; ratio per state median {np.median(q[1:]):.2f} (min {q[1:].min():.2f}, "
          f"max {q[1:].max():.2f}); ratio of the minima {r[1:, 1].min() / r[1:, 0].min():.2f}")
    print("load average at end: " + " ".join(f"{x:.2f}" for x in os.getloadavg()))
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
