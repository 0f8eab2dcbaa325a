"""Stop a dynamic run when its answer has converged (docs/sweeps.md "Stop rule").

The answer of a run is its cage-motion label with its kind (:func:`hsbearing.analysis.annotate`) and three
summaries: the mean cage slip ratio, the whirl amplitude and the whirl frequency ratio.  With
``[simulation] stop = "converged"`` the run is integrated up to ``duration`` as before, but at the check times
``min_time, min_time + interval, ...`` the run so far is annotated and the integration stops as soon as the
answer has held over ``confirm`` consecutive checks (:func:`decide`).  The CVODE solver is kept alive between
checks (a callback at each output), so a stopped run is *exactly* the prefix of the full-length run.

:func:`converged` is a pure function of a Dataset prefix (the tests feed it prefixes of synthetic motions
with known answers, :mod:`hsbearing.analysis.benchmark`); :func:`check` is one check and :func:`decide` the
rule applied to the list of checks (what the integrator callback does incrementally).
"""

from __future__ import annotations

import math
from dataclasses import asdict, dataclass

import numpy as np

__all__ = ["STOP_DEFAULTS", "STOP_CHOICES", "Check", "check", "decide", "converged", "check_times", "Monitor",
           "NEVER_STOP_KINDS"]

STOP_CHOICES = ("duration", "converged")

#: Thresholds of the rule (docs/sweeps.md, "Stop rule", with the measurements that set them).
STOP_DEFAULTS = {
    "min_time": 0.4,  # s, first check (the default cell shows a spurious "1 period" at 0.10-0.15 s)
    "interval": 0.1,  # s, between checks
    "confirm": 2,  # consecutive checks (the current one included) that must agree: confirming span 0.1 s
    "min_points": 40,  # section points of the latest check (an aperiodic section needs 40 to be read at all)
    "slip_rtol": 0.01,  # mean cage slip ratio: |change| <= max(slip_rtol |value|, slip_atol)
    "slip_atol": 2e-4,
    "amplitude_rtol": 0.02,  # whirl amplitude (RMS radius about the axis)
    "amplitude_atol_clearance": 0.005,  # ... or this fraction of the guide clearance
    "ratio_atol": 0.01,  # whirl frequency ratio (not compared for a still cage: its "whirl" is ball-pass jitter)
    "growth_max": 0.1,  # 1/s, no stop while the cage motion grows faster (e-folding < 10 s), whatever the label
    "growth_t_min": 0.1,  # s, the growth fit ignores the start-up before this time
    "transient": "auto",  # the checks' transient rule (annotate): "auto" (>= 30 % of the span) or a fraction
}

#: Kinds on which a run never stops: a growing whirl, too few points to read the section at all, and a drifting
#: arc (quasi-periodic and a slow transient cannot be told apart yet).
NEVER_STOP_KINDS = ("growing", "too-few-points", "drifting-arc", "decaying")

#: Cage-centre variables a check needs (all a check reads of the run).
CHECK_VARIABLES = ("cage_speed", "cage_center_y", "cage_center_z", "cage_velocity_y", "cage_velocity_z", "cage_angle")


@dataclass(frozen=True)
class Check:
    """The answer of a run prefix ending at ``t``."""

    t: float
    label: str
    kind: str
    points: int
    slip: float
    amplitude: float
    ratio: float
    growth: float = float("nan")  # 1/s, growth rate of the RMS motion about the mean position (last blocks)

    def text(self) -> str:
        return (f"t = {self.t:.3g} s: {self.label} ({self.kind}), {self.points} points, slip {self.slip:.5g}, "
                f"whirl {self.amplitude * 1e6:.4g} um, ratio {self.ratio:.4g}, growth {self.growth:.3g}/s")


def check_times(t_end: float, rule: dict | None = None) -> np.ndarray:
    """Check times of the rule up to ``t_end`` (inclusive, to 1e-9 s)."""
    r = dict(STOP_DEFAULTS, **(rule or {}))
    n = int(math.floor((t_end - r["min_time"]) / r["interval"] + 1e-6))
    return r["min_time"] + r["interval"] * np.arange(max(n + 1, 0))


