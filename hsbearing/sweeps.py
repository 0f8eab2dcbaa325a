"""Sweeps: many independent runs over varied case keys, in parallel, resumable, archived.

``run_sweep(case, {"axial_load": "100,500,1000N", "oil": ["4109", "4106"]}, out_dir="DIR")``
builds the Cartesian product (or, with ``zip=True``, the zipped lists) of
case overrides.  Every point is an independent run (``kind="run"``:
:func:`hsbearing.simulate`; ``kind="quasistatic"``: :func:`hsbearing.quasi_static`; ``kind="thermal"``:
the steady thermal network at its power loss, :func:`hsbearing.thermal.thermal_equilibrium`)
archived as its own netCDF file ``DIR/<case>-<hash>.nc``, where the hash is
taken over the point's full case TOML, the kind, the duration and the
point function.  ``DIR/sweep.nc`` is one Dataset with a dimension per varied
key (``point`` for zipped lists) holding each point's summary plus
``status``, ``error``, ``wall_time``, ``archive`` and ``resumed``.

Execution
---------
* ``jobs`` local worker processes (``spawn`` context; default
  ``os.cpu_count()``); ``jobs=1`` runs in the calling process.
* ``scheduler="tcp://host:port"``: the same tasks are submitted to an
  existing dask.distributed cluster.  Workers return the result Dataset to
  the client; only the client writes files (no shared file system needed).

Fault tolerance
---------------
* A point whose overrides make an invalid case (:class:`CaseError`) is
  recorded with status ``invalid`` and its message; nothing is computed.
* A :class:`SolverError` is recorded with status ``failed``; its partial
  Dataset (or, without one, an empty Dataset carrying the status) is archived.
* Any other exception in a point: status ``error`` (not archived: retried
  on the next run).
* A point that kills its worker process (segfault, OOM kill): the points
  that were running in the broken pool are re-run one at a time in a fresh
  single-worker pool, so the culprit is identified exactly and recorded as
  ``crashed``; the others complete normally.  On dask the same: tasks that
  end as ``KilledWorker`` are resubmitted one at a time, and the one that
  kills its worker again is ``crashed``.
* Resume: a point whose archive exists and is complete (opens, has the
  ``status`` attribute) is not recomputed; its record is read back from the
  archive.  Archives are written atomically by
  :func:`hsbearing.results.write_netcdf`, so an interrupted sweep leaves
  only complete archives plus, at worst, hidden temporary files
  ``.<name>.nc.*.tmp`` which the next run of the same sweep deletes (a lock
  file ``DIR/.hsbearing-sweep.lock`` keeps two sweeps out of one directory,
  so those temporaries cannot belong to a live writer).
"""

from __future__ import annotations

import contextlib
import glob
import hashlib
import itertools
import json
import math
import multiprocessing
import os
import re
import signal
import sys
import threading
import time
import traceback
from concurrent.futures import FIRST_COMPLETED, ProcessPoolExecutor, wait
from concurrent.futures.process import BrokenProcessPool
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any, Callable, Iterable, Mapping, Sequence

import numpy as np
import xarray as xr

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
from hsbearing.errors import SolverError
from hsbearing.results import VARIABLES, check_output_path, register, standard_attrs, write_netcdf
from hsbearing.units import split_number

__all__ = [
    "run_sweep",
    "plan_sweep",
    "execute",
    "assemble",
    "parse_values",
    "point_hash",
    "archive_is_complete",
    "quasistatic_summary",
    "dynamic_summary",
    "cli_main",
    "check_scheduler_address",
    "unguarded_main_call",
    "SweepPlan",
    "Point",
    "STATUS_OK",
]

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
# Quasi-static point summary (kind="quasistatic"); cage_speed and
# inner_ring_axial_displacement are the core names of results.py (scalars there).
# (also the names hsbearing.analysis.summary uses for a dynamic run, where "over the balls" is
# "over the balls and over time after the transient")
register("mean_inner_contact_load", (), "N", "ball-inner race normal load Q_i, mean over the balls (and time)")
register("mean_outer_contact_load", (), "N", "ball-outer race normal load Q_o, mean over the balls (and time)")
register("max_inner_contact_load", (), "N", "ball-inner race normal load Q_i, maximum over the balls (and time)")
register("max_outer_contact_load", (), "N", "ball-outer race normal load Q_o, maximum over the balls (and time)")

_RECORD_VARS = ("status", "error", "wall_time", "archive", "resumed")


# ----------------------------------------------------------------------------- values


@dataclass(frozen=True)
class Axis:
    """One varied key: the case key, the dim name, the values as given and as coordinates."""

    key: str  #: "table.key"
    dim: str  #: dimension name in the sweep Dataset
    kind: str  #: Field kind of the key
    values: tuple  #: override values in case-file form ("100 N", "4109", 0.52)
    coords: tuple  #: SI floats for quantities, floats/ints for numbers, strings for names


def _field(key: str, source: str):
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
    table, leaf, fld = _field(key, source)
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

    @property
    def shape(self) -> tuple[int, ...]:
        if self.zipped:
            return (len(self.points),)
        return tuple(len(a.values) for a in self.axes)

    @property
    def dims(self) -> tuple[str, ...]:
        return ("point",) if self.zipped else tuple(a.dim for a in self.axes)


def _fn_name(fn: Callable | None) -> str:
    if fn is None:
        return ""
    return f"{getattr(fn, '__module__', '?')}.{getattr(fn, '__qualname__', repr(fn))}"


