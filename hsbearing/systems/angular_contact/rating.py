"""What a ball bearing costs, from a case: fatigue life (ISO 281, ISO/TS 16281) and quasi-static power loss.

:func:`life` -- ISO 281 basic rating life L_10 and modified life L_10m with the
dynamic equivalent load, and the ISO/TS 16281 reference life from the actual
quasi-static contact loads (with and without the ball inertia effects of speed).
The formulas are in :mod:`hsbearing.models.life` (pure, cited); this module only
reads the case and the quasi-static solution.  docs/life.md.

:func:`quasi_static_power_loss` -- power loss by source at the quasi-static state,
with the dynamic model's own contact functions (docs/life.md, "friction").
"""

from __future__ import annotations

import math

import numpy as np

from hsbearing.errors import CaseError
from hsbearing.models.friction import skf2004
from hsbearing.results import make_dataset, register, standard_attrs

__all__ = ["life", "life_lines", "quasi_static_power_loss", "friction_angular_contact", "life_cli"]

for _n, _d, _u, _l in [
    ("dynamic_load_rating", (), "N", "basic dynamic radial load rating C_r (ISO 281 5.1.1, or the case's catalogue value)"),
    ("static_load_rating", (), "N", "basic static radial load rating C_0r (ISO 76, or the case's catalogue value)"),
    ("equivalent_load", (), "N", "dynamic equivalent radial load P_r = X F_r + Y F_a (ISO 281 5.2)"),
    ("basic_rating_life", (), "1e6 rev", "ISO 281 basic rating life L_10 = (C_r/P_r)^3"),
    ("viscosity_ratio", (), "1", "ISO 281 viscosity ratio kappa = nu / nu_1"),
    ("fatigue_load_limit", (), "N", "fatigue load limit C_u ~ C_0/22 (ISO 281 Annex B)"),
    ("life_modification_factor", (), "1", "ISO 281 life modification factor a_ISO"),
    ("modified_rating_life", (), "1e6 rev", "ISO 281 modified rating life L_10m = a_ISO L_10"),
    ("reference_rating_life", (), "1e6 rev", "ISO/TS 16281 basic reference rating life L_10r from the quasi-static contact loads at speed"),
    ("reference_rating_life_static", (), "1e6 rev", "ISO/TS 16281 L_10r from the static contact loads (no centrifugal/gyroscopic effects)"),
    ("modified_reference_rating_life", (), "1e6 rev", "ISO/TS 16281 modified reference rating life a_ISO(P_ref) L_10r"),
    ("inner_raceway_rating", ("ball",), "N", "ISO/TS 16281 basic dynamic load rating of the inner raceway contact Q_ci at each ball's contact angle"),
    ("outer_raceway_rating", ("ball",), "N", "ISO/TS 16281 basic dynamic load rating of the outer raceway contact Q_ce at each ball's contact angle"),
]:
    register(_n, _d, _u, _l)


def rpm(w):
    return w * 60.0 / (2.0 * math.pi)


def _kinematic_viscosity(case):
    """Operating kinematic viscosity nu [m^2/s]: [lubricant] kinematic_viscosity, else eta(T) / density."""
    lub = case.lubricant
    if lub.kinematic_viscosity is not None:
        return lub.kinematic_viscosity, "lubricant.kinematic_viscosity"
    from hsbearing.models import ehl

    return ehl.lubricant_parameters(case)["eta"] / lub.density, "eta(T) of the oil / lubricant.density"


def life(case, *, quasistatic: bool = True):
    """ISO 281 and ISO/TS 16281 lives of a radial ball-bearing case (angular_contact, deep_groove).

    Returns a Dataset (scalars; per-ball raceway ratings) with the registered
    names above and attrs listing the inputs used (X, Y, e, nu, n) and any
    range notes (kappa outside 0.1..4 clipped).
    """
    from hsbearing.case import CaseError
    from hsbearing.case import as_case as _as_case
    from hsbearing.models import geometry
    from hsbearing.models import life as L

    case = _as_case(case)
    if case.system not in ("angular_contact", "deep_groove"):
        raise CaseError(case.source, "case.system", f"the ISO 281 / ISO/TS 16281 life is for radial ball bearings "
                        f"(angular_contact, deep_groove), not {case.system!r}")
    g = geometry.derive(case)
    b, op, lub = case.bearing, case.operating, case.lubricant
    alpha = 0.0 if case.system == "deep_groove" else g.alpha0
    notes = []
    C = b.dynamic_load_rating or L.basic_dynamic_load_rating(g.Z, g.D, g.dm, alpha)
    C0 = case.friction.static_load_rating or L.basic_static_load_rating(g.Z, g.D, g.dm, alpha)
    Fa, Fr = abs(op.axial_load), math.hypot(op.radial_load, op.radial_load_z)
    if Fa == 0 and Fr == 0:
        raise CaseError(case.source, "operating.axial_load", "the rating life needs a load (axial or radial)")
    try:
        X, Y, e = L.equivalent_load_factors(Fr, Fa, alpha, C0r=C0, Z=g.Z, Dw=g.D, Dpw=g.dm)
    except ValueError as exc:
        raise CaseError(case.source, "bearing.contact_angle", str(exc)) from None
    P = L.dynamic_equivalent_radial_load(Fr, Fa, X, Y)
    L10 = L.basic_rating_life(C, P)
    n_rel = abs(rpm(op.inner_speed - op.outer_speed))
    nu, nu_src = _kinematic_viscosity(case)
    kappa = L.viscosity_ratio(nu, n_rel, g.dm) if n_rel > 0 else float("nan")
    if math.isfinite(kappa) and not 0.1 <= kappa <= 4.0:
        notes.append(f"kappa = {kappa:.3g} outside ISO 281's 0.1..4: a_ISO evaluated at {min(max(kappa, 0.1), 4.0):g}")
    Cu = L.fatigue_load_limit(C0, g.dm)
    eC = lub.contamination_factor
    a_iso = L.life_modification_factor(kappa, eC, Cu, P) if math.isfinite(kappa) else float("nan")
    data = {
        "dynamic_load_rating": C, "static_load_rating": C0, "equivalent_load": P, "basic_rating_life": L10,
        "viscosity_ratio": kappa, "fatigue_load_limit": Cu, "life_modification_factor": a_iso,
        "modified_rating_life": L.modified_rating_life(L10, a_iso),
    }
    coords = {}
    warns = []
    if quasistatic:
        from hsbearing.systems.angular_contact import contact_state
        from hsbearing.systems.angular_contact import quasistatic as qs

        inner_rot = abs(op.inner_speed) >= abs(op.outer_speed)  # the load is fixed in space (shaft/housing loads)
        out = {}
        for key, inertia in (("reference_rating_life", True), ("reference_rating_life_static", False)):
            ds = qs.solve_case(case, centrifugal=inertia, gyroscopic=inertia)
            Qci, _ = L.raceway_contact_ratings(g.D, g.dm, ds["inner_contact_angle"].values, g.Z, g.fi, g.fo)
            _, Qce = L.raceway_contact_ratings(g.D, g.dm, ds["outer_contact_angle"].values, g.Z, g.fi, g.fo)
            out[key] = L.reference_rating_life(ds["inner_contact_load"].values, ds["outer_contact_load"].values,
                                               Qci, Qce, inner_rotating=inner_rot)
            if inertia:
                data["inner_raceway_rating"], data["outer_raceway_rating"] = Qci, Qce
                warns = contact_state.warnings_for(ds.assign(**{k: ("ball", v) for k, v in
                                                                contact_state.quasi_static_contact_state(case, ds).items()}), case)
        data.update(out)
        L10r = out["reference_rating_life"]
        P_ref = C * L10r ** (-1.0 / 3.0)  # the equivalent load that gives L_10r with the bearing's C_r
        a_ref = L.life_modification_factor(kappa, eC, Cu, P_ref) if math.isfinite(kappa) else float("nan")
        data["modified_reference_rating_life"] = a_ref * L10r
        coords = {"ball": np.arange(g.Z)}
    attrs = standard_attrs(
        case, "ok", title="hsbearing rating life (ISO 281:2007, ISO/TS 16281:2008)",
        load_factor_X=X, load_factor_Y=Y, load_factor_e=e, relative_speed_rpm=n_rel,
        kinematic_viscosity_mm2_s=nu * 1e6, kinematic_viscosity_source=nu_src, contamination_factor=eC,
        contact_angle_deg=math.degrees(alpha),
        dynamic_load_rating_source="bearing.dynamic_load_rating" if b.dynamic_load_rating else "ISO 281 5.1.1 from the geometry",
        static_load_rating_source="friction.static_load_rating" if case.friction.static_load_rating else "ISO 76 from the geometry",
        notes="; ".join(notes) or "none",
        warnings=" | ".join(warns) if warns else "none",
    )
    return make_dataset(data, coords=coords, attrs=attrs)


