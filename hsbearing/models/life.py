"""Rolling-contact fatigue life of radial ball bearings: ISO 281 and ISO/TS 16281.

Pure functions, numpy, no case objects.  The standards write their formulas in
N and mm (the numerical constants 98.1, f_c, f_0 carry those units); the
functions below take SI (N, m, r/min where the standard uses r/min) and convert
to mm internally, as stated in each docstring.

References
----------
[1] ISO 281:2007, *Rolling bearings -- Dynamic load ratings and rating life*.
    Clause 5 (radial ball bearings): 5.1.1 basic dynamic radial load rating
    C_r = b_m f_c (i cos alpha)^0.7 Z^(2/3) D_w^1.8 (D_w <= 25.4 mm) and
    3.647 b_m f_c (i cos alpha)^0.7 Z^(2/3) D_w^1.4 (D_w > 25.4 mm);
    Table 1 (b_m = 1.3 for radial ball bearings), Table 2 (f_c, column
    "single-row radial contact groove and angular contact groove ball
    bearings"); 5.2 dynamic equivalent radial load P_r = X F_r + Y F_a with
    Table 3 (X, Y, e) and Table 4 (f_0 in "f_0 F_a / C_0r"); 5.3 basic rating
    life L_10 = (C_r / P_r)^3 [10^6 rev].  Clause 9 (modified rating life):
    L_nm = a_1 a_ISO L_10 (9.1), a_ISO for radial ball bearings (9.3.2,
    Eqs. for 0.1 <= kappa < 0.4, 0.4 <= kappa < 1, 1 <= kappa <= 4, a_ISO <= 50),
    kappa = nu / nu_1 with the reference viscosity
    nu_1 = 45000 n^-0.83 D_pw^-0.5 (n < 1000 r/min), 4500 n^-0.5 D_pw^-0.5
    (n >= 1000 r/min) (9.3.3); Table 13 contamination factor e_C; Annex B.3.2.3
    fatigue load limit of ball bearings C_u ~ C_0 / 22 (D_pw <= 100 mm).
[2] ISO 76:2006, *Rolling bearings -- Static load ratings*: C_0r = f_0 i Z D_w^2
    cos alpha (Table 1, same f_0 as [1] Table 4), based on 4 200 MPa at the
    centre of the most heavily loaded ball contact.
[3] ISO/TS 16281:2008, *Methods for calculating the modified reference rating life for universally loaded bearings*,
    4.3 (ball bearings): basic dynamic
    load rating of the inner and outer raceway contact
    Q_ci = 98.1 (2 r_i/(2 r_i - D_w))^0.41 (1 - gamma)^1.39/(1 + gamma)^(1/3) (gamma/cos alpha)^0.3 D_w^1.8 Z^(-1/3),
    Q_ce = 98.1 (2 r_e/(2 r_e - D_w))^0.41 (1 + gamma)^1.39/(1 - gamma)^(1/3) (gamma/cos alpha)^0.3 D_w^1.8 Z^(-1/3);
    dynamic equivalent load of the ring rotating relative to the load
    Q_e = (1/Z sum Q_j^3)^(1/3), of the ring stationary relative to the load
    Q_e = (1/Z sum Q_j^(10/3))^(3/10); reference rating life
    L_10r = [(Q_ci/Q_ei)^(-10/3) + (Q_ce/Q_ee)^(-10/3)]^(-9/10)  [10^6 rev].
    (Lundberg & Palmgren, Acta Polytech. Mech. Eng. Ser. 1 (1947); Harris &
    Kotzalas, *Rolling Bearing Analysis* 5th ed., Vol. 2, Ch. 8, Eqs. 8.14-8.32
    give the same raceway ratings with 98.1 in N, mm.)
[4] ISO/TR 1281-1:2008, explanatory notes on ISO 281: f_c of [1] Table 2 is
    the Lundberg-Palmgren expression computed with r_i = r_e = 0.52 D_w (used
    here only to cross-check the transcribed table, tests/models/test_life.py).

Reading decided here (docs/life.md): the contact angle of each ball enters its
own Q_c in ISO/TS 16281 (speed effects change alpha_i and alpha_o); the ring
life ratio is then (1/Z sum (Q_j/Q_c,j)^p)^(1/p), which is the standard's
formula when all Q_c,j are equal.
"""

