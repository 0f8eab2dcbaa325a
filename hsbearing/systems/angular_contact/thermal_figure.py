"""The figure of a thermal-network archive (``hsbearing thermal -o OUT.nc``; ``hsbearing plot OUT.nc``).

(a) the network: nodes at fixed places of a bearing half-section sketch, coloured by temperature and labelled with
    it and with the heat generated there; every link drawn with the heat it carries [W] (arrow in the sense of
    the flow); (b) node temperatures as bars; (c) the fixed-point history (lubricant temperature, power loss).
docs/thermal.md.  Matplotlib object API, Agg canvas, atomic write (:func:`hsbearing.plotting.save_figure`).
"""

from __future__ import annotations

import numpy as np

__all__ = ["plot_thermal"]

#: node -> (x, y) in the sketch (axial, radial): shaft at the bottom, housing at the top, the oil on the side
_POS = {"shaft": (0.0, 0.0), "inner_ring": (0.0, 1.0), "balls": (0.0, 2.0), "outer_ring": (0.0, 3.0),
        "housing": (0.0, 4.0), "cage": (1.25, 2.75), "oil": (2.5, 2.0), "oil_inlet": (2.5, 0.5),
        "ambient": (-1.6, 2.0)}


#: curvature of the link arrows (matplotlib ``arc3`` rad)
_RAD = 0.12


def _arc_midpoint(p0, p1):
    """Midpoint of the ``arc3`` curve from p0 to p1: the quadratic Bezier whose control point is the chord's
    midpoint moved by rad x chord length perpendicular to it; its middle is half way to the control point."""
    (x0, y0), (x1, y1) = p0, p1
    dx, dy = x1 - x0, y1 - y0
    cx, cy = 0.5 * (x0 + x1) + _RAD * dy, 0.5 * (y0 + y1) - _RAD * dx
    return 0.5 * (0.5 * (x0 + x1) + cx), 0.5 * (0.5 * (y0 + y1) + cy)


def plot_thermal(ds, path):
    from matplotlib import cm, colors
    from matplotlib.figure import Figure
    from matplotlib.ticker import MaxNLocator

    from hsbearing.plotting.common import save_figure, title_lines

    nodes = [str(n) for n in ds.node.values]
    T = {n: float(v) - 273.15 for n, v in zip(nodes, ds.node_temperature.values)}
    T["oil_inlet"] = float(ds.oil_inlet_temperature) - 273.15
    T["ambient"] = float(ds.ambient_temperature) - 273.15
    Q = {n: float(v) for n, v in zip(nodes, ds.node_heat_input.values)}
    fig = Figure(figsize=(13.0, 7.5), layout="constrained")
    gs = fig.add_gridspec(2, 2, width_ratios=(1.6, 1.0))
    fig.suptitle("\n".join(title_lines(ds)), fontsize=11)

    ax = fig.add_subplot(gs[:, 0])
    vals = np.array(list(T.values()))
    norm = colors.Normalize(vmin=vals.min(), vmax=max(vals.max(), vals.min() + 1e-6))
    cmap = cm.get_cmap("coolwarm") if hasattr(cm, "get_cmap") else __import__("matplotlib").colormaps["coolwarm"]
    for a, b, q in zip(ds.link_from.values, ds.link_to.values, ds.link_heat_flow.values):
        a, b, q = str(a), str(b), float(q)
        (x0, y0), (x1, y1) = _POS[a], _POS[b]
        if q < 0:
            (x0, y0), (x1, y1), q = (x1, y1), (x0, y0), -q
        ax.annotate("", xy=(x1, y1), xytext=(x0, y0),
                    arrowprops=dict(arrowstyle="-|>", color="0.4", lw=0.8 + 2.5 * q / max(float(ds.heat_generated), 1e-9),
                                    shrinkA=22, shrinkB=22, connectionstyle=f"arc3,rad={_RAD}"))
        xm, ym = _arc_midpoint((x0, y0), (x1, y1))
        label = f"{q:.3g} W" if "oil_inlet" not in (a, b) else f"carried out\nby the oil flow\n{q:.3g} W"
        ax.text(xm, ym, label, fontsize=7.5, color="0.2", ha="center", va="center", zorder=5,
                bbox=dict(boxstyle="round,pad=0.15", fc="white", ec="none", alpha=0.85))
    for n, (x, y) in _POS.items():
        ax.scatter([x], [y], s=1500, color=cmap(norm(T[n])), edgecolors="k", zorder=3)
        extra = f"\n+{Q[n]:.3g} W" if Q.get(n, 0.0) > 1e-9 else ""
        ax.text(x, y, f"{n.replace('_', ' ')}\n{T[n]:.1f} °C{extra}", ha="center", va="center", fontsize=7.5, zorder=4)
    ax.set_xlim(-2.4, 3.4)
    ax.set_ylim(-0.7, 4.7)
    ax.set_axis_off()
    ax.set_title(f"(a) thermal network: heat generated {float(ds.heat_generated):.3g} W, removed by the oil "
                 f"{float(ds.heat_removed_by_oil):.3g} W, by conduction to the air {float(ds.heat_removed_by_conduction):.3g} W\n"
                 f"balance error {float(ds.heat_balance_error):.1e}; arrows: heat flow [W]", fontsize=9, loc="left")

    ax = fig.add_subplot(gs[0, 1])
    names = nodes + ["oil_inlet", "ambient"]
    y = np.arange(len(names))[::-1]
    ax.barh(y, [T[n] for n in names], color=[cmap(norm(T[n])) for n in names], edgecolor="k")
    for yi, n in zip(y, names):
        ax.text(T[n], yi, f" {T[n]:.1f}", va="center", fontsize=8)
    ax.set_yticks(y, [n.replace("_", " ") for n in names], fontsize=9)
    ax.set_xlabel("temperature [°C]")
    lo, hi = min(T.values()), max(T.values())
    ax.set_xlim(lo - 0.2 * (hi - lo) - 1.0, hi + 0.25 * (hi - lo) + 1.0)
    ax.set_title(f"(b) node temperatures; lubricant (traction, viscosity) {float(ds.lubricant_temperature) - 273.15:.1f} °C",
                 fontsize=10)
    ax.grid(alpha=0.3, axis="x")

    ax = fig.add_subplot(gs[1, 1])
    it = np.asarray(ds.iteration.values)
    ax.plot(it, np.asarray(ds.iteration_lubricant_temperature.values) - 273.15, "C3o-", label="lubricant temperature [°C]")
    ax.set_xlabel("fixed-point iteration")
    ax.xaxis.set_major_locator(MaxNLocator(integer=True))
    ax.set_ylabel("lubricant temperature [°C]", color="C3")
    ax2 = ax.twinx()
    ax2.plot(it, ds.iteration_power_loss.values, "C0s--", label="power loss [W]")
    ax2.set_ylabel("power loss [W]", color="C0")
    ax.set_title("(c) power <-> temperature fixed point", fontsize=10)
    ax.grid(alpha=0.3)
    return save_figure(fig, path)
