"""Gyroscope mini bearing with a ribbon cage under ultra-low-speed oscillation (seed 000).

Five friction-moment sources summed on the outer race ([J], Eq. 1)::

    M = M_L + sum_z [ (dM_Eo R_i + dM_Ei R_o)/D_w + (dM_Do R_i + dM_Di R_o)/D_w
                      + (dM_Si + dM_So)/2 sin(beta) + (F_mu + F_pbz) R_o / 2 ]

with the viscous moment M_L, elastic hysteresis dM_E, differential sliding
between the pure-rolling lines dM_D, pivoting dM_S ([J], Eq. 2) -- all from a
quasi-static thrust-load analysis -- and the ball/cage contact term dM_C,
which needs the ribbon-cage dynamics: ball/pocket contact states and Hertz
forces with friction ([J], Eqs. 7-13), the cage's 6-DOF Newton-Euler
equations ([J], Eqs. 14-16) and the balls' 2-DOF motion with start /
reversal acceleration and race slip ([J], Eqs. 17-21).  The state vector is
integrated by the CVODE BDF layer (:mod:`hsbearing.solvers.cvode`) instead of
the paper's hand-made variable step.

The decisions taken where the seed is ambiguous or damaged, and every
regularisation with its parameter, are listed in ``docs/validation/gyro.md``;
the short version is in the docstrings below (search for "decision").  The one
that matters most: the cage starts where its weight leaves it (resting on the
balls) and the dynamics run without the weight (``gravity=0``); with the
weight (across or along the axis, settled or centred start), pocket friction
carries our cage along and it is never struck at the reversals, which
contradicts the paper's Figs. 8-9 (:func:`cage_moment_windows` measures it),
and a centred start adds a free-fall impact of the cage at t = 3 ms.

References
----------
[J] Jiang S., Chen X., Gu J., Shen X., "Friction moment analysis of space
    gyroscope bearing with ribbon cage under ultra-low oscillatory motion",
    Chin. J. Aeronaut. 27(5) (2014) 1301-1311 (seed 000).
[H] Harris T. A., *Rolling Bearing Analysis*, 4th ed., Wiley 2001: Ch. 6
    (Hertz), Ch. 7 (thrust-loaded bearing, Eq. 7.xx: F_a = Z K_n (B D)^1.5
    sin(beta) (cos(beta_0)/cos(beta) - 1)^1.5), Ch. 10 ("Friction in rolling
    bearings": elastic hysteresis M = 3/16 alpha_r b Q, radius of the
    deformed surface R = 2 r D / (2 r + D), Palmgren viscous moment
    M_0 = 160e-7 f_0 d_m^3 [N mm] for nu n < 2000).
[Ht] Heathcote H. L., "The ball bearing: in the making, under test and on
    service", Proc. Inst. Automob. Eng. 15 (1921) 569-702 (pure-rolling lines
    at +/-0.347 a from the force balance of the strip model).
[HC] Hunt K. H., Crossley F. R. E., "Coefficient of restitution interpreted
    as damping in vibroimpact", J. Appl. Mech. 42 (1975) 440-445.
[M] Meeks C. R., Ng K. O., "The dynamics of ball separators in ball bearings
    -- part I: analysis", ASLE Trans. 28(3) (1985) 277-287 (race slip force
    mu Q s_dot / s_roll, [J] Eq. 19).
"""

from __future__ import annotations

import math
import time
from dataclasses import dataclass, field
from pathlib import Path

import numba
import numpy as np
from scipy.optimize import brentq

from hsbearing.case import CaseError
from hsbearing.errors import SolverError
from hsbearing.models.hertz import point_contact
from hsbearing.results import make_dataset, register, solver_attrs, standard_attrs

__all__ = [
    "viscous_moment",
    "hysteresis_moment",
    "pure_rolling_lines",
    "differential_sliding_moment",
    "differential_sliding_factor",
    "pivoting_moment",
    "deformed_surface_radius",
    "thrust_contact_angle",
    "spin_to_roll_ratios",
    "cage_contact_moment",
    "total_friction_moment",
    "StaticFriction",
    "static_friction",
    "ribbon_cage_mass_properties",
    "ball_cage_stiffness",
    "pocket_geometry",
    "pocket_penetration",
    "outer_race_speed",
    "transform_Ic",
    "euler_rate_matrix",
    "GyroModel",
    "build_model",
    "simulate",
    "starting_moments",
    "cage_moment_windows",
    "circumferential_play_angle",
    "start_offsets",
    "start_ensemble",
    "ensemble_lines",
    "summary",
    "study",
    "study_figures",
    "override",
    "plot_run",
]

GRAVITY = 9.80665  #: standard gravity [m/s^2]

# ----------------------------------------------------------------------------------------------
# output variables (declared once, here)
for _n, _d, _u, _l in [
    ("outer_race_speed", ("time",), "rad/s", "outer-race angular speed omega_o(t) (seed 000 operating profile)"),
    ("cage_angle", ("time",), "rad", "cage rotation angle about X (unwrapped)"),  # same declaration as hsbearing.dynamics
    ("friction_moment_total", ("time",), "N m",
     "total friction moment on the outer race M = M_L + M_E + M_D + M_S + max(M_C, 0) (seed 000 Eq. 1); peak-hold over each output interval"),
    ("friction_moment_viscous", ("time",), "N m", "viscous (lubricant drag) friction moment M_L (seed 000 Eq. 2)"),
    ("friction_moment_hysteresis", ("time",), "N m", "elastic-hysteresis friction moment M_E (seed 000 Eqs. 1-2)"),
    ("friction_moment_differential", ("time",), "N m", "differential-sliding friction moment M_D (seed 000 Eqs. 1-2)"),
    ("friction_moment_pivoting", ("time",), "N m", "pivoting (spin) friction moment M_S (seed 000 Eqs. 1-2)"),
    ("friction_moment_cage", ("time",), "N m",
     "ball/cage friction moment M_C = sum (F_mu + F_pbz) R_o/2, signed, driving positive (seed 000 Eq. 1); value of largest magnitude in each output interval"),
    ("ball_cage_contact_force", ("time", "ball"), "N", "ball/pocket normal contact force F_pbN (seed 000 Eq. 10), sum of the pocket's contact points"),
    ("sfmc", (), "N m", "starting friction moment at constant rate: max M after the start from rest (seed 000 Sec. 4)"),
    ("sfmo", (), "N m", "starting friction moment under oscillation: mean of the max M of each reversal window (seed 000 Sec. 4)"),
    ("rfmc", (), "N m", "running friction moment at constant rate M_E + M_D + M_S + M_L (seed 000 Sec. 5.1)"),
    ("window_max_moment", ("window",), "N m", "max total friction moment M in each oscillation window (seed 000 Sec. 4)"),
    ("window", ("window",), "1", "index of the oscillation window (0 = start from rest)"),
    # sweep summary of a gyro run (gyro.summary)
    ("sfmo_sd", (), "N m", "sample standard deviation (n - 1) of the reversal-window maxima of M (seed 000 Sec. 4)"),
    ("sfmo_stderr", (), "N m", "standard error of SFMO: sfmo_sd / sqrt(reversal_windows)"),
    ("reversal_windows", (), "1", "number of reversal windows averaged in SFMO"),
    ("pocket_clearance", (), "m", "ball/pocket clearance A = k - D_w/2 (seed 000 Sec. 3.2)"),
    ("cage_mass", (), "kg", "cage mass used by the model (ribbon strips of thickness s, or cage.mass)"),
    # start ensemble (simulation.start_positions > 1; gyro.start_ensemble)
    ("start_offset", ("start_offset",), "1",
     "initial turn of the cage about the axis as a fraction of its circumferential pocket play (-0.5..0.5; 0 = the default start)"),
    ("sfmc_ensemble", ("start_offset",), "N m",
     ("SFMC of each start of the start ensemble: max M in a constant-rate start of one oscillation_period from rest, "
      "cage turned by start_offset of its play (seed 000 Sec. 4)")),
    ("sfmc_ensemble_mean", (), "N m", "mean of sfmc_ensemble over the start offsets (SFMC averaged over the initial cage position)"),
    ("sfmc_ensemble_sd", (), "N m", "sample standard deviation (n - 1) of sfmc_ensemble over the start offsets"),
]:
    register(_n, _d, _u, _l)