from __future__ import annotations

import math

import numpy as np

__all__ = [
    "FC_GAMMA", "FC_RADIAL_BALL", "F0_GAMMA", "F0_RADIAL_BALL",
    "factor_fc", "factor_fc_lundberg_palmgren", "factor_f0",
    "basic_dynamic_load_rating", "basic_static_load_rating",
    "equivalent_load_factors", "dynamic_equivalent_radial_load",
    "basic_rating_life", "reference_viscosity", "viscosity_ratio",
    "fatigue_load_limit", "life_modification_factor", "modified_rating_life",
    "raceway_contact_ratings", "equivalent_contact_load", "reference_rating_life",
    "life_in_hours",
]

M_TO_MM = 1e3

#: [1] Table 2: gamma = D_w cos(alpha) / D_pw and f_c of single-row radial contact groove
#: and angular contact groove ball bearings (N, mm).
FC_GAMMA = np.array([0.01, 0.02, 0.03, 0.04, 0.05, 0.06, 0.07, 0.08, 0.09, 0.10, 0.12, 0.14, 0.16, 0.18, 0.20,
                     0.22, 0.24, 0.26, 0.28, 0.30, 0.32, 0.34, 0.36, 0.38, 0.40])
FC_RADIAL_BALL = np.array([29.1, 35.8, 40.3, 43.8, 46.7, 49.1, 51.1, 52.8, 54.3, 55.5, 57.5, 58.8, 59.6, 59.9, 59.9,
                           59.6, 59.0, 58.2, 57.1, 56.0, 54.6, 53.2, 51.7, 50.0, 48.4])

#: [1] Table 4 / [2] Table 1: f_0 of radial contact groove and angular contact groove ball bearings (N, mm).
F0_GAMMA = np.round(np.arange(0.0, 0.405, 0.01), 2)
F0_RADIAL_BALL = np.array([14.7, 14.9, 15.1, 15.3, 15.5, 15.7, 15.9, 16.1, 16.3, 16.5, 16.4, 16.1, 15.9, 15.6, 15.4,
                           15.2, 14.9, 14.7, 14.4, 14.2, 14.0, 13.7, 13.5, 13.2, 13.0, 12.8, 12.5, 12.3, 12.1, 11.8,
                           11.6, 11.4, 11.2, 10.9, 10.7, 10.5, 10.3, 10.0, 9.8, 9.6, 9.4])

#: [1] Table 3, single-row angular contact groove ball bearings with alpha >= 20 deg: alpha [deg] -> (e, X, Y)
#: for F_a/F_r > e (F_a/F_r <= e: X = 1, Y = 0).
_AC_XY = {20: (0.57, 0.43, 1.00), 25: (0.68, 0.41, 0.87), 30: (0.80, 0.39, 0.76), 35: (0.95, 0.37, 0.66),
          40: (1.14, 0.35, 0.57), 45: (1.34, 0.33, 0.50)}
#: [1] Table 3, radial contact groove ball bearings (single row): f_0 F_a / C_0r -> (e, Y), X = 0.56.
_DG_ARG = np.array([0.172, 0.345, 0.689, 1.03, 1.38, 2.07, 3.45, 5.17, 6.89])
_DG_E = np.array([0.19, 0.22, 0.26, 0.28, 0.30, 0.34, 0.38, 0.42, 0.44])
_DG_Y = np.array([2.30, 1.99, 1.71, 1.55, 1.45, 1.31, 1.15, 1.04, 1.00])
#: [1] Table 3, angular contact alpha = 15 deg (single row): i F_a / C_0r -> (e, Y), X = 0.44.
_AC15_ARG = np.array([0.015, 0.029, 0.058, 0.087, 0.12, 0.17, 0.29, 0.44, 0.58])
_AC15_E = np.array([0.38, 0.40, 0.43, 0.46, 0.47, 0.50, 0.55, 0.56, 0.56])
_AC15_Y = np.array([1.47, 1.40, 1.30, 1.23, 1.19, 1.12, 1.02, 1.00, 1.00])


