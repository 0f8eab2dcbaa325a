"""The case schema: every key of every table declared once (dimension, required for which system, default, bounds, closed vocabulary, one-line doc)."""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any

SYSTEMS = ("angular_contact", "deep_groove", "gyro_ribbon_cage", "wire_race")

#: Most cage start positions of the gyro SFMC start ensemble (each one is a run of one oscillation period).
MAX_START_POSITIONS = 64



@dataclass(frozen=True)
class Field:
    """Declaration of one case-file key.

    kind : a key of :data:`DIMENSIONS`, or ``"number"`` (plain float),
        ``"int"``, ``"str"``, ``"bool"``, ``"choice"``.
    required : the systems for which the key must be present (``"all"``),
        or an empty tuple when optional.
    default : value used when absent (in the case-file form, e.g. ``"0 N"``).
    positive : value must be > 0.  nonneg : value must be >= 0.
    choices : closed vocabulary for ``"choice"`` fields.
    doc : one line for ``docs/nomenclature.md`` and the error messages.
    """

    kind: str
    doc: str
    required: tuple[str, ...] | str = ()
    default: Any = None
    positive: bool = False
    nonneg: bool = False
    choices: tuple[str, ...] = ()
    minimum: float | None = None
    maximum: float | None = None


def _f(kind, doc, **kw) -> Field:
    return Field(kind=kind, doc=doc, **kw)


ALL = "all"
AC_DG = ("angular_contact", "deep_groove")
ROLLING = ("angular_contact", "deep_groove", "gyro_ribbon_cage")

_MATERIAL = {
    "elastic_modulus": _f("pressure", "Young's modulus E", required=ALL, positive=True),
    "poisson_ratio": _f("number", "Poisson's ratio nu", required=ALL, minimum=0.0, maximum=0.5),
    "density": _f("density", "mass density rho", required=ALL, positive=True),
    "surface_roughness": _f("length", "rms surface roughness R_q of the rolling surfaces (film parameter lambda; "
                            "composite sqrt(R_q,ball^2 + R_q,race^2))", default="0.05 um", nonneg=True),
}

