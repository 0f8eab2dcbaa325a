"""Quantities with units: the one parser of case files, lubricant files, overrides and CLI quantities.

``parse_quantity("14000 rpm", "angular_speed")`` -> SI float.  Split out of :mod:`hsbearing.case` so that the
lubricant-file reader (:mod:`hsbearing.lubricant`), which the case loader calls, does not import the case
module back; :mod:`hsbearing.case` re-exports every name.
"""

from __future__ import annotations

import functools
import math
import re
from typing import Any

import numpy as np

from hsbearing.errors import CaseError

#: Dimension name -> (pint dimensionality check unit, SI unit string).
DIMENSIONS: dict[str, str] = {
    "length": "m",
    "angle": "rad",
    "angular_speed": "rad/s",
    "force": "N",
    "moment": "N*m",
    "temperature": "K",
    "time": "s",
    "pressure": "Pa",
    "density": "kg/m**3",
    "mass": "kg",
    "inertia": "kg*m**2",
    "dynamic_viscosity": "Pa*s",
    "kinematic_viscosity": "m**2/s",
    "stiffness": "N/m",
    "damping": "N*s/m",
    "pressure_coefficient": "1/Pa",
    "thermal_conductivity": "W/(m*K)",
    "temperature_coefficient": "1/K",
    "velocity": "m/s",
    "frequency": "Hz",
    "volume_flow_rate": "m**3/s",
    "specific_heat": "J/(kg*K)",
    "heat_transfer_coefficient": "W/(m**2*K)",
}

# ----------------------------------------------------------------------------
# units


@functools.lru_cache(maxsize=1)
def _ureg():
    import pint

    ureg = pint.UnitRegistry(autoconvert_offset_to_baseunit=True)
    ureg.define("rpm = revolution / minute = r_per_min")
    ureg.define("rev = revolution")
    ureg.define("r = revolution")  # "14000 r/min", the notation of the trade (and of what hsbearing prints)
    return ureg


#: Kinds whose SI unit pint treats as dimensionless or as 1/s, where a cycle and a radian are confused unless
#: the angle is made explicit: pint reads "Hz" and "1/min" as 1/s and "25 %" as 0.25 rad.
ANGULAR_KINDS = ("angle", "angular_speed", "frequency")


def has_angle_unit(q, ureg) -> bool:
    """True if the unit of ``q`` contains an angle unit (rad, deg, revolution, turn, cycle, rpm ...)."""
    for name in q._units:
        _, base = ureg.get_base_units(name)
        if "radian" in base._units:
            return True
    return False


def angular_si(q, ureg, kind: str, value: str, source: str, key: str | None) -> float:
    """SI value of an angle [rad], an angular speed [rad/s] or a frequency [Hz = cycles/s], never confusing
    cycles with radians.

    - angle: the unit must be an angle unit (``deg``, ``rad``, ``turn``); a quoted bare number or a ratio
      (``"0.5"``, ``"25 %"``) is refused (only zero may be written without a unit).
    - angular speed: with an angle unit (``rad/s``, ``rpm``, ``r/min``, ``rev/s``, ``deg/s``) as written;
      without one (``Hz``, ``1/min``, ``1/s``, ``kHz``) the number counts **revolutions** per unit time,
      so ``"233.33 Hz"`` = 233.33 rev/s = 2 pi 233.33 rad/s and ``"14000 1/min"`` = 14000 r/min.
    - frequency: cycles per second; an angular unit (``rad/s``, ``rpm``) is converted to cycles.
    """
    has_angle = has_angle_unit(q, ureg)
    dim = q.dimensionality
    if kind == "angle":
        if q.magnitude == 0 and not dim:
            return 0.0
        if not has_angle or dim:
            raise CaseError(source, key, f"{value!r} is not an angle: give an angle unit, e.g. \"{q.magnitude:g} deg\" "
                                         "(a bare number or a ratio is not read as radians)")
        return float(q.to("radian").magnitude)
    if dim != ureg.Quantity(1, "1/s").dimensionality:
        raise CaseError(source, key, f"{value!r} is not {_a(kind)} (expected units like {example_unit(kind)})")
    if kind == "angular_speed":
        if has_angle:
            return float(q.to("radian/second").magnitude)
        return float(q.to("1/second").magnitude) * 2.0 * math.pi  # revolutions per second -> rad/s
    # frequency [Hz]: cycles per second
    if has_angle:
        return float(q.to("radian/second").magnitude) / (2.0 * math.pi)
    return float(q.to("1/second").magnitude)


