"""Gyroscope mini bearing with ribbon cage (Jiang et al. 2014): friction sources and cage dynamics.

Literature values come from tests/data/jiang2014_friction_moments.csv (Jiang et al. 2014 Table 2, calculated values)
and jiang2014_gyro_bearing.csv (Table 1).  Runs here are short (<= 0.15 s simulated); see
docs/validation/gyro.md for the full comparison.
"""

from __future__ import annotations

import csv
import math
from pathlib import Path

import numpy as np
import pytest

import hsbearing
from hsbearing.case import CaseError
from hsbearing.systems.gyro import model as gyro  # the gyro system (physics: hsbearing.models.friction.gyro)

DATA = Path(__file__).resolve().parents[2] / "data"


def _table2():
    with open(DATA / "jiang2014_friction_moments.csv") as fh:
        rows = [r for r in csv.DictReader(line for line in fh if not line.startswith("#"))]
    return [{k: float(v) for k, v in r.items()} for r in rows]


def _case(**kw):
    return hsbearing.load_case("jiang2014_gyro", **kw)


# --------------------------------------------------------------------------- case vs Table 1


def test_case_matches_table1():
    """The bundled case carries Table 1 of Jiang et al. 2014 (jiang2014_gyro_bearing.csv)."""
    with open(DATA / "jiang2014_gyro_bearing.csv") as fh:
        rows = {r["parameter"]: float(r["value"]) for r in csv.DictReader(line for line in fh if not line.startswith("#"))}
    c = _case()
    mm = 1e-3
    assert c.bearing.ball_diameter == pytest.approx(rows["ball_diameter_Dw"] * mm)
    assert c.bearing.ball_count == rows["number_of_balls_z"]
    assert c.bearing.pitch_diameter == pytest.approx(0.5 * (rows["inner_diameter_of_inner_race_d"] + rows["outer_diameter_of_outer_race_D"]) * mm)
    assert c.bearing.inner_conformity == rows["inner_race_conformity_fi"]
    assert c.cage.pocket_depth == pytest.approx(rows["depth_of_ribbon_cage_pocket_k"] * mm)
    assert c.cage.pocket_diameter == pytest.approx(rows["diameter_of_cage_pocket_dp"] * mm)
    assert c.cage.thickness == pytest.approx(rows["thickness_of_cage_s"] * mm)
    A = c.cage.pocket_depth - c.bearing.ball_diameter / 2  # seed Sec. 3.2: A = k - D_w/2
    assert A == pytest.approx(rows["clearance_between_cage_pocket_and_ball_A"] * mm)
    assert c.friction.coefficient == 0.08 and c.friction.hysteresis_loss == 0.008


# --------------------------------------------------------------------------- friction sources (Eq. 2)


def test_heathcote_pure_rolling_lines():
    """Symmetric PRLs from the strip force balance: +/-0.347 a (Heathcote 1921)."""
    X1, X2 = gyro.pure_rolling_lines(0.0)
    assert X2 == pytest.approx(0.347, abs=5e-4) and X1 == pytest.approx(-X2)
    # band carries half the strip load for any shift that keeps it inside
    for s in (0.2, 0.6, 1.0):
        X1, X2 = gyro.pure_rolling_lines(s)
        assert X1 + X2 == pytest.approx(-s)
        assert (X2 - X1) - (X2**3 - X1**3) / 3 == pytest.approx(2 / 3)


def test_differential_sliding_factor_readings():
    """The physical reading of Eq. 2's M_D bracket stays below the bound 1/10; the printed signs with cubes do not."""
    X1, X2 = gyro.pure_rolling_lines(0.0)
    phys = gyro.differential_sliding_factor(X1, X2, "physical")
    assert 0.0 < phys < 0.1
    # independent quadrature of the strip model: load (1 - Y^2), arm Y^2/2, sign reversing at the PRLs
    Y = np.linspace(-1, 1, 400001)
    sgn = np.where((Y > X1) & (Y < X2), -1.0, 1.0)
    quad = np.trapezoid(0.75 * (1 - Y**2) * sgn * Y**2 / 2, Y)
    assert phys == pytest.approx(quad, rel=1e-5)
    assert gyro.differential_sliding_factor(X1, X2, "seed_cubes") > 0.1


