"""``hsbearing sweep``: the base case of the command line and the printed table."""

from __future__ import annotations

import sys
from pathlib import Path
from typing import Sequence

import numpy as np
import xarray as xr

from hsbearing.case import (
    Case,
    CaseError,
    load_case,
)
from hsbearing.errors import SolverError
from hsbearing.results import check_output_path
from hsbearing.workflows.sweeps.backends import check_scheduler_address
from hsbearing.workflows.sweeps.execute import run_sweep
from hsbearing.workflows.sweeps.plan import plan_sweep, zip_

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


#: the columns of the printed table, in order: cage answer, loads, what users compare (power, torque, film, pressure),
#: gyro moments, thermal temperatures and heats (a column is printed when the sweep carries it)
TABLE_KEYS = ("classification", "mean_cage_slip_ratio", "mean_cage_slip_ratio_raceway_control", "cage_slip_ratio",
              "whirl_amplitude", "whirl_frequency_ratio", "mean_inner_contact_load", "mean_outer_contact_load",
              "cage_speed", "power_loss", "drive_torque", "min_film_thickness", "min_film_parameter",
              "max_contact_pressure", "sfmc", "sfmc_ensemble_mean", "sfmc_ensemble_sd", "sfmo", "sfmo_stderr", "rfmc",
              "inner_ring_temperature", "outer_ring_temperature", "ball_temperature", "cage_temperature",
              "housing_temperature", "shaft_temperature", "oil_outlet_temperature", "lubricant_temperature",
              "heat_generated", "heat_removed_by_oil", "heat_removed_by_conduction")


def _nonzero(ds, name) -> bool:
    v = ds[name]
    if v.dtype.kind not in "fiu":
        return False
    a = np.asarray(v.values, dtype=float)
    return bool(np.any(np.isfinite(a) & (np.abs(a) > 1e-12)))


def print_table(ds: xr.Dataset, file=None) -> None:
    """One line per point: varied values, status, the summary values users compare (with their units), error.

    The first line of a point carries the cage answer (class, slip, whirl), the contact loads, the power loss,
    drive torque, smallest film and lambda, largest contact pressure (run and quasi-static sweeps) or the node
    temperatures and heats (thermal sweeps); an indented second line gives the power loss by source
    (``power_loss_<source>``, the sources that are not zero at every point) and, for a thermal sweep, the heat
    along every path of the network (``heat_flow_<from>_to_<to>``)."""
    from hsbearing.display import format_value

    file = file or sys.stdout
    keys = [v for v in TABLE_KEYS if v in ds]
    if "lubricant_name" in ds and any("oil" in str(c) or "lubricant" in str(c) for c in ds.coords):
        keys.insert(0, "lubricant_name")  # the oils varied: each by its own name (a file's name, not its path)
    by_source = [str(v) for v in ds.data_vars if str(v).startswith(("power_loss_", "thermal_power_loss_"))
                 and _nonzero(ds, v)]
    heat = [str(v) for v in ds.data_vars if str(v).startswith("heat_flow_")]
    dims = ds["status"].dims
    labels = [c for c in ds.coords if str(c).endswith("_label")]
    for idx in np.ndindex(*ds["status"].shape):
        pt = ds.isel(dict(zip_(dims, idx)))
        parts = [f"{str(c)[:-6]}={pt[c].values.item()}" for c in labels]
        parts.append(f"status={pt['status'].values.item()}")
        for k in keys:  # in the units users read (hsbearing.display): um, r/min, %, uN m, degC, GPa
            parts.append(f"{k}={format_value(pt[k], k)}")
        if pt["error"].values.item():
            parts.append(f"error={pt['error'].values.item()}")
        print("  ".join(parts), file=file)
        more = [f"{k}={format_value(pt[k], k)}" for k in by_source + heat]
        if more:
            print("    " + "  ".join(more), file=file)


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


def extend_request(args, case) -> str | None:
    """What ``--extend [--max-duration T]`` asks of ``hsbearing run`` and ``hsbearing sweep`` (opt-in): None (no
    extension), "default" (the default budget) or the budget text (checked by the caller).  Bad input
    (``--max-duration`` without ``--extend``, ``--extend`` of a system whose runs cannot be extended) is a CaseError
    before anything is computed or written."""
    extend, text = bool(getattr(args, "extend", False)), getattr(args, "max_duration", None)
    if not extend:
        if text:
            raise CaseError("--max-duration", "max_duration", "only with --extend")
        return None
    from hsbearing import systems

    if systems.get(case).extend is None:
        raise CaseError("--extend", "case.system", f"runs of the {case.system!r} system cannot be extended (only the "
                                                   "angular-contact model's)")
    return text if text else "default"


def sweep_extend_arg(args, case):
    """``extend=`` of :func:`run_sweep` from ``hsbearing sweep --extend [--max-duration T]`` (:func:`extend_request`;
    also an input error with another kind than run); the budget itself is checked by :func:`plan_sweep`."""
    if getattr(args, "extend", False) and getattr(args, "kind", "run") != "run":
        raise CaseError("--extend", None, f"only with --kind run (dynamic runs), not --kind {args.kind}")
    return extend_request(args, case)


def cli_main(args) -> int:
    """``hsbearing sweep CASE --vary KEY=V1,V2 [--zip] [-j N] [--scheduler ADDR] [--kind] [--duration] -o DIR``.

    Exit code 0 when every point is ok, 1 when some point failed numerically
    (its status and error are in ``DIR/sweep.nc``; the other points are
    kept), 2 on bad input, including a varied value that makes an invalid
    case (nothing computed or written), unless ``--keep-going``.
    """
    case = cli_base_case(args)
    vary = _parse_vary(args.vary)
    extend = sweep_extend_arg(args, case)
    out = Path(args.output)
    check_output_path(out, directory=True)
    if args.scheduler:
        check_scheduler_address(args.scheduler)
    if not getattr(args, "keep_going", False):
        # On the command line a value that makes an invalid case is bad input: exit 2 before anything is
        # computed or written (the library, and --keep-going, record such points as "invalid" and go on).
        plan = plan_sweep(case, vary, zip=args.zip, kind=args.kind, duration=args.duration, extend=extend)
        bad = [pt for pt in plan.points if pt.case is None]
        if bad:
            where = ", ".join(f"{k}={v}" for k, v in bad[0].overrides.items())
            more = f" (and {len(bad) - 1} more point(s); --keep-going records them and runs the rest)" if len(bad) > 1 else \
                " (--keep-going records it and runs the rest)"
            raise CaseError("--vary", None, f"point {where} is not a valid case: {bad[0].error}{more}")
    try:
        ds = run_sweep(case, vary, zip=args.zip, jobs=args.jobs, scheduler=args.scheduler, out_dir=out,
                       kind=args.kind, duration=args.duration, progress=True,
                       keep=getattr(args, "keep", "answer"), extend=extend)
    except SolverError as exc:
        if exc.partial is None:
            raise
        ds = exc.partial  # every point crashed: the table says why, exit 1 below
    print_table(ds)
    n, n_ok = ds.attrs["sweep_points"], ds.attrs["sweep_points_ok"]
    print(f"{n_ok} of {n} points ok ({ds.attrs['sweep_points_resumed']} resumed); wall time "
          f"{ds.attrs['sweep_wall_time']:.1f} s; sweep: {out / 'sweep.nc'}")
    return 0 if n_ok == n else 1