def life_lines(ds) -> list[str]:
    """Printed summary of :func:`life` (lives in million revolutions, :func:`hsbearing.display.format_life`, and hours at the case speed)."""
    from hsbearing.display import format_grouped, format_life

    n = float(ds.attrs.get("relative_speed_rpm", 0.0))

    def h(x):
        from hsbearing.models.life import life_in_hours

        return format_grouped(life_in_hours(float(x), n), "h") if n > 0 and math.isfinite(float(x)) else "n/a (no rotation)"

    def g(x, fmt: str, why: str = "no rotation: no lubricant film, kappa is not defined") -> str:
        x = float(x)
        return format(x, fmt) if math.isfinite(x) else f"n/a ({why})"

    def lf(x, why: str) -> str:
        x = float(x)
        return format_life(x) if math.isfinite(x) else f"n/a ({why})"

    a = ds.attrs
    lines = [
        f"rating life (ISO 281:2007; ISO/TS 16281:2008), n = {n:.6g} r/min:",
        f"  C_r = {float(ds.dynamic_load_rating) / 1e3:.4g} kN ({a['dynamic_load_rating_source']}), "
        f"C_0r = {float(ds.static_load_rating) / 1e3:.4g} kN ({a['static_load_rating_source']})",
        f"  P_r = X F_r + Y F_a = {float(ds.equivalent_load):.5g} N (X = {a['load_factor_X']:.3g}, Y = {a['load_factor_Y']:.3g}, "
        f"e = {a['load_factor_e']:.3g})",
        f"  L_10  = {format_life(ds.basic_rating_life)} = {h(ds.basic_rating_life)}",
        f"  kappa = {g(ds.viscosity_ratio, '.3g')} (nu = {a['kinematic_viscosity_mm2_s']:.3g} mm^2/s), e_C = {a['contamination_factor']:g}, "
        f"C_u = {float(ds.fatigue_load_limit):.4g} N, a_ISO = {g(ds.life_modification_factor, '.3g', 'needs kappa')}",
        f"  L_10m = {lf(ds.modified_rating_life, 'needs a_ISO')} = {h(ds.modified_rating_life)}",
    ]
    if "reference_rating_life" in ds:
        lines += [
            f"  ISO/TS 16281 L_10r from the quasi-static contact loads: {format_life(ds.reference_rating_life)} "
            f"= {h(ds.reference_rating_life)} (static loads, no ball inertia: {format_life(ds.reference_rating_life_static)})",
            f"  modified reference life a_ISO L_10r = {lf(ds.modified_reference_rating_life, 'needs a_ISO')} "
            f"= {h(ds.modified_reference_rating_life)}",
        ]
    if a.get("notes", "none") != "none":
        lines.append(f"  note: {a['notes']}")
    if a.get("warnings", "none") != "none":
        lines += [f"warning: {w}" for w in str(a["warnings"]).split(" | ")]
    return lines


def life_cli(args) -> int:
    """``hsbearing life CASE [--set k=v] [-o OUT.nc]``: ISO 281 and ISO/TS 16281 lives (radial ball bearings)."""
    from hsbearing.case import load_case, parse_sets
    from hsbearing.results import check_archive_name, write_netcdf

    case = load_case(args.case, **parse_sets(getattr(args, "set", None)))
    out = getattr(args, "output", None)
    check_archive_name(out)
    ds = life(case)
    from hsbearing.lubricant import header_lines, oil_label

    print(f"case {case.name}: Fa = {abs(case.operating.axial_load):g} N, Fr = "
          f"{math.hypot(case.operating.radial_load, case.operating.radial_load_z):g} N, {oil_label(case.lubricant)} at "
          f"{case.lubricant.temperature - 273.15:.4g} degC")
    for line in header_lines(case):
        print(line)
    print("\n".join(life_lines(ds)))
    if out:
        write_netcdf(ds, out)
        print(f"archive: {out}")
    return 0