def point_hash(case: Case, kind: str, duration: float | None, point_fn: Callable | None = None) -> str:
    """SHA-1 (hex) of the point's full case TOML + kind + duration (+ point function name)."""
    text = case.to_toml() + f"\n#kind={kind}\n#duration={duration!r}\n#point_fn={_fn_name(point_fn)}\n"
    return hashlib.sha1(text.encode()).hexdigest()


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
) -> SweepPlan:
    """Validate the varied keys and values and build every point's case (no computation)."""
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
        table, leaf, fld = _field(key, source)
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
                from hsbearing.thermal import check_inputs

                check_inputs(pc)  # system, geometry and oil flow of every point, before anything is computed
        except CaseError as exc:
            points.append(Point(idx, overrides, None, error=str(exc)))
            continue
        h = point_hash(pc, kind, duration, point_fn)
        points.append(Point(idx, overrides, pc, archive=f"{pc.name}-{h[:12]}.nc", hash=h))
    return SweepPlan(base, axes, zip, points, kind, duration, point_fn, dict(vary))


zip_ = zip  # the builtin, shadowed by the ``zip`` keyword inside plan_sweep/run_sweep


# ----------------------------------------------------------------------------- one point (runs in the worker)


def quasistatic_summary(ds: xr.Dataset) -> dict[str, Any]:
    """Scalars of a quasi-static result: mean/max contact loads, cage speed, axial displacement."""
    out: dict[str, Any] = {}
    for side in ("inner", "outer"):
        name = f"{side}_contact_load"
        if name in ds:
            q = np.asarray(ds[name].values, dtype=float)
            out[f"mean_{name}"] = float(np.mean(q))
            out[f"max_{name}"] = float(np.max(q))
    for name in ("cage_speed", "inner_ring_axial_displacement"):
        if name in ds and ds[name].ndim == 0:
            out[name] = float(ds[name].values)
    return out


#: scalars of a thermal equilibrium (kind="thermal") kept in the sweep summary (names of hsbearing.thermal)
THERMAL_SUMMARY = ("inner_ring_temperature", "outer_ring_temperature", "ball_temperature", "cage_temperature",
                   "housing_temperature", "shaft_temperature", "oil_outlet_temperature", "lubricant_temperature",
                   "heat_generated", "heat_removed_by_oil", "heat_removed_by_conduction", "heat_balance_error",
                   "fixed_point_iterations")


def thermal_summary(ds: xr.Dataset) -> dict[str, Any]:
    """Scalars of a thermal equilibrium: component, oil outlet and lubricant temperatures [K], heat generated
    and removed by the oil and by conduction [W], the balance error and the fixed-point iterations, and the
    power loss by source at equilibrium (``thermal_power_loss_<source>`` [W])."""
    names = list(THERMAL_SUMMARY) + sorted(str(n) for n in ds.data_vars if str(n).startswith("thermal_power_loss_"))
    return {n: float(ds[n].values) for n in names if n in ds and ds[n].ndim == 0}


def point_summary(kind: str, ds: xr.Dataset) -> dict[str, Any]:
    """The summary scalars of one point's Dataset, by the sweep's kind."""
    if kind == "quasistatic":
        return quasistatic_summary(ds)
    if kind == "thermal":
        return thermal_summary(ds)
    return dynamic_summary(ds)


def dynamic_summary(ds: xr.Dataset) -> dict[str, Any]:
    """Scalars of a dynamic run, by :func:`hsbearing.analysis.summary` (the analysis module's).

    A gyro ribbon-cage run (``attrs["model"] == "gyro_ribbon_cage"``) is summarised by
    :func:`hsbearing.systems.gyro.model.summary` instead: SFMC/SFMO/RFMC and their statistics (with the
    start-ensemble SFMC mean and sd when ``simulation.start_positions`` > 1), none
    of the whirl / classification / contact-load fields, which do not apply to that model.
    """
    from hsbearing import systems

    system = systems.for_archive(ds)
    if ds.attrs.get("model") == "gyro_ribbon_cage":  # a gyro run, also one whose attrs lost the case system
        system = systems.get("gyro_ribbon_cage")
    if system is None or system.run_summary is None:
        system = systems.get("angular_contact")
    return system.run_summary(ds)


def _scalar(v: Any) -> Any:
    if isinstance(v, np.generic):
        v = v.item()
    if isinstance(v, np.ndarray) and v.ndim == 0:
        v = v.item()
    if isinstance(v, (bool, np.bool_)):
        return int(v)
    if isinstance(v, (int, float, str)):
        return v
    if v is None:
        return float("nan")
    return str(v)


def _compute_point(case: Case, kind: str, duration, point_fn) -> tuple[dict, xr.Dataset | None]:
    """Compute one point; never raises for a point's own failure.  Returns (record, dataset)."""
    t0 = time.perf_counter()
    ds = None
    rec: dict[str, Any] = {"status": STATUS_OK, "error": "", "summary": {}}
    try:
        if point_fn is not None:
            ds = point_fn(case, duration)
        elif kind == "quasistatic":
            from hsbearing.quasistatic import solve_case

            ds = solve_case(case)
        elif kind == "thermal":
            from hsbearing.thermal import thermal_equilibrium

            ds = thermal_equilibrium(case)
        else:
            from hsbearing.systems import simulate

            ds = simulate(case, duration=duration)
        rec["status"] = str(ds.attrs.get("status", STATUS_OK))
        if rec["status"] != STATUS_OK and ds.attrs.get("error"):  # a result that says why it is not ok (e.g. thermal runaway)
            rec["error"] = str(ds.attrs["error"])
    except CaseError as exc:
        rec.update(status="invalid", error=str(exc))
        ds = None
    except SolverError as exc:
        rec.update(status="failed", error=f"SolverError: {exc}")
        ds = exc.partial if isinstance(exc.partial, xr.Dataset) else None
        if ds is None:
            ds = xr.Dataset(attrs=standard_attrs(case, status="failed"))
        ds = ds.copy()
        ds.attrs.setdefault("status", "failed")
        ds.attrs["error"] = str(exc)
    except Exception as exc:  # a bug or an unexpected failure: record it, the sweep goes on
        tb = traceback.extract_tb(exc.__traceback__)
        where = f" ({Path(tb[-1].filename).name}:{tb[-1].lineno})" if tb else ""
        rec.update(status="error", error=f"{type(exc).__name__}: {exc}{where}")
        ds = None
    if ds is not None and rec["status"] != "invalid" and len(ds.data_vars):
        try:
            summ = point_summary(kind, ds)
            rec["summary"] = {k: _scalar(v) for k, v in summ.items()}
        except Exception as exc:  # summary of a partial/odd dataset: keep the archive, say why
            rec["summary_error"] = f"summary failed: {type(exc).__name__}: {exc}"
            rec["error"] = "; ".join(e for e in (rec["error"], rec["summary_error"]) if e)
    rec["wall_time"] = time.perf_counter() - t0
    return rec, ds


