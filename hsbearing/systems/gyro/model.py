"""The gyro bearing system (Jiang et al. 2014): model builder, simulation, derived moments, start
ensemble, parameter studies and figures.  The physics (friction-moment sources, ribbon-cage contact, the
compiled right-hand side) is :mod:`hsbearing.models.friction.gyro`; the decisions are in
``docs/validation/gyro.md``.
"""

from __future__ import annotations

import math
import time
from dataclasses import dataclass, field
from pathlib import Path

import numpy as np
from scipy.optimize import brentq

from hsbearing.errors import CaseError, SolverError
from hsbearing.models.friction import gyro as _physics
from hsbearing.models.friction.gyro import (  # noqa: F401 - the physics, also public here
    _P_BETA,
    _P_CHI,
    _P_D,
    _P_DM,
    _P_DP,
    _P_E,
    _P_G,
    _P_GX,
    _P_GY,
    _P_GZ,
    _P_IB,
    _P_JX,
    _P_JY,
    _P_JZ,
    _P_K,
    _P_LEN,
    _P_MB,
    _P_MC,
    _P_MU,
    _P_MU_C,
    _P_NABLA,
    _P_NO,
    _P_OSC,
    _P_Q,
    _P_RI,
    _P_RO,
    _P_T,
    _P_TR,
    _P_VREG_C,
    _P_VREG_R,
    _P_WI,
    GRAVITY,
    StaticFriction,
    _speed,
    ball_cage_stiffness,
    cage_contact_moment,
    circumferential_play_angle,
    deformed_surface_radius,
    differential_sliding_factor,
    differential_sliding_moment,
    euler_rate_matrix,
    hysteresis_moment,
    kernel,
    outer_race_speed,
    pivoting_moment,
    pocket_geometry,
    pocket_penetration,
    pure_rolling_lines,
    ribbon_cage_mass_properties,
    spin_to_roll_ratios,
    static_friction,
    thrust_contact_angle,
    total_friction_moment,
    transform_Ic,
    viscous_moment,
)
from hsbearing.results import make_dataset, register, solver_attrs, standard_attrs

#: the physics' public names (re-exported above) and this module's own
__all__ = [*_physics.__all__,
           "GyroModel",
           "build_model",
           "simulate",
           "starting_moments",
           "cage_moment_windows",
           "start_offsets",
           "start_ensemble",
           "ensemble_lines",
           "summary",
           "override",
           "plot_run",
           ]

# ----------------------------------------------------------------------------------------------
# output variables (declared once, here)
for _n, _d, _u, _l in [
    ("outer_race_speed", ("time",), "rad/s", "outer-race angular speed omega_o(t) (Jiang et al. 2014 operating profile)"),
    ("cage_angle", ("time",), "rad", "cage rotation angle about X (unwrapped)"),  # same declaration as hsbearing.systems.angular_contact.dynamics
    ("friction_moment_total", ("time",), "N m",
     "total friction moment on the outer race M = M_L + M_E + M_D + M_S + max(M_C, 0) (Jiang et al. 2014 Eq. 1); peak-hold over each output interval"),
    ("friction_moment_viscous", ("time",), "N m", "viscous (lubricant drag) friction moment M_L (Jiang et al. 2014 Eq. 2)"),
    ("friction_moment_hysteresis", ("time",), "N m", "elastic-hysteresis friction moment M_E (Jiang et al. 2014 Eqs. 1-2)"),
    ("friction_moment_differential", ("time",), "N m", "differential-sliding friction moment M_D (Jiang et al. 2014 Eqs. 1-2)"),
    ("friction_moment_pivoting", ("time",), "N m", "pivoting (spin) friction moment M_S (Jiang et al. 2014 Eqs. 1-2)"),
    ("friction_moment_cage", ("time",), "N m",
     "ball/cage friction moment M_C = sum (F_mu + F_pbz) R_o/2, signed, driving positive (Jiang et al. 2014 Eq. 1); value of largest magnitude in each output interval"),
    ("ball_cage_contact_force", ("time", "ball"), "N", "ball/pocket normal contact force F_pbN (Jiang et al. 2014 Eq. 10), sum of the pocket's contact points"),
    ("sfmc", (), "N m", "starting friction moment at constant rate: max M after the start from rest (Jiang et al. 2014 Sec. 4)"),
    ("sfmo", (), "N m", "starting friction moment under oscillation: mean of the max M of each reversal window (Jiang et al. 2014 Sec. 4)"),
    ("rfmc", (), "N m", "running friction moment at constant rate M_E + M_D + M_S + M_L (Jiang et al. 2014 Sec. 5.1)"),
    ("window_max_moment", ("window",), "N m", "max total friction moment M in each oscillation window (Jiang et al. 2014 Sec. 4)"),
    ("window", ("window",), "1", "index of the oscillation window (0 = start from rest)"),
    # sweep summary of a gyro run (gyro.summary)
    ("sfmo_sd", (), "N m", "sample standard deviation (n - 1) of the reversal-window maxima of M (Jiang et al. 2014 Sec. 4)"),
    ("sfmo_stderr", (), "N m", "standard error of SFMO: sfmo_sd / sqrt(reversal_windows)"),
    ("reversal_windows", (), "1", "number of reversal windows averaged in SFMO"),
    ("pocket_clearance", (), "m", "ball/pocket clearance A = k - D_w/2 (Jiang et al. 2014 Sec. 3.2)"),
    ("cage_mass", (), "kg", "cage mass used by the model (ribbon strips of thickness s, or cage.mass)"),
    # start ensemble (simulation.start_positions > 1; gyro.start_ensemble)
    ("start_offset", ("start_offset",), "1",
     "initial turn of the cage about the axis as a fraction of its circumferential pocket play (-0.5..0.5; 0 = the default start)"),
    ("sfmc_ensemble", ("start_offset",), "N m",
     ("SFMC of each start of the start ensemble: max M in a constant-rate start of one oscillation_period from rest, "
      "cage turned by start_offset of its play (Jiang et al. 2014 Sec. 4)")),
    ("sfmc_ensemble_mean", (), "N m", "mean of sfmc_ensemble over the start offsets (SFMC averaged over the initial cage position)"),
    ("sfmc_ensemble_sd", (), "N m", "sample standard deviation (n - 1) of sfmc_ensemble over the start offsets"),
]:
    register(_n, _d, _u, _l)


