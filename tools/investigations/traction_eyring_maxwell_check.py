"""The kernel's isothermal law "eyring" against the Maxwell-Eyring equation integrated along the streamlines.

"eyring" (hsbearing.models.traction.eyring: Barus viscosity, tau0 = 2 Lambda / alpha constant, at 5 strips x N_MINOR
Gauss nodes; the build-up eyring.maxwell_eyring_buildup, the exact solution of the Maxwell-Eyring equation with each
point's flow properties held along its path) and, for comparison, the closed-form linear Maxwell build-up
tau_f (1 - exp(-tel / tau_f)) it had before (``buildup="closed"``), against tests/helpers/maxwell_eyring_reference.py
with the same rheology (PhysicalParameters(thermal=False, pressure_viscosity="barus", eyring_temperature="constant"):
the same b, p0, h, G_eff, tau0 and Lambda), Johnson & Tevaarwerk's equation integrated to convergence (n_x = 400
Richardson, 16 Gauss strips).  Contacts: the default case's inner contact (182 N, 16.3 m/s, 130 degC) of 4109, 4106,
4050, and four 4106 cases of the physical law's grid.  Tolerance of the physical law's check: 10 % + 3e-4.

Run: PYTHONPATH=. .venv/bin/python tools/investigations/traction_eyring_maxwell_check.py  (about a minute)
     ... traction_eyring_maxwell_check.py --grid  (the whole grid of the physical law's check: 4106 at 100 / 182 /
     5000 N x 1 / 16.3 / 100 m/s x 27 / 130 / 230 degC and the default contacts of 4109 and 4050; a few minutes)
"""

from __future__ import annotations

import sys
from pathlib import Path

import numpy as np

sys.path.insert(0, str(Path(__file__).resolve().parents[2] / "tests" / "helpers"))
import maxwell_eyring_reference as mx  # noqa: E402

import hsbearing  # noqa: E402
from hsbearing.models import hertz  # noqa: E402
from hsbearing.models.traction import eyring as ey  # noqa: E402
from hsbearing.models.traction import thermal as th  # noqa: E402

EP = 228.6e9
GEOMETRY = {100.0: (3.87e-3, 0.124), 182.0: (3.87e-3, 0.124), 5000.0: (8.5e-3, 0.35)}
SLIPS = np.array([1e-4, 1e-3, 3e-3, 0.01, 0.05, 0.3])
REL, ABS = 0.10, 3e-4
CASES = [("4109", 182.0, 16.3, 130.0), ("4106", 182.0, 16.3, 130.0), ("4050", 182.0, 16.3, 130.0),
         ("4106", 5000.0, 16.3, 130.0), ("4106", 100.0, 100.0, 27.0), ("4106", 182.0, 1.0, 230.0),
         ("4106", 182.0, 100.0, 130.0)]
GRID = CASES[:3] + [("4106", W, U, T) for W in (182.0, 100.0, 5000.0) for U in (16.3, 1.0, 100.0)
                    for T in (130.0, 27.0, 230.0) if (W, U, T) != (182.0, 16.3, 130.0)]


def main():
    prm = th.PhysicalParameters(thermal=False, pressure_viscosity="barus", eyring_temperature="constant")
    print("| oil | W [N] | U [m/s] | T [degC] | S | mu eyring | mu closed form | mu ref | eyring/ref - 1 | closed/ref - 1 "
          "| in tol (eyring, closed) |")
    print("|---|---|---|---|---|---|---|---|---|---|---|")
    n = bad = bad_closed = 0
    worst = 0.0
    for oil, W, U, T_C in (GRID if "--grid" in sys.argv[1:] else CASES):
        T = T_C + 273.15
        eta, alpha, beta, K, _ = hsbearing._oil_at(oil, T)
        Rx, Ry = GEOMETRY[W]
        c = hertz.point_contact(Rx, Ry, W, EP, 0.0, EP, 0.0)
        k, a = float(c.ellipticity), float(c.a)
        tau0 = ey.eyring_stress_default(ey.DEFAULT_LAMBDA, alpha)
        args = (W, U, EP, Rx, k, a, eta, alpha, tau0, ey.DEFAULT_LAMBDA, ey.DEFAULT_SHEAR_MODULUS)
        law = ey.contact_mu(SLIPS, *args)
        closed = ey.contact_mu(SLIPS, *args, buildup="closed")
        if W == 182.0 and U == 16.3:  # the registry's "eyring" at the default contact is this law
            reg = hsbearing.traction_coefficient(oil, SLIPS, W, U, T, Rx, Ry, EP, law="eyring")
            assert np.allclose(reg, law, rtol=1e-9), (reg, law)
        ref = mx.contact_mu(SLIPS, W, U, EP, Rx, k, a, T, eta, alpha, beta, prm)
        for s, ml, mc, mr in zip(SLIPS, law, closed, ref):
            tol = REL * abs(mr) + ABS
            ok, okc = abs(ml - mr) <= tol, abs(mc - mr) <= tol
            n += 1
            bad += not ok
            bad_closed += not okc
            worst = max(worst, abs(ml - mr) / tol)
            print(f"| {oil} | {W:.0f} | {U:g} | {T_C:.0f} | {s:g} | {ml:.5f} | {mc:.5f} | {mr:.5f} | {ml / mr - 1:+.3f} | "
                  f"{mc / mr - 1:+.3f} | {'yes' if ok else 'NO'}, {'yes' if okc else 'NO'} |", flush=True)
    print(f"\neyring: {n - bad} / {n} within 10 % + 3e-4 (largest use of the tolerance {worst:.2f}); "
          f"closed-form build-up: {n - bad_closed} / {n}")


if __name__ == "__main__":
    main()
