"""Traction laws of seed 004 for a negative rolling (entrainment) speed -- issue 20, "untested paths".

Zhang et al. 2016 (seed 004) Eqs. 2-4 are fitted for U > 0 (Ubar = eta0 U / (E' R) enters through
powers, log Ubar).  A ball rolls backwards whenever the inner ring turns the other way (-omega_i, the mirror
case of tests/test_invariance.py) or on the outer race of an outer-ring drive; the entrainment speed of a
contact is then negative.  The physical reading: the film and its rheology depend on the magnitude of the
entrainment speed only, and the direction of the traction comes from the signed slide-roll ratio S, so
mu(S, W, -U) = mu(S, W, U) and mu(-S) = -mu(S), finite for every law, in numpy and in the numba kernel that
the dynamic model uses.  The kernel's contact traction itself (force opposing the local slip for either
rolling direction) is checked through the model's mirror symmetry (test_invariance.py::
test_mirror_rhs_without_land_film).
"""

from __future__ import annotations

import numpy as np
import pytest

from hsbearing.models import traction
from hsbearing.models.hertz import reduced_modulus
from hsbearing.models.traction import zhang2016

EP = float(reduced_modulus(208e9, 0.3, 208e9, 0.3))
LAWS = sorted(zhang2016.LAWS.items(), key=lambda kv: kv[1])


def _grid():
    S = np.array([-0.3, -0.02, -1e-4, 1e-4, 0.003, 0.05, 0.5])
    W = np.array([1.0, 50.0, 300.0, 2000.0])
    U = np.array([0.05, 2.0, 16.3, 40.0])
    T = np.array([300.15, 403.15])
    R = np.array([3.9e-3, 7.2e-3])
    return [a.ravel() for a in np.meshgrid(S, W, U, T, R, indexing="ij")]


@pytest.mark.parametrize("key,lid", LAWS, ids=[f"{o}-{n}" for (o, n), _ in LAWS])
def test_negative_rolling_speed_gives_the_same_mu(key, lid):
    oil, law = key
    mu = traction.get(oil, law)
    S, W, U, T, R = _grid()
    fwd = mu(S, W, U, T, EP, R)
    back = mu(S, W, -U, T, EP, R)
    assert np.all(np.isfinite(back))
    np.testing.assert_array_equal(back, fwd)  # the law sees |U| only
    np.testing.assert_allclose(mu(-S, W, -U, T, EP, R), -fwd, rtol=1e-12, atol=0)  # direction from S
    # the numba kernel of the dynamics hot path agrees for U < 0
    for i in range(0, S.size, 7):
        c = zhang2016.coefficients_nb(lid, W[i], -U[i], T[i], EP, R[i])
        assert zhang2016.mu_nb(*c, S[i]) == pytest.approx(fwd[i], rel=1e-12, abs=1e-300)


@pytest.mark.parametrize("oil", sorted(traction.OILS))
def test_zero_and_tiny_negative_rolling_speed_is_finite_and_even(oil):
    """At the reversal of a rolling direction U passes through zero: the default laws stay finite and even in U."""
    mu = traction.get(oil)
    U = np.array([-1e-6, -1e-9, 0.0, 1e-9, 1e-6])
    for S in (-0.1, 0.01, 0.1):
        v = mu(S, 200.0, U, 403.15, EP, 3.9e-3)
        assert np.all(np.isfinite(v)), v
        assert v[0] == v[-1] and v[1] == v[3]


_LOW_SPEED = ("the fitted laws (seed 004 Eqs. 2-3, fitted for U of metres per second) extrapolate as a power of "
              "Ubar below it: at W = 200 N, 130 degC, S = 0.1 the default laws give mu = 0.35 (4109), 2.09 (4106), "
              "2.01 (4050) at U = 1 mm/s (the dynamic kernel's rolling_eps) and 0.14 / 0.62 / 0.59 at 1 cm/s; "
              "no EHL contact has |mu| > ~0.15 (issue 15: traction reading, oils helper)")


@pytest.mark.xfail(strict=True, raises=AssertionError, reason=_LOW_SPEED)
@pytest.mark.parametrize("oil", sorted(traction.OILS))
def test_low_rolling_speed_traction_is_bounded(oil):
    """Physical bound |mu| < 0.2 down to U = 1 mm/s (the smallest rolling speed the dynamic kernel passes to the
    law, MODEL_DEFAULTS["rolling_eps"]), either rolling direction."""
    mu = traction.get(oil)
    U = np.array([-1.0, -0.1, -0.01, -1e-3, 1e-3, 0.01, 0.1, 1.0])
    for S in (-0.1, 0.01, 0.1):
        v = mu(S, 200.0, U, 403.15, EP, 3.9e-3)
        assert np.all(np.abs(v) < 0.2), (S, v)
