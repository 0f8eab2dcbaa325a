"""Figure of an ``hsbearing preload`` archive (dim ``preload``): starting torque and contact forces (Shan et al. 2010)."""

from __future__ import annotations

from pathlib import Path

import numpy as np

from hsbearing.plotting import common  # common.save_figure: one place to capture every figure
from hsbearing.plotting.common import ISO76_BALL_PRESSURE, _figure, vals

__all__ = ['plot_preload']


def plot_preload(ds, path) -> Path:
    """Figure of ``hsbearing preload`` (wire-race bearing, Shan et al. 2010) to ``path`` (PNG).

    (a) starting torque against the preload: rolling-resistance torque M_sc (Eq. 4) and M_s = M_sc + M_u
    (Eq. 11), with the target-torque band and the preload window when the archive has them;
    (b) maximum contact pressure of the four ball/wire contacts, with the ISO 76 limit
    (:data:`ISO76_BALL_PRESSURE`) drawn and the preloads beyond it shaded.
    """
    path = Path(path)
    fig = _figure((12, 4.9))
    ax1, ax2 = fig.subplots(1, 2)
    um = vals(ds, "preload", 1e6)
    fig.suptitle(f"{ds.attrs.get('case_name', 'wire race')}: starting torque and contact pressure against the preload "
                 "(Shan et al. 2010 model)", fontsize=11)
    ax1.plot(um, vals(ds, "rolling_torque"), "-", color="C0", label="$M_{sc}$ rolling resistance (Eq. 4)")
    ax1.plot(um, vals(ds, "torque"), "--", color="C1", label="$M_s = M_{sc} + M_u$ (Eq. 11)")
    tt, win = ds.attrs.get("target_torque"), ds.attrs.get("preload_window")
    if tt is not None and np.size(tt) == 2:
        ax1.axhspan(float(np.ravel(tt)[0]), float(np.ravel(tt)[1]), color="0.85", zorder=0,
                    label=f"target {float(np.ravel(tt)[0]):g}-{float(np.ravel(tt)[1]):g} N m")
    if win is not None and np.size(win) == 2:
        w = np.ravel(win) * 1e6
        ax1.axvspan(w[0], w[1], color="C0", alpha=0.12, zorder=0, label=f"preload window {w[0]:.1f}-{w[1]:.1f} \u00b5m")
    ax1.set_xlabel("preload \u03b4 [\u00b5m]")
    ax1.set_ylabel("starting torque [N m]")
    ax1.set_title("(a) starting torque", fontsize=10)
    ax1.grid(alpha=0.3)
    ax1.legend(fontsize=8, loc="upper left")
    pmax = np.zeros_like(um)
    for j in range(1, 5):
        name = f"p_max{j}"
        if name in ds:
            p = vals(ds, name, 1e-9)
            pmax = np.maximum(pmax, p)
            ax2.plot(um, p, lw=1.1, ls=("-", "--", "-.", ":")[j - 1], label=f"contact {j}: $P_{{0{j}}}$")
    lim = ISO76_BALL_PRESSURE * 1e-9
    ax2.axhline(lim, color="r", lw=1.2, label=f"ISO 76 static limit for ball bearings, {lim:g} GPa")
    over = pmax > lim
    if over.any():
        ax2.axvspan(um[over].min(), um.max(), color="r", alpha=0.08, zorder=0,
                    label=f"above the limit from {um[over].min():.3g} \u00b5m")
    ax2.set_xlabel("preload \u03b4 [\u00b5m]")
    ax2.set_ylabel("maximum contact pressure [GPa]")
    ax2.set_title("(b) maximum contact pressure", fontsize=10)
    ax2.grid(alpha=0.3)
    ax2.legend(fontsize=8, loc="upper left")
    return common.save_figure(fig, path)