def _worker_init() -> None:  # pragma: no cover - runs in the worker processes
    """Die with the parent (Linux): an interrupted sweep leaves no orphan computing."""
    with contextlib.suppress(Exception):
        signal.signal(signal.SIGINT, signal.SIG_IGN)  # the parent handles Ctrl-C and shuts us down
    if sys.platform.startswith("linux"):
        with contextlib.suppress(Exception):
            import ctypes

            libc = ctypes.CDLL("libc.so.6", use_errno=True)
            libc.prctl(1, signal.SIGTERM)  # PR_SET_PDEATHSIG
            if os.getppid() == 1:
                os._exit(1)


# ----------------------------------------------------------------------------- archives


def archive_is_complete(path: str | os.PathLike) -> bool:
    """True if ``path`` opens as netCDF, carries the ``status`` attribute and every variable's data reads
    back (HDF5 checksums and zlib streams verified: a corrupted archive is not complete)."""
    try:
        with xr.open_dataset(path, engine="netcdf4") as ds:
            if "status" not in ds.attrs:
                return False
            ds.load()
            return True
    except Exception:
        return False


def _read_record(path: Path, expected_hash: str | None = None) -> dict | None:
    """The sweep record of a point archive, or None if it is not a complete, readable archive.

    The whole archive is read (``load``), not only its header: bytes corrupted inside a data chunk fail
    the chunk's checksum (``fletcher32``, :func:`hsbearing.results.write_netcdf`) or its zlib stream here,
    so a resumed sweep recomputes the point instead of trusting it (issue 13, item 9).

    ``expected_hash``: the point's identity (:func:`point_hash`); an archive whose own ``sweep_point_hash``
    differs (another point's archive copied over this name, a stale file) or is missing is not this point's
    result: None, so the point is recomputed (issue 27, class 3).
    """
    try:
        with xr.open_dataset(path, engine="netcdf4") as ds:
            if "status" not in ds.attrs:
                return None
            if expected_hash is not None and str(ds.attrs.get("sweep_point_hash", "")) != expected_hash:
                return None
            ds = ds.load()
            rec = json.loads(ds.attrs["sweep_record"]) if "sweep_record" in ds.attrs else None
            if rec is None:  # an archive written by something else
                rec = {"status": str(ds.attrs["status"]), "error": str(ds.attrs.get("error", "")),
                       "wall_time": float("nan"), "summary_error": "no summary stored"}
            from hsbearing.analysis.orbit import classified_by_older_rules

            stale = ds.attrs.get("sweep_kind", "run") == "run" and "time" in ds.dims and classified_by_older_rules(ds)
            if stale:  # classified by older rules: re-read with the current classifier (the run is kept)
                rec["summary_error"] = "classified by an older classifier version"
            if rec.get("summary_error"):  # summarise again (the analysis may have been fixed since)
                kind = ds.attrs.get("sweep_kind", "run")
                try:
                    summ = point_summary(kind, ds)
                    rec["summary"] = {k: _scalar(v) for k, v in summ.items()}
                    rec["error"] = "; ".join(e for e in rec.get("error", "").split("; ")
                                             if e and not e.startswith("summary failed") and e != rec["summary_error"])
                    rec.pop("summary_error")
                except Exception as exc:
                    rec["summary_error"] = f"summary failed: {type(exc).__name__}: {exc}"
            return rec
    except Exception:
        return None


def _write_archive(ds: xr.Dataset, rec: dict, path: Path, plan: SweepPlan, point: Point) -> None:
    ds = ds.copy()
    ds.attrs["sweep_kind"] = plan.kind
    ds.attrs["sweep_duration"] = "" if plan.duration is None else plan.duration
    ds.attrs["sweep_point_hash"] = point.hash
    ds.attrs["sweep_overrides"] = json.dumps(point.overrides)
    if "case_toml" not in ds.attrs and point.case is not None:
        ds.attrs["case_toml"] = point.case.to_toml()
    ds.attrs["sweep_record"] = json.dumps({k: v for k, v in rec.items()}, default=str)
    ds.attrs.setdefault("status", rec["status"])
    write_netcdf(ds, path)


def _clean_temporaries(archive_dir: Path, names: Iterable[str]) -> list[Path]:
    """Delete leftover temporary files of this sweep's archives (interrupted writes): ``.hsb-<hash of the
    name>-*.tmp`` (:func:`hsbearing.results.temp_prefix`) and the older ``.<name>.*.tmp``."""
    from hsbearing.results import temp_prefix

    removed = []
    for name in set(names):
        for p in [*archive_dir.glob(f"{temp_prefix(name)}*.tmp"), *archive_dir.glob(f".{glob.escape(name)}.*.tmp")]:
            with contextlib.suppress(FileNotFoundError):
                p.unlink()
                removed.append(p)
    return removed


@contextlib.contextmanager
def _dir_lock(directory: Path):
    """Exclusive advisory lock on DIR (released by the OS if the process dies)."""
    directory.mkdir(parents=True, exist_ok=True)
    try:
        import fcntl
    except ImportError:  # pragma: no cover - not POSIX: no lock
        yield
        return
    path = directory / LOCK_NAME
    while True:
        fh = open(path, "a+")
        try:
            fcntl.flock(fh, fcntl.LOCK_EX | fcntl.LOCK_NB)
        except OSError:
            fh.close()
            raise CaseError(str(directory), None, "another hsbearing sweep is running in this directory") from None
        try:  # the file we locked must still be the one at the path (a finishing sweep unlinks it)
            same = os.fstat(fh.fileno()).st_ino == os.stat(path).st_ino
        except FileNotFoundError:
            same = False
        if same:
            break
        fh.close()
    try:
        yield
    finally:
        with contextlib.suppress(OSError):  # no empty lock file left behind (issue 27); unlinked while still held
            os.unlink(path)
        fh.close()


