"""Case files: TOML with unit strings -> frozen dataclasses in SI.

A case is a TOML file with the tables ``[case]``, ``[bearing]``, ``[cage]``,
``[materials.ball]``, ``[materials.races]``, ``[materials.cage]``,
``[lubricant]``, ``[operating]``, ``[simulation]``, ``[friction]`` and ``[thermal]``.
Quantities are strings with units (``"9.525 mm"``, ``"14000 rpm"``,
``"130 degC"``, ``"1 kN"``); dimensionless numbers are plain numbers.  Every
value is converted once, here, to SI (m, kg, s, N, rad, rad/s, K, Pa).

The whole schema is the table :data:`SCHEMA` below: one :class:`Field` per
key, with its dimension, whether it is required, its default and its checks.
The frozen dataclasses (:class:`Case`, ``case.bearing`` ...) are generated
from it, so a key is declared exactly once.

Errors in a case raise :class:`CaseError`, whose one-line message names the
file and the key (the CLI prints it and exits with code 2).
"""

from __future__ import annotations

import dataclasses
import difflib
import math
import os
import re
import tomllib
from dataclasses import dataclass
from importlib import resources
from pathlib import Path
from typing import Any, Mapping

from hsbearing.errors import CaseError  # defined in errors (below models/); case.CaseError is the same class

__all__ = [
    "Case",
    "CaseError",
    "Field",
    "SCHEMA",
    "SYSTEMS",
    "load_case",
    "list_cases",
    "case_path",
    "resolve_key",
    "parse_quantity",
]

#: Closed vocabulary of the bearing systems a case can describe.
SYSTEMS = ("angular_contact", "deep_groove", "gyro_ribbon_cage", "wire_race")

#: Most cage start positions of the gyro SFMC start ensemble (each one is a run of one oscillation period).
MAX_START_POSITIONS = 64

from hsbearing.units import DIMENSIONS  # noqa: E402,F401 - dimension name -> SI unit string (public here)


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
        "inner_ring_mass": _f("mass", "inner ring (+ shaft) mass m_i", positive=True),
        "inner_ring_axial_inertia": _f("inertia", "inner ring polar moment of inertia", positive=True),
        "inner_ring_diametral_inertia": _f("inertia", "inner ring diametral moment of inertia", positive=True),
        # --- wire race bearing (seed 001) ---
        "wire_diameter": _f("length", "wire race diameter d_w (seed 001)", positive=True),
        "wire_groove_conformity": _f("number", "wire groove conformity r_groove/D (seed 001)"),
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
        # --- ribbon cage (seed 000) ---
        "thickness": _f("length", "ribbon cage thickness s (seed 000)", positive=True),
        "pocket_depth": _f("length", "ribbon cage pocket depth k (seed 000)", positive=True),
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
        "viscosity_law": _f("choice", "viscosity-temperature law: walther (ASTM D341 through the oil class's 40/100 degC data) or table1 (seed 004 Table 1 exponential)", default="walther", choices=("walther", "table1")),
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
        # --- gyro bearing (seed 000) ---
        "mode": _f("choice", "constant rate or oscillation (seed 000)", default="constant", choices=("constant", "oscillation")),
        "oscillation_period": _f("time", "period of the speed reversal (seed 000)", default="2 s", positive=True),
        "ramp_time": _f("time", "time to reach outer_speed from rest at constant acceleration (seed 000 Eq. 17)", positive=True),
        # --- wire race (seed 001) ---
        "preload": _f("length", "preload magnitude delta (seed 001)", nonneg=True),
        "framework_weight": _f("force", "gravity of the outer framework G_o (seed 001)", nonneg=True),
    },
    "friction": {
        "coefficient": _f("number", "Coulomb friction coefficient (ball/race, ball/cage)", default=0.07, nonneg=True),
        "cage_coefficient": _f("number", "ball/cage pocket friction coefficient", default=0.1, nonneg=True),
        "hysteresis_loss": _f("number", "elastic hysteresis loss fraction alpha_r", default=0.008, nonneg=True),
        "viscous_factor": _f("number", "Palmgren lubrication factor f_0 of the viscous moment M_L (seed 000 Eq. 2)", nonneg=True),
        "cage_restitution": _f("number", "ball/cage impact coefficient of restitution (Hunt-Crossley damping, seed 000 model)", minimum=0.0, maximum=1.0),
        "rolling_resistance": _f("length", "rolling-friction resistance coefficient zeta (seed 001)", nonneg=True),
        "unconsidered_torque": _f("moment", "torque not covered by the model M_u (seed 001)", nonneg=True),
        "law": _f("choice", "sliding friction law", default="stribeck", choices=("stribeck", "coulomb")),
        # --- SKF 2004 frictional-moment model / seed 003 Stribeck-type coefficient ---
        "boundary_coefficient": _f("number", "boundary-film sliding coefficient mu_bl (SKF model; 0.15 mineral oil)", default=0.15, nonneg=True),
        "ehl_coefficient": _f("number", "full-film sliding coefficient mu_EHL (SKF model; 0.05 mineral oil)", default=0.05, nonneg=True),
        "static_load_rating": _f("force", "basic static load rating C_0 (SKF model contact angle alpha_F)", positive=True),
        "skf_reading": _f("choice", "G_sl under combined load: SKF catalogue, or the seed 003 reading", default="catalogue", choices=("catalogue", "seed003")),
        "skf_drag_variable": _f("number", "SKF drag-loss variable V_M read from the catalogue diagram (oil bath only)", nonneg=True),
        "spin_torque_reading": _f("choice", "seed 003 spinning torque: dissipated power m_s omega_s / omega, or Tong-Hong projection sum |m_s| sin(alpha)", default="power", choices=("power", "projection")),
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
                   "the upper bound; rule and thresholds: hsbearing.stoprule, docs/sweeps.md)", default="duration",
                   choices=("duration", "converged")),
        "start_positions": _f("int", "gyro model (seed 000): cage start positions of the SFMC start ensemble (extra constant-rate "
                              "starts of one oscillation_period, cage turned over -1/2..+1/2 of its pocket play); 1 = none",
                              default=1, positive=True, maximum=MAX_START_POSITIONS),
    },
}

TABLES = tuple(SCHEMA)

