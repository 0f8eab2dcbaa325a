"""Cage forces of the dynamic model: ball/pocket contact and friction, guide-land film (Zhang et al. 2016, Eqs. 11-16).

Scalar, pure, numba-compiled functions; assembled in :mod:`hsbearing.models.ball_bearing.kernel`.

References
----------
[1] Zhang W. et al., Chin. J. Aeronaut. 29 (2016), Eqs. (11)-(16), Fig. 4.
[2] Harris T. A., Kotzalas M. N., *Rolling Bearing Analysis*, 5th ed., Vol. 1,
    Ch. 6 (Hertz point contact, Q = K delta^1.5, Eq. 6.40).
[3] Hamrock B. J., Schmid S. R., Jacobson B. O., *Fundamentals of Fluid Film
    Lubrication*, 2nd ed., Dekker 2004: Ch. 15 (squeeze film: sphere
    approaching a plane, W = 6 pi eta R^2 (dh/dt) / h), Ch. 10/12 (short-width
    journal bearing, Ocvirk; friction torque 2 pi eta R^3 L omega / (c sqrt(1 - eps^2))).
[4] San Andres L., *Modern Lubrication Theory*, Notes 4 "Static load
    performance of plain journal bearings" and Notes 5 (Texas A&M, open course
    notes): short-length bearing pressure with journal rotation, whirl and
    squeeze (pressure profiles for each), Guembel (half-Sommerfeld) condition
    p >= 0.
[5] Gupta P. K., "Dynamics of rolling-element bearings, Part III: ball bearing
    analysis", J. Lubr. Technol. 101 (1979) 312-318: ball/cage and cage/race
    interactions (elastic pocket contact, hydrodynamic guide land).
[6] Childs D., *Turbomachinery Rotordynamics*, Wiley 1993, Ch. 3 (short
    plain journal bearing, dynamic Reynolds equation with whirl and squeeze,
    pi-film / Guembel pressure, Sommerfeld substitution for the integrals).

The guide-land film (:func:`guide_land_forces`) places the pressurised film where the
gap converges for any whirl and squeeze (Guembel p >= 0); the pi-film closed form on a
fixed half circle is right only for 0 <= whirl < half the surface speed without squeeze
(docs/dynamics.md).
"""

from __future__ import annotations

import math

from numba import njit

from hsbearing.compile_cache import check_compile_cache
from hsbearing.models.ball_bearing.ring import tilt_rotation

__all__ = ["cage_orientation", "cage_generalised_moments", "pocket_normal_force", "pocket_friction_factor", "guide_land_forces", "guide_land_torque",
           "guide_land_power", "land_film_integrals", "smooth_eccentricity", "cage_equations_of_motion"]


@njit(cache=True)
def cage_orientation(phi, psi_y, psi_z, phidot, psidot_y, psidot_z):
    """Rotation R_c = R_tilt(psi) R_x(phi) of the cage and its angular velocity (space frame).

    The cage turns by phi about its own axis and is tilted by the rotation
    vector psi = (0, psi_y, psi_z) (:func:`hsbearing.models.ball_bearing.ring.tilt_rotation`);
    omega = J(psi) psi' + phi' R_c e_x.  Exact for any tilt.

    Returns (R_c row-major 9-tuple, (omega_x, omega_y, omega_z), J 9-tuple).
    """
    Rt, J = tilt_rotation(psi_y, psi_z)
    c, s = math.cos(phi), math.sin(phi)
    R = (Rt[0], Rt[1] * c + Rt[2] * s, -Rt[1] * s + Rt[2] * c,
         Rt[3], Rt[4] * c + Rt[5] * s, -Rt[4] * s + Rt[5] * c,
         Rt[6], Rt[7] * c + Rt[8] * s, -Rt[7] * s + Rt[8] * c)
    wx = J[1] * psidot_y + J[2] * psidot_z + phidot * R[0]
    wy = J[4] * psidot_y + J[5] * psidot_z + phidot * R[3]
    wz = J[7] * psidot_y + J[8] * psidot_z + phidot * R[6]
    return R, (wx, wy, wz), J


