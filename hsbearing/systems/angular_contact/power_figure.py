"""The power figure of an angular-contact dynamic run: where the shaft's power goes.

``hsbearing run`` writes it next to the run figure as ``OUT_power.png``; ``hsbearing plot OUT.nc`` too.
Panels, from the dataset variables of :mod:`hsbearing.systems.angular_contact.balances` (docs/power_loss.md):

(a) ``power_loss_<source>`` stacked against time (each smoothed by a centred moving mean over
    ``smooth_ms``, 0.5 ms by default, so ball-passage ripple does not hide the levels), with the
    shaft's ``drive_power`` drawn over it: their difference is d(mechanical energy)/dt;
(b) ``drive_torque`` [N mm] against time, raw and smoothed;
(c) mean power by source over the second half of the run (the interval the ``hsbearing run`` summary
    averages over), as horizontal bars with the share of the total.

Matplotlib object API, Agg canvas, atomic write (:func:`hsbearing.plotting.save_figure`).
"""

from __future__ import annotations

from pathlib import Path

import numpy as np

__all__ = ["has_power", "power_figure_path", "plot_power"]


def has_power(ds) -> bool:
    """True for a dynamic run archive carrying the power accounting (``power_loss`` and ``drive_torque`` over time)."""
    return (all(v in ds.variables for v in ("power_loss", "drive_torque", "drive_power"))
            and ds.sizes.get(ds["power_loss"].dims[0] if ds["power_loss"].dims else "time", 0) >= 2)


def power_figure_path(run_png) -> Path:
    """``OUT.png`` -> ``OUT_power.png``: the power figure written next to the run figure."""
    p = Path(run_png)
    return p.with_name(p.stem + "_power" + (p.suffix or ".png"))


def _moving_mean(t: np.ndarray, y: np.ndarray, window: float) -> np.ndarray:
    """Centred moving mean of y(t) over ``window`` seconds (uniform output spacing assumed; edges shrink)."""
    if t.size < 3 or window <= 0.0:
        return y
    dt = float(np.median(np.diff(t)))
    n = int(round(window / dt)) if dt > 0 else 1
    if n < 2:
        return y
    c = np.concatenate([[0.0], np.cumsum(y)])
    i = np.arange(y.size)
    lo = np.clip(i - n // 2, 0, y.size)
    hi = np.clip(i + (n - n // 2), 0, y.size)
    return (c[hi] - c[lo]) / (hi - lo)


def plot_power(ds, path, smooth_ms: float = 0.5) -> Path:
    """Draw the power figure of a dynamic run archive to ``path`` (PNG) and return the path."""
    from matplotlib.figure import Figure

    from hsbearing.plotting import save_figure, title_lines
    from hsbearing.systems.angular_contact.balances import SOURCES

    # the histories' own time: "time", or "time_decimated" in an archive kept reduced (--keep answer)
    t = np.asarray(ds[ds["power_loss"].dims[0]].values, float)
    t_ms = (t - t[0]) * 1e3
    w = smooth_ms * 1e-3
    fig = Figure(figsize=(12.5, 8.5), layout="constrained")
    gs = fig.add_gridspec(2, 2, width_ratios=(2.2, 1.0))
    fig.suptitle("\n".join(title_lines(ds)), fontsize=11)

    # (a) power by source, stacked, smoothed
    ax = fig.add_subplot(gs[0, 0])
    names = [s for s in SOURCES if f"power_loss_{s}" in ds]
    series = [_moving_mean(t, np.asarray(ds[f"power_loss_{s}"].values, float), w) for s in names]
    ax.stackplot(t_ms, *series, labels=[s.replace("_", " ") for s in names], alpha=0.85)
    drive = _moving_mean(t, np.asarray(ds["drive_power"].values, float), w)
    ax.plot(t_ms, drive, "k-", lw=1.2, label="drive power (shaft); drive - loss = dE/dt")
    # headroom above the curves for the legend, so it never covers the drive-power line
    top = np.nanmax([np.nanmax(np.sum(series, axis=0)) if series else 0.0, np.nanmax(drive) if drive.size else 0.0])
    bottom = min(0.0, float(np.nanmin(drive))) if drive.size else 0.0
    if np.isfinite(top) and top > bottom:
        ax.set_ylim(bottom, top + 0.6 * (top - bottom))
    ax.set_xlabel("time [ms]")
    ax.set_ylabel("power [W]")
    ax.set_title(f"(a) power loss by source, stacked (moving mean over {smooth_ms:g} ms)", fontsize=10)
    ax.legend(fontsize=8, loc="upper right", ncol=2)
    ax.grid(alpha=0.3)

    # (b) drive torque
    ax = fig.add_subplot(gs[1, 0])
    T = np.asarray(ds["drive_torque"].values, float) * 1e3
    ax.plot(t_ms, T, color="0.7", lw=0.6, label="drive torque")
    ax.plot(t_ms, _moving_mean(t, T, w), "C3-", lw=1.2, label=f"moving mean over {smooth_ms:g} ms")
    ax.set_xlabel("time [ms]")
    ax.set_ylabel("drive torque [N mm]")
    ax.set_title("(b) torque the shaft supplies to the inner ring (positive: driving)", fontsize=10)
    ax.legend(fontsize=8, loc="best")
    ax.grid(alpha=0.3)

    # (c) mean by source over the second half (the run summary's interval)
    ax = fig.add_subplot(gs[:, 1])
    half = t >= t[0] + 0.5 * (t[-1] - t[0])
    means = np.array([float(np.mean(np.asarray(ds[f"power_loss_{s}"].values, float)[half])) for s in names])
    total = float(np.mean(np.asarray(ds["power_loss"].values, float)[half]))
    drive = float(np.mean(np.asarray(ds["drive_power"].values, float)[half]))
    y = np.arange(len(names))[::-1]
    ax.barh(y, means, color=[f"C{i}" for i in range(len(names))], alpha=0.85)
    for yi, m in zip(y, means):
        share = 100.0 * m / total if total else float("nan")
        ax.text(m, yi, f" {m:.3g} W ({share:.0f} %)", va="center", fontsize=8)
    ax.set_yticks(y, [s.replace("_", " ") for s in names], fontsize=9)
    ax.set_xlabel("mean power [W]")
    ax.set_xlim(0, max(means.max(initial=0.0), 1e-12) * 1.45)
    ax.set_title(f"(c) mean over t = {t_ms[half][0]:.3g}..{t_ms[-1]:.3g} ms\n"
                 f"loss {total:.3g} W, drive {drive:.3g} W, torque {np.mean(T[half]):.3g} N mm", fontsize=10)
    ax.grid(alpha=0.3, axis="x")
    return save_figure(fig, path)
