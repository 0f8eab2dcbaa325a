"""Inner-ring kinematics and equations of motion (Zhang et al. 2016, Eqs. 17-21).

References
----------
[1] Zhang W. et al., Chin. J. Aeronaut. 29 (2016), Eqs. (17)-(21).
[2] Harris T. A., Kotzalas M. N., *Rolling Bearing Analysis*, 5th ed., Vol. 1,
    Ch. 2 (groove curvature centres: inner at radius d_m/2 + (f_i - 1/2) D cos alpha_0,
    outer at d_m/2 - (f_o - 1/2) D cos alpha_0, separated by A = (f_i + f_o - 1) D
    along the line of contact, Eq. 2.9) and Vol. 2, Ch. 1 (displacements of the
    inner-ring groove centre locus under axial, radial and tilting displacement).
"""

from __future__ import annotations

import math

from numba import njit

from hsbearing.compile_cache import check_compile_cache

__all__ = ["tilt_rotation", "inner_groove_centre", "tilt_generalised_moments", "ring_equations_of_motion"]


@njit(cache=True)
def tilt_rotation(by, bz):
    """Rotation matrix R and left Jacobian J of the ring tilt, a rotation vector beta = (0, beta_y, beta_z).

    Rodrigues: R = I + (sin t / t) K + ((1 - cos t) / t^2) K^2, and the angular velocity of the
    tilting ring is omega = J beta' with J = I + ((1 - cos t) / t^2) K + ((t - sin t) / t^3) K^2,
    K = [beta x], t = |beta| (exponential map of SO(3); e.g. Chirikjian, *Stochastic Models,
    Information Theory and Lie Groups*, Vol. 2, 2012, Ch. 10).  Exact for any tilt, so the
    raceway geometry stays consistent at the 0.2 deg tilts of a single bearing under radial
    load (first-order kinematics would misplace the groove by t^2 rho / 2 ~ 0.2 um, 5 % of
    the contact deflection).

    Returns two 9-tuples (row-major R, row-major J).
    """
    t2 = by * by + bz * bz
    if t2 < 1e-12:
        a = 1.0 - t2 / 6.0
        b = 0.5 - t2 / 24.0
        cc = 1.0 / 6.0 - t2 / 120.0
    else:
        t = math.sqrt(t2)
        a = math.sin(t) / t
        b = (1.0 - math.cos(t)) / t2
        cc = (t - math.sin(t)) / (t2 * t)
    # K = [[0, -bz, by], [bz, 0, 0], [-by, 0, 0]];  K^2 = [[-t2, 0, 0], [0, -bz^2, by bz], [0, by bz, -by^2]]
    R = (1.0 - b * t2, -a * bz, a * by,
         a * bz, 1.0 - b * bz * bz, b * by * bz,
         -a * by, b * by * bz, 1.0 - b * by * by)
    J = (1.0 - cc * t2, -b * bz, b * by,
         b * bz, 1.0 - cc * bz * bz, cc * by * bz,
         -b * by, cc * by * bz, 1.0 - cc * by * by)
    return R, J


