"""Loss by source of the NASA TP-2275 bearings against their measured heat generation, before -> after the churning
terms (mixture co-rotation, jet-oil acceleration, cage windage), with the drag band.  The table of docs/power_loss.md,
"Drag band, jet-oil acceleration, cage windage: the TP-2275 bearings".

PROVENANCE: as tools/investigations/tp2275_power_loss.py (35-mm) -- third-party digitisation of TP-2275, geometry
partly assumed.  120-mm: the same third party's tables (github.com/YUXinluhk/BallBearing-Dynamics paper/manuscript.tex,
"NASA TP-2275 test bearing parameters", "Selected NASA TP-2275 experimental measurements"; inputs/NASA_120mm_*.toml:
2224 N, 2280 cm^3/min, oil in 394 K): 15 balls of 20.64 mm, d_m 160 mm, contact angle 25 deg there, but 20 deg in the
abstract of the 120-mm jet-lubrication study of the same group (ASME J. Lubr. Technol. 98 (1976) 32) -- both run.
Every other 120-mm dimension is the 35-mm reconstruction's proportions scaled by the ball diameter (ASSUMED).

Nothing is fitted: no constant of any law is chosen from these data; all of them validate, none calibrates.

Usage: PYTHONPATH=. python tools/investigations/tp2275_heat_by_source.py
"""

from __future__ import annotations

import math
import sys
from pathlib import Path

import numpy as np

sys.path.insert(0, str(Path(__file__).resolve().parent))

from tp2275_power_loss import CASE, MEASURED  # noqa: E402

from hsbearing.case import loads_case  # noqa: E402
from hsbearing.systems.angular_contact.rating import quasi_static_power_loss  # noqa: E402

#: 120-mm bearing, measured heat [W] at shaft speed [r/min] (third-party digitisation, above)
MEASURED_120 = {5000: 2500.0, 8000: 4800.0, 12000: 8800.0}


def case_120(contact_angle_deg: float):
    D = 20.64
    s = CASE.replace("{fraction}", "")
    for old, new in (
        ('name = "nasa_tp2275_35mm"', 'name = "nasa_tp2275_120mm"'),
        ("ball_count = 16 ", "ball_count = 15 "), ('ball_diameter = "7.14 mm"', f'ball_diameter = "{D} mm"'),
        ('pitch_diameter = "46.5 mm"', 'pitch_diameter = "160 mm"'),
        ('contact_angle = "24 deg"', f'contact_angle = "{contact_angle_deg:g} deg"'),
        ('bore_diameter = "35 mm"', 'bore_diameter = "120 mm"'), ('outside_diameter = "58 mm"', 'outside_diameter = "200 mm"'),
        ('width = "13 mm"', f'width = "{13 / 7.14 * D:.4g} mm"'),
        ('outer_land_diameter = "51.2 mm"', f'outer_land_diameter = "{160 + 4.7 / 7.14 * D:.5g} mm"'),
        ('inner_land_diameter = "40.9 mm"', f'inner_land_diameter = "{160 - 0.787 * D:.5g} mm"'),
        ('outside_diameter = "51.0 mm"', f'outside_diameter = "{160 + 0.63 * D:.5g} mm"'),
        ('bore_diameter = "45.3 mm"', f'bore_diameter = "{160 - 0.168 * D:.5g} mm"'),
        ('width = "8.25 mm"', f'width = "{1.155 * D:.4g} mm"'), ('pocket_diameter = "7.215 mm"', f'pocket_diameter = "{1.0105 * D:.5g} mm"'),
        ('oil_flow_rate = "760 cm^3/min"', 'oil_flow_rate = "2280 cm^3/min"'),
        ('inner_speed = "72000 rpm"', 'inner_speed = "12000 rpm"'), ('axial_load = "667 N"', 'axial_load = "2224 N"'),
    ):
        assert old in s, old
        s = s.replace(old, new, 1)
    return loads_case(s)


