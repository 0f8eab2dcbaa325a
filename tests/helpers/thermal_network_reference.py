"""Independent assembly of the bearing's steady thermal network (docs/thermal.md), without hsbearing.systems.angular_contact.thermal.

The same elements as ``thermal.bearing_network`` -- written here from their sources, not imported -- joined here into
a linear system G T = q (the oil-side convection depends on the oil temperature through the viscosity: solved by
Newton on that one unknown with the linear system inside), so that tests/validation/test_thermal_network.py can check
the package's network link by link and as a whole:

* conduction through a cylindrical wall ln(r2/r1)/(2 pi k L) (Incropera), inner ring bore -> race radius, outer ring race
  -> outside diameter **in series with** the housing wall;
* two-layer cylindrical wall by finite volumes (:func:`two_layer_wall_fv`), the check of that series combination;
* race contact: the isothermal elliptic constriction K(m)/(2 pi k a) of each body (scipy's ellipk, not the package's
  AGM) plus the central EHL film h/(k_oil pi a b), Z contacts in parallel;
* ring / ball / cage to oil: Harris's h = 0.0986 k Pr^(1/3) sqrt(n_eff / nu), n_eff [r/min] = twice the body's speed
  relative to the oil that turns with the cage; each relative speed derived here (:func:`speeds_relative_to_the_oil`);
* shaft: two pin fins with the rotating-cylinder h in still air (Becker / Kreith), housing: h A;
* oil: advection m c_p (T_oil - T_in) at the well-mixed cavity temperature.

The only hsbearing import is the viscosity law (``hsbearing.models.viscosity.dynamic_viscosity``, checked by
tests/models/test_viscosity.py), passed in as ``eta_of_T``.
"""

from __future__ import annotations

import math

import numpy as np
from scipy.special import ellipk

NODES = ("inner_ring", "outer_ring", "balls", "cage", "oil", "housing", "shaft")
AIR_K, AIR_NU, AIR_PR = 0.028, 1.8e-5, 0.71  # air at 20-100 degC (Incropera, Table A.4 order of magnitude)


def wall(r1, r2, L, k):
    """Cylindrical wall resistance [K/W]."""
    return math.log(r2 / r1) / (2.0 * math.pi * k * L)


def two_layer_wall_fv(r1, r2, r3, L1, L2, k1, k2, n=400):
    """Resistance [K/W] of two cylindrical layers r1..r2 (conductivity k1, axial length L1) and r2..r3 (k2, L2) by
    finite volumes in r: 1 W enters at r1, T = 0 at r3; each layer's heat spreads over its own length (the network's
    1-D assumption).  Face conductances 2 pi k L r_f / dr, the interface by the series of the two half cells.
    Returns T(r1) (extrapolated from the first cell centre by its half-cell resistance)."""
    e1 = np.geomspace(r1, r2, n + 1)
    e2 = np.geomspace(r2, r3, n + 1)
    edges = np.r_[e1, e2[1:]]
    kk = np.r_[np.full(n, k1), np.full(n, k2)]
    LL = np.r_[np.full(n, L1), np.full(n, L2)]
    rc = np.sqrt(edges[:-1] * edges[1:])  # geometric centres: the half-cell resistances below are exact logs
    m = rc.size

    def half(i, r_from, r_to):
        return math.log(max(r_from, r_to) / min(r_from, r_to)) / (2 * math.pi * kk[i] * LL[i])

    A = np.zeros((m, m))
    b = np.zeros(m)
    for i in range(m - 1):
        g = 1.0 / (half(i, rc[i], edges[i + 1]) + half(i + 1, edges[i + 1], rc[i + 1]))
        A[i, i] += g
        A[i + 1, i + 1] += g
        A[i, i + 1] -= g
        A[i + 1, i] -= g
    g_out = 1.0 / half(m - 1, rc[-1], edges[-1])
    A[-1, -1] += g_out
    b[0] = 1.0
    T = np.linalg.solve(A, b)
    return float(T[0] + half(0, edges[0], rc[0]) * 1.0)


def constriction(a, b, k):
    """Isothermal elliptic contact on a half-space [K/W]: K(m)/(2 pi k a_1), a_1 the semi-major axis, m = 1 - (b/a)^2
    (capacitance of an elliptic disk, Smythe)."""
    a1, b1 = max(a, b), min(a, b)
    return float(ellipk(1.0 - (b1 / a1) ** 2)) / (2.0 * math.pi * k * a1)


def speeds_relative_to_the_oil(omega_i, omega_o, D, dm, alpha):
    """Speeds [rad/s] of each body relative to the oil, which turns with the cage, from rolling without slip.

    Cage (epicyclic): omega_c = ((1 - g) omega_i + (1 + g) omega_o) / 2, g = D cos(alpha)/d_m.  Rings: omega_ring -
    omega_c.  Ball about its own axis: its surface speed D/2 omega_b equals the outer race's surface speed relative to
    the cage at the contact radius (d_m + D cos(alpha))/2 -- derived here from the OUTER race (the package's docstring
    derives it from the inner one)."""
    g = D * math.cos(alpha) / dm
    wc = 0.5 * ((1.0 - g) * omega_i + (1.0 + g) * omega_o)
    wb = 0.5 * (dm + D * math.cos(alpha)) * abs(omega_o - wc) / (0.5 * D)
    return {"inner_ring": abs(omega_i - wc), "outer_ring": abs(omega_o - wc), "balls": wb, "cage": 0.0, "cage_speed": wc}


