"""EHL traction laws of the aviation oils 4109, 4106 and 4050 (Zhang et al. 2016).

mu = (A_L + B_L S) exp(-C_L S) + D_L                        ([1], Eq. 1)

with A_L ... D_L power laws of the dimensionless load, speed and temperature
(Eqs. 2-4).  The decisions taken on the conventions (units, E, R, T, S) and
on oil 4050 are argued with evidence in ``docs/traction.md``; in short:

* inputs in SI, **temperature in degC inside the law** (the API takes kelvin),
  E = reduced modulus E' = 2/((1-nu1^2)/E1 + (1-nu2^2)/E2) [Pa],
  R = Rx, the effective radius in the rolling direction [m] (for the
  ball-on-disc rig of [1] R = Rx = ball radius), W the normal load [N],
  U = (U_1 + U_2)/2 the rolling (entrainment) velocity [m/s],
  S = slide-roll ratio |U_1 - U_2| / U as a fraction (not percent);
* 4109 (Eq. 2) and 4106 (Eq. 3) are used as printed.  Their "bounded"
  reading only adds a smooth saturation of the load factor |Wc/W - 1| <= 3,
  active far below the critical load (W < Wc/4), where the printed law
  makes mu grow as 1/W (traction force not vanishing with the load);
* 4050's printed Eq. 4 is not a traction curve under any convention tested
  (C_L ~ 1e-26: mu = D + B S grows without bound).  Its default is the
  documented fallback ``analogue_4106``: the form and coefficients of Eq. 3
  evaluated with 4050's own Table 1 properties (eta0, beta, K), bounded as
  above.  ``law="printed"`` keeps Eq. 4 for comparison.
* every law except "printed" is bounded at low rolling speed by
  :func:`limiting_shear_speed_floor`: the fitted power laws in Ubar (exponents
  -0.2 to -0.66) are not extrapolated below the speed at which their plateau
  D_L reaches the limiting-shear-stress coefficient of an EHL film
  (docs/traction.md, "Low rolling speed").

Sign convention: the seed's S >= 0.  Here mu is extended as an odd function
of the signed slide-roll ratio, mu(-S) = -mu(S), so the traction opposes the
slip.  For Eqs. 2-3 A_L = -D_L exactly, so mu(0) = 0 and the odd extension is
continuous with a continuous slope (C^1; the curvature jumps by 2 |f''(0)|
at S = 0, harmless for BDF).  Eq. 4 (printed) has mu(0+) = A_L + D_L != 0:
its constant part is regularised as (A_L + D_L) tanh(S / S_EPS).

References
----------
[1] Zhang W., Deng S., Chen G., Cui Y., "Impact of lubricant traction
    coefficient on cage's dynamic characteristics in high-speed angular
    contact ball bearing", Chin. J. Aeronaut. (2016),
    doi:10.1016/j.cja.2016.08.019, Table 1 and Eqs. (1)-(4).
"""

from __future__ import annotations

import math

import numpy as np

from hsbearing.models.traction.eyring_limit import LAMBDA_BRACKET

__all__ = [
    "LAWS",
    "DEFAULT_LAW",
    "PARAMS",
    "S_EPS",
    "LOAD_FACTOR_MAX",
    "NOTCH_FLOOR",
    "PERCENT",
    "LIMITING_SHEAR_COEFFICIENT",
    "notch_floor",
    "limiting_shear_speed_floor",
    "coefficients",
    "dimensionless_groups",
    "traction_coefficient",
]

