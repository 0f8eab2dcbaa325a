"""Issue 15, item 4: the default case and the seed's Table 3 temperatures for each oil, old and chosen reading.

Usage (from the repository root; serial, long: minutes per run on a loaded 2-core machine)::

    .venv/bin/python docs/figures/oils_consequence_runs.py OUT.jsonl [--duration-default 0.3] [--duration 0.05]
                                                                      [--reading old|chosen]
    .venv/bin/python docs/figures/oils_consequence_runs.py --table OUT.jsonl      # the markdown table of docs/traction.md

"old"    = lubricant.traction_law "bounded" (4109, 4106) / "analogue_4106" (4050), S a fraction,
           critical-load notch as printed, and lubricant.viscosity_law "table1";
"chosen" = the defaults of this version: "percent" / "analogue_4106_percent" and "walther".
Each line of OUT.jsonl: the case overrides, the run's summary (hsbearing.analysis.orbit.summary),
the mean ball pitch angle after the transient [deg] and the quasi-static cage slip and pitch angle.
"""

from __future__ import annotations

import json
import math
import sys
import time

import numpy as np

import hsbearing
from hsbearing.analysis import orbit
from hsbearing.analysis import poincare as pc

OLD = {"4109": "bounded", "4106": "bounded", "4050": "analogue_4106"}


def pitch_deg(wx, wy):
    """Ball pitch angle beta = atan2(-omega_y, omega_x) folded to [-90, 90] deg (quasistatic.py convention)."""
    b = np.arctan2(-wy, wx)
    b = np.where(b > 0.5 * np.pi, b - np.pi, np.where(b < -0.5 * np.pi, b + np.pi, b))
    return np.degrees(b)


def one(oil, T_C, reading, duration):
    over = {"lubricant.oil": oil, "lubricant.temperature": f"{T_C:g} degC"}
    if reading == "old":
        over.update({"lubricant.traction_law": OLD[oil], "lubricant.viscosity_law": "table1"})
    case = hsbearing.load_case("zhang2016", **over)
    rec = {"oil": oil, "T_C": T_C, "reading": reading, "duration": duration, "overrides": over}
    qs = hsbearing.quasi_static(case)
    rec["qs_cage_slip_ratio"] = float(np.asarray(qs["cage_slip_ratio"]).mean()) if "cage_slip_ratio" in qs else float("nan")
    rec["qs_pitch_deg"] = float(np.degrees(np.asarray(qs["ball_pitch_angle"]).mean())) if "ball_pitch_angle" in qs else float("nan")
    t0 = time.time()
    try:
        ds = hsbearing.simulate(case, duration=duration)
        rec["status"] = ds.attrs.get("status")
    except Exception as exc:  # keep going: report the failure in the table
        rec["status"] = f"failed: {exc}"
        rec["wall_s"] = time.time() - t0
        return rec
    rec["wall_s"] = time.time() - t0
    rec["solver_steps"] = int(ds.attrs.get("solver_steps", -1))
    s = orbit.summary(ds, case)
    for k in ("classification", "whirl_frequency_ratio", "mean_cage_slip_ratio", "whirl_amplitude",
              "whirl_radius_max", "n_poincare_points", "transient_discarded"):
        rec[k] = s.get(k)
    mask, _ = pc.after_transient(ds)
    idx = np.nonzero(mask)[0]
    wx = ds["ball_angular_velocity_x"].values[idx].astype(float)
    wy = ds["ball_angular_velocity_y"].values[idx].astype(float)
    rec["pitch_deg"] = float(np.mean(pitch_deg(wx, wy)))
    rec["pitch_deg_std"] = float(np.std(pitch_deg(wx, wy)))
    for side in ("inner", "outer"):
        v = f"{side}_slide_roll_ratio"
        if v in ds:
            rec[f"{side}_srr_rms"] = float(np.sqrt(np.mean(ds[v].values[idx].astype(float) ** 2)))
    return rec


def from_archive(oil, T_C, reading, duration, nc, over=None):
    """The record of :func:`one` computed from an existing run archive (e.g. a study point) instead of a new run."""
    from hsbearing.results import open_run

    over = over or {"lubricant.oil": oil, "lubricant.temperature": f"{T_C:g} degC"}
    case = hsbearing.load_case("zhang2016", **over)
    ds = open_run(nc)
    rec = {"oil": oil, "T_C": T_C, "reading": reading, "duration": duration, "overrides": over, "archive": str(nc),
           "status": ds.attrs.get("status"), "solver_steps": int(ds.attrs.get("solver_steps", -1))}
    s = orbit.summary(ds, case)
    for k in ("classification", "whirl_frequency_ratio", "mean_cage_slip_ratio", "whirl_amplitude",
              "whirl_radius_max", "n_poincare_points", "transient_discarded"):
        rec[k] = s.get(k)
    mask, _ = pc.after_transient(ds)
    idx = np.nonzero(mask)[0]
    b = pitch_deg(ds["ball_angular_velocity_x"].values[idx].astype(float),
                  ds["ball_angular_velocity_y"].values[idx].astype(float))
    rec["pitch_deg"], rec["pitch_deg_std"] = float(np.mean(b)), float(np.std(b))
    v = "inner_slide_roll_ratio"
    if v in ds:
        rec["inner_srr_rms"] = float(np.sqrt(np.mean(ds[v].values[idx].astype(float) ** 2)))
    return rec


