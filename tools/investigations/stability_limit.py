"""What sets CVODE's step on the default case: BDF stability of the ball/race contact modes.

    .venv/bin/python tools/investigations/stability_limit.py [--span 0.01]

Prints, for the bundled Zhang et al. 2016 case:
1. steps over ``--span`` against the tolerances (rtol 1e-4..1e-6, atol x0.1..x100) and the maximum BDF order:
   an accuracy-limited step would grow like tol^(-1/(q+1)) (x1.6 fewer steps per decade at order 4);
2. the step sizes CVODE takes (percentiles) and which state dominates its local-error estimate;
3. the eigenvalues of the Jacobian at the end of the span: the fastest modes (|lambda|, frequency, damping
   ratio zeta = -Re/|lambda|, the states that carry them), and for each BDF order q the largest step h at which
   every damped mode (Re lambda < 0) lies in the stability region of BDF-q (root condition of
   rho(z) - h lambda sigma(z) checked numerically).
BDF3-5 are not A-stable (Widlund angles 86.0, 73.4, 51.8 deg): a lightly damped fast mode outside that sector
bounds the step whatever the tolerance; BDF1-2 are A-stable but their accuracy needs smaller steps.
"""

from __future__ import annotations

import argparse
import collections
import ctypes
import glob
import math
import os
import time

import numpy as np


def bdf_rho(q: int) -> np.ndarray:
    """Coefficients of y_{n+1-k}, k = 0..q, of BDF-q in the form sum_j (1/j) nabla^j y_{n+1} = h f_{n+1}."""
    c = np.zeros(q + 1)
    for j in range(1, q + 1):
        for k in range(j + 1):
            c[k] += (-1) ** k * math.comb(j, k) / j
    return c


def bdf_stable(q: int, z: complex) -> bool:
    """Root condition of BDF-q for the test equation y' = lambda y at z = h lambda."""
    poly = bdf_rho(q).astype(complex)
    poly[0] -= z
    return bool(np.max(np.abs(np.roots(poly))) <= 1.0 + 1e-12)


def largest_stable_step(q: int, lams: np.ndarray, h_grid: np.ndarray) -> float:
    """Largest h of ``h_grid`` (increasing) below which all damped modes are BDF-q stable at every grid step."""
    best = 0.0
    for h in h_grid:
        if all(bdf_stable(q, h * lam) for lam in lams):
            best = h
        else:
            break
    return best


