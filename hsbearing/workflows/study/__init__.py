"""Bundled studies: a set of sweeps with the paper's results next to ours, and a report.

A study is a TOML file (``hsbearing/studies/<name>.toml``, shipped in the
wheel) with a ``[study]`` table (base case, oils, default duration), one
``[[table]]`` per paper table (overrides ``set``, the varied key ``vary`` and
its ``values``, and ``[table.paper]``: the paper's classification of every
cell) and ``[[figure]]`` entries naming representative cells.

``run_study("zhang2016", out_dir)`` plans every table as a product sweep
``oil x values`` (:func:`hsbearing.workflows.sweeps.plan_sweep`), computes all the
points in one pass (:func:`hsbearing.workflows.sweeps.execute`; points shared by two
tables, e.g. 1000 N at 130 degC, are computed once), then writes::

    DIR/runs/<case>-<hash>.nc    one archive per point (resumable)
    DIR/<table>.nc               one sweep Dataset per table (dims oil x <key>)
    DIR/figures/*.png            whirl orbits + Poincare maps; slip ratio curves
    DIR/report.md                paper vs ours for every cell, figures, wall time

Agreement is a finding, not a target: the report lists every cell where our
classification differs and names what can drive a difference.

Bands over the unknown inputs (``run_study(..., bands=True)``, ``hsbearing study
NAME --bands``): the study's ``[bands]`` table names case keys the paper does not
give, a range for each, and a Latin-hypercube sample of those ranges with a fixed
seed (:func:`band_samples`; the nominal case is sample 0 when
``include_nominal``).  Every cell runs every sample (common random numbers, so the
cells are comparable).  A sample is only a set of case overrides: its points go to
the same ``DIR/runs/<case>-<hash>.nc`` archives as the nominal study (the hash is
taken over the full case), so the nominal points of an earlier ``hsbearing study``
in the same directory are reused, and an interrupted banded study resumes.  The
banded outputs do not overwrite the nominal ones::

    DIR/<table>_bands.nc         one Dataset per table (dims sample x oil x <key>)
    DIR/report_bands.md          per cell: class fractions over the band, majority, agrees, occurs

The package, by concern (every name is importable from ``hsbearing.workflows.study`` as before)::

    spec.py      the study file, load_study and its checks, the band samples (Latin hypercube), the directory layout
    execute.py   run_study: plan, compute or collect, assemble the netCDF tables (one pass for all points)
    cells.py     reading a table's cells: our class, class fractions over the band, stability rank, wall times
    table6.py    Table 6 of the paper derived by a stated rule
    figures.py   whirl orbits and Poincare maps of every cell, slip ratio figures, the orbit drift diagnostic
    report.py    report.md and report_bands.md
    cli.py       ``hsbearing study``
"""

from __future__ import annotations

from hsbearing.case import load_case, parse_quantity  # noqa: F401  (names of the former module, used by callers)
from hsbearing.workflows.study.cells import (  # noqa: F401
    _details,
    _ours,
    band_cell_stats,
    band_counts,
    band_range,
    cell_stats,
    fmt,
    fraction_text,
    point_walls,
    section_stats,
    stability_rank,
    sum_wall,
    value_label,
)
from hsbearing.workflows.study.cli import cli_main
from hsbearing.workflows.study.execute import (  # noqa: F401
    _assemble,
    _backend_label,
    backend_or_none,
    execute_or_collect,
    run_banded,
    run_study,
)
from hsbearing.workflows.study.figures import (  # noqa: F401
    axis_values,
    orbit_drift,
    pick_sample,
    plot_cells,
    plot_gallery,
    plot_slip,
    plot_slip_band,
    poincare,
)
from hsbearing.workflows.study.report import SUPERSEDED, table6_lines, write_band_report, write_report  # noqa: F401
from hsbearing.workflows.study.spec import (  # noqa: F401
    BAND_METHODS,
    BAND_RESOLUTION,
    BANDS_SUFFIX,
    FIGURES,
    RUNS,
    STATUS_MISSING,
    BandSample,
    Study,
    band_samples,
    check_bands,
    effective_value,
    format_override,
    latin_hypercube,
    list_studies,
    load_study,
    normalise_label,
    sample_text,
    studies_dir,
    study_help,
)
from hsbearing.workflows.study.table6 import TABLE6_INDEX_TOL, TABLE6_RULE, TABLE6_SLIP_TOL, derive_table6  # noqa: F401

__all__ = ["list_studies", "study_help", "load_study", "run_study", "normalise_label", "write_report", "cli_main",
           "BandSample", "band_samples", "latin_hypercube", "band_cell_stats", "write_band_report",
           "stability_rank", "derive_table6", "TABLE6_RULE", "orbit_drift"]
