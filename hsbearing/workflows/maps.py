"""Cage-stability maps: a two-key sweep drawn as a class map plus a cage-instability indicator map.

``run_map(case, x=("bearing.outer_land_diameter", "52.3,52.4,52.5mm"), y=("cage.pocket_diameter",
"9.6,9.7mm"), out_dir="DIR")`` is a product sweep over the two keys through
:func:`hsbearing.workflows.sweeps.run_sweep` (same point archives, same resume, same local-process / dask
execution, same progress bar) followed by:

- ``DIR/map.nc``: the sweep Dataset (dims ``(y, x)``) with the map attrs: ``map_x``, ``map_y`` (case
  keys), ``map_indicator`` (the indicator variable) and its definition, ``map_wall_time`` (this
  invocation) [s], ``map_point_wall_time_sum`` / ``_mean`` / ``_max`` over the points computed (not
  resumed) [s].  Every point carries ``classification``, ``classification_detail`` (sub-label of
  "1 period": still cage / synchronous whirl / ...), ``cage_instability_index`` and ``wall_time`` [s].
- ``DIR/map.png``: class map (one coloured cell per point, with sub-label) next to the indicator map
  (:func:`hsbearing.plotting.maps.plot_map`).

The indicator is :func:`hsbearing.analysis.whirl.cage_instability_index`: the normalised
whirl-radius dispersion sd(r)/mean(r) of the cage mass centre after the transient (Ghaisas, Wassgren &
Sadeghi 2004, J. Tribol. 126), 0 for a steady circular whirl about the bearing axis.

The sweep's own ``DIR/sweep.nc`` is written as well (it is the same Dataset without the map attrs).
"""

from __future__ import annotations

import sys
import time
from pathlib import Path
from typing import Any, Callable

import numpy as np
import xarray as xr

import hsbearing.analysis.orbit  # noqa: F401 - registers the summary variables (units, long_name) before assemble
from hsbearing.case import CaseError, load_case, resolve_key
from hsbearing.results import write_netcdf
from hsbearing.workflows.sweeps import cli_base_case, plan_sweep, run_sweep

__all__ = ["run_map", "INDICATOR", "INDICATOR_DEFINITION", "wall_time_lines", "cli_main"]

#: Summary variable drawn as the scalar map.
INDICATOR = "cage_instability_index"
INDICATOR_DEFINITION = (
    "sd(r)/mean(r) of the cage mass-centre whirl radius r = sqrt(D_Y^2 + D_Z^2) after the transient "
    "(Ghaisas, Wassgren & Sadeghi 2004, ASME J. Tribol. 126: dispersion of the cage whirl about its mean orbit); "
    "mean floored at 5 % of the guide clearance; 0 = steady circular whirl or still cage")


def _axis(spec, source: str) -> tuple[str, Any]:
    """``("key", values)`` or ``"key=v1,v2,..."`` -> (full key, values)."""
    if isinstance(spec, str):
        if "=" not in spec:
            raise CaseError(source, spec, "expected KEY=V1,V2,..., e.g. --x axial_load=500,1000N")
        key, _, values = spec.partition("=")
        key, values = key.strip(), values.strip()
    else:
        key, values = spec
    table, leaf = resolve_key(key, source=source)
    return f"{table}.{leaf}", values


def _plan_vary(x, y) -> dict:
    kx, vx = _axis(x, "--x")
    ky, vy = _axis(y, "--y")
    if kx == ky:
        raise CaseError("--y", ky, "the map needs two different keys (the same key is given to --x and --y)")
    return {ky: vy, kx: vx}  # dims (y, x): rows = y, columns = x


