"""Guide-land film of the cage: the closed form against independent Reynolds solutions.

:func:`hsbearing.models.ball_bearing.cage.guide_land_forces` (short-width Reynolds equation, Guembel p >= 0, exact
Sommerfeld-type integrals over the positive-pressure half circle) is compared with

* a numerical solution of the same short-width equation built from the two-circle film geometry, p
  clipped at 0 on a fine Theta grid and integrated numerically (tests/helpers/_reynolds.py), over eccentricity
  0.1-0.95, whirl -0.5 to 1.5 of the surface speed, squeeze of both signs, both directions of rotation;
* a 2-D finite-volume Reynolds solution with cavitation (projected SOR) for the finite-length land of the
  default case (L/D = 1.8/52.4) -- the short-width error.

The kernel's land-force assembly is tested through the package (rhs with the land film on and off), and
the linearised whirl of a cage on its land film is checked against the characteristic equation.
Geometry: zhang2016 default (oil 4109 at 130 degC, eta = 3.604 mPa s; land radius 26.2 mm, clearance
0.2 mm; two lands of ~1.8 mm, docs/dynamics.md).
"""

import math
import sys
from pathlib import Path

import numpy as np
import pytest

from hsbearing.models.ball_bearing import kernel_io as kio
from hsbearing.models.ball_bearing.cage import guide_land_forces, guide_land_power, guide_land_torque

sys.path.insert(0, str(Path(__file__).resolve().parents[1]))
from _reynolds import finite_bearing_forces, short_bearing_forces  # noqa: E402

ETA, R, L, C_GAP, M, OMEGA = 3.604e-3, 0.0262, 1.8e-3, 2.0e-4, 3.749e-3, 600.8


def _damping(L=L):
    return math.pi * ETA * R * L**3 / (2.0 * C_GAP**3)  # direct damping at the centre, eps -> 0


# --------------------------------------------------------------------------- closed form vs numerical Reynolds
EPS = (0.1, 0.2, 0.35, 0.5, 0.65, 0.8, 0.9, 0.95)
WHIRL = (-0.5, -0.25, 0.0, 0.25, 0.45, 0.5, 0.55, 0.63, 0.75, 1.0, 1.5)  # phi' / omega_sum
SQUEEZE = (-0.5, -0.05, 0.0, 0.05, 0.5)  # eps' / |omega_sum|


@pytest.mark.parametrize("omega_sum", [OMEGA, -OMEGA])
def test_land_film_matches_numerical_short_bearing_in_every_regime(omega_sum):
    """Within 2 % of the force magnitude for all 432 non-zero regimes (measured: max 3e-6 with 8001 nodes)."""
    worst = 0.0
    n_cases = 0
    for eps in EPS:
        for wr in WHIRL:
            for sq in SQUEEZE:
                args = (eps, sq * abs(omega_sum), omega_sum, wr * omega_sum, ETA, R, L, C_GAP)
                Fr, Ft = guide_land_forces(*args)
                nr, nt = short_bearing_forces(*args)
                ref = math.hypot(nr, nt)
                scale = ETA * R * L**3 / C_GAP**2 * abs(omega_sum) * eps  # force scale of this eccentricity
                if ref < 1e-6 * scale:  # force-free regime: half-frequency whirl, no squeeze
                    assert abs(Fr) < 1e-6 * scale and abs(Ft) < 1e-6 * scale
                    continue
                err = math.hypot(Fr - nr, Ft - nt) / ref
                worst = max(worst, err)
                n_cases += 1
                assert err < 0.02, (args, (Fr, Ft), (nr, nt))
    print(f"omega_sum {omega_sum}: {n_cases} regimes, worst relative error {worst:.2e}")
    assert n_cases >= 400
    assert worst < 0.005  # the observed agreement, so a drift of the formula shows up long before 2 %


