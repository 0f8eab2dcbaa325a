"""phi_T of models/ehl.py (Gupta et al. 1992) and the Murch & Wilson curve against our own thermal inlet solution.

Run: ``PYTHONPATH=. python tools/investigations/thermal_inlet_comparison.py [--quick | --full-dissipation]``

Grid (docs/power_loss.md, "Inlet heating: proof against our own thermal inlet"): oils 4109/4106/4050 at 27, 130,
230 degC (viscosity and its slope beta = -d ln eta / dT from the Walther law, density 920 kg/m^3 as in
tests/models/test_inlet_heating.py; conductivity K from Table 1 of Zhang et al. 2016), entrainment 1, 10, 30, 100
m/s, p_h 0.5 and 3 GPa, slide-roll 0 and 0.3; line contact of the same p_h, R = 4 mm, E' = 2.26e11 Pa,
b = 4 R p_h / E'.  The reference is tests/helpers/thermal_inlet_reference.py (Ertel-Grubin inlet).
"""

from __future__ import annotations

import math
import sys

sys.path.insert(0, "tests/helpers")

import numpy as np  # noqa: E402
import thermal_inlet_reference as ref  # noqa: E402

from hsbearing.models import ehl  # noqa: E402
from hsbearing.models.traction import OILS  # noqa: E402
from hsbearing.models.viscosity import dynamic_viscosity  # noqa: E402

R, EP, RHO = 4.0e-3, 2.26e11, 920.0
TEMPS_C = (27.0, 130.0, 230.0)
SPEEDS = (1.0, 10.0, 30.0, 100.0)
PRESSURES = (0.5e9, 3.0e9)
SLIPS = (0.0, 0.3)


def eta_beta(oil, T):
    """Walther viscosity [Pa s] and its slope beta = -d ln eta / dT [1/K] (central difference over +-1 K)."""
    eta = float(dynamic_viscosity(oil, T, density=RHO))
    beta = -0.5 * math.log(float(dynamic_viscosity(oil, T + 1.0, density=RHO)) /
                           float(dynamic_viscosity(oil, T - 1.0, density=RHO)))
    return eta, beta


def case_row(oil, Tc, u, ph, s, n=64):
    o = OILS[oil]
    eta, beta = eta_beta(oil, Tc + 273.15)
    b = 4.0 * R * ph / EP
    res = ref.thermal_ratio(eta, o.alpha, beta, o.K, u, s, R, b, n=n)
    L = res["L"]
    phi = float(ehl.thermal_reduction_factor(ehl.thermal_loading_parameter(eta, beta, u, o.K), ph, EP, s))
    return {"oil": oil, "T_C": Tc, "u": u, "p_h": ph, "s": s, "L": L, "h_iso": res["h_iso"],
            "reference": res["ratio"], "phi_T": phi, "murch_wilson": float(ref.murch_wilson_curve(L)),
            "err_phi_T": phi / res["ratio"] - 1.0}


def grid(quick=False):
    oils = ("4109",) if quick else tuple(OILS)
    rows = []
    for oil in oils:
        for Tc in TEMPS_C:
            for u in SPEEDS:
                for ph in PRESSURES:
                    for s in SLIPS:
                        rows.append(case_row(oil, Tc, u, ph, s))
    return rows


def full_dissipation_table():
    """The two readings of the dissipation against phi_T and the Murch-Wilson curve (docs/power_loss.md): line
    contact R = 4 mm, u = 10 m/s, alpha = 1.3e-8 /Pa, beta = 0.03 /K, k = 0.1 W/(m K), eta0 set by L."""
    u, alpha, beta, k = 10.0, 1.3e-8, 0.03, 0.1
    print("| p_h [GPa] | s | L | reference, reduced dissipation | reference, full dissipation (cap reached) | "
          "phi_T (ehl, Gupta) | Murch-Wilson |")
    print("|---|---|---|---|---|---|---|")
    for ph in (0.5e9, 3.0e9):
        b = 4.0 * R * ph / EP
        for s in (0.0, 0.3):
            for L in (1.0, 10.0, 100.0):
                eta0 = L * k / (beta * u * u)
                try:
                    res = ref.full_dissipation_ratio(eta0, alpha, beta, k, u, s, R, b, ph, nv=200)
                    fd = f"{res['ratio']:.3f} ({'yes' if res['capped'] else 'no'})"
                except RuntimeError:
                    fd = "no solution"
                red = ref.thermal_ratio(eta0, alpha, beta, k, u, s, R, b, n=64)["ratio"]
                phi = float(ehl.thermal_reduction_factor(L, ph, EP, s))
                print(f"| {ph / 1e9:.1f} | {s:.1f} | {L:g} | {red:.3f} | {fd} | {phi:.3f} | "
                      f"{float(ref.murch_wilson_curve(L)):.3f} |", flush=True)


def main(argv=None):
    args = argv or sys.argv[1:]
    if "--full-dissipation" in args:
        full_dissipation_table()
        return
    quick = "--quick" in args
    rows = grid(quick)
    print("| oil | T [degC] | u [m/s] | p_h [GPa] | s | L | h_iso [nm] | reference | phi_T (ehl) | error | Murch-Wilson |")
    print("|---|---|---|---|---|---|---|---|---|---|---|")
    for r in rows:
        print(f"| {r['oil']} | {r['T_C']:.0f} | {r['u']:.0f} | {r['p_h'] / 1e9:.1f} | {r['s']:.1f} | {r['L']:.3g} | "
              f"{r['h_iso'] * 1e9:.1f} | {r['reference']:.3f} | {r['phi_T']:.3f} | {100 * r['err_phi_T']:+.1f} % | "
              f"{r['murch_wilson']:.3f} |", flush=True)
    err = np.array([r["err_phi_T"] for r in rows])
    print(f"phi_T / reference - 1: min {100 * err.min():+.1f} %, max {100 * err.max():+.1f} %; "
          f"within 10 %: {int((np.abs(err) <= 0.10).sum())} of {err.size}")


if __name__ == "__main__":
    main()
