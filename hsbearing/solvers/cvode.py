"""SUNDIALS CVODE (BDF) through scikit-sundae: the only module that imports ``sksundae``.

Nothing here knows about bearings.  :func:`integrate` advances
``y' = f(t, y)`` with CVODE's variable-order BDF (the counterpart of ADAMS'
GSTIFF), returns the solution at requested output times and the solver
statistics, and never hides a failure: on error it returns what was computed
up to the failure with ``status = "failed at t = ...: <message>"``.

Stepping is done in CVODE's one-step mode so that the number of internal
steps is known (scikit-sundae 1.2 exposes only cumulative rhs/Jacobian
evaluation counts); outputs are CVODE's own dense interpolation inside the
last step (``CVodeGetDky`` via a normal-mode call behind the current time),
so output sampling does not constrain the step size.

scikit-sundae 1.2 does not expose the error-test and nonlinear-convergence
failure counters; they are reported as absent rather than invented.
"""

from __future__ import annotations

import time as _time
from dataclasses import dataclass, field
from typing import Callable

import numpy as np
import sksundae as sun

__all__ = ["IntegrationResult", "integrate"]


@dataclass
class IntegrationResult:
    """Trajectory and statistics of one integration."""

    t: np.ndarray  #: output times actually reached [s], shape (n,)
    y: np.ndarray  #: states at ``t``, shape (n, N)
    status: str  #: "ok" or "failed at t = ...: message"
    stats: dict = field(default_factory=dict)  #: steps, rhs_evals, jac_evals, wall_time, ...

    @property
    def success(self) -> bool:
        return self.status == "ok"


def integrate(
    rhs: Callable,
    y0,
    t_eval,
    *,
    rtol: float = 1e-5,
    atol=1e-8,
    jacfn: Callable | None = None,
    method: str = "BDF",
    max_step: float = 0.0,
    first_step: float = 0.0,
    max_order: int | None = None,
    max_num_steps: int = 100000,
    linsolver: str = "dense",
    progress: bool = False,
    progress_desc: str = "simulating",
    wall_limit: float | None = None,
    callback: Callable | None = None,
) -> IntegrationResult:
    """Integrate ``rhs(t, y, ydot)`` (in place) from ``t_eval[0]`` through ``t_eval``.

    Parameters
    ----------
    rhs : callable ``rhs(t, y, ydot)`` writing ``ydot[:]`` in place.
    y0 : initial state, shape (N,).
    t_eval : increasing output times [s]; ``t_eval[0]`` is the initial time.
    rtol, atol : CVODE tolerances (``atol`` scalar or per-state array).
    jacfn : optional ``jacfn(t, y, ydot, JJ)`` filling the dense (N, N) Jacobian.
    max_step, first_step, max_order : CVODE options (0 = CVODE default).
    max_num_steps : internal steps allowed between two outputs.
    progress : show a tqdm bar of simulated time with ETA (stderr).
    wall_limit : stop (status "failed ... wall-time limit") after this many seconds.
    callback : optional ``callback(t, y)`` called at each output.
    """
    t_eval = np.asarray(t_eval, dtype=float)
    y0 = np.ascontiguousarray(y0, dtype=float)
    n_out = t_eval.size
    ys = np.empty((n_out, y0.size))
    ys[0] = y0
    options = dict(method=method, rtol=rtol, atol=atol, max_num_steps=max_num_steps, linsolver=linsolver)
    if jacfn is not None:
        options["jacfn"] = jacfn
    if max_step:
        options["max_step"] = max_step
    if first_step:
        options["first_step"] = first_step
    if max_order:
        options["max_order"] = max_order
    solver = sun.cvode.CVODE(rhs, **options)
    t0, t_end = float(t_eval[0]), float(t_eval[-1])
    bar = None
    if progress:
        from tqdm import tqdm

        bar = tqdm(total=t_end - t0, desc=progress_desc, unit="s", unit_scale=True, leave=True,
                   bar_format="{l_bar}{bar}| {n:.4g}/{total:.4g} s simulated [{elapsed}<{remaining}]")
    wall0 = _time.perf_counter()
    steps = 0
    status = "ok"
    nfev = njev = 0
    k_done = 1  # outputs filled
    try:
        init = solver.init_step(t0, y0)
        if not init.success:
            raise _Failure(t0, init.message)
        t_cur = t0
        for k in range(1, n_out):
            t_out = float(t_eval[k])
            while t_cur < t_out:
                r = solver.step(t_end, method="onestep", tstop=t_end)
                if r.status < 0 or not np.isfinite(r.t):
                    raise _Failure(t_cur, r.message)
                if r.t > t_cur:  # after a dense-output call the next one-step call may return in place
                    steps += 1
                t_cur = float(r.t)
                nfev, njev = int(r.nfev), int(r.njev)
                if wall_limit is not None and _time.perf_counter() - wall0 > wall_limit:
                    raise _Failure(t_cur, f"wall-time limit of {wall_limit:g} s reached")
            if t_out == t_cur:
                ys[k] = r.y
            else:
                ro = solver.step(t_out)  # dense output inside the last step
                if ro.status < 0:
                    raise _Failure(t_cur, ro.message)
                ys[k] = ro.y
            if not np.all(np.isfinite(ys[k])):
                raise _Failure(t_out, "non-finite state")
            k_done = k + 1
            if callback is not None:
                callback(t_out, ys[k])
            if bar is not None:
                bar.update(t_out - float(t_eval[k - 1]))
    except _Failure as exc:
        status = f"failed at t = {exc.t:.6g} s: {exc.message}"
    except KeyboardInterrupt:
        status = f"failed at t = {float(t_eval[k_done - 1]):.6g} s: interrupted"
    finally:
        if bar is not None:
            bar.close()
    wall = _time.perf_counter() - wall0
    stats = {
        "method": f"CVODE {method} (SUNDIALS {sun.SUNDIALS_VERSION}, scikit-sundae {sun.__version__})",
        "steps": steps,
        "rhs_evals": nfev,
        "jac_evals": njev,
        "wall_time": wall,
        "rtol": rtol,
        "atol": float(np.min(atol)) if np.ndim(atol) else float(atol),
        "jacobian": "user" if jacfn is not None else "CVODE finite differences",
    }
    return IntegrationResult(t=t_eval[:k_done].copy(), y=ys[:k_done].copy(), status=status, stats=stats)


class _Failure(Exception):
    def __init__(self, t: float, message: str):
        super().__init__(message)
        self.t = t
        self.message = message
