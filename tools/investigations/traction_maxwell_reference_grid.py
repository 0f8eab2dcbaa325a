"""The physical traction law's viscoelastic build-up against the Maxwell-Eyring equation integrated along x.

Isothermal (thermal = False in both): the law's closed form tau_f (1 - exp(-tel / tau_f)) against the numerical
solution of Johnson & Tevaarwerk's Maxwell-Eyring equation with the same flow curve
(tests/helpers/maxwell_eyring_reference.py).  Grid: oil 4106, 100 / 182 / 5000 N, 1 / 16.3 / 100 m/s, 27 / 130 /
230 degC, S = 1e-4 ... 0.3; then the default contact of 4109 and 4050.  Tolerance (docs/traction.md, written before
the grid was run): |mu_law - mu_ref| <= 0.10 |mu_ref| + 3e-4.  One line per case (markdown).

Run: PYTHONPATH=. .venv/bin/python tools/investigations/traction_maxwell_reference_grid.py  (a few minutes)

The law marches the Maxwell-Eyring equation on its own 16 cells x 5 strips (thermal.maxwell_eyring_march).  With
``--closed``: the law's former closed-form build-up tau_f (1 - exp(-tel / tau_f)) (PhysicalParameters(buildup=
"closed")) instead: 137 / 174 within, the misses at the elastic-plastic knee.
"""

from __future__ import annotations

import sys
from pathlib import Path

import numpy as np

sys.path.insert(0, str(Path(__file__).resolve().parents[2] / "tests" / "helpers"))
import maxwell_eyring_reference as mx  # noqa: E402

import hsbearing  # noqa: E402
from hsbearing.models import hertz  # noqa: E402
from hsbearing.models.traction import thermal as th  # noqa: E402

EP = 228.6e9
GEOMETRY = {100.0: (3.87e-3, 0.124), 182.0: (3.87e-3, 0.124), 5000.0: (8.5e-3, 0.35)}
SLIPS = np.array([1e-4, 1e-3, 3e-3, 0.01, 0.05, 0.3])
REL, ABS = 0.10, 3e-4


def compare(oil, W, U, T_C, S=SLIPS, closed=False):
    T = T_C + 273.15
    eta, alpha, beta, K, _ = hsbearing._oil_at(oil, T)
    Rx, Ry = GEOMETRY[W]
    c = hertz.point_contact(Rx, Ry, W, EP, 0.0, EP, 0.0)
    k, a = float(c.ellipticity), float(c.a)
    prm = th.PhysicalParameters(thermal=False)
    law_prm = prm.with_(buildup="closed") if closed else prm
    law = th.contact_mu(S, W, U, EP, Rx, k, a, T, eta, alpha, beta, K, law_prm)
    ref, info = mx.contact_mu(S, W, U, EP, Rx, k, a, T, eta, alpha, beta, prm, return_strips=True)
    # Deborah number of the centre (Johnson & Tevaarwerk): eta(p0) U / (G_eff b)
    z, S0 = th.roelands_indices(eta, alpha, beta, T)
    De = float(th.roelands_viscosity(info["p0"], T, eta, T, z, S0)) * abs(U) / (info["Ge"] * info["b"])
    return law, ref, info, De


def main():
    closed = "--closed" in sys.argv[1:]
    if closed:
        print("the law's former closed-form build-up (column 'mu law')\n")
    print("| oil | W [N] | U [m/s] | T [degC] | p0 [GPa] | De | S | mu law | mu ref | law/ref - 1 | in tol |")
    print("|---|---|---|---|---|---|---|---|---|---|---|")
    n = bad = 0
    worst = (0.0, None)
    cases = [("4106", W, U, T) for W in (182.0, 100.0, 5000.0) for U in (16.3, 1.0, 100.0) for T in (130.0, 27.0, 230.0)]
    cases += [("4109", 182.0, 16.3, 130.0), ("4050", 182.0, 16.3, 130.0)]
    for oil, W, U, T in cases:
        law, ref, info, De = compare(oil, W, U, T, closed=closed)
        for s, ml, mr in zip(SLIPS, law, ref):
            ok = abs(ml - mr) <= REL * abs(mr) + ABS
            n += 1
            bad += not ok
            r = ml / mr - 1.0
            if abs(r) > abs(worst[0]):
                worst = (r, (oil, W, U, T, s))
            print(f"| {oil} | {W:.0f} | {U:g} | {T:.0f} | {info['p0'] / 1e9:.2f} | {De:.2g} | {s:g} | {ml:.5f} | "
                  f"{mr:.5f} | {r:+.3f} | {'yes' if ok else 'NO'} |", flush=True)
    print(f"\n{n - bad} / {n} within the tolerance; largest relative deviation {worst[0]:+.3f} at {worst[1]}")


if __name__ == "__main__":
    main()
