"""Physical EHL traction model for any oil: Maxwell elastic build-up, Eyring flow, limiting shear.

The traction of a ball/race contact computed from the oil's own properties (its inlet viscosity eta_in,
its pressure-viscosity coefficient alpha) and three rheological constants (Eyring stress tau_0,
limiting-shear-stress coefficient Lambda, film shear modulus G), not from a curve fit.  It is registered
as the law ``"eyring"`` of every oil (:mod:`hsbearing.models.traction`) and compiled into the dynamics
kernel (:mod:`hsbearing.models.traction._kernels`, ``EYRING_LAW_ID``).

Local constitutive law at a point of the Hertz ellipse with pressure p, film thickness h, rolling speed U
and slide-roll ratio S (shear rate S U / h), a fluid element having travelled x - x_in from the inlet edge::

    eta(p)  = eta_in exp(alpha p)                          Barus (the oil's alpha, as eyring_limit, linear_region)
    tau_v   = tau_0 asinh( eta(p) S U / (h tau_0) )        Eyring viscous flow stress                [1], [2]
    tau_f   = (tau_v^-4 + tau_L^-4)^(-1/4),  tau_L = Lambda p
                                                           flow stress capped by the limiting shear [3], [5]
    tau_el  = G_eff S (x - x_in) / h                       elastic strain carried from the inlet      [1]
    tau     = maxwell_eyring_buildup(tau_el, tau_f, tau_f / sigma_f)
                                                           Maxwell-Eyring build-up towards tau_f      [1]

The last line (:func:`maxwell_eyring_buildup`) is the exact solution of Johnson & Tevaarwerk's non-linear
Maxwell equation (U / G) dtau/dx + gdot_v(tau) = S U / h along the path from the inlet with the point's own flow
properties (viscosity, Eyring stress, limiting shear) held along it, the viscous rate gdot_v written as the sinh of
the stress over its local stress scale tau_0 / kappa, kappa = dtau_v/dtau at tau_f (exact for the Eyring flow,
kappa = 1, and the tangent of the cap).  Until 0.1.0 the law took the linear Maxwell solution
tau_f (1 - exp(-tau_el / tau_f)) (:func:`closed_form_buildup`, still its limit sigma_f -> 0): that rounds the
elastic-plastic knee to 63 % of tau_f where tau_el = tau_f and was 12-24 % below the Maxwell-Eyring equation
integrated along the streamlines at the knee (docs/traction.md, "Maxwell-Eyring build-up of the kernel law").  So:

* small S: tau = min-like of tau_el and the viscous stress point by point; in the high-pressure centre
  the film's elastic compliance sets the slope (the viscous slope with Barus viscosity is orders of
  magnitude stiffer there), at the low-pressure edge the viscous one does (Deborah number < 1).  The
  rolling creep of the solids (Carter, C = 2 R_x / b) is in series with the film through
  ``G_eff = G C / (E_f + C)``, E_f = 4 G b / (pi h p_0) the elastic film's slope
  (:func:`effective_shear_modulus`): where the film is elastic over the whole contact the low-slip slope is
  1 / (1/E_f + 1/C), the estimate of ``linear_region`` (tested: 0.975 of it); with the default G at the
  default case the viscous edge brings it to 0.65 of that contact-level series;
* large S: tau -> tau_L = Lambda p at every point, so mu -> Lambda;
* in between the Eyring flow (tau_0, log in S) and the limiting shear set the knee.

mu = sign(S) \\iint tau dA / W over the Hertz ellipse (p = p_0 sqrt(1 - (x/b)^2 - (y/a)^2)).  Isothermal: no
shear heating in the film (an upper estimate at large slip, where measured curves fall with the heat;
docs/traction.md, "Physical model").  Film thickness: Hamrock & Dowson central film [4] at the contact's
load, speed, R_x and ellipticity.

Quadrature (the kernel's split): the kernel integrates along the major axis (transverse, y = a u) over
the strips of :func:`hsbearing.models.ball_bearing.ball.strip_load_weights`; in each strip :func:`strip_mu` integrates
across the minor axis (rolling, x = b_u sin(theta), b_u = b sqrt(1 - u^2)) with :data:`N_MINOR`
Gauss-Legendre nodes in theta: the substitution removes the square-root edges of the Hertz pressure, so
the integrand is smooth and a handful of nodes suffice (tested against a fine 2-D grid over the ellipse,
tests/models/test_traction_eyring.py).  A strip needs its local peak pressure p_0 sqrt(1 - u^2): the one extra
argument of the kernel's per-node call.

Parameters and defaults (each overridable in a lubricant file, docs/traction.md "Lubricant files"):

* Lambda = :data:`DEFAULT_LAMBDA` = 0.047, the upper end of the ester bracket of
  :data:`eyring_limit.LAMBDA_BRACKET` (Hoeglund's paraffinic M100, [5] Table 2), the same value that bounds
  the seed laws at low speed (zhang2016.LIMITING_SHEAR_COEFFICIENT); measured values 0.035-0.088 ([5]).
* tau_0 = 2 Lambda / alpha (the Bair & Winer relation as used in [5] Eq. 12): 5.1 MPa for alpha =
  18.5 GPa^-1 (4106), 7.3 MPa for 12.8 GPa^-1 (4109) -- inside the 2-20 MPa of Eyring stresses of EHL
  oils ([2]).
* G = :data:`DEFAULT_SHEAR_MODULUS` = 0.3 GPa, the geometric middle of the 0.1-1.0 GPa measured by Johnson
  & Roberts at 1-2 GPa ([6]; the window of ``linear_region``).
* temperature: Lambda(T) = Lambda_ref (1 + k_L (T - T_ref)), tau_0(T) = tau_0,ref (1 + k_t (T - T_ref));
  default k_L = k_t = 0 (no measured temperature coefficient of these oils was found); tau_0 = 2 Lambda / alpha
  follows alpha(T) when the lubricant file gives alpha at several temperatures.  The oil's own viscosity
  eta_in(T) (Walther) enters through the Eyring argument and the film thickness.

References
----------
[1] Johnson K. L., Tevaarwerk J. L., "Shear behaviour of elastohydrodynamic oil films", Proc. R. Soc.
    Lond. A 356 (1977) 215-236 (Maxwell model with Eyring dashpot; elastic, non-linear viscous and
    elastic-plastic regimes of the traction curve).
[2] Evans C. R., Johnson K. L., "The rheological properties of elastohydrodynamic lubricants",
    Proc. IMechE C 200 (1986) 303-312 (Eyring stress of EHL oils; the range of order 2-20 MPa is the one
    usually quoted from it -- the paper itself could not be retrieved through this session's search tools).
[3] Bair S., Winer W. O., "A rheological model for elastohydrodynamic contacts based on primary
    laboratory data", J. Lubr. Technol. 101 (1979) 258-265 (limiting shear stress tau_L = Lambda p).
    The cap of the Eyring stress at tau_L is the plain minimum in [5] Eq. (7); here a smooth 4-norm
    minimum (:func:`smooth_min`: C-infinity for CVODE, 1.5 % below the minimum where one stress is twice
    the other).
[4] Hamrock B. J., Dowson D., J. Lubr. Technol. 99 (1977) 264-276, central film thickness
    (:func:`hsbearing.models.ehl.central_film_thickness`).
[5] Arana A., Larrañaga J., Ulacia I., Proc. IMechE Part J 233(2) (2019) 303-316: Eq. (7), Eq. (12)
    (tau_E = 2 Lambda / alpha) and Table 2 (Lambda of base oils, Hoeglund).
[6] Johnson K. L., Roberts A. D., Proc. R. Soc. Lond. A 337 (1974) 217-242 (film shear modulus
    0.1-1.0 GPa at 1-2 GPa, mineral oil; as logged in docs/traction.md).
[7] Johnson K. L., *Contact Mechanics*, Cambridge 1985, Sec. 8.4 (Carter's creep, C = 2 R_x / b).
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from hsbearing.models.traction.eyring_limit import LAMBDA_BRACKET

__all__ = [
    "DEFAULT_LAMBDA", "DEFAULT_SHEAR_MODULUS", "N_MINOR", "MINOR_NODES", "EyringParameters", "eyring_stress_default",
    "central_film", "effective_shear_modulus", "contact_coefficients", "maxwell_eyring_buildup", "closed_form_buildup",
    "flow_stress", "strip_mu", "contact_mu", "ellipse_mu", "SIGMA_HARD",
]

#: Default limiting-shear-stress coefficient [-] (upper end of eyring_limit.LAMBDA_BRACKET, [5] Table 2).
DEFAULT_LAMBDA = LAMBDA_BRACKET[1]
#: Default elastic shear modulus of the film [Pa] (geometric middle of 0.1-1 GPa, [6]).
DEFAULT_SHEAR_MODULUS = 0.3e9
#: Gauss-Legendre nodes in theta across the minor axis of a strip (x = b_u sin theta).
N_MINOR = 8
#: ln z above which asinh(z) = ln(2 z) to double precision (1/(4 z^2) < 2^-53 for z > 2.4e7).
LOG_ASINH = 17.0
#: sigma_f = tau_f kappa / tau_0 above which e^-sigma_f (< 2.4e-16) is dropped beside 1 in the build-up
#: (:func:`maxwell_eyring_buildup`: its log-sum-exp form, no overflow of e^sigma_f)
SIGMA_HARD = 36.0


def _minor_nodes(n):
    t, w = np.polynomial.legendre.leggauss(n)
    th = 0.5 * math.pi * t
    # (sin theta, cos theta, weight * cos theta (dx = b_u cos theta dtheta; the pi/2 cancels in mu))
    return np.ascontiguousarray(np.stack([np.sin(th), np.cos(th), w * np.cos(th)], axis=1))


#: (sin theta_j, cos theta_j, w_j cos theta_j) of the N_MINOR nodes (captured by the numba kernel, which pairs the
#: mirror nodes +-theta_j: they must stay an even, bit-symmetric set, _kernels._node_pairs checks it).
MINOR_NODES = _minor_nodes(N_MINOR)
MINOR_NODES.setflags(write=False)


def eyring_stress_default(Lambda, alpha):
    """tau_0 = 2 Lambda / alpha [Pa] (Bair & Winer as used in [5] Eq. 12)."""
    return 2.0 * Lambda / alpha


@dataclass(frozen=True)
class EyringParameters:
    """Rheological constants of the model at a reference temperature (SI).

    Lambda : limiting-shear-stress coefficient [-];  tau0 : Eyring stress [Pa] (None: 2 Lambda / alpha(T))
    G : film elastic shear modulus [Pa];  T_ref : reference temperature [K]
    k_Lambda, k_tau0 : linear temperature coefficients [1/K]
    """

    Lambda: float = DEFAULT_LAMBDA
    tau0: float | None = None
    G: float = DEFAULT_SHEAR_MODULUS
    T_ref: float = 313.15
    k_Lambda: float = 0.0
    k_tau0: float = 0.0

    def at(self, T, alpha):
        """(tau_0, Lambda, G) at temperature T [K] for the oil's alpha(T) [1/Pa]."""
        lam = self.Lambda * (1.0 + self.k_Lambda * (float(T) - self.T_ref))
        if not lam > 0.0:
            raise ValueError(f"the limiting-shear coefficient at {float(T) - 273.15:.4g} degC is {lam:.3g} (<= 0): "
                             "check its temperature coefficient")
        if self.tau0 is None:
            tau0 = eyring_stress_default(lam, alpha)
        else:
            tau0 = self.tau0 * (1.0 + self.k_tau0 * (float(T) - self.T_ref))
        if not tau0 > 0.0:
            raise ValueError(f"the Eyring stress at {float(T) - 273.15:.4g} degC is {tau0:.3g} Pa (<= 0): "
                             "check its temperature coefficient")
        return float(tau0), float(lam), float(self.G)


