"""Output variables: one registry (name, dims, units, long_name) -> xarray attrs; atomic netCDF I/O.

Every variable a model writes into a result Dataset is declared once with
:func:`register` (the core names of docs/design.md are declared below; a model
module declares its own at import).  :func:`make_dataset` builds a Dataset
from plain arrays and attaches the declared attrs, so units and descriptions
are never typed twice.  :func:`write_netcdf` writes through a temporary file
in the target directory and renames it into place, so a reader (or an
interrupted run) never sees half a file.
"""

from __future__ import annotations

import contextlib
import json
import os
import tempfile
import time
from dataclasses import dataclass
from pathlib import Path
from typing import Any, Mapping

import numpy as np
import xarray as xr

from hsbearing.case.load import special_file_kind

__all__ = ["Variable", "VARIABLES", "register", "make_dataset", "write_netcdf", "open_run", "solver_attrs", "atomic_write", "sigint_held_during_netcdf_io",
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


# Core names (docs/design.md "Dataset names").  Dims listed are the dynamic ones; the quasi-static
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
    # dynamic run (hsbearing.systems.angular_contact.dynamics) and its annotation (hsbearing.analysis)
    "guide_clearance": "m", "pocket_clearance": "m", "theoretical_cage_speed_nominal": "rad/s",
    "transient_discarded": "s", "cage_slip_contact_angle": "rad",
    # extension of an undetermined run (hsbearing.systems.angular_contact.extend)
    "extension_max_duration": "s", "extension_growth_rate": "1/s",
    # solver statistics
    "solver_wall_time": "s", "solver_total_wall_time": "s", "solver_wall_time_s": "s", "solver_rtol": "1",
    "solver_atol": "SI unit of each state times its scale (hsbearing.models.ball_bearing.state.ATOL_SCALE)",
    # quasi-static equilibrium
    "inner_speed": "rad/s", "outer_speed": "rad/s", "applied_loads": "N, N, N, N m, N m (F_x, F_y, F_z, M_y, M_z)",
    # gyro bearing (Jiang et al. 2014 model)
    "contact_angle_deg": "degree", "ball_load_N": "N", "cage_mass_kg": "kg", "ball_cage_stiffness": "N/m^1.5",
    "hunt_crossley_chi": "s/m", "creep_speed": "m/s", "cage_slip_speed": "m/s", "fine_interval": "s",
    "pocket_clearance_m": "m", "oscillation_period": "s", "cage_gravity": "m/s^2", "cage_gravity_direction": "1",
    "prl_inner": "1 (fraction of the contact semi-major axis)", "prl_outer": "1 (fraction of the contact semi-major axis)",
    "start_ensemble_play_rad": "rad", "start_ensemble_duration_s": "s", "start_ensemble_wall_time_s": "s",
    # wire-race preload sweep (Shan et al. 2010 model)
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
    """Global attrs every archive carries: package version, case TOML text, status, creation time; for a Case also
    what its ``archive_attrs()`` gives (the oil's ``lubricant_name``, ``lubricant_provenance``,
    ``lubricant_notices``) and its sanity-envelope lines merged into ``warnings``."""
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
    more = case.archive_attrs() if hasattr(case, "archive_attrs") else {}  # (a Case; asked, not imported: no cycle)
    env = more.pop("envelope_warnings", [])
    attrs.update(more)  # the oil by its own name and where its data come from
    attrs.update(extra)
    if env:  # the sanity envelope (case.envelope_warnings): warned, kept in the archive
        have = [w for w in str(attrs.get("warnings", "none")).split(" | ") if w and w != "none"]
        attrs["warnings"] = " | ".join(have + [w for w in env if w not in have])
    return _clean_attrs(attrs)


def _absolute_source(source) -> str:
    """The case file as an absolute path when ``source`` names an existing file (else unchanged, e.g. ``<string>``)."""
    try:
        p = Path(str(source))
        return str(p.resolve()) if p.is_file() else str(source)
    except (OSError, ValueError):
        return str(source)


#: Prefix of every temporary file hsbearing writes next to an output (``.hsb-<8 hex of the final name>-<random>.tmp``,
#: ~26 characters): short, so a temporary name fits wherever the final name fits (NAME_MAX 255; the temporary
#: used to be ``.<name>.<random>.tmp``, 13 characters longer than the name itself).
TEMP_PREFIX = ".hsb-"


def temp_prefix(name: str) -> str:
    """The temporary-name prefix of the output file ``name`` (a hash of the name, so leftovers can be matched)."""
    import hashlib

    return f"{TEMP_PREFIX}{hashlib.sha1(name.encode('utf-8', 'surrogateescape')).hexdigest()[:8]}-"


def final_target(path: str | os.PathLike) -> Path:
    """The file a write to ``path`` replaces: ``path`` itself or, for a symbolic link (chains included, dangling
    too), the file the link points at.  Writing *through* the link keeps the link a link (docs/output.md)."""
    path = Path(path)
    if path.is_symlink():
        return Path(os.path.realpath(path))
    return path


class atomic_write:
    """Context manager yielding a temporary path next to ``path``'s final target; renamed onto it on success.

    On any exception the temporary file is removed and ``path`` is untouched, so readers (and an
    interrupted run) never see half a file.  The file gets ordinary umask permissions.  A symbolic link
    is written *through*: the temporary file goes to the directory of the link's target and is renamed onto
    the target, so the link stays a link.  A path that is a device node, FIFO or socket is refused (it
    would be replaced by a regular file): OSError.
    """

    def __init__(self, path: str | os.PathLike, suffix: str = ".tmp"):
        self.path = Path(path)
        self.suffix = suffix if len(suffix) <= 8 else ".tmp"  # a long suffix must not make the name too long

    def __enter__(self) -> Path:
        self.target = final_target(self.path)
        kind = special_file_kind(self.target)
        if kind:
            raise OSError(f"{self.path} is {kind}, not a regular file: not replaced")
        self.target.parent.mkdir(parents=True, exist_ok=True)
        fd, tmp = tempfile.mkstemp(prefix=temp_prefix(self.target.name), suffix=self.suffix, dir=self.target.parent)
        os.close(fd)
        self.tmp = Path(tmp)
        return self.tmp

    def __exit__(self, exc_type, exc, tb) -> bool:
        if exc_type is None:
            try:
                umask = os.umask(0)
                os.umask(umask)
                os.chmod(self.tmp, 0o666 & ~umask)  # mkstemp creates 0600
                kind = special_file_kind(self.target)  # became a device/FIFO meanwhile: do not replace it
                if kind:
                    raise OSError(f"{self.path} is {kind}, not a regular file: not replaced")
                os.replace(self.tmp, self.target)
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


def _name_max(directory: Path) -> int:
    try:
        return int(os.pathconf(directory, "PC_NAME_MAX"))
    except (OSError, ValueError, AttributeError):
        return 255


def check_archive_name(path) -> None:
    """Raise CaseError unless ``path`` (an ``-o`` archive; None: no archive asked) ends in ``.nc`` / ``.nc4``."""
    if path and not str(path).endswith((".nc", ".nc4")):
        from hsbearing.case import CaseError

        raise CaseError("-o", None, f"{str(path)!r}: the archive must be a .nc file")


def check_output_path(path: str | os.PathLike, *, source: str = "-o", directory: bool = False,
                      derived: tuple | list = ()) -> Path:
    """Check, before any computation, that ``path`` can be written; raise CaseError if not.

    The message reads ``<source> <path>: <reason>``.  ``directory=False``: ``path`` is a file (it may
    exist as a regular file, or a symbolic link to one, which is written through; never a directory, a
    device node, a FIFO or a socket); ``directory=True``: an output directory (it may exist, but not as a
    file).  The nearest existing ancestor must be a directory in which a file can be created: probed by
    creating and deleting a temporary file, so read-only file systems and permissions are caught even
    for root.  A file name longer than the file system allows is refused.  ``derived``: further file
    paths written from this one (``out.png`` next to ``out.nc``, ``DIR/sweep.nc``), checked the same way
    and named in the message.  Nothing is left behind.
    """
    from hsbearing.case import CaseError

    path = Path(path)
    where = f"{source} {path}"
    if not directory and (str(path) in ("", ".", "..") or path.name in ("", ".", "..")):
        raise CaseError(where, None, "not a file name")
    if "\0" in str(path):
        raise CaseError(where, None, "contains a NUL character")
    for part in path.parts:  # before any stat: a too-long component makes every os call fail
        if len(os.fsencode(part)) > 255:
            raise CaseError(where, None, f"a file name longer than 255 bytes ({len(os.fsencode(part))})")
    kind = special_file_kind(path)
    if kind:
        raise CaseError(where, None, f"is {kind}, not a regular file (refused: it would be replaced by the archive)")
    if path.exists():
        if directory and not path.is_dir():
            raise CaseError(where, None, "exists and is not a directory")
        if not directory and path.is_dir():
            raise CaseError(where, None, "is a directory (give a file name)")
    target = path if directory else final_target(path)
    anc = target if directory and target.is_dir() else target.parent
    while not anc.exists():
        if anc.is_symlink():
            raise CaseError(where, None, f"cannot be created: {anc} is a broken symbolic link")
        anc = anc.parent
    if not anc.is_dir():
        raise CaseError(where, None, f"cannot be created: {anc} is a file, not a directory")
    nmax = _name_max(anc)
    for part in (target.parts if not target.is_absolute() else target.parts[1:]):
        if len(os.fsencode(part)) > nmax:
            raise CaseError(where, None, f"a file name longer than {nmax} bytes ({len(os.fsencode(part))})")
    try:
        fd, probe = tempfile.mkstemp(prefix=".hsbearing-write-check.", dir=anc)
    except OSError as exc:
        raise CaseError(where, None, f"cannot be written: no write access to {anc} "
                                     f"({exc.strerror or type(exc).__name__})") from None
    os.close(fd)
    os.unlink(probe)
    for d in derived:
        d = Path(d)
        dwhere = f"{where} (derived output {d})"
        dkind = special_file_kind(d)
        if dkind:
            raise CaseError(dwhere, None, f"is {dkind}, not a regular file (refused: it would be replaced)")
        if d.is_dir():
            raise CaseError(dwhere, None, "is a directory: the file cannot be written")
        dt = final_target(d)
        danc = dt.parent
        while not danc.exists():
            danc = danc.parent
        if not danc.is_dir():
            raise CaseError(dwhere, None, f"cannot be created: {danc} is a file, not a directory")
        if len(os.fsencode(dt.name)) > _name_max(danc):
            raise CaseError(dwhere, None, f"a file name longer than {_name_max(danc)} bytes")
        if danc != anc and not os.access(danc, os.W_OK):
            raise CaseError(dwhere, None, f"cannot be written: no write access to {danc}")
    return path


def write_netcdf(ds: xr.Dataset, path: str | os.PathLike, *, fallback: bool = True) -> Path:
    """Write ``ds`` to ``path`` atomically (temporary file in the same directory, then rename), zlib-compressed.

    ``ds.attrs`` gains the ``NAME_units`` companions of :data:`ATTR_UNITS` it lacks (in place, so the
    Dataset in memory and the archive carry the same attributes).

    A failed write (disk full, file-size limit, directory made read-only, the target turned into a device)
    leaves ``path`` untouched and no temporary file; with ``fallback`` the Dataset is then written to
    :func:`fallback_dirs` and :class:`hsbearing.errors.OutputWriteError` says where it went.
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
    with sigint_held_during_netcdf_io():  # a Ctrl-C inside xarray's netCDF backend can leave its lock taken
        try:
            with atomic_write(path) as tmp:
                ds.to_netcdf(tmp, engine="netcdf4", format="NETCDF4", encoding=encoding)
        except (OSError, RuntimeError) as exc:  # netCDF4 reports a full disk / EFBIG as RuntimeError("NetCDF: HDF error")
            from hsbearing.errors import OutputWriteError

            reason = _write_failure_reason(exc, final_target(path).parent)
            saved = _write_fallback(ds, path, encoding) if fallback else None
            raise OutputWriteError(path, reason, saved) from None
    return path


def _write_failure_reason(exc: BaseException, directory: Path) -> str:
    import shutil

    reason = getattr(exc, "strerror", None) or str(exc) or type(exc).__name__
    try:
        import resource

        soft, _ = resource.getrlimit(resource.RLIMIT_FSIZE)
        if soft != resource.RLIM_INFINITY:
            reason += f" (file-size limit of this process, ulimit -f: {soft} bytes)"
    except (ImportError, OSError, ValueError):
        pass
    try:
        free = shutil.disk_usage(directory).free
        if free < 50e6:
            reason += f" ({free / 1e3:.0f} kB free on the file system of {directory}; disk full?)"
    except OSError:
        pass
    return reason


def fallback_dirs(path: Path) -> list[Path]:
    """Where a result goes when its own path cannot take it: the system temporary directory, then the working
    directory (each only if it is not the directory that just failed)."""
    failed = final_target(path).parent.resolve()
    out = []
    for d in (Path(tempfile.gettempdir()), Path.cwd()):
        try:
            d = d.resolve()
        except OSError:
            continue
        if d != failed and d not in out:
            out.append(d)
    return out


def _write_fallback(ds: xr.Dataset, path: Path, encoding: dict) -> Path | None:
    """Write ``ds`` to a new file ``hsbearing-rescued-<name>-<random>.nc`` in a fallback directory; its path or None."""
    stem = Path(path).stem[:60]
    for d in fallback_dirs(Path(path)):
        try:
            fd, name = tempfile.mkstemp(prefix=f"hsbearing-rescued-{stem}-", suffix=".nc", dir=d)
        except OSError:
            continue
        os.close(fd)
        try:
            ds.to_netcdf(name, engine="netcdf4", format="NETCDF4", encoding=encoding)
            return Path(name)
        except (OSError, RuntimeError):
            with contextlib.suppress(OSError):
                os.unlink(name)
    return None


@contextlib.contextmanager
def deferred_sigint():
    """Hold Ctrl-C off while the block runs: the save of a partial result after a first Ctrl-C must not be cut
    short by a second one (two Ctrl-C 0.3 s apart used to leave no archive at all).  SIGINTs received
    meanwhile are collected in the yielded list, not raised; the previous handler is restored afterwards.
    Only in the main thread (signal handlers can only be set there); elsewhere nothing changes."""
    import signal
    import threading

    got: list[int] = []
    if threading.current_thread() is not threading.main_thread():
        yield got
        return
    old = signal.signal(signal.SIGINT, lambda signum, frame: got.append(signum))
    try:
        yield got
    finally:
        signal.signal(signal.SIGINT, old)


@contextlib.contextmanager
def sigint_held_during_netcdf_io():
    """Hold Ctrl-C off during a netCDF read or write and deliver it when the I/O has ended.

    xarray's netCDF backend takes a combination of locks (netCDF-C's, HDF5's and, for a write, the file's:
    ``xarray.backends.locks.CombinedLock``) one after the other in a Python loop.  A KeyboardInterrupt raised by
    the SIGINT handler between that loop's acquisitions and the ``with`` statement that owns them leaves the locks
    taken; ``to_netcdf``'s ``finally: store.close()`` (or the ``with open_dataset(...)`` exit) then waits for them
    forever.  Seen once in about 150 interrupted commands (the Ctrl-C campaign, tests/cli/test_ctrl_c_anytime.py:
    a ``quasistatic`` blocked in ``xarray.backends.locks.acquire`` under ``write_netcdf``); reproduced
    deterministically in tests/test_netcdf_interrupt.py.  So no KeyboardInterrupt is raised inside: a SIGINT
    received meanwhile is handed to the previous handler once the block has ended (``signal.default_int_handler``:
    a KeyboardInterrupt there; the collector of :func:`deferred_sigint`: one more collected Ctrl-C), whether the
    block ended normally or by an exception.  A write that completes is kept (complete archive, then the
    interrupt).  Only in the main thread (signal handlers can only be set there, and only it receives
    KeyboardInterrupt); elsewhere nothing changes."""
    import signal
    import threading

    if threading.current_thread() is not threading.main_thread():
        yield
        return
    got: list[int] = []
    old = signal.signal(signal.SIGINT, lambda signum, frame: got.append(signum))
    try:
        yield
    finally:
        signal.signal(signal.SIGINT, old)
        if got:
            if callable(old):
                old(signal.SIGINT, None)
            elif old == signal.SIG_DFL:
                os.kill(os.getpid(), signal.SIGINT)


def open_run(path: str | os.PathLike) -> xr.Dataset:
    """Open an archive written by hsbearing, loaded into memory (the file is closed).

    Raises :class:`hsbearing.case.CaseError` naming the file for anything that is not an hsbearing archive:
    a missing or unreadable file, a file that is not netCDF, and a netCDF file that some other program wrote
    (every hsbearing archive carries the attributes of :func:`standard_attrs`: ``hsbearing_version`` and a
    ``title`` beginning with "hsbearing") or that holds no variable although its status is ``ok`` (the archive of a
    sweep point that failed before producing data keeps its failure status and message only, and is read).
    """
    from hsbearing.case import CaseError

    name = str(path)
    if not Path(path).is_file():
        raise CaseError(name, None, "no such archive" if not Path(path).exists() else "not a file")
    try:
        with sigint_held_during_netcdf_io(), xr.open_dataset(path, engine="netcdf4") as ds:
            ds = ds.load()
    except Exception as exc:  # noqa: BLE001 - any netCDF/HDF failure means: not an archive we can read
        raise CaseError(name, None, f"not a readable netCDF archive ({type(exc).__name__})") from None
    if not is_hsbearing_archive(ds):
        raise CaseError(name, None, "not an hsbearing archive: a netCDF file without the attributes every hsbearing "
                                    "archive carries (hsbearing_version, title 'hsbearing ...')")
    if not ds.data_vars and str(ds.attrs.get("status", "ok")) == "ok":  # a failed point keeps its status only
        raise CaseError(name, None, "an hsbearing archive with no variables: nothing to read")
    return ds


def is_hsbearing_archive(ds: xr.Dataset) -> bool:
    """True if ``ds`` carries the global attributes :func:`standard_attrs` gives every hsbearing archive."""
    return "hsbearing_version" in ds.attrs and str(ds.attrs.get("title", "")).startswith("hsbearing")
