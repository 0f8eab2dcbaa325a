"""DGBB friction torque: SKF 2004 model and the dgbb_prl sliding method.

Literature values: dgbb_prl Tables 2-4 (tests/data/dgbb_prl_sliding_torque.csv),
DGBB 6206, sliding torque M_sl [N mm] at 500, 5000, 15000 r/min, proposed
method (P) and SKF model (S).  Tolerances: SKF column 1 %, proposed column 3 %.  Cells we do not reproduce are xfail(strict) with the measured
error in the reason; docs/validation/dgbb_friction.md shows every cell.
"""

from __future__ import annotations

import csv
import math
from pathlib import Path

import numpy as np
import pytest
from scipy.integrate import quad

from hsbearing import load_case
from hsbearing.case import CaseError
from hsbearing.cli import main as cli
from hsbearing.models.friction import skf2004
from hsbearing.models.friction import sliding_prl as sp
from hsbearing.results import open_run
from hsbearing.systems.deep_groove.friction import friction_torque
from hsbearing.units import parse_speeds

DATA = Path(__file__).resolve().parents[2] / "data"


def _table_rows():
    with open(DATA / "dgbb_prl_sliding_torque.csv") as fh:
        rows = [r for r in csv.reader(line for line in fh if not line.startswith("#"))]
    head, body = rows[0], rows[1:]
    return [dict(zip(head, r)) for r in body]


ROWS = _table_rows()
LOADS = sorted({(r["table"], float(r["Fz_axial_N"]), float(r["Fx_radial_N"])) for r in ROWS})


def _case(Fa, Fr, **extra):
    return load_case("dgbb_6206", **{"operating.axial_load": f"{Fa} N", "operating.radial_load": f"{Fr} N", **extra})


@pytest.fixture(scope="module")
def seed_results():
    """Seed-reading results per table (spin projection + seed003 SKF G_sl), at the three speeds."""
    out = {}
    for table, Fa, Fr in LOADS:
        ds = friction_torque(_case(Fa, Fr, **{"friction.skf_reading": "dgbb_prl"}), "500,5000,15000rpm")
        out[table] = ds
    return out


def _cell(ds, rpm, name):
    i = int(np.argmin(np.abs(ds["speed"].values * 60 / (2 * math.pi) - rpm)))
    return float(ds[name].values[i]) * 1e3  # N mm


# --------------------------------------------------------------------------- SKF column, Tables 2-4


@pytest.mark.parametrize("row", ROWS, ids=lambda r: f"T{r['table']}-{r['speed_rpm']}rpm")
def test_skf_column_tables_2_4_within_1_percent(seed_results, row):
    """dgbb_prl Tables 2-4, column S (SKF model, M_sl only), within 1 %.  CONSISTENCY for Tables 3-4: the
    ``dgbb_prl`` reading (axial term + half the pure-radial term) was derived from these very cells
    (docs/validation/dgbb_friction.md); only Table 2 (the catalogue formula as printed) is agreement."""
    ds = seed_results[row["table"]]
    ours = _cell(ds, float(row["speed_rpm"]), "skf_sliding_torque")
    paper = float(row["Msl_SKF_Nmm"])
    assert ours == pytest.approx(paper, rel=0.01)


def test_skf_catalogue_reading_equals_table2_pure_axial():
    """dgbb_prl Table 2 (pure axial): the catalogue G_sl and the seed reading coincide; 1 %."""
    ds = friction_torque(_case(500, 0), "500,5000,15000rpm")
    for rpm, paper in ((500, 26.3645), (5000, 14.1014), (15000, 14.1013)):  # Table 2, column S
        assert _cell(ds, rpm, "skf_sliding_torque") == pytest.approx(paper, rel=0.01)


