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
It stops when the label is no longer "undetermined" ("determined"), when the budget ``max_duration`` of total
simulated time is reached ("budget"), or after :data:`MAX_EXTENSIONS` steps ("steps").  The archive records
every extension (``attrs["extensions"]``, JSON: from/to [s], the label and reason before, the growth rate when
measured) and why it stopped (``attrs["extension_stop_reason"]``).
"""

from __future__ import annotations

import json
import math

__all__ = ["extend_until_determined", "next_step", "MIN_STEP_FRACTION", "MAX_EXTENSIONS", "DEFAULT_BUDGET_FACTOR"]

#: A step is at least this fraction of the simulated time so far.
MIN_STEP_FRACTION = 0.25
#: At most this many extensions.
MAX_EXTENSIONS = 8
#: Default budget of ``--max-duration``: this many times the run's own duration.
DEFAULT_BUDGET_FACTOR = 3.0


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


def extend_until_determined(ds, max_duration: float, *, continue_fn=None, progress: bool = False):
    """Continue ``ds`` (an annotated dynamic run) while it is "undetermined", up to ``max_duration`` [s] in all.

    ``continue_fn(ds, duration) -> ds``: the continuation (default
    :func:`hsbearing.systems.angular_contact.dynamics.continue_run`; tests pass a synthetic one).  Returns the
    extended, re-annotated run with ``attrs["extensions"]``, ``attrs["extension_stop_reason"]`` and
    ``attrs["extension_max_duration"]``.  A run that is already determined is returned with no extension
    (stop reason "determined").  A failure of a continuation (``SolverError``) propagates with its partial run.
    """
    if continue_fn is None:
        from hsbearing.systems.angular_contact.dynamics import continue_run

        def continue_fn(d, duration):
            return continue_run(d, duration, progress=progress, source="--extend")

    steps: list[dict] = []
    t0 = float(ds["time"].values[0])
    reason = ""
    while True:
        label = ds.attrs.get("classification", "undetermined")
        t_end = float(ds["time"].values[-1])
        if label != "undetermined":
            reason = f"determined: {label}" + (f" after {len(steps)} extension(s)" if steps else " (no extension needed)")
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
        ds = continue_fn(ds, step)
        rec["label_after"] = ds.attrs.get("classification", "undetermined")
        steps.append(rec)
    ds = ds.copy()
    ds.attrs["extensions"] = json.dumps(steps)
    ds.attrs["extension_stop_reason"] = reason
    ds.attrs["extension_max_duration"] = float(max_duration)
    return ds
