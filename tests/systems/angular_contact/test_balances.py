"""Energy, power and angular-momentum balances of the dynamic model (issue 14 items 4, 5c, 5d).

What these tests would have caught: before the race-contact reactions were closed, the spin couple of
the traction distribution and the EHL rolling couple acted on the ball but never on the inner ring, so
the drive torque (and its power) missed them: the power balance P_drive = sum D + dE/dt and the
angular-momentum balance dL/dt = external torque failed by the missing couples (docs/power_loss.md).

Three levels:
- instantaneous identities at many states spread over the state space the simulation visits (both
  rotation senses, turning outer ring, tilted ring, cage on the land, balls in their pockets): the
  balances hold to rounding, every term computed independently (dE/dt by differencing the mechanical
  energy along the model's own vector field, dL/dt from the state derivative, the dissipation from the
  contact functions of models/ball_bearing/power.py, the drive power from the ring reactions);
- (c) dissipation off (friction, damping, drag off): over a simulation, mechanical energy is constant
  and L(t) - L(0) equals the impulse of the external torque, to the solver tolerance;
- (d) dissipation on: over a simulation, the work of the drive equals the dissipated energy by source
  plus the change of mechanical energy within 1 %.
"""

from __future__ import annotations

import numpy as np
import pytest

import hsbearing as h
from hsbearing.models.ball_bearing import kernel_io as kio
from hsbearing.models.ball_bearing import power as pw
from hsbearing.solvers.cvode import integrate
from hsbearing.systems.angular_contact import balances as bl
from hsbearing.systems.angular_contact import dynamics as dy


def test_power_functions_signs_and_values():
    # a force opposing the slip dissipates, one along it would feed energy (not a loss)
    assert pw.sliding_power(-2.0, 0.0, 0.0, 3.0, 5.0, 0.0) == pytest.approx(6.0)
    assert pw.sliding_power(2.0, 0.0, 0.0, 3.0, 0.0, 0.0) == pytest.approx(-6.0)
    assert pw.couple_power(0.0, -0.5, 0.0, 1.0, 4.0, 7.0) == pytest.approx(2.0)
    # damping part of a normal load while approaching (delta' > 0) and while separating with Q clipped to 0
    assert pw.normal_damping_power(12.0, 10.0, 1e-3) == pytest.approx(2e-3)
    assert pw.normal_damping_power(0.0, 10.0, -1e-3) == pytest.approx(1e-2)
    # elastic energy: dU/d delta = K delta^1.5 (central difference)
    K, d, e = 1e10, 4e-6, 1e-10
    dU = (pw.elastic_energy_hertz(K, d + e) - pw.elastic_energy_hertz(K, d - e)) / (2 * e)
    assert dU == pytest.approx(K * d**1.5, rel=1e-6)
    assert pw.elastic_energy_hertz(K, -1e-6) == 0.0


