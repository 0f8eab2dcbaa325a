"""Poincare section of the cage mass-centre motion.

Section used (default, ``section="cage_revolution"``): one point per cage
revolution -- the cage-centre displacement and velocity along Y, (D_Y, V_Y),
sampled each time the cage rotation angle about the bearing axis X crosses a
multiple of 2 pi.  This is the stroboscopic map of seed 004 (Zhang et al.
2016, Figs. 5-12 plot D_Y against V_Y): a cage whirling synchronously with
its own rotation gives one point ("1 period"), a whirl that repeats after k
cage revolutions gives k points, an incommensurate whirl a closed curve.

Alternative (``section="plane"``): the classical plane section of the
trajectory, one point each time the cage centre crosses the plane D_Z = mean
(D_Z) with dD_Z/dt > 0 (independent of the cage rotation angle).

Crossing times are found by linear interpolation of the rotation angle (or of
D_Z) between the two stored output samples that bracket the crossing; D_Y and
V_Y are then interpolated linearly at those times.  With the schema's default output
interval (20 us, ~500 samples per cage revolution at 14000 r/min) the
interpolation error is O((2 pi / 500)^2) of the orbit size; the bundled
zhang2016 case stores every 50 us (~210 samples per revolution, error
~(2 pi / 210)^2 = 9e-4), both far below the classifier tolerance (0.02).  If ``cage_angle`` is absent it is the time integral of
``cage_speed`` (trapezoidal rule); if ``cage_velocity_y`` is absent V_Y is
the time derivative of D_Y (second-order central differences,
``numpy.gradient``).

Transient (``transient="auto"``, the default of :func:`hsbearing.analysis.annotate`):
the discarded start is the later of 30 % of the simulated span and the end of
the detected drift, capped at 60 % of the span.  The drift test works on
per-revolution means of the cage-centre radius sqrt(D_Y^2 + D_Z^2) and of the
cage speed: the reference is the last 25 % of the complete revolutions (at
least 3); a revolution drifts if its mean lies outside [min(ref) - tol,
max(ref) + tol] with tol = 0.5 ptp(ref) + rel |median(ref)| (rel = 0.02 for
the radius, 0.001 for the speed); the transient ends at the start of the
revolution after the last drifting one.  Runs of fewer than 8 complete cage
revolutions use the 30 % rule alone.  A change of regime inside the
reference (the last 25 %) is not detected: such a run is too short to
classify anyway.  A float ``transient`` in [0, 1) is a
fixed fraction of the span instead.
"""

from __future__ import annotations

import numpy as np

__all__ = [
    "SECTIONS",
    "DEFAULT_TRANSIENT_FRACTION",
    "section_description",
    "cage_rotation_angle",
    "cage_velocity",
    "steady_mask",
    "transient_cut",
    "after_transient",
    "crossing_times",
    "poincare_section",
    "poincare_points",
]

#: Closed vocabulary of the Poincare sections.
SECTIONS = ("cage_revolution", "plane")

#: Leading fraction of the simulated span always discarded as start-up transient.
DEFAULT_TRANSIENT_FRACTION = 0.3
#: Largest fraction the automatic transient detection may discard.
MAX_TRANSIENT_FRACTION = 0.6


def section_description(section: str = "cage_revolution") -> str:
    """One-line text describing a section (stored in ``ds.attrs['poincare_section']``)."""
    if section == "cage_revolution":
        return ("one point per cage revolution: (D_Y, V_Y) of the cage mass centre when the cage rotation "
                "angle about X crosses a multiple of 2 pi (stroboscopic map, seed 004 Figs. 5-12)")
    if section == "plane":
        return ("plane section: (D_Y, V_Y) of the cage mass centre when D_Z crosses its mean value "
                "with dD_Z/dt > 0")
    raise ValueError(f"unknown Poincare section {section!r} (known: {', '.join(SECTIONS)})")


def _time(ds) -> np.ndarray:
    return np.asarray(ds["time"].values, dtype=float)