def run_map(case, x, y, *, out_dir, jobs: int | None = None, scheduler: str | None = None, duration=None,
            progress: bool = True, point_fn: Callable | None = None, retry_failed: bool = False,
            figure: bool = True, warm_start: bool = False, cold_sample: int = 4,
            stop: str | None = "converged", keep: str = "answer", extend="default") -> xr.Dataset:
    """Run a two-key cage-stability map and write ``out_dir/map.nc`` (and ``map.png``).

    Parameters
    ----------
    case : Case, bundled case name or path.
    x, y : ``("key", values)`` or ``"key=v1,v2,..."``; values as for :func:`hsbearing.workflows.sweeps.parse_values`.
    out_dir : directory of the point archives, ``sweep.nc``, ``map.nc`` and ``map.png``.
    jobs, scheduler, duration, progress, point_fn, retry_failed : as for :func:`hsbearing.workflows.sweeps.run_sweep`.
    figure : draw ``map.png``.
    stop : stop rule of every point, "converged" (default, as ``hsbearing map``; docs/sweeps.md "Stop rule") or
        "duration"; None = the case's ``[simulation] stop``.  Set in the case only when it changes it.
    keep : what each point archive keeps, "answer" (default) or "full" (:func:`hsbearing.workflows.sweeps.execute`).
    extend : "default" (as ``hsbearing map``: 6 x the duration of each point,
        :data:`hsbearing.systems.angular_contact.extend.WORKFLOW_BUDGET_FACTOR`), a budget [s] of total simulated
        time, or None: a point whose label is undetermined with an estimate of the time it needs is continued in
        its worker until determined, the stop rule's convergence or the budget (docs/sweeps.md "Extend until
        determined").  Warm-started points are not extended.
    warm_start : experimental (docs/sweeps.md "Warm starts"): the seed points (every other value of each axis,
        and the last) run cold, every other point starts from the final state of its nearest seed
        (:class:`hsbearing.workflows.warmstart.WarmNearest`); ``cold_sample`` of the warm points are also run cold (in
        ``out_dir/cold_sample``) and the label agreement is stored (``warm_start_agreement``,
        ``warm_start_differences``).

    Returns
    -------
    xarray.Dataset
        The map Dataset (dims ``(y_dim, x_dim)``).
    """
    base = case if not isinstance(case, (str, Path)) else load_case(case)
    if stop is not None and stop != base.simulation.stop:
        base = base.with_overrides(**{"simulation.stop": stop})
    vary = _plan_vary(x, y)
    t0 = time.perf_counter()
    warm_attrs = {}
    if warm_start:
        if point_fn is not None:
            raise ValueError("warm_start replaces the point function")
        point_fn, warm_attrs = _warm_waves(base, vary, out_dir=out_dir, jobs=jobs, scheduler=scheduler,
                                           duration=duration, progress=progress, retry_failed=retry_failed)
    ds = run_sweep(base, vary, jobs=jobs, scheduler=scheduler, out_dir=out_dir, kind="run", duration=duration,
                   progress=progress, point_fn=point_fn, retry_failed=retry_failed, keep=keep, extend=extend)
    if warm_start:
        warm_attrs.update(_cold_sample(base, vary, ds, point_fn, out_dir=out_dir, jobs=jobs, scheduler=scheduler,
                                       duration=duration, progress=progress, n=cold_sample))
        ds.attrs.update(warm_attrs)
    wall = time.perf_counter() - t0
    ky, kx = list(vary)
    dims = ds["status"].dims
    ds.attrs.update(map_attrs(ds, kx, ky, dims, wall))
    out = Path(out_dir)
    write_netcdf(ds, out / "map.nc")
    if figure:
        from hsbearing.plotting.maps import plot_map

        try:
            plot_map(ds, out / "map.png")
        except Exception as exc:  # noqa: BLE001 - the archives are written; the figure is a by-product
            print(f"hsbearing: no map figure: {type(exc).__name__}: {exc}", file=sys.stderr)
    return ds


def _warm_waves(base, vary, *, out_dir, jobs, scheduler, duration, progress, retry_failed):
    """Wave 1 of a warm-started map: the seed points, cold.  Returns the point function of wave 2 and attrs."""
    from hsbearing.workflows.sweeps import plan_sweep
    from hsbearing.workflows.warmstart import WarmNearest, seed_indices

    full = plan_sweep(base, vary, duration=duration)
    (ky, kx), (ay, ax) = list(vary), full.axes
    sy, sx = seed_indices(len(ay.values)), seed_indices(len(ax.values))
    fn = WarmNearest(index={pt.case.to_toml(): pt.index for pt in full.points if pt.case is not None})
    seed_vary = {ky: [ay.values[i] for i in sy], kx: [ax.values[i] for i in sx]}
    seeds = plan_sweep(base, seed_vary, duration=duration, point_fn=fn)
    fn.seeds = {(sy[p.index[0]], sx[p.index[1]]): str(Path(out_dir) / p.archive) for p in seeds.points
                if p.case is not None}
    run_sweep(base, seed_vary, jobs=jobs, scheduler=scheduler, out_dir=out_dir, kind="run", duration=duration,
              progress=progress, point_fn=fn, retry_failed=retry_failed)
    return fn, {"warm_start": f"seeds (cold): {len(fn.seeds)} of {len(full.points)} points (every other value of "
                              "each axis and the last); the others start from the final state of their nearest seed"}


