"""Contact state of every ball/raceway contact over a run, and the warnings a bearing engineer expects.

:func:`contact_state_variables` derives, from the stored trajectory quantities
(contact loads Q, contact angles alpha, entrainment speeds U per ball and time),
the maximum Hertz pressure, the contact-ellipse semi-major axis, the
Hamrock-Dowson central and minimum film thickness and the film parameter lambda
of the inner and outer contacts.  It runs in the dataset assembly
(:func:`hsbearing.systems.angular_contact.dynamics.to_dataset`), not in the compiled kernel.

:func:`warnings_for` lists, for a run or quasi-static Dataset, the limits a
result crosses: p_max above ISO 76's 4.2 GPa, lambda < 1, a contact ellipse
truncated by the groove shoulder, a cage whose orbit reaches its guide clearance.
They are printed and stored as the global attribute ``warnings`` (docs/life.md).
"""

from __future__ import annotations

import math

import numpy as np

from hsbearing.results import register

__all__ = ["contact_state_variables", "quasi_static_contact_state", "spin_to_roll_relative", "warnings_for", "format_warnings", "NAMES"]

for _n, _l in [
    ("inner_film_thickness_minimum", "Hamrock-Dowson minimum film thickness at the inner contact h_min,i"),
    ("outer_film_thickness_minimum", "Hamrock-Dowson minimum film thickness at the outer contact h_min,o"),
]:
    register(_n, ("time", "ball"), "m", _l)
for _n, _l in [
    ("inner_film_parameter", "film parameter lambda_i = h_min,i / composite rms roughness at the inner contact"),
    ("outer_film_parameter", "film parameter lambda_o = h_min,o / composite rms roughness at the outer contact"),
]:
    register(_n, ("time", "ball"), "1", _l)

#: the per-contact variables this module adds to a run (besides the spin-to-roll ratios the kernel gives)
NAMES = ("inner_contact_pressure", "outer_contact_pressure", "inner_contact_semimajor", "outer_contact_semimajor",
         "inner_film_thickness_central", "outer_film_thickness_central", "inner_film_thickness_minimum",
         "outer_film_thickness_minimum", "inner_film_parameter", "outer_film_parameter")


def _unit_load_axes(Rx, Ry, E1, nu1, E2, nu2):
    """Semi-axes at Q = 1 N (a_1, b_1) [m/N^(1/3)] of the exact Hertz solution; a = a_1 Q^(1/3)."""
    from hsbearing.models.hertz import point_contact

    c = point_contact(Rx, Ry, 1.0, E1, nu1, E2, nu2)
    return np.asarray(c.a), np.asarray(c.b)


