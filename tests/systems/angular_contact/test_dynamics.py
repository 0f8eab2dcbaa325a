"""Dynamic model (Zhang et al. 2016, Eqs. 5-21): unit tests of the force functions, the compiled
Jacobian, and the physics invariants (energy, symmetry, quasi-static agreement, tolerance).

The long validations are marked ``slow``.  Literature checks name their source;
everything else is a physical invariant or an independent cross-check.
"""

import math

import numpy as np
import pytest

import hsbearing as h
from hsbearing.models.ball_bearing import ball, cage, drag, ring
from hsbearing.models.ball_bearing import kernel_io as kio
from hsbearing.models.ball_bearing.state import StateLayout
from hsbearing.systems.angular_contact import dynamics as dy


@pytest.fixture(scope="module")
def case():
    return h.load_case("zhang2016")


@pytest.fixture(scope="module")
def model(case):
    return dy.build_model(case)


# ----------------------------------------------------------------------------- state layout


def test_state_layout_roundtrip():
    L = StateLayout(11)
    assert L.size == 121 and len(L.state_names) == 121 and len(set(L.state_names)) == 121
    rng = np.random.default_rng(0)
    y = rng.normal(size=L.size)
    u = L.unpack(y)
    y2 = L.pack({k: u[k] for k in ("x_b", "u_b", "theta_rel_b", "xdot_b", "udot_b", "thetadot_b",
                                   "omega_x", "omega_y", "omega_z")},
                {k: u[k] for k in ("x_c", "y_c", "z_c", "phi_c", "tilt_y_c", "tilt_z_c",
                                   "xdot_c", "ydot_c", "zdot_c", "phidot_c", "tiltdot_y_c", "tiltdot_z_c")},
                {k: u[k] for k in ("x_i", "y_i", "z_i", "tilt_y_i", "tilt_z_i",
                                   "xdot_i", "ydot_i", "zdot_i", "tiltdot_y_i", "tiltdot_z_i")})
    assert np.array_equal(y, y2)
    assert L.state_names[L.cage0] == "x_c" and L.state_names[L.ring0] == "x_i"
    assert np.all(L.atol(1e-8) > 0)


# ----------------------------------------------------------------------------- force functions


def test_groove_contact_zero_at_nominal_and_sign():
    off = 0.02 * 9.525e-3
    a = math.radians(25)
    d, nx, nr, nt = ball.groove_contact(off * math.sin(a), off * math.cos(a), 0.0, off)
    assert abs(d) < 1e-15 and math.isclose(math.atan2(nx, nr), a) and nt == 0.0
    d2, _, _, _ = ball.groove_contact(1.001 * off * math.sin(a), 1.001 * off * math.cos(a), 0.0, off)
    assert d2 > 0  # groove centre moving away from the ball = compression


def test_hertz_normal_load():
    K = 1e10
    assert ball.hertz_normal_load(0.0, 1.0, K, 1e3) == 0.0
    assert ball.hertz_normal_load(-1e-6, -1.0, K, 1e3) == 0.0
    assert math.isclose(ball.hertz_normal_load(4e-6, 0.0, K, 0.0), K * 4e-6**1.5)
    # continuous (C1) at onset: force and slope vanish
    assert ball.hertz_normal_load(1e-12, 0.0, K, 0.0) < 1e-7
    # damping adds while approaching, never pulls
    assert ball.hertz_normal_load(4e-6, 0.1, K, 1e3) > ball.hertz_normal_load(4e-6, 0.0, K, 1e3)
    assert ball.hertz_normal_load(4e-6, -1e3, K, 1e3) == 0.0


def test_strip_weights_are_the_hertz_load_distribution():
    u, w = ball.strip_load_weights(5)
    assert math.isclose(w.sum(), 1.0)
    assert np.allclose(w, w[::-1]) and np.allclose(u, -u[::-1])
    # second moment of the strip load (3/4)(1 - u^2): int u^2 (3/4)(1-u^2) du over (-1, 1) = 1/5
    assert math.isclose((w * u * u).sum(), 0.2, rel_tol=1e-12)


