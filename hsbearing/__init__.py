"""hsbearing: dynamics and friction of rolling ball bearings.

Public API (docs/design.md "Contracts"):

- :func:`load_case` -- TOML case (bundled name or path) -> frozen SI dataclasses
- :func:`simulate` -- dynamic simulation -> ``xarray.Dataset`` over ``time`` (and ``ball``)
- :func:`quasi_static` -- high-speed quasi-static equilibrium -> Dataset over ``ball``
- :func:`sweep` -- many runs over varied case keys -> one Dataset with a dim per key
- :func:`open_run` -- read an archive back
- :func:`dynamic_model` -- the model object (``y0``, ``rhs``, ``state_names``)
"""

from __future__ import annotations

from hsbearing import _interrupt

_interrupt.guard_command_start()  # the hsbearing command: a Ctrl-C while it imports ends it with 130, nothing written

from hsbearing import _moved  # noqa: E402
from hsbearing._version import __version__
from hsbearing.case import Case, CaseError, as_case, list_cases, load_case
from hsbearing.errors import SolverError
from hsbearing.results import open_run

__all__ = [
    "__version__",
    "Case",
    "CaseError",
    "SolverError",
    "load_case",
    "list_cases",
    "simulate",
    "quasi_static",
    "sweep",
    "open_run",
    "dynamic_model",
]


_moved.install()  # the old module paths, with a DeprecationWarning, for one release


def simulate(case, duration=None, *, progress: bool = False, **kwargs):
    """Run the dynamic model the case's system selects and return its Dataset.

    ``duration`` is seconds (float) or a unit string (``"0.2 s"``); None uses
    ``[simulation] duration``.  Raises :class:`SolverError` (with
    ``.partial``) on numerical failure.
    """
    from hsbearing import systems  # the registry: [case] system -> its package (hsbearing/systems/)

    return systems.simulate(as_case(case), duration=duration, progress=progress, **kwargs)


def quasi_static(case, **kwargs):
    """High-speed quasi-static equilibrium of the case (Jones-Harris) as a Dataset over ``ball``."""
    from hsbearing.systems.angular_contact import quasistatic

    return quasistatic.solve_case(as_case(case), **kwargs)


def sweep(case, vary, **kwargs):
    """Cartesian (or zipped) sweep over case keys; see :func:`hsbearing.workflows.sweeps.run_sweep`."""
    from hsbearing.workflows import sweeps

    return sweeps.run_sweep(case, vary, **kwargs)


def dynamic_model(case):
    """The dynamic model object of a case: ``y0``, ``rhs(t, y, ydot)``, ``state_names``."""
    from hsbearing.systems.angular_contact import dynamics

    return dynamics.build_model(as_case(case))
