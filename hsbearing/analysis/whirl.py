"""Classification of the whole cage motion of a run: a growing whirl, a still or parked cage, the whirl-cage
lock, the section label of :mod:`hsbearing.analysis.periods` read on the right section, the sub-labels
(synchronous, harmonic, circular whirl) and the cage instability indicator.  Thresholds and their justification:
docs/analysis.md, "Classification of a run"."""

from __future__ import annotations

import math

import numpy as np

from hsbearing.analysis.periods import classify

__all__ = [
    "DETAILS",
    "classification_detail",
    "cage_instability_index",
    "whirl_growth",
    "whirl_lock",
    "whirl_cage_phase",
    "classify_motion",
    "MOTION_DEFAULTS",
]

# ----------------------------------------------------------------------------- the whole motion: growth, still cage, section

#: Thresholds of :func:`classify_motion` (decisions in docs/analysis.md, "Classification of a run").
MOTION_DEFAULTS = dict(
    growth_ratio=1.5,  # RMS whirl radius of the last quarter / first quarter >= 1.5 (monotone): growing
    growth_floor=1e-4,  # ... unless the largest quarter is below 1e-4 x the guide clearance (numerical jitter)
    still_fraction=0.01,  # RMS radius about the orbit centre < 1 % of the guide clearance: still cage
    parked_fraction=0.05,  # ... or < 5 % of it while the centre rests >= 50 % of the clearance off the axis:
    parked_offset=0.5,  # parked on the guide land (orbit.PARKED_MOTION_FRACTION / PARKED_OFFSET_FRACTION)
    lock_turns=0.1,  # whirl-cage phase drifting less than 0.1 turn (and within 3 sigma of 0) over the window: locked
)


def whirl_growth(t, y, z, parts: int = 4) -> dict:
    """Growth or decay of the whirl about the orbit's own centre over the window.

    The window is cut into ``parts`` equal spans; ``radii`` are the RMS radii about the window's mean
    centre in each.  ``ratio`` = last / first, ``monotone`` True when the radii rise (or fall) from span to
    span, ``sigma`` = ln(ratio) / (time between the first and last span centres) [1/s] (growth rate of an
    exponential spiral r ~ e^(sigma t)).
    """
    t = np.asarray(t, float)
    y = np.asarray(y, float)
    z = np.asarray(z, float)
    ok = np.isfinite(t) & np.isfinite(y) & np.isfinite(z)
    t, y, z = t[ok], y[ok], z[ok]
    out = {"radii": [], "ratio": float("nan"), "monotone": False, "sigma": float("nan"), "direction": ""}
    if t.size < 4 * parts:
        return out
    r2 = (y - y.mean()) ** 2 + (z - z.mean()) ** 2
    edges = np.linspace(t[0], t[-1], parts + 1)
    idx = np.clip(np.searchsorted(edges, t, side="right") - 1, 0, parts - 1)
    radii = np.sqrt(np.bincount(idx, r2, minlength=parts) / np.maximum(np.bincount(idx, minlength=parts), 1))
    out["radii"] = [float(v) for v in radii]
    if radii[0] <= 0 or radii[-1] <= 0:
        return out
    ratio = float(radii[-1] / radii[0])
    d = np.diff(radii)
    out["ratio"] = ratio
    out["monotone"] = bool(np.all(d > 0) or np.all(d < 0))
    dt = (edges[-1] - edges[0]) * (parts - 1) / parts
    out["sigma"] = float(math.log(ratio) / dt) if dt > 0 else float("nan")
    return out


def whirl_cage_phase(t, y, z, cage_angle):
    """Cage revolutions phi/2 pi since the start, the whirl-cage phase psi = (theta - n phi)/2 pi [turns], the
    nearest harmonic n and the mean whirl/cage ratio (theta: whirl angle about the orbit's own centre, unwrapped)."""
    y = np.asarray(y, float)
    z = np.asarray(z, float)
    phi = np.asarray(cage_angle, float)
    theta = np.unwrap(np.arctan2(z - z.mean(), y - y.mean()))
    revs = (phi - phi[0]) / (2 * np.pi)
    dphi = phi[-1] - phi[0]
    ratio = float((theta[-1] - theta[0]) / dphi) if dphi != 0 else float("nan")
    n = int(round(ratio)) if math.isfinite(ratio) else 0
    return revs, (theta - n * phi) / (2 * np.pi), n, ratio


