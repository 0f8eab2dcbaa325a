"""Planning a sweep: the values of a varied key read by the case's rules, the points with their hashes, and the summary variables every sweep Dataset carries."""

from __future__ import annotations

import hashlib
import itertools
from dataclasses import dataclass, field
from typing import Any, Callable, Mapping, Sequence

from hsbearing.case import (
    DIMENSIONS,
    SCHEMA,
    Case,
    CaseError,
    check_output_samples,
    load_case,
    loads_case,
    parse_quantity,
    read_override,
    resolve_key,
)
from hsbearing.results import register
from hsbearing.units import split_number

#: Status of a point that completed normally.
STATUS_OK = "ok"

#: What a sweep point can compute (``--kind``).
KINDS = ("run", "quasistatic", "thermal")

#: Name of the lock file that keeps two sweeps out of one directory.
LOCK_NAME = ".hsbearing-sweep.lock"

# ----------------------------------------------------------------------------- output variables
# Declared once here (results.py style).  In a sweep Dataset they carry the sweep dims
# (one per varied key, or ``point`` for zipped lists); the registry lists them as scalars.
register("status", (), "1", "point status: ok, failed (solver), invalid (case), error, crashed (worker died)")
register("error", (), "1", "error message of a point that did not complete ('' if ok)")
register("wall_time", (), "s", "wall-clock time spent computing the point")
register("archive", (), "1", "path of the point's netCDF archive, relative to the sweep file's directory")
register("resumed", (), "1", "1 if the point was read back from an existing archive instead of computed")
register("lubricant_name", (), "", "the point's oil by its own name (a lubricant file's name, else the built-in oil)")
register("lubricant_provenance", (), "", "where the point's oil data come from: measured, data sheet, estimated alpha, "
         "traction borrowed from another oil")
# Quasi-static point summary (kind="quasistatic"); cage_speed and
# inner_ring_axial_displacement are the core names of results.py (scalars there).
# (also the names hsbearing.analysis.summary uses for a dynamic run, where "over the balls" is
# "over the balls and over time after the transient")
register("mean_inner_contact_load", (), "N", "ball-inner race normal load Q_i, mean over the balls (and time)")
register("mean_outer_contact_load", (), "N", "ball-outer race normal load Q_o, mean over the balls (and time)")
register("max_inner_contact_load", (), "N", "ball-inner race normal load Q_i, maximum over the balls (and time)")
register("max_outer_contact_load", (), "N", "ball-outer race normal load Q_o, maximum over the balls (and time)")

RECORD_VARS = ("status", "error", "wall_time", "archive", "resumed")


# ----------------------------------------------------------------------------- values


@dataclass(frozen=True)
class Axis:
    """One varied key: the case key, the dim name, the values as given and as coordinates."""

    key: str  #: "table.key"
    dim: str  #: dimension name in the sweep Dataset
    kind: str  #: Field kind of the key
    values: tuple  #: override values in case-file form ("100 N", "4109", 0.52)
    coords: tuple  #: SI floats for quantities, floats/ints for numbers, strings for names


def key_field(key: str, source: str):
    table, leaf = resolve_key(key, source=source)
    return table, leaf, SCHEMA[table][leaf]


def parse_values(key: str, spec: str | Sequence[Any], *, source: str = "--vary", unique: bool = True) -> tuple[list, list]:
    """Values of one varied key -> (override values in case-file form, coordinate values).

    ``spec`` is a list (``["100 N", "1 kN"]``, ``["4109", "4106"]``,
    ``[0.52, 0.53]``) or a CLI string ``"100,500,1000N"`` in which a unit
    written after the last item applies to every item that has none
    (``"4109,4106"`` stays strings).  Every item is read by the case's own
    rules, as ``--set`` and a case file are (:func:`hsbearing.case.read_override`:
    a TOML literal, or a quantity with any unit a case accepts); quantities
    become SI floats in the coordinates.  An unreadable item or a wrong
    dimension raises :class:`CaseError` naming ``source`` and the key; a value
    out of the key's range is left to the point's case (an invalid point).
    """
    table, leaf, fld = key_field(key, source)
    full = f"{table}.{leaf}"
    if isinstance(spec, str):
        items = [s.strip() for s in spec.split(",")]
        if any(not s for s in items):
            raise CaseError(source, full, f"empty item in value list {spec!r}")
        if fld.kind in DIMENSIONS:
            items = _unit_after_last(items)
    else:
        items = list(spec)
    if not items:
        raise CaseError(source, full, "no values given")
    values, coords = [], []
    for item in items:
        x = read_override(item, fld, source=source, key=full)
        if fld.kind in DIMENSIONS:
            values.append(item if isinstance(item, str) else f"{item} {DIMENSIONS[fld.kind]}")
        elif fld.kind in ("str", "choice"):
            x = str(item)
            values.append(x)
        else:  # number, int, bool: the value itself; a bool's coordinate is 0/1
            values.append(x)
        coords.append(int(x) if fld.kind == "bool" else x)
    if unique and len(set(coords)) != len(coords):
        raise CaseError(source, full, f"repeated value in {items!r}")
    return values, coords