def test_pivoting_moment_strip_quadrature():
    """dM_S of Eq. 2 equals the strip-model moment about the normal; zero for symmetric PRLs."""
    X1, X2 = gyro.pure_rolling_lines(0.5)
    Y = np.linspace(-1, 1, 400001)
    sgn = np.where((Y > X1) & (Y < X2), 1.0, -1.0)
    quad = abs(np.trapezoid(0.75 * (1 - Y**2) * sgn * Y, Y))  # per mu Q a
    assert gyro.pivoting_moment(1.0, 1.0, 1.0, X1, X2) == pytest.approx(quad, rel=1e-5)
    X1, X2 = gyro.pure_rolling_lines(0.0)
    assert gyro.pivoting_moment(0.08, 1.0, 5e-5, X1, X2) == pytest.approx(0.0, abs=1e-18)


def test_hysteresis_and_viscous_formulas():
    """Eq. 2: dM_E = 3/16 Q b alpha_r; M_L = 160e-7 f0 dm^3 [N mm, dm in mm]."""
    assert gyro.hysteresis_moment(2.0, 1e-5, 0.008) == pytest.approx(3 / 16 * 2.0 * 1e-5 * 0.008)
    assert gyro.viscous_moment(1.0, 6.5e-3) == pytest.approx(160e-7 * 6.5**3 * 1e-3)


@pytest.mark.parametrize("load", [1.0, 2.0, 3.0])
def test_rfmc_table2(load):
    """RFMC = M_E + M_D + M_S + M_L vs Jiang et al. 2014 Table 2 / Table 3 (calculated): 2.81 / 6.21 / 10.11 uN m, within 4 %
    (measured -3.15 %, -0.86 %, -1.53 %; the README row states this tolerance)."""
    ref = {r["load_N"]: r["RFMC_uNm"] for r in _table2()}[load]
    st = gyro.static_friction(_case(**{"operating.axial_load": f"{load} N"}))
    assert st.rfmc * 1e6 == pytest.approx(ref, rel=0.04)
    # every source present and positive; M_E, M_D, M_S grow with the load
    assert st.M_E > 0 and st.M_D > 0 and st.M_S > 0


def test_static_sources_grow_with_load():
    """Seed Sec. 4: M_E, M_D and M_S increase with the thrust load."""
    s = [gyro.static_friction(_case(**{"operating.axial_load": f"{F} N"})) for F in (1, 2, 3)]
    for name in ("M_E", "M_D", "M_S"):
        v = [getattr(x, name) for x in s]
        assert v[0] < v[1] < v[2], name
    assert s[0].beta < s[1].beta < s[2].beta  # thrust opens the contact angle of a zero-clearance bearing


# --------------------------------------------------------------------------- frames and pocket (Eqs. 5, 6, 15, Sec. 3.2)


def test_transform_orthogonal_and_euler_rates():
    """A_Ic (Eq. 5, sign-corrected) is a rotation; Eq. 15 inverts phi of Eq. 6."""
    A = np.empty((3, 3))
    P = np.empty((3, 3))
    for th in [(0.3, 0.2, -0.1), (2.0, -0.05, 0.03)]:
        gyro.transform_Ic(*th, A)
        assert np.allclose(A @ A.T, np.eye(3), atol=1e-14)
        assert np.linalg.det(A) == pytest.approx(1.0)
        gyro.euler_rate_matrix(*th, P)
        tx, ty, tz = th
        phi = np.array([[math.cos(ty) * math.cos(tz), math.sin(tz), 0],
                        [-math.cos(ty) * math.sin(tz), math.cos(tz), 0],
                        [math.sin(ty), 0, 1]])  # seed Eq. 6
        assert np.allclose(P @ phi, np.eye(3), atol=1e-13)


