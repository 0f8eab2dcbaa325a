"""The guide-land and pocket films at their film temperature, at the model's quasi-static state (docs/power_loss.md,
"Inlet heating, thermal and part-filled cage films").

:func:`film_inputs` (sliding speed, thickness, wall temperatures of each film), :func:`film_factors` (eta_eff /
eta_film of each film from :func:`hsbearing.models.ball_bearing.films.thermal_couette_film`).  Used by the
quasi-static power loss (:mod:`hsbearing.systems.angular_contact.rating`) and the thermal network's heat by body
(:mod:`hsbearing.systems.angular_contact.thermal`); imports neither.
"""

from __future__ import annotations

import numpy as np

from hsbearing.models.geometry import derive
from hsbearing.systems.angular_contact.oil_properties import oil_conductivity, viscosity_at

__all__ = ["film_inputs", "film_factors", "oil_conductivity"]


def film_inputs(case, m, walls: dict | None = None) -> dict:
    """Sliding speed, thickness and wall temperatures of the guide-land and pocket films at the model's initial
    (quasi-static) state: {"land": (U, h, T_a, T_b), "pocket": (U, h, T_a, T_b)} [m/s, m, K, K].

    Land: the cage's surface speed against the guiding ring, (phidot_c - omega_ring) R_land, over the radial land
    clearance of the centred cage; walls cage and guiding ring.  Pocket: the ball's surface speed relative to the
    cage frame, |omega_rel| D/2 (mean over the balls), over the radial pocket clearance of the centred ball; walls
    ball and cage.  Representative single films: the clearance where the film is thinnest (at the land, everywhere;
    in the pocket, round the ball's equator).
    """
    lay, y0, g = m.layout, m.y0, derive(case)
    lands = m.info["guide_lands"]
    T0 = case.lubricant.temperature
    T = {k: T0 for k in ("inner_ring", "outer_ring", "balls", "cage")}
    if walls:
        T.update({k: float(v) for k, v in walls.items() if k in T})
    out = {}
    if lands.count:
        w_ring = case.operating.outer_speed if lands.guidance == "outer_ring" else case.operating.inner_speed
        ring = "outer_ring" if lands.guidance == "outer_ring" else "inner_ring"
        U = (float(y0[lay.cage("phidot_c")]) - w_ring) * lands.radius
        out["land"] = (U, lands.clearance, T["cage"], T[ring])
    wx, wy, wz = (y0[lay.ball(n)] for n in ("omega_x", "omega_y", "omega_z"))
    rel = np.sqrt((wx - y0[lay.ball("thetadot_b")]) ** 2 + wy**2 + wz**2)
    out["pocket"] = (float(np.mean(rel)) * 0.5 * g.D, g.pocket_clearance, T["balls"], T["cage"])
    return out


def film_factors(case, m, walls=None) -> dict:
    """Thermal factor eta_eff / eta_film of the guide-land ("land") and pocket ("pocket") films at the model's initial
    state, with the film's speed, mean and largest temperature and wall temperatures (:func:`_film_corrections`).
    The factor is 1 with ``friction.thermal_films = "off"`` or without the film."""
    from hsbearing.models.ball_bearing import films
    eta_film = float(m.info["oil_viscosity"])
    k = oil_conductivity(case)
    thermal = case.friction.thermal_films == "on"
    inp = film_inputs(case, m, walls)
    out = {}
    nan = float("nan")
    for key in ("land", "pocket"):
        if key in inp and inp[key][0] != 0.0:
            U, h, Ta, Tb = inp[key]
            r = films.thermal_couette_film(lambda T: viscosity_at(case, T), U, h, k, Ta, Tb)
            out[key] = {"factor": r["eta_eff"] / eta_film if thermal else 1.0, "T_mean": r["T_mean"], "T_max": r["T_max"],
                        "speed": U, "walls": (Ta, Tb)}
        else:
            out[key] = {"factor": 1.0, "T_mean": nan, "T_max": nan, "speed": inp[key][0] if key in inp else 0.0,
                        "walls": inp[key][2:] if key in inp else (nan, nan)}
    return out