def whirl_lock(t, y, z, cage_angle) -> dict:
    """Is the whirl locked to the cage rotation?  The unwrapped whirl-cage phase and its drift.

    The whirl phase theta(t) is the angle of the cage centre about the orbit's own centre, unwrapped; the
    cage angle phi(t) its rotation about X.  n = round(d theta / d phi) is the nearest harmonic (1 for a
    whirl at the cage speed) and psi = theta - n phi the whirl-cage phase.  Its least-squares slope against
    phi / 2 pi is the drift ``rho`` in turns per cage revolution -- the signed rotation number of the
    cage-revolution (stroboscopic) section -- with the standard error ``rho_sd`` from the residual scatter
    (samples treated as independent after thinning to ~8 per cage revolution).  ``drift_turns`` is the drift
    over the window; ``locked`` is True when it is below :data:`MOTION_DEFAULTS` ["lock_turns"] and within
    three standard errors of zero.
    """
    t = np.asarray(t, float)
    y = np.asarray(y, float)
    z = np.asarray(z, float)
    phi = np.asarray(cage_angle, float)
    ok = np.isfinite(t) & np.isfinite(y) & np.isfinite(z) & np.isfinite(phi)
    t, y, z, phi = t[ok], y[ok], z[ok], phi[ok]
    out = {"harmonic": None, "ratio": float("nan"), "rho": float("nan"), "rho_sd": float("nan"),
           "drift_turns": float("nan"), "locked": None, "cage_revolutions": float("nan")}
    if t.size < 16:
        return out
    revs, psi, n, ratio = whirl_cage_phase(t, y, z, phi)
    out["cage_revolutions"] = float(abs(revs[-1]))
    if abs(revs[-1]) < 1.0:
        return out
    step = max(1, int(len(t) / (8.0 * abs(revs[-1]))))
    X, P = revs[::step], psi[::step]
    A = np.column_stack([X, np.ones_like(X)])
    coef, *_ = np.linalg.lstsq(A, P, rcond=None)
    res = P - A @ coef
    dof = max(len(X) - 2, 1)
    sd = float(np.sqrt(np.sum(res**2) / dof / max(np.sum((X - X.mean()) ** 2), 1e-300)))
    rho = float(coef[0])
    drift = abs(rho * revs[-1])
    out.update(harmonic=n, ratio=ratio, rho=rho, rho_sd=sd, drift_turns=float(drift),
               locked=bool(drift < MOTION_DEFAULTS["lock_turns"] and abs(rho) <= 3 * sd + 1e-12))
    return out


