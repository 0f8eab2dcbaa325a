"""The study figures: whirl orbit and Poincare map of every cell (:func:`plot_gallery`) and of the
representative cells a study names (:func:`plot_cells`), the cage slip ratio against a table's key (one
run per cell or over the band), and the drift diagnostic of a drawn orbit (:func:`orbit_drift`)."""

from __future__ import annotations

from pathlib import Path
from typing import Any

import numpy as np
import xarray as xr

from hsbearing.results import open_run
from hsbearing.workflows import sweeps
from hsbearing.workflows.study.cells import _ours, cell_stats, value_label
from hsbearing.workflows.study.spec import Study, normalise_label


def pick_sample(ds_cell: xr.Dataset, st: dict | None) -> int | None:
    """The sample index drawn for a banded cell: the nominal sample if it is in the majority class, else the
    first completed sample in the majority class (first of tied classes), else the first completed one."""
    n = ds_cell.sizes["sample"]
    ok = [i for i in range(n) if ds_cell["status"].values[i] == sweeps.STATUS_OK and ds_cell["archive"].values[i]]
    if not ok:
        return None
    if st and st["majority"] != "-":
        first = st["majority"].split(" / ")[0]
        for i in ok:
            lab = normalise_label(ds_cell["classification"].values[i]) if "classification" in ds_cell else ""
            if (lab or "-") == first:
                return i
    return ok[0]


def orbit_drift(t, y, z, t_start: float, clearance: float | None = None, parts: int = 4) -> dict[str, Any]:
    """Is the cage still drifting at the end of the run?  The analysed span (t > t_start) is cut into
    ``parts`` equal pieces; the mean whirl radius r = sqrt(D_Y^2 + D_Z^2) [m] of each piece is compared.
    ``drifting`` when those means change monotonically and the change exceeds both 10 % of the mean radius
    and 1 % of the guide clearance (the still-cage threshold of docs/analysis.md): a spiral that has not
    reached its attractor, whose Poincare section is an open arc, not a closed curve -- a class from it
    ("quasi-periodic" for an arc) describes the transient.  A report-side diagnostic: the classification
    itself is not changed."""
    t = np.asarray(t, float)
    r = np.hypot(np.asarray(y, float), np.asarray(z, float))
    sel = t > t_start
    r = r[sel]
    if r.size < 4 * parts:
        return {"drifting": False, "radii": [], "change": float("nan")}
    means = np.array([np.mean(c) for c in np.array_split(r, parts)])
    d = np.diff(means)
    monotone = bool(np.all(d > 0) or np.all(d < 0))
    change = float(means[-1] - means[0])
    floor = 0.01 * clearance if clearance is not None and np.isfinite(clearance) else 0.0
    drifting = monotone and abs(change) > max(0.1 * float(np.mean(means)), floor)
    return {"drifting": drifting, "radii": means.tolist(), "change": change}


