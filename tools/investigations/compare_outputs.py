"""Behaviour before and after a refactoring: snapshot every CLI output of the bundled cases, the right-hand side
and the Jacobian of the dynamic models and every Dataset variable of the archives, then compare two snapshots.

    python tools/investigations/compare_outputs.py snapshot DIR      # run the commands, write DIR/
    python tools/investigations/compare_outputs.py compare OLD NEW   # differences, one line each; exit 1 on any

It uses only the CLI and the public API (``hsbearing.dynamic_model``), so the same script runs on both sides of a
change that moves modules.  Printed lines are compared after masking wall times and temporary paths; archives are
compared variable by variable (bit-identical expected; the ODE runs within 5e-3 of each variable's scale, the
bound tests/validation of the regression archives use, because a fresh and a cached numba kernel differ there).
"""

from __future__ import annotations

import json
import re
import subprocess
import sys
from pathlib import Path

import numpy as np

# (label, argv after "hsbearing", archive suffix or None): every bundled case through every command that
# answers for it, short durations so the whole snapshot takes a few minutes.
COMMANDS = [
    ("cases", ["cases"], None),
    ("oils", ["oils"], None),
    ("oils_4109_at", ["oils", "4109", "--at", "zhang2016", "-o", "{out}.png"], None),
    ("check_zhang2016", ["check", "zhang2016"], None),
    ("run_zhang2016", ["run", "zhang2016", "--duration", "0.004s", "-q", "--no-figure", "-o", "{out}.nc"], "nc"),
    ("qs_zhang2016", ["quasistatic", "zhang2016", "-o", "{out}.nc"], "nc"),
    ("friction_zhang2016", ["friction", "zhang2016", "--speeds", "6000,14000rpm", "-o", "{out}.nc"], "nc"),
    ("thermal_zhang2016", ["thermal", "zhang2016", "-o", "{out}.nc"], "nc"),
    ("life_zhang2016", ["life", "zhang2016", "-o", "{out}.nc"], "nc"),
    ("check_dgbb_6206", ["check", "dgbb_6206"], None),
    ("qs_dgbb_6207", ["quasistatic", "dgbb_6207", "-o", "{out}.nc"], "nc"),
    ("friction_dgbb_6206", ["friction", "dgbb_6206", "--speeds", "500,5000rpm", "-o", "{out}.nc"], "nc"),
    ("life_dgbb_6208", ["life", "dgbb_6208", "-o", "{out}.nc"], "nc"),
    ("run_dgbb_6206", ["run", "dgbb_6206", "--duration", "0.002s", "-q", "--no-figure", "-o", "{out}.nc"], "nc"),
    ("check_gyro", ["check", "jiang2014_gyro"], None),
    ("friction_gyro", ["friction", "jiang2014_gyro", "-o", "{out}.nc"], "nc"),
    ("run_gyro", ["run", "jiang2014_gyro", "--duration", "0.05s", "-q", "--no-figure", "-o", "{out}.nc"], "nc"),
    ("check_wire_race", ["check", "shan2010_wire_race"], None),
    ("preload_wire_race", ["preload", "shan2010_wire_race", "-o", "{out}.nc"], "nc"),
    ("bad_key", ["run", "zhang2016", "--set", "operating.axial_lod=1kN"], None),
]
ODE = ("run_",)
#: dynamic models whose rhs and Jacobian are compared: (label, bundled case, overrides)
MODEL_CASES = (
    ("zhang2016", "zhang2016", {}),
    ("zhang2016_4050_inner_guided", "zhang2016", {"lubricant.oil": "4050", "cage.guidance": "inner_ring"}),
    ("zhang2016_radial", "zhang2016", {"operating.radial_load": "500 N", "lubricant.oil": "4106"}),
)

_MASKS = [
    (re.compile(r"\d+(\.\d+)?\s*(ms|s)\b(?= wall| \(wall|,? wall)"), "<wall>"),
    (re.compile(r"wall[ _]time[^\n,;)]*"), "wall time <masked>"),
    (re.compile(r"/tmp/[^\s'\"]+"), "<tmp>"),
    (re.compile(r"compil[a-z]+ [^\n]*"), "<compile notice>"),
]


def _mask(text: str, out_dir: str) -> str:
    text = text.replace(out_dir, "<out>")
    for pat, rep in _MASKS:
        text = pat.sub(rep, text)
    return text


def snapshot(dest: Path, models_only: bool = False) -> None:
    dest.mkdir(parents=True, exist_ok=True)
    if not models_only:
        _snapshot_cli(dest)
    _snapshot_models(dest)


def _snapshot_cli(dest: Path) -> None:
    exe = str(Path(sys.executable).with_name("hsbearing"))
    meta = {}
    for label, argv, kind in COMMANDS:
        out = str(dest / label)
        args = [a.replace("{out}", out) for a in argv]
        p = subprocess.run([exe, *args], capture_output=True, text=True, timeout=900, cwd=dest)
        meta[label] = {"rc": p.returncode, "stdout": _mask(p.stdout, str(dest)),
                       "stderr": _mask(p.stderr, str(dest)), "archive": kind}
        print(f"{label}: exit {p.returncode}", flush=True)
    (dest / "cli.json").write_text(json.dumps(meta, indent=1))


