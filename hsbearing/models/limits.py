"""Limits of a ball/raceway contact: static stress limit, film parameter, groove-shoulder truncation.

Pure functions (SI).  Used for the contact state over time and the warnings
of hsbearing.systems.angular_contact.contact_state (docs/life.md).

References
----------
[1] ISO 76:2006, *Rolling bearings -- Static load ratings*, 6.2: the basic
    static load rating of ball bearings corresponds to 4 200 MPa at the centre
    of the most heavily loaded ball/raceway contact (4 600 MPa self-aligning),
    where the permanent deformation reaches ~1e-4 of the ball diameter.
[2] Hamrock B. J., Dowson D., *Ball Bearing Lubrication*, Wiley 1981, Ch. 8 /
    Harris & Kotzalas, *Rolling Bearing Analysis* 5th ed., Vol. 1, Ch. 7:
    film parameter lambda = h_min / sqrt(R_q,1^2 + R_q,2^2); lambda < 1: the
    asperities carry part of the load (boundary/mixed lubrication).
[3] Harris & Kotzalas, 5th ed., Vol. 1, Ch. 2 (groove geometry, Eqs. 2.5-2.9)
    and Vol. 2, Ch. 1 (contact-ellipse truncation at the land of an
    angular-contact bearing under axial load): the ellipse, centred at the
    contact angle alpha on a groove of radius r = f D, spans alpha +- a/r
    (a the semi-major axis along the groove cross-section); it is truncated
    when alpha + a/r exceeds the angle of the groove shoulder.
"""

from __future__ import annotations

import numpy as np

__all__ = ["ISO76_BALL_PRESSURE", "composite_roughness", "film_parameter", "shoulder_angle_inner",
           "shoulder_angle_outer", "ellipse_edge_angle"]

#: [1] 6.2: contact pressure [Pa] at the centre of the most heavily loaded contact at C_0 of radial and thrust
#: ball bearings (4600 MPa for self-aligning ball bearings); the one constant hsbearing.display also uses.
ISO76_BALL_PRESSURE = 4.2e9


def composite_roughness(Rq1, Rq2):
    """Composite rms roughness sigma = sqrt(R_q,1^2 + R_q,2^2) [m] ([2])."""
    return np.sqrt(np.square(Rq1) + np.square(Rq2))  # [2]


def film_parameter(h_min, sigma):
    """Film parameter lambda = h_min / sigma [-] ([2]); h_min [m], sigma composite roughness [m]."""
    return np.asarray(h_min, dtype=float) / sigma  # [2]


def shoulder_angle_inner(di, ri, land_diameter):
    """Angle [rad] of the inner-ring groove shoulder from the groove bottom, seen from the groove curvature centre ([3]).

    di : groove-bottom diameter [m]; ri : groove radius f_i D [m]; land_diameter : shoulder (land) diameter [m].
    The curvature centre is at radius d_i/2 + r_i; the groove point at angle t has radius d_i/2 + r_i (1 - cos t),
    so the shoulder is at cos t_s = (d_i/2 + r_i - d_l/2) / r_i.  nan if the land does not meet the groove.
    """
    c = (0.5 * di + ri - 0.5 * land_diameter) / ri
    return float(np.arccos(c)) if -1.0 <= c <= 1.0 else float("nan")  # [3]


def shoulder_angle_outer(do, ro, land_diameter):
    """Angle [rad] of the outer-ring groove shoulder from the groove bottom ([3]).

    do : groove-bottom diameter [m]; ro : groove radius f_o D [m].  The groove point at angle t has radius
    d_o/2 - r_o (1 - cos t): cos t_s = (d_l/2 - d_o/2 + r_o) / r_o.
    """
    c = (0.5 * land_diameter - 0.5 * do + ro) / ro
    return float(np.arccos(c)) if -1.0 <= c <= 1.0 else float("nan")  # [3]


def ellipse_edge_angle(alpha, a, f, D):
    """Angle [rad] of the far end of the contact ellipse on the groove: |alpha| + a / (f D) ([3]).

    alpha : contact angle [rad]; a : semi-major axis [m] (across the rolling direction, along the groove
    cross-section); f : conformity; D : ball diameter [m].
    """
    return np.abs(np.asarray(alpha, dtype=float)) + np.asarray(a, dtype=float) / (f * D)  # [3]
