"""High-speed quasi-static equilibrium of a ball bearing (Jones 1960, Harris & Kotzalas Vol. 2 Ch. 3).

Unknowns: the 5 inner-ring displacements q = (delta_x, delta_y, delta_z,
theta_y, theta_z) and, per ball, the position (X1, X2) of the ball centre
relative to the outer groove curvature centre.  The physics (contact
geometry, Hertz loads, centrifugal force, gyroscopic moment, race-control
kinematics) is in :mod:`hsbearing.models.ball_bearing.quasistatic`.

Numerics (nested, all vectorised over balls):

1. inner level -- for a given q every ball's 2x2 force balance is solved by a
   damped Newton iteration, all balls at once (forward-difference 2x2
   Jacobians, per-ball backtracking).  The starting point is the static,
   collinear placement of the ball on the line between the groove centres
   with the two deflections split so that Q_i = Q_o; without ball inertia
   this placement *is* the exact solution and nothing is iterated, so zero
   speed reproduces the static case exactly.  Balls that cannot touch both
   races and feel no centrifugal force stay on that line with zero loads (no
   NaN, no singular Jacobian); at speed they are seated on the outer race.
2. outer level -- the 5 ring equations are solved by a damped Newton method
   (:func:`hsbearing.solvers.newton.damped_newton`, generic)
   with the exact Jacobian of the nested problem (implicit-function theorem,
   central differences), with :func:`scipy.optimize.root` (Powell hybrid) as
   the fallback when Newton stalls; residual below 1e-10 of the applied load.
   The same Jacobian, negated, is the bearing stiffness matrix.
3. routes -- static problem from the rigid-ring estimate, a load-direction
   search or load continuation; at speed from the static solution, then
   speed continuation (:func:`solve`).  ``kinematics = "friction"`` adds
   passes choosing each ball's controlling race by Jones' criterion.

Speed sweeps continue from the previous solution (``initial=``).
"""

from __future__ import annotations

import functools
import math
import time
from dataclasses import dataclass, field, replace

import numpy as np
import xarray as xr
from scipy import optimize

from hsbearing.errors import CaseError, SolverError
from hsbearing.models import geometry as _geometry
from hsbearing.models import hertz
from hsbearing.models.ball_bearing import quasistatic as qp
from hsbearing.results import make_dataset, register, solver_attrs, standard_attrs
from hsbearing.solvers.newton import damped_newton

__all__ = [
    "Problem",
    "QuasiStaticSolution",
    "build_problem",
    "solve",
    "solve_case",
    "speed_sweep",
    "to_dataset",
    "print_summary",
    "DOF_LABELS",
]

DOF_LABELS = ("x", "y", "z", "theta_y", "theta_z")

# ----------------------------------------------------------------------------- output variables

for _n, _d, _u, _l in [
    ("ball_azimuth", ("ball",), "rad", "ball azimuth psi_j = 2 pi j / Z, from +Y towards +Z"),
    ("inner_contact_deflection", ("time", "ball"), "m", "normal elastic approach at the inner contact delta_i"),
    ("outer_contact_deflection", ("time", "ball"), "m", "normal elastic approach at the outer contact delta_o"),
    ("inner_contact_semimajor", ("time", "ball"), "m", "inner contact ellipse semi-major axis a_i (transverse to rolling)"),
    ("inner_contact_semiminor", ("time", "ball"), "m", "inner contact ellipse semi-minor axis b_i (rolling direction)"),
    ("outer_contact_semimajor", ("time", "ball"), "m", "outer contact ellipse semi-major axis a_o (transverse to rolling)"),
    ("outer_contact_semiminor", ("time", "ball"), "m", "outer contact ellipse semi-minor axis b_o (rolling direction)"),
    ("inner_contact_pressure", ("time", "ball"), "Pa", "maximum Hertz pressure at the inner contact p_max,i"),
    ("outer_contact_pressure", ("time", "ball"), "Pa", "maximum Hertz pressure at the outer contact p_max,o"),
    ("inner_film_thickness_central", ("time", "ball"), "m", "Hamrock-Dowson central film thickness at the inner contact h_c,i"),
    ("outer_film_thickness_central", ("time", "ball"), "m", "Hamrock-Dowson central film thickness at the outer contact h_c,o"),
    ("inner_spin_to_roll", ("time", "ball"), "1", "spin-to-roll ratio at the inner contact omega_s,i / omega_roll,i"),
    ("outer_spin_to_roll", ("time", "ball"), "1", "spin-to-roll ratio at the outer contact omega_s,o / omega_roll,o"),
    ("ball_pitch_angle", ("time", "ball"), "rad", "ball pitch angle beta: ball rotation axis (cage frame) from the bearing axis"),
    ("ball_angular_velocity_x", ("time", "ball"), "rad/s", "ball absolute angular velocity, component along the ball-frame x (axial) axis"),
    ("ball_angular_velocity_y", ("time", "ball"), "rad/s", "ball absolute angular velocity, component along the ball-frame y (radial outward) axis"),
    ("ball_angular_velocity_z", ("time", "ball"), "rad/s", "ball absolute angular velocity, component along the ball-frame z (circumferential) axis"),
    ("ball_center_axial", ("time", "ball"), "m", "ball-centre axial position from the plane of the unloaded ball centres"),
    ("ball_center_radial", ("time", "ball"), "m", "ball-centre distance from the bearing axis"),
    ("ball_centrifugal_force", ("time", "ball"), "N", "ball centrifugal force F_c = m R_b omega_m^2"),
    ("ball_outer_race_control", ("time", "ball"), "1",
     "controlling raceway used for the ball kinematics and the gyroscopic split: 1 outer, 0 inner"),
    ("ball_jones_outer_control", ("time", "ball"), "1",
     "Jones' raceway-control criterion Q_o a_o E_o cos(a_i - a_o) > Q_i a_i E_i at the solution: 1 outer, 0 inner"),
    ("ball_race_control_ratio", ("time", "ball"), "1",
     "margin of Jones' raceway-control criterion Q_o a_o E_o cos(a_i - a_o) / (Q_i a_i E_i): > 1 outer, < 1 inner"),
    ("ball_gyroscopic_moment", ("time", "ball"), "N*m",
     "gyroscopic moment M_g = dH/dt . e_t the contact friction supplies to the ball (magnitude J omega_R omega_m sin beta)"),
    ("inner_ring_radial_displacement_y", ("time",), "m", "inner-ring displacement along Y"),
    ("inner_ring_radial_displacement_z", ("time",), "m", "inner-ring displacement along Z"),
    ("inner_ring_tilt_y", ("time",), "rad", "inner-ring tilt (small rotation) about Y"),
    ("inner_ring_tilt_z", ("time",), "rad", "inner-ring tilt (small rotation) about Z"),
    ("stiffness", ("dof", "dof2"), "mixed",
     "bearing stiffness matrix -d(ball reaction on inner ring)/d(q), q = (x, y, z, theta_y, theta_z): "
     "N/m (force/translation), N/rad (force/tilt), N*m/m (moment/translation), N*m/rad (moment/tilt)"),
    ("residual_norm", (), "1", "ring equilibrium residual, max |R| relative to the applied load scale"),
    ("ball_residual_norm", (), "N", "largest ball force-balance residual"),
]:
    register(_n, _d, _u, _l)


