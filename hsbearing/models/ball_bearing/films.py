"""Thermal and part-filled cage films: the guide-land and pocket films at a film temperature and a fill fraction.

The guide-land film (cage on its land, sliding ~90 m/s in the 35-mm TP-2275 bearing at 72 000 r/min) and the pocket
films (ball surface sliding past the pocket wall) are Couette-dominated: at the quasi-static state (cage centred, balls
centred) their dissipation is the viscous shear of a thin film, linear in the film viscosity.  Two effects the
isothermal, flooded laws of the kernel (:func:`hsbearing.models.ball_bearing.cage.guide_land_forces`,
:mod:`hsbearing.models.ball_bearing.pocket`) leave out are added here as factors on their viscosity:

* :func:`thermal_couette_film`: the film's own shear heat, conducted across the film into the two walls, raises its
  temperature and lowers its viscosity.  Closed form of the plane Couette energy balance ([1]) with uniform
  dissipation (parabolic temperature profile between the wall temperatures) and the viscosity of the oil integrated
  across that profile (harmonic mean by Gauss-Legendre quadrature), solved as a fixed point on the shear stress.
  Advection along the film and the walls' own heating are neglected: the wall temperatures are inputs (the lubricant
  temperature, or the thermal network's ring, ball and cage temperatures with ``--thermal``).
* :func:`fill_fraction_band`: a part-filled film carries the shear force only where oil wets both walls.  The
  fraction is not known (it depends on how the jet's oil reaches the land and the pockets); it is reported as a
  bounded band: from the oil volume fraction of the cavity mixture the film is fed from (a film holding the
  mixture as it is: the low end) to a flooded film (fill 1: the high end, the kernel's assumption).  Starved EHL
  race contacts (Chevalier et al. 1998; Damiens, Venner, Cann & Lubrecht 2004 [2]): a band of their own,
  :mod:`hsbearing.models.ball_bearing.starvation`.

References
----------
[1] Plane Couette flow with viscous dissipation: the energy equation k d^2T/dy^2 = -tau du/dy across a film of
    thickness h between walls at T_a (y = 0) and T_b (y = h), tau uniform (no pressure gradient), with
    du/dy = tau / eta(T); for uniform dissipation q = tau U / h the solution is
    T(s) = T_a + (T_b - T_a) s + (q h^2 / 2k) s (1 - s), s = y / h, mean rise q h^2 / (12 k) above the wall mean,
    maximum rise q h^2 / (8 k) for equal walls (Schlichting & Gersten, *Boundary-Layer Theory*, 8th ed., Sec. 3.13.2,
    "Couette flow" with dissipation; Bird, Stewart & Lightfoot, *Transport Phenomena*, 2nd ed., Sec. 10.4, viscous
    heat source).  Derived here from the equation above, not read from the books; proven against our own
    finite-volume solution of the full problem (non-uniform dissipation tau^2 / eta(T)) in
    tests/models/test_films.py (helper tests/helpers/couette_film_reference.py).
[2] Damiens B., Venner C. H., Cann P. M. E., Lubrecht A. A., "Starved lubrication of elliptical EHD contacts",
    ASME J. Tribol. 126 (2004) 105-111 (abstract read: a single parameter, the fully flooded inlet length,
    governs the starved film); Chevalier F., Lubrecht A. A., Cann P. M. E., Colin F., Dalmaz G., "Film thickness in
    starved EHL point contacts", ASME J. Tribol. 120 (1998) 126-133 (not read).  The race contacts' starvation:
    models/ball_bearing/starvation.py.
"""

from __future__ import annotations

import math

import numpy as np

__all__ = ["couette_temperature_profile", "thermal_couette_film", "fill_fraction_band", "QUAD_POINTS"]

#: Gauss-Legendre points of the harmonic-mean viscosity across the film (:func:`thermal_couette_film`)
QUAD_POINTS = 8
_S, _W = np.polynomial.legendre.leggauss(QUAD_POINTS)
_S = 0.5 * (_S + 1.0)  # nodes on (0, 1)
_W = 0.5 * _W  # weights summing to 1


def couette_temperature_profile(s, T_a: float, T_b: float, tau: float, U: float, h: float, k: float):
    """Temperature [K] across a Couette film at s = y/h in [0, 1] with uniform dissipation q = |tau U| / h ([1]).

    T(s) = T_a + (T_b - T_a) s + (|tau U| h / (2 k)) s (1 - s): the solution of k T'' = -q with T(0) = T_a,
    T(1) = T_b.  tau [Pa], U [m/s] (either sign: the heat is tau U >= 0), h [m], k [W/(m K)].
    """
    s = np.asarray(s, dtype=float)
    return T_a + (T_b - T_a) * s + abs(tau * U) * h / (2.0 * k) * s * (1.0 - s)  # [1]