# ----------------------------------------------------------------------------
# units: hsbearing.units (parse_quantity and its checks; re-exported here, where they always were)

from hsbearing.units import (  # noqa: E402,F401,I001 - the public names of the case module
    _ANGULAR_KINDS,
    MAX_MAGNITUDE,
    MAX_QUANTITY_CHARS,
    _a,
    _angular_si,
    _check_quantity_text,
    _example_unit,
    _has_angle_unit,
    _ureg,
    parse_quantity,
)

# ----------------------------------------------------------------------------
# dataclasses generated from the schema


def _make_dataclass(name: str, fields: Mapping[str, Field], extra: tuple = ()):
    spec = []
    for key, fld in fields.items():
        typ = {"int": int, "str": str, "choice": str, "bool": bool}.get(fld.kind, float)
        spec.append((key, typ | None, dataclasses.field(default=None, metadata={"schema": fld})))
    spec.extend(extra)  # derived attributes that are not case-file keys (no "schema" metadata)
    cls = dataclasses.make_dataclass(name, spec, frozen=True)
    cls.__module__ = __name__  # picklable as hsbearing.case.<name> (process pools, dask)
    return cls


Bearing = _make_dataclass("Bearing", SCHEMA["bearing"])
Cage = _make_dataclass("Cage", SCHEMA["cage"])
Material = _make_dataclass("Material", SCHEMA["materials.ball"])
#: ``case.lubricant.definition`` is the parsed lubricant file (:class:`hsbearing.lubricant.LubricantDefinition`)
#: when the oil comes from one, else None.
Lubricant = _make_dataclass("Lubricant", SCHEMA["lubricant"],
                            extra=(("definition", Any, dataclasses.field(default=None, compare=False)),))
Operating = _make_dataclass("Operating", SCHEMA["operating"])
Friction = _make_dataclass("Friction", SCHEMA["friction"])
Simulation = _make_dataclass("Simulation", SCHEMA["simulation"])
Thermal = _make_dataclass("Thermal", SCHEMA["thermal"])
CaseInfo = _make_dataclass("CaseInfo", SCHEMA["case"])


@dataclass(frozen=True)
class Materials:
    ball: Any
    races: Any
    cage: Any


@dataclass(frozen=True)
class Case:
    """A validated case in SI units.  Build it with :func:`load_case`."""

    info: Any
    bearing: Any
    cage: Any
    materials: Materials
    lubricant: Any
    operating: Any
    friction: Any
    simulation: Any
    thermal: Any = None  #: the [thermal] table (hsbearing thermal)
    text: str = ""  #: the TOML text (with overrides appended as comments)
    source: str = "<string>"
    raw: Any = None  #: the raw TOML dict after overrides (for re-serialisation)
    overrides: Any = None  #: the ``table.key -> value`` overrides applied to ``text`` (in order)

    @property
    def name(self) -> str:
        return self.info.name

    @property
    def system(self) -> str:
        return self.info.system

    def with_overrides(self, **overrides) -> "Case":
        """A new case from the same text with ``table.key=value`` overrides."""
        merged = dict(self.overrides or {})
        merged.update(overrides)
        return _build(self.raw_text_base, self.source, merged)

    @property
    def raw_text_base(self) -> str:
        return self.text.split("\n# --- overrides ---")[0]

    def to_toml(self) -> str:
        """The case as TOML text, overrides applied (round-trips through :func:`load_case`)."""
        return _dump_toml(self.raw)


# ----------------------------------------------------------------------------
# loading


def _cases_dir() -> Path:
    return Path(str(resources.files("hsbearing") / "cases"))


def list_cases() -> dict[str, str]:
    """Bundled case names -> one-line description."""
    out = {}
    for p in sorted(_cases_dir().glob("*.toml")):
        try:
            data = tomllib.loads(p.read_text())
            out[p.stem] = data.get("case", {}).get("description", "")
        except tomllib.TOMLDecodeError:
            out[p.stem] = "(unreadable)"
    return out


def case_path(name_or_path: str | Path) -> Path:
    """Resolve a bundled case name or a path to a file path."""
    p = Path(name_or_path)
    bundled = _cases_dir() / f"{name_or_path}.toml"
    if p.is_dir() and not p.suffix and bundled.exists() and p.name == str(name_or_path):
        return bundled  # a directory that happens to carry a bundled case's name does not hide the case
    if p.suffix in (".toml", ".nc") or p.exists():
        if not p.exists():
            raise CaseError(str(p), None, "no such case file" if p.suffix == ".toml" else "no such archive")
        if p.is_dir():
            raise CaseError(str(p), None, "is a directory, not a case file")
        return p
    cand = _cases_dir() / f"{name_or_path}.toml"
    if cand.exists():
        return cand
    names = sorted(list_cases())
    close = difflib.get_close_matches(str(name_or_path), names, n=1)
    hint = f"; did you mean {close[0]!r}?" if close else ""
    raise CaseError(str(name_or_path), None, f"no such case file or bundled case{hint} (bundled: {', '.join(names)})")


DEFAULT_CASE = "zhang2016"


def load_case(name_or_path: str | Path | None = None, /, **overrides) -> Case:
    """Load, convert and validate a case.

    Parameters
    ----------
    name_or_path : a bundled case name (``"zhang2016"``), a path to a TOML
        file, or None for the default case.
    **overrides : ``{"operating.axial_load": "2 kN"}``; a bare key such as
        ``axial_load`` is accepted when it names exactly one table's key.
    """
    path = case_path(name_or_path or DEFAULT_CASE)
    return _build(read_case_text(path), str(path), overrides)


def _special_file_kind(path) -> str | None:
    """What ``path`` is when it exists and is neither a regular file nor a directory (device, FIFO, socket)."""
    import stat

    try:
        mode = os.stat(path).st_mode
    except (OSError, ValueError):
        return None
    for test, name in ((stat.S_ISCHR, "a character device"), (stat.S_ISBLK, "a block device"),
                       (stat.S_ISFIFO, "a FIFO (named pipe)"), (stat.S_ISSOCK, "a socket")):
        if test(mode):
            return name
    return None if (stat.S_ISREG(mode) or stat.S_ISDIR(mode)) else "not a regular file"


