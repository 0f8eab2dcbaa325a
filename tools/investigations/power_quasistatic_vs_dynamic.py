"""Quasi-static against dynamic power loss of a case, source by source, with the causes switched off one at a time.

The quasi-static power loss (``hsbearing friction``) is the dynamic kernel's dissipation evaluated at the quasi-static
state (race-control kinematics: no rolling slip at either contact centre, no spin at the controlling race), plus the
jet-oil acceleration and the cage windage that the kernel does not have.  The dynamic run starts at that same state;
what it loses afterwards differs only through how the state moves away from it.  This tool runs the dynamic model
with the forces that make the balls slip switched off in turn (ball drag, EHL rolling force, pocket boundary
friction) and prints the power by source, the rolling slip at the contact centres and the cage slip, each as the
mean over the second half of the run (docs/power_loss.md, "Quasi-static, dynamic and SKF: what each includes").

    nice -n 10 .venv/bin/python tools/investigations/power_quasistatic_vs_dynamic.py --duration 0.02 \
        --variants default,no_drag,no_drag_no_ehl,no_slip_forces
"""

from __future__ import annotations

import argparse
import json
import time

import numpy as np

import hsbearing
from hsbearing.systems.angular_contact.balances import SOURCES
from hsbearing.systems.angular_contact.dynamics import build_model, simulate
from hsbearing.systems.angular_contact.rating import quasi_static_power_loss

#: variant -> (build_model switches, case overrides)
VARIANTS = {
    "default": ({}, {}),
    "no_drag": ({"drag": False}, {}),
    "no_ehl": ({"ehl_rolling": False}, {}),
    "no_drag_no_ehl": ({"drag": False, "ehl_rolling": False}, {}),
    # drag, EHL rolling force and pocket boundary friction off: what is left to slip the balls is the pocket film and
    # the cage's land film (the cage must still be driven)
    "no_slip_forces": ({"drag": False, "ehl_rolling": False}, {"friction.cage_coefficient": 0.0}),
}


def measure(case, variant: str, duration: float) -> dict:
    switches, sets = VARIANTS[variant]
    c = case.with_overrides(**sets) if sets else case
    qs = quasi_static_power_loss(c) if not switches else None
    model = build_model(c, **switches)
    aux, gaux = model.outputs(model.y0)
    from hsbearing.systems.angular_contact.balances import power_variables

    pv0 = power_variables(aux[None], gaux[None])
    t0 = time.perf_counter()
    ds = simulate(c, duration=duration, model=model, annotate=False)
    wall = time.perf_counter() - t0
    t = ds["time"].values
    sel = ds.isel(time=slice(int(np.searchsorted(t, 0.5 * t[-1])), None))
    out = {"variant": variant, "duration_s": duration, "wall_s": round(wall, 1),
           "start": {s: float(pv0[f"power_loss_{s}"][0]) for s in SOURCES},
           "mean": {s: float(sel[f"power_loss_{s}"].mean()) for s in SOURCES},
           "power_loss_start": float(pv0["power_loss"][0]), "power_loss_mean": float(sel.power_loss.mean()),
           "drive_power_mean": float(sel.drive_power.mean()),
           "inner_slide_roll_mean": float(sel.inner_slide_roll_ratio.mean()),
           "outer_slide_roll_mean": float(sel.outer_slide_roll_ratio.mean()),
           "cage_speed_mean": float(sel.cage_speed.mean()), "cage_speed_start": float(ds.cage_speed[0])}
    if qs is not None:
        out["quasistatic"] = {k: v for k, v in qs.items() if isinstance(v, float)}
    from hsbearing.systems.angular_contact.balances import power_difference_by_state

    out["attribution_final_state"] = {k: v for k, v in power_difference_by_state(model, ds.final_state.values)}
    return out


def main(argv=None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("case", nargs="?", default="zhang2016")
    ap.add_argument("--duration", type=float, default=0.02, help="simulated time of each run [s]")
    ap.add_argument("--variants", default="default,no_drag_no_ehl,no_slip_forces",
                    help=f"comma-separated, of {', '.join(VARIANTS)}")
    ap.add_argument("--json", help="append one JSON line per variant to this file")
    a = ap.parse_args(argv)
    case = hsbearing.load_case(a.case)
    for v in a.variants.split(","):
        r = measure(case, v.strip(), a.duration)
        print(f"{v}: total start {r['power_loss_start']:.3f} W, mean {r['power_loss_mean']:.3f} W "
              f"(drive {r['drive_power_mean']:.3f} W), S_i {r['inner_slide_roll_mean']:.3e}, "
              f"S_o {r['outer_slide_roll_mean']:.3e}, cage {r['cage_speed_start']:.2f} -> {r['cage_speed_mean']:.2f} rad/s, "
              f"wall {r['wall_s']} s")
        for s in SOURCES:
            print(f"    {s:16s} start {r['start'][s]:9.4f} W   mean {r['mean'][s]:9.4f} W")
        print("    final state, dynamic minus quasi-static by the state group put back (balances.power_difference_by_state):")
        for g, d in r["attribution_final_state"].items():
            print(f"      {g:24s} " + ", ".join(f"{s} {d[s]:+.3f}" for s in tuple(SOURCES) + ("power_loss",)
                                                 if s not in ("contact_damping", "pocket_boundary")))
        if a.json:
            with open(a.json, "a") as f:
                f.write(json.dumps(r) + "\n")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