@dataclass
class GyroModel:
    """The assembled gyro-bearing model of a case: parameters, static friction, state layout."""

    case: object
    Z: int
    p: np.ndarray
    static: StaticFriction
    cage_mass: float
    state_names: list = field(default_factory=list)
    atol: np.ndarray = None
    _diag: np.ndarray = None

    def rhs(self, t, y, ydot):
        """``rhs(t, y, ydot)`` in place (CVODE signature)."""
        kernel(t, y, self.p, self.Z, ydot, self._diag)

    def diagnostics(self, t, y):
        """Per-ball (F_N, F_pbz driving +, F_T) [N] at one state."""
        ydot = np.empty_like(y)
        diag = np.zeros((self.Z, 3))
        kernel(float(t), np.ascontiguousarray(y), self.p, self.Z, ydot, diag)
        return diag

    def y0(self, settle: bool = True, cage_offset=(0.0, 0.0, 0.0), cage_angle: float = 0.0):
        """Initial state: balls and races at rest; the cage centred or, with ``settle``, resting on the balls under gravity.

        ``cage_offset`` (x, y, z) [m] displaces the cage centre (Frame I) and ``cage_angle`` [rad]
        turns the cage about the axis before settling.
        """
        Z = self.Z
        y = np.zeros(12 + 3 * Z)
        y[0:3] = cage_offset
        y[3] = cage_angle
        y[12:12 + Z] = 2.0 * np.pi * np.arange(Z) / Z
        # settle the cage along the direction of gravity (-Y unless build_model(gravity_direction=...)):
        # static equilibrium of its weight and the pocket contacts, balls at rest.
        # Decision: the start position is the settled one even when the dynamics run without gravity
        # (default): a generic off-centre cage, as left by gravity on the test bench before the start.
        ps = self.p.copy()
        ps[_P_G] = GRAVITY
        mc_g = ps[_P_MC] * ps[_P_G]
        g_hat = ps[[_P_GX, _P_GY, _P_GZ]]
        ydot = np.empty_like(y)
        diag = np.zeros((Z, 3))
        A = np.empty((3, 3))
        transform_Ic(y[3], y[4], y[5], A)

        def net(h):
            yy = y.copy()
            yy[0:3] = y[0:3] + h * g_hat
            kernel(0.0, yy, ps, Z, ydot, diag)
            # net force against gravity: contacts minus weight (Frame c -> Frame I: A^T; cage at rest)
            return -float(g_hat @ (A.T @ ydot[6:9])) * ps[_P_MC]

        if settle and mc_g > 0:
            hi = self.p[_P_NABLA]
            if net(hi) > 0:
                if self.p[_P_G] > 0:
                    y[0:3] = y[0:3] + brentq(net, 0.0, hi, xtol=1e-16) * g_hat  # weight carried by the pocket contacts
                else:
                    # no weight in the dynamics: the cage just touches (zero approach), so no elastic
                    # energy is stored in the initial state (it would kick the cage at t = 0).
                    # (Contact is tested on the contact forces themselves: testing net + weight > 0, as
                    # before 2026-11, was rounding noise for a turned cage, which then stayed centred.)
                    p0 = self.p.copy()
                    p0[_P_G] = 0.0

                    def touching(h):
                        yy = y.copy()
                        yy[0:3] = y[0:3] + h * g_hat
                        diag[:] = 0.0
                        kernel(0.0, yy, p0, Z, ydot, diag)
                        return diag[:, 0].max() > 0.0

                    lo, up = 0.0, hi
                    for _ in range(200):
                        mid = 0.5 * (lo + up)
                        if touching(mid):
                            up = mid
                        else:
                            lo = mid
                    y[0:3] = y[0:3] + lo * g_hat
        return y


