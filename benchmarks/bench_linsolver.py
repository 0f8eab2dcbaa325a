"""CVODE's linear algebra on the dynamic model: SUNDIALS' dense LU vs the arrowhead block LU.

    .venv/bin/python benchmarks/bench_linsolver.py [--span 0.1] [--repeat 3] [--check 0.4]

1. Kernel timings on the model's Newton matrix ``I - gamma J`` (J = the compiled Jacobian at the initial state,
   gamma = 1e-6 s, a typical BDF step x coefficient): SUNDIALS' dense setup (``SUNLinSolSetup_Dense``, called
   through ctypes on a SUNDIALS dense matrix; includes the copy of the matrix into it, ~3 us) and solve, against
   :func:`hsbearing.solvers.arrowhead.factor` / ``solve`` (called from Python: includes numba's dispatch,
   ~1-2 us); best of 9 CPU-time loops each; flop counts.
2. The integration of ``--span`` simulated seconds of the default case with :func:`hsbearing.solvers.cvode.integrate`
   and ``dynamics.SOLVER_SETTINGS`` (what ``simulate`` runs) with each linear solver, alternated, best of
   ``--repeat`` by CPU time: steps, rhs and Jacobian evaluations, LU setups, Newton iterations, wall and CPU
   time, mean cage speed.
3. ``--check D``: ``dynamics.simulate`` of D simulated seconds with each solver (annotated): mean cage slip
   ratio, cage speed, classification and kind.

The machine is shared: the load average is printed; CPU times are less sensitive to it than wall times.
"""

from __future__ import annotations

import argparse
import ctypes
import os
import time

import numpy as np


def _load():
    return " ".join(f"{x:.2f}" for x in os.getloadavg())


def _cpu(fn, number, repeat=9):
    best = float("inf")
    for _ in range(repeat):
        c0 = time.process_time()
        for _ in range(number):
            fn()
        best = min(best, (time.process_time() - c0) / number)
    return best


def kernels(M: np.ndarray, st) -> None:
    import sksundae  # noqa: F401 - loads the SUNDIALS libraries

    from hsbearing.solvers import arrowhead as ah

    n = M.shape[0]
    vp = ctypes.c_void_p
    core, mat = ah._sundials_lib("core"), ah._sundials_lib("sunmatrixdense")
    dense, nv = ah._sundials_lib("sunlinsoldense"), ah._sundials_lib("nvecserial")
    ctx = vp()
    core.SUNContext_Create.argtypes = [vp, ctypes.POINTER(vp)]
    core.SUNContext_Create(None, ctypes.byref(ctx))
    mat.SUNDenseMatrix.restype, mat.SUNDenseMatrix.argtypes = vp, [ctypes.c_int64, ctypes.c_int64, vp]
    nv.N_VNew_Serial.restype, nv.N_VNew_Serial.argtypes = vp, [ctypes.c_int64, vp]
    dense.SUNLinSol_Dense.restype, dense.SUNLinSol_Dense.argtypes = vp, [vp, vp, vp]
    mat.SUNDenseMatrix_Data.restype, mat.SUNDenseMatrix_Data.argtypes = vp, [vp]
    core.N_VGetArrayPointer.restype, core.N_VGetArrayPointer.argtypes = vp, [vp]
    dense.SUNLinSolSetup_Dense.argtypes = [vp, vp]
    dense.SUNLinSolSolve_Dense.argtypes = [vp, vp, vp, vp, ctypes.c_double]
    A = mat.SUNDenseMatrix(n, n, ctx)
    b_v, x_v = nv.N_VNew_Serial(n, ctx), nv.N_VNew_Serial(n, ctx)
    LS = dense.SUNLinSol_Dense(b_v, A, ctx)
    data = np.ctypeslib.as_array(ctypes.cast(mat.SUNDenseMatrix_Data(A), ctypes.POINTER(ctypes.c_double)), (n * n,))
    bd = np.ctypeslib.as_array(ctypes.cast(core.N_VGetArrayPointer(b_v), ctypes.POINTER(ctypes.c_double)), (n,))
    xd = np.ctypeslib.as_array(ctypes.cast(core.N_VGetArrayPointer(x_v), ctypes.POINTER(ctypes.c_double)), (n,))
    Mf = np.ascontiguousarray(M.T).ravel()
    rng = np.random.default_rng(0)
    b = rng.standard_normal(n)

    def d_setup():
        data[:] = Mf
        dense.SUNLinSolSetup_Dense(LS, A)

    a = Mf.copy()
    piv = np.zeros(n, np.int64)
    work = np.zeros(ah.work_size(st))
    scr = np.zeros(n)

    def a_setup():
        ah.factor(a, n, st.idx, st.offsets, st.border, piv, work)

    a_setup()
    d_setup()
    bd[:] = b
    t_ds, t_as = _cpu(d_setup, 300), _cpu(a_setup, 300)
    t_dv = _cpu(lambda: dense.SUNLinSolSolve_Dense(LS, A, x_v, b_v, 0.0), 3000)
    xa = b.copy()
    t_av = _cpu(lambda: ah.solve(n, st.idx, st.offsets, st.border, piv, work, xa, scr), 3000)
    dense.SUNLinSolSolve_Dense(LS, A, x_v, b_v, 0.0)
    xa = b.copy()
    ah.solve(n, st.idx, st.offsets, st.border, piv, work, xa, scr)
    ref = np.linalg.solve(M, b)
    fa, fd = st.flops()
    print(f"kernels on the model's I - gamma J ({n} states, {st.describe()}; load {_load()}):")
    print(f"  factorisation: SUNDIALS dense {t_ds * 1e6:.1f} us CPU ({fd / 1e6:.2f} M flops), arrowhead "
          f"{t_as * 1e6:.1f} us ({fa / 1e6:.2f} M flops) -> {t_ds / t_as:.2f}x")
    print(f"  solve: SUNDIALS dense {t_dv * 1e6:.2f} us CPU (ctypes call ~0.3 us), arrowhead {t_av * 1e6:.2f} us "
          f"(numba dispatch ~1-2 us) -> {t_dv / t_av:.2f}x")
    print(f"  max |x - numpy.linalg.solve| / max |x|: dense {np.abs(xd - ref).max() / np.abs(ref).max():.1e}, "
          f"arrowhead {np.abs(xa - ref).max() / np.abs(ref).max():.1e}")


