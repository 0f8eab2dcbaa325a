"""``hsbearing compare``: lubricants at the same conditions, one page per comparison.

``compare(case, ["4109", "4106", "4050", "my_oil.toml"], out_dir="DIR")`` runs, for every oil (and every point of
the optional varied keys), the quasi-static equilibrium with its power loss by source, film, pressure and rating
lives; a short dynamic run with the stop rule (cage class, slip, whirl, the run's power; ``dynamics=False`` skips
it); and the thermal equilibrium when the case gives an oil flow.  The points run through the sweep machinery
(:func:`hsbearing.workflows.sweeps.execute`: ``-j``, dask, resume; archives in ``DIR/points/``).  Written:
``DIR/compare.nc`` (dimension ``oil``; the best oil per ``criterion``), ``DIR/compare.md`` and ``DIR/index.html``
with its figures as PNG files beside it (opens offline).  docs/sweeps.md, "Comparing lubricants".

By concern: ``compute`` (plans, the point function, compare.nc, the best oil per criterion), ``report`` (figures,
Markdown, HTML), ``cli`` (``hsbearing compare``).
"""

from __future__ import annotations

from hsbearing.workflows.compare.compute import (  # noqa: F401
    CRITERIA,
    DEFAULT_DURATION,
    HTML_NAME,
    MD_NAME,
    NC_NAME,
    add_best,
    best_of,
    combine,
    compare,
    parse_oils,
    plan_compare,
    quasistatic_point,
)

__all__ = ["compare", "plan_compare", "combine", "best_of", "quasistatic_point", "CRITERIA", "DEFAULT_DURATION"]
