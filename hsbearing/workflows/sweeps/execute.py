"""Running a plan on a backend and assembling the records into ``sweep.nc`` (:func:`run_sweep`)."""

from __future__ import annotations

import contextlib
import json
import math
import os
import sys
import time
from pathlib import Path
from typing import Any, Callable, Mapping, Sequence

import numpy as np
import xarray as xr

from hsbearing.case import (
    DIMENSIONS,
    SCHEMA,
)
from hsbearing.errors import ClusterLost, Interrupted, SolverError
from hsbearing.results import VARIABLES, check_output_path, standard_attrs, write_netcdf
from hsbearing.workflows.sweeps.archives import clean_temporaries, dir_lock, read_record, write_point_archive
from hsbearing.workflows.sweeps.backends import SerialBackend, deferred_sweep_sigint, make_backend
from hsbearing.workflows.sweeps.plan import RECORD_VARS, STATUS_OK, SweepPlan, fn_name, plan_sweep

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
    keep: str = "answer",
) -> list[list[dict]]:
    """Compute every point of ``plans`` (deduplicated by archive name) -> one record list per plan.

    A record: ``status``, ``error``, ``wall_time``, ``archive`` (file name or
    ''), ``resumed`` (bool) and ``summary`` (dict of scalars).

    ``keep``: what each point archive of a dynamic run keeps, "answer" (default: summaries, label and reasons,
    section points, the cage orbit, decimated histories, final state; :func:`points.keep_answer`) or "full".
    """
    from hsbearing.workflows.sweeps.points import check_keep

    check_keep(keep, "keep")
    archive_dir = Path(archive_dir)
    archive_dir.mkdir(parents=True, exist_ok=True)
    results: dict[str, dict] = {}  # archive name -> record
    todo: dict[str, tuple] = {}  # archive name -> (plan, point)
    n_total = sum(len(p.points) for p in plans)
    names = [pt.archive for plan in plans for pt in plan.points if pt.archive]
    clean_temporaries(archive_dir, names)
    n_resumed = 0
    for plan in plans:
        for pt in plan.points:
            if pt.case is None or pt.archive in results or pt.archive in todo:
                continue
            path = archive_dir / pt.archive
            rec = read_record(path, pt.hash) if path.exists() else None
            if rec is not None and keep == "full" and rec.get("kept") == "answer":
                rec = None  # the whole trajectory was asked for: a reduced archive is computed again
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
            write_point_archive(ds, rec, archive_dir / name, plan, pt)
            rec["archive"] = name
        else:
            rec["archive"] = ""
        results[name] = rec
        if bar is not None:
            dup = sum(1 for p in plans for q in p.points if q.archive == name)
            bar.update(dup)

    tasks = [(name, (pt.case, plan.kind, plan.duration, plan.point_fn, keep, pt.extend))
             for name, (plan, pt) in todo.items()]
    owned = backend is None
    if owned:
        backend = make_backend(jobs, scheduler)
    try:
        # in-process computation (jobs=1) is safely interruptible: no deferral there
        with (deferred_sweep_sigint() if not isinstance(backend, SerialBackend) else contextlib.nullcontext()), \
                (backend if owned else contextlib.nullcontext()):
            backend.run(tasks, on_done)
    except ClusterLost as exc:  # the scheduler went away: the same words, with what is kept
        if getattr(exc, "sweep_kept", None) is not None:
            raise
        n_points = sum(1 for plan in plans for pt in plan.points if pt.case is not None)
        kept = sum(1 for r in results.values() if r.get("archive"))
        err = ClusterLost(f"{exc}; {kept} of {n_points} points kept in {archive_dir}; the same command resumes "
                          "from them")
        err.sweep_kept = kept
        raise err from None
    except KeyboardInterrupt as exc:  # say what is kept and how to go on (every kept archive is complete)
        if isinstance(exc, Interrupted) and getattr(exc, "sweep_kept", None) is not None:
            raise
        n_points = sum(1 for plan in plans for pt in plan.points if pt.case is not None)
        kept = sum(1 for r in results.values() if r.get("archive"))
        err = Interrupted(f"{kept} of {n_points} points kept in {archive_dir}; the same command resumes from them")
        err.sweep_kept = kept
        raise err from None
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


