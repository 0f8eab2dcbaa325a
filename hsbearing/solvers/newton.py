"""Damped Newton iteration for a small scaled nonlinear system R(x) = 0 (generic: nothing here knows the
problem; used by the quasi-static bearing equilibrium, :mod:`hsbearing.systems.angular_contact.quasistatic`).

Steps are least-squares solutions of the scaled linear system (so a singular or rank-deficient Jacobian
still gives a step), with a backtracking line search that halves the step until the scaled residual
decreases.  The iteration stops early when a step cannot reduce the residual or when five iterations gain
less than a factor 2, so that a stuck start is left to the caller's next route (e.g. a trust-region
solver) instead of burning evaluations.
"""

from __future__ import annotations

from typing import Any, Callable

import numpy as np

__all__ = ["damped_newton"]


def damped_newton(residual: Callable[[np.ndarray], tuple[np.ndarray, Any]],
                  jacobian: Callable[[np.ndarray, Any], np.ndarray], x0: np.ndarray, tol: float, *,
                  active, xscale: np.ndarray, rscale: np.ndarray, maxiter: int = 30,
                  save: Callable[[], Any] | None = None, restore: Callable[[Any], None] | None = None):
    """Solve ``R(x) = 0`` for the unknowns ``x[active]`` (the others stay fixed); returns ``(x, R(x))``.

    Parameters
    ----------
    residual : ``residual(x) -> (R, aux)``; ``aux`` is handed to ``jacobian`` (e.g. an inner state).
    jacobian : ``jacobian(x, aux) -> dR/dx`` (full square matrix; only the active block is used).
    x0 : starting point.
    tol : convergence on ``max |R[active] / rscale[active]|``; the iteration aims at ``1e-3 tol`` and stops
        at ``tol`` once an iteration gains less than a factor 10 (quadratic convergence has ended).
    active : indices of the unknowns solved for.
    xscale, rscale : scales of the unknowns and of the residual components (the linear system is solved
        in the scaled variables ``z = x / xscale`` and residuals ``R / rscale``).
    save, restore : optional hooks around each trial step of the line search: ``save()`` before the
        residual of a trial point, ``restore(saved)`` when the trial is rejected (for a residual that
        keeps state, e.g. a warm start of an inner solve).
    """
    a = active
    x = x0
    R, aux = residual(x)
    history = []
    target = 1e-3 * tol  # one step past the tolerance costs little and leaves margin (quadratic convergence)
    for _ in range(maxiter):
        rn = np.max(np.abs(R[a] / rscale[a]))
        history.append(rn)
        if rn < target or (rn < tol and len(history) > 1 and rn > 0.1 * history[-2]):
            break
        if len(history) > 5 and history[-1] > 0.5 * history[-6]:
            break
        J = jacobian(x, aux)[np.ix_(a, a)]
        Js = J * xscale[a][None, :] / rscale[a][:, None]
        try:
            dz = np.linalg.lstsq(Js, -R[a] / rscale[a], rcond=1e-13)[0]
        except np.linalg.LinAlgError:
            break
        dx = np.zeros(len(x))
        dx[a] = dz * xscale[a]
        t, improved = 1.0, False
        for _ in range(12):
            xn = x + t * dx
            saved = save() if save is not None else None
            Rn, auxn = residual(xn)
            if np.max(np.abs(Rn[a] / rscale[a])) < rn:
                improved = True
                break
            if restore is not None:
                restore(saved)
            t *= 0.5
        if not improved:
            break
        x, R, aux = xn, Rn, auxn
    return x, R
