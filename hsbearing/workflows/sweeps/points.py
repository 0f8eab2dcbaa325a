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


def with_power_and_film(case: Case, ds: xr.Dataset, *, power: dict | None = None) -> xr.Dataset:
    """A quasi-static Dataset with what a sweep compares added: the power loss by source and the drive torque at
    that state (:func:`hsbearing.systems.angular_contact.rating.quasi_static_power_loss`, scalars ``power_loss``,
    ``power_loss_<source>`` [W], ``drive_torque`` [N m]) and the minimum film and lambda per ball
    (:func:`hsbearing.systems.angular_contact.contact_state.quasi_static_contact_state`).  Where the case cannot
    give one (a system without the dynamic model's cage data), the attribute ``power_loss_note`` says why.
    ``power``: the case's ``quasi_static_power_loss`` when the caller already has it (not computed again)."""
    from hsbearing.results import VARIABLES
    from hsbearing.systems.angular_contact import contact_state
    from hsbearing.systems.angular_contact.rating import quasi_static_power_loss

    ds = ds.copy()
    try:
        state = contact_state.quasi_static_contact_state(case, ds)
        for k, v in state.items():
            if k not in ds and k in VARIABLES:
                ds[k] = xr.Variable(("ball",), np.asarray(v, dtype=float),
                                    attrs={"units": VARIABLES[k].units, "long_name": VARIABLES[k].long_name})
    except (KeyError, ValueError, AttributeError) as exc:
        ds.attrs["film_note"] = f"minimum film not computed: {type(exc).__name__}: {exc}"
    try:
        p = quasi_static_power_loss(case, bands=False) if power is None else power
    except (CaseError, SolverError, KeyError, ValueError, AttributeError, ArithmeticError) as exc:
        ds.attrs["power_loss_note"] = f"power loss not computed at this state: {type(exc).__name__}: {exc}"
        return ds

    for name in ("power_loss", "drive_torque"):
        ds[name] = xr.Variable((), p[name], attrs={"units": VARIABLES[name].units, "long_name": VARIABLES[name].long_name
                                                    + " (at the quasi-static state)"})
    for src, val in p.items():
        name = f"power_loss_{src}"
        if name in VARIABLES:
            ds[name] = xr.Variable((), float(val), attrs={"units": VARIABLES[name].units,
                                                          "long_name": VARIABLES[name].long_name + " (at the quasi-static state)"})
    return ds


def quasistatic_summary(ds: xr.Dataset) -> dict[str, Any]:
    """Scalars of a quasi-static result: mean/max contact loads, cage speed and slip, axial displacement, and
    (when the Dataset carries them, :func:`with_power_and_film`) the power loss by source, drive torque,
    smallest film and lambda and largest contact pressure (:func:`hsbearing.analysis.orbit.contact_power_summary`)."""
    from hsbearing.analysis.orbit import contact_power_summary

    out: dict[str, Any] = {}
    for side in ("inner", "outer"):
        name = f"{side}_contact_load"
        if name in ds:
            q = np.asarray(ds[name].values, dtype=float)
            out[f"mean_{name}"] = float(np.mean(q))
            out[f"max_{name}"] = float(np.max(q))
    for name in ("cage_speed", "cage_slip_ratio", "inner_ring_axial_displacement"):
        if name in ds and ds[name].ndim == 0:
            out[name] = float(ds[name].values)
    out.update(contact_power_summary(ds))
    for name in QS_OPTIONAL_SUMMARY:  # carried by a compare point (hsbearing.workflows.compare): life, drag band
        if name in ds and ds[name].ndim == 0:
            out[name] = float(ds[name].values)
    return out


#: scalars a quasi-static point may carry besides its loads, power and film (``hsbearing compare`` adds them: the
#: rating lives of ``rating.life`` and the total power loss at the two ends of the drag band), summarised when present
QS_OPTIONAL_SUMMARY = ("drag_band_power_loss_low", "drag_band_power_loss_high", "viscosity_ratio",
                       "life_modification_factor", "basic_rating_life", "modified_rating_life", "reference_rating_life",
                       "modified_reference_rating_life")


