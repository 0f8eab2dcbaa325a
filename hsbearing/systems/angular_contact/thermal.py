"""Steady thermal network of an angular-contact ball bearing, coupled to its quasi-static power loss.

``hsbearing thermal CASE [-o OUT.nc]``.  Nodes (unknown temperatures): inner ring, outer ring, balls, cage,
oil (the cavity oil, well mixed: its temperature is the oil outlet temperature), housing, shaft; fixed: the oil
inlet and the ambient air.  Heat enters at the bodies in contact (the quasi-static power loss by source and by
contact, split half to each body of a contact), flows by conduction (cylindrical walls, Hertzian contacts),
by convection to the oil and to the air, and leaves with the oil (m c_p (T_out - T_in)) and to the air
(housing surface, shaft).  The network is solved as a steady nonlinear system (the oil-side convection
coefficient depends on the oil temperature through its viscosity) with the project's damped Newton
(:func:`hsbearing.solvers.newton.damped_newton`), and iterated with the power loss: the lubricant temperature
that the viscosity and the traction law use is set to the mean temperature of the race contacts until it
changes by less than ``[thermal] tolerance`` (fixed point).  docs/thermal.md gives the equations, their
sources and the assumptions.

References
----------
[1] Harris T. A., Kotzalas M. N., *Rolling Bearing Analysis*, 5th ed., Vol. 2, the chapter on friction heat
    generation and heat transfer in rolling bearings: thermal network of rings, balls, oil, housing and
    shaft, heat from the friction of each contact, cylindrical conduction resistances, ring-to-oil convection
    h = 0.0986 [ (n / nu) (1 +- D cos(alpha) / d_m) ]^(1/2) k Pr^(1/3) (form as reproduced in later papers;
    not read from the book here; n in r/min, the unit of n in the chapter's list of symbols, and the reading
    that agrees with the rotating-disk similarity solution: docs/thermal.md, "Review").
[2] Takabi J., Khonsari M. M., "Experimental testing and thermal analysis of ball bearings", Tribology
    International 60 (2013) 93-103: thermal network of a ball bearing with the same elements (not read here).
[3] Pouly F., Changenet C., Ville F., Velex P., Damiens B., "Power loss predictions in high-speed rolling
    element bearings using thermal networks", Tribology Transactions 53 (2010) 957-967 (not read here).
[4] Incropera F. P., DeWitt D. P., *Fundamentals of Heat and Mass Transfer*: conduction resistance of a
    cylindrical wall ln(r_2/r_1) / (2 pi k L); fin of infinite... and finite length G = sqrt(h P k A) tanh(m L),
    m = sqrt(h P / (k A)); rotating cylinder in still air Nu = 0.133 Re^(2/3) Pr^(1/3), Re = omega d^2 / nu
    (Becker / Kreith correlation, Re < 4.3e5, 0.7 < Pr < 670).
[5] Yovanovich M. M., thermal constriction resistance of a circular contact of radius a on a half-space,
    R = 1 / (4 k a) per body (isothermal contact; the isoflux contact's mean temperature gives 8/(3 pi^2 k a)).
[6] Isothermal elliptic contact on a half-space: R = K(m) / (2 pi k a), a the semi-major axis, m = 1 - (b/a)^2
    (the capacitance of an elliptic disk, Jeans / Smythe; the same result Yovanovich's constriction papers use).
[7] von Karman T. (1921), Cochran W. G. (1934), Sparrow E. M., Gregg J. L. (1959): the rotating disk in a fluid
    at rest, h = -theta'(0) k sqrt(omega / nu), -theta'(0) -> 0.6205 Pr^(1/3) as Pr -> infinity: the reference
    of the ring-to-oil correlation's unit (tests/validation/test_thermal_reference.py solves it).
"""

from __future__ import annotations

import math
import sys
from dataclasses import dataclass, field

import numpy as np

from hsbearing.results import make_dataset, register, register_attr_units, standard_attrs
from hsbearing.systems.angular_contact.oil_properties import viscosity_at as _viscosity  # the old name, kept

__all__ = ["NODES", "Network", "solve_network", "cylinder_resistance", "constriction_resistance", "fin_conductance",
           "rotating_cylinder_h", "harris_oil_h", "body_oil_speeds", "bearing_network", "heat_by_body", "thermal_equilibrium",
           "thermal_lines", "thermal_cli"]

#: unknown-temperature nodes of the bearing network
NODES = ("inner_ring", "outer_ring", "balls", "cage", "oil", "housing", "shaft")
#: fixed-temperature nodes
FIXED = ("oil_inlet", "ambient")

#: air at 20-100 degC for the shaft convection [4]: conductivity [W/(m K)], kinematic viscosity [m^2/s], Prandtl
AIR_K, AIR_NU, AIR_PR = 0.028, 1.8e-5, 0.71


# ----------------------------------------------------------------------------- elements (pure)
def cylinder_resistance(r_in: float, r_out: float, length: float, k: float) -> float:
    """Radial conduction resistance of a cylindrical wall [K/W]: ln(r_out / r_in) / (2 pi k L) ([4])."""
    return math.log(r_out / r_in) / (2.0 * math.pi * k * length)


def constriction_resistance(a: float, k: float, b: float | None = None) -> float:
    """Constriction resistance of an isothermal contact on a half-space of conductivity k [K/W] ([5], [6]).

    Circle of radius a (``b`` None or b = a): 1 / (4 k a).  Ellipse of semi-axes a, b: K(m) / (2 pi k a_1),
    a_1 = max(a, b), m = 1 - (min/max)^2, K the complete elliptic integral of the first kind (the capacitance of
    an elliptic disk; reduces to 1/(4 k a) at m = 0).  The circle of the same area, 1/(4 k sqrt(a b)), is 20 %
    too high at a/b = 6 and 32 % at a/b = 9 (the race contacts of zhang2016): checked against a boundary-element
    solution in tests/validation/test_thermal_reference.py."""
    if b is None or b == a:
        return 1.0 / (4.0 * k * a)
    a1, b1 = max(a, b), min(a, b)
    return _ellipk(1.0 - (b1 / a1) ** 2) / (2.0 * math.pi * k * a1)