def _opt(value, default):
    return default if value is None else value


def build_model(case, *, creep_speed: float = 2e-5, cage_slip_speed: float = 1e-5,
                restitution: float | None = None, reference_impact_speed: float | None = None,
                gravity: float = 0.0, gravity_direction=(0.0, -1.0, 0.0)) -> GyroModel:
    """Parameters of the assembled model from a ``gyro_ribbon_cage`` case.

    creep_speed : v_reg of the ball/race traction [m/s] (regularised [J] Eq. 19).
    cage_slip_speed : v_reg of the ball/cage friction [m/s] (regularised [J] Eq. 12).
    restitution : Hunt-Crossley restitution (default ``friction.cage_restitution`` or 0.5).
    reference_impact_speed : speed at which the restitution holds (default: the ball
        orbit speed at n_o, d_m/2 (1 + gamma)/2 |n_o|).
    gravity : acceleration of gravity on the cage [m/s^2] (0 = in orbit; default of the case).
    gravity_direction : direction of gravity in Frame I (X = bearing axis) [-], normalised here;
        default -Y (horizontal bearing axis, gravity across it).  Also the direction in which
        :meth:`GyroModel.y0` settles the cage.
    """
    if case.system != "gyro_ribbon_cage":
        raise CaseError(case.source, "case.system", f"the gyro model needs system 'gyro_ribbon_cage', got {case.system!r}")
    b, c, m, op = case.bearing, case.cage, case.materials, case.operating
    for key, val in (("cage.pocket_diameter", c.pocket_diameter), ("cage.pocket_depth", c.pocket_depth),
                     ("cage.thickness", c.thickness), ("operating.ramp_time", op.ramp_time)):
        if val is None:
            raise CaseError(case.source, key, "missing required key for the gyro ribbon-cage model")
    D, dm, Z = b.ball_diameter, b.pitch_diameter, b.ball_count
    Dp, k = c.pocket_diameter, c.pocket_depth
    if not (0.5 * D < k <= 0.5 * Dp * (1.0 + 1e-9)):
        raise CaseError(case.source, "cage.pocket_depth",
                        f"pocket depth k = {k*1e3:g} mm must lie between D/2 = {D*500:g} mm and D_p/2 = {Dp*500:g} mm (Jiang et al. 2014 Sec. 3.2)")
    st = static_friction(case)
    e, nabla = pocket_geometry(D, Dp, k)
    K = ball_cage_stiffness(D, Dp, m.ball.elastic_modulus, m.ball.poisson_ratio, m.cage.elastic_modulus, m.cage.poisson_ratio)
    if c.mass is not None:
        mc = c.mass
        Jx = _opt(c.axial_inertia, mc * (0.5 * dm) ** 2)
        Jy = _opt(c.diametral_inertia, 0.5 * Jx)
    else:
        width = c.width if c.width is not None else Dp
        mc, Jx, Jy = ribbon_cage_mass_properties(dm, Z, c.thickness, width, Dp, k, m.cage.density)
        Jx = _opt(c.axial_inertia, Jx)
        Jy = _opt(c.diametral_inertia, Jy)
    rho_b = m.ball.density
    mb = rho_b * math.pi * D**3 / 6.0
    Ib = mb * D**2 / 10.0
    gamma = D * math.cos(st.beta) / dm
    e_r = restitution if restitution is not None else _opt(case.friction.cage_restitution, 0.5)
    n_o = op.outer_speed
    if reference_impact_speed is None:
        reference_impact_speed = max(abs(n_o) * 0.5 * (1.0 + gamma) * 0.5 * dm, 1e-6)
    chi = 1.5 * (1.0 - e_r) / reference_impact_speed  # [HC]: chi = 3 (1 - e) / (2 v_impact)
    p = np.zeros(_P_LEN)
    p[_P_DM], p[_P_D], p[_P_DP], p[_P_E], p[_P_NABLA] = dm, D, Dp, e, nabla
    p[_P_K], p[_P_CHI], p[_P_MU_C], p[_P_VREG_C] = K, chi, case.friction.cage_coefficient, cage_slip_speed
    p[_P_MC], p[_P_JX], p[_P_JY], p[_P_JZ] = mc, Jx, Jy, Jy
    p[_P_MB], p[_P_IB], p[_P_Q], p[_P_MU], p[_P_VREG_R], p[_P_BETA] = mb, Ib, st.Q, case.friction.coefficient, creep_speed, st.beta
    p[_P_RI], p[_P_RO], p[_P_G] = st.Ri, st.Ro, gravity
    p[_P_NO], p[_P_TR] = n_o, op.ramp_time
    p[_P_OSC] = 1.0 if op.mode == "oscillation" else 0.0
    p[_P_T] = op.oscillation_period
    p[_P_WI] = op.inner_speed
    g_dir = np.asarray(gravity_direction, dtype=float)
    if g_dir.shape != (3,) or not np.linalg.norm(g_dir) > 0:
        raise ValueError(f"gravity_direction must be a non-zero 3-vector, got {gravity_direction!r}")
    p[_P_GX], p[_P_GY], p[_P_GZ] = g_dir / np.linalg.norm(g_dir)
    names = (["cage_Rx", "cage_Ry", "cage_Rz", "cage_theta_x", "cage_theta_y", "cage_theta_z",
              "cage_Vx", "cage_Vy", "cage_Vz", "cage_wx", "cage_wy", "cage_wz"]
             + [f"ball{j}_psi" for j in range(Z)] + [f"ball{j}_orbit_speed" for j in range(Z)]
             + [f"ball{j}_rotation_speed" for j in range(Z)])
    w_ref = max(abs(n_o), 1e-3)
    atol = np.concatenate([
        np.full(3, 1e-13), np.full(3, 1e-11), np.full(3, 1e-10), np.full(3, 1e-8 * w_ref),
        np.full(Z, 1e-11), np.full(Z, 1e-8 * w_ref), np.full(Z, 1e-7 * w_ref)])
    return GyroModel(case=case, Z=Z, p=p, static=st, cage_mass=mc, state_names=names, atol=atol,
                     _diag=np.zeros((Z, 3)))


