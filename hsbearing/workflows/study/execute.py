"""Running a study: every table planned as a product sweep ``oil x values`` (over the band samples too with
``bands=True``), all points computed in one pass (:func:`hsbearing.workflows.sweeps.execute`) or, report only, read
back from the archives on disk; then one netCDF table per paper table and the report."""

from __future__ import annotations

import contextlib
import os
import time
from pathlib import Path
from typing import Any, Callable

import numpy as np
import xarray as xr

from hsbearing.case import CaseError, load_case, parse_quantity
from hsbearing.results import register, write_netcdf
from hsbearing.workflows import sweeps
from hsbearing.workflows.study.report import write_band_report, write_report
from hsbearing.workflows.study.spec import (
    BANDS_SUFFIX,
    RUNS,
    STATUS_MISSING,
    BandSample,
    Study,
    band_samples,
    load_study,
    normalise_label,
    sample_text,
)

# the study tables' own variables (docs/nomenclature.md); the band key coordinates are band_<leaf of the case key>
for _n, _d, _u, _l in [
    ("paper_classification", "", "1", "the paper's classification of the cell (study tables)"),
    ("sample", ("sample",), "1", "band sample index of a banded study table (0 = the nominal case when included)"),
    ("sample_label", ("sample",), "1", "band sample label: nominal, lhs1, lhs2, ..."),
    ("band_outer_land_diameter", ("sample",), "m", "bearing.outer_land_diameter of the band sample (guide clearance)"),
    ("band_guide_land_width", ("sample",), "m", "cage.guide_land_width of the band sample (default included)"),
    ("band_pocket_diameter", ("sample",), "m", "cage.pocket_diameter of the band sample"),
]:
    register(_n, _d, _u, _l)


def run_study(
    name,
    out_dir: str | os.PathLike,
    *,
    jobs: int | None = None,
    scheduler: str | None = None,
    duration=None,
    progress: bool = True,
    point_fn: Callable | None = None,
    tables: list[str] | None = None,
    bands: bool = False,
    band_samples_limit: int | None = None,
    report_only: bool = False,
    stop: str | None = "converged",
    keep: str = "answer",
    extend="default",
) -> dict[str, Any]:
    """Run a study; returns ``{"tables": {id: Dataset}, "report": Path, "wall_time": s, ...}``.

    ``duration`` (s or unit string) overrides ``[study] duration``;
    ``point_fn`` replaces the dynamic model (tests, dry runs) and is named in
    the report; ``tables`` restricts to some table ids; ``bands`` runs every
    cell over the samples of ``[bands]`` (:func:`band_samples`) and writes
    ``DIR/<table>_bands.nc`` and ``DIR/report_bands.md`` instead;
    ``band_samples_limit`` K runs only the first K samples (the nominal one and
    the first K-1 Latin-hypercube points: same archives, so a later run with
    all samples resumes them; a prefix of a Latin hypercube is not stratified,
    and the report says so); ``report_only`` computes nothing: the tables and
    the report are made from the archives already in ``DIR/runs`` (the others
    are "missing"), e.g. to look at a banded study while it runs (use a copy of
    the directory: a running study holds its lock); ``stop`` ("duration" or
    "converged", :mod:`hsbearing.analysis.stoprule`) sets ``simulation.stop`` of every
    point (default converged, as ``hsbearing study``; "duration" or None: the
    study case's, i.e. the whole duration).  It is part of each point's case,
    hence of its archive hash: stopped and full-length runs never alias.  ``keep``: what each point archive
    keeps, "answer" (default) or "full" (:func:`hsbearing.workflows.sweeps.execute`).  ``extend``: "default" (6 x
    each point's duration), a budget [s] of total simulated time or None: a point whose label is undetermined with
    an estimate of the time it needs is continued in its worker until determined, the stop rule's convergence or
    the budget (:func:`hsbearing.workflows.sweeps.plan.extension_budget`); part of each extended point's hash.
    """
    study = load_study(name)
    # only "converged" is written into the cases: the study case stops at its duration, and a default left out of
    # the TOML keeps the archive hashes of the full-length runs
    if stop not in (None, "duration", "converged"):
        raise CaseError("--stop", "stop", f"must be duration or converged, got {stop!r}")
    stop_set = {"simulation.stop": "converged"} if stop == "converged" else {}
    out = Path(out_dir)
    dur = duration if duration is not None else study.spec["study"].get("duration")
    if isinstance(dur, str):
        dur = parse_quantity(dur, "time", source="--duration" if duration is not None else study.source_path,
                             key="duration")
    chosen = [t for t in study.tables if tables is None or t["id"] in tables]
    if not chosen:
        raise CaseError(study.source_path, "table", f"no table selected (have: {', '.join(t['id'] for t in study.tables)})")
    if bands:
        return run_banded(study, chosen, out, dur, jobs=jobs, scheduler=scheduler, progress=progress,
                           point_fn=point_fn, limit=band_samples_limit, report_only=report_only, stop_set=stop_set,
                           keep=keep, extend=extend)
    plans = [_table_plan(study, t, _table_case(study, t, {}, stop_set), dur, point_fn,
                         f"{study.source_path} [{t['id']}]", extend) for t in chosen]
    with _computed(plans, out, jobs=jobs, scheduler=scheduler, progress=progress,
                   report_only=report_only, keep=keep) as (records, wall, backend_label):
        datasets = {}
        for t, plan, recs in zip(chosen, plans, records):
            ds = _assemble(study, t, plan, recs, backend_label)
            paper = _paper_classification(study, t, ds["status"].dims)
            if paper is not None:
                ds["paper_classification"] = paper
            write_netcdf(ds, out / f"{t['id']}.nc")
            datasets[t["id"]] = ds
        info = _run_info(plans, records, wall=wall, backend_label=backend_label, dur=dur, stop_set=stop_set,
                         point_fn=point_fn)
        report = write_report(study, datasets, out, info)
    return {"tables": datasets, "report": report, **info}


