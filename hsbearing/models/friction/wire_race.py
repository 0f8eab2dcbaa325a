"""Wire-race ball bearing: preload magnitude versus starting torque (Shan et al. 2010).

A wire-race bearing carries its balls on four hardened wires, two in the
inner ring and two in the outer ring; each ball touches the four wires at the
contact angle alpha (+-alpha about the radial plane), so the contacts form two
diagonals: contacts 1 (inner wire) and 3 (outer wire) on one diagonal,
contacts 2 (inner) and 4 (outer) on the other.  The preload delta is set by
grinding the shims between the ring halves; at start-up the balls roll
without sliding and the bearing torque is the sum of the rolling-resistance
couples M_r = zeta F_N of the 4 Z contacts [1].

Model chain (all pure, vectorised functions, one per equation)::

    geometry (wire_contact_radii) -> K_i, K_o (Eqs. 5-6, exact Hertz)
    preload delta --(Eq. 7 + Eq. 10, solved for F1)--> F1..F4, delta1..delta4, p_max1..p_max4
    F_j --(Eqs. 2-4)--> rolling torque M_sc;   + M_u (Eq. 11) -> starting torque M_s
    measured torques --(Eqs. 11-13)--> zeta, M_u

References
----------
[1] Shan X.-B., Wang L.-L., Xie T., Chen W.-S., "A simple approach for
    determining the preload of a wire race ball bearing", J. Zhejiang Univ.
    Sci. A 11(8) (2010), doi:10.1631/jzus.A0900583 (Shan et al. 2010).  Eqs. 1-13,
    Tables 1-3, Fig. 9a.
[2] Shan X.-B., Xie T., Chen W.-S., "A new method for determining the preload
    in a wire race ball bearing", Tribol. Int. 40(5) (2007) 869-875 -- where
    [1] defines E*, R_e and F_2(e) of Eqs. 5-6 (not available to us; see
    docs/validation/wire_race.md for what Table 2 of [1] implies).
[3] Johnson K. L., *Contact Mechanics*, Cambridge 1985, Sec. 4.2
    (delta = (9 P^2 / (16 E*^2 R_e))^(1/3) F_2(e), i.e. P = K delta^1.5 with
    K = sqrt(16 E*^2 R_e / (9 F_2(e)^3)) -- Eqs. 5-6 of [1] print E* without
    the square, a dimensional slip).
[4] Hamrock B. J., Dowson D., *Ball Bearing Lubrication*, Wiley 1981, Ch. 3
    (the exact elliptical solution in :mod:`hsbearing.models.hertz`).

Conventions and decisions (details in docs/validation/wire_race.md)
-------------------------------------------------------------------
* alpha is measured from the radial plane (Harris convention, as everywhere
  in hsbearing).  The framework weight G_o rests on the outer ring and loads
  the 2-4 diagonal: axial equilibrium of the outer ring is
  Z (F2 - F1) sin(alpha) = G_o.  Eq. 7 of [1] is printed as
  Z (F1 sin(alpha) - F2 cos(alpha)) + G_o = 0; both forms agree at the
  paper's alpha = pi/4 and only the symmetric one is an equilibrium for
  another angle (both diagonals make the same angle with the axis), so
  :func:`framework_equilibrium_F2` implements the symmetric form and the
  printed one is kept as :func:`framework_equilibrium_residual_printed` for
  the tests.
* Wire geometry: a round wire of diameter d_w (the as-built state of [1],
  "non-conforming contact"); optionally a ground track of radius
  f_w D (``bearing.wire_groove_conformity``).  The wire axis is a circle about
  the bearing axis, so in the rolling (circumferential) direction the inner
  wire is convex and the outer wire concave (torus normal curvature).
* K_i, K_o come from the exact elliptic-integral Hertz solution
  (:func:`hsbearing.models.hertz.point_contact`) instead of Johnson's
  F_2(e) chart fit; the two differ by 0.4 % here (tests/systems/wire_race/test_wire_race.py).
  They are 15-16 % above the K implied by Table 2 of [1]; no reading of
  Table 1 reproduces both its deformation and its pressure columns (docs).
* zeta is only defined together with a force model: measured torques fix
  zeta * (F1 + F2).  Fit it (Eqs. 12-13, :func:`fit_rolling_resistance`) with
  the forces of the same stiffness you predict with; the bundled case does.

This module holds the closed forms (Eqs. 1-10); the case-level contacts, the preload sweep, the fit of
zeta and M_u, the preload window and ``hsbearing preload`` are the wire-race system,
:mod:`hsbearing.systems.wire_race`.
"""