def read_case_text(path: str | Path) -> str:
    """The TOML text of a case file, or of the case stored in an hsbearing archive (``.nc``).

    Anything else (a directory, a file that is not UTF-8 text, a netCDF file without a stored case)
    raises :class:`CaseError` naming the path.
    """
    path = Path(path)
    if path.is_dir():
        raise CaseError(str(path), None, "is a directory, not a case file")
    kind = _special_file_kind(path)  # before opening: reading a FIFO or a terminal device blocks for ever
    if kind:
        raise CaseError(str(path), None, f"is {kind}, not a case file (give a regular TOML file)")
    try:
        with open(path, "rb") as fh:
            head = fh.read(8)
    except OSError as exc:
        raise CaseError(str(path), None, f"cannot read the case file ({exc.strerror or type(exc).__name__})") from None
    if head.startswith((b"\x89HDF", b"CDF")):  # a netCDF archive: the case stored in it (``hsbearing run OUT.nc``)
        return case_text_from_archive(path)
    if path.suffix == ".nc":
        raise CaseError(str(path), None, "not a netCDF archive (and not a TOML case: the name ends in .nc)")
    try:
        return path.read_bytes().decode("utf-8")
    except UnicodeDecodeError as exc:
        raise CaseError(str(path), None, f"not a UTF-8 text file (byte {exc.start}); TOML case files must be UTF-8") from None
    except OSError as exc:
        raise CaseError(str(path), None, f"cannot read the case file ({exc.strerror or type(exc).__name__})") from None


def case_text_from_archive(path: str | Path) -> str:
    """The case TOML (global attribute ``case_toml``) stored in an archive written by hsbearing."""
    try:
        import netCDF4

        with netCDF4.Dataset(str(path), "r") as nc:
            text = nc.getncattr("case_toml") if "case_toml" in nc.ncattrs() else None
    except Exception as exc:  # noqa: BLE001 - any HDF/netCDF failure is "not a readable archive"
        raise CaseError(str(path), None, f"not a readable netCDF archive ({type(exc).__name__})") from None
    if not isinstance(text, str) or not text.strip():
        raise CaseError(str(path), "case_toml", "the archive stores no case (not written by hsbearing run)")
    return text


def loads_case(text: str, source: str = "<string>", **overrides) -> Case:
    """Like :func:`load_case` from TOML text."""
    return _build(text, source, overrides)


def resolve_key(key: str, source: str = "<override>") -> tuple[str, str]:
    """``"operating.axial_load"`` or ``"axial_load"`` -> (table, key)."""
    if "." in key:
        table, _, leaf = key.rpartition(".")
        if table not in SCHEMA:
            close = difflib.get_close_matches(table, TABLES, n=1)
            hint = f"; did you mean {close[0]!r}?" if close else ""
            raise CaseError(source, key, f"unknown table {table!r}{hint}")
        if leaf not in SCHEMA[table]:
            close = difflib.get_close_matches(leaf, list(SCHEMA[table]), n=1)
            hint = f"; did you mean '{table}.{close[0]}'?" if close else ""
            raise CaseError(source, key, f"unknown key{hint}")
        return table, leaf
    hits = [t for t in SCHEMA if key in SCHEMA[t]]
    if key == "oil":
        hits = ["lubricant"]
    if len(hits) == 1:
        return hits[0], key
    if not hits:
        allkeys = [f"{t}.{k}" for t in SCHEMA for k in SCHEMA[t]]
        close = difflib.get_close_matches(key, [a.rpartition(".")[2] for a in allkeys], n=1)
        hint = f"; did you mean {close[0]!r}?" if close else ""
        raise CaseError(source, key, f"unknown key{hint}")
    raise CaseError(source, key, f"ambiguous key, name the table: {', '.join(h + '.' + key for h in hits)}")


def _parse_override_value(value: Any) -> Any:
    if not isinstance(value, str):
        return value
    try:
        return tomllib.loads(f"v = {value}")["v"]
    except (tomllib.TOMLDecodeError, RecursionError):
        return value


def _get_table(raw: dict, table: str) -> dict:
    node = raw
    for part in table.split("."):
        node = node.setdefault(part, {})
    return node


def _build(text: str, source: str, overrides: Mapping[str, Any]) -> Case:
    overridden = {".".join(resolve_key(k, source=f"{source} (override)")) for k in (overrides or {})}
    try:
        return _build_checked(text, source, overrides)
    except CaseError as exc:
        if exc.key in overridden and not exc.source.endswith("(override)"):
            # the file is fine; the value given on top of it is not: name the override as the source
            raise CaseError(f"{exc.source} (override)", exc.key, exc.message) from None
        raise


#: Deepest nesting of arrays / inline tables accepted in a case file (a case needs 3: [materials.ball]).
MAX_TOML_DEPTH = 20


def _toml_depth(text: str) -> int:
    """Upper bound of the bracket nesting of ``text`` (strings and comments skipped roughly: a bound, not a parse)."""
    depth = best = 0
    quote = None
    i, n = 0, len(text)
    while i < n:
        ch = text[i]
        if quote:
            if ch == "\\" and quote == '"':
                i += 2
                continue
            if ch == quote or ch == "\n":
                quote = None
        elif ch in "\"'":
            quote = ch
        elif ch == "#":
            j = text.find("\n", i)
            i = n if j < 0 else j
            continue
        elif ch in "[{":
            depth += 1
            best = max(best, depth)
        elif ch in "]}":
            depth = max(0, depth - 1)
        i += 1
    return best


def _toml_loads(text: str, source: str) -> dict:
    """``tomllib.loads`` with every failure as a CaseError: malformed TOML, nesting deep enough to exhaust the
    recursion (tomllib parses nested arrays recursively: RecursionError)."""
    if _toml_depth(text) > MAX_TOML_DEPTH:
        raise CaseError(source, None, f"malformed TOML: arrays/inline tables nested deeper than {MAX_TOML_DEPTH} levels")
    try:
        return tomllib.loads(text)
    except tomllib.TOMLDecodeError as exc:
        raise CaseError(source, None, f"malformed TOML: {exc}") from None
    except RecursionError:
        raise CaseError(source, None, "malformed TOML: nested too deeply") from None