def test_skf_catalogue_pure_radial_is_twice_the_seed_value():
    """The seed's SKF column of Table 3 is half the catalogue G_sl = S1 d_m^-0.26 F_r^(5/3) (documented)."""
    c = skf2004.DGBB_SERIES["62"]
    cat = skf2004.sliding_variable_G_sl(500, 0, 46.0, 11200.0, c, "catalogue")
    seed = skf2004.sliding_variable_G_sl(500, 0, 46.0, 11200.0, c, "dgbb_prl")
    assert cat / seed == pytest.approx(2.0, rel=1e-12)
    assert 0.05 * seed == pytest.approx(0.9400, rel=1e-3)  # Table 3, column S, 15000 r/min


def test_skf_coefficient_and_weighting():
    """mu_sl = phi_bl mu_bl + (1 - phi_bl) mu_EHL with phi_bl = exp(-2.6e-8 (n nu)^1.4 d_m) (SKF 2004)."""
    phi = skf2004.boundary_weighting_phi_bl(500, 20.0, 46.0)
    assert phi == pytest.approx(math.exp(-2.6e-8 * (500 * 20.0) ** 1.4 * 46.0))
    mu = skf2004.sliding_coefficient_mu_sl(np.array([0.0, 500, 1e5]), 20.0, 46.0, 0.12, 0.05)
    assert mu[0] == pytest.approx(0.12) and mu[-1] == pytest.approx(0.05)
    assert 0.05 < mu[1] < 0.12
    # CONSISTENCY, not validation: nu = 20 mm^2/s is FITTED to the speed ratio of Table 2 column S (with mu_bl =
    # 0.12, mu_EHL = 0.05); this checks the fit is carried into the case, the ratio is not an agreement
    assert mu[1] / 0.05 == pytest.approx(26.3645 / 14.1013, rel=2e-4)


def test_skf_alpha_F_and_rolling_moment():
    """alpha_F = 24.6 (F_a/C_0)^0.24 deg; M_rr grows with speed and is damped by phi_ish, phi_rs (< 1)."""
    assert math.degrees(skf2004.contact_angle_alpha_F(500, 11200)) == pytest.approx(24.6 * (500 / 11200) ** 0.24)
    assert skf2004.inlet_shear_factor_phi_ish(15000, 20.0, 46.0) < 1.0
    assert skf2004.replenishment_factor_phi_rs(15000, 20.0, 30.0, 62.0) < 1.0
    ds = friction_torque(_case(500, 0), "500,5000,15000rpm")
    m = ds["skf_rolling_torque"].values
    assert np.all(np.diff(m) > 0)
    np.testing.assert_allclose(ds["skf_total_torque"].values,
                               m + ds["skf_sliding_torque"].values + ds["skf_drag_torque"].values)


def test_skf_unknown_series_is_a_case_error():
    with pytest.raises(CaseError, match="bearing.designation"):
        friction_torque(load_case("dgbb_6206", **{"bearing.designation": "7206"}), "500rpm")


# --------------------------------------------------------------------------- proposed column, Tables 2-4

_XFAIL = {
    "3": "Table 3 (pure radial): our differential sliding is ~1.7x the seed's (M_sl/mu 30.5 vs 18.1 N mm); it equals "
         "the Heathcote closed form, and even the zero-clearance lower bound is +65 %; the seed's Kakuta/Eq. 13-19 "
         "formulas are lost -- see docs/validation/dgbb_friction.md, 'Table 3: second look'",
}


@pytest.mark.parametrize(
    "row",
    [pytest.param(r, marks=pytest.mark.xfail(strict=True, reason=_XFAIL[r["table"]])) if r["table"] in _XFAIL else r
     for r in ROWS],
    ids=lambda r: f"T{r['table']}-{r['speed_rpm']}rpm",
)
def test_proposed_column_tables_2_4_within_3_percent(seed_results, row):
    """dgbb_prl Tables 2-4, column P (proposed method), within 3 %."""
    ds = seed_results[row["table"]]
    ours = _cell(ds, float(row["speed_rpm"]), "sliding_torque")
    assert ours == pytest.approx(float(row["Msl_proposed_Nmm"]), rel=0.03)