def _ellipk(m: float) -> float:
    """Complete elliptic integral of the first kind K(m), parameter m = e^2 < 1: pi / (2 AGM(1, sqrt(1 - m)))
    (arithmetic-geometric mean; Abramowitz & Stegun 17.6)."""
    x, y = 1.0, math.sqrt(1.0 - m)
    while abs(x - y) > 1e-15 * x:
        x, y = 0.5 * (x + y), math.sqrt(x * y)
    return math.pi / (2.0 * x)


def fin_conductance(h: float, d: float, k: float, length: float) -> float:
    """Conductance of a cylindrical pin fin of diameter d, length L, adiabatic tip [W/K] ([4]):
    sqrt(h P k A) tanh(m L), P = pi d, A = pi d^2 / 4, m = sqrt(h P / (k A))."""
    P, A = math.pi * d, 0.25 * math.pi * d * d
    m = math.sqrt(h * P / (k * A))
    return math.sqrt(h * P * k * A) * math.tanh(m * length)


def rotating_cylinder_h(omega: float, d: float, k: float = AIR_K, nu: float = AIR_NU, Pr: float = AIR_PR) -> float:
    """Convection coefficient of a cylinder of diameter d turning at omega in still air [W/(m^2 K)] ([4]):
    Nu = 0.133 Re^(2/3) Pr^(1/3), Re = omega d^2 / nu; below Re ~ 1 the free-convection floor 5 W/(m^2 K) is used."""
    Re = abs(omega) * d * d / nu
    return max(0.133 * Re ** (2.0 / 3.0) * Pr ** (1.0 / 3.0) * k / d, 5.0)


#: the constant of the ring-to-oil correlation of [1], with n in r/min (docs/thermal.md, "Review")
HARRIS_OIL_CONSTANT = 0.0986


def harris_oil_h(omega: float, nu: float, k: float, Pr: float, factor: float = 1.0) -> float:
    """Bearing surface to oil convection coefficient [W/(m^2 K)] ([1]):
    h = 0.0986 k Pr^(1/3) sqrt(n factor / nu), n = 30 omega / pi the speed in **r/min** (the correlation's unit,
    [1]'s nomenclature), omega [rad/s], nu [m^2/s].  For a ring, omega is its speed relative to the other ring
    and factor = 1 + D cos(alpha)/d_m for the inner ring, 1 - D cos(alpha)/d_m for the outer: n factor is then twice
    the ring's speed relative to the cage, with which the oil is taken to turn.  Other bodies: omega factor = twice
    their speed relative to that oil (:func:`bearing_network`).  Read with n in r/min the correlation is 0.72-0.79
    of the laminar rotating disk's h = C(Pr) k sqrt(omega_rel / nu) (von Karman similarity solution [7], Pr 18-572);
    read with omega in rad/s it would be 0.23-0.26 of it (docs/thermal.md, "Review"; tests/validation/test_thermal_reference.py)."""
    n = abs(omega) * 30.0 / math.pi
    return HARRIS_OIL_CONSTANT * k * Pr ** (1.0 / 3.0) * math.sqrt(n * factor / nu)


def body_oil_speeds(omega: float, gamma: float, dm: float, D: float) -> dict:
    """Speed [rad/s] of each body relative to the oil turning with the cage, for a relative ring speed omega and
    gamma = D cos(alpha) / d_m (rolling kinematics without slip, Harris & Kotzalas Vol. 1 ch. 8):
    inner ring omega (1 + gamma)/2, outer ring omega (1 - gamma)/2, balls their rolling speed about their own
    axis (d_m / (2 D)) (1 - gamma^2) omega, cage 0 (it turns with the oil: its surfaces see the oil sheared
    towards the two rings instead; :func:`bearing_network` takes the mean of the two rings', omega / 2)."""
    w = abs(omega)
    return {"inner_ring": 0.5 * w * (1.0 + gamma), "outer_ring": 0.5 * w * (1.0 - gamma),
            "balls": dm / (2.0 * D) * (1.0 - gamma * gamma) * w, "cage": 0.0}


# ----------------------------------------------------------------------------- generic steady network
@dataclass
class Network:
    """A steady thermal network.

    nodes : names of the unknown temperatures.  fixed : name -> temperature [K] of the boundary nodes.
    links : (a, b, G, kind): heat a -> b = G (T_a - T_b) [W]; G a number [W/K] or a callable G(T) of the
        dict of all temperatures (a nonlinear link); kind a label ("conduction", "convection oil", ...).
    advection : (node, inlet, m_cp): a flow of heat capacity rate m_cp [W/K] enters at the fixed node
        ``inlet`` and leaves node ``node`` at its temperature: heat carried away m_cp (T_node - T_inlet).
    sources : node -> heat generated [W].
    """

    nodes: list
    fixed: dict
    links: list = field(default_factory=list)
    advection: list = field(default_factory=list)
    sources: dict = field(default_factory=dict)

    def temperatures(self, x) -> dict:
        T = dict(self.fixed)
        T.update(zip(self.nodes, (float(v) for v in x)))
        return T

    def flows(self, T: dict) -> list[tuple[str, str, str, float]]:
        """(a, b, kind, heat a -> b [W]) for every link and advection (advection: node -> inlet)."""
        out = []
        for a, b, G, kind in self.links:
            g = G(T) if callable(G) else G
            out.append((a, b, kind, g * (T[a] - T[b])))
        for node, inlet, mcp in self.advection:
            out.append((node, inlet, "advection", mcp * (T[node] - T[inlet])))
        return out

    def residual(self, x) -> np.ndarray:
        """Heat balance of every node: generated - net outflow [W]."""
        T = self.temperatures(x)
        idx = {n: i for i, n in enumerate(self.nodes)}
        R = np.array([float(self.sources.get(n, 0.0)) for n in self.nodes])
        for a, b, _, q in self.flows(T):
            if a in idx:
                R[idx[a]] -= q
            if b in idx:
                R[idx[b]] += q
        return R


