"""Extend a dynamic run whose cage-motion label is "undetermined" until it is determined or a budget is spent.

``hsbearing run --extend [--max-duration T]`` (opt-in).  The run goes on from its last state
(:func:`hsbearing.systems.angular_contact.dynamics.continue_run`) in steps; each step is re-classified over the
whole run (the transient rule of :func:`hsbearing.analysis.annotate` applies to the longer run; a whirl that was
growing is read on its saturated part only, the growth cut off where it is measured to end and at least
:data:`SATURATED_REVOLUTIONS` cage revolutions after it, :func:`annotate_saturated`).  The step is what the
undetermined label says it needs:

- a growing or decaying whirl: one e-folding time 1/|sigma| of its measured growth rate (the radius changes by a
  factor e, so the next label sees either the saturated orbit or a clearly continuing growth);
- a drifting arc of section points: the time the classifier estimates to close one turn (``run_longer_s``);
- a whirl that grew, read on its saturated part (:func:`annotate_saturated`) that is still too short or still
  changing: the time that part still needs (``run_longer_s``);
- anything else (an irregular section, too few points): half the current simulated time;

bounded below by :data:`MIN_STEP_FRACTION` of the current simulated time and above by what the budget leaves.
It stops when the label is no longer "undetermined" ("determined"), when the stop rule's convergence holds on the
extended run (``converge=True``, the maps and studies: an undetermined answer that no longer moves, "converged"),
when the budget ``max_duration`` of total simulated time is reached ("budget"), or after :data:`MAX_EXTENSIONS`
steps ("steps").  Only a run that asks for it is extended (:func:`extension_wanted`): undetermined, not ended by
the stop rule as converged, and with an estimate of the time it needs (a growth rate, the time to close a drifting
arc, too few section points, or a reason that says "run longer").  The archive records every extension
(``attrs["extensions"]``, JSON: from/to [s], the label and reason before, the growth rate when measured), why it
stopped (``attrs["extension_stop_reason"]``) and, for a growing whirl, the last growth rate measured
(``extension_growth_rate`` [1/s]) and the saturated orbit when it saturated within the budget
(``extension_saturated_orbit``).

``hsbearing map`` and ``hsbearing study`` extend every point in its worker, before the archive is reduced to what
it keeps (:func:`hsbearing.workflows.sweeps.points.compute_point`), with :data:`WORKFLOW_BUDGET_FACTOR` times the
point's duration as the default budget.

**Linear-regime fast-forward** (maps and studies, ``fast_forward=True``; not ``run --extend``): a growing whirl
whose amplitude is still far below the guide clearance is in the linear regime of its Hopf bifurcation (the
Stuart-Landau amplitude equation dA/dt = sigma A - l |A|^2 A, Landau 1944, Stuart 1960: for |A| << sqrt(sigma/l) the
cubic term is negligible), where the motion from the state with the whirl deviation scaled by k equals the motion
ln(k)/sigma later.  :func:`plan_fast_forward` scales the cage centre's deviation from its orbit centre (position and
velocity, ``y_c, z_c, ydot_c, zdot_c`` of ``final_state``) so that the whirl amplitude becomes
:data:`FAST_FORWARD_FRACTION` of the radial guide clearance, once per run, when the growth is monotone and the scale
is at least :data:`FAST_FORWARD_MIN_FACTOR`.  The time axis of the archive then runs on: the samples after the jump
are ln(k)/sigma behind the physical time of an unscaled start (recorded in ``attrs["fast_forward"]``), and the run
is classified on the part after the jump only (the transient rule applied to that part,
:func:`annotate_after_fast_forward`).
"""

from __future__ import annotations

import json
import math

from hsbearing.analysis.stoprule import NEVER_STOP_KINDS, STOP_DEFAULTS
from hsbearing.results import register

__all__ = ["extend_until_determined", "next_step", "plan_fast_forward", "apply_fast_forward",
           "annotate_after_fast_forward", "annotate_saturated", "SATURATED_REVOLUTIONS", "twin_fast_forward", "FAST_FORWARD_FRACTION", "FAST_FORWARD_TWIN_TIME", "FAST_FORWARD_TWIN_MAX", "FAST_FORWARD_MIN_FACTOR", "extension_wanted", "extension_summary", "MIN_STEP_FRACTION",
           "MAX_EXTENSIONS", "DEFAULT_BUDGET_FACTOR", "WORKFLOW_BUDGET_FACTOR", "ESTIMATE_KINDS"]