def _gamma(Dw, Dpw, alpha):
    return Dw * math.cos(alpha) / Dpw


def factor_fc(gamma):
    """Factor f_c [N/mm^1.8] of [1] Table 2 (radial/angular contact groove ball bearings), linear interpolation.

    Parameters
    ----------
    gamma : D_w cos(alpha) / D_pw [-], 0.01 <= gamma <= 0.40 (the table's range; outside: ValueError)
    """
    g = float(gamma)
    if not FC_GAMMA[0] - 1e-12 <= g <= FC_GAMMA[-1] + 1e-12:
        raise ValueError(f"gamma = {g:.4g} outside ISO 281 Table 2 (0.01..0.40)")
    return float(np.interp(g, FC_GAMMA, FC_RADIAL_BALL))  # [1], Table 2 (linear interpolation allowed)


def factor_fc_lundberg_palmgren(gamma, fi=0.52, fe=0.52, reduction=1.0):
    """Closed-form f_c [N/mm^1.8] of Lundberg-Palmgren as in [4] (cross-check of [1] Table 2).

    f_c = 39.9 lambda gamma^0.3 (1 - gamma)^1.39 / (1 + gamma)^(1/3) (2 f_i/(2 f_i - 1))^0.41
          x {1 + [1.04 ((1 - gamma)/(1 + gamma))^1.72 (f_i (2 f_e - 1) / (f_e (2 f_i - 1)))^0.41]^(10/3)}^(-0.3)

    ``reduction`` is the factor lambda (reduction for edge stresses and
    manufacturing); [1] Table 2 corresponds to a constant lambda ~ 0.957
    (measured, tests/models/test_life.py).
    """
    g = np.asarray(gamma, dtype=float)
    base = 39.9 * reduction * g**0.3 * (1 - g) ** 1.39 / (1 + g) ** (1 / 3) * (2 * fi / (2 * fi - 1)) ** 0.41
    ratio = 1.04 * ((1 - g) / (1 + g)) ** 1.72 * (fi * (2 * fe - 1) / (fe * (2 * fi - 1))) ** 0.41
    return base * (1 + ratio ** (10 / 3)) ** -0.3  # [4]


def factor_f0(gamma):
    """Factor f_0 [N/mm^2] of [2] Table 1 / [1] Table 4 (radial/angular contact groove ball bearings)."""
    g = float(gamma)
    if not 0.0 <= g <= F0_GAMMA[-1] + 1e-12:
        raise ValueError(f"gamma = {g:.4g} outside ISO 76 Table 1 (0..0.40)")
    return float(np.interp(g, F0_GAMMA, F0_RADIAL_BALL))  # [2], Table 1


def basic_dynamic_load_rating(Z, Dw, Dpw, alpha, rows=1, bm=1.3):
    """Basic dynamic radial load rating C_r [N] of a radial ball bearing ([1] 5.1.1).

    C_r = b_m f_c (i cos alpha)^0.7 Z^(2/3) D_w^1.8               (D_w <= 25.4 mm)
    C_r = 3.647 b_m f_c (i cos alpha)^0.7 Z^(2/3) D_w^1.4         (D_w > 25.4 mm)

    Parameters
    ----------
    Z : balls per row [-].  Dw : ball diameter [m].  Dpw : pitch diameter [m].
    alpha : nominal contact angle [rad].  rows : i [-].  bm : rating factor, [1] Table 1 (1.3).
    """
    fc = factor_fc(_gamma(Dw, Dpw, alpha))
    dw = Dw * M_TO_MM
    if dw <= 25.4:
        return bm * fc * (rows * math.cos(alpha)) ** 0.7 * Z ** (2 / 3) * dw**1.8  # [1] 5.1.1
    return 3.647 * bm * fc * (rows * math.cos(alpha)) ** 0.7 * Z ** (2 / 3) * dw**1.4  # [1] 5.1.1