def motion_growth(t, y, z, block: float = 0.1, blocks: int = 4, t_min: float = 0.1) -> float:
    """Growth rate [1/s] of the cage-centre motion: log-linear fit of the RMS radius about the block mean over
    the last ``blocks`` blocks of ``block`` seconds (none before ``t_min``, the start-up); NaN if < 3 blocks.

    The classifier's growth test needs a factor 1.5 across its window, so a slow exponential growth of a
    resting cage reads "still" on a short window and "growing" on a long one (measured: the 3000 r/min cells
    of Table 4 grow 9 % per 0.1 s from 0.23 um and read "still" up to 0.8-0.9 s, "growing" from 0.9-1.0 s).
    """
    t, y, z = (np.asarray(a, float) for a in (t, y, z))
    end = t[-1]
    rms, mid = [], []
    for k in range(blocks):
        lo, hi = end - (k + 1) * block, end - k * block
        if lo < t_min - 1e-12:
            break
        m = (t >= lo) & (t <= hi) & np.isfinite(y) & np.isfinite(z)
        if m.sum() < 8:
            break
        yy, zz = y[m], z[m]
        r = math.sqrt(float(np.mean((yy - yy.mean()) ** 2 + (zz - zz.mean()) ** 2)))
        if not r > 0:
            break
        rms.append(math.log(r))
        mid.append(0.5 * (lo + hi))
    if len(rms) < 3:
        return float("nan")
    return float(np.polyfit(mid, rms, 1)[0])


def check(ds, case=None, *, section: str = "transverse", block: float = STOP_DEFAULTS["interval"],
          transient="auto", growth_t_min: float = STOP_DEFAULTS["growth_t_min"]) -> Check:
    """Annotate the run ``ds`` (a prefix) and return its answer.

    ``ds`` needs ``time`` and the cage-centre variables (:data:`CHECK_VARIABLES`, the velocities and the angle
    optional) and, for the slip ratio and the clearance, ``case`` or ``attrs["case_toml"]``.
    """
    from hsbearing.analysis import annotate

    keep = [v for v in CHECK_VARIABLES if v in ds.variables]
    small = ds[keep]
    a = annotate(small, case, section=section, transient=transient)

    def f(name):
        return float(a[name]) if name in a else float("nan")

    return Check(t=float(ds["time"].values[-1]), label=str(a.attrs.get("classification", "undetermined")),
                 kind=str(a.attrs.get("classification_kind", "")), points=int(a["poincare_y"].size),
                 slip=f("mean_cage_slip_ratio"), amplitude=f("whirl_amplitude"), ratio=f("whirl_frequency_ratio"),
                 growth=motion_growth(ds["time"].values, ds["cage_center_y"].values, ds["cage_center_z"].values,
                                      block=block, t_min=growth_t_min))


def _close(a: float, b: float, rtol: float, atol: float) -> bool:
    if not (math.isfinite(a) and math.isfinite(b)):
        return math.isnan(a) and math.isnan(b)
    return abs(a - b) <= max(rtol * max(abs(a), abs(b)), atol)


def decide(checks: list[Check], rule: dict | None = None, clearance: float | None = None) -> tuple[bool, str]:
    """Whether to stop after the last of ``checks`` (in time order), and why (or why not).

    Stop when the last ``confirm`` checks have the same label and kind, the last has at least ``min_points``
    section points and is not "undetermined" of a kind in :data:`NEVER_STOP_KINDS`, and the summaries of
    every pair of consecutive checks in that span agree within the tolerances of the rule.
    """
    r = dict(STOP_DEFAULTS, **(rule or {}))
    n = int(r["confirm"])
    if not checks:
        return False, "no check yet"
    last = checks[-1]
    if last.t < r["min_time"] - 1e-9:
        return False, f"before the minimum time {r['min_time']:g} s"
    if last.label == "undetermined" and (last.kind in NEVER_STOP_KINDS or not last.kind):
        return False, f"undetermined ({last.kind or 'no kind'}): never stops on it"
    if last.kind in NEVER_STOP_KINDS:
        return False, f"kind {last.kind}: never stops on it"
    if last.kind != "still" and last.points < r["min_points"]:
        return False, f"{last.points} section points < {r['min_points']}"
    if not (last.growth <= r["growth_max"]):
        return False, (f"the cage motion grows at {last.growth:.3g}/s (> {r['growth_max']:g}/s, or not measurable): "
                       + ("a slow instability of a resting cage may still come" if last.kind == "still" else
                          "the orbit has not reached its size"))
    if len(checks) < n:
        return False, f"{len(checks)} check(s) < {n} to confirm"
    span = checks[-n:]
    if any(c.label != last.label or c.kind != last.kind for c in span):
        return False, "label changed: " + "; ".join(f"{c.t:.3g} s {c.label} ({c.kind})" for c in span)
    atol_amp = r["amplitude_atol_clearance"] * clearance if clearance and clearance > 0 else 0.0
    for a, b in zip(span[:-1], span[1:]):
        if not _close(a.slip, b.slip, r["slip_rtol"], r["slip_atol"]):
            return False, f"mean cage slip ratio moved {a.slip:.5g} -> {b.slip:.5g} ({a.t:.3g} -> {b.t:.3g} s)"
        if not _close(a.amplitude, b.amplitude, r["amplitude_rtol"], atol_amp):
            return False, f"whirl amplitude moved {a.amplitude:.4g} -> {b.amplitude:.4g} m ({a.t:.3g} -> {b.t:.3g} s)"
        if last.kind != "still" and not _close(a.ratio, b.ratio, 0.0, r["ratio_atol"]):
            return False, f"whirl frequency ratio moved {a.ratio:.4g} -> {b.ratio:.4g} ({a.t:.3g} -> {b.t:.3g} s)"
    return True, (f"converged: {last.label} ({last.kind}) and the summaries held over {n} checks "
                  f"{span[0].t:.3g}-{last.t:.3g} s ({last.points} section points; slip {last.slip:.5g}, "
                  f"whirl {last.amplitude * 1e6:.4g} um, ratio {last.ratio:.4g})")