#: Slip scale [-] of the tanh regularisation of a nonzero mu(0+) (printed Eq. 4 only).
S_EPS = 1.0e-4
#: Saturation value of the load factor |Wc/W - 1| in the bounded readings [-].
LOAD_FACTOR_MAX = 3.0
#: Exponent of the smooth saturation f / (1 + (f/f_max)^n)^(1/n) [-].
LOAD_FACTOR_SHARPNESS = 8.0
#: Floor of the load factor |Wc/W - 1| near the critical load in the "percent" readings [-]:
#: f -> (f^m + f_0^m)^(1/m), so mu(W_c) = mu at the load where |Wc/W - 1| = f_0 instead of 0
#: (docs/traction.md, "critical-load notch").
NOTCH_FLOOR = 0.25
#: Exponent m of the smooth floor [-].
NOTCH_SHARPNESS = 4.0
#: Limiting-shear-stress coefficient Lambda = tau_L / p that bounds the plateau D_L of every non-printed law at low
#: rolling speed [-]: the upper end of the bracket of :data:`eyring_limit.LAMBDA_BRACKET` (Hoeglund's paraffinic
#: mineral oil M100, Arana et al. 2019 Table 2; an ester lies below it, docs/traction.md).
LIMITING_SHEAR_COEFFICIENT = LAMBDA_BRACKET[1]
#: Exponent m of the smooth speed floor Ubar_eff = (Ubar^m + Ubar*^m)^(1/m) [-].
SPEED_FLOOR_SHARPNESS = 4.0
#: Slide-roll ratio scale of the "percent" readings: the printed S is read in percent, S_printed = 100 S [-].
PERCENT = 100.0
#: Floors that keep the kernels finite (W = 0, U = 0, T <= 0 degC) [N], [m/s], [degC].
W_FLOOR, U_FLOOR, T_FLOOR_C = 1.0e-9, 1.0e-6, 1.0e-3

# Table 1 of [1]: eta0 [Pa s], beta [1/degC], K [N/(s degC)]
_OIL = {
    "4109": (0.033, 0.0215, 0.0966),
    "4106": (0.055, 0.031531, 0.0965788),
    "4050": (0.060, 0.035, 0.0966),
}
# Eq. 2 (4109) and Eq. 3 (4106): Wc = c2 T^2 + c1 T + c0, and (coef, pW, pU, pT) of A_L, B_L, C_L, D_L
_EQ2 = ((7.956015e12, 5553.090, 1.758455e-6),
        ((-4.793526e-8, 0.0068361, -0.4047492, -0.1833848),
         (8.37449e-15, 0.01409715, -0.5868325, -0.8173636),
         (1.180823e-4, 0.0061321, -0.2061700, -0.3431740),
         (4.793526e-8, 0.0068361, -0.4047492, -0.1833848)))
_EQ3 = ((-2.279669e12, 5959.008, 1.647125e-6),
        ((-1.172032e-7, 0.0104047, -0.530571, -0.0371558),
         (1.164665e-11, 0.0146206, -0.6592641, -0.443983),
         (3.962211e-6, 0.00992, -0.3987271, -0.3237042),
         (1.172032e-7, 0.0104047, -0.530571, -0.0371558)))
# Eq. 4 (4050): no critical-load factor, Tbar = T K / (eta0 U^2)
_EQ4 = ((0.0, 0.0, 0.0),
        ((0.0016, 1.1227, 0.8493, 0.8816),
         (7.2804, -0.1372, 0.2116, 0.1766),
         (61.4605, 0.3831, 2.9404, 1.6113),
         (16.7177, 0.3403, 0.4748, 0.2488)))

TBAR_SQRT, TBAR_BRINKMAN = 0, 1

#: Registry of laws: (oil, law) -> law id.  Row ``law_id`` of :data:`PARAMS` holds its constants.
LAWS: dict[tuple[str, str], int] = {}
_DESCRIPTIONS: dict[tuple[str, str], str] = {}
_rows = []


def _add(oil, law, props_oil, eq, tbar_kind, has_wc, fmax, description, s_scale=1.0, notch_floor=0.0,
         mu_limit=LIMITING_SHEAR_COEFFICIENT):
    eta0, beta, K = _OIL[props_oil]
    (c2, c1, c0), coefs = eq
    row = [eta0, beta, K, float(tbar_kind), float(has_wc), c2, c1, c0, fmax]
    for c in coefs:
        row.extend(c)
    row.extend([s_scale, notch_floor, mu_limit])
    LAWS[(oil, law)] = len(_rows)
    if mu_limit > 0.0:
        description += f"; plateau floored at the limiting shear {mu_limit:g} at low rolling speed"
    _DESCRIPTIONS[(oil, law)] = description
    _rows.append(row)