def parse_quantity(value: Any, kind: str, *, source: str = "<value>", key: str | None = None) -> float:
    """Convert a case-file value of dimension ``kind`` to an SI float.

    Strings carry units (``"9.525 mm"``); a bare number is accepted for a
    dimensional key only if it is zero (``0``) -- otherwise the unit is
    ambiguous and a :class:`CaseError` asks for one.
    """
    if kind not in DIMENSIONS:
        raise KeyError(kind)
    si = DIMENSIONS[kind]
    if isinstance(value, bool):
        raise CaseError(source, key, f"expected {_a(kind)} with units, got {value!r}")
    if isinstance(value, (int, float)):
        if value == 0:
            return 0.0
        raise CaseError(source, key, f"expected {_a(kind)} with units like \"{value} {example_unit(kind)}\", got bare number "
                                     f"{value!r}: a value needs a unit (only 0 may be written without one)")
    if not isinstance(value, str):
        raise CaseError(source, key, f"expected a quantity string with units, got {type(value).__name__}")
    check_quantity_text(value, kind, source, key)
    ureg = _ureg()
    try:
        q = ureg.Quantity(value.strip())
    except Exception as exc:  # pint raises several kinds
        hint = suggest_spelling(value, kind)
        hint = f"; did you mean {hint!r}?" if hint else ""
        raise CaseError(source, key, f"cannot parse quantity {value!r} ({type(exc).__name__}){hint}") from None
    if not isinstance(q, ureg.Quantity):  # plain number in a string
        q = ureg.Quantity(float(q), "")
    try:
        if kind == "temperature":
            out = q.to("kelvin").magnitude
        elif kind in ANGULAR_KINDS:
            out = angular_si(q, ureg, kind, value, source, key)
        else:
            out = q.to(si).magnitude
    except CaseError:
        raise
    except Exception:
        if not q._units and kind != "temperature":
            raise CaseError(source, key, f"{value!r} has no unit: write e.g. \"{value.strip()} {example_unit(kind)}\" "
                                         "(no unit is assumed)") from None
        raise CaseError(
            source, key, f"{value!r} is not {_a(kind)} (expected units like {example_unit(kind)})"
        ) from None
    try:
        out = float(out)
    except (TypeError, ValueError, OverflowError):
        raise CaseError(source, key, f"cannot parse quantity {value!r} (not a real number)") from None
    if not math.isfinite(out):
        raise CaseError(source, key, f"must be finite, got {value!r}")
    limit = MAX_MAGNITUDE.get(kind, 1e20)
    if abs(out) > limit:
        raise CaseError(source, key, f"{value!r} is an absurd magnitude for a {kind.replace('_', ' ')} "
                                     f"(more than {limit:g} {DIMENSIONS[kind]})")
    return out


#: Unit spellings of the trade that pint does not read, and what they mean (case-insensitive whole words).
_SPELLINGS = {
    "cst": "mm^2/s",  # centistokes: 1 cSt = 1 mm^2/s
    "kgf": "kgf", "kp": "kgf", "kgp": "kgf",  # kilogram-force (kilopond)
    "lbf": "lbf", "lbs": "lb", "gf": "gf",
    "cc": "cm^3", "ccm": "cm^3",
    "rpm": "rpm", "u/min": "rpm", "1/min": "rpm", "upm": "rpm",
}
_WORD = re.compile(r"[A-Za-z_]+(?:/[A-Za-z_]+)?")
_TRAILING_POWER = re.compile(r"\b([A-Za-z]+)([23])\b")


