"""Figure of a gyro-bearing run (Jiang et al. 2014, like [J] Figs. 7-9): speeds, M_C, the friction-moment sources."""

from __future__ import annotations

from pathlib import Path

import numpy as np

from hsbearing.plotting import common  # common.save_figure: one place to capture every figure
from hsbearing.plotting.common import RPM, _figure, vals

__all__ = ['GYRO_SOURCES', 'plot_gyro']


#: The five friction-moment sources of the gyro model ([J] Eq. 1), in stacking order: name, label, colour.
GYRO_SOURCES = (("friction_moment_viscous", "$M_L$ viscous", "#17becf"),
                ("friction_moment_hysteresis", "$M_E$ elastic hysteresis", "#2ca02c"),
                ("friction_moment_differential", "$M_D$ differential sliding", "#ff7f0e"),
                ("friction_moment_pivoting", "$M_S$ pivoting", "#8c564b"),
                ("friction_moment_cage", "$M_C$ ball/cage (driving part)", "#e377c2"))


def plot_gyro(ds, path) -> Path:
    """Figure of a gyro-bearing run (like [J] Figs. 7-9) to ``path`` (PNG).

    (a) outer-race, cage and ball-1 orbital speeds [r/min]; (b) ball/cage friction moment M_C [uN m];
    (c) the sources stacked as bands, M_L + M_E + M_D + M_S + max(M_C, 0) = M ([J] Eq. 1), so that
    sources of nearly equal size stay distinguishable (their time means are in the legend), and M on top.
    """
    path = Path(path)
    u = 1e6
    t = vals(ds, "time")
    fig = _figure((10, 9))
    ax = fig.subplots(3, 1, sharex=True)
    if "outer_race_speed" in ds:
        ax[0].plot(t, vals(ds, "outer_race_speed", RPM), color="0.5", lw=1.0, ls="--", label="outer race")
    if "ball_orbit_speed" in ds:
        ax[0].plot(t, vals(ds.isel(ball=0), "ball_orbit_speed", RPM), "k-", lw=1, label="ball 1 orbit")
    if "cage_speed" in ds:
        ax[0].plot(t, vals(ds, "cage_speed", RPM), "r-", lw=0.8, label="cage")
    ax[0].set_ylabel("angular speed [r/min]")
    ax[0].set_title("(a) speeds", fontsize=10)
    ax[0].legend(loc="best", fontsize=8)
    if "friction_moment_cage" in ds:
        ax[1].plot(t, vals(ds, "friction_moment_cage", u), "-", color=GYRO_SOURCES[-1][2], lw=0.8)
    ax[1].set_ylabel("$M_C$ [\u00b5N m]")
    ax[1].set_title("(b) ball/cage friction moment $M_C$ (signed; peak of each output interval)", fontsize=10)
    bands, labels, colours = [], [], []
    for name, lab, col in GYRO_SOURCES:
        if name in ds:
            v = vals(ds, name, u)
            v = np.maximum(v, 0.0) if name == "friction_moment_cage" else v
            bands.append(v)
            labels.append(f"{lab}: mean {np.nanmean(v):.3g} \u00b5N m")
            colours.append(col)
    if bands:
        ax[2].stackplot(t, *bands, labels=labels, colors=colours, alpha=0.85, lw=0)
    if "friction_moment_total" in ds:
        ax[2].plot(t, vals(ds, "friction_moment_total", u), color="b", lw=1.1, label="$M$ total (Eq. 1)")
    ax[2].set_ylabel("friction moment [\u00b5N m]")
    ax[2].set_xlabel("time [s]")
    ax[2].set_title("(c) friction-moment sources, stacked: $M_L + M_E + M_D + M_S + \\max(M_C, 0) = M$", fontsize=10)
    ax[2].legend(loc="upper left", bbox_to_anchor=(1.01, 1.0), fontsize=8, frameon=False)
    for a in ax:
        a.grid(alpha=0.3)
    title = f"{ds.attrs.get('case_name', '')}: " + ", ".join(
        f"{v.upper()} = {float(ds[v]) * u:.3g} \u00b5N m" for v in ("sfmc", "sfmo", "rfmc") if v in ds and np.isfinite(float(ds[v])))
    if "sfmc_ensemble_mean" in ds and np.isfinite(float(ds["sfmc_ensemble_mean"])):  # the start ensemble's result
        n = int(ds.sizes.get("start_offset", 0))
        title += (f"; SFMC over {n} start positions {float(ds['sfmc_ensemble_mean']) * u:.3g} +/- "
                  f"{float(ds['sfmc_ensemble_sd']) * u:.2g} \u00b5N m (mean +/- sd; SFMC above: this start)")
    if ds.attrs.get("status", "ok") != "ok":
        title += f" [{ds.attrs['status']}]"
    import textwrap

    fig.suptitle("\n".join(textwrap.wrap(title, 120)), fontsize=10)
    return common.save_figure(fig, path)
