"""Figure of an ``hsbearing friction`` archive (dim ``speed``, ``sliding_torque``): dgbb_prl method vs SKF 2004."""

from __future__ import annotations

import math
from pathlib import Path

import numpy as np

from hsbearing.plotting import common  # common.save_figure: one place to capture every figure
from hsbearing.plotting.common import RPM, _figure, case_labels, vals
from hsbearing.systems.deep_groove.friction import friction_torque

__all__ = ["plot_friction", "make_figures"]


def plot_friction(ds, path) -> Path:
    """Figure of ``hsbearing friction`` (dgbb_prl sliding method and SKF 2004 model) to ``path`` (PNG).

    (a) torques against the inner-ring speed [N mm]: the sliding components M_s (spinning), M_r (ball
    rotation), M_d (orbital) and their sum M_sl by the dgbb_prl method (solid), the SKF 2004 M_sl,
    M_rr, M_drag and total M (dashed / dotted); (b) contact load and angle of each ball at the first
    speed (the archive's ``note``).
    """
    path = Path(path)
    fig = _figure((12, 4.9))
    ax1, ax2 = fig.subplots(1, 2, width_ratios=[1.4, 1.0])
    rpm = vals(ds, "speed", RPM)
    lab = case_labels(ds)
    head = ", ".join([ds.attrs.get("case_name", "friction torque")]
                     + [lab[k] for k in ("axial_load", "radial_load") if k in lab])
    extra = [f"law {ds.attrs['friction_law']}" if "friction_law" in ds.attrs else "",
             f"\u03bd = {float(ds.attrs['kinematic_viscosity_mm2_s']):g} mm\u00b2/s" if "kinematic_viscosity_mm2_s" in ds.attrs else ""]
    fig.suptitle("friction torque: " + ", ".join([head] + [e for e in extra if e]), fontsize=11)
    rows = (("sliding_torque", "$M_{sl}$ sliding (dgbb_prl method)", "k", "-", 2.0),
            ("spinning_torque", "$M_s$ spinning", "C0", "-", 1.2),
            ("orbital_sliding_torque", "$M_d$ orbital (differential) sliding", "C2", "-", 1.2),
            ("rotation_sliding_torque", "$M_r$ ball-rotation sliding", "C1", "-", 1.2),
            ("skf_sliding_torque", "SKF 2004 $M_{sl}$", "k", "--", 1.4),
            ("skf_rolling_torque", "SKF 2004 $M_{rr}$ rolling", "C4", "--", 1.2),
            ("skf_drag_torque", "SKF 2004 $M_{drag}$", "C5", ":", 1.2),
            ("skf_total_torque", "SKF 2004 total $M$", "C3", "--", 1.6))
    for name, label, col, ls, lw in rows:
        if name in ds:
            ax1.plot(rpm, vals(ds, name, 1e3), ls=ls, color=col, lw=lw, marker="o" if len(rpm) <= 12 else None,
                     ms=4, label=label)
    if len(rpm) > 1 and np.all(rpm > 0) and rpm.max() / rpm.min() >= 10:
        ax1.set_xscale("log")
    ax1.set_xlabel("inner-ring speed n [r/min]")
    ax1.set_ylabel("torque [N mm]")
    ax1.set_title("(a) friction torques", fontsize=10)
    ax1.grid(alpha=0.3, which="both")
    ax1.legend(fontsize=7.5, loc="best")
    nb = None
    if "ball_contact_load" in ds:
        q = np.atleast_1d(vals(ds, "ball_contact_load"))
        nb = q.size
        x = np.arange(1, nb + 1)
        ax2.bar(x, q, width=0.6, color="C0", label="contact load Q")
        ax2.set_xticks(x)
        ax2.set_ylabel("contact load Q [N]")
        if "ball_contact_angle" in ds:
            a2 = ax2.twinx()
            a2.plot(x, np.degrees(np.atleast_1d(vals(ds, "ball_contact_angle"))), "o-", color="C3", label="contact angle")
            a2.set_ylabel("contact angle [\N{DEGREE SIGN}]", color="C3")
    ax2.set_xlabel("ball")
    sp = f" at n = {rpm[0]:.0f} r/min" if len(rpm) else ""
    ax2.set_title(f"(b) ball contacts{sp}", fontsize=10)
    ax2.grid(alpha=0.3, axis="y")
    return common.save_figure(fig, path)


