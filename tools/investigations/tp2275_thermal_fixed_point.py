"""The thermal network's fixed point with each race at its own inlet temperature: the former rule (both races'
contact losses at the fixed point's lubricant temperature, ``race_rule="lubricant"``) against the per-race rule
(``race_rule="per_race"``, the default of ``hsbearing thermal`` and ``friction --thermal``).  docs/thermal.md,
"Each race at its own inlet temperature inside the fixed point".

For each bearing and speed, each rule: the fixed-point iterations, the node temperatures, the race inlet
temperatures the last iteration evaluated the losses at, the heat the network balanced, the total loss that
``hsbearing friction --thermal`` reports (quasi-static loss with each race at (T_ring + T_b)/2 of that network,
rating._thermal_row) and the difference between the race-contact heat the network balanced and the race-contact
loss reported (traction + EHL rolling, both races).  Cases: the bundled zhang2016 case; the NASA TP-2275 35-mm
bearing (tools/investigations/tp2275_power_loss.py) and the 120-mm one at 25 and 20 deg
(tools/investigations/tp2275_heat_by_source.py), third-party readings; nothing is fitted, the measured heat only
validates (ratio printed).

Usage: PYTHONPATH=. python tools/investigations/tp2275_thermal_fixed_point.py [--no-120]
"""

from __future__ import annotations

import math
import sys
import time
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent))

from tp2275_heat_by_source import MEASURED_120, case_120  # noqa: E402
from tp2275_power_loss import CASE, MEASURED  # noqa: E402

from hsbearing.case import load_case, loads_case  # noqa: E402
from hsbearing.systems.angular_contact.rating import quasi_static_power_loss, race_inlet_temperatures  # noqa: E402
from hsbearing.systems.angular_contact.thermal import thermal_equilibrium  # noqa: E402

RACE = ("race_traction_inner", "race_traction_outer", "ehl_rolling_inner", "ehl_rolling_outer")


def point(case, rule):
    """(thermal Dataset, friction --thermal row) of ``case`` with the fixed point's race rule ``rule``."""
    th = thermal_equilibrium(case, race_rule=rule)
    assert th.attrs["status"] == "ok", th.attrs.get("error")
    T = {"inner_ring": float(th.inner_ring_temperature), "outer_ring": float(th.outer_ring_temperature),
         "balls": float(th.ball_temperature), "cage": float(th.cage_temperature)}
    Ti, To = race_inlet_temperatures(T["inner_ring"], T["outer_ring"], T["balls"])
    c = case.with_overrides(**{"lubricant.temperature": f"{float(th.lubricant_temperature)!r} K"})
    r = quasi_static_power_loss(c, None, walls=T, race_temperatures=(Ti, To), bands=False)
    return th, r, (Ti, To)


def report(title, case, speeds, measured=None):
    t0 = time.perf_counter()
    print(f"\n## {title}")
    print("| n [r/min] | rule | iterations | T_ir / T_or / T_b / T_oil [degC] | race inlet used inner / outer [degC] | "
          "(T_ir+T_b)/2 / (T_or+T_b)/2 [degC] | network heat [W] | friction --thermal total [W] | race heat network - "
          "reported [W] | ratio to measured |")
    print("|" + "---|" * 10)
    for n in speeds:
        cw = case.with_overrides(**{"operating.inner_speed": f"{n * math.pi / 30!r} rad/s"})
        out = {}
        for rule in ("lubricant", "per_race"):
            th, r, (Ti, To) = point(cw, rule)
            out[rule] = r["power_loss"]
            race_net = sum(float(th[f"thermal_power_loss_{s}"]) for s in RACE)
            race_rep = r["race_traction"] + r["ehl_rolling"]
            C = lambda v: float(v) - 273.15  # noqa: E731
            ratio = f"{r['power_loss'] / measured[n]:.4f}" if measured else ""
            print(f"| {n if rule == 'lubricant' else ''} | {rule} | {int(th.fixed_point_iterations)} | "
                  f"{C(th.inner_ring_temperature):.2f} / {C(th.outer_ring_temperature):.2f} / {C(th.ball_temperature):.2f} / "
                  f"{C(th.oil_outlet_temperature):.2f} | {C(th.inner_race_inlet_temperature):.2f} / "
                  f"{C(th.outer_race_inlet_temperature):.2f} | {C(Ti):.2f} / {C(To):.2f} | {float(th.heat_generated):.2f} | "
                  f"{r['power_loss']:.2f} | {race_net - race_rep:+.4f} | {ratio} |")
        print(f"| | after - before | | | | | | {out['per_race'] - out['lubricant']:+.3f} W | | |")
    print(f"({time.perf_counter() - t0:.0f} s)")


def main():
    report("zhang2016 (bundled case, 1 L/min assumed)", load_case("zhang2016"), [14000])
    base = loads_case(CASE.replace("{fraction}", ""))
    report("TP-2275 35-mm bore, defaults + --thermal", base, sorted(MEASURED), MEASURED)
    if "--no-120" not in sys.argv:
        for a in (25.0, 20.0):
            report(f"TP-2275 120-mm bore, {a:g} deg (held out), defaults + --thermal", case_120(a), sorted(MEASURED_120),
                   MEASURED_120)


if __name__ == "__main__":
    main()