def thermal_couette_film(eta_of_T, U: float, h: float, k: float, T_a: float, T_b: float,
                         *, rtol: float = 1e-12, max_iter: int = 200) -> dict:
    """Shear stress, effective viscosity and temperatures of a Couette film heated by its own shear ([1]).

    The film of thickness h [m] between walls at T_a and T_b [K] sliding at U [m/s] (either sign) is sheared
    at the uniform stress tau = U / (h <1/eta>), <1/eta> the mean of 1/eta(T(s)) over the temperature profile
    of :func:`couette_temperature_profile` (Gauss-Legendre, :data:`QUAD_POINTS` nodes), itself set by tau:
    the fixed point tau = g(tau) is unique (g falls as tau rises: more heat, thinner oil) and is found by
    bisection on |tau| in (0, |U| eta(min(T_a, T_b)) / h].

    Parameters
    ----------
    eta_of_T : callable T [K] -> dynamic viscosity [Pa s] of the oil at ambient pressure (decreasing in T)
    U : sliding speed of one wall against the other [m/s]; h : film thickness [m] (> 0);
    k : oil thermal conductivity [W/(m K)]; T_a, T_b : wall temperatures [K]

    Returns
    -------
    dict: tau [Pa] (sign of U), eta_eff = tau h / U [Pa s] (the isothermal-law viscosity that gives the same
    stress), T_mean (film mean [K]), T_max [K], heat_a, heat_b (heat flux into wall a, b [W/m^2], sum tau U),
    isothermal_ratio = eta_eff / eta((T_a + T_b)/2).
    """
    if not h > 0.0 or not k > 0.0:
        raise ValueError("need h > 0 and k > 0")
    T_ref = 0.5 * (T_a + T_b)
    eta_ref = float(eta_of_T(T_ref))
    if U == 0.0:
        return {"tau": 0.0, "eta_eff": eta_ref, "T_mean": T_ref, "T_max": max(T_a, T_b), "heat_a": 0.0,
                "heat_b": 0.0, "isothermal_ratio": 1.0}
    V = abs(U)

    def g(t):
        T = couette_temperature_profile(_S, T_a, T_b, t, V, h, k)
        inv = float(np.sum(_W / np.array([float(eta_of_T(x)) for x in T])))
        return V / (h * inv)

    lo, hi = 0.0, V * float(eta_of_T(min(T_a, T_b))) / h  # f(t) = t - g(t): f(lo) < 0 <= f(hi)
    for _ in range(max_iter):
        mid = 0.5 * (lo + hi)
        if mid - g(mid) > 0.0:
            hi = mid
        else:
            lo = mid
        if hi - lo <= rtol * hi:
            break
    t = 0.5 * (lo + hi)
    q = t * V  # heat generated per unit area [W/m^2]
    rise = q * h / (2.0 * k)
    s_max = min(max(0.5 + (T_b - T_a) / (2.0 * rise), 0.0), 1.0) if rise > 0.0 else (0.0 if T_a >= T_b else 1.0)
    T_max = float(couette_temperature_profile(s_max, T_a, T_b, t, V, h, k))
    cond = k * (T_b - T_a) / h  # conduction from b to a through the film
    return {"tau": math.copysign(t, U), "eta_eff": t * h / V, "T_mean": T_ref + q * h / (12.0 * k), "T_max": T_max,
            "heat_a": 0.5 * q + cond, "heat_b": 0.5 * q - cond, "isothermal_ratio": t * h / V / eta_ref}


def fill_fraction_band(cavity_oil_fraction: float) -> tuple[float, float]:
    """(low, high) fill fraction of a part-filled cage film [-] (module docstring).

    low = the oil volume fraction X of the cavity mixture the film is fed from (a film holding the mixture as it
    is; air carries no shear at these viscosity ratios); high = 1 (flooded, the kernel's film).  The dissipation
    of a part-filled Couette film is the flooded one times the wetted fraction (the shear acts only where oil
    bridges the gap).  Nothing in the band is chosen from heat data.
    """
    X = float(cavity_oil_fraction)
    if not 0.0 <= X <= 1.0:
        raise ValueError("cavity oil fraction must be within [0, 1]")
    return X, 1.0