# --------------------------------------------------------------------------- figures (dgbb_prl Figs. 8-16)


def make_figures(outdir="docs/figures", speeds_rpm=None) -> list:
    """Draw the dgbb_prl style figures (Figs. 8-16) as ``outdir/dgbb_*.png``; returns the paths.

    Solid: dgbb_prl method (this package); dashed: SKF 2004 catalogue M_sl;
    dotted: the seed's reading of the SKF model (differs only with radial load).
    """
    import matplotlib

    matplotlib.use("Agg")
    from pathlib import Path

    import matplotlib.pyplot as plt

    from hsbearing.case import load_case

    out = Path(outdir)
    out.mkdir(parents=True, exist_ok=True)
    rpm = np.asarray(speeds_rpm if speeds_rpm is not None else np.geomspace(100, 20000, 40))
    speeds = rpm * 2 * math.pi / 60
    paths = []

    def run(name="dgbb_6206", Fa=500, Fr=0, **extra):
        case = load_case(name, **{"operating.axial_load": f"{Fa} N", "operating.radial_load": f"{Fr} N", **extra})
        ds = friction_torque(case, speeds)
        seed = skf_seed_sliding(case, speeds)
        return ds, seed

    def skf_seed_sliding(case, w):
        from hsbearing.models.friction import skf2004

        return skf2004.skf_moments(case, w, reading="dgbb_prl")["skf_sliding_torque"]

    def save(fig, name):
        p = out / name
        fig.tight_layout()
        fig.savefig(p, dpi=110)
        plt.close(fig)
        paths.append(p)

    def components(Fa, Fr, fname, title):
        ds, seed = run(Fa=Fa, Fr=Fr)
        fig, ax = plt.subplots(figsize=(6.4, 4.2))
        for var, lab, st in (("sliding_torque", "$M_{sl}$ (dgbb_prl method)", "k-"), ("spinning_torque", "$M_s$ spinning", "C0-"),
                             ("rotation_sliding_torque", "$M_r$ ball rotation", "C1-"), ("orbital_sliding_torque", "$M_d$ orbital motion", "C2-")):
            ax.plot(rpm, ds[var].values * 1e3, st, label=lab)
        if Fa > 0:  # the energy-consistent spin reading
            alt, _ = run(Fa=Fa, Fr=Fr, **{"friction.spin_torque_reading": "power"})
            ax.plot(rpm, alt["sliding_torque"].values * 1e3, "k-.", lw=1, label="$M_{sl}$ with spin as dissipated power")
        ax.plot(rpm, ds["skf_sliding_torque"].values * 1e3, "k--", label="SKF 2004 $M_{sl}$ (catalogue)")
        if Fr > 0:
            ax.plot(rpm, seed * 1e3, "k:", label="SKF $M_{sl}$ as read by dgbb_prl")
        ax.set_xscale("log")
        ax.set_xlabel("inner-ring speed n [r/min]")
        ax.set_ylabel("torque [N mm]")
        ax.set_title(title, fontsize=10)
        ax.grid(True, which="both", alpha=0.3)
        ax.legend(fontsize=8)
        save(fig, fname)

    def family(param_list, fname, title, label_fmt, runner):
        fig, ax = plt.subplots(figsize=(6.4, 4.2))
        for i, p in enumerate(param_list):
            ds, seed = runner(p)
            ax.plot(rpm, ds["sliding_torque"].values * 1e3, f"C{i}-", label=label_fmt(p) + " dgbb_prl method")
            ax.plot(rpm, ds["skf_sliding_torque"].values * 1e3, f"C{i}--", label=label_fmt(p) + " SKF catalogue")
        ax.set_xscale("log")
        ax.set_xlabel("inner-ring speed n [r/min]")
        ax.set_ylabel("sliding friction torque $M_{sl}$ [N mm]")
        ax.set_title(title, fontsize=10)
        ax.grid(True, which="both", alpha=0.3)
        ax.legend(fontsize=7, ncol=2)
        save(fig, fname)

    # Fig. 8: Stribeck-type vs Coulomb mu = 0.07
    ds_s, _ = run()
    ds_c, _ = run(**{"friction.law": "coulomb", "friction.coefficient": 0.07})
    fig, ax = plt.subplots(figsize=(6.4, 4.2))
    for ds, st, lab in ((ds_s, "-", "Stribeck-type (SKF-weighted) mu"), (ds_c, "--", "Coulomb mu = 0.07")):
        for var, col, name in (("sliding_torque", "k", "$M_{sl}$"), ("spinning_torque", "C0", "$M_s$"), ("orbital_sliding_torque", "C2", "$M_d$")):
            ax.plot(rpm, ds[var].values * 1e3, col + st, label=f"{name}, {lab}")
    ax.set_xscale("log")
    ax.set_xlabel("inner-ring speed n [r/min]")
    ax.set_ylabel("torque [N mm]")
    ax.set_title("DGBB 6206, Fa = 500 N: friction law (dgbb_prl Fig. 8)", fontsize=10)
    ax.grid(True, which="both", alpha=0.3)
    ax.legend(fontsize=7)
    save(fig, "dgbb_friction_law.png")

    components(500, 0, "dgbb_components_axial.png", "DGBB 6206, pure axial Fa = 500 N (dgbb_prl Fig. 9, Table 2)")
    family([500, 1000, 1500], "dgbb_axial_load.png", "DGBB 6206, pure axial load (dgbb_prl Fig. 10)",
           lambda p: f"Fa = {p} N,", lambda p: run(Fa=p, Fr=0))
    family(["dgbb_6206", "dgbb_6207", "dgbb_6208"], "dgbb_size_axial.png", "Fa = 500 N, bearing size (dgbb_prl Fig. 11)",
           lambda p: p[5:] + ",", lambda p: run(name=p, Fa=500, Fr=0))
    components(0, 500, "dgbb_components_radial.png", "DGBB 6206, pure radial Fr = 500 N (dgbb_prl Fig. 12, Table 3)")
    family([500, 1000, 1500], "dgbb_radial_load.png", "DGBB 6206, pure radial load (dgbb_prl Fig. 13)",
           lambda p: f"Fr = {p} N,", lambda p: run(Fa=0, Fr=p))
    family(["dgbb_6206", "dgbb_6207", "dgbb_6208"], "dgbb_size_radial.png", "Fr = 500 N, bearing size (dgbb_prl Fig. 14)",
           lambda p: p[5:] + ",", lambda p: run(name=p, Fa=0, Fr=500))
    components(1000, 1000, "dgbb_components_combined.png", "DGBB 6206, Fa = Fr = 1000 N (dgbb_prl Fig. 15, Table 4)")
    family([500, 1000, 1500], "dgbb_combined_load.png", "DGBB 6206, Fr = 1000 N, varying Fa (dgbb_prl Fig. 16)",
           lambda p: f"Fa = {p} N,", lambda p: run(Fa=p, Fr=1000))
    return paths


if __name__ == "__main__":  # python -m hsbearing.systems.deep_groove.figures [OUTDIR]
    import sys as _sys

    for _p in make_figures(_sys.argv[1] if len(_sys.argv) > 1 else "docs/figures"):
        print(_p)
