"""Numba kernels of the Zhang et al. 2016 traction laws for the dynamics hot path (scalar, allocation-free).

Twins of :func:`hsbearing.models.traction.zhang2016.coefficients` and
:func:`~hsbearing.models.traction.zhang2016.traction_coefficient`; reached as
``hsbearing.models.traction._kernels`` (a module of its own, so that importing the
registry does not import numba).  Equations and references: see zhang2016.
"""

from __future__ import annotations

import math

import numba
import numpy as np

from hsbearing.compile_cache import check_compile_cache
from hsbearing.models.traction.eyring import LOG_ASINH, MINOR_NODES, SIGMA_HARD
from hsbearing.models.traction.tables import (
    ASINH_EXP,
    COTH,
    EXP_NEG,
    LN_TANH_HALF,
    LOG1M_EXP,
    LOG1P,
    LOG_ASINH_LOW,
    ONE_MINUS_EXP_END,
    ONE_MINUS_EXP_OVER_X,
    SIGMA_TABLE,
    SOFTPLUS_END,
    SOFTPLUS_NEG,
)
from hsbearing.models.traction.zhang2016 import (
    LOAD_FACTOR_SHARPNESS,
    NOTCH_SHARPNESS,
    PARAMS,
    S_EPS,
    SPEED_FLOOR_SHARPNESS,
    T_FLOOR_C,
    U_FLOOR,
    W_FLOOR,
)

__all__ = ["coefficients_nb", "mu_nb", "traction_coefficients_nb", "race_traction_coefficients_nb", "traction_mu_nb", "eyring_coefficients_nb",
           "eyring_strip_mu_nb", "eyring_strip_mu_exact_nb", "table_eval_nb", "EYRING_LAW_ID", "COEFFICIENTS_LAW_ID"]

#: Law ids of the oil-independent laws (the registered seed laws are rows 0, 1, ... of zhang2016.PARAMS):
#: the physical model (models.traction.eyring) and the seed form with user coefficients (kernel parameters
#: traction.c_A .. c_D).  Same values as hsbearing.models.traction.EYRING_LAW_ID / COEFFICIENTS_LAW_ID.
EYRING_LAW_ID = -1
COEFFICIENTS_LAW_ID = -2

_P = PARAMS  # captured as a compile-time constant array


@numba.njit(cache=True, nogil=True, inline="always")
def _pnorm(a, b, m):
    """(a^m + b^m)^(1/m) for a, b >= 0 [-]; m = 4 or 8 by products and square roots (no libm pow; the
    result within a few ulp of the pow form), any other m by pow."""
    if m == 4.0:
        a2, b2 = a * a, b * b
        return math.sqrt(math.sqrt(a2 * a2 + b2 * b2))
    if m == 8.0:
        a2, b2 = a * a, b * b
        a4, b4 = a2 * a2, b2 * b2
        return math.sqrt(math.sqrt(math.sqrt(a4 * a4 + b4 * b4)))
    return (a**m + b**m) ** (1.0 / m)