#: A step is at least this fraction of the simulated time so far.
MIN_STEP_FRACTION = 0.25
#: At most this many extensions.
MAX_EXTENSIONS = 8
#: Default budget of ``--max-duration``: this many times the run's own duration.
DEFAULT_BUDGET_FACTOR = 3.0
#: Default budget of a map or study point (``hsbearing map`` / ``study``): this many times the point's duration
#: (docs/sweeps.md, "Extend until determined": fast-forwarded at ~1.2 s to 0.1 x the clearance, the growing whirls of
#: the load x temperature map at 1-1.6/s are read on their saturated orbit by 4.0-6.8 s; the slowest, 0.72/s, would
#: need 9.3 s: a compromise with the 2 x wall-time target of the map).
WORKFLOW_BUDGET_FACTOR = 6.0
#: Fast-forward target: the whirl amplitude (RMS radius about the orbit centre) after the scaling, as a fraction of
#: the radial guide clearance.  Why 0.1: in the map cells whose whirls saturated naturally (docs/sweeps.md) the
#: amplitude grew by a constant factor per 0.2 s (within 2 %) up to 13-17 % of the clearance; the non-linearity of
#: the guide-land film ~ 1/(1 - e^2) is 1 % at e = 0.1.
FAST_FORWARD_FRACTION = 0.1
#: Fast-forward only when it scales the whirl by at least this factor (otherwise the run simply goes on).
FAST_FORWARD_MIN_FACTOR = 2.0
#: Names of the cage-centre states scaled by the fast-forward (positions, then velocities).
FAST_FORWARD_STATES = (("y_c", "z_c"), ("ydot_c", "zdot_c"))
#: Undetermined kinds whose classifier details carry an estimate of the time the run still needs.
ESTIMATE_KINDS = ("growing", "decaying", "drifting-arc", "too-few-points")

# what a sweep, map or study table carries of an extension (one value per point)
register("simulated_time", (), "s", "simulated time of the run, extensions included")
register("extension_count", (), "1", "number of extensions of a run that was undetermined at its duration")
register("extension_stop_reason", (), "1", "why the extension of an undetermined run stopped (determined, "
         "converged, budget, steps, failed) or why it was not extended")
register("extension_growth_rate", (), "1/s", "growth rate of the cage whirl measured before the last extension "
         "(NaN when none was measured)")


def _details(ds) -> dict:
    try:
        return json.loads(ds.attrs.get("classification_details", "{}")) or {}
    except (TypeError, ValueError):
        return {}


def next_step(ds) -> tuple[float, str]:
    """The extension [s] an undetermined run asks for, and why (see the module text)."""
    t = ds["time"].values
    span = float(t[-1] - t[0]) if t.size > 1 else 0.0
    det = _details(ds)
    g = det.get("growth") or {}
    kind = det.get("kind", "")
    sigma = g.get("sigma")
    if kind in ("growing", "decaying") and sigma not in (None, 0) and math.isfinite(float(sigma)):
        step, why = 1.0 / abs(float(sigma)), f"{kind} whirl, growth rate {float(sigma):.3g} 1/s: one e-folding time"
    elif det.get("run_longer_s") is not None and math.isfinite(float(det["run_longer_s"])):
        step = float(det["run_longer_s"])
        why = ("drifting arc: the time to close one turn of the section" if kind == "drifting-arc" else
               f"{kind or 'undetermined'} after a growth: the time its saturated orbit still needs to be read")
    else:
        step, why = 0.5 * span, f"{kind or 'undetermined'} section: half the simulated time"
    floor = MIN_STEP_FRACTION * span
    if step < floor:
        step, why = floor, why + f" (raised to {MIN_STEP_FRACTION:g} of the simulated time)"
    return step, why


def _finite(x) -> bool:
    try:
        return x is not None and math.isfinite(float(x))
    except (TypeError, ValueError):
        return False


def extension_wanted(ds) -> tuple[bool, str]:
    """Whether an annotated run asks to be extended, and why (not).

    Yes when its label is "undetermined", the stop rule did not end it as converged (``stopped_at`` NaN or
    absent) and it carries an estimate of the time it needs: a kind of :data:`ESTIMATE_KINDS` (growth rate,
    time to close a drifting arc, too few section points) or a reason that says "run longer".
    """
    label = ds.attrs.get("classification")
    if label is None:
        return False, "not classified"
    if label != "undetermined":
        return False, f"determined: {label} (no extension needed)"
    if _finite(ds.attrs.get("stopped_at")):
        return False, ("not extended: the stop rule ended the run as converged "
                       f"({ds.attrs.get('stop_reason', '')})")
    kind = _details(ds).get("kind") or str(ds.attrs.get("classification_kind", ""))
    if kind in ESTIMATE_KINDS or "run longer" in str(ds.attrs.get("classification_reason", "")):
        return True, f"undetermined ({kind or 'no kind'}) with an estimate of the time it needs"
    return False, f"not extended: undetermined ({kind or 'no kind'}) without an estimate of the time it needs"