def suggest_spelling(value: str, kind: str) -> str | None:
    """A spelling pint reads for a common way of writing a unit, if one parses as ``kind``: ``"0.86 g/cm3"`` ->
    ``"0.86 g/cm^3"``, ``"20 mm2/s"`` -> ``"20 mm^2/s"``, ``"10 KGF"`` / ``"10 kp"`` -> ``"10 kgf"``,
    ``"20 cst"`` -> ``"20 mm^2/s"``; None when no such rewriting gives a quantity of that kind."""
    number, unit = split_number(str(value))
    if not number or not unit:
        return None
    candidates = [_TRAILING_POWER.sub(r"\1^\2", unit)]  # cm3 -> cm^3, mm2 -> mm^2
    spelled = _WORD.sub(lambda m: _SPELLINGS.get(m.group(0).lower(), m.group(0)), unit)
    candidates += [spelled, _TRAILING_POWER.sub(r"\1^\2", spelled)]
    candidates += [_WORD.sub(lambda m: _SPELLINGS.get(m.group(0).lower(), m.group(0)), unit.lower())]
    for cand in candidates:
        if cand == unit:
            continue
        text = f"{number} {cand}"
        try:
            parse_quantity(text, kind)
        except Exception:  # noqa: BLE001 - not this one
            continue
        return text
    return None


def split_number(text: str) -> tuple[str, str]:
    """``"2.5kN"`` -> ``("2.5", "kN")``: the leading number of a quantity text (the longest start of it that
    Python's ``float`` reads, beginning with a digit, a sign or a point) and the rest, both stripped;
    ``("", text)`` when the text does not begin with a number, ``(text, "")`` for a bare number.  Text only:
    the quantity itself is read by :func:`parse_quantity`."""
    s = text.strip()
    if not s or len(s) > MAX_QUANTITY_CHARS or not (s[0].isdigit() or s[0] in "+-."):
        return "", s
    for end in range(len(s), 0, -1):
        try:
            float(s[:end])
        except ValueError:
            continue
        return s[:end].strip(), s[end:].strip()
    return "", s


#: Largest accepted magnitude of a quantity, in SI units of its dimension: far above any bearing
#: (a 100 m bearing, 1e7 rad/s, 1e10 N), so that only typing errors such as "1e30 mm" are refused.
MAX_MAGNITUDE: dict[str, float] = {
    "length": 100.0, "angle": 1e4, "angular_speed": 1e7, "force": 1e10, "moment": 1e10, "temperature": 1e4,
    "time": 1e7, "pressure": 1e13, "density": 1e5, "mass": 1e7, "inertia": 1e7, "dynamic_viscosity": 1e8,
    "kinematic_viscosity": 1e2, "stiffness": 1e15, "damping": 1e12, "pressure_coefficient": 1e-3,
    "thermal_conductivity": 1e4, "temperature_coefficient": 1e2, "velocity": 1e5, "frequency": 1e9,
    "volume_flow_rate": 10.0, "specific_heat": 1e6, "heat_transfer_coefficient": 1e8,
}

#: Longest quantity string accepted (a case value is a number and a unit).
MAX_QUANTITY_CHARS = 100

# a power operator and its exponent: only a small literal exponent of a unit is accepted ("m^3", "m**-2")
_POWER = re.compile(r"(\*\*|\^)")
_UNIT_POWER = re.compile(r"[A-Za-z_\u00b5\u03bc\u00b0]\s*(?:\*\*|\^)\s*\(?\s*[-+]?\d{1,2}(?:\.\d+)?\s*\)?(?!\s*(?:\*\*|\^|\d))")


