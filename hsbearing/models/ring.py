"""Inner-ring kinematics and equations of motion (seed 004, Eqs. 17-21).

References
----------
[1] Zhang W. et al., Chin. J. Aeronaut. 29 (2016), seed 004, Eqs. (17)-(21).
[2] Harris T. A., Kotzalas M. N., *Rolling Bearing Analysis*, 5th ed., Vol. 1,
    Ch. 2 (groove curvature centres: inner at radius d_m/2 + (f_i - 1/2) D cos alpha_0,
    outer at d_m/2 - (f_o - 1/2) D cos alpha_0, separated by A = (f_i + f_o - 1) D
    along the line of contact, Eq. 2.9) and Vol. 2, Ch. 1 (displacements of the
    inner-ring groove centre locus under axial, radial and tilting displacement).
"""

from __future__ import annotations

import math

from numba import njit

__all__ = ["inner_groove_centre", "ring_equations_of_motion"]


@njit(cache=True)
def inner_groove_centre(theta, rho_i, g_i, xi, yi, zi, by, bz, vxi, vyi, vzi, byd, bzd, thetadot):
    """Inner-race groove curvature centre seen from a ball at azimuth theta, and its rate.

    The groove-centre locus of the inner ring is the circle of radius rho_i at
    axial offset g_i in the ring frame ([2] Vol. 1, Ch. 2); the ring is
    displaced by (x_i, y_i, z_i) and tilted by the small angles (beta_y,
    beta_z) ([2] Vol. 2, Ch. 1, first order in the tilts):
    c = o_i + p + beta x p with p = (g_i, rho_i cos theta, rho_i sin theta).

    Returns
    -------
    cx, cr : axial and radial (along e_r(theta)) coordinates [m];
    cx_dot, cr_dot : their time derivatives [m/s], including the motion of
        the azimuth theta at thetadot.
    """
    c = math.cos(theta)
    s = math.sin(theta)
    cx = xi + g_i + rho_i * (by * s - bz * c)
    yy = yi + bz * g_i
    zz = zi - by * g_i
    cr = yy * c + zz * s + rho_i
    cx_dot = vxi + rho_i * (byd * s - bzd * c) + rho_i * (by * c + bz * s) * thetadot
    cr_dot = (vyi + bzd * g_i) * c + (vzi - byd * g_i) * s + (-yy * s + zz * c) * thetadot
    return cx, cr, cx_dot, cr_dot


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
