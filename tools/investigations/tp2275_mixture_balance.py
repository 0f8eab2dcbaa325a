"""The NASA TP-2275 bearings with the mixture co-rotation from the cavity mixture's angular-momentum balance
(``friction.mixture_corotation_law = "balance"``) against their measured heat generation: k(n) and its band, loss by
source, ratio to the measurement at each speed, speed exponents.  The table of docs/power_loss.md, "The mixture's
momentum balance: the TP-2275 bearings".

PROVENANCE: as tools/investigations/tp2275_heat_by_source.py (35-mm: third-party digitisation of TP-2275, geometry
partly assumed; 120-mm: the same third party's tables, 25 deg there and 20 deg in the abstract of the 120-mm study,
both run; every other 120-mm dimension scaled from the 35-mm reconstruction, ASSUMED).

Nothing is fitted: the balance's inputs (wall laws, throughflow, side openings, C_D) are textbook laws or bands fixed
before these data were compared; both bearings validate, none calibrates.

Usage: PYTHONPATH=. python tools/investigations/tp2275_mixture_balance.py   (~3 min on the shared machine)
       PYTHONPATH=. python tools/investigations/tp2275_mixture_balance.py --sensitivity   (the balance's sensitivity
       to the wall law, the cage's surfaces and an oil recirculation, 35-mm, ~30 s)
"""

from __future__ import annotations

import math
import sys
from pathlib import Path

import numpy as np

sys.path.insert(0, str(Path(__file__).resolve().parent))

from tp2275_heat_by_source import MEASURED_120, case_120  # noqa: E402
from tp2275_power_loss import CASE, MEASURED  # noqa: E402

from hsbearing.case import loads_case  # noqa: E402
from hsbearing.systems.angular_contact.rating import quasi_static_power_loss  # noqa: E402

CONTACT = ("race_traction", "ehl_rolling", "pocket_film", "guide_land")


def exponent(ns, ys):
    return float(np.polyfit(np.log(ns), np.log(ys), 1)[0])


def report(title, case, measured):
    bal_case = case.with_overrides(**{"friction.mixture_corotation_law": "balance"})
    ns = sorted(measured)
    meas = np.array([measured[n] for n in ns])
    print(f"\n## {title}")
    print("| n [r/min] | measured [W] | k balance (band) | contacts* [W] | ball drag [W] | ring surface [W] | cage surfaces [W] "
          "| total balance [W] (ratio) | churning band [W] | total band [W] (ratio) | total k = 0 [W] (ratio) |")
    print("|" + "---|" * 11)
    cols = {k: [] for k in ("bal", "lo", "hi", "k0", "contacts", "churn", "ball", "churn_k0")}
    cage_note = set()
    for n, m in zip(ns, meas):
        w = n * math.pi / 30
        b = quasi_static_power_loss(bal_case, w)
        f = quasi_static_power_loss(case, w, bands=False)
        contacts = sum(b[s] for s in CONTACT)
        ball = b["drag"] - b["drag_ring_share"]
        rest = b["power_loss"] - b["drag"]
        lo, hi = rest + b["drag_balance_band_low"], rest + b["drag_balance_band_high"]
        for key, val in (("bal", b["power_loss"]), ("lo", lo), ("hi", hi), ("k0", f["power_loss"]), ("contacts", contacts),
                         ("churn", b["drag"]), ("ball", ball), ("churn_k0", f["drag"] + f["jet_oil_acceleration"])):
            cols[key].append(val)
        cage_note.add(b["mixture_balance_cage"])
        print(f"| {n} | {m:.0f} | {b['mixture_corotation']:.3f} ({b['mixture_corotation_balance_low']:.3f}.."
              f"{b['mixture_corotation_balance_high']:.3f}) | {contacts:.0f} | {ball:.1f} | {b['drag_ring_share']:.1f} | "
              f"{b['cage_windage']:.1f} | {b['power_loss']:.0f} ({b['power_loss'] / m:.2f}) | "
              f"{b['drag_balance_band_low']:.0f}..{b['drag_balance_band_high']:.0f} | {lo:.0f}..{hi:.0f} "
              f"({lo / m:.2f}..{hi / m:.2f}) | {f['power_loss']:.0f} ({f['power_loss'] / m:.2f}) |")
    e = {key: exponent(ns, v) for key, v in cols.items()}
    print(f"| speed exponent | {exponent(ns, meas):.2f} | | {e['contacts']:.2f} | {e['ball']:.2f} | | | {e['bal']:.2f} | "
          f"churning {e['churn']:.2f} (k = 0: drag + jet {e['churn_k0']:.2f}) | {e['lo']:.2f}..{e['hi']:.2f} | {e['k0']:.2f} |")
    print("(* contacts = race traction + EHL rolling + pocket film + guide land; churning = ball drag + ring surface; "
          "with the balance the jet-oil term is inside the churning (throughflow); band: side openings as stationary "
          "walls or not x air throughflow 0 or the inner ring's free-disc pumping x C_D subcritical or crisis; "
          f"cage surfaces = the cage windage with the balance on: {'; '.join(sorted(cage_note))})")


