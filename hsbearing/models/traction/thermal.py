"""Thermal physical EHL traction: Roelands viscosity, Eyring flow, limiting shear, Maxwell build-up, shear heating.

Registered as the law ``"physical"`` of every oil (:mod:`hsbearing.models.traction`), beside the isothermal
``"eyring"`` (:mod:`hsbearing.models.traction.eyring`), whose local constitutive structure it keeps.  What it adds:

1. **Pressure-viscosity by Roelands** [1] instead of Barus, with its temperature form::

       ln(eta / eta_R) = ln(eta_in / eta_R) [ ((T - 138) / (T_in - 138))^(-S0) (1 + p / p_R)^z ]
       eta_R = 6.31e-5 Pa s, p_R = 1.96e8 Pa,  z = alpha p_R / ln(eta_in / eta_R),
       S0 = beta_in (T_in - 138) / ln(eta_in / eta_R)        (:func:`roelands_viscosity`, :func:`roelands_indices`)

   z and S0 are fixed by the oil's own low-pressure data at the inlet temperature T_in: alpha (its measured
   alpha(T) where the lubricant file gives one) and beta_in = -d ln eta / dT of its viscosity law.
2. **Eyring stress with temperature** tau_0(T) = tau_0,in T / T_in: Eyring's rate theory tau_0 = k_B T / V with
   a constant activation volume V ([2]; :func:`eyring_stress_at`).  tau_0,in = 2 Lambda / alpha as in "eyring".
3. **Shear heating** (:func:`strip_mu`): the heat tau dU per unit area (dU = |S| U the sliding speed) of each
   point of a strip is conducted into both moving surfaces; the surface temperature rise is Jaeger's moving
   band source on a half-space [3], [4] at any Peclet number (:func:`band_source_influence`, closed-form cell
   integrals of the kernel e^X K_0(|X|)); the heat is shared between the surfaces by Blok's partition [5]
   (:func:`heat_partition`); across the film, conduction with the heat where the fluid shears: the Eyring rate
   rises exponentially with the temperature above the surfaces, so the exact thermal Couette solution of Nahme
   [7] applies (:func:`nahme_film`: xi tanh xi = N, N = beta_f tau dU h / (8 K)) -- the film shears like one at
   the surface temperature at 2 xi / sinh(2 xi) times the mean rate; beta_f is the chord of ln(rate) between the
   surface and the mid-film temperature (iterated).  History (docs/traction.md): the first version took the film
   at its mean temperature tau dU h / (12 K) above the surfaces (Nahme's small-N limit) and overestimated mu at
   cold oil with strong heating by up to 1.6x against the reference; Nahme with the tangent at the surface
   underestimated it by up to 0.4x (ln eta is convex in T); the chord is within the tolerance.  Temperature and stress are solved
   together by a relaxed fixed point over the strip, so mu falls beyond its maximum at large slip.
   Compression heating is not included: it is reversible to first order (heat at the inlet, as much cooling at
   the outlet as the pressure falls) and does not depend on slip.

4. **Viscoelastic build-up by the Maxwell-Eyring equation** (:func:`maxwell_eyring_march`, Johnson & Tevaarwerk
   1977 [8]) integrated cell by cell along each strip, inside the thermal fixed point.  It replaced the closed form
   tau_f (1 - exp(-tel / tau_f)) of :func:`local_stress` (the kernel law "eyring"'s point-by-point law, kept as
   ``PhysicalParameters(buildup="closed")``), which an independent streamline integration showed 11-25 % low at
   the elastic-plastic knee (tests/validation/test_traction_maxwell_reference.py, docs/traction.md).

Proof: tests/validation/test_traction_thermal_reference.py against an independent finite-volume solution of
the energy equation with its own march of the Maxwell-Eyring equation (tests/helpers/thermal_traction_fv.py);
tests/validation/test_traction_maxwell_reference.py (isothermal) against the Maxwell-Eyring equation integrated to
convergence along every streamline (tests/helpers/maxwell_eyring_reference.py); tolerances and results:
docs/traction.md, "Thermal physical model".

References
----------
[1] Roelands C. J. A., Correlational aspects of the viscosity-temperature-pressure relationship of lubricating
    oils, PhD thesis, TH Delft (1966); the form with eta_R = 6.31e-5 Pa s (ln = -9.67), p_R = 1.96e8 Pa
    (5.1e-9 1/Pa) and the temperature index S0 around 138 K is the one Stachowiak & Batchelor, Engineering
    Tribology, Ch. 2, print beside their Table 2.3 (read through the search tool); Houpert L., J. Tribol. 107
    (1985) uses the same form (not re-read here).

[2] Eyring H., J. Chem. Phys. 4 (1936) 283-291 (rate theory: the stress scale k_B T / V).

[3] Jaeger J. C., Proc. R. Soc. N.S.W. 76 (1942) (moving sources of heat; band source); Carslaw H. S., Jaeger J. C.,
    Conduction of Heat in Solids, 2nd ed., Oxford 1959 (moving line source): the steady temperature of a
    half-space moving at speed u under a line source Q per unit length, T = (Q / (pi k)) e^X K_0(|X|),
    X = u d / (2 kappa), d the distance downstream of the source (the kernel is checked here against its 1-D
    high-Peclet limit, which follows from the constant-flux solution of a semi-infinite solid).

[4] Archard J. F., Wear 2 (1959) (flash temperatures: the high- and low-Peclet regimes).

[5] Blok H., Proc. General Discussion on Lubrication, IMechE (1937) (flash temperature; the heat
    divides so that both surfaces reach the same temperature).

[6] Johnson K. L., Greenwood J. A., Wear 61 (1980) (thermal analysis of an Eyring fluid in EHL traction:
    conduction across the film to the surfaces, their flash temperatures) -- the structure followed here; its
    numbers could not be read through the search tools (docs/traction.md).

[7] Nahme R., Ing.-Arch. 11 (1940) (as usually cited; not read here) (thermal Couette flow with viscosity exponential in temperature; the
    closed form e^phi = cosh^2 xi / cosh^2(2 xi y / h) is derived in :func:`nahme_film`'s docstring and checked in
    tests/models/test_traction_thermal.py against a finite-difference film).

[8] Johnson K. L., Tevaarwerk J. L., Shear behaviour of elastohydrodynamic oil films, Proc. R. Soc. Lond. A 356
    (1977) 215-236: the Maxwell model with a non-linear (sinh) viscous element, gdot = (1/G) dtau/dt +
    (tau0/eta) sinh(tau/tau0) (read as an abstract; the equation as reproduced throughout the EHL traction
    literature, e.g. Evans & Johnson 1986) -- :func:`maxwell_eyring_march`.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, replace

import numpy as np
from scipy.special import k0e, k1e

from hsbearing.models.traction.eyring import (
    DEFAULT_LAMBDA,
    DEFAULT_SHEAR_MODULUS,
    central_film,
    effective_shear_modulus,
    eyring_stress_default,
)

__all__ = [
    "ROELANDS_ETA_R", "ROELANDS_P_R", "STEEL_CONDUCTIVITY", "STEEL_DIFFUSIVITY", "N_CELLS", "PhysicalParameters",
    "roelands_indices", "roelands_viscosity", "barus_viscosity", "eyring_stress_at", "local_stress",
    "maxwell_eyring_march",
    "midfilm_temperature_rise", "film_mean_temperature_rise", "nahme_xi", "nahme_film", "heat_partition",
    "band_source_influence",
    "strip_mu", "contact_mu",
]

#: Roelands reference viscosity [Pa s] and pressure [Pa] ([1]).
ROELANDS_ETA_R = 6.31e-5
ROELANDS_P_R = 1.96e8
#: Bearing steel (AISI 52100): conductivity [W/(m K)] (the thermal network's default, 40-46) and diffusivity
#: k / (rho c) with rho = 7800 kg/m^3, c = 460 J/(kg K) [m^2/s].
STEEL_CONDUCTIVITY = 42.0
STEEL_DIFFUSIVITY = 42.0 / (7800.0 * 460.0)
#: cells of a strip along the rolling direction (edges at x = b_u sin theta, theta uniform: fine at both edges)
N_CELLS = 16


@dataclass(frozen=True)
class PhysicalParameters:
    """Rheological and thermal choices of the law (SI).  Each choice can be switched for the sensitivity study.

    Lambda : limiting-shear coefficient at T_ref [-];  k_Lambda : its linear temperature coefficient [1/K]
    tau0 : Eyring stress at the inlet temperature [Pa] (None: 2 Lambda / alpha, as "eyring")
    G : film shear modulus [Pa]
    pressure_viscosity : "roelands" or "barus";  z : Roelands index (None: from alpha at the inlet)
    eyring_temperature : "eyring" (tau0 proportional to T) or "constant"
    thermal : shear heating on (True) or off (isothermal at the inlet temperature)
    buildup : "march" (the Maxwell-Eyring equation integrated cell by cell, :func:`maxwell_eyring_march`) or
    "closed" (the closed form tau_f (1 - exp(-tel / tau_f)) of :func:`local_stress`, the law before the march:
    11-25 % low at the elastic-plastic knee; kept for comparison)
    k_solid, kappa_solid : conductivity [W/(m K)] and diffusivity [m^2/s] of both solids
    """

    Lambda: float = DEFAULT_LAMBDA
    k_Lambda: float = 0.0
    T_ref: float = 313.15
    tau0: float | None = None
    G: float = DEFAULT_SHEAR_MODULUS
    pressure_viscosity: str = "roelands"
    z: float | None = None
    eyring_temperature: str = "eyring"
    thermal: bool = True
    buildup: str = "march"
    k_solid: float = STEEL_CONDUCTIVITY
    kappa_solid: float = STEEL_DIFFUSIVITY

    def with_(self, **kw) -> "PhysicalParameters":
        return replace(self, **kw)

    def limiting_shear(self, T):
        """Lambda(T) = Lambda (1 + k_Lambda (T - T_ref)) [-] (floored at 1e-4 of Lambda)."""
        return self.Lambda * np.maximum(1.0 + self.k_Lambda * (np.asarray(T, dtype=float) - self.T_ref), 1e-4)


def roelands_indices(eta_in, alpha, beta_in, T_in):
    """(z, S0) of the Roelands law [1] from the oil's inlet data: z = alpha p_R / ln(eta_in / eta_R),
    S0 = beta_in (T_in - 138 K) / ln(eta_in / eta_R) [-].  eta_in [Pa s] > eta_R, alpha [1/Pa], beta_in [1/K]."""
    L = math.log(eta_in / ROELANDS_ETA_R)
    if not L > 0.0:
        raise ValueError(f"the Roelands law needs eta_in > {ROELANDS_ETA_R} Pa s (got {eta_in:.3g})")
    return alpha * ROELANDS_P_R / L, beta_in * (T_in - 138.0) / L


def roelands_viscosity(p, T, eta_in, T_in, z, S0):
    """Roelands pressure-temperature viscosity [Pa s] ([1]):
    eta = eta_R exp{ ln(eta_in/eta_R) ((T - 138)/(T_in - 138))^(-S0) (1 + p/p_R)^z }.  Vectorised in p, T."""
    L = math.log(eta_in / ROELANDS_ETA_R)
    p = np.asarray(p, dtype=float)
    tt = ((np.asarray(T, dtype=float) - 138.0) / (T_in - 138.0)) ** (-S0)
    return ROELANDS_ETA_R * np.exp(L * tt * (1.0 + np.maximum(p, 0.0) / ROELANDS_P_R) ** z)


def barus_viscosity(p, T, eta_in, T_in, alpha, beta_in):
    """Barus viscosity with an exponential temperature factor [Pa s]: eta_in exp(alpha p - beta_in (T - T_in))
    (the "eyring" law's pressure law; used in the sensitivity study)."""
    return eta_in * np.exp(alpha * np.asarray(p, dtype=float) - beta_in * (np.asarray(T, dtype=float) - T_in))


def eyring_stress_at(tau0_in, T, T_in, mode="eyring"):
    """Eyring stress at film temperature T [Pa]: tau0_in T / T_in (rate theory, [2]: k_B T / V at constant
    activation volume) or tau0_in ("constant")."""
    if mode == "constant":
        return tau0_in * np.ones_like(np.asarray(T, dtype=float))
    return tau0_in * np.asarray(T, dtype=float) / T_in


def local_stress(p, eta, gdot, tau0, tauL, tel):
    """Shear stress of the film at one point [Pa] (the "eyring" constitutive law, point by point):
    tau_v = tau0 asinh(eta gdot / tau0) (Eyring flow, Johnson & Tevaarwerk 1977), tau_f = smooth minimum of
    tau_v and tau_L = Lambda p (Bair & Winer 1979), tau = tau_f (1 - exp(-tel / tau_f)) (Maxwell build-up of the
    elastic stress tel = G_eff S (x - x_in) / h).  p [Pa], eta [Pa s], gdot = |S| U / h [1/s], tau0, tauL,
    tel [Pa]; vectorised; 0 where p <= 0 or gdot = 0."""
    p, eta, gdot, tau0, tauL, tel = np.broadcast_arrays(*(np.asarray(v, dtype=float) for v in
                                                          (p, eta, gdot, tau0, tauL, tel)))
    out = np.zeros(p.shape)
    ok = (p > 0.0) & (gdot > 0.0) & (tel > 0.0)
    if not np.any(ok):
        return out
    arg = eta[ok] * gdot[ok] / tau0[ok]
    tv = tau0[ok] * np.where(arg > 1e7, np.log(2.0 * np.maximum(arg, 1.0)), np.arcsinh(np.minimum(arg, 1e7)))
    lo, hi = np.minimum(tv, tauL[ok]), np.maximum(tv, tauL[ok])
    tf = lo / np.sqrt(np.sqrt(1.0 + (lo / hi) ** 4))
    out[ok] = -tf * np.expm1(-tel[ok] / tf)
    return out


def maxwell_eyring_march(x, p, eta, tau0, tauL, G, gdot, U, x_in, tau_guess=None):
    """Shear stress along a streamline by the Maxwell-Eyring equation, marched cell by cell [Pa] (array like x).

    The constitutive equation of Johnson & Tevaarwerk 1977 [8] (their eq. for the non-linear Maxwell fluid),
    steady, along a streamline moving at the rolling speed U (d/dt = U d/dx)::

        gdot = (1 / G) U dtau/dx + gdot_v(tau),     tau = 0 at the inlet edge x_in,

    gdot = |S| U / h the imposed shear rate [1/s], G the film's effective shear modulus [Pa], gdot_v the steady
    viscous rate at the stress tau: the inverse of the law's own flow curve tau_f = (tau_v^-4 + tau_L^-4)^(-1/4),
    tau_v = tau0 asinh(eta gdot_v / tau0) (:func:`local_stress`), i.e.
    tau_v(tau) = (tau^-4 - tau_L^-4)^(-1/4), gdot_v = (tau0 / eta) sinh(tau_v / tau0) (infinite at tau_L).

    Why it replaced the closed form tau_f (1 - exp(-tel / tau_f)) of :func:`local_stress`: that is the exact
    solution of the *linear* Maxwell equation at a viscosity constant along the path; in a Hertz contact the
    viscosity changes by orders of magnitude along the path and the flow is non-linear.  Against the equation
    integrated to convergence along every streamline (tests/helpers/maxwell_eyring_reference.py) the closed form
    was 11-25 % low at the elastic-plastic knee (S = 1e-3 ... 1e-2; 37 of 174 cases outside the tolerance 10 % +
    3e-4, docs/traction.md); marched on the law's own cells it is within it everywhere.

    Scheme: one backward-Euler step per cell, from the previous point (x_in for the first) to the cell's point
    x[i], with the cell's eta [Pa s], tau0 [Pa], tau_L [Pa] (L-stable: the relaxation length eta U / G is far
    below a cell where the viscosity is low).  The implicit equation
    f(tau) = tau - tau_prev - dx G gdot / U + dx (G / U) gdot_v(tau) = 0 is increasing in tau, negative at 0 and
    positive at min(tau_prev + dx G gdot / U, tau_L): Newton safeguarded by that bracket (bisection when a
    Newton step leaves it), to 1e-12 relative.  ``tau_guess`` (the last fixed-point iterate) starts Newton.
    x ascending [m]; p, eta, tau0, tauL arrays like x (tau = 0 where p <= 0); G, gdot >= 0, U != 0 scalars.
    """
    n = len(x)
    out = np.zeros(n)
    if gdot <= 0.0:
        return out
    B = G / abs(U)
    A = B * gdot
    xs = np.asarray(x, dtype=float).tolist()
    ps = np.asarray(p, dtype=float).tolist()
    es = np.broadcast_to(np.asarray(eta, dtype=float), (n,)).tolist()
    t0s = np.broadcast_to(np.asarray(tau0, dtype=float), (n,)).tolist()
    tLs = np.broadcast_to(np.asarray(tauL, dtype=float), (n,)).tolist()
    gs = None if tau_guess is None else np.asarray(tau_guess, dtype=float).tolist()
    tau, xp = 0.0, float(x_in)
    sinh, cosh = math.sinh, math.cosh
    for i in range(n):
        dx = xs[i] - xp
        xp = xs[i]
        tL = tLs[i]
        if ps[i] <= 0.0 or tL <= 0.0:
            tau = 0.0
            continue
        base = tau + dx * A
        hi = min(base, tL * (1.0 - 1e-12))
        lo = 0.0
        c, t0 = dx * B * t0s[i] / es[i], t0s[i]
        t = gs[i] if gs is not None and 0.0 < gs[i] < hi else 0.5 * hi
        for _ in range(100):
            q = 1.0 - (t / tL) ** 4  # tv = (t^-4 - tL^-4)^(-1/4) = t q^(-1/4), no overflow at small t
            tv = t * q ** -0.25 if q > 0.0 else 1e300
            r = min(tv / t0, 700.0)
            f = t - base + c * sinh(r)
            if f > 0.0:
                hi = t
            else:
                lo = t
            df = 1.0 + c * cosh(r) / t0 * q ** -1.25 if r < 700.0 else math.inf
            tn = t - f / df
            if not lo < tn < hi:
                tn = 0.5 * (lo + hi)
            if abs(tn - t) <= 1e-12 * t or hi - lo <= 1e-13 * hi:
                t = tn
                break
            t = tn
        tau = t
        out[i] = tau
    return out


def midfilm_temperature_rise(tau, dU, h, K):
    """Mid-film temperature above the surfaces [K]: tau dU h / (8 K), conduction across a film of thickness h
    heated uniformly by tau gdot (gdot = dU / h) with both surfaces at one temperature (Couette flow, e.g.
    Johnson & Greenwood 1980 [6] in the low-stress limit)."""
    return tau * dU * h / (8.0 * K)


def film_mean_temperature_rise(tau, dU, h, K):
    """Mean film temperature above the surfaces [K]: 2/3 of :func:`midfilm_temperature_rise` (the mean of the
    parabolic profile), tau dU h / (12 K): the temperature the film's viscosity and Eyring stress are taken at."""
    return tau * dU * h / (12.0 * K)


def heat_partition(u1, u2):
    """Fractions (w1, w2) of the film's heat going into surfaces 1 and 2: w_i = sqrt|u_i| / (sqrt|u1| + sqrt|u2|),
    Blok's partition [5] (equal flash temperatures of two high-Peclet surfaces of the same steel); (0.5, 0.5) when
    both are at rest."""
    s1, s2 = math.sqrt(abs(u1)), math.sqrt(abs(u2))
    if s1 + s2 == 0.0:
        return 0.5, 0.5
    return s1 / (s1 + s2), s2 / (s1 + s2)


def _band_antiderivative(X):
    """F(X) = int_0^X e^t K_0(|t|) dt (signed X) [-]: X e^X (K0 + K1) - 1 for X > 0, -(|X| e^-|X| (K0 - K1) + 1)
    for X < 0, through the scaled Bessel functions k0e = e^x K0, k1e = e^x K1 (no overflow)."""
    X = np.asarray(X, dtype=float)
    a = np.abs(X)
    with np.errstate(invalid="ignore"):
        pos = a * (k0e(a) + k1e(a)) - 1.0  # int_0^a e^t K0(t) dt
        neg = 1.0 - a * np.exp(-2.0 * a) * (k1e(a) - k0e(a))  # int_0^a e^-t K0(t) dt = a e^-a (K0 - K1) + 1
    pos = np.where(a == 0.0, 0.0, pos)
    neg = np.where(a == 0.0, 0.0, neg)
    return np.where(X >= 0.0, pos, -neg)


def band_source_influence(edges, xc, u, k, kappa):
    """Surface temperature rise at the points ``xc`` per unit heat flux in each cell [edges_j, edges_j+1] of a
    half-space moving at speed u along x [K m^2 / W] (matrix, rows xc, columns cells).

    Jaeger's moving line source [3]: T(x) = (Q / (pi k)) e^X K_0(|X|), X = u (x - xi) / (2 kappa); a uniform flux
    q over a cell is the integral of line sources, done in closed form: d/dX [X e^X (K0(X) + K1(X))] = e^X K0(X)
    and d/dX [X e^-X (K0(X) - K1(X))] = e^-X K0(X) (X > 0).  So each entry is
    (2 kappa / (pi k |u|)) [F(X(edge_j)) - F(X(edge_j+1))] with F of :func:`_band_antiderivative` -- valid at any
    Peclet number; its high-Peclet limit is the 1-D transient result 2 q sqrt(kappa t / pi) / k (tested).
    u = 0 (a surface at rest) falls back to u = 1e-9 m/s (the stationary 2-D source has no steady state).
    """
    edges = np.asarray(edges, dtype=float)
    xc = np.asarray(xc, dtype=float)
    uu = u if abs(u) > 1e-9 else 1e-9
    c = 2.0 * kappa / abs(uu)
    # X measured downstream of the source: d = (x - xi) sign(u)
    d_hi = (xc[:, None] - edges[None, :-1]) * math.copysign(1.0, uu)  # xi = lower edge
    d_lo = (xc[:, None] - edges[None, 1:]) * math.copysign(1.0, uu)  # xi = upper edge
    F_hi = _band_antiderivative(d_hi / c)
    F_lo = _band_antiderivative(d_lo / c)
    return (c / (math.pi * k)) * np.abs(F_hi - F_lo)


def _strip_grid(b_u, n_cells):
    th = np.linspace(-0.5 * math.pi, 0.5 * math.pi, n_cells + 1)
    edges = b_u * np.sin(th)
    thc = 0.5 * (th[:-1] + th[1:])
    xc = b_u * np.sin(thc)
    return edges, xc


def _film_nodes(n=8):
    g, w = np.polynomial.legendre.leggauss(n)
    return 0.5 * (g + 1.0), w


#: Gauss-Legendre nodes 2y/h in (0, 1) and weights across half the film (nahme_film's mean)
_FILM_NODES = _film_nodes()


def nahme_xi(N):
    """Root xi >= 0 of xi tanh(xi) = N [-] (Newton; vectorised): the cross-film solution of
    :func:`nahme_film`.  Unique for every N >= 0 (xi tanh xi rises monotonically from 0)."""
    N = np.maximum(np.asarray(N, dtype=float), 0.0)
    xi = np.where(N < 1.0, np.sqrt(N), N + 0.0)  # xi ~ sqrt(N) for small N, ~ N for large N
    for _ in range(60):
        t = np.tanh(xi)
        f = xi * t - N
        df = t + xi * (1.0 - t * t)
        step = np.where(df > 0.0, f / np.where(df > 0.0, df, 1.0), 0.0)
        xi = np.maximum(xi - step, 0.5 * xi)
        if np.all(np.abs(step) <= 1e-14 * (1.0 + xi)):
            break
    return xi


def nahme_film(N):
    """Thermal Couette film with a rate exponential in temperature (Nahme 1940 [7]): (F, phi_max, phi_mean).

    A film of thickness h between two surfaces at one temperature, sheared at a uniform stress tau with a local rate
    gdot(z) = gdot_s exp(beta_f theta(z)) (theta the rise above the surfaces, beta_f = d ln gdot / dT at fixed
    stress, > 0: the viscosity falls with temperature) and heated by tau gdot(z), conducted to both surfaces: K theta'' = -tau gdot.  With phi = beta_f theta
    the exact solution is e^phi = cosh^2(xi) / cosh^2(2 xi y / h) (the Bratu problem), xi tanh xi = N,
    N = beta_f tau dU h / (8 K) (the isothermal mid-film rise times beta_f).  Returns F = gdot_s / (dU / h) =
    2 xi / sinh(2 xi) (the film shears like one at the surface temperature at F times the mean rate),
    phi_max = 2 ln cosh xi and the mean of phi over the film (8-point Gauss).  N -> 0: F = 1 - 2N/3, phi_mean = 2N/3
    (the uniform-heating parabola).  Vectorised.
    """
    xi = nahme_xi(N)
    with np.errstate(over="ignore", invalid="ignore"):
        F = np.where(xi > 1e-8, 2.0 * xi / np.sinh(np.minimum(2.0 * xi, 700.0)), 1.0)
    lc = xi + np.log1p(np.exp(-2.0 * xi)) - math.log(2.0)  # ln cosh xi without overflow
    y, w = _FILM_NODES  # 2 y / h in (0, 1) (symmetric film)
    a = xi[..., None] * y if np.ndim(xi) else xi * y
    lca = a + np.log1p(np.exp(-2.0 * a)) - math.log(2.0)
    phi = 2.0 * (lc[..., None] if np.ndim(xi) else lc) - 2.0 * lca
    mean = 0.5 * np.sum(w * phi, axis=-1)
    return F, 2.0 * lc, mean


def _log_rate(p, T, tau, eta_of, tau0_of):
    """ln of the Eyring rate (tau0(T)/eta(p, T)) sinh(tau/tau0(T)) [ln 1/s] (no overflow)."""
    t0 = tau0_of(T)
    x = np.maximum(tau / t0, 1e-300)
    lsinh = np.where(x > 20.0, x - math.log(2.0), np.log(np.sinh(np.minimum(x, 20.0))))
    return np.log(t0) + lsinh - np.log(eta_of(p, T))


def strip_mu(S, U, p0u, b_u, h, T_in, oil, prm: PhysicalParameters, *, Ge, tau0_in, n_cells=N_CELLS,
             tol=1e-4, max_iter=3000, return_fields=False):
    """Traction coefficient of one strip of the Hertz ellipse, thermal [-] (odd in S, even in U).

    S slide-roll ratio (U1 - U2)/U; U rolling speed [m/s]; p0u the strip's peak pressure [Pa]; b_u its half-width
    along the rolling direction [m]; h film thickness [m]; T_in inlet (and far-field surface) temperature [K];
    oil = dict(eta_in, alpha, beta_in, K); Ge effective film shear modulus [Pa]; tau0_in Eyring stress at T_in.

    The strip is cut into ``n_cells`` cells (edges x = b_u sin theta, theta uniform).  In each: the surface
    temperature T_s from the heat tau dU of all cells (:func:`band_source_influence` of both surfaces, Blok's
    partition :func:`heat_partition`, their mean); the film across its thickness by :func:`nahme_film` (the Eyring
    rate's temperature sensitivity beta_f at T_s, the stress of the last iterate): the viscous flow stress is the
    one at T_s and F dU / h; then the limiting shear at the film mean temperature and the Maxwell-Eyring equation
    marched along the strip's cells (:func:`maxwell_eyring_march`; ``buildup="closed"``: the closed form of
    :func:`local_stress`).  A relaxed fixed point on (T_s, tau).  mu = sum tau dx / sum p dx.
    With ``thermal = False``: the local stress at T_in (no heat).
    """
    if S == 0.0 or U == 0.0 or p0u <= 0.0:
        return (0.0, {}) if return_fields else 0.0
    s, Ua = abs(S), abs(U)
    edges, xc = _strip_grid(b_u, n_cells)
    dx = np.diff(edges)
    p = p0u * np.sqrt(np.maximum(1.0 - (xc / b_u) ** 2, 0.0))
    tel = Ge * s * (xc + b_u) / h  # elastic stress from the inlet edge (the inlet at -b_u in the frame U > 0)
    dU = s * Ua
    gdot = dU / h
    eta_in, alpha, beta_in, K = oil["eta_in"], oil["alpha"], oil["beta_in"], oil["K"]
    if prm.pressure_viscosity == "roelands":
        z, S0 = roelands_indices(eta_in, alpha, beta_in, T_in)
        if prm.z is not None:
            z = prm.z

        def eta_of(pp, T):
            return roelands_viscosity(pp, T, eta_in, T_in, z, S0)
    elif prm.pressure_viscosity == "barus":
        def eta_of(pp, T):
            return barus_viscosity(pp, T, eta_in, T_in, alpha, beta_in)
    else:
        raise ValueError(f"unknown pressure_viscosity {prm.pressure_viscosity!r} (roelands, barus)")

    def tau0_of(T):
        return eyring_stress_at(tau0_in, T, T_in, prm.eyring_temperature)

    if prm.buildup not in ("march", "closed"):
        raise ValueError(f"unknown buildup {prm.buildup!r} (march, closed)")

    def stress(Ts, Tm, F, guess=None):
        eta = eta_of(p, Ts)
        if prm.buildup == "closed":
            return local_stress(p, eta, gdot * F, tau0_of(Ts), prm.limiting_shear(Tm) * p, tel)
        # the film heated across its thickness shears like one at T_s at F times the mean rate (nahme_film): its
        # mean viscous rate at a stress is that of a film of viscosity eta(T_s) F
        return maxwell_eyring_march(xc, p, eta * F, tau0_of(Ts), prm.limiting_shear(Tm) * p, Ge, gdot, Ua, -b_u,
                                    tau_guess=guess)

    Ts = np.full(n_cells, float(T_in))
    one = np.ones(n_cells)
    tau = stress(Ts, Ts, one)
    Tm = Ts.copy()
    it = 0
    if prm.thermal:
        # surface speeds in the frame U > 0: u1 = U (1 + S/2), u2 = U (1 - S/2) (both the same direction for |S| < 2)
        u1, u2 = Ua * (1.0 + 0.5 * S), Ua * (1.0 - 0.5 * S)
        w1, w2 = heat_partition(u1, u2)
        # mean of the two surface temperatures (equal in Blok's limit)
        M = 0.5 * (w1 * band_source_influence(edges, xc, u1, prm.k_solid, prm.kappa_solid)
                   + w2 * band_source_influence(edges, xc, u2, prm.k_solid, prm.kappa_solid))
        omega, last = 0.5, np.inf
        th_max = np.zeros(n_cells)  # mid-film rise above the surfaces [K]
        for it in range(1, max_iter + 1):  # noqa: B007 (the count is returned in the fields)
            q = tau * dU
            Ts_new = T_in + M @ q
            # the Eyring rate's temperature sensitivity at the current stress: the chord from the surface to the
            # mid-film temperature of the last iterate (the exponential of Nahme's solution then meets the rate at
            # both; a tangent at the surface overstates the heat's effect where ln eta is convex in T)
            tv = np.maximum(tau, 1e-30)
            dth = np.maximum(th_max, 0.5)
            beta_f = (_log_rate(p, Ts_new + dth, tv, eta_of, tau0_of) - _log_rate(p, Ts_new, tv, eta_of, tau0_of)) / dth
            beta_f = np.maximum(beta_f, 1e-9)
            N = beta_f * tau * dU * h / (8.0 * K)
            F, phi_max, phi_mean = nahme_film(N)
            th_max = th_max + omega * (phi_max / beta_f - th_max)
            Tm_new = Ts_new + phi_mean / beta_f
            tau_new = stress(Ts_new, Tm_new, F, tau)
            change = max(np.max(np.abs(Ts_new - Ts)), np.max(np.abs(Tm_new - Tm)),
                         np.max(np.abs(tau_new - tau) / np.maximum(p, 1.0)) * 1e3)
            Ts = Ts + omega * (Ts_new - Ts)
            Tm = Tm + omega * (Tm_new - Tm)
            tau = tau + omega * (tau_new - tau)
            if change < tol:
                break
            if change > last:  # oscillating (strong heating at cold oil): relax harder
                omega = max(0.5 * omega, 0.02)
            last = change
        else:
            raise RuntimeError(f"thermal traction fixed point did not converge ({max_iter} iterations, "
                               f"last change {change:.3g})")
    mu = math.copysign(float(np.sum(tau * dx) / np.sum(p * dx)), S)
    if return_fields:
        return mu, dict(x=xc, p=p, tau=tau, T=Tm, T_surface=Ts, iterations=it)
    return mu


def contact_parameters(W, U, Ep, Rx, k, a, eta_in, alpha, prm: PhysicalParameters, T_in, h=None):
    """(b, p0, h, Ge, tau0_in) of a contact: b = a / k, p0 = 3 W / (2 pi a b), h Hamrock-Dowson central film
    (eyring.central_film) unless given, Ge = eyring.effective_shear_modulus, tau0_in = 2 Lambda(T_in) / alpha."""
    b = a / k
    p0 = 1.5 * W / (math.pi * a * b)
    if h is None:
        h = central_film(W, U, Ep, Rx, k, eta_in, alpha)
    Ge = effective_shear_modulus(prm.G, b, h, p0, Rx)
    tau0 = prm.tau0 if prm.tau0 is not None else eyring_stress_default(float(prm.limiting_shear(T_in)), alpha)
    return b, p0, h, Ge, tau0


def contact_mu(S, W, U, Ep, Rx, k, a, T_in, eta_in, alpha, beta_in, K, prm: PhysicalParameters | None = None,
               n_major=5, spin=0.0, h=None, n_cells=N_CELLS):
    """mu of a whole contact [-]: :func:`strip_mu` over the kernel's strips (ball.strip_load_weights), load-weighted.

    Strip k (y = a u_k) has slip S + spin u_k (spin: the change of the slide-roll ratio across the major axis, as
    the kernel's local slip of each strip), peak pressure p0 sqrt(1 - u_k^2), half-width b sqrt(1 - u_k^2).
    Vectorised in S.  T_in [K]; eta_in [Pa s], alpha [1/Pa], beta_in [1/K], K [W/(m K)] of the oil at T_in.
    """
    from hsbearing.models.ball_bearing.ball import strip_load_weights

    prm = prm or PhysicalParameters()
    b, p0, h, Ge, tau0 = contact_parameters(W, U, Ep, Rx, k, a, eta_in, alpha, prm, T_in, h)
    oil = dict(eta_in=eta_in, alpha=alpha, beta_in=beta_in, K=K)
    qu, qw = strip_load_weights(n_major)
    Sa = np.asarray(S, dtype=float)
    out = []
    for s in Sa.ravel():
        tot = 0.0
        for u, w in zip(qu, qw):
            su = math.sqrt(1.0 - u * u)
            tot += w * strip_mu(float(s) + spin * u, U, p0 * su, b * su, h, T_in, oil, prm, Ge=Ge, tau0_in=tau0,
                                n_cells=n_cells)
        out.append(tot)
    return np.array(out).reshape(Sa.shape)
