"""Elastohydrodynamic (EHL) film thickness of elliptical point contacts.

Hamrock-Dowson isothermal central and minimum film thickness, the lubricant
viscosity at temperature, and an optional inlet-shear-heating (thermal)
reduction factor.  Everything is vectorised numpy and SI.

References
----------
[1] Hamrock B. J., Dowson D., "Isothermal elastohydrodynamic lubrication of
    point contacts, Part III - Fully flooded results", J. Lubr. Technol. 99
    (1977) 264-276 (H_min, Eq. (63); H_c, Eq. (69)); summarised in
    Hamrock & Dowson, *Ball Bearing Lubrication*, Wiley 1981, Ch. 8, and in
    Harris & Kotzalas, *Rolling Bearing Analysis* 5th ed., Vol. 1, Ch. 7.
[2] Hamrock B. J., Brewe D. E., "Simplified solution for stresses and
    deformations", J. Lubr. Technol. 105 (1983) 171-177: k = 1.0339 (Ry/Rx)^0.636.
[3] Stachowiak G. W., Batchelor A. W., *Engineering Tribology*, Ch. 7: the
    same formulae written with the reduced radius R' (1/R' = 1/Rx + 1/Ry)
    instead of Rx.  Used here as the ``radius="reduced"`` option and as the
    published worked example the tests reproduce.
[4] Gupta P. K., Cheng H. S., Zhu D., Forster N. H., Schrand J. B.,
    "Viscoelastic effects in MIL-L-7808-type lubricant, Part I: analytical
    formulation", Tribol. Trans. 35 (1992) 269-274: inlet shear heating
    reduction factor (as quoted in Harris & Kotzalas, 5th ed., Vol. 2, Ch. 4).
[5] Zhang W., Deng S., Chen G., Cui Y., Chin. J. Aeronaut. (2016), Table 1
    (Zhang et al. 2016): eta0, alpha, beta, K of the oils 4109, 4106, 4050.

Radius convention (decided once, here)
--------------------------------------
The dimensionless groups of Hamrock & Dowson [1] use **Rx**, the effective
radius of curvature in the rolling (entrainment) direction, for U, W and to
scale H = h / Rx; ``radius="Rx"`` is the default.  Some textbooks [3] insert
the reduced radius R' = 1/(1/Rx + 1/Ry) instead.  Since h ~ R^0.46 at fixed
physical inputs, the two differ by (R'/Rx)^0.46: 28 % for a ball on a flat
(R' = Rx/2) but only 1-3 % for ball/raceway contacts where Ry >> Rx
(default case inner contact: R'/Rx = 0.970, h ratio 0.986).

Ellipticity k = a/b (transverse over rolling semi-axis, >= 1 for ball/race
contacts).  Default: the Hamrock-Brewe approximation [2], which is what the
film formulae were fitted with; the exact value from
:func:`hsbearing.models.hertz.ellipticity` may be passed instead.
"""

from __future__ import annotations

import numpy as np

__all__ = [
    "REFERENCE_TEMPERATURE",
    "viscosity_at_temperature",
    "ellipticity_hamrock_brewe",
    "dimensionless_groups",
    "central_film_thickness",
    "minimum_film_thickness",
    "thermal_loading_parameter",
    "thermal_reduction_factor",
    "film_thickness",
    "lubricant_parameters",
]

#: Reference temperature [K] of Table 1's "ambient" eta0 (Zhang et al. 2016): 27 degC,
#: the lowest (room) temperature of the seed's study (Sec. 4.1, Table 3).  See
#: docs/traction.md for the decision.
REFERENCE_TEMPERATURE = 300.15


def viscosity_at_temperature(eta0, beta, T, T_ref=REFERENCE_TEMPERATURE):
    """Ambient-pressure dynamic viscosity at temperature, exponential law.

    eta = eta0 exp(-beta (T - T_ref))   (Reynolds' viscosity-temperature law,
    with Zhang et al. 2016's Table 1 eta0 and beta [5]).

    Parameters
    ----------
    eta0 : viscosity at T_ref [Pa s]
    beta : temperature-viscosity coefficient [1/K] (= [1/degC])
    T : temperature [K]
    T_ref : reference temperature of eta0 [K] (default :data:`REFERENCE_TEMPERATURE`)

    Returns
    -------
    eta [Pa s]
    """
    return np.asarray(eta0, dtype=float) * np.exp(-np.asarray(beta, dtype=float) * (np.asarray(T, dtype=float) - T_ref))