@numba.njit(cache=True, nogil=True)
def coefficients_nb(law_id, W, U, T_K, E, R):
    """Scalar numba twin of :func:`coefficients`: returns (A, B, C, D) [-] (SI, T in K)."""
    p = _P[law_id]
    W = max(W, W_FLOOR)
    U = max(abs(U), U_FLOOR)
    T_C = max(T_K - 273.15, T_FLOOR_C)
    eta0, beta, K = p[0], p[1], p[2]
    ER = E * R
    Wb = W / (ER * R)
    Ub = eta0 * U / ER
    if p[3] == 0.0:
        Tb = T_C * math.sqrt(K * eta0 * beta) / ER
    else:
        Tb = T_C * K / (eta0 * U * U)
    f = 1.0
    if p[4] != 0.0:
        Wc = p[5] * Tb * Tb + p[6] * Tb + p[7]
        f = abs(Wc / Wb - 1.0)
        f0 = p[26]
        if f0 > 0.0:  # smooth floor of the critical-load notch (zhang2016.notch_floor)
            f = _pnorm(f, f0, NOTCH_SHARPNESS)
        fmax = p[8]
        if fmax > 0.0:
            r = f / fmax
            if r > 1e6:
                f = fmax
            else:
                f = f / _pnorm(1.0, r, LOAD_FACTOR_SHARPNESS)
    lam = p[27]
    lW, lT = math.log(Wb), math.log(Tb)
    if lam > 0.0:  # low-speed floor at the limiting shear (zhang2016.limiting_shear_speed_floor)
        Dn = abs(p[21]) * f * math.exp(p[22] * lW + p[24] * lT)
        if Dn > 0.0:
            Ub_star = math.exp(math.log(lam / Dn) / p[23])
            hi, lo = max(Ub, Ub_star), min(Ub, Ub_star)
            Ub = hi * _pnorm(1.0, lo / hi, SPEED_FLOOR_SHARPNESS)  # (Ub^m + Ub*^m)^(1/m) without over/underflow
    lU = math.log(Ub)
    A = p[9] * f * math.exp(p[10] * lW + p[11] * lU + p[12] * lT)
    B = p[13] * f * math.exp(p[14] * lW + p[15] * lU + p[16] * lT)
    C = p[17] * f * math.exp(p[18] * lW + p[19] * lU + p[20] * lT)
    D = p[21] * f * math.exp(p[22] * lW + p[23] * lU + p[24] * lT)
    s = p[25]  # S read in percent: coefficients (A, s B, s C, D) in the fractional S
    return A, B * s, C * s, D


# |x| beyond which tanh(x) rounds to +-1 in double precision: 1 - tanh(x) = 2/(e^(2x) + 1) < 2^-54 for x > 19.1
_TANH_ONE = 20.0


@numba.njit(cache=True, nogil=True)
def mu_nb(A, B, C, D, S):
    """Scalar numba twin of :func:`traction_coefficient` (odd in S) [-].

    Two libm calls at most: e^(-C|S|) is taken as 1 + expm1(-C|S|) (absolute error <= 2^-53, so
    the term B |S| e^(-C|S|) moves by at most B |S| 2^-53: round-off of mu), and tanh(S/S_EPS) is +-1
    exactly (rounded) beyond |S/S_EPS| = 20, where it is not called.
    """
    s = abs(S)
    mu0 = A + D
    sg = 1.0 if S > 0.0 else (-1.0 if S < 0.0 else 0.0)
    em1 = math.expm1(-C * s)
    x = S / S_EPS
    if x > _TANH_ONE:
        th = 1.0
    elif x < -_TANH_ONE:
        th = -1.0
    else:
        th = math.tanh(x)
    return sg * (A * em1 + B * s * (1.0 + em1)) + mu0 * th


_MN = MINOR_NODES  # captured as a compile-time constant array
_LN2 = math.log(2.0)


@numba.njit(cache=True, nogil=True)
def eyring_coefficients_nb(W, U, Ep, Rx, k, a, eta_in, alpha, tau0, Lam, G, phi_T=1.0):
    """Scalar numba twin of :func:`hsbearing.models.traction.eyring.contact_coefficients` (phi_T: the inlet-heating
    film factor, 1 = isothermal):
    (Lambda, tau_0/p_0, ln(eta_in U/(h tau_0)), alpha p_0, G_eff b/(h p_0)) [-]; floors W >= 1e-9 N, U >= 1e-6 m/s.

    The Hamrock-Dowson central film (eyring.central_film; Hamrock & Dowson, models/ehl.py [1] Eq. 69)
    h = phi_T 2.69 Rx Ub^0.67 (alpha E')^0.53 Wb^-0.067 (1 - 0.61 e^(-0.73 k)) is formed in logarithms (four logs and
    two exps instead of three pows, an exp and a log; ln h serves ln(eta U/(h tau_0)) directly): the same
    numbers within a few ulp (tests/models/test_traction_eyring.py compares with the Python evaluation).
    """
    W = max(W, W_FLOOR)
    U = max(abs(U), U_FLOOR)
    b = a / k
    p0 = 1.5 * W / (math.pi * a * b)
    ERx = Ep * Rx
    lUb = math.log(eta_in * U / ERx)  # ln Ub
    lh = (math.log(phi_T * 2.69 * Rx * (1.0 - 0.61 * math.exp(-0.73 * k))) + 0.67 * lUb + 0.53 * math.log(alpha * Ep)
          - 0.067 * math.log(W / (ERx * Rx)))  # ln h, Hamrock-Dowson (x phi_T)
    h = math.exp(lh)
    Ef = 4.0 * G * b / (math.pi * h * p0)  # elastic film slope
    Cc = 2.0 * Rx / b  # Carter creep slope
    Ge = G * Cc / (Ef + Cc)
    return Lam, tau0 / p0, lUb + math.log(ERx / tau0) - lh, alpha * p0, Ge * b / (h * p0)