def test_ehl_rolling_force_scaling():
    args = dict(Rx=3.9e-3, k=8.0, Ep=2.28e11, eta0=3e-3, alpha=1.28e-8)
    assert ball.ehl_rolling_force(10.0, 0.0, **args) == 0.0
    f1 = ball.ehl_rolling_force(10.0, 200.0, **args)
    f2 = ball.ehl_rolling_force(20.0, 200.0, **args)
    f3 = ball.ehl_rolling_force(10.0, 400.0, **args)
    assert 0 < f1 < 1.0  # a small fraction of the load (order 0.01-0.1 N at 200 N)
    assert math.isclose(f2 / f1, 2**0.66) and math.isclose(f3 / f1, 2**0.47)
    assert math.isclose(ball.ehl_rolling_force(-10.0, 200.0, **args), f1)


def test_ball_equations_gyroscopic_terms_conserve_spin_magnitude():
    # no moments: d|w|^2/dt = 2 w . w' = 0 (the frame-rotation terms only turn w)
    _, _, _, wxd, wyd, wzd = ball.ball_equations_of_motion(0, 0, 0, 0, 0, 0, 0.023, 0.0, 600.0, 1200.0, -300.0, 3.5e-3, 3e-8)
    assert abs(-2650.0 * wxd + 1200.0 * wyd + -300.0 * wzd) < 1e-6
    xdd, rdd, thdd, *_ = ball.ball_equations_of_motion(0, 0, 0, 0, 0, 0, 0.023, 0.0, 600.0, 0, 0, 3.5e-3, 3e-8)
    assert math.isclose(rdd, 0.023 * 600.0**2)  # centrifugal
    assert xdd == 0 and thdd == 0


def test_pocket_force():
    c, K, eta, R2, hmin = 50e-6, 1e9, 3e-3, 2.3e-5, 0.5e-6
    assert cage.pocket_normal_force(20e-6, 0.0, c, K, eta, R2, hmin) == 0.0
    assert cage.pocket_normal_force(20e-6, -1.0, c, K, eta, R2, hmin) == 0.0  # separating film cavitates
    assert cage.pocket_normal_force(20e-6, 0.1, c, K, eta, R2, hmin) > 0.0  # squeeze resists approach
    assert math.isclose(cage.pocket_normal_force(c + 1e-6, 0.0, c, K, 0.0, R2, hmin), K * 1e-6**1.5)
    # continuous through contact onset
    f_a = cage.pocket_normal_force(c - 1e-12, 0.01, c, K, eta, R2, hmin)
    f_b = cage.pocket_normal_force(c + 1e-12, 0.01, c, K, eta, R2, hmin)
    assert abs(f_a - f_b) < 1e-5 * max(f_a, 1e-9)
    assert cage.pocket_friction_factor(0.0, 0.1, 0.01) == pytest.approx(10.0)


def test_guide_land_short_bearing_matches_ocvirk_load_capacity():
    # Ocvirk short bearing, steady (no whirl, no squeeze): W = eta w R L^3 eps sqrt(16 eps^2 + pi^2 (1-eps^2)) / (4 c^2 (1-eps^2)^2)
    # (Hamrock, Schmid & Jacobson, Fundamentals of Fluid Film Lubrication, short-width journal bearing)
    eta, w, R, L, c = 3e-3, 600.0, 0.026, 0.011, 0.2e-3
    for eps in (0.1, 0.5, 0.8):
        Fr, Ft = cage.guide_land_forces(eps, 0.0, w, 0.0, eta, R, L, c)
        W = eta * w * R * L**3 * eps * math.sqrt(16 * eps**2 + math.pi**2 * (1 - eps**2)) / (4 * c**2 * (1 - eps**2) ** 2)
        assert math.hypot(Fr, Ft) == pytest.approx(W, rel=1e-12)
        assert Fr < 0 < Ft  # restoring along the line of centres, cross-coupled force ahead
    # half-frequency whirl carries no load (w - 2 whirl = 0), squeeze resists approach
    assert cage.guide_land_forces(0.5, 0.0, w, w / 2, eta, R, L, c) == (0.0, 0.0)
    assert cage.guide_land_forces(0.5, 10.0, 0.0, 0.0, eta, R, L, c)[0] < 0
    # Petroff torque at zero eccentricity
    assert cage.guide_land_torque(0.0, w, eta, R, L, c) == pytest.approx(-2 * math.pi * eta * R**3 * L * w / c)
    assert cage.smooth_eccentricity(0.5, 0.95) == pytest.approx(0.5, rel=1e-3)
    assert cage.smooth_eccentricity(5.0, 0.95) < 0.95


