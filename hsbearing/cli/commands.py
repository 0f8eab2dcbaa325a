"""One function per subcommand (``cmd_run``, ``cmd_sweep``, ...), each calling the library function of the same name and printing its answer."""

from __future__ import annotations

import sys
from pathlib import Path

from hsbearing import systems
from hsbearing.case import CaseError, list_cases, load_case, parse_quantity, parse_sets
from hsbearing.cli.common import case_from_args, default_output, print_summary
from hsbearing.errors import OutputWriteError, SolverError

# ----------------------------------------------------------------------------- commands


def cmd_cases(args) -> int:
    for name, desc in list_cases().items():
        print(f"{name:22s} {desc}")
    return 0


def cmd_check(args) -> int:
    from hsbearing.models import geometry

    case = case_from_args(args)
    print(f"case {case.name} ({case.system}) from {case.source}: valid")
    for line in geometry.describe(case):
        print("  " + line)
    from hsbearing import lubricant

    for line in lubricant.describe(case):  # the oil at the case temperature; a warning if alpha is estimated
        print("  " + line)
    return 0


def cmd_oils(args) -> int:
    """``hsbearing oils``: the bundled lubricants; ``hsbearing oils NAME --at CASE``: one oil at a case."""
    from hsbearing.cli import oils

    if getattr(args, "template", None):
        if args.name or args.at:
            raise CaseError("--template", None, "takes no lubricant NAME and no --at: hsbearing oils --template FILE")
        from hsbearing.results import check_output_path

        check_output_path(args.template, source="--template")
        path = oils.write_template(args.template)
        print(f"lubricant template: {path} (format: docs/traction.md, 'Lubricant files'); fill in your oil's data, "
              f"check it with 'hsbearing oils {path}' and use it with --set lubricant.file={path}")
        return 0
    if args.name is None:
        if args.at:
            raise CaseError("--at", None, "give the lubricant: hsbearing oils NAME --at CASE")
        for line in oils.format_library(oils.library_rows()):
            print(line)
        return 0
    if not args.at:
        from hsbearing import lubricant

        path = lubricant.resolve_lubricant(args.name)
        if path is None:
            raise CaseError(args.name, None, lubricant.unresolved_message(args.name))
        d = lubricant.load_lubricant(path)
        print(f"{d.name} ({d.oil_class}) from {path}")
        print(d.text.rstrip())
        if d.traction_model == "zhang2016":
            print(f"notice: the traction of {d.name} is borrowed from oil {d.traction_oil} (law {d.traction_law})")
        if d.alpha_estimated:
            print(f"notice: the pressure-viscosity coefficient alpha of {d.name} is estimated ({d.alpha_estimate} "
                  "correlation), not measured")
        return 0
    if args.output:
        from hsbearing.results import check_output_path

        check_output_path(args.output)
    case, qs, derived = oils.at_case(args.name, args.at, parse_sets(args.set))
    for line in oils.format_at_case(case, derived):
        print(line)
    stem = Path(args.name).stem
    out = Path(args.output) if args.output else Path("runs") / f"oil-{stem}-{case.name}.png"
    oils.plot_traction(case, qs, out)
    print(f"figure: {out}")
    return 0


def _duration_arg(text: str | None) -> float | None:
    if not text:
        return None
    duration = parse_quantity(text, "time", source="--duration", key="duration")
    if not duration > 0:
        raise CaseError("--duration", "duration", f"must be positive, got {text!r}")
    return duration


def _keep_interrupted(partial, out: Path) -> int:
    """Ctrl-C: keep what was computed (status "interrupted at t = ..."), say how to go on, exit 130."""
    from hsbearing.results import deferred_sigint, write_netcdf

    if partial is not None and partial.sizes.get("time", 0) > 1:
        t = float(partial["time"].values[-1])
        partial = partial.copy()
        partial.attrs["status"] = f"interrupted at t = {t:.6g} s"  # also for integrators that say "failed ...: interrupted"
        with deferred_sigint():  # a second Ctrl-C during the save must not drop the partial run
            write_netcdf(partial, out)
        hint = f" (continue it: hsbearing run --continue {out})" if "final_state" in partial else ""
        print(f"hsbearing: interrupted at t = {t:.6g} s; partial run in {out}{hint}", file=sys.stderr)
    else:
        print("hsbearing: interrupted (nothing computed yet, nothing written)", file=sys.stderr)
    return 130