def solve_network(net: Network, T0=None, tol: float = 1e-9) -> tuple[dict, np.ndarray]:
    """Steady temperatures of ``net`` [K] by damped Newton (finite-difference Jacobian): (T dict, residual [W])."""
    from hsbearing.solvers.newton import damped_newton

    n = len(net.nodes)
    Tref = np.mean(list(net.fixed.values())) if net.fixed else 300.0
    x0 = np.full(n, Tref) if T0 is None else np.asarray(T0, dtype=float)
    qscale = max(sum(abs(float(v)) for v in net.sources.values()), 1e-3)

    def residual(x):
        return net.residual(x), None

    def jacobian(x, _aux):
        R0 = net.residual(x)
        J = np.empty((n, n))
        for j in range(n):
            xp = x.copy()
            dx = 1e-6 * max(abs(x[j]), 1.0)
            xp[j] += dx
            J[:, j] = (net.residual(xp) - R0) / dx
        return J

    x, R = damped_newton(residual, jacobian, x0, tol, active=np.arange(n), xscale=np.full(n, 10.0),
                         rscale=np.full(n, qscale), maxiter=50)
    return net.temperatures(x), R


# ----------------------------------------------------------------------------- the bearing
#: what each ``thermal.power_source`` heats the network with (printed and kept in the archive's attrs)
POWER_SOURCE_NOTE = {
    "quasistatic": ("the dynamic kernel's sources at the quasi-static state (race-control ball spin, centred cage); "
                    "excludes the jet-oil acceleration and the cage windage of hsbearing friction; a dynamic run of "
                    "zhang2016 loses ~27 % more (free ball spin, cage whirl): docs/power_loss.md"),
    "dynamic": ("the means over the second half of a dynamic run of {duration:g} s (thermal.dynamic_duration) at each "
                "fixed-point iteration: the free ball's spin and the cage whirl; excludes the jet-oil acceleration and "
                "the cage windage"),
}


def heat_by_body(case, walls: dict | None = None, race_temperatures=None) -> tuple[dict, dict, object]:
    """Power loss by source and contact [W] and the heat each node receives [W], from the source that
    ``thermal.power_source`` chooses (docs/power_loss.md, "Quasi-static, dynamic and SKF: what each includes").

    ``quasistatic`` (default): the dynamic kernel's dissipation at the quasi-static state.  ``dynamic``: a dynamic run
    of ``thermal.dynamic_duration`` from that state; each source is its mean over the second half of the run, and
    the race sources are split inner/outer in the ratio of the run's final state.

    The guide-land and pocket films are taken at their film temperature between their walls (``walls``: node
    temperatures [K], the previous network solution; None: every wall at ``lubricant.temperature``), as in
    ``hsbearing friction`` (:func:`hsbearing.systems.angular_contact.rating.film_factors`, ``friction.thermal_films``).

    ``race_temperatures`` (T_inner, T_outer) [K]: each race's contacts (traction, EHL rolling, damping) with the oil
    at that race's inlet temperature (``build_model(race_temperatures=...)``, as ``hsbearing friction --thermal``);
    None: both at ``lubricant.temperature``.  The quasi-static state and the drag keep ``lubricant.temperature``.

    Split (docs/thermal.md): a race contact's traction, EHL rolling and damping losses half to the ring, half
    to the ball; the pocket losses half to the ball, half to the cage; the guide-land loss half to the cage,
    half to the guiding ring; the ball drag to the oil (the churned mixture).

    Returns (sources by name [W], heat by node [W], quasi-static Dataset of the state).
    """
    from hsbearing.models.ball_bearing.kernel import AUX_INDEX, GAUX_INDEX
    from hsbearing.systems.angular_contact.dynamics import build_model

    m = build_model(case, race_temperatures=race_temperatures)
    aux, gaux = m.outputs(m.y0)
    if case.thermal.power_source == "dynamic":
        aux, gaux = _dynamic_outputs(case, m)
    col = {n: float(np.sum(aux[:, AUX_INDEX[n]])) for n in ("P_trac_i", "P_trac_o", "P_ehl_i", "P_ehl_o", "P_damp_i",
                                                            "P_damp_o", "P_pocket_film", "P_pocket_boundary", "P_drag")}
    from hsbearing.systems.angular_contact.cage_films import film_factors

    ff = film_factors(case, m, walls)
    land = float(gaux[GAUX_INDEX["P_guide_land"]]) * ff["land"]["factor"]
    col["P_pocket_film"] *= ff["pocket"]["factor"]
    src = {"race_traction_inner": col["P_trac_i"], "race_traction_outer": col["P_trac_o"],
           "ehl_rolling_inner": col["P_ehl_i"], "ehl_rolling_outer": col["P_ehl_o"],
           "contact_damping_inner": col["P_damp_i"], "contact_damping_outer": col["P_damp_o"],
           "pocket_film": col["P_pocket_film"], "pocket_boundary": col["P_pocket_boundary"],
           "guide_land": land, "drag": col["P_drag"]}
    inner = col["P_trac_i"] + col["P_ehl_i"] + col["P_damp_i"]
    outer = col["P_trac_o"] + col["P_ehl_o"] + col["P_damp_o"]
    pocket = col["P_pocket_film"] + col["P_pocket_boundary"]
    guide = "inner_ring" if case.cage.guidance == "inner_ring" else "outer_ring"
    heat = dict.fromkeys(NODES, 0.0)
    heat["inner_ring"] += 0.5 * inner
    heat["outer_ring"] += 0.5 * outer
    heat["balls"] += 0.5 * (inner + outer) + 0.5 * pocket
    heat["cage"] += 0.5 * pocket + 0.5 * land
    heat[guide] += 0.5 * land
    heat["oil"] += col["P_drag"]
    return src, heat, m.info["quasistatic"]