def test_pocket_contact_states():
    """Seed Sec. 3.2: no contact at the centre, two points for dx = 0, one point for dx != 0."""
    c = _case()
    e, nabla = gyro.pocket_geometry(c.bearing.ball_diameter, c.cage.pocket_diameter, c.cage.pocket_depth)
    assert e == pytest.approx(0.03e-3) and nabla == pytest.approx(0.05e-3)
    dp, dm_ = gyro.pocket_penetration(0.0, 0.0, 0.0, e, nabla)
    assert dp < 0 and dm_ < 0  # no contact
    dz = 0.0401e-3  # circumferential play sqrt(nabla^2 - e^2) = 0.04 mm
    dp, dm_ = gyro.pocket_penetration(0.0, 0.0, dz, e, nabla)
    assert dp > 0 and dm_ > 0 and dp == pytest.approx(dm_)  # two points
    dp, dm_ = gyro.pocket_penetration(0.005e-3, 0.0, dz, e, nabla)
    assert dp > 0 and dm_ < 0  # one point (far cup)
    # axial play equals the seed's clearance A = k - D/2
    dp, _ = gyro.pocket_penetration(0.02e-3, 0.0, 0.0, e, nabla)
    assert dp == pytest.approx(0.0, abs=1e-12)


def test_speed_profile():
    """Start at constant acceleration; oscillation reverses every period through a ramp of the same slope."""
    w = 5 * 2 * math.pi / 60
    assert gyro.outer_race_speed(0.005, w, 0.01)[0] == pytest.approx(0.5 * w)
    assert gyro.outer_race_speed(1.0, w, 0.01)[0] == pytest.approx(w)
    assert gyro.outer_race_speed(2.01, w, 0.01, "oscillation", 2.0)[0] == pytest.approx(0.0, abs=1e-9)
    assert gyro.outer_race_speed(2.5, w, 0.01, "oscillation", 2.0) == pytest.approx((-w, -1.0))
    assert gyro.outer_race_speed(4.5, w, 0.01, "oscillation", 2.0) == pytest.approx((w, 1.0))


def test_bad_pocket_depth_is_case_error():
    with pytest.raises(CaseError, match="cage.pocket_depth"):
        gyro.build_model(_case(**{"cage.pocket_depth": "0.6 mm"}))


def test_solver_failure_keeps_partial_result():
    """Numerical failure -> SolverError with the partial Dataset (status says where it stopped)."""
    from hsbearing.errors import SolverError

    with pytest.raises(SolverError) as info:
        gyro.simulate(_case(), duration=0.5, wall_limit=0.05)
    part = info.value.partial
    assert part is not None and part.attrs["status"].startswith("failed at t =")
    assert part.sizes["time"] >= 1 and "rfmc" in part


def test_starting_moments_windows():
    t = np.linspace(0, 6, 6001)
    M = np.ones_like(t)
    M[100] = 5.0  # window 0
    M[2100] = 7.0  # window 1
    M[4100] = 9.0  # window 2
    sfmc, sfmo, mx = gyro.starting_moments(t, M, "oscillation", 2.0, 0.01)
    assert sfmc == 5.0 and sfmo == pytest.approx(8.0) and list(mx) == [5.0, 7.0, 9.0]


# --------------------------------------------------------------------------- dynamics (short runs)


@pytest.fixture(scope="module")
def start_run():
    return gyro.simulate(_case(**{"operating.outer_speed": "5 rpm"}), duration=0.12)


def _mc_ensemble(case, duration):
    """M_C = SFMC - RFMC [uN m] of the 5 starts of gyro.start_ensemble (cage turned over its circumferential play:
    -1/2, -1/4, 0, 1/4, 1/2).  One start from rest is chaotic (gyro.md: 30-140 % between offsets), so the trend
    tests below compare ENSEMBLES, paired by offset (the same start position in both members of a pair)."""
    return (gyro.start_ensemble(case, 5, duration=duration) - gyro.static_friction(case).rfmc) * 1e6