def _clearance(ds, case):
    c = ds.attrs.get("guide_clearance")
    if c is None and case is not None:
        from hsbearing.models.geometry import derive

        c = derive(case).guide_clearance
    return float(c) if c is not None and math.isfinite(float(c)) else None


def _check_kw(r: dict) -> dict:
    return {"block": r["interval"], "transient": r["transient"], "growth_t_min": r["growth_t_min"]}


def converged(ds, case=None, rule: dict | None = None, *, section: str = "transverse"):
    """Pure rule on a run prefix: (stop, reason, checks) from the checks at :func:`check_times` of ``ds``.

    Only the last ``confirm`` check times up to the end of ``ds`` are evaluated (the earlier ones cannot
    change the decision).
    """
    r = dict(STOP_DEFAULTS, **(rule or {}))
    t = np.asarray(ds["time"].values, float)
    times = check_times(float(t[-1]), r)[-int(r["confirm"]):]
    checks = [check(ds.isel(time=slice(0, int(np.searchsorted(t, tc + 1e-9)))), case, section=section,
                    **_check_kw(r)) for tc in times]
    stop, reason = decide(checks, r, _clearance(ds, case))
    return stop, reason, checks


class Monitor:
    """The rule applied while integrating: ``monitor(t, y)`` at each output, True = stop now.

    ``keep(y)`` picks what to store of each output (default: a copy of ``y``); ``to_prefix(t, rows)`` builds
    the (small) Dataset of the cage variables from the stored rows.
    """

    def __init__(self, to_prefix, t_end: float, case, rule: dict | None = None, section: str = "transverse",
                 clearance: float | None = None, keep=None, t_start: float = 0.0):
        self.rule = dict(STOP_DEFAULTS, **(rule or {}))
        self.to_prefix = to_prefix
        self.case = case
        self.section = section
        self.clearance = clearance
        self.pending = list(check_times(t_end, self.rule))
        self.pending = [tc for tc in self.pending if tc < t_end - 1e-9]  # the end itself needs no check
        self.checks: list[Check] = []
        self.ts: list[float] = []
        self.ys: list[np.ndarray] = []
        self.stopped_at: float | None = None
        self.reason = ""
        self.check_wall = 0.0
        self.t_start = float(t_start)
        self.keep = keep if keep is not None else (lambda y: np.array(y, copy=True))

    def __call__(self, t, y) -> bool:
        self.ts.append(float(t))
        self.ys.append(self.keep(y))
        tr = float(t) - self.t_start
        if not self.pending or tr < self.pending[0] - 1e-9:
            return False
        import time as _time

        while self.pending and tr >= self.pending[0] - 1e-9:
            self.pending.pop(0)
        w0 = _time.perf_counter()
        c = check(self.to_prefix(np.asarray(self.ts), np.asarray(self.ys)), self.case, section=self.section,
                  **_check_kw(self.rule))
        self.checks.append(c)
        stop, self.reason = decide(self.checks, self.rule, self.clearance)
        self.check_wall += _time.perf_counter() - w0
        if stop:
            self.stopped_at = float(t)
        return stop

    def attrs(self, rule_name: str = "converged") -> dict:
        r = self.rule
        text = (f"converged: check every {r['interval']:g} s from {r['min_time']:g} s, stop when {r['confirm']} "
                f"consecutive checks agree on label, kind and summaries (slip {r['slip_rtol']:g} rel / "
                f"{r['slip_atol']:g}, amplitude {r['amplitude_rtol']:g} rel / {r['amplitude_atol_clearance']:g} "
                f"clearance, ratio {r['ratio_atol']:g}), >= {r['min_points']} section points, only while the cage "
                f"motion grows < {r['growth_max']:g}/s, never on "
                f"{', '.join(NEVER_STOP_KINDS)}")
        return {
            "stop_rule": text if rule_name == "converged" else rule_name,
            "stopped_at": float(self.stopped_at) if self.stopped_at is not None else float("nan"),
            "stop_reason": self.reason if self.stopped_at is not None else
            ("ran to the duration (upper bound); last check: " + (self.reason or "none")),
            "stop_checks": "; ".join(c.text() for c in self.checks),
            "stop_check_wall_time": float(self.check_wall),
        }


def as_dict(c: Check) -> dict:
    return asdict(c)
