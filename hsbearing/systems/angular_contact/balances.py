"""Power loss by source, drive torque, and the energy and angular-momentum balances of the dynamic model.

The dissipated power of every source is evaluated inside the compiled kernel
(:mod:`hsbearing.models.ball_bearing.kernel`, per-ball ``aux`` and global ``gaux`` columns)
by the named functions of :mod:`hsbearing.models.ball_bearing.power`: force x relative
sliding velocity, or moment x relative angular velocity, at the contact.
:data:`SOURCES` maps each reported source to those columns -- the ONE place a
new source (a pocket or land model of another helper) is added.

Balances (docs/power_loss.md; tests/systems/angular_contact/test_balances.py):

- power: P_drive (+ P_outer_drive when the outer ring turns) = sum of the
  dissipated powers + dE/dt, E the mechanical energy
  (:func:`mechanical_energy`: kinetic + elastic + gravity
  + load potential);
- angular momentum about the bearing axis X of balls + cage + inner ring:
  dL/dt = external torque (drive, outer ring = ground, guide land, drag,
  gravity, loads).
"""

from __future__ import annotations

import numpy as np

from hsbearing import results
from hsbearing.models.ball_bearing import kernel_io as K
from hsbearing.models.ball_bearing.kernel_io import GUIDE_OUTER_RING

__all__ = ["SOURCES", "STATE_GROUPS", "power_by_source", "power_difference_by_state", "mechanical_energy", "power_variables", "power_summary_lines", "energy_rate", "angular_momentum_x",
           "angular_momentum_rate_x", "external_torque_x", "balance_terms"]

#: source -> (description, per-ball aux columns summed for it, global gaux column or None)
SOURCES = {
    "race_traction": ("traction of the race contacts (rolling and transverse slip, spin), inner + outer: "
                      "sum over the ellipse nodes of traction x local slip", ("P_trac_i", "P_trac_o"), None),
    "ehl_rolling": ("EHL rolling resistance, inner + outer: rolling couple (D/2) F_R x relative angular velocity",
                    ("P_ehl_i", "P_ehl_o"), None),
    "contact_damping": ("normal damping of the race contacts (Hunt-Crossley): damping force x approach rate",
                        ("P_damp_i", "P_damp_o"), None),
    "pocket_film": ("ball-pocket oil film: film force x approach rate", ("P_pocket_film",), None),
    "pocket_boundary": ("ball-pocket boundary friction P_S x sliding speed", ("P_pocket_boundary",), None),
    "guide_land": ("cage guide land: film forces and friction moment x velocity relative to the land, rub friction",
                   (), "P_guide_land"),
    "drag": ("drag of the air-oil mixture on the balls x orbital speed", ("P_drag",), None),
}

results.register("power_loss", ("time",), "W", "power dissipated in the bearing, sum of the power_loss_<source>")
for _s, (_d, _cols, _g) in SOURCES.items():
    results.register(f"power_loss_{_s}", ("time",), "W", f"power dissipated by {_d}")
    if _cols:
        results.register(f"power_loss_{_s}_per_ball", ("time", "ball"), "W", f"power dissipated at each ball by {_d}")
for _n, _d, _u, _l in [
    ("drive_torque", ("time",), "N*m", "torque the shaft supplies to the inner ring about its axis to hold the "
     "prescribed speed, positive when it drives"),
    ("drive_power", ("time",), "W", "power the shaft supplies to the inner ring (drive_torque x ring angular velocity)"),
    ("outer_ring_torque", ("time",), "N*m", "moment about X of the balls' and the cage's actions on the outer ring "
     "(the torque the housing holds), positive in the direction of the inner-ring rotation"),
]:
    results.register(_n, _d, _u, _l)


def power_variables(aux: np.ndarray, gaux: np.ndarray, outer_guided: bool = True) -> dict:
    """Dataset variables of the power accounting from the kernel outputs aux (time, ball, N_AUX), gaux (time, N_GAUX)."""
    A, G = K.AUX_INDEX, K.GAUX_INDEX
    out = {}
    total = np.zeros(gaux.shape[0])
    for s, (_d, cols, g) in SOURCES.items():
        per = sum((aux[..., A[c]] for c in cols), np.zeros(aux.shape[:-1])) if cols else None
        tot = per.sum(-1) if per is not None else np.zeros(gaux.shape[0])
        if g is not None:
            tot = tot + gaux[:, G[g]]
        out[f"power_loss_{s}"] = tot
        if per is not None:
            out[f"power_loss_{s}_per_ball"] = per
        total = total + tot
    out["power_loss"] = total
    out["drive_torque"] = gaux[:, G["drive_torque"]]
    out["drive_power"] = gaux[:, G["P_drive"]]
    # the land reacts on the outer ring only for outer-ring guidance (inner-ring guidance: on the inner ring)
    outer_land = gaux[:, G["land_torque_x"]] if outer_guided else 0.0
    out["outer_ring_torque"] = -(aux[..., A["tau_o"]].sum(-1) + outer_land)
    return out