def test_start_run_integrates_and_archives(start_run, tmp_path):
    ds = start_run
    assert ds.attrs["status"] == "ok" and ds.attrs["model"] == "gyro_ribbon_cage"
    assert ds.attrs["solver_steps"] > 0 and ds.attrs["solver_rhs_evals"] > 0
    for v in ("friction_moment_total", "friction_moment_cage", "friction_moment_hysteresis", "cage_speed",
              "cage_angle", "ball_orbit_speed", "sfmc", "rfmc"):
        assert v in ds and ds[v].attrs["units"]
    # the balls reach the kinematic orbit speed (1 + gamma)/2 omega_o of Eq. 3
    st = gyro.static_friction(_case())
    gamma = _case().bearing.ball_diameter * math.cos(st.beta) / _case().bearing.pitch_diameter
    w_o = 5 * 2 * math.pi / 60
    assert ds["ball_orbit_speed"].values[-1].mean() == pytest.approx(0.5 * (1 + gamma) * w_o, rel=2e-3)
    from hsbearing.results import open_run, write_netcdf

    p = write_netcdf(ds, tmp_path / "g.nc")
    back = open_run(p)
    assert float(back["sfmc"]) == pytest.approx(float(ds["sfmc"]))
    png = gyro.plot_run(back, tmp_path / "g.png")
    assert png.exists() and png.stat().st_size > 10000


@pytest.mark.slow  # long validation: default tier kept under ~10 min (docs/testing.md)
def test_cage_is_struck_and_mc_grows_with_speed():
    """Jiang et al. 2014 Sec. 4 / Table 2: the cage is struck at the start (SFMC > RFMC) and M_C = SFMC - RFMC grows with the
    input speed (Table 2, 1 N: 7.5 vs 2.4 uN m at 5 vs 2 r/min, ratio 3.1).  At 2 r/min the first impact comes at
    ~0.2 s, so the starts run 0.3 s (a 0.6 s run gives the same ensemble within 5 %: 2.92 vs 2.79 mean).
    Measured (5 starts; numpy 2.4.6 / scipy 1.17.1 / numba 0.68.1 and the older set of docs/testing.md):
    2 r/min 1.26, 1.49, 1.55, 4.73, 4.93 (mean 2.79); 5 r/min 5.20, 4.61, 4.24, 14.90, 13.99 (mean 8.59):
    ratio of means 3.08, every pair increases."""
    mc2 = _mc_ensemble(_case(**{"operating.outer_speed": "2 rpm"}), 0.3)
    mc5 = _mc_ensemble(_case(**{"operating.outer_speed": "5 rpm"}), 0.3)
    assert mc2.min() > 0.7 and mc5.min() > 0.7, (mc2, mc5)  # every start is struck (0.3 x Table 2's 2.4)
    assert mc5.mean() > 2.0 * mc2.mean(), (mc2, mc5)  # measured 3.08; Hertz impact ~ v^1.2 alone gives 3.0
    assert (mc5 > mc2).sum() >= 4, (mc2, mc5)  # measured 5 of 5