def _dynamic_outputs(case, m):
    """Kernel power columns standing for a dynamic run of ``thermal.dynamic_duration`` (``power_source = dynamic``):
    aux (Z, N_AUX) and gaux (N_GAUX,) at the run's final state, each source's columns rescaled so that their sum over
    the balls is the source's mean over the second half of the run (the inner/outer split of the race sources is the
    final state's)."""
    from hsbearing.models.ball_bearing.kernel import AUX_INDEX, GAUX_INDEX
    from hsbearing.systems.angular_contact.balances import SOURCES
    from hsbearing.systems.angular_contact.dynamics import simulate

    ds = simulate(case, duration=float(case.thermal.dynamic_duration), model=m, annotate=False)
    t = ds["time"].values
    late = ds.isel(time=slice(int(np.searchsorted(t, 0.5 * t[-1])), None))
    aux, gaux = m.outputs(ds.final_state.values)
    aux, gaux = aux.copy(), gaux.copy()
    for s, (_d, cols, g) in SOURCES.items():
        mean = float(late[f"power_loss_{s}"].mean())
        now = sum(float(np.sum(aux[:, AUX_INDEX[c]])) for c in cols) + (float(gaux[GAUX_INDEX[g]]) if g else 0.0)
        if now != 0.0:
            f = mean / now
            for c in cols:
                aux[:, AUX_INDEX[c]] *= f
            if g:
                gaux[GAUX_INDEX[g]] *= f
        elif mean != 0.0:  # the final state dissipates nothing there: the mean goes to the first column, evenly
            if cols:
                aux[:, AUX_INDEX[cols[0]]] = mean / aux.shape[0]
            else:
                gaux[GAUX_INDEX[g]] = mean
    return aux, gaux


def _geometry(case):
    """Lengths of the network [m] (docs/thermal.md; the [thermal] defaults are assumptions)."""
    b, c, th = case.bearing, case.cage, case.thermal
    D, dm, B = b.ball_diameter, b.pitch_diameter, b.width
    if B is None or b.bore_diameter is None or b.outside_diameter is None:
        from hsbearing.errors import CaseError

        raise CaseError(case.source, "bearing.width", "the thermal network needs bearing.bore_diameter, "
                        "outside_diameter and width")
    d, Do = b.bore_diameter, b.outside_diameter
    DH = th.housing_outside_diameter or 2.0 * Do
    BH = th.housing_width or 2.0 * B
    Ls = th.shaft_length or 10.0 * B
    return dict(D=D, dm=dm, B=B, d=d, Do=Do, DH=DH, BH=BH, Ls=Ls,
                gamma=D * math.cos(b.contact_angle or 0.0) / dm,
                A_ir=math.pi * (dm - D) * B, A_or=math.pi * (dm + D) * B, A_balls=b.ball_count * math.pi * D * D,
                A_cage=(math.pi * ((c.outside_diameter or dm + 0.5 * D) + (c.bore_diameter or dm - 0.5 * D)) * (c.width or B)
                        + 0.5 * math.pi * ((c.outside_diameter or dm + 0.5 * D) ** 2 - (c.bore_diameter or dm - 0.5 * D) ** 2)),
                A_housing=math.pi * DH * BH + 0.5 * math.pi * (DH * DH - Do * Do))


def bearing_network(case, heat: dict, qs, T_in: float | None = None) -> tuple[Network, dict]:
    """The network of the bearing for the heat by node ``heat`` and the quasi-static state ``qs`` (contact sizes);
    ``T_in`` the oil inlet temperature [K] (None: ``[thermal] oil_inlet_temperature``, else ``lubricant.temperature``)."""
    th, lub = case.thermal, case.lubricant
    g = _geometry(case)
    ks, kh = th.steel_thermal_conductivity, th.housing_thermal_conductivity
    from hsbearing.models.traction import OILS

    k_oil = th.oil_thermal_conductivity or OILS[lub.oil].K
    cp = th.oil_specific_heat
    T_in = T_in or th.oil_inlet_temperature or lub.temperature
    flow = _oil_flow(case)
    mcp = lub.density * flow * cp
    omega = abs(case.operating.inner_speed - case.operating.outer_speed)

    # race contacts: constriction of each body + the central EHL film, Z contacts in parallel
    def contact_G(side):
        a = np.asarray(qs[f"{side}_contact_semimajor"].values, dtype=float)
        b = np.asarray(qs[f"{side}_contact_semiminor"].values, dtype=float)
        h = np.asarray(qs[f"{side}_film_thickness_central"].values, dtype=float) if f"{side}_film_thickness_central" in qs else 0.0 * a
        ok = (a > 0) & (b > 0)
        R = (2.0 * np.array([constriction_resistance(x, ks, y) for x, y in zip(np.where(ok, a, 1.0), np.where(ok, b, 1.0))])
             + h / (k_oil * math.pi * np.where(ok, a * b, 1.0)))
        return float(np.sum(np.where(ok, 1.0 / R, 0.0)))

    G_bi, G_bo = contact_G("inner"), contact_G("outer")
    R_ir = cylinder_resistance(0.5 * g["d"], 0.5 * (g["dm"] - g["D"]), g["B"], ks)
    R_or = cylinder_resistance(0.5 * (g["dm"] + g["D"]), 0.5 * g["Do"], g["B"], ks)
    R_h = cylinder_resistance(0.5 * g["Do"], 0.5 * g["DH"], g["BH"], kh)
    h_shaft = rotating_cylinder_h(case.operating.inner_speed, g["d"])
    Re_shaft = abs(case.operating.inner_speed) * g["d"] ** 2 / AIR_NU  # correlation range Re < 4.3e5 ([4])
    G_shaft = 2.0 * fin_conductance(h_shaft, g["d"], ks, 0.5 * g["Ls"])  # both sides of the bearing
    G_house = th.housing_convection * g["A_housing"]

    def h_oil(T, factor):
        if th.oil_convection is not None:
            return th.oil_convection
        Tf = T["oil"]
        eta = _viscosity(case, Tf)
        return harris_oil_h(omega, eta / lub.density, k_oil, eta * cp / k_oil, factor)

    gm = g["gamma"]
    w_rel = body_oil_speeds(omega, gm, g["dm"], g["D"])
    f_ball = 2.0 * w_rel["balls"] / omega if omega > 0 else 1.0  # n factor = 2 n_rel (harris_oil_h)
    links = [
        ("inner_ring", "shaft", 1.0 / R_ir, "conduction"),
        ("outer_ring", "housing", 1.0 / (R_or + R_h), "conduction"),
        ("balls", "inner_ring", G_bi, "conduction"),
        ("balls", "outer_ring", G_bo, "conduction"),
        ("inner_ring", "oil", lambda T: h_oil(T, 1.0 + gm) * g["A_ir"], "convection oil"),
        ("outer_ring", "oil", lambda T: h_oil(T, 1.0 - gm) * g["A_or"], "convection oil"),
        ("balls", "oil", lambda T: h_oil(T, f_ball) * g["A_balls"], "convection oil"),
        ("cage", "oil", lambda T: h_oil(T, 1.0) * g["A_cage"], "convection oil"),
        ("housing", "ambient", G_house, "convection air"),
        ("shaft", "ambient", G_shaft, "conduction + convection air"),
    ]
    net = Network(nodes=list(NODES), fixed={"oil_inlet": T_in, "ambient": th.ambient_temperature}, links=links,
                  advection=[("oil", "oil_inlet", mcp)], sources=dict(heat))
    info = dict(G_ball_inner=G_bi, G_ball_outer=G_bo, R_inner_ring=R_ir, R_outer_ring=R_or, R_housing=R_h,
                h_shaft=h_shaft, Re_shaft=Re_shaft, G_shaft=G_shaft, G_housing=G_house, oil_heat_capacity_rate=mcp, **g)
    return net, info