# ==============================================================================================
# 1. Friction-moment sources (static analysis), [J] Eqs. 1-2
# ==============================================================================================


def viscous_moment(f0, dm, nu=None, n=None):
    """Viscous friction moment M_L [N m] (Palmgren; [J] Eq. 2, [H] Ch. 10).

    ``M_L = 160e-7 f0 dm^3`` with d_m in mm and M_L in N mm, valid for
    nu n < 2000 (nu [mm^2/s], n [r/min]); above that, ``1e-7 f0 (nu n)^(2/3)
    dm^3`` ([H]).  Ultra-low-speed gyro bearings always use the first branch.

    Parameters
    ----------
    f0 : lubrication factor [-] (decision: see ``docs/validation/gyro.md``).
    dm : pitch diameter [m].
    nu : kinematic viscosity [m^2/s], optional (only for the high-speed branch).
    n : speed [rad/s], optional.
    """
    dm_mm = np.asarray(dm, dtype=float) * 1e3
    low = 160e-7 * f0 * dm_mm**3  # [J], Eq. 2 (first line) [N mm]
    if nu is None or n is None:
        return low * 1e-3
    vn = (np.asarray(nu) * 1e6) * np.abs(np.asarray(n)) * 30.0 / math.pi  # mm^2/s * r/min
    high = 1e-7 * f0 * np.maximum(vn, 1e-300) ** (2.0 / 3.0) * dm_mm**3  # [H], Palmgren nu n >= 2000
    return np.where(vn < 2000.0, low, high) * 1e-3


def hysteresis_moment(Q, b, alpha_r):
    """Elastic-hysteresis rolling moment of one contact dM_E [N m] = 3/16 Q b alpha_r ([J], Eq. 2; [H] Ch. 10).

    Q normal load [N], b semi-axis in the rolling direction [m], alpha_r
    hysteresis loss fraction [-] (0.8 % in [J]).
    """
    return 3.0 / 16.0 * np.asarray(Q) * np.asarray(b) * alpha_r  # [J], Eq. 2 (second line)


def deformed_surface_radius(r_groove, D):
    """Radius of the deformed contact surface across the contact R_a [m] = 2 r D / (2 r + D) ([H] Ch. 10).

    Decision: [J] calls R_a "the Hertz contact radius"; the strip model of
    Eq. 2 needs the radius of the pressed surface across the contact, which
    is this harmonic mean of the groove radius r and the ball diameter D.
    """
    return 2.0 * r_groove * D / (2.0 * r_groove + D)


def _band_load(X1, X2):
    """Integral of (1 - Y^2) over [X1, X2] (strip load of the band between the PRLs, per 3Q/4)."""
    return (X2 - X1) - (X2**3 - X1**3) / 3.0


def pure_rolling_lines(shift=0.0):
    """Pure-rolling lines X1 < X2 (in units of a) from the strip force balance ([Ht]; [J] Ref. 20).

    The rolling-direction slip across the contact is a parabola
    v(y) ~ (y^2 - c^2)/(2 R_a) + (omega_s/omega_roll) y, so the two PRLs
    satisfy ``X1 + X2 = -shift`` with ``shift = 2 (R_a/a) omega_s/omega_roll``;
    the remaining unknown (the band half-width) follows from zero net
    rolling-direction friction force: the band [X1, X2] carries half of the
    strip load, i.e. ``integral (1 - Y^2) dY over [X1, X2] = 2/3``.  With
    ``shift = 0`` this gives Heathcote's +/-0.347 a.  If the band would leave
    the contact, it is clipped at the edge (-1 or +1) and only one PRL lies
    inside.

    Returns
    -------
    (X1, X2) : floats [-], -1 <= X1 < X2 <= 1.
    """
    s = float(shift)
    mid = -0.5 * s
    target = 2.0 / 3.0

    def f(h):
        lo, hi = max(mid - h, -1.0), min(mid + h, 1.0)
        return _band_load(lo, hi) - target

    h = brentq(f, 0.0, 2.0 + abs(mid), xtol=1e-14)
    return max(mid - h, -1.0), min(mid + h, 1.0)


def differential_sliding_factor(X1, X2, reading="physical"):
    """Bracket of dM_D in [J] Eq. 2 as a function of the PRLs [-].

    ``reading="physical"`` (used): strip model with arm y^2/(2 R_a), friction
    reversing between the PRLs::

        1/10 - (X2^3 - X1^3)/4 + 3 (X2^5 - X1^5)/20

    ``reading="seed"``: the transcript as printed,
    ``1/10 + (X2^2 - X1^2)/4 + (3 X1^5 - 3 X2^5)/20`` (mixed powers; with
    symmetric PRLs it does not depend on X2^2 at all).  ``reading="seed_cubes"``:
    the printed signs with cubes, which exceeds the bound 1/10 that no sign
    pattern can exceed and is therefore rejected.  See docs/validation/gyro.md.
    """
    if reading == "physical":
        return 0.1 - (X2**3 - X1**3) / 4.0 + 3.0 * (X2**5 - X1**5) / 20.0  # [J], Eq. 2 (third line), re-derived
    if reading == "seed":
        return 0.1 + (X2**2 - X1**2) / 4.0 + (3.0 * X1**5 - 3.0 * X2**5) / 20.0  # [J], Eq. 2 as transcribed
    if reading == "seed_cubes":
        return 0.1 + (X2**3 - X1**3) / 4.0 + (3.0 * X1**5 - 3.0 * X2**5) / 20.0
    raise ValueError(f"unknown reading {reading!r} (physical, seed, seed_cubes)")


