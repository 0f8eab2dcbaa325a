"""Before/after figure and table of the guide-land correction (issue 14; docs/validation/cage_whirl.md).

Usage::

    # before: main at 7229e2e (one 11 mm pi-film); after: this branch (two Reynolds/Guembel lands)
    hsbearing run zhang2016 --set lubricant.oil=4109 -o b_4109.nc      # on each checkout, and oil 4106
    .venv/bin/python tools/investigations/land_before_after.py --before b_4109.nc b_4106.nc --after a_4109.nc a_4106.nc \
        --figure docs/validation/cage_whirl_figures/land_before_after.png

Prints, per run, over the last 0.2 s: cage orbit radius relative to the guide and pocket clearances (mean,
min, max), whirl/cage speed ratio (slope of the unwrapped orbit angle / mean cage speed), the run's
classification, the mean and peak magnitude of the land force and of the ball/pocket force, the time the
cage first reaches 0.95 of the guide clearance, the mean cage slip ratio and the solver steps.
"""

from __future__ import annotations

import argparse

import numpy as np
import xarray as xr


def summary(ds, window=0.2):
    t = ds["time"].values
    y, z = ds["cage_center_y"].values, ds["cage_center_z"].values
    r = np.hypot(y, z)
    cg, cp = float(ds.attrs["guide_clearance"]), float(ds.attrs["pocket_clearance"])
    sel = t >= t[-1] - window
    k = np.nonzero(r > 0.95 * cg)[0]
    Fl = np.hypot(ds["cage_land_force_y"].values, ds["cage_land_force_z"].values)
    Qc = ds["ball_cage_force"].values
    whirl = np.polyfit(t[sel], np.unwrap(np.arctan2(z[sel], y[sel])), 1)[0]
    return {
        "oil": ds.attrs.get("case_toml", "").split('oil = "')[1].split('"')[0] if 'oil = "' in ds.attrs.get("case_toml", "") else "?",
        "r_mean/c_g": np.mean(r[sel]) / cg, "r_min/c_g": r[sel].min() / cg, "r_max/c_g": r[sel].max() / cg,
        "r_mean/c_p": np.mean(r[sel]) / cp,
        "whirl/cage": whirl / np.mean(ds["cage_speed"].values[sel]),
        "classification": str(ds.attrs.get("classification", "?")),
        "confidence": float(ds.attrs.get("classification_confidence", np.nan)),
        "land force mean [N]": Fl[sel].mean(), "land force max [N]": Fl[sel].max(),
        "pocket force mean [N]": Qc[sel].mean(), "pocket force max [N]": Qc[sel].max(),
        "t(r > 0.95 c_g) [s]": t[k[0]] if len(k) else np.nan,
        "slip ratio [%]": 100 * float(np.mean(ds["cage_slip_ratio"].values[sel])),
        "steps": int(ds.attrs.get("solver_steps", -1)),
    }


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--before", nargs="+", required=True)
    ap.add_argument("--after", nargs="+", required=True)
    ap.add_argument("--figure")
    ap.add_argument("--after-label", default="after (2 x 1.83 mm Reynolds/Guembel lands)",
                    help="title of the 'after' panels (e.g. the combined issue-14 model: lands + pocket film)")
    ap.add_argument("--title", default="zhang2016, 14000 r/min, 1 kN, 130 degC: cage whirl orbit before/after the "
                    "guide-land correction")
    a = ap.parse_args(argv)
    rows = []
    for tag, files in (("before", a.before), ("after", a.after)):
        for f in files:
            ds = xr.open_dataset(f)
            rows.append((tag, f, ds, summary(ds)))
    keys = list(rows[0][3])
    print("| run | " + " | ".join(keys) + " |")
    print("|---" * (len(keys) + 1) + "|")
    for tag, f, _, s in rows:
        print(f"| {tag} | " + " | ".join(str(v) if isinstance(v, (str, int)) else f"{float(v):.4g}" for v in s.values()) + " |")
    if a.figure:
        import matplotlib

        matplotlib.use("Agg")
        import matplotlib.pyplot as plt

        n = len(a.before)
        fig, axes = plt.subplots(2, n, figsize=(4.6 * n, 9), squeeze=False)
        for i, (tag, f, ds, s) in enumerate(rows):
            ax = axes[0 if tag == "before" else 1, i % n]
            t = ds["time"].values
            y, z = ds["cage_center_y"].values * 1e6, ds["cage_center_z"].values * 1e6
            cg = float(ds.attrs["guide_clearance"]) * 1e6
            early = t < 0.15
            ax.plot(y[early], z[early], color="0.75", lw=0.6, label="first 150 ms")
            ax.plot(y[~early], z[~early], lw=0.5, label="after 150 ms")
            th = np.linspace(0, 2 * np.pi, 400)
            ax.plot(cg * np.cos(th), cg * np.sin(th), "r--", lw=1, label=f"guide clearance {cg:.0f} um")
            ax.set_aspect("equal")
            ax.set_xlim(-1.15 * cg, 1.15 * cg)
            ax.set_ylim(-1.15 * cg, 1.15 * cg)
            ax.set_xlabel("cage centre D_Y [um]")
            ax.set_ylabel("cage centre D_Z [um]")
            label = "before (one 11 mm pi-film)" if tag == "before" else a.after_label
            ax.set_title(f"oil {s['oil']}, {label}\nr/c_g {s['r_mean/c_g']:.2f}, whirl/cage {s['whirl/cage']:.2f}, "
                         f"{s['classification']}", fontsize=9)
            if i % n == 0:
                ax.legend(fontsize=7, loc="lower left")
        fig.suptitle(a.title)
        fig.tight_layout()
        fig.savefig(a.figure, dpi=110)
        print(f"figure: {a.figure}")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
