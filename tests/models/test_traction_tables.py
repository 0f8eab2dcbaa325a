"""The tabulated strip integrand of the physical traction model (models/traction/tables.py, the kernel's
``eyring_strip_mu_nb``) against its exact twin (libm exp/asinh/expm1/log1p at every node, ``eyring_strip_mu_exact_nb``)
and the Python evaluation (``eyring.strip_mu``).  The kernel evaluates the flow stress and the constants of the
Maxwell-Eyring build-up once per mirror pair of theta nodes (exact rearrangements, rounding only).

Bounds set before measuring, from the tables' own asserted relative errors (asinh(e^x): 1.5e-13, (1-e^-y)/y: 3e-13):
|dmu| <= 5e-13 |mu| + 1e-16 and |dmu| <= 2e-14 over the whole regime the model visits (slide-roll 1e-4 ... 0.3, both
signs; rolling speed 1-100 m/s, both signs; 100-5000 N; 27-230 degC with each bundled seed oil's viscosity and
pressure-viscosity coefficient at that temperature; every strip of the kernel; inner and outer contacts).  Kept
unchanged for the Maxwell-Eyring build-up (its tables log1p 3e-13, log1p(e^-t) 3e-13, log(1 - e^z) 5e-13 enter
sigma with weights below one; measured on the strip benchmark's samples 2.6e-13).
Smoothness for BDF: the tables are C2 by construction (checked at every knot), and dmu/dS by central differences
equals the exact law's over a dense slip scan that moves nodes across every switch point (lz = -18, 17; the
build-up's near-inlet form E = 0.5; sigma_f = SIGMA_HARD).
"""

from __future__ import annotations

import math

import numba
import numpy as np
import pytest

from hsbearing.lubricant import bundled_path, load_lubricant
from hsbearing.models.ball_bearing.ball import strip_load_weights
from hsbearing.models.traction import _kernels as kt
from hsbearing.models.traction import eyring as ey
from hsbearing.models.traction import tables as tb

# E', and Rx, k = a/b, a / Q^(1/3) of two contacts: the default case's inner contact (as in test_traction_eyring) and an
# outer-like one (larger Rx, smaller ellipticity, larger ellipse; illustrative values, not read from a case)
EP = 2.2857142857e11
CONTACTS = {"inner": (3.8687463e-3, 9.2314187, 9.3449073e-4 / 300.0 ** (1.0 / 3.0)),
            "outer": (5.6e-3, 7.2, 1.05e-3 / 300.0 ** (1.0 / 3.0))}
OILS = ("4109", "4106", "4050")
QU, QW = strip_load_weights(5)

REL_BOUND, ABS_BOUND = 5e-13, 2e-14


def _coefficients(oil, T_C, W, U, contact):
    lub = load_lubricant(bundled_path(oil))
    T = T_C + 273.15
    eta, alpha = lub.dynamic_viscosity(T, 960.0), lub.alpha(T, 960.0)  # 960 kg/m^3: the default case's density
    Rx, k, acoef = CONTACTS[contact]
    Lam = ey.DEFAULT_LAMBDA
    tau0 = ey.eyring_stress_default(Lam, alpha)
    return kt.eyring_coefficients_nb(W, U, EP, Rx, k, acoef * W ** (1.0 / 3.0), eta, alpha, tau0, Lam,
                                     ey.DEFAULT_SHEAR_MODULUS)


