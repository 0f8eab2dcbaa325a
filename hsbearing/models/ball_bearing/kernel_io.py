"""What the compiled dynamic kernel reads and writes, declared once by name (Zhang et al. 2016, Eqs. 5-21).

**Parameters** (:data:`PARAMETERS`): one row per parameter -- group, name, type, units, meaning.  They are
held in a one-element NumPy structured array of dtype :data:`PARAM_DTYPE`, one nested record per group,
built by :func:`pack` from a flat ``{name: value}`` mapping (names are unique over the groups).  The kernel
reads them by name, ``p = P[0]`` then ``p.pocket.h_min`` (numba compiles the field access to a load at a
fixed offset, like the index of a float vector).  :func:`hsbearing.systems.angular_contact.dynamics.build_model` fills every
parameter in one place; :func:`pack` refuses a missing or an unknown name, and
``tests/models/test_kernel_io.py`` fails when a declared parameter is never read by the kernel source.

**Outputs** (:data:`BALL_OUTPUTS` per ball, :data:`GLOBAL_OUTPUTS` per state): one row per column -- name,
units, meaning, and the run Dataset variable it is stored as (``None``: used by the balances only).  The
kernel writes ``aux[j, AUX.Q_i]``; the column numbers are the row order of the declaration and
:func:`hsbearing.systems.angular_contact.dynamics.to_dataset` assembles the Dataset from the same rows.

No numba here: importing this module compiles nothing.  docs/kernel.md: adding a parameter or an output.
"""

from __future__ import annotations

from collections import namedtuple

import numpy as np

__all__ = ["PARAMETERS", "PARAM_GROUPS", "PARAM_DTYPE", "PARAM_GROUP", "GUIDE_BALL", "GUIDE_OUTER_RING",
           "GUIDE_INNER_RING", "GUIDANCE", "pack", "get", "set_value", "as_dict", "BALL_OUTPUTS", "GLOBAL_OUTPUTS",
           "AUX", "GAUX", "AUX_INDEX", "GAUX_INDEX", "N_AUX", "N_GAUX", "DATASET_BALL", "DATASET_GLOBAL"]

#: cage guidance (parameter ``land.guide``): ball-piloted (no land), outer-ring land, inner-ring land
GUIDE_BALL, GUIDE_OUTER_RING, GUIDE_INNER_RING = 0, 1, 2
GUIDANCE = {"ball": GUIDE_BALL, "outer_ring": GUIDE_OUTER_RING, "inner_ring": GUIDE_INNER_RING}

_F, _I, _B = "f8", "i8", "?"

