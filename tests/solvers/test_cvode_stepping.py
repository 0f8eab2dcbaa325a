"""CVODE normal-mode stepping (one C call per output interval) against the one-step path it replaces.

The normal path reads the solver statistics from CVODE's own counters through the solver memory of
scikit-sundae (hsbearing.solvers.cvode._CvodeCounters); these tests check that read against an independent
count (one Python round trip per internal step) and that both paths give the same trajectory bit for bit.
"""

import numpy as np
import pytest

from hsbearing.solvers.cvode import counters_available, integrate

MU = 1000.0


def vdp(t, y, yp):
    yp[0] = y[1]
    yp[1] = MU * (1 - y[0] ** 2) * y[1] - y[0]


def vdp_jac(t, y, yp, JJ):
    JJ[0, 0] = 0.0
    JJ[0, 1] = 1.0
    JJ[1, 0] = -2 * MU * y[0] * y[1] - 1.0
    JJ[1, 1] = MU * (1 - y[0] ** 2)


@pytest.mark.parametrize("jac", [None, vdp_jac])
def test_normal_and_onestep_take_the_same_steps(jac):
    """Stiff van der Pol over two relaxation cycles with 200 outputs: identical trajectories and counts, and the
    step count read from CVODE's memory equals the count of one-step returns made in Python."""
    t = np.linspace(0.0, 3000.0, 201)
    a = integrate(vdp, [2.0, 0.0], t, rtol=1e-6, atol=1e-9, jacfn=jac, stepping="onestep")
    b = integrate(vdp, [2.0, 0.0], t, rtol=1e-6, atol=1e-9, jacfn=jac, stepping="normal")
    assert a.success and b.success
    assert "normal mode" in b.stats["stepping"] and "one-step" in a.stats["stepping"]
    assert np.array_equal(a.y, b.y)
    assert a.stats["python_counted_steps"] == a.stats["steps"] == b.stats["steps"] > 100
    for k in ("rhs_evals", "jac_evals", "error_test_failures", "nonlinear_convergence_failures",
              "nonlinear_iterations", "linear_solver_setups"):
        assert a.stats[k] == b.stats[k], k
    # the stiff transitions of van der Pol force step rejections: the failure counters are live, not constant 0
    assert b.stats["error_test_failures"] > 0
    assert b.stats["nonlinear_iterations"] >= b.stats["steps"]
    assert b.stats["rhs_evals"] >= b.stats["nonlinear_iterations"]


def test_outputs_are_cvode_interpolation_not_step_limited():
    """Dense outputs every 1 s of a decay that CVODE steps over in large steps: the number of internal steps must
    not grow with the number of outputs (output sampling does not constrain the step size)."""
    def rhs(t, y, yp):
        yp[0] = -y[0]

    coarse = integrate(rhs, [1.0], np.linspace(0, 20, 3), rtol=1e-8, atol=1e-12)
    fine = integrate(rhs, [1.0], np.linspace(0, 20, 2001), rtol=1e-8, atol=1e-12)
    assert coarse.stats["steps"] == fine.stats["steps"]
    assert np.max(np.abs(fine.y[:, 0] - np.exp(-fine.t))) < 1e-6


def test_callback_per_output_and_interrupt_keeps_partial_result():
    """A KeyboardInterrupt raised inside the rhs (as Ctrl-C would) ends the run with the outputs reached so far,
    with the tqdm progress bar on; the per-output callback saw exactly those outputs."""
    seen = []

    def rhs(t, y, yp):
        if t > 0.55:
            raise KeyboardInterrupt
        yp[0] = -y[0]

    res = integrate(rhs, [1.0], np.linspace(0, 1, 11), rtol=1e-8, atol=1e-12, progress=True,
                    callback=lambda t, y: seen.append(t))
    assert res.status.endswith("interrupted")
    assert 5 <= res.t.size <= 7
    assert np.allclose(seen, res.t[1:])
    assert np.allclose(res.y[:, 0], np.exp(-res.t), atol=1e-6)
    assert res.stats["steps"] > 0