def basic_static_load_rating(Z, Dw, Dpw, alpha, rows=1):
    """Basic static radial load rating C_0r = f_0 i Z D_w^2 cos(alpha) [N] ([2], 4 200 MPa contact stress)."""
    return factor_f0(_gamma(Dw, Dpw, alpha)) * rows * Z * (Dw * M_TO_MM) ** 2 * math.cos(alpha)  # [2]


def equivalent_load_factors(Fr, Fa, alpha, C0r=None, Z=None, Dw=None, Dpw=None, rows=1):
    """Radial and axial load factors (X, Y) and the limit e of [1] Table 3 (single-row bearings).

    alpha = 0 (radial contact groove): X = 0.56 and e, Y interpolated in
    f_0 F_a / C_0r (needs C0r [N], Z, Dw, Dpw [m] for f_0).  alpha = 15 deg:
    X = 0.44, e and Y in i F_a / C_0r.  alpha = 20..45 deg: the table rows,
    interpolated linearly in alpha between them.  F_a/F_r <= e: X = 1, Y = 0.
    Outside the table (alpha < 15 deg but > 0, > 45 deg): ValueError.

    Returns
    -------
    (X, Y, e)
    """
    Fr, Fa = abs(float(Fr)), abs(float(Fa))
    adeg = math.degrees(alpha)
    if adeg < 0.5:
        if C0r is None or None in (Z, Dw, Dpw):
            raise ValueError("radial contact groove bearings need C0r, Z, Dw, Dpw for f_0 F_a / C_0r")
        arg = factor_f0(_gamma(Dw, Dpw, 0.0)) * Fa / C0r  # [1] Table 3, first column f_0 F_a / C_0r (N, mm)
        e = float(np.interp(arg, _DG_ARG, _DG_E))
        X, Y = 0.56, float(np.interp(arg, _DG_ARG, _DG_Y))
    elif abs(adeg - 15.0) < 0.5:
        if C0r is None:
            raise ValueError("alpha = 15 deg needs C0r for i F_a / C_0r")
        arg = rows * Fa / C0r
        e = float(np.interp(arg, _AC15_ARG, _AC15_E))
        X, Y = 0.44, float(np.interp(arg, _AC15_ARG, _AC15_Y))
    elif 20.0 - 0.5 <= adeg <= 45.0 + 0.5:
        a = min(max(adeg, 20.0), 45.0)
        angs = sorted(_AC_XY)
        e, X, Y = (float(np.interp(a, angs, [_AC_XY[k][m] for k in angs])) for m in range(3))
    else:
        raise ValueError(f"contact angle {adeg:.3g} deg: ISO 281 Table 3 rows are 0, 15, 20..45 deg")
    if Fr > 0 and Fa / Fr <= e:
        return 1.0, 0.0, e
    return X, Y, e


def dynamic_equivalent_radial_load(Fr, Fa, X, Y):
    """P_r = X F_r + Y F_a [N] ([1] 5.2)."""
    return X * abs(Fr) + Y * abs(Fa)  # [1] 5.2


def basic_rating_life(C, P, p=3.0):
    """L_10 = (C/P)^p [10^6 revolutions], p = 3 for ball bearings ([1] 5.3)."""
    return (C / P) ** p  # [1] 5.3


