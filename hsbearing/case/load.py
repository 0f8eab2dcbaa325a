"""The case dataclasses (generated from the schema, SI values) and loading a case: bundled names and paths, TOML reading with its limits, overrides, unit conversion and range checks, lubricant files."""

from __future__ import annotations

import dataclasses
import difflib
import math
import os
import tomllib
import warnings
from dataclasses import dataclass
from importlib import resources
from pathlib import Path
from typing import Any, Mapping

from hsbearing.case.checks import check_physical, check_possible
from hsbearing.case.schema import ALL, SCHEMA, SYSTEMS, TABLES, Field
from hsbearing.case.toml import dump_toml
from hsbearing.errors import CaseError  # defined in errors (below models/); case.CaseError is the same class
from hsbearing.units import DIMENSIONS, parse_quantity

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
        return dump_toml(self.raw)

    def archive_attrs(self) -> dict:
        """What every archive of this case says besides the case text (``results.standard_attrs`` asks for it):
        the oil by its own name with its provenance and notices (:func:`hsbearing.lubricant.identity_attrs`) and
        ``envelope_warnings`` (the lines of :func:`hsbearing.case.checks.envelope_warnings`)."""
        from hsbearing.case.checks import envelope_warnings
        from hsbearing.lubricant import identity_attrs

        out = dict(identity_attrs(self))
        out["envelope_warnings"] = envelope_warnings(self)
        return out


# ----------------------------------------------------------------------------
# loading


def _cases_dir() -> Path:
    return Path(str(resources.files("hsbearing") / "cases"))


def list_cases() -> dict[str, str]:
    """Bundled case names -> one-line description.

    Examples
    --------
    >>> import hsbearing
    >>> sorted(hsbearing.list_cases())
    ['dgbb_6206', 'dgbb_6207', 'dgbb_6208', 'jiang2014_gyro', 'shan2010_wire_race', 'zhang2016']
    """
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

    Returns
    -------
    Case
        Frozen dataclasses in SI units (speeds in rad/s, loads in N, lengths in m).

    Examples
    --------
    >>> import hsbearing
    >>> case = hsbearing.load_case("zhang2016", axial_load="2 kN")
    >>> case.operating.axial_load, case.lubricant.oil, case.bearing.ball_count
    (2000.0, '4109', 11)
    >>> print(f"{case.operating.inner_speed * 60 / (2 * 3.141592653589793):.0f} r/min")
    14000 r/min
    """
    path = case_path(name_or_path or DEFAULT_CASE)
    return _build(read_case_text(path), str(path), overrides)


def special_file_kind(path) -> str | None:
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
    kind = special_file_kind(path)  # before opening: reading a FIFO or a terminal device blocks for ever
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
        lit = override_literal(SCHEMA[table][leaf].kind, v)
        _get_table(raw, table)[leaf] = lit
        override_lines.append(f"# {table}.{leaf} = {lit if hasattr(v, 'magnitude') else v!r}")
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
    check_physical(case, source)
    check_possible(case, source)
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
            return None  # unknown name: check_physical says so, listing the known ones
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


#: old spellings of closed-vocabulary values, accepted for one release with a DeprecationWarning
CHOICE_ALIASES: dict[str, dict[str, str]] = {"friction.skf_reading": {"seed003": "dgbb_prl"}}


def _check_range(x: Any, v: Any, fld: Field, source: str, full: str) -> Any:
    """``x`` (the value ``v`` as given, converted) within the key's vocabulary and bounds."""
    if fld.kind == "choice":
        new = CHOICE_ALIASES.get(full, {}).get(x) if isinstance(x, str) else None
        if new is not None:
            warnings.warn(f"{source}: {full} = {x!r} is an old name, use {new!r}", DeprecationWarning, stacklevel=3)
            x = new
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
    return _coerce(override_literal(fld.kind, value), fld, source, key or "<override>")


def override_literal(kind: str, value: Any) -> Any:
    """An override as it goes into the case's TOML tables: str/choice keys as text, others a TOML literal
    when the text is one (``"0.52"`` -> 0.52; ``"100 N"`` stays text).  A pint Quantity becomes its text
    (``"10000 revolutions_per_minute"``) and a plain number for a key with a dimension is read in the key's SI
    unit (``inner_speed=1047.2`` -> ``"1047.2 rad/s"``), so the API takes what users hold."""

    if kind in ("str", "choice"):
        return str(value)
    if hasattr(value, "magnitude") and hasattr(value, "units") and not isinstance(value, str):
        return f"{float(value.magnitude)!r} {value.units}"
    if kind in DIMENSIONS and isinstance(value, (int, float)) and not isinstance(value, bool):
        return f"{float(value)!r} {DIMENSIONS[kind]}"
    return _parse_override_value(value)


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