def chosen_from_study(study_dir, out):
    """Append the "chosen" records of Table 3 from a nominal `hsbearing study zhang2016 -o STUDY_DIR`."""
    import pathlib

    import xarray as xr

    d = pathlib.Path(study_dir)
    t3 = xr.open_dataset(d / "table3.nc")
    for oil in t3.oil.values:
        for i, T in enumerate(t3.temperature.values):
            nc = d / str(t3["archive"].sel(oil=oil).values[i])
            rec = from_archive(str(oil), round(float(T) - 273.15, 2), "chosen", 1.2, nc)
            with open(out, "a") as fh:
                fh.write(json.dumps(rec) + "\n")
            print(json.dumps(rec), flush=True)


def table(path):
    """Markdown table: old vs chosen side by side per (oil, T)."""
    recs = {}
    for line in open(path):
        r = json.loads(line)
        recs[(r["oil"], r["T_C"], r["reading"])] = r
    rows = ["| oil | T [degC] | run [s] | class old / chosen | whirl / cage speed old / chosen | cage slip [%] old / chosen | "
            "ball pitch [deg] old / chosen | inner SRR rms [%] old / chosen | whirl radius RMS [um] old / chosen |",
            "|---|---|---|---|---|---|---|---|---|"]

    def f(r, k, scale=1.0, fmt="{:.3g}"):
        v = r.get(k) if r else None
        return "-" if v is None or (isinstance(v, float) and not math.isfinite(v)) else fmt.format(scale * v)

    for oil in ("4109", "4106", "4050"):
        for T in (27.0, 80.0, 130.0, 180.0):
            o, c = recs.get((oil, T, "old")), recs.get((oil, T, "chosen"))
            if not (o or c):
                continue
            dur = (o or c)["duration"]
            rows.append(f"| {oil} | {T:g} | {dur:g} | {(o or {}).get('classification', '-')} / {(c or {}).get('classification', '-')} | "
                        f"{f(o, 'whirl_frequency_ratio')} / {f(c, 'whirl_frequency_ratio')} | "
                        f"{f(o, 'mean_cage_slip_ratio', 100, '{:.2f}')} / {f(c, 'mean_cage_slip_ratio', 100, '{:.2f}')} | "
                        f"{f(o, 'pitch_deg', 1, '{:.1f}')} / {f(c, 'pitch_deg', 1, '{:.1f}')} | "
                        f"{f(o, 'inner_srr_rms', 100, '{:.2f}')} / {f(c, 'inner_srr_rms', 100, '{:.2f}')} | "
                        f"{f(o, 'whirl_amplitude', 1e6, '{:.0f}')} / {f(c, 'whirl_amplitude', 1e6, '{:.0f}')} |")
    return "\n".join(rows)


def main(argv):
    if argv[1] == "--chosen-from-study":  # --chosen-from-study STUDY_DIR OUT.jsonl
        chosen_from_study(argv[2], argv[3])
        return
    if argv[1] == "--table":
        print(table(argv[2]))
        return
    out = argv[1]
    dur_default = float(argv[argv.index("--duration-default") + 1]) if "--duration-default" in argv else 0.3
    dur = float(argv[argv.index("--duration") + 1]) if "--duration" in argv else 0.05
    readings = ("old", "chosen")
    if "--reading" in argv:  # run one reading only (two processes on two cores)
        readings = (argv[argv.index("--reading") + 1],)
    jobs = [("4109", 130.0, r, dur_default) for r in readings]
    for oil in ("4109", "4106", "4050"):
        for T in (27.0, 80.0, 130.0, 180.0):
            if oil == "4109" and T == 130.0:
                continue
            for r in readings:
                jobs.append((oil, T, r, dur))
    for job in jobs:
        rec = one(*job)
        with open(out, "a") as fh:
            fh.write(json.dumps(rec) + "\n")
        print(json.dumps(rec), flush=True)


if __name__ == "__main__":
    main(sys.argv)