from __future__ import annotations

import math

import numpy as np
from scipy.optimize import brentq

from hsbearing.models.hertz import point_contact

__all__ = [
    "rolling_resistance_moment",
    "bearing_rolling_torque",
    "starting_torque",
    "wire_contact_radii",
    "contact_stiffness",
    "framework_equilibrium_F2",
    "framework_equilibrium_residual_printed",
    "contact_forces_from_torque",
    "contact_deformation",
    "preload_from_forces",
    "preload_from_torque",
    "contact_forces_from_preload",
]


# ----------------------------------------------------------------------------- Eqs. 1-4: torque


def rolling_resistance_moment(zeta, F_N):
    """Rolling-resistance couple at one contact, M_r = zeta F_N.

    Parameters
    ----------
    zeta : coefficient of rolling frictional resistance [m]
    F_N : normal contact force [N]

    Returns
    -------
    M_r [N m].  [1], Eq. 1 (and Eq. 2 for contact j of ball i).
    """
    return np.asarray(zeta, dtype=float) * np.asarray(F_N, dtype=float)  # [1], Eq. 1 / Eq. 2


def bearing_rolling_torque(zeta, Z, F1, F2, F3, F4, alpha):
    """Bearing rolling-resistance torque M_sc = zeta Z (F1 + F2 + F3 + F4) cos(alpha).

    All Z balls carry the same four forces (axisymmetric preload and framework
    weight).  Parameters: zeta [m], Z [-], F1..F4 [N], alpha [rad].
    Returns the torque [N m] about the bearing axis -- [1], Eqs. 3-4 (the
    "calculated bearing torque" M_sc of Table 2).
    """
    F = np.asarray(F1, float) + np.asarray(F2, float) + np.asarray(F3, float) + np.asarray(F4, float)
    return zeta * Z * F * np.cos(alpha)  # [1], Eq. 4 (= Eq. 3 with F_ij = F_j for every ball i)


def starting_torque(zeta, Z, F1, F2, alpha, M_u=0.0):
    """Starting torque M_s = 2 zeta Z (F1 + F2) cos(alpha) + M_u (with F3 = F1, F4 = F2).

    Parameters: zeta [m], Z [-], F1, F2 [N], alpha [rad], M_u torque of the
    factors the model leaves out [N m].  Returns [N m].  [1], Eq. 11.
    """
    return 2.0 * zeta * Z * (np.asarray(F1, float) + np.asarray(F2, float)) * np.cos(alpha) + M_u  # [1], Eq. 11


# ----------------------------------------------------------------------------- Eqs. 5-6: contact stiffness


def wire_contact_radii(D, d_w, d_m, alpha, groove_conformity=None):
    """Effective radii (Rx along the wire = rolling direction, Ry across) of the ball-wire contacts.

    Parameters
    ----------
    D : ball diameter [m];  d_w : wire diameter [m];  d_m : pitch diameter [m]
    alpha : contact angle from the radial plane [rad]
    groove_conformity : None for a round wire (cross-section convex, radius
        d_w/2), else f_w = r_track / D of a ground track (concave, > 0.5).

    Returns
    -------
    (Rx_i, Ry_i, Rx_o, Ry_o) [m] for the inner-ring and outer-ring wires.

    Notes
    -----
    Curvature sum of a sphere (1/r_b both ways) and a torus ([4], Ch. 3,
    Eq. 3.27 convention, convex positive).  Along the wire, the torus normal
    curvature at a contact point at distance rho from the bearing axis whose
    normal makes the angle alpha with the radial direction is cos(alpha)/rho
    -- convex on the inner wires (normal pointing outwards, rho = d_m/2 -
    r_b cos(alpha)), concave on the outer wires (rho = d_m/2 + r_b
    cos(alpha)).  Across the wire: 1/r_w (round) or -1/(f_w D) (track).
    """
    r_b = 0.5 * D
    ca = np.cos(alpha)
    rho_i = 0.5 * d_m - r_b * ca  # contact-point distance from the axis, inner wire
    rho_o = 0.5 * d_m + r_b * ca  # outer wire
    kx_i = 1.0 / r_b + ca / rho_i  # torus normal curvature, convex inner wire
    kx_o = 1.0 / r_b - ca / rho_o  # concave outer wire
    if groove_conformity is None:
        ky = 1.0 / r_b + 2.0 / d_w  # round wire: convex cross-section
    else:
        ky = 1.0 / r_b - 1.0 / (groove_conformity * D)  # ground track, conforming cross-section
    return 1.0 / kx_i, 1.0 / ky, 1.0 / kx_o, 1.0 / ky