# ----------------------------------------------------------------------------- problem definition


#: The floor of the load scale as a fraction of the unloaded bearing's force scale Z (m g + F_c): far below any
#: operating load (0.06 N for the 6207 at 5000 r/min, 0.3 N for zhang2016 at 14000 r/min, 5e-4 N for a
#: 6207 at rest), and where the direct routes still converge at once (measured: 5e-3 N on both at speed).
FORCE_FLOOR_FRACTION = 1e-3


@dataclass(frozen=True)
class Problem:
    """Everything the equilibrium needs, in SI (built by :func:`build_problem`)."""

    Z: int
    D: float
    dm: float
    fi: float
    fo: float
    alpha0: float
    psi: np.ndarray  #: ball azimuths [rad]
    ball_mass: float
    ball_inertia: float
    stiffness: qp.ContactStiffness
    loads: np.ndarray  #: applied (F_x, F_y, F_z, M_y, M_z) [N, N m]
    omega_i: float = 0.0  #: inner-ring speed [rad/s]
    omega_o: float = 0.0  #: outer-ring speed [rad/s]
    centrifugal: bool = True
    gyroscopic: bool = True
    control: str = "outer_race_control"
    E1: float = 208e9
    nu1: float = 0.3
    E2: float = 208e9
    nu2: float = 0.3
    aligned: bool = False  #: deep-groove layout (grooves in the mid-plane, clearance P_d)
    outer_mask: tuple | None = None  #: per-ball outer control (kinematics "friction"); None = all outer
    fixed_tilt: bool = False  #: hold theta_y = theta_z = 0 (moments become reactions)
    #: (lambda_i, lambda_o) for every ball instead of Harris' rule from the controlling race
    #: (comparison with other codes' readings, docs/quasistatic.md); None = Harris
    gyro_split: tuple | None = None

    @property
    def A(self) -> float:
        return (self.fi + self.fo - 1.0) * self.D

    @property
    def applied_scale(self) -> float:
        """The largest applied load [N] (moments / (d_m/2)); 0 for an unloaded bearing."""
        L = self.loads
        return float(max(abs(L[0]), math.hypot(L[1], L[2]), math.hypot(L[3], L[4]) / (0.5 * self.dm)))

    @property
    def force_floor(self) -> float:
        """1e-3 Z (m g + F_c) [N] (:data:`FORCE_FLOOR_FRACTION` of :func:`qp.unloaded_force_scale`): the absolute
        floor of the residual tolerances, and the load below which the solve comes down from the floor."""
        return FORCE_FLOOR_FRACTION * qp.unloaded_force_scale(self.Z, self.ball_mass, self.D, self.dm, self.alpha0,
                                                              self.omega_i, self.omega_o,
                                                              self.centrifugal and self.moving)

    @property
    def load_scale(self) -> float:
        """Force scale [N] of the residual tolerances: the largest applied load (moments / (d_m/2)), at least
        the unloaded bearing's own force scale :attr:`force_floor` (a relative tolerance on a vanishing load
        has no answer; the ball weight the model neglects and the round-off of the centrifugal forces bound
        what a residual can mean)."""
        return max(self.applied_scale, self.force_floor)

    @property
    def A1_0(self) -> float:
        """Axial offset of the groove curvature centres at zero displacement [m]."""
        return 0.0 if self.aligned else self.A * math.sin(self.alpha0)

    @property
    def layout(self):
        return qp.groove_centre_layout(self.D, self.dm, self.fi, self.fo, self.alpha0, self.aligned)

    @property
    def outer_control(self) -> np.ndarray:
        """Per-ball controlling race (True = outer) for the kinematics and the lambda split."""
        if self.control == "friction":
            return np.ones(self.Z, bool) if self.outer_mask is None else np.asarray(self.outer_mask, bool)
        return np.full(self.Z, self.control == "outer_race_control")

    @property
    def moving(self) -> bool:
        return self.omega_i != 0.0 or self.omega_o != 0.0


@functools.lru_cache(maxsize=64)
def _contact_stiffness(D, dm, fi, fo, E1, nu1, E2, nu2) -> qp.ContactStiffness:
    """The K(alpha) table of a bearing, built once per geometry and materials (speed sweeps, studies)."""
    return qp.ContactStiffness.build(D, dm, fi, fo, E1, nu1, E2, nu2)


def build_problem(case, *, inner_speed=None, centrifugal=True, gyroscopic=True, control=None,
                  fixed_tilt=False) -> Problem:
    """A :class:`Problem` from a case (``inner_speed`` [rad/s] overrides ``[operating] inner_speed``).

    Deep-groove cases use the aligned-groove layout with the diametral
    clearance; angular-contact cases the layout at the free contact angle.
    ``fixed_tilt=True`` holds the ring tilts at zero (3 DOF; the moments the
    balls apply are then reactions, reported in the residual).
    """
    if case.system not in ("angular_contact", "deep_groove", "gyro_ribbon_cage"):
        raise CaseError(case.source, "case.system",
                        f"the quasi-static model covers angular_contact, deep_groove and gyro_ribbon_cage bearings, "
                        f"not {case.system!r}")
    g = _geometry.derive(case)
    b, r = case.materials.ball, case.materials.races
    control = control or case.simulation.kinematics
    if control not in ("outer_race_control", "inner_race_control", "friction"):
        raise CaseError(case.source, "simulation.kinematics",
                        f"unknown kinematics {control!r} (outer_race_control, inner_race_control, friction)")
    stiff = _contact_stiffness(g.D, g.dm, g.fi, g.fo, b.elastic_modulus, b.poisson_ratio,
                               r.elastic_modulus, r.poisson_ratio)
    op = case.operating
    loads = np.array([op.axial_load, op.radial_load, op.radial_load_z, op.moment_y, op.moment_z], dtype=float)
    wi = op.inner_speed if inner_speed is None else float(inner_speed)
    return Problem(
        Z=g.Z, D=g.D, dm=g.dm, fi=g.fi, fo=g.fo, alpha0=g.alpha0,
        psi=2.0 * np.pi * np.arange(g.Z) / g.Z,
        ball_mass=g.ball_mass, ball_inertia=g.ball_inertia, stiffness=stiff, loads=loads,
        omega_i=float(wi), omega_o=float(op.outer_speed), centrifugal=bool(centrifugal), gyroscopic=bool(gyroscopic),
        control=control,
        E1=b.elastic_modulus, nu1=b.poisson_ratio, E2=r.elastic_modulus, nu2=r.poisson_ratio,
        aligned=(case.system == "deep_groove"), fixed_tilt=bool(fixed_tilt),
    )


# ----------------------------------------------------------------------------- ball level


