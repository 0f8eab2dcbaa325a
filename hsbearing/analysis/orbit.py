"""Cage whirl orbit, and the annotation of a dynamic run (slip ratio, whirl, Poincare section, period).

:func:`annotate` adds to a dynamic-run Dataset the cage slip ratio over time,
the scalar summaries (mean slip ratio, whirl amplitude and frequency), the
Poincare section points and the period classification with its confidence.
:func:`summary` returns the scalars a sweep tabulates.

Whirl quantities are computed after the start-up transient (automatic
detection, at least the first 30 % and at most 60 % of the simulated span;
rule in :mod:`hsbearing.analysis.poincare`):

- ``whirl_amplitude``: RMS radius sqrt(D_Y^2 + D_Z^2) of the cage mass centre
  about the bearing axis; ``whirl_radius_max``: its peak value;
- ``whirl_frequency``: the dominant frequency of the complex signal
  (D_Y - mean) + i (D_Z - mean) (Hann window, parabolic peak refinement);
  positive for a forward whirl (in the sense of a positive rotation about X,
  Y towards Z), negative for a backward whirl;
- ``whirl_frequency_ratio``: 2 pi whirl_frequency / mean cage speed (1 for a
  whirl synchronous with the cage rotation).
"""

from __future__ import annotations

import json
import math
from typing import Any

import numpy as np
import xarray as xr

from hsbearing.analysis import poincare as _pc
from hsbearing.analysis.slip import cage_slip_ratio, raceway_control_cage_speed, theoretical_cage_speed
from hsbearing.analysis.spectrum import whirl_frequency  # noqa: F401 - public here as before
from hsbearing.analysis.whirl import cage_instability_index as _instability
from hsbearing.analysis.whirl import classification_detail as _detail
from hsbearing.analysis.whirl import classify_motion as _motion
from hsbearing.results import VARIABLES, register

_trapz = getattr(np, "trapezoid", None) or np.trapz  # numpy < 2 has only trapz

__all__ = ["annotate", "summary", "contact_power_summary", "POWER_SUMMARY", "CLASSIFIER_VERSION", "classified_by_older_rules", "whirl_metrics", "whirl_frequency", "whirl_ratio_note", "REQUIRED",
           "PARKED_MOTION_FRACTION", "PARKED_OFFSET_FRACTION"]

#: A cage is "parked" when its centre, after the transient, moves less than this fraction of the guide
#: clearance (RMS about its mean position) ...
PARKED_MOTION_FRACTION = 0.05
#: ... while that mean position lies at least this fraction of the clearance off the bearing axis.
PARKED_OFFSET_FRACTION = 0.5

#: Version of the classification rules; a stored label made under another version is recomputed by
#: :func:`summary` (so sweeps, studies and maps re-read their archives with the current classifier).
CLASSIFIER_VERSION = "2026-11-26 transverse section + orbit tests"

#: Variables a dynamic-run Dataset must carry for :func:`annotate`.
REQUIRED = ("time", "cage_speed", "cage_center_y", "cage_center_z")

