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
    pure-rolling identity, re-derived in tests/analysis/test_analysis.py).
[2] Zhang W., Deng S., Chen G., Cui Y., Chin. J. Aeronaut. 29 (2016), Sec. 5,
    Figs. 13-15 (Zhang et al. 2016): the cage slip ratio is used as a stability criterion;
    the seed does not print its formula, so the usual definition
    S_c = (omega_c,th - omega_c) / omega_c,th (e.g. Gupta, *Advanced Dynamics of
    Rolling Elements*, 1984, Ch. 6 cage slip) is used here.

[3] Jones A. B., "Ball motion and sliding friction in ball bearings", J. Basic
    Eng. 81 (1959) 1-12: raceway control hypothesis (the ball rolls without
    spinning on the controlling race); Harris & Kotzalas, 5th ed., Vol. 2
    (Advanced Concepts), Ch. 3 (ball speeds under outer-raceway control,
    omega_c / omega_i = (1 - (D/d_m) cos alpha_i) / (1 + cos(alpha_i - alpha_o))
    for a fixed outer ring).

The contact angle used for gamma is the nominal (free) contact angle
``geom.alpha0`` unless ``alpha`` is given (e.g. the loaded mean contact angle
of a quasi-static solution); see docs/analysis.md.
"""

from __future__ import annotations

import numpy as np

__all__ = ["theoretical_cage_speed", "cage_slip_ratio", "raceway_control_cage_speed"]


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

    Examples
    --------
    The default case at 14000 r/min, with the nominal 25 deg contact angle:

    >>> import math, hsbearing
    >>> from hsbearing.analysis import theoretical_cage_speed
    >>> case = hsbearing.load_case("zhang2016")
    >>> w_c = theoretical_cage_speed(case, 14000 * 2 * math.pi / 60)
    >>> print(f"{float(w_c) * 60 / (2 * math.pi):.1f} r/min")
    5686.3 r/min
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

    Examples
    --------
    A cage turning at 5700 r/min where pure rolling gives 5686 r/min runs ahead of it (negative slip):

    >>> from hsbearing.analysis import cage_slip_ratio
    >>> print(f"{float(cage_slip_ratio(5700.0, 5686.3)) * 100:.2f} %")
    -0.24 %
    """
    wc = np.asarray(cage_speed, dtype=float)
    th = np.asarray(theoretical, dtype=float)
    with np.errstate(divide="ignore", invalid="ignore"):
        s = np.where(th != 0.0, (th - wc) / np.where(th != 0.0, th, 1.0), np.nan)  # [2] Sec. 5, slip definition
    return s.item() if np.ndim(s) == 0 else s


def raceway_control_cage_speed(geom, inner_speed, outer_speed, alpha_i, alpha_o, control: str = "outer"):
    """Cage (ball orbital) speed under raceway control with the loaded contact angles [rad/s].

    Kinematics of one ball in the cage frame, meridian plane (x axial, r
    radial), contact points (D/2)(sin alpha_o, cos alpha_o) at the outer race
    and -(D/2)(sin alpha_i, cos alpha_i) at the inner race, ball angular
    velocity (w_x, w_r): rolling without slip in the rolling direction at both
    contacts and no spin at the controlling contact ([3], Jones 1959) give
    three linear equations in (omega_c, w_x, w_r), solved here.  For a fixed
    outer ring and outer control the solution is the closed form
    omega_c / omega_i = (1 - (D/d_m) cos alpha_i) / (1 + cos(alpha_i - alpha_o))
    ([3], Harris & Kotzalas Vol. 2 Ch. 3), and for alpha_i = alpha_o it is the
    pure-rolling speed of :func:`theoretical_cage_speed`.

    Parameters
    ----------
    geom : Geometry or Case
    inner_speed, outer_speed : float
        Ring speeds about the bearing axis [rad/s].
    alpha_i, alpha_o : float or array_like
        Loaded inner and outer contact angles [rad] (broadcast together).
    control : {"outer", "inner"}
        The race at which the ball does not spin.

    Returns
    -------
    float or numpy.ndarray
        omega_c [rad/s].
    """
    if not hasattr(geom, "dm"):
        from hsbearing.models.geometry import derive

        geom = derive(geom)
    if control not in ("outer", "inner"):
        raise ValueError(f"control must be 'outer' or 'inner', not {control!r}")
    ai, ao = np.broadcast_arrays(np.asarray(alpha_i, float), np.asarray(alpha_o, float))
    h, R = 0.5 * geom.D, 0.5 * geom.dm
    wi, wo = float(inner_speed), float(outer_speed)
    ci, si, co, so = np.cos(ai), np.sin(ai), np.cos(ao), np.sin(ao)
    A = np.zeros(ai.shape + (3, 3))
    b = np.zeros(ai.shape + (3,))
    # unknowns (omega_c, w_x, w_r); circumferential surface speed of the ball = w_x c_r - w_r c_x
    A[..., 0, :] = np.stack([R + h * co, h * co, -h * so], -1)  # rolling at the outer contact [3]
    b[..., 0] = wo * (R + h * co)
    A[..., 1, :] = np.stack([R - h * ci, -h * ci, h * si], -1)  # rolling at the inner contact [3]
    b[..., 1] = wi * (R - h * ci)
    if control == "outer":  # no spin at the outer contact: (w_ball - w_ring_o) . n_o = 0  [3]
        A[..., 2, :] = np.stack([so, so, co], -1)
        b[..., 2] = wo * so
    else:  # no spin at the inner contact
        A[..., 2, :] = np.stack([si, si, ci], -1)
        b[..., 2] = wi * si
    wc = np.linalg.solve(A, b[..., None])[..., 0, 0]
    return wc.item() if np.ndim(wc) == 0 else wc