def test_drag_force():
    D, rho, C = 9.525e-3, 50.0, 0.5
    f = drag.ball_drag_force(14.0, D, rho, C, 0.0)
    assert f == pytest.approx(-0.5 * C * rho * math.pi * D**2 / 4 * 14.0**2)  # sphere drag 1/2 C_D rho v^2 A
    assert drag.ball_drag_force(-14.0, D, rho, C, 0.0) == pytest.approx(-f)
    assert drag.ball_drag_force(0.0, D, rho, C, 0.01) == 0.0
    assert drag.mixture_density(960.0, 0.05) == pytest.approx(0.05 * 960 + 0.95 * 1.1)


def _ring_point(phi, rho, g, xi, yi, zi, by, bz):
    """Inertial position of the groove-circle point at ring-frame azimuth phi (exact rotation)."""
    from scipy.spatial.transform import Rotation

    c = np.array([g, rho * np.cos(phi), rho * np.sin(phi)])
    return np.array([xi, yi, zi]) + Rotation.from_rotvec([0.0, by, bz]).apply(c)


def test_tilt_rotation_is_the_exponential_map():
    from scipy.spatial.transform import Rotation

    for by, bz in ((0.0, 0.0), (2e-4, -3e-4), (3e-3, 4e-3), (1e-9, 0.0)):
        R, J = ring.tilt_rotation(by, bz)
        assert np.allclose(np.reshape(R, (3, 3)), Rotation.from_rotvec([0, by, bz]).as_matrix(), atol=1e-15)
        # left Jacobian: R(beta + J^-1 w dt) = exp(w dt) R(beta)
        w = np.array([0.3, -0.2, 0.5])
        bd = np.linalg.solve(np.reshape(J, (3, 3)), w)
        dt = 1e-6
        lhs = Rotation.from_rotvec(np.array([0, by, bz]) + bd * dt).as_matrix()
        rhs = Rotation.from_rotvec(w * dt).as_matrix() @ np.reshape(R, (3, 3))
        assert np.allclose(lhs, rhs, atol=1e-12)
    # small tilts: the generalised moments are the moments
    R, J = ring.tilt_rotation(1e-7, -1e-7)
    assert ring.tilt_generalised_moments(0.3, 1.0, -2.0, R, J) == pytest.approx((1.0, -2.0), rel=1e-6)


def test_inner_groove_centre_is_the_nearest_point_and_its_rate():
    x, r, th = 3e-7, 0.02301, 0.7
    rho, g = 0.02345, 1.2e-4
    pos = (1.6e-5, 7e-6, -4e-6)
    tilt = (2e-3, -3e-3)
    R, J = ring.tilt_rotation(*tilt)
    vel, tilt_rate = (0.01, -0.02, 0.03), (0.5, -0.4)
    wt = np.reshape(J, (3, 3)) @ np.array([0.0, *tilt_rate])
    dX, dR, dT, vX, vR, vT = ring.inner_groove_centre(x, r, th, rho, g, *pos, R, *vel, *wt)
    b = np.array([x, r * math.cos(th), r * math.sin(th)])
    # brute force: nearest point of the (tilted, displaced) groove-centre circle
    phis = th + np.linspace(-6e-3, 6e-3, 120001)
    pts = np.array([_ring_point(p, rho, g, *pos, *tilt) for p in phis])
    dist = np.linalg.norm(pts - b, axis=1)
    assert math.sqrt(dX**2 + dR**2 + dT**2) == pytest.approx(dist.min(), abs=1e-12)
    assert abs(dT) > 1e-8  # displaced/tilted ring: the normal leaves the ball's azimuth plane
    # envelope theorem: d|c - b|/dt = n . (v_c(fixed azimuth) - v_b), checked by moving the ring
    dt = 1e-7
    pos2 = tuple(p + v * dt for p, v in zip(pos, vel))
    tilt2 = tuple(p + v * dt for p, v in zip(tilt, tilt_rate))
    d2 = ring.inner_groove_centre(x, r, th, rho, g, *pos2, ring.tilt_rotation(*tilt2)[0], *vel, *wt)
    L1 = math.sqrt(dX**2 + dR**2 + dT**2)
    L2 = math.sqrt(d2[0]**2 + d2[1]**2 + d2[2]**2)
    assert (L2 - L1) / dt == pytest.approx((dX * vX + dR * vR + dT * vT) / L1, rel=1e-4)


