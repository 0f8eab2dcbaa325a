"""Size of the inlet-shear-heating factor phi_T (models/ehl.py thermal_reduction_factor, Gupta et al. 1992 as quoted in
Harris & Kotzalas) at the contacts of the TP-2275 35-mm reconstruction: a DIAGNOSTIC for the next step, not applied
to any force.  Entrainment speeds are rough (pure rolling at the mean quasi-static contact angles and ball-centre radius);
p_h the mean Hertz pressure; E' of steel on steel; inlet viscosity at the oil-in 394 K.

Usage: PYTHONPATH=. python tools/investigations/tp2275_inlet_heating_size.py
"""

from __future__ import annotations

import math
import sys
from pathlib import Path

import numpy as np

sys.path.insert(0, str(Path(__file__).resolve().parent))

from tp2275_power_loss import MEASURED, case_for  # noqa: E402

from hsbearing.models import ehl  # noqa: E402
from hsbearing.systems.angular_contact.rating import quasi_static_power_loss  # noqa: E402


def main():
    case = case_for("")
    lp = ehl.lubricant_parameters(case)
    Ep = 208e9 / (1 - 0.3**2)  # the reconstruction's steel, both bodies
    D = case.bearing.ball_diameter
    print("| n [r/min] | inner u [m/s] | inner p_h [GPa] | inner L | inner phi_T | outer u [m/s] | outer p_h [GPa] | outer L | outer phi_T | ehl_rolling [W] |")
    print("|---|---|---|---|---|---|---|---|---|---|")
    for n in sorted(MEASURED):
        w = n * math.pi / 30
        r = quasi_static_power_loss(case, w, with_state=True)
        q = r["state"]
        wc = float(q.cage_speed.values)
        rb = float(np.mean(q.ball_center_radial.values))
        ai, ao = float(np.mean(q.inner_contact_angle.values)), float(np.mean(q.outer_contact_angle.values))
        cells = []
        for u, p in (((w - wc) * (rb - 0.5 * D * math.cos(ai)), float(np.mean(q.inner_contact_pressure.values))),
                     (wc * (rb + 0.5 * D * math.cos(ao)), float(np.mean(q.outer_contact_pressure.values)))):
            L = ehl.thermal_loading_parameter(lp["eta"], lp["beta"], u, lp["K"])
            cells += [f"{u:.1f}", f"{p / 1e9:.2f}", f"{L:.3g}", f"{float(ehl.thermal_reduction_factor(L, p, Ep)):.3f}"]
        print(f"| {n} | " + " | ".join(cells) + f" | {r['ehl_rolling']:.0f} |")


if __name__ == "__main__":
    main()
