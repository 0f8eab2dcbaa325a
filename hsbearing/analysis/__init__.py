"""Analysis of dynamic runs: cage slip ratio, whirl orbit, Poincare section, period classification.

- :func:`theoretical_cage_speed`, :func:`cage_slip_ratio` (``slip.py``)
- :func:`poincare_points` (``poincare.py``): one point (D_Y, V_Y) per cage revolution
- :func:`classify` (``periods.py``): the section label "1 period", "k periods", "quasi-periodic", "chaos",
  "undetermined"; the whole motion (growth, still cage, whirl lock, sub-labels): ``whirl.py``
- :func:`annotate`, :func:`summary` (``orbit.py``): everything above added to a run Dataset / as sweep scalars

"""

from __future__ import annotations

from hsbearing.analysis.orbit import annotate, summary
from hsbearing.analysis.periods import classify
from hsbearing.analysis.poincare import poincare_points
from hsbearing.analysis.slip import cage_slip_ratio, theoretical_cage_speed

__all__ = ["theoretical_cage_speed", "cage_slip_ratio", "annotate", "summary", "poincare_points", "classify"]