def power_summary_lines(ds) -> list[str]:
    """Lines of the ``hsbearing run`` summary: drive torque and power loss by source, means over the second half."""
    from hsbearing.display import format_quantity

    if "drive_torque" not in ds or ds.sizes.get("time", 0) < 2:
        return []
    t = ds["time"].values
    sel = ds.isel(time=slice(int(np.searchsorted(t, 0.5 * t[-1])), None))
    lines = [f"mean over t = {float(sel.time[0]) * 1e3:.4g}..{float(t[-1]) * 1e3:.4g} ms:",
             f"  drive_torque: {format_quantity(float(sel.drive_torque.mean()), 'N m')} (shaft torque, positive when driving)",
             f"  drive_power: {float(sel.drive_power.mean()):.4g} W",
             f"  power_loss: {float(sel.power_loss.mean()):.4g} W, by source:"]
    for s in SOURCES:
        lines.append(f"    {s}: {float(sel[f'power_loss_{s}'].mean()):.4g} W")
    return lines


# ----------------------------------------------------------------------------- balances at a state

def mechanical_energy(model, y) -> np.ndarray:
    """Total mechanical energy [J] at states ``y`` (..., N): kinetic + Hertz + pocket and land elastic - work of the loads.

    ``model``: a :class:`hsbearing.systems.angular_contact.dynamics.DynamicModel`.  For the energy test with ``friction=False, damping=False`` (then this is
    a constant of motion).  The inner ring's prescribed spin does no work on
    frictionless contacts; its spin kinetic energy is constant and omitted.
    """
    y = np.atleast_2d(y)
    L = model.layout
    P = K.as_dict(model.P)
    u = L.unpack(y)
    rb, th = L.ball_radius(y, P["dm"]), L.ball_azimuth(y)
    mb, Ib = P["m_b"], P["I_b"]
    E = 0.5 * mb * (u["xdot_b"] ** 2 + u["udot_b"] ** 2 + (rb * u["thetadot_b"]) ** 2).sum(-1)
    E += 0.5 * Ib * (u["omega_x"] ** 2 + u["omega_y"] ** 2 + u["omega_z"] ** 2).sum(-1)
    E += 0.5 * P["m_c"] * (u["xdot_c"] ** 2 + u["ydot_c"] ** 2 + u["zdot_c"] ** 2)
    E += 0.5 * P["Ip_c"] * u["phidot_c"] ** 2 + 0.5 * P["Id_c"] * (u["tiltdot_y_c"] ** 2 + u["tiltdot_z_c"] ** 2)
    E += 0.5 * P["m_i"] * (u["xdot_i"] ** 2 + u["ydot_i"] ** 2 + u["zdot_i"] ** 2)
    E += 0.5 * P["Id_i"] * (u["tiltdot_y_i"] ** 2 + u["tiltdot_z_i"] ** 2)
    E -= P["F_x"] * u["x_i"] + P["F_y"] * u["y_i"] + P["F_z"] * u["z_i"]
    E -= P["M_y"] * u["tilt_y_i"] + P["M_z"] * u["tilt_z_i"]
    gr = P["grav"]  # potential of gravity along -Y
    E += gr * (mb * (rb * np.cos(th)).sum(-1) + P["m_c"] * u["y_c"] + P["m_i"] * u["y_i"])
    # elastic energies 2/5 K delta^2.5 of the race and pocket contacts and of the cage rubbing the land,
    # from the kernel's own approaches (aux U_el, gaux U_land: valid with damping on as well)
    for k in range(y.shape[0]):
        aux, gaux = model.outputs(y[k])
        E[k] += aux[:, K.AUX_INDEX["U_el"]].sum() + gaux[K.GAUX_INDEX["U_land"]]
    return E


def energy_rate(model, y, h: float = 1e-9) -> float:
    """dE/dt [W] of the mechanical energy along the model's own vector field: (E(y + h f) - E(y - h f)) / 2h."""
    y = np.ascontiguousarray(y, dtype=float)
    f = model.f(y)
    E = mechanical_energy(model, np.stack([y + h * f, y - h * f]))
    return float((E[0] - E[1]) / (2.0 * h))