def cage_rotation_angle(ds) -> np.ndarray:
    """Cage rotation angle about X [rad] over ``time``: ``cage_angle`` or the integral of ``cage_speed``."""
    if "cage_angle" in ds:
        return np.asarray(ds["cage_angle"].values, dtype=float)
    t = _time(ds)
    w = np.asarray(ds["cage_speed"].values, dtype=float)
    ang = np.zeros_like(w)
    if len(t) > 1:
        ang[1:] = np.cumsum(0.5 * (w[1:] + w[:-1]) * np.diff(t))  # trapezoidal rule
    return ang


def cage_velocity(ds, axis: str = "y") -> np.ndarray:
    """Cage-centre velocity V_Y or V_Z [m/s]: stored ``cage_velocity_<axis>`` or dD/dt."""
    name = f"cage_velocity_{axis}"
    if name in ds:
        return np.asarray(ds[name].values, dtype=float)
    t = _time(ds)
    d = np.asarray(ds[f"cage_center_{axis}"].values, dtype=float)
    if len(t) < 3:
        return np.full_like(d, np.nan)
    return np.gradient(d, t, edge_order=2)


def steady_mask(t, transient_fraction: float = DEFAULT_TRANSIENT_FRACTION) -> tuple[np.ndarray, float]:
    """Boolean mask of the samples after the transient, and the discarded duration [s].

    The first ``transient_fraction`` of the simulated span [t_0, t_end] is discarded.
    """
    t = np.asarray(t, dtype=float)
    if not 0.0 <= transient_fraction < 1.0:
        raise ValueError("transient_fraction must be in [0, 1)")
    if len(t) == 0:
        return np.zeros(0, bool), 0.0
    t_cut = t[0] + transient_fraction * (t[-1] - t[0])
    return t >= t_cut, float(t_cut - t[0])


def _revolution_index(ds) -> np.ndarray:
    """Index of the cage revolution each output sample belongs to (0 = the first, from the run start)."""
    ang = cage_rotation_angle(ds)
    if ang.size > 1 and np.nanmean(np.diff(ang)) < 0:
        ang = -ang
    k = np.floor(np.maximum.accumulate(np.nan_to_num(ang, nan=-np.inf)) / (2 * np.pi))
    k = np.where(np.isfinite(k), k, 0).astype(int)
    return k - k[0] if k.size else k


def transient_cut(ds, transient="auto") -> float:
    """Duration [s] of the start-up transient to discard (rule in the module docstring).

    ``transient`` is ``"auto"`` (drift detection, at least 30 %, at most 60 %
    of the span) or a float fraction of the span in [0, 1).
    """
    t = _time(ds)
    if t.size < 2:
        return 0.0
    span = float(t[-1] - t[0])
    if not isinstance(transient, str):
        return steady_mask(t, float(transient))[1]
    if transient != "auto":
        raise ValueError(f"transient must be 'auto' or a fraction in [0, 1), not {transient!r}")
    lo, hi = DEFAULT_TRANSIENT_FRACTION * span, MAX_TRANSIENT_FRACTION * span
    k = _revolution_index(ds)
    nrev = int(k[-1])  # complete revolutions 0 .. nrev-1
    if nrev < 8:
        return lo
    sel = k < nrev
    cnt = np.bincount(k[sel], minlength=nrev)
    r = np.hypot(np.asarray(ds["cage_center_y"].values, float), np.asarray(ds["cage_center_z"].values, float))
    w = np.asarray(ds["cage_speed"].values, float)
    j0 = 0
    for x, rel in ((r, 0.02), (w, 1e-3)):
        xm = np.bincount(k[sel], np.nan_to_num(x[sel]), minlength=nrev) / np.maximum(cnt, 1)
        ref = xm[-max(3, int(0.25 * nrev)):]
        tol = 0.5 * np.ptp(ref) + rel * abs(np.median(ref))
        bad = np.nonzero((xm < ref.min() - tol) | (xm > ref.max() + tol))[0]
        if bad.size:
            j0 = max(j0, int(bad[-1]) + 1)
    t_drift = float(t[int(np.argmax(k >= j0))] - t[0])
    return float(min(max(t_drift, lo), hi))


