"""Starved EHL race contacts: the starved central film and the starved EHL rolling force, as a bounded band.

A ball/race contact is starved when the oil in front of it does not fill the converging gap as far upstream as the
fully flooded film needs: the pressure starts to build only at an inlet meniscus at a distance m b from the contact
centre (b the Hertz semi-axis in the rolling direction), and below a critical m* the film falls.  Three laws here,
each a function of one contact:

* :func:`critical_inlet_distance` and :func:`starved_film_ratio` -- Hamrock & Dowson's starved point-contact film
  [1]: m* = 1 + 3.06 [(R_x/b)^2 H_c]^0.58 and h_c,starved / h_c,flooded = ((m - 1)/(m* - 1))^0.29 for m < m*.
* :func:`inlet_meniscus` -- where the meniscus sits for a given oil layer h_oil carried into the inlet: the gap
  closes down to the layer there (the starved-inlet picture of Wedeven, Evans & Cameron [2]; mass conservation of a
  layer that fills the gap from that point on), h_c,starved(m) + (b^2 / (2 R_x)) G(m) = h_oil, G the separation of
  the Hertz zone's edge (:func:`hertz_inlet_gap`).
* :func:`starved_rolling_force_ratio` -- the EHL rolling force of a starved inlet over the flooded one, DERIVED
  here (no published formula was read): Grubin's inlet analysis [3] (rigid Hertzian gap outside the contact, Barus
  viscosity, the reduced pressure reaching 1/alpha at the contact edge) with the inlet cut at the meniscus, and the
  rolling force as the inlet's pressure-flow dissipation over the rolling speed, F = int (h - h_0) dp/dx dx (pure
  rolling: no Couette shear power).  In units of b and b^2/(2 R_x) both the starved Grubin film and F depend only
  on m and the flooded Hbar = h_c 2 R_x / b^2, so the ratio is a function of (m, Hbar), independent of the oil,
  speed and load otherwise.  The kernel's rolling force is Houpert's fit F_R (models/ball_bearing/ball.py [2]);
  ASSUMED: the starved one is F_R times this Grubin ratio (the inlet's dissipation falls the same fraction in
  Houpert's full solution as in Grubin's).  Grubin's flooded force includes the viscous loss of the far inlet (it
  falls as 1/m), so against an inlet flooded to infinity the ratio is already ~0.9 at m = 10 where the film is
  flooded: the rolling force is far more sensitive to the inlet length than the film.  ASSUMED: the flooded
  inlet Houpert's F_R stands for is the one the flooded film needs, cut at Hamrock-Dowson's m*; the band takes
  the ratio against that inlet (so an inlet holding oil out to m* keeps today's F_R) and reports the ratio
  against the infinite inlet beside it.

The band of one contact (:func:`starvation_band`): high end = flooded (factor 1, today's value); low end = an inlet
fed only by the cavity's air-oil mixture: of the gap the flooded film needs (out to m*), only the oil volume
fraction X is oil, h_oil = X (h_c + (b^2/(2 R_x)) G(m*)) (:func:`mixture_oil_layer`).  That is a lower bound of the
supply in the sense that it neglects the layer left on the track by the previous ball and any reflow (Cann et al.'s
replenishment): both only add oil.  It is not a bound if the mixture reaching the inlet is leaner than the cavity's
mean (oil thrown off the inner race); the band says so in docs/power_loss.md.  Nothing in it is chosen from heat
data.

References
----------
[1] Hamrock B. J., Dowson D., "Isothermal elastohydrodynamic lubrication of point contacts, Part IV: Starvation
    results", J. Lubr. Technol. 99 (1977) 15-23: m* (central film) = 1 + 3.06 [(R_x/b)^2 H_c]^0.58 and
    H_c,s = H_c,f ((m - 1)/(m* - 1))^0.29 (RECALLED from secondary accounts, e.g. Hamrock & Dowson, *Ball Bearing
    Lubrication*, Wiley 1981, Ch. 9; the paper itself was not reachable: only its citation was read, in the
    reference list of a 2018 ASME J. Tribol. paper on starved EHL with reflow).  m is the meniscus distance from
    the contact centre over b.
[2] Wedeven L. D., Evans D., Cameron A., "Optical analysis of ball bearing starvation", J. Lubr. Technol. 93 (1971)
    349-363 (NASA Lewis preprint E-5834: the opening and abstract read -- starvation inhibits the pressure
    generation and reduces the film; the inlet boundary where the gap meets the available oil is recalled).
[3] Grubin A. N., 1949 (in Ertel-Grubin inlet analysis, as presented in Hamrock, Schmid & Jacobson, *Fundamentals
    of Fluid Film Lubrication*, 2nd ed., Ch. 18, and Johnson, *Contact Mechanics*, Sec. 13.8; recalled): Hertzian
    gap outside the contact, reduced pressure q = (1 - exp(-alpha p))/alpha, dq/dx = 12 eta_0 u (h - h_0)/h^3,
    alpha q = 1 at the contact edge.
[4] Hertz line contact, separation outside the contact: h - h_0 = (b^2/(2R)) [X sqrt(X^2 - 1) - arccosh X],
    X = |x|/b >= 1 (Johnson, *Contact Mechanics*, Sec. 4.2, Eq. 4.52 form; derived here: its slope
    (b/R) sqrt(X^2 - 1) is the elastic half-space result, tested against quadrature of that slope).
Read and not used: Chevalier F., Lubrecht A. A., Cann P. M. E., Colin F., Dalmaz G. (1998), J. Tribol. 120, 126-133
(film from the inlet oil layer; not reached -- only cited); Damiens B., Venner C. H., Cann P. M. E., Lubrecht A. A.
(2004), J. Tribol. 126, 105-111 (abstract: one parameter, the flooded inlet length, governs the starved film);
SKF's kinematic replenishment factor phi_rs (models/friction/skf2004.py), an empirical factor on the whole rolling
moment, reported beside the band in tools/investigations/tp2275_starvation.py, not used in it.
"""