# ----------------------------------------------------------------------------- execution backends


class _Serial:
    """jobs=1: compute in the calling process."""

    name = "serial"

    def __enter__(self):
        return self

    def __exit__(self, *exc):
        return False

    def run(self, tasks, on_done):
        for key, args in tasks:
            on_done(key, *_compute_point(*args))


class _LocalPool:
    """Local worker processes; a crashed worker does not take the sweep down."""

    name = "processes"

    def __init__(self, jobs: int):
        self.jobs = jobs
        self.ctx = _mp_context()
        self.ex: ProcessPoolExecutor | None = None

    def _new(self, n):
        return ProcessPoolExecutor(max_workers=n, mp_context=self.ctx, initializer=_worker_init)

    def __enter__(self):
        return self

    def __exit__(self, exc_type, *exc):
        if self.ex is not None:
            if exc_type is not None:  # interrupted: do not wait for running points
                _terminate(self.ex)
            self.ex.shutdown(wait=exc_type is None, cancel_futures=True)
            self.ex = None
        return False

    def run(self, tasks, on_done):
        tasks = list(tasks)
        if not tasks:
            return
        suspects = self._run_batch(tasks, on_done, min(self.jobs, len(tasks)))
        # Points that were in flight when a worker died: one at a time, to find the culprit.
        for key, args in suspects:
            again = self._run_batch([(key, args)], on_done, 1)
            for k, _ in again:
                on_done(k, {"status": "crashed", "error": "worker process died while computing this point "
                            "(segfault, out of memory or killed)", "summary": {}, "wall_time": float("nan")}, None)

    def _run_batch(self, tasks, on_done, n) -> list:
        pending = list(tasks)
        suspects: list = []
        self.ex = self._new(n)
        futs = {}
        try:
            while pending or futs:
                while pending and len(futs) < 2 * n:  # keep the queue short: cancellable, fair
                    key, args = pending.pop(0)
                    futs[self.ex.submit(_compute_point, *args)] = (key, args)
                done, _ = wait(list(futs), timeout=_POLL, return_when=FIRST_COMPLETED)
                _check_interrupt()
                broken = False
                for f in done:
                    key, args = futs.pop(f)
                    try:
                        rec, ds = f.result()
                    except BrokenProcessPool:
                        suspects.append((key, args))
                        broken = True
                        continue
                    except Exception as exc:  # e.g. a point function that cannot be pickled
                        rec, ds = {"status": "error", "error": f"{type(exc).__name__}: {exc}", "summary": {},
                                   "wall_time": float("nan")}, None
                    on_done(key, rec, ds)
                if broken:
                    # every other in-flight point died with the pool: suspects too
                    for _f, (key, args) in futs.items():
                        suspects.append((key, args))
                    futs.clear()
                    self.ex.shutdown(wait=True, cancel_futures=True)
                    self.ex = self._new(n)
        except BaseException:
            _terminate(self.ex)
            self.ex.shutdown(wait=False, cancel_futures=True)
            self.ex = None
            raise
        self.ex.shutdown(wait=True)
        self.ex = None
        return suspects


#: Seconds between checks of a deferred Ctrl-C while waiting for points.
_POLL = 0.2
_INTERRUPTED = threading.Event()


def _check_interrupt() -> None:
    if _INTERRUPTED.is_set():
        _INTERRUPTED.clear()
        raise KeyboardInterrupt


@contextlib.contextmanager
def _deferred_sigint():
    """Turn Ctrl-C into a flag checked between waits.

    A KeyboardInterrupt raised *inside* concurrent.futures (or distributed) internals can leave
    a future's lock held, and the executor's manager thread then blocks forever at exit
    (observed: `hsbearing sweep` hung after Ctrl-C).  The flag is checked at safe points
    (:func:`_check_interrupt`) and raises KeyboardInterrupt there.  Only in the main thread and
    only if Python's default handler is installed; otherwise nothing changes.
    """
    if threading.current_thread() is not threading.main_thread() or \
            signal.getsignal(signal.SIGINT) is not signal.default_int_handler:
        yield
        return
    _INTERRUPTED.clear()
    old = signal.signal(signal.SIGINT, lambda signum, frame: _INTERRUPTED.set())
    try:
        yield
    finally:
        signal.signal(signal.SIGINT, old)
    _check_interrupt()  # a Ctrl-C during the last wait still interrupts


def _mp_context():
    """``spawn``: every worker is a direct child of the sweep process, so it dies with it.

    (``forkserver`` starts workers ~0.3 s faster here, but its workers are children of the fork
    server: when the sweep process is SIGKILLed, the server and its idle workers were observed to
    stay alive as orphans.  ``HSBEARING_MP_START=forkserver`` still selects it.)

    ``spawn`` (and ``forkserver``) workers re-import the caller's ``__main__`` script.  When the sweep
    is started from a script's top level outside ``if __name__ == "__main__":`` (the README example
    saved as a file), that re-import would start the sweep again in every worker, and every point
    would die (issue 13, item 2).  Then the workers are forked instead (Linux: ``fork`` does not
    re-run the script); where fork is not safe (macOS, Windows) a CaseError names the missing guard.
    """
    unguarded = unguarded_main_call()
    if unguarded is not None:
        if sys.platform.startswith("linux") and "fork" in multiprocessing.get_all_start_methods():
            return multiprocessing.get_context("fork")
        raise CaseError(unguarded, None, "hsbearing.sweep with jobs > 1 called outside an "
                        "'if __name__ == \"__main__\":' block: the worker processes re-import the script; "
                        "put the call under that guard (or pass jobs=1)")
    method = os.environ.get("HSBEARING_MP_START") or "spawn"
    ctx = multiprocessing.get_context(method)
    if method == "forkserver":
        ctx.set_forkserver_preload(["hsbearing.sweeps"])
    return ctx


