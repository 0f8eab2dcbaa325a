"""Cost of one strip of the physical traction model's integrand, in a compiled loop: ns per strip.

Usage (run it with each checkout first on the path to compare, alternating, in one sitting)::

    PYTHONPATH=<checkout> .venv/bin/python benchmarks/bench_strip_integrand.py [--rounds 7] [--mode grouped]

Times, per strip evaluation: the kernel's ``_kernels.eyring_strip_mu_nb`` (what the rhs calls), its exact twin
``eyring_strip_mu_exact_nb`` (libm at every node) and the seed law's ``mu_nb`` (4109 coefficients), each in its own
``numba.njit`` loop over the same 20 000 (contact, slip, strip) samples, CPU time best of ``--rounds`` alternated
rounds.  The samples cover the regime of tests/models/test_traction_tables.py: the bundled oils 4109/4106/4050 at
27-230 degC, 100-5000 N, 1-100 m/s, slide-roll 1e-4 ... 0.3 both signs; ``--mode grouped`` (default) takes five
strips per contact with slips spread +-50 % about a centre (spin), as the rhs visits them, ``--mode random``
draws every sample independently (more branch mispredictions and table misses).  Also prints the largest relative
difference of the kernel's function from the exact twin over the samples.  Uses only names that exist since the
tabulated integrand, so it runs unchanged on older checkouts.  The load average is printed beside the numbers.
"""

from __future__ import annotations

import argparse
import math
import os
import time

import numpy as np


def main(argv=None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--rounds", type=int, default=7)
    ap.add_argument("--mode", choices=("grouped", "random"), default="grouped")
    ap.add_argument("--n", type=int, default=20000)
    a = ap.parse_args(argv)
    import numba

    import hsbearing
    from hsbearing.lubricant import bundled_path, load_lubricant
    from hsbearing.models.ball_bearing.ball import strip_load_weights
    from hsbearing.models.traction import _kernels as kt
    from hsbearing.models.traction import eyring as ey

    print(f"hsbearing from {os.path.dirname(hsbearing.__file__)}; load average at start: "
          + " ".join(f"{x:.2f}" for x in os.getloadavg()))
    Ep, Rx, k, ac = 2.2857142857e11, 3.8687463e-3, 9.2314187, 9.3449073e-4 / 300.0 ** (1.0 / 3.0)  # inner contact
    rows = []
    for oil in ("4109", "4106", "4050"):
        lub = load_lubricant(bundled_path(oil))
        for T_C in (27.0, 80.0, 130.0, 230.0):
            T = T_C + 273.15
            eta, alpha = lub.dynamic_viscosity(T, 960.0), lub.alpha(T, 960.0)
            tau0 = ey.eyring_stress_default(ey.DEFAULT_LAMBDA, alpha)
            for W in (100.0, 300.0, 700.0, 2000.0, 5000.0):
                for U in (1.0, 5.0, 16.0, 40.0, 100.0):
                    rows.append(kt.eyring_coefficients_nb(W, U, Ep, Rx, k, ac * W ** (1.0 / 3.0), eta, alpha, tau0,
                                                          ey.DEFAULT_LAMBDA, ey.DEFAULT_SHEAR_MODULUS))
    C = np.array(rows)
    qu, _ = strip_load_weights(5)
    rng = np.random.default_rng(1)
    n = a.n - a.n % 5
    sgn = rng.choice([-1.0, 1.0], n)
    if a.mode == "random":
        Cs = C[rng.integers(0, len(C), n)]
        S = np.exp(rng.uniform(math.log(1e-4), math.log(0.3), n)) * sgn
        u = qu[rng.integers(0, qu.size, n)]
    else:
        Cs = C[np.repeat(rng.integers(0, len(C), n // 5), 5)]
        S = np.repeat(np.exp(rng.uniform(math.log(1e-4), math.log(0.3), n // 5)) * sgn[::5], 5)
        S = S * (1.0 + 0.5 * rng.uniform(-1.0, 1.0, n))
        u = np.tile(qu, n // 5)
    Cs = np.ascontiguousarray(Cs)
    seed = kt.coefficients_nb(0, 700.0, 16.0, 403.15, Ep, Rx)

    def loop_of(f, seed_law):
        @numba.njit
        def loop(Cs, S, u, reps):
            acc = 0.0
            for _ in range(reps):
                for i in range(S.shape[0]):
                    if seed_law:
                        acc += f(seed[0], seed[1], seed[2], seed[3], S[i])
                    else:
                        acc += f((Cs[i, 0], Cs[i, 1], Cs[i, 2], Cs[i, 3], Cs[i, 4]), S[i], u[i])
            return acc
        return loop

    loops = {"eyring_strip_mu_nb": loop_of(kt.eyring_strip_mu_nb, False),
             "eyring_strip_mu_exact_nb": loop_of(kt.eyring_strip_mu_exact_nb, False),
             "seed mu_nb": loop_of(kt.mu_nb, True)}
    fast = np.array([kt.eyring_strip_mu_nb(tuple(Cs[i]), S[i], u[i]) for i in range(n)])
    exact = np.array([kt.eyring_strip_mu_exact_nb(tuple(Cs[i]), S[i], u[i]) for i in range(n)])
    print(f"{n} samples ({a.mode}); max |mu - mu_exact| / |mu_exact| = {np.max(np.abs(fast - exact) / np.abs(exact)):.2e}")
    for f in loops.values():
        f(Cs, S, u, 1)
    best = dict.fromkeys(loops, math.inf)
    for _ in range(a.rounds):
        for name, f in loops.items():
            t0 = time.process_time()
            f(Cs, S, u, 5)
            best[name] = min(best[name], (time.process_time() - t0) / (5 * n))
    for name, t in best.items():
        print(f"{name:26s} {t * 1e9:7.1f} ns per strip (CPU, best of {a.rounds})")
    print("load average at end: " + " ".join(f"{x:.2f}" for x in os.getloadavg()))
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
