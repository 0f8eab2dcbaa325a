"""The inlet-shear-heating factor phi_T of models/ehl.py against our own thermal inlet solution.

Reference: tests/helpers/thermal_inlet_reference.py (Murch & Wilson 1975 thermal inlet, sliding as Wilson & Sheu
1983, solved from scratch; imports nothing of hsbearing).  Tolerances were written in docs/power_loss.md
("Inlet heating: proof against our own thermal inlet") before the comparison over the regime.

Default tier: the solver against its own limits (closed forms of the rigid inlet and of the heated Couette film,
Grubin's fit, L -> 0, grid convergence, the slip's sign) and a few points of the comparison.  Slow tier: the whole
regime grid (tools/investigations/thermal_inlet_comparison.py).
"""

from __future__ import annotations

import math
import sys
from pathlib import Path

import numpy as np
import pytest

sys.path.insert(0, str(Path(__file__).resolve().parents[1] / "helpers"))

import thermal_inlet_reference as ref  # noqa: E402

from hsbearing.models import ehl  # noqa: E402

R, EP = 4.0e-3, 2.26e11


def test_rigid_inlet_equals_its_closed_form():
    """Isothermal rigid parabolic inlet (b = 0): h0 = (3 pi sqrt(2)/4 alpha eta0 u sqrt(R))^(2/3), to 1e-6."""
    for eta0, u, alpha in ((0.01, 10.0, 1.3e-8), (0.001, 100.0, 2.0e-8), (0.05, 1.0, 1.0e-8)):
        h = ref.inlet_h0(eta0, alpha, u, R, 0.0, gap="rigid")
        assert h == pytest.approx(ref.rigid_isothermal_h0(eta0, alpha, u, R), rel=1e-6)


@pytest.mark.parametrize("ph", [
    pytest.param(0.5e9, marks=pytest.mark.xfail(strict=True, reason="measured: -3.1 % at GU = 4.9e-7, W = 3.1e-5 "
                                                "(the lightest load; -1.1 % and -2.1 % at the two other speeds)")),
    1.5e9, 3.0e9])
def test_hertz_inlet_gives_grubins_result(ph):
    """Isothermal Ertel-Grubin inlet against Grubin's fit 1.95 R (GU)^(8/11) W^(-1/11) (Dowson & Higginson,
    Ch. 5): within 3 %, the fit's own accuracy (tolerance in docs/power_loss.md)."""
    b = 4.0 * R * ph / EP
    w = math.pi * b * ph / 2.0
    for eta0, u in ((0.01, 10.0), (0.003, 50.0), (0.03, 2.0)):
        h = ref.inlet_h0(eta0, 1.3e-8, u, R, b)
        assert h == pytest.approx(ref.grubin_h0(eta0, 1.3e-8, u, R, EP, w), rel=0.03)


def test_heated_couette_film_equals_bratu_closed_form():
    """At r = h0/h = 1 with sliding the film is a heated Couette film (no pressure flow by symmetry); the exact
    solution of phi'' = -L sigma^2 e^phi, phi(0) = phi(1) = 0 is phi = ln(cosh^2(c/2) sech^2(c (z - 1/2))), with
    s = sigma sinh(c) / c and L sigma^2 = 2 c^2 / cosh^2(c/2).  Gb = 0 and sigma checked through the flux."""
    s = 0.3
    for c in (0.5, 2.0, 5.0):
        sigma = s * c / math.sinh(c)
        L = 2.0 * c * c / (math.cosh(0.5 * c) ** 2 * sigma**2)
        z, w = ref._grid(256)
        phi, sig0, Gb = ref._newton(np.array([1.0]), 0.0, s, 256, np.zeros((1, 257)), np.array([s]), np.array([0.0]))
        for Lk in np.geomspace(1e-2, L, 30):
            phi, sig0, Gb = ref._newton(np.array([1.0]), Lk, s, 256, phi, sig0, Gb)
        assert abs(Gb[0]) < 1e-9
        assert sig0[0] == pytest.approx(sigma, rel=1e-4)
        exact = np.log(np.cosh(0.5 * c) ** 2 / np.cosh(c * (z - 0.5)) ** 2)
        assert np.max(np.abs(phi[0] - exact)) < 1e-4 * max(1.0, exact.max())


