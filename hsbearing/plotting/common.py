"""Figure helpers shared by every system's figures and the sweep figure: atomic PNG writing, titles from the
case, the Agg figure, unit scales (the figures themselves live with their system,
``hsbearing/systems/<name>/figures.py``; the sweep/study summary figure is :mod:`hsbearing.plotting.sweep`).
"""

from __future__ import annotations

import math
import tomllib
from pathlib import Path

import numpy as np

__all__ = ["save_figure", "title_lines", "ISO76_BALL_PRESSURE"]

from hsbearing.display import ISO76_BALL_PRESSURE  # noqa: E402  (ISO 76 static limit of ball bearings [Pa])

RPM = 60.0 / (2.0 * math.pi)


def save_figure(fig, path, dpi: int = 110, metadata: dict | None = None) -> Path:
    """Save a matplotlib figure atomically (temporary file, then rename) and return its path.

    ``metadata``: text chunks of the PNG (matplotlib ``savefig(metadata=...)``), e.g. the point counts
    of a sweep figure.
    """
    from matplotlib.backends.backend_agg import FigureCanvasAgg

    from hsbearing.results import atomic_write

    path = Path(path)
    FigureCanvasAgg(fig)
    try:
        with atomic_write(path, suffix=path.suffix or ".png") as tmp:
            fig.savefig(tmp, dpi=dpi, format=(path.suffix.lstrip(".") or "png"), metadata=metadata)
    except OSError as exc:  # disk full, directory gone read-only: one line, not a traceback
        from hsbearing.errors import OutputWriteError

        raise OutputWriteError(path, exc.strerror or str(exc), note="figure not written") from None
    return path


_save = save_figure


def case_labels(ds) -> dict[str, str]:
    """Readable operating-condition labels from the ``case_toml`` attr (empty dict if absent)."""
    from hsbearing.case import parse_quantity

    text = ds.attrs.get("case_toml")
    if not text:
        return {}
    try:
        raw = tomllib.loads(text)
    except tomllib.TOMLDecodeError:
        return {}
    out = {}
    lub, op = raw.get("lubricant", {}), raw.get("operating", {})

    def q(table, key, kind):
        try:
            return parse_quantity(table[key], kind) if key in table else None
        except Exception:
            return None

    from hsbearing.lubricant import name_in_case_text

    own = name_in_case_text(lub)  # a lubricant file: the oil by its own name, never the law it borrows
    if own:
        out["oil"] = own
    elif "oil" in lub:
        out["oil"] = f"oil {lub['oil']}"
    T = q(lub, "temperature", "temperature")
    if T is not None:
        out["temperature"] = f"T = {T - 273.15:.0f} \N{DEGREE SIGN}C"
    n = q(op, "inner_speed", "angular_speed")
    if n is not None:
        out["speed"] = f"n = {n * RPM:.0f} r/min"
    Fa = q(op, "axial_load", "force")
    if Fa is not None:
        out["axial_load"] = f"Fa = {Fa:.0f} N"
    Fr = q(op, "radial_load", "force")
    if Fr:
        out["radial_load"] = f"Fr = {Fr:.0f} N"
    return out


def title_lines(ds) -> list[str]:
    """Figure title: case name and operating conditions; classification, slip and status."""
    name = ds.attrs.get("case_name", "hsbearing run")
    lab = case_labels(ds)
    first = ", ".join([name] + [lab[k] for k in ("oil", "speed", "axial_load", "radial_load", "temperature") if k in lab])
    parts = []
    if "classification" in ds.attrs:
        conf = ds.attrs.get("classification_confidence")
        c = f"cage motion: {ds.attrs['classification']}"
        if conf is not None and ds.attrs["classification"] != "undetermined":
            c += f" (confidence {float(conf):.2f})"
        parts.append(c)
    if "mean_cage_slip_ratio" in ds and np.isfinite(float(ds["mean_cage_slip_ratio"])):
        parts.append(f"mean cage slip ratio {100 * float(ds['mean_cage_slip_ratio']):.2f} %")
    status = ds.attrs.get("status", "")
    if status and status != "ok":
        parts.append(f"status: {status}")
    return [first, "; ".join(parts)] if parts else [first]


def _figure(figsize):
    from matplotlib.figure import Figure

    return Figure(figsize=figsize, layout="constrained")


def length_scale(extent_m: float) -> tuple[float, str]:
    """Display factor and unit for a length of the given extent [m]: um, or nm below 1 um."""
    return (1e9, "nm") if np.isfinite(extent_m) and extent_m < 1e-6 else (1e6, "\u00b5m")


def velocity_scale(extent: float) -> tuple[float, str]:
    """Display factor and unit for a velocity extent [m/s]: mm/s, or um/s below 1 mm/s."""
    return (1e6, "\u00b5m/s") if np.isfinite(extent) and extent < 1e-3 else (1e3, "mm/s")


def shade(ax, t_end_ms):
    if t_end_ms > 0:
        ax.axvspan(0.0, t_end_ms, color="0.9", zorder=0, label="transient (discarded)")


def _wrap(text: str, width: int) -> str:
    import textwrap

    return "\n".join(textwrap.wrap(text, width))


def per_ball_axes(ax, nb, ylabel: str, title: str, grid_axis: str) -> None:
    """Labels, ball ticks 0..nb-1 (the ``ball`` coordinate of the archives and the printed tables), legend and
    grid of a per-ball panel."""
    ax.set_xlabel("ball")
    ax.set_ylabel(ylabel)
    ax.set_title(title, fontsize=10)
    if nb:
        ax.set_xticks(np.arange(nb))
        ax.legend(fontsize=8)
    ax.grid(alpha=0.3, axis=grid_axis)




def vals(ds, name, factor=1.0):
    return np.asarray(ds[name].values, dtype=float) * factor