def _build_checked(text: str, source: str, overrides: Mapping[str, Any]) -> Case:
    raw = _toml_loads(text, source)
    override_lines = []
    for k, v in (overrides or {}).items():
        table, leaf = resolve_key(k, source=f"{source} (override)")
        _get_table(raw, table)[leaf] = _override_literal(SCHEMA[table][leaf].kind, v)
        override_lines.append(f"# {table}.{leaf} = {v!r}")
    full_text = text if not override_lines else text.rstrip("\n") + "\n# --- overrides ---\n" + "\n".join(override_lines) + "\n"
    values = _validate_tables(raw, source)
    over_lub = {resolve_key(k, source=f"{source} (override)")[1] for k in (overrides or {})
                if resolve_key(k, source=f"{source} (override)")[0] == "lubricant"}
    oil_definition = _apply_lubricant_file(raw, values, source, over_lub)
    info = CaseInfo(**values["case"])
    mats = Materials(
        ball=Material(**values["materials.ball"]),
        races=Material(**values["materials.races"]),
        cage=Material(**values["materials.cage"]),
    )
    case = Case(
        info=info,
        bearing=Bearing(**values["bearing"]),
        cage=Cage(**values["cage"]),
        materials=mats,
        lubricant=Lubricant(**values["lubricant"], definition=oil_definition),
        operating=Operating(**values["operating"]),
        friction=Friction(**values["friction"]),
        simulation=Simulation(**values["simulation"]),
        thermal=Thermal(**values["thermal"]),
        text=full_text,
        source=source,
        raw=raw,
        overrides=dict(overrides or {}),
    )
    _check_physical(case, source)
    _check_possible(case, source)
    return case


def _apply_lubricant_file(raw: dict, values: dict, source: str, overridden: set | None = None):
    """A lubricant file (``lubricant.file``, or ``lubricant.oil`` naming a bundled lubricant or a .toml file)
    -> its :class:`~hsbearing.lubricant.LubricantDefinition`; fills the lubricant values at the case
    temperature (nu, rho, alpha) that the case does not give itself, and names the traction law.  None
    when the oil is a built-in name (4109, 4106, 4050).  The file's text is embedded in ``raw`` (key
    ``lubricant.file_text``), so the archived case and its hash carry the oil's data."""
    from hsbearing import lubricant as lubmod
    from hsbearing.models import traction

    lub = values["lubricant"]
    node = raw.get("lubricant", {}) if isinstance(raw.get("lubricant"), dict) else {}
    spec, key = lub.get("file"), "lubricant.file"
    if spec is None:
        oil = lub.get("oil")
        if oil is None or oil in traction.OILS:
            return None
        if not (str(oil).endswith(".toml") or lubmod.bundled_path(oil) is not None):
            return None  # unknown name: _check_physical says so, listing the known ones
        spec, key = oil, "lubricant.oil"
    base = Path(source).parent if Path(source).suffix == ".toml" and Path(source).is_file() else None
    path = lubmod.resolve_lubricant(spec, base_dir=base)
    if path is not None:
        definition = lubmod.load_lubricant(path)
    elif lub.get("file_text"):  # the file is gone: the copy embedded when the case was saved
        definition = lubmod.loads_lubricant(lub["file_text"], f"{source} ({key} = {spec!r}, embedded copy)",
                                            default_name=Path(str(spec)).stem)
    else:
        raise CaseError(source, key, lubmod.unresolved_message(spec))
    raw.setdefault("lubricant", {})["file_text"] = definition.text
    lub["file_text"] = definition.text
    T = lub["temperature"]
    # Which of the case's own oil-property keys win over the file's values: those given as overrides; and
    # those of the case file itself when the case file names the lubricant (a case file that names another oil
    # and gets this one by --set/--vary described the other oil: its keys the file supplies are dropped from
    # raw, so that the saved case reloads to the same values).
    supplied = {"kinematic_viscosity", "dynamic_viscosity", "pressure_viscosity_coefficient", "traction_law"}
    if definition.density_ref is not None:
        supplied.add("density")
    overridden = overridden or set()
    explicit = (set(node) & supplied) if not overridden & {"file", "oil"} else set()
    explicit |= overridden & supplied
    for k in supplied - explicit:
        if k in node:
            del node[k]
            lub[k] = SCHEMA["lubricant"][k].default and _convert(SCHEMA["lubricant"][k].default, SCHEMA["lubricant"][k],
                                                                  source, f"lubricant.{k}")
    lub["oil"] = definition.traction_oil
    if "traction_law" not in explicit:
        lub["traction_law"] = definition.traction_law
    if definition.density_ref is not None and "density" not in explicit:
        lub["density"] = definition.density(T)
    rho = lub["density"]
    try:
        if not explicit & {"kinematic_viscosity", "dynamic_viscosity"}:
            lub["kinematic_viscosity"] = float(definition.kinematic_viscosity(T, rho))
            lub["dynamic_viscosity"] = None
        if "pressure_viscosity_coefficient" not in explicit:
            lub["pressure_viscosity_coefficient"] = definition.alpha(T, rho)
    except (ValueError, FloatingPointError) as exc:
        raise CaseError(source, key, f"{definition.name} at {T - 273.15:g} degC: {exc}") from None
    for k in ("kinematic_viscosity", "pressure_viscosity_coefficient", "density"):
        v = lub.get(k)
        if v is not None and not (math.isfinite(v) and v > 0):
            raise CaseError(source, key, f"{definition.name} at {T - 273.15:g} degC gives {k.replace('_', ' ')} {v!r}: "
                                         "outside the range its data support")
    return definition