#: (group, name, type, units, meaning); the kernel reads ``p.<group>.<name>``
PARAMETERS = (
    # ---- balls (Eqs. 5-10)
    ("ball", "Z", _I, "1", "number of balls"),
    ("ball", "D", _F, "m", "ball diameter"),
    ("ball", "m_b", _F, "kg", "ball mass"),
    ("ball", "I_b", _F, "kg m^2", "ball moment of inertia"),
    ("ball", "dm", _F, "m", "pitch diameter"),
    # ---- race contacts: groove geometry, Hertz, damping, EHL rolling force, ring speeds
    ("race", "rho_i", _F, "m", "radius of the inner groove-curvature centre (ring frame, unloaded)"),
    ("race", "g_i", _F, "m", "axial position of the inner groove-curvature centre"),
    ("race", "off_i", _F, "m", "inner groove-curvature centre to ball centre at contact onset, (f_i - 1/2) D"),
    ("race", "rho_o", _F, "m", "radius of the outer groove-curvature centre"),
    ("race", "g_o", _F, "m", "axial position of the outer groove-curvature centre"),
    ("race", "off_o", _F, "m", "outer groove-curvature centre to ball centre at contact onset, (f_o - 1/2) D"),
    ("race", "K_i", _F, "N/m^1.5", "Hertz load-deflection constant, inner contact"),
    ("race", "K_o", _F, "N/m^1.5", "Hertz load-deflection constant, outer contact"),
    ("race", "cd_i", _F, "N s/m^1.25", "normal damping coefficient, inner contact (models.ball.hertz_normal_load)"),
    ("race", "cd_o", _F, "N s/m^1.25", "normal damping coefficient, outer contact"),
    ("race", "acoef_i", _F, "m/N^(1/3)", "contact-ellipse semi-major axis a = acoef Q^(1/3), inner"),
    ("race", "acoef_o", _F, "m/N^(1/3)", "contact-ellipse semi-major axis a = acoef Q^(1/3), outer"),
    ("race", "Rx_i", _F, "m", "equivalent radius along the rolling direction, inner contact"),
    ("race", "Rx_o", _F, "m", "equivalent radius along the rolling direction, outer contact"),
    ("race", "k_i", _F, "1", "ellipticity of the inner contact"),
    ("race", "k_o", _F, "1", "ellipticity of the outer contact"),
    ("race", "Ep", _F, "Pa", "reduced elastic modulus ball/race"),
    ("race", "omega_i", _F, "rad/s", "inner-ring speed about its axis (prescribed)"),
    ("race", "omega_o", _F, "rad/s", "outer-ring speed about X (prescribed)"),
    # ---- lubricant
    ("lubricant", "eta_in", _F, "Pa s", "inlet viscosity of the inner race contacts (EHL rolling force, traction; outer: eta_in_o)"),
    ("lubricant", "alpha", _F, "1/Pa", "pressure-viscosity coefficient of the inner race contacts (outer: alpha_o)"),
    ("lubricant", "eta_film", _F, "Pa s", "isothermal viscosity of the pocket and guide-land films (at lubricant.temperature)"),
    ("lubricant", "land_film_factor", _F, "1", "thermal factor eta_eff / eta_film of the guide-land film (1: isothermal; run --thermal)"),
    ("lubricant", "pocket_film_factor", _F, "1", "thermal factor eta_eff / eta_film of the pocket films (1: isothermal; run --thermal)"),
    ("lubricant", "beta_T", _F, "1/K", "temperature-viscosity coefficient -d ln(eta)/dT at the inner contacts' inlet (inlet shear heating; outer: beta_T_o)"),
    ("lubricant", "K_oil", _F, "W/(m K)", "oil thermal conductivity (inlet shear heating)"),
    # ---- traction law of the race contacts (models.traction)
    ("traction", "law_id", _I, "1", "traction law (hsbearing.models.traction.law_id)"),
    ("traction", "T_K", _F, "K", "inlet temperature of the inner race contacts for the traction law (outer: T_K_o)"),
    ("traction", "U_eps", _F, "m/s", "regularisation of the rolling speed |U|"),
    ("traction", "s_eps", _F, "m/s", "regularisation of the slip speed in the traction direction"),
    ("traction", "tau0", _F, "Pa", "Eyring stress of the physical traction model (law eyring; models.traction.eyring)"),
    ("traction", "Lambda", _F, "1", "limiting-shear-stress coefficient tau_L / p of the physical traction model"),
    ("traction", "G", _F, "Pa", "elastic shear modulus of the film in the physical traction model"),
    ("traction", "c_A", _F, "1", "user coefficient A of mu = (A + B S) exp(-C S) + D (law user; S a fraction)"),
    ("traction", "c_B", _F, "1", "user coefficient B of mu = (A + B S) exp(-C S) + D"),
    ("traction", "c_C", _F, "1", "user coefficient C of mu = (A + B S) exp(-C S) + D"),
    ("traction", "c_D", _F, "1", "user coefficient D of mu = (A + B S) exp(-C S) + D"),
    # ---- the outer race contacts' inlet oil: the same quantities as eta_in, alpha, beta_T, T_K, tau0, Lambda, G at the
    # outer contacts' inlet temperature (equal to them when both races run at one temperature, every default build)
    ("outer_oil", "eta_in_o", _F, "Pa s", "inlet viscosity of the outer race contacts"),
    ("outer_oil", "alpha_o", _F, "1/Pa", "pressure-viscosity coefficient of the outer race contacts"),
    ("outer_oil", "beta_T_o", _F, "1/K", "temperature-viscosity coefficient at the outer contacts' inlet"),
    ("outer_oil", "T_K_o", _F, "K", "inlet temperature of the outer race contacts for the traction law"),
    ("outer_oil", "tau0_o", _F, "Pa", "Eyring stress of the physical traction model at the outer contacts"),
    ("outer_oil", "Lambda_o", _F, "1", "limiting-shear-stress coefficient at the outer contacts"),
    ("outer_oil", "G_o", _F, "Pa", "elastic shear modulus of the film at the outer contacts"),
    # ---- ball/cage pocket (models.pocket)
    ("pocket", "c_p", _F, "m", "pocket clearance (pocket radius - ball radius)"),
    ("pocket", "K_c", _F, "N/m^1.5", "Hertz load-deflection constant ball/pocket"),
    ("pocket", "h_min", _F, "m", "pocket film floor h_c"),
    ("pocket", "mu_c", _F, "1", "boundary friction coefficient of the pocket and of the land rub"),
    ("pocket", "v0_c", _F, "m/s", "Coulomb regularisation speed of the pocket and land-rub friction"),
    ("pocket", "R_bore_c", _F, "m", "cage bore radius (inner end of the pocket wall)"),
    ("pocket", "R_out_c", _F, "m", "cage outside radius (outer end of the pocket wall)"),
    ("pocket", "n_pocket", _I, "1", "stations around the pocket wall"),
    # ---- air-oil drag on the balls (Eq. 7)
    ("drag", "rho_e", _F, "kg/m^3", "density of the air-oil mixture"),
    ("drag", "C_D", _F, "1", "drag coefficient of a sphere"),
    ("drag", "v0_D", _F, "m/s", "regularisation speed of the drag direction"),
    # ---- cage body (Eqs. 11-16)
    ("cage", "m_c", _F, "kg", "cage mass"),
    ("cage", "Ip_c", _F, "kg m^2", "cage polar moment of inertia"),
    ("cage", "Id_c", _F, "kg m^2", "cage diametral moment of inertia"),
    # ---- guide lands (models.cage)
    ("land", "guide", _I, "1", "cage guidance: GUIDE_BALL, GUIDE_OUTER_RING or GUIDE_INNER_RING"),
    ("land", "n_land", _I, "1", "number of guide lands (0: ball-piloted)"),
    ("land", "R_land", _F, "m", "guide-land film radius (cage guide-surface radius)"),
    ("land", "L_land", _F, "m", "width of each land film"),
    ("land", "c_land", _F, "m", "radial clearance of the land"),
    ("land", "a_land", _F, "m", "axial offset of the lands from the cage mid-plane (+a, or +-a for two)"),
    ("land", "eps_max", _F, "1", "saturation of the land eccentricity ratio"),
    ("land", "K_land", _F, "N/m^1.5", "elastic rub of the cage on its lands beyond the clearance (shared)"),
    ("land", "offset_eps", _F, "m", "regularisation of the cage-axis offset from the land centre, e -> sqrt(e^2 + eps^2)"),
    # ---- inner ring body and external loads (Eqs. 17-21)
    ("ring", "m_i", _F, "kg", "inner-ring mass"),
    ("ring", "Ip_i", _F, "kg m^2", "inner-ring polar moment of inertia"),
    ("ring", "Id_i", _F, "kg m^2", "inner-ring diametral moment of inertia"),
    ("ring", "F_x", _F, "N", "external axial load on the inner ring"),
    ("ring", "F_y", _F, "N", "external radial load on the inner ring along Y"),
    ("ring", "F_z", _F, "N", "external radial load on the inner ring along Z"),
    ("ring", "M_y", _F, "N m", "external moment on the inner ring about Y"),
    ("ring", "M_z", _F, "N m", "external moment on the inner ring about Z"),
    # ---- environment and model switches
    ("env", "grav", _F, "m/s^2", "gravity along -Y (horizontal shaft); 0 switches it off"),
    ("switches", "friction", _B, "-", "traction, pocket friction, land friction moment and rub friction"),
    ("switches", "damping", _B, "-", "contact damping, pocket and land films"),
    ("switches", "ehl_rolling", _B, "-", "EHL rolling force F_R (with damping only)"),
    ("switches", "inlet_heating", _B, "-", "inlet shear heating factor on F_R (friction.inlet_heating; models.ball_bearing.ball)"),
    ("switches", "drag", _B, "-", "air-oil drag on the balls (with friction only)"),
)

