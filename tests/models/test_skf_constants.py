"""SKF 2004 frictional-moment constants: what could be checked against a source, and what could not (skf-check).

No copy of the SKF catalogue's geometry-constants table (R1..S3 per series) was reachable from this project
(docs/life.md, "SKF constants: verification").  What these tests can assert honestly:

* the formula *structure* of catalogue Table 2a (read on yumpu "SKF - Rolling Bearings" p. 106), checked by
  numerical log-derivatives of our G_rr, G_sl -- an independent check of the exponents, not of the constants;
* the p. 105 sliding-coefficient constants (phi_bl, mu_bl, mu_EHL), read on that copy;
* the angular-contact rows (72/73 B, 72/73 AC, other) against the secondary public transcription they were
  taken from, and the row selection by designation suffix / nominal contact angle;
* every row stays flagged as not checked against an SKF copy until someone does.
"""

from __future__ import annotations

import math

import pytest

from hsbearing.models.friction import skf2004


def _dlog(f, x, h=1e-6):
    """Central finite-difference d ln f / d ln x."""
    return (math.log(f(x * math.exp(h))) - math.log(f(x * math.exp(-h)))) / (2.0 * h)


C72 = skf2004.ACBB_SERIES["72 AC"]


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


# SECONDARY source, not the catalogue: a public per-series transcription of the published SKF friction-model
# tables (module note [5] of skf2004.py) -- R1, R2, R3, S1, S2, S3.  Its "other single-row" row is also used by a
# second independent implementation (with K_Z 4.4).  Agreement lowers the chance of a typo in OUR copy; it does
# not verify against SKF (docs/life.md, "SKF constants: verification").
SECONDARY_ACBB = {
    "72 B": (4.33e-7, 2.02, 2.44e-12, 1.82e-2, 0.71, 2.44e-12),
    "73 B": (4.54e-7, 2.02, 1.84e-12, 1.64e-2, 0.71, 1.84e-12),
    "72 AC": (3.58e-7, 3.64, 3.55e-12, 1.14e-2, 1.55, 3.55e-12),
    "73 AC": (3.48e-7, 3.64, 1.66e-12, 9.85e-3, 1.55, 1.66e-12),
    "other": (5.03e-7, 1.97, 1.90e-12, 1.30e-2, 0.68, 1.91e-12),
}


@pytest.mark.parametrize("row", sorted(SECONDARY_ACBB))
def test_acbb_rows_match_the_secondary_transcription(row):
    c = skf2004.ACBB_SERIES[row]
    assert (c.R1, c.R2, c.R3, c.S1, c.S2, c.S3) == pytest.approx(SECONDARY_ACBB[row], rel=1e-12)
    assert skf2004.K_Z_ACBB == pytest.approx(4.4)


def test_acbb_row_selection():
    """Suffix first (BE/BECBP -> B, AC/ACCBM -> AC), else the nominal contact angle (40 / 25 deg), else "other";
    only series 72 and 73 are tabulated.  The default case (zhang2016: 7206, 25 deg) uses 72 AC."""
    row = skf2004.angular_contact_row_of
    assert row("7206 BE") == "72 B" and row("7306 BECBP") == "73 B" and row("7206-B") == "72 B"
    assert row("7206 AC") == "72 AC" and row("7310 ACCBM") == "73 AC"
    assert row("7206", math.radians(40.0)) == "72 B" and row("7306", math.radians(25.0)) == "73 AC"
    assert row("7206", math.radians(15.0)) == "other" and row("7206") == "other"
    assert row("7206 AC", math.radians(40.0)) == "72 AC"          # the designation wins over the angle
    from hsbearing.case import load_case

    case = load_case("zhang2016")
    assert row(case.bearing.designation, case.bearing.contact_angle) == "72 AC"
    from hsbearing.case import CaseError

    for bad in ("7006", "7406 B", "6206", ""):
        with pytest.raises(CaseError, match="bearing.designation"):
            row(bad, None, "x.toml")


def test_dgbb_62_row_matches_two_secondary_transcriptions():
    """SECONDARY sources: two public SKF-model implementations (one a per-series constants dict, the other a
    worked 6206 example) list series 62/622 as R1 3.9e-7, R2 1.7, S1 3.23e-3, S2 36.5 (S1, S2 are also
    checked against dgbb_prl Table 2 in tests/systems/deep_groove/test_friction_dgbb.py); K_Z = 3.1 for deep-groove ball
    bearings in the secondary sources of the angular-contact rows."""
    c = skf2004.DGBB_SERIES["62"]
    assert (c.R1, c.R2, c.S1, c.S2) == pytest.approx((3.9e-7, 1.7, 3.23e-3, 36.5), rel=1e-12)
    assert skf2004.K_Z_DGBB == pytest.approx(3.1)


def test_rows_stay_flagged_as_secondary():
    """No angular-contact row has been read from an SKF copy: every row must carry a status saying so until
    someone checks it against the catalogue (then update the status, this test and docs/life.md)."""
    assert set(skf2004.ACBB_CONSTANTS_STATUS) == set(skf2004.ACBB_SERIES)
    assert all(v.startswith("not checked against an SKF copy") for v in skf2004.ACBB_CONSTANTS_STATUS.values())
    assert "4.97e-7" not in repr(skf2004.ACBB_SERIES)     # the unsupported from-memory 73 row is gone
