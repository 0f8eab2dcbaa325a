"""Isothermal Eyring / limiting-shear-stress estimate of the traction level of a Hertz contact.

Used as evidence on the *level* of the Zhang et al. 2016 laws (docs/traction.md, "Measured data: what
was searched, and the level"), not by the dynamics.  No measured traction curve of a comparable
ester turbine oil could be retrieved (the search is logged in docs/traction.md), so the level is
bracketed by the one family of measured parameters that could be found with their conditions:
limiting-shear-stress coefficients Lambda = tau_L / p of lubricant base oils.

Model (viscous film, no heating, no elastic compliance), evaluated pointwise over the Hertz
ellipse and integrated by quadrature (an independent numerical solution, not a closed form)::

    tau(x, y) = min( tau_E asinh( eta(p) |S| U / (tau_E h) ),  Lambda p )          ([1] Eq. 7)
    eta(p)    = eta_in exp(alpha p)   (Barus)
    tau_E     = 2 Lambda / alpha                                                    ([1] Eq. 12, [2])
    mu        = sign(S) \\iint tau dA / W

Each simplification raises mu at a given S: heating lowers eta and tau, elastic compliance of
the film lowers tau at small S ([3]), so the result is an *upper* estimate of an isothermal-free
measured curve at the same conditions -- as long as Lambda is not underestimated.  It reaches
Lambda (mu = Lambda exactly when the whole contact is at the limiting stress) at large S.

References
----------
[1] Arana A., Larrañaga J., Ulacia I., "Partial EHL friction coefficient model to predict power
    losses in cylindrical gears", Proc. IMechE Part J 233(2) (2019) 303-316: Eq. (7) (Eyring
    stress capped at tau_L = Lambda p), Eq. (12) (tau_E = (v_p/v_tau)/alpha with
    v_p/v_tau = 2 Lambda), Table 2 (Lambda measured by Hoeglund: naphthenic N100 0.053,
    paraffinic M100 0.047, PAO100 0.035) and the Bair & Winer values quoted in the text
    (LVI 260 0.047, 5P4E 0.088).
[2] Bair S., Winer W. O., "A rheological model for elastohydrodynamic contacts based on primary
    laboratory data", J. Lubr. Technol. 101 (1979) 258-265 (tau_E ~ 2 Lambda / alpha, as quoted in [1]).
[3] Johnson K. L., Tevaarwerk J. L., Proc. R. Soc. Lond. A 356 (1977) 215-236 (Maxwell fluid:
    the elastic term only lowers the stress at a given slip).
"""

from __future__ import annotations

import math

import numpy as np

__all__ = ["LAMBDA_BRACKET", "eyring_stress", "isothermal_mu"]

#: Limiting-shear-stress coefficients [-] bracketing an ester base oil: PAO100 (lower) and paraffinic
#: mineral M100 (upper), measured by Hoeglund, tabulated in [1] Table 2.  An ester is placed between a
#: PAO and a solvent-neutral mineral oil by the LSS ranking of Lubricants 13(11) 485 (2025), conclusion (b)
#: (40 degC: OSP-M > NBO-M > 500N > ester > AN-M > PAO-M).  A bracket by analogy, not a measurement of
#: the oils 4109/4106/4050.
LAMBDA_BRACKET = (0.035, 0.047)


def eyring_stress(Lambda, alpha):
    """Eyring stress tau_E = 2 Lambda / alpha [Pa] ([1] Eq. 12, [2]).

    Parameters
    ----------
    Lambda : limiting-shear-stress coefficient tau_L / p [-];  alpha : pressure-viscosity coefficient [1/Pa]
    """
    return 2.0 * Lambda / alpha


def isothermal_mu(S, W, U, eta_in, alpha, a, b, h, Lambda, tau_E=None, n=201):
    """Isothermal Eyring traction coefficient capped at Lambda p, integrated over a Hertz ellipse [-].

    Parameters
    ----------
    S : slide-roll ratio (U1 - U2)/U [-], scalar or array (a fraction);  W : normal load [N]
    U : rolling (entrainment) speed [m/s];  eta_in : inlet viscosity [Pa s]
    alpha : Barus pressure-viscosity coefficient [1/Pa];  a, b : Hertz semi-axes transverse / rolling [m]
    h : film thickness [m];  Lambda : limiting-shear-stress coefficient [-]
    tau_E : Eyring stress [Pa] (default :func:`eyring_stress`);  n : quadrature nodes per axis

    Returns
    -------
    mu : same shape as S [-], odd in S, 0 <= |mu| <= Lambda
    """
    if tau_E is None:
        tau_E = eyring_stress(Lambda, alpha)
    S = np.asarray(S, dtype=float)
    p0 = 1.5 * W / (math.pi * a * b)
    u = (np.arange(n) + 0.5) / n * 2.0 - 1.0
    X, Y = np.meshgrid(u, u, indexing="ij")
    inside = (X * X + Y * Y < 1.0).ravel()
    p = p0 * np.sqrt(1.0 - (X * X + Y * Y).ravel()[inside])
    eta = eta_in * np.exp(alpha * p)
    dA = (2.0 * b / n) * (2.0 * a / n)
    rate = np.abs(S).reshape(-1, 1) * (U / h)  # shear rate [1/s], one row per S
    tau = np.minimum(tau_E * np.arcsinh(eta * rate / tau_E), Lambda * p)
    mu = tau.sum(axis=1) * dA / W
    return (np.sign(S).ravel() * mu).reshape(S.shape)