def _random_states(m, n, seed):
    """States around the quasi-static start spread over what the simulation visits: sliding in every
    direction at both races, balls against either pocket wall, cage anywhere up to 3 % into the land,
    whirling either way, tilted, a displaced and tilting ring."""
    rng = np.random.default_rng(seed)
    L = m.layout
    Z = L.Z
    c_land = kio.get(m.P, "c_land")
    c_p = kio.get(m.P, "c_p")
    rm = 0.5 * kio.get(m.P, "dm")
    out = []
    for _ in range(n):
        y = m.y0.copy()
        u = lambda s, k=Z: rng.uniform(-s, s, k)  # noqa: E731
        y[L.ball("x_b")] += u(0.3e-6)
        y[L.ball("u_b")] += u(0.3e-6)
        y[L.ball("theta_rel_b")] = u(1.05 * c_p / rm)
        y[L.ball("xdot_b")] = u(5e-3)
        y[L.ball("udot_b")] = u(5e-3)
        y[L.ball("thetadot_b")] *= 1.0 + u(0.05)
        for k in ("omega_x", "omega_y", "omega_z"):
            w = np.abs(m.y0[L.ball("omega_x")]).max()
            y[L.ball(k)] += u(0.05 * w)
        r, a = c_land * rng.uniform(0.0, 1.03), rng.uniform(0, 2 * np.pi)
        y[L.cage("y_c")], y[L.cage("z_c")] = r * np.cos(a), r * np.sin(a)
        y[L.cage("ydot_c")], y[L.cage("zdot_c")] = u(0.1, 2)
        y[L.cage("phidot_c")] *= 1.0 + rng.uniform(-0.05, 0.05)
        y[L.cage("tilt_y_c")], y[L.cage("tilt_z_c")] = u(2e-4, 2)
        y[L.cage("tiltdot_y_c")], y[L.cage("tiltdot_z_c")] = u(1.0, 2)
        y[L.cage("xdot_c")] = rng.uniform(-0.01, 0.01)
        y[L.ring("x_i")] += rng.uniform(-0.3e-6, 0.3e-6)
        y[L.ring("y_i")], y[L.ring("z_i")] = u(1e-6, 2)
        y[L.ring("tilt_y_i")], y[L.ring("tilt_z_i")] = u(3e-5, 2)
        for k in ("xdot_i", "ydot_i", "zdot_i", "tiltdot_y_i", "tiltdot_z_i"):
            y[L.ring(k)] = rng.uniform(-2e-3, 2e-3)
        out.append(y)
    return out


def _assert_balances_close(m, y, regime):
    """The instantaneous power balance and (on the state with the tilts removed) the angular-momentum balance about
    X at state ``y`` of model ``m`` (module doc)."""
    b = bl.balance_terms(m, y)
    # scale: the largest power flowing in the balance (drive, a source, or the energy rate)
    scale = max(abs(b["drive_power"]), abs(b["outer_drive_power"]), abs(b["dE_dt"]), b["power_loss"])
    assert b["power_loss"] > 0.0
    for s in bl.SOURCES:
        assert b[f"power_loss_{s}"] >= -1e-9 * scale, (s, b[f"power_loss_{s}"])  # each source dissipates
    assert abs(b["power_residual"]) < 1e-7 * scale, (regime, b["power_residual"], scale)
    # angular momentum about X: the cage and ring rotations are Euler's small-tilt equations (seed
    # Eqs. 14-16, 20-21; I_p phi'' = e.M is not M_x once tilted), so the X balance is exact for
    # untilted cage and ring (measured 1e-14 N m) and holds to second order in the tilts otherwise
    # (docs/power_loss.md): checked on the same state with the tilts removed
    yt = y.copy()
    for k in ("tilt_y_c", "tilt_z_c", "tiltdot_y_c", "tiltdot_z_c"):
        yt[m.layout.cage(k)] = 0.0
    for k in ("tilt_y_i", "tilt_z_i", "tiltdot_y_i", "tiltdot_z_i"):
        yt[m.layout.ring(k)] = 0.0
    bt = bl.balance_terms(m, yt)
    tscale = max(abs(v) for v in bt["torques"].values()) + abs(bt["dL_dt"])
    assert abs(bt["torque_residual"]) < 1e-9 * tscale, (regime, bt["torque_residual"], tscale)
    assert abs(bt["power_residual"]) < 1e-7 * max(bt["power_loss"], abs(bt["dE_dt"]))


REGIMES = {
    "default": {},  # Zhang et al. 2016: 14000 r/min, 1 kN axial, gravity on
    "reversed": {"operating.inner_speed": "-14000 rpm"},  # the other rotation sense
    "outer_turning": {"operating.inner_speed": "6000 rpm", "operating.outer_speed": "-4000 rpm"},
    "combined_load": {"operating.radial_load": "800 N", "operating.moment_y": "2 N*m"},  # tilted ring
    # the land on the inner ring: its film and rub are internal (cage <-> ring), not an external torque
    # (independent review: the X balance was off by exactly the land torque before)
    "inner_guided": {"cage.guidance": "inner_ring"},
    # the inlet-shear-heating factor on the EHL rolling force (friction.inlet_heating): its couple's power is a source
    "inlet_heating": {"friction.inlet_heating": "on", "operating.inner_speed": "30000 rpm"},
    # the physical traction model (models.traction.eyring; the kernel's tabulated, node-paired strip integrand)
    "physical_traction": {"lubricant.traction_law": "eyring"},
}