def _validate_tables(raw: dict, source: str) -> dict[str, dict[str, Any]]:
    # unknown tables
    known_top = {t.split(".")[0] for t in SCHEMA}
    for top, val in raw.items():
        if top not in known_top:
            close = difflib.get_close_matches(top, sorted(known_top), n=1)
            hint = f"; did you mean [{close[0]}]?" if close else ""
            raise CaseError(source, top, f"unknown table{hint} (known: {', '.join(sorted(known_top))})")
        if not isinstance(val, dict):
            raise CaseError(source, top, "expected a table")
    mats = raw.get("materials", {})
    for sub in mats:
        if f"materials.{sub}" not in SCHEMA:
            close = difflib.get_close_matches(sub, ["ball", "races", "cage"], n=1)
            hint = f"; did you mean [materials.{close[0]}]?" if close else ""
            raise CaseError(source, f"materials.{sub}", f"unknown table{hint}")
        if not isinstance(mats[sub], dict):
            raise CaseError(source, f"materials.{sub}", f"expected a table [materials.{sub}], got {mats[sub]!r}")
    system = raw.get("case", {}).get("system")
    if system is None:
        raise CaseError(source, "case.system", f"missing required key (one of: {', '.join(SYSTEMS)})")
    if system not in SYSTEMS:
        raise CaseError(source, "case.system", f"unknown system {system!r} (allowed: {', '.join(SYSTEMS)})")
    out: dict[str, dict[str, Any]] = {}
    for table, fields in SCHEMA.items():
        node = raw
        for part in table.split("."):
            node = node.get(part, {}) if isinstance(node, dict) else {}
        for key in node:
            if key not in fields:
                close = difflib.get_close_matches(key, list(fields), n=1)
                hint = f"; did you mean '{table}.{close[0]}'?" if close else ""
                raise CaseError(source, f"{table}.{key}", f"unknown key{hint}")
        vals = {}
        for key, fld in fields.items():
            full = f"{table}.{key}"
            required = fld.required == ALL or system in fld.required
            if key in node:
                v = node[key]
            elif fld.default is not None:
                v = fld.default
            elif required:
                if table.startswith("materials."):
                    raise CaseError(source, full, f"missing required key ({fld.doc})")
                raise CaseError(source, full, f"missing required key ({fld.doc})")
            else:
                vals[key] = None
                continue
            vals[key] = _convert(v, fld, source, full)
        out[table] = vals
    return out


#: Conformity f = r/D at or above which a groove is no ball-bearing groove (f = 1: groove radius = ball diameter;
#: catalogue bearings 0.505-0.58, Harris & Kotzalas, Essential Concepts of Bearing Technology, Ch. 2).
MAX_CONFORMITY = 1.0

#: Largest integer a case value may be (beyond it a float conversion overflows or loses the value).
MAX_INTEGER = 2**53


def _convert(v: Any, fld: Field, source: str, full: str) -> Any:
    """A case-file value of key ``full`` in its type (quantities in SI), range-checked."""
    return _check_range(_coerce(v, fld, source, full), v, fld, source, full)


def _coerce(v: Any, fld: Field, source: str, full: str) -> Any:
    """A case-file value of key ``full`` in its type, quantities in SI: the type rules without the range ones."""
    if fld.kind in ("str", "choice"):
        if fld.kind == "str" and not isinstance(v, str):
            raise CaseError(source, full, f"expected a string, got {v!r}")
        return v
    if fld.kind == "bool":
        if not isinstance(v, bool):
            raise CaseError(source, full, f"expected true or false, got {v!r}")
        return v
    if isinstance(v, int) and not isinstance(v, bool) and abs(v) > MAX_INTEGER:
        raise CaseError(source, full, f"integer with {len(str(abs(v)))} digits is beyond any value a case can hold "
                                      f"(at most {MAX_INTEGER:.3g})")
    if fld.kind == "int":
        if isinstance(v, bool) or not isinstance(v, int):
            raise CaseError(source, full, f"expected a whole number, got {v!r}")
        x = v
    elif fld.kind == "number":
        if isinstance(v, bool) or not isinstance(v, (int, float)):
            raise CaseError(source, full, f"expected a plain number, got {v!r}")
        x = float(v)
    else:
        x = parse_quantity(v, fld.kind, source=source, key=full)
    if not math.isfinite(x):
        raise CaseError(source, full, f"must be finite, got {v!r}")
    return x


def _check_range(x: Any, v: Any, fld: Field, source: str, full: str) -> Any:
    """``x`` (the value ``v`` as given, converted) within the key's vocabulary and bounds."""
    if fld.kind == "choice":
        if x not in fld.choices:
            raise CaseError(source, full, f"unknown value {v!r} (allowed: {', '.join(fld.choices)})")
        return x
    if fld.kind in ("str", "bool"):
        return x
    if fld.positive and x <= 0:
        raise CaseError(source, full, f"must be positive, got {v!r}")
    if fld.nonneg and x < 0:
        raise CaseError(source, full, f"must not be negative, got {v!r}")
    if fld.minimum is not None and x < fld.minimum:
        raise CaseError(source, full, f"must be >= {fld.minimum}, got {v!r}")
    if fld.maximum is not None and x > fld.maximum:
        raise CaseError(source, full, f"must be <= {fld.maximum}, got {v!r}")
    return x


def read_override(value: Any, fld: Field, *, source: str = "<override>", key: str | None = None) -> Any:
    """A value given for a key on top of a case (``--set``, a ``--vary`` item, a study table's value), read as
    :func:`load_case` reads an override: text is a TOML literal (``"0.52"``, ``"12"``, ``"true"``) or, for a
    dimension, a quantity (``"100 N"``; a bare number other than 0 is refused); str and choice keys keep the
    text.  Returns the value in the key's type, a quantity in SI.  The key's range checks (positive, bounds,
    choices) are left to the case: a value out of range makes an invalid case, not a bad value list."""
    return _coerce(_override_literal(fld.kind, value), fld, source, key or "<override>")


def _override_literal(kind: str, value: Any) -> Any:
    """An override as it goes into the case's TOML tables: str/choice keys as text, others a TOML literal
    when the text is one (``"0.52"`` -> 0.52; ``"100 N"`` stays text)."""
    return str(value) if kind in ("str", "choice") else _parse_override_value(value)


