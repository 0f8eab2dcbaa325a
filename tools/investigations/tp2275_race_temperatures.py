"""NASA TP-2275 35-mm bearing with the thermal network's temperatures at the contacts: both races at one inlet
temperature, the network's (T_ir + T_or + 2 T_b)/4 (before), against each race at its own, (T_ir + T_b)/2 inner and
(T_or + T_b)/2 outer (after; ``hsbearing friction --thermal``).  docs/power_loss.md, "Each race at its own inlet
temperature".

One thermal equilibrium per speed, shared by the two rows: the network's own fixed point evaluates each race at its
own inlet temperature (``thermal_equilibrium``'s default; tools/investigations/tp2275_thermal_fixed_point.py compares
it with the former fixed point), and the two rows evaluate the contacts on that one network.  "before" is ``quasi_static_power_loss`` with both races at the network's
lubricant temperature, i.e. the kernel with one oil temperature (bit-identical to the single-temperature kernel,
tests/systems/angular_contact/test_race_temperatures.py).  Two settings: the defaults (inlet heating off) and
``friction.inlet_heating = on`` (step 3 of tools/investigations/tp2275_thermal_films.py).  Case and measured heat:
tools/investigations/tp2275_power_loss.py (a third party's reading of TP-2275; nothing is fitted, the heat validates).

Usage: PYTHONPATH=. python tools/investigations/tp2275_race_temperatures.py
"""

from __future__ import annotations

import math
import sys
import time
from pathlib import Path

import numpy as np

sys.path.insert(0, str(Path(__file__).resolve().parent))

from tp2275_power_loss import CASE, MEASURED  # noqa: E402

from hsbearing.case import loads_case  # noqa: E402
from hsbearing.systems.angular_contact.rating import quasi_static_power_loss, race_inlet_temperatures  # noqa: E402
from hsbearing.systems.angular_contact.thermal import thermal_equilibrium  # noqa: E402

SOURCES = ("race_traction", "ehl_rolling", "pocket_film", "guide_land", "drag")


def exponent(ns, ys):
    return float(np.polyfit(np.log(ns), np.log(ys), 1)[0])


def rows(case):
    ns = sorted(MEASURED)
    out = {"before": [], "after": []}
    for n in ns:
        cw = case.with_overrides(**{"operating.inner_speed": f"{n * math.pi / 30!r} rad/s"})
        th = thermal_equilibrium(cw)
        assert th.attrs["status"] == "ok", th.attrs
        T = {"inner_ring": float(th.inner_ring_temperature), "outer_ring": float(th.outer_ring_temperature),
             "balls": float(th.ball_temperature), "cage": float(th.cage_temperature)}
        T_lub = float(th.lubricant_temperature)
        Ti, To = race_inlet_temperatures(T["inner_ring"], T["outer_ring"], T["balls"])
        c_lub = cw.with_overrides(**{"lubricant.temperature": f"{T_lub} K"})
        for key, races in (("before", None), ("after", (Ti, To))):
            r = quasi_static_power_loss(c_lub, None, walls=T, race_temperatures=races)
            r["T_in"] = (T_lub, T_lub) if races is None else races
            r["T_nodes"] = (T["inner_ring"], T["outer_ring"], T["balls"])
            out[key].append(r)
    return ns, out


def report(title, case):
    t0 = time.perf_counter()
    ns, out = rows(case)
    meas = np.array([MEASURED[n] for n in ns])
    print(f"\n## {title}")
    print("| rule | n [r/min] | T_ir / T_or / T_b [degC] | inlet T inner / outer [degC] | race traction [W] | EHL rolling [W] "
          "| pocket film [W] | guide land [W] | drag [W] | jet + windage [W] | total [W] (ratio) | total band [W] (ratio) |")
    print("|" + "---|" * 12)
    for key in ("before", "after"):
        for i, n in enumerate(ns):
            r, m = out[key][i], meas[i]
            tot = r["power_loss"]
            lo = (tot - r["drag"] + r["drag_band_low"] - r["guide_land"] - r["pocket_film"] + r["guide_land_band_low"]
                  + r["pocket_film_band_low"] - r["ehl_rolling"] + r["ehl_rolling_band_low"])
            tn = r["T_nodes"]
            print(f"| {key if i == 0 else ''} | {n} | {tn[0] - 273.15:.1f} / {tn[1] - 273.15:.1f} / {tn[2] - 273.15:.1f} | "
                  f"{r['T_in'][0] - 273.15:.1f} / {r['T_in'][1] - 273.15:.1f} | "
                  + " | ".join(f"{r[s]:.1f}" for s in SOURCES)
                  + f" | {r['jet_oil_acceleration'] + r['cage_windage']:.0f} | {tot:.0f} ({tot / m:.3f}) | "
                  f"{lo:.0f} ({lo / m:.2f}) .. {tot:.0f} |")
        tots = np.array([r["power_loss"] for r in out[key]])
        print(f"| {key}: speed exponent | | | | | | | | | | {exponent(ns, tots):.3f} (measured {exponent(ns, meas):.2f}) | |")
    d = [a["power_loss"] - b["power_loss"] for a, b in zip(out["after"], out["before"])]
    print("after - before [W]: " + ", ".join(f"{x:+.1f}" for x in d) + f"   ({time.perf_counter() - t0:.0f} s)")


def main():
    base = loads_case(CASE.replace("{fraction}", ""))
    report("35-mm bore, defaults (inlet heating off) + --thermal", base)
    if "--defaults-only" not in sys.argv:
        report("35-mm bore, friction.inlet_heating = on + --thermal", base.with_overrides(**{"friction.inlet_heating": "on"}))


if __name__ == "__main__":
    main()
