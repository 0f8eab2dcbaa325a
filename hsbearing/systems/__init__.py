"""Bearing systems: one package per ``[case] system``, each a peer with the same small interface.

A system package exposes ``SYSTEM``, a :class:`System`:

- ``simulate(case, duration=None, progress=False, **kw) -> xarray.Dataset``: the dynamic run (None: the system
  has no dynamic model);
- ``build_model(case)``: the model object of that run (``y0``, ``rhs``, ``state_names``);
- ``summary_lines(ds) -> list[str]``: lines the CLI prints after the scalars of one of its runs;
- ``run_summary(ds) -> dict``: the scalars of one run for a sweep or study table;
- ``extend(ds, max_duration, **kw) -> xarray.Dataset``: continue an undetermined run until it is determined or a
  budget is spent (None: its runs are not extended; ``hsbearing map`` / ``study`` leave them as they are);
- ``friction(case, args) -> int``: ``hsbearing friction CASE`` of a case of this system (``friction_archive``:
  whether it writes ``-o OUT.nc``);
- ``archive_kind(ds) -> str | None``: the kind of an archive of this system that it draws (None: not its own);
- ``figures``: ``{kind: function(ds, path) -> Path}``, the figure of each kind of archive it draws;
- ``register_outputs()``: declares the variables its runs write (units, long_name) in this process.

:data:`SYSTEMS` maps every name of ``case.SYSTEMS`` to its System; the CLI, :func:`hsbearing.simulate`,
the sweeps and ``hsbearing plot`` go through :func:`get` / :func:`for_archive`, never by comparing names.
To add a system: docs/adding_a_system.md.
"""

from __future__ import annotations

from pathlib import Path
from typing import Callable

from hsbearing.errors import CaseError
from hsbearing.plotting import is_sweep_summary, plot_sweep
from hsbearing.systems.base import System

__all__ = ["System", "SYSTEMS", "get", "for_archive", "simulate", "figure_functions", "archive_kind", "plot_run"]


def _load() -> dict[str, System]:
    from hsbearing.systems import angular_contact, deep_groove, gyro, wire_race

    return {s.SYSTEM.name: s.SYSTEM for s in (angular_contact, deep_groove, gyro, wire_race)}


SYSTEMS: dict[str, System] = _load()


def get(case_or_name) -> System:
    """The System of a case (its ``[case] system``) or of a system name; CaseError for an unknown name."""
    name = case_or_name if isinstance(case_or_name, str) else case_or_name.system
    try:
        return SYSTEMS[name]
    except KeyError:
        source = getattr(case_or_name, "source", "case")
        raise CaseError(source, "case.system", f"unknown system {name!r} (known: {', '.join(SYSTEMS)})") from None


def for_archive(ds) -> System | None:
    """The System that wrote an archive (``attrs["case_system"]``), or None when it says none we know."""
    return SYSTEMS.get(str(ds.attrs.get("case_system", "")))


def simulate(case, duration=None, *, progress: bool = False, **kwargs):
    """The dynamic run of the case's system (:attr:`System.simulate`); CaseError if it has none."""
    system = get(case)
    if system.simulate is None:
        raise CaseError(case.source, "case.system",
                        f"system {case.system!r} has no dynamic model (use 'hsbearing preload')")
    return system.simulate(case, duration=duration, progress=progress, **kwargs)


def figure_functions() -> dict[str, Callable]:
    """``{archive kind: figure function}`` over every system (a kind is drawn by the first system declaring it)."""
    out: dict[str, Callable] = {}
    for s in SYSTEMS.values():
        for kind, fn in s.figures.items():
            out.setdefault(kind, fn)
    return out


def plot_run(ds, path) -> Path:
    """Draw the figure of a result Dataset to ``path`` (PNG) and return the path.

    See the module docstring for the dispatch.  A dynamic run that was not
    annotated is annotated first (:func:`hsbearing.analysis.annotate`, with the
    case re-read from ``attrs["case_toml"]``) so the figure shows the slip
    ratio, the Poincare map and the classification.
    """
    path = Path(path)
    kind = archive_kind(ds)
    if kind == "sweep":
        return plot_sweep(ds, path)
    return figure_functions()[kind](ds, path)


def archive_kind(ds) -> str:
    """What an hsbearing Dataset holds: ``"sweep"``, ``"gyro"``, ``"friction"``, ``"preload"``,
    ``"quasistatic"`` or ``"run"`` (see the module docstring).

    Decided from the attributes every archive carries (``title``, ``model``, ``case_system``) and
    the dimensions / variables, so archives written before this function existed are recognised too.
    Raises :class:`hsbearing.case.CaseError` for a Dataset that is none of these.
    """
    if is_sweep_summary(ds):
        return "sweep"
    for system in sorted(SYSTEMS.values(), key=lambda s: s.fallback):  # specific kinds first, generic last
        kind = system.archive_kind(ds)
        if kind is not None:
            return kind
    source = str(ds.encoding.get("source", "dataset"))
    from hsbearing.results import is_hsbearing_archive

    if is_hsbearing_archive(ds) and ds.data_vars:  # ours (life, thermal, map ...), only without a figure
        what = str(ds.attrs.get("title", "hsbearing result"))
        raise CaseError(source, None, f"an hsbearing archive ({what}) that has no figure: `hsbearing plot` draws "
                                      "run, quasi-static, friction, preload, gyro and sweep archives; read this one "
                                      "with hsbearing.open_run(PATH) (an xarray Dataset) or print it with ncdump -h")
    raise CaseError(source, None, NOT_OURS)


#: The CLI's message for a file that holds no hsbearing result it can draw (kept as it was).
NOT_OURS = ("not an hsbearing result this command can draw (no run, quasi-static, friction, preload, gyro or "
            "sweep variables)")