def contact_stiffness(Rx, Ry, E_ball, nu_ball, E_wire, nu_wire):
    """Load-deflection constant K of a ball-wire contact, F = K delta^1.5.

    [1], Eqs. 5-6 write K = sqrt(16 E* R_e / (9 F_2(e)^3)) with Johnson's
    chart factor F_2(e) ([3], Sec. 4.2; E* must be squared for the units).
    Here K is the exact elliptic-integral value of
    :func:`hsbearing.models.hertz.point_contact` (K = pi k E' sqrt(2 E(e) R /
    (9 K(e)^3)), [4] Ch. 3), which Johnson's F_2 approximates.

    Parameters: Rx, Ry [m]; E_ball, E_wire [Pa]; nu_ball, nu_wire [-].
    Returns K [N/m^1.5].
    """
    a, b = np.minimum(Rx, Ry), np.maximum(Rx, Ry)  # point_contact labels the smaller radius x
    return point_contact(a, b, 1.0, E_ball, nu_ball, E_wire, nu_wire).K  # [1], Eqs. 5-6


# ----------------------------------------------------------------------------- Eqs. 7-10


def framework_equilibrium_F2(F1, Z, alpha, G_o):
    """Force F2 (= F4) of the loaded diagonal given F1 (= F3), from the outer ring's axial equilibrium.

    Z (F2 - F1) sin(alpha) = G_o, the symmetric form of [1], Eq. 7 (equal to
    the printed Z (F1 sin(alpha) - F2 cos(alpha)) + G_o = 0 at alpha = pi/4,
    the paper's angle; see the module notes).

    Parameters: F1 [N], Z [-], alpha [rad], G_o outer framework weight [N].
    Returns F2 [N].
    """
    return np.asarray(F1, float) + G_o / (Z * np.sin(alpha))  # [1], Eq. 7 (symmetric form)


def framework_equilibrium_residual_printed(F1, F2, Z, alpha, G_o):
    """Residual of [1], Eq. 7 exactly as printed: Z (F1 sin(alpha) - F2 cos(alpha)) + G_o [N]."""
    return Z * (np.asarray(F1, float) * np.sin(alpha) - np.asarray(F2, float) * np.cos(alpha)) + G_o  # [1], Eq. 7


def contact_forces_from_torque(M_s, zeta, Z, alpha, G_o):
    """Contact forces (F1, F2) that produce the rolling torque M_s under the framework weight G_o.

    Solves Eq. 4 (M_s = 2 zeta Z (F1 + F2) cos(alpha)) with the equilibrium
    of :func:`framework_equilibrium_F2`.  At alpha = pi/4 this is [1],
    Eqs. 8-9: F1 = (M_s/(2 zeta) - G_o) / (Z (sin + cos)),
    F2 = (M_s tan(alpha)/(2 zeta) + G_o) / (Z (sin + cos)).

    Parameters: M_s rolling torque [N m] (without M_u), zeta [m], Z [-],
    alpha [rad], G_o [N].  Returns (F1, F2) [N].
    """
    S = np.asarray(M_s, float) / (2.0 * zeta * Z * np.cos(alpha))  # F1 + F2 from [1], Eq. 4
    dF = G_o / (Z * np.sin(alpha))  # F2 - F1, [1], Eq. 7
    F1 = 0.5 * (S - dF)  # [1], Eq. 8 (symmetric Eq. 7)
    F2 = 0.5 * (S + dF)  # [1], Eq. 9
    return F1, F2