# ==============================================================================================
# 4. Simulation, derived moments
# ==============================================================================================


def starting_moments(t, M, mode, period, ramp_time):
    """SFMC / SFMO from a total-moment history ([J] Sec. 4).

    SFMC: the maximum M in the first window (start from rest).  SFMO (oscillation):
    the mean of the maximum M of each complete later window [k T, (k+1) T), k >= 1
    (the reversal windows; a window counts if the run covers its first 0.5 T or
    the run ends after it).  Returns (sfmc, sfmo or nan, per-window maxima).
    """
    t = np.asarray(t)
    M = np.asarray(M)
    if mode != "oscillation":
        return float(np.max(M)), float("nan"), np.array([float(np.max(M))])
    nwin = int(np.ceil((t[-1] - t[0]) / period - 1e-9))
    maxima = []
    for k in range(nwin):
        sel = (t >= k * period) & (t < (k + 1) * period)
        covered = t[-1] >= min((k + 0.5) * period, k * period + max(0.25, 20 * ramp_time))
        if sel.any() and covered:
            maxima.append(float(np.max(M[sel])))
    maxima = np.array(maxima)
    sfmc = float(maxima[0]) if maxima.size else float("nan")
    sfmo = float(np.mean(maxima[1:])) if maxima.size > 1 else float("nan")
    return sfmc, sfmo, maxima


