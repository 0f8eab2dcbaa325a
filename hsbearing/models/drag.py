"""Drag of the balls in the air-oil mixture of the bearing cavity (F_D of Zhang et al. 2016, Eq. 7).

References
----------
[1] Harris T. A., Kotzalas M. N., *Rolling Bearing Analysis*, 5th ed., Vol. 2
    (*Advanced Concepts of Bearing Technology*), Ch. 3/5: ball drag in the
    air-oil mixture F_D = (pi/32) C_D rho_e D^2 (d_m omega_m)^1.95.  Read here, in SI,
    as 1/2 C_D rho_e (pi D^2/4) v^1.95 with v = d_m omega_m / 2 the ball-centre
    orbital speed; that is (pi/8) 2^-1.95 = pi/30.9 instead of pi/32, i.e. 3.5 %
    above the printed coefficient.  The 1.95 exponent makes the formula
    unit-dependent anyway; the drag is a minor term here (docs/validation/cage_whirl.md).
[2] Zhang W. et al., Chin. J. Aeronaut. 29 (2016), Eq. (7) (F_D).
"""

from __future__ import annotations

import math

from numba import njit

from hsbearing.compile_cache import check_compile_cache

__all__ = ["mixture_density", "ball_drag_force"]

#: air density at the bearing temperature is small; 1.1 kg/m^3 (about 50-130 degC) is used.
AIR_DENSITY = 1.1


def mixture_density(oil_density: float, oil_volume_fraction: float, air_density: float = AIR_DENSITY) -> float:
    """Effective density of the air-oil mixture rho_e = X rho_oil + (1 - X) rho_air [kg/m^3] ([1])."""
    return oil_volume_fraction * oil_density + (1.0 - oil_volume_fraction) * air_density


@njit(cache=True)
def ball_drag_force(v, D, rho_e, C_D, v0):
    """Drag on a ball moving at speed v through the mixture [N], opposite to v.

    F_D = 1/2 C_D rho_e (pi D^2 / 4) v |v|^0.95 ([1]: exponent 1.95); |v| is
    regularised as sqrt(v^2 + v0^2) so that the force is smooth at v = 0.
    Returns the signed force along the direction of v (negative for v > 0).
    """
    va = math.sqrt(v * v + v0 * v0)
    return -0.5 * C_D * rho_e * 0.25 * math.pi * D * D * v * va**0.95  # [1]


# numba bakes callees and captured constants into its cache: key the cache on them (compile_cache.py)
check_compile_cache(globals())