#: default of :func:`annotate_saturated`'s ``case``: read the case from the run's archive text
_FROM_ARCHIVE = object()


def _case_of(ds):
    """The run's case, read once from its archive text (None when it has none: a synthetic run)."""
    if "case_toml" not in ds.attrs:
        return None
    from hsbearing.case import loads_case

    return loads_case(ds.attrs["case_toml"], "extension")


def _converged(ds, case=None) -> tuple[bool, str]:
    """The stop rule's convergence on the whole (extended) run (:func:`hsbearing.analysis.stoprule.converged`)."""
    from hsbearing.analysis import stoprule

    try:
        stop, why, _ = stoprule.converged(ds, case)
    except (ValueError, KeyError, IndexError) as exc:  # a run the rule cannot read: not converged
        return False, f"stop rule not evaluated: {type(exc).__name__}: {exc}"
    return bool(stop), why


def _saturated_orbit(ds) -> str:
    """The orbit a growing whirl saturated on (after the transient of the extended run), in words."""
    def val(name):
        return float(ds[name].values) if name in ds and ds[name].ndim == 0 else float("nan")

    amp, peak, ratio = val("whirl_amplitude"), val("whirl_radius_max"), val("whirl_frequency_ratio")
    t = ds["time"].values
    cut = float(ds.attrs.get("transient_discarded", float("nan")))
    return (f"saturated orbit over {float(t[0]) + cut:.4g}-{float(t[-1]):.4g} s: whirl amplitude (RMS radius) "
            f"{amp * 1e6:.4g} um, peak radius {peak * 1e6:.4g} um, whirl/cage frequency ratio {ratio:.4g}")


def _end_window(ds, sigma: float):
    """Samples of the last window over which the whirl amplitude is measured: 0.1/sigma (the radius changes by
    10 % in it), at most a tenth of the run."""
    t = ds["time"].values
    span = float(t[-1] - t[0])
    w = min(0.1 / sigma, 0.1 * span)
    return t >= t[-1] - w, w


def plan_fast_forward(ds, fraction: float = FAST_FORWARD_FRACTION) -> tuple[dict | None, str]:
    """The linear-regime fast-forward of a growing whirl (module text), or None and why not.

    Conditions: label "undetermined" of kind "growing" with a positive growth rate sigma and a monotone growth
    (classifier details), a guide clearance ``c`` (``attrs["guide_clearance"]``), a stored state with the cage
    centre (:data:`FAST_FORWARD_STATES`), and the amplitude ``A`` (RMS radius about the orbit centre over the last
    0.1/sigma) at most ``fraction * c / FAST_FORWARD_MIN_FACTOR``.  The plan: the scale ``k = fraction * c / A``,
    the orbit centre and mean velocity it scales about, and the equivalent time ln(k)/sigma it skips.
    """
    import numpy as np

    if ds.attrs.get("classification") != "undetermined":
        return None, "determined"
    det = _details(ds)
    g = det.get("growth") or {}
    sigma = g.get("sigma")
    if det.get("kind") != "growing" or not _finite(sigma) or float(sigma) <= 0:
        return None, f"not a growing whirl (kind {det.get('kind')!r})"
    if not g.get("monotone", False):
        return None, "growth not monotone (not a clean exponential)"
    sigma = float(sigma)
    c = ds.attrs.get("guide_clearance")
    if not _finite(c) or float(c) <= 0:
        return None, "no guide clearance"
    if "final_state" not in ds or "state" not in ds.coords:
        return None, "no final state"
    names = [str(n) for n in ds["state"].values]
    if not all(n in names for pair in FAST_FORWARD_STATES for n in pair):
        return None, "the state has no cage centre"
    m, w = _end_window(ds, sigma)
    y, z = ds["cage_center_y"].values[m], ds["cage_center_z"].values[m]
    vy, vz = ds["cage_velocity_y"].values[m], ds["cage_velocity_z"].values[m]
    centre = (float(np.mean(y)), float(np.mean(z)))
    vmean = (float(np.mean(vy)), float(np.mean(vz)))
    amp = float(np.sqrt(np.mean((y - centre[0]) ** 2 + (z - centre[1]) ** 2)))
    target = fraction * float(c)
    if not amp > 0:
        return None, "no whirl to scale"
    k = target / amp
    if k < FAST_FORWARD_MIN_FACTOR:
        return None, (f"amplitude {amp * 1e6:.3g} um is within a factor {FAST_FORWARD_MIN_FACTOR:g} of the target "
                      f"{target * 1e6:.3g} um ({fraction:g} x the guide clearance): no fast-forward")
    return {"at": float(ds["time"].values[-1]), "sigma": sigma, "amplitude_before": amp, "amplitude_after": target,
            "factor": k, "equivalent_time": math.log(k) / sigma, "window": w, "orbit_centre": centre,
            "mean_velocity": vmean, "fraction_of_clearance": fraction, "guide_clearance": float(c),
            "states": [n for pair in FAST_FORWARD_STATES for n in pair],
            "why": (f"growing whirl in the linear regime: amplitude {amp * 1e6:.3g} um = {amp / float(c):.2g} x the "
                    f"guide clearance, growth rate {sigma:.3g} 1/s; cage-centre deviation scaled by {k:.3g} to "
                    f"{fraction:g} x the clearance, equivalent to {math.log(k) / sigma:.3g} s of growth")}, "planned"


