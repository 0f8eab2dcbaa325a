"""Where the physical traction law's rhs time goes: the strips the rhs itself evaluates at bench_rhs_cost's states.

Usage (with the checkout first on the path)::

    PYTHONPATH=<checkout> .venv/bin/python benchmarks/bench_eyring_rhs_strips.py [--rounds 5] [--own-run 0.02]

1. Captures every call of the law in ``kernel.rhs_kernel`` (case zhang2016, ``lubricant.traction_law = eyring``) at
   the initial state and the 51 regression states of tests/data/regression/kernel_rhs_states.npz: the per-contact
   coefficients (``traction_coefficients_nb``: its arguments) and every strip (``traction_mu_nb``: coefficients,
   slip, strip node).  The capture runs the kernel as plain Python (``NUMBA_DISABLE_JIT=1``, a subprocess) with the
   two calls wrapped; the arithmetic is the same.  ``--own-run SPAN``: instead, 51 states of a run of the physical
   law itself (the default case with ``traction_law = eyring`` over SPAN seconds, CVODE as in
   tools/generators/make_kernel_rhs_states.py, every 80th of 4081 output states), whose slips are its own.
2. Prints the calls per rhs and, over the captured strips, which branches of ``_kernels.eyring_strip_mu_nb`` the
   mirror node pairs take: sigma_f below the pair-constant tables (< 2, libm), in them (2 ... SIGMA_HARD) or above;
   the pairs taken whole by the plastic shortcut, by pair index; and the classes of the nodes of the other pairs
   (near-inlet form E < 0.5, tables of the build-up, plastic).
3. Times in compiled loops over the captured samples (CPU best of ``--rounds`` alternated rounds): the kernel's strip,
   the same strip compiled without the plastic shortcut (``_PLASTIC_MARGIN`` = inf: the code before it), the seed
   law's ``mu_nb`` (4109 coefficients), and the per-contact coefficients of both laws; checks that the two strips are
   equal bit for bit.  The load average is printed beside the numbers.
"""

from __future__ import annotations

import argparse
import math
import os
import subprocess
import sys
import tempfile
import time
from pathlib import Path

import numpy as np

ROOT = Path(__file__).resolve().parents[1]


def own_run_states(span: float, law: str = "eyring") -> np.ndarray:
    """51 states of a run of the default case with the traction law ``law`` (compiled; default the physical law),
    every 80th of 4081 (also used by bench_rhs_cost.py --own-run)."""
    import hsbearing
    from hsbearing.solvers.cvode import integrate
    from hsbearing.systems.angular_contact.dynamics import build_model

    case = hsbearing.load_case("zhang2016", **{"lubricant.traction_law": law})
    m = build_model(case)
    sim = case.simulation
    res = integrate(m.rhs, m.y0, np.linspace(0.0, span, 4081), rtol=float(sim.rtol),
                    atol=m.layout.atol(float(sim.atol)), jacfn=m.jac)
    return np.asarray(res.y)[80::80]


def capture(out: str, states: str | None) -> None:
    """Run in a subprocess with NUMBA_DISABLE_JIT=1: record the law's calls of the rhs over the states."""
    import hsbearing
    from hsbearing.models.ball_bearing import kernel as K
    from hsbearing.systems.angular_contact.dynamics import build_model

    strips, contacts = [], []
    mu0, co0 = K.traction_mu_nb, K.traction_coefficients_nb

    def mu(law, c, S, u):
        strips.append((len(contacts) - 1, S, u))
        return mu0(law, c, S, u)

    def co(p, W, U, Rx, k, a, phi_T=1.0):
        c = co0(p, W, U, Rx, k, a, phi_T)
        contacts.append(tuple(c) + (W, U, Rx, k, a, phi_T, p.race.Ep, p.lubricant.eta_in, p.lubricant.alpha,
                                    p.traction.tau0, p.traction.Lambda, p.traction.G))
        return c

    K.traction_mu_nb, K.traction_coefficients_nb = mu, co
    m = build_model(hsbearing.load_case("zhang2016", **{"lubricant.traction_law": "eyring"}))
    Y = np.load(states)["y"] if states else np.load(ROOT / "tests/data/regression/kernel_rhs_states.npz")["y_default"]
    Y = np.concatenate([m.y0[None, :], Y])
    P = m.P.view(np.recarray)  # attribute access to the record's fields in plain Python
    per_rhs = []
    for y in Y:
        n0, c0 = len(strips), len(contacts)
        K.rhs_kernel(y.copy(), P, m.qu, m.qw, np.empty(m.y0.size), m._contrib, m._aux, False, m._csum, m._gaux)
        per_rhs.append((len(contacts) - c0, len(strips) - n0))
    np.savez(out, contacts=np.array(contacts, dtype=float), strips=np.array(strips, dtype=float),
             per_rhs=np.array(per_rhs))