def contact_temperature(T: dict) -> float:
    """The lubricant temperature the quasi-static state, the drag and the viscosity of the oil node use: the mean
    of the two race contacts' inlet temperatures, ((T_ir + T_b)/2 + (T_or + T_b)/2)/2."""
    return 0.25 * (T["inner_ring"] + T["outer_ring"] + 2.0 * T["balls"])


def wall_temperatures(th) -> dict:
    """The film walls' node temperatures [K] of a :func:`thermal_equilibrium` Dataset ``th``: ``inner_ring``,
    ``outer_ring``, ``balls``, ``cage`` (the ``walls`` of ``rating.film_factors`` / ``quasi_static_power_loss``)."""
    return {"inner_ring": float(th.inner_ring_temperature), "outer_ring": float(th.outer_ring_temperature),
            "balls": float(th.ball_temperature), "cage": float(th.cage_temperature)}


def race_inlet_offset(T: dict) -> float:
    """Half the difference of the two race contacts' inlet temperatures [K]: the inner inlet (T_ir + T_b)/2 lies
    this much above :func:`contact_temperature` and the outer inlet (T_or + T_b)/2 as much below it,
    (T_ir - T_or)/4 (``rating.race_inlet_temperatures``)."""
    return 0.25 * (T["inner_ring"] - T["outer_ring"])


#: ``thermal_equilibrium(race_rule=...)``: how the fixed point evaluates the race contacts' losses
RACE_RULES = {
    "per_race": "each race's contacts at its own inlet temperature, inner (T_inner_ring + T_balls)/2, outer "
                "(T_outer_ring + T_balls)/2 (the fixed point's lubricant temperature plus -/+ (T_inner_ring - "
                "T_outer_ring)/4 of the latest network)",
    "lubricant": "both races' contacts at the fixed point's lubricant temperature (the former rule)",
}


_VARS = [
    ("node_temperature", ("node",), "K", "steady temperature of each node of the thermal network"),
    ("node_heat_input", ("node",), "W", "heat generated at each node (power loss split over the bodies in contact)"),
    ("link_heat_flow", ("link",), "W", "heat flowing along each link of the network, from link_from to link_to"),
    ("inner_ring_temperature", (), "K", "inner ring temperature (thermal network)"),
    ("outer_ring_temperature", (), "K", "outer ring temperature (thermal network)"),
    ("ball_temperature", (), "K", "ball temperature (thermal network, all balls one node)"),
    ("cage_temperature", (), "K", "cage temperature (thermal network)"),
    ("housing_temperature", (), "K", "housing outer surface temperature (thermal network)"),
    ("shaft_temperature", (), "K", "shaft temperature at the bore (thermal network)"),
    ("oil_inlet_temperature", (), "K", "oil supply temperature"),
    ("oil_outlet_temperature", (), "K", "oil outlet temperature = the well-mixed cavity oil (thermal network)"),
    ("ambient_temperature", (), "K", "air temperature around housing and shaft"),
    ("lubricant_temperature", (), "K", "temperature the quasi-static state, the drag and the oil use at equilibrium: "
     "mean of the race contacts' inlet temperatures"),
    ("inner_race_inlet_temperature", (), "K", "temperature the inner race contacts' losses were evaluated at in the last "
     "fixed-point iteration: (T_inner_ring + T_balls)/2 to the fixed point's tolerance (race_temperature_rule per_race)"),
    ("outer_race_inlet_temperature", (), "K", "temperature the outer race contacts' losses were evaluated at in the last "
     "fixed-point iteration: (T_outer_ring + T_balls)/2 to the fixed point's tolerance (race_temperature_rule per_race)"),
    ("heat_generated", (), "W", "power loss at the thermal equilibrium, sum over the sources"),
    ("heat_removed_by_oil", (), "W", "heat carried away by the oil, m c_p (T_out - T_in)"),
    ("heat_removed_by_conduction", (), "W", "heat leaving through the housing and the shaft to the air"),
    ("heat_balance_error", (), "1", "(heat generated - heat removed) / heat generated"),
    ("fixed_point_iterations", (), "1", "power <-> temperature iterations to the fixed point"),
    ("iteration_lubricant_temperature", ("iteration",), "K", "lubricant temperature used by each fixed-point iteration"),
    ("iteration_power_loss", ("iteration",), "W", "power loss at each fixed-point iteration"),
    ("iteration_inner_race_inlet_temperature", ("iteration",), "K", "inner race contacts' inlet temperature used by each "
     "fixed-point iteration"),
    ("iteration_outer_race_inlet_temperature", ("iteration",), "K", "outer race contacts' inlet temperature used by each "
     "fixed-point iteration"),
]
for _n, _d, _u, _l in _VARS:
    register(_n, _d, _u, _l)