for _n, _d, _u, _l in [
    ("theoretical_cage_speed", (), "rad/s",
     "epicyclic cage speed for rolling without slip omega_c,th = (omega_i (1 - gamma) + omega_o (1 + gamma))/2"),
    ("mean_cage_speed", (), "rad/s", "time-mean cage speed after the transient"),
    ("raceway_control_cage_speed", (), "rad/s",
     "cage speed of outer-raceway-control kinematics at the mean loaded contact angles after the transient (Jones 1959)"),
    ("mean_cage_slip_ratio_raceway_control", (), "1",
     "(raceway_control_cage_speed - mean cage speed) / raceway_control_cage_speed"),
    ("mean_cage_slip_ratio", (), "1", "time-mean cage slip ratio (omega_c,th - omega_c)/omega_c,th after the transient"),
    ("whirl_amplitude", (), "m", "RMS radius of the cage mass-centre orbit about the bearing axis after the transient"),
    ("whirl_radius_max", (), "m", "peak radius of the cage mass-centre orbit about the bearing axis after the transient"),
    ("whirl_frequency", (), "Hz", "dominant whirl frequency of the cage mass centre (> 0 forward, < 0 backward)"),
    ("whirl_frequency_ratio", (), "1", "2 pi whirl_frequency / mean cage speed (1 = synchronous whirl)"),
    ("classification_detail", (), "1",
     "sub-label of the class (sweep/map summaries; attrs of a run): still cage, synchronous whirl, harmonic whirl, "
     "circular whirl, synchronous orbit for '1 period', '' otherwise"),
    ("cage_instability_index", (), "1",
     "normalised whirl-radius dispersion sd(r)/mean(r) of the cage mass centre after the transient "
     "(Ghaisas, Wassgren & Sadeghi 2004; mean floored at 5 % of the guide clearance)"),
    ("poincare_time", ("section",), "s", "time of the Poincare section crossings"),
    ("poincare_y", ("section",), "m", "cage mass-centre displacement D_Y at the Poincare section"),
    ("poincare_vy", ("section",), "m/s", "cage mass-centre velocity V_Y at the Poincare section"),
    # the other scalars of summary() (a sweep summary carries them per point); text labels have units ""
    ("classification", (), "", "cage-motion class of the Poincare section (1 period, k periods, quasi-periodic, "
     "chaos, undetermined; static for a quasi-static state)"),
    ("classification_confidence", (), "1", "confidence of the classification, 0 to 1"),
    ("classification_kind", (), "", "which test decided the class (growth, still cage, section, ...)"),
    ("classification_alternative", (), "", "class of the same run on the other Poincare section"),
    ("poincare_section_kind", (), "", "Poincare section of the classification (transverse or cage_revolution)"),
    ("whirl_cage_lock", (), "", "lock of the cage whirl to the cage rotation, as text ('' when none found)"),
    ("classifier_version", (), "", "version of the classification rules that labelled the run"),
    ("n_poincare_points", (), "1", "number of Poincare section crossings after the transient"),
    ("transient_discarded", (), "s", "initial span of the run left out of the summary (the transient)"),
    ("guide_clearance_used", (), "1", "whirl_radius_max / radial guide clearance of the cage"),
    # what users compare between points of a sweep (summary scalars; contact_power_summary)
    ("min_film_thickness", (), "m", "smallest Hamrock-Dowson minimum film thickness h_min over the inner and outer "
     "contacts and the balls (after the transient of a run)"),
    ("min_film_parameter", (), "1", "smallest film parameter lambda = h_min / composite rms roughness over the inner "
     "and outer contacts and the balls (after the transient of a run)"),
    ("max_contact_pressure", (), "Pa", "largest maximum Hertz pressure p_max over the inner and outer contacts and the "
     "balls (after the transient of a run)"),
]:
    register(_n, _d, _u, _l)

#: the power accounting a summary carries (mean after the transient of a run; the value at the quasi-static state)
POWER_SUMMARY = ("power_loss", "power_loss_race_traction", "power_loss_ehl_rolling", "power_loss_contact_damping",
                 "power_loss_pocket_film", "power_loss_pocket_boundary", "power_loss_guide_land", "power_loss_drag",
                 "power_loss_jet_oil_acceleration", "power_loss_cage_windage",  # quasi-static churning terms
                 "drive_torque")


def _var(name: str, value, dims=None) -> xr.Variable:
    v = VARIABLES[name]
    return xr.Variable(v.dims if dims is None else dims, np.asarray(value, dtype=float),
                       attrs={"units": v.units, "long_name": v.long_name})


def _case_from_attrs(ds):
    text = ds.attrs.get("case_toml")
    if not text:
        return None
    from hsbearing.case import loads_case

    return loads_case(text, source=str(ds.attrs.get("case_source", "<archive case_toml>")))