@njit(cache=True)
def inner_groove_centre(x, r, theta, rho_i, g_i, xi, yi, zi, R, vxi, vyi, vzi, wtx, wty, wtz):
    """Inner-race groove curvature centre nearest to a ball, and its velocity, in the ball frame.

    The groove-centre locus of the inner ring is the circle of radius rho_i at
    axial offset g_i in the ring frame ([2] Vol. 1, Ch. 2).  The ring is
    displaced by (x_i, y_i, z_i) and tilted by the rotation R
    (:func:`tilt_rotation`).  The groove centre that the ball (centre b)
    touches is the point of that circle nearest to b: the one at the azimuth
    of b seen from the ring centre in the ring's own plane (exact for a
    circle).  Because it is the nearest point, the contact normal b -> c is
    the gradient of the distance |c - b| with respect to every body's
    coordinates, which keeps the contact force conservative; for a radially
    displaced ring it has a circumferential component of order
    cos(alpha) y_i sin(theta) / r in the ball frame.

    Parameters
    ----------
    x, r, theta : ball-centre axial position, radius, azimuth [m, m, rad]
    rho_i, g_i : groove-centre circle radius and axial offset in the ring frame [m]
    xi, yi, zi : ring-centre displacement [m]; R : row-major rotation of the tilt (9-tuple)
    vxi, vyi, vzi : ring-centre velocity [m/s]; wtx, wty, wtz : tilting angular velocity J beta' [rad/s]

    Returns
    -------
    dX, dR, dT : c - b in the ball frame (axial, radial, circumferential) [m]
    vX, vR, vT : velocity of the groove-circle point at fixed ring-frame azimuth [m/s]
        (the rate of |c - b| is n . (v_c - v_b) by the envelope theorem).
    """
    c = math.cos(theta)
    s = math.sin(theta)
    px, py, pz = x - xi, r * c - yi, r * s - zi  # ball centre relative to the ring centre
    qy = R[1] * px + R[4] * py + R[7] * pz  # ring frame: R^T p (y and z components)
    qz = R[2] * px + R[5] * py + R[8] * pz
    L = math.sqrt(qy * qy + qz * qz)
    cp, sp = qy / L, qz / L
    ax, ay, az = g_i, rho_i * cp, rho_i * sp  # groove point in the ring frame
    ux = R[0] * ax + R[1] * ay + R[2] * az  # R c'
    uy = R[3] * ax + R[4] * ay + R[5] * az
    uz = R[6] * ax + R[7] * ay + R[8] * az
    vx = vxi + wty * uz - wtz * uy  # o' + omega_t x (R c')
    vy = vyi + wtz * ux - wtx * uz
    vz = vzi + wtx * uy - wty * ux
    Cy, Cz = yi + uy, zi + uz
    dX = xi + ux - x
    dR = Cy * c + Cz * s - r
    dT = -Cy * s + Cz * c
    return dX, dR, dT, vx, vy * c + vz * s, -vy * s + vz * c


@njit(cache=True)
def tilt_generalised_moments(Mx, My, Mz, R, J):
    """Generalised forces (Q_y, Q_z) on the tilt coordinates from the moment M about the ring centre [N m].

    The component of M along the ring's own (tilted) axis e = R e_x is taken by
    the drive that prescribes the spin; the rest does the virtual work
    M . J d(beta), so Q = J^T (M - (M . e) e), of which the y, z components act
    on (beta_y, beta_z).  For small tilts Q = (M_y, M_z) ([1], Eqs. 20-21).
    """
    ex, ey, ez = R[0], R[3], R[6]
    me = Mx * ex + My * ey + Mz * ez
    px, py, pz = Mx - me * ex, My - me * ey, Mz - me * ez
    return J[1] * px + J[4] * py + J[7] * pz, J[2] * px + J[5] * py + J[8] * pz


@njit(cache=True)
def ring_equations_of_motion(Fx, Fy, Fz, My, Mz, spin, bdy, bdz, m, Ip, Id):
    """Inner-ring accelerations ([1], Eqs. 17-21) with the prescribed spin about X.

    m x'' = F_x (17), m y'' = F_y (18), m z'' = F_z (19);
    I_d beta_y'' = M_y - I_p spin beta_z' (20), I_d beta_z'' = M_z + I_p spin beta_y' (21)
    (Euler's equations of an axisymmetric ring, small tilts).  F and M include the
    external loads.
    """
    return (Fx / m, Fy / m, Fz / m,
            (My - Ip * spin * bdz) / Id,  # [1] Eq. 20
            (Mz + Ip * spin * bdy) / Id)  # [1] Eq. 21


# numba bakes callees and captured constants into its cache: key the cache on them (compile_cache.py)
check_compile_cache(globals())
