"""The command line of ``hsbearing``: the argparse tree of every subcommand and its options."""

from __future__ import annotations

import argparse

from hsbearing._version import __version__
from hsbearing.case import DEFAULT_CASE
from hsbearing.cli.commands import (
    cmd_cases,
    cmd_check,
    cmd_compare,
    cmd_friction,
    cmd_life,
    cmd_map,
    cmd_oils,
    cmd_plot,
    cmd_preload,
    cmd_quasistatic,
    cmd_run,
    cmd_study,
    cmd_sweep,
    cmd_thermal,
)

# ----------------------------------------------------------------------------- parser


class _Parser(argparse.ArgumentParser):
    """argparse with the CLI's error contract: one line ``hsbearing: error: ...`` (no usage block), exit 2."""

    def error(self, message):
        cmd = self.prog.split(" ", 1)[1] if " " in self.prog else ""
        hint = f" (see 'hsbearing {cmd} --help')" if cmd else " (see 'hsbearing --help')"
        self.exit(2, f"hsbearing: error: {message}{hint}\n")


def _add_keep_option(sp) -> None:
    """--keep of the sweep, the map and the study: what each point archive keeps."""
    sp.add_argument("--keep", choices=("answer", "full"), default="answer",
                    help="what each point archive keeps: answer (default: summaries, label and reasons, section points, "
                         "the cage-centre orbit, decimated histories, the final state for --continue) or full (the whole "
                         "trajectory)")


def _add_stop_option(sp, default: str | None) -> None:
    """--stop of run, sweep, map and study; ``default`` None: the case's [simulation] stop."""
    said = "default converged" if default == "converged" else "default: [simulation] stop of the case, duration"
    sp.add_argument("--stop", choices=("duration", "converged"), default=default,
                    help="stop rule: duration (run the whole duration) or converged (stop when the cage-motion label, "
                         "its kind and the summaries have held over a confirming check; the duration is the upper "
                         f"bound; docs/sweeps.md); {said}")


def _add_opt_in_extension_options(sp, what: str) -> None:
    """--extend and --max-duration of ``hsbearing run`` and ``hsbearing sweep`` (opt-in; map and study extend by
    default: :func:`_add_extension_options`)."""
    each = "the run" if what == "run" else "each point's run (kind run)"
    sp.add_argument("--extend", action="store_true",
                    help=f"while the cage-motion label is undetermined, continue {each} from its last state in steps "
                         "(an e-folding time of a growing whirl, the classifier's estimate, or half the run) until it "
                         "is determined or --max-duration is reached; the extensions and why they stopped are in the "
                         "archive (attrs extensions, extension_stop_reason)")
    sp.add_argument("--max-duration", dest="max_duration", metavar="T",
                    help="budget of --extend: total simulated time, e.g. 3s (default: "
                         + ("3 x the run's duration)" if what == "run" else "6 x the point's duration, as in a map; a "
                            "growing whirl is fast-forwarded as there: docs/sweeps.md)"))


