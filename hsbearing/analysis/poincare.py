"""Poincare section of the cage mass-centre motion.

Default (``section="transverse"``): a section **transverse to the flow**.  With a
constant inner-ring speed and a fixed (or constant-speed) outer ring the bearing
model is an autonomous system (the right-hand side never reads t), and the cage
rotation angle is an ordinary state, not a clock.  The section is the
half-plane of the cage-centre state

    D_Z = mean(D_Z),   D_Y > mean(D_Y),   crossed in the sense of the whirl

(the sense is the sign of the mean angular momentum (D_Y - ȳ) V_Z - (D_Z - z̄) V_Y
of the orbit about its own centre: upward crossings, V_Z > 0, for a forward
whirl, downward for a backward one).  The points are (D_Y, V_Y) at the
crossings, the plane of Zhang et al. 2016, Figs. 5-12.  A single circular
whirl gives **one point at any whirl/cage speed ratio**, a k-loop orbit k
points, a two-frequency orbit a closed curve, a chaotic orbit a cloud
(Poincare's transversal section of an autonomous flow: Guckenheimer & Holmes
1983, Sec. 1.4; Parker & Chua 1989, Ch. 3).  "1 period" therefore means that
the cage-centre orbit is periodic, not that the whole state is: the cage
rotation (and the ball-pass excitation) may run at an incommensurate
frequency, and whether the whirl is locked to the cage rotation is reported
separately (:func:`hsbearing.analysis.whirl.whirl_lock`).

Alternatives (kept as options):

- ``section="cage_revolution"``: one point per cage revolution, when the cage
  rotation angle about X crosses a multiple of 2 pi -- a stroboscopic map.
  Stroboscopic sections are the right tool for *forced* (non-autonomous)
  systems whose forcing is a clock (Guckenheimer & Holmes 1983, Sec. 1.5); here
  it turns a single circular whirl at 0.95-0.99 x the cage speed into points
  that creep around an ellipse, so its label follows the arithmetic of the
  whirl/cage ratio, not the orbit's shape.  Its rotation number is what the
  lock test reports.
- ``section="plane"``: the full plane D_Z = mean(D_Z) crossed upwards (both
  sides of the centre).

Crossing times are found by linear interpolation of the rotation angle (or of
D_Z) between the two stored output samples that bracket the crossing; D_Y and
V_Y are then interpolated linearly at those times.  With the schema's default output
interval (20 us, ~500 samples per cage revolution at 14000 r/min) the
interpolation error is O((2 pi / 500)^2) of the orbit size; the bundled
zhang2016 case stores every 50 us (~210 samples per revolution, error
~(2 pi / 210)^2 = 9e-4), both far below the classifier tolerance (0.02).  If ``cage_angle`` is absent it is the time integral of
``cage_speed`` (trapezoidal rule); if ``cage_velocity_y``/``cage_velocity_z`` are absent (a measured
orbit, positions only) V_Y and V_Z are the derivative of a local polynomial fitted to D_Y, D_Z
(:func:`hsbearing.analysis.derivative.smoothed_velocity`: a Savitzky-Golay derivative whose window follows
the orbit's dominant frequency, noise gain stated there), not central differences, which amplify
position noise into a cloud of section points.

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
    "DEFAULT_SECTION",
    "transverse_crossings",
    "section_crossings",
    "DEFAULT_TRANSIENT_FRACTION",
    "section_description",
    "cage_rotation_angle",
    "cage_velocity",
    "cage_velocities",
    "steady_mask",
    "transient_cut",
    "drift_end",
    "saturation_cut",
    "after_transient",
    "crossing_times",
    "poincare_section",
    "poincare_points",
]

#: Closed vocabulary of the Poincare sections.
SECTIONS = ("transverse", "cage_revolution", "plane")

#: The default section (:func:`poincare_section`, :func:`hsbearing.analysis.annotate`, the CLI and the case).
DEFAULT_SECTION = "transverse"

#: Leading fraction of the simulated span always discarded as start-up transient.
DEFAULT_TRANSIENT_FRACTION = 0.3
#: Largest fraction the automatic transient detection may discard.
MAX_TRANSIENT_FRACTION = 0.6


def section_description(section: str = DEFAULT_SECTION) -> str:
    """One-line text describing a section (stored in ``ds.attrs['poincare_section']``)."""
    if section == "transverse":
        return ("transverse section of the autonomous flow: (D_Y, V_Y) of the cage mass centre when it crosses the "
                "half-plane D_Z = mean(D_Z), D_Y > mean(D_Y) in the sense of the whirl (one point per loop of the orbit)")
    if section == "cage_revolution":
        return ("one point per cage revolution: (D_Y, V_Y) of the cage mass centre when the cage rotation "
                "angle about X crosses a multiple of 2 pi (stroboscopic map, Zhang et al. 2016 Figs. 5-12)")
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


def cage_velocities(ds) -> tuple[np.ndarray, np.ndarray, str]:
    """Cage-centre velocities V_Y, V_Z [m/s] and where they come from ("stored" or the estimator's line).

    Stored ``cage_velocity_y``/``cage_velocity_z`` when both are present; otherwise both are estimated from
    the positions by :func:`hsbearing.analysis.derivative.smoothed_velocity` (never one stored and one
    estimated: their noise would differ).
    """
    from hsbearing.analysis.derivative import method_text, smoothed_velocity

    if "cage_velocity_y" in ds and "cage_velocity_z" in ds:
        return (np.asarray(ds["cage_velocity_y"].values, dtype=float),
                np.asarray(ds["cage_velocity_z"].values, dtype=float), "stored")
    vy, vz, info = smoothed_velocity(_time(ds), ds["cage_center_y"].values, ds["cage_center_z"].values)
    return vy, vz, method_text(info)


def cage_velocity(ds, axis: str = "y") -> np.ndarray:
    """Cage-centre velocity V_Y or V_Z [m/s]: stored ``cage_velocity_<axis>`` or estimated (:func:`cage_velocities`)."""
    vy, vz, _ = cage_velocities(ds)
    return vy if axis == "y" else vz


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


def drift_end(ds) -> float | None:
    """Duration [s] from the start after which the run no longer drifts, or None (fewer than 8 revolutions).

    The drift detection of the module text: the per-revolution means of the cage-centre radius and of the cage
    speed are compared with the band of the last quarter of the revolutions (its half-range plus 2 % of the
    radius, 0.1 % of the speed); the run drifts until the last revolution outside that band.
    """
    return _drift_end(ds, _time(ds), _revolution_index(ds))


def _drift_end(ds, t: np.ndarray, k: np.ndarray) -> float | None:
    """:func:`drift_end` with the sample times ``t`` and revolution index ``k`` already computed."""
    nrev = int(k[-1]) if k.size else 0  # complete revolutions 0 .. nrev-1
    if nrev < 8:
        return None
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
    return float(t[int(np.argmax(k >= j0))] - t[0])


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
    t_drift = drift_end(ds)
    if t_drift is None:
        return lo
    return float(min(max(t_drift, lo), hi))


def saturation_cut(ds) -> tuple[float, int]:
    """Duration [s] to discard of a run that starts with a growth to saturation (a growing whirl continued until
    it saturates), and the number of complete cage revolutions after it: the drift end (:func:`drift_end`), at
    least 30 % of the span, with no 60 % cap (the growth may last most of the run).  Fewer than 8 revolutions:
    the 30 % floor."""
    t = _time(ds)
    if t.size < 2:
        return 0.0, 0
    span = float(t[-1] - t[0])
    k = _revolution_index(ds)  # once: the drift test and the count below share it
    t_drift = _drift_end(ds, t, k)
    cut = max(DEFAULT_TRANSIENT_FRACTION * span, t_drift if t_drift is not None else 0.0)
    nrev = int(k[-1])
    first = int(k[int(np.argmax(t >= t[0] + cut * (1 - 1e-12)))]) if t[-1] >= t[0] + cut else nrev
    return float(cut), max(nrev - first - 1, 0)  # the revolution the cut falls in is not complete after it


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


def transverse_crossings(t, y, z, vy=None, vz=None, hysteresis: float = 0.05):
    """Crossings of the half-plane D_Z = z̄, D_Y > ȳ in the sense of the whirl (the transverse section).

    Parameters
    ----------
    t, y, z : (n,) array_like
        Time [s] and the cage-centre coordinates D_Y, D_Z [m] over the analysed window.
    vy, vz : (n,) array_like, optional
        Velocities [m/s] (for the sense of the whirl; finite differences of y, z without them).
    hysteresis : float
        A crossing counts only when D_Z - z̄ has been below -hysteresis x (RMS radius about the centre)
        (on the far side of the plane) since the previous crossing: noise near the plane is not a loop.

    Returns
    -------
    times : (m,) ndarray
        Crossing times [s] (linear interpolation of D_Z - z̄ between the bracketing samples).
    definition : dict
        ``centre_y``, ``centre_z`` [m] (the window means), ``sense`` (+1 forward: crossing with V_Z > 0,
        -1 backward: V_Z < 0, 0 when the orbit has no sense of rotation).
    """
    t = np.asarray(t, float)
    y = np.asarray(y, float)
    z = np.asarray(z, float)
    ok = np.isfinite(t) & np.isfinite(y) & np.isfinite(z)
    t, y, z = t[ok], y[ok], z[ok]
    defn = {"centre_y": float("nan"), "centre_z": float("nan"), "sense": 0}
    if t.size < 3:
        return np.zeros(0), defn
    yc, zc = float(np.mean(y)), float(np.mean(z))
    dy, dz = y - yc, z - zc
    if vy is None or vz is None:
        from hsbearing.analysis.derivative import smoothed_velocity

        vy_, vz_, _ = smoothed_velocity(t, y, z)
    else:
        vy_, vz_ = np.asarray(vy, float)[ok], np.asarray(vz, float)[ok]
    L = float(np.nanmean(dy * vz_ - dz * vy_))  # mean angular momentum about the orbit centre: sense of the whirl
    sense = 1 if L > 0 else -1 if L < 0 else 0
    defn.update(centre_y=yc, centre_z=zc, sense=sense)
    if sense == 0:
        return np.zeros(0), defn
    s = sense * dz
    i = np.nonzero((s[:-1] < 0.0) & (s[1:] >= 0.0))[0]
    if i.size > 1 and hysteresis > 0:
        # Schmitt trigger: a crossing counts only if the orbit went below -h since the previous one, so
        # noise jittering about the plane (h = hysteresis x RMS radius about the centre) is not a new loop
        h = hysteresis * float(np.sqrt(np.mean(dy * dy + dz * dz)))
        below = np.nonzero(s < -h)[0]
        keep_i = []
        last = -1
        for j in i:
            if last < 0 or (below.size and np.searchsorted(below, last + 1) < below.size
                            and below[np.searchsorted(below, last + 1)] <= j):
                keep_i.append(j)
                last = j
        i = np.asarray(keep_i, dtype=int)
    frac = -s[i] / (s[i + 1] - s[i])
    yi = dy[i] + frac * (dy[i + 1] - dy[i])
    keep = yi > 0.0  # the half-plane on the +Y side of the centre
    return t[i][keep] + frac[keep] * (t[i + 1][keep] - t[i][keep]), defn


def section_crossings(section: str, t, y, z, vy=None, vz=None, phi=None) -> tuple[np.ndarray, dict]:
    """Crossing times [s] of ``section`` over samples (t, D_Y, D_Z[, V_Y, V_Z, cage angle phi]) of the analysed
    window, and the section's definition (centre and sense where it has them; ``kind`` not included).

    ``"cage_revolution"``: the cage angle (turned positive) crossing multiples of 2 pi (needs ``phi``);
    ``"transverse"``: :func:`transverse_crossings`; ``"plane"``: D_Z crossing its mean upwards."""
    section_description(section)  # validates the name
    t = np.asarray(t, dtype=float)
    if section == "cage_revolution":
        if phi is None:
            raise ValueError("section 'cage_revolution' needs the cage angle")
        phase = np.asarray(phi, dtype=float)
        if np.nanmean(np.diff(phase)) < 0:  # cage turning the negative way: count its revolutions
            phase = -phase
        return crossing_times(t, phase), {}
    if section == "transverse":
        return transverse_crossings(t, y, z, vy, vz)
    zc = np.asarray(z, dtype=float) - np.mean(z)
    up = np.nonzero((zc[:-1] < 0.0) & (zc[1:] >= 0.0))[0]
    frac = -zc[up] / (zc[up + 1] - zc[up])
    return t[up] + frac * (t[up + 1] - t[up]), {"centre_z": float(np.mean(z)), "sense": 1}


def poincare_section(ds, section: str = DEFAULT_SECTION, transient=None, return_definition: bool = False):
    """Section crossing times [s] and points (D_Y [m], V_Y [m/s]) after the transient.

    ``transient``: see :func:`after_transient` (None = the run's stored cut, else automatic).
    ``return_definition``: also return the section's definition (dict: ``kind``, and for the transverse
    section its centre and sense), as stored with the label by :func:`hsbearing.analysis.annotate`.

    Returns
    -------
    times : (n,) ndarray
    points : (n, 2) ndarray
        Columns D_Y, V_Y of the cage mass centre.
    definition : dict
        Only with ``return_definition``.
    """
    section_description(section)  # validates the name
    t = _time(ds)
    mask, _ = after_transient(ds, transient)
    ts = t[mask]
    defn: dict = {"kind": section}
    if ts.size < 2:
        out = (np.zeros(0), np.zeros((0, 2)))
        return (*out, defn) if return_definition else out
    y = np.asarray(ds["cage_center_y"].values, dtype=float)
    vy = cage_velocity(ds, "y")
    z = np.asarray(ds["cage_center_z"].values, dtype=float)
    phi = cage_rotation_angle(ds)[mask] if section == "cage_revolution" else None
    vz = cage_velocity(ds, "z")[mask] if section == "transverse" else None
    tc, d = section_crossings(section, ts, y[mask], z[mask], vy[mask], vz, phi)
    defn.update(d)
    pts = np.column_stack([np.interp(tc, t, y), np.interp(tc, t, vy)])
    return (tc, pts, defn) if return_definition else (tc, pts)


def poincare_points(ds, section: str | None = None, transient=None) -> np.ndarray:
    """The (n, 2) Poincare points (D_Y [m], V_Y [m/s]) of a dynamic run (see module docstring).

    ``section=None``: the section the run was annotated with (``attrs["poincare_section_kind"]``), else
    the default.  If the Dataset already carries ``poincare_y``/``poincare_vy`` (written by
    :func:`hsbearing.analysis.annotate`) for the same section and no other transient is asked, those are
    returned, so the figure and the stored classification agree.
    """
    stored = ds.attrs.get("poincare_section_kind")
    if section is None:
        section = stored or DEFAULT_SECTION
    if ("poincare_y" in ds and "poincare_vy" in ds and transient is None and section == stored):
        return np.column_stack([np.asarray(ds["poincare_y"].values, float), np.asarray(ds["poincare_vy"].values, float)])
    return poincare_section(ds, section, transient)[1]