def _ball_state(P: Problem, X1, X2, q, free=None):
    """All per-ball quantities for ball-centre positions (X1, X2) and ring displacement q."""
    A1, A2 = qp.groove_centre_separation(q, P.psi, P.D, P.dm, P.fi, P.fo, P.alpha0, P.aligned)
    di, do, si, ci, so, co, Li, Lo = qp.contact_geometry(X1, X2, A1, A2, P.D, P.fi, P.fo)
    Ki, Ko = P.stiffness.K(ci, co)
    Qi = qp.hertz_load(Ki, di)
    Qo = qp.hertz_load(Ko, do)
    _, _, x_o0, R_o = P.layout
    R_b = R_o + X2
    if P.moving:
        wm, wx, wy = qp.race_control_kinematics(P.omega_i, P.omega_o, R_b, P.D, si, ci, so, co, P.outer_control)
    else:
        wm = wx = wy = np.zeros_like(X1)
    Fc = qp.centrifugal_force(P.ball_mass, R_b, wm) if P.centrifugal else np.zeros_like(X1)
    Mg = qp.gyroscopic_moment(P.ball_inertia, wm, wy) if P.gyroscopic else np.zeros_like(X1)
    lam_i, lam_o = _split(P)
    Fi, Fo = qp.gyroscopic_friction(Mg, P.D, lam_i, lam_o)
    if free is not None and np.any(free):
        Fi = np.where(free, 0.0, Fi)
        Fo = np.where(free, 0.0, Fo)
    r_ax, r_rad = qp.ball_equilibrium_residual(Qi, Qo, si, ci, so, co, Fc, Fi, Fo)
    return dict(A1=A1, A2=A2, di=di, do=do, si=si, ci=ci, so=so, co=co, Qi=Qi, Qo=Qo, Ki=Ki, Ko=Ko,
                R_b=R_b, x_b=x_o0 + X1, wm=wm, wx=wx, wy=wy, Fc=Fc, Mg=Mg, Fi=Fi, Fo=Fo,
                res=np.stack([r_ax, r_rad]))


def _split(P: Problem):
    """(lambda_i, lambda_o) per ball: Harris' rule from the controlling race, or the override ``P.gyro_split``."""
    if P.gyro_split is None:
        return qp.gyroscopic_split(P.outer_control)
    return np.full(P.Z, float(P.gyro_split[0])), np.full(P.Z, float(P.gyro_split[1]))


def _ring_contributions(P: Problem, st, q):
    """Per-ball force/moment on the inner ring, shape (5, Z) (see :func:`qp.inner_ring_reaction`)."""
    x_i0, R_i, _, _ = P.layout
    return qp.inner_ring_reaction(st["Qi"], st["Fi"], st["si"], st["ci"], P.psi, x_i0, R_i, P.fi * P.D)


def _line_placement(P: Problem, q):
    """Starting ball placement and the 'free' mask.

    The ball lies on the line joining the groove curvature centres.  If the
    total approach delta_n = L - A is positive it is split so that
    K_i delta_i^1.5 = K_o delta_o^1.5 (the exact static solution).  A ball that
    cannot touch both races is 'free' when it feels no centrifugal force
    (zero loads, left on the line); otherwise it is seated on the outer race
    with the deflection of an estimated centrifugal force (cage speed of
    Harris Vol. 1 Eq. 8.21), from where the Newton iteration starts.
    """
    A1, A2 = qp.groove_centre_separation(q, P.psi, P.D, P.dm, P.fi, P.fo, P.alpha0, P.aligned)
    L = np.hypot(A1, A2)
    c = A2 / L
    Ki, Ko = P.stiffness.K(c, c)
    dn = L - P.A
    ratio = (Ko / Ki) ** (2.0 / 3.0)  # delta_i / delta_o for equal loads
    do = np.where(dn > 0, dn / (1.0 + ratio), 0.5 * dn)
    spinning = P.centrifugal and P.moving
    if spinning:
        g = P.D * np.cos(P.alpha0) / P.dm
        wc = 0.5 * (P.omega_i * (1.0 - g) + P.omega_o * (1.0 + g))  # Harris Vol. 1, Eq. 8.21
        Fc = qp.centrifugal_force(P.ball_mass, 0.5 * P.dm, wc)
        do_c = (Fc / Ko) ** (2.0 / 3.0)
        do = np.where(dn > 0, np.maximum(do, np.minimum(do_c, dn)), do_c)
    Lo = (P.fo - 0.5) * P.D + do
    X1, X2 = A1 / L * Lo, A2 / L * Lo
    free = (dn <= 0) & (not spinning)
    return X1, X2, free


def _solve_balls(P: Problem, q, X1, X2, tol, maxiter=60):
    """Damped Newton on every ball's 2x2 force balance (vectorised).  Returns X1, X2, state, free, iters."""
    Xl1, Xl2, free = _line_placement(P, q)
    inertia = P.moving and (P.centrifugal or P.gyroscopic)
    if X1 is None or not inertia:  # without ball inertia the collinear placement is exact
        X1, X2 = Xl1, Xl2
    X1 = np.where(free, Xl1, X1)
    X2 = np.where(free, Xl2, X2)
    h = 1e-7 * P.D
    st = _ball_state(P, X1, X2, q, free)
    if not inertia:  # exact static solution: nothing to iterate
        return X1, X2, st, free, 0
    # a ball touching neither race (zero Jacobian) restarts from the placement
    lost = (~free) & (st["Qi"] <= 0) & (st["Qo"] <= 0)
    if np.any(lost):
        X1 = np.where(lost, Xl1, X1)
        X2 = np.where(lost, Xl2, X2)
        st = _ball_state(P, X1, X2, q, free)
    res = np.where(free, 0.0, st["res"])
    nrm = np.max(np.abs(res), axis=0)
    # per-ball tolerance: absolute, or round-off level of the ball's own forces
    tol = tol + 1e-13 * (st["Qi"] + st["Qo"] + np.abs(st["Fc"]))
    it = 0
    step_cap = 0.05 * P.D
    while np.any(nrm > tol) and it < maxiter:
        it += 1
        act = nrm > tol
        J = np.empty((P.Z, 2, 2))
        for k in range(2):  # forward differences: the Newton step only needs a few digits
            dX1 = h if k == 0 else 0.0
            dX2 = h if k == 1 else 0.0
            rp = np.where(free, 0.0, _ball_state(P, X1 + dX1, X2 + dX2, q, free)["res"])
            J[:, :, k] = ((rp - res) / h).T
        det = J[:, 0, 0] * J[:, 1, 1] - J[:, 0, 1] * J[:, 1, 0]
        ok = act & (np.abs(det) > 0)
        safe_det = np.where(ok, det, 1.0)
        s1 = -(J[:, 1, 1] * res[0] - J[:, 0, 1] * res[1]) / safe_det
        s2 = -(-J[:, 1, 0] * res[0] + J[:, 0, 0] * res[1]) / safe_det
        s1 = np.where(ok, s1, 0.0)
        s2 = np.where(ok, s2, 0.0)
        sn = np.hypot(s1, s2)
        scale = np.minimum(1.0, step_cap / np.maximum(sn, 1e-300))
        s1, s2 = s1 * scale, s2 * scale
        # backtracking per ball: halve the step where the residual grows
        t = np.ones(P.Z)
        for _ in range(30):
            Y1, Y2 = X1 + t * s1, X2 + t * s2
            st_new = _ball_state(P, Y1, Y2, q, free)
            r_new = np.where(free, 0.0, st_new["res"])
            n_new = np.max(np.abs(r_new), axis=0)
            bad = ok & (n_new > nrm) & (n_new > tol)
            if not np.any(bad):
                break
            t = np.where(bad, 0.5 * t, t)
        X1, X2, st, res, nrm = Y1, Y2, st_new, r_new, n_new
        if not np.any(ok & (nrm > tol)):
            break
    return X1, X2, st, free, it