def classify_motion(t, y, z, vy=None, vz=None, cage_angle=None, *, clearance: float | None = None,
                    section: str = "transverse", scale=None,
                    growth_ratio: float = MOTION_DEFAULTS["growth_ratio"],
                    growth_floor: float = MOTION_DEFAULTS["growth_floor"],
                    still_fraction: float = MOTION_DEFAULTS["still_fraction"], growth: dict | None = None,
                    lock: dict | None = None, **classify_kw):
    """Classify the cage-centre motion over an analysed window (after the transient).

    Order (docs/analysis.md, "Classification of a run"):

    1. **growth / decay** of the whirl about the orbit's own centre (:func:`whirl_growth`): the RMS radius
       of the last quarter >= ``growth_ratio`` x the first (or <= 1/``growth_ratio``), rising (falling)
       from quarter to quarter -> ``"undetermined"`` (kind "growing" / "decaying"), unless a decaying
       whirl has already come to rest (then step 2 decides);
    2. **still cage**: RMS radius about the orbit centre over the last half < ``still_fraction`` x the
       guide ``clearance`` -> ``"1 period"`` (kind "still"); the section is not consulted (a cage pressed
       on its land jitters at the ball-pass frequency through the section thousands of times);
    3. **section** (:func:`hsbearing.analysis.poincare.transverse_crossings` by default) and
       :func:`classify` of its points (D_Y, V_Y), scaled by the orbit's peak-to-peak extent (no floor: a
       cage at rest is answered by step 2, so the old floor at half the clearance is not needed and would
       hide a small torus).

    Parameters
    ----------
    t, y, z : (n,) array_like
        Time [s] and cage-centre displacements D_Y, D_Z [m].
    vy, vz : (n,) array_like, optional
        Cage-centre velocities [m/s]; without them (either one None) both are estimated from y, z by
        :func:`hsbearing.analysis.derivative.smoothed_velocity` (local-polynomial derivative).
    cage_angle : (n,) array_like, optional
        Cage rotation angle about X [rad]; needed for ``section="cage_revolution"`` and the lock report.
    clearance : float, optional
        Radial guide clearance [m]: the scale of "still" and of the tolerance floor.
    section : str
        ``"transverse"`` (default), ``"cage_revolution"`` or ``"plane"``.
    scale : (2,) array_like, optional
        Attractor extent of (D_Y, V_Y) for the tolerance (default: from the orbit, floored as above).
    growth, lock : dict, optional
        :func:`whirl_growth` and :func:`whirl_lock` of these same samples, e.g. the ``growth`` and ``lock``
        details of an earlier call under another section: taken as given instead of computed again (neither
        depends on the section).

    Returns
    -------
    label, confidence, details : str, float, dict
        As :func:`classify`, plus ``growth`` (:func:`whirl_growth`), ``lock`` (:func:`whirl_lock`),
        ``orbit_rms_radius`` [m], ``modulation_y`` [m] / ``modulation_vy`` [m/s] (largest distance of a
        section point from its cluster median, for periodic labels: the amplitude of what the section does
        not resolve, e.g. a ball-pass ripple), ``section`` (definition) and the section ``times``/``points``.
    """
    from hsbearing.analysis import poincare as _pc

    t = np.asarray(t, float)
    y = np.asarray(y, float)
    z = np.asarray(z, float)
    ok = np.isfinite(t) & np.isfinite(y) & np.isfinite(z)
    if vy is None or vz is None:  # positions only: a derivative that does not amplify noise (analysis.derivative)
        from hsbearing.analysis.derivative import smoothed_velocity

        vy, vz, _ = smoothed_velocity(t, y, z)
    vy = np.asarray(vy, float)
    vz = np.asarray(vz, float)
    ok &= np.isfinite(vy) & np.isfinite(vz)
    t, y, z, vy, vz = t[ok], y[ok], z[ok], vy[ok], vz[ok]
    phi = None if cage_angle is None else np.asarray(cage_angle, float)[ok]
    c = float(clearance) if clearance is not None and math.isfinite(clearance) and clearance > 0 else None
    if growth is None:
        growth = whirl_growth(t, y, z)
    if lock is None and phi is not None:
        lock = whirl_lock(t, y, z, phi)
    extra: dict = {"growth": growth, "lock": lock,
                   "orbit_rms_radius": None, "modulation_y": None, "modulation_vy": None,
                   "section": {"kind": section}, "times": np.zeros(0), "points": np.zeros((0, 2))}
    if t.size < 16:
        det = {"n_points": 0, "kind": "too-few-points", "reason": "fewer than 16 orbit samples after the transient"}
        return "undetermined", 0.0, {**det, **extra}
    half = t >= t[0] + 0.5 * (t[-1] - t[0])
    yh, zh = y[half], z[half]
    rho_half = float(np.sqrt(np.mean((yh - yh.mean()) ** 2 + (zh - zh.mean()) ** 2)))
    extra["orbit_rms_radius"] = float(np.sqrt(np.mean((y - y.mean()) ** 2 + (z - z.mean()) ** 2)))
    g = extra["growth"]
    offset = float(np.hypot(yh.mean(), zh.mean()))
    parked = (c is not None and rho_half < MOTION_DEFAULTS["parked_fraction"] * c
              and offset >= MOTION_DEFAULTS["parked_offset"] * c)
    still = c is not None and (rho_half < still_fraction * c or parked)
    # 1. growth / decay
    if g["monotone"] and math.isfinite(g["ratio"]) and (g["ratio"] >= growth_ratio or g["ratio"] <= 1 / growth_ratio):
        big = max(g["radii"])
        if c is None or big >= growth_floor * c:
            growing = g["ratio"] > 1
            if growing or not still:
                kind = "growing" if growing else "decaying"
                e_time = 1.0 / abs(g["sigma"]) if math.isfinite(g["sigma"]) and g["sigma"] != 0 else float("inf")
                rs = " -> ".join(f"{v * 1e6:.3g}" for v in g["radii"])
                what = ("the whirl is growing: the run has not reached its attractor" if growing else
                        "the whirl is decaying: converging, not settled")
                det = {"n_points": 0, "kind": kind,
                       "reason": (f"{what} (RMS radius about the orbit centre per quarter of the window {rs} um, "
                                  f"growth rate {g['sigma']:.3g} 1/s, e-folding time {e_time:.3g} s); run longer")}
                return "undetermined", 0.0, {**det, **extra}
    # 2. still cage
    if still:
        if rho_half < still_fraction * c:
            why = (f"cage centre at rest: RMS radius about its mean position {rho_half:.3g} m < "
                   f"{still_fraction:g} x guide clearance {c:.3g} m over the last half of the window "
                   "(a fixed point; the section is not consulted)")
        else:
            why = (f"cage parked on its guide land: centre {offset:.3g} m off the axis (>= "
                   f"{MOTION_DEFAULTS['parked_offset']:g} x clearance {c:.3g} m), moving only {rho_half:.3g} m RMS "
                   f"(< {MOTION_DEFAULTS['parked_fraction']:g} x clearance) about that point: a forced jitter, "
                   "not a whirl (the section is not consulted)")
        det = {"n_points": 0, "kind": "still", "period": 1, "reason": why}
        return "1 period", 1.0, {**det, **extra}
    # 3. the section
    tc, d = _pc.section_crossings(section, t, y, z, vy, vz, phi)
    defn = {"kind": section, **d}
    pts = np.column_stack([np.interp(tc, t, y), np.interp(tc, t, vy)])
    extra.update(section=defn, times=tc, points=pts)
    orbit = np.column_stack([y, vy])
    if scale is None:  # the orbit's own extent (a cage at rest was answered by the still test above)
        scale = np.ptp(orbit, axis=0)
    label, conf, det = classify(pts, scale=scale, **classify_kw)
    if det.get("period") and len(pts):
        k = int(det["period"])
        meds = np.array([np.median(pts[r::k], axis=0) for r in range(k)])
        dev = np.abs(np.concatenate([pts[r::k] - meds[r] for r in range(k)]))
        extra["modulation_y"] = float(dev[:, 0].max())
        extra["modulation_vy"] = float(dev[:, 1].max())
    if det.get("kind") == "drifting-arc" and len(tc) > 1 and math.isfinite(det.get("sections_per_turn") or float("nan")):
        dt_sec = float(np.mean(np.diff(tc)))
        more = max(det["sections_per_turn"] - (len(tc) - 1), 0.0) * dt_sec
        det["run_longer_s"] = more
        det["reason"] += f" (~{more:.2g} s more)"
    return label, conf, {**det, **extra}