def quasi_static_power_loss(case, speed=None, with_state: bool = False, walls: dict | None = None, bands: bool = True,
                            race_temperatures=None):
    """Power loss by source [W] at the quasi-static state, with the dynamic model's contact functions.

    The dynamic model is built from the case (:func:`hsbearing.systems.angular_contact.dynamics.build_model`); its
    initial state is the quasi-static equilibrium (race-control kinematics, all balls at the
    cage speed, cage centred in its land, balls centred in their pockets).  The compiled
    kernel's per-source dissipation (:mod:`hsbearing.systems.angular_contact.balances`) is evaluated at that one state:
    race traction (rolling and transverse slip, spin, from the traction law of the oil), EHL
    rolling couple, drag, and the guide-land film of the centred cage.  The pocket sources are
    zero there (no ball touches its pocket in the quasi-static state) and contact damping is
    zero (no approach rate).  Needs the dynamic model's data (outer-ring guided cage, land).

    The guide-land and pocket films are then taken at their film temperature and reported over a fill-fraction
    band (:func:`_film_corrections`, ``friction.thermal_films``); the EHL rolling loss over a starvation band
    (:func:`_starvation_band`).

    Parameters
    ----------
    case : Case.  speed : inner-ring speed [rad/s] (None: the case's).
    walls : body temperatures [K] of the film walls, keys ``inner_ring``, ``outer_ring``, ``balls``, ``cage`` (the
        thermal network's, ``hsbearing friction --thermal``); None: every wall at ``lubricant.temperature``.
    race_temperatures : (T_inner, T_outer) [K], the race contacts' inlet temperatures (traction, EHL rolling and the
        starvation band's films of each race at its own; ``build_model``); None: both at lubricant.temperature.
    bands : False for a caller that reads only the sources and totals (a quasi-static sweep point): the starvation
        band, the costly one (0.1-0.25 s), is not computed and no ``*_band_low``/``*_band_high`` key is returned
        (never half a set of bands).

    Returns
    -------
    dict source -> W, plus ``power_loss`` [W], ``drive_torque`` [N m] and ``friction_torque`` =
    power_loss / |omega_i - omega_o| [N m].
    """
    from hsbearing.systems.angular_contact.balances import SOURCES, power_variables
    from hsbearing.systems.angular_contact.dynamics import build_model

    if speed is not None:
        case = case.with_overrides(**{"operating.inner_speed": f"{float(speed)} rad/s"})
    m = build_model(case, race_temperatures=race_temperatures)
    aux, gaux = m.outputs(m.y0)
    pv = power_variables(aux[None], gaux[None])
    out = {s: float(pv[f"power_loss_{s}"][0]) for s in SOURCES}
    out["power_loss"] = float(pv["power_loss"][0])
    out["drive_torque"] = float(pv["drive_torque"][0])
    for key in ("cavity_oil_fraction", "drag_reynolds_number", "drag_coefficient"):  # the drag law's inputs (build_model)
        out[key] = float(m.info[key])
    _cavity_losses(case, m, out)
    _film_corrections(case, m, out, walls)
    if bands:
        _starvation_band(case, m, out, aux)
    else:
        for key in [k for k in out if k.endswith(("_band_low", "_band_high"))]:
            del out[key]
    w = abs(case.operating.inner_speed - case.operating.outer_speed)
    out["friction_torque"] = out["power_loss"] / w if w > 0 else float("nan")
    if with_state:  # the quasi-static Dataset the state comes from, the case at that speed, the race temperatures
        out["state"], out["case"], out["race_temperatures"] = m.info["quasistatic"], case, race_temperatures
    return out


#: the quasi-static sources outside the dynamic kernel (models/ball_bearing/churning.py), after balances.SOURCES
CAVITY_SOURCES = ("jet_oil_acceleration", "cage_windage")
for _s, _d in (("jet_oil_acceleration", "the acceleration of the jet's oil to the speed it leaves with (m_dot v^2)"),
               ("cage_windage", "the windage of the cage's side faces (rotating-disc estimate)")):
    register(f"power_loss_{_s}", (), "W", f"power dissipated by {_d} (quasi-static; not in the dynamic model)")


def _cavity_losses(case, m, out):
    """Mixture co-rotation, jet-oil acceleration, cage windage and the drag band at the quasi-static state (in place).

    ``friction.mixture_corotation`` k = 0 keeps the kernel's drag bit for bit; k > 0 replaces it by
    :func:`~hsbearing.models.ball_bearing.churning.ball_drag_power` at the velocity relative to the mixture (C_D at the
    relative Reynolds number).  ``friction.cavity_losses = "off"`` sets the two extra sources to 0.  The drag band
    (:func:`~hsbearing.models.ball_bearing.churning.drag_band`) is reported whatever the options.
    The dynamic kernel (hsbearing run) has none of these: its drag is that of k = 0 (docs/power_loss.md).
    """
    from hsbearing.models import geometry
    from hsbearing.models.ball_bearing import churning
    from hsbearing.models.ball_bearing.drag import ball_drag_coefficient

    g = geometry.derive(case)
    fr, lub, op = case.friction, case.lubricant, case.operating
    v = float(m.info["drag_orbital_speed"])
    rho_e, mu_e = float(m.info["drag_density"]), float(m.info["drag_viscosity"])
    gamma = g.D * math.cos(g.alpha0) / g.dm
    w_i, w_o = op.inner_speed, op.outer_speed
    k_c = churning.couette_corotation_fraction(gamma, w_i, w_o) if (w_i or w_o) else float("nan")
    kernel_drag, C_0 = out["drag"], out["drag_coefficient"]
    # the kernel's drag is at each ball's own orbital speed (ball centre slightly off the pitch circle): the ratio of
    # the kernel's drag to the law at the pitch-circle speed v carries that (1 + O(1e-3)) into every variant below
    P_0 = churning.ball_drag_power(v, 0.0, g.D, rho_e, C_0)[1] if (m.info["drag"] and rho_e > 0.0 and v != 0.0) else 0.0
    geo = kernel_drag / (g.Z * P_0) if P_0 > 0.0 else 1.0
    bal = _mixture_balance(case, m, g, v, rho_e, mu_e) if P_0 > 0.0 else None
    balance = fr.mixture_corotation_law == "balance" and bal is not None
    k = bal["nominal"]["k"] if balance else float(fr.mixture_corotation)
    out["drag_ring_share"] = 0.0
    if balance:  # the balls at the balance's swirl, plus the rings' surfaces driving the mixture (docs/power_loss.md)
        b = bal["nominal"]
        ring = b["P_inner"] + b["P_outer"]
        out["drag"] = geo * b["P_balls"] + ring
        out["drag_coefficient"], out["drag_reynolds_number"] = b["C_D"], rho_e * abs(v - b["u"]) * g.D / mu_e
        out["drag_mixture_share"], out["drag_ring_share"] = geo * (b["P_balls"] - b["P_wake"]), ring
    elif k > 0.0 and P_0 > 0.0:
        C_D, Re = ball_drag_coefficient(rho_e, mu_e, (1.0 - k) * v, g.D)
        if m.info["options"]["drag_coefficient"] is not None:
            C_D = float(m.info["options"]["drag_coefficient"])
        _, P, _, P_mix = churning.ball_drag_power(v, k * v, g.D, rho_e, C_D)  # mixture at k x the cage speed at each ball
        out["drag"], out["drag_coefficient"], out["drag_reynolds_number"] = geo * g.Z * P, C_D, Re
        out["drag_mixture_share"] = geo * g.Z * P_mix
    else:
        out["drag_mixture_share"] = 0.0
    jet = windage = 0.0
    out["mixture_balance_cage"] = bal["cage_note"] if bal else "no balance (cage at rest or no mixture)"
    if fr.cavity_losses == "on":
        # with the balance the supplied oil's acceleration is inside the drag (its throughflow term): not counted twice
        m_oil = _supplied_oil_mass_flow(lub)
        if m_oil > 0.0 and not balance:
            jet = churning.jet_oil_acceleration_power(m_oil, v)[0]
        c = case.cage
        w_c = 2.0 * v / g.dm  # the cage's angular velocity at the quasi-static state
        if balance and b["cage"]:  # the cage's surfaces are terms of the balance: their power is the cage windage
            windage = b["P_cage"]
        elif c.bore_diameter and c.outside_diameter and rho_e > 0.0:
            M = churning.rotating_annulus_windage_moment((1.0 - k) * w_c, 0.5 * c.bore_diameter, 0.5 * c.outside_diameter,
                                                         rho_e, mu_e)
            windage = -M * w_c  # the moment resists the cage's motion relative to the mixture; the cage moves at w_c
    out["jet_oil_acceleration"], out["cage_windage"] = jet, windage
    out["power_loss"] += out["drag"] - kernel_drag + jet + windage
    k_hi = k_c if math.isfinite(k_c) else 0.0
    band = churning.drag_band(g.Z, v, g.D, rho_e, mu_e, max(min(k_hi, 1.0), 0.0)) if P_0 > 0.0 else {"low": 0.0, "high": 0.0}
    out["drag_band_low"], out["drag_band_high"] = geo * band["low"], geo * band["high"]
    out["mixture_corotation_couette"] = k_c
    out["mixture_corotation"] = k
    nan = float("nan")
    out["mixture_corotation_balance"] = bal["nominal"]["k"] if bal else nan
    out["mixture_corotation_balance_low"] = bal["k_low"] if bal else nan
    out["mixture_corotation_balance_high"] = bal["k_high"] if bal else nan
    P_bal = [geo * c["P_balls"] + c["P_inner"] + c["P_outer"] for c in bal["corners"]] if bal else [0.0]
    out["drag_balance_band_low"], out["drag_balance_band_high"] = min(P_bal), max(P_bal)