# ----------------------------------------------------------------------------- ring level


@dataclass
class QuasiStaticSolution:
    """Result of :func:`solve` (numpy arrays over balls, SI)."""

    problem: Problem
    q: np.ndarray  #: (delta_x, delta_y, delta_z, theta_y, theta_z)
    X1: np.ndarray
    X2: np.ndarray
    state: dict
    free: np.ndarray
    stiffness: np.ndarray  #: 5x5
    residual: np.ndarray  #: ring residual (5,) [N, N m]
    residual_norm: float  #: max |R| / load scale
    ball_residual_norm: float  #: [N]
    stats: dict = field(default_factory=dict)


class _Ring:
    """The 5-DOF ring problem with the balls solved inside (caches the last ball state)."""

    def __init__(self, P: Problem, X1=None, X2=None):
        self.P = P
        self.Fs = P.load_scale
        self.xs = np.array([1e-6, 1e-6, 1e-6, 1e-6 / (0.5 * P.dm), 1e-6 / (0.5 * P.dm)])  # variable scales
        self.rs = np.array([self.Fs, self.Fs, self.Fs, self.Fs * 0.5 * P.dm, self.Fs * 0.5 * P.dm])
        self.X1, self.X2 = X1, X2
        self.act = np.arange(3) if P.fixed_tilt else np.arange(5)  #: DOFs solved for
        self.ball_tol = 1e-13 * self.Fs
        self.nfev = 0
        self.njev = 0
        self.ball_iters = 0

    def balls(self, q):
        X1, X2, st, free, it = _solve_balls(self.P, q, self.X1, self.X2, self.ball_tol)
        self.ball_iters += it
        return X1, X2, st, free

    def residual(self, q, keep=True):
        X1, X2, st, free = self.balls(q)
        if keep:
            self.X1, self.X2 = X1, X2
        self.nfev += 1
        R = self.P.loads + _ring_contributions(self.P, st, q).sum(axis=1)
        return R, (X1, X2, st, free)

    def jacobian(self, q, X1, X2, free):
        """dR/dq of the nested problem (implicit-function theorem, central differences)."""
        self.njev += 1
        P = self.P
        h = 1e-7 * P.D
        hq = np.array([h, h, h, h / (0.5 * P.dm), h / (0.5 * P.dm)])
        # partials with respect to the ball positions
        dg_dX = np.empty((P.Z, 2, 2))
        dF_dX = np.empty((P.Z, 5, 2))
        for k in range(2):
            e1 = h if k == 0 else 0.0
            e2 = h if k == 1 else 0.0
            sp = _ball_state(P, X1 + e1, X2 + e2, q, free)
            sm = _ball_state(P, X1 - e1, X2 - e2, q, free)
            dg_dX[:, :, k] = ((sp["res"] - sm["res"]) / (2 * h)).T
            dF_dX[:, :, k] = ((_ring_contributions(P, sp, q) - _ring_contributions(P, sm, q)) / (2 * h)).T
        dg_dq = np.empty((P.Z, 2, 5))
        dF_dq = np.empty((5, 5))
        dFj_dq = np.empty((P.Z, 5, 5))
        for k in range(5):
            dq = np.zeros(5)
            dq[k] = hq[k]
            sp = _ball_state(P, X1, X2, q + dq, free)
            sm = _ball_state(P, X1, X2, q - dq, free)
            dg_dq[:, :, k] = ((sp["res"] - sm["res"]) / (2 * hq[k])).T
            dFj_dq[:, :, k] = ((_ring_contributions(P, sp, q + dq) - _ring_contributions(P, sm, q - dq)) / (2 * hq[k])).T
        dF_dq = dFj_dq.sum(axis=0)
        # dX/dq = -(dg/dX)^-1 dg/dq for the balls in equilibrium with loads; free balls do not move
        det = np.linalg.det(dg_dX)
        ok = (~free) & (np.abs(det) > 0)
        dX_dq = np.zeros((P.Z, 2, 5))
        if np.any(ok):
            dX_dq[ok] = -np.linalg.solve(dg_dX[ok], dg_dq[ok])
        return dF_dq + np.einsum("jab,jbc->ac", dF_dX, dX_dq)


def _initial_ring_guess(P: Problem) -> np.ndarray:
    """Static rigid-ring starting point: closed-form axial solution plus a Stribeck radial estimate."""
    Fa, Fy, Fz, My, Mz = P.loads
    A, a0 = P.A, P.alpha0
    q = np.zeros(5)
    if abs(Fa) > 0:
        a, Q = qp.axial_static_single_ball(abs(Fa), P.Z, P.D, P.dm, P.fi, P.fo, a0, P.stiffness)
        q[0] = math.copysign(A * math.cos(a0) * math.tan(a), Fa) - P.A1_0
        alpha = a
    else:
        q[0] = -P.A1_0  # grooves aligned: the ring centres itself axially
        alpha = 0.0
    Fr = math.hypot(Fy, Fz)
    if Fr > 0:
        Ki, Ko = P.stiffness.K(math.cos(alpha), math.cos(alpha))
        Kn = (Ki ** (-2 / 3) + Ko ** (-2 / 3)) ** -1.5
        Qmax = 5.0 * Fr / (P.Z * max(math.cos(alpha), 0.3))  # Stribeck
        dr = (Qmax / Kn) ** (2 / 3) / max(math.cos(alpha), 0.3)
        if abs(Fa) == 0:
            dr += A * (1 - math.cos(a0))
        q[1], q[2] = dr * Fy / Fr, dr * Fz / Fr
    Mr = math.hypot(My, Mz)
    if Mr > 0:
        Ki, Ko = P.stiffness.K(math.cos(alpha), math.cos(alpha))
        Kn = (Ki ** (-2 / 3) + Ko ** (-2 / 3)) ** -1.5
        R = 0.5 * P.dm
        Qmax = 4.0 * Mr / (P.Z * R * max(math.sin(alpha), 0.3))
        th = (Qmax / Kn) ** (2 / 3) / R
        q[3], q[4] = th * My / Mr, th * Mz / Mr
    return q


def _newton_ring(ring: _Ring, q, tol, maxiter=30):
    """Damped Newton on the ring equations (scaled; :func:`hsbearing.solvers.newton.damped_newton`): returns q
    and the last residual.  The ball positions of a rejected line-search trial are restored, so the next
    trial starts its ball solve from the last accepted ones.
    """

    def save():
        return ring.X1, ring.X2

    def restore(saved):
        ring.X1, ring.X2 = saved

    return damped_newton(ring.residual, lambda x, pack: ring.jacobian(x, pack[0], pack[1], pack[3]), q, tol,
                         active=ring.act, xscale=ring.xs, rscale=ring.rs, maxiter=maxiter, save=save, restore=restore)