def test_momentum_exchange_conserves_axial_momentum():
    """Physical invariants: with race traction, friction and damping off, ball/cage impacts conserve the angular
    momentum about the axis and the kinetic energy."""
    c = _case(**{"friction.coefficient": 0.0, "friction.cage_coefficient": 0.0, "friction.cage_restitution": 1.0})
    m = gyro.build_model(c)
    y = m.y0()
    Z = m.Z
    y[12 + Z:12 + 2 * Z] = 0.3  # balls orbit, cage at rest -> impact
    from hsbearing.solvers.cvode import integrate

    m.p[gyro._P_NO] = 0.0
    res = integrate(m.rhs, y, np.linspace(0, 0.1, 201), rtol=1e-9, atol=m.atol * 1e-2)
    assert res.success

    def L(yy):
        rm = 0.5 * c.bearing.pitch_diameter
        return m.p[gyro._P_JX] * yy[9] + m.p[gyro._P_MB] * rm**2 * yy[12 + Z:12 + 2 * Z].sum()

    def E(yy):  # kinetic energy: cage translation + rotation, ball orbit (no contact at the ends)
        rm = 0.5 * c.bearing.pitch_diameter
        V, w = yy[6:9], yy[9:12]
        J = m.p[[gyro._P_JX, gyro._P_JY, gyro._P_JZ]]
        return (0.5 * m.p[gyro._P_MC] * V @ V + 0.5 * J @ (w * w)
                + 0.5 * m.p[gyro._P_MB] * rm**2 * (yy[12 + Z:12 + 2 * Z] ** 2).sum())

    assert abs(res.y[-1, 9]) > 0.1  # the cage was struck
    assert L(res.y[-1]) == pytest.approx(L(res.y[0]), rel=1e-4)
    assert m.diagnostics(0.0, y)[:, 0].max() == 0.0  # the start stores no elastic energy
    assert m.diagnostics(res.t[-1], res.y[-1])[:, 0].max() == 0.0  # contacts open at the end
    assert E(res.y[-1]) == pytest.approx(E(res.y[0]), rel=1e-4)  # elastic impacts, no friction


def test_thickness_raises_starting_moment():
    """Jiang et al. 2014 Sec. 4, Fig. 10: M increases with the cage thickness s (heavier cage).  Ensembles of 5 starts
    (0.12 s at 5 r/min: the start impacts are over by then), paired by start offset.  Measured M_C: s = 0.15 mm
    5.20, 4.61, 4.24, 14.90, 13.99 (mean 8.59); s = 0.30 mm 8.17, 7.14, 7.13, 20.68, 22.39 (mean 13.10): ratio
    of means 1.53, every pair increases."""
    base = _case()
    thin, thick = (_mc_ensemble(gyro.override(base, **{"cage.thickness": v}), 0.12) for v in ("0.15 mm", "0.30 mm"))
    assert thick.mean() > 1.2 * thin.mean(), (thin, thick)
    assert (thick > thin).sum() >= 4, (thin, thick)


def test_clearance_raises_starting_moment_small_A():
    """Jiang et al. 2014 Sec. 4, Fig. 11: M increases with the pocket clearance A (checked for A = 0.01 -> 0.03 mm, k =
    D_w/2 + A; above 0.03 mm our model does not follow the paper, see docs/validation/gyro.md).  Ensembles of 5
    starts paired by offset (each start turned by the same fraction of its own play).  Measured M_C: A = 0.01 mm
    2.33, 2.25, 2.27, 10.69, 11.16 (mean 5.74); A = 0.03 mm 7.60, 3.74, 4.04, 16.50, 14.60 (mean 9.30): ratio of
    means 1.62, every pair increases."""
    base = _case()
    small, large = (_mc_ensemble(gyro.override(base, **{"cage.pocket_depth": k}), 0.12) for k in ("0.66 mm", "0.68 mm"))
    assert large.mean() > 1.2 * small.mean(), (small, large)
    assert (large > small).sum() >= 4, (small, large)


