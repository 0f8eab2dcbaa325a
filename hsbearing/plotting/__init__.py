"""The run and sweep figures (``hsbearing run`` / ``hsbearing plot OUT.nc`` / ``DIR/sweep.png``).

:func:`plot_run` dispatches on the Dataset:

the kind of archive (:func:`archive_kind`, from its attributes and dimensions) selects the figure:

- ``"sweep"``: a sweep or study summary (:func:`is_sweep_summary`: ``attrs["title"] == "hsbearing sweep"``
  or ``sweep_vary`` in the attrs, as written by :func:`hsbearing.sweeps.assemble`) -> :func:`plot_sweep`:
  the summary variables against the varied keys;
- otherwise the system that draws it (:mod:`hsbearing.systems`: each system's ``archive_kind`` and
  ``figures``; the figure code lives in ``hsbearing/systems/<name>/figures.py``):
- ``"gyro"``: a gyro-bearing run (``attrs["model"] == "gyro_ribbon_cage"``) -> ``systems.gyro.figures.plot_gyro``:
  speeds, M_C, the friction-moment sources;
- ``"friction"``: ``hsbearing friction`` (dim ``speed``, ``sliding_torque``) -> ``systems.deep_groove.figures``;
- ``"preload"``: ``hsbearing preload`` (dim ``preload``) -> ``systems.wire_race.figures``;
- ``"quasistatic"``: no ``time`` dimension, per-ball contact loads -> per-ball contact loads and angles;
- ``"run"``: the dynamic-run figure (``systems.angular_contact.figures``): (a) cage whirl orbit D_Y-D_Z with the
  guide clearance circle, (b) Poincare map (D_Y, V_Y) -- the same section
  points as the stored classification (:mod:`hsbearing.analysis.poincare`),
  (c) cage speed against time with the pure-rolling speed, (d) cage slip ratio.

Shared helpers: :mod:`hsbearing.plotting.common`; the sweep figure: :mod:`hsbearing.plotting.sweep`.
Matplotlib is used through its object API with the Agg canvas (no pyplot, no
global backend change), and the PNG is written atomically (temporary file in
the target directory, then rename).
"""

from __future__ import annotations

from pathlib import Path

from hsbearing.plotting.common import ISO76_BALL_PRESSURE, save_figure, title_lines
from hsbearing.plotting.sweep import (
    CLASS_STYLE,
    MAX_ORDERED_SERIES,
    MAX_SERIES,
    NOT_OK_STYLE,
    _prepare_sweep,  # noqa: F401 - used by tests
    class_family,
    is_sweep_summary,
    plot_sweep,
    sweep_dims,
    sweep_figure,
    sweep_layout,
)

__all__ = ["archive_kind", "is_sweep_summary", "plot_run", "plot_sweep", "plot_friction", "plot_preload", "plot_gyro",
           "save_figure", "sweep_figure", "sweep_layout", "title_lines", "ISO76_BALL_PRESSURE", "CLASS_STYLE",
           "NOT_OK_STYLE", "MAX_SERIES", "MAX_ORDERED_SERIES", "class_family", "sweep_dims"]


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
    from hsbearing.systems import figure_functions

    return figure_functions()[kind](ds, path)


def archive_kind(ds) -> str:
    """What an hsbearing Dataset holds: ``"sweep"``, ``"gyro"``, ``"friction"``, ``"preload"``,
    ``"quasistatic"`` or ``"run"`` (see the module docstring).

    Decided from the attributes every archive carries (``title``, ``model``, ``case_system``) and
    the dimensions / variables, so archives written before this function existed are recognised too.
    Raises :class:`hsbearing.case.CaseError` for a Dataset that is none of these.
    """
    from hsbearing.case import CaseError

    if is_sweep_summary(ds):
        return "sweep"
    from hsbearing.systems import SYSTEMS

    for system in sorted(SYSTEMS.values(), key=lambda s: s.fallback):  # specific kinds first, generic last
        kind = system.archive_kind(ds)
        if kind is not None:
            return kind
    source = str(ds.encoding.get("source", "dataset"))
    raise CaseError(source, None, "not an hsbearing result this command can draw (no run, quasi-static, friction, "
                                  "preload, gyro or sweep variables)")


#: the older names of the per-system figure functions here -> the archive kind whose figure they draw
_OLD_NAMES = {"plot_gyro": "gyro", "plot_friction": "friction", "plot_preload": "preload"}


def __getattr__(name):
    """The per-system figure functions under their older names here, found through the systems registry
    (:func:`hsbearing.systems.figure_functions`), so this package imports no system's figure module by name
    (the systems' figures import hsbearing.plotting: issue 27, item 11, the last import circle)."""
    if name in _OLD_NAMES:
        from hsbearing.systems import figure_functions

        return figure_functions()[_OLD_NAMES[name]]
    raise AttributeError(f"module {__name__!r} has no attribute {name!r}")
