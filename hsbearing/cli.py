"""The ``hsbearing`` command: a thin layer over the library (the same functions, the same names).

Exit codes: 0 success; 2 bad input (one line naming the file and the key,
nothing written); 1 numerical failure (partial result kept, status says why).
"""

from __future__ import annotations

import argparse
import hashlib
import sys
from pathlib import Path

from hsbearing import __version__
from hsbearing.case import CaseError, DEFAULT_CASE, list_cases, load_case, parse_quantity
from hsbearing.errors import SolverError


class _UsageError(Exception):
    pass


def _parse_sets(items: list[str] | None, source: str = "--set") -> dict[str, str]:
    out = {}
    for item in items or []:
        if "=" not in item:
            raise CaseError(source, item, "expected key=value, e.g. --set operating.axial_load=\"2 kN\"")
        k, _, v = item.partition("=")
        out[k.strip()] = v.strip()
    return out


def _load(args) -> "object":
    return load_case(args.case or DEFAULT_CASE, **_parse_sets(getattr(args, "set", None)))


def _default_out(case, suffix: str, extra: str = "") -> Path:
    h = hashlib.sha1((case.to_toml() + extra).encode()).hexdigest()[:10]
    return Path("runs") / f"{case.name}-{h}{suffix}"


def _print_summary(ds, out: Path | None = None) -> None:
    import numpy as np

    print(f"status: {ds.attrs.get('status', '?')}")
    for name, var in ds.data_vars.items():
        if var.ndim == 0:
            val = var.values.item()
            unit = var.attrs.get("units", "")
            if isinstance(val, (float, np.floating)):
                print(f"{name}: {val:.6g} {unit}".rstrip())
            else:
                print(f"{name}: {val} {unit}".rstrip())
    if "sfmc_ensemble" in ds:  # gyro start ensemble (simulation.start_positions > 1): mean +/- sd and each start
        from hsbearing.models.friction import gyro

        print("\n".join(gyro.ensemble_lines(ds)))
    if "drive_torque" in ds:  # dynamic run: drive torque and power loss by source (hsbearing.balances)
        from hsbearing.balances import power_summary_lines

        print("\n".join(power_summary_lines(ds)))
    if ds.attrs.get("warnings", "none") != "none":  # contact/film/cage limits (hsbearing.contact_state)
        for w in str(ds.attrs["warnings"]).split(" | "):
            print(f"warning: {w}")
    for key in ("classification", "classification_confidence"):
        if key in ds.attrs:
            print(f"{key}: {ds.attrs[key]}")
    stats = {k[len("solver_"):]: v for k, v in ds.attrs.items() if k.startswith("solver_")}
    if stats:
        print("solver: " + ", ".join(f"{k}={v}" for k, v in stats.items()))
    if out is not None:
        print(f"archive: {out}")


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
    return 0


def cmd_run(args) -> int:
    from hsbearing import simulate
    from hsbearing.results import write_netcdf

    case = _load(args)
    duration = parse_quantity(args.duration, "time", source="--duration", key="duration") if args.duration else None
    if duration is not None and not duration > 0:
        raise CaseError("--duration", "duration", f"must be positive, got {args.duration!r}")
    out = Path(args.output) if args.output else _default_out(case, ".nc", f"duration={duration}")
    try:
        ds = simulate(case, duration=duration, progress=not args.quiet)
    except SolverError as exc:
        if exc.partial is not None:
            write_netcdf(exc.partial, out)
            print(f"hsbearing: numerical failure: {exc}; partial result in {out}", file=sys.stderr)
        else:
            print(f"hsbearing: numerical failure: {exc}", file=sys.stderr)
        return 1
    write_netcdf(ds, out)
    _print_summary(ds, out)
    if not args.no_plot:
        from hsbearing import plotting

        png = plotting.plot_run(ds, out.with_suffix(".png"))
        if png:
            print(f"figure: {png}")
    return 0


def cmd_quasistatic(args) -> int:
    from hsbearing import quasi_static
    from hsbearing.results import write_netcdf

    case = _load(args)
    try:
        ds = quasi_static(case)
    except SolverError as exc:
        if exc.partial is not None and args.output:
            write_netcdf(exc.partial, args.output)
            print(f"hsbearing: numerical failure: {exc}; partial result in {args.output}", file=sys.stderr)
        else:
            print(f"hsbearing: numerical failure: {exc}", file=sys.stderr)
        return 1
    from hsbearing.solvers import quasistatic

    quasistatic.print_summary(ds)
    if args.output:
        write_netcdf(ds, args.output)
        print(f"archive: {args.output}")
    return 0


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

    rc = sweeps.cli_main(args)
    if not getattr(args, "no_figure", False):
        out = Path(args.output)
        _summary_figure(out / "sweep.nc", out / "sweep.png")
    return rc


def cmd_study(args) -> int:
    from hsbearing import study

    rc = study.cli_main(args)
    if not getattr(args, "no_figure", False):
        out = Path(args.output)
        for t in study.load_study(args.name).tables:
            _summary_figure(out / f"{t['id']}.nc", out / f"{t['id']}.png")
    return rc


def cmd_friction(args) -> int:
    from hsbearing import rating  # dispatch by [case] system: every ball-bearing case answers

    return rating.friction_cli(args)


def cmd_life(args) -> int:
    from hsbearing import rating

    return rating.life_cli(args)


def cmd_preload(args) -> int:
    from hsbearing.models.friction import wire_race

    return wire_race.cli_main(args)


