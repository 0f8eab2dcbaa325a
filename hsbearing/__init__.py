"""hsbearing: dynamics and friction of rolling ball bearings.

Public API (the contracts of docs/design.md):

- :func:`load_case` -- TOML case (bundled name or path) -> frozen SI dataclasses
- :func:`simulate` -- dynamic simulation -> ``xarray.Dataset`` over ``time`` (and ``ball``)
- :func:`quasi_static` -- high-speed quasi-static equilibrium -> Dataset over ``ball``
- :func:`sweep` -- many runs over varied case keys -> one Dataset with a dim per key
- :func:`open_run` -- read an archive back
- :func:`dynamic_model` -- the model object (``y0``, ``rhs``, ``state_names``)
- :func:`compare` -- lubricants at the same conditions -> Dataset over ``oil`` and a page (``hsbearing compare``)
- :func:`traction_coefficient` -- the traction coefficient of one contact for any traction law
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
    "compare",
    "traction_coefficient",
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


def friction(case, speeds=None, **overrides):
    """Quasi-static power loss by source and the SKF 2004 frictional moment over inner-ring speeds (what
    ``hsbearing friction CASE`` computes for an angular-contact case).

    Parameters
    ----------
    case : a :class:`Case`, a bundled case name or a case file path.
    speeds : inner-ring speeds: unit strings (``"10000 rpm"``, ``"5000,14000rpm"``), a pint Quantity, SI floats
        [rad/s] or a list of them; None = the case's ``operating.inner_speed``.
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
    return friction_angular_contact(c, speeds)


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


def compare(case, oils, *, out_dir, vary=None, dynamics: bool = True, duration=None, stop: str = "converged",
            jobs: int | None = None, scheduler: str | None = None, progress: bool = False, figures: bool = True,
            **overrides):
    """Lubricants at the same conditions (``hsbearing compare``): a Dataset over ``oil`` and a page in ``out_dir``.

    Parameters
    ----------
    case : a :class:`Case`, a bundled case name or a case file path (angular_contact).
    oils : ``"4109,4106,my_oil.toml"`` or a list: built-in oils, bundled lubricants, lubricant files (a file path
        relative to the case file, then the working directory, as ``lubricant.file``).
    out_dir : directory of ``index.html``, ``compare.md``, ``compare.nc`` and the point archives (``points/``);
        the same call again reuses the point archives.
    vary : ``{key: values}`` of other case keys, every oil at each value (as :func:`sweep`).
    dynamics : run the dynamic model for each oil (cage class, slip, whirl, the run's power); False: quasi-static only.
    duration : upper bound of each dynamic run [s] or a unit string (default 1.2 s).
    stop : ``"converged"`` (default: stop once the cage answer holds, docs/sweeps.md) or ``"duration"``.
    jobs, scheduler : local worker processes or a dask.distributed scheduler address (as :func:`sweep`).
    progress : a progress bar on stderr.  figures : draw the page's figures.
    **overrides : case values (``axial_load="2 kN"``): unit strings, pint Quantities or SI floats.

    Returns
    -------
    xr.Dataset over ``oil`` (and the varied keys): each oil's quasi-static power by source, drive torque, film,
    pressure, lives; the dynamic run's class, slip, whirl and power (``dynamic_*``); the thermal temperatures when
    the case has an oil flow; ``best_oil`` / ``best_margin`` per ``criterion``; ``lubricant_name``,
    ``lubricant_provenance`` and ``lubricant_notices`` per oil.

    Examples
    --------
    >>> import hsbearing
    >>> ds = hsbearing.compare("zhang2016", "4109,4106", out_dir="runs/oils", dynamics=False)  # doctest: +SKIP
    >>> ds["best_oil"].sel(criterion="power_loss").item()  # doctest: +SKIP
    '4109'
    """
    from hsbearing.workflows.compare import compare as _compare

    return _compare(as_case(case, overrides), oils, vary=vary, out_dir=out_dir, dynamics=dynamics, duration=duration,
                    stop=stop, jobs=jobs, scheduler=scheduler, progress=progress, figures=figures)


#: oil density for a registered oil name given to :func:`traction_coefficient` [kg/m^3] (the case's default
#: lubricant.density)
TRACTION_DENSITY = 850.0


def _oil_at(oil, T):
    """(eta [Pa s], alpha [1/Pa], beta = -d ln eta/dT [1/K], K [W/(m K)], definition or None) of an oil at T [K]:
    a registered oil name (Walther viscosity at TRACTION_DENSITY, Table 1 alpha and K) or a lubricant file."""
    import numpy as np

    from hsbearing.models import traction

    if str(oil) in traction.OILS:
        from hsbearing.models.viscosity import dynamic_viscosity

        o = traction.OILS[str(oil)]

        def eta(t):
            return float(dynamic_viscosity(str(oil), t, law="walther", density=TRACTION_DENSITY))

        return eta(T), o.alpha, -(np.log(eta(T + 0.5)) - np.log(eta(T - 0.5))), o.K, None
    from hsbearing.lubricant import load_lubricant, resolve_lubricant, unresolved_message

    path = resolve_lubricant(str(oil))
    if path is None:
        raise CaseError("traction_coefficient", "oil", unresolved_message(str(oil)))
    d = load_lubricant(path)
    v = d.at(T, TRACTION_DENSITY)
    beta = -(np.log(d.dynamic_viscosity(T + 0.5, TRACTION_DENSITY)) - np.log(d.dynamic_viscosity(T - 0.5, TRACTION_DENSITY)))
    K = v["K"] if v["K"] is not None else traction.OILS[d.traction_oil].K
    return v["eta"], v["alpha"], beta, K, d


