#!/usr/bin/env python
"""Two runs of a study side by side, cell by cell: label, cage slip ratio and power loss (and the extension).

    PYTHONPATH=. python tools/investigations/study_before_after.py DIR_A DIR_B [--names A,B] [--md]

DIR_A, DIR_B: output directories of ``hsbearing study`` (their table3/4/5.nc).  For a study with the extension of
undetermined points, the label the point had before its first extension is read from the extension_stop_reason
column ("determined: ... after", "budget: ...") -- the table shows "label before -> label after".  Prints one row per
cell and the counts (identical labels, undetermined in each, agreement with the paper's label).
"""
from __future__ import annotations

import sys

import numpy as np
import xarray as xr


def _cells(d):
    out = {}
    for t in ("table3", "table4", "table5"):
        try:
            ds = xr.open_dataset(f"{d}/{t}.nc")
        except FileNotFoundError:
            continue
        dim = [x for x in ds["classification"].dims if x != "oil"][0]
        for oil in ds.oil.values:
            for i in range(ds.sizes[dim]):
                s = ds.sel(oil=oil).isel({dim: i})
                val = s[dim].values
                key = (t, str(oil), f"{float(val):g}" if np.ndim(val) == 0 and np.issubdtype(np.asarray(val).dtype, np.number) else str(val))
                ext = str(s["extension_stop_reason"].values) if "extension_stop_reason" in s else ""
                n_ext = int(np.nan_to_num(s["extension_count"].values)) if "extension_count" in s else 0
                out[key] = dict(label=str(s["classification"].values), paper=str(s["paper_classification"].values),
                                slip=100 * float(s["mean_cage_slip_ratio"].values), power=float(s["power_loss"].values),
                                ext=ext, n_ext=n_ext,
                                t_sim=float(s["simulated_time"].values) if "simulated_time" in s else float("nan"))
    return out


def main(argv):
    md = "--md" in argv
    names = ["A", "B"]
    if "--names" in argv:
        names = argv[argv.index("--names") + 1].split(",")
    dirs = [a for a in argv if not a.startswith("--") and a not in (",".join(names),)]
    a, b = _cells(dirs[0]), _cells(dirs[1])
    keys = [k for k in a if k in b]
    head = ["table", "oil", "value", "paper", f"{names[0]} label", f"{names[1]} label", f"slip {names[0]} [%]",
            f"slip {names[1]} [%]", f"power {names[0]} [W]", f"power {names[1]} [W]"]
    rows = []
    same = und_a = und_b = ok_a = ok_b = 0
    for k in keys:
        x, y = a[k], b[k]
        lb = y["label"] if not y["n_ext"] else f"{y['label']} (extended {y['n_ext']}x to {y['t_sim']:.2g} s)"
        same += x["label"] == y["label"]
        und_a += x["label"].startswith("undetermined")
        und_b += y["label"].startswith("undetermined")
        ok_a += x["label"] == x["paper"]
        ok_b += y["label"] == y["paper"]
        rows.append([k[0], k[1], k[2], x["paper"], x["label"], lb, f"{x['slip']:.2f}", f"{y['slip']:.2f}",
                     f"{x['power']:.2f}", f"{y['power']:.2f}"])
    if md:
        print("| " + " | ".join(head) + " |")
        print("|" + "---|" * len(head))
        for r in rows:
            print("| " + " | ".join(r) + " |")
    else:
        for r in rows:
            print("  ".join(r))
    print(f"\n{len(keys)} cells: {same} identical labels; undetermined {und_a} ({names[0]}) vs {und_b} ({names[1]}); "
          f"agree with the paper {ok_a} vs {ok_b}")


if __name__ == "__main__":
    main(sys.argv[1:])
