"""Lock/drift figure of a dynamic run (``OUT_lock.png``): is the cage whirl locked to the cage rotation?

(a) the whirl-cage phase psi = (theta - n phi) / 2 pi [turns] against the cage revolutions after the transient,
with its least-squares line (the drift rho of :func:`hsbearing.analysis.whirl.whirl_lock`); a locked whirl is
flat, a whirl at 0.98 x the cage speed drifts by -0.02 turn per revolution.  (b) the once-per-cage-revolution
(clock) section, whose points creep along the orbit by that drift -- the section the label is *not* read on (the
model is autonomous; docs/analysis.md §0), shown beside the transverse one of the run figure.
"""

from __future__ import annotations

from pathlib import Path

import numpy as np

__all__ = ["lock_figure_path", "has_lock", "plot_lock"]


def lock_figure_path(run_png) -> Path:
    """``OUT_lock.png`` next to the run figure ``OUT.png``."""
    p = Path(run_png)
    return p.with_name(p.stem + "_lock.png")


def has_lock(ds) -> bool:
    return all(v in ds for v in ("cage_center_y", "cage_center_z", "cage_speed")) and "time" in ds.dims


def plot_lock(ds, path) -> Path:
    """Draw the lock/drift figure of a dynamic run to ``path`` (PNG, atomic write)."""
    from matplotlib.figure import Figure

    from hsbearing.analysis import poincare
    from hsbearing.analysis.whirl import whirl_cage_phase, whirl_lock
    from hsbearing.plotting.common import save_figure

    t = np.asarray(ds["time"].values, float)
    mask, _ = poincare.after_transient(ds)
    y = np.asarray(ds["cage_center_y"].values, float)[mask]
    z = np.asarray(ds["cage_center_z"].values, float)[mask]
    phi = poincare.cage_rotation_angle(ds)[mask]
    fig = Figure(figsize=(11, 4.5), layout="constrained")
    ax1, ax2 = fig.subplots(1, 2)
    if y.size >= 16:
        revs, psi, n, ratio = whirl_cage_phase(t[mask], y, z, phi)
        lock = whirl_lock(t[mask], y, z, phi)
        ax1.plot(revs, psi - psi[0], lw=0.8, color="C0", label=f"whirl-cage phase (n = {n})")
        if lock.get("locked") is not None:
            ax1.plot(revs, lock["rho"] * (revs - revs[0]), "r--", lw=1.0,
                     label=f"drift {lock['rho']:+.4f} \u00b1 {lock['rho_sd']:.1e} turn/rev")
            state = "locked" if lock["locked"] else "not locked"
            ax1.set_title(f"(a) whirl at {ratio:.4f} x cage speed: {state}", fontsize=10)
        ax1.legend(fontsize=8)
    ax1.set_xlabel("cage revolutions after the transient")
    ax1.set_ylabel("whirl-cage phase \u03c8 [turn]")
    ax1.grid(alpha=0.3)
    try:
        _, pts = poincare.poincare_section(ds, "cage_revolution")
    except Exception:  # noqa: BLE001 - an odd archive: the panel says so
        pts = np.zeros((0, 2))
    if len(pts):
        sc = ax2.scatter(pts[:, 0] * 1e6, pts[:, 1] * 1e3, c=np.arange(len(pts)), s=12, cmap="viridis")
        fig.colorbar(sc, ax=ax2, label="section index (time \u2192)")
    alt = ds.attrs.get("classification_alternative", "")
    sec = ds.attrs.get("classification_alternative_section", "cage_revolution")
    lab = ds.attrs.get("classification", "")
    ax2.set_title(f"(b) clock section (once per cage revolution): {alt or '-'}\n"
                  f"label of the run ({ds.attrs.get('poincare_section_kind', 'transverse')} section): {lab}"
                  if sec == "cage_revolution" else "(b) clock section", fontsize=10)
    ax2.set_xlabel("cage centre $D_Y$ [\u00b5m]")
    ax2.set_ylabel("cage centre velocity $V_Y$ [mm/s]")
    ax2.grid(alpha=0.3)
    return save_figure(fig, path)