# ----------------------------------------------------------------------------- sub-labels and instability indicator

#: Closed vocabulary of ``classification_detail`` (the sub-label of a class; '' when there is none).
#: "1 period" (Zhang et al. 2016, Figs. 5a, 6a, 8b, 9b, 11a: "single circle whirl" + one Poincare point) is
#: split into what the section alone cannot tell apart::
#:
#:   "still cage"            the cage centre does not move (fixed point, concentric or offset);
#:   "synchronous whirl"     a single-circle whirl at (within ratio_tol) the cage speed, either sense: the
#:                           paper's "1 period" (Fig. 5a);
#:   "harmonic whirl"        a circular whirl at an integer multiple n >= 2 of the cage speed;
#:   "circular whirl"        a circular whirl at a speed that is no integer multiple of the cage speed (the
#:                           transverse section gives one point at any whirl speed);
#:   "synchronous orbit"     any other closed single-loop orbit (not a circle) -- under the cage-revolution
#:                           section: an orbit repeating once per cage revolution.
DETAILS = ("", "still cage", "synchronous whirl", "harmonic whirl", "circular whirl", "synchronous orbit")

#: Thresholds of :func:`classification_detail` (decisions in docs/analysis.md, "Sub-labels of 1 period").
DETAIL_DEFAULTS = dict(
    still_fraction=0.01,  # orbit RMS radius about its own centre < 1 % of the guide clearance: still
    circle_spread=0.15,  # sd / mean of the radius about the orbit centre <= 0.15: a circle
    ratio_tol=0.1,  # |whirl frequency / cage rotation frequency| within 0.1 of an integer
)


