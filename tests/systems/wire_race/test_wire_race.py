"""Wire-race ball bearing, preload vs starting torque (issue 8, Shan et al. 2010: Shan et al. 2010).

Tiers: (1) literature -- Table 2 and Table 3 of Shan et al. 2010 (tests/data/shan2010_preload_table2.csv),
each test names the table; (2) the paper's printed equations vs our implementation; (3) physical
invariants; (4) CLI contract.  Known, documented deviations (docs/validation/wire_race.md) are
asserted as such, with the bound that would reveal a change.
"""

from __future__ import annotations

import math
import subprocess
import sys
from pathlib import Path

import numpy as np
import pandas as pd
import pytest

from hsbearing import load_case
from hsbearing.case import CaseError
from hsbearing.models.hertz import reduced_modulus
from hsbearing.results import open_run
from hsbearing.systems.wire_race import (
    model as wr,  # the wire-race system (closed forms: hsbearing.models.friction.wire_race)
)

DATA = Path(__file__).resolve().parents[2] / "data"
T2 = pd.read_csv(DATA / "shan2010_preload_table2.csv", comment="#")
ALPHA = math.pi / 4  # Table 1
Z = 90  # Table 1
G_O = 806.27  # Table 1 [N]


@pytest.fixture(scope="module")
def case():
    return load_case("shan2010_wire_race")


def table2_stiffness():
    """K implied by Table 2 of Shan et al. 2010 itself: mean of F_j / delta_j^1.5 over its rows (inner j=1,2; outer j=3,4)."""
    K_i = np.mean(np.r_[T2.F1_N / (T2.delta1_um * 1e-6) ** 1.5, T2.F2_N / (T2.delta2_um * 1e-6) ** 1.5])
    K_o = np.mean(np.r_[T2.F1_N / (T2.delta3_um * 1e-6) ** 1.5, T2.F2_N / (T2.delta4_um * 1e-6) ** 1.5])
    return float(K_i), float(K_o)


# ----------------------------------------------------------------------------- Table 2


def test_table2_consistency_forces_with_the_stiffness_table2_implies(case):
    """CONSISTENCY check, not validation: the stiffness is fitted on Table 2 itself, then Table 2 is reproduced.
    Table 2 (Shan et al. 2010): F1, F2, delta_1..4 within 1 % from the preload column, Eqs. 7 and 10.

    The stiffness K_i, K_o is the one Table 2 itself implies (F_j/delta_j^1.5 of its own columns),
    because the paper's E*, R_e, F_2(e) come from an earlier paper we do not have (see the next test
    for our Hertz value).  This checks the preload definition (Eq. 10: four deformations, cos alpha),
    the framework-weight split (Eq. 7) and the inversion, against every row.
    """
    K = table2_stiffness()
    c = wr.contacts(case, T2.delta_um.values * 1e-6, stiffness=K)
    np.testing.assert_allclose(c.F1, T2.F1_N, rtol=0.01)
    np.testing.assert_allclose(c.F2, T2.F2_N, rtol=0.01)
    np.testing.assert_allclose(c.F3, T2.F1_N, rtol=0.01)  # Table 2: F3 = F1 (below Eq. 7)
    np.testing.assert_allclose(c.F4, T2.F2_N, rtol=0.01)
    for j in (1, 2, 3, 4):
        np.testing.assert_allclose(getattr(c, f"delta{j}") * 1e6, T2[f"delta{j}_um"], rtol=0.01, err_msg=f"delta{j}")
    # the split F2 - F1 = G_o / (Z cos(pi/4)) = 12.67 N of Table 2 (Eq. 7)
    np.testing.assert_allclose(c.F2 - c.F1, G_O / (Z * math.sin(ALPHA)), rtol=1e-12)
    np.testing.assert_allclose((T2.F2_N - T2.F1_N).values, 12.67, atol=0.021)


