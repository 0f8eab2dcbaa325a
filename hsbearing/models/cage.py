"""Cage forces of the dynamic model: ball/pocket contact and friction, guide-land film (seed 004, Eqs. 11-16).

Scalar, pure, numba-compiled functions; assembled in :mod:`hsbearing.models.kernel`.

References
----------
[1] Zhang W. et al., Chin. J. Aeronaut. 29 (2016), seed 004, Eqs. (11)-(16), Fig. 4.
[2] Harris T. A., Kotzalas M. N., *Rolling Bearing Analysis*, 5th ed., Vol. 1,
    Ch. 6 (Hertz point contact, Q = K delta^1.5, Eq. 6.40).
[3] Hamrock B. J., Schmid S. R., Jacobson B. O., *Fundamentals of Fluid Film
    Lubrication*, 2nd ed., Dekker 2004: Ch. 15 (squeeze film: sphere
    approaching a plane, W = 6 pi eta R^2 (dh/dt) / h), Ch. 10/12 (short-width
    journal bearing, Ocvirk; friction torque 2 pi eta R^3 L omega / (c sqrt(1 - eps^2))).
[4] San Andres L., *Modern Lubrication Theory*, Notes 4-5 (Texas A&M, open
    course notes): dynamic short-length journal bearing, pi-film, with whirl
    and squeeze:  F_r = -(eta R L^3/c^2) [ (w - 2 phi') eps^2/(1-eps^2)^2
    + pi eps' (1 + 2 eps^2) / (2 (1-eps^2)^(5/2)) ],
    F_t = (eta R L^3/c^2) [ pi (w - 2 phi') eps / (4 (1-eps^2)^(3/2))
    + 2 eps eps' / (1-eps^2)^2 ]  (also Childs D., *Turbomachinery
    Rotordynamics*, Wiley 1993, Ch. 3).
[5] Gupta P. K., "Dynamics of rolling-element bearings, Part III: ball bearing
    analysis", J. Lubr. Technol. 101 (1979) 312-318: ball/cage and cage/race
    interactions (elastic pocket contact, hydrodynamic guide land).
"""

from __future__ import annotations

import math

from numba import njit

from hsbearing.models.ring import tilt_rotation

__all__ = ["cage_orientation", "cage_generalised_moments", "pocket_normal_force", "pocket_friction_factor", "guide_land_forces", "guide_land_torque",
           "smooth_eccentricity", "cage_equations_of_motion"]


@njit(cache=True)
def cage_orientation(phi, psi_y, psi_z, phidot, psidot_y, psidot_z):
    """Rotation R_c = R_tilt(psi) R_x(phi) of the cage and its angular velocity (space frame).

    The cage turns by phi about its own axis and is tilted by the rotation
    vector psi = (0, psi_y, psi_z) (:func:`hsbearing.models.ring.tilt_rotation`);
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
def guide_land_forces(eps, eps_dot, omega_sum, whirl, eta, R, L, c):
    """Short (Ocvirk) journal-bearing film forces on the cage at the guide land [N].

    Parameters
    ----------
    eps : eccentricity ratio e/c [-] (already saturated below 1);
    eps_dot : its rate [1/s]; omega_sum : cage + land speeds about X [rad/s];
    whirl : whirl speed phi' of the line of centres [rad/s];
    eta : oil viscosity [Pa s]; R : cage outer radius [m]; L : film length [m];
    c : radial guide clearance [m].

    Returns
    -------
    F_r, F_t : film force on the cage along the line of centres (positive
    away from the land centre) and perpendicular to it (positive in the
    direction of rotation) [4]; omega - 2 phi' of a fixed bearing becomes
    omega_cage + omega_land - 2 phi'.
    """
    k = eta * R * L**3 / (c * c)
    w = omega_sum - 2.0 * whirl
    s = 1.0 - eps * eps
    Fr = -k * (w * eps * eps / (s * s) + math.pi * eps_dot * (1.0 + 2.0 * eps * eps) / (2.0 * s * s * math.sqrt(s)))  # [4]
    Ft = k * (math.pi * w * eps / (4.0 * s * math.sqrt(s)) + 2.0 * eps * eps_dot / (s * s))  # [4]
    return Fr, Ft


@njit(cache=True)
def guide_land_torque(eps, omega_rel, eta, R, L, c):
    """Viscous friction moment M_cx of the guide-land film on the cage [N m] ([3], Petroff with eccentricity).

    M = -2 pi eta R^3 L omega_rel / (c sqrt(1 - eps^2)); omega_rel = cage speed -
    land speed [rad/s].  This is the M_cx of [1], Eq. (14).
    """
    return -2.0 * math.pi * eta * R**3 * L * omega_rel / (c * math.sqrt(1.0 - eps * eps))  # [3]


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
