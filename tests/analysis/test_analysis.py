"""Analysis of dynamic runs: cage slip ratio, Poincare section, period classifier, annotate/summary.

Tiers:
- independent derivation: the theoretical cage speed re-derived from rolling without slip at both contacts;
- literature values: the classifier on the forced Duffing oscillator x'' + 0.3 x' - x + x^3 = g cos(1.2 t),
  whose periods are tabulated in Jordan & Smith, *Nonlinear Ordinary Differential Equations*, 4th ed., OUP 2007,
  Ch. 13 (period doubling of the Duffing oscillator: g = 0.20 period 1, 0.28 period 2, 0.29 period 4,
  0.37 period 5, 0.50 chaos, 0.65 period 2), and on the logistic map (chaotic at r = 4 with Lyapunov
  exponent ln 2, e.g. Ott, *Chaos in Dynamical Systems*, 2nd ed., Sec. 2.3; period 4 at r = 3.5,
  period 3 in the window at r = 3.83);
- synthetic cage runs (periodic, k-periodic, quasi-periodic, chaotic) through annotate(), noise robustness,
  too few points -> "undetermined".
"""

from __future__ import annotations

import json
import math

import numpy as np
import pytest

import hsbearing
from hsbearing.analysis import annotate, cage_slip_ratio, classify, poincare_points, summary, theoretical_cage_speed
from hsbearing.analysis.periods import correlation_dimension, lyapunov_exponent, zero_one_test
from hsbearing.analysis.poincare import crossing_times, poincare_section, steady_mask, transient_cut
from hsbearing.models.geometry import derive
from hsbearing.results import make_dataset, standard_attrs

RPM = 2 * math.pi / 60


@pytest.fixture(scope="module")
def case():
    return hsbearing.load_case("zhang2016")


# ----------------------------------------------------------------------------- synthetic data


from synthetic_runs import cage_run, duffing, logistic_points  # noqa: E402,F401 - tests/helpers (conftest.py)


def test_theoretical_cage_speed_rederived_from_rolling_without_slip(case):
    """Rolling at both contacts: (w_i - w_c) r_i = (w_c - w_o) r_o = w_b D/2, r_i,o = d_m/2 -/+ (D/2) cos(alpha)."""
    g = derive(case)
    for wi, wo, alpha in [(14000 * RPM, 0.0, None), (14000 * RPM, -3000 * RPM, math.radians(15)), (0.0, 5000 * RPM, 0.0)]:
        a = g.alpha0 if alpha is None else alpha
        ri = g.dm / 2 - g.D / 2 * math.cos(a)
        ro = g.dm / 2 + g.D / 2 * math.cos(a)
        wc = (wi * ri + wo * ro) / (ri + ro)  # solves (wi - wc) ri = (wc - wo) ro
        assert theoretical_cage_speed(g, wi, wo, alpha=alpha) == pytest.approx(wc, rel=1e-12)


def test_theoretical_cage_speed_default_case_value(case):
    # 7206 of Zhang et al. 2016 as the bundled case reads it: D = 9.525 mm, d_m = 46 mm, alpha_0 = 25 deg:
    # gamma = 9.525 cos 25 / 46 = 0.18766, w_c / w_i = (1 - gamma)/2 = 0.40617 (hand calculation)
    w = theoretical_cage_speed(case, 14000 * RPM, 0.0)
    assert w / (14000 * RPM) == pytest.approx(0.40617, abs=5e-5)
    assert w * 60 / (2 * math.pi) == pytest.approx(5686.4, abs=1.0)  # r/min


def test_theoretical_cage_speed_vectorised_and_contact_angle(case):
    g = derive(case)
    wi = np.array([1000.0, 2000.0, 3000.0])
    w = theoretical_cage_speed(g, wi, 0.0)
    assert w.shape == (3,) and np.allclose(w / wi, w[0] / wi[0])
    # larger contact angle -> smaller gamma -> faster cage (inner ring rotating)
    assert theoretical_cage_speed(g, 1000.0, 0.0, alpha=math.radians(40)) > theoretical_cage_speed(g, 1000.0, 0.0, alpha=0.0)
    a = np.radians([0.0, 20.0, 40.0])
    assert theoretical_cage_speed(g, 1000.0, 0.0, alpha=a).shape == (3,)