def differential_sliding_moment(mu, Q, a, Ra, X1, X2, reading="physical"):
    """Differential-sliding (contact-geometry) moment of one contact dM_D [N m] ([J], Eq. 2).

    ``dM_D = mu Q a^2 / R_a * factor(X1, X2)``; mu friction coefficient [-],
    Q normal load [N], a semi-axis across the rolling direction [m], R_a radius
    of the deformed surface [m], X1, X2 pure-rolling lines [-].
    """
    return mu * np.asarray(Q) * np.asarray(a) ** 2 / Ra * differential_sliding_factor(X1, X2, reading)  # [J], Eq. 2


def pivoting_moment(mu, Q, a, X1, X2):
    """Pivoting (spin) moment of one contact dM_S [N m] ([J], Eq. 2).

    ``dM_S = 3 mu Q a / 8 [2 (X2^2 - X1^2) + X1^4 - X2^4]`` -- the moment
    about the contact normal of the rolling-direction strip forces, reversing
    at the PRLs (re-derived: it is exact for the strip model, and zero for
    symmetric PRLs).  Returned as a magnitude.
    """
    return np.abs(3.0 * mu * np.asarray(Q) * np.asarray(a) / 8.0
                  * (2.0 * (X2**2 - X1**2) + X1**4 - X2**4))  # [J], Eq. 2 (fourth line)


def thrust_contact_angle(Fa, Z, D, dm, fi, fo, E1, nu1, E2, nu2, beta0=0.0):
    """Operating contact angle [rad] and ball load [N] of a thrust-loaded ball bearing ([H] Ch. 7).

    Solves ``B D (cos(beta0)/cos(beta) - 1) = delta_i(Q) + delta_o(Q)`` with
    ``Q = Fa/(Z sin(beta))`` and exact Hertz deflections
    (:func:`hsbearing.models.hertz.point_contact`), i.e. Harris' relation
    F_a = Z K_n (B D)^1.5 sin(beta) (cos(beta0)/cos(beta) - 1)^1.5.
    Centrifugal and gyroscopic effects are negligible at a few r/min.
    """
    B = fi + fo - 1.0

    def resid(beta):
        Q = Fa / (Z * math.sin(beta))
        ci, co = _race_contacts(beta, Q, D, dm, fi, fo, E1, nu1, E2, nu2)
        return B * D * (math.cos(beta0) / math.cos(beta) - 1.0) - float(ci.deflection + co.deflection)

    beta = brentq(resid, max(beta0, 1e-6) + 1e-9, 1.3, xtol=1e-14)
    return beta, Fa / (Z * math.sin(beta))


def _race_contacts(beta, Q, D, dm, fi, fo, E1, nu1, E2, nu2):
    gamma = D * math.cos(beta) / dm
    Rx_i, Rx_o = 0.5 * D * (1.0 - gamma), 0.5 * D * (1.0 + gamma)  # [H] Ch. 2 curvature radii
    Ry_i, Ry_o = fi * D / (2.0 * fi - 1.0), fo * D / (2.0 * fo - 1.0)
    return (point_contact(Rx_i, Ry_i, Q, E1, nu1, E2, nu2), point_contact(Rx_o, Ry_o, Q, E1, nu1, E2, nu2))


def spin_to_roll_ratios(beta, gamma):
    """Spin-to-roll ratios (omega_s/omega_roll) at the inner and outer contacts [-].

    Decision: ball rotation axis tilted by the contact angle beta, as in the
    ball angular velocity of [J] (w_b = w_br [cos beta, ., sin beta]); the
    outer race turns, the inner race is fixed.  In the frame turning with the
    ball set the races turn at -omega_m (inner) and omega_o - omega_m (outer)
    and their normal components give the spin ([H] Ch. 8 kinematics):
    inner ``tan(beta) gamma/(1 - gamma)``, outer ``tan(beta) gamma/(1 + gamma)``
    with gamma = D cos(beta)/d_m.
    """
    return math.tan(beta) * gamma / (1.0 - gamma), math.tan(beta) * gamma / (1.0 + gamma)


def cage_contact_moment(F_pbz, F_N, mu, Ro):
    """Ball/cage term of Eq. 1 for one ball, dM_C [N m] = (F_mu + F_pbz) R_o / 2 with F_mu = mu F_N ([J], Eq. 1).

    F_pbz [N] is the orbit-direction component of the normal ball/cage force
    on the cage, counted positive when the ball drives the cage in the
    direction of the race rotation; F_N [N] the normal force magnitude.
    """
    return (mu * np.asarray(F_N) + np.asarray(F_pbz)) * Ro / 2.0  # [J], Eq. 1 (last term)


def total_friction_moment(Z, D, Ri, Ro, beta, dME_i, dME_o, dMD_i, dMD_o, dMS_i, dMS_o, M_L, M_C=0.0):
    """Total friction moment on the outer race M [N m], [J] Eq. 1 (identical balls under thrust).

    Returns (M, M_E, M_D, M_S); ``M = M_L + M_E + M_D + M_S + M_C``.
    """
    M_E = Z * (dME_o * Ri + dME_i * Ro) / D  # [J], Eq. 1
    M_D = Z * (dMD_o * Ri + dMD_i * Ro) / D  # [J], Eq. 1
    M_S = Z * (dMS_i + dMS_o) / 2.0 * math.sin(beta)  # [J], Eq. 1
    return M_L + M_E + M_D + M_S + M_C, M_E, M_D, M_S


@dataclass(frozen=True)
class StaticFriction:
    """Quasi-static thrust analysis and the four static friction moments (SI)."""

    beta: float  #: operating contact angle [rad]
    Q: float  #: ball/race normal load [N]
    a_i: float
    b_i: float
    a_o: float
    b_o: float
    Ra_i: float  #: deformed-surface radius, inner [m]
    Ra_o: float
    X_i: tuple  #: PRLs (X1, X2) inner [-]
    X_o: tuple
    Ri: float  #: radius to the inner contact [m]
    Ro: float  #: radius to the outer contact [m]
    M_L: float
    M_E: float
    M_D: float
    M_S: float

    @property
    def rfmc(self) -> float:
        """Running friction moment at constant rate [N m] ([J] Sec. 5.1)."""
        return self.M_L + self.M_E + self.M_D + self.M_S


