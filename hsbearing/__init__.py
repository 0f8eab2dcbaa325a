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


def _api(fn):
    """Explicit keywords for a public function: an unknown keyword is a TypeError that names the function, the
    closest keyword it has and, for a case key (``axial_load=...``), where case values go (``overrides=``)."""
    import functools
    import inspect

    sig = inspect.signature(fn)

    @functools.wraps(fn)
    def wrapper(*args, **kwargs):
        try:
            sig.bind(*args, **kwargs)
        except TypeError as exc:
            known = [n for n, q in sig.parameters.items() if q.kind is not q.VAR_KEYWORD]
            unknown = [k for k in kwargs if k not in sig.parameters]
            if not unknown:
                raise TypeError(f"hsbearing.{fn.__name__}(): {exc}") from None
            raise TypeError(_unknown_keyword_message(fn.__name__, unknown[0], known)) from None
        return fn(*args, **kwargs)

    return wrapper


def _unknown_keyword_message(name: str, key: str, known: list[str]) -> str:
    import difflib

    msg = f"hsbearing.{name}() got an unknown keyword {key!r}"
    close = difflib.get_close_matches(key, known, n=1)
    if close:
        msg += f"; did you mean {close[0]!r}?"
    else:
        try:  # a case key given as a keyword: say where it goes
            from hsbearing.case.load import resolve_key

            table, leaf = resolve_key(key)
            msg += f"; {key!r} is a case value: overrides={{'{table}.{leaf}': ...}}"
        except Exception:  # noqa: BLE001 - not a case key either: list the keywords
            pass
    return msg + f" (keywords: {', '.join(known)})"


def _quantity(value, kind: str, name: str):
    """A keyword quantity as an SI float: unit string, pint Quantity or SI float (None stays None)."""
    if value is None:
        return None
    from hsbearing.case.load import override_literal
    from hsbearing.units import parse_quantity

    return parse_quantity(override_literal(kind, value), kind, source=name, key=name)