def test_raceway_control_cage_speed(case):
    """Jones (1959) outer-raceway control: closed form for a fixed outer ring; equal angles -> pure rolling."""
    from hsbearing.analysis.slip import raceway_control_cage_speed

    g = derive(case)
    wi = 14000 * RPM
    for ai, ao in [(29.12, 25.25), (40.0, 10.0), (25.0, 25.0)]:
        ai, ao = math.radians(ai), math.radians(ao)
        closed = wi * (1 - g.D / g.dm * math.cos(ai)) / (1 + math.cos(ai - ao))  # Harris & Kotzalas Vol. 2 Ch. 3
        assert raceway_control_cage_speed(g, wi, 0.0, ai, ao) == pytest.approx(closed, rel=1e-12)
    a = math.radians(20)
    for wo in (0.0, 3000 * RPM):
        pure = theoretical_cage_speed(g, wi, wo, alpha=a)
        assert raceway_control_cage_speed(g, wi, wo, a, a) == pytest.approx(pure, rel=1e-12)
        assert raceway_control_cage_speed(g, wi, wo, a, a, control="inner") == pytest.approx(pure, rel=1e-12)
    w = raceway_control_cage_speed(g, wi, 0.0, np.radians([30.0, 35.0]), np.radians([25.0, 20.0]))
    assert w.shape == (2,) and np.all(w > theoretical_cage_speed(g, wi, 0.0))  # inner angle > alpha_0 -> faster cage
    with pytest.raises(ValueError):
        raceway_control_cage_speed(g, wi, 0.0, a, a, control="both")


from hypothesis import given, settings  # noqa: E402
from hypothesis import strategies as st

_GEOM = derive(hsbearing.load_case("zhang2016"))


@settings(max_examples=60, deadline=None)
@given(s=st.floats(-0.5, 0.9), w=st.floats(1.0, 5000.0), wo=st.floats(-2000.0, 2000.0),
       a=st.floats(0.0, 1.2))
def test_slip_ratio_properties(s, w, wo, a):
    """S_c of a cage at (1 - s) omega_c,th is s; omega_c,th is linear in the ring speeds."""
    g = _GEOM
    th = theoretical_cage_speed(g, w, wo, alpha=a)
    if abs(th) > 1e-6:
        assert cage_slip_ratio((1 - s) * th, th) == pytest.approx(s, abs=1e-9)
    lin = theoretical_cage_speed(g, w, 0.0, alpha=a) + theoretical_cage_speed(g, 0.0, wo, alpha=a)
    assert th == pytest.approx(lin, rel=1e-12, abs=1e-9)
    # the cage turns between the two rings
    assert min(w, wo) - 1e-9 <= th <= max(w, wo) + 1e-9


def test_cage_slip_ratio_definition():
    assert cage_slip_ratio(97.0, 100.0) == pytest.approx(0.03)
    assert cage_slip_ratio(100.0, 100.0) == 0.0
    assert cage_slip_ratio(105.0, 100.0) == pytest.approx(-0.05)  # cage faster than pure rolling -> negative
    s = cage_slip_ratio(np.array([90.0, 100.0]), 100.0)
    assert np.allclose(s, [0.1, 0.0])
    assert math.isnan(cage_slip_ratio(1.0, 0.0))


# ----------------------------------------------------------------------------- classifier on known maps and flows


@pytest.mark.parametrize("r", [4.0, 3.9])
def test_logistic_chaos(r):
    label, conf, det = classify(logistic_points(r, n=600))
    assert label == "chaos", det
    assert conf > 0.9
    assert det["k01"] > 0.8 and det["lyapunov"] > 0.3  # both indicators (0-1 test counts from 400 points)
    label, conf, det = classify(logistic_points(r, n=60))  # short series: both indicators still agree
    assert label == "chaos" and det["k01"] > 0.5 and det["embedding_dimension"] == 1, det


def test_logistic_lyapunov_is_ln2():
    # r = 4: lambda = ln 2 = 0.693 per iteration (Ott, Sec. 2.3); Rosenstein estimate from 400 points
    lam = lyapunov_exponent(logistic_points(4.0, n=600))
    assert lam == pytest.approx(math.log(2), rel=0.15)


@pytest.mark.parametrize("r,k", [(3.2, 2), (3.5, 4), (3.83, 3)])
def test_logistic_periodic_windows(r, k):
    label, conf, det = classify(logistic_points(r))
    assert label == ("1 period" if k == 1 else f"{k} periods")
    assert det["period"] == k and conf > 0.9


