"""Coefficients of the libm-free atan of the batched pocket stations (``hsbearing.models.ball_bearing.pocket._ATAN_P``).

    .venv/bin/python tools/generators/make_atan_poly.py [--degree 11]

On |w| <= tan(pi/8) (the range left by the reduction in :func:`hsbearing.models.ball_bearing.pocket._atan_poly`),
atan(w) = w + w s P(s) with s = w^2 and P(s) = (atan(sqrt s)/sqrt s - 1)/s, analytic on [0, tan^2(pi/8)] with
its nearest singularity at s = -1.  P is interpolated at 200 Chebyshev nodes of that interval (values from
numpy's long-double atan; the series -1/3 + s/5 - s^2/7 + ... below s = 1e-4, where the quotient loses digits),
converted to ascending powers of s, and checked: the relative error of w + w s P(s), evaluated in double by
Horner's scheme as the kernel does, against long-double atan on 200001 points of the reduced range (printed;
1.07 ulp for degree 11).  Prints the tuple to paste into pocket.py.
"""

from __future__ import annotations

import argparse
from math import comb

import numpy as np
from numpy.polynomial import chebyshev as cheb

S_MAX = np.tan(np.pi / 8) ** 2


def p_exact(s):
    """(atan(sqrt s)/sqrt s - 1)/s in long double (series for small s)."""
    s = np.asarray(s, dtype=np.longdouble)
    out = np.empty_like(s)
    small = s < 1e-4
    ss = s[small]
    out[small] = sum(((-1) ** (k + 1)) * ss ** k / (2 * k + 3) for k in range(8))
    w = np.sqrt(s[~small])
    out[~small] = (np.arctan(w) / w - 1) / s[~small]
    return out


def coefficients(degree: int, nodes: int = 200) -> np.ndarray:
    u = np.cos(np.pi * (np.arange(nodes) + 0.5) / nodes)
    s = (u + 1) * 0.5 * S_MAX
    c_u = cheb.cheb2poly(cheb.chebfit(u, p_exact(s).astype(float), degree))  # powers of u = 2 s/S_MAX - 1
    a, b = np.longdouble(2) / np.longdouble(S_MAX), np.longdouble(-1)
    c_s = np.zeros(degree + 1, dtype=np.longdouble)
    for k, ck in enumerate(c_u):
        for j in range(k + 1):
            c_s[j] += np.longdouble(ck) * comb(k, j) * a ** j * b ** (k - j)
    return c_s.astype(float)


def max_relative_error(coef: np.ndarray, n: int = 200001) -> float:
    """Largest relative error of w + w s P(s) (double, Horner) against long-double atan, in units of 2^-53."""
    w = np.linspace(0.0, np.sqrt(S_MAX), n)[1:]
    s = w * w
    p = np.zeros_like(s)
    for c in coef[::-1]:
        p = p * s + c
    approx = w + w * (s * p)
    ref = np.arctan(w.astype(np.longdouble))
    return float(np.max(np.abs((approx - ref) / ref))) / 2.0 ** -53


def main(argv=None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--degree", type=int, default=11)
    args = ap.parse_args(argv)
    coef = coefficients(args.degree)
    print(f"degree {args.degree}: max relative error over |w| <= tan(pi/8): {max_relative_error(coef):.2f} ulp")
    print("_ATAN_P = (" + ", ".join(repr(float(c)) for c in coef) + ")")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