def cage_moment_windows(ds, fraction: float = 0.9):
    """Share of the ball/cage moment in each window's maximum, and how fast it dies out ([J] Figs. 8-9).

    For each window k (0 = the start, then one per reversal; the whole run for a constant-rate run):

    * ``share[k]`` = M_C / M at the instant of the window's maximum of M, i.e. 1 - RFMC / max M [-]
      ([J] Figs. 8-9 show M_C above half of M at each start and reversal);
    * ``decay[k]`` = time from the window start until ``fraction`` (0.9) of the window's integral
      of the driving M_C (max(M_C, 0)) has accumulated [s].  Impacts that die out within ~1 s, as
      in [J], give well under 1 s; a cage carried along by friction (steady M_C) gives
      ``fraction`` times the window length (1.8 s for 2 s windows).

    Uses the stored (peak-hold) series ``friction_moment_total`` / ``friction_moment_cage`` and ``rfmc``.
    Returns ``(share, decay)`` as arrays.
    """
    t = np.asarray(ds["time"].values)
    M = np.asarray(ds["friction_moment_total"].values)
    MC = np.maximum(np.asarray(ds["friction_moment_cage"].values), 0.0)
    M_static = float(ds["rfmc"].values)
    if "window" in ds.dims:
        T = float(ds.attrs.get("oscillation_period", 0.0)) or _period_of(ds)
        edges = [(k * T, (k + 1) * T) for k in range(int(ds.sizes["window"]))]
    else:
        edges = [(t[0], t[-1] + 1.0)]
    share, decay = [], []
    for t0, t1 in edges:
        sel = np.nonzero((t >= t0) & (t < t1))[0]
        if sel.size == 0:
            share.append(float("nan"))
            decay.append(float("nan"))
            continue
        Mmax = M[sel].max()
        share.append(float(1.0 - M_static / Mmax) if Mmax > 0 else float("nan"))  # M = M_static + max(M_C, 0)
        cum = np.cumsum(MC[sel])  # uniform stored interval: the integral up to a constant
        decay.append(float(t[sel[np.searchsorted(cum, fraction * cum[-1])]] - t0) if cum[-1] > 0 else 0.0)
    return np.array(share), np.array(decay)


def _period_of(ds) -> float:
    from hsbearing.case import loads_case

    return loads_case(ds.attrs["case_toml"], "archive").operating.oscillation_period


def summary(ds) -> dict:
    """Scalars of a gyro run for a sweep table (what applies to this model; [J] Sec. 4).

    ``sfmc``, ``rfmc`` [N m] always; oscillation runs add ``sfmo`` [N m], ``sfmo_sd`` (sample
    standard deviation of the reversal-window maxima), ``sfmo_stderr`` = sfmo_sd / sqrt(n) and
    ``reversal_windows`` (n); ``pocket_clearance`` A [m] and ``cage_mass`` [kg] from the run's
    attributes (A is not a case key: a sweep over A varies ``cage.pocket_depth`` = D_w/2 + A);
    ``sfmc_ensemble_mean`` / ``sfmc_ensemble_sd`` [N m] when the run holds a start ensemble
    (``simulation.start_positions`` > 1).  No whirl / classification / contact-load fields: they belong to the rolling-element dynamics.
    """
    out: dict = {}
    for name in ("sfmc", "sfmo", "rfmc", "sfmc_ensemble_mean", "sfmc_ensemble_sd"):
        if name in ds and ds[name].ndim == 0:
            out[name] = float(ds[name].values)
    if "window_max_moment" in ds:
        rev = np.asarray(ds["window_max_moment"].values, dtype=float)[1:]
        out["reversal_windows"] = int(rev.size)
        out["sfmo_sd"] = float(np.std(rev, ddof=1)) if rev.size > 1 else float("nan")
        out["sfmo_stderr"] = out["sfmo_sd"] / math.sqrt(rev.size) if rev.size > 1 else float("nan")
    if "pocket_clearance_m" in ds.attrs:
        out["pocket_clearance"] = float(ds.attrs["pocket_clearance_m"])
    if "cage_mass_kg" in ds.attrs:
        out["cage_mass"] = float(ds.attrs["cage_mass_kg"])
    return out


def simulate(case, duration=None, progress: bool = False, *, fine_interval: float = 5e-6,
             wall_limit: float | None = None, settle: bool = True, cage_offset=(0.0, 0.0, 0.0),
             cage_angle: float = 0.0, **kw):
    """Integrate the gyro-bearing model of ``case`` and return the result Dataset.

    Parameters
    ----------
    case : a ``gyro_ribbon_cage`` :class:`~hsbearing.case.Case`.
    duration : simulated time [s] (None: ``[simulation] duration``).
    fine_interval : internal sampling of the contact forces [s] (CVODE dense
        output; does not limit the step).  The stored series are decimated to
        ``[simulation] output_interval``; M and M_C are stored as the value of
        largest magnitude within each output interval (peak-hold), so the short
        ball/cage impacts survive decimation and SFMC / SFMO are taken from the
        fine sampling.
    settle : start with the cage where its weight leaves it, resting on the balls (default); False:
        exactly centred (all balls then strike the pockets at the same instant).
    cage_offset : initial displacement (x, y, z) of the cage centre in Frame I [m].
    cage_angle : initial cage angle about the axis relative to the balls [rad].
    **kw : passed to :func:`build_model` (creep_speed, cage_slip_speed, restitution, gravity,
        gravity_direction).

    With ``[simulation] start_positions`` = N > 1 the run is followed by the start ensemble
    (:func:`start_ensemble`): N constant-rate starts of one ``operating.oscillation_period`` with
    the cage turned by :func:`start_offsets` (N) of its circumferential play, the same keywords
    and ``cage_angle`` added to each turn; the Dataset then also holds ``sfmc_ensemble`` over the
    dim ``start_offset`` and ``sfmc_ensemble_mean`` / ``sfmc_ensemble_sd`` [N m].  ``sfmc`` stays
    the SFMC of this run's own (default) start.  A start that fails numerically raises
    :class:`SolverError` with this run and the ensemble so far (NaN for the missing starts).
    """
    ds = _simulate_one(case, duration, progress, fine_interval=fine_interval, wall_limit=wall_limit,
                       settle=settle, cage_offset=cage_offset, cage_angle=cage_angle, **kw)
    n = case.simulation.start_positions
    if n is not None and n > 1:
        ds = _add_start_ensemble(ds, case, n, duration=duration, progress=progress, fine_interval=fine_interval,
                                 wall_limit=wall_limit, settle=settle, cage_offset=cage_offset, cage_angle=cage_angle,
                                 **kw)
    return ds