def _is_interrupt_failure(exc: SolverError) -> bool:
    return str(exc).rstrip().endswith("interrupted")  # an integrator's Ctrl-C status (e.g. the gyro model's)


def cmd_run(args) -> int:
    from hsbearing import simulate
    from hsbearing.case import check_output_samples
    from hsbearing.errors import Interrupted
    from hsbearing.results import check_archive_name, check_output_path

    if getattr(args, "continue_from", None):
        return _cmd_continue(args)
    case = case_from_args(args)
    if getattr(args, "thermal", False):  # start at the thermal equilibrium's lubricant temperature (docs/thermal.md)
        from hsbearing.systems.angular_contact.thermal import thermal_equilibrium

        th = thermal_equilibrium(case)
        if th.attrs["status"] != "ok":  # no steady state to start from: say so before any dynamics is computed
            from hsbearing.errors import CaseError

            raise CaseError(case.source, "lubricant.oil_flow_rate", th.attrs.get("error") or
                            f"the thermal fixed point did not converge in {int(th.fixed_point_iterations)} iterations "
                            "(thermal.max_iterations, thermal.tolerance)")
        T = float(th.lubricant_temperature)
        print(f"thermal equilibrium: lubricant temperature {T - 273.15:.3f} degC (oil outlet "
              f"{float(th.oil_outlet_temperature) - 273.15:.3f} degC, {float(th.heat_generated):.4g} W); the run uses it")
        from hsbearing.systems.angular_contact.rating import race_inlet_temperatures

        race_T = race_inlet_temperatures(float(th.inner_ring_temperature), float(th.outer_ring_temperature),
                                         float(th.ball_temperature))
        print(f"contact inlet temperatures: inner race {race_T[0] - 273.15:.3f} degC, outer race "
              f"{race_T[1] - 273.15:.3f} degC ((T_ring + T_ball)/2 of each race)")
        case = case.with_overrides(**{"lubricant.temperature": f"{T} K"})
        # the guide-land and pocket films between the network's wall temperatures, as friction --thermal: their
        # thermal factors eta_eff / eta_film at the quasi-static state, constants of the run
        from hsbearing.systems.angular_contact.dynamics import thermal_cage_film_factors, thermal_film_attrs
        from hsbearing.systems.angular_contact.thermal import wall_temperatures

        films = thermal_cage_film_factors(case, wall_temperatures(th), race_T)
        film_f = (films["land"]["factor"], films["pocket"]["factor"])
        print(f"cage films: guide land x {film_f[0]:.4g}, pocket x {film_f[1]:.4g} of the isothermal viscosity "
              "(their film temperature at the quasi-static state, friction.thermal_films)")
        # which temperatures the run used: each race's contacts at its own inlet temperature; the drag and the
        # initial state at the network's lubricant temperature; the cage films at their thermal factors
        thermal_attrs = {
            "contact_temperatures": ("hsbearing run --thermal, from the thermal network's equilibrium: inner race "
                                     "contacts at thermal_inner_contact_inlet_temperature = "
                                     f"(T_inner_ring + T_balls)/2 = {race_T[0]:.6g} K, outer race contacts at "
                                     f"thermal_outer_contact_inlet_temperature = (T_outer_ring + T_balls)/2 = {race_T[1]:.6g} K "
                                     "(the inlet oil between the ball and that race's surface); drag and the initial "
                                     "state at the network's lubricant temperature "
                                     f"(T_inner_ring + T_outer_ring + 2 T_balls)/4 = {T:.6g} K (lubricant.temperature of "
                                     "case_toml), the guide-land and pocket film viscosities times their thermal factors "
                                     "(thermal_cage_film_rule); a --continue or --extend of this archive keeps "
                                     "the two inlet temperatures and the two film factors (these attrs)"),
            "thermal_lubricant_temperature": T,
            "thermal_inner_contact_inlet_temperature": race_T[0],
            "thermal_outer_contact_inlet_temperature": race_T[1],
            **{f"thermal_{k}": float(th[k]) for k in ("inner_ring_temperature", "outer_ring_temperature", "ball_temperature",
                                                      "cage_temperature", "oil_outlet_temperature")},
            **thermal_film_attrs(films, case),
        }
    else:
        thermal_attrs = {}
    duration = _duration_arg(args.duration)
    if duration is not None:
        check_output_samples(case, duration, source="--duration", key="duration")
    budget = _extend_budget(args, case, duration)
    out = Path(args.output) if args.output is not None else default_output(case, ".nc", f"duration={duration}")
    check_output_path(out, source="-o" if args.output is not None else "output", derived=_run_figures(out, args))
    check_archive_name(args.output)  # one suffix rule for every command's -o archive
    try:
        if thermal_attrs:  # each race's contacts at its own inlet temperature (dynamics.build_model)
            from hsbearing import systems

            ds = systems.simulate(case, duration=duration, progress=not args.quiet, race_temperatures=race_T,
                                  cage_film_factors=film_f)
        else:
            ds = simulate(case, duration=duration, progress=not args.quiet)
        ds.attrs.update(thermal_attrs)
        if budget is not None:
            from hsbearing.systems.angular_contact.extend import extend_until_determined

            ds = extend_until_determined(ds, budget, progress=not args.quiet)
            print(f"extension: {ds.attrs['extension_stop_reason']}")
    except Interrupted as exc:
        return _keep_interrupted(exc.partial, out)
    except SolverError as exc:
        return _run_failed(exc, out)
    return _finish_run(ds, out, args)


