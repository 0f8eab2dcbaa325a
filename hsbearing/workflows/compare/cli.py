"""``hsbearing compare CASE --oils A,B,FILE.toml [--vary KEY=V1,V2] [--no-dynamics] -o DIR``."""

from __future__ import annotations

from pathlib import Path

from hsbearing.case import CaseError


def cli_main(args) -> int:
    """Run the comparison, print the best oil per criterion and the files written.

    Exit 0 when every point is ok, 1 when some point is not (the page says which), 2 on bad input (an oil that is
    no oil, a bad --vary, a bad output directory: one line, nothing computed or written)."""
    from hsbearing.display import format_seconds
    from hsbearing.workflows.compare import compute, report
    from hsbearing.workflows.sweeps.cli import _parse_vary, cli_base_case

    case = cli_base_case(args)
    vary = _parse_vary(args.vary)
    if args.duration is not None and args.no_dynamics:
        raise CaseError("--duration", None, "--duration sets the dynamic run, which --no-dynamics switches off")
    ds = compute.compare(case, args.oils, vary=vary, out_dir=Path(args.output), dynamics=not args.no_dynamics,
                         duration=args.duration, stop=args.stop, jobs=args.jobs, scheduler=args.scheduler,
                         progress=not args.quiet, figures=not args.no_figure)
    names = [str(n) for n in ds["oil_name"].values]
    print(f"oils: {', '.join(names)}")
    for i, n in enumerate(names):
        notes = report.oils_table(ds)[1][i][3]
        if notes and notes != "none":
            for line in notes.split(" | "):
                print(f"  notice ({n}): {line}")
    print(f"dynamics: {ds.attrs['compare_dynamics']}")
    print(f"thermal: {ds.attrs['compare_thermal']}")
    for sel, label in report.vary_points(ds):
        header, rows = report.best_table(ds, sel)
        print(f"best oil per criterion{' (' + label + ')' if label else ''}:")
        for r in rows:
            by = f", runner-up {r[3]} by {r[4]} ({r[5]})" if r[3] != "-" else ""
            print(f"  {r[0]}: {r[1]} ({r[2]}{by})" + (f"; {r[6]}" if r[6] else ""))
    out = Path(args.output)
    print(f"status: {ds.attrs['status']}; wall time {format_seconds(ds.attrs['compare_wall_time'])}")
    print(f"page: {out / compute.HTML_NAME}; {out / compute.MD_NAME}; numbers: {out / compute.NC_NAME}")
    return 0 if ds.attrs["status"] == "ok" else 1