def contact_deformation(F, K):
    """Hertz contact deformation delta_j = (F_j / K)^(2/3) [m] from F_j [N] and K [N/m^1.5] ([1], Eq. 4 inverted)."""
    return (np.maximum(np.asarray(F, float), 0.0) / K) ** (2.0 / 3.0)  # [1], Eq. 4: F_j = K delta_j^1.5


def preload_from_forces(F1, F2, K_i, K_o, alpha, F3=None, F4=None):
    """Preload magnitude delta = [sum_j (F_j / K_j)^(2/3)] cos(alpha).

    Parameters: F1, F2 (inner wires), F3, F4 (outer wires; default F1, F2)
    [N]; K_i, K_o [N/m^1.5]; alpha [rad].  Returns delta [m].  [1], Eq. 10
    (first line).
    """
    F3 = F1 if F3 is None else F3
    F4 = F2 if F4 is None else F4
    return (contact_deformation(F1, K_i) + contact_deformation(F2, K_i)
            + contact_deformation(F3, K_o) + contact_deformation(F4, K_o)) * np.cos(alpha)  # [1], Eq. 10


def preload_from_torque(M_s, zeta, Z, alpha, G_o, K_i, K_o):
    """Preload magnitude delta [m] that gives the rolling torque M_s [N m] ([1], Eq. 10, second line).

    Eqs. 8-9 substituted in Eq. 10.  Raises ValueError if M_s is below
    2 zeta G_o / tan(alpha) (the 1-3 diagonal would have to pull).
    """
    F1, F2 = contact_forces_from_torque(M_s, zeta, Z, alpha, G_o)
    if np.any(np.asarray(F1) < 0):
        raise ValueError("torque too small: the 1-3 diagonal would carry a negative force")
    return preload_from_forces(F1, F2, K_i, K_o, alpha)  # [1], Eq. 10


def contact_forces_from_preload(delta, Z, alpha, G_o, K_i, K_o):
    """Contact forces (F1, F2) [N] for a preload delta [m]: Eq. 10 with Eq. 7, solved for F1.

    delta(F1) = cos(alpha) (K_i^-2/3 + K_o^-2/3) (F1^2/3 + F2(F1)^2/3) is
    increasing in F1, so each preload has one root (brentq).  Below the
    preload delta_0 = delta(F1 = 0) the 1-3 diagonal is unloaded: F1 = 0 is
    returned and F2 = G_o / (Z sin(alpha)) (the weight alone; the
    remaining preload is a gap on the 1-3 diagonal).

    Parameters: delta [m] (scalar or array), Z [-], alpha [rad], G_o [N],
    K_i, K_o [N/m^1.5].  Returns (F1, F2) arrays shaped like delta.
    """
    delta = np.asarray(delta, dtype=float)
    c = math.cos(alpha) * (K_i ** (-2.0 / 3.0) + K_o ** (-2.0 / 3.0))

    def eq10(F1, target):
        F2 = framework_equilibrium_F2(F1, Z, alpha, G_o)
        return c * (F1 ** (2.0 / 3.0) + F2 ** (2.0 / 3.0)) - target  # [1], Eq. 10

    F1 = np.zeros(delta.shape)
    flat = F1.reshape(-1)
    for n, d in enumerate(delta.reshape(-1)):
        if not np.isfinite(d) or d < 0:
            raise ValueError(f"preload must be finite and >= 0, got {d}")
        if eq10(0.0, d) >= 0.0:
            flat[n] = 0.0  # 1-3 diagonal unloaded
            continue
        if G_o == 0.0:
            flat[n] = (0.5 * d / c) ** 1.5  # Eq. 10 with F1 = F2, closed form
            continue
        hi = (d / c) ** 1.5 * (1.0 + 1e-9)  # F1^(2/3) <= d/c
        flat[n] = hi if eq10(hi, d) <= 0.0 else brentq(eq10, 0.0, hi, args=(d,), xtol=1e-300, rtol=1e-13)
    F2 = framework_equilibrium_F2(F1, Z, alpha, G_o)
    return F1, F2


# ----------------------------------------------------------------------------- Eqs. 11-13: fit