def test_table2_deformations_with_our_hertz_stiffness(case):
    """Table 2 (Shan et al. 2010): delta_1..4 within 1 % from rows >= 20 um with OUR exact-Hertz K_i, K_o.

    The deformations are almost independent of K (their sum is fixed by the preload, Eq. 10); only the
    10 um row, where the framework weight splits the two diagonals strongly, moves by 1.5 %.
    """
    c = wr.contacts(case, T2.delta_um.values * 1e-6)
    rows = T2.delta_um.values >= 20
    for j in (1, 2, 3, 4):
        np.testing.assert_allclose(getattr(c, f"delta{j}")[rows] * 1e6, T2[f"delta{j}_um"][rows], rtol=0.01, err_msg=f"delta{j}")
        np.testing.assert_allclose(getattr(c, f"delta{j}") * 1e6, T2[f"delta{j}_um"], rtol=0.02, err_msg=f"delta{j}")


def test_table2_forces_with_our_hertz_stiffness_documented_deviation(case):
    """KNOWN DEVIATION (docs/validation/wire_race.md): exact Hertz with the Table 1 data gives K 15 % above
    the K implied by Table 2, so F1, F2 are 15-18 % above Table 2.  No reading of E*, R_e, F_2(e) with the
    Table 1 data reproduces both the delta and the P0 columns (see the docs); this test pins the size of
    the discrepancy so that a change in the model shows up.
    """
    K_paper = np.mean(table2_stiffness())
    c = wr.contacts(case, T2.delta_um.values * 1e-6)
    assert 1.14 < np.mean([c.K_i, c.K_o]) / K_paper < 1.17
    ratio = np.r_[c.F1 / T2.F1_N, c.F2 / T2.F2_N]
    assert np.all((ratio > 1.13) & (ratio < 1.19)), ratio


def test_table2_pressures(case):
    """Table 2 (Shan et al. 2010): P0j.  At the paper's own forces our exact-Hertz p_max is 3.7 % above P0j
    (KNOWN DEVIATION, docs/validation/wire_race.md; the requested 2 % is not met), and P0j scales as F^(1/3)
    in both -- the ratio is the same on every row to 0.1 %."""
    c = wr.contacts(case, T2.delta_um.values * 1e-6, stiffness=table2_stiffness())
    for j in (1, 2, 3, 4):
        ratio = getattr(c, f"p_max{j}") / (T2[f"P0{j}_GPa"].values * 1e9)
        assert np.ptp(ratio) < 0.0015, (j, ratio)
        assert 1.030 < ratio.mean() < 1.045, (j, ratio.mean())


ROWS = list(T2.itertuples(index=False))


@pytest.mark.parametrize(
    "row",
    [pytest.param(r, id=f"{r.delta_um:g}um",
                  marks=[pytest.mark.xfail(strict=True, reason="Table 2 M_sc at 100 and 120 um disagrees with Eq. 4 "
                                                                "applied to its own F1, F2 (40.81 vs 43.08, 50.63 vs 56.63)")]
                  if r.delta_um in (100, 120) else []) for r in ROWS],
)
def test_table2_calculated_torque_from_its_forces(row):
    """Table 2 (Shan et al. 2010): M_sc = Eq. 4 with Table 3's zeta and Table 2's F1, F2, within 1 % (7 of 9 rows)."""
    zeta = 1.0265e-4  # Table 3
    Msc = wr.bearing_rolling_torque(zeta, Z, row.F1_N, row.F2_N, row.F1_N, row.F2_N, ALPHA)
    assert Msc == pytest.approx(row.Msc_Nm, rel=0.01)


PAPER_ZETA_MU = {"friction.rolling_resistance": "1.0265e-4 m", "friction.unconsidered_torque": "17.3245 N*m"}  # Table 3
CONSISTENT = ~np.isin(T2.delta_um.values, (100, 120))  # rows whose M_sc agrees with Eq. 4 of their own forces


def test_table2_calculated_torque_chain_paper_stiffness(case):
    """Table 2 (Shan et al. 2010): M_sc from the preload through Eqs. 10, 7, 4 with the paper's stiffness and Table 3's
    zeta, within 1 % (rows other than 100 and 120 um, see the xfail above)."""
    c = wr.contacts(case.with_overrides(**PAPER_ZETA_MU), T2.delta_um.values * 1e-6, stiffness=table2_stiffness())
    np.testing.assert_allclose(c.rolling_torque[CONSISTENT], T2.Msc_Nm[CONSISTENT], rtol=0.01)
    np.testing.assert_allclose(c.torque - c.rolling_torque, 17.3245)  # + M_u (Table 3), Eq. 11


