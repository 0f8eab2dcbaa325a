"""Per-cell table of a map computed without and with the extension of undetermined points (docs/sweeps.md).

    python tools/investigations/map_extension_table.py BEFORE_DIR AFTER_DIR

Reads ``map.nc`` of both directories (or, while a map is still running, its point archives) and prints a Markdown
table (rows: the map's y values; one cell per x value: the label before -> after, with the simulated time and how
the extension ended), the undetermined counts, the point wall-time sums and the directory sizes.
"""

from __future__ import annotations

import json
import sys
from pathlib import Path

import numpy as np
import xarray as xr


def _points(d: Path) -> dict:
    """``{(x label, y label): record}`` from the point archives of a map directory."""
    out = {}
    for p in sorted(d.glob("*.nc")):
        if p.name in ("map.nc", "sweep.nc"):
            continue
        try:
            with xr.open_dataset(p) as ds:
                a = dict(ds.attrs)
                t = ds["time"].values if "time" in ds.coords else np.zeros(1)
        except (OSError, ValueError):
            continue
        ov = json.loads(a.get("sweep_overrides", "{}"))
        rec = json.loads(a.get("sweep_record", "{}"))
        det = json.loads(a.get("classification_details", "{}") or "{}")
        key = tuple(str(v) for v in ov.values())
        out[key] = {"label": a.get("classification", "?"), "kind": det.get("kind", ""),
                    "detail": a.get("classification_detail", ""), "t": float(t[-1] - t[0]),
                    "growth": (det.get("growth") or {}).get("sigma"), "ext": a.get("extension_stop_reason", ""),
                    "n_ext": len(json.loads(a.get("extensions", "[]") or "[]")), "rate": a.get("extension_growth_rate"),
                    "wall": float(rec.get("wall_time", float("nan"))), "reason": a.get("classification_reason", "")}
    return out


def _short(r: dict) -> str:
    lab = r["label"] + (f" ({r['kind']})" if r["kind"] and r["label"] == "undetermined" else "")
    return lab.replace("1 period", "1P")


def _size(d: Path) -> int:
    return sum(p.stat().st_size for p in d.rglob("*") if p.is_file())


def main(before: str, after: str) -> int:
    b, a = _points(Path(before)), _points(Path(after))
    keys = sorted(set(b) | set(a))
    ys = sorted({k[0] for k in keys}, key=lambda s: float(s.split()[0]))
    xs = sorted({k[1] for k in keys}, key=lambda s: float(s.split()[0]))
    print("| " + " / ".join(("y", "x")) + " | " + " | ".join(xs) + " |")
    print("|---" * (len(xs) + 1) + "|")
    for y in ys:
        cells = []
        for x in xs:
            rb, ra = b.get((y, x)), a.get((y, x))
            if rb is None and ra is None:
                cells.append("")
                continue
            text = _short(rb) if rb else "-"
            if ra:
                text += " -> " + _short(ra)
                if ra["n_ext"]:
                    text += f" ({ra['t']:.2g} s, {ra['ext'].split(':')[0]})"
            cells.append(text)
        print(f"| {y} | " + " | ".join(cells) + " |")
    for name, pts in (("before", b), ("after", a)):
        und = [(k, r) for k, r in pts.items() if r["label"] == "undetermined"]
        wall = sum(r["wall"] for r in pts.values() if np.isfinite(r["wall"]))
        sim = sum(r["t"] for r in pts.values())
        print(f"\n{name}: {len(pts)} points, {len(und)} undetermined, sum of point wall times {wall:.0f} s, "
              f"simulated {sim:.1f} s")
        for k, r in und:
            g = f", growth {r['growth']:.3g}/s" if r["growth"] is not None else ""
            print(f"  {k}: {r['kind']}{g}, {r['t']:.3g} s; {r['ext'] or r['reason'][:160]}")
    print(f"\nsizes: before {_size(Path(before)) / 1e6:.1f} MB, after {_size(Path(after)) / 1e6:.1f} MB")
    return 0


if __name__ == "__main__":
    if len(sys.argv) != 3:
        print(__doc__, file=sys.stderr)
        sys.exit(2)
    sys.exit(main(sys.argv[1], sys.argv[2]))
