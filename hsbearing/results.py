"""Output variables: one registry (name, dims, units, long_name) -> xarray attrs; atomic netCDF I/O.

Every variable a model writes into a result Dataset is declared once with
:func:`register` (the core names of DESIGN.md are declared below; a model
module declares its own at import).  :func:`make_dataset` builds a Dataset
from plain arrays and attaches the declared attrs, so units and descriptions
are never typed twice.  :func:`write_netcdf` writes through a temporary file
in the target directory and renames it into place, so a reader (or an
interrupted run) never sees half a file.
"""

from __future__ import annotations

import json
import os
import tempfile
import time
from dataclasses import dataclass
from pathlib import Path
from typing import Any, Mapping

import numpy as np
import xarray as xr

__all__ = ["Variable", "VARIABLES", "register", "make_dataset", "write_netcdf", "open_run", "solver_attrs", "atomic_write",
           "ATTR_UNITS", "register_attr_units", "with_attr_units", "check_output_path"]


@dataclass(frozen=True)
class Variable:
    name: str
    dims: tuple[str, ...]
    units: str
    long_name: str


VARIABLES: dict[str, Variable] = {}


def register(name: str, dims: tuple[str, ...] | str, units: str, long_name: str) -> Variable:
    """Declare an output variable.  Re-declaring with different metadata is an error."""
    if isinstance(dims, str):
        dims = (dims,) if dims else ()
    var = Variable(name, tuple(dims), units, long_name)
    old = VARIABLES.get(name)
    if old is not None and old != var:
        raise ValueError(f"output variable {name!r} declared twice with different metadata: {old} vs {var}")
    VARIABLES[name] = var
    return var


# Core names (DESIGN.md "Dataset names").  Dims listed are the dynamic ones; the quasi-static
# dataset uses the same names without ``time`` (make_dataset drops missing dims).
for _n, _d, _u, _l in [
    ("time", ("time",), "s", "simulated time"),
    ("ball", ("ball",), "1", "ball index"),
    ("inner_contact_load", ("time", "ball"), "N", "normal load at the ball-inner race contact Q_i"),
    ("outer_contact_load", ("time", "ball"), "N", "normal load at the ball-outer race contact Q_o"),
    ("inner_contact_angle", ("time", "ball"), "rad", "contact angle at the inner race alpha_i"),
    ("outer_contact_angle", ("time", "ball"), "rad", "contact angle at the outer race alpha_o"),
    ("cage_speed", ("time",), "rad/s", "cage angular speed about the bearing axis omega_c"),
    ("cage_slip_ratio", ("time",), "1", "cage slip ratio (omega_c,th - omega_c)/omega_c,th, epicyclic speed at the nominal contact angle"),
    ("cage_center_y", ("time",), "m", "cage mass-centre displacement along Y"),
    ("cage_center_z", ("time",), "m", "cage mass-centre displacement along Z"),
    ("ball_orbit_speed", ("time", "ball"), "rad/s", "ball orbital (revolution) speed about the bearing axis"),
    ("ball_spin_speed", ("time", "ball"), "rad/s", "magnitude of the ball angular velocity relative to the orbiting (cage) frame, omega_R"),
    ("inner_ring_axial_displacement", ("time",), "m", "inner-ring displacement along the bearing axis X"),
    # label coordinates of the quasi-static stiffness matrix (rows dof, columns dof2); text, so no units
    ("dof", ("dof",), "", "inner-ring degree of freedom of a stiffness row: x (axial), y, z (radial) displacement, "
                          "theta_y, theta_z tilt"),
    ("dof2", ("dof2",), "", "inner-ring degree of freedom of a stiffness column (same labels as dof)"),
]:
    register(_n, _d, _u, _l)


#: Units of the global attributes that carry a dimension.  An archive written by :func:`write_netcdf`
#: stores, next to each such attribute ``NAME`` present, a companion attribute ``NAME_units`` (netCDF
#: global attributes have no attributes of their own; CF has no convention for them).  Attributes not
#: listed here are texts, counts or dimensionless numbers.  Declare new ones with :func:`register_attr_units`.
ATTR_UNITS: dict[str, str] = {
    # dynamic run (hsbearing.dynamics) and its annotation (hsbearing.analysis)
    "guide_clearance": "m", "pocket_clearance": "m", "theoretical_cage_speed_nominal": "rad/s",
    "transient_discarded": "s", "cage_slip_contact_angle": "rad",
    # solver statistics
    "solver_wall_time": "s", "solver_total_wall_time": "s", "solver_wall_time_s": "s", "solver_rtol": "1",
    "solver_atol": "SI unit of each state times its scale (hsbearing.models.state.ATOL_SCALE)",
    # quasi-static equilibrium
    "inner_speed": "rad/s", "outer_speed": "rad/s", "applied_loads": "N, N, N, N m, N m (F_x, F_y, F_z, M_y, M_z)",
    # gyro bearing (seed 000 model)
    "contact_angle_deg": "degree", "ball_load_N": "N", "cage_mass_kg": "kg", "ball_cage_stiffness": "N/m^1.5",
    "hunt_crossley_chi": "s/m", "creep_speed": "m/s", "cage_slip_speed": "m/s", "fine_interval": "s",
    "pocket_clearance_m": "m", "oscillation_period": "s", "cage_gravity": "m/s^2", "cage_gravity_direction": "1",
    "prl_inner": "1 (fraction of the contact semi-major axis)", "prl_outer": "1 (fraction of the contact semi-major axis)",
    "start_ensemble_play_rad": "rad", "start_ensemble_duration_s": "s", "start_ensemble_wall_time_s": "s",
    # wire-race preload sweep (seed 001 model)
    "rolling_resistance": "m", "unconsidered_torque": "N m", "framework_weight": "N", "contact_angle": "rad",
    "target_torque": "N m", "preload_window": "m",
    # friction torque
    "kinematic_viscosity_mm2_s": "mm^2/s",
    # sweeps and studies
    "sweep_wall_time": "s", "sweep_duration": "s",
}