def central_film(W, U, Ep, Rx, k, eta_in, alpha, phi_T=1.0):
    """Hamrock-Dowson central film thickness h_c [m] ([4]; :func:`hsbearing.models.ehl.central_film_thickness`),
    times the inlet-shear-heating factor phi_T [-] (:func:`hsbearing.models.ehl.thermal_reduction_factor`,
    Gupta et al. 1992; 1 = isothermal, the default; the kernel passes the contact's factor at slip 0 when
    ``friction.inlet_heating = on``, like the reported films).

    W normal load [N], U rolling speed [m/s] (|U| used), Ep reduced modulus [Pa], Rx [m], k = a/b [-],
    eta_in [Pa s], alpha [1/Pa].
    """
    Ub = eta_in * abs(U) / (Ep * Rx)
    Wb = W / (Ep * Rx * Rx)
    return phi_T * Rx * 2.69 * Ub**0.67 * (alpha * Ep) ** 0.53 * Wb**-0.067 * (1.0 - 0.61 * math.exp(-0.73 * k))


def effective_shear_modulus(G, b, h, p0, Rx):
    """G_eff = G C / (E_f + C): the film's shear modulus with the solids' rolling creep in series [Pa].

    E_f = 4 G b / (pi h p0) is the low-slip slope of the elastic film over the Hertz ellipse
    (mean of G (x - x_in) / h weighted by area, divided by the mean pressure; \\iint (x - x_in) dA =
    8 a b^2 / 3, W = 2 pi a b p0 / 3), C = 2 Rx / b Carter's creep slope ([7]).  Both are linear in the
    slip, so the series combination 1 / (1/E_f + 1/C) equals the film slope with G_eff.
    """
    Ef = 4.0 * G * b / (math.pi * h * p0)
    C = 2.0 * Rx / b
    return G * C / (Ef + C)