def test_proposed_column_table4_ring_held_square_named_loose_tolerance():
    """Table 4 with the inner ring held square (no tilt) at a named looser tolerance of 5 % (-4.5 %)."""
    ds = friction_torque(_case(1000, 1000), "5000rpm", tilt=False)
    assert _cell(ds, 5000, "sliding_torque") == pytest.approx(36.1996, rel=0.05)  # Table 4, column P


def test_speed_ratio_follows_the_fitted_coefficient_consistency(seed_results):
    """CONSISTENCY, not validation: without centrifugal effects M_sl follows mu_sl(n), and the oil viscosity
    nu = 20 mm^2/s of the case is FITTED to Table 2's 500/5000 r/min ratio (column S, test_skf_coefficient_and_
    weighting); this checks that the fitted coefficient carries the proposed-method torque's speed dependence
    (column P's ratio equals column S's to 1e-3), not that the speed trend agrees with the paper."""
    ds = seed_results["2"]
    r = _cell(ds, 500, "sliding_torque") / _cell(ds, 5000, "sliding_torque")
    assert r == pytest.approx(26.4162 / 14.1291, rel=1e-3)


# --------------------------------------------------------------------------- physics invariants and trends


@pytest.fixture(scope="module")
def radial_and_axial():
    return (friction_torque(_case(0, 500), "5000rpm"), friction_torque(_case(500, 0), "5000rpm"))


def test_spinning_vanishes_under_pure_radial_load(radial_and_axial):
    """Seed Fig. 12 / conclusion 6: spinning vanishes under pure radial load (contact angle 0)."""
    rad, ax = radial_and_axial
    assert abs(float(rad["spinning_torque"][0])) < 1e-9 * float(rad["sliding_torque"][0]) + 1e-15
    assert float(ax["spinning_torque"][0]) > 0.5 * float(ax["sliding_torque"][0])


def test_axial_load_dominates(radial_and_axial):
    """Seed conclusions 5, 7: the same load axially gives a much larger sliding torque than radially."""
    rad, ax = radial_and_axial
    assert float(ax["sliding_torque"][0]) > 3.0 * float(rad["sliding_torque"][0])


def test_torque_grows_with_axial_and_radial_load():
    """Seed Figs. 10, 13, 16: M_sl increases with the axial and with the radial load."""
    ms_a = [float(friction_torque(_case(Fa, 0), "5000rpm")["sliding_torque"][0]) for Fa in (500, 1000, 1500)]
    ms_r = [float(friction_torque(_case(0, Fr), "5000rpm")["sliding_torque"][0]) for Fr in (500, 1000, 1500)]
    assert np.all(np.diff(ms_a) > 0) and np.all(np.diff(ms_r) > 0)


def test_bearing_size_trends():
    """Seed Fig. 11: under Fa = 500 N M_sl grows with size; Fig. 14: under Fr = 500 N it decreases."""
    ax = [float(friction_torque(load_case(b), "5000rpm")["sliding_torque"][0]) for b in ("dgbb_6206", "dgbb_6207", "dgbb_6208")]
    rad = [float(friction_torque(load_case(b, **{"operating.axial_load": "0 N", "operating.radial_load": "500 N"}),
                                 "5000rpm")["sliding_torque"][0]) for b in ("dgbb_6206", "dgbb_6207", "dgbb_6208")]
    assert np.all(np.diff(ax) > 0)
    assert np.all(np.diff(rad) < 0)


def test_coulomb_law_is_speed_independent_and_scales_with_mu():
    """Seed Fig. 8: with a constant Coulomb mu = 0.07 the torque does not change with speed; M ~ mu."""
    ds = friction_torque(_case(500, 0, **{"friction.law": "coulomb"}), "500,15000rpm")
    m = ds["sliding_torque"].values
    assert m[0] == pytest.approx(m[1], rel=1e-9)
    ds2 = friction_torque(_case(500, 0, **{"friction.law": "coulomb", "friction.coefficient": 0.14}), "500rpm")
    assert float(ds2["sliding_torque"][0]) == pytest.approx(2 * m[0], rel=1e-9)


