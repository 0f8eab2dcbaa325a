"""Ball / raceway contact forces of the dynamic model (Zhang et al. 2016, Eqs. 5-10).

Scalar, pure, numba-compiled functions (callable from Python too); the
per-ball assembly that calls them is :mod:`hsbearing.models.ball_bearing.kernel`.

References
----------
[1] Zhang W., Deng S., Chen G., Cui Y., Chin. J. Aeronaut. 29 (2016),
    Eqs. (5)-(10) (ball), Fig. 3.
[2] Harris T. A., Kotzalas M. N., *Rolling Bearing Analysis*, 5th ed., Vol. 1,
    Ch. 2 (groove curvature centres, Eqs. 2.5-2.10) and Ch. 6 (Hertz load-
    deflection Q = K delta^1.5, Eq. 6.40); Vol. 2 (*Advanced Concepts*), Ch. 5:
    hydrodynamic (EHL) rolling force
    F_R = 2.86 E' R_x^2 k^0.348 G^0.022 U^0.66 W^0.47 (after Houpert /
    Hamrock-Dowson).
[3] Hamrock B. J., Dowson D., *Ball Bearing Lubrication*, Wiley 1981, Ch. 3
    (Hertz), Ch. 8 (dimensionless U, G, W).
[4] Hunt K. H., Crossley F. R. E., "Coefficient of restitution interpreted as
    damping in vibroimpact", J. Appl. Mech. 42 (1975) 440-445: contact damping
    that vanishes with the penetration (no force jump at contact onset).
[5] Gupta P. K., *Advanced Dynamics of Rolling Elements*, Springer 1984, Ch. 3-4
    (ball/race traction integrated over the contact ellipse, slip varying
    across the ellipse because of spin).
"""

from __future__ import annotations

import math

import numpy as np
from numba import njit

from hsbearing.compile_cache import check_compile_cache

__all__ = [
    "groove_contact",
    "hertz_normal_load",
    "strip_load_weights",
    "ehl_rolling_force",
    "inlet_heating_factor",
    "inlet_heating_rolling_factor",
    "ball_equations_of_motion",
]


@njit(cache=True)
def groove_contact(dx, dr, dt, groove_offset):
    """Deflection and contact angle of a ball in a raceway groove.

    Parameters
    ----------
    dx, dr, dt : float
        Axial, radial and circumferential components [m] of the vector from the
        ball centre to the (nearest) groove curvature centre of the raceway.
    groove_offset : float
        (f - 1/2) D [m]: distance from the groove curvature centre to the
        unloaded ball centre ([2], Eq. 2.5: r = f D).

    Returns
    -------
    delta : float
        Elastic approach [m] (negative = clearance): |d| - (f - 1/2) D ([2], Ch. 2-3).
    nx, nr, nt : float
        Unit vector from the ball centre towards the groove centre.  For the
        inner race (nx, nr) ~ (sin alpha_i, cos alpha_i); for the outer race
        ~ (-sin alpha_o, -cos alpha_o) ([1], Fig. 3); nt is the small
        circumferential component (radially displaced ring).
    """
    L = math.sqrt(dx * dx + dr * dr + dt * dt)
    return L - groove_offset, dx / L, dr / L, dt / L


@njit(cache=True)
def hertz_normal_load(delta, delta_dot, K, c_damp):
    """Normal load of a Hertz point contact with penetration-weighted damping [N].

    Q = K delta^1.5 + c_damp delta^0.25 delta_dot for delta > 0, 0 otherwise,
    clipped at 0 (a contact does not pull).  The elastic part is [2], Eq. 6.40;
    the damping weight delta^0.25 makes the damping coefficient scale like the
    critical damping of the local linearised stiffness 1.5 K delta^0.5 (the
    Hunt-Crossley idea [4]: no force jump at contact onset).  C1 in delta.

    Parameters
    ----------
    delta : approach [m]; delta_dot : its rate [m/s];
    K : load-deflection constant [N/m^1.5]; c_damp : [N s / m^1.25].
    """
    if delta <= 0.0:
        return 0.0
    Q = K * delta * math.sqrt(delta) + c_damp * math.sqrt(math.sqrt(delta)) * delta_dot  # [2] Eq. 6.40 + [4]
    return Q if Q > 0.0 else 0.0


def strip_load_weights(n: int):
    """Gauss-Legendre nodes u_k in (-1, 1) and load fractions w_k of the contact ellipse strips.

    The Hertz pressure p = p_max sqrt(1 - (x/b)^2 - (y/a)^2) integrated over the
    rolling direction x gives a load per unit length along the major axis
    proportional to 1 - (y/a)^2 ([3], Ch. 3); with y = a u the fraction of Q
    carried by node k is (3/4) g_k (1 - u_k^2), g_k the Gauss-Legendre weights
    (they sum to 1 exactly for n >= 2).
    """
    u, g = np.polynomial.legendre.leggauss(int(n))
    w = 0.75 * g * (1.0 - u * u)
    return u, w / w.sum()