def _unit_after_last(items: list[str]) -> list[str]:
    """The CLI list convenience: ``["100", "500", "1000N"]`` -> ``["100 N", "500 N", "1000 N"]`` -- the unit
    written after the last item goes to every bare number, and a number and its unit are written with one
    space (the override text, hence the archive hash, does not depend on how the list was typed)."""
    num, unit = split_number(items[-1])
    unit = unit if num else ""
    out = []
    for s in items:
        num, rest = split_number(s)
        if num and (rest or unit):
            s = f"{num} {rest or unit}"
        out.append(s)
    return out


def _override_literal(kind: str, value: Any) -> Any:
    """A value in the form ``load_case`` overrides expect (str/choice keys stay strings there)."""
    return str(value) if kind in ("str", "choice") else value


# ----------------------------------------------------------------------------- plan


@dataclass(frozen=True)
class Point:
    """One point of a sweep: its grid index, overrides, case (None if invalid) and archive name."""

    index: tuple[int, ...]
    overrides: dict
    case: Case | None
    error: str = ""
    archive: str = ""  #: file name of the archive (in the archive directory)
    hash: str = ""
    extend: float | None = None  #: budget [s] of total simulated time to extend an undetermined run (None: never)


@dataclass
class SweepPlan:
    """What a sweep will compute: axes, points, where the archives go."""

    base: Case
    axes: list[Axis]
    zipped: bool
    points: list[Point]
    kind: str
    duration: float | None
    point_fn: Callable | None
    vary_spec: dict = field(default_factory=dict)
    extend: Any = None  #: as asked of :func:`plan_sweep` (None, "default" or a budget [s]); per point: Point.extend

    @property
    def shape(self) -> tuple[int, ...]:
        if self.zipped:
            return (len(self.points),)
        return tuple(len(a.values) for a in self.axes)

    @property
    def dims(self) -> tuple[str, ...]:
        return ("point",) if self.zipped else tuple(a.dim for a in self.axes)


def fn_name(fn: Callable | None) -> str:
    if fn is None:
        return ""
    return f"{getattr(fn, '__module__', '?')}.{getattr(fn, '__qualname__', repr(fn))}"


def point_hash(case: Case, kind: str, duration: float | None, point_fn: Callable | None = None,
               extend: float | None = None) -> str:
    """SHA-1 (hex) of the point's full case TOML + kind + duration (+ point function name) (+ the extension
    budget, only when the point is extended: the archives of points that are not keep their hashes)."""
    text = case.to_toml() + f"\n#kind={kind}\n#duration={duration!r}\n#point_fn={fn_name(point_fn)}\n"
    if extend is not None:
        text += f"#extend={float(extend)!r}\n"
    return hashlib.sha1(text.encode()).hexdigest()


#: ``extend=`` of :func:`plan_sweep` that asks for the default budget (WORKFLOW_BUDGET_FACTOR x each point's duration)
EXTEND_DEFAULT = "default"


def extension_budget(case: Case, duration: float | None, extend, *, source: str = "--max-duration") -> float | None:
    """The budget [s] of total simulated time of one point's extension (None: not extended).

    ``extend``: None/False (no extension), :data:`EXTEND_DEFAULT` or True (the default:
    :data:`hsbearing.systems.angular_contact.extend.WORKFLOW_BUDGET_FACTOR` x the point's duration), or a budget
    (s or unit string) that must be at least the point's duration.  Only systems whose runs can be extended
    (:attr:`hsbearing.systems.System.extend`) get one."""
    if extend is None or extend is False:
        return None
    from hsbearing import systems

    if systems.get(case).extend is None:
        return None
    d = float(duration) if duration is not None else float(case.simulation.duration)
    if extend is True or extend == EXTEND_DEFAULT:
        from hsbearing.systems.angular_contact.extend import WORKFLOW_BUDGET_FACTOR

        budget = WORKFLOW_BUDGET_FACTOR * d
    else:
        budget = parse_quantity(extend, "time", source=source, key="max_duration") if isinstance(extend, str) \
            else float(extend)
        if not budget >= d * (1 - 1e-12):
            raise CaseError(source, "max_duration", f"must be at least the run's duration {d:g} s, got {extend!r}")
    check_output_samples(case, budget, source=source, key="max_duration")
    return float(budget)


