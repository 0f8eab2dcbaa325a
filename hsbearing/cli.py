"""The ``hsbearing`` command: a thin layer over the library (the same functions, the same names).

Exit codes: 0 success; 2 bad input (one line naming the file and the key,
nothing written); 1 numerical failure (partial result kept, status says why).
"""

from __future__ import annotations

import argparse
import hashlib
import sys
from pathlib import Path

from hsbearing._version import __version__
from hsbearing.case import DEFAULT_CASE, CaseError, list_cases, load_case, parse_quantity, parse_sets
from hsbearing.errors import OutputWriteError, SolverError


class _UsageError(Exception):
    pass


_parse_sets = parse_sets  # the older name (hsbearing.case.parse_sets)


def _load(args) -> "object":
    sets = _parse_sets(getattr(args, "set", None))
    case = load_case(args.case or DEFAULT_CASE, **sets)
    # --stop RULE / --section NAME are --set simulation.stop / simulation.section, set only when they change the
    # case (a default left out of the TOML keeps the archive hashes)
    extra = {}
    stop, section = getattr(args, "stop", None), getattr(args, "section", None)
    if stop and stop != case.simulation.stop:
        extra["simulation.stop"] = stop
    if section and section != case.simulation.section:
        extra["simulation.section"] = section
    if extra:
        case = load_case(args.case or DEFAULT_CASE, **sets, **extra)
    _print_envelope_warnings(case)
    return case


def _print_envelope_warnings(case) -> None:
    """Values that are possible but outside the data behind the model (e.g. an oil beyond its service range)."""
    from hsbearing.case import envelope_warnings

    for w in envelope_warnings(case):
        print(f"hsbearing: warning: {case.source}: {w}", file=sys.stderr)


def _default_out(case, suffix: str, extra: str = "") -> Path:
    h = hashlib.sha1((case.to_toml() + extra).encode()).hexdigest()[:10]
    return Path("runs") / f"{case.name}-{h}{suffix}"


def _print_summary(ds, out: Path | None = None) -> None:
    """The scalars of a run in the units users read (hsbearing.display), with the reasons behind values
    that are not defined (parked cage, undetermined classification) and the whirl radius explained."""
    import numpy as np

    from hsbearing.display import format_solver_stats, format_value

    print(f"status: {ds.attrs.get('status', '?')}")
    note = None
    if "whirl_frequency_ratio" in ds:
        try:
            from hsbearing.analysis.orbit import whirl_ratio_note

            note = whirl_ratio_note(ds)
        except Exception:  # noqa: BLE001 - the value is printed as stored
            note = None
    gc = ds.attrs.get("guide_clearance")
    for name, var in ds.data_vars.items():
        if var.ndim != 0:
            continue
        text = format_value(var, name)
        if name == "whirl_frequency_ratio" and note:
            text = f"not defined ({note})"
        elif _is_nan(var):  # never a bare "nan" with exit 0: say why the value is not defined
            text = f"n/a ({_nan_reason(name, ds)})"
        elif name in ("whirl_amplitude", "whirl_radius_max"):
            text += " (RMS radius of the cage mass-centre orbit)" if name == "whirl_amplitude" else ""
            r = float(var.values)
            if name == "whirl_radius_max" and gc is not None and np.isfinite(r) and r > float(gc):
                text += (f" (cage centre {(r - float(gc)) * 1e6:.2g} \u00b5m beyond the {float(gc) * 1e6:.0f} \u00b5m "
                         "guide clearance: elastic penetration of the cage-land rub contact)")
        print(f"{name}: {text}")
    from hsbearing.systems import for_archive

    system = for_archive(ds)  # the system's own lines: gyro start ensemble; drive torque and power loss by source
    for line in (system.summary_lines(ds) if system is not None else []):
        print(line)
    if ds.attrs.get("warnings", "none") != "none":  # contact/film/cage limits (hsbearing.contact_state)
        for w in str(ds.attrs["warnings"]).split(" | "):
            print(f"warning: {w}")
    if "classification" in ds.attrs:
        cls = ds.attrs["classification"]
        reason = ds.attrs.get("classification_reason", "")
        kind = ds.attrs.get("poincare_section_kind", "")
        if cls == "undetermined":
            print(f"classification: undetermined ({reason})" if reason else "classification: undetermined")
        else:
            conf = ds.attrs.get("classification_confidence")
            det = ds.attrs.get("classification_detail", "")
            print(f"classification: {cls}" + (f", {det}" if det else "")
                  + (f" (confidence {float(conf):.2f})" if conf is not None else ""))
        if ds.attrs.get("poincare_section"):
            print(f"section: {kind + ' -- ' if kind else ''}{ds.attrs['poincare_section']}")
        alt = ds.attrs.get("classification_alternative")
        if alt:
            print(f"classification on the {ds.attrs.get('classification_alternative_section', 'other')} section: {alt}")
        if ds.attrs.get("whirl_cage_lock"):
            print(f"whirl-cage lock: {ds.attrs['whirl_cage_lock']}")
        try:
            import json as _json

            det = _json.loads(ds.attrs.get("classification_details", "{}"))
        except ValueError:
            det = {}
        if det.get("modulation_y") is not None and det.get("modulation_vy") is not None:
            print(f"section spread (modulation amplitude the label does not resolve): D_Y "
                  f"{det['modulation_y'] * 1e6:.3g} \u00b5m, V_Y {det['modulation_vy'] * 1e3:.3g} mm/s")
    stats = {k[len("solver_"):]: v for k, v in ds.attrs.items()
             if k.startswith("solver_") and not k.endswith("_units")}  # the NAME_units companions are not stats
    if stats:
        print("solver: " + format_solver_stats(stats))
    if out is not None:
        print(f"archive: {out}")