_SRC = ("race_traction_inner", "race_traction_outer", "ehl_rolling_inner", "ehl_rolling_outer", "contact_damping_inner",
        "contact_damping_outer", "pocket_film", "pocket_boundary", "guide_land", "drag")
for _s in _SRC:
    register(f"thermal_power_loss_{_s}", (), "W", f"quasi-static power loss {_s} at the thermal equilibrium")
#: the links of :func:`bearing_network` (and the oil's advection), as the scalars a sweep summary carries: heat by path
HEAT_PATHS = (("inner_ring", "shaft", "conduction"), ("outer_ring", "housing", "conduction"),
              ("balls", "inner_ring", "conduction"), ("balls", "outer_ring", "conduction"),
              ("inner_ring", "oil", "convection oil"), ("outer_ring", "oil", "convection oil"),
              ("balls", "oil", "convection oil"), ("cage", "oil", "convection oil"),
              ("housing", "ambient", "convection air"), ("shaft", "ambient", "conduction + convection air"),
              ("oil", "oil_inlet", "advection"))


def heat_path_name(src: str, dst: str) -> str:
    """Summary name of the heat flowing along the link src -> dst (``heat_flow_<src>_to_<dst>``)."""
    return f"heat_flow_{src}_to_{dst}"


for _a, _b, _k in HEAT_PATHS:
    register(heat_path_name(_a, _b), (), "W", f"heat flowing from {_a} to {_b} at the thermal equilibrium ({_k})")
_ATTR_UNITS = {"network_residual_W": "W", "network_G_ball_inner": "W/K", "network_G_ball_outer": "W/K",
               "network_R_inner_ring": "K/W", "network_R_outer_ring": "K/W", "network_R_housing": "K/W",
               "network_h_shaft": "W/(m^2*K)", "network_Re_shaft": "1", "network_G_shaft": "W/K", "network_G_housing": "W/K",
               "network_oil_heat_capacity_rate": "W/K", "network_gamma": "1",
               **{f"network_{k}": "m" for k in ("D", "dm", "B", "d", "Do", "DH", "BH", "Ls")},
               **{f"network_{k}": "m^2" for k in ("A_ir", "A_or", "A_balls", "A_cage", "A_housing")}}
_ATTR_UNITS.update({f"thermal_{k}": "K" for k in ("lubricant_temperature", "inner_ring_temperature", "outer_ring_temperature",
                                                  "ball_temperature", "cage_temperature", "oil_outlet_temperature",
                                                  "inner_contact_inlet_temperature", "outer_contact_inlet_temperature")})
for _a, _u in _ATTR_UNITS.items():  # the thermal_* ones: the attrs of a run archive of hsbearing run --thermal
    register_attr_units(_a, _u)


#: status of a thermal archive whose fixed point left the oil's range (thermal runaway at that oil flow): the
#: archive holds the last network solved, attrs["error"] says where it stopped
STATUS_NO_EQUILIBRIUM = "no_equilibrium"

#: largest change of the lubricant temperature per fixed-point iteration [K] (docs/thermal.md, "Solution")
MAX_FIXED_POINT_STEP = 40.0