def reference_viscosity(n_rpm, Dpw):
    """Rated (reference) kinematic viscosity nu_1 [m^2/s] for adequate lubrication ([1] 9.3.3).

    nu_1 = 45000 n^-0.83 D_pw^-0.5 (n < 1000 r/min), 4500 n^-0.5 D_pw^-0.5 (n >= 1000) in mm^2/s, n in r/min,
    D_pw in mm.

    Parameters
    ----------
    n_rpm : speed of the ring rotating relative to the other [r/min].  Dpw : pitch diameter [m].
    """
    n = abs(float(n_rpm))
    d = Dpw * M_TO_MM
    if n <= 0:
        raise ValueError("reference viscosity needs a speed > 0")
    nu1 = 45000.0 * n**-0.83 * d**-0.5 if n < 1000.0 else 4500.0 * n**-0.5 * d**-0.5  # [1] 9.3.3 [mm^2/s]
    return nu1 * 1e-6


def viscosity_ratio(nu, n_rpm, Dpw):
    """kappa = nu / nu_1 [-] ([1] 9.3.3); nu operating kinematic viscosity [m^2/s]."""
    return nu / reference_viscosity(n_rpm, Dpw)


def fatigue_load_limit(C0, Dpw):
    """Fatigue load limit C_u [N] of a ball bearing, the approximation of [1] Annex B.3.2.3.

    C_u = C_0 / 22 (D_pw <= 100 mm); C_u = C_0 / 22 (100 / D_pw)^0.5 (D_pw > 100 mm, D_pw in mm).
    """
    d = Dpw * M_TO_MM
    return C0 / 22.0 if d <= 100.0 else C0 / 22.0 * (100.0 / d) ** 0.5  # [1] B.3.2.3


def life_modification_factor(kappa, eC, Cu, P):
    """Life modification factor a_ISO [-] of radial ball bearings ([1] 9.3.2).

    a_ISO = 0.1 [1 - (2.5671 - 2.2649/kappa^0.054381)^0.83 (e_C C_u/P)^(1/3)]^-9.3   0.1 <= kappa < 0.4
    a_ISO = 0.1 [1 - (2.5671 - 1.9987/kappa^0.19087)^0.83 (e_C C_u/P)^(1/3)]^-9.3    0.4 <= kappa < 1
    a_ISO = 0.1 [1 - (2.5671 - 1.9987/kappa^0.071739)^0.83 (e_C C_u/P)^(1/3)]^-9.3   1 <= kappa <= 4
    kappa > 4 is taken as 4, kappa < 0.1 as 0.1 (outside the standard's range; the caller warns);
    a_ISO <= 50.  A bracket <= 0 (e_C C_u / P too large) also gives the limit 50.

    Parameters
    ----------
    kappa : viscosity ratio [-].  eC : contamination factor [-] ([1] Table 13).
    Cu : fatigue load limit [N].  P : dynamic equivalent load [N].
    """
    k = min(max(float(kappa), 0.1), 4.0)
    x = (eC * Cu / P) ** (1.0 / 3.0)
    if k < 0.4:
        t = 2.5671 - 2.2649 / k**0.054381  # [1] 9.3.2
    elif k < 1.0:
        t = 2.5671 - 1.9987 / k**0.19087  # [1] 9.3.2
    else:
        t = 2.5671 - 1.9987 / k**0.071739  # [1] 9.3.2
    bracket = 1.0 - t**0.83 * x
    if bracket <= 0.0:
        return 50.0
    return min(0.1 * bracket**-9.3, 50.0)  # [1] 9.3.2, a_ISO <= 50


def modified_rating_life(L10, a_iso, a1=1.0):
    """L_nm = a_1 a_ISO L_10 [10^6 rev] ([1] 9.1; a_1 = 1 for 90 % reliability)."""
    return a1 * a_iso * L10


