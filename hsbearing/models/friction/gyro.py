"""Gyroscope mini bearing with a ribbon cage under ultra-low-speed oscillation (Jiang et al. 2014): the physics.

This module holds the friction-moment sources, the ribbon-cage contact and the compiled right-hand side
(sections 1-3); the model builder, simulation, start ensemble, studies and figures are the gyro system,
:mod:`hsbearing.systems.gyro`.

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
    Chin. J. Aeronaut. 27(5) (2014) 1301-1311 (Jiang et al. 2014).
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
from dataclasses import dataclass

import numba
import numpy as np
from scipy.optimize import brentq

from hsbearing.compile_cache import check_compile_cache
from hsbearing.errors import CaseError
from hsbearing.models.hertz import point_contact

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
    "circumferential_play_angle",
    "GRAVITY",
]

GRAVITY = 9.80665  #: standard gravity [m/s^2]

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
# printed sign A_Ic is not orthogonal.  tests/systems/gyro/test_gyro.py checks orthogonality.


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
def kernel(t, y, p, Z, ydot, diag):
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


# numba bakes callees and captured constants into its cache: key the cache on them (compile_cache.py)
check_compile_cache(globals())