#: The schema: table -> key -> Field.  ``materials`` has three sub-tables.
SCHEMA: dict[str, dict[str, Field]] = {
    "case": {
        "name": _f("str", "short name of the case", required=ALL),
        "system": _f("choice", "which bearing system the case describes", required=ALL, choices=SYSTEMS),
        "description": _f("str", "free text", default=""),
        "source": _f("str", "where the data come from", default=""),
    },
    "bearing": {
        "designation": _f("str", "catalogue designation, e.g. 7206", default=""),
        "ball_count": _f("int", "number of balls Z", required=ALL, positive=True),
        "ball_diameter": _f("length", "ball diameter D", required=ALL, positive=True),
        "pitch_diameter": _f("length", "pitch diameter d_m", required=ALL, positive=True),
        "inner_conformity": _f("number", "inner groove conformity f_i = r_i/D", required=ROLLING),
        "outer_conformity": _f("number", "outer groove conformity f_o = r_o/D", required=ROLLING),
        "contact_angle": _f("angle", "free (nominal) contact angle alpha_0", default="0 deg", nonneg=True),
        "diametral_clearance": _f(
            "length", "diametral clearance P_d (if given, overrides contact_angle)", nonneg=True
        ),
        "bore_diameter": _f("length", "bore diameter d", positive=True),
        "outside_diameter": _f("length", "outside diameter D_o", positive=True),
        "width": _f("length", "bearing width B", positive=True),
        "inner_land_diameter": _f("length", "inner-ring land (shoulder) diameter", positive=True),
        "outer_land_diameter": _f("length", "outer-ring land diameter (cage guide surface)", positive=True),
        "dynamic_load_rating": _f("force", "basic dynamic load rating C_r (catalogue; default: ISO 281 from the geometry)", positive=True),
        "limiting_speed": _f("angular_speed", "the bearing's limiting (or reference) speed from its catalogue: above "
                             "limiting_speed x d_m the speed warning is given (default: a typical n d_m of the "
                             "lubrication method, case.checks.TYPICAL_NDM)", positive=True),
        "permissible_contact_pressure": _f("pressure", "contact pressure the raceway material is rated for: a larger "
                                           "p_max is warned (default: 4.2 GPa, ISO 76:2006 6.2 for ball bearings)",
                                           positive=True),
        "inner_ring_mass": _f("mass", "inner ring (+ shaft) mass m_i", positive=True),
        "inner_ring_axial_inertia": _f("inertia", "inner ring polar moment of inertia", positive=True),
        "inner_ring_diametral_inertia": _f("inertia", "inner ring diametral moment of inertia", positive=True),
        # --- wire race bearing (Shan et al. 2010) ---
        "wire_diameter": _f("length", "wire race diameter d_w (Shan et al. 2010)", positive=True),
        "wire_groove_conformity": _f("number", "wire groove conformity r_groove/D (Shan et al. 2010)"),
    },
    "cage": {
        "guidance": _f("choice", "cage guidance", default="outer_ring", choices=("outer_ring", "inner_ring", "ball")),
        "outside_diameter": _f("length", "cage outside diameter", positive=True),
        "bore_diameter": _f("length", "cage bore diameter", positive=True),
        "width": _f("length", "cage width", positive=True),
        "pocket_diameter": _f("length", "cage pocket diameter d_p", positive=True),
        "pocket_clearance": _f("length", "pocket clearance (d_p - D)/2 if pocket_diameter absent", nonneg=True),
        "guide_land_width": _f("length", "axial width of ONE guide-land film (default: cage/ring overlap beside the groove, "
                               "docs/dynamics.md)", positive=True),
        "guide_land_count": _f("int", "number of guide lands, separate films whose forces add (default 2: one each side "
                               "of the groove; 0 for guidance = ball)", minimum=0, maximum=2),
        "mass": _f("mass", "cage mass m_c (computed from geometry and density if absent)", positive=True),
        "axial_inertia": _f("inertia", "cage polar moment of inertia", positive=True),
        "diametral_inertia": _f("inertia", "cage diametral moment of inertia", positive=True),
        # --- ribbon cage (Jiang et al. 2014) ---
        "thickness": _f("length", "ribbon cage thickness s (Jiang et al. 2014)", positive=True),
        "pocket_depth": _f("length", "ribbon cage pocket depth k (Jiang et al. 2014)", positive=True),
    },
    "materials.ball": dict(_MATERIAL),
    "materials.races": dict(_MATERIAL),
    "materials.cage": dict(_MATERIAL),
    "lubricant": {
        "oil": _f("str", "oil name: 4109, 4106, 4050 (built in, see hsbearing.models.traction), or a bundled lubricant name or a lubricant .toml file (as lubricant.file)", default="4109"),
        "file": _f("str", "lubricant file (TOML, docs/traction.md \"Lubricant files\") or bundled lubricant name; replaces lubricant.oil; path relative to the case file, then the working directory"),
        "file_text": _f("str", "the lubricant file's text, embedded by hsbearing when the case is loaded (archives stay self-contained; used only when the file cannot be found); not written by hand"),
        "temperature": _f("temperature", "oil inlet / bearing temperature", default="20 degC"),
        "traction_law": _f("str", "reading of the traction law (see docs/traction.md)", default="default"),
        "viscosity_law": _f("choice", "viscosity-temperature law: walther (ASTM D341 through the oil class's 40/100 degC data) or table1 (Zhang et al. 2016 Table 1 exponential)", default="walther", choices=("walther", "table1")),
        "kinematic_viscosity": _f("kinematic_viscosity", "operating kinematic viscosity nu (friction models)", positive=True),
        "dynamic_viscosity": _f("dynamic_viscosity", "ambient-pressure dynamic viscosity eta_0 (overrides the oil's)", positive=True),
        "pressure_viscosity_coefficient": _f("pressure_coefficient", "alpha (overrides the oil's)", positive=True),
        "density": _f("density", "oil density", default="850 kg/m^3", positive=True),
        "lubrication": _f("choice", "oil supply / lubrication method: oil_jet (jet), oil_air (mist / air-oil), oil_bath "
                          "(bath / splash), grease, dry; with oil_flow_rate it selects the cavity oil fraction law "
                          "(docs/power_loss.md)", default="oil_jet", choices=("oil_jet", "oil_bath", "oil_air", "grease", "dry")),
        "oil_flow_rate": _f("volume_flow_rate", "oil flow through the bearing (jet or air-oil supply), e.g. \"1.5 L/min\": "
                            "cavity oil fraction of the drag (Parker, NASA TP-2275) and the heat the oil carries "
                            "(hsbearing thermal)", nonneg=True),
        "contamination_factor": _f("number", "ISO 281 contamination factor e_C (Table 13; 0.5-0.6 normal cleanliness)",
                                   default=0.5, minimum=0.0, maximum=1.0),
        "oil_volume_fraction": _f("number", "oil fraction of the air-oil mixture in the cavity (drag); an override: absent, it "
                                  "comes from oil_flow_rate (Parker's correlation, jet / air-oil) or is 0.05",
                                  minimum=0.0, maximum=1.0),
    },
    "operating": {
        "inner_speed": _f("angular_speed", "inner-ring speed n_i", default="0 rpm"),
        "outer_speed": _f("angular_speed", "outer-ring speed n_o", default="0 rpm"),
        "axial_load": _f("force", "axial load F_x (along the bearing axis X)", default="0 N"),
        "radial_load": _f("force", "radial load F_y", default="0 N"),
        "radial_load_z": _f("force", "radial load F_z", default="0 N"),
        "moment_y": _f("moment", "tilting moment M_y", default="0 N*m"),
        "moment_z": _f("moment", "tilting moment M_z", default="0 N*m"),
        # --- gyro bearing (Jiang et al. 2014) ---
        "mode": _f("choice", "constant rate or oscillation (Jiang et al. 2014)", default="constant", choices=("constant", "oscillation")),
        "oscillation_period": _f("time", "period of the speed reversal (Jiang et al. 2014)", default="2 s", positive=True),
        "ramp_time": _f("time", "time to reach outer_speed from rest at constant acceleration (Jiang et al. 2014 Eq. 17)", positive=True),
        # --- wire race (Shan et al. 2010) ---
        "preload": _f("length", "preload magnitude delta (Shan et al. 2010)", nonneg=True),
        "framework_weight": _f("force", "gravity of the outer framework G_o (Shan et al. 2010)", nonneg=True),
    },
    "friction": {
        "coefficient": _f("number", "Coulomb friction coefficient (ball/race, ball/cage)", default=0.07, nonneg=True),
        "cage_coefficient": _f("number", "ball/cage pocket friction coefficient", default=0.1, nonneg=True),
        "hysteresis_loss": _f("number", "elastic hysteresis loss fraction alpha_r", default=0.008, nonneg=True),
        "viscous_factor": _f("number", "Palmgren lubrication factor f_0 of the viscous moment M_L (Jiang et al. 2014 Eq. 2)", nonneg=True),
        "cage_restitution": _f("number", "ball/cage impact coefficient of restitution (Hunt-Crossley damping, Jiang et al. 2014 model)", minimum=0.0, maximum=1.0),
        "rolling_resistance": _f("length", "rolling-friction resistance coefficient zeta (Shan et al. 2010)", nonneg=True),
        "unconsidered_torque": _f("moment", "torque not covered by the model M_u (Shan et al. 2010)", nonneg=True),
        "law": _f("choice", "sliding friction law", default="stribeck", choices=("stribeck", "coulomb")),
        # --- SKF 2004 frictional-moment model / dgbb_prl Stribeck-type coefficient ---
        "boundary_coefficient": _f("number", "boundary-film sliding coefficient mu_bl (SKF model; 0.15 mineral oil)", default=0.15, nonneg=True),
        "ehl_coefficient": _f("number", "full-film sliding coefficient mu_EHL (SKF model; 0.05 mineral oil)", default=0.05, nonneg=True),
        "static_load_rating": _f("force", "basic static load rating C_0 (SKF model contact angle alpha_F)", positive=True),
        "skf_reading": _f("choice", "G_sl under combined load: SKF catalogue, or the dgbb_prl reading", default="catalogue", choices=("catalogue", "dgbb_prl")),
        "skf_drag_variable": _f("number", "SKF drag-loss variable V_M read from the catalogue diagram (oil bath only)", nonneg=True),
        "mixture_corotation": _f("number", "fraction k of the cage orbital speed at which the cavity's air-oil mixture is "
                                 "carried round; the quasi-static ball drag and cage windage act on the speed relative to "
                                 "it (0: mixture at rest, the drag law's own assumption; the band 0..Couette estimate is "
                                 "reported by hsbearing friction; docs/power_loss.md)", default=0.0, minimum=0.0, maximum=1.0),
        "mixture_corotation_law": _f("choice", "how the quasi-static drag gets the mixture co-rotation: fixed "
                                     "(friction.mixture_corotation), or balance (the cavity mixture's steady angular-"
                                     "momentum balance: ball drag, ring walls, oil throughflow; models/ball_bearing/"
                                     "churning.py; the supplied oil's acceleration is then inside the drag; "
                                     "docs/power_loss.md)", default="fixed", choices=("fixed", "balance")),
        "cavity_losses": _f("choice", "jet-oil acceleration (m_dot v^2) and cage-face windage in the quasi-static power loss: "
                            "on, or off (drag only, as before)", default="on", choices=("on", "off")),
        "inlet_heating": _f("choice", "inlet shear heating of the race contacts: the EHL rolling force x phi_T^(0.66/0.67), "
                            "phi_T the film factor of Gupta et al. 1992 from each contact's own inlet viscosity, speed, "
                            "pressure and slip (models/ball_bearing/ball.py), in the dynamic kernel and so in the quasi-static "
                            "power loss; default off: the factor is not yet proven against our own thermal inlet solution "
                            "(docs/power_loss.md)", default="off", choices=("on", "off")),
        "thermal_films": _f("choice", "guide-land and pocket films of the quasi-static power loss at their film temperature "
                            "(shear heat conducted into the two walls, models/ball_bearing/films.py): on, or off "
                            "(isothermal at the wall temperature, as before); the fill-fraction band is reported either way "
                            "(docs/power_loss.md)", default="on", choices=("on", "off")),
        "spin_torque_reading": _f("choice", "dgbb_prl spinning torque: dissipated power m_s omega_s / omega, or Tong-Hong projection sum |m_s| sin(alpha)", default="power", choices=("power", "projection")),
    },
    "thermal": {  # hsbearing thermal (docs/thermal.md); defaults are typical values, each with its origin
        "ambient_temperature": _f("temperature", "air around the housing and the shaft (default 20 degC: a test-rig room; "
                                  "an engine bearing chamber is hotter)", default="20 degC"),
        "oil_inlet_temperature": _f("temperature", "oil supply temperature (default: lubricant.temperature)"),
        "oil_specific_heat": _f("specific_heat", "oil specific heat c_p (default 2000 J/(kg K): synthetic ester "
                                "aviation oils, 1.9-2.1 kJ/(kg K) at 100-150 degC)", default="2000 J/(kg*K)", positive=True),
        "oil_thermal_conductivity": _f("thermal_conductivity", "oil thermal conductivity (default: the oil's K of the traction "
                                       "model, Zhang et al. 2016 Table 1: 0.0966 W/(m K) for 4109)", positive=True),
        "steel_thermal_conductivity": _f("thermal_conductivity", "rings, balls and shaft (default 42 W/(m K): AISI 52100 / "
                                         "GCr15, 40-46)", default="42 W/(m*K)", positive=True),
        "housing_thermal_conductivity": _f("thermal_conductivity", "housing (default 50 W/(m K): carbon steel)",
                                           default="50 W/(m*K)", positive=True),
        "housing_outside_diameter": _f("length", "housing outside diameter (default: 2 x bearing outside diameter, assumed)",
                                       positive=True),
        "housing_width": _f("length", "housing axial width (default: 2 x bearing width, assumed)", positive=True),
        "shaft_length": _f("length", "exposed shaft length, half each side of the bearing (default: 10 x bearing width, "
                           "assumed)", positive=True),
        "housing_convection": _f("heat_transfer_coefficient", "housing outer surfaces to the air (default 10 W/(m^2 K): "
                                 "free convection plus radiation, Incropera & DeWitt typical 2-25)", default="10 W/(m^2*K)",
                                 positive=True),
        "oil_convection": _f("heat_transfer_coefficient", "bearing surfaces to the oil; overrides the Harris & Kotzalas "
                             "correlation (docs/thermal.md)", positive=True),
        "tolerance": _f("number", "fixed-point tolerance on the lubricant temperature [K]", default=0.01, positive=True),
        "max_iterations": _f("int", "most fixed-point iterations (power <-> temperatures)", default=30, positive=True),
        "power_source": _f("choice", "the power loss the network is heated by: quasistatic (default: the kernel's sources "
                           "at the quasi-static state, race-control ball spin) or dynamic (means of a dynamic run of "
                           "thermal.dynamic_duration at each fixed-point iteration: the free ball's spin and the cage "
                           "whirl; docs/power_loss.md)", default="quasistatic", choices=("quasistatic", "dynamic")),
        "dynamic_duration": _f("time", "simulated time of each dynamic run of power_source = dynamic; its power is the "
                               "mean over the second half (default 0.1 s: the ball spin settles in ~10 ms, the cage "
                               "whirl of zhang2016 by ~40 ms)", default="0.1 s", positive=True),
    },
    "simulation": {
        "duration": _f("time", "simulated time", default="0.05 s", positive=True),
        "output_interval": _f("time", "output sampling interval", default="20 us", positive=True),
        "rtol": _f("number", "relative tolerance", default=1e-5, positive=True),
        "atol": _f("number", "absolute tolerance (scaled states)", default=1e-8, positive=True),
        "model": _f("str", "model variant", default="default"),
        "kinematics": _f("choice", "quasi-static ball kinematics", default="outer_race_control",
                         choices=("outer_race_control", "inner_race_control", "friction")),
        "section": _f("choice", "Poincare section of the cage-motion classification: transverse (half-plane of the "
                      "cage-centre state, crossed in the sense of the whirl; default), cage_revolution (once per cage "
                      "revolution, stroboscopic) or plane (D_Z = mean, upward)", default="transverse",
                      choices=("transverse", "cage_revolution", "plane")),
        "stop": _f("choice", "when a dynamic run stops: duration (run the whole duration) or converged (stop when the "
                   "cage-motion label, its kind and the summaries have held over a confirming interval; duration is then "
                   "the upper bound; rule and thresholds: hsbearing.analysis.stoprule, docs/sweeps.md)", default="duration",
                   choices=("duration", "converged")),
        "start_positions": _f("int", "gyro model (Jiang et al. 2014): cage start positions of the SFMC start ensemble (extra constant-rate "
                              "starts of one oscillation_period, cage turned over -1/2..+1/2 of its pocket play); 1 = none",
                              default=1, positive=True, maximum=MAX_START_POSITIONS),
    },
}

TABLES = tuple(SCHEMA)

#: Conformity f = r/D at or above which a groove is no ball-bearing groove (f = 1: groove radius = ball diameter;
#: catalogue bearings 0.505-0.58, Harris & Kotzalas, Essential Concepts of Bearing Technology, Ch. 2).
MAX_CONFORMITY = 1.0