#: scalars of a thermal equilibrium (kind="thermal") kept in the sweep summary (names of hsbearing.systems.angular_contact.thermal)
THERMAL_SUMMARY = ("inner_ring_temperature", "outer_ring_temperature", "ball_temperature", "cage_temperature",
                   "housing_temperature", "shaft_temperature", "oil_outlet_temperature", "lubricant_temperature",
                   "heat_generated", "heat_removed_by_oil", "heat_removed_by_conduction", "heat_balance_error",
                   "fixed_point_iterations")


def thermal_summary(ds: xr.Dataset) -> dict[str, Any]:
    """Scalars of a thermal equilibrium: component, oil outlet and lubricant temperatures [K], heat generated
    and removed by the oil and by conduction [W], the balance error and the fixed-point iterations, the
    power loss by source at equilibrium (``thermal_power_loss_<source>`` [W]) and the heat along every link of
    the network (``heat_flow_<from>_to_<to>`` [W], :data:`hsbearing.systems.angular_contact.thermal.HEAT_PATHS`)."""
    names = list(THERMAL_SUMMARY) + sorted(str(n) for n in ds.data_vars if str(n).startswith("thermal_power_loss_"))
    out = {n: float(ds[n].values) for n in names if n in ds and ds[n].ndim == 0}
    if "link_heat_flow" in ds and "link_from" in ds.coords and "link_to" in ds.coords:  # heat by path
        from hsbearing.systems.angular_contact.thermal import heat_path_name

        for a, b, q in zip(ds["link_from"].values, ds["link_to"].values, ds["link_heat_flow"].values):
            out[heat_path_name(str(a), str(b))] = float(q)
    return out


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


#: What a point archive keeps: "answer" (default) or "full" (the whole trajectory).
KEEP_CHOICES = ("answer", "full")
#: Variables kept at the full output rate by keep="answer": the cage-centre orbit the classifier re-reads.
ORBIT_VARIABLES = ("cage_center_y", "cage_center_z", "cage_velocity_y", "cage_velocity_z", "cage_angle", "cage_speed")
#: Samples of every other time history kept by keep="answer" (decimated, on dim ``time_decimated``).
DECIMATED_SAMPLES = 400


def check_keep(keep: str, source: str = "--keep") -> str:
    if keep not in KEEP_CHOICES:
        raise CaseError(source, "keep", f"must be one of {', '.join(KEEP_CHOICES)}, got {keep!r}")
    return keep