def test_whirl_above_half_speed_is_still_restoring():
    """Issue 14 example (R 26 mm, L 11 mm, c 0.2 mm, eta 3.6 mPa s, omega 600 1/s, eps 0.85, whirl 0.63 omega):

    the numerical Reynolds solution gives F_r = -4.56 N (restoring); the old pi-film code gave +4.56 N.  Above
    half speed the radial force stays restoring in |w|, only the tangential force changes sign.
    """
    Fr, Ft = guide_land_forces(0.85, 0.0, 600.0, 0.63 * 600.0, 3.6e-3, 0.026, 0.011, 2e-4)
    assert Fr == pytest.approx(-4.56, abs=0.01)
    for wr in (0.3, 0.7):  # symmetric about half speed: w = +-0.4 omega
        Fr_w, Ft_w = guide_land_forces(0.6, 0.0, OMEGA, wr * OMEGA, ETA, R, L, C_GAP)
        assert Fr_w < 0
        assert (Ft_w > 0) == (wr < 0.5)
    a = guide_land_forces(0.6, 0.0, OMEGA, 0.3 * OMEGA, ETA, R, L, C_GAP)
    b = guide_land_forces(0.6, 0.0, OMEGA, 0.7 * OMEGA, ETA, R, L, C_GAP)
    assert a[0] == pytest.approx(b[0], rel=1e-12) and a[1] == pytest.approx(-b[1], rel=1e-12)


def test_separating_squeeze_does_not_suck_the_cage_to_the_land():
    """Issue 14 example: eps 0.8 moving away from the land (eps' = -20 1/s) at half-speed whirl: the film
    pressure is on the far side, |F| ~ 0.02 N (the fixed-half code gave +1.95 N toward the land)."""
    Fr, Ft = guide_land_forces(0.8, -20.0, 600.0, 300.0, 3.6e-3, 0.026, 0.011, 2e-4)
    nr, nt = short_bearing_forces(0.8, -20.0, 600.0, 300.0, 3.6e-3, 0.026, 0.011, 2e-4)
    assert abs(Fr) < 0.05 and Fr == pytest.approx(nr, rel=0.01)
    # approaching at the same rate: a large restoring squeeze force
    Fr2, _ = guide_land_forces(0.8, 20.0, 600.0, 300.0, 3.6e-3, 0.026, 0.011, 2e-4)
    assert Fr2 < -20 * abs(Fr)


def test_half_frequency_whirl_is_force_free():
    """A circular orbit whirling at half the surface speed carries no film force (wedge and whirl cancel)."""
    for eps in (0.05, 0.3, 0.8):
        Fr, Ft = guide_land_forces(eps, 0.0, OMEGA, 0.5 * OMEGA, ETA, R, L, C_GAP)
        assert Fr == 0.0 and Ft == 0.0
        Fr, Ft = guide_land_forces(eps, 0.0, OMEGA, 0.0, ETA, R, L, C_GAP)
        assert Fr < 0 and Ft > 0  # a static offset: pulled back and pushed forward (direction of rotation)


def test_linearised_film_coefficients_at_the_centre():
    """Finite differences of the film force at a small offset: direct damping C = pi eta R L^3 / (2 c^3),
    cross-coupled stiffness K_xy = C omega / 2, no direct stiffness (San Andres, Notes 5, eps -> 0)."""
    C = _damping()
    eps = 1e-4
    Fr, Ft = guide_land_forces(eps, 0.0, OMEGA, 0.0, ETA, R, L, C_GAP)
    assert Ft / (eps * C_GAP) == pytest.approx(0.5 * C * OMEGA, rel=1e-4)
    assert abs(Fr / (eps * C_GAP)) < 1e-3 * 0.5 * C * OMEGA
    for sgn in (1.0, -1.0):  # both squeeze directions give the same damping at the centre
        Fr_v, _ = guide_land_forces(eps, sgn * 10.0, OMEGA, 0.0, ETA, R, L, C_GAP)
        Fr_0, _ = guide_land_forces(eps, 0.0, OMEGA, 0.0, ETA, R, L, C_GAP)
        assert (Fr_v - Fr_0) / (sgn * 10.0 * C_GAP) == pytest.approx(-C, rel=2e-3)


# --------------------------------------------------------------------------- finite length (2-D Reynolds)
def test_short_width_error_against_finite_length_reynolds():
    """Short-width land (L/D = 1.8/52.4) vs a 2-D finite-volume Reynolds solution with p >= 0 (PSOR).

    Measured: 0.9 % at eps 0.9 (this state); the same solver at the old 11 mm film (L/D = 0.21)
    differs by 5-16 %, so the comparison is sensitive to the finite length.
    """
    args = (0.9, -0.1 * OMEGA, OMEGA, 0.2 * OMEGA, ETA, R)
    Fr, Ft = guide_land_forces(*args, L, C_GAP)
    fr, ft, sweeps = finite_bearing_forces(*args, L, C_GAP, nt=720, nz=41)
    assert sweeps < 200000
    err = math.hypot(Fr - fr, Ft - ft) / math.hypot(fr, ft)
    assert err < 0.015
    Fr, Ft = guide_land_forces(*args, 11e-3, C_GAP)
    fr, ft, _ = finite_bearing_forces(*args, 11e-3, C_GAP, nt=360, nz=41)
    assert math.hypot(Fr - fr, Ft - ft) / math.hypot(fr, ft) > 0.05


