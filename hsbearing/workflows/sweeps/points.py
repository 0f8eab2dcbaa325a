"""One sweep point, computed in a worker: the run, quasi-static or thermal solve and its summary scalars."""

from __future__ import annotations

import contextlib
import os
import signal
import sys
import time
import traceback
from pathlib import Path
from typing import Any

import numpy as np
import xarray as xr

from hsbearing.case import (
    Case,
    CaseError,
)
from hsbearing.errors import SolverError
from hsbearing.results import standard_attrs
from hsbearing.workflows.sweeps.plan import STATUS_OK

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


#: scalars of a thermal equilibrium (kind="thermal") kept in the sweep summary (names of hsbearing.systems.angular_contact.thermal)
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


def scalar_value(v: Any) -> Any:
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


def compute_point(case: Case, kind: str, duration, point_fn) -> tuple[dict, xr.Dataset | None]:
    """Compute one point; never raises for a point's own failure.  Returns (record, dataset)."""
    t0 = time.perf_counter()
    ds = None
    rec: dict[str, Any] = {"status": STATUS_OK, "error": "", "summary": {}}
    try:
        if point_fn is not None:
            ds = point_fn(case, duration)
        elif kind == "quasistatic":
            from hsbearing.systems.angular_contact.quasistatic import solve_case

            ds = solve_case(case)
        elif kind == "thermal":
            from hsbearing.systems.angular_contact.thermal import thermal_equilibrium

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
            rec["summary"] = {k: scalar_value(v) for k, v in summ.items()}
        except Exception as exc:  # summary of a partial/odd dataset: keep the archive, say why
            rec["summary_error"] = f"summary failed: {type(exc).__name__}: {exc}"
            rec["error"] = "; ".join(e for e in (rec["error"], rec["summary_error"]) if e)
    rec["wall_time"] = time.perf_counter() - t0
    return rec, ds


def worker_init(parent: int | None = None) -> None:  # pragma: no cover - runs in the worker processes
    """Die with the parent (Linux): an interrupted sweep leaves no orphan computing.  ``parent``: the pid of
    the sweep process (a worker that finds another parent was orphaned while it started, and exits)."""
    with contextlib.suppress(Exception):
        signal.signal(signal.SIGINT, signal.SIG_IGN)  # the parent handles Ctrl-C and shuts us down
    if sys.platform.startswith("linux"):
        with contextlib.suppress(Exception):
            import ctypes

            libc = ctypes.CDLL("libc.so.6", use_errno=True)
            libc.prctl(1, signal.SIGTERM)  # PR_SET_PDEATHSIG
            # the parent died before the line above (a worker still starting up): we were re-parented, to init
            # or to a subreaper (a container's init, a process supervisor), so compare with the parent we had
            if os.getppid() == 1 or (parent is not None and os.getppid() != parent):
                os._exit(1)
