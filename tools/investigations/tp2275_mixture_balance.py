"""The NASA TP-2275 bearings with the mixture co-rotation from the cavity mixture's angular-momentum balance
(``friction.mixture_corotation_law = "balance"``) against their measured heat generation: k(n) and its band, loss by
source, ratio to the measurement at each speed, speed exponents.  The table of docs/power_loss.md, "The mixture's
momentum balance: the TP-2275 bearings".

PROVENANCE: as tools/investigations/tp2275_heat_by_source.py (35-mm: third-party digitisation of TP-2275, geometry
partly assumed; 120-mm: the same third party's tables, 25 deg there and 20 deg in the abstract of the 120-mm study,
both run; every other 120-mm dimension scaled from the 35-mm reconstruction, ASSUMED).

Nothing is fitted: the balance's inputs (wall laws, throughflow, side openings, C_D) are textbook laws or bands fixed
before these data were compared; both bearings validate, none calibrates.

Usage: PYTHONPATH=. python tools/investigations/tp2275_mixture_balance.py   (~2 min on the shared machine)
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
    print("| n [r/min] | measured [W] | k balance (band) | contacts* [W] | ball drag [W] | ring surface [W] | cage windage [W] "
          "| total balance [W] (ratio) | churning band [W] | total band [W] (ratio) | total k = 0 [W] (ratio) |")
    print("|" + "---|" * 11)
    cols = {k: [] for k in ("bal", "lo", "hi", "k0", "contacts", "churn", "ball", "churn_k0")}
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
          "walls or not x air throughflow 0 or the inner ring's free-disc pumping x C_D subcritical or crisis)")


def main():
    report("35-mm bore (16 x 7.14 mm, d_m 46.5 mm, 24 deg, 667 N, 760 cm^3/min, oil in 394 K)",
           loads_case(CASE.replace("{fraction}", "")), MEASURED)
    for a in (25.0, 20.0):
        report(f"120-mm bore (15 x 20.64 mm, d_m 160 mm, {a:g} deg, 2224 N, 2280 cm^3/min, oil in 394 K)", case_120(a),
               MEASURED_120)


if __name__ == "__main__":
    main()