def register_attr_units(name: str, units: str) -> None:
    """Declare the unit of a global attribute ``name`` (see :data:`ATTR_UNITS`)."""
    old = ATTR_UNITS.get(name)
    if old is not None and old != units:
        raise ValueError(f"global attribute {name!r} declared with units {old!r} and {units!r}")
    ATTR_UNITS[name] = units


def with_attr_units(attrs: Mapping[str, Any]) -> dict[str, Any]:
    """``attrs`` plus ``NAME_units`` for every attribute of :data:`ATTR_UNITS` present (existing companions kept)."""
    out = dict(attrs)
    for name, units in ATTR_UNITS.items():
        if name in attrs and f"{name}_units" not in attrs:
            out[f"{name}_units"] = units
    return out


def make_dataset(
    data: Mapping[str, Any],
    coords: Mapping[str, Any] | None = None,
    attrs: Mapping[str, Any] | None = None,
) -> xr.Dataset:
    """Dataset from ``{name: array}`` using the registry for dims and attrs.

    A registered variable whose array has fewer dimensions than declared
    drops the leading declared dims it lacks (so ``("time", "ball")`` becomes
    ``("ball",)`` for a quasi-static result).  Unregistered names raise.
    """
    vars_ = {}
    for name, value in data.items():
        if name not in VARIABLES:
            raise KeyError(f"output variable {name!r} is not registered in hsbearing.results")
        v = VARIABLES[name]
        arr = np.asarray(value)
        dims = v.dims[len(v.dims) - arr.ndim :] if arr.ndim <= len(v.dims) else None
        if dims is None:
            raise ValueError(f"{name}: array has {arr.ndim} dims, declared {v.dims}")
        vars_[name] = xr.Variable(dims, arr, attrs=_var_attrs(v))
    ds = xr.Dataset(vars_)
    for cname, cval in (coords or {}).items():
        c_attrs = _var_attrs(VARIABLES[cname]) if cname in VARIABLES else {}
        ds = ds.assign_coords({cname: xr.Variable((cname,), np.asarray(cval), attrs=c_attrs)})
    ds.attrs.update(_clean_attrs(with_attr_units(attrs or {})))
    return ds


def _var_attrs(v: Variable) -> dict[str, str]:
    """``units`` (omitted for a text/label variable declared with units "") and ``long_name``."""
    return {"units": v.units, "long_name": v.long_name} if v.units else {"long_name": v.long_name}


def solver_attrs(stats: Mapping[str, Any]) -> dict[str, Any]:
    """Solver statistics as flat ``solver_*`` global attrs."""
    return {f"solver_{k}": v for k, v in stats.items()}


def _clean_attrs(attrs: Mapping[str, Any]) -> dict[str, Any]:
    out = {}
    for k, v in attrs.items():
        if v is None:
            continue
        if isinstance(v, bool):
            v = int(v)
        elif isinstance(v, (dict, list, tuple)) and not (isinstance(v, (list, tuple)) and all(isinstance(x, (int, float)) for x in v)):
            v = json.dumps(v)
        elif isinstance(v, np.generic):
            v = v.item()
        out[k] = v
    return out


def standard_attrs(case=None, status: str = "ok", **extra) -> dict[str, Any]:
    """Global attrs every archive carries: package version, case TOML text, status, creation time."""
    from hsbearing._version import __version__

    attrs: dict[str, Any] = {
        "Conventions": "CF-1.8",
        "title": "hsbearing result",
        "hsbearing_version": __version__,
        "status": status,
        "created": time.strftime("%Y-%m-%dT%H:%M:%SZ", time.gmtime()),
    }
    if case is not None:
        attrs["case_name"] = case.name
        attrs["case_system"] = case.system
        attrs["case_toml"] = case.to_toml()
        attrs["case_source"] = _absolute_source(case.source)
    attrs.update(extra)
    return _clean_attrs(attrs)