def static_friction(case, *, md_reading: str = "physical", prl: str = "spin") -> StaticFriction:
    """M_L, M_E, M_D, M_S of a gyro case from the thrust-load quasi-static analysis ([J] Eqs. 1-2).

    ``prl="spin"`` places the PRLs from the spin-to-roll ratio and the force
    balance (:func:`pure_rolling_lines`); ``prl="symmetric"`` uses Heathcote's
    +/-0.347 (then M_S = 0).
    """
    b, m = case.bearing, case.materials
    D, dm, Z = b.ball_diameter, b.pitch_diameter, b.ball_count
    fi, fo = b.inner_conformity, b.outer_conformity
    Fa = case.operating.axial_load
    if Fa <= 0:
        raise CaseError(case.source, "operating.axial_load", "the gyro model needs a positive thrust load")
    mu = case.friction.coefficient
    E1, nu1, E2, nu2 = m.ball.elastic_modulus, m.ball.poisson_ratio, m.races.elastic_modulus, m.races.poisson_ratio
    beta, Q = thrust_contact_angle(Fa, Z, D, dm, fi, fo, E1, nu1, E2, nu2, beta0=b.contact_angle or 0.0)
    ci, co = _race_contacts(beta, Q, D, dm, fi, fo, E1, nu1, E2, nu2)
    a_i, b_i, a_o, b_o = float(ci.a), float(ci.b), float(co.a), float(co.b)
    Ra_i, Ra_o = deformed_surface_radius(fi * D, D), deformed_surface_radius(fo * D, D)
    gamma = D * math.cos(beta) / dm
    if prl == "spin":
        sr_i, sr_o = spin_to_roll_ratios(beta, gamma)
        X_i = pure_rolling_lines(2.0 * Ra_i / a_i * sr_i)
        X_o = pure_rolling_lines(2.0 * Ra_o / a_o * sr_o)
    elif prl == "symmetric":
        X_i = X_o = pure_rolling_lines(0.0)
    else:
        raise ValueError(f"unknown prl option {prl!r} (spin, symmetric)")
    Ri = 0.5 * dm - 0.5 * D * math.cos(beta)
    Ro = 0.5 * dm + 0.5 * D * math.cos(beta)
    f0 = case.friction.viscous_factor if case.friction.viscous_factor is not None else 0.0
    M_L = float(viscous_moment(f0, dm))
    alpha_r = case.friction.hysteresis_loss
    dME_i, dME_o = hysteresis_moment(Q, b_i, alpha_r), hysteresis_moment(Q, b_o, alpha_r)
    dMD_i = differential_sliding_moment(mu, Q, a_i, Ra_i, *X_i, reading=md_reading)
    dMD_o = differential_sliding_moment(mu, Q, a_o, Ra_o, *X_o, reading=md_reading)
    dMS_i, dMS_o = pivoting_moment(mu, Q, a_i, *X_i), pivoting_moment(mu, Q, a_o, *X_o)
    _, M_E, M_D, M_S = total_friction_moment(Z, D, Ri, Ro, beta, dME_i, dME_o, dMD_i, dMD_o, dMS_i, dMS_o, M_L)
    return StaticFriction(beta=beta, Q=Q, a_i=a_i, b_i=b_i, a_o=a_o, b_o=b_o, Ra_i=Ra_i, Ra_o=Ra_o, X_i=X_i, X_o=X_o,
                          Ri=Ri, Ro=Ro, M_L=M_L, M_E=float(M_E), M_D=float(M_D), M_S=float(M_S))


# ==============================================================================================
# 2. Ribbon cage: geometry, mass, contact  ([J] Sec. 3.2, Eqs. 7-13)
# ==============================================================================================


def ribbon_cage_mass_properties(dm, Z, s, width, Dp, k, density):
    """Mass [kg] and moments of inertia (J_x axial, J_y = J_z diametral) [kg m^2] of a ribbon cage.

    Decision (the seed gives no cage mass): two stamped strips of thickness
    s and radial width ``width`` on the pitch circle, each with Z spherical
    cups of diameter D_p and depth k; the sheet area of one strip is the flat
    ring pi d_m w plus, per pocket, the cup (spherical cap 2 pi (D_p/2) k)
    minus the flat disc it replaces (pi (D_p/2)^2).  Inertias of a thin ring
    at the pitch radius: J_x = m (d_m/2)^2, J_y = J_z = J_x / 2.
    """
    Rp = 0.5 * Dp
    area_strip = math.pi * dm * width + Z * (2.0 * math.pi * Rp * k - math.pi * Rp**2)
    mass = 2.0 * density * s * area_strip
    Jx = mass * (0.5 * dm) ** 2
    return mass, Jx, 0.5 * Jx


def ball_cage_stiffness(D, Dp, E1, nu1, E2, nu2):
    """Hertz constant K_pb [N/m^1.5] of a ball (diameter D) in a spherical cup (diameter D_p) ([J] Eq. 10).

    Conforming sphere-in-sphere contact: Rx = Ry = 1/(2/D - 2/D_p); exact
    Hertz via :func:`hsbearing.models.hertz.point_contact` ("dry" contact as
    for the races, [J] Sec. 3.2).
    """
    R = 1.0 / (2.0 / D - 2.0 / Dp)
    return float(point_contact(R, R, 1.0, E1, nu1, E2, nu2).K)


def pocket_geometry(D, Dp, k):
    """(e, nabla): offset of the cup curvature centres from the pocket centre |D_p/2 - k| [m]
    and the free radial play nabla = D_p/2 - D/2 [m] ([J] Sec. 3.2)."""
    return abs(0.5 * Dp - k), 0.5 * Dp - 0.5 * D


def pocket_penetration(dx, dy, dz, e, nabla):
    """Contact approach of a ball in a ribbon pocket, (delta_plus, delta_minus) [m] ([J] Sec. 3.2, Eq. 10).

    The pocket is two spherical cups of radius D_p/2 whose centres sit at
    x = -e (cup of the +x strip) and x = +e (cup of the -x strip).  With the
    ball centre at (dx, dy, dz) in the pocket frame, the cup on the far side
    is at distance ``epsilon = sqrt((|dx| + e)^2 + dy^2 + dz^2)`` and the
    approach is ``epsilon - nabla`` ([J]); contact when > 0.  Both cups are
    evaluated, so ``dx = 0`` gives the two-point contact and ``dx != 0`` the
    one-point contact of [J] without a switch.
    """
    dp = math.sqrt((dx + e) ** 2 + dy * dy + dz * dz) - nabla  # [J], epsilon - nabla, +x cup
    dmi = math.sqrt((dx - e) ** 2 + dy * dy + dz * dz) - nabla  # [J], -x cup
    return dp, dmi


def outer_race_speed(t, n_o, ramp_time, mode="constant", period=2.0):
    """Outer-race angular speed omega_o(t) [rad/s] and its sign of travel ([J] Sec. 3.4, Eq. 17).

    Start from rest at constant acceleration eps = n_o/ramp_time up to n_o.
    Oscillation: the commanded speed alternates +n_o, -n_o, +n_o ... in
    windows of length ``period`` (window 0 starts from rest); each reversal
    is a ramp at the same constant acceleration (2 ramp_time from +n_o to
    -n_o).  Decision: the seed's "+/- n_o with a 2 s period" is read as one
    reversal every 2 s, SFMO being the mean over those windows.
    """
    return _speed(float(t), float(n_o), float(ramp_time), 1 if mode == "oscillation" else 0, float(period))