def apply_fast_forward(ds, plan: dict):
    """``ds`` with its ``final_state`` cage-centre deviation from the orbit centre (positions) and from the mean
    velocity (velocities) scaled by ``plan["factor"]`` (:func:`plan_fast_forward`)."""
    import numpy as np

    names = [str(n) for n in ds["state"].values]
    y = np.array(ds["final_state"].values, dtype=float)
    k = plan["factor"]
    for (a, b), ref in zip(FAST_FORWARD_STATES, (plan["orbit_centre"], plan["mean_velocity"]), strict=True):
        for n, r in ((a, ref[0]), (b, ref[1])):
            i = names.index(n)
            y[i] = r + k * (y[i] - r)
    out = ds.copy()
    out["final_state"] = (ds["final_state"].dims, y)
    out["final_state"].attrs = dict(ds["final_state"].attrs)
    return out


#: Time [s] the run and its kicked twin are continued before their difference is taken (the fast modes the kick
#: excites decay in 2-5 ms in the map cells: measured, docs/sweeps.md).
FAST_FORWARD_TWIN_TIME = 0.02
#: The run and its twin are continued in steps of FAST_FORWARD_TWIN_TIME until the RMS of their cage-centre
#: difference over the last half step exceeds that over the half step before (it grows: what is left is the growing mode),
#: at most this long [s] (no fast-forward otherwise).  In hot oil the kick's decaying motions last longer than 20 ms
#: (180 degC/4000 N: a single 20 ms step left them dominant and the jump gained nothing).
FAST_FORWARD_TWIN_MAX = 0.2


def _rhs_evals(ds) -> int:
    try:
        return int(ds.attrs.get("solver_rhs_evals", 0))
    except (TypeError, ValueError):
        return 0


