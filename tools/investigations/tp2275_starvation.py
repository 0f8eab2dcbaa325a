"""NASA TP-2275 bearings: the starvation band of the race contacts beside the other bands, against measured heat.

For each speed: the flooded EHL rolling loss (today's value, the band's high end), its low end (every race inlet fed
only by the cavity mixture at the cavity oil fraction X: models/ball_bearing/starvation.py), the same against
Grubin's inlet flooded to infinity (reported, not used), the thinnest contact's starved/flooded central film, the
range of the contacts' Hbar = h_c 2 R_x / b^2, meniscus m and critical m*, SKF's kinematic replenishment factor
phi_rs at the same speed (an empirical factor on the catalogue rolling moment, models/friction/skf2004.py, for
comparison only), and the total band without and with starvation against the measured heat generation.  Both with
the contacts at the oil-in temperature (defaults) and with the thermal network's temperatures (--thermal).

Cases and provenance: tools/investigations/tp2275_heat_by_source.py.  Nothing is fitted: no data calibrate, all
validate; the band's ends are physical bounds fixed before the heat data were looked at (docs/power_loss.md).

Usage: PYTHONPATH=. python tools/investigations/tp2275_starvation.py [--no-120] [--no-thermal]
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
from hsbearing.models.friction.skf2004 import K_RS, K_Z_ACBB, replenishment_factor_phi_rs  # noqa: E402
from hsbearing.systems.angular_contact import rating  # noqa: E402


def exponent(ns, ys):
    return float(np.polyfit(np.log(ns), np.log(ys), 1)[0])


def rows_for(case, ns, thermal):
    out = []
    for n in ns:
        w = n * math.pi / 30.0
        r = rating._thermal_row(case, w) if thermal else rating.quasi_static_power_loss(case, w, with_state=True)
        cw = r["case"]
        nu = rating._kinematic_viscosity(cw)[0] * 1e6
        b = case.bearing
        d, D = (b.bore_diameter or 0.035) * 1e3, (b.outside_diameter or 0.072) * 1e3
        r["phi_rs"] = float(replenishment_factor_phi_rs(n, nu, d, D, K_rs=K_RS[case.lubricant.lubrication], K_Z=K_Z_ACBB))
        r["nu"] = nu
        out.append(r)
    return out


def report(title, case, measured, thermal):
    ns = sorted(measured)
    t0 = time.perf_counter()
    rows = rows_for(case, ns, thermal)
    dt = time.perf_counter() - t0
    print(f"\n## {title}{' -- with --thermal' if thermal else ' -- contacts at the oil-in temperature'}")
    print("| n [r/min] | measured [W] | X | EHL rolling flooded [W] | EHL rolling starved (low end) [W] | vs infinite inlet [W] "
          "| film ratio low (inner / outer) | Hbar | m .. m* | SKF phi_rs | total [W] | total band without starvation [W] (ratio) "
          "| total band with starvation [W] (ratio) |")
    print("|" + "---|" * 13)
    lows, highs, lows0 = [], [], []
    for n, r in zip(ns, rows):
        mes = measured[n]
        tot_hi = (r["power_loss"] - r["drag"] + r["drag_band_high"] - r["guide_land"] - r["pocket_film"]
                  + r["guide_land_band_high"] + r["pocket_film_band_high"])
        tot_lo0 = (r["power_loss"] - r["drag"] + r["drag_band_low"] - r["guide_land"] - r["pocket_film"]
                   + r["guide_land_band_low"] + r["pocket_film_band_low"])
        tot_lo = tot_lo0 - r["ehl_rolling"] + r["ehl_rolling_band_low"]
        lows.append(tot_lo)
        highs.append(tot_hi)
        lows0.append(tot_lo0)
        c = np.array(r["starvation_contacts"])
        print(f"| {n} | {mes:.0f} | {r['cavity_oil_fraction']:.3f} | {r['ehl_rolling']:.0f} | {r['ehl_rolling_band_low']:.1f} | "
              f"{r['ehl_rolling_band_low_infinite_inlet']:.1f} | {r['inner_starved_film_ratio_low']:.2f} / "
              f"{r['outer_starved_film_ratio_low']:.2f} | {c[:, 0].min():.3f}..{c[:, 0].max():.3f} | "
              f"{c[:, 1].min():.3f}..{c[:, 2].max():.2f} | {r['phi_rs']:.3f} | {r['power_loss']:.0f} | "
              f"{tot_lo0:.0f}..{tot_hi:.0f} ({tot_lo0 / mes:.2f}..{tot_hi / mes:.2f}) | "
              f"{tot_lo:.0f}..{tot_hi:.0f} ({tot_lo / mes:.2f}..{tot_hi / mes:.2f}) |")
    meas = [measured[n] for n in ns]
    print(f"| exponent | {exponent(ns, meas):.2f} | | | | | | | | | {exponent(ns, [r['power_loss'] for r in rows]):.2f} | "
          f"{exponent(ns, lows0):.2f}..{exponent(ns, highs):.2f} | {exponent(ns, lows):.2f}..{exponent(ns, highs):.2f} |")
    print(f"(kinematic viscosity at the contacts {', '.join(format(r['nu'], '.2f') for r in rows)} mm^2/s; {dt:.1f} s)")


def main():
    thermal_too = "--no-thermal" not in sys.argv
    c35 = loads_case(CASE.replace("{fraction}", ""))
    for thermal in (False, True) if thermal_too else (False,):
        report("35-mm bore (16 x 7.14 mm, d_m 46.5 mm, 24 deg, 667 N, 760 cm^3/min, oil in 394 K)", c35, MEASURED, thermal)
    if "--no-120" not in sys.argv:
        for a in (25.0, 20.0):
            report(f"120-mm bore ({a:g} deg; held out)", case_120(a), MEASURED_120, False)


if __name__ == "__main__":
    main()