def test_local_energy_balance_closes():
    """Heat generated in the film (int L sigma^2 e^phi) = heat conducted into both walls (phi'(0) - phi'(1)),
    second-order one-sided differences: an independent check of the discrete energy equation (1e-3)."""
    n = 256
    z, w = ref._grid(n)
    for s in (0.0, 0.3):
        for L in (1.0, 30.0):
            Ls, _ = ref.local_factor_table(np.array([0.2, 0.8]), L, s, n=n)
            # re-run the last step to get the fields
            r = np.array([0.2, 0.8])
            Gb = 12.0 * (1.0 - r)
            phi, sig0 = np.zeros((2, n + 1)), s - 0.5 * Gb
            for Lk in Ls:
                phi, sig0, Gb = ref._newton(r, Lk, s, n, phi, sig0, Gb)
            sig = sig0[:, None] + Gb[:, None] * z[None, :]
            gen = (w * L * sig**2 * np.exp(phi)).sum(axis=1)
            h = 1.0 / n
            d0 = (-3 * phi[:, 0] + 4 * phi[:, 1] - phi[:, 2]) / (2 * h)
            d1 = (3 * phi[:, -1] - 4 * phi[:, -2] + phi[:, -3]) / (2 * h)
            assert d0 - d1 == pytest.approx(gen, rel=1e-3)


def test_ratio_tends_to_one_and_falls_with_heating():
    """ratio -> 1 as L -> 0 (> 0.999 at L = 1e-3), falls monotonically with L, same for both rolling senses."""
    b = 4.0 * R * 1.5e9 / EP
    beta, k, u, alpha = 0.03, 0.1, 10.0, 1.3e-8
    out = []
    for L in (1e-3, 1.0, 30.0):
        eta0 = L * k / (beta * u * u)
        out.append(ref.thermal_ratio(eta0, alpha, beta, k, u, 0.0, R, b, n=64)["ratio"])
    assert out[0] > 0.999
    assert out[0] > out[1] > out[2]
    # rolling the other way: the inlet is mirrored, the ratio the same (L ~ u^2)
    eta0 = 1.0 * k / (beta * u * u)
    assert ref.thermal_ratio(eta0, alpha, beta, k, -u, 0.0, R, b, n=64)["ratio"] == out[1]


def test_grid_convergence_and_slip_sign():
    """Local factor: n = 64 vs 256 within 1e-3 (second order: the 128 -> 256 change is ~1/4 of 64 -> 128);
    ratio: quadrature points and interpolation nodes doubled change it by < 1e-5; s -> -s: same factor."""
    r = np.array([0.05, 0.5, 0.9])
    f64, f128, f256 = (ref.local_factor(r, 30.0, 0.2, n=n) for n in (64, 128, 256))
    assert np.max(np.abs(f64 / f256 - 1.0)) < 1e-3
    assert np.max(np.abs(f128 - f256)) < 0.35 * np.max(np.abs(f64 - f128))
    assert np.array_equal(ref.local_factor(r, 30.0, -0.2, n=64), f64)
    b = 4.0 * R * 1.0e9 / EP
    eta0 = 10.0 * 0.1 / (0.03 * 100.0)
    a = ref.thermal_ratio(eta0, 1.3e-8, 0.03, 0.1, 10.0, 0.1, R, b, n=64)["ratio"]
    c = ref.thermal_ratio(eta0, 1.3e-8, 0.03, 0.1, 10.0, 0.1, R, b, n=64, nr=96, nq=400)["ratio"]
    assert a == pytest.approx(c, rel=1e-5)


# --- the physical traction law's film sees the inlet factor (friction.inlet_heating = on) ---------------------