# quintic Hermite tables of the strip integrand's one-variable functions (models.traction.tables), captured as
# compile-time constants: asinh(e^x) and (1 - e^-y)/y
_G_TAB, _G_X0, _G_IH = ASINH_EXP.coef, ASINH_EXP.x0, 1.0 / ASINH_EXP.h
_Q_TAB, _Q_X0, _Q_IH = ONE_MINUS_EXP_OVER_X.coef, ONE_MINUS_EXP_OVER_X.x0, 1.0 / ONE_MINUS_EXP_OVER_X.h
_G_LO, _Q_END = LOG_ASINH_LOW, ONE_MINUS_EXP_END
# and the Maxwell-Eyring build-up's log(1 - e^z) on [-40, -1.75] and log1p(e^-t) on [0, 40]
_LM_TAB, _LM_X0, _LM_IH = LOG1M_EXP.coef, LOG1M_EXP.x0, 1.0 / LOG1M_EXP.h
# and log1p(A) on [0, 1] for the form near the inlet (E < _E_NEAR)
_L_TAB, _L_X0, _L_IH = LOG1P.coef, LOG1P.x0, 1.0 / LOG1P.h
_E_NEAR = 0.5
# and the pair constants coth sigma_f, ln tanh(sigma_f / 2), e^-sigma_f on [2, 36] (one grid: one cell look-up)
assert COTH.h == LN_TANH_HALF.h == EXP_NEG.h and COTH.x0 == LN_TANH_HALF.x0 == EXP_NEG.x0
_CT_TAB, _LT_TAB, _EN_TAB = COTH.coef, LN_TANH_HALF.coef, EXP_NEG.coef
_SIG_T0, _SIG_IH = SIGMA_TABLE[0], 1.0 / COTH.h


@numba.njit(cache=True, nogil=True, inline="always", error_model="numpy")
def _horner5(coef, i, t):
    return coef[i, 0] + t * (coef[i, 1] + t * (coef[i, 2] + t * (coef[i, 3] + t * (coef[i, 4] + t * coef[i, 5]))))
_SP_TAB, _SP_X0, _SP_IH, _SP_END = SOFTPLUS_NEG.coef, SOFTPLUS_NEG.x0, 1.0 / SOFTPLUS_NEG.h, SOFTPLUS_END


@numba.njit(cache=True, nogil=True, inline="always", error_model="numpy")
def table_eval_nb(coef, x0, inv_h, x):
    """A :mod:`~hsbearing.models.traction.tables` table (coefficients ``coef``, start ``x0``, 1/cell width
    ``inv_h``) at x [-]: one look-up and a degree-5 Horner polynomial; x outside the table is clamped to its end
    cells (callers branch before).  Generic: any local stress law of a strip integrand can tabulate its smooth
    one-variable functions with ``tables.build`` and evaluate them here."""
    v = (x - x0) * inv_h
    n = coef.shape[0]
    i = int(v) if v > 0.0 else 0
    if i > n - 1:
        i = n - 1
    t = v - i
    return coef[i, 0] + t * (coef[i, 1] + t * (coef[i, 2] + t * (coef[i, 3] + t * (coef[i, 4] + t * coef[i, 5]))))