def contact_coefficients(W, U, Ep, Rx, k, a, eta_in, alpha, tau0, Lambda, G, phi_T=1.0):
    """Per-contact coefficients (Lambda, r0, lv, cp, ce) of :func:`strip_mu` [-].

    r0 = tau_0 / p_0, lv = ln(eta_in |U| / (h tau_0)), cp = alpha p_0, ce = G_eff b / (h p_0), with p_0 the
    Hertz peak pressure 3 W / (2 pi a b), b = a / k the semi-axis along the rolling direction, h the
    central film (:func:`central_film`, times the inlet-heating factor phi_T).  Scalars.
    """
    b = a / k
    p0 = 1.5 * W / (math.pi * a * b)
    h = central_film(W, U, Ep, Rx, k, eta_in, alpha, phi_T)
    Ge = effective_shear_modulus(G, b, h, p0, Rx)
    return Lambda, tau0 / p0, math.log(eta_in * abs(U) / (h * tau0)), alpha * p0, Ge * b / (h * p0)


def smooth_min(x, y):
    """Smooth minimum (x^-4 + y^-4)^(-1/4) of two positive stresses [Pa] (C-infinity; within 1.5 % of
    min(x, y) when one is twice the other, 16 % below it when they are equal)."""
    lo, hi = min(x, y), max(x, y)
    r = lo / hi
    r2 = r * r
    return lo / math.sqrt(math.sqrt(1.0 + r2 * r2))