def test_eyring_film_and_coefficients_carry_phi_T():
    """eyring.central_film x phi_T; the per-contact coefficients with phi_T equal those of a film phi_T h
    (lv = ln(eta U / (h tau0)) shifts by -ln phi_T); the numba twin equals the Python evaluation (1e-13)."""
    from hsbearing.models.ball_bearing import kernel_io as kio
    from hsbearing.models.traction import EYRING_LAW_ID
    from hsbearing.models.traction import _kernels as kt
    from hsbearing.models.traction import eyring as ey

    Rx, k, eta, alpha = 3.0e-3, 8.0, 0.01, 1.1e-8
    tau0 = ey.eyring_stress_default(0.047, alpha)
    for phi in (1.0, 0.7, 0.2):
        for W, U in ((100.0, 5.0), (2000.0, -60.0)):
            a = 1.0e-4 * W ** (1.0 / 3.0)
            h1 = ey.central_film(W, U, EP, Rx, k, eta, alpha)
            assert ey.central_film(W, U, EP, Rx, k, eta, alpha, phi) == pytest.approx(phi * h1, rel=1e-15)
            c1 = ey.contact_coefficients(W, U, EP, Rx, k, a, eta, alpha, tau0, 0.047, 0.3e9)
            cp = ey.contact_coefficients(W, U, EP, Rx, k, a, eta, alpha, tau0, 0.047, 0.3e9, phi)
            assert cp[2] == pytest.approx(c1[2] - math.log(phi), abs=1e-12)
            vals = {n: 0.0 for n in kio.PARAM_GROUP}
            P = kio.pack(vals)
            for name, v in (("law_id", EYRING_LAW_ID), ("Ep", EP), ("eta_in", eta), ("alpha", alpha),
                            ("tau0", tau0), ("Lambda", 0.047), ("G", 0.3e9)):
                kio.set_value(P, name, v)
            cn = kt.traction_coefficients_nb(P[0], W, U, Rx, k, a, phi)
            np.testing.assert_allclose(cn, cp, rtol=1e-13)


@pytest.fixture(scope="module")
def fast_case():
    from hsbearing.case import load_case

    return load_case("zhang2016").with_overrides(**{"operating.inner_speed": "40000 rpm"})


def test_kernel_passes_the_factor_to_the_physical_law_only(fast_case):
    """With the option on, the seed law's traction is unchanged (only F_R moves, tests/models/test_inlet_heating.py)
    and the physical law's traction moves (its film is phi_T h at slip 0); off: both bit for bit as before."""
    from hsbearing.models.ball_bearing.kernel import AUX_INDEX
    from hsbearing.systems.angular_contact.dynamics import build_model

    cols = [AUX_INDEX[c] for c in ("T_roll_i", "T_roll_o", "T_trans_i", "T_trans_o", "P_trac_i", "P_trac_o")]

    def aux(case):
        m = build_model(case)
        return m.outputs(m.y0)[0][:, cols]

    seed_off, seed_on = aux(fast_case), aux(fast_case.with_overrides(**{"friction.inlet_heating": "on"}))
    assert np.array_equal(seed_off, seed_on)
    ey_case = fast_case.with_overrides(**{"lubricant.traction_law": "eyring"})
    ey_off, ey_on = aux(ey_case), aux(ey_case.with_overrides(**{"friction.inlet_heating": "on"}))
    assert not np.allclose(ey_off, ey_on, rtol=1e-6)
    assert np.all(np.isfinite(ey_on))


# --- phi_T of models/ehl.py and the Murch-Wilson curve against the reference (tolerances: docs/power_loss.md) ---


def _row(oil, Tc, u, ph, s):
    sys.path.insert(0, str(Path(__file__).resolve().parents[2] / "tools" / "investigations"))
    import thermal_inlet_comparison as cmp

    return cmp.case_row(oil, Tc, u, ph, s)


def test_gupta_factor_reduces_to_the_murch_wilson_curve():
    """Literature against literature: at p_h/E' -> 0 and s = 0 the Gupta et al. 1992 factor (ehl.py [4]) is the
    published Murch & Wilson (1975) curve 3.94 / (3.94 + L^0.62) within 10 % for L = 0.01-1000 (the two fits of
    the same inlet analysis; measured: 7 % at most, at L ~ 100)."""
    L = np.geomspace(0.01, 1000.0, 41)
    gupta = ehl.thermal_reduction_factor(L, 0.0, EP, 0.0)
    np.testing.assert_allclose(gupta, ref.murch_wilson_curve(L), rtol=0.10)


@pytest.mark.parametrize("oil,Tc,u", [("4109", 130.0, 10.0), ("4050", 230.0, 30.0), ("4109", 230.0, 1.0)])
def test_phi_T_holds_where_the_inlet_heats_little(oil, Tc, u):
    """L <= 0.05 (hot oil or slow rolling): phi_T within the 10 % tolerance of the reference at 0.5 and 3 GPa,
    s = 0 and 0.3 (measured: 0-10 % below it)."""
    for ph in (0.5e9, 3.0e9):
        for s in (0.0, 0.3):
            r = _row(oil, Tc, u, ph, s)
            assert r["L"] <= 0.06
            assert abs(r["err_phi_T"]) <= 0.10