def thermal_equilibrium(case, *, progress=None, T_start=None, x0_nodes=None, race_rule: str = "per_race"):
    """Fixed point of the power loss and the thermal network; returns the Dataset (docs/thermal.md).

    ``T_start`` [K]: the lubricant temperature of the first iteration (default the oil inlet temperature);
    ``x0_nodes`` [K]: the node temperatures the first network solve starts from (default all at the mean of
    the fixed nodes).  Both only move the starting point (the uniqueness check of docs/thermal.md).

    ``race_rule`` (:data:`RACE_RULES`): ``per_race`` (default) evaluates each race's contact losses at that race's
    inlet temperature: the iterate's lubricant temperature T_lub plus (inner) or minus (outer) the offset
    (T_ir - T_or)/4 of the latest network solved (zero before the first), so that at the fixed point they are
    (T_ir + T_b)/2 and (T_or + T_b)/2 of the converged network, the temperatures ``hsbearing friction --thermal``
    evaluates its losses at.  The quasi-static state, the drag and the oil node keep T_lub, the guide-land and
    pocket films their walls' node temperatures.  Converged when T_lub and both race inlet temperatures move by
    less than ``thermal.tolerance`` (|dT_lub| + |d offset| < tolerance); with equal ring temperatures (offset 0)
    this is the former criterion and the iteration is the former one, bit for bit.  ``lubricant``: both races at
    T_lub (the former rule, kept for comparison)."""
    from hsbearing.case import as_case
    from hsbearing.errors import CaseError

    case = as_case(case)
    if race_rule not in RACE_RULES:
        raise ValueError(f"race_rule must be one of {', '.join(RACE_RULES)}, got {race_rule!r}")
    th = case.thermal
    T_in = th.oil_inlet_temperature or case.lubricant.temperature
    T_lub = T_in if T_start is None else float(T_start)
    hist_T, hist_P, hist_Ti, hist_To = [], [], [], []
    T_nodes, converged, it, runaway = None, False, 0, ""
    if x0_nodes is not None:
        T_nodes = dict(zip(NODES, (float(v) for v in x0_nodes)))
    per_race = race_rule == "per_race"
    # the race inlet offset the losses are evaluated with: from the latest network (the start's nodes if given)
    d_race = race_inlet_offset(T_nodes) if per_race and T_nodes is not None else 0.0
    for it in range(1, th.max_iterations + 1):
        races = (T_lub + d_race, T_lub - d_race) if per_race else None
        checks = [("lubricant temperature", T_lub)]
        if races is not None and d_race != 0.0:  # each race's inlet must lie in the oil's range too (build_model)
            checks += [("inner race inlet temperature", races[0]), ("outer race inlet temperature", races[1])]
        cases_at, bad = [], None
        for what, T_what in checks:
            try:
                cases_at.append(case.with_overrides(**{"lubricant.temperature": f"{T_what} K"}))
            except CaseError as exc:
                bad = (what, T_what, exc)
                break
        if bad:  # the fixed point left the oil's range: no equilibrium at this oil flow
            what, T_what, exc = bad
            if not hist_T:  # the start itself is outside the oil's data: bad input
                raise exc
            # a result, not bad input (thermal runaway at this flow): the last network solved is kept, with its status
            runaway = (f"no thermal equilibrium: at iteration {it} the {what} reaches {T_what - 273.15:.1f} degC "
                       f"(power {hist_P[-1]:.4g} W at {hist_T[-1] - 273.15:.1f} degC, oil flow "
                       f"{case.lubricant.oil_flow_rate * 6e4:.4g} L/min), beyond the oil's range ({exc.message}); "
                       "more oil flow (lubricant.oil_flow_rate) or a cooler inlet is needed")
            it -= 1
            break
        c = cases_at[0]  # the case at T_lub
        src, heat, qs = heat_by_body(c, walls=T_nodes, race_temperatures=races)
        net, info = bearing_network(c, heat, qs, T_in)
        x0 = None if T_nodes is None else [T_nodes[n] for n in NODES]
        T_nodes, R = solve_network(net, x0)
        hist_T.append(T_lub)
        hist_P.append(sum(src.values()))
        hist_Ti.append(T_lub + d_race)
        hist_To.append(T_lub - d_race)
        T_new = contact_temperature(T_nodes)
        d_new = race_inlet_offset(T_nodes) if per_race else 0.0
        if progress:
            progress(it, T_lub, hist_P[-1], T_new)
        # each race's inlet moved by T_new - T_lub +- (d_new - d_race): both below the tolerance
        if abs(T_new - T_lub) + abs(d_new - d_race) < th.tolerance:
            converged = True
            break
        d_race = d_new
        # under-relaxed (the power falls as the oil thins), the step bounded so that a start far from the
        # equilibrium (a cold start at high speed: a large power at a thick oil) cannot leave the oil's range
        T_lub = T_lub + max(-MAX_FIXED_POINT_STEP, min(MAX_FIXED_POINT_STEP, 0.8 * (T_new - T_lub)))
    flows = net.flows(T_nodes)
    P = sum(net.sources.values())
    q_oil = sum(q for a, b, k, q in flows if k == "advection")
    q_cond = sum(q for a, b, k, q in flows if b == "ambient")
    data = {
        "node_temperature": np.array([T_nodes[n] for n in NODES]),
        "node_heat_input": np.array([net.sources[n] for n in NODES]),
        "link_heat_flow": np.array([q for *_, q in flows]),
        "inner_ring_temperature": T_nodes["inner_ring"], "outer_ring_temperature": T_nodes["outer_ring"],
        "ball_temperature": T_nodes["balls"], "cage_temperature": T_nodes["cage"],
        "housing_temperature": T_nodes["housing"], "shaft_temperature": T_nodes["shaft"],
        "oil_inlet_temperature": T_nodes["oil_inlet"], "oil_outlet_temperature": T_nodes["oil"],
        "ambient_temperature": T_nodes["ambient"], "lubricant_temperature": hist_T[-1],
        "inner_race_inlet_temperature": hist_Ti[-1], "outer_race_inlet_temperature": hist_To[-1],
        "heat_generated": P, "heat_removed_by_oil": q_oil, "heat_removed_by_conduction": q_cond,
        "heat_balance_error": (P - q_oil - q_cond) / P if P else 0.0,
        "fixed_point_iterations": float(it),
        "iteration_lubricant_temperature": np.array(hist_T), "iteration_power_loss": np.array(hist_P),
        "iteration_inner_race_inlet_temperature": np.array(hist_Ti),
        "iteration_outer_race_inlet_temperature": np.array(hist_To),
    }
    data.update({f"thermal_power_loss_{s}": src[s] for s in _SRC})
    coords = {"node": list(NODES), "link": [f"{a}->{b}" for a, b, *_ in flows], "iteration": np.arange(1, len(hist_T) + 1)}
    status = "ok" if converged else STATUS_NO_EQUILIBRIUM if runaway else "not_converged"
    attrs = standard_attrs(
        case, status, title="hsbearing thermal: steady thermal network at the power loss", error=runaway or None,
        archive_kind="thermal", converged=int(converged), network_residual_W=float(np.max(np.abs(R))),
        heat_split=("race contact -> 1/2 ring + 1/2 balls; pocket -> 1/2 balls + 1/2 cage; guide land -> 1/2 cage + "
                    "1/2 guiding ring; ball drag -> oil"),
        lubricant_temperature_rule="(T_inner_ring + T_outer_ring + 2 T_balls) / 4",
        race_temperature_rule=f"{race_rule}: {RACE_RULES[race_rule]}",
        power_source=case.thermal.power_source,
        power_source_note=POWER_SOURCE_NOTE[case.thermal.power_source].format(
            duration=float(case.thermal.dynamic_duration)),
        **{f"network_{k}": float(v) for k, v in info.items()},
    )
    ds = make_dataset(data, coords=coords, attrs=attrs)
    return ds.assign_coords(link_from=("link", [a for a, *_ in flows]), link_to=("link", [b for _, b, *_ in flows]),
                            link_kind=("link", [k for _, _, k, _ in flows]))


