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

By concern: ``schema`` (every key once: dimension, default, bounds, vocabulary, one-line doc), ``load`` (the frozen dataclasses generated from the schema; bundled cases, TOML reading, overrides, unit conversion, lubricant files), ``checks`` (values that are each valid but impossible together, the bearing envelope, the oil's service range), ``toml`` (the case TOML writer).
"""

from __future__ import annotations

from hsbearing.case.checks import (  # noqa: F401
    MAX_OUTPUT_SAMPLES,
    OIL_DECOMPOSITION_C,
    OIL_TEMPERATURE_C,
    check_envelope,
    check_guide_lands,
    check_output_samples,
    check_physical,
    check_possible,
    envelope_warnings,
)
from hsbearing.case.load import (  # noqa: F401
    CHOICE_ALIASES,
    DEFAULT_CASE,
    MAX_INTEGER,
    MAX_TOML_DEPTH,
    Bearing,
    Cage,
    Case,
    CaseInfo,
    Friction,
    Lubricant,
    Material,
    Materials,
    Operating,
    Simulation,
    Thermal,
    as_case,
    case_path,
    case_text_from_archive,
    list_cases,
    load_case,
    loads_case,
    parse_sets,
    read_case_text,
    read_override,
    resolve_key,
)
from hsbearing.case.schema import (  # noqa: F401
    AC_DG,
    ALL,
    MAX_CONFORMITY,
    MAX_START_POSITIONS,
    ROLLING,
    SCHEMA,
    SYSTEMS,
    TABLES,
    Field,
)
from hsbearing.errors import CaseError  # noqa: F401 - the same class as hsbearing.errors.CaseError
from hsbearing.units import DIMENSIONS, MAX_MAGNITUDE, MAX_QUANTITY_CHARS, parse_quantity  # noqa: F401 - where they always were

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