@numba.njit(cache=True)
def _speed(t, n_o, t_r, osc, T):
    eps = n_o / t_r
    if osc == 0 or t < T:
        return min(eps * t, n_o), 1.0 if n_o >= 0 else -1.0
    k = int(t // T)
    tau = t - k * T
    sgn = 1.0 if k % 2 == 0 else -1.0  # direction of window k
    w = -sgn * n_o + sgn * eps * tau  # ramp from the previous direction
    if sgn > 0:
        w = min(w, n_o)
    else:
        w = max(w, -n_o)
    return w, sgn


@numba.njit(cache=True)
def transform_Ic(tx, ty, tz, A):
    """Transform matrix A_Ic from Frame I to Frame c (v^c = A_Ic v^I), sequential x-y-z angles ([J], Eq. 5)."""
    cx, sx, cy, sy, cz, sz = math.cos(tx), math.sin(tx), math.cos(ty), math.sin(ty), math.cos(tz), math.sin(tz)
    A[0, 0] = cy * cz  # [J], Eq. 5
    A[0, 1] = cx * sz + sx * sy * cz
    A[0, 2] = sx * sz - cx * sy * cz
    A[1, 0] = -cy * sz
    A[1, 1] = cx * cz - sx * sy * sz
    A[1, 2] = sx * cz + cx * sy * sz
    A[2, 0] = sy
    A[2, 1] = -sx * cy
    A[2, 2] = cx * cy


@numba.njit(cache=True)
def euler_rate_matrix(tx, ty, tz, P):
    """Matrix of [J] Eq. 15: d(theta)/dt = P omega^c (inverse of phi of Eq. 6)."""
    cy, cz, sz = math.cos(ty), math.cos(tz), math.sin(tz)
    ty_ = math.tan(ty)
    P[0, 0] = cz / cy  # [J], Eq. 15
    P[0, 1] = -sz / cy
    P[0, 2] = 0.0
    P[1, 0] = sz
    P[1, 1] = cz
    P[1, 2] = 0.0
    P[2, 0] = -ty_ * cz
    P[2, 1] = ty_ * sz
    P[2, 2] = 1.0


# Decision on Eq. 5: the seed prints A_Ic[1, 0] = cos(ty) sin(tz); the product Rz Ry Rx of the
# sequential rotations gives -cos(ty) sin(tz) (also the sign used in phi of Eq. 6, row 2); with the
# printed sign A_Ic is not orthogonal.  tests/test_gyro.py checks orthogonality.


@numba.njit(cache=True)
def _reg_sign(v, v_reg):
    """Regularised Coulomb direction v / sqrt(v^2 + v_reg^2) [-] (smooth; linear below v_reg like [M] / [J] Eq. 19)."""
    return v / math.sqrt(v * v + v_reg * v_reg)


@numba.njit(cache=True)
def _hunt_crossley(K, delta, ddelta, chi):
    """Hertz normal force with Hunt-Crossley damping K delta^1.5 (1 + chi d(delta)/dt), >= 0 [N] ([J] Eq. 10; [HC])."""
    if delta <= 0.0:
        return 0.0
    f = K * delta * math.sqrt(delta) * (1.0 + chi * ddelta)  # [J], Eq. 10 (+ [HC] damping)
    return f if f > 0.0 else 0.0


# ==============================================================================================
# 3. Assembled dynamic model: state vector, rhs (numba), [J] Eqs. 7-21
# ==============================================================================================
#
# State layout (N = 12 + 3 Z):
#   y[0:3]            R^I     cage centre position in Frame I [m]
#   y[3:6]            theta   cage sequential angles (theta_x = cage angle about the axis) [rad]
#   y[6:9]            V^c     cage centre velocity, components in Frame c [m/s]   ([J] Eq. 14)
#   y[9:12]           w^c     cage angular velocity in Frame c [rad/s]
#   y[12:12+Z]        psi_j   ball orbit angles [rad]
#   y[12+Z:12+2Z]     W_j     ball orbit speeds w_bc [rad/s]
#   y[12+2Z:12+3Z]    w_j     ball absolute rotation speeds about the rolling axis [rad/s]

# parameter vector indices
(_P_DM, _P_D, _P_DP, _P_E, _P_NABLA, _P_K, _P_CHI, _P_MU_C, _P_VREG_C, _P_MC, _P_JX, _P_JY, _P_JZ,
 _P_MB, _P_IB, _P_Q, _P_MU, _P_VREG_R, _P_BETA, _P_RI, _P_RO, _P_G, _P_NO, _P_TR, _P_OSC, _P_T, _P_WI,
 _P_GX, _P_GY, _P_GZ, _P_LEN) = range(31)


@numba.njit(cache=True)
def _kernel(t, y, p, Z, ydot, diag):
    """Right-hand side of the assembled model; ``diag[j] = (F_N, F_pbz (driving +), F_T)`` per ball."""
    dm, D, Dp, e, nabla = p[_P_DM], p[_P_D], p[_P_DP], p[_P_E], p[_P_NABLA]
    K, chi, mu_c, vreg_c = p[_P_K], p[_P_CHI], p[_P_MU_C], p[_P_VREG_C]
    mc, Jx, Jy, Jz = p[_P_MC], p[_P_JX], p[_P_JY], p[_P_JZ]
    mb, Ib, Q, mu, vreg_r, beta = p[_P_MB], p[_P_IB], p[_P_Q], p[_P_MU], p[_P_VREG_R], p[_P_BETA]
    Ri, Ro, g = p[_P_RI], p[_P_RO], p[_P_G]
    w_o, sgn = _speed(t, p[_P_NO], p[_P_TR], int(p[_P_OSC]), p[_P_T])
    w_i = p[_P_WI]
    rm = 0.5 * dm
    Rp = 0.5 * Dp
    A = np.empty((3, 3))
    P = np.empty((3, 3))
    transform_Ic(y[3], y[4], y[5], A)
    euler_rate_matrix(y[3], y[4], y[5], P)
    Rx, Ry, Rz = y[0], y[1], y[2]
    V0, V1, V2 = y[6], y[7], y[8]
    w0, w1, w2 = y[9], y[10], y[11]
    # cage weight G_c ([J] Sec. 3.3) along the unit vector (g_x, g_y, g_z) of Frame I (default -Y: horizontal
    # bearing axis), in Frame c
    gx, gy, gz = p[_P_GX], p[_P_GY], p[_P_GZ]
    Fc0 = (A[0, 0] * gx + A[0, 1] * gy + A[0, 2] * gz) * mc * g
    Fc1 = (A[1, 0] * gx + A[1, 1] * gy + A[1, 2] * gz) * mc * g
    Fc2 = (A[2, 0] * gx + A[2, 1] * gy + A[2, 2] * gz) * mc * g
    Mc0 = 0.0
    Mc1 = 0.0
    Mc2 = 0.0
    ca, sa = math.cos(beta), math.sin(beta)
    for j in range(Z):
        psi = y[12 + j]
        W = y[12 + Z + j]
        wb = y[12 + 2 * Z + j]
        psip = 2.0 * math.pi * j / Z
        cp, sp = math.cos(psip), math.sin(psip)
        # ball centre (Frame I) relative to the cage centre, in Frame c; [J] Eq. 4
        bx, by, bz = -Rx, rm * math.cos(psi) - Ry, rm * math.sin(psi) - Rz
        rc0 = A[0, 0] * bx + A[0, 1] * by + A[0, 2] * bz
        rc1 = A[1, 0] * bx + A[1, 1] * by + A[1, 2] * bz
        rc2 = A[2, 0] * bx + A[2, 1] * by + A[2, 2] * bz
        # ball centre in Frame p (B_i of Eq. 7 about the pocket centre r_cp = (0, rm cos, rm sin))
        q1, q2 = rc1 - rm * cp, rc2 - rm * sp
        dx = rc0
        dy = cp * q1 + sp * q2
        dz = -sp * q1 + cp * q2
        # ball centre velocity (Frame I -> c -> p), [J] Eq. 7 first term
        vIy, vIz = -W * rm * math.sin(psi), W * rm * math.cos(psi)
        vc0 = A[0, 1] * vIy + A[0, 2] * vIz
        vc1 = A[1, 1] * vIy + A[1, 2] * vIz
        vc2 = A[2, 1] * vIy + A[2, 2] * vIz
        vb0 = vc0
        vb1 = cp * vc1 + sp * vc2
        vb2 = -sp * vc1 + cp * vc2
        # cage velocity terms in Frame p: B V^c and B w^c, [J] Eq. 8
        Vp0, Vp1, Vp2 = V0, cp * V1 + sp * V2, -sp * V1 + cp * V2
        wp0, wp1, wp2 = w0, cp * w1 + sp * w2, -sp * w1 + cp * w2
        # ball rotation vector in Frame p: axis in the axial-radial plane tilted by beta
        ob0, ob1, ob2 = wb * ca, wb * sa, 0.0
        FN_sum = 0.0
        Fpbz = 0.0
        FT_sum = 0.0
        Fb2 = 0.0  # orbit-direction force on the ball
        Mb = 0.0  # moment on the ball about its rolling axis
        for side in range(2):
            cx = -e if side == 0 else e
            d0, d1, d2 = dx - cx, dy, dz
            dist = math.sqrt(d0 * d0 + d1 * d1 + d2 * d2)
            delta = dist - nabla  # [J], epsilon - nabla (Eq. 10)
            if delta <= 0.0:
                continue
            n0, n1, n2 = d0 / dist, d1 / dist, d2 / dist
            # contact point: from the pocket centre r_pq, from the ball centre r_bq, from the cage centre r_cq
            pq0, pq1, pq2 = cx + Rp * n0, Rp * n1, Rp * n2
            bq0, bq1, bq2 = pq0 - dx, pq1 - dy, pq2 - dz
            cq0, cq1, cq2 = pq0, rm + pq1, pq2
            # [J] Eq. 7: ball surface velocity at Q
            ub0 = vb0 + ob1 * bq2 - ob2 * bq1
            ub1 = vb1 + ob2 * bq0 - ob0 * bq2
            ub2 = vb2 + ob0 * bq1 - ob1 * bq0
            # [J] Eq. 8: cage velocity at Q
            uc0 = Vp0 + wp1 * cq2 - wp2 * cq1
            uc1 = Vp1 + wp2 * cq0 - wp0 * cq2
            uc2 = Vp2 + wp0 * cq1 - wp1 * cq0
            # [J] Eq. 9: relative velocity (ball w.r.t. cage here; the seed's cage w.r.t. ball is its negative)
            r0, r1, r2 = ub0 - uc0, ub1 - uc1, ub2 - uc2
            ddelta = r0 * n0 + r1 * n1 + r2 * n2
            FN = _hunt_crossley(K, delta, ddelta, chi)  # [J], Eq. 10
            if FN == 0.0:
                continue
            # [J] Eq. 11: tangential relative velocity; Eq. 12: friction (regularised)
            t0, t1, t2 = r0 - ddelta * n0, r1 - ddelta * n1, r2 - ddelta * n2
            vt = math.sqrt(t0 * t0 + t1 * t1 + t2 * t2)
            s = mu_c * FN / math.sqrt(vt * vt + vreg_c * vreg_c)  # [J], Eq. 12 with |v| -> sqrt(|v|^2 + v_reg^2)
            # force on the ball: normal -FN n (towards the cup centre) plus friction -s t
            f0, f1, f2 = -FN * n0 - s * t0, -FN * n1 - s * t1, -FN * n2 - s * t2
            # force on the cage = -f; accumulate [J] Eq. 13 in Frame c (B^T), moment r_cq x (-f)
            g0, g1, g2 = -f0, -f1, -f2
            Fc0 += g0
            Fc1 += cp * g1 - sp * g2
            Fc2 += sp * g1 + cp * g2
            m0 = cq1 * g2 - cq2 * g1
            m1 = cq2 * g0 - cq0 * g2
            m2 = cq0 * g1 - cq1 * g0
            Mc0 += m0
            Mc1 += cp * m1 - sp * m2
            Mc2 += sp * m1 + cp * m2
            Fb2 += f2
            Mb += (bq1 * f2 - bq2 * f1) * ca + (bq2 * f0 - bq0 * f2) * sa
            FN_sum += FN
            Fpbz += FN * n2 * sgn  # orbit component of the normal force on the cage, driving positive
            FT_sum += s * vt
        diag[j, 0] = FN_sum
        diag[j, 1] = Fpbz
        diag[j, 2] = FT_sum
        # ball/race slip ([J] Eqs. 19-21, regularised): contact-point velocities along the orbit
        vcen = W * rm
        s_i = vcen - wb * 0.5 * D - w_i * Ri  # ball minus inner race
        s_o = vcen + wb * 0.5 * D - w_o * Ro  # ball minus outer race
        F_si = -mu * Q * _reg_sign(s_i, vreg_r)  # [J], Eq. 19 ([M]) with Coulomb saturation
        F_so = -mu * Q * _reg_sign(s_o, vreg_r)
        ydot[12 + j] = W
        ydot[12 + Z + j] = (F_si + F_so + Fb2) / (mb * rm)  # [J], Eq. 20 (first line)
        ydot[12 + 2 * Z + j] = ((F_so - F_si) * 0.5 * D + Mb) / Ib  # [J], Eq. 20 (second line)
    # cage: [J] Eq. 14 (position, expressed in Frame I), Eq. 15, Eq. 16
    ydot[0] = A[0, 0] * V0 + A[1, 0] * V1 + A[2, 0] * V2
    ydot[1] = A[0, 1] * V0 + A[1, 1] * V1 + A[2, 1] * V2
    ydot[2] = A[0, 2] * V0 + A[1, 2] * V1 + A[2, 2] * V2
    ydot[3] = P[0, 0] * w0 + P[0, 1] * w1
    ydot[4] = P[1, 0] * w0 + P[1, 1] * w1
    ydot[5] = P[2, 0] * w0 + P[2, 1] * w1 + w2
    ydot[6] = Fc0 / mc - (w1 * V2 - w2 * V1)  # [J], Eq. 16
    ydot[7] = Fc1 / mc - (w2 * V0 - w0 * V2)
    ydot[8] = Fc2 / mc - (w0 * V1 - w1 * V0)
    ydot[9] = (Mc0 - (Jz - Jy) * w1 * w2) / Jx  # [J], Eq. 16 (Euler)
    ydot[10] = (Mc1 - (Jx - Jz) * w0 * w2) / Jy  # decision: seed prints (J_y - J_z); Euler's law has (J_x - J_z)
    ydot[11] = (Mc2 - (Jy - Jx) * w0 * w1) / Jz


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
        _kernel(t, y, self.p, self.Z, ydot, self._diag)

    def diagnostics(self, t, y):
        """Per-ball (F_N, F_pbz driving +, F_T) [N] at one state."""
        ydot = np.empty_like(y)
        diag = np.zeros((self.Z, 3))
        _kernel(float(t), np.ascontiguousarray(y), self.p, self.Z, ydot, diag)
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
            _kernel(0.0, yy, ps, Z, ydot, diag)
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
                        _kernel(0.0, yy, p0, Z, ydot, diag)
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
                        f"pocket depth k = {k*1e3:g} mm must lie between D/2 = {D*500:g} mm and D_p/2 = {Dp*500:g} mm (seed 000 Sec. 3.2)")
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
        ds = _add_start_ensemble(ds, case, n, progress=progress, fine_interval=fine_interval, wall_limit=wall_limit,
                                 settle=settle, cage_offset=cage_offset, cage_angle=cage_angle, **kw)
    return ds