def _orbit_about_centre(y, z):
    y = np.asarray(y, float)
    z = np.asarray(z, float)
    ok = np.isfinite(y) & np.isfinite(z)
    y, z = y[ok], z[ok]
    yc, zc = float(np.mean(y)), float(np.mean(z))
    return y - yc, z - zc


def classification_detail(label: str, t, y, z, cage_speed, clearance: float, *,
                          still_fraction: float = DETAIL_DEFAULTS["still_fraction"],
                          circle_spread: float = DETAIL_DEFAULTS["circle_spread"],
                          ratio_tol: float = DETAIL_DEFAULTS["ratio_tol"]) -> tuple[str, dict]:
    """Sub-label of a classification from the continuous cage-centre orbit (after the transient).

    Only ``"1 period"`` has sub-labels (:data:`DETAILS`); other labels return ``""``.  Zhang et al. 2016
    pairs "1 period" with "the single circle whirl" of the cage centre and one Poincare point
    (Zhang et al. 2016, Sec. 4, Fig. 5a); the cage-revolution section gives one point as well for a
    cage centre that does not move at all, so the orbit itself decides:

    1. RMS distance of the orbit from its own centre ``rho`` < ``still_fraction`` x guide clearance
       -> ``"still cage"`` (the mean offset of the centre is reported, not judged);
    2. else the whirl frequency f_w (dominant frequency of (y - mean) + i (z - mean)) over the cage
       rotation frequency f_c = mean(cage_speed) / 2 pi; ``n = round(|f_w / f_c|)``;
       the radius about the orbit centre has sd/mean <= ``circle_spread`` (a circle) and
       ``| |f_w / f_c| - n | <= ratio_tol``: n = 1 -> ``"synchronous whirl"``, n >= 2 ->
       ``"harmonic whirl"``;
    3. otherwise ``"synchronous orbit"`` (a closed non-circular orbit, or a circle whose frequency
       ratio is not an integer -- the section still repeats, e.g. a whirl locked to the section
       through the ball-pass excitation).

    Parameters
    ----------
    label : str
        The class from :func:`classify`.
    t : (n,) array_like
        Time [s] of the orbit samples.
    y, z : (n,) array_like
        Cage mass-centre displacements D_Y, D_Z [m].
    cage_speed : (n,) array_like or float
        Cage rotation speed about X [rad/s].
    clearance : float
        Guide clearance (radial) [m]; the scale of "still".

    Returns
    -------
    detail : str
        One of :data:`DETAILS`.
    info : dict
        ``orbit_rms_radius`` [m] (about the orbit centre), ``orbit_offset`` [m] (of the orbit
        centre from the bearing axis), ``radius_spread`` [1], ``whirl_cage_ratio`` [1] (signed),
        ``harmonic`` (n) and ``reason``.
    """
    info: dict = {"orbit_rms_radius": None, "orbit_offset": None, "radius_spread": None,
                  "whirl_cage_ratio": None, "harmonic": None, "reason": ""}
    if label != "1 period":
        return "", info
    from hsbearing.analysis.spectrum import whirl_frequency

    t = np.asarray(t, float)
    y = np.asarray(y, float)
    z = np.asarray(z, float)
    ok = np.isfinite(t) & np.isfinite(y) & np.isfinite(z)
    t, y, z = t[ok], y[ok], z[ok]
    if len(t) < 16:
        info["reason"] = "fewer than 16 orbit samples"
        return "", info
    info["orbit_offset"] = float(math.hypot(np.mean(y), np.mean(z)))
    dy, dz = _orbit_about_centre(y, z)
    r = np.hypot(dy, dz)
    rho = float(np.sqrt(np.mean(r * r)))
    info["orbit_rms_radius"] = rho
    c = float(clearance) if clearance and math.isfinite(clearance) and clearance > 0 else float("nan")
    if math.isfinite(c) and rho < still_fraction * c:
        info["reason"] = (f"cage centre at rest: orbit RMS radius {rho:.3g} m < {still_fraction:g} x guide "
                          f"clearance {c:.3g} m (offset {info['orbit_offset']:.3g} m)")
        return "still cage", info
    rbar = float(np.mean(r))
    spread = float(np.std(r) / rbar) if rbar > 0 else float("inf")
    info["radius_spread"] = spread
    w = np.asarray(cage_speed, float)
    w = float(np.nanmean(w[ok] if w.ndim and w.size == ok.size else w))
    fw = whirl_frequency(t, y, z)
    ratio = 2 * math.pi * fw / w if (w != 0 and math.isfinite(fw)) else float("nan")
    info["whirl_cage_ratio"] = ratio
    if math.isfinite(ratio):
        n = int(round(abs(ratio)))
        info["harmonic"] = n
        if spread <= circle_spread and n >= 1 and abs(abs(ratio) - n) <= ratio_tol:
            kind = "synchronous whirl" if n == 1 else "harmonic whirl"
            info["reason"] = (f"circular whirl (radius sd/mean {spread:.2f} <= {circle_spread}) at {ratio:+.3f} x "
                              f"the cage speed, radius {rbar:.3g} m")
            return kind, info
        if spread <= circle_spread:
            info["reason"] = (f"circular whirl (radius sd/mean {spread:.2f} <= {circle_spread}) at {ratio:+.3f} x "
                              f"the cage speed (no integer multiple), radius {rbar:.3g} m")
            return "circular whirl", info
    info["reason"] = (f"closed single-loop orbit, not a circle (radius sd/mean {spread:.2f} > {circle_spread}, "
                      f"whirl/cage {ratio:+.3f})")
    return "synchronous orbit", info