def _ball_state(Fa, Fr):
    from hsbearing.systems.deep_groove.friction import contact_states

    case = _case(Fa, Fr)
    return contact_states(case)


def test_energy_balance_inner_ring_torque_equals_dissipated_power():
    """Friction torque on the inner ring about the axis = dissipated power / omega_i (each ball, steady state)."""
    psi, Q, al, states = _ball_state(1000, 1000)
    for st in states:
        if st.Q[0] <= 0:
            continue
        for traction in ("strip", "full"):
            b = sp.solve_ball(st, 9.525e-3, 46e-3, traction=traction)
            assert b.residual < 1e-8
            assert -b.inner_ring_torque == pytest.approx(b.total, rel=1e-6)
            assert b.total > 0
            # force balance of the ball in the rolling direction
            assert b.friction_force[0] == pytest.approx(-b.friction_force[1], abs=1e-8 * st.Q[0])


def test_prl_locations_pure_radial_symmetric_and_inside():
    """Pure radial load (alpha = 0): two PRLs symmetric about the centre, near the Jones/Harris 0.347 a."""
    psi, Q, al, states = _ball_state(0, 500)
    b = sp.solve_ball(states[0], 9.525e-3, 46e-3)
    for c1, c2 in b.prl:
        assert c1 == pytest.approx(-c2, abs=1e-6)
        assert 0.30 < c1 < 0.36  # strip theory with F = 0: 3c - c^3 = 1 -> c = 0.347 (flat contact)
        assert c1 == pytest.approx(_jones_c(), abs=3e-3)  # curvature corrections are O(a^2 / (R D)) (measured 0.3462)


def test_prl_axial_load_two_lines_shifted():
    """Axial load: spin shifts the PRLs off-centre (c1 + c2 != 0), both inside the ellipse."""
    psi, Q, al, states = _ball_state(500, 0)
    b = sp.solve_ball(states[0], 9.525e-3, 46e-3)
    for c1, c2 in b.prl:
        assert -1 < c2 < c1 < 1
        assert abs(c1 + c2) > 0.1


# --------------------------------------------------------------------------- closed forms of strip theory


@pytest.mark.parametrize("c1,c2", [(0.3, -0.4), (0.8, 0.1), (0.9, -0.95), (0.0, -0.2)])
def test_strip_closed_forms_match_quadrature(c1, c2):
    """Eq. 10 / Eq. 7 of dgbb_prl (rebuilt): integrals of the strip load 3/4 (1 - xi^2) with sign pattern."""
    sgn = lambda x: -1.0 if c2 < x < c1 else 1.0
    F = sum(quad(lambda x: 0.75 * (1 - x * x) * sgn(x), lo, hi)[0] for lo, hi in ((-1, c2), (c2, c1), (c1, 1)))
    M = sum(quad(lambda x: 0.75 * (1 - x * x) * x * sgn(x), lo, hi)[0] for lo, hi in ((-1, c2), (c2, c1), (c1, 1)))
    assert sp.strip_force_2prl(c1, c2) == pytest.approx(F, abs=1e-12)
    assert sp.strip_spin_moment_2prl(c1, c2, 1.0) == pytest.approx(M, abs=1e-12)


@pytest.mark.parametrize("c", [-0.7, 0.0, 0.4])
def test_strip_one_prl_closed_forms(c):
    sgn = lambda x: -1.0 if x < c else 1.0
    F = sum(quad(lambda x: 0.75 * (1 - x * x) * sgn(x), lo, hi)[0] for lo, hi in ((-1, c), (c, 1)))
    M = sum(quad(lambda x: 0.75 * (1 - x * x) * x * sgn(x), lo, hi)[0] for lo, hi in ((-1, c), (c, 1)))
    assert sp.strip_force_1prl(c) == pytest.approx(-F, abs=1e-12)  # sign: positive on (-1, c)
    assert sp.strip_spin_moment_1prl(c, 1.0) == pytest.approx(M, abs=1e-12)