def test_cage_moment_windows_mechanism_metrics():
    """cage_moment_windows: share of M_C in each window maximum (1 - RFMC / max M) and the time by which 90 % of the
    window's driving M_C has accumulated -- short for decaying impacts, 0.9 T for a cage carried along."""
    import xarray as xr

    T, dt = 2.0, 1e-3
    t = np.arange(0.0, 2 * T, dt)
    rf = 3e-6
    decaying = 6e-6 * np.exp(-(t % T) / 0.1)  # impacts at every window start, e-folding 0.1 s
    steady = np.full_like(t, 0.3e-6)  # cage carried by friction
    for MC, share, lo, hi in [(decaying, 6 / 9, 0.2, 0.25), (steady, 0.3 / 3.3, 0.9 * T - 0.01, 0.9 * T + 0.01)]:
        ds = xr.Dataset({"friction_moment_total": ("time", rf + MC), "friction_moment_cage": ("time", MC), "rfmc": rf,
                         "window_max_moment": ("window", [0.0, 0.0])}, coords={"time": t},
                        attrs={"oscillation_period": T})
        sh, dec = gyro.cage_moment_windows(ds)
        assert sh == pytest.approx([share, share], rel=1e-9)
        assert np.all((dec > lo) & (dec < hi)), dec  # decaying: t90 = 0.1 ln 10 = 0.23 s


def _play_angle(c):
    return gyro.circumferential_play_angle(c.bearing.ball_diameter, c.cage.pocket_diameter, c.cage.pocket_depth,
                                           c.bearing.pitch_diameter)


@pytest.mark.slow  # long validation: default tier kept under ~10 min (docs/testing.md)
def test_reversal_mechanism_default_vs_cage_weight():
    """Jiang et al. 2014 Figs. 8-9: M_C is more than half of M at the onset of every reversal.  The default (weightless
    dynamics, cage touching) shows it; with the cage weight in the dynamics the cage rests on the pockets, is
    carried by friction and is never struck (the reason the default leaves the weight out, docs/validation/gyro.md).

    The bouncing cage is chaotic, so the default is asserted over an ENSEMBLE: 5 starts with the cage turned over
    its circumferential play (gyro.start_offsets(5)) x 3 reversal windows of T = 0.25 s = 15 windows.  Measured
    with numpy 2.4.6 / scipy 1.17.1 / numba 0.68.1 (requirements.lock) and numpy 1.26.4 / scipy 1.13.1 /
    numba 0.60.0 (docs/testing.md): share median 0.833, minimum 0.742, 15/15 windows above 0.5 -- identical on
    both sets.  Thresholds: median > 0.6, at least 12 of 15 windows > 0.5.
    The weighted cage is not chaotic (it rests on the pockets: 3 starts x 3 windows gave share 0.067-0.070, t90
    0.221-0.223 s), so one start suffices; steady M_C gives t90 = 0.9 T = 0.225 s.
    The decay of M_C within ~1 s after a reversal needs the paper's 2 s windows: slow tier,
    test_reversal_decay_2s_windows_ensemble (in 0.25 s windows a later impact and a steady M_C look alike)."""
    T = 0.25
    c = _case(**{"operating.mode": "oscillation", "operating.oscillation_period": f"{T} s"})
    play = _play_angle(c)
    share = np.concatenate([gyro.cage_moment_windows(gyro.simulate(c, duration=1.0, cage_angle=f * play))[0][1:]
                            for f in gyro.start_offsets(5)])
    assert share.size == 15
    assert np.median(share) > 0.6, share  # measured 0.833 (both dependency sets)
    assert (share > 0.5).sum() >= 12, share  # measured 15 of 15
    share, t90 = gyro.cage_moment_windows(gyro.simulate(c, duration=1.0, gravity=gyro.GRAVITY))
    assert share[1:].max() < 0.15 and t90[1:].min() > 0.85 * T  # measured 0.068, 0.222 s (steady M_C: 0.9 T)