def _is_nan(var) -> bool:
    import numpy as np

    try:
        return var.dtype.kind == "f" and bool(np.isnan(var.values))
    except (TypeError, ValueError):
        return False


def _nan_reason(name: str, ds) -> str:
    """Why a summary scalar of a run is not defined (printed instead of "nan")."""
    if name == "sfmo" or name.startswith("sfmo_"):
        import tomllib

        try:
            mode = tomllib.loads(str(ds.attrs.get("case_toml", ""))).get("operating", {}).get("mode", "constant")
        except tomllib.TOMLDecodeError:
            mode = "?"
        if mode != "oscillation":
            return "SFMO is the starting moment under oscillation: operating.mode = oscillation"
        return "SFMO needs at least two reversal windows: simulate longer than two oscillation periods"
    if name.startswith("whirl_") or name == "mean_cage_speed":
        n = int(ds.sizes.get("time", 0))
        return (f"fewer than 16 cage-centre samples after the transient ({n} samples in the run): simulate longer "
                "or sample more often")
    if name.startswith("sfmc") or name == "rfmc":
        return "no complete starting window in the run: simulate longer"
    return "not defined for this run"


# ----------------------------------------------------------------------------- commands


def cmd_cases(args) -> int:
    for name, desc in list_cases().items():
        print(f"{name:22s} {desc}")
    return 0


def cmd_check(args) -> int:
    from hsbearing.models import geometry

    case = _load(args)
    print(f"case {case.name} ({case.system}) from {case.source}: valid")
    for line in geometry.describe(case):
        print("  " + line)
    from hsbearing import lubricant

    for line in lubricant.describe(case):  # the oil at the case temperature; a warning if alpha is estimated
        print("  " + line)
    return 0