@pytest.mark.parametrize("eps", [0.3, 0.6, 0.9, 0.95])
def test_short_width_error_within_2_percent_up_to_eps_095(eps):
    """The README's "short-width error vs 2-D <= 2 % for the case lands, eps <= 0.95", over the regimes of the
    land film: squeeze toward and away from the land, whirl backward, zero, forward and beyond the surface speed
    (a whirl of half the surface speed with no squeeze carries no load and is left out).  Measured: <= 0.23 % at
    eps <= 0.6, 0.9 % at 0.9, 1.86 % at 0.95 (the short-width error grows with eps)."""
    for ed, whirl in ((-0.1, 0.2), (0.5, 0.0), (0.0, 0.0), (0.1, -0.5), (-0.1, 1.5)):
        args = (eps, ed * OMEGA, OMEGA, whirl * OMEGA, ETA, R)
        Fr, Ft = guide_land_forces(*args, L, C_GAP)
        fr, ft, _ = finite_bearing_forces(*args, L, C_GAP, nt=720, nz=41)
        assert math.hypot(Fr - fr, Ft - ft) / math.hypot(fr, ft) < 0.02, (eps, ed, whirl)


# --------------------------------------------------------------------------- dissipation
def test_land_film_never_produces_power():
    """guide_land_power >= 0 over the regime grid (the film only dissipates), for a fixed and a turning land."""
    for omega_land in (0.0, 0.3 * OMEGA):
        for eps in EPS:
            for wr in WHIRL:
                for sq in SQUEEZE:
                    wc = OMEGA - omega_land
                    ws = wc + omega_land
                    whirl, ed = wr * ws, sq * OMEGA
                    Fr, Ft = guide_land_forces(eps, ed, ws, whirl, ETA, R, L, C_GAP)
                    Mx = guide_land_torque(eps, wc - omega_land, ETA, R, L, C_GAP)
                    D = guide_land_power(Fr, Ft, eps * C_GAP, ed * C_GAP, whirl, Mx, wc, omega_land)
                    assert D > 0.0


# --------------------------------------------------------------------------- land geometry from the case
def test_default_lands_from_the_groove_geometry():
    """Zhang et al. 2016 default: outer groove r_o = 0.53 x 9.525 mm centred at d_o/2 - r_o; at the 52.4 mm land diameter it
    is 2 sqrt(r_o^2 - (26.2 - 22.74)^2) ~ 7.35 mm wide, leaving two lands of (11 - 7.35)/2 ~ 1.83 mm under the cage."""
    import hsbearing
    from hsbearing.models.geometry import derive, guide_lands

    case = hsbearing.load_case("zhang2016")
    g = derive(case)
    gl = guide_lands(case)
    r_o, rho = 0.53 * 9.525e-3, 0.5 * g.do - 0.53 * 9.525e-3
    gw = 2 * math.sqrt(r_o**2 - (26.2e-3 - rho) ** 2)
    assert gl.groove_width == pytest.approx(gw, rel=1e-9) and 7.2e-3 < gw < 7.5e-3
    assert gl.count == 2 and gl.width == pytest.approx(0.5 * (11e-3 - gw), rel=1e-9)
    assert gl.clearance == pytest.approx(0.2e-3) and gl.radius == pytest.approx(26e-3)
    assert gl.offsets == pytest.approx((-(5.5e-3 - 0.5 * gl.width), 5.5e-3 - 0.5 * gl.width))
    one = guide_lands(hsbearing.load_case("zhang2016", **{"cage.guide_land_count": 1, "cage.guide_land_width": "1 mm"}))
    assert one.count == 1 and one.width == pytest.approx(1e-3) and one.offsets == pytest.approx((5e-3,))


