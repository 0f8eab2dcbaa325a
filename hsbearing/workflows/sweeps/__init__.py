"""Sweeps: many independent runs over varied case keys, in parallel, resumable, archived.

``run_sweep(case, {"axial_load": "100,500,1000N", "oil": ["4109", "4106"]}, out_dir="DIR")``
builds the Cartesian product (or, with ``zip=True``, the zipped lists) of
case overrides.  Every point is an independent run (``kind="run"``:
:func:`hsbearing.simulate`; ``kind="quasistatic"``: :func:`hsbearing.quasi_static`; ``kind="thermal"``:
the steady thermal network at its power loss, :func:`hsbearing.systems.angular_contact.thermal.thermal_equilibrium`)
archived as its own netCDF file ``DIR/<case>-<hash>.nc``, where the hash is
taken over the point's full case TOML, the kind, the duration and the
point function.  ``DIR/sweep.nc`` is one Dataset with a dimension per varied
key (``point`` for zipped lists) holding each point's summary plus
``status``, ``error``, ``wall_time``, ``archive`` and ``resumed``.

Execution
---------
* ``jobs`` local worker processes (``spawn`` context; default
  ``os.cpu_count()``); ``jobs=1`` runs in the calling process.
* ``scheduler="tcp://host:port"``: the same tasks are submitted to an
  existing dask.distributed cluster.  Workers return the result Dataset to
  the client; only the client writes files (no shared file system needed).

Fault tolerance
---------------
* A point whose overrides make an invalid case (:class:`CaseError`) is
  recorded with status ``invalid`` and its message; nothing is computed.
* A :class:`SolverError` is recorded with status ``failed``; its partial
  Dataset (or, without one, an empty Dataset carrying the status) is archived.
* Any other exception in a point: status ``error`` (not archived: retried
  on the next run).
* A point that kills its worker process (segfault, OOM kill): the points
  that were running in the broken pool are re-run one at a time in a fresh
  single-worker pool, so the culprit is identified exactly and recorded as
  ``crashed``; the others complete normally.  On dask the same: tasks that
  end as ``KilledWorker`` are resubmitted one at a time, and the one that
  kills its worker again is ``crashed``.
* Resume: a point whose archive exists and is complete (opens, has the
  ``status`` attribute) is not recomputed; its record is read back from the
  archive.  Archives are written atomically by
  :func:`hsbearing.results.write_netcdf`, so an interrupted sweep leaves
  only complete archives plus, at worst, hidden temporary files
  ``.<name>.nc.*.tmp`` which the next run of the same sweep deletes (a lock
  file ``DIR/.hsbearing-sweep.lock`` keeps two sweeps out of one directory,
  so those temporaries cannot belong to a live writer).

The package by concern: ``plan`` (values of a varied key, the points and their hashes, the summary variables), ``points`` (one point, computed in a worker, and its summary), ``archives`` (point archives, resume, the directory lock), ``backends`` (serial, local process pool, dask.distributed; Ctrl-C), ``execute`` (run the plan, assemble ``sweep.nc``, :func:`run_sweep`), ``cli`` (the printed table and ``hsbearing sweep``).
"""

from __future__ import annotations

from hsbearing.workflows.sweeps.archives import (  # noqa: F401
    archive_is_complete,
    clean_temporaries,
    dir_lock,
    read_record,
    write_point_archive,
)
from hsbearing.workflows.sweeps.backends import (  # noqa: F401
    DaskBackend,
    LocalPoolBackend,
    SerialBackend,
    check_scheduler_address,
    deferred_sweep_sigint,
    make_backend,
    mp_context,
    unguarded_main_call,
)
from hsbearing.workflows.sweeps.cli import cli_base_case, cli_main, print_table  # noqa: F401
from hsbearing.workflows.sweeps.execute import assemble, execute, run_sweep  # noqa: F401
from hsbearing.workflows.sweeps.plan import (  # noqa: F401
    KINDS,
    LOCK_NAME,
    RECORD_VARS,
    STATUS_OK,
    Axis,
    Point,
    SweepPlan,
    fn_name,
    key_field,
    parse_values,
    plan_sweep,
    point_hash,
    zip_,
)
from hsbearing.workflows.sweeps.points import (  # noqa: F401
    THERMAL_SUMMARY,
    compute_point,
    dynamic_summary,
    point_summary,
    quasistatic_summary,
    scalar_value,
    thermal_summary,
    worker_init,
)

__all__ = [
    "run_sweep",
    "plan_sweep",
    "execute",
    "assemble",
    "parse_values",
    "point_hash",
    "archive_is_complete",
    "quasistatic_summary",
    "dynamic_summary",
    "cli_main",
    "check_scheduler_address",
    "unguarded_main_call",
    "SweepPlan",
    "Point",
    "STATUS_OK",
]
