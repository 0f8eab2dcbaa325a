"""Lubricants at the same conditions: the points (through the sweep machinery), ``compare.nc`` and the best oil
per criterion.

Three sweeps over ``oil`` (and the user's ``--vary`` keys) run as plans of one :func:`sweeps.execute` call, so
``-j``, ``--scheduler`` (dask), resume and the point archives are the sweep's:

* ``quasistatic`` with :func:`quasistatic_point`: the equilibrium, the power loss by source and drive torque at it
  (``rating.quasi_static_power_loss``), the film and pressure per ball, the total power loss at the two ends of the
  drag band (``drag_band_power_loss_low/high``), and the ISO 281 / ISO/TS 16281 lives (``rating.life``);
* ``run`` (unless ``dynamics=False``): a dynamic run of at most ``duration`` with the stop rule on
  (``simulation.stop = "converged"``): cage class, slip, whirl, and the run's own power;
* ``thermal`` when the case can give a thermal network (oil flow, bore/outside diameter/width): the equilibrium
  temperatures and where the heat goes; otherwise skipped, and ``compare.nc`` says why (``thermal_skipped``).
"""

from __future__ import annotations

import json
import math
import os
import time
from pathlib import Path
from typing import Any, Mapping

import numpy as np
import xarray as xr

from hsbearing.case import CaseError, as_case
from hsbearing.results import VARIABLES, check_output_path, register, standard_attrs
from hsbearing.workflows.compare.report import HTML_NAME, MD_NAME, NC_NAME

#: the dynamic run's upper bound when none is given: the study's 1.2 s, with the stop rule on (runs of the
#: default case stop at 0.5-0.7 s once the cage answer holds; docs/sweeps.md "Stop rule")
DEFAULT_DURATION = 1.2
#: where the point archives go, inside the output directory
POINTS_DIR = "points"
#: a relative difference below this is reported as "no difference" (the numbers still given)
TIE = 1e-3

register("drag_band_power_loss_low", (), "W", "quasi-static power loss with the ball drag at the low end of the drag "
         "band (qs_drag_band_low: the unsettled mixture co-rotation and drag coefficient)")
register("drag_band_power_loss_high", (), "W", "quasi-static power loss with the ball drag at the high end of the drag "
         "band (qs_drag_band_high)")

#: (criterion, variable, better, what): ``better`` is "lower", "higher" or "abs_lower" (closest to zero)
CRITERIA = (
    ("power_loss", "power_loss", "lower", "power loss at the quasi-static state"),
    ("drive_torque", "drive_torque", "lower", "drive torque at the quasi-static state"),
    ("dynamic_power_loss", "dynamic_power_loss", "lower", "power loss of the dynamic run (time mean after the transient)"),
    ("cage_slip", "mean_cage_slip_ratio", "abs_lower", "cage slip of the dynamic run (closest to zero)"),
    ("cage_whirl", "whirl_amplitude", "lower", "cage whirl radius (RMS) of the dynamic run"),
    ("film_parameter", "min_film_parameter", "higher", "film parameter lambda of the thinnest contact (quasi-static; higher is better)"),
    ("film_thickness", "min_film_thickness", "higher", "minimum film thickness of the thinnest contact (quasi-static; higher is better)"),
    ("contact_pressure", "max_contact_pressure", "lower", "maximum contact pressure (quasi-static; lower is better)"),
    ("modified_rating_life", "modified_rating_life", "higher", "ISO 281 modified rating life L_10m"),
    ("modified_reference_rating_life", "modified_reference_rating_life", "higher",
     "ISO/TS 16281 modified reference rating life"),
    ("inner_ring_temperature", "inner_ring_temperature", "lower", "inner-ring temperature at thermal equilibrium"),
    ("oil_outlet_temperature", "oil_outlet_temperature", "lower", "oil outlet temperature at thermal equilibrium"),
)
#: criteria with an uncertainty band run for every oil: variable -> (value at the low end, value at the high end)
BANDS = {"power_loss": ("drag_band_power_loss_low", "drag_band_power_loss_high")}

#: record variables of each sweep, kept in compare.nc under ``<kind>_<name>``
_RECORDS = ("status", "error", "archive")
#: the kind's prefix in compare.nc for its record variables and for its summaries that collide with another kind's
_PREFIX = {"quasistatic": "quasistatic", "run": "dynamic", "thermal": "thermal"}


