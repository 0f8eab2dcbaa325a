"""Evidence for the stop rule (docs/sweeps.md, "Stop rule"): the checks of the rule on prefixes of full-length runs.

    PYTHONPATH=. python tools/investigations/stoprule_prefixes.py STUDY_DIR [--json OUT.json]

STUDY_DIR holds a study's full-length point archives (runs/) and its tables (table3.nc ...).  For every cell the
check (:func:`hsbearing.analysis.stoprule.check`) is evaluated on the prefixes 0.1, 0.15, 0.2, 0.3, ..., 1.2 s of its
archive; the rule (:func:`hsbearing.analysis.stoprule.decide`) is then replayed for the default thresholds and a grid of
minimum time x confirming checks x minimum points, and the label it would stop on is compared with the
full-length label of the table.  Nothing is integrated: a stopped run is exactly a prefix of the full run.
"""

from __future__ import annotations

import argparse
import glob
import json
from pathlib import Path

import numpy as np
import xarray as xr

from hsbearing.analysis import stoprule

TIMES = [0.1, 0.15, 0.2, 0.3, 0.4, 0.5, 0.6, 0.7, 0.8, 0.9, 1.0, 1.1, 1.2]


def prefix_checks(study_dir: Path) -> dict:
    cells = {}
    for tab in sorted(glob.glob(str(study_dir / "table*.nc"))):
        t = xr.open_dataset(tab)
        dims = list(t["classification"].dims)
        for idx in np.ndindex(t["classification"].shape):
            sel = dict(zip(dims, idx))
            name = str(t["archive"].isel(sel).values).split("/")[-1]
            cells[name] = dict(table=Path(tab).stem, cell="/".join(str(t[d].values[i]) for d, i in zip(dims, idx)),
                               label=str(t["classification"].isel(sel).values),
                               kind=str(t["classification_kind"].isel(sel).values))
    for name, c in cells.items():
        ds = xr.open_dataset(study_dir / "runs" / name)
        small = ds[list(stoprule.CHECK_VARIABLES)].load()
        small.attrs = {k: ds.attrs[k] for k in ("case_toml", "guide_clearance") if k in ds.attrs}
        ds.close()
        tt = small["time"].values
        c["clearance"] = float(small.attrs.get("guide_clearance", "nan"))
        c["checks"] = [stoprule.as_dict(stoprule.check(small.isel(time=slice(0, int(np.searchsorted(tt, T + 1e-9))))))
                       for T in TIMES if T <= tt[-1] + 1e-9]
    return cells


def replay(cells: dict, rule: dict | None = None, t_full: float = 1.2):
    """(cells agreeing, simulated seconds, differences, per-cell (stop time, label, reason))."""
    r = dict(stoprule.STOP_DEFAULTS, **(rule or {}))
    agree, total, diffs, rows = 0, 0.0, [], []
    for _name, c in sorted(cells.items(), key=lambda kv: (kv[1]["table"], kv[1]["cell"])):
        hist, stop_t, reason = [], None, ""
        for k in c["checks"]:
            on_grid = abs((k["t"] - r["min_time"]) / r["interval"] - round((k["t"] - r["min_time"]) / r["interval"])) < 1e-6
            if k["t"] < r["min_time"] - 1e-9 or not on_grid:
                continue
            if k["t"] >= t_full - 1e-9:
                break
            hist.append(stoprule.Check(**k))
            stop, reason = stoprule.decide(hist, r, c["clearance"])
            if stop:
                stop_t = k["t"]
                break
        label = hist[-1].label if stop_t else c["label"]
        total += stop_t or t_full
        agree += label == c["label"]
        if label != c["label"]:
            diffs.append((c["table"], c["cell"], c["label"], label, stop_t))
        rows.append((c["table"], c["cell"], c["label"], c["kind"], stop_t or t_full, label, reason))
    return agree, total, diffs, rows


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("study_dir", type=Path)
    ap.add_argument("--json", type=Path, default=None, help="write the checks of every prefix")
    ap.add_argument("--from-json", type=Path, default=None, help="replay checks written before")
    a = ap.parse_args(argv)
    cells = json.loads(a.from_json.read_text()) if a.from_json else prefix_checks(a.study_dir)
    if a.json:
        a.json.write_text(json.dumps(cells, indent=1))
    agree, total, diffs, rows = replay(cells)
    print(f"default rule: {agree}/{len(cells)} labels as the full-length runs, {total:.1f} s simulated of "
          f"{1.2 * len(cells):.1f}; differences: {diffs}")
    for row in rows:
        print(f"  {row[0]} {row[1]:14s} full {row[2]:13s} ({row[3]:10s}) stop {row[4]:.2f} s  {row[6][:100]}")
    for mt in (0.1, 0.2, 0.3, 0.4, 0.5):
        for cf in (1, 2, 3):
            for mp in (0, 20, 40):
                ag, tot, d, _ = replay(cells, dict(min_time=mt, confirm=cf, min_points=mp))
                print(f"min_time {mt} confirm {cf} min_points {mp}: {ag}/{len(cells)}, {tot:.1f} s",
                      [f"{x[0]} {x[1]}: {x[3]} at {x[4]}" for x in d])
    ag, tot, d, _ = replay(cells, dict(growth_max=1e9))
    print(f"without the growth guard: {ag}/{len(cells)}, {tot:.1f} s", [f"{x[0]} {x[1]}: {x[3]} at {x[4]}" for x in d])


if __name__ == "__main__":
    main()