def _check_physical(case: Case, source: str) -> None:
    """Cross-key checks: conformities, balls on the pitch circle, pocket vs ball, oil."""
    b, c = case.bearing, case.cage
    for key in ("inner_conformity", "outer_conformity"):
        f = getattr(b, key)
        if f is not None and f <= 0.5:
            raise CaseError(source, f"bearing.{key}", f"conformity must be > 0.5 (groove radius larger than the ball radius), got {f}")
        if f is not None and f >= MAX_CONFORMITY:
            raise CaseError(source, f"bearing.{key}", f"conformity {f:g} means a groove radius of {f:g} ball diameters: "
                                                      f"not a ball-bearing groove (must be below {MAX_CONFORMITY:g}; "
                                                      "real bearings 0.505-0.58)")
    D, dm, Z = b.ball_diameter, b.pitch_diameter, b.ball_count
    if D >= dm:
        raise CaseError(source, "bearing.ball_diameter", f"ball diameter {D*1e3:g} mm is not smaller than the pitch diameter {dm*1e3:g} mm")
    chord = dm * math.sin(math.pi / Z)  # centre-to-centre distance of neighbouring balls
    if Z > 1 and chord <= D:
        raise CaseError(
            source, "bearing.ball_count",
            f"{Z} balls of {D*1e3:g} mm do not fit the pitch circle of {dm*1e3:g} mm (neighbour spacing {chord*1e3:.3f} mm)",
        )
    if c.pocket_diameter is not None and c.pocket_diameter <= D:
        raise CaseError(source, "cage.pocket_diameter", f"cage pocket {c.pocket_diameter*1e3:g} mm is not larger than the ball {D*1e3:g} mm")
    if b.bore_diameter is not None and b.outside_diameter is not None and b.bore_diameter >= b.outside_diameter:
        raise CaseError(source, "bearing.bore_diameter", "bore diameter must be smaller than the outside diameter")
    if b.width is not None and b.width < D:  # before the guide lands (a narrow ring leaves no land either)
        raise CaseError(source, "bearing.width", f"ring width {b.width * 1e3:g} mm is narrower than the ball {D * 1e3:g} mm")
    _check_guide_lands(case, source)
    if case.system in ("angular_contact", "deep_groove", "gyro_ribbon_cage"):
        from hsbearing.models import traction

        oil = case.lubricant.oil
        if oil not in traction.OILS:
            close = difflib.get_close_matches(oil, list(traction.OILS), n=1)
            hint = f"; did you mean {close[0]!r}?" if close else ""
            from hsbearing.lubricant import bundled_lubricants

            raise CaseError(source, "lubricant.oil", f"unknown oil {oil!r}{hint} (known: {', '.join(traction.OILS)}; "
                            f"bundled lubricants: {', '.join(bundled_lubricants())}; or a lubricant file path ending in .toml)")
        law = case.lubricant.traction_law
        d = case.lubricant.definition
        if law == traction.USER_LAW:
            if d is None or d.coefficients is None:
                raise CaseError(source, "lubricant.traction_law", "law 'user' needs a lubricant file with traction.model = "
                                "\"coefficients\" or \"table\" (docs/traction.md, \"Lubricant files\")")
        elif law not in traction.KNOWN_LAWS[oil]:
            raise CaseError(source, "lubricant.traction_law",
                            f"unknown traction law {law!r} for oil {oil} (known: {', '.join(traction.KNOWN_LAWS[oil])})")
        if case.system == "angular_contact" and case.lubricant.temperature <= 273.15 and traction.is_seed_law(law):
            raise CaseError(source, "lubricant.temperature",
                            "the seed 004 traction laws are fitted in degC and undefined at or below 0 degC")


def _check_guide_lands(case: Case, source: str) -> None:
    """Guide-land keys: land inside the cage, lands wider than the ring/cage, no land left by the groove."""
    if case.system not in ("angular_contact", "deep_groove") or case.cage is None:
        return
    from hsbearing.models.geometry import GuideLandError, guide_lands

    c = case.cage
    if c.guide_land_count == 0 and c.guidance != "ball":
        raise CaseError(source, "cage.guide_land_count", f"guidance = {c.guidance} needs at least one land (0 only for guidance = ball)")
    try:
        guide_lands(case)
    except GuideLandError as exc:
        raise CaseError(source, exc.key, exc.message) from None

#: Most output samples one run may store (duration / output_interval + 1); about 3 kB each for an
#: 11-ball bearing, so the limit keeps a run's arrays near 1.5 GB.
MAX_OUTPUT_SAMPLES = 500_000

#: A case name becomes a file name (``runs/<name>-<hash>.nc``): letters, digits, ``_ - . +``, no path.
_NAME = re.compile(r"^[A-Za-z0-9][A-Za-z0-9_.+-]{0,99}$")


def check_output_samples(case: "Case", duration: float | None = None, *, source: str | None = None,
                         key: str = "simulation.output_interval") -> int:
    """Number of output samples of a run of ``duration`` [s] (None: the case's); CaseError above the limit."""
    sim = case.simulation
    T = sim.duration if duration is None else float(duration)
    dt = min(sim.output_interval, T) if T > 0 else sim.output_interval
    n = T / dt + 1.0 if dt > 0 else math.inf
    if not n <= MAX_OUTPUT_SAMPLES:
        raise CaseError(source or case.source, key,
                        f"duration {T:g} s / output_interval {sim.output_interval:g} s gives {n:.3g} output samples "
                        f"(at most {MAX_OUTPUT_SAMPLES}): raise simulation.output_interval or shorten the duration")
    return int(n)


