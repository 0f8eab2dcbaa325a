"""The wire-race bearing (Shan et al. 2010): starting torque against preload (``hsbearing preload``,
:mod:`hsbearing.systems.wire_race.model`), its figure (:mod:`hsbearing.systems.wire_race.figures`); the
closed forms are :mod:`hsbearing.models.friction.wire_race`.  No dynamic model."""

from __future__ import annotations

import numpy as np

from hsbearing.systems.base import System

__all__ = ["SYSTEM", "friction_command", "preload_command", "archive_kind"]


def friction_command(case, args) -> int:
    """``hsbearing friction CASE``: the Shan et al. 2010 starting torque at the case preload."""
    from hsbearing.errors import CaseError
    from hsbearing.results import write_netcdf

    out = getattr(args, "output", None)
    from hsbearing.systems.wire_race import model as wire_race

    delta = case.operating.preload
    if delta is None:
        raise CaseError(case.source, "operating.preload", "the starting torque needs the preload")
    ds = wire_race.preload_sweep(case, np.array([delta]))
    print(f"case {case.name}: wire-race bearing, starting torque at the case preload (Shan et al. 2010 Eqs. 4, 11)")
    for line in wire_race._format_table(ds):
        print(line)
    print(f"note: preload sweep and target window: hsbearing preload {case.name}")
    from hsbearing.models.limits import ISO76_BALL_PRESSURE

    top = max(float(np.nanmax(ds[f"p_max{j}"].values)) for j in range(1, 5) if f"p_max{j}" in ds)
    if top > ISO76_BALL_PRESSURE:
        w = (f"maximum contact pressure {top * 1e-9:.3g} GPa exceeds the {ISO76_BALL_PRESSURE * 1e-9:g} GPa of ISO 76:2006 "
             "(static load rating of ball bearings): the raceways deform permanently")
        ds.attrs["warnings"] = w
        print(f"warning: {w}")
    if out:
        write_netcdf(ds, out)
        print(f"archive: {out}")
    return 0


def preload_command(case, args) -> int:
    """``hsbearing preload CASE``: starting torque over preloads, optional preload window."""
    from hsbearing.systems.wire_race.model import preload_command as run

    return run(case, args)


def archive_kind(ds) -> str | None:
    """``"preload"``: an ``hsbearing preload`` archive (dim ``preload``) or any archive of a wire-race case."""
    return "preload" if "preload" in ds.dims or ds.attrs.get("case_system") == SYSTEM.name else None


def _plot_preload(ds, path):
    from hsbearing.systems.wire_race.figures import plot_preload

    return plot_preload(ds, path)


def _register_outputs():
    import hsbearing.systems.wire_race.model  # noqa: F401 - declares the preload variables


SYSTEM = System(
    name="wire_race",
    description="wire-race bearing: preload vs starting torque (Shan et al. 2010)",
    friction=friction_command, archive_kind=archive_kind, figures={"preload": _plot_preload},
    register_outputs=_register_outputs,
)