def quasistatic_point(case, duration=None) -> xr.Dataset:
    """One oil's quasi-static point of ``hsbearing compare``: the equilibrium with the power by source, drive torque,
    film and pressure (:func:`hsbearing.workflows.sweeps.points.with_power_and_film`), the total power loss at both
    ends of the drag band and the rating lives (:func:`hsbearing.systems.angular_contact.rating.life`) as scalars.
    A life the case cannot give (no load) is left out and ``life_note`` says why."""
    from hsbearing.systems.angular_contact import rating
    from hsbearing.systems.angular_contact.quasistatic import solve_case
    from hsbearing.workflows.sweeps.points import QS_OPTIONAL_SUMMARY, with_power_and_film

    p = rating.quasi_static_power_loss(case)
    ds = with_power_and_film(case, solve_case(case), power=p)
    rest = p["power_loss"] - p["drag"]
    for end in ("low", "high"):
        name = f"drag_band_power_loss_{end}"
        ds[name] = xr.Variable((), rest + p[f"drag_band_{end}"], attrs={"units": "W", "long_name": VARIABLES[name].long_name})
    try:
        life = rating.life(case)
    except CaseError as exc:
        ds.attrs["life_note"] = f"rating life not computed: {exc}"
        return ds
    for name in QS_OPTIONAL_SUMMARY:
        if name in life and life[name].ndim == 0:
            ds[name] = life[name]
    ds.attrs["life_inputs"] = (f"X = {life.attrs['load_factor_X']:.4g}, Y = {life.attrs['load_factor_Y']:.4g}, nu = "
                               f"{life.attrs['kinematic_viscosity_mm2_s']:.4g} mm^2/s, e_C = {life.attrs['contamination_factor']:g}")
    return ds


def parse_oils(oils) -> list[str]:
    """``"4109,4106,my_oil.toml"`` or a list -> the oils as given (names, bundled lubricant names, .toml files)."""
    items = [o.strip() for o in oils.split(",")] if isinstance(oils, str) else [str(o).strip() for o in oils]
    if not items or any(not o for o in items):
        raise CaseError("--oils", None, f"expected a comma-separated list of oils (names or lubricant .toml files), got {oils!r}")
    seen = set()
    for o in items:
        if o in seen:
            raise CaseError("--oils", None, f"oil {o!r} given twice")
        seen.add(o)
    return items


def plan_compare(case, oils, vary: Mapping[str, Any] | None = None, *, dynamics: bool = True, duration=None,
                 stop: str = "converged"):
    """The plans of a comparison (quasi-static, run, thermal) and why thermal is skipped ('' if it is not).

    Raises CaseError for bad input (an oil that is no oil, a varied key given twice or ``oil`` in ``vary``, a value
    that makes an invalid case): nothing is computed or written."""
    from hsbearing.systems.angular_contact import thermal
    from hsbearing.workflows.sweeps.plan import plan_sweep

    case = as_case(case)
    if case.system != "angular_contact":
        raise CaseError(case.source, "case.system", f"hsbearing compare runs angular_contact cases (the ball-bearing "
                                                    f"dynamic model), not {case.system!r}")
    oils = parse_oils(oils)
    vary = dict(vary or {})
    for k in vary:
        if k.rpartition(".")[2] in ("oil", "file"):
            raise CaseError("--vary", k, "the oils are given by --oils")
    full = {"lubricant.oil": oils, **vary}
    # an oil that is no oil is the fault of --oils, a value that makes an invalid case with a good oil of --vary
    for source, spec in (("--oils", {"lubricant.oil": oils}), ("--vary", full)):
        plan = plan_sweep(case, spec, kind="quasistatic", point_fn=quasistatic_point)
        bad = [pt for pt in plan.points if pt.case is None]
        if bad:
            where = ", ".join(f"{k}={v}" for k, v in bad[0].overrides.items())
            raise CaseError(source, None, f"point {where} is not a valid case: {bad[0].error}")
    plans = {"quasistatic": plan}
    if dynamics:
        run_case = case if case.simulation.stop == stop else case.with_overrides(**{"simulation.stop": stop})
        dur = DEFAULT_DURATION if duration is None else duration
        plans["run"] = plan_sweep(run_case, full, kind="run", duration=dur)
    skipped = ""
    try:
        for pt in plans["quasistatic"].points:
            thermal.check_inputs(pt.case)
    except CaseError as exc:
        skipped = f"thermal equilibrium skipped: {exc}"
    else:
        plans["thermal"] = plan_sweep(case, full, kind="thermal")
    return plans, skipped