def _check_possible(case: Case, source: str) -> None:
    """Values that are each in range but impossible for a bearing, or unsafe as file names (issue 13, item 7)."""
    b, c, info = case.bearing, case.cage, case.info
    if not _NAME.match(info.name):
        raise CaseError(source, "case.name", f"{info.name!r} is not a plain file name (letters, digits, _ - . +; "
                                             "no path, no spaces; at most 100 characters): it names the output files")
    if b.contact_angle is not None and not b.contact_angle < 0.5 * math.pi:
        raise CaseError(source, "bearing.contact_angle",
                        f"must be below 90 deg (a radial or angular-contact bearing), got {math.degrees(b.contact_angle):g} deg")
    if case.lubricant.temperature is not None and not case.lubricant.temperature > 0:
        raise CaseError(source, "lubricant.temperature",
                        f"{case.lubricant.temperature:g} K is at or below absolute zero")
    D, dm = b.ball_diameter, b.pitch_diameter
    mm = lambda x: f"{x * 1e3:g} mm"  # noqa: E731
    if b.bore_diameter is not None and b.bore_diameter >= dm - D:
        raise CaseError(source, "bearing.bore_diameter", f"bore {mm(b.bore_diameter)} does not leave room for the "
                        f"inner raceway (pitch diameter {mm(dm)} - ball diameter {mm(D)} = {mm(dm - D)})")
    if b.outside_diameter is not None and b.outside_diameter <= dm + D:
        raise CaseError(source, "bearing.outside_diameter", f"outside diameter {mm(b.outside_diameter)} does not "
                        f"enclose the outer raceway (pitch diameter + ball diameter = {mm(dm + D)})")
    if b.inner_land_diameter is not None and not (b.bore_diameter or 0.0) < b.inner_land_diameter < dm:
        raise CaseError(source, "bearing.inner_land_diameter", f"{mm(b.inner_land_diameter)} must lie between the bore "
                        f"and the pitch diameter {mm(dm)}")
    if b.outer_land_diameter is not None and not dm < b.outer_land_diameter < (b.outside_diameter or math.inf):
        raise CaseError(source, "bearing.outer_land_diameter", f"{mm(b.outer_land_diameter)} must lie between the "
                        f"pitch diameter {mm(dm)} and the outside diameter")
    if c.outside_diameter is not None:
        if c.outside_diameter <= dm:
            raise CaseError(source, "cage.outside_diameter", f"cage outside diameter {mm(c.outside_diameter)} must be "
                            f"larger than the pitch diameter {mm(dm)} (the pockets straddle the pitch circle)")
        if b.outside_diameter is not None and c.outside_diameter >= b.outside_diameter:
            raise CaseError(source, "cage.outside_diameter", f"cage {mm(c.outside_diameter)} is larger than the "
                            f"bearing (outside diameter {mm(b.outside_diameter)})")
        if c.guidance == "outer_ring" and b.outer_land_diameter is not None and c.outside_diameter >= b.outer_land_diameter:
            raise CaseError(source, "bearing.outer_land_diameter", f"guide land {mm(b.outer_land_diameter)} is not "
                            f"larger than the outer-ring guided cage (cage.outside_diameter {mm(c.outside_diameter)})")
    if c.bore_diameter is not None:
        if c.bore_diameter >= dm:
            raise CaseError(source, "cage.bore_diameter", f"cage bore {mm(c.bore_diameter)} must be smaller than the "
                            f"pitch diameter {mm(dm)} (the pockets straddle the pitch circle)")
        if c.outside_diameter is not None and c.bore_diameter >= c.outside_diameter:
            raise CaseError(source, "cage.bore_diameter", "cage bore must be smaller than the cage outside diameter")
        if b.bore_diameter is not None and c.bore_diameter <= b.bore_diameter:
            raise CaseError(source, "cage.bore_diameter", f"cage bore {mm(c.bore_diameter)} is inside the bearing bore "
                            f"{mm(b.bore_diameter)}")
        if c.guidance == "inner_ring" and b.inner_land_diameter is not None and c.bore_diameter <= b.inner_land_diameter:
            raise CaseError(source, "bearing.inner_land_diameter", f"guide land {mm(b.inner_land_diameter)} is not "
                            f"smaller than the inner-ring guided cage bore (cage.bore_diameter {mm(c.bore_diameter)})")
    _check_envelope(case, source)
    check_output_samples(case, source=source)


#: Temperature envelope of the bundled oils [degC]: (pour point, lowest service temperature, highest service
#: temperature) of the specification class each oil is read as (hsbearing.models.viscosity.OIL_SPEC):
#: MIL-PRF-7808 (4109) and MIL-PRF-23699 (4106, 4050) turbine oils, pour points -60 / -54 degC (spec maxima),
#: service ranges -51..204 and -40..204 degC (the specs' qualification ranges).  Beyond the service range the
#: oil data (40/100 degC viscosities, the traction fits) are extrapolated: a warning.  Below the pour point
#: the oil does not flow, above OIL_DECOMPOSITION_C ester base stocks decompose thermally: an error.
OIL_TEMPERATURE_C: dict[str, tuple[float, float, float]] = {
    "4109": (-60.0, -51.0, 204.0),
    "4106": (-54.0, -40.0, 204.0),
    "4050": (-54.0, -40.0, 204.0),
}
#: Above this [degC] no lubricating oil of the bundled classes is a liquid film (thermal decomposition of the
#: ester base stock; flash points of the classes 210-270 degC): refused.
OIL_DECOMPOSITION_C = 350.0


def _free_contact_angle(b) -> float | None:
    """Free contact angle [rad] implied by the diametral clearance (None if no clearance is given)."""
    if b.diametral_clearance is None or b.inner_conformity is None or b.outer_conformity is None:
        return None
    A = (b.inner_conformity + b.outer_conformity - 1.0) * b.ball_diameter
    c = 1.0 - b.diametral_clearance / (2.0 * A)
    return math.acos(max(-1.0, min(1.0, c))) if c > -1.0 else math.pi