def main(argv=None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--span", type=float, default=0.01)
    a = ap.parse_args(argv)
    import sksundae as sun

    import hsbearing as h
    from hsbearing.solvers.cvode import _CvodeCounters, integrate
    from hsbearing.systems.angular_contact import dynamics as dy

    case = h.load_case("zhang2016")
    m = dy.build_model(case)
    L = m.layout
    rtol, atol = case.simulation.rtol, case.simulation.atol
    t_eval = dy._time_grid(a.span, case.simulation.output_interval)
    integrate(m.rhs, m.y0, t_eval[:3], rtol=rtol, atol=L.atol(atol), jacfn=m.jac)  # compile / cache load
    print(f"load average {' '.join(f'{x:.2f}' for x in os.getloadavg())}; {time.strftime('%Y-%m-%d %H:%M UTC', time.gmtime())}; "
          f"{a.span * 1e3:g} ms of the default case, CVODE defaults")

    print("1. steps against tolerance and maximum order")
    for rt, at, mo in [(1e-5, 1e-8, None), (1e-4, 1e-8, None), (1e-6, 1e-8, None), (1e-6, 1e-9, None),
                       (1e-5, 1e-7, None), (1e-5, 1e-6, None), (1e-5, 1e-8, 2), (1e-5, 1e-8, 3)]:
        r = integrate(m.rhs, m.y0, t_eval, rtol=rt, atol=L.atol(at), jacfn=m.jac, max_order=mo)
        s = r.stats
        print(f"   rtol {rt:g} atol {at:g} (x scales) max order {mo or 5}: {r.status}, steps {s['steps']}, "
              f"error-test failures {s['error_test_failures']}, rhs {s['rhs_evals']}")

    print("2. step sizes and the state dominating CVODE's local-error estimate (one-step mode, every step)")
    solver = sun.cvode.CVODE(m.rhs, method="BDF", rtol=rtol, atol=L.atol(atol), jacfn=m.jac, max_num_steps=100000)
    solver.init_step(0.0, m.y0)
    c = _CvodeCounters.locate(solver)
    nv = ctypes.CDLL(glob.glob(os.path.join(os.path.dirname(c.lib._name), "libsundials_nvecserial*"))[0])
    nv.N_VNew_Serial.restype, nv.N_VNew_Serial.argtypes = ctypes.c_void_p, [ctypes.c_int64, ctypes.c_void_p]
    nv.N_VGetArrayPointer_Serial.restype = ctypes.POINTER(ctypes.c_double)
    nv.N_VGetArrayPointer_Serial.argtypes = [ctypes.c_void_p]
    nv.N_VDestroy_Serial.argtypes = [ctypes.c_void_p]
    for fn in ("CVodeGetEstLocalErrors", "CVodeGetErrWeights"):
        getattr(c.lib, fn).argtypes = [ctypes.c_void_p, ctypes.c_void_p]
    ctx = (ctypes.c_void_p * 1).from_address(c.mem.value)[0]
    n = m.y0.size
    ve, vw = nv.N_VNew_Serial(n, ctx), nv.N_VNew_Serial(n, ctx)
    e = np.ctypeslib.as_array(nv.N_VGetArrayPointer_Serial(ve), (n,))
    w = np.ctypeslib.as_array(nv.N_VGetArrayPointer_Serial(vw), (n,))
    kind = [nm.split("[")[0] for nm in L.state_names]
    top, hs, orders, tcur = collections.Counter(), [], collections.Counter(), 0.0
    while tcur < a.span:
        r = solver.step(a.span, method="onestep", tstop=a.span)
        if r.status < 0:
            break
        tcur = float(r.t)
        c.lib.CVodeGetEstLocalErrors(c.mem, ve)
        c.lib.CVodeGetErrWeights(c.mem, vw)
        top[kind[int(np.argmax(np.abs(e * w)))]] += 1
        st = c.read()
        hs.append(st["last_step"])
        orders[st["last_order"]] += 1
    y_end = np.array(r.y)
    nv.N_VDestroy_Serial(ve)
    nv.N_VDestroy_Serial(vw)
    hs = np.array(hs)
    print(f"   {hs.size} steps; h percentiles 5/25/50/75/95 [us]: "
          f"{' / '.join(f'{x:.2f}' for x in np.percentile(hs * 1e6, [5, 25, 50, 75, 95]))}; orders {dict(sorted(orders.items()))}")
    print("   largest weighted local error: " + ", ".join(f"{k} {v / hs.size:.0%}" for k, v in top.most_common(6)))

    print(f"3. Jacobian eigenvalues at t = {a.span * 1e3:g} ms")
    J, yd = np.zeros((n, n)), np.zeros(n)
    m.rhs(a.span, y_end, yd)
    m.jac(a.span, y_end, yd, J)
    lam, V = np.linalg.eig(J)
    print(f"   {'|lambda| [1/s]':>14s} {'f [kHz]':>8s} {'zeta':>7s}  states")
    seen = 0
    for i in np.argsort(-np.abs(lam)):
        if lam[i].imag < 0 or seen >= 8:
            continue
        seen += 1
        v = np.abs(V[:, i])
        print(f"   {abs(lam[i]):14.3e} {abs(lam[i].imag) / 2e3 / np.pi:8.2f} {-lam[i].real / abs(lam[i]):7.4f}  "
              f"{', '.join(L.state_names[k] for k in np.argsort(-v)[:3])}")
    damped = lam[lam.real < 0]
    print(f"   {np.sum(lam.real >= 0)} modes with Re >= 0 (undamped/growing: not a stability bound of the method)")
    grid = np.arange(0.25e-6, 40e-6, 0.25e-6)
    for q in (1, 2, 3, 4, 5):
        hmax = largest_stable_step(q, damped, grid)
        print(f"   BDF{q}: every damped mode stable for h <= {hmax * 1e6:.2f} us" if hmax < grid[-1]
              else f"   BDF{q}: stable over the whole grid (to {grid[-1] * 1e6:.0f} us)")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