def _node_pairs(nodes):
    """The theta nodes (an even count) as mirror pairs (theta_j, -theta_j), j < n/2: rows (cos theta_j,
    1 + sin theta_j, 1 - sin theta_j, w_j cos theta_j, 1 / cos theta_j).  Gauss-Legendre nodes are symmetric to
    the last bit (numpy symmetrises them; sin is odd and cos even in libm), so the two nodes of a pair share their
    pressure and hence their flow stress exactly; anything else is refused."""
    n = nodes.shape[0]
    sn, cs, w = nodes[:, 0], nodes[:, 1], nodes[:, 2]
    if n % 2 or not (np.array_equal(sn, -sn[::-1]) and np.array_equal(cs, cs[::-1]) and np.array_equal(w, w[::-1])):
        raise ValueError("eyring.MINOR_NODES must be an even number of mirror-symmetric nodes (the paired strip "
                         "integrand of _kernels.eyring_strip_mu_nb)")
    m = n // 2
    return np.ascontiguousarray(np.stack([cs[:m], 1.0 + sn[:m], 1.0 - sn[:m], w[:m], 1.0 / cs[:m]], axis=1))


_PAIRS = _node_pairs(MINOR_NODES)
_NPAIR = _PAIRS.shape[0]
_SUM_WCS = float(np.sum(MINOR_NODES[:, 2] * MINOR_NODES[:, 1]))  # sum_j w_j cos^2 theta_j: den = su * this
_PAIR_MIN = np.ascontiguousarray(np.minimum(_PAIRS[:, 1], _PAIRS[:, 2]))  # the smaller 1 +- sin theta_j of a pair
#: E - sigma_f beyond which the build-up is sigma_f exactly (to the last bit) in _buildup_nb: both its corrections
#: are skipped there (log1p(e^-t), t >= SOFTPLUS_END = 40; ln(1 - e^z), z <= -40), plus 1 for the rounding of
#: the lower bound of E that decides it before the pair constants (eyring_strip_mu_nb, the plastic pair)
_PLASTIC_MARGIN = SOFTPLUS_END + 1.0
_PLASTIC_SAFETY = 1.0 + 1e-6  # covers the rounding of E (relative 1e-12 at most) and of the build-up's E - sigma_f
assert SOFTPLUS_END == -LOG1M_EXP.x0 == 40.0


@numba.njit(cache=True, nogil=True, inline="always", error_model="numpy")
def _asinh_exp_nb(lz):
    """asinh(e^lz) [-]: lz + ln 2 above LOG_ASINH, the table ASINH_EXP on [LOG_ASINH_LOW, LOG_ASINH], e^lz below."""
    if lz > LOG_ASINH:
        return lz + _LN2
    if lz >= _G_LO:
        return table_eval_nb(_G_TAB, _G_X0, _G_IH, lz)
    return math.exp(lz)


