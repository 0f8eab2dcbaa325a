"""SKF 2004 frictional-moment constants: what could be checked against a source, and what could not (skf-check).

No copy of the SKF catalogue's geometry-constants table (R1..S3 per series) was reachable from this project
(docs/life.md, "SKF constants: verification").  What these tests can assert honestly:

* the formula *structure* of catalogue Table 2a (read on yumpu "SKF - Rolling Bearings" p. 106), checked by
  numerical log-derivatives of our G_rr, G_sl -- an independent check of the exponents, not of the constants;
* the p. 105 sliding-coefficient constants (phi_bl, mu_bl, mu_EHL), read on that copy;
* the 72-series angular-contact row against ONE secondary public transcription (not the catalogue);
* the 73-series row stays flagged unverified until someone checks it.
"""

from __future__ import annotations

import math

import numpy as np
import pytest

from hsbearing.models.friction import skf2004


def _dlog(f, x, h=1e-6):
    """Central finite-difference d ln f / d ln x."""
    return (math.log(f(x * math.exp(h))) - math.log(f(x * math.exp(-h)))) / (2.0 * h)


C72 = skf2004.ACBB_SERIES["72"]


def test_acbb_G_rr_exponents_follow_table_2a():
    """Table 2a (yumpu p. 106): G_rr = R1 d_m^1.97 (F_r + F_g + R2 F_a)^0.54, F_g = R3 d_m^4 n^2.
    Log-derivatives of our function: 1.97 in d_m at n = 0; 0.54 in F_r when F_a = n = 0; with F_r = F_a = 0 the
    speed term alone gives G_rr ~ d_m^(1.97 + 4*0.54) n^(2*0.54)."""
    g = skf2004.rolling_variable_G_rr_angular_contact
    assert _dlog(lambda dm: float(g(500.0, 800.0, dm, 0.0, C72)), 46.0) == pytest.approx(1.97, abs=1e-6)
    assert _dlog(lambda fr: float(g(fr, 0.0, 46.0, 0.0, C72)), 700.0) == pytest.approx(0.54, abs=1e-6)
    assert _dlog(lambda n: float(g(0.0, 0.0, 46.0, n, C72)), 14000.0) == pytest.approx(1.08, abs=1e-6)
    assert _dlog(lambda dm: float(g(0.0, 0.0, dm, 14000.0, C72)), 46.0) == pytest.approx(1.97 + 2.16, abs=1e-6)
    # R2 weights F_a against F_r: G_rr(F_r = R2 F, 0) == G_rr(0, F_a = F) at n = 0
    assert float(g(C72.R2 * 1000.0, 0.0, 46.0, 0.0, C72)) == pytest.approx(float(g(0.0, 1000.0, 46.0, 0.0, C72)), rel=1e-12)
    # F_g enters with R3: F_r = R3 d_m^4 n^2 at n = 0 equals the speed term alone
    fg = C72.R3 * 46.0**4 * 14000.0**2
    assert float(g(fg, 0.0, 46.0, 0.0, C72)) == pytest.approx(float(g(0.0, 0.0, 46.0, 14000.0, C72)), rel=1e-12)


def test_acbb_G_sl_exponents_follow_table_2a():
    """Table 2a: G_sl = S1 d_m^0.26 ((F_r + F_g)^(4/3) + S2 F_a^(4/3)), F_g = S3 d_m^4 n^2."""
    g = skf2004.sliding_variable_G_sl_angular_contact
    assert _dlog(lambda dm: float(g(500.0, 800.0, dm, 0.0, C72)), 46.0) == pytest.approx(0.26, abs=1e-6)
    assert _dlog(lambda fa: float(g(0.0, fa, 46.0, 0.0, C72)), 800.0) == pytest.approx(4.0 / 3.0, abs=1e-6)
    assert _dlog(lambda fr: float(g(fr, 0.0, 46.0, 0.0, C72)), 800.0) == pytest.approx(4.0 / 3.0, abs=1e-6)
    assert _dlog(lambda n: float(g(0.0, 0.0, 46.0, n, C72)), 14000.0) == pytest.approx(8.0 / 3.0, abs=1e-6)
    # S2 weights F_a^(4/3) against F_r^(4/3); S3 (not R3) builds the sliding F_g
    assert float(g(0.0, 1000.0, 46.0, 0.0, C72)) / float(g(1000.0, 0.0, 46.0, 0.0, C72)) == pytest.approx(C72.S2, rel=1e-12)
    fg = C72.S3 * 46.0**4 * 14000.0**2
    assert float(g(fg, 0.0, 46.0, 0.0, C72)) == pytest.approx(float(g(0.0, 0.0, 46.0, 14000.0, C72)), rel=1e-12)