def _extend_budget(args, case, duration) -> float | None:
    """The --max-duration of ``hsbearing run --extend`` [s] (None without --extend); bad input exits 2 before any run."""
    from hsbearing.case import check_output_samples
    from hsbearing.systems.angular_contact.extend import DEFAULT_BUDGET_FACTOR
    from hsbearing.workflows.sweeps.cli import extend_request

    text = extend_request(args, case)
    if text is None:
        return None
    d = duration if duration is not None else float(case.simulation.duration)
    if text == "default":
        return DEFAULT_BUDGET_FACTOR * d
    budget = parse_quantity(text, "time", source="--max-duration", key="max_duration")
    if not budget >= d:
        raise CaseError("--max-duration", "max_duration", f"must be at least the run's duration {d:g} s, got {text!r}")
    check_output_samples(case, budget, source="--max-duration", key="max_duration")
    return budget


def _run_figures(out: Path, args) -> list[Path]:
    """The figures a run writes next to its archive (checked with the archive before the compute)."""
    if getattr(args, "no_plot", False):
        return []
    from hsbearing.systems.angular_contact.lock_figure import lock_figure_path
    from hsbearing.systems.angular_contact.power_figure import power_figure_path

    png = out.with_suffix(".png")
    return [png, power_figure_path(png), lock_figure_path(png)]


def _run_failed(exc, out: Path) -> int:
    """A run (or its continuation) that stopped: an interrupt reported as a solver failure exits 130 with the
    partial run kept; a numerical failure writes the partial result (if any) and exits 1."""
    from hsbearing.results import deferred_sigint, write_netcdf

    if _is_interrupt_failure(exc):
        return _keep_interrupted(exc.partial, out)
    if exc.partial is not None:
        with deferred_sigint():
            write_netcdf(exc.partial, out)
        print(f"hsbearing: numerical failure: {exc}; partial result in {out}", file=sys.stderr)
    else:
        print(f"hsbearing: numerical failure: {exc}", file=sys.stderr)
    return 1


def _finish_run(ds, out: Path, args) -> int:
    from hsbearing.results import write_netcdf

    try:
        write_netcdf(ds, out)
    except OutputWriteError:
        print_summary(ds, None)  # the numbers are printed; the archive went to the fallback the error names
        raise
    print_summary(ds, out)
    if not args.no_plot:
        png = systems.plot_run(ds, out.with_suffix(".png"))
        if png:
            print(f"figure: {png}")
        _power_figure(ds, out.with_suffix(".png"))
    return 0


def _power_figure(ds, run_png: Path) -> None:
    """Second and third figures of a dynamic run: power loss by source and drive torque
    (hsbearing.systems.angular_contact.power_figure), and the whirl-cage lock/drift with the clock section
    (hsbearing.systems.angular_contact.lock_figure)."""
    from hsbearing.systems.angular_contact import lock_figure
    from hsbearing.systems.angular_contact import power_figure as plotting_power

    if plotting_power.has_power(ds):
        print(f"figure: {plotting_power.plot_power(ds, plotting_power.power_figure_path(run_png))}")
    if lock_figure.has_lock(ds) and "classification" in ds.attrs and ds.attrs.get("model") != "gyro_ribbon_cage":
        print(f"figure: {lock_figure.plot_lock(ds, lock_figure.lock_figure_path(run_png))}")


