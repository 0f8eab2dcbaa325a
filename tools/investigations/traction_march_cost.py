"""Cost of the physical traction law per contact: the closed-form build-up against the Maxwell-Eyring march.

thermal.contact_mu (5 strips x 16 cells, thermal fixed point) at the default case's inner contact (182 N, 16.3 m/s,
130 degC, p0 1.28 GPa) of 4109, 4106 and 4050, slips 1e-3, 3e-3, 0.05, 0.3; wall time per contact and slip, the
best of 3 repeats (the machine is shared: the best is the least disturbed), thermal and isothermal.

Run: PYTHONPATH=. .venv/bin/python tools/investigations/traction_march_cost.py  (about a minute)
"""

from __future__ import annotations

import time

import numpy as np

import hsbearing
from hsbearing.models import hertz
from hsbearing.models.traction import thermal as th

EP, RX, RY, W, U, T = 228.6e9, 3.87e-3, 0.124, 182.0, 16.3, 403.15
SLIPS = np.array([1e-3, 3e-3, 0.05, 0.3])


def main():
    c = hertz.point_contact(RX, RY, W, EP, 0.0, EP, 0.0)
    k, a = float(c.ellipticity), float(c.a)
    th.contact_mu(0.01, W, U, EP, RX, k, a, T, *hsbearing._oil_at("4106", T)[:4])  # imports, warm-up
    print("| oil | heat | closed form [ms] | march [ms] | ratio |")
    print("|---|---|---|---|---|")
    for oil in ("4109", "4106", "4050"):
        eta, alpha, beta, K, _ = hsbearing._oil_at(oil, T)
        for thermal in (True, False):
            out = []
            for buildup in ("closed", "march"):
                prm = th.PhysicalParameters(thermal=thermal, buildup=buildup)
                best = np.inf
                for _ in range(3):
                    t0 = time.perf_counter()
                    th.contact_mu(SLIPS, W, U, EP, RX, k, a, T, eta, alpha, beta, K, prm)
                    best = min(best, (time.perf_counter() - t0) / len(SLIPS))
                out.append(best * 1e3)
            print(f"| {oil} | {'thermal' if thermal else 'isothermal'} | {out[0]:.1f} | {out[1]:.1f} | "
                  f"{out[1] / out[0]:.2f} |", flush=True)


if __name__ == "__main__":
    main()