def solve(P: Problem, *, initial=None, tol=1e-10, maxfev=200) -> QuasiStaticSolution:
    """Solve the quasi-static equilibrium of problem ``P`` (see :func:`_solve_fixed_control`).

    With ``kinematics = "friction"`` the controlling raceway of every ball is
    chosen by Jones' criterion (:func:`qp.race_control_criterion`): start
    with outer control, re-solve with the controls the criterion gives at the
    solution, until they no longer change (at most 6 passes; a ball that
    keeps flipping keeps its last control and the attribute
    ``race_control_converged`` is 0).
    """
    if P.control != "friction":
        return _solve_fixed_control(P, initial=initial, tol=tol, maxfev=maxfev)
    mask = P.outer_control if P.outer_mask is None else np.asarray(P.outer_mask, bool)
    sol, seen = initial, []
    for it in range(6):
        Pk = replace(P, outer_mask=tuple(bool(x) for x in mask))
        sol = _solve_fixed_control(Pk, initial=sol, tol=tol, maxfev=maxfev)
        new = _jones_mask(sol)
        seen.append(tuple(mask))
        if np.array_equal(new, mask):
            sol.stats["race_control_passes"] = it + 1
            sol.stats["race_control_converged"] = 1
            return sol
        mask = new
        if tuple(mask) in seen:  # cycling between two control patterns
            break
    sol.stats["race_control_passes"] = len(seen)
    sol.stats["race_control_converged"] = 0
    return sol


def _jones_mask(sol) -> np.ndarray:
    """Jones' criterion evaluated at a solution (True = outer control)."""
    P, st = sol.problem, sol.state
    Rxi, Ryi, Rxo, Ryo = _contact_radii(P, st)
    hi = hertz.point_contact(Rxi, Ryi, st["Qi"], P.E1, P.nu1, P.E2, P.nu2)
    ho = hertz.point_contact(Rxo, Ryo, st["Qo"], P.E1, P.nu1, P.E2, P.nu2)
    return qp.race_control_criterion(st["Qi"], hi.a, hi.second_kind, st["Qo"], ho.a, ho.second_kind,
                                     np.arctan2(st["si"], st["ci"]), np.arctan2(st["so"], st["co"]))


def _solve_fixed_control(P: Problem, *, initial=None, tol=1e-10, maxfev=200) -> QuasiStaticSolution:
    """Solve the quasi-static equilibrium of problem ``P``.

    initial : a :class:`QuasiStaticSolution` or a Dataset written by
        :func:`to_dataset` to continue from (speed sweeps).  Without it (or
        if it fails) the default route: the static problem first (rigid-ring
        estimate; then a search along the load direction; then load
        continuation), and for a moving bearing the high-speed problem from
        the static solution (then speed continuation).
    tol : ring residual tolerance relative to the load scale.

    Raises :class:`SolverError` naming the residual (with the partial result)
    when every route fails.
    """
    t0 = time.perf_counter()
    stats = {"ring_evaluations": 0, "jacobian_evaluations": 0, "continuation_steps": 0, "start": ""}
    q0, X1, X2 = _unpack_initial(P, initial)
    sol, err = None, None
    if q0 is not None:
        try:
            sol = _solve_from(P, q0, X1, X2, tol, maxfev, stats)
            stats["start"] = "initial"
        except SolverError as exc:
            err = exc
    if sol is None:
        try:
            sol = _solve_default(P, tol, maxfev, stats)
        except SolverError as exc:
            raise exc if err is None or exc.partial is not None else err  # noqa: B904 - the earlier failure, as it was
    sol.problem = P
    sol.stats.update(stats)
    sol.stats["wall_time_s"] = time.perf_counter() - t0
    return sol


def _solve_default(P: Problem, tol, maxfev, stats) -> QuasiStaticSolution:
    applied, floor = P.applied_scale, P.force_floor
    if 0.0 < applied < floor:
        # A load below the bearing's own force scale: the contacts it loads are barely closed (Hertz
        # stiffness ~ Q^(1/3) -> 0), where Newton from the unloaded side has no slope.  Solve the same load
        # direction at the force floor (well conditioned), then come down to the load in steps of 10 from
        # the loaded side (each a few Newton steps: the Hertz law's step shrinks the approach and never opens
        # the contact).  Below 1e-3 of the absolute tolerance (tol x force floor) the state no longer
        # changes within that tolerance: the unloaded limit (the ring at the end of its play in the load
        # direction), which is then the answer at the load itself.
        try:
            sol = _solve_default(replace(P, loads=P.loads * (floor / applied)), tol, maxfev, stats)
            F = floor
            while F > applied and F > 1e-3 * tol * floor:
                F = max(0.1 * F, applied)
                sol = _solve_from(replace(P, loads=P.loads * (F / applied)), sol.q, sol.X1, sol.X2, tol, maxfev,
                                  stats)
                stats["continuation_steps"] += 1
            sol = _solve_from(P, sol.q, sol.X1, sol.X2, tol, maxfev, stats)
            stats["start"] += " > load continuation below the force floor"
            return sol
        except SolverError:
            pass
    inertia = P.moving and (P.centrifugal or P.gyroscopic)
    static_P = replace(P, centrifugal=False, gyroscopic=False) if inertia else P
    static = _solve_static(static_P, tol, maxfev, stats)
    if not inertia:
        return static
    try:
        sol = _solve_from(P, static.q, static.X1, static.X2, tol, maxfev, stats)
        stats["start"] += " > speed"
        return sol
    except SolverError:
        pass
    q, X1, X2 = static.q, static.X1, static.X2
    for f in np.linspace(0.125, 1.0, 8):  # continuation in speed from the static state
        sol = _solve_from(replace(P, omega_i=P.omega_i * f, omega_o=P.omega_o * f), q, X1, X2, tol, maxfev, stats)
        q, X1, X2 = sol.q, sol.X1, sol.X2
        stats["continuation_steps"] += 1
    stats["start"] += " > speed continuation"
    return sol


def _solve_static(P: Problem, tol, maxfev, stats) -> QuasiStaticSolution:
    """Static problem: rigid-ring estimate, then load-direction search, then load continuation."""
    try:
        sol = _solve_from(P, _initial_ring_guess(P), None, None, tol, maxfev, stats)
        stats["start"] = "rigid-ring estimate"
        return sol
    except SolverError as exc:
        first = exc
    qd = _load_direction_guess(P)
    try:
        sol = _solve_from(P, qd, None, None, tol, maxfev, stats)
        stats["start"] = "load-direction search"
        return sol
    except SolverError:
        pass
    q, X1, X2 = qd, None, None
    try:
        for f in np.linspace(0.125, 1.0, 8):  # load continuation
            sol = _solve_from(replace(P, loads=P.loads * f), q, X1, X2, tol, maxfev, stats)
            q, X1, X2 = sol.q, sol.X1, sol.X2
            stats["continuation_steps"] += 1
    except SolverError:
        raise first from None
    stats["start"] = "load continuation"
    return sol