@njit(cache=True)
def cage_generalised_moments(Mx, My, Mz, R, J):
    """Generalised forces (Q_phi, Q_psi_y, Q_psi_z) of a moment M about the cage centre [N m].

    With omega = J psi' + phi' e (e = R_c e_x), the virtual work M . omega dt gives
    Q_phi = e . M and Q_psi = J^T M (y, z components); for small tilts
    (M_x, M_y, M_z) ([1], Eqs. 14-16).
    """
    return (R[0] * Mx + R[3] * My + R[6] * Mz,
            J[1] * Mx + J[4] * My + J[7] * Mz,
            J[2] * Mx + J[5] * My + J[8] * Mz)


@njit(cache=True)
def pocket_normal_force(e, e_dot, clearance, K, eta, R_sq, h_min):
    """Normal force between a ball and its cylindrical cage pocket [N] (>= 0, pushes the ball back).

    Elastic part: Hertz K delta^1.5 with delta = e - clearance > 0 ([2], Eq. 6.40;
    steel ball in the polyamide pocket).  Film part: squeeze of the oil film
    of thickness h = clearance - e, 6 pi eta R^2 e_dot / h ([3], Ch. 15, a
    sphere approaching a plane; R_sq = R^2 of the equivalent sphere), with h
    replaced by the smooth positive h_eff = (h + sqrt(h^2 + 4 h_min^2)) / 2
    (= h for h >> h_min, h_min^2/|h| in contact; regularisation documented in
    docs/dynamics.md).  Only an approaching ball (e_dot > 0) loads the film
    (half-Sommerfeld: a separating film cavitates).

    Parameters
    ----------
    e : ball-centre offset from the pocket centre in the pocket plane [m];
    e_dot : its rate [m/s]; clearance : (d_p - D)/2 [m]; K : [N/m^1.5];
    eta : oil viscosity [Pa s]; R_sq : [m^2]; h_min : [m].
    """
    F = 0.0
    delta = e - clearance
    if delta > 0.0:
        F += K * delta * math.sqrt(delta)  # [2] Eq. 6.40
    if e_dot > 0.0 and eta > 0.0:
        h = clearance - e
        h_eff = 0.5 * (h + math.sqrt(h * h + 4.0 * h_min * h_min))
        F += 6.0 * math.pi * eta * R_sq * e_dot / h_eff  # [3] Ch. 15, squeeze film
    return F


@njit(cache=True)
def pocket_friction_factor(v_slide, mu, v0):
    """Regularised Coulomb factor: friction force = -mu Q v / sqrt(|v|^2 + v0^2) [-] per unit load and velocity.

    Returns mu / sqrt(v_slide^2 + v0^2) [s/m]; multiplied by the pocket load
    and the sliding velocity vector it gives the pocket sliding friction P_S
    of [1], Eqs. 5-16 (tanh-like regularisation of sign(v), v0 in
    docs/dynamics.md).
    """
    return mu / math.sqrt(v_slide * v_slide + v0 * v0)


@njit(cache=True)
def smooth_eccentricity(eps, eps_max):
    """Smooth saturation eps / (1 + (eps/eps_max)^8)^(1/8) [-] keeping the film formulas finite."""
    q = eps / eps_max
    q2 = q * q
    q8 = q2 * q2 * q2 * q2
    return eps / (1.0 + q8) ** 0.125


@njit(cache=True)
def _sommerfeld_angle(theta, eps):
    """Sommerfeld angle gamma(theta) of the film h/c = 1 - eps cos(theta), continuous and increasing [rad].

    tan(gamma/2) = sqrt((1 + eps)/(1 - eps)) tan(theta/2), so that
    1 - eps cos(theta) = (1 - eps^2)/(1 + eps cos(gamma)) and gamma(theta + 2 pi) = gamma(theta) + 2 pi
    ([6], Sommerfeld substitution; [3], Ch. 10).
    """
    n = math.floor((theta + math.pi) / (2.0 * math.pi))
    t = theta - 2.0 * math.pi * n  # in [-pi, pi)
    g = 2.0 * math.atan2(math.sqrt(1.0 + eps) * math.sin(0.5 * t), math.sqrt(1.0 - eps) * math.cos(0.5 * t))
    return g + 2.0 * math.pi * n