def compare(case, oils, *, vary: Mapping[str, Any] | None = None, out_dir, dynamics: bool = True, duration=None,
            stop: str = "converged", jobs: int | None = None, scheduler: str | None = None, progress: bool = True,
            figures: bool = True, keep: str = "answer") -> xr.Dataset:
    """Compare lubricants at the same conditions and write the page (see :mod:`hsbearing.workflows.compare`)."""
    from hsbearing.workflows.compare import report
    from hsbearing.workflows.sweeps.archives import clean_temporaries, dir_lock
    from hsbearing.workflows.sweeps.backends import check_scheduler_address, make_backend
    from hsbearing.workflows.sweeps.execute import assemble, execute

    out = Path(out_dir)
    check_output_path(out, source="output directory", directory=True,
                      derived=[out / NC_NAME, out / MD_NAME, out / HTML_NAME])
    if scheduler:
        check_scheduler_address(scheduler)
    plans, skipped = plan_compare(case, oils, vary, dynamics=dynamics, duration=duration, stop=stop)
    t0 = time.perf_counter()
    with make_backend(jobs, scheduler) as backend, dir_lock(out):
        clean_temporaries(out, [NC_NAME, MD_NAME, HTML_NAME])
        recs = execute(list(plans.values()), out / POINTS_DIR, progress=progress, backend=backend, keep=keep)
        sweeps = {kind: assemble(plan, r, archive_prefix=f"{POINTS_DIR}/") for (kind, plan), r in zip(plans.items(), recs)}
        ds = combine(sweeps, skipped=skipped, dynamics=dynamics,
                     duration=plans["run"].duration if "run" in plans else None, wall_time=time.perf_counter() - t0,
                     backend=f"dask {scheduler}" if scheduler else f"jobs={jobs or os.cpu_count()}")
        ds = ds.assign(lubricant_notices=("oil", oil_notices(plans["quasistatic"], ds),
                                          {"units": "", "long_name": "what a user must know before reading the oil's "
                                           "results as its own (traction borrowed, alpha estimated, recommended law)"}))
        report.write_all(ds, sweeps, out, figures=figures)
    return ds


def oil_notices(plan, ds) -> list[str]:
    """The one-line notices of each oil (:func:`hsbearing.lubricant.notices`), joined by ' | ' ('none' without)."""
    from hsbearing.lubricant import identity_attrs

    by_oil = {}
    for pt in plan.points:
        if pt.case is not None:
            by_oil.setdefault(str(pt.overrides.get("lubricant.oil")), identity_attrs(pt.case).get("lubricant_notices", ""))
    return [by_oil.get(str(o), "") for o in ds["oil"].values]