@pytest.mark.parametrize("g,expected", [(0.20, "1 period"), (0.28, "2 periods"), (0.29, "4 periods"),
                                        (0.37, "5 periods"), (0.50, "chaos"), (0.65, "2 periods")])
def test_duffing_period_doubling_jordan_smith(g, expected):
    """Jordan & Smith (2007) Ch. 13: Duffing x'' + 0.3x' - x + x^3 = g cos 1.2t, stroboscopic section."""
    t, y, T, spp, skip = duffing(g, n_periods=200 if expected != "chaos" else 260)
    sec = y[:, ::spp].T[skip:]
    label, conf, det = classify(sec, signal=y.T[skip * spp:])
    assert label == expected, det


def test_quasi_periodic_torus_section():
    rho = (math.sqrt(5) - 1) / 2
    th = 2 * np.pi * rho * np.arange(400)
    P = np.column_stack([np.cos(th) + 0.3 * np.cos(2 * th), np.sin(th)])
    label, conf, det = classify(P)
    assert label == "quasi-periodic", det
    assert det["kind"] == "invariant-curve" and det["same_sense"] == 1.0 and det["turns"] > 100
    assert det["k01"] is None  # an invariant curve is recognised before any chaos indicator is computed
    assert det["rotation_number"] == pytest.approx(1 - rho, abs=1e-3)  # folded to [0, 0.5]
    assert det["closed_curve_ratio"] < 1.2


def test_quasi_periodic_near_resonance_is_not_periodic():
    # rotation number 0.25 + 0.003: the 4 "clusters" drift by 2 pi * 0.003 * 4 per round -> not 4 periods
    th = 2 * np.pi * (0.25 + 0.003) * np.arange(400)
    P = np.column_stack([np.cos(th), np.sin(th)])
    label, _, det = classify(P)
    assert label == "quasi-periodic", det


def test_period_k_clusters_and_noise():
    rng = np.random.default_rng(3)
    base = np.array([[1.0, 0.0], [0.2, 0.9], [-1.0, 0.1], [0.1, -0.8]])
    P = np.tile(base, (30, 1))
    assert classify(P)[0] == "4 periods"
    noisy = P + 0.002 * rng.standard_normal(P.shape)  # 0.1 % of the extent
    label, conf, det = classify(noisy)
    assert label == "4 periods" and 0.5 < conf <= 1.0


def test_still_converging_period_is_flagged():
    n = np.arange(60)
    P = np.column_stack([0.3 + 0.5 * np.exp(-n / 4.0), -0.2 + 0.3 * np.exp(-n / 4.0)])  # settles by point ~20
    label, conf, det = classify(P, scale=[1.0, 1.0])
    assert label == "1 period" and "transient still decaying" in det["reason"] and conf <= 0.8


def test_noise_does_not_turn_one_period_into_chaos():
    rng = np.random.default_rng(7)
    for sigma in (1e-4, 1e-3, 4e-3):  # fraction of the orbit extent
        P = np.array([0.4, -0.2]) + sigma * rng.standard_normal((300, 2))
        label, conf, det = classify(P, scale=[1.0, 1.0])
        assert label == "1 period", (sigma, det)
    # the same cloud without an attractor scale cannot be told from noise: documented limitation
    P = np.array([0.4, -0.2]) + 1e-3 * rng.standard_normal((300, 2))
    assert classify(P)[0] != "1 period"


def test_quasi_periodic_with_small_noise_stays_quasi_periodic():
    rng = np.random.default_rng(11)
    rho = (math.sqrt(5) - 1) / 2
    th = 2 * np.pi * rho * np.arange(400)
    P = np.column_stack([np.cos(th), 0.5 * np.sin(th)]) + 0.003 * rng.standard_normal((400, 2))
    assert classify(P)[0] == "quasi-periodic"