@pytest.mark.parametrize("overrides, key", [
    ({"cage.guide_land_width": "11 mm"}, "cage.guide_land_width"),  # the old meaning (whole film length)
    ({"cage.guide_land_width": "2.5 mm"}, "cage.guide_land_width"),  # runs into the groove
    ({"bearing.outer_land_diameter": "51.9 mm"}, "bearing.outer_land_diameter"),  # land inside the cage
    ({"bearing.outer_land_diameter": "56 mm"}, "bearing.outer_land_diameter"),  # beyond the raceway
    ({"cage.guide_land_count": 0}, "cage.guide_land_count"),
    ({"cage.guide_land_count": 3}, "cage.guide_land_count"),
    ({"cage.guidance": "inner_ring", "bearing.inner_land_diameter": "45 mm"}, "bearing.inner_land_diameter"),
    ({"cage.guidance": "ball", "cage.guide_land_count": 2}, "cage.guide_land_count"),
])
def test_bad_land_combinations_are_bad_input(overrides, key):
    import hsbearing
    from hsbearing.errors import CaseError

    with pytest.raises(CaseError) as exc:
        hsbearing.load_case("zhang2016", **overrides)
    assert exc.value.key == key


def test_bad_land_is_exit_2_with_one_line(tmp_path):
    import subprocess

    exe = Path(sys.executable).parent / "hsbearing"
    r = subprocess.run([str(exe), "check", "zhang2016", "--set", "cage.guide_land_width=11mm"], capture_output=True,
                       text=True, cwd=tmp_path)
    assert r.returncode == 2
    lines = r.stderr.strip().splitlines()
    assert len(lines) == 1 and "cage.guide_land_width" in lines[0] and "zhang2016.toml" in lines[0]
    assert not list(tmp_path.iterdir())


# --------------------------------------------------------------------------- the kernel's land assembly
@pytest.fixture(scope="module")
def model():
    import hsbearing
    from hsbearing.systems.angular_contact.dynamics import build_model

    return build_model(hsbearing.load_case("zhang2016"), gravity=0.0)


def _cage_rows(model, y, lands_on=True):
    """Cage generalised accelerations (x'', y'', z'', phi'', psi_y'', psi_z'') from the package's rhs."""
    from hsbearing.models.ball_bearing import kernel as K

    P = model.P.copy()
    if not lands_on:
        kio.set_value(P, "n_land", 0)
    out = np.empty_like(y)
    K.rhs_kernel(y, P, model.qu, model.qw, out, np.zeros((model.layout.Z, K.N_CONTRIB)),
                 np.zeros((model.layout.Z, K.N_AUX)), False, np.zeros(K.N_CONTRIB), np.zeros(K.N_GAUX))
    c = model.layout.cage0
    return out[c + 6:c + 12]