def _supplied_oil_mass_flow(lub) -> float:
    """Mass flow [kg/s] of the oil supplied into the cavity: density x ``oil_flow_rate`` for a jet or air-oil supply
    with a flow rate, else 0 (the jet-oil acceleration term and the mixture balance's throughflow)."""
    if lub.oil_flow_rate is None or lub.lubrication not in ("oil_jet", "oil_air"):
        return 0.0
    return lub.density * lub.oil_flow_rate


def _mixture_balance(case, m, g, v, rho_e, mu_e):
    """The cavity mixture's angular-momentum balance at the quasi-static state
    (:func:`~hsbearing.models.ball_bearing.churning.mixture_momentum_balance`), nominal and over its band.

    Walls: the rings' lands (``bearing.inner_land_diameter`` / ``outer_land_diameter``; absent, the raceway contact
    radii r_m (1 -+ gamma)) over ``bearing.width`` (absent: the ball diameter).  Throughflow: the supplied oil,
    density x ``oil_flow_rate`` (jet or air-oil supply; else none), plus air from 0 (nominal) to the flow the inner
    ring's two side faces pump as free discs (the band's other end, with the side openings as stationary walls).
    Cage: its bore, outside surface and side faces turning at the cage speed (``cage.bore_diameter``,
    ``outside_diameter``, ``width``, ``guidance``: the guided surface is a film, not a wall of the mixture); without
    those keys the cage's surfaces are left out (``cage_note`` says which key is missing; nothing is invented).
    C_D: the drag law's (held subcritical, or the case's ``lubricant``-independent override) at the relative speed;
    the band also takes the sphere's crisis branch.  Returns None when the cage stands still or there is no mixture.
    Returns dict nominal (the balance's dict, = corners[0]), corners (the four balances: side openings off/on with
    the air throughflow 0 / its bound, each with C_D subcritical / crisis), k_low, k_high.
    """
    from hsbearing.models.ball_bearing import churning
    from hsbearing.models.ball_bearing import drag as drag_law

    op, b, lub = case.operating, case.bearing, case.lubricant
    r_m = 0.5 * g.dm
    w_c = v / r_m
    if w_c == 0.0 or rho_e <= 0.0:
        return None
    gamma = g.D * math.cos(g.alpha0) / g.dm
    r_i = 0.5 * b.inner_land_diameter if b.inner_land_diameter else r_m * (1.0 - gamma)
    r_o = 0.5 * b.outer_land_diameter if b.outer_land_diameter else r_m * (1.0 + gamma)
    if not r_i < r_m < r_o:
        r_i, r_o = r_m * (1.0 - gamma), r_m * (1.0 + gamma)
    length = b.width or g.D
    c = case.cage
    cage, missing = None, [k for k in ("bore_diameter", "outside_diameter", "width") if not getattr(c, k)]
    if missing:
        note = "cage surfaces left out: " + ", ".join(f"cage.{k}" for k in missing) + " not given"
    elif not r_i < 0.5 * c.bore_diameter < r_m < 0.5 * c.outside_diameter < r_o:
        note = "cage surfaces left out: the cage does not lie between the ring walls of the balance"
    else:
        cage = {"r_bore": 0.5 * c.bore_diameter, "r_outside": 0.5 * c.outside_diameter, "width": c.width,
                "guidance": c.guidance}
        faces = {"outer_ring": "bore", "inner_ring": "outside surface", "ball": "bore, outside surface"}[c.guidance]
        note = f"cage surfaces in the balance: {faces}" + (", side faces" if c.width < length else "")
    m_oil = _supplied_oil_mass_flow(lub)
    m_air = 2.0 * drag_law.AIR_DENSITY * churning.free_disc_pumped_flow(op.inner_speed, r_i,
                                                                        drag_law.AIR_VISCOSITY / drag_law.AIR_DENSITY)
    C_fixed = m.info["options"]["drag_coefficient"]

    def c_sub(w):
        return float(C_fixed) if C_fixed is not None else drag_law.ball_drag_coefficient(rho_e, mu_e, w, g.D)[0]

    def c_crisis(w):
        return float(C_fixed) if C_fixed is not None else drag_law.sphere_drag_coefficient(
            max(rho_e * w * g.D / mu_e, drag_law.RE_FLOOR))

    common = dict(Z=g.Z, D=g.D, r_m=r_m, r_i=r_i, r_o=r_o, length=length, omega_i=op.inner_speed,
                  omega_o=op.outer_speed, omega_c=w_c, rho_e=rho_e, mu_e=mu_e, cage=cage)
    corners = []
    for side, air in ((False, 0.0), (True, m_air)):
        for cd in (c_sub, c_crisis):
            corners.append(churning.mixture_momentum_balance(drag_coefficient=cd, mass_flow=m_oil + air,
                                                             side_walls=side, **common))
    ks = [c["k"] for c in corners]
    return {"nominal": {**corners[0], "cage": cage is not None}, "corners": corners, "k_low": min(ks), "k_high": max(ks),
            "cage_note": note}


def _film_corrections(case, m, out, walls=None):
    """Guide-land and pocket films at their film temperature, with the fill-fraction band (in place).

    The kernel's films are isothermal at the viscosity eta_film of ``lubricant.temperature`` and flooded; at the
    quasi-static state (cage and balls centred) their dissipation is linear in the film viscosity (checked in
    tests/systems/angular_contact/test_thermal_films.py), so the film at temperature is the kernel's power times
    eta_eff / eta_film, eta_eff from :func:`~hsbearing.models.ball_bearing.films.thermal_couette_film` (shear heat
    conducted into the two walls at ``walls``' temperatures).  ``friction.thermal_films = "off"``: the factor is 1
    (as before), the walls still reported.  The band: fill fraction from the cavity oil fraction X (low) to 1
    (high, the default value), :func:`~hsbearing.models.ball_bearing.films.fill_fraction_band`.
    """
    from hsbearing.models.ball_bearing import films

    low, high = films.fill_fraction_band(float(m.info["cavity_oil_fraction"]))
    from hsbearing.systems.angular_contact.cage_films import film_factors

    ff = film_factors(case, m, walls)
    for src, key in (("guide_land", "land"), ("pocket_film", "pocket")):
        iso, f = out[src], ff[key]["factor"]
        if math.isfinite(ff[key]["T_mean"]):  # no film (a ball-piloted cage has no land): no temperature keys
            out[f"{key}_film_temperature"], out[f"{key}_film_max_temperature"] = ff[key]["T_mean"], ff[key]["T_max"]
            out[f"{key}_film_speed"], out[f"{key}_film_wall_temperatures"] = ff[key]["speed"], ff[key]["walls"]
        out[f"{key}_film_factor"] = f
        out[src] = high * f * iso
        out["power_loss"] += out[src] - iso
        out[f"{src}_band_low"], out[f"{src}_band_high"] = low * f * iso, high * f * iso