# ----------------------------------------------------------------------------- assembled model


def test_model_start_matches_quasistatic_loads(model):
    qs = model.info["quasistatic"]
    aux, _ = model.outputs(model.y0)
    # same geometry, Hertz constants and positions as the quasi-static solver: loads agree closely
    assert np.allclose(aux[:, 0], qs["inner_contact_load"].values, rtol=5e-3)
    assert np.allclose(aux[:, 1], qs["outer_contact_load"].values, rtol=5e-3)
    assert np.allclose(aux[:, 2], qs["inner_contact_angle"].values, atol=1e-4)
    assert np.allclose(aux[:, 3], qs["outer_contact_angle"].values, atol=1e-4)
    assert np.all(np.isfinite(model.f(model.y0)))


@pytest.mark.parametrize("loads", [{}, {"operating.radial_load": "800 N", "operating.moment_z": "1 N*m"}])
def test_arrowhead_jacobian_matches_full_finite_differences(loads):
    model = dy.build_model(h.load_case("zhang2016", **loads))
    y = model.y0.copy()
    rng = np.random.default_rng(1)
    L = model.layout
    y[L.ball("theta_rel_b")] += rng.normal(scale=1e-3, size=L.Z)  # break the symmetry
    y[L.cage("y_c")] = 20e-6
    y[L.cage("phi_c")] = 0.002
    y[L.cage("tilt_y_c")] += 1e-3  # tilted cage and (under radial load) ring: the J^T M maps
    y[L.cage("tiltdot_z_c")] = 0.3
    N = y.size
    J = np.zeros((N, N))
    model.jac(0.0, y, None, J)
    Jn = np.zeros((N, N))
    for k in range(N):
        hk = 1e-6 * max(abs(y[k]), model.hscale[k])
        yp, ym = y.copy(), y.copy()
        yp[k] += hk
        ym[k] -= hk
        Jn[:, k] = (model.f(yp) - model.f(ym)) / (2 * hk)
    scale = np.abs(Jn).max(axis=1, keepdims=True) + 1e-30
    err = np.abs(J - Jn) / scale
    assert np.max(err) < 2e-3, np.unravel_index(np.argmax(err), err.shape)


@pytest.mark.parametrize("loads", [
    {},
    {"operating.radial_load": "800 N"},  # ring tilts by ~3.6e-3 rad: exercises the exact tilt kinematics
    {"operating.radial_load": "500 N", "operating.radial_load_z": "-300 N", "operating.moment_y": "2 N*m"},
])
def test_energy_is_conserved_without_friction_and_damping(loads):
    """Done-when (c): friction and damping off -> total mechanical energy constant to the solver tolerance.

    Under radial load the frictionless balls are pushed round by the circumferential component of the
    contact normal, hit their pockets (tens of N) and kick the cage onto the land: every contact,
    the ring and cage tilts and the land rub take part.
    """
    case = h.load_case("zhang2016", **loads)
    m = dy.build_model(case, friction=False, damping=False, gravity=9.81)
    from hsbearing.solvers.cvode import integrate

    t = np.linspace(0.0, 3e-3 if loads else 2e-3, 31)
    res = integrate(m.rhs, m.y0, t, rtol=1e-9, atol=m.layout.atol(1e-12), jacfn=m.jac)
    assert res.success, res.status
    E = dy.mechanical_energy(m, res.y)
    # the energy exchanged between kinetic and elastic forms (the scale of what could go wrong):
    aux, _ = m.outputs(m.y0)
    elastic = (0.4 * aux[:, 0] * (aux[:, 0] / kio.get(m.P, "K_i")) ** (2 / 3)).sum()
    assert np.ptp(E) < 1e-5 * elastic, (np.ptp(E), elastic)  # (a wrong contact geometry gave 6e-2)
    # and the motion is not trivial (the start is out of dynamic equilibrium without friction)
    assert np.ptp(res.y[:, m.layout.ring("x_i")]) > 1e-9