@pytest.mark.parametrize("which", ["logistic", "torus", "period4"])
def test_labels_do_not_depend_on_units(which):
    """Per-coordinate scaling and offsets (m vs um, mm/s vs m/s) leave the label and the indicators unchanged."""
    if which == "logistic":
        P = logistic_points(3.9, n=200)
    elif which == "torus":
        th = 2 * np.pi * (math.sqrt(2) - 1) * np.arange(200)
        P = np.column_stack([np.cos(th), 0.4 * np.sin(th)])
    else:
        P = np.tile([[1.0, 0.0], [0.2, 0.9], [-1.0, 0.1], [0.1, -0.8]], (50, 1))
    a = classify(P)
    b = classify(P * np.array([1e-6, 3e-3]) + np.array([5e-6, -1e-3]))
    assert a[0] == b[0] and a[1] == pytest.approx(b[1], abs=1e-9)
    for key in ("lyapunov", "correlation_dimension"):
        if a[2][key] is not None:
            assert a[2][key] == pytest.approx(b[2][key], rel=1e-6, abs=1e-9)


def test_too_few_points_is_undetermined():
    label, conf, det = classify(np.array([[0.0, 1.0], [0.0, 1.0], [0.0, 1.0]]))
    assert label == "undetermined" and conf == 0.0 and "only 3" in det["reason"]
    # aperiodic but too short to separate quasi-periodic from chaos
    label, conf, det = classify(logistic_points(4.0, n=30))
    assert label == "undetermined" and "need >=" in det["reason"]
    # empty / non-finite input
    assert classify(np.zeros((0, 2)))[0] == "undetermined"
    assert classify(np.full((10, 2), np.nan))[0] == "undetermined"


def test_scattered_groups_and_rings_around_a_period_2_orbit():
    """Random scatter around 2 groups is not proven chaos (the FNN test finds no low-dimensional embedding):
    undetermined, with the groups named; small rings around the 2 points -> quasi-periodic (2 islands)."""
    rng = np.random.default_rng(5)
    base = np.tile([[1.0, 0.0], [-1.0, 0.2]], (35, 1))
    scattered = base + 0.06 * rng.standard_normal(base.shape)  # spread ~ 8 % of the orbit > tol 2 %
    label, conf, det = classify(scattered, scale=[2.4, 2.4])
    assert label == "undetermined" and det["groups"] == 2 and "2 separated groups" in det["reason"], det
    th = 2 * np.pi * 0.618 * np.arange(70)
    rings = base + 0.15 * np.column_stack([np.cos(th), np.sin(th)])
    label, conf, det = classify(rings, scale=[2.4, 2.4])
    assert label == "quasi-periodic" and det["local_thickness"] < 0.3, det


def test_banded_logistic_chaos():
    # r = 3.6: two-band chaotic attractor (Lyapunov ~0.18 per iteration)
    label, conf, det = classify(logistic_points(3.6, n=300))
    assert label == "chaos", det


def test_local_thickness_curve_vs_cloud():
    from hsbearing.analysis.periods import local_thickness

    rng = np.random.default_rng(2)
    for n in (50, 200):
        th = 2 * np.pi * rng.uniform(size=n)
        assert local_thickness(np.column_stack([np.cos(th), 0.5 * np.sin(th)])) < 0.15
        assert local_thickness(rng.standard_normal((n, 2))) > 0.5


def test_zero_one_test_limits():
    rng = np.random.default_rng(0)
    n = np.arange(1000)
    assert zero_one_test(np.sin(0.9 * n) + 0.5 * np.sin(0.9 * math.sqrt(2) * n)) < 0.2  # quasi-periodic
    assert zero_one_test(logistic_points(4.0, n=1000)[:, 0]) > 0.9
    assert math.isnan(zero_one_test(rng.standard_normal(5)))


def test_correlation_dimension_of_curve_and_area():
    rng = np.random.default_rng(1)
    th = rng.uniform(0, 2 * np.pi, 800)
    assert correlation_dimension(np.column_stack([np.cos(th), np.sin(th)])) == pytest.approx(1.0, abs=0.2)
    assert correlation_dimension(rng.uniform(size=(800, 2))) == pytest.approx(2.0, abs=0.3)


def test_zhang2016_vocabulary_matches_labels():
    import csv
    from pathlib import Path

    rows = [r for r in csv.DictReader(l for l in (Path(__file__).resolve().parents[1] / "data" / "zhang2016_periods.csv").open()
                                      if not l.startswith("#"))]
    labels = {r["response"] for r in rows}
    from hsbearing.analysis.periods import period_label

    allowed = {"quasi-periodic", "chaos"} | {period_label(k) for k in range(1, 17)}
    assert labels <= allowed, labels - allowed


# ----------------------------------------------------------------------------- Poincare section