def twin_fast_forward(ds, plan: dict, continue_fn, tau: float = FAST_FORWARD_TWIN_TIME):
    """The fast-forward along the growing mode of the whole state, found from a kicked twin.

    The run ``a`` and a twin ``b`` whose cage-centre deviation was scaled (:func:`apply_fast_forward`) are both
    continued in steps ``tau`` until their difference grows (at most :data:`FAST_FORWARD_TWIN_MAX`); the kick's components on the decaying modes die out, so the difference of the final states
    b - a lies along the growing (unstable) mode of the whole state -- balls, cage, ring -- not only the cage centre
    (a cage-centre kick alone projects by ~1 % on it and decays back within milliseconds).  The new final state is
    a + gamma (b - a), gamma = (target - A_a) / |b - a|_cage, with |b - a|_cage the RMS of the difference of the two
    cage-centre orbits over the last tau/2 and A_a the amplitude of ``a`` there.  Returns ``a`` (the run continued
    by ``tau``) with that final state, and the record (the plan with the twin's numbers).
    """
    import numpy as np

    a, b = ds, apply_fast_forward(ds, plan)
    cy, cz = plan["orbit_centre"]

    def rms(x, y, m):
        return float(np.sqrt(np.mean(x[m] ** 2 + y[m] ** 2)))

    twin_time = 0.0
    while True:  # until the difference grows again: the kick's decaying motions have died out
        a, b = continue_fn(a, tau), continue_fn(b, tau)
        twin_time += tau
        ta, tb = a["time"].values, b["time"].values
        if ta.size != tb.size or not np.allclose(ta, tb):
            raise ValueError("the twin continuation is not on the run's time grid")
        m = ta >= ta[-1] - 0.5 * tau
        m_prev = (ta >= ta[-1] - tau) & ~m
        dy = b["cage_center_y"].values - a["cage_center_y"].values
        dz = b["cage_center_z"].values - a["cage_center_z"].values
        d_amp, d_prev = rms(dy, dz, m), rms(dy, dz, m_prev)
        if d_amp > d_prev or twin_time >= FAST_FORWARD_TWIN_MAX - 1e-12:
            break
    if d_amp <= d_prev:
        raise ValueError(f"the difference of the run and its twin still decays after {twin_time:g} s")
    amp_a = rms(a["cage_center_y"].values - cy, a["cage_center_z"].values - cz, m)
    target = plan["amplitude_after"]
    if not d_amp > 0 or amp_a >= target:
        raise ValueError("the twin did not separate from the run")
    gamma = (target - amp_a) / d_amp
    ya, yb = np.asarray(a["final_state"].values, float), np.asarray(b["final_state"].values, float)
    y = ya + gamma * (yb - ya)
    names = [str(n) for n in a["state"].values]
    r_new = math.hypot(y[names.index("y_c")] - cy, y[names.index("z_c")] - cz)
    out = a.copy()
    out["final_state"] = (a["final_state"].dims, y)
    out["final_state"].attrs = dict(a["final_state"].attrs)
    rec = dict(plan)
    k = target / amp_a
    rec.update(at=float(ta[-1]), amplitude_before=amp_a, factor=k, equivalent_time=math.log(k) / plan["sigma"],
               twin_time=twin_time, twin_kick=plan["factor"], twin_difference_amplitude=d_amp, gamma=gamma,
               radius_after=r_new, states="all (along b - a)",
               twin_rhs_evals=_rhs_evals(b) - _rhs_evals(ds),
               why=(f"growing whirl in the linear regime: amplitude {amp_a * 1e6:.3g} um = {amp_a / plan['guide_clearance']:.2g} x "
                    f"the guide clearance, growth rate {plan['sigma']:.3g} 1/s; the whole state moved along the growing "
                    f"mode (a twin with the cage-centre deviation scaled by {plan['factor']:.3g}, both continued "
                    f"{twin_time:g} s; {gamma:.3g} x their difference added) to {plan['fraction_of_clearance']:g} x the "
                    f"clearance, equivalent to {math.log(k) / plan['sigma']:.3g} s of growth"))
    return out, rec


#: The classification of a whirl that grew to saturation keeps at least this many complete cage revolutions after
#: its growth (:func:`annotate_saturated`): the stop rule's ``min_points`` (an aperiodic section needs 40 points to
#: be read at all; the whirls of the map run at 0.95-1.0 x the cage speed, one transverse section point a loop).
SATURATED_REVOLUTIONS = int(STOP_DEFAULTS["min_points"])


def _revolution_time(ds) -> float:
    """Duration [s] of one cage revolution at the run's last mean cage speed (NaN when the cage stands still)."""
    import numpy as np

    w = np.asarray(ds["cage_speed"].values, float)
    t = ds["time"].values
    m = t >= t[-1] - 0.1 * float(t[-1] - t[0])
    wm = abs(float(np.nanmean(w[m]))) if m.any() else float("nan")
    return 2.0 * math.pi / wm if wm > 0 else float("nan")


def _step_after_fast_forward(plan: dict, ds=None) -> float:
    """The extension after a fast-forward: the growth from the target to saturation, (ln(1/fraction) + 1.2)/sigma
    (the 1.2/sigma: the approach to within 1 % of the saturated radius of the Stuart-Landau whirl, from 0.2 to 0.99
    of it in 3.5/sigma; 0.5/sigma in the map cell 27 degC/2000 N, 18 -> 152 um in 1.5 s at 1.84/s), plus
    :data:`SATURATED_REVOLUTIONS` cage revolutions of the saturated orbit to classify.  The classification cuts
    the growth off where it ends (:func:`annotate_saturated`, measured, not a fixed fraction of the run).  Measured
    on the nine fast-forwarded cells of the load x temperature map (docs/sweeps.md): the whirl is within 2 % of its
    saturated amplitude 2.6-2.9/sigma after the jump, 0.6-0.9/sigma before this estimate.  Without ``ds`` (no cage
    speed known) the classification part is the growth time itself."""
    sat = (math.log(1.0 / plan["fraction_of_clearance"]) + 1.2) / plan["sigma"]
    rev = _revolution_time(ds) if ds is not None else float("nan")
    return sat + (SATURATED_REVOLUTIONS * rev if math.isfinite(rev) else sat)


