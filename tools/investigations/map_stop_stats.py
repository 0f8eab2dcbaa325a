"""Stop-rule statistics of a finished map or sweep directory: which points stopped early, when, why.

    python tools/investigations/map_stop_stats.py DIR            # DIR/map.nc (or DIR/sweep.nc) and its point archives

Prints one line per point (grid values, class and kind, stopped_at or "bound", simulated time, CVODE steps and rhs
evaluations, point wall time) and the totals: points stopped early, mean / total simulated time against the
upper bound, rhs evaluations, and the sum of point wall times.  Reads only; writes nothing.
"""

from __future__ import annotations

import math
import sys
from pathlib import Path

import numpy as np
import xarray as xr


def main(argv: list[str] | None = None) -> int:
    argv = sys.argv[1:] if argv is None else argv
    if len(argv) != 1:
        print(__doc__.strip().splitlines()[2].strip(), file=sys.stderr)
        return 2
    d = Path(argv[0])
    src = d / "map.nc" if (d / "map.nc").exists() else d / "sweep.nc"
    if not src.exists():
        print(f"map_stop_stats.py: {d}: no map.nc or sweep.nc", file=sys.stderr)
        return 2
    ds = xr.open_dataset(src)
    dims = ds["status"].dims
    rows = []
    for ix in np.ndindex(*ds["status"].shape):
        pt = ds.isel(dict(zip(dims, ix)))
        coords = "  ".join(f"{dim}={pt[f'{dim}_label'].values.item() if f'{dim}_label' in pt.coords else pt[dim].values.item()}"
                           for dim in dims)
        arch = str(pt["archive"].values.item())
        if not arch:
            rows.append((coords, None))
            continue
        with xr.open_dataset(d / arch) as a:
            at = a.attrs
            t_end = float(a["time"].values[-1])
            rows.append((coords, {
                "label": f"{at.get('classification', '?')} ({at.get('classification_kind', '?')})",
                "stopped_at": float(at.get("stopped_at", math.nan)),
                "t_end": t_end,
                "steps": int(at.get("solver_steps", 0)),
                "rhs": int(at.get("solver_rhs_evals", 0)),
                "wall": float(pt["wall_time"]),
            }))
    bound = max(r["t_end"] for _, r in rows if r)
    for coords, r in rows:
        if r is None:
            print(f"{coords}  (no archive)")
            continue
        st = "bound" if math.isnan(r["stopped_at"]) else f"{r['stopped_at']:.2f} s"
        print(f"{coords}  {r['label']}  stop {st}  simulated {r['t_end']:.2f} s  steps {r['steps']}  rhs {r['rhs']}  "
              f"wall {r['wall']:.1f} s")
    ok = [r for _, r in rows if r]
    early = [r for r in ok if not math.isnan(r["stopped_at"])]
    sim = np.array([r["t_end"] for r in ok])
    print(f"{len(ok)} points with archives; {len(early)} stopped early by the stop rule, {len(ok) - len(early)} ran to "
          f"the {bound:g} s bound; simulated time mean {sim.mean():.3f} s (total {sim.sum():.1f} s = "
          f"{sim.sum() / (bound * len(ok)):.2f} of {len(ok)} x {bound:g} s); stop times of the early points: "
          + (f"{min(r['stopped_at'] for r in early):.1f}-{max(r['stopped_at'] for r in early):.1f} s, mean "
             f"{np.mean([r['stopped_at'] for r in early]):.2f} s" if early else "none"))
    print(f"rhs evaluations {sum(r['rhs'] for r in ok)}; sum of point wall times {sum(r['wall'] for r in ok):.0f} s; "
          f"map wall time {ds.attrs.get('map_wall_time', math.nan):.0f} s")
    return 0


if __name__ == "__main__":
    sys.exit(main())