def _add_start_ensemble(ds, case, n: int, **kw):
    """``ds`` with the start ensemble of ``n`` starts (``sfmc_ensemble`` ...); see :func:`simulate`."""
    offsets = start_offsets(n)
    vals = np.full(n, np.nan)
    failure = None
    t0 = time.perf_counter()
    try:
        for i, v in enumerate(_ensemble_sfmc(case, offsets, **kw)):
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
    out.attrs["start_ensemble_duration_s"] = float(case.operating.oscillation_period)
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

        compile_notice((_kernel,), "the gyro model", seconds=5)
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


def study(case, key: str, values, *, duration=None, out_dir=None, jobs: int = 1, **kw):
    """Run ``case`` for each value of one case key (e.g. ``cage.thickness`` or ``pocket_clearance``).

    ``key="pocket_clearance"`` means the seed's A = k - D_w/2 (not a case key) and varies
    ``cage.pocket_depth = D_w/2 + A``.  Returns ``{value: Dataset}`` in the order of ``values``.

    The points go through the sweep machinery (:func:`hsbearing.sweeps.run_sweep`): ``jobs``
    worker processes (1 = in this process), one archive per point in ``out_dir`` (None: a
    temporary directory, deleted on return) and resume when ``out_dir`` already holds them.  The
    point cases are built exactly as :func:`override` builds them (same TOML text), so a point's
    (chaotic) trajectory is the same as a direct :func:`simulate` of ``override(case, key=value)``.
    Simulation keywords (``**kw``: gravity, settle, ...) cannot be passed through a sweep point;
    with any of them the points run in this process, one after the other.
    A point that fails numerically raises :class:`SolverError` with its partial Dataset.
    """
    import tempfile
    from contextlib import nullcontext

    from hsbearing.results import open_run
    from hsbearing.sweeps import run_sweep

    values = list(values)
    if key == "pocket_clearance":
        vary_key = "cage.pocket_depth"
        # k written as a short decimal ("0.67 mm", as on the command line and in the case file): a value
        # 1e-16 away would start a different chaotic trajectory
        items = [f"{round((case.bearing.ball_diameter / 2 + float(A)) * 1e3, 9)!r} mm" for A in values]
    else:
        vary_key, items = key, values
    if kw:
        out = {}
        for v, item in zip(values, items):
            out[v] = simulate(override(case, **{vary_key: item}), duration=duration, **kw)
        return out
    with (tempfile.TemporaryDirectory(prefix="gyro-study-") if out_dir is None else nullcontext(out_dir)) as d:
        sw = run_sweep(case, {vary_key: items}, jobs=jobs, out_dir=d, duration=duration, progress=False)
        out = {}
        for v, status, err, arch in zip(values, sw["status"].values, sw["error"].values, sw["archive"].values):
            if status == "invalid":
                raise CaseError(case.source, vary_key, f"value {v!r}: {err}")
            ds = open_run(Path(d) / arch) if arch else None
            if status != "ok":
                raise SolverError(f"gyro study {vary_key} = {v!r}: {status}: {err}", partial=ds)
            out[v] = ds
    return out