@pytest.mark.slow
def test_reversal_decay_2s_windows_ensemble():
    """Jiang et al. 2014 Figs. 8-9 / Sec. 4: after a reversal M_C "rapidly reduces after about 1 s" (2 s windows).  Ensemble of
    3 starts (cage turned over its play) x 2 reversal windows of T = 2 s: the median time t90 by which 90 % of the
    window's driving M_C has accumulated is below 0.7 T for the default (impacts that die out), while the weighted
    cage, carried by friction, gives a steady M_C (t90 -> 0.9 T).  Measured on both dependency sets of
    docs/testing.md (identical): default t90 1.16, 1.22, 1.46, 1.15, 1.23, 0.78 s (median 1.19 s = 0.59 T), share
    0.67-0.86; weighted cage t90 1.64, 1.82 s (>= 0.82 T), share 0.06, 0.11."""
    T = 2.0
    c = _case(**{"operating.mode": "oscillation"})
    assert c.operating.oscillation_period == T
    play = _play_angle(c)
    t90 = np.concatenate([gyro.cage_moment_windows(gyro.simulate(c, duration=6.1, cage_angle=f * play))[1][1:]
                          for f in gyro.start_offsets(3)])
    assert t90.size == 6
    assert np.median(t90) < 0.7 * T, t90
    share, t90g = gyro.cage_moment_windows(gyro.simulate(c, duration=6.1, gravity=gyro.GRAVITY))
    assert share[1:].max() < 0.2 and t90g[1:].min() > 0.75 * T, (share, t90g)


def test_turned_cage_start_touches_with_zero_approach():
    """start_ensemble turns the cage by fractions of its circumferential play before settling: the settled start
    must still touch the balls (contact after 1 nm more) without stored elastic energy (regression: a turned cage
    used to stay exactly centred because the contact test was rounding noise)."""
    c = _case()
    m = gyro.build_model(c)
    e, nabla = gyro.pocket_geometry(c.bearing.ball_diameter, c.cage.pocket_diameter, c.cage.pocket_depth)
    play = math.sqrt(nabla**2 - e**2) / (0.5 * c.bearing.pitch_diameter)
    for f in (-0.5, -0.25, 0.25, 0.5):
        y = m.y0(cage_angle=f * play)
        assert y[1] < -10e-6  # dropped towards the balls (20-30 um)
        assert m.diagnostics(0.0, y)[:, 0].max() == 0.0
        y[1] -= 1e-9
        assert m.diagnostics(0.0, y)[:, 0].max() > 0.0


def test_gravity_direction_settles_along_it():
    """gravity_direction: the cage settles along the given direction -- along the axis it rests on the balls after
    the axial play A = k - D_w/2 (Jiang et al. 2014 Sec. 3.2) plus a Hertz approach of nanometres; the default is -Y."""
    c = _case()
    A = c.cage.pocket_depth - c.bearing.ball_diameter / 2
    y = gyro.build_model(c, gravity=gyro.GRAVITY, gravity_direction=(1.0, 0.0, 0.0)).y0()
    assert A < y[0] < A + 2e-8 and y[1] == 0.0 and y[2] == 0.0
    y = gyro.build_model(c, gravity=gyro.GRAVITY).y0()
    assert y[0] == 0.0 and y[2] == 0.0 and -0.05e-3 < y[1] < -0.039e-3  # radial play 0.04 mm (default -Y)
    with pytest.raises(ValueError):
        gyro.build_model(c, gravity_direction=(0.0, 0.0, 0.0))


def test_oscillation_window0_is_the_constant_start():
    """For t < T the oscillation profile equals the constant-rate start, so window 0 gives SFMC."""
    a = gyro.simulate(_case(), duration=0.06)
    b = gyro.simulate(_case(**{"operating.mode": "oscillation"}), duration=0.06)
    assert np.allclose(a["friction_moment_total"].values, b["friction_moment_total"].values, rtol=1e-9, atol=1e-15)