def whirl_metrics(ds, transient=None) -> dict[str, float]:
    """Whirl amplitude [m], peak radius [m], frequency [Hz] and frequency ratio after the transient.

    ``transient``: see :func:`hsbearing.analysis.poincare.after_transient`.
    """
    t = np.asarray(ds["time"].values, float)
    mask, _ = _pc.after_transient(ds, transient)
    y_all = np.asarray(ds["cage_center_y"].values, float)
    z_all = np.asarray(ds["cage_center_z"].values, float)
    w_all = np.asarray(ds["cage_speed"].values, float)
    mask = mask & np.isfinite(y_all) & np.isfinite(z_all) & np.isfinite(w_all)  # a failed run may end in NaN
    y, z, w = y_all[mask], z_all[mask], w_all[mask]
    out = dict(whirl_amplitude=float("nan"), whirl_radius_max=float("nan"), whirl_frequency=float("nan"),
               whirl_frequency_ratio=float("nan"), mean_cage_speed=float("nan"))
    if mask.sum() == 0:
        return out
    r = np.hypot(y, z)
    ts = t[mask]
    span = ts[-1] - ts[0]
    mean = (lambda a: float(_trapz(a, ts) / span)) if span > 0 else (lambda a: float(np.mean(a)))
    out["whirl_amplitude"] = math.sqrt(max(mean(r**2), 0.0))
    out["whirl_radius_max"] = float(np.max(r))
    out["mean_cage_speed"] = mean(w)
    fw = whirl_frequency(ts, y, z)
    out["whirl_frequency"] = fw
    if np.isfinite(fw) and out["mean_cage_speed"] != 0:
        out["whirl_frequency_ratio"] = 2 * np.pi * fw / out["mean_cage_speed"]
    return out


def whirl_ratio_note(ds, clearance: float | None = None) -> str | None:
    """Why ``whirl_frequency_ratio`` is not defined for this run, or None when it is.

    A cage pressed against its guide land (e.g. radial load + moment) does not whirl: its centre rests
    at an offset and only jitters about it, so the dominant frequency of the (mean-removed) orbit is
    that jitter -- typically the ball-pass frequency Z x cage speed -- not a whirl.  "Parked" here: after
    the transient the centre moves less than :data:`PARKED_MOTION_FRACTION` of the guide clearance
    (RMS about its mean position) while the mean position lies at least :data:`PARKED_OFFSET_FRACTION`
    of the clearance off the axis.  ``clearance`` [m] defaults to ``attrs["guide_clearance"]``.
    """
    c = clearance if clearance is not None else ds.attrs.get("guide_clearance")
    if c is None or not all(v in ds.variables for v in REQUIRED):
        return None
    c = float(c)
    mask, _ = _pc.after_transient(ds)
    y = np.asarray(ds["cage_center_y"].values, float)
    z = np.asarray(ds["cage_center_z"].values, float)
    mask = mask & np.isfinite(y) & np.isfinite(z)
    if not (c > 0 and mask.sum() >= 2):
        return None
    y, z = y[mask], z[mask]
    yc, zc = float(np.mean(y)), float(np.mean(z))
    offset = math.hypot(yc, zc)
    motion = math.sqrt(float(np.mean((y - yc) ** 2 + (z - zc) ** 2)))
    if not (motion < PARKED_MOTION_FRACTION * c and offset >= PARKED_OFFSET_FRACTION * c):
        return None
    text = (f"cage parked: its centre rests {offset * 1e6:.0f} \u00b5m off the axis ({100 * offset / c:.0f} % of the "
            f"{c * 1e6:.0f} \u00b5m guide clearance) and moves only {motion * 1e6:.2g} \u00b5m RMS about that point, so it does not whirl")
    if "whirl_frequency" in ds and "mean_cage_speed" in ds:
        fw, wc = float(ds["whirl_frequency"]), float(ds["mean_cage_speed"])
        if np.isfinite(fw) and np.isfinite(wc) and wc != 0:
            k = abs(2 * np.pi * fw / wc)
            text += f"; the {abs(fw):.4g} Hz peak of that jitter is {k:.2f} x the cage speed"
            nb = ds.sizes.get("ball")
            if nb and abs(k - nb) < 0.05 * nb:
                text += f" (ball pass, Z = {nb})"
    return text


def _jsonable(d):
    """A dict with NaN/inf floats as None and numpy scalars/arrays as plain Python (for a JSON attr)."""
    if isinstance(d, dict):
        return {k: _jsonable(v) for k, v in d.items()}
    if isinstance(d, (list, tuple)):
        return [_jsonable(v) for v in d]
    if isinstance(d, np.ndarray):
        return _jsonable(d.tolist())
    if isinstance(d, (np.floating, float)):
        return float(d) if math.isfinite(d) else None
    if isinstance(d, (np.integer,)):
        return int(d)
    if isinstance(d, np.bool_):
        return bool(d)
    return d