def _add_start_ensemble(ds, case, n: int, duration: float | None = None, **kw):
    """``ds`` with the start ensemble of ``n`` starts (``sfmc_ensemble`` ...); see :func:`simulate`.

    Each start runs one oscillation period, or the run's ``duration`` if shorter (``--duration`` applies to the
    ensemble too).  The offset-0 start of a constant-rate run of that same length is the run itself:
    its SFMC is reused, not computed a second time."""
    offsets = start_offsets(n)
    period = float(case.operating.oscillation_period)
    run_T = float(duration) if duration is not None else float(case.simulation.duration)
    T = min(run_T, period)
    reuse = None
    if case.operating.mode == "constant" and run_T == T and "sfmc" in ds and tuple(kw.get("cage_offset", (0, 0, 0))) == (0, 0, 0):
        reuse = float(ds["sfmc"].values)  # this run is the offset-0 start (same case, same length, same start)
    vals = np.full(n, np.nan)
    failure = None
    t0 = time.perf_counter()
    try:
        for i, v in enumerate(_ensemble_sfmc(case, offsets, T, reuse_zero=reuse, **kw)):
            vals[i] = v
    except SolverError as exc:
        failure = exc
    data = {
        "sfmc_ensemble": vals,
        "sfmc_ensemble_mean": float(np.mean(vals)),  # NaN if a start failed
        "sfmc_ensemble_sd": float(np.std(vals, ddof=1)),
    }
    ens = make_dataset(data, {"start_offset": offsets})
    out = ds.assign(ens.data_vars).assign_coords(start_offset=ens["start_offset"])
    out.attrs["start_ensemble_play_rad"] = circumferential_play_angle(
        case.bearing.ball_diameter, case.cage.pocket_diameter, case.cage.pocket_depth, case.bearing.pitch_diameter)
    out.attrs["start_ensemble_duration_s"] = T
    out.attrs["start_ensemble_wall_time_s"] = time.perf_counter() - t0
    if failure is not None:
        i = int(np.argmax(np.isnan(vals)))
        out.attrs["status"] = f"start ensemble failed at start_offset {offsets[i]:g}: {failure}"
        raise SolverError(f"gyro start ensemble, start_offset {offsets[i]:g}: {failure}", partial=out) from None
    return out


def ensemble_lines(ds) -> list[str]:
    """Lines for a printed summary of a run with a start ensemble (``hsbearing run``): SFMC mean +/- sd
    and the value of each start [uN m]; [] when ``ds`` has none."""
    if "sfmc_ensemble" not in ds or "start_offset" not in ds.coords:
        return []
    u = 1e6
    vals = np.asarray(ds["sfmc_ensemble"].values, dtype=float)
    offs = np.asarray(ds["start_offset"].values, dtype=float)
    lines = [(f"start ensemble: SFMC = {float(ds['sfmc_ensemble_mean']) * u:.4g} +/- {float(ds['sfmc_ensemble_sd']) * u:.4g} "
              f"\u00b5N m (mean +/- sample sd of {vals.size} constant-rate starts, cage turned by start_offset of its play)")]
    for f, v in zip(offs, vals):
        lines.append(f"  start_offset {f:5g}: SFMC {v * u:.4g} \u00b5N m" + (" (the default start)" if f == 0.0 else ""))
    return lines