#: group names in declaration order
PARAM_GROUPS = tuple(dict.fromkeys(g for g, *_ in PARAMETERS))
#: parameter name -> its group
PARAM_GROUP = {n: g for g, n, *_ in PARAMETERS}
assert len(PARAM_GROUP) == len(PARAMETERS), "parameter names must be unique over the groups"
#: dtype of the parameter record: one nested record per group
PARAM_DTYPE = np.dtype([(grp, np.dtype([(n, t) for g, n, t, *_ in PARAMETERS if g == grp])) for grp in PARAM_GROUPS])


def pack(values: dict) -> np.ndarray:
    """The parameter record (a one-element structured array of :data:`PARAM_DTYPE`) from ``{name: value}``.

    Every declared parameter must be given, and only those: a missing or unknown name raises ``KeyError``.
    """
    missing = [n for n in PARAM_GROUP if n not in values]
    unknown = [n for n in values if n not in PARAM_GROUP]
    if missing or unknown:
        raise KeyError(f"kernel parameters: missing {missing}, unknown {unknown} (hsbearing/models/ball_bearing/kernel_io.py)")
    P = np.zeros(1, dtype=PARAM_DTYPE)
    for n, v in values.items():
        P[PARAM_GROUP[n]][n] = v
    return P


def get(P: np.ndarray, name: str):
    """Value of parameter ``name`` in the record ``P`` (a Python float, int or bool)."""
    return P[PARAM_GROUP[name]][name][0].item()


