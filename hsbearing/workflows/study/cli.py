"""``hsbearing study``: run a bundled study (or a study file) and print where its tables and report are."""

from __future__ import annotations

import sys
from pathlib import Path
from typing import Callable

from hsbearing.case import CaseError
from hsbearing.workflows import sweeps
from hsbearing.workflows.study.execute import run_study as _run_study
from hsbearing.workflows.study.spec import BANDS_SUFFIX, STATUS_MISSING


def cli_main(args, run_study: Callable | None = None) -> int:
    """``hsbearing study NAME -o DIR [--bands [--band-samples K] | --no-bands] [--table ID ...] [-j N]
    [--scheduler ADDR] [--duration 0.05s]``.

    Exit 0 when every point completed, 1 when some did not (the report lists
    them), 2 on bad input.  ``run_study``: the function that runs the study (default
    :func:`hsbearing.workflows.study.execute.run_study`; ``hsbearing study`` passes ``hsbearing.workflows.study.run_study``).
    """
    out = Path(args.output)
    if out.exists() and not out.is_dir():
        raise CaseError(str(out), None, "output must be a directory")
    bands = bool(getattr(args, "bands", False))
    limit = getattr(args, "band_samples", None)
    if limit is not None and not bands:
        raise CaseError("--band-samples", None, "only with --bands")
    from hsbearing.workflows.maps import extend_arg

    extend = extend_arg(args)
    res = (run_study or _run_study)(args.name, out, jobs=args.jobs, scheduler=args.scheduler, duration=args.duration,
                                    progress=not getattr(args, "quiet", False), bands=bands, band_samples_limit=limit,
                                    tables=getattr(args, "tables", None),
                                    report_only=bool(getattr(args, "report_only", False)),
                                    stop=getattr(args, "stop", None), keep=getattr(args, "keep", "answer"),
                                    extend=extend)
    n_bad = sum(int(((ds["status"] != sweeps.STATUS_OK) & (ds["status"] != STATUS_MISSING)).sum())
                for ds in res["tables"].values())
    print(f"study {args.name}{' (bands)' if bands else ''}: {res['n_unique_points']} distinct points, "
          f"{res['n_computed']} computed, wall time {res['wall_time']:.1f} s ({res['backend']})")
    for tid in res["tables"]:
        print(f"table: {out / (tid + (BANDS_SUFFIX if bands else '') + '.nc')}")
    print(f"report: {res['report']}")
    if n_bad:
        print(f"hsbearing: {n_bad} table cells did not complete (see the report)", file=sys.stderr)
        return 1
    return 0