def run_banded(study: Study, chosen: list[dict], out: Path, dur, *, jobs, scheduler, progress, point_fn,
                limit: int | None = None, report_only: bool = False, stop_set: dict | None = None,
               keep: str = "answer", extend="default") -> dict[str, Any]:
    """cells x band samples in one pass (one progress bar over all points); see :func:`run_study`."""
    from hsbearing.models.geometry import GuideLandError, guide_lands

    all_samples = band_samples(study)
    if limit is not None and not (isinstance(limit, int) and 1 <= limit):
        raise CaseError("--band-samples", None, f"must be a positive integer, got {limit!r}")
    samples = all_samples[:limit] if limit else all_samples
    plans: dict[tuple[str, int], sweeps.SweepPlan] = {}
    for t in chosen:
        for smp in samples:
            where = f"{study.source_path} [{t['id']}, band sample {smp.label}]"
            try:
                base = _table_case(study, t, smp.overrides, stop_set or {})
                guide_lands(base)
            except (GuideLandError, CaseError) as exc:
                raise CaseError(study.source_path, "bands", f"sample {smp.label} ({sample_text(smp)}) is not a "
                                f"valid case for {t['id']}: {exc}") from None
            plan = _table_plan(study, t, base, dur, point_fn, where, extend)
            bad = [pt for pt in plan.points if pt.case is None]
            if bad:
                raise CaseError(study.source_path, "bands", f"sample {smp.label} ({sample_text(smp)}): "
                                f"{bad[0].error}")
            plans[(t["id"], smp.index)] = plan
    keys = list(plans)
    with _computed([plans[k] for k in keys], out, jobs=jobs, scheduler=scheduler, progress=progress,
                   report_only=report_only, keep=keep) as (records, wall, backend_label):
        recs = dict(zip(keys, records))
        datasets = {}
        for t in chosen:
            parts = [_assemble(study, t, plans[(t["id"], smp.index)], recs[(t["id"], smp.index)], backend_label)
                     for smp in samples]
            ds = _banded_table(study, t, parts, samples)
            write_netcdf(ds, out / f"{t['id']}{BANDS_SUFFIX}.nc")
            datasets[t["id"]] = ds
        info = _run_info(list(plans.values()), records, wall=wall, backend_label=backend_label, dur=dur,
                         stop_set=stop_set, point_fn=point_fn)
        info.update({"samples": samples, "n_band_samples": len(all_samples)})
        report = write_band_report(study, datasets, out, info)
    return {"tables": datasets, "report": report, **info}


# ----------------------------------------------------------------------------- shared by both


def _table_case(study: Study, t: dict, overrides: dict, stop_set: dict):
    """The study's base case with the table's ``set`` overrides, then ``overrides`` (a band sample's), then
    the stop rule."""
    return load_case(study.spec["study"]["case"], **t.get("set", {}), **overrides, **stop_set)


def _table_plan(study: Study, t: dict, base, dur, point_fn, source: str, extend=None) -> sweeps.SweepPlan:
    """A table as a product sweep ``oil x values`` of ``base`` (its points extended with ``extend``)."""
    vary = {"lubricant.oil": study.oils, t["vary"]: list(t["values"])}
    return sweeps.plan_sweep(base, vary, kind="run", duration=dur, point_fn=point_fn, source=source, extend=extend)


def backend_or_none(jobs, scheduler, report_only: bool):
    return contextlib.nullcontext() if report_only else sweeps.make_backend(jobs, scheduler)


def _backend_label(jobs, scheduler, report_only: bool) -> str:
    return ("report only (nothing computed)" if report_only else
            f"dask {scheduler}" if scheduler else f"jobs={jobs or os.cpu_count()}")


@contextlib.contextmanager
def _computed(plans, out: Path, *, jobs, scheduler, progress, report_only: bool, keep: str = "answer"):
    """Lock ``out``, compute the points of ``plans`` into ``out/runs`` (or, report only, read back the archives
    there) and yield ``(records per plan, wall time [s], backend label)``; the lock is held until the block
    ends, so the tables and the report are written under it."""
    t0 = time.perf_counter()
    with backend_or_none(jobs, scheduler, report_only) as backend, sweeps.dir_lock(out):
        records = execute_or_collect(plans, out / RUNS, progress=progress, backend=backend, report_only=report_only,
                                     keep=keep)
        yield records, time.perf_counter() - t0, _backend_label(jobs, scheduler, report_only)


