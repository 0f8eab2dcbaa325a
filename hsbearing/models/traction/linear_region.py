"""Independent estimate of the low-slip slope dmu/dS of an EHL traction curve (the linear region).

Used as evidence for the reading of the Zhang et al. 2016 laws (docs/traction.md, "Evidence"), not by the
dynamics.  At S -> 0 nothing heats and nothing shear-thins, so the traction of a lubricated
Hertzian contact is linear in S with a slope set by three compliances in series:

* the viscous film (Newtonian, Barus pressure-viscosity):  tau = eta(p) S U / h,
  slope N = U / (h W) \\iint eta(p) dA                                            ([2], [3]);
* the elastic film (the Maxwell fluid's elastic limit): a fluid element that entered the
  contact at the inlet edge x_in(y) carries the strain S (x - x_in)/h at x, so
  tau = G S (x - x_in)/h and E_f = G / (h W) \\iint (x - x_in) dA                   ([3]);
* the elastic solids (rolling creep, Carter's 2-D linear limit):  xi = (b / (2 R)) Q/P, so
  C = 2 R_x / b, b the semi-axis in the rolling direction                           ([1]);

dmu/dS = 1 / (1/N + 1/E_f + 1/C).  Each term is evaluated by quadrature over the Hertz
ellipse (not a closed form), so the estimate is an independent numerical solution.

References
----------
[1] Johnson K. L., *Contact Mechanics*, Cambridge 1985, Sec. 8.4 (Carter's solution of
    2-D rolling with traction; linear creep xi = (a/2R) Q/P for small Q/(mu P)).
[2] Hamrock B. J., Dowson D., J. Lubr. Technol. 99 (1977) 264-276 (central film thickness,
    via :func:`hsbearing.models.ehl.film_thickness`).
[3] Johnson K. L., Tevaarwerk J. L., "Shear behaviour of elastohydrodynamic oil films",
    Proc. R. Soc. Lond. A 356 (1977) 215-236: Maxwell model tau/G' + tau-dot... ; the effective
    elastic shear modulus of EHL films is of order 0.1-1 GPa (order of magnitude used here).
"""

from __future__ import annotations

import math

import numpy as np

__all__ = ["carter_creep_slope", "film_slopes", "low_slip_slope"]


def carter_creep_slope(Rx, b):
    """Low-slip slope of the elastic solids, C = 2 R_x / b [-] ([1], Sec. 8.4).

    Parameters
    ----------
    Rx : effective radius in the rolling direction [m];  b : Hertz semi-axis in the rolling direction [m]
    """
    return 2.0 * Rx / b


def film_slopes(W, U, eta_in, alpha, a, b, h, G, n=201):
    """(N, E_f): viscous and elastic film slopes of a Hertz ellipse by quadrature [-].

    Parameters
    ----------
    W : normal load [N];  U : rolling speed [m/s];  eta_in : inlet viscosity [Pa s]
    alpha : pressure-viscosity coefficient [1/Pa];  a, b : semi-axes transverse / rolling [m]
    h : film thickness [m];  G : elastic shear modulus of the film [Pa];  n : quadrature nodes per axis
    """
    p0 = 1.5 * W / (math.pi * a * b)
    # midpoint grid on the unit square mapped to the ellipse (x along rolling over b, y transverse over a)
    u = (np.arange(n) + 0.5) / n * 2.0 - 1.0
    X, Y = np.meshgrid(u, u, indexing="ij")
    inside = X * X + Y * Y < 1.0
    dA = (2.0 * b / n) * (2.0 * a / n)
    r2 = np.where(inside, X * X + Y * Y, 1.0)
    p = p0 * np.sqrt(1.0 - r2)
    eta = eta_in * np.exp(alpha * p)  # Barus
    N = U / (h * W) * float(np.sum(np.where(inside, eta, 0.0)) * dA)
    x_in = -np.sqrt(np.clip(1.0 - Y * Y, 0.0, None))  # inlet edge at this y (units of b)
    strain_len = (X - x_in) * b  # distance travelled inside the contact [m]
    E_f = G / (h * W) * float(np.sum(np.where(inside, strain_len, 0.0)) * dA)
    return N, E_f


def low_slip_slope(W, U, eta_in, alpha, Rx, a, b, h, G):
    """Series combination 1 / (1/N + 1/E_f + 1/C) of :func:`film_slopes` and :func:`carter_creep_slope` [-]."""
    N, E_f = film_slopes(W, U, eta_in, alpha, a, b, h, G)
    C = carter_creep_slope(Rx, b)
    return 1.0 / (1.0 / N + 1.0 / E_f + 1.0 / C)
