"""Cost of one map point, split into the integrator and the rest, in any checkout of hsbearing (docs/performance.md).

    PYTHONPATH=SRC python tools/investigations/map_point_cost.py LOAD_N TEMP_C [--duration 1.2] [--profile OUT]
        [--callback-timing] [--repeat N]

Runs the point of the load x temperature map of docs/sweeps.md at axial load LOAD_N [N] and oil temperature TEMP_C
[degC] through the map's own point function (``workflows.sweeps.points.compute_point``, keep "answer", no
extension; in a checkout from before the package layout, ``sweeps._compute_point``), the case planned exactly as
the map plans it (``plan_sweep`` of zhang2016 with the stop rule "converged"), after a 1 ms warm-up run that loads
or compiles the numba kernels outside the timing.  SRC is the checkout to measure (the script imports whatever
``hsbearing`` is first on the path and prints where it came from), so the same file compares two checkouts:
alternate them and repeat, the machine is shared.

Prints one JSON line per repetition: label, simulated time, CVODE steps, rhs and Jacobian evaluations (the
archive's ``solver_*`` attrs), process CPU time [s] of the point (user + sys, ``resource.getrusage``), CPU inside
``solvers.cvode.integrate`` and outside it (building the model, the quasi-static start, the Dataset, the summary,
the reduction of the archive), CPU of writing the point archive, its size, and the CPU per rhs evaluation inside
the integrator.  ``--callback-timing`` also times the stop rule's callback at every output (two extra clock reads
per output: costs ~1 % itself); ``--profile OUT`` writes a cProfile of the point.
"""

from __future__ import annotations

import argparse
import json
import os
import resource
import sys
import tempfile
import time


def _cpu() -> float:
    r = resource.getrusage(resource.RUSAGE_SELF)
    return r.ru_utime + r.ru_stime


def main(argv=None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("load", help="axial load [N]")
    ap.add_argument("temp", help="oil temperature [degC]")
    ap.add_argument("--duration", type=float, default=1.2, help="duration bound [s] (the map's: 1.2)")
    ap.add_argument("--profile", default=None, help="write a cProfile of the point to this file")
    ap.add_argument("--callback-timing", action="store_true", help="also time the stop rule's callback")
    ap.add_argument("--repeat", type=int, default=1, help="repetitions in this process")
    a = ap.parse_args(argv)

    import hsbearing
    from hsbearing.solvers import cvode

    acc = {"integrate": 0.0, "callback": 0.0}
    original = cvode.integrate

    def integrate(*args, **kw):  # the integrator, timed in process CPU
        cb = kw.get("callback")
        if cb is not None and a.callback_timing:
            def timed(t, y):
                c0 = time.process_time()
                try:
                    return cb(t, y)
                finally:
                    acc["callback"] += time.process_time() - c0
            kw["callback"] = timed
        c0 = time.process_time()
        try:
            return original(*args, **kw)
        finally:
            acc["integrate"] += time.process_time() - c0

    cvode.integrate = integrate  # simulate() imports it from the module at call time
    try:
        from hsbearing.workflows.sweeps import plan as planning
        from hsbearing.workflows.sweeps.points import compute_point

        def point(case):
            return compute_point(case, "run", a.duration, None, keep="answer", extend=None)
    except ImportError:  # a checkout from before the package layout
        from hsbearing.sweeps import _compute_point

        from hsbearing import sweeps as planning

        def point(case):
            return _compute_point(case, "run", a.duration, None)
    from hsbearing.case import load_case
    from hsbearing.results import write_netcdf
    from hsbearing.systems import simulate

    base = load_case("zhang2016").with_overrides(**{"simulation.stop": "converged"})
    plan = planning.plan_sweep(base, {"lubricant.temperature": [f"{a.temp}degC"],
                                      "operating.axial_load": [f"{a.load}N"]}, duration=a.duration)
    case = plan.points[0].case
    simulate(case.with_overrides(**{"simulation.stop": "duration"}), duration=1e-3)  # kernels loaded or compiled
    for _ in range(a.repeat):
        acc.update(integrate=0.0, callback=0.0)
        prof = None
        if a.profile:
            import cProfile

            prof = cProfile.Profile()
            prof.enable()
        c0, w0 = _cpu(), time.perf_counter()
        rec, ds = point(case)
        c1, w1 = _cpu(), time.perf_counter()
        if prof is not None:
            prof.disable()
            prof.dump_stats(a.profile)
        with tempfile.TemporaryDirectory() as d:
            path = os.path.join(d, "point.nc")
            c2 = _cpu()
            write_netcdf(ds, path)
            c3 = _cpu()
            size = os.path.getsize(path)
        at = ds.attrs
        rhs = at.get("solver_rhs_evals")
        out = {
            "hsbearing": os.path.dirname(hsbearing.__file__), "load_N": a.load, "temperature_degC": a.temp,
            "label": rec["summary"].get("classification"),
            "simulated_s": round(float(ds["time"].values[-1]), 4) if "time" in ds.coords else None,
            "steps": at.get("solver_steps"), "rhs": rhs, "jac": at.get("solver_jac_evals"),
            "cpu_point_s": round(c1 - c0, 2), "wall_point_s": round(w1 - w0, 2),
            "cpu_integrate_s": round(acc["integrate"], 2), "cpu_outside_s": round(c1 - c0 - acc["integrate"], 2),
            "cpu_write_s": round(c3 - c2, 2), "archive_MB": round(size / 1e6, 2),
            "cpu_per_rhs_us": round(1e6 * acc["integrate"] / rhs, 1) if rhs else None,
            "load_average": round(os.getloadavg()[0], 2),
        }
        if a.callback_timing:
            out["cpu_callback_s"] = round(acc["callback"], 2)
        print(json.dumps(out), flush=True)
    return 0


if __name__ == "__main__":
    sys.exit(main())