def test_table2_calculated_torque_chain_our_stiffness(case):
    """Table 2 (Shan et al. 2010): M_sc within 1 % with OUR Hertz stiffness and the bundled case's zeta (Eq. 12 refit
    with our forces): the torque depends on zeta * F only, which the measured torques fix."""
    c = wr.contacts(case, T2.delta_um.values * 1e-6)
    np.testing.assert_allclose(c.rolling_torque[CONSISTENT], T2.Msc_Nm[CONSISTENT], rtol=0.01)


def test_case_zeta_is_the_eq12_refit_with_our_forces(case):
    """CONSISTENCY check: zeta is fitted on Table 2.  The bundled case's zeta, M_u are Eqs. 12-13 applied to Table
    2's M_bm with this model's forces (so a
    change of the contact model that is not carried into the case fails here)."""
    fit = wr.fit_rolling_resistance(T2.delta_um.values * 1e-6, T2.Mbm_Nm.values, case, first_group=4)
    assert case.friction.rolling_resistance == pytest.approx(fit.zeta, rel=1e-4)
    assert case.friction.unconsidered_torque == pytest.approx(fit.M_u, abs=1e-3)
    # zeta * (F1 + F2) is what the measurement fixes: our zeta is the paper's / (our F / paper F)
    c = wr.contacts(case, T2.delta_um.values * 1e-6)
    force_ratio = np.mean(c.F1 + c.F2) / np.mean(T2.F1_N + T2.F2_N)
    assert fit.zeta * force_ratio == pytest.approx(1.0265e-4, rel=1e-4)


# ----------------------------------------------------------------------------- Table 3


def test_table3_zeta_and_Mu_grouping_method():
    """Table 3 (Shan et al. 2010): zeta = 1.0265e-4 m, M_u = 17.3245 N m and the group means, from the measured
    bearing torques M_bm and the F1, F2 columns of Table 2 (Eqs. 12-13, groups of 4 and 5 rows).  This reproduces
    the paper's arithmetic on its own Table 2 (a check of our Eqs. 12-13), not an independent validation."""
    fit = wr.fit_rolling_resistance(measured_torques=T2.Mbm_Nm.values, forces=(T2.F1_N.values, T2.F2_N.values),
                                    Z=Z, alpha=ALPHA, method="grouping", first_group=4)
    zeta, M_u = fit
    assert zeta == pytest.approx(1.0265e-4, rel=5e-5)  # Table 3: 1.0265e-4 m (5 digits)
    assert M_u == pytest.approx(17.3245, abs=6e-4)  # Table 3
    assert fit.M_s_I == pytest.approx(26.3600, abs=6e-5)  # Table 3
    assert fit.M_s_II == pytest.approx(75.1440, abs=6e-5)
    assert fit.F_sum_I == pytest.approx(691.5500, abs=6e-5)
    assert fit.F_sum_II == pytest.approx(4425.3220, abs=6e-5)
    assert fit.M_s_mean == pytest.approx(53.4622, abs=6e-5)


def test_table3_uses_measured_bearing_torque_and_Msm_is_Mbm_minus_Mu():
    """Table 3 (Shan et al. 2010) group means are those of the M_bm column ('measured bearing torque'); the M_sm column
    ('measured starting torque') of Table 2 is M_bm - M_u to 0.01 N m, so fitting M_sm gives the same zeta
    and M_u = 0 (documented in docs/validation/wire_race.md)."""
    np.testing.assert_allclose((T2.Mbm_Nm - T2.Msm_Nm).values, 17.3245, atol=0.011)
    fit = wr.fit_rolling_resistance(measured_torques=T2.Msm_Nm.values, forces=(T2.F1_N.values, T2.F2_N.values),
                                    Z=Z, alpha=ALPHA, first_group=4)
    assert abs(fit.M_s_I - 26.36) > 10  # Table 3's M_s^I = 26.36 is not an M_sm mean
    assert fit.zeta == pytest.approx(1.0265e-4, rel=5e-4) and abs(fit.M_u) < 0.01