def keep_answer(ds: xr.Dataset) -> xr.Dataset:
    """What a map or sweep point's answer and figures need, out of a whole dynamic run.

    Kept: every variable without a ``time`` dim (the summaries, the Poincare section points, ``final_state``
    for ``hsbearing run --continue``), all attributes (label, its reasons, the case), the cage-centre orbit
    (:data:`ORBIT_VARIABLES`) at the full output rate -- so that the classifier re-reads a kept archive
    exactly as the whole run -- and every other time history (slip ratio, ball and contact variables)
    decimated to about :data:`DECIMATED_SAMPLES` samples on the dim ``time_decimated``.  A Dataset
    without ``time`` (quasi-static, thermal) is returned unchanged.
    """
    if "time" not in ds.dims:
        return ds
    n = ds.sizes["time"]
    step = max(1, -(-n // DECIMATED_SAMPLES))
    timed = [k for k, v in ds.data_vars.items() if "time" in v.dims]
    other = [k for k in timed if k not in ORBIT_VARIABLES]
    out = ds.drop_vars(other)
    if other and step > 1:
        dec = ds[other].isel(time=slice(None, None, step)).rename({"time": "time_decimated"})
        dec = dec.drop_vars([c for c in dec.coords if c != "time_decimated" and "time_decimated" not in dec[c].dims])
        out = out.assign(dec.data_vars).assign_coords(time_decimated=dec["time_decimated"])
        out["time_decimated"].attrs.update(units="s", long_name=f"time of the decimated histories (every {step}th output)")
    elif other:
        out = out.assign(ds[other].data_vars)
    out.attrs["keep"] = "answer"
    out.attrs["keep_definition"] = (
        f"cage-centre orbit ({', '.join(v for v in ORBIT_VARIABLES if v in ds)}) at every one of the {n} outputs; "
        f"the other {len(other)} time histories every {step}th output (dim time_decimated); summaries, section points, "
        "final_state and attrs whole (--keep full for the whole trajectory)")
    return out


def extend_point(case: Case, ds: xr.Dataset, budget: float, point_fn, rec: dict) -> xr.Dataset:
    """A run extended until its label is determined, the stop rule's convergence holds or ``budget`` [s] of
    simulated time is spent (the system's :attr:`~hsbearing.systems.System.extend`, the stop rule's convergence
    checked after each step); a continuation that fails numerically ends the extension and the run is kept as it
    was before it.  ``point_fn.continue_fn(ds, duration)`` continues a stand-in point function's runs."""
    from hsbearing import systems

    system = systems.get(case)
    if system.extend is None:
        return ds
    kw = {"converge": True, "keep_on_failure": True, "fast_forward": True}
    if point_fn is not None:
        kw["continue_fn"] = point_fn.continue_fn
    t0 = time.perf_counter()
    try:
        ds = system.extend(ds, budget, **kw)
    except Exception as exc:  # noqa: BLE001 - the run itself is complete: keep it, say why it was not extended
        tb = traceback.extract_tb(exc.__traceback__)
        where = f" ({Path(tb[-1].filename).name}:{tb[-1].lineno})" if tb else ""
        ds = ds.copy()
        ds.attrs["extension_stop_reason"] = f"failed: {type(exc).__name__}: {exc}{where}; the run is kept unextended"
        ds.attrs["extensions"] = "[]"
    rec["extension_wall_time"] = time.perf_counter() - t0
    return ds


def compute_point(case: Case, kind: str, duration, point_fn, keep: str = "full",
                  extend: float | None = None) -> tuple[dict, xr.Dataset | None]:
    """Compute one point; never raises for a point's own failure.  Returns (record, dataset).

    ``extend``: budget [s] of total simulated time; a run whose label is undetermined is extended
    (:func:`extend_point`) before its summary.  ``keep="answer"``: the dataset is reduced by :func:`keep_answer`
    after its summary is computed (in the worker, so only what is kept travels to the client)."""
    t0 = time.perf_counter()
    ds = None
    rec: dict[str, Any] = {"status": STATUS_OK, "error": "", "summary": {}}
    try:
        if point_fn is not None:
            ds = point_fn(case, duration)
        elif kind == "quasistatic":
            from hsbearing.systems.angular_contact.quasistatic import solve_case

            ds = with_power_and_film(case, solve_case(case))
        elif kind == "thermal":
            from hsbearing.systems.angular_contact.thermal import thermal_equilibrium

            ds = thermal_equilibrium(case)
        else:
            from hsbearing.systems import simulate

            ds = simulate(case, duration=duration)
        rec["status"] = str(ds.attrs.get("status", STATUS_OK))
        if extend is not None and kind == "run" and rec["status"] == STATUS_OK:
            ds = extend_point(case, ds, extend, point_fn, rec)
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
            if "lubricant_name" in ds.attrs:  # the oil by its own name, and where its data come from
                rec["summary"]["lubricant_name"] = str(ds.attrs["lubricant_name"])
                rec["summary"]["lubricant_provenance"] = str(ds.attrs.get("lubricant_provenance", ""))
        except Exception as exc:  # summary of a partial/odd dataset: keep the archive, say why
            rec["summary_error"] = f"summary failed: {type(exc).__name__}: {exc}"
            rec["error"] = "; ".join(e for e in (rec["error"], rec["summary_error"]) if e)
    if keep == "answer" and ds is not None and kind == "run":
        try:
            ds = keep_answer(ds)
        except Exception as exc:  # noqa: BLE001 - keep the whole run rather than lose it
            rec["keep_error"] = f"kept whole: {type(exc).__name__}: {exc}"
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