def _asinh_exp(lz):
    """asinh(e^lz) without overflow."""
    if lz > LOG_ASINH:
        return lz + math.log(2.0)
    return math.asinh(math.exp(lz))


def closed_form_buildup(tel, tf):
    """Linear Maxwell build-up tau_f (1 - exp(-tau_el / tau_f)) [same unit as the stresses]: the exact solution of
    (1/G) dtau/dt + tau / eta = gdot at a viscosity constant along the path (Johnson & Tevaarwerk [1]), the law's
    build-up until 0.1.0 (12-24 % low at the knee against the Maxwell-Eyring equation; kept for that comparison:
    ``strip_mu(..., buildup="closed")``)."""
    return -tf * math.expm1(-tel / tf)


def flow_stress(tv, tL):
    """(tau_f, sigma_f) of a point: the flow stress tau_f = (tau_v^-4 + tau_L^-4)^(-1/4) (:func:`smooth_min`) and
    sigma_f = tau_f kappa / tau_0 in units of the stress scale tau_0 / kappa of :func:`maxwell_eyring_buildup`,
    kappa = dtau_v/dtau at tau_f = (tau_v / tau_f)^5 = (1 + r^4)^(5/4), r = tau_v / tau_L; so
    sigma_f = (tau_v / tau_0)(1 + r^4).  Returns (tau_f [unit of tau_v], kappa [-]); the scale is tau_0 / kappa."""
    lo, hi = min(tv, tL), max(tv, tL)
    r = tv / tL
    r2 = r * r
    g4 = 1.0 + r2 * r2
    tf = lo / math.sqrt(math.sqrt(1.0 + (lo / hi) ** 4))
    return tf, g4 * math.sqrt(math.sqrt(g4))