def contact_state_variables(case, Qi, Qo, ai, ao, Ui, Uo, race_temperatures=None) -> dict:
    """Per-contact Hertz and EHL state from loads [N], contact angles [rad] and entrainment speeds [m/s].

    Arrays of any common shape (time, ball).  Hertz: exact elliptic solution
    (hsbearing.models.hertz) at each sample's own contact angle, through
    a = a_1(alpha) Q^(1/3), b = b_1(alpha) Q^(1/3) with a_1, b_1 tabulated on 65
    angles over the range the run visits (interpolation error < 1e-5, the
    semi-axes vary smoothly with Rx(alpha)); p_max = 1.5 Q / (pi a b).  Film:
    :func:`hsbearing.models.ehl.film_thickness` (Hamrock-Dowson, radius Rx; isothermal, or with
    ``friction.inlet_heating = "on"`` times the inlet-shear-heating factor phi_T of each contact -- the same factor
    and inputs as the kernel's EHL rolling force, at the centre slide-roll ratio 0: the slip is not an input here).  lambda with the composite roughness of
    ``materials.ball.surface_roughness`` and ``materials.races.surface_roughness``.
    Unloaded contacts: p = 0, film and lambda NaN.  ``race_temperatures`` (T_inner, T_outer) [K]: each race's film
    with the oil at its own contact inlet temperature (as the kernel's ``build_model(race_temperatures=...)``);
    None: both at lubricant.temperature.
    """
    from hsbearing.models import ehl, hertz
    from hsbearing.models.geometry import curvature_radii, derive
    from hsbearing.models.limits import composite_roughness, film_parameter

    g = derive(case)
    mb, mr = case.materials.ball, case.materials.races
    Ep = float(hertz.reduced_modulus(mb.elastic_modulus, mb.poisson_ratio, mr.elastic_modulus, mr.poisson_ratio))
    def oil(c):
        try:
            return ehl.lubricant_parameters(c)
        except (KeyError, AttributeError):
            return None

    lp = oil(case)
    sigma = float(composite_roughness(mb.surface_roughness, mr.surface_roughness))
    out = {}
    case0 = case
    for side, Q, al, U in (("inner", Qi, ai, Ui), ("outer", Qo, ao, Uo)):
        if race_temperatures is not None:  # this race's oil at its own contact inlet temperature
            T_side = float(race_temperatures[0] if side == "inner" else race_temperatures[1])
            case = case0.with_overrides(**{"lubricant.temperature": f"{T_side!r} K"})
            lp = oil(case)
        Q = np.asarray(Q, dtype=float)
        al = np.asarray(al, dtype=float)
        U = np.abs(np.asarray(U, dtype=float))
        lo, hi = float(np.nanmin(np.abs(al))), float(np.nanmax(np.abs(al)))
        grid = np.linspace(lo, max(hi, lo + 1e-6), 65)
        Rxi, Ryi, Rxo, Ryo = curvature_radii(g.D, g.dm, grid, g.fi, g.fo)
        Rx_g, Ry_g = (Rxi, Ryi) if side == "inner" else (Rxo, Ryo)
        a1, b1 = _unit_load_axes(Rx_g, np.broadcast_to(Ry_g, grid.shape), mb.elastic_modulus, mb.poisson_ratio,
                                 mr.elastic_modulus, mr.poisson_ratio)
        aa = np.abs(al)
        Qp = np.clip(Q, 0.0, None)
        a = np.interp(aa, grid, a1) * Qp ** (1.0 / 3.0)
        b = np.interp(aa, grid, b1) * Qp ** (1.0 / 3.0)
        with np.errstate(invalid="ignore", divide="ignore"):
            p = np.where(Qp > 0, 1.5 * Qp / (np.pi * a * b), 0.0)  # Hamrock & Dowson 1981, Eq. 3.36
        out[f"{side}_contact_pressure"] = p
        out[f"{side}_contact_semimajor"] = a
        if lp is not None:
            Rx = np.interp(aa, grid, Rx_g)
            Ry = float(np.broadcast_to(Ry_g, grid.shape)[0])
            ok = (Qp > 0) & (U > 0)
            hc = np.full(Q.shape, np.nan)
            hm = np.full(Q.shape, np.nan)
            if np.any(ok):
                th = {}
                if getattr(case.friction, "inlet_heating", "off") == "on":
                    from hsbearing.systems.angular_contact.oil_properties import inlet_beta as _inlet_beta
                    from hsbearing.systems.angular_contact.oil_properties import oil_conductivity as _oil_conductivity

                    th = dict(thermal=True, beta=_inlet_beta(case), K=_oil_conductivity(case), p_max=p[ok])
                hc[ok], hm[ok] = ehl.film_thickness(Qp[ok], U[ok], Rx[ok], Ry, Ep, lp["eta"], lp["alpha"], **th)
            out[f"{side}_film_thickness_central"] = hc
            out[f"{side}_film_thickness_minimum"] = hm
            out[f"{side}_film_parameter"] = film_parameter(hm, sigma)
    return out


def quasi_static_contact_state(case, qs, race_temperatures=None) -> dict:
    """:func:`contact_state_variables` of a quasi-static Dataset (its loads, angles, orbit speeds; entrainment
    speed |omega_race - omega_m| (r_b -/+ (D/2) cos alpha) as the quasi-static solver's film); ``race_temperatures``
    as there."""
    from hsbearing.models.geometry import derive

    D = derive(case).D
    wm, rb = qs["ball_orbit_speed"].values, qs["ball_center_radial"].values
    ai, ao = qs["inner_contact_angle"].values, qs["outer_contact_angle"].values
    ui = np.abs(case.operating.inner_speed - wm) * (rb - 0.5 * D * np.cos(ai))
    uo = np.abs(case.operating.outer_speed - wm) * (rb + 0.5 * D * np.cos(ao))
    return contact_state_variables(case, qs["inner_contact_load"].values, qs["outer_contact_load"].values, ai, ao, ui, uo,
                                   race_temperatures=race_temperatures)