@pytest.mark.xfail(strict=True, reason="measured: phi_T 0.453 against the reference 0.818 (-45 %) at 4109, 130 degC, "
                   "100 m/s, 3 GPa, s = 0.3 (L = 2.3); -17 % at 0.5 GPa, s = 0 -- the Gupta factor reduces the film "
                   "far more than our thermal inlet (docs/power_loss.md)")
def test_phi_T_within_tolerance_at_bearing_speeds():
    for ph, s in ((0.5e9, 0.0), (3.0e9, 0.3)):
        r = _row("4109", 130.0, 100.0, ph, s)
        assert abs(r["err_phi_T"]) <= 0.10


@pytest.mark.xfail(strict=True, reason="measured: reference 0.668 (rigid inlet) and 0.653 (Hertz inlet, 0.5 GPa) "
                   "against the Murch-Wilson curve 0.486 at L = 10, s = 0 (+37 %, +34 %; 0.5 GPa, R = 4 mm): our reading of their "
                   "inlet (reduced dissipation) heats less than theirs (docs/power_loss.md)")
def test_reference_reproduces_the_murch_wilson_curve():
    beta, k, u, alpha = 0.03, 0.1, 10.0, 1.3e-8
    eta0 = 10.0 * k / (beta * u * u)
    for b in (0.0, 4.0 * R * 0.5e9 / EP):
        gap = "rigid" if b == 0.0 else "hertz"
        r = ref.thermal_ratio(eta0, alpha, beta, k, u, 0.0, R, b, gap=gap, n=64)["ratio"]
        assert r == pytest.approx(float(ref.murch_wilson_curve(10.0)), rel=0.10)


@pytest.mark.slow
@pytest.mark.xfail(strict=True, reason="measured over the regime grid (tools/investigations/thermal_inlet_comparison.py, "
                   "144 points): 75 of 144 within 10 %, phi_T below the reference everywhere, worst -84 % "
                   "(4109 27 degC 100 m/s 3 GPa: 0.050 clipped against 0.321)")
def test_phi_T_against_the_reference_over_the_regime():
    sys.path.insert(0, str(Path(__file__).resolve().parents[2] / "tools" / "investigations"))
    import thermal_inlet_comparison as cmp

    rows = cmp.grid()
    err = np.array([r["err_phi_T"] for r in rows])
    assert np.all(err <= 0.0)  # the direction holds everywhere: phi_T never above the reference
    assert np.all(np.abs(err) <= 0.10)


def _full(L, ph, s=0.0):
    beta, k, u, alpha = 0.03, 0.1, 10.0, 1.3e-8
    eta0 = L * k / (beta * u * u)
    return ref.full_dissipation_ratio(eta0, alpha, beta, k, u, s, R, 4.0 * R * ph / EP, ph, nv=200)["ratio"]


def test_full_dissipation_reference_meets_the_murch_wilson_curve():
    """With the heating of the real viscosity (e^(alpha p)) the reference meets the published Murch & Wilson
    (1975) curve 3.94 / (3.94 + L^0.62) within the 10 % set in docs/power_loss.md: 3 GPa, L = 10, s = 0
    (measured 0.484 against 0.486)."""
    assert _full(10.0, 3.0e9) == pytest.approx(float(ref.murch_wilson_curve(10.0)), rel=0.10)


@pytest.mark.slow
@pytest.mark.xfail(strict=True, reason="measured: 0.537 against 0.486 at 0.5 GPa, L = 10 (+10.5 %); 0.870 against "
                   "0.798 at L = 1 (+9 %); 0.849 / 0.798 at 3 GPa, L = 1 (+6 %)")
def test_full_dissipation_reference_meets_the_curve_at_low_pressure():
    for L, ph in ((1.0, 3.0e9), (1.0, 0.5e9), (10.0, 0.5e9)):
        assert _full(L, ph) == pytest.approx(float(ref.murch_wilson_curve(L)), rel=0.10)