def combine(sweeps: Mapping[str, xr.Dataset], *, skipped: str = "", dynamics: bool = True, duration=None,
            wall_time: float = float("nan"), backend: str = "") -> xr.Dataset:
    """One Dataset over ``oil`` (and the varied keys) from the comparison's sweeps, with the best oil per criterion."""
    qs = sweeps["quasistatic"]
    seen: set[str] = set()
    data: dict[str, xr.DataArray] = {}
    for kind, sw in sweeps.items():
        sw = sw.rename({"lubricant.oil": "oil"}) if "lubricant.oil" in sw.dims else sw
        for name in sw.data_vars:
            name = str(name)
            if name in ("wall_time", "resumed"):
                continue
            if name in _RECORDS:
                out_name = f"{_PREFIX[kind]}_{name}"
            elif name in ("lubricant_name", "lubricant_provenance"):
                if name in seen:
                    continue
                out_name = name
            else:
                out_name = name if name not in seen else f"{_PREFIX[kind]}_{name}"
            var = sw[name].copy()
            if out_name != name and name not in _RECORDS:
                var.attrs["long_name"] = f"{_PREFIX[kind]}: " + var.attrs.get("long_name", name)
            if name in _RECORDS:
                var.attrs = {"units": "", "long_name": f"{_PREFIX[kind]} point: " + VARIABLES[name].long_name}
            var.attrs.setdefault("units", "")
            var.attrs.setdefault("long_name", out_name.replace("_", " "))
            data[out_name] = var
            seen.add(name)
    ds = xr.Dataset(data)
    ds = ds.rename({"lubricant.oil": "oil", "lubricant.oil_label": "oil_label"}) if "lubricant.oil" in ds.dims else ds
    if "oil" in ds.coords:
        ds["oil"].attrs.update({"long_name": "the oil as given (built-in name, bundled lubricant or lubricant file)",
                                "units": ""})
    ds = ds.assign_coords(oil_name=("oil", [str(v) for v in _oil_names(ds)],
                                    {"long_name": "the oil by its own name (a lubricant file's name)", "units": ""}))
    ds = add_best(ds)
    vary_dims = [d for d in ds["quasistatic_status"].dims if d != "oil"]
    ds.attrs.update(standard_attrs(None, status=_status(ds)))
    base = qs.attrs
    ds.attrs.update({
        "title": "hsbearing compare: lubricants at the same conditions",
        "case_name": base.get("case_name", ""),
        "case_toml": base.get("case_toml", ""),
        "compare_oils": json.dumps([str(o) for o in ds["oil"].values]),
        "compare_vary": json.dumps({d: [str(v) for v in ds[f"{d}_label"].values] for d in vary_dims if f"{d}_label" in ds}),
        "compare_dynamics": ("dynamic run of at most {} s per oil, stop rule on (simulation.stop = converged)".format(
            _g(duration)) if dynamics else "none (--no-dynamics): quasi-static comparison only; no cage class or whirl"),
        "compare_thermal": skipped or "thermal equilibrium of every oil (hsbearing thermal of its case)",
        "compare_wall_time": wall_time,
        "compare_backend": backend,
        "compare_criteria": json.dumps([(c, v, b) for c, v, b, _ in CRITERIA if v in ds]),
    })
    if skipped:
        ds.attrs["thermal_skipped"] = skipped
    return ds


def _g(x) -> str:
    try:
        return f"{float(x):g}"
    except (TypeError, ValueError):
        return str(x)


def _status(ds) -> str:
    bad = []
    for name in ("quasistatic_status", "dynamic_status", "thermal_status"):
        if name in ds:
            n = int(np.sum(np.asarray(ds[name].values, dtype=object) != "ok"))
            if n:
                bad.append(f"{n} {name.removesuffix('_status')} point(s) not ok")
    return "ok" if not bad else "partial: " + ", ".join(bad)


def _oil_names(ds) -> list[str]:
    names = []
    for i, o in enumerate(ds["oil"].values):
        n = ""
        if "lubricant_name" in ds:
            vals = np.asarray(ds["lubricant_name"].isel(oil=i).values, dtype=object).ravel()
            n = next((str(v) for v in vals if str(v)), "")
        names.append(n or str(o))
    return names


def _score(values: np.ndarray, better: str) -> np.ndarray:
    """Smaller is better: the value, its negative, or its magnitude."""
    v = np.asarray(values, dtype=float)
    return v if better == "lower" else -v if better == "higher" else np.abs(v)


def best_of(values, names, better: str) -> dict:
    """The best and runner-up of one criterion at one point: ``{"best", "runner_up", "value", "runner_up_value",
    "margin", "relative_margin"}`` (margin = how much worse the runner-up is, in the variable's units, >= 0); NaN
    values (a point that is not ok) take no part.  Fewer than two finite values: no runner-up (NaN margin)."""
    v = np.asarray(values, dtype=float)
    ok = np.flatnonzero(np.isfinite(v))
    out = {"best": "", "runner_up": "", "value": math.nan, "runner_up_value": math.nan, "margin": math.nan,
           "relative_margin": math.nan}
    if not ok.size:
        return out
    s = _score(v, better)
    order = ok[np.argsort(s[ok], kind="stable")]
    out["best"], out["value"] = str(names[order[0]]), float(v[order[0]])
    if order.size > 1:
        out["runner_up"], out["runner_up_value"] = str(names[order[1]]), float(v[order[1]])
        out["margin"] = float(s[order[1]] - s[order[0]])
        out["relative_margin"] = out["margin"] / abs(out["value"]) if out["value"] != 0 else math.inf
    return out


def _relative_meaningful(units: str) -> bool:
    """A relative difference of absolute temperatures says nothing (0.2 % of 405 K is 0.8 K): not given for K."""
    return units != "K"