def plot_gallery(study: Study, t: dict, ds: xr.Dataset, root: Path, path: Path,
                  drift_log: list | None = None) -> Path | None:
    """Whirl orbit (top) and Poincare map D_Y-V_Y (bottom) of EVERY cell of a table: one column per value,
    two rows per oil.  A banded table draws one sample per cell (:func:`pick_sample`) and prints the class
    fractions over the band in the panel title."""
    plt = _pyplot()

    dim = t["vary"].rpartition(".")[2]
    banded = "sample" in ds.dims
    oils, nval = study.oils, ds.sizes[dim]
    fig, axes = plt.subplots(2 * len(oils), nval, figsize=(2.15 * nval, 1.95 * 2 * len(oils)), squeeze=False)
    drawn = 0
    for io, o in enumerate(oils):
        for iv in range(nval):
            cell = ds.sel(oil=o).isel({dim: iv})
            ax_o, ax_p = axes[2 * io, iv], axes[2 * io + 1, iv]
            for ax in (ax_o, ax_p):
                ax.tick_params(labelsize=5, length=2, pad=1)
                ax.locator_params(nbins=3)
                ax.ticklabel_format(useOffset=False)
            paper = str(cell["paper_classification"].values) if "paper_classification" in cell else ""
            if banded:
                st = cell_stats(ds, dim, o, iv)
                k = pick_sample(cell, st)
                pt = cell.isel(sample=k) if k is not None else None
                frac = ", ".join(f"{c} {f:.0%}" for c, f in st["fractions"].items()) or "-"
                head = f"{o}, {value_label(ds, dim, iv)}  paper: {paper or '-'}\nband: {frac}"
                if pt is not None:
                    head += f"\nshown: {pt['sample_label'].item()} ({_ours(pt)})"
            else:
                pt = cell
                head = f"{o}, {value_label(ds, dim, iv)}\npaper: {paper or '-'}\nours: {_ours(pt)}"
            ax_o.set_title(head, fontsize=5.2, loc="left")
            run = None
            if pt is not None and pt["archive"].item():
                try:
                    run = open_run(root / pt["archive"].item())
                except Exception:
                    run = None
            if run is None or "cage_center_y" not in run or "time" not in run.dims:
                ax_o.text(0.5, 0.5, "no run", ha="center", va="center", transform=ax_o.transAxes, fontsize=6)
                ax_p.set_axis_off()
                continue
            try:
                y = np.asarray(run["cage_center_y"].values, float) * 1e6
                z = np.asarray(run["cage_center_z"].values, float) * 1e6
                tt = np.asarray(run["time"].values, float)
                t_tr = float(run.attrs.get("transient_discarded", tt[0]))
                late = tt > t_tr
                ax_o.plot(y[~late], z[~late], lw=0.25, color="0.75")
                ax_o.plot(y[late], z[late], lw=0.3, color="C0")
                gc = run.attrs.get("guide_clearance")
                dr = orbit_drift(tt, y * 1e-6, z * 1e-6, t_tr, float(gc) if gc is not None else None)
                if dr["drifting"]:
                    ax_o.text(0.02, 0.02, f"DRIFT {dr['change'] * 1e6:+.0f} \u00b5m", transform=ax_o.transAxes,
                              fontsize=5.5, color="m", va="bottom")
                    if drift_log is not None:
                        drift_log.append(f"{t['id']}, oil {o}, {value_label(ds, dim, iv)}"
                                         + (f" (sample {pt['sample_label'].item()})" if banded else "")
                                         + f": class {_ours(pt)}, mean whirl radius per quarter of the analysed "
                                           f"span {', '.join(f'{x * 1e6:.1f}' for x in dr['radii'])} \u00b5m")
                if gc is not None and np.isfinite(float(gc)):
                    th = np.linspace(0, 2 * np.pi, 181)
                    ax_o.plot(float(gc) * 1e6 * np.cos(th), float(gc) * 1e6 * np.sin(th), "r--", lw=0.4)
                ax_o.set_aspect("equal", "datalim")
                pts = poincare(run)
                if pts is not None and len(pts):
                    ax_p.plot(pts[:, 0] * 1e6, pts[:, 1] * 1e3, ".", ms=1.5, color="C3")
                    ax_p.text(0.02, 0.96, f"{len(pts)} pts", transform=ax_p.transAxes, fontsize=5, va="top")
                else:
                    ax_p.text(0.5, 0.5, "no section points", ha="center", va="center", transform=ax_p.transAxes,
                              fontsize=6)
                drawn += 1
            finally:
                run.close()
            if iv == 0:
                ax_o.set_ylabel("D_Z [\u00b5m]", fontsize=5.5)
                ax_p.set_ylabel("V_Y [mm/s]", fontsize=5.5)
            if io == len(oils) - 1:
                ax_p.set_xlabel("D_Y [\u00b5m]", fontsize=5.5)
    if not drawn:
        plt.close(fig)
        return None
    import textwrap

    width, height = fig.get_figwidth(), fig.get_figheight()
    title = textwrap.fill(f"{t.get('title', t['id'])}: every cell -- whirl orbit (grey: transient, red dashed: guide "
                          "clearance) over its Poincare map (once per cage revolution)", width=int(width * 15))
    fig.suptitle(title, fontsize=7)
    # fixed margins in inches (tight_layout costs seconds with ~70 axes)
    n_title = title.count("\n") + 1
    fig.subplots_adjust(left=0.5 / width, right=1 - 0.08 / width, bottom=0.4 / height,
                        top=1 - (0.6 + 0.13 * n_title) / height, hspace=0.62, wspace=0.42)
    return _save_closed(fig, path, plt)