def ellipticity_hamrock_brewe(Rx, Ry):
    """Ellipticity parameter k = a/b ~ 1.0339 (Ry/Rx)^0.636 [-] ([2]; [1] uses 1.03 (Ry/Rx)^0.64)."""
    return 1.0339 * (np.asarray(Ry, dtype=float) / np.asarray(Rx, dtype=float)) ** 0.636


def _radius(Rx, Ry, radius):
    Rx = np.asarray(Rx, dtype=float)
    if radius == "Rx":
        return Rx
    if radius == "reduced":
        return 1.0 / (1.0 / Rx + 1.0 / np.asarray(Ry, dtype=float))
    raise ValueError(f"unknown radius convention {radius!r} (Rx, reduced)")


def dimensionless_groups(eta0, u, alpha, Ep, R, Q):
    """Hamrock-Dowson dimensionless speed, material and load parameters [1].

    U = eta0 u / (E' R),  G = alpha E',  W = Q / (E' R^2)   ([1], Eqs. 4-6)

    Parameters
    ----------
    eta0 : ambient-pressure viscosity at the inlet temperature [Pa s]
    u : mean entrainment (rolling) velocity (u_1 + u_2)/2 [m/s]
    alpha : pressure-viscosity coefficient [1/Pa]
    Ep : reduced modulus E' = 2/((1-nu1^2)/E1 + (1-nu2^2)/E2) [Pa]
    R : radius used for the groups [m] (Rx in [1]; see the module docstring)
    Q : normal load [N]

    Returns
    -------
    (U, G, W) [-]
    """
    U = eta0 * u / (Ep * R)  # [1], speed parameter
    G = alpha * Ep  # [1], material parameter
    W = Q / (Ep * R * R)  # [1], load parameter
    return U, G, W


def central_film_thickness(U, G, W, k):
    """Dimensionless central film thickness H_c = h_c / R [-].

    H_c = 2.69 U^0.67 G^0.53 W^-0.067 (1 - 0.61 e^(-0.73 k))   ([1], Eq. 69)
    """
    return 2.69 * U**0.67 * G**0.53 * W**-0.067 * (1.0 - 0.61 * np.exp(-0.73 * k))  # [1], Eq. 69


def minimum_film_thickness(U, G, W, k):
    """Dimensionless minimum film thickness H_min = h_min / R [-].

    H_min = 3.63 U^0.68 G^0.49 W^-0.073 (1 - e^(-0.68 k))   ([1], Eq. 63)
    """
    return 3.63 * U**0.68 * G**0.49 * W**-0.073 * (1.0 - np.exp(-0.68 * k))  # [1], Eq. 63


def thermal_loading_parameter(eta0, beta, u, K):
    """Inlet thermal loading parameter L = beta eta0 u^2 / K [-] ([4]).

    Parameters: eta0 [Pa s], beta [1/K], u entrainment velocity [m/s],
    K thermal conductivity of the oil [W/(m K)].
    """
    return beta * eta0 * u * u / K  # [4], thermal loading factor L = -(d eta/dT) u^2 / K


def thermal_reduction_factor(L, p_max, Ep, slide_roll=0.0):
    """Inlet shear heating reduction factor phi_T = h_thermal / h_isothermal [-].

    phi_T = [1 - 13.2 (p_h/E') L^0.42] / [1 + 0.213 (1 + 2.23 s^0.83) L^0.64]   ([4])

    Parameters
    ----------
    L : thermal loading parameter, :func:`thermal_loading_parameter` [-]
    p_max : maximum Hertz pressure p_h [Pa]
    Ep : reduced modulus E' [Pa]
    slide_roll : slide-roll ratio s = |u_1 - u_2| / u (>= 0) [-]

    Returns
    -------
    phi_T in (0, 1]; clipped below at 0.05 where the fit is extrapolated far
    beyond its range (it would otherwise turn negative).
    """
    L = np.asarray(L, dtype=float)
    s = np.abs(np.asarray(slide_roll, dtype=float))
    num = 1.0 - 13.2 * (np.asarray(p_max, dtype=float) / Ep) * L**0.42  # [4]
    den = 1.0 + 0.213 * (1.0 + 2.23 * s**0.83) * L**0.64  # [4]
    return np.clip(num / den, 0.05, 1.0)