def _simulate_one(case, duration=None, progress: bool = False, *, fine_interval: float = 5e-6,
                  wall_limit: float | None = None, settle: bool = True, cage_offset=(0.0, 0.0, 0.0),
                  cage_angle: float = 0.0, progress_desc: str = "gyro", **kw):
    """One run of :func:`simulate`, without the start ensemble (``progress_desc``: label of the progress bar)."""
    from hsbearing.solvers.cvode import integrate

    if isinstance(duration, str):
        from hsbearing.case import parse_quantity

        duration = parse_quantity(duration, "time", source="duration", key="duration")
    if progress:  # say so before a first-run compilation (hsbearing.jit)
        from hsbearing.jit import compile_notice

        compile_notice((kernel,), "the gyro model", seconds=5)
    model = build_model(case, **kw)
    sim = case.simulation
    T_end = float(duration if duration is not None else sim.duration)
    if not T_end > 0:
        raise CaseError(case.source, "simulation.duration", "must be positive")
    dt_out = min(sim.output_interval, T_end)
    fine = min(fine_interval, dt_out)
    nsub = max(1, int(round(dt_out / fine)))
    fine = dt_out / nsub
    n_out = int(math.floor(T_end / dt_out + 1e-9))
    t_fine = np.linspace(0.0, n_out * dt_out, n_out * nsub + 1)
    y0 = model.y0(settle=settle, cage_offset=cage_offset, cage_angle=cage_angle)
    from hsbearing.jit import warm_up

    warm_up(model.rhs, y0)  # compile the read-only-state signature CVODE uses before the progress bar starts
    res = integrate(model.rhs, y0, t_fine, rtol=min(sim.rtol, 1e-6), atol=model.atol,
                    max_step=min(model.case.operating.ramp_time, 0.01), max_num_steps=200000,
                    progress=progress, progress_desc=progress_desc, wall_limit=wall_limit)
    ds = _assemble(model, res, nsub)
    ds.attrs["cage_start"] = ("settled" if settle else "centred") + (
        f", offset {list(map(float, cage_offset))} m" if any(cage_offset) else "") + (
        f", turned {cage_angle:.6g} rad" if cage_angle else "")
    if not res.success:
        raise SolverError(f"gyro model: {res.status}", partial=ds)
    return ds


def _assemble(model: GyroModel, res, nsub: int):
    st = model.static
    Z = model.Z
    case = model.case
    op = case.operating
    t, Y = res.t, res.y
    n = t.size
    diag = np.zeros((n, Z, 3))
    w_o = np.empty(n)
    sgn = np.empty(n)
    for i in range(n):
        diag[i] = model.diagnostics(t[i], Y[i])
        w_o[i], sgn[i] = _speed(float(t[i]), model.p[_P_NO], model.p[_P_TR], int(model.p[_P_OSC]), model.p[_P_T])
    mu_c = case.friction.cage_coefficient
    dMC = cage_contact_moment(diag[:, :, 1], diag[:, :, 0], mu_c, st.Ro)  # [J], Eq. 1 (last term)
    M_C = dMC.sum(axis=1)
    M_static = st.rfmc
    M = M_static + np.maximum(M_C, 0.0)  # [J] Sec. 4: only the driving cage contacts add to M
    sfmc, sfmo, maxima = starting_moments(t, M, op.mode, op.oscillation_period, op.ramp_time)
    # decimate: index of stored samples = every nsub-th fine sample
    idx = np.arange(0, n, nsub)
    def peak(x):
        out = np.empty(idx.size)
        for m_, i0 in enumerate(idx):
            seg = x[max(0, i0 - nsub + 1):i0 + 1]
            out[m_] = seg[np.argmax(np.abs(seg))]
        return out
    ts = t[idx]
    Ys = Y[idx]
    ones = np.ones(idx.size)
    data = {
        "outer_race_speed": w_o[idx],
        "cage_speed": Ys[:, 9],
        "cage_angle": Ys[:, 3],
        "ball_orbit_speed": Ys[:, 12 + Z:12 + 2 * Z],
        "ball_spin_speed": np.abs(Ys[:, 12 + 2 * Z:12 + 3 * Z] - Ys[:, 12 + Z:12 + 2 * Z]),  # |spin - orbit|
        "cage_center_y": Ys[:, 1],
        "cage_center_z": Ys[:, 2],
        "ball_cage_contact_force": diag[idx, :, 0],
        "friction_moment_total": peak(M),
        "friction_moment_viscous": st.M_L * ones,
        "friction_moment_hysteresis": st.M_E * ones,
        "friction_moment_differential": st.M_D * ones,
        "friction_moment_pivoting": st.M_S * ones,
        "friction_moment_cage": peak(M_C),
        "rfmc": st.rfmc,
        "sfmc": sfmc,
    }
    if op.mode == "oscillation":
        data["sfmo"] = sfmo
        data["window_max_moment"] = maxima
    coords = {"time": ts, "ball": np.arange(Z)}
    if op.mode == "oscillation":
        coords["window"] = np.arange(maxima.size)
    extra = dict(
        model="gyro_ribbon_cage",
        contact_angle_deg=math.degrees(st.beta), ball_load_N=st.Q,
        cage_mass_kg=model.cage_mass, ball_cage_stiffness=model.p[_P_K],
        hunt_crossley_chi=model.p[_P_CHI], creep_speed=model.p[_P_VREG_R], cage_slip_speed=model.p[_P_VREG_C],
        prl_inner=list(st.X_i), prl_outer=list(st.X_o), fine_interval=float(t[1] - t[0]) if n > 1 else 0.0,
        pocket_clearance_m=float(case.cage.pocket_depth - 0.5 * case.bearing.ball_diameter),
        oscillation_period=float(op.oscillation_period),
        cage_gravity=float(model.p[_P_G]), cage_gravity_direction=[float(x) for x in model.p[[_P_GX, _P_GY, _P_GZ]]],
    )
    attrs = standard_attrs(case, res.status, **extra)
    attrs.update(solver_attrs(res.stats))
    return make_dataset(data, coords, attrs)


