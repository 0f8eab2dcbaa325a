"""Point archives: completeness, resume (a record read back only under its own point hash), temporaries and the directory lock that keeps two sweeps out of one directory."""

from __future__ import annotations

import contextlib
import glob
import json
import os
from pathlib import Path
from typing import Iterable

import xarray as xr

from hsbearing.case import (
    CaseError,
)
from hsbearing.results import sigint_held_during_netcdf_io, write_netcdf
from hsbearing.workflows.sweeps.plan import LOCK_NAME, Point, SweepPlan
from hsbearing.workflows.sweeps.points import point_summary, scalar_value

# ----------------------------------------------------------------------------- archives


def archive_is_complete(path: str | os.PathLike) -> bool:
    """True if ``path`` opens as netCDF, carries the ``status`` attribute and every variable's data reads
    back (HDF5 checksums and zlib streams verified: a corrupted archive is not complete)."""
    try:
        with sigint_held_during_netcdf_io(), xr.open_dataset(path, engine="netcdf4") as ds:
            if "status" not in ds.attrs:
                return False
            ds.load()
            return True
    except Exception:
        return False


def read_record(path: Path, expected_hash: str | None = None) -> dict | None:
    """The sweep record of a point archive, or None if it is not a complete, readable archive.

    The whole archive is read (``load``), not only its header: bytes corrupted inside a data chunk fail
    the chunk's checksum (``fletcher32``, :func:`hsbearing.results.write_netcdf`) or its zlib stream here,
    so a resumed sweep recomputes the point instead of trusting it.

    ``expected_hash``: the point's identity (:func:`point_hash`); an archive whose own ``sweep_point_hash``
    differs (another point's archive copied over this name, a stale file) or is missing is not this point's
    result: None, so the point is recomputed.
    """
    try:
        with sigint_held_during_netcdf_io(), xr.open_dataset(path, engine="netcdf4") as ds:
            if "status" not in ds.attrs:
                return None
            if expected_hash is not None and str(ds.attrs.get("sweep_point_hash", "")) != expected_hash:
                return None
            ds = ds.load()
            rec = json.loads(ds.attrs["sweep_record"]) if "sweep_record" in ds.attrs else None
            if rec is None:  # an archive written by something else
                rec = {"status": str(ds.attrs["status"]), "error": str(ds.attrs.get("error", "")),
                       "wall_time": float("nan"), "summary_error": "no summary stored"}
            rec["kept"] = str(ds.attrs.get("keep", "full"))  # what the archive keeps (points.keep_answer)
            from hsbearing.analysis.orbit import classified_by_older_rules

            stale = ds.attrs.get("sweep_kind", "run") == "run" and "time" in ds.dims and classified_by_older_rules(ds)
            if stale:  # classified by older rules: re-read with the current classifier (the run is kept)
                rec["summary_error"] = "classified by an older classifier version"
            if rec.get("summary_error"):  # summarise again (the analysis may have been fixed since)
                kind = ds.attrs.get("sweep_kind", "run")
                try:
                    summ = point_summary(kind, ds)
                    rec["summary"] = {k: scalar_value(v) for k, v in summ.items()}
                    rec["error"] = "; ".join(e for e in rec.get("error", "").split("; ")
                                             if e and not e.startswith("summary failed") and e != rec["summary_error"])
                    rec.pop("summary_error")
                except Exception as exc:
                    rec["summary_error"] = f"summary failed: {type(exc).__name__}: {exc}"
            return rec
    except Exception:
        return None


def write_point_archive(ds: xr.Dataset, rec: dict, path: Path, plan: SweepPlan, point: Point) -> None:
    ds = ds.copy()
    ds.attrs["sweep_kind"] = plan.kind
    ds.attrs["sweep_duration"] = "" if plan.duration is None else plan.duration
    ds.attrs["sweep_point_hash"] = point.hash
    ds.attrs["sweep_overrides"] = json.dumps(point.overrides)
    if "case_toml" not in ds.attrs and point.case is not None:
        ds.attrs["case_toml"] = point.case.to_toml()
    ds.attrs["sweep_record"] = json.dumps({k: v for k, v in rec.items()}, default=str)
    ds.attrs.setdefault("status", rec["status"])
    write_netcdf(ds, path)


def clean_temporaries(archive_dir: Path, names: Iterable[str]) -> list[Path]:
    """Delete leftover temporary files of this sweep's archives (interrupted writes): ``.hsb-<hash of the
    name>-*.tmp`` (:func:`hsbearing.results.temp_prefix`) and the older ``.<name>.*.tmp``."""
    from hsbearing.results import temp_prefix

    removed = []
    for name in set(names):
        for p in [*archive_dir.glob(f"{temp_prefix(name)}*.tmp"), *archive_dir.glob(f".{glob.escape(name)}.*.tmp")]:
            with contextlib.suppress(FileNotFoundError):
                p.unlink()
                removed.append(p)
    return removed


@contextlib.contextmanager
def dir_lock(directory: Path):
    """Exclusive advisory lock on DIR (released by the OS if the process dies)."""
    directory.mkdir(parents=True, exist_ok=True)
    try:
        import fcntl
    except ImportError:  # pragma: no cover - not POSIX: no lock
        yield
        return
    path = directory / LOCK_NAME
    while True:
        fh = open(path, "a+")
        try:
            fcntl.flock(fh, fcntl.LOCK_EX | fcntl.LOCK_NB)
        except OSError:
            fh.close()
            raise CaseError(str(directory), None, "another hsbearing sweep is running in this directory") from None
        try:  # the file we locked must still be the one at the path (a finishing sweep unlinks it)
            same = os.fstat(fh.fileno()).st_ino == os.stat(path).st_ino
        except FileNotFoundError:
            same = False
        if same:
            break
        fh.close()
    try:
        yield
    finally:
        with contextlib.suppress(OSError):  # no empty lock file left behind; unlinked while still held
            os.unlink(path)
        fh.close()