def maxwell_eyring_buildup(tel, tf, ts):
    """Shear stress of a point by the Maxwell-Eyring equation along its path from the inlet, the point's flow
    properties held along the path [same unit as the stresses] (>= 0; tel, tf, ts > 0).

    tel : the elastic stress G_eff |S| (x - x_in) / h carried from the inlet;  tf : the point's flow stress (the
    steady stress of its Eyring flow capped by the limiting shear, :func:`flow_stress`);  ts : its stress scale
    tau_0 / kappa.

    Johnson & Tevaarwerk's non-linear Maxwell fluid ([1]; the equation of tests/helpers/maxwell_eyring_reference.py),
    steady along a streamline at the rolling speed U, written with the elastic stress as the path variable
    (dtau_el = G gdot dx / U)::

        dtau/dtau_el = 1 - gdot_v(tau) / gdot,   tau = 0 at tau_el = 0,

    with the viscous rate in the form the Eyring law gives it, gdot_v(tau) / gdot = sinh(tau / ts) / sinh(tau_f / ts):
    exact for the Eyring flow below the cap (ts = tau_0), and elsewhere the Eyring law with its argument
    tau_v(tau) / tau_0 linearised at tau_f (slope kappa = dtau_v/dtau = (tau_v / tau_f)^5 of the smooth cap
    tau_v(tau) = (tau^-4 - tau_L^-4)^(-1/4)), which is where the rate turns the stress over.  With
    sigma = tau / ts, sigma_f = tau_f / ts and t = e^sigma the equation integrates in closed form (partial
    fractions of 2 sinh(sigma_f) / ((e^sigma_f - t)(t + e^-sigma_f)))::

        tau_el / (ts tanh sigma_f) = E = ln[(t + q) (1/q - 1) / ((1/q - t)(1 + q))],   q = e^-sigma_f,

    inverted without cancellation as

        sigma = log1p( (1 + q)(1 - q)(1 - x) / ((1 - q) x + q (1 + q)) ),   x = e^-E.

    Limits: sigma_f -> 0 (a Newtonian point) gives tau_f (1 - exp(-tau_el / tau_f)), the linear Maxwell film
    (:func:`closed_form_buildup`); sigma_f >> 1 gives -ts ln(e^-tau_el/ts + e^-tau_f/ts), a minimum of the
    elastic and the flow stress rounded over the width ts -- Johnson & Tevaarwerk's elastic-then-plastic film.
    Above :data:`SIGMA_HARD` that form is used (q < 2.4e-16 dropped beside 1).  Tested against the equation
    integrated numerically with the law's own flow curve (tests/models/test_traction_eyring.py).
    """
    sf = tf / ts
    if not sf > 0.0:  # an underflowed flow stress (|S| ~ 1e-320): no stress
        return 0.0
    if sf > SIGMA_HARD:
        E = tel / ts
        return ts * (min(E, sf) - math.log1p(math.exp(-abs(E - sf))))
    em = -math.expm1(-sf)  # 1 - q
    q = math.exp(-sf)  # (not 1 - em: q's relative accuracy counts down to e^-36)
    E = tel / ts * (1.0 + q * q) / (em * (1.0 + q))  # / tanh sigma_f, tanh = (1 - q^2) / (1 + q^2)
    xm = -math.expm1(-E)  # 1 - x, x = e^-E (each directly: x meets q in the denominator)
    return ts * math.log1p((1.0 + q) * em * xm / (em * math.exp(-E) + q * (1.0 + q)))