def test_least_squares_fit_is_the_least_squares():
    """Option method='least_squares' (Eq. 11 by ordinary least squares): its rms residual is not above the
    grouping method's, and it passes through the centroid like Eq. 13."""
    kw = dict(measured_torques=T2.Mbm_Nm.values, forces=(T2.F1_N.values, T2.F2_N.values), Z=Z, alpha=ALPHA)
    g = wr.fit_rolling_resistance(method="grouping", first_group=4, **kw)
    ls = wr.fit_rolling_resistance(method="least_squares", **kw)
    assert ls.residual_rms <= g.residual_rms + 1e-12
    x = 2 * Z * (T2.F1_N + T2.F2_N).values * math.cos(ALPHA)
    slope, icpt = np.polyfit(x, T2.Mbm_Nm.values, 1)
    assert ls.zeta == pytest.approx(slope, rel=1e-10) and ls.M_u == pytest.approx(icpt, rel=1e-10)
    assert 0.9 < ls.zeta / g.zeta < 1.1  # the two estimates of zeta agree within 10 % on these data


def test_fit_exact_on_synthetic_data(case):
    """Both fit methods recover zeta and M_u exactly from torques generated by Eq. 11."""
    pre = np.linspace(10e-6, 160e-6, 9)
    c = wr.contacts(case, pre)
    M = wr.starting_torque(2.0e-4, Z, c.F1, c.F2, ALPHA, 5.0)
    for method in ("grouping", "least_squares"):
        zeta, M_u = wr.fit_rolling_resistance(pre, M, case, method=method)
        assert zeta == pytest.approx(2.0e-4, rel=1e-9) and M_u == pytest.approx(5.0, rel=1e-9)


# ----------------------------------------------------------------------------- printed equations


def test_eq7_printed_and_symmetric_forms_agree_at_45_degrees():
    F1 = np.array([0.0, 45.93, 3330.34])
    F2 = wr.framework_equilibrium_F2(F1, Z, ALPHA, G_O)
    np.testing.assert_allclose(wr.framework_equilibrium_residual_printed(F1, F2, Z, ALPHA, G_O), 0.0, atol=1e-9)
    a = math.radians(30)  # away from 45 deg the printed form is not an equilibrium of the axial forces
    F2b = wr.framework_equilibrium_F2(F1, Z, a, G_O)
    assert np.all(np.abs(wr.framework_equilibrium_residual_printed(F1, F2b, Z, a, G_O)) > 1.0)


def test_eqs_8_9_as_printed_at_45_degrees():
    zeta = 1.0265e-4
    M_s = np.array([1.37, 50.0, 87.19])
    F1, F2 = wr.contact_forces_from_torque(M_s, zeta, Z, ALPHA, G_O)
    s, c, t = math.sin(ALPHA), math.cos(ALPHA), math.tan(ALPHA)
    np.testing.assert_allclose(F1, (M_s / (2 * zeta) - G_O) / (Z * (s + c)), rtol=1e-12)  # Eq. 8
    np.testing.assert_allclose(F2, (M_s * t / (2 * zeta) + G_O) / (Z * (s + c)), rtol=1e-12)  # Eq. 9
    # and Eq. 4 gives the torque back
    np.testing.assert_allclose(wr.bearing_rolling_torque(zeta, Z, F1, F2, F1, F2, ALPHA), M_s, rtol=1e-12)