def raceway_contact_ratings(Dw, Dpw, alpha, Z, fi, fe):
    """Basic dynamic load ratings (Q_ci, Q_ce) [N] of the inner and outer raceway contacts ([3] 4.3).

    Q_ci = 98.1 (2 f_i/(2 f_i - 1))^0.41 (1 - gamma)^1.39/(1 + gamma)^(1/3) (gamma/cos alpha)^0.3 D_w^1.8 Z^(-1/3)
    Q_ce = 98.1 (2 f_e/(2 f_e - 1))^0.41 (1 + gamma)^1.39/(1 - gamma)^(1/3) (gamma/cos alpha)^0.3 D_w^1.8 Z^(-1/3)
    (N, mm), 2 r/(2 r - D_w) = 2 f/(2 f - 1), gamma = D_w cos(alpha) / D_pw.

    Parameters
    ----------
    Dw, Dpw : ball and pitch diameter [m].  alpha : contact angle [rad] (array: one per ball).
    Z : ball count.  fi, fe : groove conformities r/D_w [-].
    """
    a = np.asarray(alpha, dtype=float)
    g = Dw * np.cos(a) / Dpw
    dw = Dw * M_TO_MM
    common = 98.1 * (g / np.cos(a)) ** 0.3 * dw**1.8 * Z ** (-1.0 / 3.0)  # [3] 4.3
    Qci = common * (2 * fi / (2 * fi - 1)) ** 0.41 * (1 - g) ** 1.39 / (1 + g) ** (1.0 / 3.0)  # [3] 4.3
    Qce = common * (2 * fe / (2 * fe - 1)) ** 0.41 * (1 + g) ** 1.39 / (1 - g) ** (1.0 / 3.0)  # [3] 4.3
    return Qci, Qce


def equivalent_contact_load(Q, rotating: bool):
    """Dynamic equivalent rolling-element load of a raceway [N] ([3] 4.3).

    Ring rotating relative to the load: Q_e = (1/Z sum Q_j^3)^(1/3);
    ring stationary relative to the load: Q_e = (1/Z sum Q_j^(10/3))^(3/10).
    """
    Q = np.clip(np.asarray(Q, dtype=float), 0.0, None)
    p = 3.0 if rotating else 10.0 / 3.0
    return float(np.mean(Q**p) ** (1.0 / p))  # [3] 4.3


def reference_rating_life(Qi, Qe, Qci, Qce, inner_rotating: bool = True):
    """Basic reference rating life L_10r [10^6 rev of the rotating ring] from the ball loads ([3] 4.3).

    L_10r = [(Q_ci/Q_ei)^(-10/3) + (Q_ce/Q_ee)^(-10/3)]^(-9/10), with the
    equivalent loads of :func:`equivalent_contact_load` (cubic mean on the ring
    that rotates relative to the load, 10/3 mean on the other).  Per-ball ratings
    (arrays Qci, Qce, one contact angle per ball): the ring ratio is
    (1/Z sum (Q_j/Q_c,j)^p)^(1/p) (module docstring).

    Parameters
    ----------
    Qi, Qe : inner / outer contact loads per ball [N].  Qci, Qce : raceway ratings [N] (scalars or per ball).
    inner_rotating : the inner ring rotates relative to the load (a shaft load with the outer ring fixed).
    """
    Qi = np.clip(np.asarray(Qi, dtype=float), 0.0, None)
    Qe = np.clip(np.asarray(Qe, dtype=float), 0.0, None)
    pi = 3.0 if inner_rotating else 10.0 / 3.0
    pe = 10.0 / 3.0 if inner_rotating else 3.0
    ri = float(np.mean((Qi / np.asarray(Qci, dtype=float)) ** pi) ** (1.0 / pi))  # Q_ei / Q_ci
    re = float(np.mean((Qe / np.asarray(Qce, dtype=float)) ** pe) ** (1.0 / pe))  # Q_ee / Q_ce
    if ri == 0.0 and re == 0.0:
        return math.inf
    return (ri ** (10.0 / 3.0) + re ** (10.0 / 3.0)) ** -0.9  # [3] 4.3


def life_in_hours(L_mrev, n_rpm):
    """Life in operating hours = L 10^6 / (60 n) [h] (n [r/min])."""
    n = abs(float(n_rpm))
    return math.inf if n == 0 else L_mrev * 1e6 / (60.0 * n)