def set_value(P: np.ndarray, name: str, value) -> None:
    """Set parameter ``name`` of the record ``P`` in place."""
    P[PARAM_GROUP[name]][name] = value


def as_dict(P: np.ndarray) -> dict:
    """``{name: value}`` of every parameter of the record ``P``."""
    return {n: get(P, n) for n in PARAM_GROUP}


# ------------------------------------------------------------------------------------------ outputs
#: per-ball outputs: (name, units, meaning, run Dataset variable or None); column = row number
BALL_OUTPUTS = (
    ("Q_i", "N", "inner contact normal load", "inner_contact_load"),
    ("Q_o", "N", "outer contact normal load", "outer_contact_load"),
    ("alpha_i", "rad", "inner contact angle", "inner_contact_angle"),
    ("alpha_o", "rad", "outer contact angle", "outer_contact_angle"),
    ("T_roll_i", "N", "inner-race traction on the ball, rolling component", "inner_traction_rolling"),
    ("T_trans_i", "N", "inner-race traction on the ball, transverse component", "inner_traction_transverse"),
    ("T_roll_o", "N", "outer-race traction on the ball, rolling component", "outer_traction_rolling"),
    ("T_trans_o", "N", "outer-race traction on the ball, transverse component", "outer_traction_transverse"),
    ("S_i", "1", "slide-roll ratio at the inner contact centre", "inner_slide_roll_ratio"),
    ("S_o", "1", "slide-roll ratio at the outer contact centre", "outer_slide_roll_ratio"),
    ("U_i", "m/s", "rolling speed at the inner contact", "inner_rolling_speed"),
    ("U_o", "m/s", "rolling speed at the outer contact", "outer_rolling_speed"),
    ("Q_c", "N", "pocket force on the ball in the pocket plane", "ball_cage_force"),
    ("P_S", "N", "pocket boundary friction force (magnitude)", "ball_cage_friction"),
    ("F_R_i", "N", "EHL rolling force at the inner contact", "inner_rolling_force"),
    ("F_R_o", "N", "EHL rolling force at the outer contact", "outer_rolling_force"),
    ("F_D", "N", "air-oil drag on the ball (signed, circumferential)", "ball_drag_force"),
    ("spin_roll_i", "1", "spin-to-roll ratio at the inner contact (kernel sign convention)", None),
    ("spin_roll_o", "1", "spin-to-roll ratio at the outer contact (kernel sign convention)", None),
    ("P_trac_i", "W", "power dissipated by the inner-race traction", None),
    ("P_trac_o", "W", "power dissipated by the outer-race traction", None),
    ("P_ehl_i", "W", "power dissipated by the inner EHL rolling couple", None),
    ("P_ehl_o", "W", "power dissipated by the outer EHL rolling couple", None),
    ("P_damp_i", "W", "power dissipated by the inner contact's normal damping", None),
    ("P_damp_o", "W", "power dissipated by the outer contact's normal damping", None),
    ("P_pocket_film", "W", "power dissipated in the pocket film (shear + squeeze)", "ball_cage_film_power"),
    ("P_pocket_boundary", "W", "power dissipated by pocket boundary friction", "ball_cage_boundary_power"),
    ("P_drag", "W", "power dissipated by the air-oil drag (mixture at rest)", None),
    ("U_el", "J", "elastic energy stored in the ball's race and pocket contacts", None),
    ("tau_o", "N m", "moment about X (through the origin) of the outer-race actions on the ball", None),
    ("Q_film", "N", "pocket film load (pressure over the pocket wall, both sides)", "ball_cage_film_load"),
    ("Q_solid", "N", "pocket Hertz (solid) load", "ball_cage_elastic_force"),
)

