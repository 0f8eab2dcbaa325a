"""The cage-stability map figure (``DIR/map.png`` of ``hsbearing map``).

Two panels over the same (x, y) grid of the two varied keys (:mod:`hsbearing.workflows.maps`):

(a) **class map**: one cell per point, coloured by the cage-motion class (colours of
    :data:`hsbearing.plotting.CLASS_STYLE`), with the label, its sub-label
    (``classification_detail``: still cage / synchronous whirl / ...) and the confidence written in
    the cell; points that are not ok are hatched and say their status;
(b) **indicator map**: the cage-instability index (``cage_instability_index``, sd/mean of the whirl
    radius, Ghaisas et al. 2004) as a colour per cell with its value written in it, colour bar beside.

Matplotlib object API, Agg canvas, atomic PNG write (:func:`hsbearing.plotting.save_figure`).
"""

from __future__ import annotations

from pathlib import Path

import numpy as np
import xarray as xr

__all__ = ["plot_map"]


def _labels(ds, dim) -> list[str]:
    lab = f"{dim}_label"
    vals = ds[lab].values if lab in ds.coords else ds[dim].values
    return [str(v) for v in vals]


def _axis_title(ds, dim) -> str:
    c = ds[dim]
    key = c.attrs.get("case_key", dim)
    return key


def plot_map(ds: xr.Dataset, path) -> Path:
    """Draw the class map and the indicator map of a map Dataset (dims (y, x)) to ``path`` (PNG)."""
    from matplotlib.colors import Normalize
    from matplotlib.figure import Figure
    from matplotlib.patches import Rectangle

    from hsbearing.plotting import CLASS_STYLE, NOT_OK_STYLE, class_family, save_figure

    ydim = ds.attrs.get("map_y_dim") or ds["status"].dims[0]
    xdim = ds.attrs.get("map_x_dim") or ds["status"].dims[1]
    ds = ds.transpose(ydim, xdim, ...)
    ny, nx = ds.sizes[ydim], ds.sizes[xdim]
    status = np.asarray(ds["status"].values).astype(str)
    cls = np.asarray(ds["classification"].values).astype(str) if "classification" in ds else np.full((ny, nx), "")
    det = np.asarray(ds["classification_detail"].values).astype(str) if "classification_detail" in ds else \
        np.full((ny, nx), "")
    conf = np.asarray(ds["classification_confidence"].values, float) if "classification_confidence" in ds else \
        np.full((ny, nx), np.nan)
    ind = np.asarray(ds["cage_instability_index"].values, float) if "cage_instability_index" in ds else \
        np.full((ny, nx), np.nan)
    ok = status == "ok"

    fig = Figure(figsize=(max(9.0, min(18.0, 3.2 * nx + 4.0)), max(3.8, min(12.0, 1.2 * ny + 2.2))))
    ax1, ax2 = fig.subplots(1, 2)
    vmax = float(np.nanmax(ind[ok])) if np.isfinite(ind[ok]).any() else 1.0
    norm = Normalize(vmin=0.0, vmax=max(vmax, 1e-3))
    from matplotlib import colormaps

    cmap = colormaps["viridis"]
    compact = nx > 8 or ny > 12
    for i in range(ny):
        for j in range(nx):
            r = i  # first y value at the bottom (like a plot axis)
            if not ok[i, j]:
                for ax in (ax1, ax2):
                    ax.add_patch(Rectangle((j, r), 1, 1, facecolor="#fbe3e3", edgecolor="white", hatch="xx", lw=2))
                    if not compact:
                        ax.text(j + 0.5, r + 0.5, f"not ok: {status[i, j]}", ha="center", va="center", fontsize=8,
                                color=NOT_OK_STYLE[1])
                continue
            f = class_family(cls[i, j])
            ax1.add_patch(Rectangle((j, r), 1, 1, facecolor=CLASS_STYLE[f][1] if f else "white",
                                    alpha=0.35 if f != "undetermined" else 0.18, edgecolor="white", lw=2))
            v = ind[i, j]
            ax2.add_patch(Rectangle((j, r), 1, 1, facecolor=cmap(norm(v)) if np.isfinite(v) else "#eeeeee",
                                    edgecolor="white", lw=2))
            if not compact:
                txt = cls[i, j] if f else "-"
                if det[i, j] and det[i, j] != "nan":
                    txt += f"\n{det[i, j]}"
                if np.isfinite(conf[i, j]) and f not in (None, "undetermined"):
                    txt += f"\n({conf[i, j]:.2f})"
                ax1.text(j + 0.5, r + 0.5, txt, ha="center", va="center", fontsize=8)
                ax2.text(j + 0.5, r + 0.5, f"{v:.3g}" if np.isfinite(v) else "n/a", ha="center", va="center",
                         fontsize=9, color="white" if np.isfinite(v) and norm(v) < 0.6 else "k")
    for ax in (ax1, ax2):
        ax.set_xlim(0, nx)
        ax.set_ylim(0, ny)
        ax.set_xticks(np.arange(nx) + 0.5)
        ax.set_xticklabels(_labels(ds, xdim), fontsize=8)
        ax.set_yticks(np.arange(ny) + 0.5)
        ax.set_yticklabels(_labels(ds, ydim), fontsize=8)
        ax.set_xlabel(_axis_title(ds, xdim))
        ax.set_ylabel(_axis_title(ds, ydim))
        ax.tick_params(length=0)
        for sp in ax.spines.values():
            sp.set_visible(False)
    if compact:
        from matplotlib.patches import Patch

        present = [f for f in CLASS_STYLE if any(class_family(c) == f for c in cls[ok])]
        ax1.legend([Patch(facecolor=CLASS_STYLE[f][1], alpha=0.35) for f in present], present, fontsize=7.5,
                   loc="upper left", bbox_to_anchor=(1.01, 1.0), frameon=False)
    ax1.set_title("(a) cage motion: class, sub-label (confidence)", fontsize=10)
    ax2.set_title("(b) cage-instability index sd(r)/mean(r) of the whirl radius\n(Ghaisas et al. 2004; 0 = steady)",
                  fontsize=10)
    from matplotlib.cm import ScalarMappable

    fig.colorbar(ScalarMappable(norm=norm, cmap=cmap), ax=ax2, label="cage_instability_index [1]")
    n_ok = int(ok.sum())
    dur = ds.attrs.get("sweep_duration", "")
    dur_txt = f", {float(dur) * 1e3:g} ms per run" if dur not in ("", None) else ""
    fig.suptitle(f"cage-stability map of {ds.attrs.get('case_name', '')}: {n_ok} of {ok.size} points ok{dur_txt}",
                 fontsize=11)
    fig.tight_layout()
    return save_figure(fig, path, metadata={"Description": f"{n_ok} of {ok.size} points ok"})
