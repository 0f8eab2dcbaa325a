"""Bundled studies: a set of sweeps with the paper's results next to ours, and a report.

A study is a TOML file (``hsbearing/studies/<name>.toml``, shipped in the
wheel) with a ``[study]`` table (base case, oils, default duration), one
``[[table]]`` per paper table (overrides ``set``, the varied key ``vary`` and
its ``values``, and ``[table.paper]``: the paper's classification of every
cell) and ``[[figure]]`` entries naming representative cells.

``run_study("zhang2016", out_dir)`` plans every table as a product sweep
``oil x values`` (:func:`hsbearing.sweeps.plan_sweep`), computes all the
points in one pass (:func:`hsbearing.sweeps.execute`; points shared by two
tables, e.g. 1000 N at 130 degC, are computed once), then writes::

    DIR/runs/<case>-<hash>.nc    one archive per point (resumable)
    DIR/<table>.nc               one sweep Dataset per table (dims oil x <key>)
    DIR/figures/*.png            whirl orbits + Poincare maps; slip ratio curves
    DIR/report.md                paper vs ours for every cell, figures, wall time

Agreement is a finding, not a target: the report lists every cell where our
classification differs and names what can drive a difference.

Bands over the unknown inputs (``run_study(..., bands=True)``, ``hsbearing study
NAME --bands``): the study's ``[bands]`` table names case keys the paper does not
give, a range for each, and a Latin-hypercube sample of those ranges with a fixed
seed (:func:`band_samples`; the nominal case is sample 0 when
``include_nominal``).  Every cell runs every sample (common random numbers, so the
cells are comparable).  A sample is only a set of case overrides: its points go to
the same ``DIR/runs/<case>-<hash>.nc`` archives as the nominal study (the hash is
taken over the full case), so the nominal points of an earlier ``hsbearing study``
in the same directory are reused, and an interrupted banded study resumes.  The
banded outputs do not overwrite the nominal ones::

    DIR/<table>_bands.nc         one Dataset per table (dims sample x oil x <key>)
    DIR/report_bands.md          per cell: class fractions over the band, majority, agrees, occurs
"""

from __future__ import annotations

import contextlib
import math
import os
import sys
import time
import tomllib
from dataclasses import dataclass
from importlib import resources
from pathlib import Path
from typing import Any, Callable

import numpy as np
import xarray as xr

from hsbearing import sweeps
from hsbearing.case import DIMENSIONS, CaseError, load_case, parse_quantity
from hsbearing.results import atomic_write, open_run, register, write_netcdf

__all__ = ["list_studies", "study_help", "load_study", "run_study", "normalise_label", "write_report", "cli_main",
           "BandSample", "band_samples", "latin_hypercube", "band_cell_stats", "write_band_report",
           "stability_rank", "derive_table6", "TABLE6_RULE", "orbit_drift"]

RUNS = "runs"
FIGURES = "figures"

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


def _studies_dir() -> Path:
    return Path(str(resources.files("hsbearing") / "studies"))


def list_studies() -> dict[str, str]:
    """Bundled study names -> title."""
    out = {}
    for p in sorted(_studies_dir().glob("*.toml")):
        with contextlib.suppress(tomllib.TOMLDecodeError):
            out[p.stem] = tomllib.loads(p.read_text()).get("study", {}).get("title", "")
    return out


def study_help() -> str:
    """The bundled studies for ``hsbearing study --help``: name, title and measured runtime of each."""
    lines = ["bundled studies:"]
    for p in sorted(_studies_dir().glob("*.toml")):
        with contextlib.suppress(tomllib.TOMLDecodeError):
            st = tomllib.loads(p.read_text()).get("study", {})
            lines.append(f"  {p.stem}: {st.get('title', '')}")
            if st.get("runtime"):
                lines.append(f"    runtime: {st['runtime']} (--duration shortens it)")
            if st.get("runtime_bands"):
                lines.append(f"    with --bands: {st['runtime_bands']}")
    return "\n".join(lines)


def normalise_label(label: str) -> str:
    """Paper/analysis period labels to one vocabulary ("Quasi-periodicity" -> "quasi-periodic")."""
    s = str(label).strip().lower()
    if s.startswith("quasi"):
        return "quasi-periodic"
    if s.startswith("chao"):
        return "chaos"
    if s in ("1 period", "one period", "period-1", "periodic", "1 periods"):
        return "1 period"
    parts = s.split()
    if len(parts) == 2 and parts[0].isdigit() and parts[1].startswith("period"):
        return f"{int(parts[0])} period" + ("s" if int(parts[0]) > 1 else "")
    return s


@dataclass
class Study:
    name: str
    source_path: str
    spec: dict

    @property
    def tables(self) -> list[dict]:
        return self.spec.get("table", [])

    @property
    def figures(self) -> list[dict]:
        return self.spec.get("figure", [])

    @property
    def oils(self) -> list[str]:
        return list(self.spec["study"]["oils"])

    @property
    def bands(self) -> dict | None:
        """The ``[bands]`` table (unknown inputs as ranges), or None."""
        return self.spec.get("bands")


def load_study(name_or_path: str | os.PathLike) -> Study:
    """A bundled study by name, or a study TOML file; checked for consistency (CaseError if not)."""
    p = Path(name_or_path)
    if not (p.suffix == ".toml" and p.exists()):
        cand = _studies_dir() / f"{name_or_path}.toml"
        if not cand.exists():
            raise CaseError(str(name_or_path), None, f"no such study (bundled: {', '.join(list_studies())})")
        p = cand
    try:
        spec = tomllib.loads(p.read_text())
    except tomllib.TOMLDecodeError as exc:
        raise CaseError(str(p), None, f"malformed TOML: {exc}") from None
    src = str(p)
    if "study" not in spec:
        raise CaseError(src, "study", "missing [study] table")
    for key in ("case", "oils"):
        if key not in spec["study"]:
            raise CaseError(src, f"study.{key}", "missing required key")
    oils = list(spec["study"]["oils"])
    ids = set()
    for i, t in enumerate(spec.get("table", [])):
        where = f"table[{i}]"
        for key in ("id", "vary", "values"):
            if key not in t:
                raise CaseError(src, f"{where}.{key}", "missing required key")
        ids.add(t["id"])
        paper = t.get("paper", {})
        for oil, labels in paper.items():
            if oil not in oils:
                raise CaseError(src, f"{where}.paper.{oil}", f"oil not in study.oils {oils}")
            if len(labels) != len(t["values"]):
                raise CaseError(src, f"{where}.paper.{oil}", f"{len(labels)} labels for {len(t['values'])} values")
    for i, f in enumerate(spec.get("figure", [])):
        for cell in f.get("cells", []):
            tab = next((t for t in spec.get("table", []) if t["id"] == cell[0]), None)
            if tab is None or cell[1] not in oils or cell[2] not in tab["values"]:
                raise CaseError(src, f"figure[{i}].cells", f"unknown cell {cell!r}")
    if "bands" in spec:
        _check_bands(spec["bands"], src)
    for oil, row in spec.get("table6", {}).items():
        if oil not in oils:
            raise CaseError(src, f"table6.{oil}", f"oil not in study.oils {oils}")
        for tid in row:
            if tid not in ids:
                raise CaseError(src, f"table6.{oil}.{tid}", f"unknown table (have: {', '.join(sorted(ids))})")
    return Study(spec["study"].get("name", p.stem), src, spec)


BAND_METHODS = ("lhs",)


def _check_bands(b: dict, src: str) -> None:
    """The ``[bands]`` table: keys with [low, high] ranges, method, seed, samples, include_nominal."""
    from hsbearing.sweeps import _field

    if not isinstance(b, dict):
        raise CaseError(src, "bands", "must be a table")
    known = {"keys", "method", "seed", "samples", "include_nominal"}
    for k in b:
        if k not in known:
            raise CaseError(src, f"bands.{k}", f"unknown key (allowed: {', '.join(sorted(known))})")
    if b.get("method", "lhs") not in BAND_METHODS:
        raise CaseError(src, "bands.method", f"unknown method {b.get('method')!r} (allowed: {', '.join(BAND_METHODS)})")
    seed = b.get("seed")
    if not isinstance(seed, int) or isinstance(seed, bool) or seed < 0:
        raise CaseError(src, "bands.seed", f"must be a non-negative integer (a fixed seed), got {seed!r}")
    n = b.get("samples")
    if not isinstance(n, int) or isinstance(n, bool) or n < 1:
        raise CaseError(src, "bands.samples", f"must be a positive integer, got {n!r}")
    if not isinstance(b.get("include_nominal", True), bool):
        raise CaseError(src, "bands.include_nominal", "must be true or false")
    keys = b.get("keys")
    if not isinstance(keys, dict) or not keys:
        raise CaseError(src, "bands.keys", "missing: a table of case keys, each [low, high]")
    for key, rng in keys.items():
        table, leaf, fld = _field(key, src)
        full = f"{table}.{leaf}"
        if full != key:
            raise CaseError(src, f"bands.keys.{key}", f"give the full case key ({full})")
        if not (isinstance(rng, list) and len(rng) == 2):
            raise CaseError(src, f"bands.keys.{key}", "must be [low, high]")
        lo, hi = (parse_quantity(v, fld.kind, source=src, key=f"bands.keys.{key}") for v in rng)
        if not lo < hi:
            raise CaseError(src, f"bands.keys.{key}", f"low {rng[0]} is not below high {rng[1]}")