# ==============================================================================================
# 5. Parameter studies and figures
# ==============================================================================================


def override(case, **overrides):
    """``case`` with further ``table.key=value`` overrides, keeping the ones already applied.

    (``Case.with_overrides`` restarts from the file text, dropping earlier overrides.)
    """
    from hsbearing.case import loads_case

    return loads_case(case.to_toml(), case.source, **overrides)


def start_offsets(n: int) -> np.ndarray:
    """The ``n`` initial cage turns of the start ensemble as fractions of the play [-]: uniform over
    -1/2..+1/2 (``n`` = 1: [0]).  Written as (2 i - (n - 1)) / (2 (n - 1)) so that an odd ``n`` gives
    exactly 0.0 in the middle (the default start) and n = 5 gives exactly -0.5, -0.25, 0, 0.25, 0.5."""
    n = int(n)
    if n < 1:
        raise ValueError(f"start_offsets: n must be >= 1, got {n}")
    if n == 1:
        return np.zeros(1)
    return np.array([(2 * i - (n - 1)) / (2 * (n - 1)) for i in range(n)], dtype=float)


def _ensemble_sfmc(case, offsets, duration: float | None = None, *, cage_angle: float = 0.0,
                   reuse_zero: float | None = None, **kw):
    """Yield the SFMC [N m] of a constant-rate start for each offset (fraction of the play); see start_ensemble.
    ``reuse_zero``: the SFMC of the offset-0 start when it is already known (yielded without a run)."""
    play = circumferential_play_angle(case.bearing.ball_diameter, case.cage.pocket_diameter, case.cage.pocket_depth,
                                      case.bearing.pitch_diameter)
    T = duration if duration is not None else case.operating.oscillation_period
    # a constant-rate case is used as it is, so that offset 0 is bit for bit the plain start of that case
    c = case if case.operating.mode == "constant" else override(case, **{"operating.mode": "constant"})
    n = len(offsets)
    for k, f in enumerate(offsets, 1):  # each progress bar says which start it is
        if f == 0.0 and reuse_zero is not None:
            yield reuse_zero
            continue
        yield float(_simulate_one(c, duration=T, cage_angle=cage_angle + f * play,
                                  progress_desc=f"gyro start {k}/{n} (offset {f:+g})", **kw)["sfmc"])


def start_ensemble(case, n: int = 5, duration: float | None = None, **kw):
    """SFMC of ``n`` starts from rest with the cage turned by fractions of its circumferential play [N m].

    A bouncing cage is chaotic: the first impacts depend on where the cage sits in its pockets when
    the race starts.  The offsets are :func:`start_offsets` (n), uniform over -1/2 .. +1/2 of the
    circumferential play (:func:`circumferential_play_angle`); each start is a constant-rate run of
    ``duration`` (None: ``operating.oscillation_period``) from the settled, touching cage of the
    default start turned by that angle.  ``**kw`` go to :func:`simulate` (``cage_angle`` is added to
    each turn); ``simulation.start_positions`` of ``case`` is not used here.
    Returns the array of SFMC values, in the order of :func:`start_offsets`.
    """
    return np.array(list(_ensemble_sfmc(case, start_offsets(n), duration, **kw)))


def plot_run(ds, path) -> Path:
    """Figure of a gyro run (like [J] Figs. 7-9): speeds, M_C, the five sources and M; returns the PNG path.

    Drawn by :func:`hsbearing.systems.gyro.figures.plot_gyro`.
    """
    from hsbearing.systems.gyro.figures import plot_gyro

    return plot_gyro(ds, Path(path))