def _check_envelope(case: Case, source: str) -> None:
    """Impossible bearings (issue 27, class 7): whatever does not fit in the bearing's envelope."""
    b, c = case.bearing, case.cage
    D, dm, Z = b.ball_diameter, b.pitch_diameter, b.ball_count
    mm = lambda x: f"{x * 1e3:g} mm"  # noqa: E731
    if case.system in ("angular_contact", "deep_groove") and b.diametral_clearance is not None:
        A = (b.inner_conformity + b.outer_conformity - 1.0) * D
        alpha = _free_contact_angle(b)
        if alpha is not None and not alpha < 0.5 * math.pi:
            raise CaseError(source, "bearing.diametral_clearance",
                            f"{b.diametral_clearance * 1e6:g} um gives a free contact angle of "
                            f"{math.degrees(alpha):.4g} deg (>= 90 deg: the balls would not be held between the "
                            f"rings); it must be below 2 (f_i + f_o - 1) D = {2 * A * 1e6:.4g} um")
    if c is not None:
        if c.width is not None and b.width is not None and c.width > b.width:
            raise CaseError(source, "cage.width", f"cage width {mm(c.width)} is wider than the bearing "
                                                  f"(bearing.width {mm(b.width)})")
        dp = c.pocket_diameter if c.pocket_diameter is not None else (
            D + 2.0 * c.pocket_clearance if c.pocket_clearance is not None else None)
        if dp is not None and Z > 1:
            chord = dm * math.sin(math.pi / Z)  # centre distance of neighbouring pockets
            if dp >= chord:
                key = "cage.pocket_diameter" if c.pocket_diameter is not None else "cage.pocket_clearance"
                raise CaseError(source, key, f"{Z} pockets of {mm(dp)} overlap on the pitch circle of {mm(dm)} "
                                             f"(neighbour spacing {chord * 1e3:.4g} mm): no cage bar is left between them")
        if (case.system in ("angular_contact", "deep_groove") and dp is not None and c.width is not None
                and c.width <= dp):
            raise CaseError(source, "cage.width", f"cage width {mm(c.width)} is not wider than its pockets ({mm(dp)}): "
                                                  "the pockets cut the cage ring through")
        if c.pocket_depth is not None and c.pocket_depth <= 0.5 * D:
            raise CaseError(source, "cage.pocket_depth", f"pocket depth {mm(c.pocket_depth)} is not deeper than the ball "
                                                         f"radius {mm(0.5 * D)}: the ball does not fit the pocket")
        if c.mass is None and c.outside_diameter and c.bore_diameter and c.width and dp is not None:
            vol = math.pi / 4 * (c.outside_diameter**2 - c.bore_diameter**2) * c.width \
                - Z * math.pi / 4 * dp**2 * (c.outside_diameter - c.bore_diameter) / 2
            if not vol > 0:
                raise CaseError(source, "cage.pocket_diameter", f"the {Z} pockets of {mm(dp)} remove the whole cage "
                                                                "(computed cage mass 0 g): give smaller pockets or cage.mass")
    if case.system == "angular_contact" and case.operating.axial_load < 0:
        raise CaseError(source, "operating.axial_load",
                        f"{case.operating.axial_load:g} N: a single angular-contact bearing carries axial load in one "
                        "direction only (positive: the inner ring pushed along +X into its contacts); a negative load "
                        "lifts the balls off the contact angle -- mount the bearing the other way round (give the "
                        "load as positive)")
    oil, T = case.lubricant.oil, case.lubricant.temperature
    if T is not None:
        t_c = T - 273.15
        if t_c > OIL_DECOMPOSITION_C:  # any system: no lubricating oil film there
            raise CaseError(source, "lubricant.temperature", f"{t_c:g} degC: no oil film at this temperature (the "
                                                             f"turbine-oil classes decompose above ~{OIL_DECOMPOSITION_C:g} degC)")
        if _oil_data_used(case):  # the oil's own data: below its pour point it does not flow
            pour, _, _ = OIL_TEMPERATURE_C[oil]
            if t_c < pour:
                raise CaseError(source, "lubricant.temperature", f"{t_c:g} degC is below the pour point of oil {oil} "
                                                                 f"({pour:g} degC): the oil does not flow")


def _oil_data_used(case: Case) -> bool:
    """The model reads the named oil's data (viscosity, traction): the angular-contact model with a bundled oil
    (the other systems carry the oil name as a placeholder and use their own viscosity)."""
    return (case.system == "angular_contact" and case.lubricant.oil in OIL_TEMPERATURE_C
            and getattr(case.lubricant, "file", None) is None)


def envelope_warnings(case: Case) -> list[str]:
    """Values inside what is possible but outside the data behind the model (printed as warnings by the CLI)."""
    out = []
    oil, T = case.lubricant.oil, case.lubricant.temperature
    if T is not None and _oil_data_used(case):
        _, lo, hi = OIL_TEMPERATURE_C[oil]
        t_c = T - 273.15
        if not lo <= t_c <= hi:
            out.append(f"lubricant.temperature: {t_c:g} degC is outside the service range of oil {oil} "
                       f"({lo:g}..{hi:g} degC): its viscosity and traction data are extrapolated")
    return out


# ----------------------------------------------------------------------------
# tiny TOML writer for the raw dict (strings, numbers, bools, nested tables)


def _dump_toml(raw: Mapping[str, Any]) -> str:
    lines: list[str] = []

    def scalar(v):
        if isinstance(v, bool):
            return "true" if v else "false"
        if isinstance(v, (int, float)):
            return repr(v)
        if isinstance(v, str):
            return _toml_string(v)
        if isinstance(v, list):
            return "[" + ", ".join(scalar(x) for x in v) + "]"
        raise TypeError(type(v))

    def emit(prefix: str, table: Mapping[str, Any]):
        plain = {k: v for k, v in table.items() if not isinstance(v, dict)}
        subs = {k: v for k, v in table.items() if isinstance(v, dict)}
        if prefix and plain:
            lines.append(f"[{prefix}]")
        for k, v in plain.items():
            lines.append(f"{_toml_key(k)} = {scalar(v)}")
        if plain:
            lines.append("")
        for k, v in subs.items():
            emit(f"{prefix}.{_toml_key(k)}" if prefix else _toml_key(k), v)

    emit("", raw)
    return "\n".join(lines)


_TOML_ESCAPES = {"\\": "\\\\", '"': '\\"', "\b": "\\b", "\t": "\\t", "\n": "\\n", "\f": "\\f", "\r": "\\r"}


def _toml_string(v: str) -> str:
    """A TOML basic string: quote, backslash and every control character escaped (TOML 1.0, "String")."""
    out = []
    for ch in v:
        if ch in _TOML_ESCAPES:
            out.append(_TOML_ESCAPES[ch])
        elif ord(ch) < 0x20 or ord(ch) == 0x7F:
            out.append(f"\\u{ord(ch):04X}")
        else:
            out.append(ch)
    return '"' + "".join(out) + '"'


_BARE_KEY = re.compile(r"^[A-Za-z0-9_-]+$")


def _toml_key(k: str) -> str:
    return k if _BARE_KEY.match(k) else _toml_string(k)


def parse_sets(items: list[str] | None, source: str = "--set") -> dict[str, str]:
    """``["table.key=value", ...]`` (the CLI's repeated ``--set``) -> ``{"table.key": "value"}``; CaseError
    naming ``source`` for an item without ``=``."""
    out = {}
    for item in items or []:
        if "=" not in item:
            raise CaseError(source, item, "expected key=value, e.g. --set operating.axial_load=\"2 kN\"")
        k, _, v = item.partition("=")
        out[k.strip()] = v.strip()
    return out


def as_case(case, overrides=None) -> "Case":
    """A :class:`Case` as given (with ``overrides`` applied), or loaded from a bundled name / path."""
    if isinstance(case, Case):
        return case.with_overrides(**overrides) if overrides else case
    return load_case(case, **(overrides or {}))
