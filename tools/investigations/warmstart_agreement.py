"""Warm starts against cold starts (issue 28, item 2; docs/sweeps.md "Warm starts").

    PYTHONPATH=. python tools/investigations/warmstart_agreement.py STUDY_DIR [-j 2] [--json OUT.json]

STUDY_DIR holds a full-length (cold) study: runs/ and table3.nc ... .  Each cell listed in PAIRS is re-run from
the final state of its neighbouring cell (the next value of the table's varied key, same oil) with the stop rule
and the warm transient rule (:data:`hsbearing.workflows.warmstart.WARM_RULE`), and its label compared with the cold
full-length label of that cell.  Nothing is written into STUDY_DIR.
"""

from __future__ import annotations

import argparse
import json
import time
from concurrent.futures import ProcessPoolExecutor
from pathlib import Path

import numpy as np
import xarray as xr

#: (table, oil, neighbour value, target value): adjacent cells of the nominal Zhang et al. 2016 study
PAIRS = [
    ("table3", "4109", 300.15, 353.15), ("table3", "4050", 353.15, 453.15),
    ("table4", "4109", 500.0, 1000.0), ("table4", "4109", 1000.0, 2000.0), ("table4", "4050", 1000.0, 2000.0),
    ("table4", "4106", 3000.0, 6000.0),
    ("table5", "4109", 100.0, 500.0), ("table5", "4106", 500.0, 1000.0), ("table5", "4109", 500.0, 1000.0),
]


def _cell(study_dir: Path, table: str, oil: str, value: float):
    t = xr.open_dataset(study_dir / f"{table}.nc")
    dim = [d for d in t["classification"].dims if d != "oil"][0]
    c = t.sel(oil=oil).sel({dim: value}, method="nearest")
    return dict(archive=study_dir / "runs" / str(c["archive"].values).split("/")[-1],
                label=str(c["classification"].values), kind=str(c["classification_kind"].values),
                slip=float(c["mean_cage_slip_ratio"].values), amplitude=float(c["whirl_amplitude"].values))


def run_pair(args):
    study_dir, (table, oil, v_from, v_to) = args
    from hsbearing.case import loads_case
    from hsbearing.workflows.warmstart import simulate_warm

    src, dst = _cell(study_dir, table, oil, v_from), _cell(study_dir, table, oil, v_to)
    nb = xr.open_dataset(src["archive"])
    nb = nb[["final_state"]].assign_attrs(nb.attrs).load()
    with xr.open_dataset(dst["archive"]) as d:
        case = loads_case(d.attrs["case_toml"], str(dst["archive"]))
    w0 = time.perf_counter()
    ds = simulate_warm(case, nb, duration=1.2)
    return dict(table=table, oil=oil, neighbour=v_from, value=v_to, cold_label=dst["label"], cold_kind=dst["kind"],
                cold_slip=dst["slip"], cold_amplitude=dst["amplitude"],
                warm_label=ds.attrs["classification"], warm_kind=ds.attrs.get("classification_kind", ""),
                warm_slip=float(ds["mean_cage_slip_ratio"]), warm_amplitude=float(ds["whirl_amplitude"]),
                stopped_at=float(ds.attrs["stopped_at"]), end=float(ds["time"][-1]), wall=time.perf_counter() - w0,
                rhs_evals=int(ds.attrs.get("solver_rhs_evals", -1)), reason=ds.attrs["stop_reason"])


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("study_dir", type=Path)
    ap.add_argument("-j", "--jobs", type=int, default=2)
    ap.add_argument("--json", type=Path, default=None)
    a = ap.parse_args(argv)
    with ProcessPoolExecutor(a.jobs) as ex:
        rows = list(ex.map(run_pair, [(a.study_dir, p) for p in PAIRS]))
    agree = sum(r["warm_label"] == r["cold_label"] for r in rows)
    for r in rows:
        print(f"{r['table']} {r['oil']} {r['neighbour']:g} -> {r['value']:g}: cold {r['cold_label']} ({r['cold_kind']}), "
              f"warm {r['warm_label']} ({r['warm_kind']}) stopped at {r['end']:.2f} s, wall {r['wall']:.0f} s; slip "
              f"{r['cold_slip']:.4g} / {r['warm_slip']:.4g}, whirl {r['cold_amplitude'] * 1e6:.3g} / "
              f"{r['warm_amplitude'] * 1e6:.3g} um{'' if r['warm_label'] == r['cold_label'] else '   DIFFERENT'}")
    ends = np.array([r["end"] for r in rows])
    print(f"agreement {agree}/{len(rows)}; simulated {ends.sum():.2f} s (mean {ends.mean():.2f} s per point)")
    if a.json:
        a.json.write_text(json.dumps(rows, indent=1))


if __name__ == "__main__":
    main()