# ----------------------------------------------------------------------------- bands


@dataclass(frozen=True)
class BandSample:
    """One sample of the band: its index and label, the case overrides (unit strings; none for the nominal
    case) and the SI values of the band keys (for the nominal sample: the case's effective values)."""

    index: int
    label: str
    overrides: dict
    values: dict


def latin_hypercube(n: int, d: int, seed: int) -> np.ndarray:
    """An ``n x d`` Latin-hypercube sample of the unit cube: each column has exactly one point in each
    of the n strata [i/n, (i+1)/n), at a uniform random position inside it (McKay, Beckman & Conover,
    Technometrics 21 (1979) 239-245).  ``numpy.random.default_rng(seed)``: the same seed gives the same
    sample (PCG64 is stable across numpy versions)."""
    rng = np.random.default_rng(seed)
    u = np.empty((n, d))
    for j in range(d):
        u[:, j] = (rng.permutation(n) + rng.random(n)) / n
    return u


#: band values are rounded to this [m] so the overrides (and the archive hashes) are short and exact
BAND_RESOLUTION = 1e-7

_UNIT_OUT = {"length": (1e3, "mm")}


def _format_override(kind: str, si: float) -> str:
    """A band value as a case-file string: lengths in mm with 4 decimals (0.1 um), else SI with its unit."""
    if kind in _UNIT_OUT:
        scale, unit = _UNIT_OUT[kind]
        return f"{si * scale:.4f} {unit}"
    unit = DIMENSIONS.get(kind, "")
    return f"{si!r} {unit}".strip()


def _effective_value(case, key: str) -> float:
    """The SI value of a band key in a case, including the derived defaults (land width, pocket diameter)."""
    table, _, leaf = key.rpartition(".")
    obj = case
    for part in table.split("."):
        obj = getattr(obj, part)
    v = getattr(obj, leaf, None)
    if v is not None:
        return float(v)
    if key == "cage.guide_land_width":
        from hsbearing.models.geometry import guide_lands

        return float(guide_lands(case).width)
    if key == "cage.pocket_diameter" and case.cage.pocket_clearance is not None:
        return float(case.bearing.ball_diameter + 2 * case.cage.pocket_clearance)
    return float("nan")


def band_samples(study: "Study", case=None) -> list[BandSample]:
    """The band samples of a study: the nominal case first (if ``include_nominal``), then ``samples``
    Latin-hypercube points of the ranges in ``[bands.keys]`` (seed ``[bands] seed``), values rounded to
    0.1 um.  ``case`` (default: the study's base case) gives the nominal values."""
    b = study.bands
    if not b:
        raise CaseError(study.source_path, "bands", "this study defines no [bands] table")
    from hsbearing.sweeps import _field

    keys = list(b["keys"])
    kinds = [_field(k, study.source_path)[2].kind for k in keys]
    ranges = [tuple(parse_quantity(v, kd, source=study.source_path, key=f"bands.keys.{k}") for v in b["keys"][k])
              for k, kd in zip(keys, kinds)]
    base = case if case is not None else load_case(study.spec["study"]["case"])
    out: list[BandSample] = []
    if b.get("include_nominal", True):
        out.append(BandSample(0, "nominal", {}, {k: _effective_value(base, k) for k in keys}))
    u = latin_hypercube(int(b["samples"]), len(keys), int(b["seed"]))
    for i, row in enumerate(u):
        vals, ov = {}, {}
        for k, kd, (lo, hi), x in zip(keys, kinds, ranges, row):
            v = round((lo + x * (hi - lo)) / BAND_RESOLUTION) * BAND_RESOLUTION
            ov[k] = _format_override(kd, v)
            vals[k] = parse_quantity(ov[k], kd)
        out.append(BandSample(len(out), f"lhs{i + 1}", ov, vals))
    return out


def band_cell_stats(labels, statuses, confidences=None, details=None, paper: str = "") -> dict[str, Any]:
    """Aggregate one cell over the band samples.

    ``labels``/``statuses``/``confidences``/``details``: one entry per sample (the classification, the
    point status, the classifier confidence, the sub-label).  Samples whose status is not ok are left
    out of the fractions (``n_failed``); "undetermined" is an outcome like any class.  Returns
    ``fractions`` {class: fraction of the completed samples}, ``subfractions`` {class: {sub-label:
    fraction}}, ``majority`` (the most frequent class; ties joined with " / "), ``tie``, ``agrees``
    (the paper's class is the majority, alone), ``agrees_tied`` (the paper's class is one of tied
    majorities), ``occurs`` (the paper's class appears in at least one sample), ``confidence`` (mean
    confidence of the samples in the majority class), ``n_ok``, ``n_failed``, ``n``.
    """
    n = len(labels)
    confidences = list(confidences) if confidences is not None else [float("nan")] * n
    details = list(details) if details is not None else [""] * n
    ok = [i for i in range(n) if statuses[i] == sweeps.STATUS_OK]
    counts: dict[str, int] = {}
    sub: dict[str, dict[str, int]] = {}
    for i in ok:
        c = normalise_label(labels[i]) or "-"
        counts[c] = counts.get(c, 0) + 1
        if details[i]:
            sub.setdefault(c, {})
            sub[c][str(details[i])] = sub[c].get(str(details[i]), 0) + 1
    n_ok = len(ok)
    paper = normalise_label(paper) if paper else ""
    if n_ok:
        top = max(counts.values())
        winners = sorted(c for c, k in counts.items() if k == top)
    else:
        winners = []
    maj = " / ".join(winners) if winners else "-"
    conf = [float(confidences[i]) for i in ok if (normalise_label(labels[i]) or "-") in winners
            and confidences[i] is not None and np.isfinite(float(confidences[i]))]
    return {
        "fractions": {c: k / n_ok for c, k in sorted(counts.items(), key=lambda kv: (-kv[1], kv[0]))},
        "subfractions": {c: {d: k / n_ok for d, k in sorted(v.items())} for c, v in sub.items()},
        "majority": maj,
        "tie": len(winners) > 1,
        "agrees": bool(paper) and winners == [paper],
        "agrees_tied": bool(paper) and len(winners) > 1 and paper in winners,
        "occurs": bool(paper) and counts.get(paper, 0) > 0,
        "confidence": float(np.mean(conf)) if conf else float("nan"),
        "n_ok": n_ok,
        "n_failed": n - n_ok,
        "n": n,
    }