def test_eq10_second_line_equals_first_line():
    zeta, K_i, K_o = 1.0265e-4, 7.8e9, 7.9e9
    M_s = np.array([5.0, 40.0, 90.0])
    F1, F2 = wr.contact_forces_from_torque(M_s, zeta, Z, ALPHA, G_O)
    d_first = wr.preload_from_forces(F1, F2, K_i, K_o, ALPHA)
    s, c, t = math.sin(ALPHA), math.cos(ALPHA), math.tan(ALPHA)
    d_second = (c / (Z * (s + c)) ** (2 / 3) * (K_i ** (-2 / 3) + K_o ** (-2 / 3))
                * ((M_s / (2 * zeta) - G_O) ** (2 / 3) + (M_s * t / (2 * zeta) + G_O) ** (2 / 3)))  # Eq. 10 as printed
    np.testing.assert_allclose(d_first, d_second, rtol=1e-12)
    np.testing.assert_allclose(wr.preload_from_torque(M_s, zeta, Z, ALPHA, G_O, K_i, K_o), d_second, rtol=1e-12)
    with pytest.raises(ValueError):
        wr.preload_from_torque(0.1, zeta, Z, ALPHA, G_O, K_i, K_o)  # < 2 zeta G_o / tan(alpha) = 0.166 N m


def test_preload_round_trip(case):
    pre = np.linspace(5e-6, 300e-6, 25)
    c = wr.contacts(case, pre)
    back = wr.preload_from_forces(c.F1, c.F2, c.K_i, c.K_o, ALPHA)
    np.testing.assert_allclose(back, pre, rtol=1e-9)
    back2 = wr.preload_from_torque(c.rolling_torque, case.friction.rolling_resistance, Z, ALPHA, G_O, c.K_i, c.K_o)
    np.testing.assert_allclose(back2, pre, rtol=1e-9)


# ----------------------------------------------------------------------------- Hertz (Eqs. 5-6)


def johnson_K(Rp, Rpp, E1, nu1, E2, nu2):
    """Johnson (1985) Sec. 4.2: K = sqrt(16 E*^2 R_e / (9 F_2^3)), F_2 = 1 - ((R'/R'')^0.0684 - 1)^1.531 (chart fit)."""
    Es = 0.5 * reduced_modulus(E1, nu1, E2, nu2)
    Rp, Rpp = max(Rp, Rpp), min(Rp, Rpp)
    F2 = 1 - ((Rp / Rpp) ** 0.0684 - 1) ** 1.531
    return math.sqrt(16 * Es**2 * math.sqrt(Rp * Rpp) / (9 * F2**3))


def test_exact_stiffness_vs_johnson_F2_chart(case):
    """Eqs. 5-6 read with E*^2 (Johnson): our exact K agrees with Johnson's F_2(e) form within 0.5 %."""
    m = case.materials
    Rx_i, Ry_i, Rx_o, Ry_o = wr.wire_contact_radii(14.288e-3, 3e-3, 889.6e-3, ALPHA)
    for Rx, Ry in ((Rx_i, Ry_i), (Rx_o, Ry_o)):
        K = wr.contact_stiffness(Rx, Ry, m.ball.elastic_modulus, 0.3, m.races.elastic_modulus, 0.3)
        assert K == pytest.approx(johnson_K(Rx, Ry, 208e9, 0.3, 219.4e9, 0.3), rel=0.005)


def test_wire_geometry_invariants():
    D, dw, dm = 14.288e-3, 3e-3, 889.6e-3
    Rx_i, Ry_i, Rx_o, Ry_o = wr.wire_contact_radii(D, dw, dm, ALPHA)
    assert Ry_i == Ry_o == pytest.approx(1 / (2 / D + 2 / dw))
    assert Rx_i < D / 2 < Rx_o  # inner wire convex, outer wire concave along the rolling direction
    # a huge pitch diameter makes the two wires identical
    a = wr.wire_contact_radii(D, dw, 1e6, ALPHA)
    assert a[0] == pytest.approx(a[2], rel=1e-6)
    # a ground track (conforming) is much stiffer than a round wire
    E, nu = 208e9, 0.3
    K_round = wr.contact_stiffness(Rx_i, Ry_i, E, nu, E, nu)
    g = wr.wire_contact_radii(D, dw, dm, ALPHA, groove_conformity=0.53)
    assert wr.contact_stiffness(g[0], g[1], E, nu, E, nu) > 2 * K_round


# ----------------------------------------------------------------------------- physical invariants