def cmd_oils(args) -> int:
    """``hsbearing oils``: the bundled lubricants; ``hsbearing oils NAME --at CASE``: one oil at a case."""
    from hsbearing import oils

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
        return 0
    if args.output:
        from hsbearing.results import check_output_path

        check_output_path(args.output)
    case, qs, derived = oils.at_case(args.name, args.at, _parse_sets(args.set))
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
    from hsbearing.results import check_output_path

    if getattr(args, "continue_from", None):
        return _cmd_continue(args)
    case = _load(args)
    if getattr(args, "thermal", False):  # start at the thermal equilibrium's lubricant temperature (docs/thermal.md)
        from hsbearing.thermal import thermal_equilibrium

        th = thermal_equilibrium(case)
        if th.attrs["status"] != "ok":  # no steady state to start from: say so before any dynamics is computed
            from hsbearing.errors import CaseError

            raise CaseError(case.source, "lubricant.oil_flow_rate", th.attrs.get("error") or
                            f"the thermal fixed point did not converge in {int(th.fixed_point_iterations)} iterations "
                            "(thermal.max_iterations, thermal.tolerance)")
        T = float(th.lubricant_temperature)
        print(f"thermal equilibrium: lubricant temperature {T - 273.15:.3f} degC (oil outlet "
              f"{float(th.oil_outlet_temperature) - 273.15:.3f} degC, {float(th.heat_generated):.4g} W); the run uses it")
        case = case.with_overrides(**{"lubricant.temperature": f"{T} K"})
    duration = _duration_arg(args.duration)
    if duration is not None:
        check_output_samples(case, duration, source="--duration", key="duration")
    out = Path(args.output) if args.output is not None else _default_out(case, ".nc", f"duration={duration}")
    check_output_path(out, source="-o" if args.output is not None else "output", derived=_run_figures(out, args))
    try:
        ds = simulate(case, duration=duration, progress=not args.quiet)
    except Interrupted as exc:
        return _keep_interrupted(exc.partial, out)
    except SolverError as exc:
        return _run_failed(exc, out)
    return _finish_run(ds, out, args)


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
    from hsbearing.errors import OutputWriteError
    from hsbearing.results import write_netcdf

    try:
        write_netcdf(ds, out)
    except OutputWriteError:
        _print_summary(ds, None)  # the numbers are printed; the archive went to the fallback the error names
        raise
    _print_summary(ds, out)
    if not args.no_plot:
        from hsbearing import plotting

        png = plotting.plot_run(ds, out.with_suffix(".png"))
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
    from hsbearing import dynamics
    from hsbearing.errors import Interrupted
    from hsbearing.results import check_output_path, open_run

    src = Path(args.continue_from)
    if args.case or args.set:
        raise CaseError("--continue", None, "takes no CASE and no --set: the run goes on with the case stored in the archive")
    if not src.is_file():
        raise CaseError(str(src), None, "no such archive" if not src.exists() else "not a file")
    try:
        prev = open_run(src)
    except Exception as exc:  # noqa: BLE001 - any netCDF/HDF failure is bad input here
        raise CaseError(str(src), None, f"not a readable netCDF archive ({type(exc).__name__})") from None
    out = Path(args.output) if args.output is not None else src
    check_output_path(out, source="-o" if args.output is not None else "--continue", derived=_run_figures(out, args))
    try:
        ds = dynamics.continue_run(prev, _duration_arg(args.duration), progress=not args.quiet, source=str(src))
    except Interrupted as exc:
        return _keep_interrupted(exc.partial, out)
    except SolverError as exc:
        return _run_failed(exc, out)
    return _finish_run(ds, out, args)


def cmd_quasistatic(args) -> int:
    from hsbearing import quasi_static
    from hsbearing.results import check_output_path, write_netcdf

    case = _load(args)
    if args.output is not None:
        check_output_path(args.output)
    try:
        ds = quasi_static(case)
    except SolverError as exc:
        if exc.partial is not None and args.output is not None:
            write_netcdf(exc.partial, args.output)
            print(f"hsbearing: numerical failure: {exc}; partial result in {args.output}", file=sys.stderr)
        else:
            print(f"hsbearing: numerical failure: {exc}", file=sys.stderr)
        return 1
    from hsbearing import quasistatic

    quasistatic.print_summary(ds)
    from hsbearing.display import contact_pressure_warning

    p_all = [ds[n].values for n in ("inner_contact_pressure", "outer_contact_pressure") if n in ds]
    warn = contact_pressure_warning(p_all) if p_all else None
    if warn:
        print(warn, file=sys.stderr)
    for w in _quasistatic_warnings(case, ds):  # the limits run, friction and life print for the same state
        print(f"warning: {w}")
    if args.output is not None:
        write_netcdf(ds, args.output)
        print(f"archive: {args.output}")
    return 0


def _quasistatic_warnings(case, ds) -> list[str]:
    """Contact-state warnings of a quasi-static state (shoulder truncation, film parameter), as ``friction``
    prints them (:func:`hsbearing.contact_state.warnings_for`); the ISO 76 pressure line is printed on stderr."""
    from hsbearing import contact_state

    try:
        state = contact_state.quasi_static_contact_state(case, ds)
        lines = contact_state.warnings_for(ds.assign(**{k: ("ball", v) for k, v in state.items()}), case)
    except (KeyError, ValueError):  # a system whose quasi-static Dataset lacks the contact variables
        return []
    return [w for w in lines if not w.startswith("maximum contact pressure")]


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


def cmd_sweep(args) -> int:
    from hsbearing import sweeps
    from hsbearing.results import check_output_path

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
    from hsbearing import maps

    return maps.cli_main(args)