def test_tables_meet_their_bounds_against_the_exact_functions():
    """Random points (not the build grid) against numpy's arcsinh/exp and expm1; relative error within the bounds."""
    rng = np.random.default_rng(7)
    x = rng.uniform(tb.LOG_ASINH_LOW, tb.LOG_ASINH, 200_000)
    g = np.arcsinh(np.exp(x))
    assert np.max(np.abs(tb.evaluate(tb.ASINH_EXP, x) / g - 1.0)) <= 1.5e-13
    y = np.concatenate([rng.uniform(0.0, tb.ONE_MINUS_EXP_END, 200_000), np.geomspace(1e-12, 1e-3, 1000)])
    q = -np.expm1(-y) / y
    assert np.max(np.abs(tb.evaluate(tb.ONE_MINUS_EXP_OVER_X, y) / q - 1.0)) <= 3e-13
    assert tb.ASINH_EXP.max_rel_error <= 1.5e-13 and tb.ONE_MINUS_EXP_OVER_X.max_rel_error <= 3e-13
    # the switch points join within round-off: asinh(e^x) = x + ln 2 above 17, = e^x below -18; 1 - e^-40 = 1
    assert tb.LOG_ASINH == ey.LOG_ASINH  # the kernel branches on eyring's constant, the table ends at this one
    assert tb.evaluate(tb.ASINH_EXP, tb.LOG_ASINH) == pytest.approx(tb.LOG_ASINH + math.log(2.0), rel=2e-16)
    assert tb.evaluate(tb.ASINH_EXP, tb.LOG_ASINH_LOW) == pytest.approx(math.exp(tb.LOG_ASINH_LOW), rel=1e-15)
    end = tb.ONE_MINUS_EXP_END
    assert end * tb.evaluate(tb.ONE_MINUS_EXP_OVER_X, end) == pytest.approx(1.0, rel=2e-16)
    # the Maxwell-Eyring build-up's tables
    a = np.linspace(0.0, 1.0, 20001)[1:]
    assert np.max(np.abs(tb.evaluate(tb.LOG1P, a) / np.log1p(a) - 1.0)) <= 3e-13
    t = np.linspace(0.0, tb.SOFTPLUS_END, 20001)
    assert np.max(np.abs(tb.evaluate(tb.SOFTPLUS_NEG, t) / np.log1p(np.exp(-t)) - 1.0)) <= 3e-13
    z = np.linspace(tb.LOG1M_EXP_START, tb.LOG1M_EXP_END, 20001)
    assert np.max(np.abs(tb.evaluate(tb.LOG1M_EXP, z) / np.log1p(-np.exp(z)) - 1.0)) <= 5e-13
    assert tb.LOG1P.max_rel_error <= 3e-13 and tb.SOFTPLUS_NEG.max_rel_error <= 3e-13
    assert tb.LOG1M_EXP.max_rel_error <= 5e-13
    # log(1 - e^z) is evaluated at z = ln tanh(sigma_f / 2) - sigma_f - E, whose maximum over sigma_f (at asinh 1,
    # E = 0) lies inside the table
    sf = np.linspace(1e-3, 40.0, 400001)
    assert np.max(np.log(np.tanh(sf / 2)) - sf) == pytest.approx(math.log(math.sqrt(2.0) - 1.0) - math.asinh(1.0),
                                                                 abs=1e-9)
    assert math.log(math.sqrt(2.0) - 1.0) - math.asinh(1.0) < tb.LOG1M_EXP_END
    # where the dropped tails begin, they are below 4.3e-18
    assert math.log1p(math.exp(-tb.SOFTPLUS_END)) < 4.3e-18 and -math.log1p(-math.exp(tb.LOG1M_EXP_START)) < 4.3e-18


@pytest.mark.parametrize("tab", [tb.ASINH_EXP, tb.ONE_MINUS_EXP_OVER_X, tb.LOG1P, tb.SOFTPLUS_NEG, tb.LOG1M_EXP],
                         ids=lambda t: t.name)
def test_tables_are_c2_across_every_knot(tab):
    """Value, first and second derivative of cell i at its right end equal those of cell i+1 at its left end."""
    c = tab.coef
    right = c[:-1]
    v_r = right.sum(axis=1)
    d_r = right[:, 1] + 2 * right[:, 2] + 3 * right[:, 3] + 4 * right[:, 4] + 5 * right[:, 5]
    s_r = 2 * right[:, 2] + 6 * right[:, 3] + 12 * right[:, 4] + 20 * right[:, 5]
    left = c[1:]
    scale = np.abs(left[:, 0]) + np.abs(left[:, 1]) + np.abs(left[:, 2]) + 1e-300
    assert np.max(np.abs(v_r - left[:, 0]) / scale) < 1e-14
    assert np.max(np.abs(d_r - left[:, 1]) / scale) < 1e-13
    assert np.max(np.abs(s_r - 2 * left[:, 2]) / scale) < 1e-12


def test_build_refuses_a_table_above_its_bound():
    with pytest.raises(ValueError, match="above the bound"):
        tb.build("asinh(exp(x))", tb._asinh_exp, tb._asinh_exp_d1, tb._asinh_exp_d2, -18.0, 17.0, 0.25, rtol=1e-13)