def test_failure_statistics_and_partial_result():
    """y' = y^2 blows up at t = 1: the run fails with the partial trajectory and CVODE's statistics at failure."""
    def rhs(t, y, yp):
        yp[0] = y[0] ** 2

    res = integrate(rhs, [1.0], np.linspace(0, 2.0, 21), rtol=1e-6, atol=1e-9, max_num_steps=2000)
    assert res.status.startswith("failed at t = ")
    assert res.t[-1] < 1.0 and res.t.size > 5
    # global error grows like the solution near the pole: 1e-3 relative at t = 0.9 with rtol 1e-6
    assert np.allclose(res.y[:, 0], 1.0 / (1.0 - res.t), rtol=1e-3)
    assert res.stats["steps"] > 0 and res.stats["rhs_evals"] > res.stats["steps"]


def test_bearing_model_same_trajectory_and_statistics():
    """The default Zhang et al. 2016 case over 2 ms (about 400 internal steps, 40 outputs): normal mode reproduces the
    one-step trajectory bit for bit, with the same step, rhs and Jacobian counts."""
    import hsbearing as h
    from hsbearing.systems.angular_contact import dynamics as dy

    case = h.load_case("zhang2016")
    m = dy.build_model(case)
    t = np.linspace(0.0, 2e-3, 41)
    kw = dict(rtol=case.simulation.rtol, atol=m.layout.atol(case.simulation.atol), jacfn=m.jac)
    a = integrate(m.rhs, m.y0, t, stepping="onestep", **kw)
    b = integrate(m.rhs, m.y0, t, stepping="normal", **kw)
    assert a.success and b.success
    assert np.array_equal(a.y, b.y)
    assert a.stats["python_counted_steps"] == b.stats["steps"] > 100
    assert (a.stats["rhs_evals"], a.stats["jac_evals"]) == (b.stats["rhs_evals"], b.stats["jac_evals"])


def test_cvode_settings_reach_cvode():
    """A CVODE optional input set through the solver memory changes what CVODE does: LSetupFrequency = 1 (msbp)
    makes CVODE refactor at every step (default: at most every 20 steps), with a solution of the same accuracy;
    unknown names are refused."""
    t = np.linspace(0.0, 3000.0, 31)
    a = integrate(vdp, [2.0, 0.0], t, rtol=1e-6, atol=1e-9, jacfn=vdp_jac)
    b = integrate(vdp, [2.0, 0.0], t, rtol=1e-6, atol=1e-9, jacfn=vdp_jac, cvode_settings={"LSetupFrequency": 1})
    assert a.success and b.success
    assert a.stats["linear_solver_setups"] < a.stats["steps"] / 2
    assert b.stats["linear_solver_setups"] >= b.stats["steps"]
    assert b.stats["cvode_settings"] == "LSetupFrequency=1"
    assert np.max(np.abs(a.y[:, 0] - b.y[:, 0])) < 1e-3
    with pytest.raises(ValueError, match="unknown CVODE setting"):
        integrate(vdp, [2.0, 0.0], t, cvode_settings={"MaxSpeed": 1})


def test_long_output_interval_resumes_after_max_num_steps():
    """One output interval needing more internal steps than max_num_steps: normal mode resumes (CV_TOO_MUCH_WORK)
    and ends with the same steps and state as one-step mode, which has no per-interval limit."""
    t = np.array([0.0, 3000.0])
    a = integrate(vdp, [2.0, 0.0], t, rtol=1e-6, atol=1e-9, jacfn=vdp_jac, max_num_steps=50, stepping="onestep")
    b = integrate(vdp, [2.0, 0.0], t, rtol=1e-6, atol=1e-9, jacfn=vdp_jac, max_num_steps=50, stepping="normal")
    assert a.success and b.success
    assert b.stats["steps"] > 10 * 50
    assert b.stats["steps"] == a.stats["steps"] and np.array_equal(a.y, b.y)


def test_cvode_counters_are_reachable():
    """The locked scikit-sundae exposes CVODE's own counters and settings; these tests used to skip silently when
    it did not -- now a scikit-sundae without them fails here (and in the tests that need them)."""
    assert counters_available()