def spin_to_roll_relative(ratio_entrainment, alpha, D, r_b, side: str, roll_sign=1.0):
    """Spin-to-roll ratio with the roll rate of the ball relative to the race [-], from the kernel's ratio.

    The kernel gives omega_s (D/2) / U (U the entrainment speed).  The roll rate of the ball relative to the race
    (the quasi-static dataset's denominator, Harris & Kotzalas Vol. 2, Eqs. 8.44-8.45) is
    (2U/D) / (1 - gamma) at the inner race and (2U/D) / (1 + gamma) at the outer, gamma = D cos(alpha) / (2 r_b),
    r_b the ball-centre orbit radius [m]: the race's own rotation adds U cos(alpha) / r_contact.  So the ratio is
    the kernel's times (1 - gamma) (inner) or (1 + gamma) (outer).  The kernel divides by |U|; ``roll_sign``
    (sign of the race speed relative to the ball orbit, omega_race - omega_m) restores a ratio that does not
    change sign with the sense of rotation, as the quasi-static one.
    """
    gam = D * np.cos(np.asarray(alpha, dtype=float)) / (2.0 * np.asarray(r_b, dtype=float))
    return np.asarray(ratio_entrainment, dtype=float) * ((1.0 - gam) if side == "inner" else (1.0 + gam)) * roll_sign


def warnings_for(ds, case) -> list[str]:
    """Warnings for a run / quasi-static Dataset carrying the contact-state variables (one line each)."""
    from hsbearing.models import limits
    from hsbearing.models.geometry import derive

    out = []
    g = derive(case)
    p = [ds[n].values for n in ("inner_contact_pressure", "outer_contact_pressure") if n in ds]
    if p:
        top = max(float(np.nanmax(x)) if np.size(x) and np.isfinite(x).any() else 0.0 for x in p)
        rated = getattr(case.bearing, "permissible_contact_pressure", None)
        if rated is not None and top > rated:
            out.append(f"maximum contact pressure {top * 1e-9:.3g} GPa exceeds the {rated * 1e-9:.3g} GPa the raceway "
                       "material is rated for (bearing.permissible_contact_pressure)")
        elif rated is None and top > limits.ISO76_BALL_PRESSURE:
            out.append(f"maximum contact pressure {top * 1e-9:.3g} GPa exceeds the {limits.ISO76_BALL_PRESSURE * 1e-9:g} GPa "
                       "of ISO 76:2006 (static load rating of ball bearings): the raceways deform permanently")
    lam = [ds[n].values for n in ("inner_film_parameter", "outer_film_parameter") if n in ds]
    if lam:
        vals = np.concatenate([np.ravel(x) for x in lam])
        vals = vals[np.isfinite(vals)]
        if vals.size and vals.min() < 1.0:
            out.append(f"film parameter lambda down to {vals.min():.3g} < 1 (composite roughness "
                       f"{math.hypot(case.materials.ball.surface_roughness, case.materials.races.surface_roughness) * 1e6:.3g} um): "
                       "mixed/boundary lubrication, the EHL traction and film results do not hold there")
    b = case.bearing
    for side, land, d, r, f in (("inner", b.inner_land_diameter, g.di, g.ri, g.fi), ("outer", b.outer_land_diameter, g.do, g.ro, g.fo)):
        if land is None or f"{side}_contact_semimajor" not in ds or f"{side}_contact_angle" not in ds:
            continue
        ts = (limits.shoulder_angle_inner if side == "inner" else limits.shoulder_angle_outer)(d, r, land)
        if not math.isfinite(ts):
            continue
        edge = limits.ellipse_edge_angle(ds[f"{side}_contact_angle"].values, ds[f"{side}_contact_semimajor"].values, f, g.D)
        e = float(np.nanmax(edge))
        if e > ts:
            out.append(f"{side} contact ellipse truncated by the groove shoulder: its edge reaches {math.degrees(e):.3g} deg "
                       f"from the groove bottom, the shoulder ({side}_land_diameter {land * 1e3:.4g} mm) is at "
                       f"{math.degrees(ts):.3g} deg: edge stresses, the Hertz results underestimate the pressure")
    if "cage_center_y" in ds and "cage_center_z" in ds and math.isfinite(g.guide_clearance):
        r = np.hypot(ds["cage_center_y"].values, ds["cage_center_z"].values)
        frac = float(np.nanmax(r)) / g.guide_clearance if r.size else 0.0
        if frac >= 0.95:
            out.append(f"cage orbit reaches {frac * 100:.3g} % of its guide clearance ({g.guide_clearance * 1e6:.3g} um): "
                       "the cage rubs its guide land")
    return out


def format_warnings(ws) -> str:
    """The ``warnings`` attribute: the warnings joined by ' | ', or 'none'."""
    return " | ".join(ws) if ws else "none"
