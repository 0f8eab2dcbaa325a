"""The linear-regime fast-forward of growing whirls (hsbearing.systems.angular_contact.extend) on real map cells.

    python tools/investigations/fast_forward_check.py natural ARCHIVE [T0]
        a cell whose whirl saturated naturally: its case from ARCHIVE (a map point archive extended without
        the fast-forward), run to T0 (default 0.4 s), fast-forwarded and extended to 3.6 s; prints label, peak
        radius, frequency ratio, whirl_amplitude and the RMS radius over the last 0.25 s of both runs
    python tools/investigations/fast_forward_check.py cell ARCHIVE OUT.nc [BUDGET]
        a cell through the map's worker path (compute_point: 1.2 s, keep answer, extension with the fast-forward,
        budget default 7.2 s); prints the label before/after, the reason, simulated time, rhs evaluations

docs/sweeps.md, "Linear-regime fast-forward of growing whirls".
"""

from __future__ import annotations

import json
import sys
import time

import numpy as np
import xarray as xr


def _saturated(ds, w=0.25):
    t = ds["time"].values
    m = t >= t[-1] - w
    r = np.hypot(ds["cage_center_y"].values[m], ds["cage_center_z"].values[m])
    return float(np.sqrt(np.mean(r ** 2)))


def natural(archive: str, t0: float = 0.4) -> None:
    import hsbearing
    from hsbearing.case import loads_case
    from hsbearing.systems.angular_contact.extend import extend_until_determined

    nat = xr.open_dataset(archive)
    case = loads_case(nat.attrs["case_toml"], archive)
    ds = hsbearing.simulate(case, duration=t0, stop="duration")
    out = extend_until_determined(ds, 3.6, converge=True, keep_on_failure=True, fast_forward=True)
    for name, d in (("natural", nat), ("fast-forwarded", out)):
        print(f"{name}: {d.attrs['classification']}, peak {float(d['whirl_radius_max']) * 1e6:.2f} um, ratio "
              f"{float(d['whirl_frequency_ratio']):.5f}, whirl_amplitude {float(d['whirl_amplitude']) * 1e6:.1f} um, "
              f"RMS radius last 0.25 s {_saturated(d) * 1e6:.2f} um, simulated {float(d['time'].values[-1]):.3f} s, "
              f"rhs {d.attrs.get('solver_rhs_evals')}")
    print("fast_forward:", out.attrs.get("fast_forward"))


def cell(archive: str, out_path: str, budget: float = 7.2) -> None:
    from hsbearing.case import loads_case
    from hsbearing.workflows.sweeps.points import compute_point

    nat = xr.open_dataset(archive)
    case = loads_case(nat.attrs["case_toml"], archive)
    w0 = time.perf_counter()
    rec, ds = compute_point(case, "run", 1.2, None, keep="answer", extend=budget)
    ds.to_netcdf(out_path)
    t = ds["time"].values
    det = json.loads(ds.attrs.get("classification_details", "{}") or "{}")
    print(json.dumps({"before": nat.attrs["classification"], "after": ds.attrs["classification"],
                      "kind": det.get("kind"), "reason": ds.attrs.get("classification_reason", ""),
                      "stop": ds.attrs.get("extension_stop_reason", ""), "simulated_time": float(t[-1] - t[0]),
                      "rhs_evals": int(ds.attrs.get("solver_rhs_evals", 0)),
                      "fast_forward": json.loads(ds.attrs.get("fast_forward", "{}")),
                      "wall_time": time.perf_counter() - w0}, default=float))


if __name__ == "__main__":
    if len(sys.argv) >= 3 and sys.argv[1] == "natural":
        natural(sys.argv[2], *(float(a) for a in sys.argv[3:4]))
    elif len(sys.argv) >= 4 and sys.argv[1] == "cell":
        cell(sys.argv[2], sys.argv[3], *(float(a) for a in sys.argv[4:5]))
    else:
        print(__doc__, file=sys.stderr)
        sys.exit(2)