def plot_run(ds, path) -> Path:
    """Figure of a gyro run (like [J] Figs. 7-9): speeds, M_C, the five sources and M; returns the PNG path.

    Drawn by :func:`hsbearing.plotting.plot_gyro` (figures live in the plotting module).
    """
    from hsbearing.plotting import plot_gyro

    return plot_gyro(ds, Path(path))


def circumferential_play_angle(D, Dp, k, dm):
    """Circumferential play of the ribbon cage about the axis [rad] ([J] Sec. 3.2 pocket geometry).

    A ball in a pocket of two spherical cups (diameter D_p, depth k) can move along the orbit by
    sqrt(nabla^2 - e^2) = sqrt(nabla^2 - (nabla - A)^2) before it touches (nabla = (D_p - D)/2,
    e = |D_p/2 - k|, A = k - D/2; :func:`pocket_geometry`), i.e. an angle of that length over the
    pitch radius d_m/2.  D ball diameter [m], Dp pocket diameter [m], k pocket depth [m], dm pitch
    diameter [m].
    """
    e, nabla = pocket_geometry(D, Dp, k)
    return math.sqrt(max(nabla**2 - e**2, 0.0)) / (0.5 * dm)  # [J] Sec. 3.2, play along the orbit


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


def _ensemble_sfmc(case, offsets, duration: float | None = None, *, cage_angle: float = 0.0, **kw):
    """Yield the SFMC [N m] of a constant-rate start for each offset (fraction of the play); see start_ensemble."""
    play = circumferential_play_angle(case.bearing.ball_diameter, case.cage.pocket_diameter, case.cage.pocket_depth,
                                      case.bearing.pitch_diameter)
    T = duration if duration is not None else case.operating.oscillation_period
    # a constant-rate case is used as it is, so that offset 0 is bit for bit the plain start of that case
    c = case if case.operating.mode == "constant" else override(case, **{"operating.mode": "constant"})
    n = len(offsets)
    for k, f in enumerate(offsets, 1):  # each progress bar says which start it is
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