def test_symmetric_zero_force_prl_is_0347():
    """Jones/Harris: symmetric PRLs with zero net force at c = 0.347 (3c - c^3 = 1)."""
    from scipy.optimize import brentq

    c = brentq(lambda c: sp.strip_force_2prl(c, -c), 0.1, 0.9)
    assert c == pytest.approx(0.3473, abs=1e-4)
    assert 3 * c - c**3 == pytest.approx(1.0, abs=1e-12)  # zero net strip force (Jones 1959)
    assert _heathcote_integral(c) == pytest.approx(0.16114, abs=1e-5)
    cs = np.linspace(0.05, 0.95, 91)
    assert np.all(_heathcote_integral(cs) >= _heathcote_integral(c) - 1e-12)  # c* minimises the dissipation


def test_pure_spin_moment_upper_bound():
    """Strip spinning moment of one contact never exceeds 3/8 mu Q a E(e) of pure spin (Eq. 5)."""
    from scipy.special import ellipe

    psi, Q, al, states = _ball_state(500, 0)
    st = states[0]
    b = sp.solve_ball(st, 9.525e-3, 46e-3)
    for k in range(2):
        e2 = 1 - (st.b[k] / st.a[k]) ** 2
        assert abs(b.spin_moment[k]) <= sp.spinning_moment_pure_spin(1.0, st.Q[k], st.a[k], ellipe(e2)) * 1.0001


# --------------------------------------------------------------------------- API, CLI


def test_parse_speeds_forms():
    w = 2 * math.pi * 500 / 60
    np.testing.assert_allclose(parse_speeds("500,5000rpm"), [w, 10 * w])
    np.testing.assert_allclose(parse_speeds(["500 rpm", 10.0]), [w, 10.0])
    np.testing.assert_allclose(parse_speeds(52.0), [52.0])
    for bad in ("500,5000", "fast", "-5 rpm", "500 N", ""):
        with pytest.raises(CaseError):
            parse_speeds(bad)


def test_dataset_names_and_units():
    ds = friction_torque("dgbb_6206", ["500 rpm"])
    for name in ("spinning_torque", "rotation_sliding_torque", "orbital_sliding_torque", "sliding_torque",
                 "skf_sliding_torque", "skf_rolling_torque", "skf_drag_torque", "skf_total_torque"):
        assert ds[name].dims == ("speed",) and ds[name].attrs["units"] == "N*m"
    assert ds["speed"].attrs["units"] == "rad/s"
    np.testing.assert_allclose(ds["sliding_torque"], ds["spinning_torque"] + ds["rotation_sliding_torque"] + ds["orbital_sliding_torque"])
    assert "case_toml" in ds.attrs


def test_cli_writes_archive(tmp_path, capsys):
    out = tmp_path / "f.nc"
    assert cli(["friction", "dgbb_6206", "--speeds", "500,5000rpm", "-o", str(out)]) == 0
    text = capsys.readouterr().out
    assert "N mm" in text and "SKF M_sl" in text
    ds = open_run(out)
    assert ds.sizes["speed"] == 2
    assert float(ds["skf_sliding_torque"][1]) * 1e3 == pytest.approx(14.1014, rel=1e-3)  # Table 2, S


@pytest.mark.parametrize("speeds", ["500,5000", "abc rpm", "0rpm", "5 N"])
def test_cli_bad_speeds_exit_2_nothing_written(tmp_path, capsys, speeds):
    out = tmp_path / "f.nc"
    assert cli(["friction", "dgbb_6206", "--speeds", speeds, "-o", str(out)]) == 2
    err = capsys.readouterr().err
    assert "speeds" in err and len(err.strip().splitlines()) == 1
    assert not out.exists()


def test_cli_bad_set_exit_2(tmp_path):
    out = tmp_path / "f.nc"
    assert cli(["friction", "dgbb_6206", "--set", "friction.law=viscous", "-o", str(out)]) == 2
    assert not out.exists()


# --------------------------------------------------------------------------- load distribution