def traction_coefficient(oil, S, load, rolling_speed, temperature, Rx, Ry, E_reduced, law="default"):
    """Traction coefficient mu of one lubricated ball/race contact (docs/traction.md).

    Parameters
    ----------
    oil : a registered oil ("4109", "4106", "4050"), a bundled lubricant name or a lubricant file path.
    S : slide-roll ratio (U1 - U2)/U, a fraction, signed (float or array); mu has its sign.
    load : normal contact load; rolling_speed : entrainment speed (U1 + U2)/2; temperature : oil inlet
        temperature; Rx, Ry : effective radii in the rolling and transverse directions; E_reduced : reduced
        modulus E' = 2/((1-nu1^2)/E1 + (1-nu2^2)/E2).  Each a unit string ("500 N", "130 degC"), a pint Quantity
        or an SI float.
    law : "default" (the oil's registered law: the Zhang et al. 2016 fit of 4109/4106/4050, or a lubricant
        file's [traction] law), "eyring" (isothermal physical model), "physical" (thermal physical model,
        hsbearing.models.traction.thermal), or a named law of a registered oil ("percent", "printed", ...).

    Returns
    -------
    mu : float (or an array shaped like S) [-].  Bad input: CaseError naming the argument.

    Examples
    --------
    >>> import hsbearing
    >>> mu = hsbearing.traction_coefficient("4109", 0.05, "500 N", "16.3 m/s", "130 degC", "3.87 mm", "124 mm",
    ...                                     "228.6 GPa")
    >>> print(f"{mu:.4f}")
    0.0090
    """
    import numpy as np

    from hsbearing.case.load import override_literal
    from hsbearing.models import hertz, traction
    from hsbearing.units import parse_quantity

    def q(v, kind, key):
        return parse_quantity(override_literal(kind, v), kind, source="traction_coefficient", key=key)

    W, U, T = q(load, "force", "load"), q(rolling_speed, "velocity", "rolling_speed"), q(temperature, "temperature",
                                                                                           "temperature")
    rx, ry, Ep = q(Rx, "length", "Rx"), q(Ry, "length", "Ry"), q(E_reduced, "pressure", "E_reduced")
    for key, v in (("load", W), ("Rx", rx), ("Ry", ry), ("E_reduced", Ep), ("temperature", T)):
        if not v > 0.0:
            raise CaseError("traction_coefficient", key, f"must be > 0 (got {v:g} SI)")
    try:
        Sa = np.asarray(S, dtype=float)
    except (TypeError, ValueError):
        raise CaseError("traction_coefficient", "S", f"a slide-roll ratio is a number or an array, got {S!r}") from None
    if not np.all(np.isfinite(Sa)):
        raise CaseError("traction_coefficient", "S", "must be finite")
    eta, alpha, beta, K, d = _oil_at(oil, T)
    oil_name = str(oil) if d is None else d.traction_oil
    if law == "default" and d is not None:  # the lubricant file's own law
        law = {"zhang2016": d.traction_law, "eyring": traction.EYRING_LAW}.get(d.traction_model, traction.USER_LAW)
    known = tuple(traction.KNOWN_LAWS[oil_name]) + ((traction.USER_LAW,) if d is not None and d.coefficients else ())
    if law not in known:
        raise CaseError("traction_coefficient", "law", f"unknown traction law {law!r} for this oil (known: "
                                                       f"{', '.join(known)})")
    if ry < rx:
        raise CaseError("traction_coefficient", "Ry", f"must be >= Rx (a ball/race contact: the ellipse's major axis "
                                                      f"lies across the rolling direction; got Ry = {ry:g} m < Rx = {rx:g} m)")
    c = hertz.point_contact(rx, ry, W, Ep, 0.0, Ep, 0.0)  # nu = 0 and E1 = E2 = E': the reduced modulus is E'
    a = float(c.a)
    k = float(c.ellipticity)
    eyring = d.eyring.at(T, alpha) if (d is not None and d.eyring is not None) else None
    try:
        mu = traction.contact_mu(oil_name, Sa, W, U, T, Ep, rx, ry, law, k=k, a=a, eta=eta, alpha=alpha,
                                 eyring=eyring, coefficients=None if d is None else d.coefficients, beta=beta, K=K)
    except ValueError as exc:
        raise CaseError("traction_coefficient", "temperature" if "degC" in str(exc) else "law", str(exc)) from None
    mu = np.asarray(mu, dtype=float)
    return float(mu) if mu.ndim == 0 else mu