def _starvation_band(case, m, out, aux):
    """EHL rolling loss and central films of the race contacts over the starvation band (in place).

    High end: flooded (the kernel's F_R, today's ``ehl_rolling``).  Low end: each race contact's inlet fed only by
    the cavity mixture at its oil fraction X (:func:`~hsbearing.models.ball_bearing.starvation.starvation_band`):
    that contact's kernel EHL rolling power times its rolling-force ratio, summed; the film ratio of the thinnest
    loaded contact of each race reported.  Contact inputs at the quasi-static state: load, Hertz semi-axes and the
    flooded Hamrock-Dowson central film of :func:`~hsbearing.systems.angular_contact.contact_state.quasi_static_contact_state`
    (with the inlet-heating factor when ``friction.inlet_heating = on``, as the kernel's F_R), R_x at the contact
    angle.  Nothing changes in the kernel or in ``power_loss``.
    """
    from hsbearing.models.ball_bearing import starvation
    from hsbearing.models.ball_bearing.kernel_io import AUX_INDEX
    from hsbearing.models.geometry import curvature_radii, derive
    from hsbearing.systems.angular_contact.contact_state import quasi_static_contact_state

    X = float(m.info["cavity_oil_fraction"])
    out["ehl_rolling_band_high"] = out["ehl_rolling"]
    low = low_inf = 0.0
    seen = []  # (Hbar, m, m*) of every loaded contact, for the investigation tools
    cache = {}
    qs = m.info["quasistatic"]
    # each race's films at its own contact inlet temperature (as the kernel's F_R; None: lubricant.temperature)
    st = quasi_static_contact_state(case, qs, race_temperatures=m.info.get("race_temperatures"))
    g = derive(case)
    for side, col in (("inner", "P_ehl_i"), ("outer", "P_ehl_o")):
        P = aux[:, AUX_INDEX[col]]
        Q = qs[f"{side}_contact_load"].values
        al = qs[f"{side}_contact_angle"].values
        Rxi, _, Rxo, _ = curvature_radii(g.D, g.dm, al, g.fi, g.fo)
        Rx = Rxi if side == "inner" else Rxo
        hc, a, p = (st.get(f"{side}_{k}") for k in ("film_thickness_central", "contact_semimajor", "contact_pressure"))
        worst = 1.0
        for j in range(len(P)):
            ok = hc is not None and Q[j] > 0.0 and np.isfinite(hc[j]) and hc[j] > 0.0 and math.isfinite(X)
            if not ok or P[j] == 0.0:
                low += P[j]
                low_inf += P[j]
                continue
            b = 1.5 * Q[j] / (math.pi * a[j] * p[j])  # p_max = 3 Q / (2 pi a b)
            key = (min(max(X, 0.0), 1.0), float(hc[j]), float(Rx[j]), b)
            if key not in cache:  # balls in the same state (a pure axial load) share one evaluation
                cache[key] = starvation.starvation_band(*key)
            band = cache[key]
            low += P[j] * band["force"]
            low_inf += P[j] * band["force_vs_infinite_inlet"]
            worst = min(worst, band["film"])
            seen.append((2.0 * float(hc[j]) * float(Rx[j]) / (b * b), band["m"], band["m_star"]))
        out[f"{side}_starved_film_ratio_low"] = worst
    out["ehl_rolling_band_low"] = low
    out["ehl_rolling_band_low_infinite_inlet"] = low_inf
    out["starvation_contacts"] = seen


# ----------------------------------------------------------------------------- hsbearing friction CASE (every ball bearing)

NOTE_QS = ("quasi-static model: (ours) power lost at the quasi-static state with the dynamic model's contact laws: race "
            "traction (rolling, transverse slip and spin, the oil's traction law), EHL rolling couple (with its inlet-shear-heating "
            "factor if friction.inlet_heating = on), the pocket film of the "
            "centred balls (entraining shear of the turning ball in its pocket), guide-land film of the centred cage (both "
            "films at their Couette film temperature, friction.thermal_films; flooded, the fill band reported; the race "
            "contacts flooded, a starvation band of the EHL rolling loss reported), ball "
            "drag in the air-oil mixture (cavity oil fraction above; relative to the mixture carried round at friction.mixture_corotation "
            "of the cage speed), the jet oil's acceleration to the cage pitch speed (m_dot v^2) and the cage-face windage "
            "(rotating-disc estimate; friction.cavity_losses); excludes pocket boundary friction and contact damping "
            "(zero at that state), the cage whirl, seals (none modelled) and the inner ring's shear of the mixture (except with "
            "friction.mixture_corotation_law = balance: the co-rotation from the mixture's angular-momentum balance, the drag then "
            "including the ring surface's power on the mixture and the supplied oil's acceleration)")
NOTE_SKF = ("SKF 2004 model: catalogue frictional moment M = M_rr + M_sl + M_seal + M_drag (SKF General Catalogue 6000 EN, "
             "'Friction'), an empirical fit for the bearing series at mu_EHL (friction.ehl_coefficient, default 0.05: the "
             "catalogue's mineral-oil value, 0.04 for synthetic oils); M_seal = 0 (open "
             "bearing), M_drag only for an oil bath (V_M from the catalogue diagram); independent of this package's traction law")

#: ours -> the SKF terms: which of our sources sit with which SKF term (docs/power_loss.md, "SKF 2004 side by side")
OURS_AS_SKF = {
    "rolling": ("ehl_rolling", "contact_damping"),
    "sliding": ("race_traction", "pocket_film", "pocket_boundary", "guide_land"),
    "drag": ("drag", "jet_oil_acceleration", "cage_windage"),
    "seal": (),
}

#: Surrogate of the SKF speed ratings for the validity warning [mm r/min].  Read (SKF, "The SKF model for calculating
#: the frictional moment", list of conditions at its start; scribd copy of the catalogue section): the model holds for
#: "constant speed, below the speed ratings" and a "bearing [that] does not exceed the limits of misalignment".  The
#: speed ratings are the per-bearing reference and limiting speeds of the product tables, which could not be read
#: here, and a case carries none: n d_m above 1e6 is flagged as a stand-in (ASSUMED, not from the tables; single-row
#: angular contact ball bearings are rated at a few 1e5 to ~1e6 mm r/min with oil).  The warning says so.
SKF_NDM_LIMIT = 1.0e6