@pytest.mark.parametrize("state", [
    # (y/c, z/c, vy/(c w), vz/(c w), tilt_y, tilt_z, tiltdot_y/w, tiltdot_z/w)
    (0.5, 0.0, 0.0, 0.3, 0.0, 0.0, 0.0, 0.0),  # whirl 0.6 w: above half speed
    (0.0, -0.7, 0.2, 0.0, 0.0, 0.0, 0.0, 0.0),  # backward whirl
    (0.3, 0.4, -0.05, 0.02, 0.0, 0.0, 0.0, 0.0),  # moving away from the land
    (0.6, -0.2, 0.05, 0.1, 0.0, 0.0, 0.0, 0.0),  # approaching
    (0.3, 0.2, 0.0, 0.1, 8e-3, -5e-3, 2e-4, 1e-4),  # tilted: the two lands see different offsets
])
def test_kernel_land_force_is_the_sum_of_the_land_films(model, state):
    """(rhs with lands - rhs without) x (m_c, I_p, I_d) = sum over the lands of guide_land_forces projected on Y, Z,
    their moments a_k e_x x F_k and the Petroff torques -- evaluated independently here from the case geometry
    (with the kernel's documented smooth saturation of eps, smooth_eccentricity)."""
    from hsbearing.models.ball_bearing.cage import cage_generalised_moments, cage_orientation, smooth_eccentricity
    from hsbearing.models.geometry import guide_lands

    gl = guide_lands(model.case)
    P = model.P
    sat = kio.get(P, "eps_max")
    c, R_, L_, eta = gl.clearance, gl.radius, gl.width, kio.get(P, "eta_film")
    y = model.y0.copy()
    cg = model.layout.cage0
    w = y[cg + 9]
    sy, sz, svy, svz, ty, tz, tdy, tdz = state
    y[cg + 1], y[cg + 2], y[cg + 7], y[cg + 8] = sy * c, sz * c, svy * c * w, svz * c * w
    y[cg + 4], y[cg + 5], y[cg + 10], y[cg + 11] = ty, tz, tdy * w, tdz * w
    d = _cage_rows(model, y) - _cage_rows(model, y, lands_on=False)
    # cage axis e and angular velocity from the package's kinematics (cage_orientation, exact for any tilt)
    Rc, (wx, wy, wz), Jc = cage_orientation(y[cg + 3], ty, tz, w, y[cg + 10], y[cg + 11])
    ex = np.array([Rc[0], Rc[3], Rc[6]])
    om = np.array([wx, wy, wz])
    F = np.zeros(3)
    M = np.zeros(3)
    for a in gl.offsets:
        p = y[cg:cg + 3] + a * ex  # the cage-axis point in the plane of land k
        v = y[cg + 6:cg + 9] + np.cross(om, a * ex)
        py, pz, vy, vz = p[1], p[2], v[1], v[2]
        e = math.hypot(py, pz)
        eps = smooth_eccentricity(e / c, sat)
        Fr, Ft = guide_land_forces(eps, (py * vy + pz * vz) / e / c, w, (py * vz - pz * vy) / e**2, eta, R_, L_, c)
        fk = np.array([0.0, (Fr * py - Ft * pz) / e, (Fr * pz + Ft * py) / e])
        F += fk
        M += np.cross(a * ex, fk) + guide_land_torque(eps, w, eta, R_, L_, c) * ex
    Q = cage_generalised_moments(M[0], M[1], M[2], Rc, Jc)
    m, Ip, Id = kio.get(model.P, "m_c"), kio.get(model.P, "Ip_c"), kio.get(model.P, "Id_c")
    scale = math.hypot(F[1], F[2])
    assert d[0] == pytest.approx(0.0, abs=1e-12)
    assert d[1] * m == pytest.approx(F[1], abs=1e-9 * scale) and d[2] * m == pytest.approx(F[2], abs=1e-9 * scale)
    assert d[3] * Ip == pytest.approx(Q[0], rel=1e-9)
    mscale = abs(Q[0]) + abs(gl.offsets[0]) * scale
    assert d[4] * Id == pytest.approx(Q[1], abs=1e-9 * mscale) and d[5] * Id == pytest.approx(Q[2], abs=1e-9 * mscale)
    if not (ty or tz):  # untilted: both lands carry the same force, no net tilting moment
        assert abs(Q[1]) < 1e-12 * mscale and abs(Q[2]) < 1e-12 * mscale


def test_kernel_linearised_cage_whirl_on_the_land_films(model):
    """Linearised growth, not a trajectory: the film-only Jacobian of the kernel's cage rows near the centre gives the
    root of m s^2 + C (s - i w/2) = 0 with C = n pi eta R L^3 / (2 c^3) of the case's n lands (forward whirl,
    growing; with the case's two 1.83 mm lands m w ~ 10 C, so s ~ sqrt(i C w / (2 m)) - C/(2m): 67 1/s, whirl
    0.15 w -- not the m w << C half-frequency limit of the old 11 mm film).  Linearised at an offset of 1e-3 c:
    at exactly zero offset the kernel's line of centres is undefined and the film damping drops out."""
    from hsbearing.models.geometry import guide_lands

    gl = guide_lands(model.case)
    y0 = model.y0.copy()
    cg = model.layout.cage0
    w = y0[cg + 9]
    y0[cg + 1] = 1e-3 * gl.clearance
    eta = kio.get(model.P, "eta_film")
    A = np.zeros((4, 4))
    A[0, 2] = A[1, 3] = 1.0
    base = _cage_rows(model, y0) - _cage_rows(model, y0, lands_on=False)
    for col, idx, h in ((0, cg + 1, 1e-6 * gl.clearance), (1, cg + 2, 1e-6 * gl.clearance),
                        (2, cg + 7, 1e-6 * gl.clearance * w), (3, cg + 8, 1e-6 * gl.clearance * w)):
        y = y0.copy()
        y[idx] += h
        d = _cage_rows(model, y) - _cage_rows(model, y, lands_on=False) - base
        A[2, col], A[3, col] = d[1] / h, d[2] / h
    lam = np.linalg.eigvals(A)
    s_k = lam[np.argmax(lam.real)]
    m = kio.get(model.P, "m_c")
    C = gl.count * math.pi * eta * gl.radius * gl.width**3 / (2 * gl.clearance**3)
    roots = np.roots([m, C, -0.5j * C * w])
    s_th = roots[np.argmax(roots.real)]
    assert s_k.real > 0
    assert s_k.real == pytest.approx(s_th.real, rel=0.02)
    assert abs(s_k.imag) == pytest.approx(abs(s_th.imag), rel=0.02)