#: global outputs: (name, units, meaning, run Dataset variable or None)
GLOBAL_OUTPUTS = (
    ("F_cy", "N", "guide-land force on the cage along Y", "cage_land_force_y"),
    ("F_cz", "N", "guide-land force on the cage along Z", "cage_land_force_z"),
    ("M_cx", "N m", "guide-land friction moment on the cage along its axis", "cage_land_moment"),
    ("ring_torque", "N m", "moment about X of the ball actions (and inner land) on the inner ring",
     "inner_ring_friction_torque"),
    ("drive_torque", "N m", "moment the shaft supplies to hold the inner-ring speed (positive when it drives)", None),
    ("P_drive", "W", "power of the drive torque", None),
    ("P_guide_land", "W", "power dissipated by the land films and the rub", None),
    ("U_land", "J", "elastic energy of the cage rubbing its lands", None),
    ("land_torque_x", "N m", "moment about X (through the origin) of the land actions on the cage", None),
)

AUX_INDEX = {row[0]: i for i, row in enumerate(BALL_OUTPUTS)}
GAUX_INDEX = {row[0]: i for i, row in enumerate(GLOBAL_OUTPUTS)}
N_AUX = len(BALL_OUTPUTS)
N_GAUX = len(GLOBAL_OUTPUTS)
#: column numbers by name, for the compiled kernel (a global tuple: numba folds ``AUX.Q_i`` to a constant)
AUX = namedtuple("AuxColumns", list(AUX_INDEX))(*range(N_AUX))
GAUX = namedtuple("GauxColumns", list(GAUX_INDEX))(*range(N_GAUX))
#: run Dataset variable -> output column, from the rows that name one
DATASET_BALL = {row[3]: row[0] for row in BALL_OUTPUTS if row[3] is not None}
DATASET_GLOBAL = {row[3]: row[0] for row in GLOBAL_OUTPUTS if row[3] is not None}