def _load_direction_guess(P: Problem) -> np.ndarray:
    """Ring position along the generalised load direction where the ball reaction balances the load.

    q(s) = q_b + s d with d = (F_x, F_y, F_z, M_y/R^2, M_z/R^2) / |.| (R = d_m/2, so that a
    tilt moves the groove centres like a translation), q_b the axial centring;
    bisection on s of d . W (F + reaction(q(s))) = 0 (W weights moments by 1/R).  Brings a
    ring that starts without any contact (clearance) into the loaded state.
    """
    R = 0.5 * P.dm
    Fx, Fy, Fz, My, Mz = P.loads
    d = np.array([Fx, Fy, Fz, My / R**2, Mz / R**2])
    trans = np.hypot(np.hypot(d[0], d[1]), d[2])
    norm = math.hypot(trans, R * math.hypot(d[3], d[4]))
    if norm == 0:
        return _initial_ring_guess(P)
    d = d / norm
    qb = np.zeros(5)
    qb[0] = -P.A1_0 if Fx == 0 else 0.0
    W = np.array([1.0, 1.0, 1.0, 1.0 / R, 1.0 / R])

    def g(sv):
        q = qb + sv * d
        X1, X2, st, free, _ = _solve_balls(P, q, None, None, 1e-13 * P.load_scale)
        R_ = P.loads + _ring_contributions(P, st, q).sum(axis=1)
        return float(np.dot(d * W, R_))

    lo, hi = 0.0, 1e-7
    while g(hi) > 0 and hi < 0.5 * P.D:
        lo, hi = hi, 2.0 * hi
    for _ in range(60):
        mid = 0.5 * (lo + hi)
        if g(mid) > 0:
            lo = mid
        else:
            hi = mid
    return qb + hi * d


def _solve_from(P, q0, X1, X2, tol, maxfev, stats):
    ring = _Ring(P, X1, X2)
    a = ring.act
    q0 = np.array(q0, dtype=float)
    if P.fixed_tilt:
        q0[3:] = 0.0
    scale = ring.xs[a]

    def full(z):
        q = q0.copy()
        q[a] = z * scale
        return q

    def fun(z):
        R, _ = ring.residual(full(z))
        return R[a] / ring.rs[a]

    def jac(z):
        q = full(z)
        X1, X2, st, free = ring.balls(q)
        return ring.jacobian(q, X1, X2, free)[np.ix_(a, a)] * scale[None, :] / ring.rs[a][:, None]

    # damped Newton with the implicit-function Jacobian first (cheap when the start is good),
    # Powell's hybrid method from the better of the two points if that stalls
    R0, _ = ring.residual(q0)
    r0 = np.max(np.abs(R0[a] / ring.rs[a]))
    q = q0
    if r0 > tol:
        X1s, X2s = ring.X1, ring.X2
        qn, Rn = _newton_ring(ring, q0, tol)
        rn_ = np.max(np.abs(Rn[a] / ring.rs[a])) if np.all(np.isfinite(Rn)) else np.inf
        q = qn if rn_ < r0 else q0
        if rn_ > tol:
            if not rn_ < r0:
                ring.X1, ring.X2 = X1s, X2s
            with np.errstate(all="ignore"):
                res = optimize.root(fun, q[a] / scale, jac=jac, method="hybr", options={"maxfev": maxfev, "xtol": 1e-14})
            if np.all(np.isfinite(res.x)):
                q = full(res.x)
            q, _ = _newton_ring(ring, q, tol)
    R, (X1, X2, st, free) = ring.residual(q)
    rn = float(np.max(np.abs(R[a] / ring.rs[a])))
    J = ring.jacobian(q, X1, X2, free)
    stats["ring_evaluations"] += ring.nfev
    stats["jacobian_evaluations"] += ring.njev
    stats["ball_newton_iterations"] = stats.get("ball_newton_iterations", 0) + ring.ball_iters
    bres = float(np.max(np.abs(np.where(free, 0.0, st["res"])))) if P.Z else 0.0
    sol = QuasiStaticSolution(problem=P, q=q, X1=X1, X2=X2, state=st, free=free, stiffness=-J, residual=R,
                              residual_norm=rn, ball_residual_norm=bres, stats={})
    if not np.all(np.isfinite(R)) or rn > tol:
        ds = None
        try:
            ds = to_dataset(sol, status="failed")
        except Exception:  # pragma: no cover - the partial result is best effort
            pass
        hint = ""
        Fx, My, Mz = P.loads[0], P.loads[3], P.loads[4]
        if not P.aligned and (Fx <= 0 or math.hypot(My, Mz) > Fx * 0.5 * P.dm):
            hint = ("; an angular-contact bearing needs an axial load F_x > 0 in its contact direction, and a "
                    "tilting moment below about F_x d_m/2: this load may have no equilibrium")
        raise SolverError(
            f"quasi-static equilibrium did not converge: ring residual max|R|/F = {rn:.3e} "
            f"(tolerance {tol:.1e}; R = {np.array2string(R, precision=4)} [N, N m]){hint}", partial=ds)
    if not P.aligned and P.Z:
        # An angular-contact ring carries its contacts on the thrust side of the groove only: the other side
        # is a low shoulder / counterbore (Harris & Kotzalas Vol. 1, Ch. 1-2), so an equilibrium that loads a
        # contact at an angle of the opposite sign to the nominal one has the balls riding over that shoulder.
        # Newton can reach such a root (the groove model is symmetric); it is not an equilibrium of the bearing.
        sgn = 1.0 if P.alpha0 >= 0 else -1.0
        Q = np.concatenate([st["Qi"], st["Qo"]])
        a = np.concatenate([np.arctan2(st["si"], st["ci"]), np.arctan2(st["so"], st["co"])])
        loaded = Q > 1e-6 * max(float(np.max(Q)), 1e-12)
        worst = float(np.min(sgn * a[loaded])) if loaded.any() else 0.0
        if worst < 0.0:
            ds = None
            try:
                ds = to_dataset(sol, status="failed")
            except Exception:  # pragma: no cover - the partial result is best effort
                pass
            raise SolverError(
                f"no equilibrium on the thrust side of the grooves: the only solution found loads contacts at "
                f"{math.degrees(worst):.1f} deg, on the low-shoulder side of an angular-contact bearing; an "
                "angular-contact bearing needs an axial load F_x > 0 in its contact direction, and a tilting moment "
                "below about F_x d_m/2", partial=ds)
    return sol


def _unpack_initial(P: Problem, initial):
    if initial is None:
        return None, None, None
    if isinstance(initial, QuasiStaticSolution):
        if initial.problem.Z != P.Z:
            return None, None, None
        return initial.q.copy(), initial.X1.copy(), initial.X2.copy()
    if isinstance(initial, xr.Dataset):
        if initial.sizes.get("ball") != P.Z:
            return None, None, None
        q = np.array([float(initial[n]) for n in ("inner_ring_axial_displacement", "inner_ring_radial_displacement_y",
                                                   "inner_ring_radial_displacement_z", "inner_ring_tilt_y",
                                                   "inner_ring_tilt_z")])
        _, _, x_o0, R_o = P.layout
        X1 = initial["ball_center_axial"].values - x_o0
        X2 = initial["ball_center_radial"].values - R_o
        return q, X1, X2
    raise TypeError(f"initial must be a QuasiStaticSolution or an xarray Dataset, not {type(initial).__name__}")


# ----------------------------------------------------------------------------- outputs


