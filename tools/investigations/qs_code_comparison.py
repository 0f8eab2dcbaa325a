"""Quasi-static 7206 check at 14000 r/min: one modelling assumption varied at a time.

Prints the two tables of docs/quasistatic.md, "Comparison with independent codes":
1. the variants (race control, gyroscopic split and sign, centrifugal radius) at 14000 r/min;
2. the margin of Jones' raceway-control criterion along the speed, with the exact Hertz
   semi-axes/elliptic integrals and with the Hamrock-Brewe (1983) approximations.

Run: .venv/bin/python tools/investigations/qs_code_comparison.py     (about 10-20 s)
"""

from __future__ import annotations

import contextlib
import math
from dataclasses import replace

import numpy as np

from hsbearing import load_case
from hsbearing.models import hertz
from hsbearing.models.ball_bearing import quasistatic as qp
from hsbearing.systems.angular_contact import quasistatic as qs

RPM = math.pi / 30.0
# the 7206-type bearing of issue 3 (also tests/systems/angular_contact/test_quasistatic.py B7206)
B7206 = {
    "bearing.ball_count": "11", "bearing.ball_diameter": "9.525 mm", "bearing.pitch_diameter": "46 mm",
    "bearing.inner_conformity": "0.52", "bearing.outer_conformity": "0.53", "bearing.contact_angle": "25 deg",
    "materials.ball.elastic_modulus": "208 GPa", "materials.races.elastic_modulus": "208 GPa",
    "materials.ball.poisson_ratio": "0.3", "materials.races.poisson_ratio": "0.3", "operating.axial_load": "1000 N",
}


@contextlib.contextmanager
def centrifugal_at_pitch_radius(dm):
    """Variant: F_c = m (d_m/2) omega_m^2 (Harris' form) instead of the actual orbit radius."""
    orig = qp.centrifugal_force
    qp.centrifugal_force = lambda m, R_b, wm: orig(m, 0.5 * dm + 0.0 * R_b, wm)
    try:
        yield
    finally:
        qp.centrifugal_force = orig


def criterion_ratio(sol, method="exact"):
    """Jones' criterion margin of ball 0 with the Hertz semi-axis and E(e) of ``method``."""
    P, st = sol.problem, sol.state
    Rxi, Ryi, Rxo, Ryo = qs._contact_radii(P, st)
    hi = hertz.point_contact(Rxi, Ryi, st["Qi"], P.E1, P.nu1, P.E2, P.nu2, method=method)
    ho = hertz.point_contact(Rxo, Ryo, st["Qo"], P.E1, P.nu1, P.E2, P.nu2, method=method)
    return float(qp.race_control_ratio(st["Qi"], hi.a, hi.second_kind, st["Qo"], ho.a, ho.second_kind,
                                       np.arctan2(st["si"], st["ci"]), np.arctan2(st["so"], st["co"]))[0])


def row(sol):
    st = sol.state
    return dict(ai=math.degrees(math.atan2(st["si"][0], st["ci"][0])),
                ao=math.degrees(math.atan2(st["so"][0], st["co"][0])),
                Qi=float(st["Qi"][0]), Qo=float(st["Qo"][0]), wm=float(st["wm"][0]),
                dx=float(sol.q[0]) * 1e6, ratio=criterion_ratio(sol), ratio_hb=criterion_ratio(sol, "hamrock_brewe"))


VARIANTS = [
    # label, control, gyroscopic, gyro_split override, centrifugal at d_m/2
    ("A  ours (default): outer control, lambda 0/2", "outer_race_control", True, None, False),
    ("B  outer control, lambda 1/1", "outer_race_control", True, (1.0, 1.0), False),
    ("C  outer control, no gyroscopic moment", "outer_race_control", False, None, False),
    ("D  inner control, lambda 1/1 (Harris 'otherwise')", "inner_race_control", True, None, False),
    ("E  inner control, lambda 2/0", "inner_race_control", True, (2.0, 0.0), False),
    ("F  inner control, no gyroscopic moment", "inner_race_control", False, None, False),
    ("G  outer control, gyroscopic sign reversed", "outer_race_control", True, (0.0, -2.0), False),
    ("H  outer control, F_c at d_m/2", "outer_race_control", True, None, True),
    ("J  friction: Jones' criterion per ball (exact Hertz)", "friction", True, None, False),
]


def variants(case, speed=14000 * RPM):
    out = {}
    for label, control, gyro, split, fc_dm in VARIANTS:
        P = replace(qs.build_problem(case, inner_speed=speed, control=control, gyroscopic=gyro), gyro_split=split)
        with centrifugal_at_pitch_radius(P.dm) if fc_dm else contextlib.nullcontext():
            out[label] = row(qs.solve(P))
    return out


def main():
    case = load_case("zhang2016", **B7206)
    res = variants(case)
    ref = res[VARIANTS[0][0]]
    print("| variant | alpha_i [deg] | alpha_o [deg] | Q_i [N] | Q_o [N] | cage speed [rad/s] (vs A) "
          "| delta_x [um] | Jones ratio exact / H-B |")
    print("|---|---|---|---|---|---|---|---|")
    for label, r in res.items():
        print(f"| {label} | {r['ai']:.3f} ({r['ai'] - ref['ai']:+.2f}) | {r['ao']:.3f} ({r['ao'] - ref['ao']:+.2f}) "
              f"| {r['Qi']:.2f} | {r['Qo']:.2f} | {r['wm']:.2f} ({100 * (r['wm'] / ref['wm'] - 1):+.2f} %) "
              f"| {r['dx']:.3f} | {r['ratio']:.4f} / {r['ratio_hb']:.4f} |")
    print()
    print("| speed [r/min] | outer control: alpha_i / alpha_o, Jones ratio exact / H-B "
          "| inner control: alpha_i / alpha_o, Jones ratio exact / H-B |")
    print("|---|---|---|")
    for n in (8000, 12000, 13000, 13500, 14000, 14500, 15000, 16000, 20000):
        cells = []
        for control in ("outer_race_control", "inner_race_control"):
            r = row(qs.solve(qs.build_problem(case, inner_speed=n * RPM, control=control)))
            cells.append(f"{r['ai']:.3f} / {r['ao']:.3f}, {r['ratio']:.4f} / {r['ratio_hb']:.4f}")
        print(f"| {n} | {cells[0]} | {cells[1]} |")


if __name__ == "__main__":
    main()