def validation(out_dir="docs/figures", *, osc_duration: float = 20.3, study_duration: float = 20.3,
               ensemble: int = 5, gravity_check: bool = True, jobs: int = 1):
    """Recompute the seed 000 comparison (Table 2 cells, s and A studies) and draw docs/figures/gyro_*.png.

    ``python -m hsbearing.models.friction.gyro [OUT_DIR] [--jobs N]``; prints the Markdown rows used in
    docs/validation/gyro.md.  Takes about half an hour on one core.  The s and A studies run through
    the sweep machinery (:func:`study`) with ``jobs`` worker processes.
    """
    import csv

    from hsbearing.case import load_case

    out = Path(out_dir)
    out.mkdir(parents=True, exist_ok=True)
    base = load_case("jiang2014_gyro")
    ref = {}
    data = Path(__file__).resolve().parents[3] / "tests" / "data" / "seed000_friction_moments.csv"
    if data.exists():
        with open(data) as fh:
            for r in csv.DictReader(line for line in fh if not line.startswith("#")):
                ref[(float(r["load_N"]), float(r["speed_r_per_min"]))] = r
    rows = []
    keep = {}
    u = 1e6
    for n in (2, 5):
        for F in (1, 2, 3):
            c = override(base, **{"operating.axial_load": f"{F} N", "operating.outer_speed": f"{n} rpm"})
            d_o = simulate(override(c, **{"operating.mode": "oscillation"}), duration=osc_duration)
            keep[(F, n)] = d_o
            wm = d_o.window_max_moment.values * u
            ens = start_ensemble(c, ensemble) * u if ensemble else np.array([wm[0]])
            r = ref.get((float(F), float(n)), {})
            rows.append((F, n, float(d_o.rfmc) * u, r.get("RFMC_uNm", "?"), wm[0], ens.mean(), ens.std(), r.get("SFMC_uNm", "?"),
                         wm[1:].mean(), wm[1:].std(), wm[1:].size, r.get("SFMO_uNm", "?")))
            print(f"cell {F} N {n} r/min: window maxima {np.round(wm, 2)}; start ensemble {np.round(ens, 2)}; "
                  f"steps {d_o.attrs['solver_steps']}, wall {d_o.attrs['solver_wall_time']:.1f} s", flush=True)
    print("| load [N] | n_o [r/min] | RFMC ours | RFMC paper | SFMC ours (settled start) | SFMC ours, ensemble mean +/- sd "
          "| SFMC paper | SFMO ours, mean +/- sd (windows) | SFMO paper |")
    print("|---|---|---|---|---|---|---|---|---|")
    for r in rows:
        print("| {} | {} | {:.2f} | {} | {:.2f} | {:.2f} +/- {:.2f} | {} | {:.2f} +/- {:.2f} ({}) | {} |".format(*r))
    if gravity_check:
        for n in (2, 5):
            c = override(base, **{"operating.outer_speed": f"{n} rpm"})
            d_g = simulate(c, duration=0.3, gravity=GRAVITY)
            d_0 = simulate(c, duration=2.0, settle=False)
            print(f"1 N, {n} r/min: SFMC with cage gravity in the dynamics (0.3 s) = {float(d_g.sfmc)*u:.3f} uN m "
                  f"(steps {d_g.attrs['solver_steps']}); SFMC from an exactly centred cage = {float(d_0.sfmc)*u:.3f} uN m", flush=True)
    plot_run(keep[(1, 5)], out / "gyro_run_1N_5rpm_oscillation.png")
    plot_run(keep[(1, 2)], out / "gyro_run_1N_2rpm_oscillation.png")
    study_figures(out, study_duration=study_duration, jobs=jobs)
    return rows


def study_figures(out_dir="docs/figures", *, study_duration: float = 20.3, jobs: int = 1,
                  which=("thickness", "clearance")):
    """The s and A studies of [J] Figs. 10-11 (oscillation, 1 N, +/-5 and +/-2 r/min) through :func:`study`;
    draws ``gyro_thickness.png`` / ``gyro_clearance.png`` (M histories and SFMO +/- standard error) and
    prints one line per point."""
    from matplotlib.figure import Figure

    from hsbearing.case import load_case
    from hsbearing.plotting import save_figure

    out = Path(out_dir)
    out.mkdir(parents=True, exist_ok=True)
    base = load_case("jiang2014_gyro")
    u = 1e6
    plans = {
        "thickness": ("cage.thickness", ["0.15 mm", "0.20 mm", "0.25 mm", "0.30 mm"], "s", "gyro_thickness.png"),
        "clearance": ("pocket_clearance", [0.01e-3, 0.02e-3, 0.03e-3, 0.04e-3, 0.05e-3], "A", "gyro_clearance.png"),
    }
    for key, values, label, fname in (plans[w] for w in which):
        fig = Figure(figsize=(9, 8), layout="constrained")
        axs = fig.subplots(3, 1)
        curves = {}
        for ax, n in zip(axs[:2], (5, 2)):
            c = override(base, **{"operating.mode": "oscillation", "operating.outer_speed": f"{n} rpm"})
            res = study(c, key, values, duration=study_duration, jobs=jobs)
            xs, ms, ses = [], [], []
            for v, ds in res.items():
                lab = v if isinstance(v, str) else f"{v*1e3:.2f} mm"
                sm = summary(ds)
                ax.plot(ds.time.values, ds.friction_moment_total.values * u, lw=0.6, label=f"{label} = {lab}")
                print(f"study {key} = {lab}, n = {n} r/min: SFMC {sm['sfmc']*u:.2f}, SFMO {sm['sfmo']*u:.2f} "
                      f"+/- {sm['sfmo_stderr']*u:.2f} (standard error, {sm['reversal_windows']} windows) uN m", flush=True)
                xs.append(float(lab.split()[0]))
                ms.append(sm["sfmo"] * u)
                ses.append(sm["sfmo_stderr"] * u)
            curves[n] = (xs, ms, ses)
            ax.set_ylabel(r"M [$\mu$N m]")
            ax.set_title(f"1 N, +/-{n} r/min: total friction moment M (peak-hold)", fontsize=9)
            ax.legend(fontsize=7, ncol=5)
        axs[1].set_xlabel("time [s]")
        for n, (xs, ms, ses) in curves.items():
            axs[2].errorbar(xs, ms, yerr=ses, marker="o", capsize=3, label=f"+/-{n} r/min")
        axs[2].set_xlabel(f"{label} [mm]")
        axs[2].set_ylabel(r"SFMO [$\mu$N m]" + "\n(mean +/- standard error)")
        axs[2].legend(fontsize=8)
        save_figure(fig, out / fname)


if __name__ == "__main__":  # pragma: no cover
    import argparse

    _ap = argparse.ArgumentParser(description="seed 000 validation tables and docs/figures/gyro_*.png")
    _ap.add_argument("out_dir", nargs="?", default="docs/figures")
    _ap.add_argument("-j", "--jobs", type=int, default=1, help="worker processes for the s and A studies")
    _a = _ap.parse_args()
    validation(_a.out_dir, jobs=_a.jobs)