def plot_slip_band(ds: xr.Dataset, t: dict, oils: list[str], path: Path) -> Path | None:
    """Cage slip ratio against the table's key: the nominal sample as a line, the band's range shaded and
    every sample as a dot (compare the paper's Figs. 13-15)."""
    if "mean_cage_slip_ratio" not in ds:
        return None
    plt, dim, x, fig, ax = _slip_axes(ds, t, (5.8, 4.0))
    labels = list(ds["sample_label"].values)
    for j, o in enumerate(oils):
        y = np.asarray(ds["mean_cage_slip_ratio"].sel(oil=o).transpose("sample", dim).values, float) * 100
        ok = np.asarray(ds["status"].sel(oil=o).transpose("sample", dim).values) == sweeps.STATUS_OK
        y = np.where(ok, y, np.nan)
        col = f"C{j}"
        with np.errstate(all="ignore"):
            lo, hi = np.nanmin(y, axis=0), np.nanmax(y, axis=0)
        ax.fill_between(x, lo, hi, color=col, alpha=0.18, lw=0)
        for k in range(y.shape[0]):
            ax.plot(x, y[k], ".", color=col, ms=3)
        k0 = labels.index("nominal") if "nominal" in labels else None
        if k0 is not None:
            ax.plot(x, y[k0], "-", color=col, label=f"oil {o} (nominal; band shaded)")
        else:
            ax.plot(x, np.nanmedian(y, axis=0), "-", color=col, label=f"oil {o} (band median; range shaded)")
    _finish_slip(fig, ax, t, dim, f"{t['id']}: cage slip ratio over the band (compare "
                 f"{t.get('slip_figure', 'the paper')})", legend_size=7)
    return _save_closed(fig, path, plt)


def axis_values(ds: xr.Dataset, key: str, dim: str) -> tuple[np.ndarray, str]:
    x = np.asarray(ds[dim].values, dtype=float)
    units = ds[dim].attrs.get("units", "")
    if units == "K":
        return x - 273.15, "\N{DEGREE SIGN}C"
    return x, units


def _save(fig, path: Path) -> Path:
    from hsbearing.plotting import save_figure

    return save_figure(fig, path)


def _pyplot():
    """``matplotlib.pyplot`` on the Agg backend (no display needed)."""
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    return plt


def _save_closed(fig, path: Path, plt) -> Path:
    """Write the figure (atomically, :func:`hsbearing.plotting.save_figure`) and close it, also on failure."""
    try:
        return _save(fig, path)
    finally:
        plt.close(fig)


def _slip_axes(ds: xr.Dataset, t: dict, figsize: tuple[float, float]):
    """pyplot, the table's dim, its axis values (degC for a temperature) and a new figure and axes for a cage
    slip ratio figure of table ``t``."""
    plt = _pyplot()
    dim = t["vary"].rpartition(".")[2]
    x, _ = axis_values(ds, t["vary"], dim)
    fig, ax = plt.subplots(figsize=figsize)
    return plt, dim, x, fig, ax