def test_friction_and_damping_only_dissipate():
    """With both rings at rest, traction, pocket and land friction, films and contact damping can only
    remove energy: spinning balls and a moving cage must lose mechanical energy monotonically."""
    case = h.load_case("zhang2016", **{"operating.inner_speed": "0 rpm"})
    m = dy.build_model(case, initial="nominal")
    L = m.layout
    y0 = m.y0.copy()
    y0[L.ball("thetadot_b")] = 300.0
    y0[L.ball("omega_x")] = -2000.0
    y0[L.ball("omega_y")] = 800.0
    y0[L.cage("phidot_c")] = 250.0
    y0[L.cage("ydot_c")] = 0.05
    y0[L.ring("x_i")] = 12e-6
    from hsbearing.solvers.cvode import integrate

    t = np.linspace(0.0, 4e-3, 201)
    res = integrate(m.rhs, y0, t, rtol=1e-8, atol=L.atol(1e-10), jacfn=m.jac)
    assert res.success, res.status
    E = dy.mechanical_energy(m, res.y)
    assert np.all(np.diff(E) < 0)
    assert E[-1] < 0.05 * E[0]  # most of the kinetic energy is gone in 4 ms


def test_rings_turning_together_carry_balls_and_cage_rigidly():
    """Both rings at 3000 r/min: the bearing turns as a rigid body -- cage and ball orbit speeds equal the
    ring speed, the balls' absolute angular velocity is the ring speed about X, no sliding at the
    contacts, no land torque.  Checks the outer-race kinematics (outer_speed) and the nominal start.
    Drag is off: the model takes the air-oil mixture at rest (docs/dynamics.md)."""
    case = h.load_case("zhang2016", **{"operating.inner_speed": "3000 rpm", "operating.outer_speed": "3000 rpm"})
    w = case.operating.inner_speed
    m = dy.build_model(case, initial="nominal", drag=False, gravity=0.0)
    ds = dy.simulate(case, duration=2e-3, model=m, annotate=False)
    assert np.allclose(ds.cage_speed.values / w, 1.0, atol=1e-4)
    # The balls settle from the nominal start: with the limiting-shear floor of the traction law at zero rolling
    # speed (issue 15; mu <= Lambda instead of the old blow-up that locked them at once) the orbit speed deviates
    # by up to 1.9e-4 in the first 0.2 ms (measured), then by < 2e-5 and 1e-7 at the end.
    late = ds.time.values >= 0.5 * float(ds.time[-1])
    assert np.allclose(ds.ball_orbit_speed.values / w, 1.0, atol=5e-4)
    assert np.allclose(ds.ball_orbit_speed.values[late] / w, 1.0, atol=1e-5)
    assert np.allclose(ds.ball_angular_velocity_x.values[-1] / w, 1.0, atol=1e-4)
    for race in ("inner", "outer"):
        slip = ds[f"{race}_slide_roll_ratio"].values * ds[f"{race}_rolling_speed"].values
        assert np.abs(slip).max() < 1e-2  # m/s (settling of the balls on the races at the start)
    assert np.abs(ds.cage_land_moment.values).max() < 1e-5


def test_short_run_is_symmetric_and_finite(case):
    """Done-when (b), short span: pure axial load keeps the balls identical and the cage inside its clearance."""
    ds = dy.simulate(case, duration=2e-3, annotate=False, gravity=0.0)
    assert ds.attrs["status"] == "ok"
    for v in ("inner_contact_load", "outer_contact_load", "ball_orbit_speed"):
        a = ds[v].values[-1]
        assert np.ptp(a) <= 0.01 * np.abs(a).mean(), v
    r = np.hypot(ds.cage_center_y.values, ds.cage_center_z.values)
    assert r.max() < ds.attrs["guide_clearance"]
    assert ds.attrs["solver_steps"] > 0 and ds.attrs["solver_rhs_evals"] > 0
    # docs/design.md dataset contract
    for name, dims, units in [("inner_contact_load", ("time", "ball"), "N"), ("outer_contact_load", ("time", "ball"), "N"),
                              ("inner_contact_angle", ("time", "ball"), "rad"), ("outer_contact_angle", ("time", "ball"), "rad"),
                              ("cage_speed", ("time",), "rad/s"), ("cage_slip_ratio", ("time",), "1"),
                              ("cage_center_y", ("time",), "m"), ("cage_center_z", ("time",), "m"),
                              ("ball_orbit_speed", ("time", "ball"), "rad/s"), ("ball_spin_speed", ("time", "ball"), "rad/s"),
                              ("inner_ring_axial_displacement", ("time",), "m")]:
        assert ds[name].dims == dims and ds[name].attrs["units"] == units, name
    assert ds.sizes["ball"] == 11 and ds.time.values[-1] == pytest.approx(2e-3)
    assert "zhang2016" in ds.attrs["case_toml"] and ds.attrs["model"] == "zhang2016_dynamics"