def _absolute_source(source) -> str:
    """The case file as an absolute path when ``source`` names an existing file (else unchanged, e.g. ``<string>``)."""
    try:
        p = Path(str(source))
        return str(p.resolve()) if p.is_file() else str(source)
    except (OSError, ValueError):
        return str(source)


class atomic_write:
    """Context manager yielding a temporary path next to ``path``; renamed onto ``path`` on success.

    On any exception the temporary file is removed and ``path`` is untouched, so readers (and an
    interrupted run) never see half a file.  The file gets ordinary umask permissions.
    """

    def __init__(self, path: str | os.PathLike, suffix: str = ".tmp"):
        self.path = Path(path)
        self.suffix = suffix

    def __enter__(self) -> Path:
        self.path.parent.mkdir(parents=True, exist_ok=True)
        fd, tmp = tempfile.mkstemp(prefix=f".{self.path.name}.", suffix=self.suffix, dir=self.path.parent)
        os.close(fd)
        self.tmp = Path(tmp)
        return self.tmp

    def __exit__(self, exc_type, exc, tb) -> bool:
        if exc_type is None:
            try:
                umask = os.umask(0)
                os.umask(umask)
                os.chmod(self.tmp, 0o666 & ~umask)  # mkstemp creates 0600
                os.replace(self.tmp, self.path)
            except BaseException:  # e.g. the target is a directory: no temporary file left behind
                self._discard()
                raise
        else:
            self._discard()
        return False

    def _discard(self) -> None:
        try:
            os.unlink(self.tmp)
        except FileNotFoundError:
            pass


def check_output_path(path: str | os.PathLike, *, source: str = "-o", directory: bool = False) -> Path:
    """Check, before any computation, that ``path`` can be written; raise CaseError if not.

    The message reads ``<source> <path>: <reason>``.  ``directory=False``: ``path`` is a file (it may
    exist, but not as a directory); ``directory=True``: an output directory (it may exist, but not as a
    file).  The nearest existing ancestor must be a directory in which a file can be created: probed by
    creating and deleting a temporary file, so read-only file systems and permissions are caught even
    for root.  Nothing is left behind.
    """
    from hsbearing.case import CaseError

    path = Path(path)
    where = f"{source} {path}"
    if not directory and (str(path) in ("", ".", "..") or path.name in ("", ".", "..")):
        raise CaseError(where, None, "not a file name")
    if path.exists():
        if directory and not path.is_dir():
            raise CaseError(where, None, "exists and is not a directory")
        if not directory and path.is_dir():
            raise CaseError(where, None, "is a directory (give a file name)")
    anc = path if directory and path.is_dir() else path.parent
    while not anc.exists():
        if anc.is_symlink():
            raise CaseError(where, None, f"cannot be created: {anc} is a broken symbolic link")
        anc = anc.parent
    if not anc.is_dir():
        raise CaseError(where, None, f"cannot be created: {anc} is a file, not a directory")
    try:
        fd, probe = tempfile.mkstemp(prefix=".hsbearing-write-check.", dir=anc)
    except OSError as exc:
        raise CaseError(where, None, f"cannot be written: no write access to {anc} "
                                     f"({exc.strerror or type(exc).__name__})") from None
    os.close(fd)
    os.unlink(probe)
    return path


def write_netcdf(ds: xr.Dataset, path: str | os.PathLike) -> Path:
    """Write ``ds`` to ``path`` atomically (temporary file in the same directory, then rename), zlib-compressed.

    ``ds.attrs`` gains the ``NAME_units`` companions of :data:`ATTR_UNITS` it lacks (in place, so the
    Dataset in memory and the archive carry the same attributes).
    """
    path = Path(path)
    for k, v in with_attr_units(ds.attrs).items():  # the unit companions (ATTR_UNITS) also on the caller's Dataset,
        ds.attrs.setdefault(k, v)                     # so that what is written is what is in memory
    ds = ds.copy()
    ds.attrs = _clean_attrs(ds.attrs)
    # fletcher32: an HDF5 checksum per chunk, so a corrupted archive fails on read instead of
    # returning wrong numbers (a sweep resume reads every point's data through it)
    encoding = {
        name: {"zlib": True, "complevel": 4, "shuffle": True, "fletcher32": True}
        for name, var in ds.variables.items()
        if var.dtype.kind in "fiub" and var.ndim > 0
    }
    with atomic_write(path) as tmp:
        ds.to_netcdf(tmp, engine="netcdf4", format="NETCDF4", encoding=encoding)
    return path


def open_run(path: str | os.PathLike) -> xr.Dataset:
    """Open an archive written by hsbearing, loaded into memory (the file is closed)."""
    with xr.open_dataset(path, engine="netcdf4") as ds:
        return ds.load()