def angular_momentum_x(model, y) -> np.ndarray:
    """Angular momentum about the bearing axis X [N m s] of balls + cage + inner ring (the ring's spin omitted: constant).

    Balls: m r^2 theta' + I omega_x; cage: m_c (y_c z_c' - z_c y_c') + I_p phi_c'; ring: m_i (y_i z_i' - z_i y_i').
    """
    y = np.atleast_2d(y)
    L, P = model.layout, K.as_dict(model.P)
    u = L.unpack(y)
    rb = L.ball_radius(y, P["dm"])
    H = (P["m_b"] * rb**2 * u["thetadot_b"] + P["I_b"] * u["omega_x"]).sum(-1)
    H += P["m_c"] * (u["y_c"] * u["zdot_c"] - u["z_c"] * u["ydot_c"]) + P["Ip_c"] * u["phidot_c"]
    H += P["m_i"] * (u["y_i"] * u["zdot_i"] - u["z_i"] * u["ydot_i"])
    return H


def angular_momentum_rate_x(model, y) -> float:
    """dL/dt [N m] of :func:`angular_momentum_x` from the state derivative f(y) (exact, no differencing)."""
    y = np.ascontiguousarray(y, dtype=float)
    L, P = model.layout, K.as_dict(model.P)
    f = model.f(y)
    u, du = L.unpack(y), L.unpack(f)
    rb = L.ball_radius(y, P["dm"])
    H = (P["m_b"] * (2.0 * rb * u["udot_b"] * u["thetadot_b"] + rb**2 * du["thetadot_b"])
         + P["I_b"] * du["omega_x"]).sum()
    H += P["m_c"] * (u["y_c"] * du["zdot_c"] - u["z_c"] * du["ydot_c"]) + P["Ip_c"] * du["phidot_c"]
    H += P["m_i"] * (u["y_i"] * du["zdot_i"] - u["z_i"] * du["ydot_i"])
    return float(H)


def external_torque_x(model, y) -> dict:
    """External moments about X [N m] on balls + cage + inner ring at state y, by origin.

    drive (T_d e_x), outer ring (ground) on the balls, guide land on the cage, drag on the balls,
    gravity (-Y), external loads on the ring (moments of F_y, F_z at the ring centre).
    """
    from hsbearing.models.ball_bearing.ring import tilt_rotation

    y = np.ascontiguousarray(y, dtype=float)
    L, P = model.layout, K.as_dict(model.P)
    aux, gaux = model.outputs(y)
    A, G = K.AUX_INDEX, K.GAUX_INDEX
    u = L.unpack(y)
    rb, th = L.ball_radius(y, P["dm"]), L.ball_azimuth(y)
    R, _J = tilt_rotation(float(u["tilt_y_i"]), float(u["tilt_z_i"]))
    g = P["grav"]
    return {
        "drive": float(gaux[G["drive_torque"]] * R[0]),
        "outer_ring": float(aux[:, A["tau_o"]].sum()),
        # external only when the land is on the (ground) outer ring; inner-ring guidance: internal cage <-> ring
        "guide_land": float(gaux[G["land_torque_x"]]) if model.param("guide") == GUIDE_OUTER_RING else 0.0,
        "drag": float((rb * aux[:, A["F_D"]]).sum()),
        "gravity": float(g * (P["m_b"] * (rb * np.sin(th)).sum() + P["m_c"] * u["z_c"] + P["m_i"] * u["z_i"])),
        "loads": float(u["y_i"] * P["F_z"] - u["z_i"] * P["F_y"]),
    }


def _load_moment_power_correction(model, y) -> float:
    """Power of the external ring moment M = (0, M_y, M_z) not contained in the rate of its potential -M.beta [W]:
    M . (omega_i e + J beta') - M . beta'."""
    from hsbearing.models.ball_bearing.ring import tilt_rotation

    P, L = K.as_dict(model.P), model.layout
    u = L.unpack(np.ascontiguousarray(y, dtype=float))
    R, J = tilt_rotation(float(u["tilt_y_i"]), float(u["tilt_z_i"]))
    by, bz = float(u["tiltdot_y_i"]), float(u["tiltdot_z_i"])
    wi = P["omega_i"]
    My, Mz = P["M_y"], P["M_z"]
    Oy = wi * R[3] + J[4] * by + J[5] * bz
    Oz = wi * R[6] + J[7] * by + J[8] * bz
    return float(My * (Oy - by) + Mz * (Oz - bz))


