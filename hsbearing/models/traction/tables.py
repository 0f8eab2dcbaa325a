"""Quintic Hermite tables of smooth one-variable functions: the transcendental parts of a strip integrand at the
cost of a table look-up and a degree-5 polynomial, C2 across the cells, with a bound checked when built.

Why: the physical traction model integrates a local stress over 8 nodes x 5 strips of every contact at every rhs
call, and each node's libm calls (an exp, an asinh, an expm1) were ~90 % of that cost (docs/traction.md,
"Tabulated strip integrand").  Every local stress law of the strip integrand (the isothermal Eyring law of
:mod:`~hsbearing.models.traction.eyring`, a thermal one) is built from a few smooth functions of ONE variable;
each such function is tabulated here once, at import, and evaluated in the kernel by
:func:`hsbearing.models.traction._kernels.table_eval_nb`.  Nothing per contact, nothing remembered between rhs calls:
the rhs stays a pure function of the state, so CVODE's Newton iterations and finite-difference Jacobians see the
same smooth function as before, within the table's bound.

Construction (standard piecewise quintic Hermite interpolation, e.g. de Boor, *A Practical Guide to Splines*,
Ch. II; Burden & Faires, *Numerical Analysis*, Sec. 3.4 for the Hermite error term): on a uniform grid
x_i = x0 + i h, cell i carries the degree-5 polynomial in t = (x - x_i)/h in [0, 1] that matches f, f' and f'' at
both ends.  Adjacent cells share those values, so the interpolant is C2 everywhere (to round-off); its error is

    f(x) - H(x) = f^(6)(xi) / 720 (x - x_i)^3 (x - x_{i+1})^3,   |.| <= max|f^(6)| h^6 / 46080

(the Hermite remainder with triple nodes at both ends).  :func:`build` measures the actual error against the exact
function on a grid 64 points per cell and refuses a table above the requested tolerance; :class:`Table` keeps the
measured error for the docs and the tests.

Coefficients of cell i (p(t) = sum_k c_k t^k), with f0, d0 = h f'(x_i), s0 = h^2 f''(x_i) at the left end and
f1, d1, s1 at the right end:

    c0 = f0, c1 = d0, c2 = s0 / 2
    c3 = 10 (f1 - f0) - 6 d0 - 4 d1 - (3 s0 - s1) / 2
    c4 = -15 (f1 - f0) + 8 d0 + 7 d1 + (3 s0 - 2 s1) / 2
    c5 = 6 (f1 - f0) - 3 d0 - 3 d1 - (s0 - s1) / 2
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

__all__ = ["Table", "build", "evaluate", "ASINH_EXP", "ONE_MINUS_EXP_OVER_X", "LOG1P", "SOFTPLUS_NEG", "LOG1M_EXP", "COTH",
           "LN_TANH_HALF", "EXP_NEG"]


@dataclass(frozen=True)
class Table:
    """A quintic Hermite table of f on [x0, x0 + n h]: ``coef`` (n, 6), cell width ``h``, measured max errors."""

    name: str
    x0: float
    h: float
    coef: np.ndarray
    max_abs_error: float
    max_rel_error: float

    @property
    def x1(self) -> float:
        return self.x0 + self.coef.shape[0] * self.h


def _coefficients(f0, d0, s0, f1, d1, s1):
    df = f1 - f0
    return np.stack([f0, d0, 0.5 * s0,
                     10.0 * df - 6.0 * d0 - 4.0 * d1 - 0.5 * (3.0 * s0 - s1),
                     -15.0 * df + 8.0 * d0 + 7.0 * d1 + 0.5 * (3.0 * s0 - 2.0 * s1),
                     6.0 * df - 3.0 * d0 - 3.0 * d1 - 0.5 * (s0 - s1)], axis=1)


def evaluate(tab: Table, x) -> np.ndarray:
    """The table at x (vectorised Python twin of ``_kernels.table_eval_nb``; x clamped to the table's range)."""
    x = np.asarray(x, dtype=float)
    n = tab.coef.shape[0]
    u = (x - tab.x0) / tab.h
    i = np.clip(np.floor(u).astype(np.int64), 0, n - 1)
    t = u - i
    c = tab.coef[i]
    return c[..., 0] + t * (c[..., 1] + t * (c[..., 2] + t * (c[..., 3] + t * (c[..., 4] + t * c[..., 5]))))


def build(name, f, df, d2f, x0, x1, h, rtol, atol=0.0) -> Table:
    """Table of f on [x0, x1] with cells of width h from the exact f, f', f'' (vectorised callables).

    Checked on 64 points per cell against f: raises ValueError if |f - H| > atol + rtol |f| anywhere.
    """
    n = int(round((x1 - x0) / h))
    if not n >= 1 or abs(x0 + n * h - x1) > 1e-9 * max(1.0, abs(x1)):
        raise ValueError(f"table {name}: [{x0}, {x1}] is not a whole number of cells of {h}")
    x = x0 + h * np.arange(n + 1)
    F, D, S = f(x), h * df(x), h * h * d2f(x)
    coef = _coefficients(F[:-1], D[:-1], S[:-1], F[1:], D[1:], S[1:])
    tab = Table(name, float(x0), float(h), np.ascontiguousarray(coef), 0.0, 0.0)
    xs = (x0 + h * (np.arange(n * 64) + 0.5) / 64.0)
    ex, ap = f(xs), evaluate(tab, xs)
    err = np.abs(ap - ex)
    bad = err > atol + rtol * np.abs(ex)
    if bad.any():
        k = int(np.argmax(err - rtol * np.abs(ex)))
        raise ValueError(f"table {name}: error {err[k]:.3g} at x = {xs[k]:.6g} (f = {ex[k]:.6g}) above the bound")
    rel = float(np.max(err / np.maximum(np.abs(ex), np.finfo(float).tiny)))
    coef.setflags(write=False)
    return Table(name, float(x0), float(h), tab.coef, float(err.max()), rel)


# --- the two functions of the isothermal Eyring strip integrand (models.traction.eyring) ---------------------------

#: lz at and above which asinh(e^lz) = lz + ln 2 to double precision (1/(4 z^2) < 2^-53 for z > 2.4e7); = eyring.LOG_ASINH
LOG_ASINH = 17.0
#: lz below which asinh(e^lz) = e^lz to double precision (z^2/6 < 2^-53): the kernel calls exp there (rare)
LOG_ASINH_LOW = -18.0


def _asinh_exp(x):
    return np.arcsinh(np.exp(x))


def _asinh_exp_d1(x):  # d/dx asinh(e^x) = e^x / sqrt(1 + e^2x) = 1 / sqrt(1 + e^-2x)
    return 1.0 / np.sqrt(1.0 + np.exp(-2.0 * x))


def _asinh_exp_d2(x):  # e^-2x (1 + e^-2x)^(-3/2)
    e = np.exp(-2.0 * x)
    return e / (1.0 + e) ** 1.5


#: asinh(e^lz) on [LOG_ASINH_LOW, LOG_ASINH]: the Eyring flow stress tau_0 asinh(eta gamma / tau_0) with
#: ln(eta gamma / tau_0) = lz (Barus: lz linear in p).  1120 cells of 1/32; relative error <= 1.5e-13 asserted
#: (measured 9.2e-14; h^6 convergence: 5.9e-12 at 1/16, 1.6e-15 at 1/64).
ASINH_EXP = build("asinh(exp(x))", _asinh_exp, _asinh_exp_d1, _asinh_exp_d2, LOG_ASINH_LOW, LOG_ASINH,
                  1.0 / 32.0, rtol=1.5e-13)


def _q_series(y, m):
    """m-th derivative of (1 - e^-y)/y from its series sum_k (-1)^k y^k / (k+1)! (y < 0.5)."""
    out = np.zeros_like(y)
    for k in range(m, m + 30):
        c = (-1.0) ** k / math.factorial(k + 1) * math.factorial(k) / math.factorial(k - m)
        out = out + c * y ** (k - m)
    return out


def _q0(y):
    y = np.asarray(y, dtype=float)
    small = y < 0.5
    yl = np.where(small, 1.0, y)
    return np.where(small, _q_series(np.where(small, y, 0.0), 0), -np.expm1(-yl) / yl)


def _q1(y):  # (y e^-y + expm1(-y)) / y^2
    y = np.asarray(y, dtype=float)
    small = y < 0.5
    yl = np.where(small, 1.0, y)
    return np.where(small, _q_series(np.where(small, y, 0.0), 1), (yl * np.exp(-yl) + np.expm1(-yl)) / yl**2)


def _q2(y):  # -(y^2 e^-y + 2 y e^-y + 2 expm1(-y)) / y^3
    y = np.asarray(y, dtype=float)
    small = y < 0.5
    yl = np.where(small, 1.0, y)
    return np.where(small, _q_series(np.where(small, y, 0.0), 2),
                    -(yl * yl * np.exp(-yl) + 2.0 * yl * np.exp(-yl) + 2.0 * np.expm1(-yl)) / yl**3)


#: y at and beyond which 1 - e^-y rounds to 1 (e^-40 = 4e-18 < 2^-54): the Maxwell build-up is complete
ONE_MINUS_EXP_END = 40.0
#: (1 - e^-y) / y on [0, ONE_MINUS_EXP_END]: the Maxwell build-up tau = tau_f y q(y), y = tau_el / tau_f, with
#: RELATIVE accuracy down to y -> 0 (the elastic limit tau = tau_el).  640 cells of 1/16; relative error
#: <= 3e-13 asserted (measured 1.8e-13; 2.9e-15 at 1/32).
ONE_MINUS_EXP_OVER_X = build("(1 - exp(-x)) / x", _q0, _q1, _q2, 0.0, ONE_MINUS_EXP_END, 1.0 / 16.0,
                             rtol=3e-13)


# --- the two functions of the Maxwell-Eyring build-up (eyring.maxwell_eyring_buildup) -------------------------------

def _log1p(x):
    return np.log1p(x)


def _log1p_d1(x):
    return 1.0 / (1.0 + x)


def _log1p_d2(x):
    return -1.0 / (1.0 + x) ** 2


#: log1p(A) on [0, 1]: the build-up sigma = log1p(A) of its well-conditioned form near the inlet (elastic stress
#: E < 0.5, where A <= 0.65), with RELATIVE accuracy down to A -> 0 (the Hermite cell at 0 matches f, f', f''
#: exactly, so the error is O(A^3)).  128 cells of 1/128; relative error <= 3e-13 asserted.
LOG1P = build("log1p(x)", _log1p, _log1p_d1, _log1p_d2, 0.0, 1.0, 1.0 / 128.0, rtol=3e-13)


def _softplus_neg(t):  # log1p(e^-t), t >= 0
    return np.log1p(np.exp(-t))


def _softplus_neg_d1(t):
    return -1.0 / (1.0 + np.exp(t))


def _softplus_neg_d2(t):
    e = np.exp(-t)
    return e / (1.0 + e) ** 2


#: t at and beyond which log1p(e^-t) < 4.3e-18 is dropped (the rounded minimum of the build-up's log-sum-exp form)
SOFTPLUS_END = 40.0
#: log1p(e^-t) on [0, SOFTPLUS_END]: the rounding of the minimum min(E, sigma_f) - log1p(e^-|E - sigma_f|) of the
#: build-up where e^-sigma_f is below round-off (eyring.SIGMA_HARD).  960 cells of 1/24; relative error <= 3e-13 asserted.
SOFTPLUS_NEG = build("log1p(exp(-x))", _softplus_neg, _softplus_neg_d1, _softplus_neg_d2, 0.0, SOFTPLUS_END,
                     1.0 / 24.0, rtol=3e-13)


def _log1m_exp(z):  # log(1 - e^z) = log1p(-e^z), z <= -1.75 (e^z <= 0.17: log1p keeps the relative accuracy)
    return np.log1p(-np.exp(z))


def _log1m_exp_d1(z):  # -e^z / (1 - e^z) = -1 / (e^-z - 1)
    return -1.0 / np.expm1(-z)


def _log1m_exp_d2(z):  # -e^z / (1 - e^z)^2 = -e^-z / (e^-z - 1)^2
    e = np.expm1(-z)
    return -(e + 1.0) / (e * e)


#: z below which log(1 - e^z) (> -4.3e-18 there) is dropped
LOG1M_EXP_START = -40.0
#: the upper end of the table (the argument never exceeds ln(sqrt 2 - 1) - asinh 1 = -1.7627)
LOG1M_EXP_END = -1.75
#: log(1 - e^z) on [LOG1M_EXP_START, LOG1M_EXP_END]: the build-up's factor ln(1 - q tanh(sigma_f/2) e^-E) (its argument
#: ln tanh(sigma_f/2) - sigma_f - E <= -1.763, the maximum at sigma_f = asinh 1).  The relative error is asserted.
LOG1M_EXP = build("log(1 - exp(x))", _log1m_exp, _log1m_exp_d1, _log1m_exp_d2, LOG1M_EXP_START, LOG1M_EXP_END,
                  1.0 / 32.0, rtol=5e-13)



# --- the per-pair constants of the build-up as functions of sigma_f alone (the kernel's pairs, sigma_f in [2, 36]) ---

def _coth(x):
    return 1.0 / np.tanh(x)


def _coth_d1(x):
    return -1.0 / np.sinh(x) ** 2


def _coth_d2(x):
    return 2.0 * np.cosh(x) / np.sinh(x) ** 3


def _ln_tanh_half(x):  # ln tanh(x/2) = ln((1 - e^-x) / (1 + e^-x)), without the rounding of tanh near 1
    return np.log1p(-np.exp(-x)) - np.log1p(np.exp(-x))


def _ln_tanh_half_d1(x):
    return 1.0 / np.sinh(x)


def _ln_tanh_half_d2(x):
    return -np.cosh(x) / np.sinh(x) ** 2


#: sigma_f range of the two tables below (below: libm; above eyring.SIGMA_HARD = 36 both are 1 and 0 to round-off)
SIGMA_TABLE = (2.0, 36.0)
#: coth sigma_f on SIGMA_TABLE: E = tau_el / (ts tanh sigma_f).  1088 cells of 1/32; relative error <= 3e-13 asserted.
COTH = build("coth(x)", _coth, _coth_d1, _coth_d2, SIGMA_TABLE[0], SIGMA_TABLE[1], 1.0 / 32.0, rtol=3e-13)
#: ln tanh(sigma_f / 2) on SIGMA_TABLE: the build-up's lam.  1088 cells of 1/32; relative error <= 3e-13 asserted.
LN_TANH_HALF = build("ln(tanh(x/2))", _ln_tanh_half, _ln_tanh_half_d1, _ln_tanh_half_d2, SIGMA_TABLE[0],
                     SIGMA_TABLE[1], 1.0 / 32.0, rtol=3e-13)



def _exp_neg(x):
    return np.exp(-x)


def _exp_neg_d1(x):
    return -np.exp(-x)


#: e^-sigma_f on SIGMA_TABLE (q of the build-up; the same grid as COTH and LN_TANH_HALF, so the kernel locates the cell
#: once for the three).  Relative error <= 3e-13 asserted.
EXP_NEG = build("exp(-x)", _exp_neg, _exp_neg_d1, _exp_neg, SIGMA_TABLE[0], SIGMA_TABLE[1], 1.0 / 32.0, rtol=3e-13)