def execute_or_collect(plans, archive_dir: Path, *, progress, backend, report_only: bool,
                       keep: str = "answer") -> list[list[dict]]:
    """:func:`hsbearing.workflows.sweeps.execute`, or with ``report_only`` the records of the archives already on disk
    (status "missing" for the others; nothing is computed or written in ``archive_dir``)."""
    if not report_only:
        return sweeps.execute(plans, archive_dir, progress=progress, backend=backend, keep=keep)
    cache: dict[str, dict] = {}
    out = []
    for plan in plans:
        recs = []
        for pt in plan.points:
            if pt.archive not in cache:
                path = archive_dir / pt.archive
                rec = sweeps.read_record(path, pt.hash) if path.exists() else None
                cache[pt.archive] = (dict(rec, archive=pt.archive, resumed=True) if rec is not None else
                                     {"status": STATUS_MISSING, "error": "not computed yet (report only)",
                                      "wall_time": float("nan"), "archive": "", "resumed": False, "summary": {}})
            recs.append(cache[pt.archive])
        out.append(recs)
    return out


def _assemble(study: Study, t: dict, plan, recs: list[dict], backend_label: str) -> xr.Dataset:
    """The sweep Dataset of one table (of one band sample), archives named relative to the study directory."""
    return sweeps.assemble(plan, recs, archive_prefix=f"{RUNS}/",
                           attrs={"study": study.name, "study_table": t["id"], "sweep_backend": backend_label})


def _paper_classification(study: Study, t: dict, dims) -> xr.Variable | None:
    """The paper's class of every cell of table ``t`` on ``dims`` (oil x the table's key), or None."""
    paper = t.get("paper", {})
    if not paper:
        return None
    lab = np.array([[normalise_label(paper[o][i]) if o in paper else "" for i in range(len(t["values"]))]
                    for o in study.oils], dtype=object)
    return xr.Variable(tuple(dims), lab, attrs={"long_name": f"classification in the paper ({t.get('title', t['id'])})"})


def _banded_table(study: Study, t: dict, parts: list[xr.Dataset], samples: list[BandSample]) -> xr.Dataset:
    """One Dataset over ``sample x oil x <key>`` from the tables of the band samples, with the sample index,
    label and band values as coordinates and the band definition in the attributes."""
    from hsbearing.results import VARIABLES

    ds = xr.concat(parts, dim="sample", data_vars="all", coords="minimal", compat="override",
                   combine_attrs="override")
    ds = ds.assign_coords(sample=("sample", np.array([s.index for s in samples]),
                                  {"long_name": "band sample (0 = nominal case when included)"}))
    ds = ds.assign_coords(sample_label=("sample", np.array([s.label for s in samples], dtype=object),
                                        {"long_name": "band sample label"}))
    for key in study.bands["keys"]:
        leaf = key.rpartition(".")[2]
        ds = ds.assign_coords({f"band_{leaf}": ("sample", np.array([s.values[key] for s in samples], float),
                                                {"long_name": f"{key} of the band sample", "units": "m",
                                                 "case_key": key})})
    paper = _paper_classification(study, t, [d for d in ds["status"].dims if d != "sample"])
    if paper is not None:
        ds["paper_classification"] = paper
    for name in ["sample", "sample_label", "paper_classification"] + [f"band_{k.rpartition('.')[2]}"
                                                                        for k in study.bands["keys"]]:
        if name in ds.variables and name in VARIABLES:
            ds[name].attrs.update({"units": VARIABLES[name].units, "long_name": VARIABLES[name].long_name})
    ds.attrs.update({"band_method": study.bands.get("method", "lhs"), "band_seed": int(study.bands["seed"]),
                     "band_samples": len(samples),
                     "band_include_nominal": int(bool(study.bands.get("include_nominal", True)))})
    return ds


def _extension_info(plans) -> str:
    budgets = sorted({pt.extend for plan in plans for pt in plan.points if pt.extend is not None})
    if not budgets:
        return "none"
    return (f"undetermined runs with an estimate of the time they need continued until determined, the stop rule's "
            f"convergence or {', '.join(f'{b:.6g}' for b in budgets)} s of simulated time in all")


def _run_info(plans, records, *, wall: float, backend_label: str, dur, stop_set: dict | None, point_fn) -> dict:
    """What the report says of the invocation: wall time, backend, duration, stop rule, point function, and
    the distinct points planned and computed (a point shared by two tables counted once)."""
    return {
        "wall_time": wall,
        "backend": backend_label,
        "duration": dur,
        "stop": "converged" if stop_set else "duration",
        "point_fn": sweeps.fn_name(point_fn),
        "extension": _extension_info(plans),
        "n_unique_points": len({pt.archive or id(pt) for plan in plans for pt in plan.points}),
        "n_computed": len({r.get("archive") or id(r) for recs in records for r in recs
                           if not r.get("resumed") and r.get("status") not in ("invalid", STATUS_MISSING)}),
    }