@njit(cache=True)
def land_film_integrals(eps, theta1, theta2):
    """Film integrals (I_cc, I_sc, I_ss) of cos^2, sin cos, sin^2 over (1 - eps cos(theta))^3, theta1..theta2 [-].

    Exact, through the Sommerfeld angle gamma of :func:`_sommerfeld_angle`
    ([6]): d theta / h^3 = (1 + eps cos g)^2 / (1 - eps^2)^(5/2) d g,
    cos(theta) = (cos g + eps)/(1 + eps cos g), sin(theta) = sqrt(1 - eps^2) sin g / (1 + eps cos g), so

    I_cc = int (cos g + eps)^2 dg / (1 - eps^2)^(5/2),
    I_sc = int sin g (cos g + eps) dg / (1 - eps^2)^2,
    I_ss = int sin^2 g dg / (1 - eps^2)^(3/2):

    trigonometric polynomials, finite and free of cancellation for every
    0 <= eps < 1 (h = 1 - eps cos theta, i.e. theta measured from the minimum film).
    """
    g1 = _sommerfeld_angle(theta1, eps)
    g2 = _sommerfeld_angle(theta2, eps)
    s1, c1 = math.sin(g1), math.cos(g1)
    s2, c2 = math.sin(g2), math.cos(g2)
    dg = g2 - g1
    ds2 = s2 * c2 - s1 * c1  # (sin 2g2 - sin 2g1) / 2
    s = 1.0 - eps * eps
    rs = math.sqrt(s)
    I_cc = (0.5 * dg + 0.5 * ds2 + 2.0 * eps * (s2 - s1) + eps * eps * dg) / (s * s * rs)
    I_sc = (0.5 * (s2 * s2 - s1 * s1) - eps * (c2 - c1)) / (s * s)
    I_ss = (0.5 * dg - 0.5 * ds2) / (s * rs)
    return I_cc, I_sc, I_ss


@njit(cache=True)
def guide_land_forces(eps, eps_dot, omega_sum, whirl, eta, R, L, c):
    """Film force of one guide land on the cage: short-bearing Reynolds equation with Guembel cavitation [N].

    Valid for any whirl speed (below, at, above half the surface speed, backward) and any squeeze rate.

    Parameters
    ----------
    eps : eccentricity ratio e/c of the cage centre from the land centre [-], 0 <= eps < 1
        (already saturated below 1 by :func:`smooth_eccentricity`);
    eps_dot : its rate [1/s] (> 0: the cage approaches the land);
    omega_sum : sum of the two surface speeds about X, cage + land [rad/s];
    whirl : angular speed phi' of the line of centres about X [rad/s];
    eta : oil viscosity [Pa s]; R : film radius [m]; L : axial width of this land [m];
    c : radial guide clearance [m].

    Returns
    -------
    F_r : film force on the cage along the line of centres, positive away from the land
        centre (toward the land) [N];
    F_t : perpendicular to it, positive in the direction of rotation [N] -- the positive sense of the
        angle theta, i.e. +X (counter-clockwise seen from +X): for a cage turning the other way
        (omega_sum < 0) a forward whirl gives F_t < 0.

    Notes
    -----
    With theta measured from the line of centres (minimum film at theta = 0) in the
    direction of rotation, h = c (1 - eps cos theta), and the short-width Reynolds
    equation ([3], Ch. 10; [4], Notes 4; [6], Ch. 3)
    d/dz (h^3 dp/dz) = 12 eta [(omega_sum/2) dh/dtheta + dh/dt]
    = 12 eta c [eps (omega_sum - 2 phi')/2 sin(theta) - eps' cos(theta)]
    gives, with p = 0 at z = +-L/2,
    p = -6 eta c G(theta) (L^2/4 - z^2) / h^3,   G = a sin(theta) + b cos(theta),
    a = eps (omega_sum - 2 phi')/2, b = -eps'.
    Guembel condition p >= 0 ([4], [6]): the film carries pressure where G < 0,
    G = A sin(theta + beta), beta = atan2(b, a): the arc (-pi - beta, -beta) -- always a
    half circle, whose position follows the sign of w = omega_sum - 2 phi' and of eps'
    (tan(beta) = -2 eps' / (eps w)).  Integrating -p (cos, sin) R dtheta dz:
    F_r = K (a I_sc + b I_cc), F_t = K (a I_ss + b I_sc),
    K = eta R L^3 / c^2, with the exact integrals of :func:`land_film_integrals`.
    For w > 0, eps' = 0 this is the pi-film of Ocvirk, F_r = -K w eps^2/(1-eps^2)^2,
    F_t = K pi w eps / (4 (1-eps^2)^(3/2)) ([3], Ch. 10); for w < 0 the lobe moves to
    the other half: F_r stays restoring (|w|), F_t changes sign.  The short-width
    error against a finite-length solution is O((L/2R)^2): docs/dynamics.md.
    """
    a = 0.5 * eps * (omega_sum - 2.0 * whirl)
    b = -eps_dot
    if a == 0.0 and b == 0.0:
        return 0.0, 0.0
    beta = math.atan2(b, a)
    I_cc, I_sc, I_ss = land_film_integrals(eps, -math.pi - beta, -beta)
    k = eta * R * L**3 / (c * c)
    Fr = k * (a * I_sc + b * I_cc)  # [4] Notes 4, [6] Ch. 3: -int p cos(theta) R dtheta dz over p > 0
    Ft = k * (a * I_ss + b * I_sc)  # -int p sin(theta) R dtheta dz over p > 0
    return Fr, Ft