def unguarded_main_call() -> str | None:
    """``"script.py:LINE"`` if the current call comes from the top-level code of a ``__main__`` script
    outside an ``if __name__ == "__main__":`` block (the statement that spawn workers would re-run), else None.

    Interactive sessions and ``python -c`` have no script file and are never re-run.  A script whose
    source cannot be read or parsed is assumed guarded.
    """
    import ast

    main = sys.modules.get("__main__")
    path = getattr(main, "__file__", None)
    if not path or main is None:
        return None
    frame = sys._getframe(1)
    while frame is not None and not (frame.f_globals is main.__dict__ and frame.f_code.co_name == "<module>"):
        frame = frame.f_back
    if frame is None:
        return None
    line = frame.f_lineno
    try:
        tree = ast.parse(Path(path).read_text(encoding="utf-8"), filename=str(path))
    except (OSError, SyntaxError, UnicodeDecodeError, ValueError):
        return None
    for node in tree.body:
        if node.lineno <= line <= (node.end_lineno or node.lineno):
            return None if isinstance(node, ast.If) and _is_main_guard(node.test) else f"{path}:{line}"
    return None


def _is_main_guard(test) -> bool:
    import ast

    if not (isinstance(test, ast.Compare) and len(test.ops) == 1 and isinstance(test.ops[0], ast.Eq)):
        return False
    sides = [test.left, test.comparators[0]]
    names = [x for x in sides if isinstance(x, ast.Name) and x.id == "__name__"]
    consts = [x for x in sides if isinstance(x, ast.Constant) and x.value == "__main__"]
    return len(names) == 1 and len(consts) == 1


def _terminate(ex: ProcessPoolExecutor) -> None:
    fn = getattr(ex, "terminate_workers", None)  # Python >= 3.14
    if fn is not None:
        with contextlib.suppress(Exception):
            fn()
        return
    for p in list((getattr(ex, "_processes", None) or {}).values()):
        with contextlib.suppress(Exception):
            p.terminate()


_SCHEDULER_ADDRESS = re.compile(
    r"^(?:(?:tcp|tls|ws|wss|ucx)://)?(?:[A-Za-z0-9](?:[A-Za-z0-9.-]*[A-Za-z0-9])?|\[[0-9A-Fa-f:.]+\]):(\d{1,5})/?$")


def check_scheduler_address(address: str, *, in_process_ok: bool = False) -> str:
    """A dask.distributed scheduler address ``[tcp://]host:port`` (also tls/ws/wss/ucx, ``inproc://``);
    CaseError naming ``--scheduler`` otherwise, at once (the client would retry an unparseable
    address until its connect timeout)."""
    a = str(address).strip()
    proto = a.split("://", 1)[0].lower() if "://" in a else "tcp"
    if proto == "inproc":  # a scheduler living in this very process (a library caller's LocalCluster(processes=False))
        if not in_process_ok:
            raise CaseError("--scheduler", None, f"{address!r}: an inproc:// scheduler exists only inside the process "
                                                 "that started it; give its tcp://host:port address")
        if len(a) > len("inproc://"):
            return a
    if proto == "tls":
        raise CaseError("--scheduler", None, f"{address!r}: TLS schedulers need a security configuration (certificates) "
                                             "that hsbearing does not pass; use a tcp:// or ws:// address (e.g. over an "
                                             "SSH tunnel)")
    if proto == "ucx":
        import importlib.util

        if importlib.util.find_spec("ucp") is None and importlib.util.find_spec("distributed_ucxx") is None:
            raise CaseError("--scheduler", None, f"{address!r}: the ucx:// protocol needs ucx-py, which is not "
                                                 "installed; use a tcp:// address")
    m = _SCHEDULER_ADDRESS.match(a)
    if not m or not 0 < int(m.group(1)) < 65536:
        raise CaseError("--scheduler", None, f"{address!r} is not a scheduler address (expected [tcp://]host:port, "
                                             "e.g. tcp://127.0.0.1:8786)")
    return a


class _Dask:
    """Submit the points to an existing dask.distributed scheduler."""

    name = "dask"

    #: seconds to wait for the scheduler before reporting bad input
    CONNECT_TIMEOUT = 15.0

    def __init__(self, address: str, timeout: float | None = None):
        check_scheduler_address(address, in_process_ok=True)
        self.address = address
        self.timeout = self.CONNECT_TIMEOUT if timeout is None else timeout
        self.client = None

    def __enter__(self):
        try:
            from distributed import Client
        except ImportError:  # pragma: no cover - dask[distributed] is a dependency
            raise CaseError("--scheduler", None, "dask.distributed is not installed") from None
        try:
            self.client = Client(self.address, timeout=self.timeout, set_as_default=False)
            # a worker-less scheduler would queue forever: say so (the tasks still wait for workers)
            if not self.client.scheduler_info().get("workers"):
                print(f"hsbearing: the dask scheduler at {self.address} has no workers yet; tasks wait for one",
                      file=sys.stderr)
        except (OSError, TimeoutError) as exc:
            raise CaseError("--scheduler", None, f"cannot connect to the dask scheduler at {self.address} ({exc})") from None
        except (TypeError, ValueError, RuntimeError, ImportError) as exc:  # a protocol the client cannot set up
            raise CaseError("--scheduler", None, f"cannot connect to the dask scheduler at {self.address} "
                                                 f"({type(exc).__name__}: {str(exc).splitlines()[0] if str(exc) else ''})") from None
        return self

    def __exit__(self, exc_type, *exc):
        if self.client is not None:
            self.client.close()
            self.client = None
        return False

    def run(self, tasks, on_done):
        tasks = list(tasks)
        killed = self._run_batch(tasks, on_done)
        # Points whose worker died (KilledWorker): possibly innocent neighbours of the point that kills
        # its worker.  Re-run them one at a time, so the culprit is identified exactly.
        for key, args, _ in killed:
            for k, _, exc in self._run_batch([(key, args)], on_done):
                on_done(k, {"status": "crashed", "error": f"worker process died while computing this point "
                            f"({type(exc).__name__}: {exc})", "summary": {}, "wall_time": float("nan")}, None)

    def _run_batch(self, tasks, on_done) -> list:
        import uuid

        from distributed import as_completed

        futs = {}
        killed = []
        tag = uuid.uuid4().hex[:8]
        for key, args in tasks:
            point = args[0]
            name = f"hsbearing-point-{point.name if point is not None else 'x'}-{key}-{tag}"
            futs[self.client.submit(_compute_point, *args, key=name, pure=False)] = (key, args)
        try:
            with self.client.as_current():
                finished = as_completed(list(futs))
            for f in _poll_iter(finished):
                key, args = futs[f]
                try:
                    rec, ds = f.result()
                except Exception as exc:
                    if type(exc).__name__ == "KilledWorker":
                        killed.append((key, args, exc))
                        continue
                    rec, ds = {"status": "error", "error": f"{type(exc).__name__}: {exc}", "summary": {},
                               "wall_time": float("nan")}, None
                on_done(key, rec, ds)
        except BaseException:
            for f in futs:
                with contextlib.suppress(Exception):
                    f.cancel()
            raise
        return killed


