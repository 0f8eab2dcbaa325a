"""Backwards-compatible import path: the quasi-static bearing equilibrium is :mod:`hsbearing.quasistatic`
(issue 19: ``solvers/`` knows nothing of bearings).  ``hsbearing.solvers.quasistatic`` is that same module
object, so attributes (also private ones and monkeypatches) are shared."""

import sys

from hsbearing import quasistatic as _quasistatic

sys.modules[__name__] = _quasistatic