def cmd_study(args) -> int:
    from hsbearing import study, sweeps
    from hsbearing.results import check_output_path

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
    if system.friction_archive:
        from hsbearing.results import check_archive_name

        check_archive_name(out)
    return system.friction(case, args)


def cmd_thermal(args) -> int:
    from hsbearing import thermal

    _check_output_option(args)
    return thermal.thermal_cli(args)


def cmd_life(args) -> int:
    from hsbearing import rating

    _check_output_option(args)
    return rating.life_cli(args)


def cmd_preload(args) -> int:
    from hsbearing.systems import wire_race

    _check_output_option(args)
    return wire_race.preload_command(_load(args), args)


def _check_figure_format(output) -> None:
    """The figure format is the file suffix; refuse one matplotlib cannot write (before anything is drawn)."""
    from matplotlib.backend_bases import FigureCanvasBase

    fmt = Path(output).suffix.lstrip(".").lower() or "png"
    kinds = FigureCanvasBase.get_supported_filetypes()
    if fmt not in kinds:
        raise CaseError(f"-o {output}", None, f"figure format {fmt!r} is not supported (use one of: "
                                              f"{', '.join(sorted(kinds))})")


def cmd_plot(args) -> int:
    from hsbearing import plotting
    from hsbearing.results import open_run

    path = Path(args.archive)
    if not path.exists():
        raise CaseError(str(path), None, "no such archive")
    _check_output_option(args)
    if args.output is not None:
        _check_figure_format(args.output)
    try:
        ds = open_run(path)
    except Exception as exc:
        raise CaseError(str(path), None, f"not a readable netCDF archive ({type(exc).__name__})") from None
    try:  # a sweep/study summary (one dimension per varied key) gets the sweep figure (plotting.plot_sweep)
        png = plotting.plot_run(ds, Path(args.output) if args.output else path.with_suffix(".png"))
    except CaseError as exc:  # e.g. a summary with too many lines for one figure: name the archive
        raise CaseError(str(path), exc.key, exc.message) from None
    print(f"figure: {png}")
    if plotting.archive_kind(ds) == "run":
        _power_figure(ds, Path(png))
    return 0


# ----------------------------------------------------------------------------- parser


class _Parser(argparse.ArgumentParser):
    """argparse with the CLI's error contract: one line ``hsbearing: error: ...`` (no usage block), exit 2."""

    def error(self, message):
        cmd = self.prog.split(" ", 1)[1] if " " in self.prog else ""
        hint = f" (see 'hsbearing {cmd} --help')" if cmd else " (see 'hsbearing --help')"
        self.exit(2, f"hsbearing: error: {message}{hint}\n")


