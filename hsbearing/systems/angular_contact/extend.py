"""Extend a dynamic run whose cage-motion label is "undetermined" until it is determined or a budget is spent.

``hsbearing run --extend [--max-duration T]`` (opt-in).  The run goes on from its last state
(:func:`hsbearing.systems.angular_contact.dynamics.continue_run`) in steps; each step is re-classified over the
whole run (the transient rule of :func:`hsbearing.analysis.annotate` applies to the longer run).  The step is
what the undetermined label says it needs:

- a growing or decaying whirl: one e-folding time 1/|sigma| of its measured growth rate (the radius changes by a
  factor e, so the next label sees either the saturated orbit or a clearly continuing growth);
- a drifting arc of section points: the time the classifier estimates to close one turn (``run_longer_s``);
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
"""

from __future__ import annotations

import json
import math

from hsbearing.analysis.stoprule import NEVER_STOP_KINDS
from hsbearing.results import register

__all__ = ["extend_until_determined", "next_step", "extension_wanted", "extension_summary", "MIN_STEP_FRACTION",
           "MAX_EXTENSIONS", "DEFAULT_BUDGET_FACTOR", "WORKFLOW_BUDGET_FACTOR", "ESTIMATE_KINDS"]

#: A step is at least this fraction of the simulated time so far.
MIN_STEP_FRACTION = 0.25
#: At most this many extensions.
MAX_EXTENSIONS = 8
#: Default budget of ``--max-duration``: this many times the run's own duration.
DEFAULT_BUDGET_FACTOR = 3.0
#: Default budget of a map or study point (``hsbearing map`` / ``study``): this many times the point's duration
#: (docs/sweeps.md, "Extend until determined": the growing whirls of the load x temperature map have e-folding
#: times of 0.3-1.2 s; the transient rule discards at most 60 % of a run, so a whirl that saturates by ~1.4 s is
#: read on its saturated orbit in 3.6 s).
WORKFLOW_BUDGET_FACTOR = 3.0
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
        step, why = float(det["run_longer_s"]), "drifting arc: the time to close one turn of the section"
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


def extend_until_determined(ds, max_duration: float, *, continue_fn=None, progress: bool = False,
                            converge: bool = False, keep_on_failure: bool = False):
    """Continue ``ds`` (an annotated dynamic run) while it is "undetermined", up to ``max_duration`` [s] in all.

    ``continue_fn(ds, duration) -> ds``: the continuation (default
    :func:`hsbearing.systems.angular_contact.dynamics.continue_run`; tests pass a synthetic one).  Returns the
    extended, re-annotated run with ``attrs["extensions"]``, ``attrs["extension_stop_reason"]``,
    ``attrs["extension_max_duration"]``, ``attrs["extension_growth_rate"]`` and, for a growing whirl that became
    determined, ``attrs["extension_saturated_orbit"]``.  A run that does not ask for an extension
    (:func:`extension_wanted`) is returned with none (its stop reason says why).  ``converge``: also stop when the
    stop rule's convergence holds on the extended run.  A failure of a continuation (``SolverError``)
    propagates with its partial run, or with ``keep_on_failure`` ends the extension, keeping the run as it was
    before the failed step (stop reason "failed: ...").
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
    case = _case_of(ds) if converge and wanted else None
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
        step = min(step, left)
        g = (_details(ds).get("growth") or {}).get("sigma")
        rec = {"from": t_end, "to": t_end + step, "why": why, "label_before": label,
               "reason_before": ds.attrs.get("classification_reason", ""),
               "growth_rate": float(g) if g is not None and math.isfinite(float(g)) else None}
        try:
            ds = continue_fn(ds, step)
        except SolverError as exc:
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