def cmd_plot(args) -> int:
    from hsbearing import plotting
    from hsbearing.results import open_run

    path = Path(args.archive)
    if not path.exists():
        raise CaseError(str(path), None, "no such archive")
    try:
        ds = open_run(path)
    except Exception as exc:
        raise CaseError(str(path), None, f"not a readable netCDF archive ({type(exc).__name__})") from None
    try:  # a sweep/study summary (one dimension per varied key) gets the sweep figure (plotting.plot_sweep)
        png = plotting.plot_run(ds, Path(args.output) if args.output else path.with_suffix(".png"))
    except CaseError as exc:  # e.g. a summary with too many lines for one figure: name the archive
        raise CaseError(str(path), exc.key, exc.message) from None
    print(f"figure: {png}")
    return 0


# ----------------------------------------------------------------------------- parser


def build_parser() -> argparse.ArgumentParser:
    p = argparse.ArgumentParser(prog="hsbearing", description="Dynamics and friction of rolling ball bearings.")
    p.add_argument("--version", action="version", version=f"hsbearing {__version__}")
    sub = p.add_subparsers(dest="command", metavar="COMMAND")

    def with_case(sp, optional=True):
        sp.add_argument("case", nargs="?" if optional else None, default=None,
                        help="bundled case name or path to a TOML case (default: %s)" % DEFAULT_CASE)
        sp.add_argument("--set", action="append", metavar="KEY=VALUE",
                        help='override a case value, e.g. --set operating.axial_load="2 kN" (repeatable)')

    sp = sub.add_parser("cases", help="list the bundled cases")
    sp.set_defaults(func=cmd_cases)

    sp = sub.add_parser("check", help="validate a case and print the derived geometry")
    with_case(sp)
    sp.set_defaults(func=cmd_check)

    sp = sub.add_parser("run", help="dynamic simulation (default case: zhang2016)")
    with_case(sp)
    sp.add_argument("-o", "--output", help="netCDF archive (default runs/<case>-<hash>.nc)")
    sp.add_argument("--duration", help="simulated time, e.g. 0.2s (default: [simulation] duration)")
    sp.add_argument("--no-plot", action="store_true", help="do not draw the PNG figure")
    sp.add_argument("-q", "--quiet", action="store_true", help="no progress bar")
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
    sp.add_argument("-j", "--jobs", type=int, default=None, help="worker processes (default: cores)")
    sp.add_argument("--scheduler", default=None, help="dask.distributed scheduler address tcp://host:port")
    sp.add_argument("--kind", default="run", choices=("run", "quasistatic"), help="what each point computes")
    sp.add_argument("--duration", help="simulated time of each run, e.g. 0.05s")
    sp.add_argument("-o", "--output", required=True, help="output directory")
    sp.add_argument("--no-figure", action="store_true", help="do not draw DIR/sweep.png")
    sp.set_defaults(func=cmd_sweep)

    sp = sub.add_parser("study", help="a bundled study (e.g. zhang2016: Tables 3-5 of seed 004)")
    sp.add_argument("name", help="study name")
    sp.add_argument("-o", "--output", required=True, help="output directory")
    sp.add_argument("-j", "--jobs", type=int, default=None)
    sp.add_argument("--scheduler", default=None)
    sp.add_argument("--duration", help="simulated time of each run")
    sp.add_argument("--no-figure", action="store_true", help="do not draw DIR/<table>.png (summary figure of each table)")
    sp.set_defaults(func=cmd_study)

    sp = sub.add_parser("friction", help="friction torque / power loss of any ball-bearing case, with the SKF 2004 model "
                                         "as a cross-check")
    with_case(sp, optional=False)
    sp.add_argument("--speeds", default=None, help="comma list with a unit, e.g. 500,5000,15000rpm "
                                                   "(default: 500,5000,15000rpm deep groove; the case speed angular contact)")
    sp.add_argument("-o", "--output", help="netCDF archive")
    sp.set_defaults(func=cmd_friction)

    sp = sub.add_parser("life", help="ISO 281 rating life and ISO/TS 16281 reference life of a radial ball-bearing case")
    with_case(sp, optional=False)
    sp.add_argument("-o", "--output", help="netCDF archive")
    sp.set_defaults(func=cmd_life)

    sp = sub.add_parser("preload", help="wire-race bearing: preload vs starting torque (seed 001)")
    with_case(sp, optional=False)
    sp.add_argument("--preload", default="10..160um", help="range lo..hi[unit] or comma list, e.g. 10..160um")
    sp.add_argument("--target-torque", default=None, help="starting-torque window lo..hi, e.g. 90..100N*m -> preload window")
    sp.add_argument("-o", "--output", help="netCDF archive")
    sp.set_defaults(func=cmd_preload)

    sp = sub.add_parser("plot", help="draw the figures of a run, quasi-static, friction, preload, gyro archive "
                                     "or a sweep/study summary")
    sp.add_argument("archive", help="netCDF archive written by hsbearing")
    sp.add_argument("-o", "--output", help="PNG path (default: next to the archive)")
    sp.set_defaults(func=cmd_plot)
    return p


def main(argv: list[str] | None = None) -> int:
    parser = build_parser()
    args = parser.parse_args(argv)
    if not getattr(args, "func", None):
        parser.print_help()
        return 2
    try:
        return int(args.func(args) or 0)
    except CaseError as exc:
        print(f"hsbearing: error: {exc}", file=sys.stderr)
        return 2
    except SolverError as exc:
        print(f"hsbearing: numerical failure: {exc}", file=sys.stderr)
        return 1
    except KeyboardInterrupt:
        print("hsbearing: interrupted", file=sys.stderr)
        return 130


if __name__ == "__main__":  # pragma: no cover
    sys.exit(main())
