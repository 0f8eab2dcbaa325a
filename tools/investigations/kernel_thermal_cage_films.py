"""The dynamic kernel's guide-land and pocket films with and without their thermal factor eta_eff / eta_film at the
lubricant temperature (walls at lubricant.temperature, as ``hsbearing friction`` without --thermal): cage whirl, slip
and power by source of a zhang2016 run (14000 r/min) and of the NASA TP-2275 35-mm bearing at 72 000 r/min
(tools/investigations/tp2275_power_loss.py's reconstruction).  The evidence for whether the kernel should apply the
factor by default (docs/power_loss.md, "Thermal cage films"); today only ``run --thermal`` applies it (at the thermal
network's walls).  Nothing is fitted.

Usage: PYTHONPATH=. python tools/investigations/kernel_thermal_cage_films.py [zhang2016|tp2275 ...] [--duration S]
"""

from __future__ import annotations

import argparse
import sys
import time
from pathlib import Path

import numpy as np

sys.path.insert(0, str(Path(__file__).resolve().parent))

from tp2275_power_loss import case_for  # noqa: E402

from hsbearing import analysis  # noqa: E402
from hsbearing.case import load_case  # noqa: E402
from hsbearing.systems.angular_contact.balances import SOURCES  # noqa: E402
from hsbearing.systems.angular_contact.cage_films import film_factors  # noqa: E402
from hsbearing.systems.angular_contact.dynamics import build_model, simulate  # noqa: E402

CASES = {"zhang2016": (lambda: load_case("zhang2016"), 0.1),
         "tp2275": (lambda: case_for("").with_overrides(**{"operating.inner_speed": "72000 rpm"}), 0.05)}


def one(case, factors, duration):
    m = build_model(case, cage_film_factors=factors)
    t = time.perf_counter()
    ds = simulate(case, duration=duration, model=m)
    wall = time.perf_counter() - t
    s = dict(analysis.summary(ds))
    half = ds.time.values >= 0.5 * float(ds.time.values[-1])  # the second half of the run
    power = {k: float(np.mean(ds[f"power_loss_{k}"].values[half])) for k in SOURCES if f"power_loss_{k}" in ds}
    total = float(np.mean(ds["power_loss"].values[half])) if "power_loss" in ds else float("nan")
    return s, power, total, wall


def fmt(v) -> str:
    return f"{v:.5g}" if isinstance(v, (float, np.floating)) else str(v)


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("cases", nargs="*", default=list(CASES))
    ap.add_argument("--duration", type=float, default=None)
    a = ap.parse_args()
    for name in a.cases:
        make, dur = CASES[name]
        case = make()
        dur = a.duration or dur
        ff = film_factors(case, build_model(case))
        f = (ff["land"]["factor"], ff["pocket"]["factor"])
        print(f"\n## {name}: {dur:g} s; thermal factors at the lubricant temperature "
              f"{case.lubricant.temperature:.1f} K: guide land {f[0]:.4f} (film {ff['land']['T_mean']:.1f} K, "
              f"{ff['land']['speed']:.1f} m/s), pocket {f[1]:.4f} (film {ff['pocket']['T_mean']:.1f} K, "
              f"{ff['pocket']['speed']:.1f} m/s)")
        rows = {}
        for label, fac in (("isothermal", None), ("thermal factor", f)):
            rows[label] = one(case, fac, dur)
            s, p, tot, wall = rows[label]
            print(f"{label}: wall {wall:.1f} s")
        keys = [k for k in rows["isothermal"][0] if any(w in k for w in ("label", "whirl", "slip", "cage_speed", "land",
                                                                             "pocket", "orbit", "eccentric"))]
        print("| quantity | isothermal | thermal factor |")
        print("|---|---|---|")
        for k in keys:
            v0, v1 = rows["isothermal"][0][k], rows["thermal factor"][0][k]
            print(f"| {k} | {fmt(v0)} | {fmt(v1)} |")
        for k in rows["isothermal"][1]:
            print(f"| power_loss_{k} [W] (2nd-half mean) | {rows['isothermal'][1][k]:.4g} | "
                  f"{rows['thermal factor'][1][k]:.4g} |")
        print(f"| power_loss [W] (2nd-half mean) | {rows['isothermal'][2]:.4g} | {rows['thermal factor'][2]:.4g} |")


if __name__ == "__main__":
    main()