def to_dataset(sol: QuasiStaticSolution, case=None, status: str = "ok") -> xr.Dataset:
    """The solution as a Dataset over ``ball`` with the names of docs/design.md."""
    P, st = sol.problem, sol.state
    Rxi, Ryi, Rxo, Ryo = _contact_radii(P, st)
    hi = hertz.point_contact(Rxi, Ryi, st["Qi"], P.E1, P.nu1, P.E2, P.nu2)
    ho = hertz.point_contact(Rxo, Ryo, st["Qo"], P.E1, P.nu1, P.E2, P.nu2)
    # spin-to-roll ratios are speed-independent under race control: use a nominal
    # inner-ring speed when the bearing stands still.
    if P.moving:
        wm, wx, wy = st["wm"], st["wx"], st["wy"]
        wi, wo = P.omega_i, P.omega_o
    else:
        wi, wo = 1.0, 0.0
        wm, wx, wy = qp.race_control_kinematics(wi, wo, st["R_b"], P.D, st["si"], st["ci"], st["so"], st["co"],
                                                P.outer_control)
    spin_i, roll_i, spin_o, roll_o = qp.contact_spin_roll(wx, wy, wm, wi, wo, st["si"], st["ci"], st["so"], st["co"])
    with np.errstate(invalid="ignore", divide="ignore"):
        sr_i = np.where(roll_i != 0, spin_i / roll_i, 0.0)
        sr_o = np.where(roll_o != 0, spin_o / roll_o, 0.0)
        beta_src = (st["wx"], st["wy"]) if P.moving else (wx, wy)
        beta = np.arctan2(-beta_src[1], beta_src[0])
    beta = np.where(beta > 0.5 * np.pi, beta - np.pi, np.where(beta < -0.5 * np.pi, beta + np.pi, beta))
    ratio = qp.race_control_ratio(st["Qi"], hi.a, hi.second_kind, st["Qo"], ho.a, ho.second_kind,
                                  np.arctan2(st["si"], st["ci"]), np.arctan2(st["so"], st["co"]))
    q = sol.q
    data = {
        "inner_contact_load": st["Qi"],
        "outer_contact_load": st["Qo"],
        "inner_contact_angle": np.arctan2(st["si"], st["ci"]),
        "outer_contact_angle": np.arctan2(st["so"], st["co"]),
        "inner_contact_deflection": st["di"],
        "outer_contact_deflection": st["do"],
        "inner_contact_semimajor": hi.a,
        "inner_contact_semiminor": hi.b,
        "outer_contact_semimajor": ho.a,
        "outer_contact_semiminor": ho.b,
        "inner_contact_pressure": hi.p_max,
        "outer_contact_pressure": ho.p_max,
        "inner_spin_to_roll": sr_i,
        "outer_spin_to_roll": sr_o,
        "ball_pitch_angle": beta,
        "ball_orbit_speed": st["wm"],
        "ball_spin_speed": np.hypot(st["wx"], st["wy"]),
        "ball_angular_velocity_x": st["wx"] + st["wm"],
        "ball_angular_velocity_y": st["wy"],
        "ball_angular_velocity_z": np.zeros(P.Z),
        "ball_center_axial": st["x_b"],
        "ball_center_radial": st["R_b"],
        "ball_centrifugal_force": st["Fc"],
        "ball_outer_race_control": P.outer_control.astype(np.int8),
        "ball_jones_outer_control": (ratio > 1.0).astype(np.int8),
        "ball_race_control_ratio": ratio,
        "ball_gyroscopic_moment": st["Mg"],
        "cage_speed": float(np.mean(st["wm"])),
        "cage_slip_ratio": _cage_slip(case, float(np.mean(st["wm"])), P.omega_i, P.omega_o),
        "inner_ring_axial_displacement": q[0],
        "inner_ring_radial_displacement_y": q[1],
        "inner_ring_radial_displacement_z": q[2],
        "inner_ring_tilt_y": q[3],
        "inner_ring_tilt_z": q[4],
        "stiffness": sol.stiffness,
        "residual_norm": sol.residual_norm,
        "ball_residual_norm": sol.ball_residual_norm,
    }
    if case is not None:
        hc = _film(case, P, st, Rxi, Ryi, Rxo, Ryo)
        if hc is not None:
            data["inner_film_thickness_central"], data["outer_film_thickness_central"] = hc
    attrs = dict(
        model="quasi-static Jones-Harris (hsbearing.systems.angular_contact.quasistatic)",
        kinematics=P.control,
        lambda_inner=float(_split(P)[0].mean()),
        lambda_outer=float(_split(P)[1].mean()),
        centrifugal=P.centrifugal, gyroscopic=P.gyroscopic,
        inner_speed=P.omega_i, outer_speed=P.omega_o,
        applied_loads=[float(x) for x in P.loads],
        unloaded_balls=int(np.sum((st["Qi"] <= 0) | (st["Qo"] <= 0))),
    )
    stats = dict(sol.stats)
    # the common solver_* names every archive carries (dynamic runs: CVODE steps, rhs and Jacobian evaluations)
    stats.update(method="quasi-static: scipy root on the ring equilibrium, Newton per ball",
                 steps=int(stats.get("ring_evaluations", 0)), rhs_evals=int(stats.get("ring_evaluations", 0)),
                 jac_evals=int(stats.get("jacobian_evaluations", 0)), wall_time=float(stats.get("wall_time_s", 0.0)))
    attrs.update(solver_attrs(stats))
    full = standard_attrs(case, status=status, **attrs) if case is not None else attrs | {"status": status}
    ds = make_dataset(data, coords={"ball": np.arange(P.Z), "dof": list(DOF_LABELS), "dof2": list(DOF_LABELS)},
                      attrs=full)
    ds = ds.assign_coords(ball_azimuth=("ball", P.psi, {"units": "rad", "long_name": "ball azimuth psi_j, from +Y towards +Z"}))
    return ds


def _contact_radii(P: Problem, st):
    """Rolling/transverse radii of each contact at its own contact angle (Harris Vol. 1 Eqs. 2.27-2.31)."""
    gi = P.D * st["ci"] / P.dm
    go = P.D * st["co"] / P.dm
    Rxi = 0.5 * P.D * (1.0 - gi)
    Rxo = 0.5 * P.D * (1.0 + go)
    Ryi = np.full(P.Z, P.fi * P.D / (2 * P.fi - 1))
    Ryo = np.full(P.Z, P.fo * P.D / (2 * P.fo - 1))
    return Rxi, Ryi, Rxo, Ryo


def _film(case, P, st, Rxi, Ryi, Rxo, Ryo):
    """Hamrock-Dowson isothermal central film thickness (h_c,i, h_c,o) [m], or None without oil data.

    Entrainment speed of a contact = surface speed of the race relative to
    the cage at the contact centre, where race-control kinematics impose
    pure rolling (ball and race surfaces move together):
    u_i = |omega_i - omega_m| (R_b - (D/2) cos a_i),
    u_o = |omega_o - omega_m| (R_b + (D/2) cos a_o), R_b = ball-centre orbit
    radius.  Unloaded or standing contacts get NaN.
    """
    from hsbearing.models import ehl

    props = _oil_properties(case)
    if props is None:
        return None
    eta, alpha_p = props
    ui = np.abs(P.omega_i - st["wm"]) * (st["R_b"] - 0.5 * P.D * st["ci"])
    uo = np.abs(P.omega_o - st["wm"]) * (st["R_b"] + 0.5 * P.D * st["co"])
    Ep = float(hertz.reduced_modulus(P.E1, P.nu1, P.E2, P.nu2))
    out = []
    for Q, u, Rx, Ry in ((st["Qi"], ui, Rxi, Ryi), (st["Qo"], uo, Rxo, Ryo)):
        ok = (Q > 0) & (u > 0)
        h = np.full(P.Z, np.nan)
        if np.any(ok):
            h[ok] = ehl.film_thickness(Q[ok], u[ok], Rx[ok], Ry[ok], Ep, eta, alpha_p)[0]
        out.append(h)
    return tuple(out)