def balance_terms(model, y) -> dict:
    """Power and angular-momentum balance terms at state y (all floats, SI).

    Returns drive power, the dissipated power of each source and their sum, dE/dt, the power
    residual P_drive - sum D - dE/dt; dL/dt, the external torques and the torque residual.
    """
    aux, gaux = model.outputs(np.ascontiguousarray(y, dtype=float))
    pv = power_variables(aux[None], gaux[None], model.param("guide") == GUIDE_OUTER_RING)
    out = {k: float(v[0]) if np.ndim(v) == 1 else v[0] for k, v in pv.items()}
    out["dE_dt"] = energy_rate(model, y)
    # a turning outer ring is held at its speed by a drive too: it supplies -(torque on the outer ring) omega_o
    out["outer_drive_power"] = -out["outer_ring_torque"] * float(model.param("omega_o"))
    # external moment on the ring: the mechanical energy carries its potential -M.beta (small tilts); the
    # moment works at the ring's angular velocity omega_i e + J beta' (with the spin too, the drive takes it)
    out["load_moment_power"] = _load_moment_power_correction(model, y)
    out["power_residual"] = (out["drive_power"] + out["outer_drive_power"] + out["load_moment_power"]
                             - out["power_loss"] - out["dE_dt"])
    tq = external_torque_x(model, y)
    out["torques"] = tq
    out["dL_dt"] = angular_momentum_rate_x(model, y)
    out["torque_residual"] = out["dL_dt"] - sum(tq.values())
    return out


# ----------------------------------------------------------------------------- quasi-static vs dynamic, by state
#: groups of state components, in the order :func:`power_difference_by_state` puts them back to the quasi-static
#: state; the cage angle phi_c (the rotation reference of the balls' azimuths) is never replaced
STATE_GROUPS = (
    ("ball_orbital_speed", ("thetadot_b",), (), ()),
    ("ball_angular_velocity", ("omega_x", "omega_y", "omega_z"), (), ()),
    # the cage's whirl carries the pockets, so the balls' places in them go back with it (one without the other
    # would push a ball through its pocket wall)
    ("cage_and_ball_positions", ("x_b", "u_b", "theta_rel_b", "xdot_b", "udot_b"),
     ("x_c", "y_c", "z_c", "tilt_y_c", "tilt_z_c", "xdot_c", "ydot_c", "zdot_c", "phidot_c", "tiltdot_y_c",
      "tiltdot_z_c"), ()),
    ("inner_ring", (), (), ("x_i", "y_i", "z_i", "tilt_y_i", "tilt_z_i", "xdot_i", "ydot_i", "zdot_i", "tiltdot_y_i",
                            "tiltdot_z_i")),
)


def power_by_source(model, y) -> dict:
    """Power dissipated by each source of :data:`SOURCES` and the total [W] at one state ``y`` of ``model``."""
    aux, gaux = model.outputs(y)
    pv = power_variables(aux[None], gaux[None], outer_guided=model.P["land"]["guide"][0] == GUIDE_OUTER_RING)
    out = {s: float(pv[f"power_loss_{s}"][0]) for s in SOURCES}
    out["power_loss"] = float(pv["power_loss"][0])
    return out


def power_difference_by_state(model, y_dynamic, y_quasistatic=None) -> list[tuple[str, dict]]:
    """The dynamic-minus-quasi-static power loss by source, attributed to the parts of the state that differ.

    The quasi-static power loss (:func:`hsbearing.systems.angular_contact.rating.quasi_static_power_loss`) is the
    kernel's dissipation at the quasi-static state ``y_quasistatic`` (default ``model.y0``); a dynamic run's is the
    same kernel's at its states.  Starting from ``y_dynamic``, the groups of :data:`STATE_GROUPS` are put back to
    their quasi-static values one after the other; the change of each source at each step is that group's share
    (an ordered, exactly telescoping attribution: the steps sum to P(y_dynamic) - P(y_quasistatic), up to the cage
    angle, which is kept).  Returns ``[(group, {source: W})]``, first ``("dynamic", P(y_dynamic))`` and last
    ``("quasistatic", P(y at the end))``; the shares in between are P(before) - P(after) (docs/power_loss.md).
    """
    y0 = np.asarray(model.y0 if y_quasistatic is None else y_quasistatic, dtype=float)
    y = np.array(y_dynamic, dtype=float)
    L = model.layout
    prev = power_by_source(model, y)
    out = [("dynamic", prev)]
    for name, ball, cage, ring in STATE_GROUPS:
        for n in ball:
            y[L.ball(n)] = y0[L.ball(n)]
        for n in cage:
            y[L.cage(n)] = y0[L.cage(n)]
        for n in ring:
            y[L.ring(n)] = y0[L.ring(n)]
        now = power_by_source(model, y)
        out.append((name, {k: prev[k] - now[k] for k in prev}))
        prev = now
    out.append(("quasistatic", prev))
    return out
