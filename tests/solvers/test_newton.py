"""solvers.newton.damped_newton (the generic part of the quasi-static solve, issue 19) on problems with
known roots, independent of any bearing."""

from __future__ import annotations

import numpy as np

from hsbearing.solvers.newton import damped_newton


def _circle_line(x):
    # x0^2 + x1^2 = 4 and x0 = x1 (root sqrt 2, sqrt 2); x2 does not enter
    return np.array([x[0] ** 2 + x[1] ** 2 - 4.0, x[0] - x[1], 0.0]), None


def _jac(x, _aux):
    return np.array([[2 * x[0], 2 * x[1], 0.0], [1.0, -1.0, 0.0], [0.0, 0.0, 1.0]])


def test_converges_to_the_root_and_keeps_inactive_unknowns():
    x, R = damped_newton(_circle_line, _jac, np.array([3.0, 0.5, 7.0]), 1e-12, active=np.array([0, 1]),
                         xscale=np.ones(3), rscale=np.ones(3))
    assert np.allclose(x[:2], np.sqrt(2.0), rtol=0, atol=1e-13)
    assert x[2] == 7.0 and np.max(np.abs(R[:2])) < 1e-12


def test_scaling_does_not_change_the_root():
    x, _ = damped_newton(_circle_line, _jac, np.array([3.0, 0.5, 0.0]), 1e-12, active=[0, 1],
                         xscale=np.array([1e-3, 1e3, 1.0]), rscale=np.array([1e4, 1e-2, 1.0]))
    assert np.allclose(x[:2], np.sqrt(2.0), rtol=0, atol=1e-12)


def test_no_root_stops_without_a_step_that_grows_the_residual():
    # x^2 + 1 = 0 has no real root: the iteration must stop (not loop), at a point no worse than the start,
    # and restore is called for every rejected trial
    calls = {"save": 0, "restore": 0}

    def res(x):
        return np.array([x[0] ** 2 + 1.0]), None

    def save():
        calls["save"] += 1
        return None

    def restore(_):
        calls["restore"] += 1

    x, R = damped_newton(res, lambda x, _: np.array([[2 * x[0]]]), np.array([0.3]), 1e-12, active=[0],
                         xscale=np.ones(1), rscale=np.ones(1), save=save, restore=restore)
    assert abs(R[0]) <= 0.3 ** 2 + 1.0
    assert calls["save"] >= calls["restore"] > 0