@pytest.mark.parametrize("contact", list(CONTACTS))
@pytest.mark.parametrize("oil", OILS)
def test_tabulated_strip_mu_within_its_bound_over_the_whole_regime(oil, contact):
    """|dmu| against the exact kernel twin and the Python evaluation over the regime (module docstring)."""
    S = np.geomspace(1e-4, 0.3, 41)
    S = np.concatenate([S, -S])
    worst_rel = worst_abs = 0.0
    lz_seen = []
    for T_C in (27.0, 80.0, 150.0, 230.0):
        for W in (100.0, 700.0, 5000.0):
            for U in (1.0, -1.0, 10.0, 100.0, -100.0):
                c = _coefficients(oil, T_C, W, U, contact)
                Lam, r0, lv, cp, ce = c
                for u in list(QU) + [0.93]:
                    su = math.sqrt(1.0 - u * u)
                    for s in S:
                        fast = kt.eyring_strip_mu_nb(c, s, u)
                        exact = kt.eyring_strip_mu_exact_nb(c, s, u)
                        d = abs(fast - exact)
                        worst_abs = max(worst_abs, d)
                        worst_rel = max(worst_rel, d / abs(exact))
                        assert d <= REL_BOUND * abs(exact) + 1e-16, (oil, T_C, W, U, u, s, fast, exact)
                        lz_seen.append(lv + math.log(abs(s)) + cp * su * ey.MINOR_NODES[:, 1])
                    py = ey.strip_mu(c, 0.01, u)
                    assert kt.eyring_strip_mu_nb(c, 0.01, u) == pytest.approx(py, rel=REL_BOUND, abs=1e-16)
    assert worst_abs <= ABS_BOUND, worst_abs
    lz = np.concatenate(lz_seen)
    # the regime exercises the table and the ln-branch of asinh(e^lz) (measured: lz from -13.6 to above 17)
    assert lz.max() > tb.LOG_ASINH
    assert ((lz > tb.LOG_ASINH_LOW) & (lz < tb.LOG_ASINH)).mean() > 0.2
    # below the regime (the kernel's regularised slip goes down to s_eps / U): the e^lz branch, same bound
    c = _coefficients(oil, 230.0, 100.0, 100.0, contact)
    lows = 0
    for s in np.geomspace(1e-12, 1e-4, 60):
        for u in QU:
            Lam, r0, lv, cp, ce = c
            lows += int(lv + math.log(s) < tb.LOG_ASINH_LOW)
            fast, exact = kt.eyring_strip_mu_nb(c, s, u), kt.eyring_strip_mu_exact_nb(c, s, u)
            assert abs(fast - exact) <= REL_BOUND * abs(exact) + 1e-16, (s, u, fast, exact)
    assert lows > 0


def _nodes(c, s, u):
    """(E, sigma_f, lz) at the nodes (as eyring_strip_mu_nb computes them: E = tau_el / (ts tanh sigma_f))."""
    Lam, r0, lv, cp, ce = c
    su = math.sqrt(1.0 - u * u)
    sn, cs = ey.MINOR_NODES[:, 0], ey.MINOR_NODES[:, 1]
    pi_ = su * cs
    lz = lv + math.log(s) + cp * pi_
    tv = r0 * np.arcsinh(np.exp(np.minimum(lz, 700.0)))
    g4 = 1.0 + (tv / (Lam * pi_)) ** 4
    sf = tv * g4 / r0
    its = g4 ** 1.25 / r0
    return ce * s * su * (1.0 + sn) * its / np.tanh(sf), sf, lz


def _crossings(c, u, S):
    """Names of the switch points some node crosses between neighbouring slips of S."""
    crossed, prev = set(), None
    for s in S:
        E, sf, lz = _nodes(c, s, u)
        state = (tuple(lz > tb.LOG_ASINH), tuple(lz < tb.LOG_ASINH_LOW), tuple(E < 0.5), tuple(sf > ey.SIGMA_HARD))
        if prev is not None:
            crossed |= {n for n, a, b in zip(("lz=17", "lz=-18", "E=0.5", "sigma_f=36"), prev, state) if a != b}
        prev = state
    return crossed


SCANS = [("4109", 27.0, 5000.0, 1.0), ("4106", 120.0, 700.0, 20.0), ("4050", 230.0, 100.0, 100.0)]


