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
    "friction",
    "thermal",
    "life",
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


def friction(case, speeds=None, *, thermal=False, **overrides):
    """Quasi-static power loss by source and the SKF 2004 frictional moment over inner-ring speeds (what
    ``hsbearing friction CASE`` computes for an angular-contact case).

    Parameters
    ----------
    case : a :class:`Case`, a bundled case name or a case file path.
    speeds : inner-ring speeds: unit strings (``"10000 rpm"``, ``"5000,14000rpm"``), a pint Quantity, SI floats
        [rad/s] or a list of them; None = the case's ``operating.inner_speed``.
    thermal : as ``hsbearing friction --thermal``: at each speed the thermal network's temperatures reach the
        contacts (needs ``lubricant.oil_flow_rate``; the temperatures used are variables of the Dataset).
    **overrides : case values (``axial_load="2 kN"``, ``oil="4106"``, ``temperature=373.15``): unit strings,
        pint Quantities or SI floats, as :func:`load_case`.

    Returns
    -------
    xr.Dataset over ``speed``: ``qs_power_loss`` and ``qs_power_loss_<source>`` [W], ``qs_friction_torque`` and the
    ``skf_*`` moments [N m]; attrs name the oil (``lubricant_name``, ``lubricant_provenance``) and the ``warnings``.
    """
    import numpy as np

    from hsbearing.systems.angular_contact.rating import friction_angular_contact, require_angular_contact

    c = as_case(case, overrides)
    require_angular_contact(c, "hsbearing.friction is the angular-contact model; other systems: the command "
                               "hsbearing friction")
    if speeds is None:
        speeds = np.array([abs(c.operating.inner_speed)])
    return friction_angular_contact(c, speeds, thermal=bool(thermal))


def thermal(case, *, lubricant_temperature_start=None, **overrides):
    """Thermal equilibrium of the bearing (``hsbearing thermal CASE``): the fixed point of the quasi-static power
    loss and the thermal network (docs/thermal.md).

    Parameters
    ----------
    case : a :class:`Case`, a bundled case name or a case file path.
    lubricant_temperature_start : temperature of the first iteration: unit string, pint Quantity or kelvin; None =
        the oil inlet temperature.
    **overrides : case values (``oil_flow_rate="1 L/min"``, ``inner_speed=1466.1``): unit strings, pint Quantities
        or SI floats.

    Returns
    -------
    xr.Dataset: node temperatures [K], heat by link [W], the power loss by source at equilibrium; its ``status``
    says whether a steady state exists.
    """
    from hsbearing.systems.angular_contact.thermal import check_inputs, thermal_equilibrium

    c = as_case(case, overrides)
    check_inputs(c)
    T0 = None
    if lubricant_temperature_start is not None:
        from hsbearing.case.load import override_literal
        from hsbearing.units import parse_quantity

        lit = override_literal("temperature", lubricant_temperature_start)
        T0 = parse_quantity(lit, "temperature", source="lubricant_temperature_start")
    return thermal_equilibrium(c, T_start=T0)


def life(case, *, quasistatic: bool = True, **overrides):
    """ISO 281 and ISO/TS 16281 rating lives of a radial ball-bearing case (``hsbearing life CASE``).

    Parameters
    ----------
    case : a :class:`Case`, a bundled case name or a case file path (angular_contact, deep_groove).
    quasistatic : also compute the ISO/TS 16281 reference lives from the quasi-static contact loads.
    **overrides : case values (``axial_load="2 kN"``, ``radial_load=500.0``): unit strings, pint Quantities or SI
        floats.

    Returns
    -------
    xr.Dataset of scalars (L_10, L_10m [1e6 rev], a_ISO, kappa, ...) and per-ball raceway ratings.
    """
    from hsbearing.systems.angular_contact.rating import life as _life

    return _life(as_case(case, overrides), quasistatic=quasistatic)