from __future__ import annotations

import math

import numpy as np

__all__ = ["hertz_inlet_gap", "critical_inlet_distance", "starved_film_ratio", "inlet_meniscus", "mixture_oil_layer",
           "grubin_inlet", "starved_rolling_force_ratio", "starvation_band", "FLOODED_M"]

#: meniscus distance [b] taken as "flooded" by the Grubin inlet: its pressure integral is converged to < 1e-9 and
#: its dissipation (tail ~ 1/m) to ~2e-4 of its value there
FLOODED_M = 5000.0
#: nodes of the Grubin quadrature (trapezoid on X = 1 + t^2, t = sqrt(m - 1) u^2); second order, 1e-5 at 1500
GRUBIN_NODES = 1500


def hertz_inlet_gap(X):
    """Separation G(X) [-] of a Hertz line contact outside the contact, in units of b^2 / (2R) ([4]).

    G = X sqrt(X^2 - 1) - arccosh X for |X| >= 1 (either side: |X|), 0 inside the contact.
    """
    Xa = np.maximum(np.abs(np.asarray(X, dtype=float)), 1.0)
    r = np.sqrt(Xa * Xa - 1.0)
    return Xa * r - np.log(Xa + r)  # [4]


def critical_inlet_distance(h_c, Rx, b):
    """Hamrock-Dowson critical inlet distance m* [-] of the central film ([1]): 1 + 3.06 [(R_x/b)^2 h_c/R_x]^0.58.

    h_c flooded central film [m], R_x rolling-direction radius [m], b rolling-direction Hertz semi-axis [m].
    """
    return 1.0 + 3.06 * (np.asarray(h_c, dtype=float) * np.asarray(Rx, dtype=float) / np.asarray(b, dtype=float) ** 2) ** 0.58  # [1]