def film_thickness(Q, u, Rx, Ry, Ep, eta0, alpha, *, k=None, radius="Rx", beta=None, K=None,
                   p_max=None, slide_roll=0.0, thermal=False):
    """Central and minimum EHL film thickness of an elliptical contact [m].

    Parameters
    ----------
    Q : normal load [N]
    u : mean entrainment velocity (u_1 + u_2)/2 [m/s]
    Rx, Ry : effective radii in rolling / transverse direction [m]
    Ep : reduced modulus E' [Pa] (:func:`hsbearing.models.hertz.reduced_modulus`)
    eta0 : inlet (ambient-pressure) viscosity [Pa s], e.g. from :func:`viscosity_at_temperature`
    alpha : pressure-viscosity coefficient [1/Pa]
    k : ellipticity a/b [-]; default Hamrock-Brewe [2]
    radius : ``"Rx"`` (Hamrock-Dowson [1], default) or ``"reduced"`` (R', [3])
    thermal : apply :func:`thermal_reduction_factor` (needs beta [1/K], K [W/(m K)], p_max [Pa])

    Returns
    -------
    (h_c, h_min) [m]
    """
    R = _radius(Rx, Ry, radius)
    if k is None:
        k = ellipticity_hamrock_brewe(Rx, Ry)
    U, G, W = dimensionless_groups(eta0, u, alpha, Ep, R, Q)
    h_c = R * central_film_thickness(U, G, W, k)
    h_min = R * minimum_film_thickness(U, G, W, k)
    if thermal:
        if beta is None or K is None or p_max is None:
            raise ValueError("thermal=True needs beta, K and p_max")
        phi = thermal_reduction_factor(thermal_loading_parameter(eta0, beta, u, K), p_max, Ep, slide_roll)
        h_c, h_min = h_c * phi, h_min * phi
    return h_c, h_min


def lubricant_parameters(case):
    """Inlet viscosity and thermal data of a case's lubricant, SI.

    Precedence for the inlet viscosity eta [Pa s] at the case temperature T:

    1. ``lubricant.kinematic_viscosity`` nu (an operating value) -> eta = nu rho;
    2. ``lubricant.dynamic_viscosity`` eta0 given -> eta0 exp(-beta (T - T_ref)),
       :func:`viscosity_at_temperature` (it replaces Table 1's ambient value), T_ref =
       :data:`REFERENCE_TEMPERATURE`;
    3. otherwise ``lubricant.viscosity_law``: "walther" (default; ASTM D341 through the oil's
       specification-class viscosities at 40 and 100 degC, times ``lubricant.density``) or
       "table1" (Table 1's exponential law), :func:`hsbearing.models.viscosity.dynamic_viscosity`
       (decision: docs/traction.md, "Viscosity").

    alpha [1/Pa] is ``lubricant.pressure_viscosity_coefficient`` or the oil's; beta [1/K] and
    K [W/(m K)] are the oil's (Table 1).

    Returns
    -------
    dict with eta, alpha, beta, K, T
    """
    from hsbearing.models.traction import OILS

    lub = case.lubricant
    oil = OILS[lub.oil]
    T = lub.temperature
    if lub.kinematic_viscosity is not None:
        eta = lub.kinematic_viscosity * lub.density
    elif lub.dynamic_viscosity is not None:
        eta = float(viscosity_at_temperature(lub.dynamic_viscosity, oil.beta, T))
    else:
        from hsbearing.models.viscosity import dynamic_viscosity

        law = getattr(lub, "viscosity_law", "walther")
        eta = float(dynamic_viscosity(lub.oil, T, law=law, density=lub.density, T_ref=REFERENCE_TEMPERATURE))
    alpha = lub.pressure_viscosity_coefficient if lub.pressure_viscosity_coefficient is not None else oil.alpha
    return {"eta": float(eta), "alpha": float(alpha), "beta": oil.beta, "K": oil.K, "T": T}