@_api
def simulate(case, duration=None, *, overrides=None, stop=None, section=None, rtol=None, atol=None,
             thermal: bool = False, extend: bool = False, max_duration=None, progress: bool = False,
             cvode_settings=None, wall_limit=None):
    """Run the dynamic model the case's system selects and return its Dataset (``hsbearing run CASE``).

    Parameters
    ----------
    case : Case, str or path
        A :class:`Case`, a bundled case name or a case file path.
    duration : str, pint.Quantity or float, optional
        Simulated time: ``"0.2 s"``, ``Q_(200, "ms")`` or seconds; None = ``[simulation] duration``
        (``--duration``).
    overrides : dict, optional
        Case values ``{"operating.axial_load": "2 kN", "oil": "4106", "inner_speed": 1466.1}``: unit strings,
        pint Quantities or SI floats, as :func:`load_case` (``--set``).
    stop : {"duration", "converged"}, optional
        Stop rule (``--stop``); None = ``[simulation] stop``.
    section : {"transverse", "cage_revolution", "plane"}, optional
        Poincare section of the cage-motion label (``--section``); None = ``[simulation] section``.
    rtol, atol : float, optional
        CVODE tolerances; None = ``[simulation] rtol`` / ``atol``.
    thermal : bool, default False
        Solve the thermal network first (:func:`thermal`) and run at its lubricant temperature, each race's
        contacts at their own inlet temperature (T_ring + T_ball)/2, the guide-land and pocket films at the thermal
        factors of ``friction --thermal`` (frozen at the quasi-static state) (``--thermal``; attrs
        ``thermal_inner_/outer_contact_inlet_temperature``, ``thermal_guide_land_film_factor``,
        ``thermal_pocket_film_factor``; angular-contact cases with ``lubricant.oil_flow_rate``).
    extend : bool, default False
        While the cage-motion label is undetermined, continue the run in steps up to ``max_duration``
        (``--extend``; angular-contact cases).
    max_duration : str, pint.Quantity or float, optional
        Budget of ``extend`` (``--max-duration``); None = 3 x the run's duration.
    progress : bool, default False
        tqdm progress bar of the simulated time (the CLI's default unless ``-q``).
    cvode_settings : dict, optional
        CVODE optional inputs of the angular-contact model (``{}``: CVODE's own defaults; docs/dynamics.md).
    wall_limit : str, pint.Quantity or float, optional
        Stop the integration with a :class:`SolverError` (its ``.partial`` kept) after this much wall-clock time
        (angular-contact model); None = no limit.

    Returns
    -------
    xarray.Dataset over ``time`` (and ``ball``); ``attrs["status"]`` is ``"ok"``.

    Raises
    ------
    CaseError
        Bad input (a case value, a quantity, a choice).
    SolverError
        Numerical failure, with ``.partial`` the Dataset up to the failure.
    TypeError
        An unknown keyword (a case value given as a keyword is named: it goes in ``overrides``).

    Examples
    --------
    >>> import hsbearing
    >>> ds = hsbearing.simulate("zhang2016", duration="5 ms", overrides={"axial_load": "2 kN"})  # doctest: +SKIP
    >>> ds.attrs["status"]  # doctest: +SKIP
    'ok'
    >>> ds.cage_speed.attrs["units"]  # doctest: +SKIP
    'rad/s'
    """
    from hsbearing import systems  # the registry: [case] system -> its package (hsbearing/systems/)

    sets = dict(overrides or {})
    for key, value in (("simulation.stop", stop), ("simulation.section", section), ("simulation.rtol", rtol),
                       ("simulation.atol", atol)):
        if value is not None:
            sets[key] = value
    c = as_case(case, sets)
    duration = _quantity(duration, "time", "duration")
    if duration is not None and not duration > 0:
        raise CaseError("duration", "duration", f"must be positive, got {duration!r}")
    budget = _quantity(max_duration, "time", "max_duration")
    if budget is not None and not extend:
        raise CaseError("max_duration", "max_duration", "only with extend=True")
    if thermal or extend:
        from hsbearing.systems.angular_contact.rating import require_angular_contact

        require_angular_contact(c, "thermal= and extend= are options of the angular-contact model",
                                source="simulate", key="thermal" if thermal else "extend")
    kw = {} if cvode_settings is None else {"cvode_settings": cvode_settings}
    if thermal:
        c, kw["race_temperatures"], films = _thermal_start(c)
        kw["cage_film_factors"] = (films["land"]["factor"], films["pocket"]["factor"])
    limit = _quantity(wall_limit, "time", "wall_limit")
    if limit is not None:
        if not limit > 0:
            raise CaseError("wall_limit", "wall_limit", f"must be positive, got {wall_limit!r}")
        from hsbearing.systems.angular_contact.rating import require_angular_contact

        require_angular_contact(c, "wall_limit= is an option of the angular-contact model", source="simulate",
                                key="wall_limit")
        kw["wall_limit"] = limit
    ds = systems.simulate(c, duration=duration, progress=progress, **kw)
    if thermal:  # which temperatures the race contacts ran at (an extension below keeps them: dynamics.continue_run)
        from hsbearing.systems.angular_contact.dynamics import thermal_film_attrs

        Ti, To = kw["race_temperatures"]
        ds.attrs.update(contact_temperatures=(
            "hsbearing.simulate(thermal=True): inner race contacts at (T_inner_ring + T_balls)/2, outer at "
            "(T_outer_ring + T_balls)/2 of the thermal network; drag and the initial state at its lubricant "
            "temperature (lubricant.temperature of case_toml); the guide-land and pocket films at their thermal "
            "factors (thermal_cage_film_rule)"),
            thermal_inner_contact_inlet_temperature=Ti, thermal_outer_contact_inlet_temperature=To,
            **thermal_film_attrs(films, c))
    if extend:
        from hsbearing.systems.angular_contact.extend import DEFAULT_BUDGET_FACTOR, extend_until_determined

        d = duration if duration is not None else float(c.simulation.duration)
        if budget is None:
            budget = DEFAULT_BUDGET_FACTOR * d
        elif not budget >= d:
            raise CaseError("max_duration", "max_duration", f"must be at least the run's duration {d:g} s")
        ds = extend_until_determined(ds, budget, progress=progress)
    return ds


def _thermal_start(case):
    """The case at the lubricant temperature of its thermal equilibrium, the inner and outer race contacts' inlet
    temperatures (T_ir + T_b)/2, (T_or + T_b)/2 [K] (``hsbearing run --thermal``; rating.race_inlet_temperatures), and
    the guide-land and pocket films' thermal factors between the network's wall temperatures
    (dynamics.thermal_cage_film_factors, as ``hsbearing friction --thermal``)."""
    from hsbearing.systems.angular_contact.thermal import check_inputs, thermal_equilibrium, wall_temperatures

    check_inputs(case)
    th = thermal_equilibrium(case)
    if th.attrs["status"] != "ok":
        raise CaseError(case.source, "lubricant.oil_flow_rate", th.attrs.get("error") or
                        f"the thermal fixed point did not converge in {int(th.fixed_point_iterations)} iterations "
                        "(thermal.max_iterations, thermal.tolerance)")
    from hsbearing.systems.angular_contact.rating import race_inlet_temperatures

    races = race_inlet_temperatures(float(th.inner_ring_temperature), float(th.outer_ring_temperature),
                                    float(th.ball_temperature))
    from hsbearing.systems.angular_contact.dynamics import thermal_cage_film_factors

    ct = case.with_overrides(**{"lubricant.temperature": f"{float(th.lubricant_temperature)!r} K"})
    return ct, races, thermal_cage_film_factors(ct, wall_temperatures(th), races)