def _cmd_continue(args) -> int:
    """``hsbearing run --continue ARCHIVE.nc [--duration T] [-o OUT.nc]``: extend a run from its last state."""
    from hsbearing.errors import Interrupted
    from hsbearing.results import check_archive_name, check_output_path, open_run
    from hsbearing.systems.angular_contact import dynamics

    src = Path(args.continue_from)
    if args.case or args.set:
        raise CaseError("--continue", None, "takes no CASE and no --set: the run goes on with the case stored in the archive")
    if getattr(args, "extend", False) or getattr(args, "max_duration", None):
        raise CaseError("--continue", None, "takes no --extend / --max-duration: give --duration to extend by")
    if not src.is_file():
        raise CaseError(str(src), None, "no such archive" if not src.exists() else "not a file")
    prev = open_run(src)  # CaseError naming the file for anything that is not an hsbearing archive
    out = Path(args.output) if args.output is not None else src
    check_output_path(out, source="-o" if args.output is not None else "--continue", derived=_run_figures(out, args))
    check_archive_name(args.output)
    try:
        ds = dynamics.continue_run(prev, _duration_arg(args.duration), progress=not args.quiet, source=str(src))
    except Interrupted as exc:
        return _keep_interrupted(exc.partial, out)
    except SolverError as exc:
        return _run_failed(exc, out)
    return _finish_run(ds, out, args)


def cmd_quasistatic(args) -> int:
    from hsbearing import quasi_static
    from hsbearing.results import check_archive_name, check_output_path, write_netcdf

    case = case_from_args(args)
    if args.output is not None:
        check_output_path(args.output)
    check_archive_name(args.output)  # one suffix rule for every command's -o archive
    try:
        ds = quasi_static(case)
    except SolverError as exc:
        if exc.partial is not None and args.output is not None:
            write_netcdf(exc.partial, args.output)
            print(f"hsbearing: numerical failure: {exc}; partial result in {args.output}", file=sys.stderr)
        else:
            print(f"hsbearing: numerical failure: {exc}", file=sys.stderr)
        return 1
    from hsbearing.systems.angular_contact import quasistatic

    quasistatic.print_summary(ds)
    from hsbearing.display import contact_pressure_warning

    p_all = [ds[n].values for n in ("inner_contact_pressure", "outer_contact_pressure") if n in ds]
    warn = contact_pressure_warning(p_all) if p_all else None
    if warn:
        print(warn, file=sys.stderr)
    qs_warns = _quasistatic_warnings(case, ds)
    for w in qs_warns:  # the limits run, friction and life print for the same state
        print(f"warning: {w}")
    have = [w for w in str(ds.attrs.get("warnings", "none")).split(" | ") if w and w != "none"]
    if qs_warns or have:  # the archive carries every line printed (the case envelope is already in it)
        ds.attrs["warnings"] = " | ".join(have + [w for w in qs_warns if w not in have])
    if args.output is not None:
        write_netcdf(ds, args.output)
        print(f"archive: {args.output}")
    return 0


def _quasistatic_warnings(case, ds) -> list[str]:
    """Contact-state warnings of a quasi-static state (shoulder truncation, film parameter), as ``friction``
    prints them (:func:`hsbearing.systems.angular_contact.contact_state.warnings_for`); the ISO 76 pressure line is printed on stderr."""
    from hsbearing.systems.angular_contact import contact_state

    try:
        state = contact_state.quasi_static_contact_state(case, ds)
        lines = contact_state.warnings_for(ds.assign(**{k: ("ball", v) for k, v in state.items()}), case)
    except (KeyError, ValueError):  # a system whose quasi-static Dataset lacks the contact variables
        return []
    return [w for w in lines if "ISO 76" not in w]  # the ISO 76 line is printed on stderr (display)


def _summary_figure(nc: Path, png: Path) -> None:
    """Draw the figure of a sweep/study summary next to it; a figure that cannot be drawn is a note, not a failure."""
    from hsbearing import plotting
    from hsbearing.results import open_run

    if not nc.exists():
        return
    try:
        print(f"figure: {plotting.plot_sweep(open_run(nc), png)}")
    except Exception as exc:  # noqa: BLE001 - the archives are written; the figure is a by-product, never the exit code
        print(f"hsbearing: no figure for {nc}: {exc}", file=sys.stderr)


def cmd_compare(args) -> int:
    from hsbearing.workflows.compare.cli import cli_main

    return cli_main(args)