def _add_extension_options(sp) -> None:
    """--max-duration and --no-extend of the map and the study (the extension of undetermined points)."""
    sp.add_argument("--max-duration", dest="max_duration", metavar="T",
                    help="budget of the extension of undetermined points: total simulated time of a point, e.g. 3s "
                         "(default: 6 x the duration); a point whose cage-motion label is undetermined with an estimate "
                         "of the time it needs is continued in its worker until determined, the stop rule's "
                         "convergence or this budget (docs/sweeps.md)")
    sp.add_argument("--no-extend", dest="no_extend", action="store_true",
                    help="do not extend undetermined points (each runs its duration, or less with the stop rule)")

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
    _add_stop_option(sp, None)
    sp.add_argument("--section", choices=("transverse", "cage_revolution", "plane"),
                    help="Poincare section of the cage-motion label (default: [simulation] section, transverse: "
                         "one point per loop of the cage-centre orbit; cage_revolution: once per cage revolution)")
    sp.add_argument("--no-figure", "--no-plot", dest="no_plot", action="store_true",
                    help="do not draw the PNG figure (--no-plot is the older spelling)")
    sp.add_argument("-q", "--quiet", action="store_true", help="no progress bar")
    sp.add_argument("--thermal", action="store_true", help="solve the thermal network first (hsbearing thermal) and run "
                    "at its temperatures: each race's contacts at (T_ring + T_ball)/2, the cage films at their film temperature "
                    "(frozen at the quasi-static state), drag at the lubricant temperature; needs lubricant.oil_flow_rate")
    _add_opt_in_extension_options(sp, "run")
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
    _add_keep_option(sp)
    _add_stop_option(sp, None)
    _add_opt_in_extension_options(sp, "point")
    sp.add_argument("-o", "--output", required=True, help="output directory")
    sp.add_argument("--no-figure", "--no-plot", dest="no_figure", action="store_true",
                    help="do not draw DIR/sweep.png (--no-plot is accepted as in 'hsbearing run')")
    sp.set_defaults(func=cmd_sweep)

    sp = sub.add_parser("compare", help="lubricants at the same conditions: one page (DIR/index.html, opens offline), "
                                        "DIR/compare.md and DIR/compare.nc (dimension oil)")
    with_case(sp)
    sp.add_argument("--oils", required=True, metavar="A,B,FILE.toml",
                    help="the oils to compare: built-in (4109, 4106, 4050), bundled lubricants ('hsbearing oils') or "
                         "lubricant files (format: 'hsbearing oils --template'), e.g. --oils 4109,4106,4050,my_oil.toml")
    sp.add_argument("--vary", action="append", metavar="KEY=V1,V2,...",
                    help="also vary a case key, every oil at each value, e.g. --vary axial_load=500,1000N (repeatable)")
    sp.add_argument("--no-dynamics", action="store_true",
                    help="quasi-static comparison only (tens of seconds per oil with the thermal equilibrium): no dynamic "
                         "run, so no cage class or whirl")
    sp.add_argument("--duration", help="upper bound of each oil's dynamic run, e.g. 0.6s (default 1.2 s, stopped "
                                       "earlier by the stop rule once the cage answer holds)")
    sp.add_argument("--stop", choices=("duration", "converged"), default="converged",
                    help="stop rule of the dynamic runs (default converged: docs/sweeps.md, Stop rule)")
    sp.add_argument("-j", "--jobs", type=int, default=None,
                    help="local worker processes (default: the number of cores; 1 = in this process)")
    sp.add_argument("--scheduler", default=None, metavar="ADDR", help="dask.distributed scheduler tcp://host:port")
    sp.add_argument("-o", "--output", required=True, help="output directory (resumable: the same command reuses "
                                                          "the point archives in DIR/points)")
    sp.add_argument("-q", "--quiet", action="store_true", help="no progress bar")
    sp.add_argument("--no-figure", "--no-plot", dest="no_figure", action="store_true",
                    help="no figures on the page")
    sp.set_defaults(func=cmd_compare)

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
    _add_keep_option(sp)
    _add_stop_option(sp, "converged")
    _add_extension_options(sp)
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

    from hsbearing.workflows.study import study_help

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
    sp.add_argument("-q", "--quiet", action="store_true", help="no progress bar")
    sp.add_argument("--duration", help="simulated time of each run (default: the study's, e.g. 1.2 s)")
    _add_keep_option(sp)
    _add_stop_option(sp, "converged")
    _add_extension_options(sp)
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
    sp.add_argument("--thermal", action="store_true", help="angular contact: at each speed solve the thermal network "
                    "(hsbearing thermal) and feed its temperatures to the contacts (race contacts at its lubricant "
                    "temperature, land and pocket films between their walls' temperatures); needs lubricant.oil_flow_rate")
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
                                     "thickness and mu(S) at the case's contacts (quasi-static); --template FILE: "
                                     "a lubricant file to fill in",
                        description="The bundled lubricants, one oil at a case, or a template of your own lubricant "
                                    "file. A lubricant file (TOML) gives the oil's name, its kinematic viscosity at two "
                                    "temperatures, density, pressure-viscosity coefficient (or 'so_klaus_1980' when "
                                    "unknown) and a [traction] table; the format is in docs/traction.md, section "
                                    "'Lubricant files', and 'hsbearing oils --template my_oil.toml' writes a commented "
                                    "one. Use it with --set lubricant.file=my_oil.toml or --vary oil=4109,my_oil.toml.")
    sp.add_argument("name", nargs="?", default=None, help="bundled lubricant name or lubricant .toml file")
    sp.add_argument("--template", metavar="FILE", help="write a commented lubricant file to FILE (the format, "
                                                       "with an ISO VG 32 data sheet's values to replace)")
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