def test_crossing_times_interpolated():
    t = np.linspace(0, 1, 101)
    phase = 2 * np.pi * 3.3 * t  # 3 crossings of 2 pi k at t = k / 3.3
    tc = crossing_times(t, phase)
    assert np.allclose(tc, np.arange(1, 4) / 3.3, atol=1e-12)
    # a back-and-forth phase counts a multiple of 2 pi only when crossed upwards
    ph = np.array([6.0, 6.4, 6.2, 6.5, 12.7])
    assert len(crossing_times(np.arange(5.0), ph)) == 2


def test_section_points_of_a_synchronous_whirl(case):
    ds = cage_run("period", case, n_rev=20, transient=False)
    tc, P = poincare_section(ds, "cage_revolution")
    # the cage angle starts at 0: crossings at every revolution after the transient cut
    assert len(P) >= 13
    wc = float(ds["cage_speed"][0])
    assert np.allclose(np.diff(tc), 2 * np.pi / wc, rtol=1e-9)
    assert np.allclose(P[:, 0], 20e-6 * math.cos(0.3), rtol=1e-4)
    assert np.allclose(P[:, 1], -20e-6 * wc * math.sin(0.3), rtol=1e-4)


def test_section_without_angle_or_velocity_agrees(case):
    full = cage_run("quasi", case, n_rev=30)
    bare = cage_run("quasi", case, n_rev=30, with_angle=False, with_velocity=False)
    t1, P1 = poincare_section(full, "cage_revolution")
    t2, P2 = poincare_section(bare, "cage_revolution")  # angle integrated from cage_speed, V_Y differentiated from D_Y
    # crossings fall on output samples here, so float rounding may move one across the transient cut: match times
    j = np.abs(t2[None, :] - t1[:, None]).argmin(axis=1)
    ok = np.abs(t2[j] - t1) < 1e-9
    assert ok.sum() >= len(t1) - 1 and len(t1) >= 18
    ext = np.ptp(P1, axis=0)
    assert np.all(np.abs(P1[ok] - P2[j[ok]]) <= 2e-3 * ext)


def test_section_independent_of_output_interval(case):
    """Coarser output (40 instead of 200 samples per revolution) gives the same section points within 0.5 %."""
    fine = cage_run("quasi", case, n_rev=30, spr=200, transient=False)
    coarse = cage_run("quasi", case, n_rev=30, spr=40, transient=False)
    t1, P1 = poincare_section(fine, "cage_revolution", transient=0.3)
    t2, P2 = poincare_section(coarse, "cage_revolution", transient=0.3)
    j = np.abs(t2[None, :] - t1[:, None]).argmin(axis=1)
    ok = np.abs(t2[j] - t1) < 1e-9
    assert ok.sum() >= len(t1) - 1
    assert np.all(np.abs(P1[ok] - P2[j[ok]]) <= 5e-3 * np.ptp(P1, axis=0))