def skf_validity_warnings(case, n_rpm) -> list[str]:
    """Where the SKF 2004 model is used outside its stated range (speed / n d_m, lubrication, oil)."""
    out = []
    dm_mm = case.bearing.pitch_diameter * 1e3
    ndm = float(np.max(np.abs(n_rpm))) * dm_mm
    if ndm > SKF_NDM_LIMIT:
        out.append(f"SKF 2004 model likely outside its range: n d_m = {ndm:.3g} mm r/min above {SKF_NDM_LIMIT:.0e} (the "
                   "model is stated for 'constant speed, below the speed ratings' -- SKF, 'The SKF model for calculating "
                   "the frictional moment'; the bearing's own reference/limiting speeds are not in the case, the 1e6 "
                   "stand-in is assumed); its G_rr, G_sl were not fitted there: order of magnitude only")
    lub = case.lubricant.lubrication
    if lub not in ("oil_jet", "oil_bath", "oil_air", "grease"):
        out.append(f"SKF 2004 model outside its range: lubrication = {lub} (the model is for grease, oil bath, oil-air "
                   "or oil jet lubrication)")
    return out


#: Ball Reynolds number above which the drag warning is given: from 2e5 a smooth sphere's C_D (standard drag
#: curve, models/ball_bearing/drag.py [4]) enters its crisis, and free-stream turbulence moves the crisis lower.
DRAG_CRISIS_RE = 2.0e5


def _register_qs_power():
    register("speed", ("speed",), "rad/s", "inner-ring rotational speed n")  # as hsbearing friction of a deep-groove case
    from hsbearing.systems.angular_contact.balances import SOURCES

    register("qs_power_loss", ("speed",), "W", "power loss at the quasi-static state, sum of the qs_power_loss_<source>")
    register("qs_friction_torque", ("speed",), "N*m", "friction torque of the quasi-static power loss, qs_power_loss / |omega_i - omega_o|")
    register("cavity_oil_fraction", ("speed",), "1", "oil volume fraction of the air-oil mixture the ball drag uses "
             "(lubricant.oil_volume_fraction, or Parker's correlation from lubricant.oil_flow_rate)")
    register("drag_reynolds_number", ("speed",), "1", "Reynolds number of the ball in the air-oil mixture, "
             "rho_e v D / mu_e at the cage orbital speed of the quasi-static state")
    register("drag_coefficient", ("speed",), "1", "drag coefficient C_D of the ball drag: the smooth sphere's standard "
             "drag curve (Clift, Grace & Weber 1978, Table 5.2) at drag_reynolds_number")
    for term in ("rolling", "sliding", "drag", "seal"):
        register(f"qs_power_as_skf_{term}", ("speed",), "W", f"our quasi-static power loss grouped as the SKF "
                 f"{term} term (rating.OURS_AS_SKF)")
        register(f"skf_power_{term}", ("speed",), "W", f"SKF 2004 {term} term of the frictional moment x speed")
    for s in SOURCES:
        register(f"qs_power_loss_{s}", ("speed",), "W", f"power loss at the quasi-static state by source {s} (hsbearing.systems.angular_contact.balances.SOURCES)")
    register("qs_power_loss_jet_oil_acceleration", ("speed",), "W", "power to accelerate the supplied jet oil from rest to the "
             "cage pitch speed v, m_dot v^2 (momentum conservation; models/ball_bearing/churning.py); 0 without "
             "lubricant.oil_flow_rate or with friction.cavity_losses = off")
    register("qs_power_loss_cage_windage", ("speed",), "W", "windage of the two cage side faces turning relative to the "
             "cavity mixture, free rotating-disc estimate (von Karman; models/ball_bearing/churning.py)")
    register("qs_drag_mixture_share", ("speed",), "W", "part of qs_power_loss_drag spent driving the co-rotating mixture "
             "(F u summed over the balls; 0 for friction.mixture_corotation = 0)")
    register("qs_drag_band_low", ("speed",), "W", "lowest ball drag over the unsettled choices: mixture co-rotation 0 or "
             "the Couette estimate, C_D held subcritical or with the sphere's drag crisis (docs/power_loss.md)")
    register("qs_drag_band_high", ("speed",), "W", "highest ball drag over the same choices as qs_drag_band_low")
    register("mixture_corotation", ("speed",), "1", "fraction of the cage orbital speed at which the cavity mixture is "
             "carried round in the quasi-static drag (friction.mixture_corotation)")
    register("mixture_corotation_balance", ("speed",), "1", "mixture co-rotation from the cavity mixture's "
             "angular-momentum balance (ball drag, ring walls, oil throughflow; models/ball_bearing/churning.py "
             "mixture_momentum_balance): the value friction.mixture_corotation_law = balance uses")
    register("mixture_corotation_balance_low", ("speed",), "1", "lowest co-rotation of the balance over its unsettled "
             "inputs (side openings as stationary walls or not, air throughflow 0 or the inner ring's free-disc pumping, "
             "C_D subcritical or with the crisis)")
    register("mixture_corotation_balance_high", ("speed",), "1", "highest co-rotation of the balance over the same inputs")
    register("qs_drag_balance_band_low", ("speed",), "W", "lowest churning power of the balance over its unsettled inputs: "
             "the balls' drag power at the balance's swirl plus the rotating ring surface's power on the mixture")
    register("qs_drag_balance_band_high", ("speed",), "W", "highest churning power of the balance over the same inputs")
    register("qs_drag_ring_share", ("speed",), "W", "part of qs_power_loss_drag that the rotating ring's surfaces spend "
             "on the cavity mixture (friction.mixture_corotation_law = balance; 0 otherwise)")
    register("mixture_corotation_couette", ("speed",), "1", "upper estimate of the mixture co-rotation: circular Couette "
             "flow between the raceways at the pitch radius over the cage's pure-rolling speed")
    for key, what in (("land", "guide-land film (cage on its guiding ring)"), ("pocket", "pocket films (ball in its pocket)")):
        register(f"{key}_film_temperature", ("speed",), "K", f"mean temperature of the {what}: Couette shear heat conducted "
                 "into the two walls (models/ball_bearing/films.py; nan without the film)")
        register(f"{key}_film_max_temperature", ("speed",), "K", f"largest temperature across the {what}")
        register(f"{key}_film_viscosity_factor", ("speed",), "1", f"viscosity of the {what} at its film temperature over "
                 "the isothermal one at lubricant.temperature (1 with friction.thermal_films = off)")
        register(f"{key}_film_wall_temperature_a", ("speed",), "K", f"temperature of the first wall of the {what} (land: "
                 "cage; pocket: ball)")
        register(f"{key}_film_wall_temperature_b", ("speed",), "K", f"temperature of the second wall of the {what} (land: "
                 "guiding ring; pocket: cage)")
    for src in ("guide_land", "pocket_film"):
        register(f"qs_{src}_band_low", ("speed",), "W", f"qs_power_loss_{src} with the film part-filled at the "
                 "cavity oil fraction (low end of the fill band; docs/power_loss.md)")
        register(f"qs_{src}_band_high", ("speed",), "W", f"qs_power_loss_{src} with the film flooded (high end "
                 "of the fill band = qs_power_loss_{src})")
    register("qs_ehl_rolling_band_low", ("speed",), "W", "qs_power_loss_ehl_rolling with every race contact's inlet "
             "fed only by the cavity mixture at the cavity oil fraction (low end of the starvation band: Hamrock-Dowson "
             "meniscus, Grubin inlet rolling-force ratio; models/ball_bearing/starvation.py, docs/power_loss.md)")
    register("qs_ehl_rolling_band_high", ("speed",), "W", "qs_power_loss_ehl_rolling with flooded race contacts (high "
             "end of the starvation band = qs_power_loss_ehl_rolling)")
    for side in ("inner", "outer"):
        register(f"{side}_starved_film_ratio_low", ("speed",), "1", f"central film of the thinnest loaded {side} race "
                 "contact at the low end of the starvation band over its flooded film (Hamrock-Dowson starved film; "
                 "1 at the high end)")
    register("qs_total_band_low", ("speed",), "W", "qs_power_loss with the drag at its band's low end, the land and "
             "pocket films at their fill band's low end and the EHL rolling loss at its starvation band's low end")
    register("qs_total_band_high", ("speed",), "W", "qs_power_loss with the drag at its band's high end, the land "
             "and pocket films at their fill band's high end and the EHL rolling loss flooded (its band's high end)")