@pytest.mark.parametrize("Fa,Fr", [(500, 0), (0, 500), (1000, 1000), (1500, 1000)])
def test_static_load_distribution_equilibrium(Fa, Fr):
    """Sum Q sin(alpha) = F_a, sum Q cos(alpha) cos(psi) = F_r, zero moment (free tilt)."""
    psi, Q, al = sp.static_load_distribution(9, 9.525e-3, 46e-3, 0.52, 0.52, 12.5e-6, 208e9, 0.3, 208e9, 0.3, Fa, Fr)
    assert np.sum(Q * np.sin(al)) == pytest.approx(Fa, abs=1e-6 * max(Fa, Fr))
    assert np.sum(Q * np.cos(al) * np.cos(psi)) == pytest.approx(Fr, abs=1e-6 * max(Fa, Fr))
    assert np.sum(Q * np.sin(al) * np.cos(psi)) == pytest.approx(0.0, abs=1e-6 * max(Fa, Fr))


def test_static_contacts_match_the_quasistatic_solver_without_inertia():
    """Independent cross-check: our static distribution = hsbearing.systems.angular_contact.quasistatic with
    centrifugal and gyroscopic effects off (Fa = Fr = 1 kN, free tilt)."""
    from hsbearing.systems.angular_contact import quasistatic  # part of the package: missing is an error, not a skip
    from hsbearing.systems.deep_groove.friction import contact_states

    case = _case(1000, 1000)
    psi, Q, al, _ = contact_states(case)
    ds = quasistatic.solve_case(case, inner_speed=50.0, centrifugal=False, gyroscopic=False)
    np.testing.assert_allclose(ds["inner_contact_load"].values, Q, rtol=1e-4)
    np.testing.assert_allclose(ds["inner_contact_angle"].values, al, atol=1e-5)


def test_strip_integration_converged(monkeypatch):
    """Exact sign integration on the line: halving the node spacing changes M/mu by < 1e-5 (Table 4 state)."""
    psi, Q, al, states = _ball_state(1000, 1000)
    vals = []
    for n in (801, 1601, 3201):
        monkeypatch.setattr(sp, "_NLINE", n)
        vals.append(sum(sp.solve_ball(st, 9.525e-3, 46e-3).total for st in states[:3]))
    assert vals[1] == pytest.approx(vals[2], rel=1e-5)
    assert abs(vals[1] - vals[2]) < abs(vals[0] - vals[2])  # converging


def test_angular_contact_case_coulomb_runs_and_skf_is_nan():
    """The PRL method needs no nominal contact angle (dgbb_prl conclusion): runs on the ACBB case with
    Coulomb friction; SKF DGBB moments are reported as NaN, not invented."""
    ds = friction_torque(load_case("zhang2016", **{"friction.law": "coulomb"}), "1000rpm")
    assert float(ds["sliding_torque"][0]) > 0
    assert float(ds["spinning_torque"][0]) > 0.5 * float(ds["sliding_torque"][0])  # 25 deg: spin dominates
    assert np.isnan(float(ds["skf_sliding_torque"][0]))


def test_angular_contact_case_answers(tmp_path):
    """Issue 17 item 2: the angular-contact case answers (quasi-static power loss by source and the SKF 2004
    angular-contact model, hsbearing.systems.angular_contact.rating; tests/cli/test_friction_cli.py) instead of refusing."""
    out = tmp_path / "f.nc"
    assert cli(["friction", "zhang2016", "-o", str(out)]) == 0
    assert out.exists()