def test_no_framework_weight_gives_equal_diagonals(case):
    c = wr.contacts(case.with_overrides(**{"operating.framework_weight": "0 N"}), [20e-6, 100e-6])
    np.testing.assert_allclose(c.F1, c.F2, rtol=1e-12)


def test_torque_increases_with_preload_and_unloaded_diagonal(case):
    pre = np.linspace(0.0, 200e-6, 81)
    c = wr.contacts(case, pre)
    assert np.all(np.diff(c.torque) > 0) and np.all(np.diff(c.F1) >= 0)
    # below delta_0 = delta(F1 = 0) the 1-3 diagonal is unloaded and F2 carries the weight alone
    d0 = wr.preload_from_forces(0.0, G_O / (Z * math.sin(ALPHA)), c.K_i, c.K_o, ALPHA)
    assert 1e-6 < d0 < 3e-6
    low = pre < d0
    assert np.all(c.F1[low] == 0) and np.all(c.F1[~low] > 0)
    np.testing.assert_allclose(c.F2[low], G_O / (Z * math.sin(ALPHA)))


def test_equilibrium_of_the_outer_ring(case):
    """Axial forces on the outer ring: Z (F4 - F3) sin(alpha) = G_o at every preload."""
    c = wr.contacts(case, np.linspace(10e-6, 160e-6, 7))
    np.testing.assert_allclose(Z * (c.F4 - c.F3) * math.sin(ALPHA), G_O, rtol=1e-10)


def test_preload_window_paper_target(case):
    """Sec. 4.1 of Shan et al. 2010: starting torque 90-100 N m -> preload 130-140 um.  That window is read from the
    MEASURED curve (M_bm of Table 2, linear interpolation: 132.2-141.6 um); the paper's own model (Eq. 11 with
    its K and Table 3) gives 141.7-154.4 um, and so does ours (self-consistent zeta): we assert ours against the
    paper's model within 0.5 um and report the 2-14 um gap to the measured window (docs/validation/wire_race.md)."""
    lo, hi = wr.preload_window(case, 90.0, 100.0)
    lo_p, hi_p = wr.preload_window(case.with_overrides(**PAPER_ZETA_MU), 90.0, 100.0, stiffness=table2_stiffness())
    assert lo == pytest.approx(lo_p, abs=0.5e-6) and hi == pytest.approx(hi_p, abs=0.5e-6)
    assert 141e-6 < lo < 143e-6 and 153.5e-6 < hi < 155.5e-6  # regression of the values in the docs
    measured = np.interp([90.0, 100.0], T2.Mbm_Nm, T2.delta_um) * 1e-6  # Table 2, M_bm column
    assert measured[0] == pytest.approx(130e-6, abs=2.5e-6) and measured[1] == pytest.approx(140e-6, abs=2.5e-6)
    c = wr.contacts(case, [lo, hi])
    np.testing.assert_allclose(c.torque, [90.0, 100.0], rtol=1e-8)
    with pytest.raises(CaseError):
        wr.preload_window(case, 1.0, 100.0)  # below the torque at zero preload (M_u = 17.3 N m)
    with pytest.raises(CaseError):
        wr.preload_window(case, 100.0, 90.0)


def test_dataset_contract(case):
    ds = wr.preload_sweep(case)
    assert ds.sizes["preload"] == 31 and ds["preload"].attrs["units"] == "m"
    assert float(ds.preload[0]) == pytest.approx(10e-6) and float(ds.preload[-1]) == pytest.approx(160e-6)
    units = {"F": "N", "delta": "m", "p_max": "Pa"}
    for q, u in units.items():
        for j in (1, 2, 3, 4):
            assert ds[f"{q}{j}"].dims == ("preload",) and ds[f"{q}{j}"].attrs["units"] == u
    assert ds["torque"].attrs["units"] == "N*m"
    assert ds.attrs["case_system"] == "wire_race" and ds.attrs["status"] == "ok"
    assert "shan2010_wire_race" in ds.attrs["case_toml"]


def test_wrong_system_is_a_case_error():
    with pytest.raises(CaseError):
        wr.preload_sweep(load_case("zhang2016"))