_register_qs_power()
for _row in skf2004.OUTPUTS:  # the skf_* variables of friction_angular_contact
    register(*_row)


def require_angular_contact(case, what: str, *, source: str | None = None, key: str = "case.system") -> None:
    """CaseError (naming ``source`` -- the case file by default -- and ``key``) unless the case is an angular-contact
    bearing: for what only this system's engine does (``what`` says what was asked), so that the front ends need
    not compare system names."""
    if case.system != "angular_contact":
        raise CaseError(source or case.source, key, f"{what} (got a {case.system} case)")


def _thermal_row(case, w):
    """``hsbearing friction --thermal`` at inner-ring speed w [rad/s]: the thermal equilibrium of the case at w, then
    the quasi-static power loss with its temperatures at the contacts: each race's contacts (traction, EHL rolling,
    film viscosity) at its own inlet temperature, (T_ir + T_b)/2 inner and (T_or + T_b)/2 outer
    (:func:`race_inlet_temperatures`), the quasi-static state, drag, jet and windage at the network's lubricant
    temperature (T_ir + T_or + 2 T_b)/4, and the guide-land and pocket films between their walls'
    node temperatures (cage / guiding ring; ball / cage).  The network's fixed point evaluated its heat by the same
    rule (``thermal_equilibrium``, race_rule ``per_race``), so these losses are the heat it balanced, to the fixed
    point's tolerance.  A CaseError naming lubricant.oil_flow_rate if the network has no steady state at w."""
    from hsbearing.systems.angular_contact.thermal import thermal_equilibrium, wall_temperatures

    cw = case.with_overrides(**{"operating.inner_speed": f"{float(w)} rad/s"})
    th = thermal_equilibrium(cw)
    if th.attrs["status"] != "ok":
        raise CaseError(case.source, "lubricant.oil_flow_rate", th.attrs.get("error") or
                        f"the thermal fixed point did not converge at {rpm(w):.6g} r/min in "
                        f"{int(th.fixed_point_iterations)} iterations (thermal.max_iterations, thermal.tolerance)")
    T = wall_temperatures(th)
    T_lub = float(th.lubricant_temperature)
    T_i, T_o = race_inlet_temperatures(T["inner_ring"], T["outer_ring"], T["balls"])
    r = quasi_static_power_loss(cw.with_overrides(**{"lubricant.temperature": f"{T_lub} K"}), None, with_state=True,
                                walls=T, race_temperatures=(T_i, T_o))
    r["thermal"] = dict(T, oil=float(th.oil_outlet_temperature), contact=0.5 * (T_i + T_o), inner_contact=T_i,
                        outer_contact=T_o, lubricant=T_lub, iterations=float(th.fixed_point_iterations))
    return r


def race_inlet_temperatures(T_inner_ring: float, T_outer_ring: float, T_balls: float) -> tuple[float, float]:
    """Contact inlet temperatures [K] of the inner and outer race contacts from the bearing's surface temperatures:
    the oil drawn into a ball/race contact lies between the two surfaces that meet there and takes their mean,
    T_in,i = (T_ir + T_b)/2 and T_in,o = (T_or + T_b)/2 -- this package's rule (an assumption, docs/power_loss.md
    "Temperatures at the contacts"): an isothermal inlet at the mean of its two walls, as the guide-land and pocket
    films take their walls (cage_films).  Their mean is the network's (T_ir + T_or + 2 T_b)/4."""
    return 0.5 * (T_inner_ring + T_balls), 0.5 * (T_outer_ring + T_balls)


THERMAL_RULE = ("hsbearing friction --thermal: per speed, the thermal network's equilibrium (hsbearing thermal); each "
                "race's contacts (traction, EHL rolling, EHL film) at their own inlet temperature, the inlet oil between "
                "the ball and that race's surface: inner_contact_inlet_temperature = (T_inner_ring + T_balls)/2, "
                "outer_contact_inlet_temperature = (T_outer_ring + T_balls)/2 (contact_inlet_temperature is their mean); "
                "guide-land film between thermal_cage_temperature and the guiding ring's node temperature, pocket films "
                "between thermal_ball_temperature and thermal_cage_temperature (friction.thermal_films); the quasi-static "
                "state, drag, jet and windage with the oil at the network's lubricant temperature, which is "
                "contact_inlet_temperature = (T_inner_ring + T_outer_ring + 2 T_balls)/4 to the fixed point's tolerance")
for _n, _l in (("contact_inlet_temperature", "mean of inner_contact_inlet_temperature and "
                "outer_contact_inlet_temperature with --thermal, (T_ir + T_or + 2 T_b)/4 (kept for compatibility: the "
                "race contacts use their own race's value); the quasi-static state, drag, jet and windage use the "
                "network's lubricant temperature, equal to it to the fixed point's tolerance"),
               ("inner_contact_inlet_temperature", "inlet temperature of the inner race contacts (traction, EHL rolling, "
                "film viscosity) with --thermal: (T_ir + T_b)/2 of the thermal network"),
               ("outer_contact_inlet_temperature", "inlet temperature of the outer race contacts (traction, EHL rolling, "
                "film viscosity) with --thermal: (T_or + T_b)/2 of the thermal network"),
               ("thermal_inner_ring_temperature", "inner ring node temperature of the thermal network (--thermal)"),
               ("thermal_outer_ring_temperature", "outer ring node temperature of the thermal network (--thermal)"),
               ("thermal_ball_temperature", "ball node temperature of the thermal network (--thermal)"),
               ("thermal_cage_temperature", "cage node temperature of the thermal network (--thermal)"),
               ("thermal_oil_outlet_temperature", "oil outlet temperature of the thermal network (--thermal)")):
    register(_n, ("speed",), "K", _l)