def _cold_sample(base, vary, ds, fn, *, out_dir, jobs, scheduler, duration, progress, n):
    """Run ``n`` warm-started points cold as well (``out_dir/cold_sample``) and compare their labels."""
    from hsbearing.workflows.sweeps import plan_sweep

    full = plan_sweep(base, vary, duration=duration)
    warm = [p for p in full.points if p.case is not None and p.index not in fn.seeds]
    if not warm or n <= 0:
        return {}
    pick = [warm[int(k)] for k in np.unique(np.linspace(0, len(warm) - 1, min(n, len(warm))).round().astype(int))]
    (ky, kx), (ay, ax) = list(vary), full.axes
    zv = {ky: [ay.values[p.index[0]] for p in pick], kx: [ax.values[p.index[1]] for p in pick]}
    cold = run_sweep(base, zv, zip=True, jobs=jobs, scheduler=scheduler, out_dir=Path(out_dir) / "cold_sample",
                     kind="run", duration=duration, progress=progress)
    lab_w = [str(ds["classification"].values[p.index]) for p in pick]
    lab_c = [str(v) for v in np.asarray(cold["classification"].values).ravel()]
    diff = [f"{ky}={ay.values[p.index[0]]}, {kx}={ax.values[p.index[1]]}: warm {w}, cold {c}"
            for p, w, c in zip(pick, lab_w, lab_c) if w != c]
    return {"warm_start_agreement": f"{len(pick) - len(diff)}/{len(pick)} sampled warm points have the cold label",
            "warm_start_differences": "; ".join(diff) or "none"}


def map_attrs(ds: xr.Dataset, kx: str, ky: str, dims, wall: float) -> dict:
    """The map attrs (keys, indicator, wall-time statistics of the points computed in this invocation)."""
    wt = np.asarray(ds["wall_time"].values, float).ravel()
    resumed = np.asarray(ds["resumed"].values).ravel().astype(bool)
    computed = wt[(~resumed) & np.isfinite(wt)]
    allpts = wt[np.isfinite(wt)]
    return {
        "map_x": kx,
        "map_y": ky,
        "map_x_dim": dims[1],
        "map_y_dim": dims[0],
        "map_indicator": INDICATOR,
        "map_indicator_definition": INDICATOR_DEFINITION,
        "map_wall_time": float(wall),
        "map_points_computed": int(computed.size),
        "map_point_wall_time_sum": float(computed.sum()) if computed.size else 0.0,
        "map_point_wall_time_mean": float(computed.mean()) if computed.size else float("nan"),
        "map_point_wall_time_max": float(computed.max()) if computed.size else float("nan"),
        "map_point_wall_time_mean_all": float(allpts.mean()) if allpts.size else float("nan"),
    }


def wall_time_lines(ds: xr.Dataset) -> list[str]:
    """One line per point (keys, class, sub-label, indicator, wall time) and the totals."""
    dims = ds["status"].dims
    lines = []
    for idx in np.ndindex(*ds["status"].shape):
        pt = ds.isel(dict(zip(dims, idx)))
        parts = [f"{d}={pt[f'{d}_label'].values.item() if f'{d}_label' in pt.coords else pt[d].values.item()}"
                 for d in dims]
        parts.append(f"status={pt['status'].values.item()}")
        for name in ("classification", "classification_detail"):
            if name in pt:
                v = pt[name].values.item()
                if v:
                    parts.append(f"{name}={v}")
        if INDICATOR in pt:
            parts.append(f"{INDICATOR}={float(pt[INDICATOR]):.3g}")
        n_ext = float(pt["extension_count"]) if "extension_count" in pt else float("nan")
        if n_ext > 0:
            head = str(pt["extension_stop_reason"].values.item()).split(":")[0]
            parts.append(f"extended={int(n_ext)}x to {float(pt['simulated_time']):.3g} s ({head})")
        wt = float(pt["wall_time"])
        parts.append(f"wall_time={wt:.2f} s" + (" (resumed: time of the original run)" if int(pt["resumed"]) else ""))
        lines.append("  ".join(parts))
    a = ds.attrs
    lines.append(
        f"{a['sweep_points_ok']} of {a['sweep_points']} points ok ({a['sweep_points_resumed']} resumed); "
        f"wall time {a['map_wall_time']:.1f} s for this invocation; {a['map_points_computed']} point(s) computed: "
        f"sum {a['map_point_wall_time_sum']:.1f} s, mean {a['map_point_wall_time_mean']:.2f} s, "
        f"max {a['map_point_wall_time_max']:.2f} s per point")
    return lines