CONTACT = ("race_traction", "ehl_rolling", "pocket_film", "guide_land")


def rows_for(case, measured):
    """[(n, before, after, at_couette)] of quasi_static_power_loss dicts."""
    out = []
    for n in sorted(measured):
        w = n * math.pi / 30
        before = quasi_static_power_loss(case.with_overrides(**{"friction.cavity_losses": "off"}), w)
        after = quasi_static_power_loss(case, w)
        kc = after["mixture_corotation_couette"]
        at_kc = quasi_static_power_loss(case.with_overrides(**{"friction.mixture_corotation": f"{kc:.6g}"}), w)
        out.append((n, before, after, at_kc))
    return out


def exponent(ns, ys):
    return float(np.polyfit(np.log(ns), np.log(ys), 1)[0])


def report(title, case, measured):
    rows = rows_for(case, measured)
    ns = [r[0] for r in rows]
    meas = np.array([measured[n] for n in ns])
    print(f"\n## {title}")
    print("| n [r/min] | measured [W] | contacts* [W] | drag before [W] | total before [W] (ratio) | jet m_dot v^2 [W] | "
          "cage windage [W] | total after [W] (ratio) | drag band [W] | total band [W] (ratio) | k_C | total at k_C, C_D subcrit. [W] (ratio) |")
    print("|" + "---|" * 12)
    cols = {"before": [], "after": [], "lo": [], "hi": [], "kc": [], "contacts": [], "drag": []}
    for (n, b, a, k), m in zip(rows, meas):
        contacts = sum(a[s] for s in CONTACT)
        rest = a["power_loss"] - a["drag"]
        lo, hi = rest + a["drag_band_low"], rest + a["drag_band_high"]
        for key, val in (("before", b["power_loss"]), ("after", a["power_loss"]), ("lo", lo), ("hi", hi),
                         ("kc", k["power_loss"]), ("contacts", contacts), ("drag", b["drag"])):
            cols[key].append(val)
        print(f"| {n} | {m:.0f} | {contacts:.0f} | {b['drag']:.0f} | {b['power_loss']:.0f} ({b['power_loss'] / m:.2f}) | "
              f"{a['jet_oil_acceleration']:.1f} | {a['cage_windage']:.1f} | {a['power_loss']:.0f} ({a['power_loss'] / m:.2f}) | "
              f"{a['drag_band_low']:.0f}..{a['drag_band_high']:.0f} | {lo:.0f}..{hi:.0f} ({lo / m:.2f}..{hi / m:.2f}) | "
              f"{a['mixture_corotation_couette']:.3f} | {k['power_loss']:.0f} ({k['power_loss'] / m:.2f}) |")
    e = {key: exponent(ns, v) for key, v in cols.items()}
    print(f"| speed exponent | {exponent(ns, meas):.2f} | {e['contacts']:.2f} | {e['drag']:.2f} | {e['before']:.2f} | | | "
          f"{e['after']:.2f} | | {e['lo']:.2f}..{e['hi']:.2f} | | {e['kc']:.2f} |")
    print("(* contacts = race traction + EHL rolling + pocket film + guide land; X, Re, C_D: "
          + "; ".join(f"{r[0]}: {r[2]['cavity_oil_fraction']:.3g}, {r[2]['drag_reynolds_number']:.3g}, {r[2]['drag_coefficient']:.3g}"
                      for r in rows) + ")")
    return rows


def main():
    report("35-mm bore (16 x 7.14 mm, d_m 46.5 mm, 24 deg, 667 N, 760 cm^3/min, oil in 394 K)",
           loads_case(CASE.replace("{fraction}", "")), MEASURED)
    for a in (25.0, 20.0):
        report(f"120-mm bore (15 x 20.64 mm, d_m 160 mm, {a:g} deg, 2224 N, 2280 cm^3/min, oil in 394 K)", case_120(a), MEASURED_120)


if __name__ == "__main__":
    main()