def _pocket_at_start(model, n_st=None):
    """pocket_wrench of ball 0 at the start state as a function of (ex, et, s0): the pocket frame of ball 0 is the
    inertial frame at the start (cage untilted, phi_c = 0, ball 0 at psi = 0), relative spin (omega - phi_c' e_x)."""
    from hsbearing.models.ball_bearing.pocket import PocketKinematics, PocketParams, pocket_wrench

    P, y = model.P, model.y0
    names = model.state_names
    wc = y[model.layout.cage0 + 9]
    wx, wr, wt = (y[names.index(f"omega_{a}[0]")] for a in "xyz")
    D2 = 0.5 * kio.get(P, "D")
    prm = PocketParams(eta=kio.get(P, "eta_film"), Rb=D2, Rp=D2 + kio.get(P, "c_p"), R_bore=kio.get(P, "R_bore_c"),
                       R_out=kio.get(P, "R_out_c"), hdm=0.5 * kio.get(P, "dm"),
                       n_st=int(kio.get(P, "n_pocket")) if n_st is None else n_st, h_c=kio.get(P, "h_min"),
                       K=kio.get(P, "K_c"), mu=kio.get(P, "mu_c"), v0=kio.get(P, "v0_c"))
    s0 = y[names.index("u_b[0]")]

    def wrench(ex, et, ds0=0.0):  # (Fx, Fr, Ft) on the ball
        kin = PocketKinematics(ex=ex, et=et, s0=s0 + ds0, vx=0.0, vr=0.0, vt=0.0, wx=wx - wc, wr=wr, wt=wt)
        return np.array(pocket_wrench(kin, prm)[:3])

    return wrench


def _kinetic_shares(model, v):
    """Kinetic-energy shares of an eigenvector v: ball rotation (I_b w^2), ball translation (m_b v^2), cage translation
    (m_c v^2).  Energy weights, not the solver's atol scaling (atol divides lengths by 1e-3 m and angular velocities by
    1e3 rad/s: that scaling made a ball-spin mode look like a cage mode)."""

    P = model.P
    e = {"ball rotation": 0.0, "ball translation": 0.0, "cage translation": 0.0}
    for i, n in enumerate(model.state_names):
        if n.startswith("omega_"):
            e["ball rotation"] += kio.get(P, "I_b") * abs(v[i]) ** 2
        elif n.startswith(("xdot_b", "udot_b")):
            e["ball translation"] += kio.get(P, "m_b") * abs(v[i]) ** 2
        elif n in ("xdot_c", "ydot_c", "zdot_c"):
            e["cage translation"] += kio.get(P, "m_c") * abs(v[i]) ** 2
    s = sum(e.values())
    return {k: x / s for k, x in e.items()}