@pytest.mark.parametrize("oil,T_C,W,U", SCANS)
def test_derivative_in_slip_continuous_and_equal_to_the_exact_law(oil, T_C, W, U):
    """dmu/dS by central differences (step 1e-4 S) over 4000 slips per sign: equal to the exact law's within
    1e-6 of its scale, so no kink or jump where a node changes branch (each scan crosses a switch point; together
    lz = 17, the build-up's near-inlet form E = 0.5 and sigma_f = SIGMA_HARD: the test below)."""
    c = _coefficients(oil, T_C, W, U, "inner")
    u = QU[1]
    S = np.geomspace(1e-4, 0.3, 4000)
    for sgn in (1.0, -1.0):
        d_fast, d_exact = [], []
        for s in S:
            h = 1e-4 * s
            d_fast.append((kt.eyring_strip_mu_nb(c, sgn * (s + h), u) - kt.eyring_strip_mu_nb(c, sgn * (s - h), u)) / (2 * h))
            d_exact.append((kt.eyring_strip_mu_exact_nb(c, sgn * (s + h), u)
                            - kt.eyring_strip_mu_exact_nb(c, sgn * (s - h), u)) / (2 * h))
        d_fast, d_exact = np.array(d_fast), np.array(d_exact)
        scale = np.max(np.abs(d_exact))
        assert np.max(np.abs(d_fast - d_exact)) <= 1e-6 * scale
        # and the derivative itself has no jump between neighbouring slips beyond the exact law's own variation
        jump_fast = np.abs(np.diff(d_fast))
        jump_exact = np.abs(np.diff(d_exact))
        assert np.max(jump_fast - jump_exact) <= 1e-6 * scale
    assert _crossings(c, u, S), "the scan crossed no switch point"


def test_derivative_scans_cross_every_switch_point():
    """The three scans above together move nodes across every branch point of the tabulated integrand."""
    crossed = set()
    for oil, T_C, W, U in SCANS:
        c = _coefficients(oil, T_C, W, U, "inner")
        crossed |= _crossings(c, QU[1], np.geomspace(1e-4, 0.3, 4000))
    assert {"lz=17", "E=0.5", "sigma_f=36"} <= crossed, crossed


def test_mirror_node_pairs_are_exact():
    """The kernel evaluates the flow stress once per mirror pair (+-theta_j share p/p0 = su cos theta_j): this needs
    nodes symmetric to the last bit, which Gauss-Legendre nodes are; an odd or asymmetric set is refused."""
    N = ey.MINOR_NODES
    assert np.array_equal(N[:, 0], -N[::-1, 0]) and np.array_equal(N[:, 1], N[::-1, 1])
    assert np.array_equal(N[:, 2], N[::-1, 2])
    P = kt._node_pairs(N)
    m = N.shape[0] // 2
    assert P.shape == (m, 5)
    np.testing.assert_array_equal(P[:, 0], N[:m, 1])
    np.testing.assert_array_equal(P[:, 1], 1.0 + N[:m, 0])
    np.testing.assert_array_equal(P[:, 2], 1.0 + N[::-1, 0][:m])  # the mirror node's 1 + sin theta
    np.testing.assert_array_equal(P[:, 3], N[:m, 2])
    assert kt._SUM_WCS == pytest.approx(float(np.sum(N[:, 2] * N[:, 1])), rel=1e-15)
    with pytest.raises(ValueError, match="mirror-symmetric"):
        kt._node_pairs(ey._minor_nodes(7))
    bad = N.copy()
    bad[0, 1] = np.nextafter(bad[0, 1], 1.0)
    with pytest.raises(ValueError, match="mirror-symmetric"):
        kt._node_pairs(bad)


@pytest.mark.parametrize("oil", OILS)
def test_contact_coefficients_in_logarithms_equal_the_python_evaluation_over_the_regime(oil):
    """eyring_coefficients_nb forms the Hamrock-Dowson film in logarithms; the Python twin (eyring.contact_coefficients,
    central_film with pows) agrees within 1e-13 relative over 100-5000 N, +-1-100 m/s, 27-230 degC, two contacts."""
    lub = load_lubricant(bundled_path(oil))
    worst = 0.0
    for T_C in (27.0, 80.0, 150.0, 230.0):
        T = T_C + 273.15
        eta, alpha = lub.dynamic_viscosity(T, 960.0), lub.alpha(T, 960.0)
        tau0 = ey.eyring_stress_default(ey.DEFAULT_LAMBDA, alpha)
        for Rx, k, acoef in CONTACTS.values():
            for W in (100.0, 700.0, 5000.0):
                a = acoef * W ** (1.0 / 3.0)
                for U in (1.0, -1.0, 10.0, 100.0, -100.0):
                    args = (W, U, EP, Rx, k, a, eta, alpha, tau0, ey.DEFAULT_LAMBDA, ey.DEFAULT_SHEAR_MODULUS)
                    cn = np.array(kt.eyring_coefficients_nb(*args))
                    cp = np.array(ey.contact_coefficients(*args))
                    worst = max(worst, float(np.max(np.abs(cn - cp) / np.abs(cp))))
    assert worst <= 1e-13, worst