def starved_film_ratio(m, m_star):
    """h_c,starved / h_c,flooded = ((m - 1)/(m* - 1))^0.29 for 1 <= m < m*, 1 for m >= m* ([1])."""
    m = np.asarray(m, dtype=float)
    ms = np.asarray(m_star, dtype=float)
    r = np.clip((m - 1.0) / (ms - 1.0), 0.0, 1.0)
    return r**0.29  # [1]


def inlet_meniscus(h_oil, h_c, Rx, b):
    """Meniscus distance m [-] of an inlet carrying an oil layer h_oil [m] (module docstring, [1], [2]).

    Solves h_c phi(m) + (b^2/(2 R_x)) G(m) = h_oil by bisection on m in (1, m*]; the left side rises monotonically
    from 0 at m = 1.  Returns m* (flooded) when the layer fills the gap at m* (h_oil >= h_c + (b^2/2R_x) G(m*)).
    Scalars.
    """
    h_oil, h_c, Rx, b = float(h_oil), float(h_c), float(Rx), float(b)
    if not (h_c > 0.0 and Rx > 0.0 and b > 0.0):
        raise ValueError("need h_c, Rx, b > 0")
    ms = float(critical_inlet_distance(h_c, Rx, b))
    scale = b * b / (2.0 * Rx)

    def gap(m):
        return h_c * float(starved_film_ratio(m, ms)) + scale * float(hertz_inlet_gap(m))

    if h_oil >= gap(ms):
        return ms
    if h_oil <= 0.0:
        return 1.0
    lo, hi = 1.0, ms
    for _ in range(200):
        mid = 0.5 * (lo + hi)
        if gap(mid) > h_oil:
            hi = mid
        else:
            lo = mid
        if hi - lo < 1e-13 * ms:
            break
    return 0.5 * (lo + hi)


def mixture_oil_layer(oil_fraction, h_c, Rx, b):
    """Oil layer [m] of an inlet fed only by the cavity mixture (module docstring): X (h_c + (b^2/(2R_x)) G(m*))."""
    X = float(oil_fraction)
    if not 0.0 <= X <= 1.0:
        raise ValueError("oil volume fraction must be within [0, 1]")
    ms = float(critical_inlet_distance(h_c, Rx, b))
    return X * (h_c + b * b / (2.0 * Rx) * float(hertz_inlet_gap(ms)))


def _grubin_integrals(H0, m, n=GRUBIN_NODES):
    """Node values along the inlet (edge first): X, G, the pressure-rise density g = G/(H0+G)^3 and its cumulative
    integral from the edge K(X) ([3])."""
    u = np.linspace(0.0, 1.0, n)
    t = math.sqrt(m - 1.0) * u * u
    X = 1.0 + t * t
    G = hertz_inlet_gap(X)
    g = G / (H0 + G) ** 3
    K = np.concatenate(([0.0], np.cumsum(0.5 * (g[1:] + g[:-1]) * np.diff(X))))
    return X, G, g, K


def grubin_inlet(H0, m, n=GRUBIN_NODES):
    """(I, Fhat) of Grubin's inlet cut at m with central film H0 = h_0 2R/b^2 ([3], module docstring).

    I = int_1^m G/(H0+G)^3 dX: the rise of the reduced pressure over 12 eta_0 |u| (2R)^2 / b^3 (Grubin's condition
    alpha q = 1 at the edge fixes I for a contact); Fhat = int_1^m G (G/(H0+G)^3) / K(X) dX with K(X) = int_1^X,
    the inlet's pressure-flow dissipation over |u|, in units of b^2 / (2 R alpha): (h - h_0) dp/dx with
    alpha dp/dx = (alpha dq/dx) / (1 - alpha q) and 1 - alpha q = K/I.
    """
    X, G, g, K = _grubin_integrals(H0, m, n)
    with np.errstate(divide="ignore", invalid="ignore"):
        f = np.where(K > 0.0, G * g / K, 0.0)  # -> 0 like sqrt(X - 1) at the edge
    return float(K[-1]), float(np.sum(0.5 * (f[1:] + f[:-1]) * np.diff(X)))