def test_auto_transient_waits_for_the_drift_to_end(case):
    """A whirl growing until t = 0.45 T (like a cage spiralling out to its guide land) and a cage-speed step."""
    ds = cage_run("period", case, n_rev=60, transient=False)
    t = ds.time.values
    T = t[-1]
    grow = np.clip(t / (0.45 * T), 0.05, 1.0)
    ph = ds.cage_angle.values + 0.3
    wc = float(ds.cage_speed[0])
    ds = ds.assign(cage_center_y=("time", 20e-6 * grow * np.cos(ph)), cage_center_z=("time", 20e-6 * grow * np.sin(ph)),
                   cage_velocity_y=("time", -20e-6 * grow * wc * np.sin(ph)))
    cut = transient_cut(ds, "auto")
    rev = 2 * np.pi / wc
    assert 0.45 * T - 2 * rev <= cut <= 0.45 * T + 2 * rev  # within 2 % of the final radius: +-2 revolutions
    out = annotate(ds, case)
    assert out.attrs["transient_discarded"] == pytest.approx(cut)
    assert float(out["whirl_amplitude"]) == pytest.approx(20e-6, rel=1e-3)
    assert out.attrs["classification"] == "1 period"
    # fixed fraction on request
    assert transient_cut(ds, 0.1) == pytest.approx(0.1 * T)
    assert annotate(ds, case, transient=0.1).attrs["transient_discarded"] == pytest.approx(0.1 * T)
    # a cage-speed drop at 0.5 T (a new regime): the cut follows, capped at 60 % of the span
    w = np.where(t < 0.5 * T, wc * 1.01, wc)
    assert 0.5 * T - rev <= transient_cut(ds.assign(cage_speed=("time", w)), "auto") <= 0.5 * T + 2 * rev
    w = np.where(t < 0.7 * T, wc * 1.01, wc)  # (a change inside the last 25 %, the reference, is not detected)
    assert transient_cut(ds.assign(cage_speed=("time", w)), "auto") == pytest.approx(0.6 * T)
    # stationary synthetic runs keep the 30 % floor
    for kind in ("k", "quasi", "chaos"):
        run = cage_run(kind, case)
        assert transient_cut(run, "auto") == pytest.approx(0.3 * float(run.time[-1]))
    # a growth to saturation read by saturation_cut: the drift end without the 60 % cap, the revolutions after it
    from hsbearing.analysis.poincare import saturation_cut

    grow = np.clip(t / (0.7 * T), 0.05, 1.0)  # ends before the reference (the last 25 %)
    slow = ds.assign(cage_center_y=("time", 20e-6 * grow * np.cos(ph)), cage_center_z=("time", 20e-6 * grow * np.sin(ph)))
    assert transient_cut(slow, "auto") == pytest.approx(0.6 * T)
    cut, kept = saturation_cut(slow)
    assert 0.7 * T - 2 * rev <= cut <= 0.7 * T + 2 * rev
    assert (T - cut) / rev - 2 <= kept <= (T - cut) / rev  # complete revolutions after the one the cut is in
    for kind in ("k", "quasi", "chaos"):
        run = cage_run(kind, case)
        assert saturation_cut(run)[0] == pytest.approx(0.3 * float(run.time[-1]))


def test_plane_section(case):
    """Alternative section: D_Z crossing its mean upwards; a circular whirl gives one point per whirl turn."""
    ds = annotate(cage_run("period", case), case, section="plane")
    assert ds.attrs["poincare_section_kind"] == "plane" and "D_Z crosses" in ds.attrs["poincare_section"]
    assert ds.attrs["classification"] == "1 period"
    P = poincare_points(ds, section="plane")
    assert np.allclose(P[:, 0], 20e-6, rtol=1e-3) and np.allclose(P[:, 1], 0.0, atol=1e-3 * 20e-6 * 600)
    assert annotate(cage_run("quasi", case), case, section="plane").attrs["classification"] == "quasi-periodic"
    with pytest.raises(ValueError, match="unknown Poincare section"):
        annotate(cage_run("period", case, n_rev=5), case, section="radial")


def test_steady_mask():
    m, dt = steady_mask(np.linspace(0, 10, 11), 0.3)
    assert dt == pytest.approx(3.0) and m.sum() == 8


# ----------------------------------------------------------------------------- annotate / summary


@pytest.mark.parametrize("kind,expected", [("period", "1 period"), ("k", "4 periods"), ("quasi", "quasi-periodic"),
                                           ("chaos", "chaos")])
def test_annotate_labels_synthetic_cage_runs(case, kind, expected):
    """The cage-revolution (stroboscopic) section, kept as an option: these runs are clocked by the cage."""
    ds = annotate(cage_run(kind, case), case, section="cage_revolution")
    assert ds.attrs["classification"] == expected, ds.attrs["classification_details"]
    assert 0.0 < ds.attrs["classification_confidence"] <= 1.0
    assert ds.attrs["transient_discarded"] == pytest.approx(0.3 * float(ds.time[-1]))
    assert "cage revolution" in ds.attrs["poincare_section"]
    assert ds.attrs["classification_alternative_section"] == "transverse"
    json.loads(ds.attrs["classification_details"])


def test_rotation_number_matches_whirl_ratio(case):
    """Quasi-periodic cage run: section rotation number = incommensurate/cage frequency ratio (folded)."""
    ds = annotate(cage_run("quasi", case), case)
    det = json.loads(ds.attrs["classification_details"])
    rho = (math.sqrt(5) - 1) / 2
    assert det["rotation_number"] == pytest.approx(min(rho, 1 - rho), abs=2e-3)


def test_annotate_three_periods_and_noise(case):
    ds = annotate(cage_run("k", case, k=3, noise=0.002), case)
    assert ds.attrs["classification"] == "3 periods"
    ds = annotate(cage_run("period", case, noise=0.003), case)
    assert ds.attrs["classification"] == "1 period"