def _snapshot_models(dest: Path) -> None:
    import hsbearing

    arrays = {}
    for name, case, overrides in MODEL_CASES:
        m = hsbearing.dynamic_model(hsbearing.load_case(case, **overrides))
        rng = np.random.default_rng(7)
        y0 = np.asarray(m.y0, dtype=float)
        for k, y in enumerate([y0, y0 * (1 + 1e-3 * rng.standard_normal(y0.size))]):
            yd = np.zeros_like(y)
            m.rhs(0.0, y, yd)
            arrays[f"{name}_rhs{k}"] = yd.copy()
            jac = np.zeros((y.size, y.size))
            m.jac(0.0, y, yd, jac)
            arrays[f"{name}_jac{k}"] = jac
        arrays[f"{name}_y0"] = y0
    np.savez(dest / "model.npz", **arrays)


def _scale(a: np.ndarray) -> float:
    a = np.asarray(a, dtype=float)
    finite = a[np.isfinite(a)]
    return float(np.max(np.abs(finite))) if finite.size else 0.0


def compare(old: Path, new: Path) -> int:
    import xarray as xr

    bad = 0
    a, b = json.loads((old / "cli.json").read_text()), json.loads((new / "cli.json").read_text())
    for label in a:
        for key in ("rc", "stdout", "stderr"):
            if a[label][key] != b.get(label, {}).get(key):
                bad += 1
                print(f"DIFF {label} {key}")
                if key != "rc":
                    import difflib

                    for line in difflib.unified_diff(a[label][key].splitlines(), b[label][key].splitlines(),
                                                     lineterm="", n=0):
                        print("   ", line)
        if a[label]["archive"] and a[label]["rc"] in (0, 1):
            fa, fb = old / f"{label}.nc", new / f"{label}.nc"
            if not fb.exists():
                print(f"DIFF {label}: archive missing")
                bad += 1
                continue
            da, db = xr.open_dataset(fa), xr.open_dataset(fb)
            names = set(da.variables) | set(db.variables)
            for v in sorted(names):
                if v not in da.variables or v not in db.variables:
                    print(f"DIFF {label}: variable {v} only in {'old' if v in da.variables else 'new'}")
                    bad += 1
                    continue
                x, y = da[v].values, db[v].values
                if x.shape != y.shape:
                    print(f"DIFF {label}.{v}: shape {x.shape} -> {y.shape}")
                    bad += 1
                    continue
                if x.dtype.kind in "fiu":
                    tol = 5e-3 * _scale(x) if label.startswith(ODE) else 0.0
                    diff = np.nanmax(np.abs(x.astype(float) - y.astype(float))) if x.size else 0.0
                    same_nan = np.array_equal(np.isnan(x.astype(float)), np.isnan(y.astype(float)))
                    if diff > tol or not same_nan:
                        print(f"DIFF {label}.{v}: max |d| {diff:.3e} (tolerance {tol:.3e})")
                        bad += 1
                elif not np.array_equal(x, y):
                    print(f"DIFF {label}.{v}: values differ")
                    bad += 1
                if dict(da[v].attrs) != dict(db[v].attrs):
                    print(f"DIFF {label}.{v}: attrs {dict(da[v].attrs)} -> {dict(db[v].attrs)}")
                    bad += 1
            skip = {"wall_time", "solver_wall_time", "created", "hsbearing_version", "history"}
            for k in sorted(set(da.attrs) | set(db.attrs)):
                if k in skip or "wall" in k or "time_s" in k:
                    continue
                va, vb = str(da.attrs.get(k)), str(db.attrs.get(k))
                if va != vb:
                    print(f"DIFF {label} attr {k}: {va[:200]!r} -> {vb[:200]!r}")
                    bad += 1
    ma, mb = np.load(old / "model.npz"), np.load(new / "model.npz")
    for k in ma.files:
        if k not in mb.files or ma[k].shape != mb[k].shape or not np.array_equal(ma[k], mb[k]):
            d = np.max(np.abs(ma[k] - mb[k])) if k in mb.files and ma[k].shape == mb[k].shape else float("nan")
            print(f"DIFF model {k}: max |d| {d:.3e}")
            bad += 1
    print(f"{bad} difference(s)")
    return 1 if bad else 0


if __name__ == "__main__":
    if sys.argv[1:2] == ["snapshot"]:
        snapshot(Path(sys.argv[2]).resolve(), models_only="--models-only" in sys.argv)
    elif sys.argv[1:2] == ["compare"]:
        sys.exit(compare(Path(sys.argv[2]), Path(sys.argv[3])))
    else:
        sys.exit(__doc__)