@njit(cache=True)
def ehl_rolling_force(U, Q, Rx, k, Ep, eta0, alpha):
    """Hydrodynamic (EHL) rolling force F_R [N] at a ball/race contact.

    F_R = 2.86 E' R_x^2 k^0.348 G^0.022 Ubar^0.66 Wbar^0.47 ([2] Vol. 2, Ch. 5),
    with Ubar = eta0 |U| / (E' R_x), G = alpha E', Wbar = Q / (E' R_x^2) ([3]).

    Parameters
    ----------
    U : rolling (entrainment) speed [m/s]; Q : normal load [N];
    Rx : rolling-direction effective radius [m]; k : ellipticity a/b [-];
    Ep : reduced modulus E' [Pa]; eta0 : inlet viscosity [Pa s];
    alpha : pressure-viscosity coefficient [1/Pa].
    """
    if Q <= 0.0:
        return 0.0
    Ub = eta0 * abs(U) / (Ep * Rx)
    Wb = Q / (Ep * Rx * Rx)
    G = alpha * Ep
    return 2.86 * Ep * Rx * Rx * k**0.348 * G**0.022 * Ub**0.66 * Wb**0.47  # [2] Vol. 2, Ch. 5


@njit(cache=True)
def inlet_heating_factor(eta0, beta, K, U, p_max, Ep, slide_roll):
    """Inlet shear heating film factor phi_T = h_thermal / h_isothermal [-] at one contact (Gupta et al. 1992).

    phi_T = [1 - 13.2 (p_h/E') L^0.42] / [1 + 0.213 (1 + 2.23 |s|^0.83) L^0.64], L = beta eta0 U^2 / K, clipped to
    [0.05, 1]: the scalar twin of :func:`hsbearing.models.ehl.thermal_reduction_factor` with
    :func:`hsbearing.models.ehl.thermal_loading_parameter` (ehl.py [4]; equal to round-off:
    tests/models/test_inlet_heating.py).  eta0 [Pa s], beta [1/K], K [W/(m K)], U entrainment speed [m/s]
    (either sign), p_max [Pa], Ep [Pa], slide_roll [-].
    """
    L = beta * eta0 * U * U / K  # ehl.py [4]
    s = abs(slide_roll)
    num = 1.0 - 13.2 * (p_max / Ep) * L**0.42  # ehl.py [4]
    den = 1.0 + 0.213 * (1.0 + 2.23 * s**0.83) * L**0.64  # ehl.py [4]
    f = num / den
    return min(max(f, 0.05), 1.0)


#: exponents of the inlet viscosity-speed product in the EHL rolling force (0.66, [2] Vol. 2 Ch. 5) and in the
#: Hamrock-Dowson central film (0.67, ehl.py [1] Eq. 69)
_FR_EXP, _HC_EXP = 0.66, 0.67


@njit(cache=True)
def inlet_heating_rolling_factor(phi_T):
    """Factor on the EHL rolling force F_R of an inlet whose film is reduced by phi_T [-].

    The inlet shear heating acts on the inlet's effective viscosity: the film factor phi_T is read as an effective
    inlet viscosity eta_eff with (eta_eff / eta0)^0.67 = phi_T (h_c ~ (eta0 U)^0.67, ehl.py [1] Eq. 69); the same
    inlet gives F_R ~ (eta_eff U)^0.66 ([2] Vol. 2 Ch. 5), so F_R,thermal / F_R = phi_T^(0.66/0.67).  A
    consistency derivation (one thermal inlet for the film and the rolling force), ASSUMED: the thermal rolling-
    resistance corrections of Goksem & Hargreaves (1978) and Biboulet & Houpert (2010) were searched for and NOT
    read; this is not their formula.
    """
    return phi_T ** (_FR_EXP / _HC_EXP)


@njit(cache=True)
def ball_equations_of_motion(Fx, Fr, Ft, Mx, My, Mz, r, rdot, thetadot, wy, wz, m, I):
    """Accelerations of one ball from the resultant force and moment in its frame ([1], Eqs. 5-10).

    Translational equations in cylindrical coordinates (x axial, r radial,
    theta orbit): m x'' = F_x, m (r'' - r theta'^2) = F_r (the centrifugal
    force F_n of Eq. 6 appears as m r theta'^2), m (r theta'' + 2 r' theta')
    = F_t (Eq. 7; the Coriolis term is the F_v of the seed for a varying
    radius).  Rotation of a sphere (isotropic inertia I) with the absolute
    angular velocity expressed in the frame that turns at theta' about X:
    I w_x' = M_x, I w_y' = M_y + I theta' w_z, I w_z' = M_z - I theta' w_y
    ([1], Eqs. 8-10: the I_b omega theta' gyroscopic terms).

    Returns (x'', r'', theta'', w_x', w_y', w_z') [m/s^2, m/s^2, rad/s^2, rad/s^2 x3].
    """
    xdd = Fx / m  # [1] Eq. 5
    rdd = Fr / m + r * thetadot * thetadot  # [1] Eq. 6
    thdd = (Ft / m - 2.0 * rdot * thetadot) / r  # [1] Eq. 7
    wxd = Mx / I  # [1] Eq. 8
    wyd = My / I + thetadot * wz  # [1] Eq. 9
    wzd = Mz / I - thetadot * wy  # [1] Eq. 10
    return xdd, rdd, thdd, wxd, wyd, wzd


# numba bakes callees and captured constants into its cache: key the cache on them (compile_cache.py)
check_compile_cache(globals())