def test_pocket_film_restoring_and_its_quadrature_jump(model):
    """The pocket film at the start state's ball spin (relative spin ~(-3250, 1210, 0) rad/s) pushes a displaced ball
    back to the pocket centre in every direction of the pocket plane (restoring stiffness: the thin side of the gap is
    the pressurised one; same sign and within 5 % of the independent 2-D Reynolds solution, measured 3.7 %), and has no stiffness
    along the axis of the cylindrical pocket.  At a vanishing offset its force along the pocket axis depends
    on the *direction* of the offset by ~3e-5 N (0.15 % of the 0.018 N film force): the 16 trapezoidal stations turn
    with the offset direction over an integrand with kinks (cavitation), and the jump falls as 1/n^2 with the number
    of stations (quadrature error, not physics; docs/validation/cage_whirl.md).  That jump divided by a sub-micron
    offset is what made the full-model Jacobian at a 0.2 um cage offset show a spurious real +186 1/s mode."""
    f = _pocket_at_start(model)
    h = 1e-7
    k_tt = -(f(0.0, h)[2] - f(0.0, -h)[2]) / (2 * h)
    k_xx = -(f(h, 0.0)[0] - f(-h, 0.0)[0]) / (2 * h)
    k_rr = -(f(0.0, 0.0, h)[1] - f(0.0, 0.0, -h)[1]) / (2 * h)
    assert k_tt > 1000 and k_xx > 500  # N/m, measured 1581, 742
    # along the axis of a cylindrical pocket the gap does not change (only the edges move): no stiffness (measured -3)
    assert abs(k_rr) < 0.01 * k_tt
    # the sign and size against the independent 2-D Reynolds solution (tests/helpers/pocket_reynolds_fd.py, p >= 0) of the same
    # gap and spin: secant stiffness over e_t = -+0.2 c (measured -2995 N/m 2-D, -3105 N/m model; both restoring)
    from pocket_reynolds_fd import solve_pocket_film


    P, y, names = model.P, model.y0, model.state_names
    w = tuple(y[names.index(f"omega_{a}[0]")] for a in "xyz")
    w = (w[0] - y[model.layout.cage0 + 9], w[1], w[2])
    D2, c = 0.5 * kio.get(P, "D"), kio.get(P, "c_p")
    s0 = y[names.index("u_b[0]")]
    Ft = [solve_pocket_film(0.0, e, s0, (0.0, 0.0, 0.0), w, kio.get(P, "eta_film"), D2, D2 + c, kio.get(P, "R_bore_c"), kio.get(P, "R_out_c"),
                            0.5 * kio.get(P, "dm"), n_theta=180, n_u=60)["F"][2] for e in (-0.2 * c, 0.2 * c)]
    k_2d = -(Ft[1] - Ft[0]) / (0.4 * c)
    k_model = -(f(0.0, 0.2 * c)[2] - f(0.0, -0.2 * c)[2]) / (0.4 * c)
    assert k_2d > 0 and k_model == pytest.approx(k_2d, rel=0.05)
    jumps = []
    for n in (16, 32):
        g = _pocket_at_start(model, n)
        F = np.array([g(1e-10 * math.cos(a), 1e-10 * math.sin(a)) for a in np.linspace(0, 2 * math.pi, 13)[:-1]])
        jumps.append(np.ptp(F[:, 1]))
        assert np.ptp(F[:, 1]) < 5e-3 * np.abs(F).max()  # within the documented quadrature error (0.8 %)
    assert jumps[1] < jumps[0] / 3  # converges like 1/n^2 (measured 2.8e-5 -> 7.0e-6 N)


def test_full_model_linearised_cage_modes(model):
    """The full model's Jacobian (balls, cage, ring; gravity off) at the start state with the cage 2 um off-centre
    (1e-2 c: well above the sub-micron offsets where the pocket quadrature's direction jump dominates, see above).

    With the pocket film the balls hold the cage: the cage's direct translational stiffness is the
    sum of the 11 pockets' film stiffnesses, Z/2 (k_tt + k_rr) (balls frozen; measured 8743 vs 8680 N/m), 130x the
    land films' cross-coupled stiffness C w/2 (67.5 N/m).  The land-film whirl (67 1/s on the films alone,
    test_kernel_linearised_cage_whirl_on_the_land_films) is therefore not a mode of the linearised full model: its
    least-damped cage mode is the mass on the pocket films, m s^2 + c s + k - i k_c = 0 with the pockets' damping c
    and cross-coupled stiffness k_c (the circumferential wedge of the spinning balls), a damped forward whirl near
    sqrt(k/m) = 1530 rad/s (measured -53 + 1514i 1/s full model, -44 + 1527i from the cage rows).  No cage mode
    grows; the least stable mode of the model is a slow ball-rotation mode (+6.1 +- 12.1i 1/s, cage share 0.1 %) of a
    start state that is not an equilibrium (the pocket films decelerate the ball spin at ~7e5 rad/s^2).  So the
    cage's departure to the land in the simulation is not a linear instability of the start state.  Linearised
    dynamics, not a trajectory."""
    from hsbearing.models.geometry import guide_lands

    gl = guide_lands(model.case)
    Z = model.layout.Z
    y = model.y0.copy()
    cg = model.layout.cage0
    y[cg + 1] = 1e-2 * gl.clearance
    J = np.zeros((y.size, y.size))
    model.jac(0.0, y, None, J)
    m = kio.get(model.P, "m_c")
    # cage rows with the balls frozen: m zeta'' = -(k - i k_c) zeta - (c + i c_c) zeta', zeta = y + i z
    k = -0.5 * m * (J[cg + 7, cg + 1] + J[cg + 8, cg + 2])
    k_c = 0.5 * m * (J[cg + 8, cg + 1] - J[cg + 7, cg + 2])
    c = -0.5 * m * (J[cg + 7, cg + 7] + J[cg + 8, cg + 8])
    c_c = -0.5 * m * (J[cg + 8, cg + 7] - J[cg + 7, cg + 8])
    f = _pocket_at_start(model)
    h = 1e-7
    k_tt = -(f(0.0, h)[2] - f(0.0, -h)[2]) / (2 * h)
    k_rr = -(f(0.0, 0.0, h)[1] - f(0.0, 0.0, -h)[1]) / (2 * h)
    assert k == pytest.approx(0.5 * Z * (k_tt + k_rr), rel=0.03)  # the pockets are the cage's spring
    C = gl.count * math.pi * kio.get(model.P, "eta_film") * gl.radius * gl.width**3 / (2 * gl.clearance**3)
    assert 0.5 * C * y[cg + 9] < 0.02 * k
    assert c > 0 and k_c > 0  # damping, and a forward-whirl (destabilising) cross-coupling
    roots = np.roots([m, c + 1j * c_c, k - 1j * k_c])
    s_cage = roots[np.argmax(roots.imag)]  # the forward whirl
    assert s_cage.real < 0
    lam, V = np.linalg.eig(J)
    share = np.array([_kinetic_shares(model, V[:, i])["cage translation"] for i in range(lam.size)])
    cage = (share > 0.5) & (lam.imag > 0)
    assert np.all(lam[share > 0.5].real < 0)  # every cage-dominated mode is damped
    s_full = lam[cage][np.argmax(lam[cage].real)]  # the least-damped cage mode
    assert s_full.imag == pytest.approx(s_cage.imag, rel=0.03)
    assert s_full.real == pytest.approx(s_cage.real, rel=0.35)  # ball coupling shifts it (measured -53 vs -44)
    top = int(np.argmax(lam.real))
    assert share[top] < 0.01 and lam[top].real < 10.0  # least stable: a slow ball-rotation mode (measured 6.1 1/s)