def _finish_slip(fig, ax, t: dict, dim: str, title: str, legend_size: float) -> None:
    """Labels, title, grid and legend of a cage slip ratio figure."""
    ax.set_xlabel(t.get("axis_label", dim))
    ax.set_ylabel("cage slip ratio [%]")
    ax.set_title(title, fontsize=9)
    ax.grid(alpha=0.3)
    ax.legend(fontsize=legend_size)
    fig.tight_layout()


def plot_slip(ds: xr.Dataset, t: dict, oils: list[str], path: Path) -> Path | None:
    if "mean_cage_slip_ratio" not in ds:
        return None
    plt, dim, x, fig, ax = _slip_axes(ds, t, (5.5, 3.8))
    for o in oils:
        y = np.asarray(ds["mean_cage_slip_ratio"].sel(oil=o).values, float) * 100
        ax.plot(x, y, "o-", label=f"oil {o}")
    _finish_slip(fig, ax, t, dim, f"{t['id']}: cage slip ratio (compare {t.get('slip_figure', 'paper')})",
                 legend_size=8)
    return _save_closed(fig, path, plt)


def plot_cells(study: Study, datasets: dict, figspec: dict, path: Path) -> Path | None:
    cells = []
    for tid, oil, value in figspec.get("cells", []):
        ds = datasets.get(tid)
        if ds is None:
            continue
        t = next(t for t in study.tables if t["id"] == tid)
        dim = t["vary"].rpartition(".")[2]
        i = list(t["values"]).index(value)
        pt = ds.sel(oil=oil).isel({dim: i})
        arch = pt["archive"].item()
        if not arch:
            continue
        try:
            run = open_run(path.parent.parent / arch)
        except Exception:
            continue
        if "cage_center_y" not in run or "time" not in run.dims:
            continue
        cells.append((f"{oil}, {value}", run, _ours(pt), str(pt["paper_classification"].item()) if "paper_classification" in pt else ""))
    if not cells:
        return None
    plt = _pyplot()

    n = len(cells)
    fig, axes = plt.subplots(2, n, figsize=(3.0 * n, 6.0), squeeze=False)
    for j, (label, run, ours, paper) in enumerate(cells):
        y = np.asarray(run["cage_center_y"].values, float) * 1e6
        z = np.asarray(run["cage_center_z"].values, float) * 1e6
        ax = axes[0, j]
        t = np.asarray(run["time"].values, float)
        t_tr = float(run.attrs.get("transient_discarded", t[0]))
        early = t <= t_tr
        if early.any() and not early.all():
            ax.plot(y[early], z[early], lw=0.4, color="0.75", label="transient")
            ax.plot(y[~early], z[~early], lw=0.4, color="C0", label="analysed")
            ax.legend(fontsize=6, loc="upper right")
        else:
            ax.plot(y, z, lw=0.4)
        ax.set_aspect("equal", "datalim")
        ax.set_xlabel("D_Y [\u00b5m]")
        ax.set_ylabel("D_Z [\u00b5m]")
        ax.set_title(f"{label}\npaper: {paper or '-'}\nours: {ours}", fontsize=8)
        ax = axes[1, j]
        pts = poincare(run)
        if pts is not None and len(pts):
            ax.plot(pts[:, 0] * 1e6, pts[:, 1] * 1e3, ".", ms=3)
        else:
            ax.text(0.5, 0.5, "no section points", ha="center", va="center", transform=ax.transAxes, fontsize=8)
        ax.set_xlabel("D_Y [\u00b5m]")
        ax.set_ylabel("V_Y [mm/s]")
    fig.suptitle(figspec.get("title", figspec["id"]) + "  (top: whirl orbit; bottom: Poincare map)", fontsize=9)
    fig.tight_layout()
    return _save_closed(fig, path, plt)


def poincare(run: xr.Dataset):
    try:
        from hsbearing.analysis import poincare_points

        return np.asarray(poincare_points(run), float)
    except Exception:
        return None