def sensitivity(case, speeds=(28000, 72000)):
    """The balance's k and churning (balls + ring surface) at the 35-mm quasi-static inputs with the wall moments and
    the throughflow scaled: how far the unsourced wall law and an oil recirculation (drops stripped on the outer ring
    and re-entrained, a throughflow N times the supply) move k, the churning and its speed exponent.  Not a fit:
    no factor is chosen, the table shows what each would do."""
    from hsbearing.models.ball_bearing import churning
    from hsbearing.models.ball_bearing.drag import ball_drag_coefficient
    from hsbearing.systems.angular_contact.dynamics import build_model

    b, lub = case.bearing, case.lubricant
    r_m = 0.5 * b.pitch_diameter
    inputs = []
    for n in speeds:
        w = n * math.pi / 30
        m = build_model(case.with_overrides(**{"operating.inner_speed": f"{w} rad/s"}))
        inputs.append((w, *(float(m.info[x]) for x in ("drag_orbital_speed", "drag_density", "drag_viscosity"))))
    c = case.cage
    cage = {"r_bore": 0.5 * c.bore_diameter, "r_outside": 0.5 * c.outside_diameter, "width": c.width,
            "guidance": c.guidance}
    print("\n## Sensitivity of the balance (35-mm; wall moments x f via the wall and cage lengths, throughflow x N; "
          "churning = balls + ring surface + cage surfaces)")
    print("| variant | " + " | ".join(f"k at {n} | churning at {n} [W]" for n in speeds) + " | churning exponent |")
    print("|" + "---|" * (2 * len(speeds) + 2))
    for label, f, N, law, with_cage in (
            ("nominal (full-gap wall law, cage surfaces)", 1, 1, "full_gap", True),
            ("full-gap wall law, no cage", 1, 1, "full_gap", False),
            ("former half-gap wall law, no cage (before)", 1, 1, "half_gap", False),
            ("walls x 0.5 (our mixing-length level)", 0.5, 1, "full_gap", True), ("walls x 2", 2, 1, "full_gap", True),
            ("throughflow x 3", 1, 3, "full_gap", True), ("throughflow x 10", 1, 10, "full_gap", True),
            ("throughflow x 20", 1, 20, "full_gap", True)):
        ks, Ps = [], []
        for w, v, rho, mu in inputs:
            res = churning.mixture_momentum_balance(
                Z=b.ball_count, D=b.ball_diameter, r_m=r_m, r_i=0.5 * b.inner_land_diameter,
                r_o=0.5 * b.outer_land_diameter, length=f * b.width, omega_i=w, omega_o=0.0, omega_c=v / r_m,
                rho_e=rho, mu_e=mu, drag_coefficient=lambda x, rho=rho, mu=mu: ball_drag_coefficient(rho, mu, x, b.ball_diameter)[0],
                mass_flow=N * lub.density * lub.oil_flow_rate, wall_law=law,
                cage={**cage, "width": f * cage["width"]} if with_cage else None)
            ks.append(res["k"])
            Ps.append(res["P_balls"] + res["P_inner"] + res["P_cage"])
        print(f"| {label} | " + " | ".join(f"{k:.3f} | {P:.1f}" for k, P in zip(ks, Ps)) + f" | {exponent(list(speeds), Ps):.2f} |")


def main():
    if "--sensitivity" in sys.argv:
        sensitivity(loads_case(CASE.replace("{fraction}", "")))
        return
    report("35-mm bore (16 x 7.14 mm, d_m 46.5 mm, 24 deg, 667 N, 760 cm^3/min, oil in 394 K)",
           loads_case(CASE.replace("{fraction}", "")), MEASURED)
    for a in (25.0, 20.0):
        report(f"120-mm bore (15 x 20.64 mm, d_m 160 mm, {a:g} deg, 2224 N, 2280 cm^3/min, oil in 394 K)", case_120(a),
               MEASURED_120)


if __name__ == "__main__":
    main()