def cmd_sweep(args) -> int:
    from hsbearing.results import check_output_path
    from hsbearing.workflows import sweeps

    out = Path(args.output)
    check_output_path(out, directory=True, derived=[out / "sweep.nc"] + ([] if args.no_figure else [out / "sweep.png"]))
    if args.scheduler:
        sweeps.check_scheduler_address(args.scheduler)

    rc = sweeps.cli_main(args)
    if not getattr(args, "no_figure", False):
        out = Path(args.output)
        _summary_figure(out / "sweep.nc", out / "sweep.png")
    return rc


def cmd_map(args) -> int:
    from hsbearing.workflows import maps

    return maps.cli_main(args)


def cmd_study(args) -> int:
    from hsbearing.results import check_output_path
    from hsbearing.workflows import study, sweeps

    out = Path(args.output)
    derived = [out / "report.md", out / "report_bands.md"]
    for t in study.load_study(args.name).tables:  # an unknown study is refused here, before anything else
        derived += [out / f"{t['id']}.nc", out / f"{t['id']}.png", out / f"{t['id']}_bands.nc"]
    check_output_path(out, directory=True, derived=derived)
    if args.scheduler:
        sweeps.check_scheduler_address(args.scheduler)

    rc = study.cli_main(args, run_study=study.run_study)  # looked up here: the package's name is the API
    if not getattr(args, "no_figure", False) and not getattr(args, "bands", False):  # banded tables: report figures
        out = Path(args.output)
        for t in study.load_study(args.name).tables:
            if getattr(args, "tables", None) and t["id"] not in args.tables:
                continue
            _summary_figure(out / f"{t['id']}.nc", out / f"{t['id']}.png")
    return rc


def _check_output_option(args) -> None:
    from hsbearing.results import check_output_path

    if getattr(args, "output", None) is not None:
        check_output_path(args.output)


def cmd_friction(args) -> int:
    from hsbearing import systems  # dispatch by [case] system: every ball-bearing case answers

    _check_output_option(args)
    case = load_case(args.case, **parse_sets(getattr(args, "set", None)))
    out = getattr(args, "output", None)
    system = systems.get(case)
    if getattr(args, "thermal", False):
        from hsbearing.systems.angular_contact.rating import require_angular_contact
        from hsbearing.systems.angular_contact.thermal import check_inputs

        require_angular_contact(case, "--thermal needs the thermal network of an angular-contact bearing",
                                source="--thermal", key="thermal")
        check_inputs(case)  # the network's inputs (oil flow, ring dimensions): exit 2 before any compute
    if system.friction_archive:
        from hsbearing.results import check_archive_name

        check_archive_name(out)
    return system.friction(case, args)


def cmd_thermal(args) -> int:
    from hsbearing.systems.angular_contact import thermal

    _check_output_option(args)
    return thermal.thermal_cli(args)


def cmd_life(args) -> int:
    from hsbearing.systems.angular_contact import rating

    _check_output_option(args)
    return rating.life_cli(args)


def cmd_preload(args) -> int:
    from hsbearing.systems import wire_race

    _check_output_option(args)
    return wire_race.preload_command(case_from_args(args), args)


def _check_figure_format(output) -> None:
    """The figure format is the file suffix; refuse one matplotlib cannot write (before anything is drawn)."""
    from matplotlib.backend_bases import FigureCanvasBase

    fmt = Path(output).suffix.lstrip(".").lower() or "png"
    kinds = FigureCanvasBase.get_supported_filetypes()
    if fmt not in kinds:
        raise CaseError(f"-o {output}", None, f"figure format {fmt!r} is not supported (use one of: "
                                              f"{', '.join(sorted(kinds))})")


def cmd_plot(args) -> int:
    from hsbearing.results import open_run

    path = Path(args.archive)
    if not path.exists():
        raise CaseError(str(path), None, "no such archive")
    _check_output_option(args)
    if args.output is not None:
        _check_figure_format(args.output)
    try:
        ds = open_run(path)
    except CaseError as exc:  # not ours: the plot command's own words (the file is named either way)
        if exc.message.startswith(("not an hsbearing archive", "an hsbearing archive with no variables")):
            raise CaseError(str(path), None, systems.NOT_OURS) from None
        raise
    try:  # a sweep/study summary (one dimension per varied key) gets the sweep figure (plotting.plot_sweep)
        png = systems.plot_run(ds, Path(args.output) if args.output else path.with_suffix(".png"))
    except CaseError as exc:  # e.g. a summary with too many lines for one figure: name the archive
        raise CaseError(str(path), exc.key, exc.message) from None
    print(f"figure: {png}")
    if systems.archive_kind(ds) == "run":
        _power_figure(ds, Path(png))
    return 0