# ----------------------------------------------------------------------------- run


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
    "converged", :mod:`hsbearing.stoprule`) sets ``simulation.stop`` of every
    point (default converged, as ``hsbearing study``; "duration" or None: the
    study case's, i.e. the whole duration).  It is part of each point's case,
    hence of its archive hash: stopped and full-length runs never alias.
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
        return _run_banded(study, chosen, out, dur, jobs=jobs, scheduler=scheduler, progress=progress,
                           point_fn=point_fn, limit=band_samples_limit, report_only=report_only, stop_set=stop_set)
    plans = []
    for t in chosen:
        base = load_case(study.spec["study"]["case"], **t.get("set", {}), **stop_set)
        vary = {"lubricant.oil": study.oils, t["vary"]: list(t["values"])}
        plans.append(sweeps.plan_sweep(base, vary, kind="run", duration=dur, point_fn=point_fn,
                                       source=f"{study.source_path} [{t['id']}]"))
    t0 = time.perf_counter()
    with _backend_or_none(jobs, scheduler, report_only) as backend, sweeps._dir_lock(out):
        records = _execute_or_collect(plans, out / RUNS, progress=progress, backend=backend, report_only=report_only)
        wall = time.perf_counter() - t0
        backend_label = ("report only (nothing computed)" if report_only else
                         f"dask {scheduler}" if scheduler else f"jobs={jobs or os.cpu_count()}")
        datasets = {}
        for t, plan, recs in zip(chosen, plans, records):
            ds = sweeps.assemble(plan, recs, archive_prefix=f"{RUNS}/",
                                 attrs={"study": study.name, "study_table": t["id"], "sweep_backend": backend_label})
            paper = t.get("paper", {})
            if paper:
                lab = np.array([[normalise_label(paper[o][i]) if o in paper else "" for i in range(len(t["values"]))]
                                for o in study.oils], dtype=object)
                ds["paper_classification"] = xr.Variable(ds["status"].dims, lab, attrs={
                    "long_name": f"classification in the paper ({t.get('title', t['id'])})"})
            write_netcdf(ds, out / f"{t['id']}.nc")
            datasets[t["id"]] = ds
        n_points = len({pt.archive or id(pt) for plan in plans for pt in plan.points})
        info = {
            "wall_time": wall,
            "backend": backend_label,
            "duration": dur,
            "stop": "converged" if stop_set else "duration",
            "point_fn": sweeps._fn_name(point_fn),
            "n_unique_points": n_points,
            "n_computed": len({r.get("archive") or id(r) for recs in records for r in recs
                               if not r.get("resumed") and r.get("status") not in ("invalid", STATUS_MISSING)}),
        }
        report = write_report(study, datasets, out, info)
    return {"tables": datasets, "report": report, **info}



def _backend_or_none(jobs, scheduler, report_only: bool):
    return contextlib.nullcontext() if report_only else sweeps._backend(jobs, scheduler)


STATUS_MISSING = "missing"


def _execute_or_collect(plans, archive_dir: Path, *, progress, backend, report_only: bool) -> list[list[dict]]:
    """:func:`hsbearing.sweeps.execute`, or with ``report_only`` the records of the archives already on disk
    (status "missing" for the others; nothing is computed or written in ``archive_dir``)."""
    if not report_only:
        return sweeps.execute(plans, archive_dir, progress=progress, backend=backend)
    cache: dict[str, dict] = {}
    out = []
    for plan in plans:
        recs = []
        for pt in plan.points:
            if pt.archive not in cache:
                path = archive_dir / pt.archive
                rec = sweeps._read_record(path, pt.hash) if path.exists() else None
                cache[pt.archive] = (dict(rec, archive=pt.archive, resumed=True) if rec is not None else
                                     {"status": STATUS_MISSING, "error": "not computed yet (report only)",
                                      "wall_time": float("nan"), "archive": "", "resumed": False, "summary": {}})
            recs.append(cache[pt.archive])
        out.append(recs)
    return out


def _run_banded(study: Study, chosen: list[dict], out: Path, dur, *, jobs, scheduler, progress, point_fn,
                limit: int | None = None, report_only: bool = False, stop_set: dict | None = None) -> dict[str, Any]:
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
                base = load_case(study.spec["study"]["case"], **t.get("set", {}), **smp.overrides, **(stop_set or {}))
                guide_lands(base)
            except GuideLandError as exc:
                raise CaseError(study.source_path, "bands", f"sample {smp.label} ({_sample_text(smp)}) is not a "
                                f"valid case for {t['id']}: {exc}") from None
            except CaseError as exc:
                raise CaseError(study.source_path, "bands", f"sample {smp.label} ({_sample_text(smp)}) is not a "
                                f"valid case for {t['id']}: {exc}") from None
            vary = {"lubricant.oil": study.oils, t["vary"]: list(t["values"])}
            plan = sweeps.plan_sweep(base, vary, kind="run", duration=dur, point_fn=point_fn, source=where)
            bad = [pt for pt in plan.points if pt.case is None]
            if bad:
                raise CaseError(study.source_path, "bands", f"sample {smp.label} ({_sample_text(smp)}): "
                                f"{bad[0].error}")
            plans[(t["id"], smp.index)] = plan
    keys = list(plans)
    t0 = time.perf_counter()
    with _backend_or_none(jobs, scheduler, report_only) as backend, sweeps._dir_lock(out):
        records = _execute_or_collect([plans[k] for k in keys], out / RUNS, progress=progress, backend=backend,
                                      report_only=report_only)
        wall = time.perf_counter() - t0
        recs = dict(zip(keys, records))
        backend_label = ("report only (nothing computed)" if report_only else
                         f"dask {scheduler}" if scheduler else f"jobs={jobs or os.cpu_count()}")
        datasets = {}
        for t in chosen:
            parts = []
            for smp in samples:
                ds = sweeps.assemble(plans[(t["id"], smp.index)], recs[(t["id"], smp.index)], archive_prefix=f"{RUNS}/",
                                     attrs={"study": study.name, "study_table": t["id"], "sweep_backend": backend_label})
                parts.append(ds)
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
            paper = t.get("paper", {})
            if paper:
                lab = np.array([[normalise_label(paper[o][i]) if o in paper else "" for i in range(len(t["values"]))]
                                for o in study.oils], dtype=object)
                dims = [d for d in ds["status"].dims if d != "sample"]
                ds["paper_classification"] = xr.Variable(tuple(dims), lab, attrs={
                    "long_name": f"classification in the paper ({t.get('title', t['id'])})"})
            from hsbearing.results import VARIABLES

            for name in ["sample", "sample_label", "paper_classification"] + [f"band_{k.rpartition('.')[2]}"
                                                                                for k in study.bands["keys"]]:
                if name in ds.variables and name in VARIABLES:
                    ds[name].attrs.update({"units": VARIABLES[name].units, "long_name": VARIABLES[name].long_name})
            ds.attrs.update({"band_method": study.bands.get("method", "lhs"), "band_seed": int(study.bands["seed"]),
                             "band_samples": len(samples),
                             "band_include_nominal": int(bool(study.bands.get("include_nominal", True)))})
            write_netcdf(ds, out / f"{t['id']}{BANDS_SUFFIX}.nc")
            datasets[t["id"]] = ds
        all_points = {pt.archive or id(pt) for plan in plans.values() for pt in plan.points}
        info = {
            "wall_time": wall,
            "backend": backend_label,
            "duration": dur,
            "stop": "converged" if stop_set else "duration",
            "point_fn": sweeps._fn_name(point_fn),
            "n_unique_points": len(all_points),
            "n_computed": len({r.get("archive") or id(r) for rs in records for r in rs
                               if not r.get("resumed") and r.get("status") not in ("invalid", STATUS_MISSING)}),
            "samples": samples,
            "n_band_samples": len(all_samples),
        }
        report = write_band_report(study, datasets, out, info)
    return {"tables": datasets, "report": report, **info}


BANDS_SUFFIX = "_bands"


def _sample_text(smp: BandSample) -> str:
    return ", ".join(f"{k.rpartition('.')[2]} = {v * 1e3:.4f} mm" for k, v in smp.values.items())

# ----------------------------------------------------------------------------- report


def _value_label(ds: xr.Dataset, dim: str, i: int) -> str:
    return str(ds[f"{dim}_label"].values[i])


def _fmt(x, spec=".3g") -> str:
    try:
        x = float(x)
    except (TypeError, ValueError):
        return str(x)
    return "-" if not math.isfinite(x) else format(x, spec)


def write_report(study: Study, datasets: dict[str, xr.Dataset], out: Path, info: dict) -> Path:
    """``out/report.md`` with the comparison tables, the figures and the wall time."""
    figdir = out / FIGURES
    figdir.mkdir(parents=True, exist_ok=True)
    lines: list[str] = []
    st = study.spec["study"]
    lines += [f"# {st.get('title', study.name)}", ""]
    lines += [f"Source: {st.get('source', '')}. Study definition: `hsbearing/studies/{study.name}.toml`; "
              f"generated by `hsbearing study {study.name}` (hsbearing {_version()}) on "
              f"{time.strftime('%Y-%m-%d %H:%M UTC', time.gmtime())}.", ""]
    if info.get("point_fn"):
        lines += [f"> **Not the dynamic model.** The points of this report were computed by the point function "
                  f"`{info['point_fn']}` (a stand-in used to test the study machinery); its classifications "
                  "say nothing about the bearing.", ""]
    dur = info.get("duration")
    lines += ["## Run", "",
              f"- simulated time per point: {_fmt(dur * 1e3 if dur else float('nan'), '.4g')} ms"
              + ("" if dur else " (the case's `[simulation] duration`)")
              + (" at most: stop rule `converged` (a run stops when its answer has converged; its archive records "
                 "`stopped_at` and `stop_reason`; docs/sweeps.md)" if info.get("stop") == "converged" else ""),
              f"- execution: {info['backend']} on {os.cpu_count()} core(s) of `{_host()}`",
              f"- points: {info['n_unique_points']} distinct cases ({info['n_computed']} computed in this invocation, "
              f"the others resumed from `{RUNS}/`)",
              (f"- wall time of this invocation (report only: nothing computed): {info['wall_time']:.1f} s"
               if info["backend"].startswith("report only") else
               f"- **wall time of the whole study (this invocation): {info['wall_time']:.1f} s**"),
              f"- sum of the per-point wall times: {_sum_wall(datasets):.1f} s"] + _section_stats(datasets) + [""]
    totals = [0, 0, 0]  # agree, classified, undetermined
    alt_totals = [0, 0]  # the cage-revolution (clock) section's label: agree, classified
    disagreements: list[str] = []
    for t in study.tables:
        ds = datasets.get(t["id"])
        if ds is None:
            continue
        dim = t["vary"].rpartition(".")[2]
        lines += [f"## {t.get('title', t['id'])}", ""]
        header = f"| {t.get('axis_label', dim)} | " + " | ".join(f"{o} paper | {o} ours" for o in study.oils) + " |"
        lines += [header, "|" + "---|" * (1 + 2 * len(study.oils))]
        for i in range(ds.sizes[dim]):
            row = [_value_label(ds, dim, i)]
            for o in study.oils:
                pt = ds.sel(oil=o).isel({dim: i})
                paper = str(pt["paper_classification"].values) if "paper_classification" in ds else ""
                ours = _ours(pt)
                ok = paper and ours == paper
                if paper and pt["status"].item() == sweeps.STATUS_OK:
                    if ours == "undetermined":
                        totals[2] += 1
                    else:
                        totals[0] += int(bool(ok))
                        totals[1] += 1
                if paper and not ok:
                    disagreements.append(f"{t['id']}, oil {o}, {row[0]}: paper {paper}, ours {ours}{_details(pt)}")
                alt = _ours(pt, "classification_alternative")
                if paper and pt["status"].item() == sweeps.STATUS_OK and alt not in ("-", "undetermined"):
                    alt_totals[0] += int(alt == paper)
                    alt_totals[1] += 1
                cell = f"{ours} {'(=)' if ok else '(x)'}" if paper else ours
                if alt != "-":
                    cell += f"; clock: {alt}" + ((" (=)" if alt == paper else " (x)") if paper else "")
                row += [paper or "-", cell]
            lines.append("| " + " | ".join(row) + " |")
        lines += ["", "Cage slip ratio [%] (time mean after the transient; ours) -- "
                  f"compare {t.get('slip_figure', 'the paper')}:", ""]
        lines += [f"| {t.get('axis_label', dim)} | " + " | ".join(study.oils) + " |", "|" + "---|" * (1 + len(study.oils))]
        for i in range(ds.sizes[dim]):
            row = [_value_label(ds, dim, i)]
            for o in study.oils:
                pt = ds.sel(oil=o).isel({dim: i})
                row.append(_fmt(pt["mean_cage_slip_ratio"].item() * 100, ".2f") if "mean_cage_slip_ratio" in ds else "-")
            lines.append("| " + " | ".join(row) + " |")
        png = _plot_slip(ds, t, study.oils, figdir / f"slip_{t['id']}.png")
        if png:
            lines += ["", f"![cage slip ratio, {t['id']}]({FIGURES}/{png.name})"]
        lines.append("")
    n_cells = sum(len(t["values"]) * len(study.oils) for t in study.tables if t["id"] in datasets)
    lines += ["## Agreement", "",
              f"Classification agrees with the paper in **{totals[0]} of {totals[1]}** cells that completed and "
              f"were classified; {totals[2]} completed cells are *undetermined* (too few Poincare points or an "
              f"inconclusive test: simulate longer); {n_cells - totals[1] - totals[2]} of {n_cells} cells did not "
              "complete.", ""]
    if alt_totals[1]:
        lines += [f"Under the cage-revolution (clock, once per cage revolution) section kept for comparison ('clock:' in "
                  f"the tables), the label agrees in {alt_totals[0]} of {alt_totals[1]} classified cells.  Our label is "
                  "read on the section transverse to the flow (docs/analysis.md): the model is autonomous and the cage "
                  "angle is not a clock.", ""]
    if disagreements:
        lines += ["Cells where ours differs:", ""] + [f"- {d}" for d in disagreements] + [""]
    lines += [
        "What can drive a difference (a finding, not a target to tune for):",
        "",
        "- the reading of the traction-coefficient formulas of the three oils (Eq. 2 and Table 1; see docs/traction.md);",
        "- the geometry the paper does not give (conformities, pitch diameter, nominal contact angle, land and guide "
        "clearances: marked \"assumed\" in `hsbearing/cases/zhang2016.toml`);",
        "- the simulated duration: a short run may still carry the start-up transient, and a classification from few "
        "Poincare points is less certain (see the confidence in each point archive);",
        "- the classification thresholds of `hsbearing.analysis.classify` (docs/analysis.md), whereas the paper "
        "classifies its Poincare maps by eye.",
        "",
    ]
    figs = []
    for f in study.figures:
        png = _plot_cells(study, datasets, f, figdir / f"{f['id']}.png")
        if png:
            figs.append(f"### {f.get('title', f['id'])}\n\n![{f['id']}]({FIGURES}/{png.name})\n")
    if figs:
        lines += ["## Whirl orbits and Poincare maps of representative cells", ""] + figs
    gal = []
    drift: list[str] = []
    for t in study.tables:
        if t["id"] in datasets:
            png = _plot_gallery(study, t, datasets[t["id"]], out, figdir / f"cells_{t['id']}.png", drift)
            if png:
                gal.append(f"![every cell of {t['id']}]({FIGURES}/{png.name})\n")
    if gal:
        lines += ["## Every cell: whirl orbit and Poincare map", ""] + gal + _drift_lines(drift)
    lines += _table6_lines(study, datasets)
    failed = [(tid, ds) for tid, ds in datasets.items() if (ds["status"] != sweeps.STATUS_OK).any()]
    if failed:
        lines += ["## Points that did not complete", ""]
        for tid, ds in failed:
            for idx in np.ndindex(*ds["status"].shape):
                pt = ds.isel(dict(zip(ds["status"].dims, idx)))
                if pt["status"].item() != sweeps.STATUS_OK:
                    where = ", ".join(f"{str(c)[:-6]}={pt[c].item()}" for c in ds.coords if str(c).endswith("_label"))
                    lines.append(f"- {tid}: {where}: {pt['status'].item()}: {pt['error'].item()}")
        lines.append("")
    path = out / "report.md"
    with atomic_write(path) as tmp:
        tmp.write_text("\n".join(lines))
    return path


# ----------------------------------------------------------------------------- banded report

#: the superseded study (land-film sign error and the other cage-physics defects of the cage-physics issue)
SUPERSEDED = {"zhang2016": "9 of 37 classified cells agreed (one run per cell, guessed clearances; docs/validation/zhang2016.md before issue 16)"}


def _fraction_text(st: dict) -> str:
    bits = []
    for c, f in st["fractions"].items():
        sub = st["subfractions"].get(c)
        extra = f" [{', '.join(f'{d} {g:.2f}' for d, g in sub.items())}]" if sub else ""
        bits.append(f"{c} {f:.2f}{extra}")
    return "; ".join(bits) or "-"


def _cell_stats(ds: xr.Dataset, dim: str, oil: str, i: int) -> dict:
    pt = ds.sel(oil=oil).isel({dim: i})
    n = pt.sizes["sample"]

    def col(name, default):
        return list(pt[name].values) if name in pt else [default] * n

    paper = str(pt["paper_classification"].values) if "paper_classification" in pt else ""
    return band_cell_stats(col("classification", ""), col("status", ""), col("classification_confidence", np.nan),
                           col("classification_detail", ""), paper=paper) | {"paper": paper}


def _band_counts(stats: list[dict]) -> dict[str, int]:
    evaluated = [s for s in stats if s["paper"] and s["n_ok"]]
    return {
        "cells": len([s for s in stats if s["paper"]]),
        "evaluated": len(evaluated),
        "agrees": sum(s["agrees"] for s in evaluated),
        "tied": sum(s["agrees_tied"] for s in evaluated),
        "occurs": sum(s["occurs"] for s in evaluated),
        "undetermined": sum(s["majority"] == "undetermined" for s in evaluated),
    }


def write_band_report(study: Study, datasets: dict[str, xr.Dataset], out: Path, info: dict) -> Path:
    """``out/report_bands.md``: per cell the class fractions over the band, the majority, agrees/occurs,
    the agreement counts per table and overall, the band definition and the wall times."""
    figdir = out / FIGURES
    figdir.mkdir(parents=True, exist_ok=True)
    st = study.spec["study"]
    b = study.bands
    samples: list[BandSample] = info["samples"]
    lines: list[str] = [f"# {st.get('title', study.name)}: with the unknown inputs as bands", ""]
    lines += [f"Source: {st.get('source', '')}. Study definition: `hsbearing/studies/{study.name}.toml` "
              f"(`[bands]`); generated by `hsbearing study {study.name} --bands` (hsbearing {_version()}) on "
              f"{time.strftime('%Y-%m-%d %H:%M UTC', time.gmtime())}.", ""]
    if info.get("point_fn"):
        lines += [f"> **Not the dynamic model.** The points of this report were computed by the point function "
                  f"`{info['point_fn']}` (a stand-in used to test the study machinery); its classifications "
                  "say nothing about the bearing.", ""]
    # -- run and wall times
    dur = info.get("duration")
    walls = _point_walls(datasets)
    n_pts = len(walls)
    mean_w = float(np.mean(list(walls.values()))) if walls else float("nan")
    cores = os.cpu_count() or 1
    lines += ["## Run and wall time", "",
              f"- simulated time per point: {_fmt(dur * 1e3 if dur else float('nan'), '.4g')} ms"
              + ("" if dur else " (the case's `[simulation] duration`)")
              + (" at most: stop rule `converged` (docs/sweeps.md)" if info.get("stop") == "converged" else ""),
              f"- execution: {info['backend']} on {cores} core(s) of `{_host()}`",
              f"- points: {info['n_unique_points']} distinct cases = cells x {len(samples)} band samples "
              f"({info['n_computed']} computed in this invocation, the others resumed from `{RUNS}/`, e.g. the "
              "nominal points of an earlier `hsbearing study` in the same directory)",
              (f"- wall time of this invocation (report only: nothing computed): {info['wall_time']:.1f} s"
               if info["backend"].startswith("report only") else
               f"- **wall time of the banded study (this invocation): {info['wall_time']:.1f} s**"),
              f"- sum of the per-point wall times (all {n_pts} distinct points, resumed ones as recorded in their "
              f"archives): {sum(walls.values()):.1f} s; mean per point {_fmt(mean_w, '.3g')} s",
              _nominal_wall_line(out, info["wall_time"], study.name),
              f"- **projection: a 4000-run map on a 16-core cluster** = 4000 x {_fmt(mean_w, '.3g')} s / 16 = "
              f"{_fmt(4000 * mean_w / 16 / 60, '.3g')} min (the mean point wall time recorded by the runs at this "
              "duration, one point per core, no scheduling overhead; the runs shared this machine's "
              f"{cores} core(s) with other work, so the per-point time includes that contention)",
              ""] + _section_stats(datasets) + [""]
    # -- band definition
    lines += ["## The band", "",
              f"Method: {b.get('method', 'lhs')} (Latin hypercube, seed {b['seed']}), {b['samples']} samples"
              + (" plus the nominal case (sample 0)" if b.get("include_nominal", True) else "")
              + "; the same samples in every cell (common random numbers). Ranges and their justification: "
                f"`hsbearing/studies/{study.name}.toml` and docs/validation/{study.name}.md.", ""]
    if len(samples) < info.get("n_band_samples", len(samples)):
        lines += [f"> **Only the first {len(samples)} of the {info['n_band_samples']} band samples were run** "
                  "(`--band-samples`): a prefix of a Latin hypercube is not stratified, so the fractions below are "
                  "over a random, not a Latin-hypercube, sample of the band. The other samples resume later with the "
                  "same archives.", ""]
    base = load_case(st["case"])
    hdr = ["sample"] + [f"`{k}` [mm]" for k in b["keys"]]
    derived = []
    if "bearing.outer_land_diameter" in b["keys"] and base.cage.outside_diameter:
        derived.append(("radial guide clearance [um]",
                        lambda v: (v["bearing.outer_land_diameter"] - base.cage.outside_diameter) / 2 * 1e6))
    if "cage.pocket_diameter" in b["keys"]:
        derived.append(("radial pocket clearance [um]",
                        lambda v: (v["cage.pocket_diameter"] - base.bearing.ball_diameter) / 2 * 1e6))
    hdr += [d[0] for d in derived]
    lines += ["| " + " | ".join(hdr) + " |", "|" + "---|" * len(hdr)]
    rng = ["range"] + [" - ".join(str(x) for x in b["keys"][k]) for k in b["keys"]] + [""] * len(derived)
    lines.append("| " + " | ".join(rng) + " |")
    for smp in samples:
        row = [f"{smp.index} ({smp.label})"] + [f"{smp.values[k] * 1e3:.4f}" for k in b["keys"]]
        row += [f"{f(smp.values):.1f}" for _, f in derived]
        lines.append("| " + " | ".join(row) + " |")
    lines.append("")
    # -- per table
    all_stats: list[dict] = []
    per_table: list[tuple[str, dict]] = []
    for t in study.tables:
        ds = datasets.get(t["id"])
        if ds is None:
            continue
        dim = t["vary"].rpartition(".")[2]
        lines += [f"## {t.get('title', t['id'])}", "",
                  "Class fractions over the band samples that completed (sub-labels of \"1 period\" in brackets); "
                  "*majority*: the most frequent class (ties joined by /); *agrees*: the paper's class is the "
                  "majority alone (\"tie\": one of tied majorities); *occurs*: the paper's class appears in at "
                  "least one sample; *confidence*: mean classifier confidence of the samples in the majority class; "
                  "*whirl / cage speed*: dominant whirl frequency of the cage centre over the cage speed (1 = a "
                  "whirl synchronous with the section, the paper's \"1 period\" single circle; +-11 = Z: a vibration at the "
                  "ball-pass frequency, seen where the cage is held on one spot of the land).",
                  "",
                  f"| {t.get('axis_label', dim)} | oil | paper | ours over the band | majority | agrees | occurs | "
                  "confidence | samples ok | whirl / cage speed (band range) |", "|" + "---|" * 10]
        tstats = []
        for i in range(ds.sizes[dim]):
            for o in study.oils:
                stt = _cell_stats(ds, dim, o, i)
                stt["where"] = f"{t['id']}, oil {o}, {_value_label(ds, dim, i)}"
                tstats.append(stt)
                agree = "yes" if stt["agrees"] else ("tie" if stt["agrees_tied"] else "no")
                lines.append(f"| {_value_label(ds, dim, i)} | {o} | {stt['paper'] or '-'} | {_fraction_text(stt)} | "
                             f"{stt['majority']} | {agree if stt['paper'] else '-'} | "
                             f"{('yes' if stt['occurs'] else 'no') if stt['paper'] else '-'} | "
                             f"{_fmt(stt['confidence'], '.2f')} | {stt['n_ok']}/{stt['n']} | "
                             f"{_band_range(ds.sel(oil=o).isel({dim: i}), 'whirl_frequency_ratio')} |")
        c = _band_counts(tstats)
        per_table.append((t["id"], c))
        all_stats += tstats
        lines += ["", f"{t['id']}: the paper's class is the majority in **{c['agrees']} of {c['evaluated']}** cells "
                      f"(+{c['tied']} tied), occurs in **{c['occurs']} of {c['evaluated']}**.", ""]
        if "mean_cage_slip_ratio" in ds:
            lines += [f"Cage slip ratio [%] (time mean after the transient): nominal sample and the range over the "
                      f"band -- compare {t.get('slip_figure', 'the paper')}:", "",
                      f"| {t.get('axis_label', dim)} | " + " | ".join(study.oils) + " |",
                      "|" + "---|" * (1 + len(study.oils))]
            labels = list(ds["sample_label"].values)
            for i in range(ds.sizes[dim]):
                row = [_value_label(ds, dim, i)]
                for o in study.oils:
                    cell = ds.sel(oil=o).isel({dim: i})
                    v = np.asarray(cell["mean_cage_slip_ratio"].values, float) * 100
                    v = np.where(np.asarray(cell["status"].values) == sweeps.STATUS_OK, v, np.nan)
                    nom = v[labels.index("nominal")] if "nominal" in labels else float("nan")
                    fin = v[np.isfinite(v)]
                    row.append(f"{_fmt(nom, '.2f')} [{_fmt(fin.min(), '.2f')}, {_fmt(fin.max(), '.2f')}]"
                               if fin.size else "-")
                lines.append("| " + " | ".join(row) + " |")
            png = _plot_slip_band(ds, t, study.oils, figdir / f"slip_bands_{t['id']}.png")
            if png:
                lines += ["", f"![cage slip ratio over the band, {t['id']}]({FIGURES}/{png.name})"]
            lines.append("")
        drift: list[str] = []
        png = _plot_gallery(study, t, ds, out, figdir / f"cells_bands_{t['id']}.png", drift)
        if png:
            lines += ["Every cell (one sample each: the nominal one when it is in the majority class):", "",
                      f"![every cell of {t['id']} over the band]({FIGURES}/{png.name})", ""]
        lines += _drift_lines(drift)
    # -- counts
    tot = _band_counts(all_stats)
    lines += ["## Agreement over the band", "",
              "| table | cells | cells with a completed sample | majority agrees | tied majority incl. paper | "
              "occurs | majority undetermined |", "|" + "---|" * 7]
    for tid, c in per_table + [("**all**", tot)]:
        lines.append(f"| {tid} | {c['cells']} | {c['evaluated']} | {c['agrees']} | {c['tied']} | {c['occurs']} | "
                     f"{c['undetermined']} |")
    lines += ["", f"**Majority agreement: {tot['agrees']} of {tot['evaluated']} cells; occurrence: {tot['occurs']} "
                  f"of {tot['evaluated']}.** Superseded table: {SUPERSEDED.get(study.name, 'none')}.", "",
              "### What changed from the superseded table, and why", "",
              "> **[LEAD: to be filled from the results]** -- the cage-physics fixes since the superseded table "
              "(land-film sign, guide lands from the geometry, oil laws; docs/validation/cage_whirl.md), the "
              "classifier's sub-labels (still cage / synchronous whirl under \"1 period\"), and what the band "
              "changes: cells whose class depends on the unknown clearances.", ""]
    lines += _table6_lines(study, datasets)
    failed = []
    n_missing = 0
    for tid, ds in datasets.items():
        for idx in np.ndindex(*ds["status"].shape):
            pt = ds.isel(dict(zip(ds["status"].dims, idx)))
            if pt["status"].item() == STATUS_MISSING:
                n_missing += 1
            elif pt["status"].item() != sweeps.STATUS_OK:
                where = ", ".join(f"{str(c)[:-6]}={pt[c].item()}" for c in pt.coords if str(c).endswith("_label"))
                failed.append(f"- {tid}: {where}: {pt['status'].item()}: {pt['error'].item()}")
    if n_missing:
        lines += [f"> **Partial report:** {n_missing} table cells x samples have no archive yet (report only); "
                  "they are left out of the fractions.", ""]
    if failed:
        lines += ["## Points that did not complete", ""] + failed + [""]
    path = out / f"report{BANDS_SUFFIX}.md"
    with atomic_write(path) as tmp:
        tmp.write_text("\n".join(lines))
    return path


def _nominal_wall_line(out: Path, banded_wall: float, name: str) -> str:
    """The nominal study's wall time as its ``report.md`` in the same directory states it, and the sum."""
    import re

    rep = out / "report.md"
    m = re.search(r"wall time of the whole study \(this invocation\): ([0-9.]+) s", rep.read_text()) if rep.exists() else None
    if not m:
        return (f"- wall time of the nominal study: no `report.md` of `hsbearing study {name}` in this directory "
                "(the nominal points were computed here)")
    nom = float(m.group(1))
    return (f"- wall time of the nominal study (its `report.md`, last invocation): {nom:.1f} s; **whole study = nominal "
            f"+ banded invocations: {nom + banded_wall:.1f} s** (a resumed invocation counts only what it computed)")


def _band_range(cell: xr.Dataset, name: str) -> str:
    """'a .. b' of a summary over the completed samples of a cell (2 decimals), '-' if none."""
    if name not in cell:
        return "-"
    v = np.asarray(cell[name].values, float)
    v = v[(np.asarray(cell["status"].values) == sweeps.STATUS_OK) & np.isfinite(v)]
    if not v.size:
        return "-"
    return f"{v.min():.2f}" if np.isclose(v.min(), v.max(), atol=5e-3) else f"{v.min():.2f} .. {v.max():.2f}"


def _drift_lines(drift: list[str]) -> list[str]:
    if not drift:
        return []
    return (["Cells drawn above whose cage is still drifting at the end of the run (`orbit_drift`: the mean whirl "
             "radius changes monotonically over the analysed span by more than 10 % and 1 % of the guide "
             "clearance, \"DRIFT\" in the panel): their section is an open arc of the transient, so their class "
             "(often \"quasi-periodic\") is not that of an attractor; a longer run would settle them:", ""]
            + [f"- {d}" for d in drift] + [""])


def _point_walls(datasets) -> dict[str, float]:
    walls: dict[str, float] = {}
    for ds in datasets.values():
        for a, w in zip(np.asarray(ds["archive"].values).ravel(), np.asarray(ds["wall_time"].values).ravel()):
            if a and a not in walls and np.isfinite(w):
                walls[str(a)] = float(w)
    return walls



# ----------------------------------------------------------------------------- every cell, slip bands, Table 6


def stability_rank(label: str) -> float:
    """Rank of a class by the paper's criterion "fewer periods ... are beneficial to cage's stability" (Sec. 5):
    k periods -> k (1 period -> 1), quasi-periodic -> 10, chaos -> 11; undetermined / failed -> NaN."""
    c = normalise_label(label)
    if c == "1 period":
        return 1.0
    parts = c.split()
    if len(parts) == 2 and parts[0].isdigit() and parts[1].startswith("period"):
        return float(parts[0])
    return {"quasi-periodic": 10.0, "chaos": 11.0}.get(c, float("nan"))


def _pick_sample(ds_cell: xr.Dataset, st: dict | None) -> int | None:
    """The sample index drawn for a banded cell: the nominal sample if it is in the majority class, else the
    first completed sample in the majority class (first of tied classes), else the first completed one."""
    n = ds_cell.sizes["sample"]
    ok = [i for i in range(n) if ds_cell["status"].values[i] == sweeps.STATUS_OK and ds_cell["archive"].values[i]]
    if not ok:
        return None
    if st and st["majority"] != "-":
        first = st["majority"].split(" / ")[0]
        for i in ok:
            lab = normalise_label(ds_cell["classification"].values[i]) if "classification" in ds_cell else ""
            if (lab or "-") == first:
                return i
    return ok[0]


def orbit_drift(t, y, z, t_start: float, clearance: float | None = None, parts: int = 4) -> dict[str, Any]:
    """Is the cage still drifting at the end of the run?  The analysed span (t > t_start) is cut into
    ``parts`` equal pieces; the mean whirl radius r = sqrt(D_Y^2 + D_Z^2) [m] of each piece is compared.
    ``drifting`` when those means change monotonically and the change exceeds both 10 % of the mean radius
    and 1 % of the guide clearance (the still-cage threshold of docs/analysis.md): a spiral that has not
    reached its attractor, whose Poincare section is an open arc, not a closed curve -- a class from it
    ("quasi-periodic" for an arc) describes the transient.  A report-side diagnostic: the classification
    itself is not changed."""
    t = np.asarray(t, float)
    r = np.hypot(np.asarray(y, float), np.asarray(z, float))
    sel = t > t_start
    r = r[sel]
    if r.size < 4 * parts:
        return {"drifting": False, "radii": [], "change": float("nan")}
    means = np.array([np.mean(c) for c in np.array_split(r, parts)])
    d = np.diff(means)
    monotone = bool(np.all(d > 0) or np.all(d < 0))
    change = float(means[-1] - means[0])
    floor = 0.01 * clearance if clearance is not None and np.isfinite(clearance) else 0.0
    drifting = monotone and abs(change) > max(0.1 * float(np.mean(means)), floor)
    return {"drifting": drifting, "radii": means.tolist(), "change": change}


def _plot_gallery(study: Study, t: dict, ds: xr.Dataset, root: Path, path: Path,
                  drift_log: list | None = None) -> Path | None:
    """Whirl orbit (top) and Poincare map D_Y-V_Y (bottom) of EVERY cell of a table: one column per value,
    two rows per oil.  A banded table draws one sample per cell (:func:`_pick_sample`) and prints the class
    fractions over the band in the panel title."""
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    dim = t["vary"].rpartition(".")[2]
    banded = "sample" in ds.dims
    oils, nval = study.oils, ds.sizes[dim]
    fig, axes = plt.subplots(2 * len(oils), nval, figsize=(2.15 * nval, 1.95 * 2 * len(oils)), squeeze=False)
    drawn = 0
    for io, o in enumerate(oils):
        for iv in range(nval):
            cell = ds.sel(oil=o).isel({dim: iv})
            ax_o, ax_p = axes[2 * io, iv], axes[2 * io + 1, iv]
            for ax in (ax_o, ax_p):
                ax.tick_params(labelsize=5, length=2, pad=1)
                ax.locator_params(nbins=3)
                ax.ticklabel_format(useOffset=False)
            paper = str(cell["paper_classification"].values) if "paper_classification" in cell else ""
            if banded:
                st = _cell_stats(ds, dim, o, iv)
                k = _pick_sample(cell, st)
                pt = cell.isel(sample=k) if k is not None else None
                frac = ", ".join(f"{c} {f:.0%}" for c, f in st["fractions"].items()) or "-"
                head = f"{o}, {_value_label(ds, dim, iv)}  paper: {paper or '-'}\nband: {frac}"
                if pt is not None:
                    head += f"\nshown: {pt['sample_label'].item()} ({_ours(pt)})"
            else:
                pt = cell
                head = f"{o}, {_value_label(ds, dim, iv)}\npaper: {paper or '-'}\nours: {_ours(pt)}"
            ax_o.set_title(head, fontsize=5.2, loc="left")
            run = None
            if pt is not None and pt["archive"].item():
                try:
                    run = open_run(root / pt["archive"].item())
                except Exception:
                    run = None
            if run is None or "cage_center_y" not in run or "time" not in run.dims:
                ax_o.text(0.5, 0.5, "no run", ha="center", va="center", transform=ax_o.transAxes, fontsize=6)
                ax_p.set_axis_off()
                continue
            try:
                y = np.asarray(run["cage_center_y"].values, float) * 1e6
                z = np.asarray(run["cage_center_z"].values, float) * 1e6
                tt = np.asarray(run["time"].values, float)
                t_tr = float(run.attrs.get("transient_discarded", tt[0]))
                late = tt > t_tr
                ax_o.plot(y[~late], z[~late], lw=0.25, color="0.75")
                ax_o.plot(y[late], z[late], lw=0.3, color="C0")
                gc = run.attrs.get("guide_clearance")
                dr = orbit_drift(tt, y * 1e-6, z * 1e-6, t_tr, float(gc) if gc is not None else None)
                if dr["drifting"]:
                    ax_o.text(0.02, 0.02, f"DRIFT {dr['change'] * 1e6:+.0f} \u00b5m", transform=ax_o.transAxes,
                              fontsize=5.5, color="m", va="bottom")
                    if drift_log is not None:
                        drift_log.append(f"{t['id']}, oil {o}, {_value_label(ds, dim, iv)}"
                                         + (f" (sample {pt['sample_label'].item()})" if banded else "")
                                         + f": class {_ours(pt)}, mean whirl radius per quarter of the analysed "
                                           f"span {', '.join(f'{x * 1e6:.1f}' for x in dr['radii'])} \u00b5m")
                if gc is not None and np.isfinite(float(gc)):
                    th = np.linspace(0, 2 * np.pi, 181)
                    ax_o.plot(float(gc) * 1e6 * np.cos(th), float(gc) * 1e6 * np.sin(th), "r--", lw=0.4)
                ax_o.set_aspect("equal", "datalim")
                pts = _poincare(run)
                if pts is not None and len(pts):
                    ax_p.plot(pts[:, 0] * 1e6, pts[:, 1] * 1e3, ".", ms=1.5, color="C3")
                    ax_p.text(0.02, 0.96, f"{len(pts)} pts", transform=ax_p.transAxes, fontsize=5, va="top")
                else:
                    ax_p.text(0.5, 0.5, "no section points", ha="center", va="center", transform=ax_p.transAxes,
                              fontsize=6)
                drawn += 1
            finally:
                run.close()
            if iv == 0:
                ax_o.set_ylabel("D_Z [\u00b5m]", fontsize=5.5)
                ax_p.set_ylabel("V_Y [mm/s]", fontsize=5.5)
            if io == len(oils) - 1:
                ax_p.set_xlabel("D_Y [\u00b5m]", fontsize=5.5)
    if not drawn:
        plt.close(fig)
        return None
    import textwrap

    width, height = fig.get_figwidth(), fig.get_figheight()
    title = textwrap.fill(f"{t.get('title', t['id'])}: every cell -- whirl orbit (grey: transient, red dashed: guide "
                          "clearance) over its Poincare map (once per cage revolution)", width=int(width * 15))
    fig.suptitle(title, fontsize=7)
    # fixed margins in inches (tight_layout costs seconds with ~70 axes)
    n_title = title.count("\n") + 1
    fig.subplots_adjust(left=0.5 / width, right=1 - 0.08 / width, bottom=0.4 / height,
                        top=1 - (0.6 + 0.13 * n_title) / height, hspace=0.62, wspace=0.42)
    try:
        return _save(fig, path)
    finally:
        plt.close(fig)


def _plot_slip_band(ds: xr.Dataset, t: dict, oils: list[str], path: Path) -> Path | None:
    """Cage slip ratio against the table's key: the nominal sample as a line, the band's range shaded and
    every sample as a dot (compare the paper's Figs. 13-15)."""
    if "mean_cage_slip_ratio" not in ds:
        return None
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    dim = t["vary"].rpartition(".")[2]
    x, _ = _axis_values(ds, t["vary"], dim)
    fig, ax = plt.subplots(figsize=(5.8, 4.0))
    labels = list(ds["sample_label"].values)
    for j, o in enumerate(oils):
        y = np.asarray(ds["mean_cage_slip_ratio"].sel(oil=o).transpose("sample", dim).values, float) * 100
        ok = np.asarray(ds["status"].sel(oil=o).transpose("sample", dim).values) == sweeps.STATUS_OK
        y = np.where(ok, y, np.nan)
        col = f"C{j}"
        with np.errstate(all="ignore"):
            lo, hi = np.nanmin(y, axis=0), np.nanmax(y, axis=0)
        ax.fill_between(x, lo, hi, color=col, alpha=0.18, lw=0)
        for k in range(y.shape[0]):
            ax.plot(x, y[k], ".", color=col, ms=3)
        k0 = labels.index("nominal") if "nominal" in labels else None
        if k0 is not None:
            ax.plot(x, y[k0], "-", color=col, label=f"oil {o} (nominal; band shaded)")
        else:
            ax.plot(x, np.nanmedian(y, axis=0), "-", color=col, label=f"oil {o} (band median; range shaded)")
    ax.set_xlabel(t.get("axis_label", dim))
    ax.set_ylabel("cage slip ratio [%]")
    ax.set_title(f"{t['id']}: cage slip ratio over the band (compare {t.get('slip_figure', 'the paper')})", fontsize=9)
    ax.grid(alpha=0.3)
    ax.legend(fontsize=7)
    fig.tight_layout()
    try:
        return _save(fig, path)
    finally:
        plt.close(fig)


TABLE6_RULE = (
    "For every condition (a value of a table) the most stable oil is the one whose cage class ranks best by the "
    "paper's own criterion (Sec. 5: \"fewer periods of dynamic response ... and smaller slip ratio of cage are "
    "beneficial to cage's stability\"): k periods -> rank k, quasi-periodic -> 10, chaos -> 11, undetermined "
    "not ranked; the class is the majority class over the band (banded study) or the single run's class; ties "
    "are broken by the cage-instability index (sd/mean of the whirl radius, Ghaisas et al. 2004; band mean; "
    "differences below 0.05 do not count), then by the absolute cage slip ratio (band mean; differences below "
    "0.1 percentage point do not count); oils still tied are all recommended. Each table's values are split into a lower half "
    "(low temperature / light load), an upper half (high / heavy) and, for an odd count, the middle value "
    "(medium); an oil is recommended for a category when it is the most stable oil at a value of it.")


def _cell_score(ds: xr.Dataset, dim: str, oil: str, i: int) -> tuple[float, float, float, str]:
    cell = ds.sel(oil=oil).isel({dim: i})
    if "sample" in ds.dims:
        st = _cell_stats(ds, dim, oil, i)
        cls = st["majority"] if not st["tie"] else max(st["majority"].split(" / "), key=lambda c: (
            stability_rank(c) if np.isfinite(stability_rank(c)) else 99))  # a tie counts as the worse class
        ok = np.asarray(cell["status"].values) == sweeps.STATUS_OK
    else:
        cls = _ours(cell)
        ok = np.array(cell["status"].item() == sweeps.STATUS_OK)

    def mean(name):
        if name not in cell:
            return float("nan")
        v = np.atleast_1d(np.asarray(cell[name].values, float))[np.atleast_1d(ok)]
        v = v[np.isfinite(v)]
        return float(np.mean(np.abs(v) if name == "mean_cage_slip_ratio" else v)) if v.size else float("nan")

    return stability_rank(cls), mean("cage_instability_index"), mean("mean_cage_slip_ratio"), cls


#: differences below these are not told apart by the Table 6 rule (the index of a steady orbit is noise of
#: ~0.01-0.05; slip ratios within 0.1 percentage point are the same for the paper's Figs. 13-15)
TABLE6_INDEX_TOL = 0.05
TABLE6_SLIP_TOL = 1e-3


def _most_stable(oils: list[str], scores: dict) -> list[str]:
    """Best class rank; then the instability index within TABLE6_INDEX_TOL of the lowest; then the absolute
    slip ratio within TABLE6_SLIP_TOL of the lowest; every oil left is a winner."""
    r0 = min(scores[o][0] for o in oils)
    left = [o for o in oils if scores[o][0] == r0]
    for j, tol in ((1, TABLE6_INDEX_TOL), (2, TABLE6_SLIP_TOL)):
        vals = [scores[o][j] for o in left if np.isfinite(scores[o][j])]
        if vals:
            m = min(vals)
            left = [o for o in left if np.isfinite(scores[o][j]) and scores[o][j] <= m + tol]
    return left


def _categories(t: dict) -> list[str]:
    n = len(t["values"])
    low, high = (("low temperature", "high temperature") if t["vary"].endswith("temperature")
                 else ("light load", "heavy load"))
    mid = "medium temperature" if t["vary"].endswith("temperature") else "medium load"
    half = n // 2
    return [low] * half + ([mid] if n % 2 else []) + [high] * half


def derive_table6(study: Study, datasets: dict[str, xr.Dataset]) -> dict[str, Any]:
    """Our Table 6 by :data:`TABLE6_RULE`: ``{"best": {table: [(value label, [oils], detail)]},
    "table": {oil: {table: "category (values)"}}}``."""
    best: dict[str, list] = {}
    table: dict[str, dict[str, str]] = {o: {} for o in study.oils}
    for t in study.tables:
        ds = datasets.get(t["id"])
        if ds is None:
            continue
        dim = t["vary"].rpartition(".")[2]
        cats = _categories(t)
        rows = []
        per_oil: dict[str, dict[str, list[str]]] = {o: {} for o in study.oils}
        for i in range(ds.sizes[dim]):
            scores = {o: _cell_score(ds, dim, o, i) for o in study.oils}
            ranked = [o for o in study.oils if np.isfinite(scores[o][0])]
            if not ranked:
                rows.append((_value_label(ds, dim, i), [], "no oil classified"))
                continue

            winners = _most_stable(ranked, scores)
            detail = "; ".join(f"{o}: {scores[o][3]}, index {_fmt(scores[o][1], '.2f')}, |slip| "
                               f"{_fmt(scores[o][2] * 100, '.2f')} %" for o in study.oils)
            rows.append((_value_label(ds, dim, i), winners, detail))
            for o in winners:
                per_oil[o].setdefault(cats[i], []).append(_value_label(ds, dim, i))
        best[t["id"]] = rows
        for o in study.oils:
            table[o][t["id"]] = "; ".join(f"{c} ({', '.join(v)})" for c, v in per_oil[o].items()) or "-"
    return {"best": best, "table": table}


def _table6_lines(study: Study, datasets: dict[str, xr.Dataset]) -> list[str]:
    paper = study.spec.get("table6", {})
    if not paper:
        return []
    d = derive_table6(study, datasets)
    tids = [t["id"] for t in study.tables if t["id"] in datasets]
    heads = {t["id"]: t.get("table6_column", t["id"]) for t in study.tables}
    lines = ["## Table 6: recommended working condition per oil, the paper's and ours", "",
             f"Rule (ours): {TABLE6_RULE}", "",
             "| oil | " + " | ".join(f"{heads[k]}: paper | {heads[k]}: ours" for k in tids) + " |",
             "|" + "---|" * (1 + 2 * len(tids))]
    for o in study.oils:
        row = [o]
        for k in tids:
            row += [str(paper.get(o, {}).get(k, "-")), d["table"][o].get(k, "-")]
        lines.append("| " + " | ".join(row) + " |")
    lines += ["", "The most stable oil at every condition (ours; the basis of the table above):", ""]
    for k in tids:
        for value, winners, detail in d["best"][k]:
            lines.append(f"- {k}, {value}: **{', '.join(winners) or '-'}** ({detail})")
    return lines + [""]


def _ours(pt: xr.Dataset, name: str = "classification") -> str:
    status = pt["status"].item()
    if status != sweeps.STATUS_OK:
        return f"({status})" if name == "classification" else "-"
    if name not in pt:
        return "-"
    return normalise_label(pt[name].item()) or "-"


def _section_stats(datasets) -> list[str]:
    n = np.concatenate([np.asarray(ds["n_poincare_points"].values, float).ravel() for ds in datasets.values()
                        if "n_poincare_points" in ds] or [np.array([])])
    n = n[np.isfinite(n)]
    if not n.size:
        return []
    line = (f"- Poincare section points per run: median {np.median(n):.0f} (min {n.min():.0f}, max {n.max():.0f})")
    try:
        from hsbearing.analysis.classify import DEFAULTS

        line += (f"; the classifier needs >= {DEFAULTS['n_min']} for any label and >= {DEFAULTS['n_min_aperiodic']} "
                 "to tell quasi-periodic from chaos (docs/analysis.md)")
    except Exception:
        pass
    return [line]


def _details(pt: xr.Dataset) -> str:
    bits = []
    if "classification_confidence" in pt and np.isfinite(float(pt["classification_confidence"].item())):
        bits.append(f"confidence {float(pt['classification_confidence'].item()):.2f}")
    if "n_poincare_points" in pt and np.isfinite(float(pt["n_poincare_points"].item())):
        bits.append(f"{int(pt['n_poincare_points'].item())} section points")
    return f" ({', '.join(bits)})" if bits else ""


def _sum_wall(datasets) -> float:
    seen, total = set(), 0.0
    for ds in datasets.values():
        for a, w in zip(ds["archive"].values.ravel(), ds["wall_time"].values.ravel()):
            if a and a not in seen and np.isfinite(w):
                seen.add(a)
                total += float(w)
    return total


def _version() -> str:
    from hsbearing import __version__

    return __version__


def _host() -> str:
    import platform

    return platform.node() or "?"


def _axis_values(ds: xr.Dataset, key: str, dim: str) -> tuple[np.ndarray, str]:
    x = np.asarray(ds[dim].values, dtype=float)
    units = ds[dim].attrs.get("units", "")
    if units == "K":
        return x - 273.15, "\N{DEGREE SIGN}C"
    return x, units


def _save(fig, path: Path) -> Path:
    from hsbearing.plotting import save_figure

    return save_figure(fig, path)


def _plot_slip(ds: xr.Dataset, t: dict, oils: list[str], path: Path) -> Path | None:
    if "mean_cage_slip_ratio" not in ds:
        return None
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    dim = t["vary"].rpartition(".")[2]
    x, _ = _axis_values(ds, t["vary"], dim)
    fig, ax = plt.subplots(figsize=(5.5, 3.8))
    for o in oils:
        y = np.asarray(ds["mean_cage_slip_ratio"].sel(oil=o).values, float) * 100
        ax.plot(x, y, "o-", label=f"oil {o}")
    ax.set_xlabel(t.get("axis_label", dim))
    ax.set_ylabel("cage slip ratio [%]")
    ax.set_title(f"{t['id']}: cage slip ratio (compare {t.get('slip_figure', 'paper')})", fontsize=9)
    ax.grid(alpha=0.3)
    ax.legend(fontsize=8)
    fig.tight_layout()
    try:
        return _save(fig, path)
    finally:
        plt.close(fig)


def _plot_cells(study: Study, datasets: dict, figspec: dict, path: Path) -> Path | None:
    cells = []
    for tid, oil, value in figspec.get("cells", []):
        ds = datasets.get(tid)
        if ds is None:
            continue
        t = next(t for t in study.tables if t["id"] == tid)
        dim = t["vary"].rpartition(".")[2]
        i = list(t["values"]).index(value)
        pt = ds.sel(oil=oil).isel({dim: i})
        arch = pt["archive"].item()
        if not arch:
            continue
        try:
            run = open_run(path.parent.parent / arch)
        except Exception:
            continue
        if "cage_center_y" not in run or "time" not in run.dims:
            continue
        cells.append((f"{oil}, {value}", run, _ours(pt), str(pt["paper_classification"].item()) if "paper_classification" in pt else ""))
    if not cells:
        return None
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    n = len(cells)
    fig, axes = plt.subplots(2, n, figsize=(3.0 * n, 6.0), squeeze=False)
    for j, (label, run, ours, paper) in enumerate(cells):
        y = np.asarray(run["cage_center_y"].values, float) * 1e6
        z = np.asarray(run["cage_center_z"].values, float) * 1e6
        ax = axes[0, j]
        t = np.asarray(run["time"].values, float)
        t_tr = float(run.attrs.get("transient_discarded", t[0]))
        early = t <= t_tr
        if early.any() and not early.all():
            ax.plot(y[early], z[early], lw=0.4, color="0.75", label="transient")
            ax.plot(y[~early], z[~early], lw=0.4, color="C0", label="analysed")
            ax.legend(fontsize=6, loc="upper right")
        else:
            ax.plot(y, z, lw=0.4)
        ax.set_aspect("equal", "datalim")
        ax.set_xlabel("D_Y [\u00b5m]")
        ax.set_ylabel("D_Z [\u00b5m]")
        ax.set_title(f"{label}\npaper: {paper or '-'}\nours: {ours}", fontsize=8)
        ax = axes[1, j]
        pts = _poincare(run)
        if pts is not None and len(pts):
            ax.plot(pts[:, 0] * 1e6, pts[:, 1] * 1e3, ".", ms=3)
        else:
            ax.text(0.5, 0.5, "no section points", ha="center", va="center", transform=ax.transAxes, fontsize=8)
        ax.set_xlabel("D_Y [\u00b5m]")
        ax.set_ylabel("V_Y [mm/s]")
    fig.suptitle(figspec.get("title", figspec["id"]) + "  (top: whirl orbit; bottom: Poincare map)", fontsize=9)
    fig.tight_layout()
    try:
        return _save(fig, path)
    finally:
        plt.close(fig)


def _poincare(run: xr.Dataset):
    try:
        from hsbearing.analysis import poincare_points

        return np.asarray(poincare_points(run), float)
    except Exception:
        return None


# ----------------------------------------------------------------------------- CLI


def cli_main(args) -> int:
    """``hsbearing study NAME -o DIR [--bands [--band-samples K] | --no-bands] [--table ID ...] [-j N]
    [--scheduler ADDR] [--duration 0.05s]``.

    Exit 0 when every point completed, 1 when some did not (the report lists
    them), 2 on bad input.
    """
    out = Path(args.output)
    if out.exists() and not out.is_dir():
        raise CaseError(str(out), None, "output must be a directory")
    bands = bool(getattr(args, "bands", False))
    limit = getattr(args, "band_samples", None)
    if limit is not None and not bands:
        raise CaseError("--band-samples", None, "only with --bands")
    res = run_study(args.name, out, jobs=args.jobs, scheduler=args.scheduler, duration=args.duration, progress=True,
                    bands=bands, band_samples_limit=limit, tables=getattr(args, "tables", None),
                    report_only=bool(getattr(args, "report_only", False)), stop=getattr(args, "stop", None))
    n_bad = sum(int(((ds["status"] != sweeps.STATUS_OK) & (ds["status"] != STATUS_MISSING)).sum())
                for ds in res["tables"].values())
    print(f"study {args.name}{' (bands)' if bands else ''}: {res['n_unique_points']} distinct points, "
          f"{res['n_computed']} computed, wall time {res['wall_time']:.1f} s ({res['backend']})")
    for tid in res["tables"]:
        print(f"table: {out / (tid + (BANDS_SUFFIX if bands else '') + '.nc')}")
    print(f"report: {res['report']}")
    if n_bad:
        print(f"hsbearing: {n_bad} table cells did not complete (see the report)", file=sys.stderr)
        return 1
    return 0
