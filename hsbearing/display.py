"""Printed output in the units bearing engineers read (the archives stay SI).

One rule for every printed scalar (``hsbearing run`` summary, sweep table): the SI value of a
registered variable is converted by its ``units`` attr -- lengths below 1 mm in um, angular speeds in
r/min, small moments in uN m or N mm, angles in degrees, slip ratios in %, other ratios (unit ``"1"``)
printed without a unit -- with 4 significant digits.  The figures use the same units.
"""

from __future__ import annotations

import math

__all__ = ["format_value", "format_quantity", "format_seconds", "format_solver_stats", "format_life", "format_grouped"]

_RPM = 60.0 / (2.0 * math.pi)
MICRO = "\u00b5"


def format_quantity(value, units: str, name: str = "", digits: int = 4) -> str:
    """``value`` [SI ``units``] as text in a readable unit, e.g. ``(2.003e-4, "m") -> "200.3 µm"``.

    Non-finite values print as ``"nan"``; unknown units print unchanged.
    """
    try:
        v = float(value)
    except (TypeError, ValueError):
        return f"{value} {units}".rstrip()
    if not math.isfinite(v):
        return "nan"
    g = f"{{:.{digits}g}}"
    u = (units or "").replace("*", " ").strip()
    a = abs(v)
    if u in ("1", ""):
        if "slip_ratio" in name:  # a slip ratio reads as a percentage
            return g.format(100 * v) + " %"
        return g.format(v)
    if u == "m":
        if a == 0 or a < 1e-6:
            return g.format(v * 1e9) + " nm" if a else "0 m"
        if a < 1e-3:
            return g.format(v * 1e6) + f" {MICRO}m"
        if a < 1.0:
            return g.format(v * 1e3) + " mm"
        return g.format(v) + " m"
    if u == "rad/s":
        return g.format(v * _RPM) + " r/min"
    if u == "rad":
        return g.format(math.degrees(v)) + " \N{DEGREE SIGN}"
    if u == "N m":
        if a and a < 1e-3:
            return g.format(v * 1e6) + f" {MICRO}N m"
        if a and a < 1.0:
            return g.format(v * 1e3) + " N mm"
        return g.format(v) + " N m"
    if u == "Pa":
        return (g.format(v * 1e-9) + " GPa") if a >= 1e8 else (g.format(v * 1e-6) + " MPa")
    if u == "K":
        return g.format(v - 273.15) + " \N{DEGREE SIGN}C"
    if u == "s":
        return format_seconds(v)
    return f"{g.format(v)} {u}"


def format_life(million_revolutions, digits: int = 4) -> str:
    """A rating life given in 10^6 revolutions as text: ``13630.4 -> "13 630 million rev"``.

    Four significant digits, thousands grouped by a space (ISO 80000-1), no exponent between 0.001 and 10^9;
    outside that range the exponent is written out (``"1.363 x 10^12 million rev"``).  Non-finite -> ``"nan"``.

    Examples
    --------
    >>> format_life(13630.4)
    '13 630 million rev'
    >>> format_life(0.5432)
    '0.5432 million rev'
    >>> format_life(1.363e12)
    '1.363 x 10^12 million rev'
    """
    return format_grouped(million_revolutions, "million rev", digits)


def format_grouped(value, unit: str, digits: int = 4) -> str:
    """``value`` to ``digits`` significant digits, thousands grouped by a space, then ``unit``; an exponent
    (``"1.363 x 10^12 h"``) only below 0.001 or from 10^9 on.  Used for lives (million rev, hours).

    Examples
    --------
    >>> format_grouped(16234.7, "h")
    '16 230 h'
    """
    x = float(value)
    if not math.isfinite(x):
        return "nan"
    a = abs(x)
    if a and (a < 1e-3 or a >= 1e9):
        e = int(math.floor(math.log10(a)))
        return f"{x / 10**e:.{digits - 1}f} x 10^{e} {unit}"
    if a == 0:
        return f"0 {unit}"
    x = float(f"{x:.{digits - 1}e}")  # rounded to the significant digits (16234.7 -> 16230, 999.96 -> 1000)
    exponent = int(math.floor(math.log10(abs(x))))
    decimals = max(0, digits - 1 - exponent)
    text = f"{x:,.{decimals}f}".replace(",", " ")
    return f"{text} {unit}"


def format_value(var, name: str = "", digits: int = 4) -> str:
    """A scalar xarray variable (with a ``units`` attr) as readable text; see :func:`format_quantity`."""
    val = var.values.item() if hasattr(var, "values") else var
    units = var.attrs.get("units", "") if hasattr(var, "attrs") else ""
    if isinstance(val, (str, bytes)):
        return val.decode() if isinstance(val, bytes) else val
    if isinstance(val, bool) or isinstance(val, int):
        return f"{val} {units}".rstrip() if units not in ("1", "") else str(val)
    return format_quantity(val, units, name, digits)


def format_seconds(t: float) -> str:
    """A duration rounded for reading: ``38.14458563 -> "38.1 s"``, ``0.00123 -> "1.23 ms"``, ``3725 -> "1 h 02 min"``."""
    t = float(t)
    if not math.isfinite(t):
        return "nan"
    a = abs(t)
    if a >= 3600:
        return f"{int(a // 3600)} h {int(round(a % 3600 / 60)):02d} min"
    if a >= 100:
        return f"{int(a // 60)} min {int(round(a % 60)):02d} s"
    if a >= 1 or a == 0:
        return f"{t:.3g} s"
    if a >= 1e-3:
        return f"{t * 1e3:.3g} ms"
    return f"{t * 1e6:.3g} {MICRO}s"


def format_solver_stats(stats: dict) -> str:
    """``solver_*`` statistics on one line: counts as integers, times rounded, tolerances in 3 digits."""
    parts = []
    for k, v in stats.items():
        if isinstance(v, bool):
            txt = str(v)
        elif isinstance(v, int):
            txt = str(v)
        elif isinstance(v, float):
            if "wall_time" in k:
                txt = format_seconds(v)
            elif float(v).is_integer() and abs(v) < 1e15:
                txt = str(int(v))
            else:
                txt = f"{v:.3g}"
        else:
            txt = str(v)
        parts.append(f"{k}={txt}")
    return ", ".join(parts)


# Contact pressure [Pa] bearing steel carries at rest in a ball bearing (ISO 76:2006, 6.2): one constant,
# defined with the other limits in hsbearing.models.limits
from hsbearing.models.limits import ISO76_BALL_PRESSURE  # noqa: E402


def contact_pressure_warning(p_max, where: str = "") -> str | None:
    """A warning line when the largest of ``p_max`` [Pa] exceeds :data:`ISO76_BALL_PRESSURE`, else None.

    ``where`` says at which point the largest value occurs (e.g. ``"at preload 160 µm"``).
    """
    import numpy as np

    p = np.asarray(p_max, dtype=float)
    if not p.size or not np.isfinite(p).any():
        return None
    top = float(np.nanmax(p))
    if top <= ISO76_BALL_PRESSURE:
        return None
    return (f"hsbearing: warning: maximum contact pressure {top * 1e-9:.3g} GPa{(' (' + where + ')') if where else ''} "
            f"exceeds the {ISO76_BALL_PRESSURE * 1e-9:g} GPa bearing steel carries in a ball bearing (ISO 76:2006 static "
            "load rating); beyond it the raceways deform permanently and the elastic (Hertz) results do not hold")