@pytest.mark.parametrize("regime", list(REGIMES))
def test_instantaneous_power_and_momentum_balance(regime):
    """P_drive + P_outer_drive = sum of dissipated powers + dE/dt, and dL/dt = sum of external torques,
    at 12 states per regime: every term from its own computation (see the module doc)."""
    case = h.load_case("zhang2016", **REGIMES[regime])
    m = dy.build_model(case)
    for y in _random_states(m, 12, seed=len(regime)):
        _assert_balances_close(m, y, regime)


def _run(m, y0, t, rtol):
    res = integrate(m.rhs, y0, t, rtol=rtol, atol=m.layout.atol(rtol * 1e-3), jacfn=m.jac)
    assert res.success, res.status
    return res


def _impulse(m, Y, t):
    tau = np.array([sum(bl.external_torque_x(m, y).values()) for y in Y])
    return np.concatenate([[0.0], np.cumsum(0.5 * (tau[1:] + tau[:-1]) * np.diff(t))])


@pytest.mark.parametrize("kick", [False, True])
def test_dissipation_off_conserves_energy_and_angular_momentum(kick):
    """(c): friction, damping (films, EHL rolling) and drag off, gravity on: E constant and L(t) - L(0) =
    the external torque's impulse (gravity, loads, ground and drive reactions), to the solver tolerance.
    With ``kick`` the balls start off their pocket centres at orbit speeds +-3 % off the cage's, so they
    hit their pockets and angular momentum is exchanged between balls and cage.  Axial load: the ring
    and cage stay untilted, where the model's rotation equations conserve L_X exactly (docs/power_loss.md)."""
    case = h.load_case("zhang2016")
    m = dy.build_model(case, friction=False, damping=False, drag=False, gravity=9.81)
    L = m.layout
    y0 = m.y0.copy()
    if kick:
        rng = np.random.default_rng(7)
        y0[L.ball("thetadot_b")] *= 1.0 + rng.uniform(-0.03, 0.03, L.Z)
        y0[L.cage("ydot_c")] = 0.02
    t = np.linspace(0.0, 3e-3, 301)
    res = _run(m, y0, t, 1e-9)
    E = dy.mechanical_energy(m, res.y)
    aux, _ = m.outputs(y0)
    elastic = aux[:, dy.K.AUX_INDEX["U_el"]].sum()
    assert np.ptp(E) < 1e-6 * elastic, (np.ptp(E), elastic)
    H = bl.angular_momentum_x(m, res.y)
    J = _impulse(m, res.y, t)
    # scale: the angular momentum exchanged among the bodies (balls <-> cage through the pockets)
    u = L.unpack(res.y)
    Hc = kio.get(m.P, "Ip_c") * u["phidot_c"] + kio.get(m.P, "m_c") * (u["y_c"] * u["zdot_c"] - u["z_c"] * u["ydot_c"])
    exch = max(np.ptp(Hc), np.ptp(H - Hc))
    err = np.abs((H - H[0]) - J).max()
    tilt = np.hypot(u["tilt_y_c"], u["tilt_z_c"]).max()
    if kick:
        assert exch > 1e-6  # N m s: the pockets did exchange momentum (~3 % of the balls' orbital share)
        # the pocket impacts tilt the cage (measured up to 1.7e-3 rad); I_p phi'' = e.M then differs from
        # the X torque by (e - e_x).M (Euler's small-tilt equations): measured err/exch 2.4e-4
        assert err < 1e-3 * exch, (err, exch, tilt)
    else:  # cage tilt 1.4e-7 rad: measured err 4.6e-12 N m s = 5e-6 of the exchanged 9e-7 N m s
        assert err < 1e-4 * max(exch, 1e-9), (err, exch, np.ptp(H), tilt)