_add("4109", "printed", "4109", _EQ2, TBAR_SQRT, 1, 0.0, "Zhang et al. 2016 Eq. 2 as printed", mu_limit=0.0)
_add("4106", "printed", "4106", _EQ3, TBAR_SQRT, 1, 0.0, "Zhang et al. 2016 Eq. 3 as printed", mu_limit=0.0)
_add("4050", "printed", "4050", _EQ4, TBAR_BRINKMAN, 0, 0.0,
     "Zhang et al. 2016 Eq. 4 as printed (NOT a traction curve: C_L ~ 1e-26, mu grows linearly with S)", mu_limit=0.0)
_add("4109", "bounded", "4109", _EQ2, TBAR_SQRT, 1, LOAD_FACTOR_MAX,
     "Eq. 2 with the load factor |Wc/W-1| smoothly saturated at 3 (W << Wc only)")
_add("4106", "bounded", "4106", _EQ3, TBAR_SQRT, 1, LOAD_FACTOR_MAX,
     "Eq. 3 with the load factor |Wc/W-1| smoothly saturated at 3 (W << Wc only)")
_add("4050", "analogue_4106", "4050", _EQ3, TBAR_SQRT, 1, LOAD_FACTOR_MAX,
     "fallback: Eq. 3 (4106 fit) evaluated with 4050's Table 1 eta0, beta, K; bounded")
_add("4109", "percent", "4109", _EQ2, TBAR_SQRT, 1, LOAD_FACTOR_MAX,
     "Eq. 2 with S read in percent (S_printed = 100 S), bounded, critical-load notch floored at |Wc/W-1| = 0.25",
     s_scale=PERCENT, notch_floor=NOTCH_FLOOR)
_add("4106", "percent", "4106", _EQ3, TBAR_SQRT, 1, LOAD_FACTOR_MAX,
     "Eq. 3 with S read in percent (S_printed = 100 S), bounded, critical-load notch floored at |Wc/W-1| = 0.25",
     s_scale=PERCENT, notch_floor=NOTCH_FLOOR)
_add("4050", "analogue_4106_percent", "4050", _EQ3, TBAR_SQRT, 1, LOAD_FACTOR_MAX,
     "fallback: Eq. 3 (4106 fit) with 4050's Table 1 eta0, beta, K, S read in percent, bounded, notch floored",
     s_scale=PERCENT, notch_floor=NOTCH_FLOOR)

#: Constants of every law, one row per law id: eta0, beta, K, tbar_kind, has_wc, c2, c1, c0,
#: f_max (0 = printed, no saturation), then (coef, pW, pU, pT) for A_L, B_L, C_L, D_L (columns 9-24),
#: then s_scale (25: 1 = S a fraction, 100 = S in percent), the notch floor f_0 (26: 0 = none) and the
#: limiting-shear coefficient of the low-speed floor (27: 0 = none, the printed laws).
PARAMS = np.array(_rows, dtype=float)
PARAMS.setflags(write=False)

#: Default reading per oil (see docs/traction.md, "Decision").
DEFAULT_LAW = {"4109": "percent", "4106": "percent", "4050": "analogue_4106_percent"}


def describe(oil: str, law: str) -> str:
    """One-line description of a registered law."""
    return _DESCRIPTIONS[(oil, law)]


# ----------------------------------------------------------------------------
# numpy (vectorised) implementation


def dimensionless_groups(law_id: int, W, U, T_C, E, R):
    """Dimensionless load, speed and temperature of [1], Eqs. 2-4.

    Wbar = W / (E R^2),  Ubar = eta0 U / (E R),
    Tbar = T sqrt(K eta0 beta) / (E R)   (Eqs. 2, 3)   or
    Tbar = T K / (eta0 U^2)              (Eq. 4),
    all in SI with T in degC.

    Parameters
    ----------
    law_id : row of :data:`PARAMS`
    W : normal load [N];  U : rolling velocity (U_1 + U_2)/2 [m/s]
    T_C : lubricant (inlet) temperature [degC];  E : reduced modulus E' [Pa]
    R : effective radius in the rolling direction Rx [m]

    Returns
    -------
    (Wbar, Ubar, Tbar) [-]
    """
    p = PARAMS[law_id]
    eta0, beta, K = p[0], p[1], p[2]
    Wb = W / (E * R * R)  # [1], Eqs. 2-4
    Ub = eta0 * U / (E * R)  # [1], Eqs. 2-4
    if p[3] == TBAR_SQRT:
        Tb = T_C * math.sqrt(K * eta0 * beta) / (E * R)  # [1], Eqs. 2-3
    else:
        Tb = T_C * K / (eta0 * U * U)  # [1], Eq. 4
    return Wb, Ub, Tb