def thermal_lines(ds) -> list[str]:
    """Printed summary of :func:`thermal_equilibrium`."""
    C = lambda v: f"{float(v) - 273.15:.2f} degC"  # noqa: E731
    if ds.attrs.get("status") == STATUS_NO_EQUILIBRIUM:
        lines = [f"NO thermal equilibrium -- {ds.attrs.get('error', '')}",
                 f"the last network solved ({int(ds.fixed_point_iterations)} fixed-point iterations, lubricant temperature "
                 f"{C(ds.lubricant_temperature)}; not a steady state):"]
    else:
        lines = [f"thermal network ({'converged' if ds.attrs.get('converged') else 'NOT converged'} in "
                 f"{int(ds.fixed_point_iterations)} fixed-point iterations, lubricant temperature "
                 f"{C(ds.lubricant_temperature)}):"]
    for n in NODES:
        i = list(ds.node.values).index(n)
        lines.append(f"  {n:12s} {C(ds.node_temperature.values[i]):>12s}   heat in {float(ds.node_heat_input.values[i]):8.3f} W")
    lines.append(f"  oil inlet {C(ds.oil_inlet_temperature)}, outlet {C(ds.oil_outlet_temperature)}; ambient {C(ds.ambient_temperature)}")
    lines.append(f"heat generated {float(ds.heat_generated):.3f} W = removed by the oil {float(ds.heat_removed_by_oil):.3f} W "
                 f"+ by conduction to the air (housing, shaft) {float(ds.heat_removed_by_conduction):.3f} W; "
                 f"balance error {float(ds.heat_balance_error):.2e}")
    if "inner_race_inlet_temperature" in ds:
        lines.append(f"race contacts' losses at inlet temperatures inner {C(ds.inner_race_inlet_temperature)}, outer "
                     f"{C(ds.outer_race_inlet_temperature)} (race_temperature_rule {ds.attrs.get('race_temperature_rule', '').split(':')[0]})")
    at = "at the last iteration" if ds.attrs.get("status") == STATUS_NO_EQUILIBRIUM else "at equilibrium"
    lines.append(f"power loss by source {at} [W]: " + ", ".join(
        f"{s} {float(ds[f'thermal_power_loss_{s}']):.3g}" for s in _SRC if abs(float(ds[f'thermal_power_loss_{s}'])) > 1e-9))
    Re = float(ds.attrs.get("network_Re_shaft", 0.0))
    if Re > 4.3e5:
        lines.append(f"note: shaft Reynolds number {Re:.3g} is beyond the rotating-cylinder correlation's range (4.3e5): "
                     "the shaft's air convection is extrapolated")
    if "power_source" in ds.attrs:
        lines.append(f"power source: {ds.attrs['power_source']} (thermal.power_source: quasistatic (default) or dynamic) -- "
                     f"{ds.attrs['power_source_note']}")
    lines.append("note: heat split " + ds.attrs["heat_split"] + "; correlations and assumptions: docs/thermal.md")
    return lines


def _oil_flow(case) -> float:
    """The oil flow through the bearing [m^3/s]; a CaseError naming the key if the case gives none."""
    if not case.lubricant.oil_flow_rate:
        from hsbearing.errors import CaseError

        raise CaseError(case.source, "lubricant.oil_flow_rate", "the thermal network needs the oil flow (e.g. \"1 L/min\"): "
                        "the oil carries the heat away")
    return case.lubricant.oil_flow_rate


def check_inputs(case) -> None:
    """Raise a CaseError naming the file and key if the case cannot give a thermal network: not an
    angular-contact case, no bore/outside diameter/width, no oil flow.  Called before anything is computed
    (``hsbearing thermal``, ``hsbearing sweep --kind thermal``)."""
    from hsbearing.errors import CaseError

    if case.system != "angular_contact":
        raise CaseError(case.source, "case.system", f"the thermal network is for angular_contact cases, not {case.system!r}")
    _geometry(case)
    _oil_flow(case)


def thermal_cli(args) -> int:
    """``hsbearing thermal CASE [--set k=v] [-o OUT.nc]``."""
    from hsbearing.case import load_case, parse_sets
    from hsbearing.results import check_archive_name, write_netcdf

    case = load_case(args.case, **parse_sets(getattr(args, "set", None)))
    check_inputs(case)
    out = getattr(args, "output", None)
    check_archive_name(out)  # (the path itself: cli.cmd_thermal, before this)
    ds = thermal_equilibrium(case, progress=lambda i, T, P, Tn: print(
        f"  iteration {i}: lubricant {T - 273.15:.3f} degC, power {P:.3f} W -> contacts at {Tn - 273.15:.3f} degC", flush=True))
    from hsbearing.lubricant import header_lines, oil_label

    print(f"case {case.name}: n = {case.operating.inner_speed * 30 / math.pi:.6g} r/min, {oil_label(case.lubricant)}, "
          f"oil flow {case.lubricant.oil_flow_rate * 6e4:.4g} L/min")
    print("\n".join(header_lines(case)))
    print("\n".join(thermal_lines(ds)))
    if out:
        write_netcdf(ds, out)
        print(f"archive: {out}")
    if ds.attrs["status"] == STATUS_NO_EQUILIBRIUM:
        print(f"hsbearing: {case.source}: {ds.attrs['error']}", file=sys.stderr)
    return 0 if ds.attrs["converged"] else 1
