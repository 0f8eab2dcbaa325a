"""Analysis of dynamic runs: cage slip ratio, whirl orbit, Poincare section, period classification.

Light at import: :mod:`hsbearing.analysis.slip` only needs numpy.  The
functions :func:`annotate` and :func:`summary` live in
:mod:`hsbearing.analysis.orbit` and are re-exported lazily.
"""

from __future__ import annotations

from hsbearing.analysis.slip import cage_slip_ratio, theoretical_cage_speed

__all__ = ["theoretical_cage_speed", "cage_slip_ratio", "annotate", "summary", "poincare_points", "classify"]


def __getattr__(name):
    if name in ("annotate", "summary"):
        from hsbearing.analysis import orbit

        return getattr(orbit, name)
    if name == "poincare_points":
        from hsbearing.analysis.poincare import poincare_points

        return poincare_points
    if name == "classify":
        from hsbearing.analysis.classify import classify

        return classify
    raise AttributeError(f"module 'hsbearing.analysis' has no attribute {name!r}")