def _poll_iter(ac):
    """Iterate a distributed.as_completed, checking for a deferred Ctrl-C between results."""
    while True:
        batch = ac.next_batch(block=False) if hasattr(ac, "next_batch") else None
        if batch:
            yield from batch
            continue
        if ac.is_empty():
            return
        _check_interrupt()
        time.sleep(_POLL / 4)


def _backend(jobs: int | None, scheduler: str | None):
    if scheduler:
        return _Dask(scheduler)
    jobs = (os.cpu_count() or 1) if jobs is None else int(jobs)
    if jobs < 1:
        raise CaseError("-j", None, f"jobs must be >= 1, got {jobs}")
    return _Serial() if jobs == 1 else _LocalPool(jobs)


# ----------------------------------------------------------------------------- execute + assemble


def execute(
    plans: Sequence[SweepPlan],
    archive_dir: str | os.PathLike,
    *,
    jobs: int | None = None,
    scheduler: str | None = None,
    progress: bool = True,
    retry_failed: bool = False,
    backend=None,
) -> list[list[dict]]:
    """Compute every point of ``plans`` (deduplicated by archive name) -> one record list per plan.

    A record: ``status``, ``error``, ``wall_time``, ``archive`` (file name or
    ''), ``resumed`` (bool) and ``summary`` (dict of scalars).
    """
    archive_dir = Path(archive_dir)
    archive_dir.mkdir(parents=True, exist_ok=True)
    results: dict[str, dict] = {}  # archive name -> record
    todo: dict[str, tuple] = {}  # archive name -> (plan, point)
    n_total = sum(len(p.points) for p in plans)
    names = [pt.archive for plan in plans for pt in plan.points if pt.archive]
    _clean_temporaries(archive_dir, names)
    n_resumed = 0
    for plan in plans:
        for pt in plan.points:
            if pt.case is None or pt.archive in results or pt.archive in todo:
                continue
            path = archive_dir / pt.archive
            rec = _read_record(path, pt.hash) if path.exists() else None
            if rec is not None and not (retry_failed and rec.get("status") != STATUS_OK):
                rec = dict(rec, archive=pt.archive, resumed=True)
                results[pt.archive] = rec
                continue
            todo[pt.archive] = (plan, pt)
    n_resumed = sum(1 for plan in plans for pt in plan.points if pt.archive in results)
    n_invalid = sum(1 for plan in plans for pt in plan.points if pt.case is None)

    bar = None
    if progress:
        from tqdm.auto import tqdm

        bar = tqdm(total=n_total, initial=n_resumed + n_invalid, unit="pt", desc="sweep", file=sys.stderr,
                   dynamic_ncols=True, smoothing=0.1)
        if n_resumed:
            bar.set_postfix_str(f"{n_resumed} resumed")

    def on_done(name, rec, ds):
        plan, pt = todo[name]
        rec = dict(rec)
        rec["resumed"] = False
        if ds is not None and rec["status"] != "invalid":
            _write_archive(ds, rec, archive_dir / name, plan, pt)
            rec["archive"] = name
        else:
            rec["archive"] = ""
        results[name] = rec
        if bar is not None:
            dup = sum(1 for p in plans for q in p.points if q.archive == name)
            bar.update(dup)

    tasks = [(name, (pt.case, plan.kind, plan.duration, plan.point_fn)) for name, (plan, pt) in todo.items()]
    owned = backend is None
    if owned:
        backend = _backend(jobs, scheduler)
    try:
        # in-process computation (jobs=1) is safely interruptible: no deferral there
        with (_deferred_sigint() if not isinstance(backend, _Serial) else contextlib.nullcontext()), \
                (backend if owned else contextlib.nullcontext()):
            backend.run(tasks, on_done)
    finally:
        if bar is not None:
            bar.close()
    out = []
    for plan in plans:
        recs = []
        for pt in plan.points:
            if pt.case is None:
                recs.append({"status": "invalid", "error": pt.error, "wall_time": 0.0, "archive": "",
                             "resumed": False, "summary": {}})
            else:
                recs.append(results[pt.archive])
        out.append(recs)
    return out


def _summary_attrs(name: str) -> dict:
    if name in VARIABLES:
        v = VARIABLES[name]
        return {"units": v.units, "long_name": v.long_name}
    for prefix, what in (("mean_", "mean of "), ("max_", "maximum of "), ("rms_", "RMS of ")):
        if name.startswith(prefix) and name[len(prefix):] in VARIABLES:
            v = VARIABLES[name[len(prefix):]]
            return {"units": v.units, "long_name": what + v.long_name}
    return {}


