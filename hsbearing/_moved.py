"""Old module paths of the package, importable for one more release with a DeprecationWarning.

The layout of 0.1 put the angular-contact engine, the workflows and the ball-bearing physics at other paths
(``hsbearing.dynamics``, ``hsbearing.sweeps``, ``hsbearing.models.kernel`` ...).  ``import`` of an old path
gives the module at its new path (the same module object, so ``isinstance`` checks and monkeypatching keep
working) and warns once.  The table is the record of the move (docs/ARCHITECTURE.md, CHANGELOG "Breaking
changes"); it is removed in the next release.
"""

from __future__ import annotations

import importlib
import importlib.abc
import importlib.util
import sys
import warnings

#: old dotted path -> new dotted path
MOVED = {
    "hsbearing.dynamics": "hsbearing.systems.angular_contact.dynamics",
    "hsbearing.quasistatic": "hsbearing.systems.angular_contact.quasistatic",
    "hsbearing.thermal": "hsbearing.systems.angular_contact.thermal",
    "hsbearing.rating": "hsbearing.systems.angular_contact.rating",
    "hsbearing.balances": "hsbearing.systems.angular_contact.balances",
    "hsbearing.contact_state": "hsbearing.systems.angular_contact.contact_state",
    "hsbearing.oils": "hsbearing.cli.oils",
    "hsbearing.stoprule": "hsbearing.analysis.stoprule",
    "hsbearing.warmstart": "hsbearing.workflows.warmstart",
    "hsbearing.maps": "hsbearing.workflows.maps",
    "hsbearing.sweeps": "hsbearing.workflows.sweeps",
    "hsbearing.study": "hsbearing.workflows.study",
    "hsbearing.plotting_maps": "hsbearing.plotting.maps",
    "hsbearing.systems.gyro.studies": "hsbearing.workflows.study.gyro",
    "hsbearing.models.kernel": "hsbearing.models.ball_bearing.kernel",
    "hsbearing.models.kernel_io": "hsbearing.models.ball_bearing.kernel_io",
    "hsbearing.models.state": "hsbearing.models.ball_bearing.state",
    "hsbearing.models.ball": "hsbearing.models.ball_bearing.ball",
    "hsbearing.models.pocket": "hsbearing.models.ball_bearing.pocket",
    "hsbearing.models.ring": "hsbearing.models.ball_bearing.ring",
    "hsbearing.models.power": "hsbearing.models.ball_bearing.power",
    "hsbearing.models.drag": "hsbearing.models.ball_bearing.drag",
    "hsbearing.models.quasistatic_physics": "hsbearing.models.ball_bearing.quasistatic",
}


class _Alias(importlib.abc.Loader):
    def __init__(self, new: str):
        self.new = new

    def create_module(self, spec):
        warnings.warn(f"{spec.name} moved to {self.new}; the old path is removed in the next release",
                      DeprecationWarning, stacklevel=4)
        return importlib.import_module(self.new)

    def exec_module(self, module):  # the module at its new path is already executed
        pass


class _Finder(importlib.abc.MetaPathFinder):
    def find_spec(self, name, path=None, target=None):
        new = MOVED.get(name)
        if new is None:
            return None
        return importlib.util.spec_from_loader(name, _Alias(new))


def install() -> None:
    """Put the old paths on the import system (once)."""
    if not any(isinstance(f, _Finder) for f in sys.meta_path):
        sys.meta_path.append(_Finder())