def build_parser() -> argparse.ArgumentParser:
    p = _Parser(prog="hsbearing", description="Dynamics and friction of rolling ball bearings.")
    p.add_argument("--version", action="version", version=f"hsbearing {__version__}")
    sub = p.add_subparsers(dest="command", metavar="COMMAND", parser_class=_Parser)

    def with_case(sp, optional=True, examples=""):
        if optional:
            sp.add_argument("case", nargs="?", default=None,
                            help=f"bundled case name (see 'hsbearing cases') or path to a TOML case (default: {DEFAULT_CASE})")
        else:  # required: no default is shown (friction and preload need a case of their own system)
            sp.add_argument("case", help="bundled case name (see 'hsbearing cases') or path to a TOML case" + examples)
        sp.add_argument("--set", action="append", metavar="KEY=VALUE",
                        help='override a case value, e.g. --set operating.axial_load="2 kN" (repeatable)')

    sp = sub.add_parser("cases", help="list the bundled cases (paper, bearing, operating point)")
    sp.set_defaults(func=cmd_cases)

    sp = sub.add_parser("check", help="validate a case and print the derived geometry")
    with_case(sp)
    sp.set_defaults(func=cmd_check)

    sp = sub.add_parser("run", help=f"dynamic simulation (default case {DEFAULT_CASE}: the 7206-size angular-contact "
                                    "bearing of Zhang et al. 2016, 14000 r/min, Fa = 1 kN, oil 4109, 130 \N{DEGREE SIGN}C)")
    with_case(sp)
    sp.add_argument("-o", "--output", help="netCDF archive (default runs/<case>-<hash>.nc)")
    sp.add_argument("--duration", help="simulated time, e.g. 0.2s (default: [simulation] duration)")
    sp.add_argument("--stop", choices=("duration", "converged"), default=None,
                    help="stop rule: duration (run the whole duration) or converged (stop when the cage-motion label, its kind and the summaries have held over a confirming check; the duration is the upper bound; docs/sweeps.md); default: [simulation] stop, duration")
    sp.add_argument("--section", choices=("transverse", "cage_revolution", "plane"),
                    help="Poincare section of the cage-motion label (default: [simulation] section, transverse: "
                         "one point per loop of the cage-centre orbit; cage_revolution: once per cage revolution)")
    sp.add_argument("--no-figure", "--no-plot", dest="no_plot", action="store_true",
                    help="do not draw the PNG figure (--no-plot is the older spelling)")
    sp.add_argument("-q", "--quiet", action="store_true", help="no progress bar")
    sp.add_argument("--thermal", action="store_true", help="solve the thermal network first (hsbearing thermal) and run "
                    "at its lubricant temperature (traction and viscosity); needs lubricant.oil_flow_rate")
    sp.add_argument("--continue", dest="continue_from", metavar="ARCHIVE.nc",
                    help="extend the run in ARCHIVE.nc from its last state by --duration (default: to the duration "
                         "it was started with, e.g. after Ctrl-C); written back to ARCHIVE.nc unless -o")
    sp.set_defaults(func=cmd_run)

    sp = sub.add_parser("quasistatic", help="high-speed quasi-static equilibrium")
    with_case(sp)
    sp.add_argument("-o", "--output", help="netCDF archive")
    sp.set_defaults(func=cmd_quasistatic)

    sp = sub.add_parser("sweep", help="runs over varied case keys (local processes or a dask cluster)")
    with_case(sp)
    sp.add_argument("--vary", action="append", required=True, metavar="KEY=V1,V2,...",
                    help="e.g. --vary axial_load=100,500,1000N --vary oil=4109,4106 (repeatable)")
    sp.add_argument("--zip", action="store_true", help="vary the keys together (zipped lists) instead of the product")
    sp.add_argument("--keep-going", action="store_true",
                    help="record points whose values make an invalid case (status 'invalid') and run the rest, instead of exit 2")
    sp.add_argument("-j", "--jobs", type=int, default=None,
                    help="local worker processes (default: the number of cores; 1 = in this process)")
    sp.add_argument("--scheduler", default=None, metavar="ADDR",
                    help="address tcp://host:port of a running dask.distributed scheduler; the points run on its "
                         "workers instead of local processes (-j is then ignored)")
    sp.add_argument("--kind", default="run", choices=("run", "quasistatic", "thermal"),
                    help="what each point computes: run (dynamics), quasistatic (equilibrium), thermal (steady "
                         "thermal network at its power loss, as 'hsbearing thermal')")
    sp.add_argument("--duration", help="simulated time of each run, e.g. 0.05s")
    sp.add_argument("--stop", choices=("duration", "converged"), default=None,
                    help="stop rule: duration (run the whole duration) or converged (stop when the cage-motion label, its kind and the summaries have held over a confirming check; the duration is the upper bound; docs/sweeps.md); default: [simulation] stop of the case, duration")
    sp.add_argument("-o", "--output", required=True, help="output directory")
    sp.add_argument("--no-figure", "--no-plot", dest="no_figure", action="store_true",
                    help="do not draw DIR/sweep.png (--no-plot is accepted as in 'hsbearing run')")
    sp.set_defaults(func=cmd_sweep)

    sp = sub.add_parser("map", help="cage-stability map over two keys: class map + instability indicator "
                                    "(DIR/map.nc, DIR/map.png)")
    with_case(sp)
    sp.add_argument("--x", required=True, metavar="KEY=V1,V2,...", help="key and values of the map columns, "
                    "e.g. --x bearing.outer_land_diameter=52.3,52.4,52.5mm")
    sp.add_argument("--y", required=True, metavar="KEY=V1,V2,...", help="key and values of the map rows, "
                    "e.g. --y cage.pocket_diameter=9.6,9.7mm")
    sp.add_argument("-j", "--jobs", type=int, default=None, help="worker processes (default: cores)")
    sp.add_argument("--scheduler", default=None, help="dask.distributed scheduler address tcp://host:port")
    sp.add_argument("--duration", help="simulated time of each run, e.g. 0.6s (default: [simulation] duration)")
    sp.add_argument("--stop", choices=("duration", "converged"), default='converged',
                    help="stop rule: duration (run the whole duration) or converged (stop when the cage-motion label, its kind and the summaries have held over a confirming check; the duration is the upper bound; docs/sweeps.md); default converged")
    sp.add_argument("-o", "--output", required=True, help="output directory (resumable: rerun to finish)")
    sp.add_argument("-q", "--quiet", action="store_true", help="no progress bar")
    sp.add_argument("--no-figure", "--no-plot", dest="no_figure", action="store_true", help="do not draw DIR/map.png")
    sp.add_argument("--warm-start", action="store_true",
                    help="experimental: seed points (every other value of each axis) run cold, the others start from "
                         "the final state of their nearest seed; a sample also runs cold and the label agreement is "
                         "reported (docs/sweeps.md, Warm starts)")
    sp.add_argument("--cold-sample", type=int, default=4, metavar="N",
                    help="with --warm-start: warm points also run cold to check the agreement (default 4)")
    sp.set_defaults(func=cmd_map)

    from hsbearing.study import study_help

    sp = sub.add_parser("study", help="a bundled study: the paper's tables recomputed, with a report "
                                      "(zhang2016: cage stability, Zhang et al. 2016 Tables 3-5)",
                        description="Run a bundled study: its sweeps, the paper's values next to ours, DIR/report.md "
                                    "and one figure per table.", epilog=study_help(),
                        formatter_class=argparse.RawDescriptionHelpFormatter)
    sp.add_argument("name", help="study name (listed below)")
    sp.add_argument("-o", "--output", required=True, help="output directory")
    sp.add_argument("-j", "--jobs", type=int, default=None,
                    help="local worker processes (default: the number of cores; 1 = in this process)")
    sp.add_argument("--scheduler", default=None, metavar="ADDR",
                    help="address tcp://host:port of a running dask.distributed scheduler; the points run on its "
                         "workers instead of local processes")
    sp.add_argument("--duration", help="simulated time of each run (default: the study's, e.g. 1.2 s)")
    sp.add_argument("--stop", choices=("duration", "converged"), default='converged',
                    help="stop rule: duration (run the whole duration) or converged (stop when the cage-motion label, its kind and the summaries have held over a confirming check; the duration is the upper bound; docs/sweeps.md); default converged")
    grp = sp.add_mutually_exclusive_group()
    grp.add_argument("--bands", dest="bands", action="store_true", default=False,
                     help="run every cell over the study's [bands] samples of the unknown inputs (guide clearance, "
                          "land width, pocket clearance): DIR/<table>_bands.nc, DIR/report_bands.md; reuses the "
                          "nominal points already in DIR/runs")
    grp.add_argument("--no-bands", dest="bands", action="store_false",
                     help="the nominal case only, one run per cell (default): DIR/<table>.nc, DIR/report.md")
    sp.add_argument("--table", dest="tables", action="append", default=None, metavar="ID",
                    help="run only this table of the study (repeatable, e.g. --table table3 --table table5)")
    sp.add_argument("--report-only", action="store_true",
                    help="compute nothing: tables and report from the archives already in DIR/runs (the others are "
                         "reported missing); for a look at a running study, use a copy of DIR")
    sp.add_argument("--band-samples", type=int, default=None, metavar="K",
                    help="with --bands: run only the first K band samples (the nominal one first); the others "
                         "resume later from the same DIR")
    sp.add_argument("--no-figure", "--no-plot", dest="no_figure", action="store_true",
                    help="do not draw DIR/<table>.png (summary figure of each table)")
    sp.set_defaults(func=cmd_study)

    sp = sub.add_parser("friction", help="friction torque / power loss of any ball-bearing case (angular contact: "
                                         "quasi-static power loss by source; deep groove: sliding friction with "
                                         "pure-rolling lines; gyro, wire race: their own models), with the SKF 2004 "
                                         "frictional-moment model as a cross-check")
    with_case(sp, optional=False, examples=", e.g. zhang2016 or dgbb_6206")
    sp.add_argument("--speeds", default=None, help="comma list with a unit, e.g. 500,5000,15000rpm "
                                                   "(default: 500,5000,15000rpm deep groove; the case speed angular contact)")
    sp.add_argument("-o", "--output", help="netCDF archive")
    sp.set_defaults(func=cmd_friction)

    sp = sub.add_parser("thermal", help="steady thermal network (rings, balls, cage, oil, housing, shaft) at the "
                                        "quasi-static power loss, iterated with the lubricant temperature (docs/thermal.md)")
    with_case(sp, optional=False, examples=", e.g. zhang2016")
    sp.add_argument("-o", "--output", help="netCDF archive")
    sp.set_defaults(func=cmd_thermal)

    sp = sub.add_parser("life", help="ISO 281 rating life and ISO/TS 16281 reference life of a radial ball-bearing case")
    with_case(sp, optional=False, examples=", e.g. zhang2016")
    sp.add_argument("-o", "--output", help="netCDF archive")
    sp.set_defaults(func=cmd_life)

    sp = sub.add_parser("preload", help="wire-race bearing: preload vs starting torque (Shan et al. 2010, "
                                        "case shan2010_wire_race)")
    with_case(sp, optional=False, examples=", e.g. shan2010_wire_race")
    sp.add_argument("--preload", default="10..160um", help="range lo..hi[unit] or comma list, e.g. 10..160um")
    sp.add_argument("--target-torque", default=None, help="starting-torque window lo..hi, e.g. 90..100N*m -> preload window")
    sp.add_argument("-o", "--output", help="netCDF archive")
    sp.set_defaults(func=cmd_preload)

    sp = sub.add_parser("oils", help="list the bundled lubricants; NAME --at CASE: an oil's viscosity, alpha, film "
                                     "thickness and mu(S) at the case's contacts (quasi-static)")
    sp.add_argument("name", nargs="?", default=None, help="bundled lubricant name or lubricant .toml file")
    sp.add_argument("--at", metavar="CASE", help="bundled case name or case file to evaluate the oil at")
    sp.add_argument("--set", action="append", metavar="KEY=VALUE", help="override a case value (repeatable)")
    sp.add_argument("-o", "--output", help="PNG of mu(S) (default runs/oil-NAME-CASE.png)")
    sp.set_defaults(func=cmd_oils)

    sp = sub.add_parser("plot", help="draw the figures of a run, quasi-static, friction, preload, gyro archive "
                                     "or a sweep/study summary")
    sp.add_argument("archive", help="netCDF archive written by hsbearing")
    sp.add_argument("-o", "--output", help="PNG path (default: next to the archive)")
    sp.set_defaults(func=cmd_plot)
    return p