@numba.njit(cache=True, nogil=True, inline="always", error_model="numpy")
def _buildup_nb(E, sf, lam, em, k1, k2):
    """sigma = tau / ts of :func:`hsbearing.models.traction.eyring.maxwell_eyring_buildup` at one node [-] from
    E = tau_el / (ts tanh sigma_f), sigma_f, lam = ln tanh(sigma_f / 2), em = 1 - q, k1 = (1 + q) em, k2 = q (1 + q)
    (above SIGMA_HARD: 0, 1, 1, 0).  Near the inlet (E < 0.5) the form of the exact twin,
    sigma = log1p(k1 (1 - x) / (em x + k2)), with 1 - x = E (1 - e^-E)/E (ONE_MINUS_EXP_OVER_X) and log1p from the
    table LOG1P (its argument <= 0.65 there): the form below loses the relative accuracy as E -> 0 (sigma -> 0 as a
    difference of terms of size ln tanh(sigma_f / 2)).  Elsewhere

        sigma = sigma_f + ln(1 - e^(lam - sigma_f - E)) - ln(1 + e^(lam + sigma_f - E))

    (the same exact solution: ln of its numerator (1 + q) - q (1 - q) x and denominator (1 - q) x + q (1 + q) over
    (1 + q) and q (1 + q), x = e^-E, q = e^-sigma_f, tanh(sigma_f / 2) = (1 - q) / (1 + q)).  Two tables of one
    variable, no libm: ln(1 + e^z) = max(z, 0) + log1p(e^-|z|) (SOFTPLUS_NEG; dropped beyond |z| = 40, < 4.3e-18)
    and ln(1 - e^z) (LOG1M_EXP, z <= -1.763 always; dropped below -40)."""
    if E < _E_NEAR:
        xm = E * table_eval_nb(_Q_TAB, _Q_X0, _Q_IH, E)  # 1 - x
        return table_eval_nb(_L_TAB, _L_X0, _L_IH, k1 * xm / (em * (1.0 - xm) + k2))
    z2 = sf + lam - E
    if z2 > 0.0:  # elastic side: sigma = E - lam - ... (sigma_f cancels exactly)
        sig = E - lam
        t = z2
    else:
        sig = sf
        t = -z2
    if t < _SP_END:
        sig -= table_eval_nb(_SP_TAB, _SP_X0, _SP_IH, t)
    z1 = lam - sf - E
    if z1 > _LM_X0:
        sig += table_eval_nb(_LM_TAB, _LM_X0, _LM_IH, z1)
    return sig


