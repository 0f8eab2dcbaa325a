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

from hsbearing.case import CaseError, load_case, parse_quantity
from hsbearing.results import open_run, write_netcdf, atomic_write
from hsbearing import sweeps

__all__ = ["list_studies", "study_help", "load_study", "run_study", "normalise_label", "write_report", "cli_main"]

RUNS = "runs"
FIGURES = "figures"


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
    return Study(spec["study"].get("name", p.stem), src, spec)


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
) -> dict[str, Any]:
    """Run a study; returns ``{"tables": {id: Dataset}, "report": Path, "wall_time": s, ...}``.

    ``duration`` (s or unit string) overrides ``[study] duration``;
    ``point_fn`` replaces the dynamic model (tests, dry runs) and is named in
    the report; ``tables`` restricts to some table ids.
    """
    study = load_study(name)
    out = Path(out_dir)
    dur = duration if duration is not None else study.spec["study"].get("duration")
    if isinstance(dur, str):
        dur = parse_quantity(dur, "time", source="--duration" if duration is not None else study.source_path,
                             key="duration")
    chosen = [t for t in study.tables if tables is None or t["id"] in tables]
    if not chosen:
        raise CaseError(study.source_path, "table", f"no table selected (have: {', '.join(t['id'] for t in study.tables)})")
    plans = []
    for t in chosen:
        base = load_case(study.spec["study"]["case"], **t.get("set", {}))
        vary = {"lubricant.oil": study.oils, t["vary"]: list(t["values"])}
        plans.append(sweeps.plan_sweep(base, vary, kind="run", duration=dur, point_fn=point_fn,
                                       source=f"{study.source_path} [{t['id']}]"))
    t0 = time.perf_counter()
    with sweeps._backend(jobs, scheduler) as backend, sweeps._dir_lock(out):
        records = sweeps.execute(plans, out / RUNS, progress=progress, backend=backend)
        wall = time.perf_counter() - t0
        backend_label = f"dask {scheduler}" if scheduler else f"jobs={jobs or os.cpu_count()}"
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
            "point_fn": sweeps._fn_name(point_fn),
            "n_unique_points": n_points,
            "n_computed": len({r.get("archive") or id(r) for recs in records for r in recs
                               if not r.get("resumed") and r.get("status") != "invalid"}),
        }
        report = write_report(study, datasets, out, info)
    return {"tables": datasets, "report": report, **info}


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
              + ("" if dur else " (the case's `[simulation] duration`)"),
              f"- execution: {info['backend']} on {os.cpu_count()} core(s) of `{_host()}`",
              f"- points: {info['n_unique_points']} distinct cases ({info['n_computed']} computed in this invocation, "
              f"the others resumed from `{RUNS}/`)",
              f"- **wall time of the whole study (this invocation): {info['wall_time']:.1f} s**",
              f"- sum of the per-point wall times: {_sum_wall(datasets):.1f} s"] + _section_stats(datasets) + [""]
    totals = [0, 0, 0]  # agree, classified, undetermined
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
                row += [paper or "-", f"{ours} {'(=)' if ok else '(x)'}" if paper else ours]
            lines.append("| " + " | ".join(row) + " |")
        lines += ["", "Cage slip ratio (time mean after the transient; ours) -- "
                  f"compare {t.get('slip_figure', 'the paper')}:", ""]
        lines += [f"| {t.get('axis_label', dim)} | " + " | ".join(study.oils) + " |", "|" + "---|" * (1 + len(study.oils))]
        for i in range(ds.sizes[dim]):
            row = [_value_label(ds, dim, i)]
            for o in study.oils:
                pt = ds.sel(oil=o).isel({dim: i})
                row.append(_fmt(pt["mean_cage_slip_ratio"].item(), ".4f") if "mean_cage_slip_ratio" in ds else "-")
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


def _ours(pt: xr.Dataset) -> str:
    status = pt["status"].item()
    if status != sweeps.STATUS_OK:
        return f"({status})"
    if "classification" not in pt:
        return "-"
    return normalise_label(pt["classification"].item()) or "-"


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
        return x - 273.15, "degC"
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
        ax.set_xlabel("D_Y [um]")
        ax.set_ylabel("D_Z [um]")
        ax.set_title(f"{label}\npaper: {paper or '-'}\nours: {ours}", fontsize=8)
        ax = axes[1, j]
        pts = _poincare(run)
        if pts is not None and len(pts):
            ax.plot(pts[:, 0] * 1e6, pts[:, 1] * 1e3, ".", ms=3)
        else:
            ax.text(0.5, 0.5, "no section points", ha="center", va="center", transform=ax.transAxes, fontsize=8)
        ax.set_xlabel("D_Y [um]")
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
    """``hsbearing study NAME -o DIR [-j N] [--scheduler ADDR] [--duration 0.05s]``.

    Exit 0 when every point completed, 1 when some did not (the report lists
    them), 2 on bad input.
    """
    out = Path(args.output)
    if out.exists() and not out.is_dir():
        raise CaseError(str(out), None, "output must be a directory")
    res = run_study(args.name, out, jobs=args.jobs, scheduler=args.scheduler, duration=args.duration, progress=True)
    n_bad = sum(int((ds["status"] != sweeps.STATUS_OK).sum()) for ds in res["tables"].values())
    print(f"study {args.name}: {res['n_unique_points']} distinct points, {res['n_computed']} computed, "
          f"wall time {res['wall_time']:.1f} s ({res['backend']})")
    for tid in res["tables"]:
        print(f"table: {out / (tid + '.nc')}")
    print(f"report: {res['report']}")
    if n_bad:
        print(f"hsbearing: {n_bad} table cells did not complete (see the report)", file=sys.stderr)
        return 1
    return 0