def notch_floor(f, f0):
    """Smooth floor of the critical-load factor: (f^m + f_0^m)^(1/m), m = NOTCH_SHARPNESS (identity if f_0 == 0).

    The printed factor |Wc/W - 1| of [1], Eqs. 2-3 vanishes at W = W_c and with it mu for every S; the
    floor keeps the "transition" at the critical load that the fitted data show (docs/traction.md) without
    a zero.  f, f_0 [-].  Differs from f by < 0.4 % for f >= 3 f_0 and < 0.1 % for f >= 4 f_0.
    """
    if f0 <= 0.0:
        return f
    m = NOTCH_SHARPNESS
    return (f**m + f0**m) ** (1.0 / m)


def limiting_shear_speed_floor(Ub, Dn, pU, Lambda):
    """Smooth floor of the dimensionless rolling speed at which the fitted plateau reaches the limiting shear [-].

    The plateau of Eqs. 2-3 (and of the 4050 analogue) is D_L = Dn Ubar^pU with pU = -0.40 (4109) or -0.53
    (4106) < 0: extrapolated to Ubar -> 0 it grows without bound (mu = 2.09 at U = 1 mm/s, 4106, 200 N, 130 degC), far
    outside the range of the rig tests the laws were fitted to (which the seed does not state) and above any
    EHL traction.  Physically the mean shear stress of an EHL film cannot exceed its limiting shear stress
    tau_L = Lambda p ([1] Eq. 7, [2]): a traction plateau above Lambda is impossible, whatever the speed
    (slower rolling only removes the shear heating that lowers mu below Lambda).  So the laws are evaluated at

        Ubar_eff = (Ubar^m + Ubar*^m)^(1/m),   Ubar* = (Lambda / Dn)^(1/pU),   m = SPEED_FLOOR_SHARPNESS,

    Ubar* being the speed at which the fitted plateau equals Lambda: D_L(Ubar_eff) <= Lambda everywhere, the
    coefficients A_L..D_L freeze at their Ubar* values as U -> 0 (both directions of rolling: the laws see |U|),
    and Ubar_eff is C-infinity in Ubar > 0 (CVODE).  Above Ubar* the change is of order (Ubar*/Ubar)^m / m:
    < 1e-5 in mu at the default case (16.3 m/s, 130 degC), < 0.2 % at >= 5 m/s and >= 50 N (tested).
    Lambda = :data:`LIMITING_SHEAR_COEFFICIENT`.
    Mixed and boundary friction (film parameter < 1, mu_bl ~ 0.1) are not part of this EHL law; the run's
    lambda < 1 warning flags those contacts (docs/life.md, "Warnings").

    Parameters
    ----------
    Ub : dimensionless rolling speed eta0 U / (E' R) [-] (> 0)
    Dn : |D_L| / Ubar^pU, the speed-independent part of the plateau (load factor included) [-]
    pU : Ubar exponent of D_L [-] (< 0)
    Lambda : limiting-shear-stress coefficient [-] (<= 0: no floor, Ub returned)

    References
    ----------
    [1] Arana A., Larrañaga J., Ulacia I., Proc. IMechE Part J 233(2) (2019) 303-316, Eq. (7) and Table 2.
    [2] Bair S., Winer W. O., J. Lubr. Technol. 101 (1979) 258-265 (limiting shear stress tau_L = Lambda p).
    """
    if Lambda <= 0.0:
        return Ub
    Dn = np.asarray(Dn, dtype=float)
    with np.errstate(divide="ignore"):
        Ub_star = np.where(Dn > 0.0, (Lambda / np.where(Dn > 0.0, Dn, 1.0)) ** (1.0 / pU), 0.0)
    m = SPEED_FLOOR_SHARPNESS
    hi, lo = np.maximum(Ub, Ub_star), np.minimum(Ub, Ub_star)
    return hi * (1.0 + (lo / hi) ** m) ** (1.0 / m)  # = (Ub^m + Ub*^m)^(1/m), without over/underflow