def main(argv: list[str] | None = None) -> int:
    parser = build_parser()
    args = parser.parse_args(argv)
    if not getattr(args, "func", None):  # bare `hsbearing`: say what is missing, on one line
        print("hsbearing: error: no command given (commands: cases, check, run, quasistatic, sweep, map, study, "
              "friction, life, preload, plot; see 'hsbearing --help')", file=sys.stderr)
        return 2
    try:
        rc = int(args.func(args) or 0)
        sys.stdout.flush()  # a closed pipe shows here (BrokenPipeError below), not in the interpreter's exit
        return rc
    except CaseError as exc:
        print(f"hsbearing: error: {exc}", file=sys.stderr)
        return 2
    except OutputWriteError as exc:  # computed, but the final write failed: where the result went, exit 1
        print(f"hsbearing: error: {exc}", file=sys.stderr)
        return 1
    except SolverError as exc:
        print(f"hsbearing: numerical failure: {exc}", file=sys.stderr)
        return 1
    except KeyboardInterrupt:
        print("hsbearing: interrupted", file=sys.stderr)
        return 130
    except (ArithmeticError, _linalg_error()) as exc:  # a singular matrix / overflow deep in a model: one line, exit 1
        print(f"hsbearing: numerical failure: {type(exc).__name__}: {str(exc).splitlines()[0] if str(exc) else ''} "
              "(the inputs are valid but the model cannot solve them; check the geometry and loads)", file=sys.stderr)
        return 1
    except BrokenPipeError:
        # the reader of stdout went away (``hsbearing check ... | head -1``): not an error of ours.
        # Point stdout at /dev/null so that the interpreter's final flush does not complain.
        _silence_stdout()
        return 0


def _linalg_error() -> type:
    import numpy as np

    return np.linalg.LinAlgError


def _silence_stdout() -> None:
    import os

    try:
        devnull = os.open(os.devnull, os.O_WRONLY)
        os.dup2(devnull, sys.stdout.fileno())
        os.close(devnull)
    except (OSError, ValueError, AttributeError):  # no real stdout (in-process use): nothing to silence
        pass


if __name__ == "__main__":  # pragma: no cover
    sys.exit(main())