@numba.njit(cache=True, nogil=True, error_model="numpy")
def eyring_strip_mu_nb(c, S, u):
    """:func:`eyring_strip_mu_exact_nb` with node pairs sharing their flow stress and its Maxwell-Eyring constants,
    and every per-node function from a table (odd in S) [-].

    Tables: asinh(e^lz) = lz + ln 2 above :data:`LOG_ASINH` (exact to double precision), the table
    ``tables.ASINH_EXP`` on [LOG_ASINH_LOW, LOG_ASINH] (relative error <= 1.5e-13), e^lz below (exact to double
    precision: asinh z = z (1 - z^2/6 ...)); the build-up (:func:`_buildup_nb`) from ``tables.SOFTPLUS_NEG`` and
    ``tables.LOG1M_EXP``; per pair below SIGMA_HARD one libm exp and one log (q = e^-sigma_f,
    lam = ln tanh(sigma_f / 2) = ln((1 - q) / (1 + q))) and 1 - q = sigma_f (1 - e^-sigma_f)/sigma_f from
    ``tables.ONE_MINUS_EXP_OVER_X`` (relative accuracy as sigma_f -> 0).  One libm log per strip (ln|S|).

    Same arithmetic as the exact twin up to rounding (the reorganisation is exact algebra):
    - the mirror nodes +-theta_j have the same pressure p/p0 = su cos theta_j, hence the same Eyring stress tau_v,
      flow stress tau_f, stress scale ts = tau_0 / kappa and sigma_f = tau_f / ts; only tau_el = ce s su
      (1 +- sin theta_j) differs: the asinh table, the cap and the constants of the build-up are evaluated once per
      pair (4 times per strip, not 8);
    - r = tau_v / tau_L = tau_v (1/(Lambda su)) (1/cos theta_j) (one division per strip), sigma_f =
      (tau_v / tau_0)(1 + r^4) (eyring.flow_stress: tau_f kappa / tau_0 with kappa = (1 + r^4)^(5/4)), 1 / ts =
      (1 + r^4)^(5/4) / tau_0: ts the pair's one division; below SIGMA_HARD two more (lam, 1 / tanh sigma_f);
      above it lam = 0 and tanh sigma_f = 1 (both within 2 e^-36 = 5e-16);
    - den = sum_j w_j p_j/p0 = su sum_j w_j cos theta_j (a constant of the nodes).
    Every switch point joins its two sides within round-off (tests/models/test_traction_tables.py: the bound
    against the exact twin over the whole regime, and finite-difference derivatives across the switch points).
    """
    if S == 0.0:
        return 0.0
    Lam, r0, lv, cp, ce = c
    s = abs(S)
    su = math.sqrt(max(1.0 - u * u, 0.0))
    lS = lv + math.log(s)
    cel = ce * s * su
    csu = cp * su
    iLs = 1.0 / (Lam * su)  # 1 / tau_L = iLs / cos theta_j
    ir0 = 1.0 / r0
    num = 0.0
    for j in range(_NPAIR):
        cs, opn, omn, w, ics = _PAIRS[j, 0], _PAIRS[j, 1], _PAIRS[j, 2], _PAIRS[j, 3], _PAIRS[j, 4]
        mn = _PAIR_MIN[j]
        tv = r0 * _asinh_exp_nb(lS + csu * cs)
        r = tv * (iLs * ics)  # tau_v / tau_L
        r2 = r * r
        g4 = 1.0 + r2 * r2
        its = g4 * math.sqrt(math.sqrt(g4)) * ir0  # kappa / tau_0 = 1 / ts
        sf = tv * g4 * ir0  # sigma_f
        if not sf > 0.0:  # an underflowed flow stress (|S| ~ 1e-320)
            continue
        if cel * its * mn > (sf + _PLASTIC_MARGIN) * _PLASTIC_SAFETY * min(sf, 1.0):  # both nodes fully plastic
            # (E >= cel its mn coth sigma_f, coth x >= 1 / min(x, 1)): sigma = sigma_f, no pair constants
            num += w / its * (sf + sf)
            continue
        lam, em, k1, k2 = 0.0, 1.0, 1.0, 0.0
        fac = its  # 1 / (ts tanh sigma_f)
        if sf >= _SIG_T0 and sf <= SIGMA_HARD:  # the pair constants from the tables of sigma_f (one cell)
            v = (sf - _SIG_T0) * _SIG_IH
            i = min(int(v), _CT_TAB.shape[0] - 1)
            t = v - i
            q = _horner5(_EN_TAB, i, t)
            em = 1.0 - q  # q <= e^-2: no cancellation
            k1 = (1.0 + q) * em
            k2 = q * (1.0 + q)
            lam = _horner5(_LT_TAB, i, t)
            fac = its * _horner5(_CT_TAB, i, t)
        elif sf < _SIG_T0:
            q = math.exp(-sf)
            em = sf * table_eval_nb(_Q_TAB, _Q_X0, _Q_IH, sf)  # 1 - q, relative accuracy as sigma_f -> 0
            k1 = (1.0 + q) * em
            k2 = q * (1.0 + q)
            lam = math.log(em / (1.0 + q))
            fac = its * (1.0 + q * q) / k1
        e = cel * fac
        num += w / its * (_buildup_nb(e * opn, sf, lam, em, k1, k2) + _buildup_nb(e * omn, sf, lam, em, k1, k2))
    mu = num / (su * _SUM_WCS)
    return mu if S > 0.0 else -mu


@numba.njit(cache=True, nogil=True)
def _buildup_exact_nb(tel, tf, ts):
    """Scalar numba twin of :func:`hsbearing.models.traction.eyring.maxwell_eyring_buildup` (same operations)."""
    sf = tf / ts
    if not sf > 0.0:
        return 0.0
    if sf > SIGMA_HARD:
        E = tel / ts
        return ts * (min(E, sf) - math.log1p(math.exp(-abs(E - sf))))
    em = -math.expm1(-sf)
    q = math.exp(-sf)
    E = tel / ts * (1.0 + q * q) / (em * (1.0 + q))
    xm = -math.expm1(-E)
    return ts * math.log1p((1.0 + q) * em * xm / (em * math.exp(-E) + q * (1.0 + q)))