def _base_case(case) -> Case:
    return case if isinstance(case, Case) else load_case(case)


def plan_sweep(
    case,
    vary: Mapping[str, Any],
    *,
    zip: bool = False,  # noqa: A002 - the documented keyword
    kind: str = "run",
    duration=None,
    point_fn: Callable | None = None,
    source: str = "--vary",
    extend=None,
) -> SweepPlan:
    """Validate the varied keys and values and build every point's case (no computation).

    ``extend`` (kind "run"): extend every point whose label is undetermined until it is determined
    (:func:`extension_budget`: None, "default" or a budget); part of each extended point's hash."""
    if kind not in KINDS:
        raise CaseError("--kind", None, f"unknown kind {kind!r} (allowed: {', '.join(KINDS)})")
    base = _base_case(case)
    if not vary:
        raise CaseError(source, None, "nothing to vary (give at least one --vary KEY=V1,V2,...)")
    if isinstance(duration, str):
        duration = parse_quantity(duration, "time", source="--duration", key="duration")
    if duration is not None and not (duration > 0):
        raise CaseError("--duration", "duration", f"must be positive, got {duration!r}")
    if kind in ("quasistatic", "thermal"):
        duration = None  # meaningless for an equilibrium: kept out of the archive hash
    axes: list[Axis] = []
    seen: dict[str, str] = {}
    for key, spec in vary.items():
        table, leaf, fld = key_field(key, source)
        full = f"{table}.{leaf}"
        if full in seen:
            raise CaseError(source, full, "varied twice")
        values, coords = parse_values(full, spec, source=source, unique=not zip)
        seen[full] = leaf
        axes.append(Axis(full, leaf, fld.kind, tuple(values), tuple(coords)))
    leaves = [a.dim for a in axes]
    axes = [
        Axis(a.key, a.key if leaves.count(a.dim) > 1 else a.dim, a.kind, a.values, a.coords) for a in axes
    ]
    if zip:
        n = {len(a.values) for a in axes}
        if len(n) != 1:
            raise CaseError(source, None, "--zip needs lists of equal length: " + ", ".join(f"{a.key} has {len(a.values)}" for a in axes))
        combos = [tuple((i,) * len(axes)) for i in range(n.pop())]
        indices = [(c[0],) for c in combos]
        seen_rows: dict[tuple, int] = {}
        for i in range(len(combos)):
            row = tuple(a.coords[i] for a in axes)
            if row in seen_rows:
                raise CaseError(source, None, f"--zip points {seen_rows[row]} and {i} are the same: {row}")
            seen_rows[row] = i
    else:
        combos = list(itertools.product(*[range(len(a.values)) for a in axes]))
        indices = combos
    base_text = base.to_toml()
    points = []
    for idx, combo in zip_(indices, combos):
        overrides = {a.key: a.values[i] for a, i in zip_(axes, combo)}
        lit = {a.key: _override_literal(a.kind, a.values[i]) for a, i in zip_(axes, combo)}
        try:
            pc = loads_case(base_text, base.source, **lit)
            if kind == "run" and duration is not None and point_fn is None:
                check_output_samples(pc, duration, source="--duration", key="duration")
            if kind == "thermal" and point_fn is None:
                from hsbearing.systems.angular_contact.thermal import check_inputs

                check_inputs(pc)  # system, geometry and oil flow of every point, before anything is computed
        except CaseError as exc:
            points.append(Point(idx, overrides, None, error=str(exc)))
            continue
        # a stand-in point function is extended only when it brings its own continuation (``continue_fn``)
        extendable = kind == "run" and (point_fn is None or getattr(point_fn, "continue_fn", None) is not None)
        budget = extension_budget(pc, duration, extend) if extendable else None
        h = point_hash(pc, kind, duration, point_fn, budget)
        points.append(Point(idx, overrides, pc, archive=f"{pc.name}-{h[:12]}.nc", hash=h, extend=budget))
    return SweepPlan(base, axes, zip, points, kind, duration, point_fn, dict(vary), extend=extend)


zip_ = zip  # the builtin, shadowed by the ``zip`` keyword inside plan_sweep/run_sweep