def strip_mu(c, S, u, nodes=None, buildup="maxwell"):
    """Traction coefficient of the strip at y = a u of the contact (coefficients ``c``) at slip S [-] (odd in S).

    Integrates tau / p over the strip's width with the theta nodes (``nodes``: default :data:`MINOR_NODES`), tau by
    :func:`maxwell_eyring_buildup` (``buildup="closed"``: :func:`closed_form_buildup`, the law before 0.1.0).
    """
    Lam, r0, lv, cp, ce = c
    if S == 0.0:
        return 0.0
    if buildup not in ("maxwell", "closed"):
        raise ValueError(f"unknown buildup {buildup!r} (maxwell, closed)")
    nodes = MINOR_NODES if nodes is None else nodes
    s = abs(S)
    su = math.sqrt(max(1.0 - u * u, 0.0))
    lS = lv + math.log(s)
    num = den = 0.0
    for sn, cs, w in nodes:
        pi_ = su * cs  # p / p_0
        tL = Lam * pi_
        tv = r0 * _asinh_exp(lS + cp * pi_)
        tel = ce * s * su * (1.0 + sn)
        if buildup == "closed":
            num += w * closed_form_buildup(tel, smooth_min(tv, tL))
        else:
            tf, kap = flow_stress(tv, tL)
            num += w * maxwell_eyring_buildup(tel, tf, r0 / kap)
        den += w * pi_
    return math.copysign(num / den, S)


def contact_mu(S, W, U, Ep, Rx, k, a, eta_in, alpha, tau0, Lambda, G, n_major=5, phi_T=1.0, buildup="maxwell"):
    """mu of a whole contact: :func:`strip_mu` summed over the kernel's strips (strip_load_weights) [-].

    The Python twin of what the kernel does per contact (one slip S for every strip: no spin).  Vectorised in S.
    ``buildup="closed"``: the closed-form linear Maxwell build-up of the law before 0.1.0 (comparison only).
    """
    from hsbearing.models.ball_bearing.ball import strip_load_weights

    c = contact_coefficients(W, U, Ep, Rx, k, a, eta_in, alpha, tau0, Lambda, G, phi_T)
    qu, qw = strip_load_weights(n_major)
    S = np.asarray(S, dtype=float)
    out = np.array([sum(w * strip_mu(c, s, u, buildup=buildup) for u, w in zip(qu, qw)) for s in S.ravel()])
    return out.reshape(S.shape)


def ellipse_mu(S, W, U, Ep, Rx, k, a, eta_in, alpha, tau0, Lambda, G, n=400):
    """Reference: the same local law on a fine midpoint grid over the Hertz ellipse (x, y) [-] (no strips, no
    theta substitution): an independent quadrature for the tests.  Vectorised in S (fraction)."""
    b = a / k
    p0 = 1.5 * W / (math.pi * a * b)
    h = central_film(W, U, Ep, Rx, k, eta_in, alpha)
    Ge = effective_shear_modulus(G, b, h, p0, Rx)
    t = (np.arange(n) + 0.5) / n * 2.0 - 1.0
    X, Y = np.meshgrid(t, t, indexing="ij")  # X along rolling (units of b), Y transverse (units of a)
    inside = X * X + Y * Y < 1.0
    X, Y = X[inside], Y[inside]
    p = p0 * np.sqrt(1.0 - X * X - Y * Y)
    x_in = -np.sqrt(1.0 - Y * Y)
    out = []
    for s in np.atleast_1d(np.asarray(S, dtype=float)).ravel():
        if s == 0.0:
            out.append(0.0)
            continue
        g = abs(s) * abs(U) / h
        lz = np.log(eta_in * g / tau0) + alpha * p
        asn = np.where(lz > LOG_ASINH, lz + math.log(2.0), np.arcsinh(np.exp(np.minimum(lz, LOG_ASINH))))
        tv = tau0 * asn
        tL = Lambda * p
        lo, hi = np.minimum(tv, tL), np.maximum(tv, tL)
        tf = lo / np.sqrt(np.sqrt(1.0 + (lo / hi) ** 4))
        g4 = 1.0 + (tv / tL) ** 4
        tel = Ge * abs(s) * (X - x_in) * b / h
        tau = _BUILDUP(tel, tf, tau0 / (g4 * np.sqrt(np.sqrt(g4)))).astype(float)
        out.append(math.copysign(float(tau.sum() / p.sum()), s))  # the grid's own load (no edge error at Lambda)
    return np.array(out).reshape(np.shape(S))


_BUILDUP = np.frompyfunc(maxwell_eyring_buildup, 3, 1)