@numba.njit(cache=True, nogil=True)
def eyring_strip_mu_exact_nb(c, S, u):
    """Scalar numba twin of :func:`hsbearing.models.traction.eyring.strip_mu` with libm's exp, asinh, expm1 and log1p
    at every node (odd in S) [-]: the reference of the paired :func:`eyring_strip_mu_nb` the kernel calls."""
    if S == 0.0:
        return 0.0
    Lam, r0, lv, cp, ce = c
    s = abs(S)
    su = math.sqrt(max(1.0 - u * u, 0.0))
    lS = lv + math.log(s)
    num = 0.0
    den = 0.0
    for j in range(_MN.shape[0]):
        sn, cs, w = _MN[j, 0], _MN[j, 1], _MN[j, 2]
        pi_ = su * cs
        tL = Lam * pi_
        lz = lS + cp * pi_
        if lz > LOG_ASINH:
            asn = lz + _LN2
        else:
            asn = math.asinh(math.exp(lz))
        tv = r0 * asn
        lo, hi = min(tv, tL), max(tv, tL)  # flow stress and kappa (eyring.flow_stress)
        rr = tv / tL
        r2 = rr * rr
        g4 = 1.0 + r2 * r2
        rl = lo / hi
        rl2 = rl * rl
        tf = lo / math.sqrt(math.sqrt(1.0 + rl2 * rl2))
        kap = g4 * math.sqrt(math.sqrt(g4))
        tel = ce * s * su * (1.0 + sn)
        num += w * _buildup_exact_nb(tel, tf, r0 / kap)
        den += w * pi_
    mu = num / den
    return mu if S > 0.0 else -mu


@numba.njit(cache=True, nogil=True)
def traction_coefficients_nb(p, W, U, Rx, k, a, phi_T=1.0):
    """Per-contact coefficients of the case's traction law (p: the kernel's parameter record, ``P[0]``).

    Registered seed laws (law_id >= 0): (A, B, C, D, 0) of :func:`coefficients_nb` (unchanged); user
    coefficients: (c_A, c_B, c_C, c_D, 0); the physical model: :func:`eyring_coefficients_nb`.
    W normal load [N], U rolling speed [m/s], Rx [m], k = a/b [-], a semi-major axis [m]; phi_T the contact's
    inlet-heating film factor (the physical model's central film only; 1 = isothermal).
    """
    return race_traction_coefficients_nb(p, W, U, Rx, k, a, phi_T, p.traction.T_K, p.lubricant.eta_in, p.lubricant.alpha,
                                         p.traction.tau0, p.traction.Lambda, p.traction.G)


@numba.njit(cache=True, nogil=True)
def race_traction_coefficients_nb(p, W, U, Rx, k, a, phi_T, T_K, eta_in, alpha, tau0, Lam, G):
    """:func:`traction_coefficients_nb` with the inlet oil of one race given: its temperature T_K [K] (seed laws),
    inlet viscosity eta_in [Pa s], pressure-viscosity coefficient alpha [1/Pa] and the physical model's tau0 [Pa],
    Lambda [-], G [Pa] at that temperature (the kernel's inner race: the record's ``lubricant``/``traction`` fields;
    the outer race: its ``outer_oil`` fields).  The law and the user coefficients come from the record ``p``."""
    lid = p.traction.law_id
    if lid >= 0:
        A, B, C, D = coefficients_nb(lid, W, U, T_K, p.race.Ep, Rx)
        return A, B, C, D, 0.0
    if lid == COEFFICIENTS_LAW_ID:
        return p.traction.c_A, p.traction.c_B, p.traction.c_C, p.traction.c_D, 0.0
    return eyring_coefficients_nb(W, U, p.race.Ep, Rx, k, a, eta_in, alpha, tau0, Lam, G, phi_T)


@numba.njit(cache=True, nogil=True)
def traction_mu_nb(law_id, c, S, u):
    """mu at slide-roll ratio S of the strip at u (y = a u) with the per-contact coefficients c [-] (odd in S)."""
    if law_id == EYRING_LAW_ID:
        return eyring_strip_mu_nb(c, S, u)
    return mu_nb(c[0], c[1], c[2], c[3], S)


# numba bakes callees and captured constants into its cache: key the cache on them (compile_cache.py)
check_compile_cache(globals())