def annotate_saturated(ds, t_from: float, case=_FROM_ARCHIVE):
    """Re-classify ``ds``, a run whose whirl grew from ``t_from`` [s] on (after a fast-forward: the jump; a whirl
    that grew naturally: the run's start), on its saturated part only: the part before ``t_from`` plus the growth
    after it are discarded, the growth's end measured by the drift detection
    (:func:`hsbearing.analysis.poincare.saturation_cut`: at least 30 % of that part, no 60 % cap).

    The saturated orbit is read on at least :data:`SATURATED_REVOLUTIONS` cage revolutions, and only when it is
    saturated: the whirl amplitude (RMS radius about the orbit centre) of the two halves of what is read agrees to
    the stop rule's tolerance (``amplitude_rtol`` or ``amplitude_atol_clearance`` of the guide clearance,
    :data:`hsbearing.analysis.stoprule.STOP_DEFAULTS`).  When fewer revolutions follow the growth's end, the run is
    classified on its last :data:`SATURATED_REVOLUTIONS` revolutions (the growth's tail included).  A label that
    says the whirl still moves stands ("undetermined", with its growth rate); a determined label on a part that is
    too short or not stationary is not accepted yet: "undetermined" of kind "too-few-points" (with the time the
    missing revolutions take as ``run_longer_s``) or "growing"/"decaying" (with the growth rate between the two
    halves), the label it would have had kept as ``provisional_label`` in the details.  ``case``: the run's case
    when the caller has it (an extension loop reads it once); by default it is read from the archive's text."""
    from hsbearing.analysis import annotate
    from hsbearing.analysis.poincare import saturation_cut

    t = ds["time"].values
    span = float(t[-1] - t[0])
    after = ds.isel(time=t >= t_from)
    cut_after, kept = saturation_cut(after)
    if case is _FROM_ARCHIVE:
        case = _case_of(ds)
    kw = {"section": case.simulation.section} if case is not None else {}
    where = "the fast-forward" if t_from > float(t[0]) else "the start"
    rev = _revolution_time(ds)
    short = kept < SATURATED_REVOLUTIONS and math.isfinite(rev)
    cut = (t_from - float(t[0])) + cut_after
    if short:  # the last SATURATED_REVOLUTIONS revolutions (or all that follow t_from)
        cut = max(t_from - float(t[0]), span - SATURATED_REVOLUTIONS * rev)
    out = annotate(ds, case, transient=min(max(cut, 0.0) / span, 0.99), **kw)
    out.attrs["transient_rule"] = (f"a whirl that grew from {where} at t = {t_from:.6g} s: the part before it and the "
                                   "growth after it to its measured end (drift detection, at least 30 % of that "
                                   f"part), at least {SATURATED_REVOLUTIONS} cage revolutions")
    if out.attrs.get("classification") == "undetermined":
        return out
    det = _details(out)
    provisional = out.attrs["classification"]
    if short:
        need = (SATURATED_REVOLUTIONS - kept) * rev
        det.update(kind="too-few-points", run_longer_s=need, provisional_label=provisional,
                   reason=(f"the whirl grew until t = {t_from + cut_after:.6g} s (measured end of its growth); {kept} "
                           f"of the {SATURATED_REVOLUTIONS} cage revolutions of its saturated orbit so far (on the "
                           f"last {SATURATED_REVOLUTIONS}, the growth's tail included: {provisional}); run longer "
                           f"{need:.3g} s"))
    else:
        a1, a2, half = _half_amplitudes(out)
        c = out.attrs.get("guide_clearance")
        tol = max(STOP_DEFAULTS["amplitude_rtol"] * a2,
                  STOP_DEFAULTS["amplitude_atol_clearance"] * float(c) if _finite(c) else 0.0)
        if not abs(a2 - a1) > tol:
            return out
        rate = math.log(a2 / a1) / half if a1 > 0 and a2 > 0 else float("nan")
        kind = "growing" if a2 > a1 else "decaying"
        # the step: as long again as the part read (the approach to saturation is slower than the linear growth
        # near its end: 1/rate would overshoot), at least the revolutions a reading needs
        det.update(kind=kind, provisional_label=provisional, growth={"sigma": None, "amplitude_rate": rate},
                   run_longer_s=max(2.0 * half, SATURATED_REVOLUTIONS * rev if math.isfinite(rev) else 0.0),
                   reason=(f"the whirl amplitude still changes after the measured end of its growth "
                           f"(t = {t_from + cut_after:.6g} s): {a1 * 1e6:.4g} -> {a2 * 1e6:.4g} um over the two "
                           f"halves of the part read (tolerance {tol * 1e6:.3g} um; on it: {provisional}); run longer"))
    out.attrs.update(classification="undetermined", classification_confidence=0.0,
                     classification_kind=det["kind"], classification_reason=det["reason"],
                     classification_details=json.dumps(det))
    return out


