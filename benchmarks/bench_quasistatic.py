"""Benchmark of the quasi-static solver.

Run:  .venv/bin/python benchmarks/bench_quasistatic.py

1. one solve of the default case (zhang2016: 7206 size, 1 kN axial, 14000 r/min),
   cold (including the Hertz K(alpha) table) and warm (repeated, best of 5);
2. a 50-point inner-ring speed sweep 0..20000 r/min, each point continuing
   from the previous one (hsbearing.systems.angular_contact.quasistatic.speed_sweep);
3. the same sweep with a combined load (1 kN axial + 1 kN radial + 2 N m),
   where the balls differ and the 5-DOF ring problem is fully coupled.

Wall times depend on the machine load; the target is < 0.2 s per solve.
"""

from __future__ import annotations

import math
import time

import numpy as np

from hsbearing.case import load_case
from hsbearing.systems.angular_contact import quasistatic as qs


def _time(fn, repeat=1):
    best = math.inf
    out = None
    for _ in range(repeat):
        t = time.perf_counter()
        out = fn()
        best = min(best, time.perf_counter() - t)
    return best, out


def main() -> None:
    case = load_case("zhang2016")
    t_cold, ds = _time(lambda: qs.solve_case(case))
    t_warm, ds = _time(lambda: qs.solve_case(case), repeat=5)
    print(f"default case (zhang2016, 14000 r/min, Fa = 1 kN): cold {t_cold:.3f} s, warm best-of-5 {t_warm:.3f} s; "
          f"residual {float(ds.residual_norm):.1e}, Q_i = {float(ds.inner_contact_load[0]):.3f} N, "
          f"Q_o = {float(ds.outer_contact_load[0]):.3f} N")
    speeds = np.linspace(0.0, 20000.0, 50) * math.pi / 30.0
    for label, c in (("1 kN axial", case),
                     ("1 kN axial + 1 kN radial + 2 N m", case.with_overrides(**{
                         "operating.radial_load": "1 kN", "operating.moment_y": "2 N*m"}))):
        t, sw = _time(lambda: qs.speed_sweep(c, speeds))
        print(f"50-point speed sweep 0..20000 r/min ({label}): {t:.3f} s total, {t / 50 * 1e3:.1f} ms per point; "
              f"max residual {float(sw.residual_norm.max()):.1e}; "
              f"alpha_i {math.degrees(float(sw.inner_contact_angle.isel(inner_speed=0, ball=0))):.2f} -> "
              f"{math.degrees(float(sw.inner_contact_angle.isel(inner_speed=-1, ball=0))):.2f} deg, "
              f"alpha_o -> {math.degrees(float(sw.outer_contact_angle.isel(inner_speed=-1, ball=0))):.2f} deg")


if __name__ == "__main__":
    main()