def assemble(plan: SweepPlan, records: Sequence[dict], *, archive_prefix: str = "", attrs: Mapping | None = None) -> xr.Dataset:
    """The sweep Dataset: a dim per varied key (or ``point``), summaries + record variables."""
    shape, dims = plan.shape, plan.dims
    from hsbearing import systems

    systems.get(plan.base).register_outputs()  # its summary variables are declared there (units, long_name)
    # the run summaries are computed in the workers: declare their variables here too (units, long_name),
    # or a sweep with -j >= 2 or a scheduler writes them bare
    import hsbearing.analysis.orbit  # noqa: F401
    names: list[str] = []
    for r in records:
        for k in r.get("summary", {}):
            if k not in names and k not in _RECORD_VARS:
                names.append(k)
    data_vars = {}
    for name in names:
        vals = [r.get("summary", {}).get(name) for r in records]
        is_str = any(isinstance(v, str) for v in vals)
        if is_str:
            arr = np.array(["" if v is None or (isinstance(v, float) and math.isnan(v)) else str(v) for v in vals], dtype=object)
        else:
            arr = np.array([np.nan if v is None else float(v) for v in vals], dtype=float)
        data_vars[name] = _grid(arr, plan, shape, dims, _summary_attrs(name))
    for name in _RECORD_VARS:
        if name == "wall_time":
            arr = np.array([float(r.get("wall_time", np.nan)) for r in records])
        elif name == "resumed":
            arr = np.array([int(bool(r.get("resumed", False))) for r in records], dtype=np.int8)
        elif name == "archive":
            arr = np.array([(archive_prefix + r["archive"]) if r.get("archive") else "" for r in records], dtype=object)
        else:
            arr = np.array([str(r.get(name, "")) for r in records], dtype=object)
        data_vars[name] = _grid(arr, plan, shape, dims, _summary_attrs(name))
    ds = xr.Dataset(data_vars)
    for a in plan.axes:
        fld = SCHEMA[a.key.rpartition(".")[0]][a.key.rpartition(".")[2]]
        cattrs = {"long_name": fld.doc, "case_key": a.key}
        if a.kind in DIMENSIONS:
            cattrs["units"] = DIMENSIONS[a.kind]
        coord = np.array(a.coords, dtype=object if isinstance(a.coords[0], str) else None)
        labels = np.array([str(v) for v in a.values], dtype=object)
        if plan.zipped:
            ds = ds.assign_coords({a.dim: xr.Variable(("point",), coord, attrs=cattrs)})
            ds = ds.assign_coords({f"{a.dim}_label": xr.Variable(("point",), labels, attrs={"long_name": f"{a.key} as given"})})
        else:
            ds = ds.assign_coords({a.dim: xr.Variable((a.dim,), coord, attrs=cattrs)})
            ds = ds.assign_coords({f"{a.dim}_label": xr.Variable((a.dim,), labels, attrs={"long_name": f"{a.key} as given"})})
    if plan.zipped:
        ds = ds.assign_coords(point=np.arange(len(plan.points)))
    statuses = [r.get("status") for r in records]
    n_bad = sum(1 for s in statuses if s != STATUS_OK)
    status = STATUS_OK if n_bad == 0 else f"partial: {n_bad} of {len(records)} points not ok"
    ds.attrs.update(standard_attrs(plan.base, status=status))
    ds.attrs.update(
        {
            "title": "hsbearing sweep",
            "sweep_kind": plan.kind,
            "sweep_duration": "" if plan.duration is None else plan.duration,
            "sweep_mode": "zip" if plan.zipped else "product",
            "sweep_vary": json.dumps({a.key: list(a.values) for a in plan.axes}),
            "sweep_points": len(records),
            "sweep_points_ok": len(records) - n_bad,
            "sweep_points_resumed": sum(1 for r in records if r.get("resumed")),
            "sweep_point_fn": _fn_name(plan.point_fn),
        }
    )
    ds.attrs.update(dict(attrs or {}))
    return ds


def _grid(flat: np.ndarray, plan: SweepPlan, shape, dims, attrs) -> xr.Variable:
    return xr.Variable(dims, flat.reshape(shape), attrs=attrs)


def run_sweep(
    case,
    vary: Mapping[str, Any],
    *,
    zip: bool = False,  # noqa: A002 - the documented keyword
    jobs: int | None = None,
    scheduler: str | None = None,
    out_dir: str | os.PathLike,
    kind: str = "run",
    duration=None,
    progress: bool = True,
    point_fn: Callable | None = None,
    retry_failed: bool = False,
) -> xr.Dataset:
    """Run a sweep and return (and write to ``out_dir/sweep.nc``) its Dataset.

    Parameters
    ----------
    case : Case, bundled case name or path.
    vary : ``{key: values}``; key as accepted by :func:`hsbearing.case.resolve_key`
        (``"operating.axial_load"``, ``"axial_load"``, ``"oil"``); values a list
        of unit strings / numbers / names or a CLI string ``"100,500,1000N"``.
    zip : vary the keys together (equal-length lists; one dim ``point``)
        instead of the Cartesian product (one dim per key).
    jobs : local worker processes (default ``os.cpu_count()``; 1 = in-process).
    scheduler : ``"tcp://host:port"`` of a dask.distributed scheduler (overrides ``jobs``).
    out_dir : directory of the point archives and ``sweep.nc``.
    kind : ``"run"`` (dynamics, summary by :func:`hsbearing.analysis.summary`),
        ``"quasistatic"`` or ``"thermal"`` (thermal equilibrium, summary :func:`thermal_summary`).
    duration : simulated time [s] or unit string (kind "run"); None = the case's.
    progress : tqdm progress bar on stderr.
    point_fn : ``f(case, duration) -> xr.Dataset`` replacing the computation
        (module-level, picklable); part of the archive hash.
    retry_failed : recompute points whose archive records a status other than ok.
    """
    out_dir = Path(out_dir)
    check_output_path(out_dir, source="output directory", directory=True)
    plan = plan_sweep(case, vary, zip=zip, kind=kind, duration=duration, point_fn=point_fn)
    t0 = time.perf_counter()
    # bad -j / unreachable scheduler are reported before anything is written
    with _backend(jobs, scheduler) as backend, _dir_lock(out_dir):
        _clean_temporaries(out_dir, ["sweep.nc"])  # an interrupted write of the summary (we hold the lock)
        (records,) = execute([plan], out_dir, progress=progress, retry_failed=retry_failed, backend=backend)
        ds = assemble(plan, records, attrs={"sweep_wall_time": time.perf_counter() - t0,
                                            "sweep_backend": f"dask {scheduler}" if scheduler else f"jobs={jobs or os.cpu_count()}"})
        write_netcdf(ds, out_dir / "sweep.nc")
    _raise_if_nothing_computed(ds, records, out_dir / "sweep.nc")
    return ds