@_api
def quasi_static(case, *, overrides=None, inner_speed=None, centrifugal: bool = True, gyroscopic: bool = True,
                 initial=None):
    """High-speed quasi-static equilibrium of the case (Jones-Harris) as a Dataset over ``ball``
    (``hsbearing quasistatic CASE``).

    Parameters
    ----------
    case : Case, str or path
        A :class:`Case`, a bundled case name or a case file path.
    overrides : dict, optional
        Case values ``{"axial_load": "2 kN", "oil": "4106"}``: unit strings, pint Quantities or SI floats
        (``--set``).
    inner_speed : str, pint.Quantity or float, optional
        Inner-ring speed: ``"10000 rpm"``, a Quantity or rad/s; None = ``operating.inner_speed``.
    centrifugal, gyroscopic : bool, default True
        The ball inertia effects (both False: the static solution).
    initial : xarray.Dataset, optional
        A previous solution to start the Newton iteration from (speed continuation).

    Returns
    -------
    xarray.Dataset over ``ball``: contact loads, angles, speeds, film, pressure; ``attrs["warnings"]``.

    Raises
    ------
    CaseError
        Bad input.  SolverError: the Newton iteration did not converge (``.partial``).
    TypeError
        An unknown keyword.

    Examples
    --------
    The default case: 11 balls at 1 kN axial load share it equally (about 182 N at the inner contact):

    >>> import hsbearing
    >>> qs = hsbearing.quasi_static("zhang2016")  # doctest: +SKIP
    >>> print(f"{float(qs.inner_contact_load[0]):.1f} N")  # doctest: +SKIP
    182.0 N
    """
    from hsbearing.systems.angular_contact import quasistatic

    return quasistatic.solve_case(as_case(case, overrides), inner_speed=_quantity(inner_speed, "angular_speed",
                                                                                   "inner_speed"),
                                  centrifugal=centrifugal, gyroscopic=gyroscopic, initial=initial)


@_api
def sweep(case, vary, *, out_dir, kind: str = "run", overrides=None, zip: bool = False,  # noqa: A002 - the CLI's --zip
          duration=None, stop=None, jobs: int | None = None, scheduler: str | None = None, keep: str = "answer",
          retry_failed: bool = False, progress: bool = True, point_fn=None):
    """Runs over varied case keys, one Dataset with a dim per key (``hsbearing sweep CASE --vary ...``); see
    :func:`hsbearing.workflows.sweeps.run_sweep`.

    Parameters
    ----------
    case : Case, str or path
        A :class:`Case`, a bundled case name or a case file path.
    vary : dict
        ``{key: values}``: ``{"axial_load": ["500 N", "1 kN"], "oil": "4109,4106"}`` (``--vary``); values a list
        of unit strings, pint Quantities, SI floats or names, or one CLI string ``"100,500,1000N"``.
    out_dir : str or path
        Directory of the point archives and ``sweep.nc`` (``-o``); a rerun resumes from it.
    kind : {"run", "quasistatic", "thermal"}, default "run"
        What each point computes (``--kind``).
    overrides : dict, optional
        Case values held fixed over the sweep (``--set``).
    zip : bool, default False
        Vary the keys together (equal-length lists, one dim ``point``) instead of the product (``--zip``).
    duration : str, pint.Quantity or float, optional
        Simulated time of each run (kind "run"; ``--duration``); None = the case's.
    stop : {"duration", "converged"}, optional
        Stop rule of each run (``--stop``); None = ``[simulation] stop``.
    jobs : int, optional
        Local worker processes (``-j``; default the number of cores, 1 = in this process).
    scheduler : str, optional
        ``"tcp://host:port"`` of a dask.distributed scheduler (``--scheduler``; ``jobs`` is then ignored).
    keep : {"answer", "full"}, default "answer"
        What each point archive keeps (``--keep``).
    retry_failed : bool, default False
        Recompute points whose archive records a status other than ok.
    progress : bool, default True
        tqdm progress bar on stderr.
    point_fn : callable, optional
        ``f(case, duration) -> Dataset`` replacing the computation (module level, picklable; part of the hash).

    Returns
    -------
    xarray.Dataset, also written to ``out_dir/sweep.nc``.

    Raises
    ------
    CaseError
        Bad input (a key, a value, the output directory).  SolverError: every point failed.
    TypeError
        An unknown keyword.

    Examples
    --------
    >>> import hsbearing
    >>> sw = hsbearing.sweep("zhang2016", {"operating.axial_load": ["500 N", "1 kN"]},
    ...                      kind="quasistatic", out_dir="runs/fa")  # doctest: +SKIP
    """
    from hsbearing.workflows import sweeps

    if overrides or stop is not None:
        case = as_case(case, overrides)
        if stop is not None and stop != case.simulation.stop:  # as the CLI: the same archives (hashes) as without
            case = case.with_overrides(**{"simulation.stop": stop})
    return sweeps.run_sweep(case, vary, zip=zip, jobs=jobs, scheduler=scheduler, out_dir=out_dir, kind=kind,
                            duration=_quantity(duration, "time", "duration"), progress=progress, point_fn=point_fn,
                            retry_failed=retry_failed, keep=keep)


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