# Jiang et al. 2014 Table 2 (calculated), the same runs as docs/validation/gyro.md (cases built the same way, so
# the chaotic cage trajectories are identical): SFMC = maximum M in the 2 s after the default (settled)
# start, SFMO = mean of 10 reversal-window maxima (20.3 s simulated).  ~35 s wall per cell.
_SFMC_XFAIL = {
    # measured 4.29 (-19.7 %) until session 3, 4.27 (-20.04 %) since (one chaotic trajectory at the tolerance
    # edge; the change came with the session-3 integration/compile changes, the gyro physics is unchanged)
    (1.0, 2.0): "SFMC 4.27 vs 5.34 (-20.0 %)",
    (1.0, 5.0): "SFMC 7.01 vs 10.06 (-30 %)",
    (2.0, 5.0): "SFMC 10.76 vs 13.73 (-22 %)",
}
_SFMO_XFAIL: dict = {
    # (1.0, 2.0) was "SFMO 8.10 vs 6.74 (+20.2 %)" until session 3; measured 7.93 (+17.7 %) since, and 8.10
    # again on an AMD EPYC host in session 6 (also with the code of before that session): see _EDGE
}
#: Cells whose single chaotic trajectory sits at the 20 % edge, where the miss flips with the CPU model and the
#: compiled code (numba compiles for the host): SFMC 4.27-4.29 (-20.0 / -19.7 %) and SFMO 7.93-8.10 (+17.7 /
#: +20.2 %) at 1 N, 2 r/min.  Their SFMC/SFMO may miss (then xfail) or not; every other cell is strict both ways.
_EDGE = {(1.0, 2.0)}


@pytest.mark.slow
@pytest.mark.parametrize("row", _table2(), ids=lambda r: f"{r['load_N']:g}N-{r['speed_r_per_min']:g}rpm")
def test_table2_cell(row):
    """Jiang et al. 2014 Table 2: RFMC within 10 %, SFMO > SFMC by >= 15 %, SFMC and SFMO within 20 %
    (three cells miss 20 % and are named, with the measured value, in _SFMC_XFAIL / _SFMO_XFAIL)."""
    base = hsbearing.load_case("jiang2014_gyro")
    c = gyro.override(base, **{"operating.axial_load": f"{row['load_N']:g} N", "operating.outer_speed": f"{row['speed_r_per_min']:g} rpm"})
    ds = gyro.simulate(gyro.override(c, **{"operating.mode": "oscillation"}), duration=20.3)
    wm = ds["window_max_moment"].values * 1e6
    sfmc, sfmo = float(ds["sfmc"]) * 1e6, float(ds["sfmo"]) * 1e6
    assert wm.size == 11 and sfmc == pytest.approx(wm[0]) and sfmo == pytest.approx(wm[1:].mean())
    assert float(ds["rfmc"]) * 1e6 == pytest.approx(row["RFMC_uNm"], rel=0.10)
    assert sfmo > 1.15 * sfmc  # Table 2 "increased percentage" 16-44 %
    key = (row["load_N"], row["speed_r_per_min"])
    misses = []
    if sfmc != pytest.approx(row["SFMC_uNm"], rel=0.20):
        misses.append(("sfmc", f"SFMC {sfmc:.2f} vs {row['SFMC_uNm']}"))
    if sfmo != pytest.approx(row["SFMO_uNm"], rel=0.20):
        misses.append(("sfmo", f"SFMO {sfmo:.2f} vs {row['SFMO_uNm']}"))
    # strict: a listed miss that no longer misses fails too (the lists must state the measured truth)
    expected = {m for m, table in (("sfmc", _SFMC_XFAIL), ("sfmo", _SFMO_XFAIL)) if key in table}
    found = {m for m, _ in misses}
    if key in _EDGE:  # at the tolerance edge: a miss is expected-possible, not required (see _EDGE)
        if found:
            pytest.xfail("at the 20 % edge (_EDGE): " + "; ".join(msg for _, msg in misses))
        return
    assert found <= expected, "; ".join(msg for m, msg in misses if m not in expected)
    assert expected <= found, f"listed as a miss but now within 20 %: {sorted(expected - found)} ({sfmc=:.2f}, {sfmo=:.2f})"
    if expected:
        pytest.xfail("; ".join(_SFMC_XFAIL.get(key, "") if m == "sfmc" else _SFMO_XFAIL.get(key, "") for m in sorted(expected)))