def friction_angular_contact(case, speeds, *, thermal: bool = False):
    """Quasi-static power loss by source and the SKF 2004 angular-contact moments over inner-ring speeds [rad/s].

    ``speeds``: SI floats [rad/s], unit strings (``"10000 rpm"``, ``"500,5000rpm"``), lists of them, or pint
    Quantities (:func:`hsbearing.units.parse_speeds`).  ``thermal``: the temperatures of the thermal network at each
    speed reach the contacts (:func:`_thermal_row`, :data:`THERMAL_RULE`; needs lubricant.oil_flow_rate); the
    temperatures used are variables of the Dataset.

    Returns a Dataset over ``speed`` (qs_power_loss_<source>, qs_power_loss [W],
    qs_friction_torque, skf_* [N m]).
    """
    from hsbearing.systems.angular_contact.balances import SOURCES
    from hsbearing.units import parse_speeds

    if hasattr(speeds, "to") and hasattr(speeds, "magnitude"):  # a pint Quantity (scalar or array)
        speeds = [f"{float(v)} {speeds.units:~}" for v in np.atleast_1d(speeds.magnitude)]
    w = parse_speeds(speeds, source="speeds") if not isinstance(speeds, np.ndarray) else np.asarray(speeds, dtype=float)
    if thermal:
        from hsbearing.systems.angular_contact.thermal import check_inputs

        check_inputs(case)
        rows = [_thermal_row(case, wi) for wi in w]
    else:
        rows = [quasi_static_power_loss(case, wi, with_state=True) for wi in w]
    from hsbearing.systems.angular_contact import contact_state

    warns = []
    for r in rows:
        q = r.pop("state")
        cs = contact_state.quasi_static_contact_state(r.pop("case"), q, race_temperatures=r.pop("race_temperatures"))
        for x in contact_state.warnings_for(q.assign(**{k: ("ball", v) for k, v in cs.items()}), case):
            if x not in warns:
                warns.append(x)
    data = {f"qs_power_loss_{s}": np.array([r[s] for r in rows]) for s in tuple(SOURCES) + CAVITY_SOURCES}
    for key, name in (("drag_mixture_share", "qs_drag_mixture_share"), ("drag_band_low", "qs_drag_band_low"),
                      ("drag_band_high", "qs_drag_band_high"), ("mixture_corotation", "mixture_corotation"),
                      ("mixture_corotation_couette", "mixture_corotation_couette"),
                      ("mixture_corotation_balance", "mixture_corotation_balance"),
                      ("mixture_corotation_balance_low", "mixture_corotation_balance_low"),
                      ("mixture_corotation_balance_high", "mixture_corotation_balance_high"),
                      ("drag_balance_band_low", "qs_drag_balance_band_low"),
                      ("drag_balance_band_high", "qs_drag_balance_band_high"), ("drag_ring_share", "qs_drag_ring_share")):
        data[name] = np.array([r[key] for r in rows])
    data["qs_power_loss"] = np.array([r["power_loss"] for r in rows])
    if thermal:
        for name, key in (("contact_inlet_temperature", "contact"), ("inner_contact_inlet_temperature", "inner_contact"),
                          ("outer_contact_inlet_temperature", "outer_contact"), ("thermal_inner_ring_temperature", "inner_ring"),
                          ("thermal_outer_ring_temperature", "outer_ring"), ("thermal_ball_temperature", "balls"),
                          ("thermal_cage_temperature", "cage"), ("thermal_oil_outlet_temperature", "oil")):
            data[name] = np.array([r["thermal"][key] for r in rows])
    for key in ("land", "pocket"):
        nan = float("nan")  # nan where the bearing has no such film (ball-piloted cage: no land)
        data[f"{key}_film_temperature"] = np.array([r.get(f"{key}_film_temperature", nan) for r in rows])
        data[f"{key}_film_max_temperature"] = np.array([r.get(f"{key}_film_max_temperature", nan) for r in rows])
        data[f"{key}_film_viscosity_factor"] = np.array([r[f"{key}_film_factor"] for r in rows])
        data[f"{key}_film_wall_temperature_a"] = np.array([r.get(f"{key}_film_wall_temperatures", (nan, nan))[0] for r in rows])
        data[f"{key}_film_wall_temperature_b"] = np.array([r.get(f"{key}_film_wall_temperatures", (nan, nan))[1] for r in rows])
    for src in ("guide_land", "pocket_film", "ehl_rolling"):
        for end in ("low", "high"):
            data[f"qs_{src}_band_{end}"] = np.array([r[f"{src}_band_{end}"] for r in rows])
    for side in ("inner", "outer"):
        data[f"{side}_starved_film_ratio_low"] = np.array([r[f"{side}_starved_film_ratio_low"] for r in rows])
    for end in ("low", "high"):
        data[f"qs_total_band_{end}"] = np.array([
            r["power_loss"] - r["drag"] + r[f"drag_band_{end}"]
            - r["guide_land"] - r["pocket_film"] + r[f"guide_land_band_{end}"] + r[f"pocket_film_band_{end}"]
            - r["ehl_rolling"] + r[f"ehl_rolling_band_{end}"] for r in rows])
    data["qs_friction_torque"] = np.array([r["friction_torque"] for r in rows])
    data.update(skf2004.skf_moments(case, w))
    for term, srcs in OURS_AS_SKF.items():
        data[f"qs_power_as_skf_{term}"] = sum((data[f"qs_power_loss_{x}"] for x in srcs), np.zeros(len(w)))
    wa = np.abs(w)
    data["skf_power_rolling"] = data["skf_rolling_torque"] * wa
    data["skf_power_sliding"] = data["skf_sliding_torque"] * wa
    data["skf_power_drag"] = data["skf_drag_torque"] * wa
    data["skf_power_seal"] = np.zeros(len(w))  # open bearing: no seal moment
    from hsbearing.models.ball_bearing import drag as drag_model

    lub = case.lubricant
    # the drag law's inputs as the model used them (dynamics.build_model: one law for run and friction)
    for key in ("cavity_oil_fraction", "drag_reynolds_number", "drag_coefficient"):
        data[key] = np.array([r[key] for r in rows])
    xsrc = drag_model.cavity_oil_fraction(lub.oil_volume_fraction, lub.oil_flow_rate, w[0] if len(w) else 0.0,
                                          case.bearing.pitch_diameter, lub.lubrication)[1]
    warns += [x for x in skf_validity_warnings(case, wa * 30.0 / math.pi) if x not in warns]
    Re_max = float(np.max(data["drag_reynolds_number"])) if len(w) else 0.0
    if Re_max > DRAG_CRISIS_RE:
        warns.append(f"ball Reynolds number up to {Re_max:.3g} in the air-oil mixture: near or past the drag crisis of a "
                     f"smooth sphere; C_D is held at its subcritical value ({float(np.min(data['drag_coefficient'])):.2g}, "
                     "no crisis applied); if the cavity flow does reach a crisis the drag there is up to ~5x lower "
                     "(docs/power_loss.md)")
    attrs = standard_attrs(case, "ok", title="hsbearing friction: quasi-static power loss by source, SKF 2004 model",
                           note_quasi_static=NOTE_QS, note_skf=NOTE_SKF, cavity_oil_fraction_source=xsrc,
                           contact_temperatures=THERMAL_RULE if thermal else
                           "lubricant.temperature at every contact and film wall (no --thermal)",
                           warnings=" | ".join(warns) if warns else "none",
                           mixture_balance_cage=" | ".join(dict.fromkeys(r["mixture_balance_cage"] for r in rows)))
    return make_dataset(data, coords={"speed": w}, attrs=attrs)