def add_best(ds: xr.Dataset) -> xr.Dataset:
    """Variables over (``criterion``, the varied keys): ``best_oil``, ``best_value``, ``runner_up_oil``,
    ``runner_up_value``, ``best_margin`` (how much worse the runner-up is, in the criterion's units),
    ``best_relative_margin``, and, for a criterion with a band run for every oil (:data:`BANDS`), the same ranking at
    the band's two ends (``best_oil_band_low/high``, ``best_margin_band_low/high``: every oil at the same end, since
    the unsettled choice is one for all oils)."""
    crit = [(c, v, b, w) for c, v, b, w in CRITERIA if v in ds and np.any(np.isfinite(np.asarray(ds[v].values, float)))]
    if not crit:
        return ds
    names = list(ds["oil_name"].values)
    vary_dims = [d for d in ds[crit[0][1]].dims if d != "oil"]
    shape = tuple(ds.sizes[d] for d in vary_dims)
    fields = {k: np.empty((len(crit),) + shape, dtype=object if k in ("best", "runner_up") else float)
              for k in ("best", "runner_up", "value", "runner_up_value", "margin", "relative_margin")}
    band = {f"{k}_{end}": np.full((len(crit),) + shape, "" if k == "best" else np.nan,
                                  dtype=object if k == "best" else float)
            for k in ("best", "margin") for end in ("low", "high")}
    for i, (_, var, better, _) in enumerate(crit):
        arr = ds[var].transpose("oil", *vary_dims).values
        for idx in np.ndindex(*shape):
            r = best_of(arr[(slice(None),) + idx], names, better)
            if not _relative_meaningful(ds[var].attrs.get("units", "")):
                r["relative_margin"] = math.nan
            for k in fields:
                fields[k][(i,) + idx] = r[k]
            if var in BANDS:
                for end, bvar in zip(("low", "high"), BANDS[var]):
                    if bvar in ds:
                        rb = best_of(ds[bvar].transpose("oil", *vary_dims).values[(slice(None),) + idx], names, better)
                        band[f"best_{end}"][(i,) + idx] = rb["best"]
                        band[f"margin_{end}"][(i,) + idx] = rb["margin"]
    dims = ("criterion",) + tuple(vary_dims)
    units = [ds[v].attrs.get("units", "") for _, v, _, _ in crit]
    meta = {
        "best": ("best_oil", "", "the best oil by the criterion (its own name)"),
        "runner_up": ("runner_up_oil", "", "the second-best oil by the criterion"),
        "value": ("best_value", "criterion_units", "the best oil's value of the criterion's variable"),
        "runner_up_value": ("runner_up_value", "criterion_units", "the runner-up's value"),
        "margin": ("best_margin", "criterion_units", "how much worse the runner-up is than the best (>= 0)"),
        "relative_margin": ("best_relative_margin", "1", "best_margin / |best_value| (NaN for temperatures: a ratio "
                                                         "of absolute temperatures says nothing)"),
    }
    new = {}
    for k, (name, u, long) in meta.items():
        new[name] = xr.Variable(dims, fields[k], attrs={"units": u if u != "criterion_units" else "see criterion_units",
                                                         "long_name": long})
    if any(v in BANDS for _, v, _, _ in crit):
        for end in ("low", "high"):
            new[f"best_oil_band_{end}"] = xr.Variable(dims, band[f"best_{end}"], attrs={
                "units": "", "long_name": f"the best oil with every oil at the {end} end of the criterion's band "
                                          "('' where no band is run)"})
            new[f"best_margin_band_{end}"] = xr.Variable(dims, band[f"margin_{end}"], attrs={
                "units": "see criterion_units", "long_name": f"best_margin at the {end} end of the band"})
    ds = ds.assign(new)
    ds = ds.assign_coords(
        criterion=("criterion", [c for c, _, _, _ in crit], {"long_name": "comparison criterion", "units": ""}),
        criterion_variable=("criterion", [v for _, v, _, _ in crit], {"long_name": "the variable it ranks", "units": ""}),
        criterion_better=("criterion", [b for _, _, b, _ in crit], {"long_name": "lower, higher or abs_lower is better",
                                                                    "units": ""}),
        criterion_units=("criterion", units, {"long_name": "units of the criterion's variable", "units": ""}),
        criterion_description=("criterion", [w for _, _, _, w in crit], {"long_name": "what the criterion is",
                                                                         "units": ""}),
    )
    return ds