def cage_instability_index(y, z, clearance: float | None = None, floor_fraction: float = 0.05) -> float:
    """Normalised whirl-radius dispersion sigma_r / r_mean of the cage mass centre [1].

    r = sqrt(D_Y^2 + D_Z^2) is the whirl radius about the bearing axis, sigma_r its standard
    deviation and r_mean its mean over the samples given (after the transient).  Ghaisas, Wassgren &
    Sadeghi (2004, "Cage instabilities in cylindrical roller bearings", ASME J. Tribol. 126,
    681-689) judge cage stability by the dispersion of the cage whirl about its mean orbit: a
    steady circular whirl about the bearing axis has a constant radius (index 0), an irregular
    whirl one that varies (index of order 0.3-1).

    Departure (documented in docs/sweeps.md, "Cage-stability maps"): with ``clearance`` given,
    r_mean is floored at ``floor_fraction`` x clearance, so a cage almost at rest on the bearing axis
    (r_mean -> 0, ratio 0/0 of noise) reads as stable instead of a random number; the floor does not
    change the index of any whirl using more than 5 % of the clearance.

    Parameters
    ----------
    y, z : array_like
        Cage mass-centre displacements D_Y, D_Z [m].
    clearance : float, optional
        Guide clearance [m] (for the floor).
    floor_fraction : float
        Floor of r_mean as a fraction of the clearance [1].

    Returns
    -------
    float
        sigma_r / max(r_mean, floor) [1]; NaN with fewer than 2 finite samples.
    """
    y = np.asarray(y, float)
    z = np.asarray(z, float)
    ok = np.isfinite(y) & np.isfinite(z)
    if ok.sum() < 2:
        return float("nan")
    r = np.hypot(y[ok], z[ok])
    den = float(np.mean(r))
    if clearance is not None and math.isfinite(clearance) and clearance > 0:
        den = max(den, floor_fraction * float(clearance))
    if den <= 0:
        return 0.0
    return float(np.std(r) / den)  # [1] dispersion of the whirl radius about its mean
