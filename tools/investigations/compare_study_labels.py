#!/usr/bin/env python
"""Compare the cage-motion labels of two study output directories cell by cell (table3/4/5.nc).

Usage: .venv/bin/python tools/investigations/compare_study_labels.py DIR_A DIR_B   (e.g. a study with --stop duration and one with
--stop converged, as `benchmarks/bench_sweep.py --study -o DIR` writes them).
"""
import sys

import xarray as xr

a, b = sys.argv[1], sys.argv[2]
seen = {}
diff = []
for t in ("table3", "table4", "table5"):
    da = xr.open_dataset(f"{a}/{t}.nc")
    db = xr.open_dataset(f"{b}/{t}.nc")
    dim = [d for d in da["classification"].dims if d != "oil"][0]
    for oil in da.oil.values:
        for i in range(da.sizes[dim]):
            la = str(da["classification"].sel(oil=oil).values[i])
            lb = str(db["classification"].sel(oil=oil).values[i])
            arch = str(da["archive"].sel(oil=oil).values[i])
            key = arch
            if key in seen:
                continue
            seen[key] = (t, oil, i, la, lb)
            if la != lb:
                diff.append((t, oil, str(da[f"{dim}_label"].values[i]) if f"{dim}_label" in da else i, la, lb))
print(f"{len(seen)} unique cells; {len(seen) - len(diff)} identical labels; {len(diff)} differ")
for d in diff:
    print("  differs:", d)