def test_bad_input_is_a_case_error():
    with pytest.raises(h.CaseError, match="outer_land_diameter"):  # a land inside the cage: refused at load time
        dy.build_model(h.load_case("zhang2016", **{"bearing.outer_land_diameter": "51 mm"}))


def test_solver_failure_keeps_partial(case):
    with pytest.raises(h.SolverError) as exc:
        dy.simulate(case, duration=5e-3, wall_limit=1e-6, annotate=False)
    part = exc.value.partial
    assert part is not None and part.attrs["status"].startswith("failed at t = ")


# ----------------------------------------------------------------------------- long validations


@pytest.fixture(scope="module")
def steady_run(case):
    return dy.simulate(case, duration=0.05, annotate=False, gravity=0.0)


@pytest.mark.slow
def test_pure_axial_steady_state_matches_quasistatic(case, steady_run):
    """Done-when (a): after start-up, loads and angles within 2 % of the quasi-static solution, cage speed 1 %.

    The reference is the quasi-static solution *without* the gyroscopic couple
    (``solve_case(case, gyroscopic=False)``): with oil 4109 at 130 degC the
    traction law plateaus at mu ~ 0.007, far less than the ~0.025 needed to hold the
    gyroscopic moment of outer-race control, so the dynamic ball pitch settles
    well below the race-control value (20.4 deg) and the gyroscopic couple with it.
    Since issue 15 (S read in percent, docs/traction.md) the traction saturates at
    a hundredth of the slip and holds part of it: pitch ~ 8 deg (checked below,
    between 3 and 15 deg); loads, angles and cage speed still agree with the
    couple-free solution within 2 % / 1 %.
    """
    from hsbearing.systems.angular_contact import quasistatic

    qs = quasistatic.solve_case(case, gyroscopic=False)
    ds = steady_run
    late = ds.time > 0.6 * float(ds.time[-1])
    for v in ("inner_contact_load", "outer_contact_load", "inner_contact_angle", "outer_contact_angle"):
        dyn = ds[v].sel(time=late).mean("time").values
        assert np.allclose(dyn, qs[v].values, rtol=0.02), (v, dyn, qs[v].values)
    wc = float(ds.cage_speed.sel(time=late).mean())
    assert wc == pytest.approx(float(qs["cage_speed"]), rel=0.01)
    wx = ds.ball_angular_velocity_x.sel(time=late).mean("time").values
    wy = ds.ball_angular_velocity_y.sel(time=late).mean("time").values
    pitch = np.degrees(np.arctan(np.abs(wy / wx)))
    assert np.all((pitch > 3.0) & (pitch < 15.0)), pitch  # partly held: below race control (20.4 deg)


@pytest.mark.slow
def test_pure_axial_symmetry_long(steady_run):
    """Done-when (b): balls identical within 1 %, cage centre inside the guide clearance."""
    ds = steady_run
    for v in ("inner_contact_load", "outer_contact_load", "ball_orbit_speed"):
        a = ds[v].values[-50:]
        assert np.all(np.ptp(a, axis=1) <= 0.01 * np.abs(a).mean(axis=1)), v
    r = np.hypot(ds.cage_center_y.values, ds.cage_center_z.values)
    assert r.max() < ds.attrs["guide_clearance"]