def classify(C, R):
    """Branch counts of eyring_strip_mu_nb over the strips R (contact index, S, u) with coefficients C (numpy)."""
    from hsbearing.models.traction import _kernels as kt
    from hsbearing.models.traction.eyring import SIGMA_HARD

    P, mn = kt._PAIRS, kt._PAIR_MIN
    npair = P.shape[0]
    sf_cls = {"sigma_f < 2": 0, "2 <= sigma_f <= 36": 0, "sigma_f > 36": 0}
    short = np.zeros(npair, dtype=int)
    node = {"E < 0.5": 0, "build-up tables": 0, "plastic": 0}
    all_short = 0
    for ci, S, u in R:
        Lam, r0, lv, cp, ce = C[int(ci), :5]
        s = abs(S)
        su = math.sqrt(max(1.0 - u * u, 0.0))
        tv = r0 * np.arcsinh(np.exp(np.minimum(lv + math.log(s) + cp * su * P[:, 0], 700.0)))
        g4 = 1.0 + (tv / (Lam * su * P[:, 0])) ** 4
        sf = tv * g4 / r0
        its = g4 * np.sqrt(np.sqrt(g4)) / r0
        cel = ce * s * su
        sc = cel * its * mn > (sf + kt._PLASTIC_MARGIN) * kt._PLASTIC_SAFETY * np.minimum(sf, 1.0)
        short += sc
        all_short += bool(sc.all())
        sf_cls["sigma_f < 2"] += int(np.sum(sf < 2.0))
        sf_cls["2 <= sigma_f <= 36"] += int(np.sum((sf >= 2.0) & (sf <= SIGMA_HARD)))
        sf_cls["sigma_f > 36"] += int(np.sum(sf > SIGMA_HARD))
        for j in np.flatnonzero(~sc):
            lam = math.log(math.tanh(sf[j] / 2.0)) if sf[j] <= SIGMA_HARD else 0.0
            e = cel * its[j] / (math.tanh(sf[j]) if sf[j] <= SIGMA_HARD else 1.0)
            for E in (e * P[j, 1], e * P[j, 2]):
                if E < 0.5:
                    node["E < 0.5"] += 1
                elif E - sf[j] - lam >= 40.0 and lam - sf[j] - E <= -40.0:
                    node["plastic"] += 1
                else:
                    node["build-up tables"] += 1
    return sf_cls, short, all_short, node


