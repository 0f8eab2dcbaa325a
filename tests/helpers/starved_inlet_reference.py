"""Independent 1-D solution of a starved EHL inlet (reference for models/ball_bearing/starvation.py).

Grubin's inlet analysis along the rolling direction of a contact, with the inlet cut at a meniscus:

* the gap: inside the Hertz zone |x| <= b a flat film h0; outside, the rigid Hertzian shape
  h(x) = h0 + (b^2 / (2R)) G(|x|/b), G the separation of a Hertz line contact, computed here by quadrature of its
  slope dG/dX = 2 sqrt(X^2 - 1) (not the closed form the model uses);
* Reynolds, steady, pure rolling at the mean speed u (either sign), Barus viscosity eta0 exp(alpha p), written for
  the reduced pressure q = (1 - exp(-alpha p)) / alpha:  dq/dx = 12 eta0 u (h - h0) / h^3;
* boundary conditions: q = 0 at the meniscus x_m (the gap is full of oil from the meniscus on, the Swift-Stieber /
  JFO film-rupture condition applied at the inlet boundary, no pressure upstream of it); q = 1/alpha (p infinite) at
  the contact edge (Grubin's condition: the inlet must raise the pressure to the Hertz level).  The inlet lies
  upstream: at x < -b for u > 0, at x > +b for u < 0 (the solver integrates in x, so both directions are solved, not
  mirrored).  A meniscus at infinity is the flooded inlet.
* the rolling force per unit width: the viscous dissipation of the inlet's pressure flow over u,
  F = (1/u) int u (h - h0) dp/dx dx (pure rolling: no Couette shear power), dp/dx = (dq/dx) / (1 - alpha q).

In units of b and b^2 / (2R) every result depends on the dimensionless flooded film Hbar = h0 2R / b^2 and the
meniscus distance m = |x_m| / b only (the speed, viscosity and alpha fix Hbar).  Quadrature on X = 1 + t^2
(t = sqrt(m - 1) u^2, u uniform: nodes clustered at the contact edge), which removes the square-root behaviour
there; trapezoid rule, second order in du
(checked at two resolutions by tests/models/test_starvation.py).
"""

from __future__ import annotations

import numpy as np
from scipy.optimize import brentq

#: far field of the flooded inlet, in contact semi-widths (the integrand falls as X^-4: the truncation is < 1e-9)
FLOODED_M = 2000.0


def _grid(m, sign, n):
    """x / b on the inlet side from the contact edge to the meniscus, and the gap shape G there."""
    t = np.sqrt(m - 1.0) * np.linspace(0.0, 1.0, n) ** 2  # clustered at the edge, where the pressure builds
    X = 1.0 + t * t
    dGdt = 4.0 * t * t * np.sqrt(t * t + 2.0)  # dG/dX dX/dt = 2 sqrt(X^2 - 1) * 2t, X^2 - 1 = t^2 (t^2 + 2)
    G = np.concatenate(([0.0], np.cumsum(0.5 * (dGdt[1:] + dGdt[:-1]) * np.diff(t))))
    x = -sign * X  # the inlet is upstream: x < -1 for u > 0
    return x, G


def _integral(x, y):
    return float(np.sum(0.5 * (y[1:] + y[:-1]) * np.diff(x)))


def inlet_pressure_integral(H0, m, sign=1.0, n=4000):
    """I = int from the meniscus to the contact edge of G / (H0 + G)^3 dX (the reduced-pressure rise per unit
    12 eta0 |u| (2R)^2 / b^3; integrated along the flow, so positive for either sign of u)."""
    x, G = _grid(m, sign, n)
    # along the flow: from the meniscus (upstream end, last node) to the edge (first node); dx in the flow sense
    xs, ys = x[::-1], (G / (H0 + G) ** 3)[::-1]
    return _integral(xs, ys) * sign


def starved_film(Hbar_flooded, m, sign=1.0, n=4000):
    """Dimensionless central film H0 of an inlet cut at m (Grubin's condition at the edge), for the flooded Hbar."""
    target = inlet_pressure_integral(Hbar_flooded, FLOODED_M, sign, n)
    if m >= FLOODED_M:
        return float(Hbar_flooded)
    f = lambda H: inlet_pressure_integral(H, m, sign, n) - target  # noqa: E731  falls as H rises
    lo = Hbar_flooded * 1e-8
    if f(lo) < 0.0:  # even a vanishing film cannot build the pressure: no solution (m too close to 1)
        return 0.0
    return float(brentq(f, lo, Hbar_flooded * (1.0 + 1e-9), xtol=1e-14 * Hbar_flooded, rtol=1e-12))


def rolling_force(H0, m, sign=1.0, n=4000):
    """Dimensionless inlet rolling force Fhat = F alpha 2R / b^2 per unit width of the inlet cut at m with film H0:
    int (h - h0) dp/dX dX over the inlet, dp/dX = (dq/dX) / (1 - alpha q), alpha q rising from 0 at the meniscus to 1
    at the edge (the constant 12 eta0 u (2R)^2 / b^3 cancels against Grubin's condition)."""
    x, G = _grid(m, sign, n)
    xs, Gs = x[::-1], G[::-1]  # along the flow
    g = Gs / (H0 + Gs) ** 3
    dx = np.diff(xs) * sign  # positive steps along the flow
    cum = np.concatenate(([0.0], np.cumsum(0.5 * (g[1:] + g[:-1]) * dx)))  # alpha q x I
    I_tot = cum[-1]
    rest = I_tot - cum  # I (1 - alpha q): the pressure still to be built downstream of each node
    with np.errstate(divide="ignore", invalid="ignore"):
        integrand = np.where(rest > 0.0, Gs * g / rest, 0.0)  # (h - h0) dq/dX / (1 - alpha q), units cancelled
    # at the edge (rest -> 0) the integrand -> 0 like sqrt(X - 1): the last node contributes nothing
    return float(np.sum(0.5 * (integrand[1:] + integrand[:-1]) * dx))


def starved_ratios(Hbar_flooded, m, sign=1.0, n=4000):
    """(film ratio h_c,s / h_c,ff, rolling-force ratio F_s / F_ff) of the inlet cut at m."""
    Hs = starved_film(Hbar_flooded, m, sign, n)
    Ff = rolling_force(Hbar_flooded, FLOODED_M, sign, n)
    Fs = rolling_force(Hs, m, sign, n) if Hs > 0.0 else 0.0
    return Hs / Hbar_flooded, Fs / Ff