@pytest.mark.parametrize("Fa,Fr", [(500, 0), (1000, 1000)])
def test_projection_reading_is_twice_the_spin_power(Fa, Fr):
    """Identity behind the two spin readings: the ball's spin moments balance (|m_s,i| = |m_s,e| = m) and
    omega_s,i + omega_s,e = omega_i sin(alpha) when alpha_i = alpha_e, so the dissipated spin power over
    omega_i is m sin(alpha), while the Tong-Hong projection sums both races: 2 m sin(alpha)."""
    proj = friction_torque(_case(Fa, Fr, **{"friction.spin_torque_reading": "projection"}), "5000rpm")
    powr = friction_torque(_case(Fa, Fr, **{"friction.spin_torque_reading": "power"}), "5000rpm")
    assert float(proj["spinning_torque"][0]) == pytest.approx(2 * float(powr["spinning_torque"][0]), rel=1e-4)
    psi, Q, al, states = _ball_state(Fa, Fr)
    b = sp.solve_ball(states[0], 9.525e-3, 46e-3)
    assert abs(b.spin_moment[0]) == pytest.approx(abs(b.spin_moment[1]), rel=1e-6)
    assert abs(b.spin_speed[0] + b.spin_speed[1]) == pytest.approx(math.sin(states[0].alpha[0]), rel=1e-9)


def test_regression_dgbb_friction_5000rpm():
    """REGRESSION (our own earlier output, not a validation): tests/data/regression_dgbb_friction.csv."""
    with open(DATA / "regression_dgbb_friction.csv") as fh:
        rows = list(csv.DictReader(line for line in fh if not line.startswith("#")))
    names = {"spinning": "spinning_torque", "rotation_sliding": "rotation_sliding_torque",
             "orbital_sliding": "orbital_sliding_torque", "sliding": "sliding_torque",
             "skf_sliding_catalogue": "skf_sliding_torque"}
    for r in rows:
        ds = friction_torque(_case(float(r["Fa_N"]), float(r["Fr_N"])), "5000rpm")
        for col, var in names.items():
            assert float(ds[var][0]) * 1e3 == pytest.approx(float(r[col]), rel=1e-4, abs=1e-5), (r["Fa_N"], r["Fr_N"], col)


def test_axial_load_sign_mirrors():
    """A radial ball bearing is symmetric: -F_a gives the same torques as +F_a."""
    a = friction_torque(_case(500, 200), "5000rpm")
    b = friction_torque(_case(-500, 200), "5000rpm")
    for v in ("sliding_torque", "spinning_torque", "skf_sliding_torque"):
        assert float(b[v][0]) == pytest.approx(float(a[v][0]), rel=1e-6)


def test_quasistatic_contacts_centrifugal_raises_high_speed_torque():
    """With the project's quasi-static solver (centrifugal force on) the outer contacts load up at
    15000 r/min and M_sl rises above the static value; at 500 r/min the two agree (< 0.5 %)."""
    case = _case(500, 0, **{"friction.law": "coulomb"})
    qs = friction_torque(case, "500,15000rpm", contacts="quasistatic")["sliding_torque"].values
    st = friction_torque(case, "500,15000rpm")["sliding_torque"].values
    assert qs[0] == pytest.approx(st[0], rel=5e-3)
    assert qs[1] > st[1] * 1.005


# --------------------------------------------------------------------------- Table 3 (pure radial): second look


def _jones_c():
    return sp.jones_prl_symmetric()


def _heathcote_integral(c):
    return sp.heathcote_integral(c)


def test_heathcote_integral_closed_form():
    """sliding_prl.heathcote_integral against quadrature; Jones' c* = 0.347 is its minimiser."""
    c = _jones_c()
    num, _ = quad(lambda x: 0.75 * (1 - x * x) * abs(x * x - c * c), -1, 1, points=[-c, c])
    assert _heathcote_integral(c) == pytest.approx(num, rel=1e-10)
    assert c == pytest.approx(0.3473, abs=1e-4)
    assert 3 * c - c**3 == pytest.approx(1.0, abs=1e-12)  # zero net strip force (Jones 1959)
    assert _heathcote_integral(c) == pytest.approx(0.16114, abs=1e-5)
    cs = np.linspace(0.05, 0.95, 91)
    assert np.all(_heathcote_integral(cs) >= _heathcote_integral(c) - 1e-12)  # c* minimises the dissipation