def main(argv=None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--rounds", type=int, default=5)
    ap.add_argument("--own-run", type=float, default=None, metavar="SPAN",
                    help="states of a run of the physical law over SPAN s instead of the regression states")
    ap.add_argument("--capture", default=None, help=argparse.SUPPRESS)
    ap.add_argument("--states", default=None, help=argparse.SUPPRESS)
    a = ap.parse_args(argv)
    if a.capture:
        capture(a.capture, a.states)
        return 0
    with tempfile.TemporaryDirectory() as tmp:
        out = os.path.join(tmp, "strips.npz")
        cmd = [sys.executable, __file__, "--capture", out]
        if a.own_run:
            np.savez(os.path.join(tmp, "states.npz"), y=own_run_states(a.own_run))
            cmd += ["--states", os.path.join(tmp, "states.npz")]
            print(f"states: 51 of a {a.own_run:g} s run of the physical law (and its y0)")
        else:
            print("states: y0 and the 51 regression states of bench_rhs_cost.py (a run of the case's own law)")
        subprocess.run(cmd, check=True, env=dict(os.environ, NUMBA_DISABLE_JIT="1"))
        d = np.load(out)
        C, R, per_rhs = d["contacts"], d["strips"], d["per_rhs"]
    import numba

    import hsbearing
    from hsbearing.models.traction import _kernels as kt

    print(f"hsbearing from {Path(hsbearing.__file__).parent}; load average at start: "
          + " ".join(f"{x:.2f}" for x in os.getloadavg()))
    pr = sorted({tuple(x) for x in per_rhs})
    print(f"{len(per_rhs)} states; per rhs (contacts, strips): {pr}; {kt._NPAIR} node pairs per strip")
    sf_cls, short, all_short, node = classify(C, R)
    npairs = len(R) * kt._NPAIR
    print(f"pairs: {npairs}; " + ", ".join(f"{k} {v} ({v / npairs:.1%})" for k, v in sf_cls.items()))
    print(f"plastic shortcut: {int(short.sum())} pairs ({short.sum() / npairs:.1%}); by pair (outer to centre) "
          f"{list(map(int, short))} of {len(R)} each; strips with every pair short-cut {all_short} of {len(R)}")
    print("nodes of the other pairs: " + ", ".join(f"{k} {v}" for k, v in node.items()))

    import inspect
    orig = kt._PLASTIC_MARGIN
    kt._PLASTIC_MARGIN = math.inf  # numba freezes the global at compile time: the strip without the shortcut
    try:
        full = numba.njit(error_model="numpy")(kt.eyring_strip_mu_nb.py_func)
        full((0.047, 6e-3, -3.5, 16.0, 50.0), 0.01, 0.0)
    finally:
        kt._PLASTIC_MARGIN = orig
    assert "_PLASTIC_MARGIN" in inspect.getsource(kt.eyring_strip_mu_nb.py_func)
    Cc = np.ascontiguousarray(C[:, :5])
    ci = R[:, 0].astype(np.int64)
    S, u = R[:, 1].copy(), R[:, 2].copy()
    fast = np.array([kt.eyring_strip_mu_nb(tuple(Cc[ci[i]]), S[i], u[i]) for i in range(len(S))])
    ref = np.array([full(tuple(Cc[ci[i]]), S[i], u[i]) for i in range(len(S))])
    print(f"kernel strip == strip without the shortcut, bit for bit, on all {len(S)} strips: {np.array_equal(fast, ref)}")

    def strip_loop(f):
        @numba.njit
        def loop(Cc, ci, S, u, reps):
            acc = 0.0
            for _ in range(reps):
                for i in range(S.shape[0]):
                    c = Cc[ci[i]]
                    acc += f((c[0], c[1], c[2], c[3], c[4]), S[i], u[i])
            return acc
        return loop

    seed = kt.coefficients_nb(0, 700.0, 16.0, 403.15, C[0, 11], C[0, 7])
    mu_nb = kt.mu_nb

    @numba.njit
    def seed_loop(Cc, ci, S, u, reps):
        acc = 0.0
        for _ in range(reps):
            for i in range(S.shape[0]):
                acc += mu_nb(seed[0], seed[1], seed[2], seed[3], S[i])
        return acc

    eyc, sdc = kt.eyring_coefficients_nb, kt.coefficients_nb

    @numba.njit
    def eyc_loop(C, reps):
        acc = 0.0
        for _ in range(reps):
            for i in range(C.shape[0]):
                acc += eyc(C[i, 5], C[i, 6], C[i, 11], C[i, 7], C[i, 8], C[i, 9], C[i, 12], C[i, 13], C[i, 14],
                           C[i, 15], C[i, 16], C[i, 10])[2]
        return acc

    @numba.njit
    def sdc_loop(C, reps):
        acc = 0.0
        for _ in range(reps):
            for i in range(C.shape[0]):
                acc += sdc(0, C[i, 5], C[i, 6], 403.15, C[i, 11], C[i, 7])[2]
        return acc

    reps_s, reps_c = 40, 200
    jobs = {"strip (kernel)": (strip_loop(kt.eyring_strip_mu_nb), (Cc, ci, S, u), reps_s, len(S)),
            "strip without the shortcut": (strip_loop(full), (Cc, ci, S, u), reps_s, len(S)),
            "seed law mu_nb": (seed_loop, (Cc, ci, S, u), reps_s, len(S)),
            "eyring coefficients (per contact)": (eyc_loop, (C,), reps_c, len(C)),
            "seed coefficients (per contact)": (sdc_loop, (C,), reps_c, len(C))}
    best = {k: math.inf for k in jobs}
    for f, args, _, _ in jobs.values():
        f(*args, 1)
    for _ in range(max(a.rounds, 1)):
        for k, (f, args, reps, n) in jobs.items():
            t0 = time.process_time()
            f(*args, reps)
            best[k] = min(best[k], (time.process_time() - t0) / (reps * n) * 1e9)
    for k, v in best.items():
        print(f"{k}: {v:.1f} ns per call (CPU best of {a.rounds})")
    ns, ncont = len(R) / len(per_rhs), len(C) / len(per_rhs)
    print(f"per rhs: strips {ns:.0f} x {best['strip (kernel)']:.0f} ns = {ns * best['strip (kernel)'] / 1e3:.1f} us "
          f"(without the shortcut {ns * best['strip without the shortcut'] / 1e3:.1f} us; seed law "
          f"{ns * best['seed law mu_nb'] / 1e3:.1f} us); coefficients {ncont:.0f} x "
          f"{best['eyring coefficients (per contact)']:.0f} ns = "
          f"{ncont * best['eyring coefficients (per contact)'] / 1e3:.1f} us (seed "
          f"{ncont * best['seed coefficients (per contact)'] / 1e3:.1f} us)")
    print("load average at end: " + " ".join(f"{x:.2f}" for x in os.getloadavg()))
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