def test_inner_ring_and_ball_guidance():
    """Inner-ring guidance: the land film acts between the cage bore and the ring land (relative offset), its
    reaction moves the inner ring (equal and opposite), and the faster ring drags the cage forward.  Ball-piloted:
    no land loads at all."""
    import hsbearing
    from hsbearing.models.ball_bearing import kernel as K
    from hsbearing.models.geometry import guide_lands
    from hsbearing.systems.angular_contact.dynamics import build_model

    case = hsbearing.load_case("zhang2016", **{"cage.guidance": "inner_ring"})
    gl = guide_lands(case)
    assert gl.count == 2 and gl.radius == pytest.approx(22.2e-3) and gl.clearance == pytest.approx(2.95e-3)
    m = build_model(case, gravity=0.0)
    y = m.y0.copy()
    cg, rg = m.layout.cage0, m.layout.ring0
    y[cg + 1], y[cg + 8] = 0.5 * gl.clearance, 0.1 * gl.clearance * 600.0
    y[rg + 1] = 0.1 * gl.clearance  # the ring centre moves too: the film sees the relative offset
    P0 = m.P.copy()
    kio.set_value(P0, "n_land", 0)
    scratch = (np.zeros((m.layout.Z, K.N_CONTRIB)), np.zeros((m.layout.Z, K.N_AUX)), False, np.zeros(K.N_CONTRIB))
    on, off = np.empty_like(y), np.empty_like(y)
    g_on, g_off = np.zeros(K.N_GAUX), np.zeros(K.N_GAUX)
    K.rhs_kernel(y, m.P, m.qu, m.qw, on, *scratch, g_on)
    K.rhs_kernel(y, P0, m.qu, m.qw, off, *scratch, g_off)
    Fc = (on[cg + 7:cg + 9] - off[cg + 7:cg + 9]) * kio.get(m.P, "m_c")
    Fr = (on[rg + 6:rg + 8] - off[rg + 6:rg + 8]) * kio.get(m.P, "m_i")
    assert np.hypot(*Fc) > 1e-5 and Fr == pytest.approx(-Fc, abs=1e-9)  # round-off of the ~1 kN ring-load sum
    assert g_on[K.GAUX_INDEX["M_cx"]] > 0  # the inner ring turns faster than the cage: the film drives it
    assert g_on[K.GAUX_INDEX["P_guide_land"]] > 0
    ball = build_model(hsbearing.load_case("zhang2016", **{"cage.guidance": "ball"}), gravity=0.0)
    assert kio.get(ball.P, "n_land") == 0
    _, g = ball.outputs(ball.y0)
    assert np.all(g[[K.GAUX_INDEX[n] for n in ("F_cy", "F_cz", "M_cx", "P_guide_land")]] == 0.0)