@pytest.mark.parametrize("regime", ["default", "reversed"])
def test_drive_work_equals_dissipation_plus_energy_change(regime):
    """(d): with every dissipation on, over 3 ms of the start-up transient (strong energy exchange: the
    balls' attitude settles, pocket impacts), W_drive = sum over sources of the dissipated energy +
    Delta E within 1e-4 of W_drive (the issue asks 1 %; trapezoidal rule on 10 us outputs); and the
    angular momentum balance over the same run."""
    case = h.load_case("zhang2016", **REGIMES[regime])
    m = dy.build_model(case)
    t = np.linspace(0.0, 3e-3, 301)
    res = _run(m, m.y0, t, 1e-7)
    ds = dy.to_dataset(m, t, res.y, {}, annotate=False)
    trap = lambda p: float(np.sum(0.5 * (p[1:] + p[:-1]) * np.diff(t)))  # noqa: E731
    W = trap(ds.drive_power.values)
    D = {s: trap(ds[f"power_loss_{s}"].values) for s in bl.SOURCES}
    E = dy.mechanical_energy(m, res.y)
    assert W > 0.0
    # the issue asks 1 %; measured 3e-6 (default) and 2.6e-6 (reversed) of W = 0.225 J with the single
    # 11 mm land, 1.2e-4 of W = 0.194 J with the two 1.8 mm lands (faster land-power transients: the
    # trapezoidal rule on 10 us samples; the instantaneous balance above is exact to 1e-7).  The old ring
    # reactions were off by ~4 W of 10-180 W (2-40 %, docs/power_loss.md), so 1e-3 keeps a wide margin both ways
    assert abs(W - sum(D.values()) - (E[-1] - E[0])) < 1e-3 * W, (W, D, E[-1] - E[0])
    H = bl.angular_momentum_x(m, res.y)
    J = _impulse(m, res.y, t)
    Jd = trap(ds.drive_torque.values)
    # measured 8e-6 with the single land at the cage centre; 7.1e-4 with the two lands at +-a along the cage
    # axis: they couple the cage tilt into X, where the small-tilt Euler equations hold L_X only to second
    # order in the tilt (the untilted instantaneous check above is exact to 1e-9)
    assert abs((H[-1] - H[0]) - J[-1]) < 2e-3 * abs(Jd), (H[-1] - H[0], J[-1], Jd)


def test_run_dataset_and_summary_carry_drive_torque_and_power_by_source():
    """The contract names are in the run Dataset with units, and the ``hsbearing run`` summary prints them."""
    case = h.load_case("zhang2016")
    ds = dy.simulate(case, duration=1e-3, annotate=False)
    assert ds.drive_torque.attrs["units"] == "N*m" and ds.power_loss.attrs["units"] == "W"
    total = sum(ds[f"power_loss_{s}"] for s in bl.SOURCES)
    assert np.allclose(total.values, ds.power_loss.values)
    for s, (_d, cols, _g) in bl.SOURCES.items():
        if cols:
            assert ds[f"power_loss_{s}_per_ball"].dims == ("time", "ball")
            assert np.allclose(ds[f"power_loss_{s}_per_ball"].sum("ball"), ds[f"power_loss_{s}"], rtol=1e-5)
    text = "\n".join(bl.power_summary_lines(ds))
    assert "drive_torque" in text and all(f"{s}:" in text for s in bl.SOURCES)


def test_instantaneous_power_balance_with_thermal_cage_film_factors():
    """``run --thermal``'s kernel (guide-land and pocket film viscosities times their thermal factors,
    ``build_model(cage_film_factors=...)``): the instantaneous power and momentum balances close as without,
    at 12 states (two different factors, so a film read at the other's viscosity would show)."""
    case = h.load_case("zhang2016", **{"operating.inner_speed": "30000 rpm"})
    m = dy.build_model(case, cage_film_factors=(0.63, 0.41))
    for y in _random_states(m, 12, seed=36):
        _assert_balances_close(m, y, "thermal cage films")