def test_annotate_scalars(case):
    ds = annotate(cage_run("period", case, slip=0.03), case)
    assert float(ds["mean_cage_slip_ratio"]) == pytest.approx(0.03, rel=1e-9)
    assert ds["cage_slip_ratio"].dims == ("time",) and ds["cage_slip_ratio"].attrs["units"] == "1"
    assert float(ds["whirl_amplitude"]) == pytest.approx(20e-6, rel=1e-3)
    assert float(ds["whirl_radius_max"]) == pytest.approx(20e-6, rel=1e-3)
    wc = float(ds["cage_speed"][0])
    assert float(ds["whirl_frequency"]) == pytest.approx(wc / (2 * np.pi), rel=2e-3)  # forward, synchronous
    assert float(ds["whirl_frequency_ratio"]) == pytest.approx(1.0, rel=2e-3)
    assert ds.attrs["guide_clearance"] == pytest.approx(0.2e-3)
    # no contact angles in the synthetic run: no raceway-control cross-check
    assert "raceway_control_cage_speed" not in ds
    ang = ds.assign(inner_contact_angle=(("time", "ball"), np.full((ds.time.size, 11), math.radians(29.0))),
                    outer_contact_angle=(("time", "ball"), np.full((ds.time.size, 11), math.radians(25.0))))
    out = annotate(ang, case)
    from hsbearing.analysis.slip import raceway_control_cage_speed

    w_rc = raceway_control_cage_speed(case, 14000 * RPM, 0.0, math.radians(29.0), math.radians(25.0))
    assert float(out["raceway_control_cage_speed"]) == pytest.approx(w_rc)
    assert float(out["mean_cage_slip_ratio_raceway_control"]) == pytest.approx(1 - wc / w_rc)
    # backward whirl has a negative frequency
    bw = cage_run("period", case).assign(cage_center_z=lambda d: -d.cage_center_z)
    assert float(annotate(bw, case)["whirl_frequency_ratio"]) == pytest.approx(-1.0, rel=2e-3)


def test_annotate_uses_case_from_attrs_and_does_not_modify_input(case):
    ds = cage_run("period", case)
    before = set(ds.variables)
    out = annotate(ds)  # case re-read from attrs["case_toml"]
    assert set(ds.variables) == before and "classification" not in ds.attrs
    assert float(out["theoretical_cage_speed"]) == pytest.approx(theoretical_cage_speed(case, 14000 * RPM, 0.0))


def test_annotate_short_run_is_undetermined(case):
    ds = annotate(cage_run("period", case, n_rev=6), case)
    assert ds.attrs["classification"] == "undetermined"
    assert "simulate longer" in ds.attrs["classification_reason"]


def test_annotate_partial_run_ending_in_nan(case):
    """A failed run may end with non-finite samples: summaries use the finite ones."""
    ds = cage_run("period", case, n_rev=30).drop_vars("cage_angle")
    y, w = ds.cage_center_y.values.copy(), ds.cage_speed.values.copy()
    y[-500:] = np.nan
    w[-500:] = np.nan
    out = annotate(ds.assign(cage_center_y=("time", y), cage_speed=("time", w)), case)
    assert float(out["mean_cage_slip_ratio"]) == pytest.approx(0.03, rel=1e-6)
    assert float(out["whirl_amplitude"]) == pytest.approx(20e-6, rel=1e-3)
    assert out.attrs["classification"] == "1 period"


def test_annotate_missing_variable(case):
    ds = cage_run("period", case, n_rev=5).drop_vars("cage_center_z")
    with pytest.raises(ValueError, match="cage_center_z"):
        annotate(ds, case)


def test_annotated_run_round_trips_netcdf(case, tmp_path):
    from hsbearing.results import open_run, write_netcdf

    ds = annotate(cage_run("k", case, n_rev=40), case)
    p = write_netcdf(ds, tmp_path / "run.nc")
    back = open_run(p)
    assert back.attrs["classification"] == ds.attrs["classification"]
    assert np.allclose(poincare_points(back), poincare_points(ds))
    s = summary(back)
    assert s["classification"] == "4 periods" and s["n_poincare_points"] == back["poincare_y"].size