def test_sliding_coefficient_constants_follow_catalogue_p105():
    """yumpu "SKF - Rolling Bearings" p. 105: phi_bl = 1 / e^(2.6e-8 (n nu)^1.4 d_m); mu_bl ~ 0.15;
    mu_EHL = 0.05 for mineral oils (our defaults)."""
    n, nu, dm = 3000.0, 20.0, 46.0
    assert float(skf2004.boundary_weighting_phi_bl(n, nu, dm)) == pytest.approx(math.exp(-2.6e-8 * (n * nu) ** 1.4 * dm), rel=1e-12)
    phi = float(skf2004.boundary_weighting_phi_bl(n, nu, dm))
    assert float(skf2004.sliding_coefficient_mu_sl(n, nu, dm)) == pytest.approx(phi * 0.15 + (1 - phi) * 0.05, rel=1e-12)
    assert float(skf2004.sliding_coefficient_mu_sl(0.0, nu, dm)) == pytest.approx(0.15)      # boundary limit
    assert float(skf2004.sliding_coefficient_mu_sl(1e6, nu, dm)) == pytest.approx(0.05)      # full-film limit


def test_acbb_72_row_matches_a_secondary_transcription():
    """SECONDARY source, not the catalogue: an independent open-source Python bearing-friction model
    (class ``AngularContactCalculation``) uses R1 5.03e-7, R2 1.97, R3 1.90e-12, S1 1.30e-2, S2 0.68,
    S3 1.91e-12 and K_Z 4.4 for single-row angular contact ball bearings.  Agreement of two transcriptions
    lowers the chance of a typo; it does not verify against SKF (docs/life.md)."""
    secondary = dict(R1=5.03e-7, R2=1.97, R3=1.90e-12, S1=1.30e-2, S2=0.68, S3=1.91e-12)
    for k, v in secondary.items():
        assert getattr(C72, k) == pytest.approx(v, rel=1e-12), k
    assert skf2004.K_Z_ACBB == pytest.approx(4.4)


def test_dgbb_62_row_matches_two_secondary_transcriptions():
    """SECONDARY sources: two public SKF-model implementations (one a per-series constants dict, the other a
    worked 6206 example) list series 62/622 as R1 3.9e-7, R2 1.7, S1 3.23e-3, S2 36.5 (S1, S2 are also
    checked against seed 003 Table 2 in tests/test_friction_dgbb.py); K_Z = 3.1 for deep-groove ball
    bearings in the angular-contact source above."""
    c = skf2004.DGBB_SERIES["62"]
    assert (c.R1, c.R2, c.S1, c.S2) == pytest.approx((3.9e-7, 1.7, 3.23e-3, 36.5), rel=1e-12)
    assert skf2004.K_Z_DGBB == pytest.approx(3.1)


def test_unverified_rows_stay_flagged():
    """The 73-series row was typed from memory and no source was found: it must stay marked unverified
    (module docstring and ACBB_CONSTANTS_STATUS) until someone checks it against the catalogue; every row
    has a status."""
    assert set(skf2004.ACBB_CONSTANTS_STATUS) == set(skf2004.ACBB_SERIES)
    assert skf2004.ACBB_CONSTANTS_STATUS["73"].startswith("unverified")
    assert "not checked against the SKF catalogue" in skf2004.ACBB_CONSTANTS_STATUS["72"]
    assert "UNVERIFIED" in skf2004.__doc__ and "NOT checked against a catalogue" in skf2004.__doc__
    assert np.isfinite([getattr(skf2004.ACBB_SERIES["73"], k) for k in ("R1", "R2", "R3", "S1", "S2", "S3")]).all()
