"""Cost-only changes of the compiled kernel (issue 18, session 5): they must not change the arithmetic beyond round-off.

* The Jacobian's cage and ring columns reuse, per ball, what the perturbed state cannot change (race contacts and
  gravity for the cage columns but the cage angle; the pocket wrench for the ring columns): the columns must equal
  the plain finite difference of the full right-hand side **bit for bit**.
* The libm savings of the traction law and the race-contact quadrature (``mu_nb``: one expm1 instead of expm1 + exp,
  tanh skipped where it rounds to +-1; ``coefficients_nb``: the sharpness powers 4 and 8 by products and square
  roots, log W and log T shared; half the cos/sin of the symmetric nodes; cbrt): the right-hand side over
  states of a default-case trajectory and of a radially loaded table-5 case must stay within round-off of the
  kernel before those changes.  **Regression** data, not validation: tests/data/regression/kernel_rhs_states.npz
  holds the states and the right-hand side of commit 678235b (issue 18 session 5, before the libm changes);
  regenerate it with ``tools/generators/make_kernel_rhs_states.py`` only after a deliberate physics change (the test never
  rewrites its reference).
* Issue 28 item 3 (batched pocket stations with a polynomial atan, Taylor cos/sin of the node angles,
  ``error_model="numpy"``) is held to the same test: measured 9.3e-15 (default) and 3.5e-15 (table 5) of each
  row's largest value against the kernel before it (9af7ae2), state by state.
"""

from __future__ import annotations

import math
from pathlib import Path

import numpy as np
import pytest

import hsbearing
from hsbearing.models.ball_bearing import kernel as K
from hsbearing.models.ball_bearing import kernel_io as kio
from hsbearing.systems.angular_contact.dynamics import build_model

DATA = Path(__file__).resolve().parents[1] / "data" / "regression" / "kernel_rhs_states.npz"
T5 = {"operating.radial_load": "1000 N", "lubricant.temperature": "130 degC", "operating.axial_load": "1000 N"}


def _rhs(model, y):
    Z = model.layout.Z
    out = np.empty(y.size)
    K.rhs_kernel(y, model.P, model.qu, model.qw, out, np.empty((Z, K.N_CONTRIB)), np.empty((1, 1)), False,
                 np.empty(K.N_CONTRIB), np.empty(K.N_GAUX))
    return out


@pytest.mark.parametrize("state", ["film_and_hertz", "trajectory"])
def test_jacobian_cage_and_ring_columns_equal_plain_finite_difference(state):
    """All 22 cage/ring columns of jac_kernel (11 cage columns reuse the race contacts, the 10 ring columns the
    pocket wrenches, the cage-angle column recomputes everything) equal (f(y + h e_k) - f(y)) / h bit for bit."""
    model = build_model(hsbearing.load_case("zhang2016"))
    P = model.P
    Z = model.layout.Z
    y = model.y0.copy()
    if state == "film_and_hertz":  # wall contact to wall contact, squeeze, cage off-centre and tilted
        y[2 * Z:3 * Z] = np.linspace(-1.25, 1.25, Z) * kio.get(P, "c_p") / (0.5 * kio.get(P, "dm"))
        y[3 * Z:4 * Z] = 0.01
        cg = 9 * Z
        y[cg + 1], y[cg + 2], y[cg + 4], y[cg + 5] = 5e-6, -3e-6, 2e-5, -1e-5
        y[cg + 7], y[cg + 8], y[cg + 10], y[cg + 11] = 0.02, -0.01, 0.5, 0.3
    else:
        y = np.load(DATA)["y_default"][-1].copy()
    N = y.size
    J = np.zeros((N, N))
    K.jac_kernel(y, P, model.qu, model.qw, J, model.hscale, np.empty(4 * N))
    f0 = _rhs(model, y)
    for col in range(9 * Z, N):
        h = 1.4901161193847656e-08 * max(abs(y[col]), model.hscale[col])
        yp = y.copy()
        yp[col] += h
        assert np.array_equal(J[:, col], (_rhs(model, yp) - f0) / (yp[col] - y[col])), col


@pytest.mark.parametrize("name", ["default", "t5"])
def test_rhs_within_roundoff_of_kernel_before_libm_changes(name):
    """Right-hand side over trajectory states (every 80th of 4001 over 20 ms of the default case; every 80th of
    2001 over 20 ms of table 5's 1000 N radial load) within 1e-11 of each row's largest magnitude of the stored
    values (measured: <= 5.0e-13 over all 4001 + 2001 states; the contact forces that cancel in the accelerations
    are ~1e3 times the net).  Regression, see the module docstring."""
    d = np.load(DATA)
    # the stored states and right-hand sides were made with the former constant C_D = 0.5 of the ball drag
    # (tools/generators/make_kernel_rhs_states.py pins it too): this test checks the kernel's arithmetic, not the drag law
    model = build_model(hsbearing.load_case("zhang2016", **(T5 if name == "t5" else {})), drag_coefficient=0.5)
    Y, F = d["y_" + name], d["f_" + name]
    scale = np.abs(F).max(axis=0) + 1e-300
    worst = 0.0
    for y, f in zip(Y, F):
        worst = max(worst, float((np.abs(_rhs(model, y) - f) / scale).max()))
    assert worst < 1e-11, worst
    assert math.isfinite(worst)


def test_cos_sin_small_against_libm():
    """The contact-ellipse node angles' cos/sin by Taylor series (kernel._cos_sin_small, |x| <= 0.5; libm beyond)
    equal long-double cos/sin to 2 ulp (absolute 2 * 2^-53 for cos, relative for sin) on 20001 points of
    [-0.5, 0.5] and its ends, and libm's exactly beyond.  Independent reference: numpy's long-double cos/sin."""
    x = np.concatenate([np.linspace(-0.5, 0.5, 20001), [1e-300, -1e-300, 0.5, -0.5, np.nextafter(0.5, 0)]])
    got = np.array([K._cos_sin_small(v) for v in x])
    xl = x.astype(np.longdouble)
    ec = np.abs(got[:, 0] - np.cos(xl))
    es = np.abs(got[:, 1] - np.sin(xl)) / np.maximum(np.abs(np.sin(xl)), np.longdouble(1e-300))
    assert float(ec.max()) <= 2 * 2.0 ** -53 and float(es.max()) <= 2 * 2.0 ** -53, (float(ec.max()), float(es.max()))
    for v in (0.51, -0.7, 3.0, 100.0):
        assert K._cos_sin_small(v) == (math.cos(v), math.sin(v))