def extend_arg(args):
    """``extend=`` of :func:`run_map` / ``run_study`` from ``--no-extend`` / ``--max-duration`` (CaseError for both)."""
    no, text = bool(getattr(args, "no_extend", False)), getattr(args, "max_duration", None)
    if no and text:
        raise CaseError("--max-duration", "max_duration", "not with --no-extend")
    if no:
        return None
    return text if text else "default"


def extension_lines(ds: xr.Dataset) -> list[str]:
    """What the extensions did over the points of a map or study table: counts by how they stopped."""
    if "extension_stop_reason" not in ds:
        return []
    reasons = [str(r) for r in np.asarray(ds["extension_stop_reason"].values).ravel() if str(r)]
    n = np.asarray(ds["extension_count"].values, float).ravel() if "extension_count" in ds else np.zeros(0)
    heads = {}
    for r in reasons:
        head = r.split(":")[0].split(" (")[0]
        if head.startswith("converged"):
            head = "converged"
        heads[head] = heads.get(head, 0) + 1
    done = int(np.sum(np.nan_to_num(n) > 0))
    text = "; ".join(f"{k} {v}" for k, v in sorted(heads.items(), key=lambda kv: -kv[1]))
    return [f"extension: {done} point(s) extended; how each point ended: {text}"]


def cli_main(args) -> int:
    """``hsbearing map CASE --x KEY=V1,V2 --y KEY=V1,V2 [-j N] [--scheduler ADDR] [--duration] -o DIR``.

    Exit 0 when every point is ok, 1 when some point failed numerically, 2 on bad input (checked before
    anything is computed or written: keys, values, every point's case, the output directory).
    """
    case = cli_base_case(args)
    vary = _plan_vary(args.x, args.y)
    out = Path(args.output)
    if out.exists() and not out.is_dir():
        raise CaseError(str(out), None, "output must be a directory")
    from hsbearing.results import check_output_path
    from hsbearing.workflows.sweeps import check_scheduler_address

    check_output_path(out, directory=True,  # the derived outputs too, before any point runs
                      derived=[out / "map.nc", out / "sweep.nc"]
                      + ([] if getattr(args, "no_figure", False) else [out / "map.png"]))
    if args.scheduler:
        check_scheduler_address(args.scheduler)
    extend = extend_arg(args)
    plan = plan_sweep(case, vary, duration=args.duration, extend=extend)  # a bad --max-duration: exit 2 here
    bad = [pt for pt in plan.points if pt.case is None]
    if bad:
        where = ", ".join(f"{k}={v}" for k, v in bad[0].overrides.items())
        raise CaseError("--x/--y", None, f"point {where} is not a valid case: {bad[0].error}")
    ds = run_map(case, args.x, args.y, out_dir=out, jobs=args.jobs, scheduler=args.scheduler,
                 duration=args.duration, progress=not getattr(args, "quiet", False),
                 figure=not getattr(args, "no_figure", False), warm_start=bool(getattr(args, "warm_start", False)),
                 cold_sample=int(getattr(args, "cold_sample", 4)), stop=None,
                 keep=getattr(args, "keep", "answer"), extend=extend)  # --stop is already in the case
    for line in wall_time_lines(ds) + extension_lines(ds):
        print(line)
    for k in ("warm_start", "warm_start_agreement", "warm_start_differences"):
        if k in ds.attrs:
            print(f"{k.replace('_', ' ')}: {ds.attrs[k]}")
    print(f"map: {out / 'map.nc'}")
    if not getattr(args, "no_figure", False) and (out / "map.png").exists():
        print(f"figure: {out / 'map.png'}")
    n, n_ok = ds.attrs["sweep_points"], ds.attrs["sweep_points_ok"]
    return 0 if n_ok == n else 1
