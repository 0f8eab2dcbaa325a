"""The CVODE layer against closed-form solutions (independent check) and its failure path."""

import numpy as np
import pytest

from hsbearing.solvers.cvode import integrate


def test_linear_oscillator_matches_closed_form():
    w = 2 * np.pi * 50.0

    def rhs(t, y, yp):
        yp[0] = y[1]
        yp[1] = -w * w * y[0]

    t = np.linspace(0, 0.1, 201)
    res = integrate(rhs, [1.0, 0.0], t, rtol=1e-9, atol=1e-12)
    assert res.success and res.t.size == t.size
    assert np.max(np.abs(res.y[:, 0] - np.cos(w * t))) < 1e-6
    assert res.stats["steps"] > 0 and res.stats["rhs_evals"] >= res.stats["steps"]


def test_stiff_van_der_pol_and_user_jacobian_agree():
    mu = 1000.0

    def rhs(t, y, yp):
        yp[0] = y[1]
        yp[1] = mu * (1 - y[0] ** 2) * y[1] - y[0]

    def jac(t, y, yp, JJ):
        JJ[0, 0] = 0.0
        JJ[0, 1] = 1.0
        JJ[1, 0] = -2 * mu * y[0] * y[1] - 1.0
        JJ[1, 1] = mu * (1 - y[0] ** 2)

    t = np.linspace(0, 1000.0, 11)
    a = integrate(rhs, [2.0, 0.0], t, rtol=1e-7, atol=1e-9)
    b = integrate(rhs, [2.0, 0.0], t, rtol=1e-7, atol=1e-9, jacfn=jac)
    assert a.success and b.success
    assert np.allclose(a.y[:, 0], b.y[:, 0], atol=1e-3)
    assert b.stats["jacobian"] == "user"


def test_failure_keeps_partial_result():
    def rhs(t, y, yp):  # blows up at t = 1
        yp[0] = y[0] ** 2

    t = np.linspace(0, 2.0, 21)
    res = integrate(rhs, [1.0], t, rtol=1e-6, atol=1e-9, max_num_steps=2000)
    assert not res.success
    assert res.status.startswith("failed at t = ")
    assert 1 < res.t.size < t.size
    assert np.all(np.isfinite(res.y))
    assert res.t[-1] < 1.0 + 1e-9


@pytest.mark.parametrize("limit", [1e-9])
def test_wall_limit(limit):
    def rhs(t, y, yp):
        yp[0] = -y[0]

    res = integrate(rhs, [1.0], np.linspace(0, 1, 5), wall_limit=limit)
    assert "wall-time limit" in res.status