def main(argv=None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--case", default="zhang2016")
    ap.add_argument("--span", type=float, default=0.1, help="simulated seconds of the timed integrations")
    ap.add_argument("--repeat", type=int, default=3, help="best of N (CPU time) for every timed integration")
    ap.add_argument("--check", type=float, default=0.0, help="also simulate() this long with each solver and "
                                                               "compare cage speed and classification")
    args = ap.parse_args(argv)

    import hsbearing as h
    from hsbearing.solvers.cvode import counters_available, integrate
    from hsbearing.systems.angular_contact import dynamics as dy

    print(f"load average at start: {_load()} ({os.cpu_count()} cores); {time.strftime('%Y-%m-%d %H:%M UTC', time.gmtime())}")
    case = h.load_case(args.case)
    m = dy.build_model(case)
    st = dy.arrowhead_structure(m.layout)
    n = m.y0.size
    JJ = np.zeros((n, n))
    m.jac(0.0, m.y0, None, JJ)
    kernels(np.eye(n) - 1e-6 * JJ, st)

    settings = dict(dy.SOLVER_SETTINGS) if counters_available() else {}
    rtol = case.simulation.rtol
    atol = m.layout.atol(case.simulation.atol)
    t_eval = dy._time_grid(args.span, min(case.simulation.output_interval, args.span))
    L = m.layout
    for ls in ("dense", "arrowhead"):  # warm-up (compilation, caches)
        integrate(m.rhs, m.y0, np.linspace(0, 1e-4, 3), rtol=rtol, atol=atol, jacfn=m.jac, linsolver=ls,
                  structure=st, cvode_settings=settings)
    best = {}
    print(f"\n== {args.span * 1e3:g} ms simulated, simulate()'s settings {settings}, best of {args.repeat} "
          f"(load {_load()})")
    for _ in range(args.repeat):
        for ls in ("dense", "arrowhead"):
            c0, w0 = time.process_time(), time.perf_counter()
            r = integrate(m.rhs, m.y0, t_eval, rtol=rtol, atol=atol, jacfn=m.jac, linsolver=ls, structure=st,
                          cvode_settings=settings)
            cpu, wall = time.process_time() - c0, time.perf_counter() - w0
            if ls not in best or cpu < best[ls][2]:
                best[ls] = (r, wall, cpu)
    for ls, (r, wall, cpu) in best.items():
        st_ = r.stats
        phi = r.y[:, L.cage("phi_c")]
        speed = (phi[-1] - phi[0]) / (r.t[-1] - r.t[0])
        print(f"{ls:9s}: {r.status}; steps {st_['steps']}, rhs {st_['rhs_evals']}, Jacobians {st_['jac_evals']}, "
              f"LU setups {st_['linear_solver_setups']}, Newton iterations {st_['nonlinear_iterations']}, "
              f"error-test failures {st_['error_test_failures']}; wall {wall:.2f} s, CPU {cpu:.2f} s; "
              f"mean cage speed {speed:.3f} rad/s")
    print(f"arrowhead / dense: CPU {best['arrowhead'][2] / best['dense'][2]:.3f}, wall "
          f"{best['arrowhead'][1] / best['dense'][1]:.3f}; load at end {_load()}")
    if args.check:
        print(f"\n== simulate() {args.check:g} s with each solver (load {_load()})")
        for ls in ("dense", "arrowhead"):
            c0 = time.process_time()
            ds = dy.simulate(case, args.check, model=m, linear_solver=ls)
            cpu = time.process_time() - c0
            a = ds.attrs
            keys = ("classification", "classification_kind", "classification_detail", "mean_cage_slip_ratio",
                    "cage_whirl_amplitude", "cage_instability_index")
            vals = {k: (a[k] if k in a else round(float(ds[k]), 6)) for k in keys if k in a or k in ds}
            print(f"{ls:9s}: CPU {cpu:.1f} s; {vals}; mean cage speed {float(ds['cage_speed'].mean()):.3f} rad/s")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