#: how a sweep point's value of a time series (power_loss, drive_torque ...) was taken, by sweep kind
_POINT_VALUE = {"run": "time mean after the transient of the ", "quasistatic": "value at the quasi-static state of the "}


def _summary_attrs(name: str, kind: str = "") -> dict:
    if name in VARIABLES:
        v = VARIABLES[name]
        if "time" in v.dims and kind in _POINT_VALUE:  # one value per point of a time series: say which
            return {"units": v.units, "long_name": _POINT_VALUE[kind] + v.long_name}
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
            if k not in names and k not in RECORD_VARS:
                names.append(k)
    data_vars = {}
    for name in names:
        vals = [r.get("summary", {}).get(name) for r in records]
        is_str = any(isinstance(v, str) for v in vals)
        if is_str:
            arr = np.array(["" if v is None or (isinstance(v, float) and math.isnan(v)) else str(v) for v in vals], dtype=object)
        else:
            arr = np.array([np.nan if v is None else float(v) for v in vals], dtype=float)
        data_vars[name] = _grid(arr, plan, shape, dims, _summary_attrs(name, plan.kind))
    for name in RECORD_VARS:
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
        cattrs["units"] = DIMENSIONS[a.kind] if a.kind in DIMENSIONS else "" if isinstance(a.coords[0], str) else "1"
        coord = np.array(a.coords, dtype=object if isinstance(a.coords[0], str) else None)
        labels = np.array([str(v) for v in a.values], dtype=object)
        if plan.zipped:
            ds = ds.assign_coords({a.dim: xr.Variable(("point",), coord, attrs=cattrs)})
            ds = ds.assign_coords({f"{a.dim}_label": xr.Variable(("point",), labels, attrs={"long_name": f"{a.key} as given", "units": ""})})
        else:
            ds = ds.assign_coords({a.dim: xr.Variable((a.dim,), coord, attrs=cattrs)})
            ds = ds.assign_coords({f"{a.dim}_label": xr.Variable((a.dim,), labels, attrs={"long_name": f"{a.key} as given", "units": ""})})
    if plan.zipped:
        ds = ds.assign_coords(point=xr.Variable(("point",), np.arange(len(plan.points)),
                                                attrs={"units": "1", "long_name": "index of the point of a --zip sweep"}))
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
            "sweep_point_fn": fn_name(plan.point_fn),
            "sweep_extension": _extension_text(plan),
        }
    )
    ds.attrs.update(dict(attrs or {}))
    return ds


def _extension_text(plan: SweepPlan) -> str:
    """How the sweep's points were extended (``attrs["sweep_extension"]``)."""
    budgets = sorted({pt.extend for pt in plan.points if pt.extend is not None})
    if not budgets:
        return "none"
    b = ", ".join(f"{x:.6g}" for x in budgets)
    return (f"undetermined runs with an estimate of the time they need continued until determined, the stop rule's "
            f"convergence or a budget of {b} s simulated time in all (at most 8 extensions)")


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
    keep: str = "answer",
    extend=None,
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
    keep : "answer" (default) or "full": what a dynamic point's archive keeps (:func:`execute`).
    extend : None (default: no extension), "default" or a budget [s] (float or unit string) of total simulated
        time: a run whose label is undetermined is continued in its worker until it is determined, the stop
        rule's convergence holds or the budget is spent (:func:`hsbearing.workflows.sweeps.plan.extension_budget`,
        docs/sweeps.md "Extend until determined").
    """
    out_dir = Path(out_dir)
    check_output_path(out_dir, source="output directory", directory=True)
    plan = plan_sweep(case, vary, zip=zip, kind=kind, duration=duration, point_fn=point_fn, extend=extend)
    t0 = time.perf_counter()
    # bad -j / unreachable scheduler are reported before anything is written
    with make_backend(jobs, scheduler) as backend, dir_lock(out_dir):
        clean_temporaries(out_dir, ["sweep.nc"])  # an interrupted write of the summary (we hold the lock)
        (records,) = execute([plan], out_dir, progress=progress, retry_failed=retry_failed, backend=backend,
                             keep=keep)
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