def test_summary(case):
    ds = cage_run("quasi", case)
    Z = 11
    q = np.linspace(300, 320, Z)
    ds = ds.assign(inner_contact_load=(("time", "ball"), np.tile(q, (ds.time.size, 1))))
    s = summary(ds, case)  # annotates on the fly
    assert s["classification"] == "quasi-periodic"
    assert s["mean_inner_contact_load"] == pytest.approx(310.0)
    assert s["max_inner_contact_load"] == pytest.approx(320.0)
    assert math.isnan(s["mean_outer_contact_load"])
    assert s["mean_cage_slip_ratio"] == pytest.approx(0.03, rel=1e-6)
    assert s["status"] == "ok"
    assert s["transient_discarded"] == pytest.approx(0.3 * float(ds.time[-1]))
    assert s["guide_clearance_used"] == pytest.approx(s["whirl_radius_max"] / 0.2e-3)
    for key in ("whirl_amplitude", "whirl_frequency", "classification_confidence", "mean_cage_speed"):
        assert isinstance(s[key], float)


def test_summary_of_quasi_static_dataset(case):
    ds = make_dataset({"inner_contact_load": np.full(11, 400.0), "outer_contact_load": np.full(11, 450.0)},
                      attrs=standard_attrs(case))
    s = summary(ds)
    assert s["classification"] == "static"
    assert s["mean_outer_contact_load"] == pytest.approx(450.0)


@pytest.mark.slow
def test_real_dynamic_run_is_annotated(case, tmp_path):
    """Integration with the dynamic model (hsbearing.systems.angular_contact.dynamics): a 0.15 s run carries every analysis output."""
    from hsbearing.systems import plot_run

    ds = hsbearing.simulate(case, duration=0.15)
    for name in ("cage_slip_ratio", "mean_cage_slip_ratio", "whirl_amplitude", "whirl_frequency", "poincare_y"):
        assert name in ds
    # a label of the closed vocabulary (classify.LABELS, "k periods" with an integer k >= 2), a confidence in
    # [0, 1], and a stated reason whenever the classifier declines
    import re

    label = ds.attrs["classification"]
    assert re.fullmatch(r"1 period|([2-9]|[1-9][0-9]+) periods|quasi-periodic|chaos|undetermined", label), label
    assert 0.0 <= float(ds.attrs["classification_confidence"]) <= 1.0
    assert label != "undetermined" or ds.attrs["classification_reason"]
    assert np.isfinite(float(ds["mean_cage_slip_ratio"])) and abs(float(ds["mean_cage_slip_ratio"])) < 0.5
    assert ds["poincare_y"].size >= 5  # ~14 cage revolutions, at most 60 % discarded
    assert np.all(np.hypot(ds.cage_center_y, ds.cage_center_z) <= 1.05 * ds.attrs["guide_clearance"])
    assert plot_run(ds, tmp_path / "run.png").exists()


def test_fixed_point_cage_is_one_period_not_undetermined():
    """A cage held still at an offset (noise-level motion << guide clearance) is a fixed point of the
    section: "1 period" (cage_whirl.md finding; the classifier's scale floor is half the clearance)."""
    import xarray as xr

    from hsbearing.analysis import annotate

    rng = np.random.default_rng(3)
    t = np.arange(0, 0.6, 5e-5)
    w = 600.0
    y = 8e-6 + 2e-8 * rng.standard_normal(t.size)  # 8 um offset, 20 nm noise, clearance 200 um
    z = -3e-6 + 2e-8 * rng.standard_normal(t.size)
    ds = xr.Dataset(
        {"cage_speed": ("time", np.full(t.size, w)), "cage_center_y": ("time", y), "cage_center_z": ("time", z),
         "cage_angle": ("time", w * t)},
        coords={"time": t},
        attrs={"guide_clearance": 2e-4},
    )
    out = annotate(ds, None)
    assert out.attrs["classification"] == "1 period", out.attrs["classification_reason"]


def test_summary_carries_model_scalars_for_sweeps():
    """Sweep tables take every scalar a model stores (the gyro bearing's rfmc/sfmc), not only cage metrics."""
    import hsbearing
    from hsbearing.analysis import summary

    ds = hsbearing.simulate("jiang2014_gyro", duration=0.05)
    s = summary(ds)
    assert s["rfmc"] == pytest.approx(float(ds["rfmc"])) and s["rfmc"] > 0