@njit(cache=True)
def guide_land_torque(eps, omega_rel, eta, R, L, c):
    """Viscous friction moment M_cx of one guide-land film on the cage [N m] ([3], Petroff with eccentricity).

    M = -2 pi eta R^3 L omega_rel / (c sqrt(1 - eps^2)); omega_rel = cage speed -
    land speed [rad/s]; eps the eccentricity ratio [-]; eta [Pa s]; R, L, c [m].
    Couette shear of a full film over the whole circumference (the cavitated arc is
    taken as filled: streamers; its share of the shear is an upper bound) and without
    the pressure-gradient (Poiseuille) shear, which is of relative order
    (L/2R)^2 eps^2/(1 - eps^2) (< 0.4 % at L = 1.8 mm, R = 26 mm, eps < 0.95).
    This is the M_cx of [1], Eq. (14), for one land.
    """
    return -2.0 * math.pi * eta * R**3 * L * omega_rel / (c * math.sqrt(1.0 - eps * eps))  # [3]


@njit(cache=True)
def guide_land_power(F_r, F_t, e, e_dot, whirl, M_cx, omega_cage, omega_land):
    """Power dissipated in one guide-land film [W]: minus the power of its forces on the cage and on the land.

    D = -(F_r e' + F_t e (phi' - omega_land)) - M_cx (omega_cage - omega_land)

    F_r, F_t : film force on the cage [N] (:func:`guide_land_forces`); e [m], e_dot [m/s]:
    cage offset from the land centre and its rate; whirl = phi' [rad/s]; M_cx : film moment
    on the cage [N m] (:func:`guide_land_torque`); omega_cage, omega_land [rad/s].
    The film is massless: it puts -F (through the cage centre) and M_land = -M_cx - e F_t
    on the land, so D = -(F . v_cage + M_cx omega_cage + M_land omega_land), which is the
    expression above (independent of the frame's rotation).  Source name ``guide_land``
    of the power balance.  D >= 0 is guaranteed for short lands only: the pressure part is
    c K int G^2/h^3 >= 0, but the Petroff split (cage M, land -M - e F_t) adds a cross term
    -e F_t (omega_c - omega_l)/2 bounded by the Couette shear when (L/R)^2 / (32 pi (1 - eps^2)) < 1
    (independent review: <= 1e-3 for the 1.8 mm lands of zhang2016 at eps 0.97).
    """
    return -(F_r * e_dot + F_t * e * (whirl - omega_land)) - M_cx * (omega_cage - omega_land)


@njit(cache=True)
def cage_equations_of_motion(Fx, Fy, Fz, Mx, My, Mz, phidot, psidot_y, psidot_z, m, Ip, Id):
    """Cage accelerations from the resultant force and moment ([1], Eqs. 11-16).

    Axisymmetric body, small tilts psi_y, psi_z, spin phi' about X:
    m x'' = F_x, m y'' = F_y, m z'' = F_z, I_p phi'' = M_x,
    I_d psi_y'' = M_y - I_p phi' psi_z', I_d psi_z'' = M_z + I_p phi' psi_y'
    (Euler's equations with I_y = I_z = I_d; the (I_cz - I_cx) w_cz w_cx terms of
    Eqs. 15-16 for a symmetric cage).
    """
    return (Fx / m, Fy / m, Fz / m, Mx / Ip,
            (My - Ip * phidot * psidot_z) / Id,  # [1] Eq. 15
            (Mz + Ip * phidot * psidot_y) / Id)  # [1] Eq. 16


# numba bakes callees and captured constants into its cache: key the cache on them (compile_cache.py)
check_compile_cache(globals())