def _lock_text(lock: dict) -> str:
    """One line: is the whirl locked to the cage rotation (whirl-cage phase drift, whirl.whirl_lock)."""
    if not lock or lock.get("locked") is None:
        return "not measured (no cage angle, a still cage, or less than one cage revolution)"
    n = lock["harmonic"]
    drift = f"{lock['rho']:+.4f} +- {lock['rho_sd']:.1e} turn per cage revolution"
    if lock["locked"]:
        return (f"locked {n}:1 to the cage rotation (whirl-cage phase drift {drift}, "
                f"{lock['drift_turns']:.3f} turn over {lock['cage_revolutions']:.0f} cage revolutions)")
    return (f"not locked: whirl at {lock['ratio']:.4f} x the cage speed, whirl-cage phase drifts {drift} "
            f"({lock['drift_turns']:.2f} turn over {lock['cage_revolutions']:.0f} cage revolutions)")


def annotate(ds: xr.Dataset, case=None, *, alpha=None, section: str = _pc.DEFAULT_SECTION,
             transient="auto", **classify_kw) -> xr.Dataset:
    """Add slip ratio, whirl summaries, Poincare section and period classification to a dynamic run.

    Parameters
    ----------
    ds : xarray.Dataset
        A dynamic run with ``time`` [s], ``cage_speed`` [rad/s],
        ``cage_center_y``/``cage_center_z`` [m]; optionally
        ``cage_velocity_y``/``cage_velocity_z`` [m/s] and ``cage_angle`` [rad].  Without the velocities
        (positions only: a measured orbit) they are estimated by a local-polynomial derivative
        (:func:`hsbearing.analysis.derivative.smoothed_velocity`), recorded in
        ``attrs["cage_velocity_source"]``.
    case : hsbearing.case.Case, optional
        The run's case (for the theoretical cage speed and the guide
        clearance); default: re-read from ``ds.attrs["case_toml"]``.
    alpha : float, optional
        Contact angle [rad] for the theoretical cage speed (default: the
        nominal contact angle of the case).
    section : str
        Poincare section, one of :data:`hsbearing.analysis.poincare.SECTIONS` (default ``"transverse"``,
        transverse to the flow; the label under the other section -- the cage-revolution one -- is stored
        beside it as ``attrs["classification_alternative"]``).
    transient : "auto" or float
        Start-up transient to discard: ``"auto"`` (drift detection, between
        30 % and 60 % of the span) or a fixed fraction of the span.
    **classify_kw
        Thresholds passed to :func:`hsbearing.analysis.whirl.classify_motion` /
        :func:`hsbearing.analysis.periods.classify`.

    Returns
    -------
    xarray.Dataset
        A new Dataset (the input is not modified).
    """
    _pc.section_description(section)  # an unknown section name fails before any work
    missing = [v for v in REQUIRED if v not in ds.variables]
    if missing:
        raise ValueError(f"annotate: the Dataset lacks {', '.join(missing)} (needs {', '.join(REQUIRED)})")
    ds = ds.copy()
    if case is None:
        case = _case_from_attrs(ds)
    t = np.asarray(ds["time"].values, float)
    t_discard = _pc.transient_cut(ds, transient)
    ds.attrs["transient_discarded"] = float(t_discard)
    mask, _ = _pc.after_transient(ds)

    # --- cage slip ratio (slip.py; nominal contact angle unless alpha is given)
    if case is not None:
        from hsbearing.models.geometry import derive

        geom = derive(case)
        a = geom.alpha0 if alpha is None else float(alpha)
        w_th = theoretical_cage_speed(geom, case.operating.inner_speed, case.operating.outer_speed, alpha=a)
        slip = cage_slip_ratio(ds["cage_speed"].values, w_th)
        ds["cage_slip_ratio"] = _var("cage_slip_ratio", slip, ("time",))
        ds["theoretical_cage_speed"] = _var("theoretical_cage_speed", w_th)
        ok = mask & np.isfinite(slip)
        ts = t[ok]
        sp = ts[-1] - ts[0] if ts.size > 1 else 0.0
        ms = float(_trapz(slip[ok], ts) / sp) if sp > 0 else float(np.mean(slip[ok])) if ok.any() else float("nan")
        ds["mean_cage_slip_ratio"] = _var("mean_cage_slip_ratio", ms)
        ds.attrs["cage_slip_ratio_definition"] = (
            "(omega_c,th - omega_c)/omega_c,th, omega_c,th = (omega_i (1 - gamma) + omega_o (1 + gamma))/2, "
            "gamma = D cos(alpha)/d_m (Harris & Kotzalas, Ch. 8)")
        ds.attrs["cage_slip_contact_angle"] = float(a)
        if "guide_clearance" not in ds.attrs and math.isfinite(geom.guide_clearance):
            ds.attrs["guide_clearance"] = float(geom.guide_clearance)
        if "pocket_clearance" not in ds.attrs and math.isfinite(geom.pocket_clearance):
            ds.attrs["pocket_clearance"] = float(geom.pocket_clearance)
    elif "cage_slip_ratio" in ds and mask.any():
        s = np.asarray(ds["cage_slip_ratio"].values, float)[mask]
        ds["mean_cage_slip_ratio"] = _var("mean_cage_slip_ratio", float(np.mean(s)))

    # --- whirl orbit
    for k, v in whirl_metrics(ds).items():
        ds[k] = _var(k, v)

    # --- kinematic cross-check: outer-raceway control at the mean loaded contact angles
    if (case is not None and "inner_contact_angle" in ds and "outer_contact_angle" in ds
            and "time" in ds["inner_contact_angle"].dims and mask.any()):
        sel = {"time": np.nonzero(mask)[0]}
        ai = float(ds["inner_contact_angle"].isel(sel).mean())
        ao = float(ds["outer_contact_angle"].isel(sel).mean())
        if np.isfinite(ai) and np.isfinite(ao):
            w_rc = raceway_control_cage_speed(geom, case.operating.inner_speed, case.operating.outer_speed, ai, ao)
            ds["raceway_control_cage_speed"] = _var("raceway_control_cage_speed", w_rc)
            ds["mean_cage_slip_ratio_raceway_control"] = _var(
                "mean_cage_slip_ratio_raceway_control", cage_slip_ratio(float(ds["mean_cage_speed"]), w_rc))

    # --- classification of the motion (whirl.classify_motion: growth, still cage, section, classifier)
    t_m = t[mask]
    y_m = np.asarray(ds["cage_center_y"].values, float)[mask]
    z_m = np.asarray(ds["cage_center_z"].values, float)[mask]
    vy_all, vz_all, v_source = _pc.cage_velocities(ds)
    vy_m, vz_m = vy_all[mask], vz_all[mask]
    phi_m = _pc.cage_rotation_angle(ds)[mask]
    gc = float(ds.attrs.get("guide_clearance", float("nan")))
    gcl = gc if math.isfinite(gc) and gc > 0 else None
    label, conf, det = _motion(t_m, y_m, z_m, vy_m, vz_m, phi_m, clearance=gcl, section=section, **classify_kw)
    tc, pts, defn = det.pop("times"), det.pop("points"), det.pop("section")
    ds = ds.drop_vars([v for v in ("poincare_time", "poincare_y", "poincare_vy") if v in ds.variables])
    ds["poincare_time"] = _var("poincare_time", tc)
    ds["poincare_y"] = _var("poincare_y", pts[:, 0] if len(pts) else np.zeros(0))
    ds["poincare_vy"] = _var("poincare_vy", pts[:, 1] if len(pts) else np.zeros(0))
    # --- the other section side by side (the clock section under the transverse default, and vice versa); the
    # growth and lock tests do not depend on the section: those of the first classification are passed on
    other = "cage_revolution" if section != "cage_revolution" else "transverse"
    try:
        label_o, conf_o, det_o = _motion(t_m, y_m, z_m, vy_m, vz_m, phi_m, clearance=gcl, section=other,
                                         growth=det.get("growth"), lock=det.get("lock"), **classify_kw)
    except Exception as exc:  # noqa: BLE001 - the side-by-side label is a report, never a failure of the run
        label_o, conf_o, det_o = "undetermined", 0.0, {"reason": f"not computed: {exc}"}
    # --- sub-label of the class from the continuous orbit, and the instability indicator
    if det.get("kind") == "still":
        detail, dinfo = "still cage", {"reason": det["reason"]}
    else:
        detail, dinfo = _detail(label, t_m, y_m, z_m, np.asarray(ds["cage_speed"].values, float)[mask], gc)
    ds["cage_instability_index"] = _var("cage_instability_index", _instability(y_m, z_m, gc))
    lock = det.get("lock") or {}
    ds.attrs.update(
        classification=label,
        classifier_version=CLASSIFIER_VERSION,
        classification_confidence=conf,
        classification_reason=det.get("reason", ""),
        classification_kind=det.get("kind", ""),
        classification_detail=detail,
        classification_detail_reason=dinfo.get("reason", ""),
        classification_details=json.dumps(_jsonable(det)),
        classification_alternative_section=other,
        classification_alternative=label_o,
        classification_alternative_confidence=conf_o,
        classification_alternative_reason=det_o.get("reason", ""),
        poincare_section=_pc.section_description(section),
        poincare_section_kind=section,
        poincare_section_definition=json.dumps(_jsonable(defn)),
        whirl_cage_lock=_lock_text(lock),
        cage_velocity_source=v_source,
        transient_discarded=float(t_discard),
        transient_rule=("auto: max(30 % of the span, end of drift of the per-revolution mean radius and cage speed), "
                        "at most 60 %" if transient == "auto" else f"fixed: first {100 * float(transient):g} % of the span"),
    )
    return ds


