"""Figures shared by every system: the sweep/study summary figure (``DIR/sweep.png``), the map figure and the
helpers every figure module uses (:mod:`hsbearing.plotting.common`).  This package imports no system: the
dispatch of ``hsbearing plot`` by archive kind is :func:`hsbearing.systems.plot_run` (the systems registry),
which works as follows.

The kind of archive (:func:`archive_kind`, from its attributes and dimensions) selects the figure:

- ``"sweep"``: a sweep or study summary (:func:`is_sweep_summary`: ``attrs["title"] == "hsbearing sweep"``
  or ``sweep_vary`` in the attrs, as written by :func:`hsbearing.workflows.sweeps.assemble`) -> :func:`plot_sweep`:
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

from hsbearing.plotting.common import ISO76_BALL_PRESSURE, save_figure, title_lines
from hsbearing.plotting.sweep import (
    CLASS_STYLE,
    MAX_ORDERED_SERIES,
    MAX_SERIES,
    NOT_OK_STYLE,
    class_family,
    is_sweep_summary,
    plot_sweep,
    sweep_dims,
    sweep_figure,
    sweep_layout,
)

__all__ = ["is_sweep_summary", "plot_sweep", "save_figure", "sweep_figure", "sweep_layout", "title_lines", "ISO76_BALL_PRESSURE", "CLASS_STYLE",
           "NOT_OK_STYLE", "MAX_SERIES", "MAX_ORDERED_SERIES", "class_family", "sweep_dims"]