def _saturate(f, fmax):
    """Smooth saturation f / (1 + (f/f_max)^n)^(1/n) (identity if f_max == 0)."""
    if fmax <= 0.0:
        return f
    n = LOAD_FACTOR_SHARPNESS
    r = np.minimum(f / fmax, 1e6)
    return np.where(f / fmax > 1e6, fmax, f / (1.0 + r**n) ** (1.0 / n))


def coefficients(law_id: int, W, U, T_K, E, R):
    """Coefficients A_L, B_L, C_L, D_L of [1], Eqs. 2-4 (vectorised).

    Parameters
    ----------
    law_id : row of :data:`PARAMS` (see :func:`hsbearing.models.traction.law_id`)
    W : normal load [N];  U : rolling velocity [m/s];  T_K : temperature [K]
    E : reduced modulus E' [Pa];  R : Rx [m]

    Returns
    -------
    (A, B, C, D) [-], broadcast arrays
    """
    p = PARAMS[law_id]
    W = np.maximum(np.asarray(W, dtype=float), W_FLOOR)
    U = np.maximum(np.abs(np.asarray(U, dtype=float)), U_FLOOR)
    T_C = np.maximum(np.asarray(T_K, dtype=float) - 273.15, T_FLOOR_C)  # the laws are fitted in degC
    Wb, Ub, Tb = dimensionless_groups(law_id, W, U, T_C, np.asarray(E, dtype=float), np.asarray(R, dtype=float))
    if p[4]:
        Wc = p[5] * Tb * Tb + p[6] * Tb + p[7]  # [1], Eqs. 2-3: critical load parameter
        f = _saturate(notch_floor(np.abs(Wc / Wb - 1.0), p[26]), p[8])  # [1], Eqs. 2-3: |Wc/W - 1|
    else:
        f = 1.0
    if p[27] > 0.0:  # low-speed floor at the limiting shear (limiting_shear_speed_floor)
        Ub = limiting_shear_speed_floor(Ub, abs(p[21]) * f * Wb ** p[22] * Tb ** p[24], p[23], p[27])
    out = []
    for j in range(4):
        a, pW, pU, pT = p[9 + 4 * j: 13 + 4 * j]
        out.append(a * Wb**pW * f * Ub**pU * Tb**pT)  # [1], Eqs. 2-4
    A, B, C, D = np.broadcast_arrays(*out)
    # S read in percent: (A + B S_p) exp(-C S_p) + D with S_p = s_scale S  ==  coefficients (A, s B, s C, D) in S
    return A, B * p[25], C * p[25], D


def traction_coefficient(A, B, C, D, S):
    """Traction coefficient mu(S) of [1], Eq. 1, extended as an odd function of S.

    mu = sign(S) [(A + B|S|) e^(-C|S|) + D - mu0] + mu0 tanh(S / S_EPS),  mu0 = A + D
       = sign(S) [A expm1(-C|S|) + B |S| e^(-C|S|)] + mu0 tanh(S / S_EPS)

    which is Eq. 1 for S > S_EPS (mu0 = 0 exactly for Eqs. 2-3).  The second,
    algebraically identical form avoids the cancellation of A and D at small S.

    Parameters
    ----------
    A, B, C, D : coefficients from :func:`coefficients` [-]
    S : signed slide-roll ratio (U_1 - U_2)/U [-] (fraction)

    Returns
    -------
    mu [-], with the sign of S
    """
    S = np.asarray(S, dtype=float)
    s = np.abs(S)
    mu0 = A + D
    e = np.exp(-C * s)
    return np.sign(S) * (A * np.expm1(-C * s) + B * s * e) + mu0 * np.tanh(S / S_EPS)  # [1], Eq. 1


# ----------------------------------------------------------------------------
# numba kernels: hsbearing.models.traction._kernels (coefficients_nb, mu_nb), a separate module so that
# loading a case does not import numba and this module imports nothing back (no import circle)