def _oil_properties(case):
    """(eta [Pa s] at the case temperature, alpha [1/Pa]) via :func:`hsbearing.models.ehl.lubricant_parameters`."""
    from hsbearing.models import ehl

    try:
        lp = ehl.lubricant_parameters(case)
    except (KeyError, AttributeError):  # oil without data (e.g. a friction-only case)
        return None
    return lp["eta"], lp["alpha"]


def solve_case(case, *, inner_speed=None, centrifugal=True, gyroscopic=True, initial=None) -> xr.Dataset:
    """Quasi-static equilibrium of a case as a Dataset over ``ball`` (``hsbearing.quasi_static``).

    inner_speed : [rad/s], overrides ``[operating] inner_speed``.
    centrifugal, gyroscopic : switch the ball inertia effects (both off = static).
    initial : a previous Dataset / solution to continue from (speed sweeps).
    """
    P = build_problem(case, inner_speed=inner_speed, centrifugal=centrifugal, gyroscopic=gyroscopic)
    sol = solve(P, initial=initial)
    return to_dataset(sol, case)


def speed_sweep(case, speeds, **kwargs) -> xr.Dataset:
    """Solutions at successive inner-ring speeds [rad/s], each continuing from the previous one.

    Returns one Dataset with a leading ``inner_speed`` dimension.
    """
    out, prev = [], None
    P0 = build_problem(case, **kwargs)
    for w in np.asarray(speeds, dtype=float):
        sol = solve(replace(P0, omega_i=float(w)), initial=prev)
        prev = sol
        out.append(to_dataset(sol, case))
    ds = xr.concat(out, dim="inner_speed", data_vars="all", coords="minimal", compat="override", join="override")
    ds = ds.assign_coords(inner_speed=("inner_speed", np.asarray(speeds, dtype=float),
                                       {"units": "rad/s", "long_name": "inner-ring speed"}))
    return ds


def _cage_slip(case, cage_speed: float, omega_i: float, omega_o: float) -> float:
    """Cage slip ratio against the epicyclic speed at the nominal contact angle (hsbearing.analysis.slip);
    nan at standstill or without a case."""
    if case is None:
        return float("nan")
    from hsbearing.analysis.slip import cage_slip_ratio, theoretical_cage_speed
    from hsbearing.models.geometry import derive

    w_th = theoretical_cage_speed(derive(case), omega_i, omega_o)
    return float(cage_slip_ratio(cage_speed, w_th)) if w_th else float("nan")


def print_summary(ds: xr.Dataset) -> None:
    """Human-readable summary of a quasi-static Dataset (``hsbearing quasistatic``)."""
    deg, rpm = 180.0 / math.pi, 30.0 / math.pi
    print(f"status: {ds.attrs.get('status', '?')}")
    if "case_name" in ds.attrs:
        print(f"case: {ds.attrs['case_name']}  kinematics: {ds.attrs.get('kinematics', '?')}"
              f"  inner speed: {float(ds.attrs.get('inner_speed', 0.0)) * rpm:.6g} r/min"
              + (f"  outer speed: {float(ds.attrs['outer_speed']) * rpm:.6g} r/min" if ds.attrs.get("outer_speed") else ""))
    loads = ds.attrs.get("applied_loads")
    if loads is not None:
        print("applied loads: F_x, F_y, F_z [N], M_y, M_z [N m] = " + ", ".join(f"{x:.6g}" for x in np.ravel(loads)))
    def z(name, f):  # no "-0.00000" for round-off
        v = float(ds[name]) * f
        return 0.0 if abs(v) < 5e-6 else v

    print(f"inner ring: delta_x = {z('inner_ring_axial_displacement', 1e6):.5f} um, "
          f"delta_y = {z('inner_ring_radial_displacement_y', 1e6):.5f} um, "
          f"delta_z = {z('inner_ring_radial_displacement_z', 1e6):.5f} um, "
          f"theta_y = {z('inner_ring_tilt_y', 1e3):.5f} mrad, theta_z = {z('inner_ring_tilt_z', 1e3):.5f} mrad")
    print(f"cage speed: {float(ds.cage_speed) * rpm:.6g} r/min")
    print(f"{'ball':>4} {'psi':>7} {'Q_i/N':>10} {'Q_o/N':>10} {'a_i/deg':>8} {'a_o/deg':>8} "
          f"{'p_i/GPa':>8} {'p_o/GPa':>8} {'beta/deg':>8} {'wR/rpm':>9} {'s/r_i':>7} {'s/r_o':>7}")
    for j in range(ds.sizes["ball"]):
        s = ds.isel(ball=j)
        print(f"{j:>4d} {float(s.ball_azimuth) * deg:7.2f} {float(s.inner_contact_load):10.3f} "
              f"{float(s.outer_contact_load):10.3f} {float(s.inner_contact_angle) * deg:8.3f} "
              f"{float(s.outer_contact_angle) * deg:8.3f} {float(s.inner_contact_pressure) / 1e9:8.4f} "
              f"{float(s.outer_contact_pressure) / 1e9:8.4f} {float(s.ball_pitch_angle) * deg:8.3f} "
              f"{float(s.ball_spin_speed) * rpm:9.1f} {float(s.inner_spin_to_roll) + 0.0:7.4f} {float(s.outer_spin_to_roll) + 0.0:7.4f}")
    if "inner_film_thickness_central" in ds:
        def film(name):
            h = ds[name].values
            if not np.any(np.isfinite(h)):  # zero entrainment speed: no hydrodynamic film (Hamrock-Dowson h ~ U^0.67)
                return "n/a (no rolling speed: no EHL film)"
            return f"{np.nanmin(h) * 1e9:.1f}-{np.nanmax(h) * 1e9:.1f} nm"

        print(f"central film thickness: inner {film('inner_film_thickness_central')}, "
              f"outer {film('outer_film_thickness_central')}")
    K = ds.stiffness.values
    print(f"stiffness: K_xx = {K[0, 0]:.5g} N/m, K_yy = {K[1, 1]:.5g} N/m, K_zz = {K[2, 2]:.5g} N/m, "
          f"K_theta_y = {K[3, 3]:.5g} N*m/rad, K_theta_z = {K[4, 4]:.5g} N*m/rad")
    print(f"residual: ring {float(ds.residual_norm):.2e} (relative), balls {float(ds.ball_residual_norm):.2e} N")
    stats = {k[len('solver_'):]: v for k, v in ds.attrs.items()
             if k.startswith("solver_") and not k.endswith("_units")}  # the NAME_units companions are not stats
    if stats:
        print("solver: " + ", ".join(f"{k}={v:.4g}" if isinstance(v, float) else f"{k}={v}" for k, v in stats.items()))
