"""hsbearing: dynamics and friction of rolling ball bearings.

Public API (the contracts of docs/design.md):

- :func:`load_case` -- TOML case (bundled name or path) -> frozen SI dataclasses
- :func:`simulate` -- dynamic simulation -> ``xarray.Dataset`` over ``time`` (and ``ball``)
- :func:`quasi_static` -- high-speed quasi-static equilibrium -> Dataset over ``ball``
- :func:`sweep` -- many runs over varied case keys -> one Dataset with a dim per key
- :func:`open_run` -- read an archive back
- :func:`dynamic_model` -- the model object (``y0``, ``rhs``, ``state_names``)
"""

from __future__ import annotations

from hsbearing import _moved
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

    Examples
    --------
    >>> import hsbearing
    >>> ds = hsbearing.simulate("zhang2016", duration="5 ms")  # doctest: +SKIP
    >>> ds.attrs["status"]  # doctest: +SKIP
    'ok'
    >>> ds.cage_speed.attrs["units"]  # doctest: +SKIP
    'rad/s'
    """
    from hsbearing import systems  # the registry: [case] system -> its package (hsbearing/systems/)

    return systems.simulate(as_case(case), duration=duration, progress=progress, **kwargs)


def quasi_static(case, **kwargs):
    """High-speed quasi-static equilibrium of the case (Jones-Harris) as a Dataset over ``ball``.

    Examples
    --------
    The default case: 11 balls at 1 kN axial load share it equally (about 182 N at the inner contact):

    >>> import hsbearing
    >>> qs = hsbearing.quasi_static("zhang2016")  # doctest: +SKIP
    >>> print(f"{float(qs.inner_contact_load[0]):.1f} N")  # doctest: +SKIP
    182.0 N
    """
    from hsbearing.systems.angular_contact import quasistatic

    return quasistatic.solve_case(as_case(case), **kwargs)


def sweep(case, vary, **kwargs):
    """Cartesian (or zipped) sweep over case keys; see :func:`hsbearing.workflows.sweeps.run_sweep`.

    Examples
    --------
    >>> import hsbearing
    >>> sw = hsbearing.sweep("zhang2016", {"operating.axial_load": ["500 N", "1 kN"]},
    ...                      kind="quasistatic", out_dir="runs/fa")  # doctest: +SKIP
    """
    from hsbearing.workflows import sweeps

    return sweeps.run_sweep(case, vary, **kwargs)


def dynamic_model(case):
    """The dynamic model object of a case: ``y0``, ``rhs(t, y, ydot)``, ``state_names``."""
    from hsbearing.systems.angular_contact import dynamics

    return dynamics.build_model(as_case(case))
