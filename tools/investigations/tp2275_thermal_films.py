"""NASA TP-2275 bearings against their measured heat generation, step by step: before (isothermal, flooded cage films
at the oil-in temperature) -> inlet shear heating on the EHL rolling force (friction.inlet_heating = on) -> thermal
cage films (friction.thermal_films, fill band) -> the thermal network's temperatures at the contacts (hsbearing
friction --thermal); and the defaults (inlet heating off) with --thermal.  The table of docs/power_loss.md, "Thermal, part-filled cage films and
the bearing's temperatures at the contacts".

Cases and provenance: tools/investigations/tp2275_heat_by_source.py (35-mm reconstruction of a third-party reading of
TP-2275; 120-mm held out, both contact angles).  Nothing is fitted: no data calibrate, all validate.  The thermal
network's inputs (oil-in 394 K, ambient 20 degC, housing) are its defaults (docs/thermal.md), not chosen from the data.

Usage: PYTHONPATH=. python tools/investigations/tp2275_thermal_films.py [--no-120]
"""

from __future__ import annotations

import math
import sys
import time
from pathlib import Path

import numpy as np

sys.path.insert(0, str(Path(__file__).resolve().parent))

from tp2275_heat_by_source import MEASURED_120, case_120  # noqa: E402
from tp2275_power_loss import CASE, MEASURED  # noqa: E402

from hsbearing.case import loads_case  # noqa: E402
from hsbearing.systems.angular_contact.rating import friction_angular_contact  # noqa: E402


def exponent(ns, ys):
    return float(np.polyfit(np.log(ns), np.log(ys), 1)[0])


def report(title, case, measured):
    # hsbearing friction also prints the SKF 2004 model, which needs a 72xx/73xx designation: 7207 BE (35 mm bore)
    # and 7224 BE (120 mm) are the series' bores; the SKF columns are not used in this table
    bore = round(case.bearing.bore_diameter * 1e3) if case.bearing.bore_diameter else 35
    case = case.with_overrides(**{"bearing.designation": f"72{bore // 5:02d} BE"})
    ns = sorted(measured)
    w = np.array(ns) * math.pi / 30
    meas = np.array([measured[n] for n in ns])
    steps = []
    ih = case.with_overrides(**{"friction.inlet_heating": "on"})
    for label, c, thermal in (("before (isothermal flooded films, oil-in T)",
                               case.with_overrides(**{"friction.thermal_films": "off"}), False),
                              ("step 1: inlet shear heating on F_R",
                               ih.with_overrides(**{"friction.thermal_films": "off"}), False),
                              ("step 2: + thermal cage films", ih, False),
                              ("step 3: + thermal network temperatures at the contacts", ih, True),
                              ("step 3 without step 1 (defaults + --thermal)", case, True)):
        t0 = time.perf_counter()
        ds = friction_angular_contact(c, w, thermal=thermal)
        steps.append((label, ds, time.perf_counter() - t0))
    print(f"\n## {title}")
    print("| step | n [r/min] | measured [W] | race traction [W] | EHL rolling [W] | pocket film [W] | guide land [W] | drag [W] "
          "| jet + windage [W] | total [W] (ratio) | total band [W] (ratio) | land / pocket film T [degC] | contact inlet T [degC] |")
    print("|" + "---|" * 13)
    for label, ds, _ in steps:
        for i, n in enumerate(ns):
            g = lambda k: float(ds[k].values[i])  # noqa: E731
            tot, lo, hi, m = g("qs_power_loss"), g("qs_total_band_low"), g("qs_total_band_high"), meas[i]
            Tin = g("contact_inlet_temperature") - 273.15 if "contact_inlet_temperature" in ds else case.lubricant.temperature - 273.15
            print(f"| {label if i == 0 else ''} | {n} | {m:.0f} | {g('qs_power_loss_race_traction'):.0f} | "
                  f"{g('qs_power_loss_ehl_rolling'):.0f} | {g('qs_power_loss_pocket_film'):.0f} | {g('qs_power_loss_guide_land'):.0f} | "
                  f"{g('qs_power_loss_drag'):.0f} | {g('qs_power_loss_jet_oil_acceleration') + g('qs_power_loss_cage_windage'):.0f} | "
                  f"{tot:.0f} ({tot / m:.2f}) | {lo:.0f}..{hi:.0f} ({lo / m:.2f}..{hi / m:.2f}) | "
                  f"{g('land_film_temperature') - 273.15:.1f} / {g('pocket_film_temperature') - 273.15:.1f} | {Tin:.1f} |")
        e, elo, ehi = (exponent(ns, ds[k].values) for k in ("qs_power_loss", "qs_total_band_low", "qs_total_band_high"))
        print(f"| {label}: speed exponent | | {exponent(ns, meas):.2f} | | | | | | | {e:.2f} | {elo:.2f}..{ehi:.2f} | | |")
    print("cost [s] for the speeds: " + "; ".join(f"{label}: {dt:.1f}" for label, _, dt in steps))


def main():
    report("35-mm bore (16 x 7.14 mm, d_m 46.5 mm, 24 deg, 667 N, 760 cm^3/min, oil in 394 K)",
           loads_case(CASE.replace("{fraction}", "")), MEASURED)
    if "--no-120" not in sys.argv:
        for a in (25.0, 20.0):
            report(f"120-mm bore (15 x 20.64 mm, d_m 160 mm, {a:g} deg, 2224 N, 2280 cm^3/min, oil in 394 K; held out)",
                   case_120(a), MEASURED_120)


if __name__ == "__main__":
    main()