def test_pure_radial_differential_sliding_is_the_heathcote_closed_form():
    """Independent check of the Table 3 physics (alpha = 0): per contact, the dissipated power per (mu omega_i) is
    Q a^2 |omega_B -+ Omega_k| / (2 R_k) I(c*), I = 1/5 - c^2 + 2c^3 - 2c^5/5, c* = 0.347 (Jones), with the
    rigid-body kinematics omega_m = (d_m - D)/(2 d_m), omega_B = (d_m^2 - D^2)/(2 d_m D) (cage frame;
    Harris & Kotzalas Vol. 2, Ch. 2).  Our Newton/strip solution agrees to < 1 % -- so the +69 % of
    Table 3 is not a numerical artefact of the rebuilt equilibrium."""
    _, _, _, states = _ball_state(0, 500)
    D, dm = 9.525e-3, 46e-3
    wm = (dm - D) / (2 * dm)
    wB = (dm**2 - D**2) / (2 * dm * D)
    ours = [0.0, 0.0]
    closed = [0.0, 0.0]
    for st in states:
        if st.Q[0] <= 0:
            continue
        b = sp.solve_ball(st, D, dm)
        assert b.omega_m == pytest.approx(wm, rel=2e-3)
        assert abs(b.omega_ball[0]) == pytest.approx(wB, rel=3e-3)
        for k, grad in ((0, wB + (1.0 - wm)), (1, wB - wm)):  # inner: ball + race; outer: ball - race
            ours[k] += b.contact_powers[k][1] + b.contact_powers[k][2]
            closed[k] += sp.heathcote_slip_power(st.Q[k], st.a[k], st.R[k], grad)
    for k in range(2):
        assert ours[k] == pytest.approx(closed[k], rel=0.01)


def test_pure_radial_no_load_distribution_reaches_table3():
    """dgbb_prl Table 3 (Fr = 500 N, column P 0.9057 N mm at 5000 r/min).  At alpha = 0 every contact has
    the same slip gradient per unit speed, so M_d ~ sum Q a^2 ~ sum Q^(5/3); under sum Q cos(psi) = F_r,
    Q >= 0, that sum is smallest for Q ~ cos(psi)^1.5 -- the zero-clearance rigid-ring distribution.
    Zero clearance is therefore our LOWER BOUND over non-preloaded load distributions (load zone,
    clearance, tilt), and it still exceeds Table 3 by > 60 %."""
    ms = {}
    for pd in ("0 um", "5 um", "12.5 um", "20 um"):
        ds = friction_torque(_case(0, 500, **{"bearing.diametral_clearance": pd}), "5000rpm")
        ms[pd] = _cell(ds, 5000, "sliding_torque")
        if pd == "0 um":
            Q = ds["ball_contact_load"].values
            psi = 2 * math.pi * np.arange(len(Q)) / len(Q)
            expect = np.clip(np.cos(psi), 0, None) ** 1.5
            assert Q / Q.max() == pytest.approx(expect, abs=2e-3)  # Stribeck's zero-clearance distribution
    vals = [ms[k] for k in ("0 um", "5 um", "12.5 um", "20 um")]
    assert np.all(np.diff(vals) > 0)
    assert ms["0 um"] > 1.6 * 0.9057  # Table 3, column P


def test_pure_radial_tracks_skf_shape_over_load_and_size():
    """Seed Figs. 13-14: under pure radial load the seed's P agrees with its SKF column for F_r = 500-1500 N
    and for 6206/6207/6208.  Our P / SKF-catalogue ratio is the same constant (0.80-0.82) over all six
    points: we reproduce the F_r^(5/3) d_m^-0.26 shape; what differs from Table 3 is one constant factor."""
    ratios = []
    for name, Fr in (("dgbb_6206", 500), ("dgbb_6206", 1000), ("dgbb_6206", 1500), ("dgbb_6207", 500), ("dgbb_6208", 500)):
        ds = friction_torque(load_case(name, **{"operating.axial_load": "0 N", "operating.radial_load": f"{Fr} N"}), "5000rpm")
        ratios.append(float(ds["sliding_torque"][0]) / float(ds["skf_sliding_torque"][0]))
    assert max(ratios) / min(ratios) < 1.03
    assert 0.75 < np.mean(ratios) < 0.87