# a number written in groups ("1 000 N"), not a number before a unit like "1/min"
_SPLIT_NUMBER = re.compile(r"\d\s+[-+]?\d*\.?\d+(?=\s*[A-Za-z\u00b0%]|\s*$)")


def check_quantity_text(value: str, kind: str, source: str, key: str | None) -> None:
    """Refuse, before pint sees it, text whose evaluation is unbounded.

    pint evaluates powers of integers exactly (``"10**10**10 mm"`` never returns), so a power is
    accepted only as a small literal exponent of a unit (``"kg/m^3"``, ``"m**2/s"``); numbers are
    written in e-notation (``"1e10"``).
    """
    if len(value) > MAX_QUANTITY_CHARS:
        raise CaseError(source, key, f"quantity text longer than {MAX_QUANTITY_CHARS} characters")
    n_pow = len(_POWER.findall(value))
    if n_pow and len(_UNIT_POWER.findall(value)) != n_pow:
        raise CaseError(source, key, f"cannot parse quantity {value!r}: a power is accepted only as a small "
                                     "exponent of a unit (m^3, m**2); write numbers in e-notation (1e10)")
    if _SPLIT_NUMBER.search(value):  # pint reads "1 000 N" as 1 x 000 = 0 N
        raise CaseError(source, key, f"cannot parse quantity {value!r}: digits separated by a space "
                                     "(write one number, e.g. 1000 N or 1e3 N)")


def _a(kind: str) -> str:
    """``"angular_speed"`` -> ``"an angular speed"``, ``"length"`` -> ``"a length"`` (for messages)."""
    words = kind.replace("_", " ")
    return ("an " if words[:1] in "aeiou" else "a ") + words


def example_unit(kind: str) -> str:
    return {
        "length": "mm", "angle": "deg", "angular_speed": "rpm", "force": "N", "moment": "N*m",
        "temperature": "degC", "time": "s", "pressure": "GPa", "density": "kg/m^3", "mass": "kg",
        "inertia": "kg*m^2", "dynamic_viscosity": "Pa*s", "kinematic_viscosity": "mm^2/s",
        "volume_flow_rate": "L/min", "specific_heat": "J/(kg*K)", "heat_transfer_coefficient": "W/(m^2*K)",
    }.get(kind, DIMENSIONS[kind])


def parse_speeds(speeds, source: str = "--speeds") -> np.ndarray:
    """Speeds -> rad/s array.  Accepts numbers (rad/s), unit strings, lists of them,
    and the CLI form ``"500,5000,15000rpm"`` (one unit after the last number)."""
    if isinstance(speeds, (int, float)) and not isinstance(speeds, bool):
        items = [speeds]
    elif isinstance(speeds, str):
        parts = [p.strip() for p in speeds.split(",") if p.strip()]
        if not parts:
            raise CaseError(source, "speeds", "no speed given")
        m = re.match(r"^[-+0-9.eE]+\s*(.*)$", parts[-1])
        unit = m.group(1).strip() if m else ""
        items = []
        for p in parts:
            if re.fullmatch(r"[-+]?[0-9.]+([eE][-+]?[0-9]+)?", p):
                if not unit:
                    raise CaseError(source, "speeds", f"speed {p!r} has no unit (e.g. 500,5000rpm)")
                items.append(f"{p} {unit}")
            else:
                items.append(p)
    else:
        items = list(speeds)
    out = []
    for it in items:
        if isinstance(it, (int, float)) and not isinstance(it, bool):
            val = float(it)
        else:
            val = parse_quantity(it, "angular_speed", source=source, key="speeds")
        if not math.isfinite(val) or val <= 0.0:
            raise CaseError(source, "speeds", f"speeds must be positive, got {it!r}")
        out.append(val)
    if not out:
        raise CaseError(source, "speeds", "no speed given")
    return np.asarray(out, dtype=float)
