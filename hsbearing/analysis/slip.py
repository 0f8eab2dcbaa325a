"""Cage slip ratio and the theoretical (epicyclic, pure-rolling) cage speed.

References
----------
[1] Harris T. A., Kotzalas M. N., *Rolling Bearing Analysis*, 5th ed., Vol. 1
    (Essential Concepts of Bearing Technology), CRC 2006, Ch. 8 "Rolling
    bearing kinematics", cage angular speed for rolling without slip at both
    race contacts: omega_c = 1/2 [omega_i (1 - gamma) + omega_o (1 + gamma)],
    gamma = D cos(alpha) / d_m (cited below as "Eq. 8.21"; the equation
    number is from our reading of the 5th edition and could not be checked
    against the printed page here -- the formula itself is the epicyclic
    pure-rolling identity, re-derived in tests/test_analysis.py).
[2] Zhang W., Deng S., Chen G., Cui Y., Chin. J. Aeronaut. 29 (2016), Sec. 5,
    Figs. 13-15 (seed 004): the cage slip ratio is used as a stability criterion;
    the seed does not print its formula, so the usual definition
    S_c = (omega_c,th - omega_c) / omega_c,th (e.g. Gupta, *Advanced Dynamics of
    Rolling Elements*, 1984, Ch. 6 cage slip) is used here.

The contact angle used for gamma is the nominal (free) contact angle
``geom.alpha0`` unless ``alpha`` is given (e.g. the loaded mean contact angle
of a quasi-static solution); see docs/analysis.md.
"""

from __future__ import annotations

import numpy as np

__all__ = ["theoretical_cage_speed", "cage_slip_ratio"]


def theoretical_cage_speed(geom, inner_speed, outer_speed=0.0, alpha=None):
    """Epicyclic cage speed omega_c,th for rolling without slip [rad/s].

    Parameters
    ----------
    geom : hsbearing.models.geometry.Geometry or hsbearing.case.Case
        Bearing geometry (``D`` [m], ``dm`` [m], ``alpha0`` [rad]); a Case is derived first.
    inner_speed, outer_speed : float or array_like
        Inner- and outer-ring angular speeds about the bearing axis [rad/s].
    alpha : float or array_like, optional
        Contact angle used in gamma = D cos(alpha)/d_m [rad]; default: the
        nominal contact angle ``geom.alpha0``.

    Returns
    -------
    numpy.ndarray or float
        omega_c,th = 1/2 [omega_i (1 - gamma) + omega_o (1 + gamma)] [rad/s]
        ([1], Eq. 8.21), broadcast over the inputs.
    """
    if not hasattr(geom, "dm"):
        from hsbearing.models.geometry import derive

        geom = derive(geom)
    a = geom.alpha0 if alpha is None else np.asarray(alpha, dtype=float)
    gamma = geom.D * np.cos(a) / geom.dm  # [1], Eq. 8.21 (gamma = D cos(alpha)/d_m)
    wi = np.asarray(inner_speed, dtype=float)
    wo = np.asarray(outer_speed, dtype=float)
    out = 0.5 * (wi * (1.0 - gamma) + wo * (1.0 + gamma))  # [1], Eq. 8.21
    return out.item() if np.ndim(out) == 0 else out


def cage_slip_ratio(cage_speed, theoretical):
    """Cage slip ratio S_c = (omega_c,th - omega_c) / omega_c,th [1].

    Positive when the cage lags the pure-rolling speed (the usual high-speed,
    light-load skidding case).  Vectorised; NaN where ``theoretical`` is 0.

    Parameters
    ----------
    cage_speed : float or array_like
        Cage angular speed omega_c about the bearing axis [rad/s].
    theoretical : float or array_like
        Theoretical cage speed omega_c,th [rad/s] (:func:`theoretical_cage_speed`).

    Returns
    -------
    numpy.ndarray or float
        Dimensionless slip ratio ([2], Sec. 5; definition as in Gupta 1984 Ch. 6).
    """
    wc = np.asarray(cage_speed, dtype=float)
    th = np.asarray(theoretical, dtype=float)
    with np.errstate(divide="ignore", invalid="ignore"):
        s = np.where(th != 0.0, (th - wc) / np.where(th != 0.0, th, 1.0), np.nan)  # [2] Sec. 5, slip definition
    return s.item() if np.ndim(s) == 0 else s