@pytest.mark.slow
def test_halving_rtol_changes_cage_slip_by_less_than_1_percent(case, steady_run):
    """Done-when (d)."""
    ds2 = dy.simulate(case, duration=0.05, rtol=0.5 * case.simulation.rtol, annotate=False, gravity=0.0)
    late = ds2.time > 0.6 * float(ds2.time[-1])
    s1 = float(steady_run.cage_speed.sel(time=late).mean())
    s2 = float(ds2.cage_speed.sel(time=late).mean())
    th = float(steady_run.attrs["theoretical_cage_speed_nominal"])
    slip1, slip2 = 1 - s1 / th, 1 - s2 / th
    # "less than 1 %" of the slip ratio, with a floor of 1e-4 absolute when the slip itself is tiny
    assert abs(slip1 - slip2) < max(0.01 * abs(slip1), 1e-4)


@pytest.mark.slow
def test_default_case_cage_motion_is_a_single_circle_near_the_cage_speed(case):
    """The default case (oil 4109, 130 degC, 14000 r/min, F_x = 1000 N), one 0.7 s run, read on the transverse
    section (docs/analysis.md §0): the cage centre whirls on one circle at 0.9-1.1 x the cage speed -> "1 period,
    synchronous whirl"; the once-per-cage-revolution (clock) section of the same run creeps along the orbit
    (quasi-periodic, or a drifting arc still short of a full turn at 0.7 s).  Zhang et al. 2016 Table 3 reads
    "quasi-periodicity" for this cell: the paper's reading matches the clock section, not the orbit's shape
    (tests/data/zhang2016_periods.csv is checked to hold that label, the model is not tuned to it).

    Bound to ONE trajectory (the label of a single run), hence slow tier only and documented in docs/testing.md;
    re-measure (not re-tune) when the cage physics changes."""
    import csv
    from pathlib import Path

    with open(Path(__file__).resolve().parents[2] / "data" / "zhang2016_periods.csv") as fh:
        rows = [r for r in csv.DictReader(line for line in fh if not line.startswith("#"))]
    seed = {r["response"] for r in rows if r["oil"] == "4109" and r["temperature_degC"] == "130"
            and r["axial_force_N"] == "1000" and r["radial_force_N"] == "0"}
    assert seed == {"quasi-periodic"}
    ds = dy.simulate(case, duration=0.7)
    assert ds.attrs["classification"] == "1 period", ds.attrs["classification_reason"]
    assert ds.attrs["classification_detail"] == "synchronous whirl", ds.attrs["classification_detail_reason"]
    assert 0.9 < abs(float(ds["whirl_frequency_ratio"])) < 1.1
    assert ds.attrs["classification_alternative_section"] == "cage_revolution"
    assert ds.attrs["classification_alternative"] in ("quasi-periodic", "undetermined")


@pytest.mark.slow
def test_combined_load_ring_position_matches_quasistatic():
    """Independent cross-check of the displaced/tilted-ring geometry: F_x = 1 kN + F_y = 500 N.

    The time-mean inner-ring displacements and tilt after start-up agree with the quasi-static
    solution (without gyroscopic couple, see test (a)) within 3 %, and the largest ball loads
    (ball passing the load line) within 3 %.  Measured: x_i -0.7 %, y_i +1.2 %, tilt 2.7e-3 rad +1.5 %,
    Q_i,max +0.9 %, Q_o,max +1.0 %."""
    from hsbearing.systems.angular_contact import quasistatic

    case = h.load_case("zhang2016", **{"operating.radial_load": "500 N"})
    ds = dy.simulate(case, duration=0.06, annotate=False, gravity=0.0)
    qs = quasistatic.solve_case(case, gyroscopic=False)
    late = ds.time > 0.03
    for v in ("inner_ring_axial_displacement", "inner_ring_radial_displacement_y", "inner_ring_tilt_z"):
        assert float(ds[v].sel(time=late).mean()) == pytest.approx(float(qs[v]), rel=0.03), v
    for v in ("inner_contact_load", "outer_contact_load"):
        assert float(ds[v].sel(time=late).max()) == pytest.approx(float(qs[v].max()), rel=0.03), v
    assert float(ds.cage_speed.sel(time=late).mean()) == pytest.approx(float(qs["cage_speed"]), rel=0.02)