def _grubin_starved_film(Hbar, m, I_target, n):
    """Central film H0 of the inlet cut at m that builds the same pressure as the flooded one (I = I_target):
    I falls monotonically as H0 rises; Brent's method on log H0 over (1e-12 Hbar, Hbar], relative tolerance 1e-11."""
    from scipy.optimize import brentq

    if grubin_inlet(Hbar, m, n)[0] >= I_target:
        return Hbar
    lo = math.log(1e-12 * Hbar)
    f = lambda s: grubin_inlet(math.exp(s), m, n)[0] - I_target  # noqa: E731
    if f(lo) <= 0.0:
        return 1e-12 * Hbar
    return math.exp(brentq(f, lo, math.log(Hbar), xtol=1e-11, rtol=1e-13))


def _force_ratios(m, Hbar, m_refs, n):
    """Grubin rolling force of the inlet cut at m over that of the inlets cut at each m_ref (>= m, or FLOODED_M)."""
    m, Hbar = float(m), float(Hbar)
    if not Hbar > 0.0:
        raise ValueError("need Hbar > 0")
    refs = [min(float(r), FLOODED_M) for r in m_refs]
    if m <= 1.0:
        return [0.0 for _ in refs]
    I_ff, F_ff = grubin_inlet(Hbar, FLOODED_M, n)
    F_m = None
    out = []
    for r in refs:
        if m >= r:
            out.append(1.0)
            continue
        if F_m is None:
            F_m = grubin_inlet(_grubin_starved_film(Hbar, m, I_ff, n), m, n)[1]
        F_ref = F_ff if r >= FLOODED_M else grubin_inlet(_grubin_starved_film(Hbar, r, I_ff, n), r, n)[1]
        out.append(min(F_m / F_ref, 1.0))
    return out


def starved_rolling_force_ratio(m, Hbar, m_ref=FLOODED_M, n=GRUBIN_NODES):
    """Rolling force of an inlet cut at the meniscus m over that of the inlet cut at m_ref >= m [-]: Grubin's inlet
    (derived, module docstring; ASSUMED to carry over to Houpert's F_R).  Hbar = h_c,flooded 2 R_x / b^2 [-], the
    film of the inlet at :data:`FLOODED_M`, which fixes the pressure integral I of the contact; each cut inlet's
    film solves Grubin's condition with that I.  1 for m >= m_ref; falls to 0 as m -> 1."""
    return _force_ratios(m, Hbar, (m_ref,), n)[0]


def starvation_band(oil_fraction, h_c, Rx, b):
    """Low end of the starvation band of one race contact (module docstring): dict with the meniscus ``m``, the
    critical ``m_star``, the oil layer ``h_oil`` [m], the film ratio ``film`` (Hamrock-Dowson) and the rolling-force
    ratio ``force`` (Grubin, against the inlet cut at m*: ASSUMED the flooded inlet of Houpert's F_R, so that
    X = 1 gives 1, 1), and ``force_vs_infinite_inlet`` (against Grubin's inlet to infinity, lower: reported, not
    used) of an inlet fed only by the cavity mixture at oil fraction X.  The high end is 1, 1."""
    h_oil = mixture_oil_layer(oil_fraction, h_c, Rx, b)
    ms = float(critical_inlet_distance(h_c, Rx, b))
    m = inlet_meniscus(h_oil, h_c, Rx, b)
    force, force_inf = _force_ratios(m, 2.0 * h_c * Rx / (b * b), (ms, FLOODED_M), GRUBIN_NODES)
    return {"m": m, "m_star": ms, "h_oil": h_oil, "film": float(starved_film_ratio(m, ms)), "force": force,
            "force_vs_infinite_inlet": force_inf}