def harris_h(w_rel, nu, k, Pr):
    """Harris's ring-to-oil correlation with n_eff = 2 w_rel in r/min [W/(m^2 K)]."""
    n_eff = 2.0 * abs(w_rel) * 30.0 / math.pi
    return 0.0986 * k * Pr ** (1.0 / 3.0) * math.sqrt(n_eff / nu)


def fin(h, d, k, L):
    P, A = math.pi * d, math.pi * d * d / 4.0
    m = math.sqrt(h * P / (k * A))
    return math.sqrt(h * P * k * A) * math.tanh(m * L)


def rotating_cylinder(omega, d):
    Re = abs(omega) * d * d / AIR_NU
    return max(0.133 * Re ** (2.0 / 3.0) * AIR_PR ** (1.0 / 3.0) * AIR_K / d, 5.0)


def conductances(p, contacts, T_oil, eta_of_T):
    """Every link's conductance [W/K] at the oil temperature T_oil: dict (a, b) -> G.

    ``p``: dict of the inputs (D, dm, B, d, Do, DH, BH, Ls, Z, alpha, omega_i, omega_o, ks, kh, k_oil, cp, rho,
    h_house, cage_od, cage_bore, cage_width, oil_convection or None); ``contacts``: dict side -> (a, b, h) arrays."""
    D, dm = p["D"], p["dm"]
    G = {}
    G[("inner_ring", "shaft")] = 1.0 / wall(0.5 * p["d"], 0.5 * (dm - D), p["B"], p["ks"])
    G[("outer_ring", "housing")] = 1.0 / (wall(0.5 * (dm + D), 0.5 * p["Do"], p["B"], p["ks"])
                                          + wall(0.5 * p["Do"], 0.5 * p["DH"], p["BH"], p["kh"]))
    for side, node in (("inner", "inner_ring"), ("outer", "outer_ring")):
        a, b, h = contacts[side]
        G[("balls", node)] = float(sum(1.0 / (2.0 * constriction(x, y, p["ks"]) + t / (p["k_oil"] * math.pi * x * y))
                                       for x, y, t in zip(a, b, h) if x > 0 and y > 0))
    eta = eta_of_T(T_oil)
    nu, Pr = eta / p["rho"], eta * p["cp"] / p["k_oil"]
    w = speeds_relative_to_the_oil(p["omega_i"], p["omega_o"], D, dm, p["alpha"])
    rings = 0.5 * (w["inner_ring"] + w["outer_ring"])  # the cage's faces see the oil sheared towards both rings
    areas = {"inner_ring": math.pi * (dm - D) * p["B"], "outer_ring": math.pi * (dm + D) * p["B"],
             "balls": p["Z"] * math.pi * D * D,
             "cage": math.pi * (p["cage_od"] + p["cage_bore"]) * p["cage_width"]
             + 0.5 * math.pi * (p["cage_od"] ** 2 - p["cage_bore"] ** 2)}
    for body in ("inner_ring", "outer_ring", "balls", "cage"):
        wr = rings if body == "cage" else w[body]
        h = p["oil_convection"] if p.get("oil_convection") is not None else harris_h(wr, nu, p["k_oil"], Pr)
        G[(body, "oil")] = h * areas[body]
    G[("housing", "ambient")] = p["h_house"] * (math.pi * p["DH"] * p["BH"] + 0.5 * math.pi * (p["DH"] ** 2 - p["Do"] ** 2))
    G[("shaft", "ambient")] = 2.0 * fin(rotating_cylinder(p["omega_i"], p["d"]), p["d"], p["ks"], 0.5 * p["Ls"])
    return G


def solve(p, contacts, heat, T_in, T_amb, eta_of_T, fixed=None):
    """Steady temperatures [K]: the linear network at a given oil temperature, the oil temperature by a secant
    iteration on T_oil = the linear solution's oil node (the only nonlinearity).  ``fixed``: node -> temperature
    held (a limit case).  Returns (T dict, G dict)."""
    fixed = dict(fixed or {})
    mcp = p["rho"] * p["flow"] * p["cp"]

    def linear(T_oil_guess):
        G = conductances(p, contacts, T_oil_guess, eta_of_T)
        unknown = [n for n in NODES if n not in fixed]
        idx = {n: i for i, n in enumerate(unknown)}
        A = np.zeros((len(unknown), len(unknown)))
        q = np.array([float(heat.get(n, 0.0)) for n in unknown])
        known = {"ambient": T_amb, "oil_inlet": T_in, **fixed}
        for (a, b), g in G.items():
            for x, y in ((a, b), (b, a)):
                if x in idx:
                    A[idx[x], idx[x]] += g
                    if y in idx:
                        A[idx[x], idx[y]] -= g
                    else:
                        q[idx[x]] += g * known[y]
        if "oil" in idx:
            A[idx["oil"], idx["oil"]] += mcp
            q[idx["oil"]] += mcp * T_in
        x = np.linalg.solve(A, q)
        T = dict(known)
        T.update({n: float(x[idx[n]]) for n in unknown})
        return T, G

    if "oil" in fixed:
        return linear(fixed["oil"])
    t0, t1 = T_in, T_in + 10.0
    f0 = linear(t0)[0]["oil"] - t0
    for _ in range(60):
        f1 = linear(t1)[0]["oil"] - t1
        if abs(f1) < 1e-12 * t1 or f1 == f0:
            break
        t0, t1, f0 = t1, t1 - f1 * (t1 - t0) / (f1 - f0), f1
    return linear(t1)