def after_transient(ds, transient=None) -> tuple[np.ndarray, float]:
    """Mask of the output samples after the transient, and the discarded duration [s].

    ``transient=None`` uses ``ds.attrs["transient_discarded"]`` (written by
    :func:`hsbearing.analysis.annotate`) when present, else ``"auto"``.
    """
    t = _time(ds)
    if transient is None:
        cut = ds.attrs.get("transient_discarded")
        cut = transient_cut(ds, "auto") if cut is None else float(cut)
    else:
        cut = transient_cut(ds, transient)
    if t.size == 0:
        return np.zeros(0, bool), 0.0
    return t >= t[0] + cut * (1 - 1e-12), cut


def crossing_times(t, phase, period: float = 2.0 * np.pi) -> np.ndarray:
    """Times at which a (mostly increasing) ``phase`` first crosses each multiple of ``period``.

    Linear interpolation between the bracketing samples.  Only the first
    upward crossing of each multiple counts (a cage rocking back and forth
    across a multiple of 2 pi is not a new revolution); a sample step that
    jumps over several multiples gives one crossing for each.
    """
    t = np.asarray(t, dtype=float)
    phase = np.asarray(phase, dtype=float)
    ok = np.isfinite(phase) & np.isfinite(t)
    t, phase = t[ok], phase[ok]
    if t.size < 2:
        return np.zeros(0)
    k = np.maximum.accumulate(np.floor(phase / period))  # highest multiple reached so far
    jump = (k[1:] - k[:-1]).astype(int)
    idx = np.repeat(np.nonzero(jump > 0)[0], jump[jump > 0])
    if idx.size == 0:
        return np.zeros(0)
    # multiples crossed in each step: k[i] + 1, ..., k[i + 1]
    offs = np.concatenate([np.arange(1, j + 1) for j in jump[jump > 0]])
    target = (k[idx] + offs) * period
    p0, p1 = phase[idx], phase[idx + 1]
    frac = np.clip((target - p0) / (p1 - p0), 0.0, 1.0)
    return t[idx] + frac * (t[idx + 1] - t[idx])


def poincare_section(ds, section: str = "cage_revolution", transient=None):
    """Section crossing times [s] and points (D_Y [m], V_Y [m/s]) after the transient.

    ``transient``: see :func:`after_transient` (None = the run's stored cut, else automatic).

    Returns
    -------
    times : (n,) ndarray
    points : (n, 2) ndarray
        Columns D_Y, V_Y of the cage mass centre.
    """
    section_description(section)  # validates the name
    t = _time(ds)
    mask, _ = after_transient(ds, transient)
    ts = t[mask]
    if ts.size < 2:
        return np.zeros(0), np.zeros((0, 2))
    y = np.asarray(ds["cage_center_y"].values, dtype=float)
    vy = cage_velocity(ds, "y")
    if section == "cage_revolution":
        phase = cage_rotation_angle(ds)[mask]
        if np.nanmean(np.diff(phase)) < 0:  # cage turning the negative way: count its revolutions
            phase = -phase
        tc = crossing_times(ts, phase)
    else:
        z = np.asarray(ds["cage_center_z"].values, dtype=float)[mask]
        zc = z - np.mean(z)
        up = np.nonzero((zc[:-1] < 0.0) & (zc[1:] >= 0.0))[0]
        frac = -zc[up] / (zc[up + 1] - zc[up])
        tc = ts[up] + frac * (ts[up + 1] - ts[up])
    pts = np.column_stack([np.interp(tc, t, y), np.interp(tc, t, vy)])
    return tc, pts


def poincare_points(ds, section: str = "cage_revolution", transient=None) -> np.ndarray:
    """The (n, 2) Poincare points (D_Y [m], V_Y [m/s]) of a dynamic run (see module docstring).

    If the Dataset already carries ``poincare_y``/``poincare_vy`` (written by
    :func:`hsbearing.analysis.annotate`) for the same section and no other
    transient is asked, those are returned, so the figure and the stored
    classification agree.
    """
    if ("poincare_y" in ds and "poincare_vy" in ds and transient is None
            and section == ds.attrs.get("poincare_section_kind", section)):
        return np.column_stack([np.asarray(ds["poincare_y"].values, float), np.asarray(ds["poincare_vy"].values, float)])
    return poincare_section(ds, section, transient)[1]
