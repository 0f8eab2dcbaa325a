"""Issue 29 item 2 (measurement part, partial): quasi-static power by source over speed for a 35-mm and a 120-mm
bore high-speed angular-contact bearing, and the speed exponent of the total and of each source.

No public geometry of the NASA 35-mm (TP 1732) and 120-mm (TN D-7870) bearings could be read
(docs/validation/nasa_heat_generation.md), so both bearings are ASSUMED geometrically similar to the 7206-size
bearing of zhang2016 (every length scaled by d_m / 46 mm, 11 balls, 25 deg, same conformities, same PA66 cage,
oil 4109 at 130 degC), axial load scaled with d_m^2 (1 kN at d_m 46 mm), oil jet at the flow given below.
The drag uses the model's law (models/ball_bearing/drag.py): Parker's cavity fraction (read as a fraction, unverified) or the
constant 0.05, and C_D(Re) of the smooth sphere's standard drag curve at the quasi-static orbital speed; the
columns X, Re_ball, C_D show them.  Past Re 3.38e5 C_D is held (no drag crisis in the cavity: models/ball_bearing/drag.py RE_SUBCRITICAL_MAX).
Usage: PYTHONPATH=. python tools/investigations/tp2275_speed_exponents.py
"""

import math

import numpy as np

from hsbearing.case import load_case
from hsbearing.systems.angular_contact.rating import quasi_static_power_loss

LENGTHS = ["bearing.ball_diameter", "bearing.pitch_diameter", "bearing.bore_diameter", "bearing.outside_diameter",
           "bearing.width", "bearing.outer_land_diameter", "bearing.inner_land_diameter", "cage.outside_diameter",
           "cage.bore_diameter", "cage.width", "cage.pocket_diameter"]


def scaled_case(dm_mm, flow, override=None):
    base = load_case("zhang2016")
    s = dm_mm / 46.0
    ov = {}
    for key in LENGTHS:
        t, k = key.split(".")
        v = getattr(getattr(base, t), k)
        ov[key] = f"{v * s * 1e3:.6g} mm"
    ov["operating.axial_load"] = f"{1000.0 * s * s:.6g} N"
    ov["lubricant.oil_flow_rate"] = f"{flow} L/min"
    ov["case.name"] = f"similar_dm{dm_mm:g}"
    ov["friction.cavity_losses"] = "off"  # drag only, as tabled in docs/power_loss.md (churning: tp2275_heat_by_source.py)
    case = base.with_overrides(**ov)
    if override is None:  # Parker: drop the explicit fraction of zhang2016
        from hsbearing.case import loads_case

        text = case.raw_text_base.replace("oil_volume_fraction = 0.05", "# oil_volume_fraction: Parker")
        case = loads_case(text, **ov)
    return case


def sweep(label, dm_mm, bore, flow, rpms):
    print(f"\n{label}: d_m {dm_mm} mm (bore {bore} mm), {flow} L/min oil jet, Fa {1000 * (dm_mm / 46) ** 2:.0f} N")
    res = {}
    for variant, ov in (("Parker", None), ("X=0.05", 0.05)):
        case = scaled_case(dm_mm, flow, ov)
        rows = []
        for n in rpms:
            try:
                r = quasi_static_power_loss(case, n * math.pi / 30)
            except Exception as exc:  # noqa: BLE001
                print(f"  {variant} {n} r/min failed: {type(exc).__name__}: {exc}")
                r = None
            rows.append(r)
        res[variant] = rows
        srcs = ["race_traction", "ehl_rolling", "pocket_film", "guide_land", "drag", "power_loss"]
        print(f"  [{variant}] n [r/min] " + " ".join(f"{s:>14s}" for s in srcs) + "   n d_m [1e6]        X   Re_ball   C_D")
        for n, r in zip(rpms, rows):
            if r is None:
                continue
            print(f"  [{variant}] {n:9.0f} " + " ".join(f"{r[s]:14.4g}" for s in srcs) + f"   {n * dm_mm / 1e6:11.2f}"
                  f" {r['cavity_oil_fraction']:8.3g} {r['drag_reynolds_number']:9.3g} {r['drag_coefficient']:5.3f}")
        ok = [(n, r) for n, r in zip(rpms, rows) if r is not None]
        if len(ok) >= 2:
            ln = np.log([n for n, _ in ok])
            ex = {s: np.polyfit(ln, np.log(np.maximum([r[s] for _, r in ok], 1e-12)), 1)[0] for s in srcs}
            print(f"  [{variant}] speed exponent (log-log fit): " + ", ".join(f"{s} {e:.2f}" for s, e in ex.items()))
    return res


if __name__ == "__main__":
    sweep("35-mm bore (assumed 7206-similar)", 53.5, 35, 1.0, [20000, 30000, 45000, 60000, 72000])
    sweep("120-mm bore (assumed 7206-similar)", 150.0, 120, 2.0, [8000, 12000, 16000, 20000, 25000])