def _raise_if_nothing_computed(ds: xr.Dataset, records: Sequence[dict], path: Path) -> None:
    """A sweep whose every computed point crashed or errored never returns quietly: SolverError (partial = ds)."""
    computed = [r for r in records if r.get("status") != "invalid"]
    if computed and all(r.get("status") in ("crashed", "error") for r in computed):
        first = computed[0].get("error", "")
        raise SolverError(f"all {len(computed)} computed sweep points ended crashed/error (first: {first}); "
                          f"records in {path}", partial=ds)


# ----------------------------------------------------------------------------- CLI


def _parse_vary(items: Sequence[str]) -> dict[str, str]:
    out: dict[str, str] = {}
    for item in items or []:
        if "=" not in item:
            raise CaseError("--vary", item, "expected KEY=V1,V2,..., e.g. --vary axial_load=100,500,1000N")
        k, _, v = item.partition("=")
        k = k.strip()
        if k in out:
            raise CaseError("--vary", k, "varied twice")
        out[k] = v.strip()
    return out


def print_table(ds: xr.Dataset, file=None) -> None:
    """One line per point: varied values, status, a few summary values (with their units), error."""
    from hsbearing.display import format_value

    file = file or sys.stdout
    keys = [v for v in ("mean_cage_slip_ratio", "mean_cage_slip_ratio_raceway_control", "whirl_amplitude", "classification", "mean_inner_contact_load",
                        "mean_outer_contact_load", "cage_speed", "sfmc", "sfmc_ensemble_mean", "sfmc_ensemble_sd",
                        "sfmo", "sfmo_stderr", "rfmc") if v in ds]
    dims = ds["status"].dims
    labels = [c for c in ds.coords if str(c).endswith("_label")]
    for idx in np.ndindex(*ds["status"].shape):
        pt = ds.isel(dict(zip_(dims, idx)))
        parts = [f"{str(c)[:-6]}={pt[c].values.item()}" for c in labels]
        parts.append(f"status={pt['status'].values.item()}")
        for k in keys:  # in the units users read (hsbearing.display): um, r/min, %, uN m
            parts.append(f"{k}={format_value(pt[k], k)}")
        if pt["error"].values.item():
            parts.append(f"error={pt['error'].values.item()}")
        print("  ".join(parts), file=file)


def cli_base_case(args) -> Case:
    """The case of ``hsbearing sweep`` / ``hsbearing map``: ``CASE`` (default: the default case) with the
    repeated ``--set key=value`` overrides and ``--stop RULE`` (as ``--set simulation.stop=RULE``, set only when
    it changes the case: a default left out of the TOML keeps the archive hashes)."""
    from hsbearing.case import DEFAULT_CASE, parse_sets

    sets = parse_sets(getattr(args, "set", None))
    case = load_case(args.case or DEFAULT_CASE, **sets)
    stop = getattr(args, "stop", None)
    if stop and stop != case.simulation.stop:
        case = load_case(args.case or DEFAULT_CASE, **sets, **{"simulation.stop": stop})
    return case


def cli_main(args) -> int:
    """``hsbearing sweep CASE --vary KEY=V1,V2 [--zip] [-j N] [--scheduler ADDR] [--kind] [--duration] -o DIR``.

    Exit code 0 when every point is ok, 1 when some point failed numerically
    (its status and error are in ``DIR/sweep.nc``; the other points are
    kept), 2 on bad input, including a varied value that makes an invalid
    case (nothing computed or written), unless ``--keep-going``.
    """
    case = cli_base_case(args)
    vary = _parse_vary(args.vary)
    out = Path(args.output)
    check_output_path(out, directory=True)
    if args.scheduler:
        check_scheduler_address(args.scheduler)
    if not getattr(args, "keep_going", False):
        # On the command line a value that makes an invalid case is bad input: exit 2 before anything is
        # computed or written (the library, and --keep-going, record such points as "invalid" and go on).
        plan = plan_sweep(case, vary, zip=args.zip, kind=args.kind, duration=args.duration)
        bad = [pt for pt in plan.points if pt.case is None]
        if bad:
            where = ", ".join(f"{k}={v}" for k, v in bad[0].overrides.items())
            more = f" (and {len(bad) - 1} more point(s); --keep-going records them and runs the rest)" if len(bad) > 1 else \
                " (--keep-going records it and runs the rest)"
            raise CaseError("--vary", None, f"point {where} is not a valid case: {bad[0].error}{more}")
    try:
        ds = run_sweep(case, vary, zip=args.zip, jobs=args.jobs, scheduler=args.scheduler, out_dir=out,
                       kind=args.kind, duration=args.duration, progress=True)
    except SolverError as exc:
        if exc.partial is None:
            raise
        ds = exc.partial  # every point crashed: the table says why, exit 1 below
    print_table(ds)
    n, n_ok = ds.attrs["sweep_points"], ds.attrs["sweep_points_ok"]
    print(f"{n_ok} of {n} points ok ({ds.attrs['sweep_points_resumed']} resumed); wall time "
          f"{ds.attrs['sweep_wall_time']:.1f} s; sweep: {out / 'sweep.nc'}")
    return 0 if n_ok == n else 1