def _half_amplitudes(ds) -> tuple[float, float, float]:
    """Whirl amplitude (RMS radius about the common orbit centre) of the two halves of the classified part of
    ``ds`` (after ``attrs["transient_discarded"]``) [m], and the time between the halves' centres [s]."""
    import numpy as np

    t = ds["time"].values
    m = t >= t[0] + float(ds.attrs.get("transient_discarded", 0.0)) * (1 - 1e-12)
    tt, y, z = t[m], ds["cage_center_y"].values[m], ds["cage_center_z"].values[m]
    r2 = (y - y.mean()) ** 2 + (z - z.mean()) ** 2
    h = tt < tt[0] + 0.5 * (tt[-1] - tt[0])
    return float(np.sqrt(r2[h].mean())), float(np.sqrt(r2[~h].mean())), 0.5 * float(tt[-1] - tt[0])


def annotate_after_fast_forward(ds, t_jump: float):
    """Re-classify ``ds`` on its part after the fast-forward at ``t_jump`` [s] only (:func:`annotate_saturated`;
    the samples before the jump are on another time base)."""
    return annotate_saturated(ds, t_jump)


def extend_until_determined(ds, max_duration: float, *, continue_fn=None, progress: bool = False,
                            converge: bool = False, keep_on_failure: bool = False, fast_forward: bool = False):
    """Continue ``ds`` (an annotated dynamic run) while it is "undetermined", up to ``max_duration`` [s] in all.

    ``continue_fn(ds, duration) -> ds``: the continuation (default
    :func:`hsbearing.systems.angular_contact.dynamics.continue_run`; tests pass a synthetic one).  Returns the
    extended, re-annotated run with ``attrs["extensions"]``, ``attrs["extension_stop_reason"]``,
    ``attrs["extension_max_duration"]``, ``attrs["extension_growth_rate"]`` and, for a growing whirl that became
    determined, ``attrs["extension_saturated_orbit"]``.  A run that does not ask for an extension
    (:func:`extension_wanted`) is returned with none (its stop reason says why).  ``converge``: also stop when the
    stop rule's convergence holds on the extended run.  A failure of a continuation (``SolverError``)
    propagates with its partial run, or with ``keep_on_failure`` ends the extension, keeping the run as it was
    before the failed step (stop reason "failed: ...").  ``fast_forward``: the linear-regime fast-forward of a
    growing whirl (module text; at most once per run, recorded in ``attrs["fast_forward"]``, JSON).
    """
    from hsbearing.errors import SolverError

    if continue_fn is None:
        from hsbearing.systems.angular_contact.dynamics import continue_run

        def continue_fn(d, duration):
            return continue_run(d, duration, progress=progress, source="--extend")

    steps: list[dict] = []
    t0 = float(ds["time"].values[0])
    reason = ""
    wanted, why_not = extension_wanted(ds)
    if not wanted and ds.attrs.get("classification", "undetermined") == "undetermined":
        reason = why_not
    case = _case_of(ds) if wanted else None  # read once: the stop rule and the saturated reading use it
    jump = None
    growing_from = None
    ff_note = ""
    while not reason:
        label = ds.attrs.get("classification", "undetermined")
        t_end = float(ds["time"].values[-1])
        if label != "undetermined":
            reason = f"determined: {label}" + (f" after {len(steps)} extension(s)" if steps else " (no extension needed)")
            break
        if steps and converge and _details(ds).get("kind") not in NEVER_STOP_KINDS:  # the rule never stops on those
            stop, why = _converged(ds, case)
            if stop:
                reason = f"converged (stop rule) after {len(steps)} extension(s), still undetermined: {why}"
                break
        left = max_duration - (t_end - t0)
        if left <= 1e-9 * max(max_duration, 1.0):
            reason = (f"budget: {max_duration:.6g} s of simulated time reached, still undetermined "
                      f"({ds.attrs.get('classification_reason', '')})")
            break
        if len(steps) >= MAX_EXTENSIONS:
            reason = f"steps: {MAX_EXTENSIONS} extensions made, still undetermined"
            break
        step, why = next_step(ds)
        if growing_from is None and _details(ds).get("kind") == "growing":
            growing_from = t0  # classified from now on without its growth (annotate_saturated)
        g = (_details(ds).get("growth") or {}).get("sigma")
        rec = {"from": t_end, "to": t_end + step, "why": why, "label_before": label,
               "reason_before": ds.attrs.get("classification_reason", ""),
               "growth_rate": float(g) if g is not None and math.isfinite(float(g)) else None}
        if fast_forward and jump is None and left > 4 * FAST_FORWARD_TWIN_TIME:
            plan, ff_why = plan_fast_forward(ds)
            if plan is not None:
                unscaled = ds
                try:
                    ds, jump = twin_fast_forward(ds, plan, continue_fn)
                except (SolverError, ValueError) as exc:  # no usable twin: go on without a fast-forward
                    ff_note, plan = f"twin failed: {type(exc).__name__}: {exc}", None
            if plan is not None:
                t_end = float(ds["time"].values[-1])
                left = max_duration - (t_end - t0)
                rec["from"] = t_end
                rec["fast_forward"] = jump["why"]
                step = max(step, _step_after_fast_forward(plan, ds))
                rec["why"] = ("growing whirl after the fast-forward: the growth to saturation (ln(1/fraction) + 1.2)/sigma "
                              f"and {SATURATED_REVOLUTIONS} cage revolutions of the saturated orbit")
            elif ff_why != "determined" and not ff_note:
                ff_note = ff_why
        step = min(step, left)
        rec["to"] = t_end + step
        try:
            ds = continue_fn(ds, step)
            if jump is not None:
                ds = annotate_saturated(ds, jump["at"], case)
            elif growing_from is not None:
                ds = annotate_saturated(ds, growing_from, case)
        except SolverError as exc:
            if "fast_forward" in rec:
                ds = unscaled  # the kept run ends with its own (unscaled) state
                jump = None
            if not keep_on_failure:
                raise
            reason = (f"failed: the extension {t_end:.6g} -> {t_end + step:.6g} s stopped ({exc}); the run is kept "
                      f"up to {t_end:.6g} s, still undetermined")
            break
        rec["label_after"] = ds.attrs.get("classification", "undetermined")
        steps.append(rec)
    ds = ds.copy()
    ds.attrs["extensions"] = json.dumps(steps)
    ds.attrs["extension_stop_reason"] = reason
    ds.attrs["extension_max_duration"] = float(max_duration)
    if fast_forward and steps:
        ds.attrs["fast_forward"] = json.dumps(jump) if jump is not None else json.dumps(
            {"not_done": ff_note or "not a growing whirl in the linear regime"})
    rates = [s["growth_rate"] for s in steps if s["growth_rate"] is not None]
    ds.attrs["extension_growth_rate"] = float(rates[-1]) if rates else float("nan")
    grew = any("growing" in s["why"] for s in steps)
    if grew and ds.attrs.get("classification", "undetermined") != "undetermined":
        ds.attrs["extension_saturated_orbit"] = _saturated_orbit(ds)
    return ds


def extension_summary(ds) -> dict:
    """What a sweep, map or study table carries of a run's extension (empty for a run never offered one)."""
    if "extension_stop_reason" not in ds.attrs or "time" not in ds.coords:
        return {}
    try:
        steps = json.loads(ds.attrs.get("extensions", "[]")) or []
    except (TypeError, ValueError):
        steps = []
    t = ds["time"].values
    g = ds.attrs.get("extension_growth_rate", float("nan"))
    return {"simulated_time": float(t[-1] - t[0]) if t.size else float("nan"),
            "extension_count": len(steps),
            "extension_stop_reason": str(ds.attrs["extension_stop_reason"]),
            "extension_growth_rate": float(g) if _finite(g) else float("nan")}