def _scalar(ds, name):
    if name in ds and ds[name].ndim == 0:
        return float(ds[name].values)
    return float("nan")


def classified_by_older_rules(ds) -> bool:
    """Classified by :func:`annotate` under other rules than :data:`CLASSIFIER_VERSION` (annotate always stores
    the section kind; a label put in the attrs by another producer, e.g. a study's stand-in point function, is
    not annotate's and is kept)."""
    return "poincare_section_kind" in ds.attrs and ds.attrs.get("classifier_version") != CLASSIFIER_VERSION


def _needs_annotation(ds) -> bool:
    """Not classified at all, or classified by :func:`annotate` under older rules."""
    return "classification" not in ds.attrs or classified_by_older_rules(ds)


def _extreme(ds, names, sel, how) -> float:
    vals = []
    for n in names:
        if n in ds:
            v = np.asarray((ds[n].isel(sel) if sel else ds[n]).values, dtype=float).ravel()
            vals.append(v[np.isfinite(v)])
    v = np.concatenate(vals) if vals else np.zeros(0)
    return float(how(v)) if v.size else float("nan")


def contact_power_summary(ds: xr.Dataset, sel: dict | None = None) -> dict[str, float]:
    """What users compare between the points of a sweep, from the variables a result carries.

    ``power_loss``, ``power_loss_<source>`` [W] and ``drive_torque`` [N m] (the time mean over ``sel``, the
    samples after the transient, for a run; the value for a quasi-static state that carries them as scalars);
    ``min_film_thickness`` [m] and ``min_film_parameter`` [-] (the smallest over the inner and outer contacts,
    the balls and ``sel``); ``max_contact_pressure`` [Pa] (the largest).  A quantity the result does not carry
    is left out (not NaN), so a system without it shows no column.
    """
    sel = sel or {}
    out: dict[str, float] = {}
    for name in POWER_SUMMARY:
        if name in ds:
            v = ds[name].isel({k: i for k, i in sel.items() if k in ds[name].dims}) if sel else ds[name]
            out[name] = float(np.nanmean(np.asarray(v.values, dtype=float))) if v.size else float("nan")
    for key, names, how in (
            ("min_film_thickness", ("inner_film_thickness_minimum", "outer_film_thickness_minimum"), np.min),
            ("min_film_parameter", ("inner_film_parameter", "outer_film_parameter"), np.min),
            ("max_contact_pressure", ("inner_contact_pressure", "outer_contact_pressure"), np.max)):
        if any(n in ds for n in names):
            out[key] = _extreme(ds, names, {k: i for k, i in sel.items() if k in ds.dims}, how)
    return out


