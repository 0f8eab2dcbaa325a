"""Do the solver settings of ``simulate`` change what a user reads?  Ensemble statistics, two settings.

    .venv/bin/python tools/investigations/solver_settings_ensemble.py [--span 0.1] [--members 4] [--cases default,radial,axial100,axial6k]

The cage motion is chaotic in phase: any change of the arithmetic -- a CVODE setting, the LU pivoting, the
last bit of the start -- moves one trajectory beyond the tolerance within about a millisecond.  A solver setting
is therefore judged by the statistics users read (cage speed, whirl radius, forces, power loss) over an
ensemble of starts perturbed in the last digits (initial cage velocity ydot_c + k 1e-9 m/s, k = 0..members-1),
run once with CVODE's own defaults (``cvode_settings={}``) and once with ``dynamics.SOLVER_SETTINGS``.  Printed
per statistic: the two ensemble means, their difference in units of the standard error of that difference
(z), and the CPU seconds, steps, Jacobians and LU setups per member.  tests/systems/angular_contact/test_dynamics_solver_settings.py
asserts the same comparison (slow tier).
"""

from __future__ import annotations

import argparse
import os
import time

import numpy as np

CASES = {"default": {}, "radial": {"operating.radial_load": "1000 N", "lubricant.oil": "4106"},
         "axial100": {"operating.axial_load": "100 N"},
         "axial6k": {"operating.axial_load": "6000 N", "lubricant.oil": "4050"}}


def statistics(ds) -> dict[str, float]:
    """Statistics over the second half of a run: what a cage-stability or power-loss user reads."""
    t = ds["time"].values
    h = ds.isel(time=t >= t[-1] / 2)
    r = np.hypot(h["cage_center_y"].values, h["cage_center_z"].values)
    return {
        "cage speed [rad/s]": float(h["cage_speed"].mean()),
        "whirl radius mean [um]": 1e6 * float(r.mean()),
        "whirl radius sd [um]": 1e6 * float(r.std()),
        "cage y sd [um]": 1e6 * float(h["cage_center_y"].std()),
        "ball-cage force mean [N]": float(np.abs(h["ball_cage_force"]).mean()),
        "guide-land force mean [N]": float(np.hypot(h["cage_land_force_y"], h["cage_land_force_z"]).mean()),
        "power loss mean [W]": float(h["power_loss"].mean()),
        "inner-ring friction torque mean [N m]": float(h["inner_ring_friction_torque"].mean()),
    }


def ensemble(case, span, members, settings, model):
    """``members`` runs of ``span`` from starts perturbed by k 1e-9 m/s in ydot_c; (stats per member, solver info)."""
    from hsbearing.systems.angular_contact.dynamics import simulate

    L = model.layout
    out, info = [], []
    for k in range(members):
        y0 = model.y0.copy()
        y0[L.cage("ydot_c")] += k * 1e-9
        c0 = time.process_time()
        ds = simulate(case, span, model=model, y0=y0, cvode_settings=settings, annotate=False)
        info.append({"cpu": time.process_time() - c0, "steps": int(ds.attrs["solver_steps"]),
                     "jac": int(ds.attrs["solver_jac_evals"]), "lu": int(ds.attrs["solver_linear_solver_setups"]),
                     "ncf": int(ds.attrs["solver_nonlinear_convergence_failures"])})
        out.append(statistics(ds))
    return out, info


def compare(a: list[dict], b: list[dict]) -> dict[str, tuple[float, float, float]]:
    """Per statistic: (mean a, mean b, z = |mean a - mean b| / standard error of the difference)."""
    res = {}
    for key in a[0]:
        xa, xb = np.array([s[key] for s in a]), np.array([s[key] for s in b])
        se = np.sqrt(xa.var(ddof=1) / xa.size + xb.var(ddof=1) / xb.size)
        d = abs(xa.mean() - xb.mean())
        res[key] = (float(xa.mean()), float(xb.mean()), float(d / se) if se > 0 else (0.0 if d == 0 else np.inf))
    return res


def main(argv=None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--span", type=float, default=0.1)
    ap.add_argument("--members", type=int, default=4)
    ap.add_argument("--cases", default="default,radial")
    a = ap.parse_args(argv)
    import hsbearing as h
    from hsbearing.systems.angular_contact.dynamics import SOLVER_SETTINGS, build_model, simulate

    print(f"load average {' '.join(f'{x:.2f}' for x in os.getloadavg())}; {time.strftime('%Y-%m-%d %H:%M UTC', time.gmtime())}; "
          f"{a.span * 1e3:g} ms per member, {a.members} members, statistics over the second half")
    base = h.load_case("zhang2016")
    for name in a.cases.split(","):
        case = base.with_overrides(**CASES[name]) if CASES[name] else base
        m = build_model(case)
        simulate(case, 0.001, model=m)  # compile / cache load outside the timing
        sa, ia = ensemble(case, a.span, a.members, {}, m)
        sb, ib = ensemble(case, a.span, a.members, dict(SOLVER_SETTINGS), m)
        print(f"== case {name} {CASES[name] or '(bundled zhang2016)'}")
        for lab, info in (("CVODE defaults", ia), (f"SOLVER_SETTINGS {SOLVER_SETTINGS}", ib)):
            print(f"  {lab}: CPU {np.mean([i['cpu'] for i in info]):.2f} s per member, steps "
                  f"{np.mean([i['steps'] for i in info]):.0f}, Jacobians {np.mean([i['jac'] for i in info]):.0f}, "
                  f"LU {np.mean([i['lu'] for i in info]):.0f}, convergence failures {np.mean([i['ncf'] for i in info]):.1f}")
        print(f"  {'statistic':40s} {'defaults':>12s} {'settings':>12s} {'z':>6s}")
        for key, (ma, mb, z) in compare(sa, sb).items():
            print(f"  {key:40s} {ma:12.5g} {mb:12.5g} {z:6.2f}")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