def test_kernel_dispatch_uses_the_tabulated_twin():
    c = _coefficients("4109", 80.0, 700.0, 16.0, "inner")
    for s in (1e-4, -3e-3, 0.2):
        assert kt.traction_mu_nb(kt.EYRING_LAW_ID, c, s, QU[0]) == kt.eyring_strip_mu_nb(c, s, QU[0])


def _plastic_pairs(c, s, u):
    """Per mirror pair: does eyring_strip_mu_nb take its plastic shortcut (the same test in numpy)?"""
    Lam, r0, lv, cp, ce = c
    su = math.sqrt(1.0 - u * u)
    P = kt._PAIRS
    tv = r0 * np.arcsinh(np.exp(np.minimum(lv + math.log(s) + cp * su * P[:, 0], 700.0)))
    g4 = 1.0 + (tv / (Lam * su * P[:, 0])) ** 4
    sf = tv * g4 / r0
    its = g4 * np.sqrt(np.sqrt(g4)) / r0
    return ce * s * su * its * kt._PAIR_MIN > (sf + kt._PLASTIC_MARGIN) * kt._PLASTIC_SAFETY * np.minimum(sf, 1.0)


def test_plastic_pair_shortcut_is_bit_identical_to_the_full_pair(monkeypatch):
    """A mirror pair whose two nodes both lie beyond the build-up (E - sigma_f > 41 for the smaller E, bounded from
    below before the pair constants by coth sigma_f >= 1 / min(sigma_f, 1)) contributes sigma_f per node without its
    pair constants (exp, log, tables): the full pair gives sigma_f to the last bit there (both corrections of
    _buildup_nb skipped), so the function must not change at all.  Checked bit for bit against the same kernel
    compiled without the shortcut, over the regime grid of the bound test above (every oil, 27-230 degC, 100-5000 N,
    +-1-100 m/s, every strip, slide-roll +-1e-4 ... 0.3) and dense slip scans through the shortcut's switch."""
    monkeypatch.setattr(kt, "_PLASTIC_MARGIN", math.inf)
    full = numba.njit(error_model="numpy")(kt.eyring_strip_mu_nb.py_func)
    full(_coefficients("4106", 130.0, 700.0, 16.0, "inner"), 0.01, 0.0)  # compiled with the shortcut off
    monkeypatch.undo()
    taken = total = 0
    S = np.geomspace(1e-4, 0.3, 41)
    for oil in OILS:
        for T_C in (27.0, 130.0, 230.0):
            for W in (100.0, 700.0, 5000.0):
                for U in (1.0, -16.0, 100.0):
                    for contact in CONTACTS:
                        c = _coefficients(oil, T_C, W, U, contact)
                        for u in QU:
                            for s in S:
                                for sg in (1.0, -1.0):
                                    assert kt.eyring_strip_mu_nb(c, sg * s, u) == full(c, sg * s, u), (oil, T_C, W, U, u, s)
                                pl = _plastic_pairs(c, s, u)
                                taken += int(pl.sum())
                                total += pl.size
    assert 0.2 < taken / total < 0.95, taken / total  # both paths exercised
    for oil, T_C, W, U in SCANS:  # dense scans: pairs switch between the shortcut and the full pair
        c = _coefficients(oil, T_C, W, U, "inner")
        switched = 0
        prev = None
        for s in np.geomspace(1e-4, 0.3, 4000):
            for sg in (1.0, -1.0):
                assert kt.eyring_strip_mu_nb(c, sg * s, QU[1]) == full(c, sg * s, QU[1]), (oil, s)
            pl = _plastic_pairs(c, s, QU[1])
            switched += 0 if prev is None else int(np.sum(pl != prev))
            prev = pl
        assert switched > 0