def summary(ds: xr.Dataset, case=None) -> dict[str, Any]:
    """Scalars of one run for a sweep table.

    Keys: ``status``, ``classification``, ``classification_confidence``,
    ``mean_cage_slip_ratio``, ``mean_cage_speed`` [rad/s], ``whirl_amplitude``
    [m], ``whirl_radius_max`` [m], ``whirl_frequency`` [Hz],
    ``whirl_frequency_ratio``, ``mean_inner_contact_load`` and
    ``mean_outer_contact_load`` [N] (mean over balls, and over time after the
    transient), ``max_inner_contact_load``/``max_outer_contact_load`` [N],
    ``n_poincare_points``.  A dynamic run that was not annotated is annotated
    first (on a copy).  A quasi-static Dataset (no ``time``) gives the loads
    and ``classification = "static"``.
    """
    out: dict[str, Any] = {"status": ds.attrs.get("status", "unknown")}
    dynamic = "time" in ds.dims
    if dynamic and all(v in ds.variables for v in REQUIRED) and _needs_annotation(ds):
        ds = annotate(ds, case)
    if dynamic:
        mask, _ = _pc.after_transient(ds)
        sel = {"time": np.nonzero(mask)[0]}
    else:
        sel = {}
    out["classification"] = ds.attrs.get("classification", "static" if not dynamic else "undetermined")
    out["classification_confidence"] = float(ds.attrs.get("classification_confidence", float("nan")))
    out["classification_detail"] = str(ds.attrs.get("classification_detail", ""))
    out["classification_kind"] = str(ds.attrs.get("classification_kind", ""))
    out["poincare_section_kind"] = str(ds.attrs.get("poincare_section_kind", ""))
    out["classification_alternative"] = str(ds.attrs.get("classification_alternative", ""))
    out["whirl_cage_lock"] = str(ds.attrs.get("whirl_cage_lock", ""))
    out["classifier_version"] = str(ds.attrs.get("classifier_version", ""))
    for name in ("cage_instability_index", "mean_cage_slip_ratio", "mean_cage_slip_ratio_raceway_control", "mean_cage_speed",
                 "whirl_amplitude", "whirl_radius_max", "whirl_frequency", "whirl_frequency_ratio"):
        out[name] = _scalar(ds, name)
    if not dynamic and "cage_speed" in ds:
        out["mean_cage_speed"] = float(np.mean(ds["cage_speed"].values))
    for side in ("inner", "outer"):
        name = f"{side}_contact_load"
        if name in ds:
            q = ds[name]
            if sel and "time" in q.dims:
                q = q.isel(sel)
            elif "time_decimated" in q.dims:  # a kept archive (keep="answer"): the decimated history after the transient
                td = np.asarray(ds["time_decimated"].values, float)
                t_all = np.asarray(ds["time"].values, float) if "time" in ds.dims else td
                cut = t_all[0] + float(ds.attrs.get("transient_discarded", 0.0)) if t_all.size else 0.0
                q = q.isel(time_decimated=np.nonzero(td >= cut)[0])
            out[f"mean_{name}"] = float(q.mean())
            out[f"max_{name}"] = float(q.max())
        else:
            out[f"mean_{name}"] = out[f"max_{name}"] = float("nan")
    out.update(contact_power_summary(ds, sel))
    out["n_poincare_points"] = int(ds["poincare_y"].size) if "poincare_y" in ds else 0
    out["transient_discarded"] = float(ds.attrs.get("transient_discarded", float("nan")))
    gc = ds.attrs.get("guide_clearance")
    gc = float(gc) if gc is not None else float("nan")
    out["guide_clearance_used"] = out["whirl_radius_max"] / gc if np.isfinite(gc) and gc > 0 else float("nan")
    # every other scalar result the model stored (e.g. the gyro bearing's sfmc, sfmo, rfmc)
    for name, var in ds.data_vars.items():
        if var.ndim == 0 and name not in out and var.dtype.kind in "fiu":
            out[name] = float(var.values)
    return out