@pytest.mark.parametrize("text,expect_um", [("10..160um", np.linspace(10, 160, 31)), ("10,20,40um", [10, 20, 40]),
                                            ("0.01..0.02:0.005mm", [10, 15, 20]), ("50 um", [50])])
def test_parse_range(text, expect_um):
    np.testing.assert_allclose(wr.parse_range(text, "length", "--preload") * 1e6, expect_um, rtol=1e-12)


@pytest.mark.parametrize("text", ["160..10um", "10..160", "a..bum", "10,,20um", "10..160N", "10..160:0um", ""])
def test_parse_range_errors(text):
    with pytest.raises(CaseError) as e:
        wr.parse_range(text, "length", "--preload")
    assert e.value.source == "--preload"


# ----------------------------------------------------------------------------- CLI


def run_cli(*args):
    return subprocess.run([sys.executable, "-m", "hsbearing.cli", *args], capture_output=True, text=True)


def test_cli_table_window_and_archive(tmp_path):
    out = tmp_path / "wr.nc"
    r = run_cli("preload", "shan2010_wire_race", "--preload", "10,80,160um", "--target-torque", "90..100N*m", "-o", str(out))
    assert r.returncode == 0, r.stderr
    assert "preload window for 90..100 N m:" in r.stdout and "archive:" in r.stdout
    ds = open_run(out)
    assert ds.sizes["preload"] == 3 and list(ds.attrs["preload_window"]) == pytest.approx(wr.preload_window(load_case("shan2010_wire_race"), 90, 100), rel=1e-9)
    assert not list(tmp_path.glob(".*tmp"))


@pytest.mark.parametrize("args,word", [
    (["--preload", "160..10um"], "--preload"),
    (["--preload", "10..160"], "--preload"),
    (["--target-torque", "90..100um"], "--target-torque"),
    (["--target-torque", "1..2N*m"], "--target-torque"),
    (["--set", "bearing.wire_diameter=3"], "bearing.wire_diameter"),
])
def test_cli_bad_input_exit_2_nothing_written(tmp_path, args, word):
    out = tmp_path / "x.nc"
    r = run_cli("preload", "shan2010_wire_race", *args, "-o", str(out))
    assert r.returncode == 2, r.stdout + r.stderr
    assert word in r.stderr and r.stderr.count("\n") == 1 and "Traceback" not in r.stderr
    assert not out.exists() and not list(tmp_path.iterdir())


def test_cli_wrong_system_exit_2(tmp_path):
    r = run_cli("preload", "zhang2016", "-o", str(tmp_path / "x.nc"))
    assert r.returncode == 2 and "case.system" in r.stderr and not list(tmp_path.iterdir())


# ----------------------------------------------------------------------------- property tests

# hypothesis is a test dependency (pyproject [test], requirements.lock): missing is an ImportError, not a skip
from hypothesis import given, settings  # noqa: E402
from hypothesis import strategies as st


@settings(max_examples=60, deadline=None)
@given(delta=st.one_of(st.just(0.0), st.floats(1e-12, 1e-3)), K_i=st.floats(1e8, 1e11), K_o=st.floats(1e8, 1e11),
       G_o=st.floats(0.0, 1e5), alpha_deg=st.floats(10.0, 80.0), Z=st.integers(3, 200))
def test_eq10_inversion_property(delta, K_i, K_o, G_o, alpha_deg, Z):
    """For any parameters: F2 - F1 from Eq. 7, F1 >= 0, and Eq. 10 of the returned forces gives the preload
    back whenever the 1-3 diagonal is loaded."""
    a = math.radians(alpha_deg)
    F1, F2 = wr.contact_forces_from_preload(delta, Z, a, G_o, K_i, K_o)
    assert F1 >= 0 and F2 - F1 == pytest.approx(G_o / (Z * math.sin(a)), rel=1e-9, abs=1e-9)
    if F1 > 0:
        assert wr.preload_from_forces(F1, F2, K_i, K_o, a) == pytest.approx(delta, rel=1e-7, abs=1e-13)
    else:
        assert wr.preload_from_forces(0.0, F2, K_i, K_o, a) >= delta * (1 - 1e-9)
