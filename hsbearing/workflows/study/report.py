"""The study reports: ``DIR/report.md`` (paper vs ours for every cell, one run per cell) and
``DIR/report_bands.md`` (class fractions over the band samples), with their figures and Table 6."""

from __future__ import annotations

import os
import time
from pathlib import Path

import numpy as np
import xarray as xr

from hsbearing.case import load_case
from hsbearing.results import atomic_write
from hsbearing.workflows import sweeps
from hsbearing.workflows.study.cells import (
    _details,
    _ours,
    band_counts,
    band_range,
    cell_stats,
    fmt,
    fraction_text,
    point_walls,
    section_stats,
    sum_wall,
    tables_in,
    value_label,
)
from hsbearing.workflows.study.figures import plot_cells, plot_gallery, plot_slip, plot_slip_band
from hsbearing.workflows.study.spec import BANDS_SUFFIX, FIGURES, RUNS, STATUS_MISSING, BandSample, Study
from hsbearing.workflows.study.table6 import TABLE6_RULE, derive_table6


def write_report(study: Study, datasets: dict[str, xr.Dataset], out: Path, info: dict) -> Path:
    """``out/report.md`` with the comparison tables, the figures and the wall time."""
    figdir = _figure_dir(out)
    st = study.spec["study"]
    lines = _preamble(study, info, st.get("title", study.name), bands=False)
    lines += ["## Run", "",
              _duration_line(info, "a run stops when its answer has converged; its archive records `stopped_at` and "
                                   "`stop_reason`; docs/sweeps.md"),
              _execution_line(info, os.cpu_count()),
              _extension_line(info, datasets),
              f"- points: {info['n_unique_points']} distinct cases ({info['n_computed']} computed in this invocation, "
              f"the others resumed from `{RUNS}/`)",
              _wall_line(info, "the whole study"),
              f"- sum of the per-point wall times: {sum_wall(datasets):.1f} s"] + section_stats(datasets) + [""]
    totals = [0, 0, 0]  # agree, classified, undetermined
    alt_totals = [0, 0]  # the cage-revolution (clock) section's label: agree, classified
    disagreements: list[str] = []
    for t, ds, dim in tables_in(study, datasets):
        lines += [f"## {t.get('title', t['id'])}", ""]
        header = f"| {t.get('axis_label', dim)} | " + " | ".join(f"{o} paper | {o} ours" for o in study.oils) + " |"
        lines += [header, "|" + "---|" * (1 + 2 * len(study.oils))]
        for i in range(ds.sizes[dim]):
            row = [value_label(ds, dim, i)]
            for o in study.oils:
                pt = ds.sel(oil=o).isel({dim: i})
                paper = str(pt["paper_classification"].values) if "paper_classification" in ds else ""
                ours = _ours(pt)
                ok = paper and ours == paper
                if paper and pt["status"].item() == sweeps.STATUS_OK:
                    if ours == "undetermined":
                        totals[2] += 1
                    else:
                        totals[0] += int(bool(ok))
                        totals[1] += 1
                if paper and not ok:
                    disagreements.append(f"{t['id']}, oil {o}, {row[0]}: paper {paper}, ours {ours}{_details(pt)}")
                alt = _ours(pt, "classification_alternative")
                if paper and pt["status"].item() == sweeps.STATUS_OK and alt not in ("-", "undetermined"):
                    alt_totals[0] += int(alt == paper)
                    alt_totals[1] += 1
                cell = f"{ours} {'(=)' if ok else '(x)'}" if paper else ours
                if alt != "-":
                    cell += f"; clock: {alt}" + ((" (=)" if alt == paper else " (x)") if paper else "")
                row += [paper or "-", cell]
            lines.append("| " + " | ".join(row) + " |")
        lines += ["", "Cage slip ratio [%] (time mean after the transient; ours) -- "
                  f"compare {t.get('slip_figure', 'the paper')}:", ""]
        lines += [f"| {t.get('axis_label', dim)} | " + " | ".join(study.oils) + " |", "|" + "---|" * (1 + len(study.oils))]
        for i in range(ds.sizes[dim]):
            row = [value_label(ds, dim, i)]
            for o in study.oils:
                pt = ds.sel(oil=o).isel({dim: i})
                row.append(fmt(pt["mean_cage_slip_ratio"].item() * 100, ".2f") if "mean_cage_slip_ratio" in ds else "-")
            lines.append("| " + " | ".join(row) + " |")
        png = plot_slip(ds, t, study.oils, figdir / f"slip_{t['id']}.png")
        if png:
            lines += ["", f"![cage slip ratio, {t['id']}]({FIGURES}/{png.name})"]
        lines.append("")
    n_cells = sum(len(t["values"]) * len(study.oils) for t in study.tables if t["id"] in datasets)
    lines += ["## Agreement", "",
              f"Classification agrees with the paper in **{totals[0]} of {totals[1]}** cells that completed and "
              f"were classified; {totals[2]} completed cells are *undetermined* (too few Poincare points or an "
              f"inconclusive test: simulate longer); {n_cells - totals[1] - totals[2]} of {n_cells} cells did not "
              "complete.", ""]
    if alt_totals[1]:
        lines += [f"Under the cage-revolution (clock, once per cage revolution) section kept for comparison ('clock:' in "
                  f"the tables), the label agrees in {alt_totals[0]} of {alt_totals[1]} classified cells.  Our label is "
                  "read on the section transverse to the flow (docs/analysis.md): the model is autonomous and the cage "
                  "angle is not a clock.", ""]
    if disagreements:
        lines += ["Cells where ours differs:", ""] + [f"- {d}" for d in disagreements] + [""]
    lines += [
        "What can drive a difference (a finding, not a target to tune for):",
        "",
        "- the reading of the traction-coefficient formulas of the three oils (Eq. 2 and Table 1; see docs/traction.md);",
        "- the geometry the paper does not give (conformities, pitch diameter, nominal contact angle, land and guide "
        "clearances: marked \"assumed\" in `hsbearing/cases/zhang2016.toml`);",
        "- the simulated duration: a short run may still carry the start-up transient, and a classification from few "
        "Poincare points is less certain (see the confidence in each point archive);",
        "- the classification thresholds of `hsbearing.analysis.periods` and `hsbearing.analysis.whirl` (docs/analysis.md), whereas the paper "
        "classifies its Poincare maps by eye.",
        "",
    ]
    figs = []
    for f in study.figures:
        png = plot_cells(study, datasets, f, figdir / f"{f['id']}.png")
        if png:
            figs.append(f"### {f.get('title', f['id'])}\n\n![{f['id']}]({FIGURES}/{png.name})\n")
    if figs:
        lines += ["## Whirl orbits and Poincare maps of representative cells", ""] + figs
    gal = []
    drift: list[str] = []
    for t in study.tables:
        if t["id"] in datasets:
            png = plot_gallery(study, t, datasets[t["id"]], out, figdir / f"cells_{t['id']}.png", drift)
            if png:
                gal.append(f"![every cell of {t['id']}]({FIGURES}/{png.name})\n")
    if gal:
        lines += ["## Every cell: whirl orbit and Poincare map", ""] + gal + _drift_lines(drift)
    lines += table6_lines(study, datasets)
    failed = [_failed_line(tid, pt) for tid, pt in _not_ok_points(datasets)]
    if failed:
        lines += ["## Points that did not complete", ""] + failed + [""]
    path = out / "report.md"
    with atomic_write(path) as tmp:
        tmp.write_text("\n".join(lines))
    return path


#: the superseded study (land-film sign error and the other cage-physics defects of the cage-physics issue)
SUPERSEDED = {"zhang2016": "9 of 37 classified cells agreed (one run per cell, guessed clearances; docs/validation/zhang2016.md of an earlier version)"}


def write_band_report(study: Study, datasets: dict[str, xr.Dataset], out: Path, info: dict) -> Path:
    """``out/report_bands.md``: per cell the class fractions over the band, the majority, agrees/occurs,
    the agreement counts per table and overall, the band definition and the wall times."""
    figdir = _figure_dir(out)
    st = study.spec["study"]
    b = study.bands
    samples: list[BandSample] = info["samples"]
    lines = _preamble(study, info, f"{st.get('title', study.name)}: with the unknown inputs as bands", bands=True)
    # -- run and wall times
    walls = point_walls(datasets)
    n_pts = len(walls)
    mean_w = float(np.mean(list(walls.values()))) if walls else float("nan")
    cores = os.cpu_count() or 1
    lines += ["## Run and wall time", "",
              _duration_line(info, "docs/sweeps.md"),
              _execution_line(info, cores),
              f"- points: {info['n_unique_points']} distinct cases = cells x {len(samples)} band samples "
              f"({info['n_computed']} computed in this invocation, the others resumed from `{RUNS}/`, e.g. the "
              "nominal points of an earlier `hsbearing study` in the same directory)",
              _wall_line(info, "the banded study"),
              f"- sum of the per-point wall times (all {n_pts} distinct points, resumed ones as recorded in their "
              f"archives): {sum(walls.values()):.1f} s; mean per point {fmt(mean_w, '.3g')} s",
              _nominal_wall_line(out, info["wall_time"], study.name),
              f"- **projection: a 4000-run map on a 16-core cluster** = 4000 x {fmt(mean_w, '.3g')} s / 16 = "
              f"{fmt(4000 * mean_w / 16 / 60, '.3g')} min (the mean point wall time recorded by the runs at this "
              "duration, one point per core, no scheduling overhead; the runs shared this machine's "
              f"{cores} core(s) with other work, so the per-point time includes that contention)",
              ""] + section_stats(datasets) + [""]
    # -- band definition
    lines += ["## The band", "",
              f"Method: {b.get('method', 'lhs')} (Latin hypercube, seed {b['seed']}), {b['samples']} samples"
              + (" plus the nominal case (sample 0)" if b.get("include_nominal", True) else "")
              + "; the same samples in every cell (common random numbers). Ranges and their justification: "
                f"`hsbearing/studies/{study.name}.toml` and docs/validation/{study.name}.md.", ""]
    if len(samples) < info.get("n_band_samples", len(samples)):
        lines += [f"> **Only the first {len(samples)} of the {info['n_band_samples']} band samples were run** "
                  "(`--band-samples`): a prefix of a Latin hypercube is not stratified, so the fractions below are "
                  "over a random, not a Latin-hypercube, sample of the band. The other samples resume later with the "
                  "same archives.", ""]
    base = load_case(st["case"])
    hdr = ["sample"] + [f"`{k}` [mm]" for k in b["keys"]]
    derived = []
    if "bearing.outer_land_diameter" in b["keys"] and base.cage.outside_diameter:
        derived.append(("radial guide clearance [um]",
                        lambda v: (v["bearing.outer_land_diameter"] - base.cage.outside_diameter) / 2 * 1e6))
    if "cage.pocket_diameter" in b["keys"]:
        derived.append(("radial pocket clearance [um]",
                        lambda v: (v["cage.pocket_diameter"] - base.bearing.ball_diameter) / 2 * 1e6))
    hdr += [d[0] for d in derived]
    lines += ["| " + " | ".join(hdr) + " |", "|" + "---|" * len(hdr)]
    rng = ["range"] + [" - ".join(str(x) for x in b["keys"][k]) for k in b["keys"]] + [""] * len(derived)
    lines.append("| " + " | ".join(rng) + " |")
    for smp in samples:
        row = [f"{smp.index} ({smp.label})"] + [f"{smp.values[k] * 1e3:.4f}" for k in b["keys"]]
        row += [f"{f(smp.values):.1f}" for _, f in derived]
        lines.append("| " + " | ".join(row) + " |")
    lines.append("")
    # -- per table
    all_stats: list[dict] = []
    per_table: list[tuple[str, dict]] = []
    for t, ds, dim in tables_in(study, datasets):
        lines += [f"## {t.get('title', t['id'])}", "",
                  "Class fractions over the band samples that completed (sub-labels of \"1 period\" in brackets); "
                  "*majority*: the most frequent class (ties joined by /); *agrees*: the paper's class is the "
                  "majority alone (\"tie\": one of tied majorities); *occurs*: the paper's class appears in at "
                  "least one sample; *confidence*: mean classifier confidence of the samples in the majority class; "
                  "*whirl / cage speed*: dominant whirl frequency of the cage centre over the cage speed (1 = a "
                  "whirl synchronous with the section, the paper's \"1 period\" single circle; +-11 = Z: a vibration at the "
                  "ball-pass frequency, seen where the cage is held on one spot of the land).",
                  "",
                  f"| {t.get('axis_label', dim)} | oil | paper | ours over the band | majority | agrees | occurs | "
                  "confidence | samples ok | whirl / cage speed (band range) |", "|" + "---|" * 10]
        tstats = []
        for i in range(ds.sizes[dim]):
            for o in study.oils:
                stt = cell_stats(ds, dim, o, i)
                stt["where"] = f"{t['id']}, oil {o}, {value_label(ds, dim, i)}"
                tstats.append(stt)
                agree = "yes" if stt["agrees"] else ("tie" if stt["agrees_tied"] else "no")
                lines.append(f"| {value_label(ds, dim, i)} | {o} | {stt['paper'] or '-'} | {fraction_text(stt)} | "
                             f"{stt['majority']} | {agree if stt['paper'] else '-'} | "
                             f"{('yes' if stt['occurs'] else 'no') if stt['paper'] else '-'} | "
                             f"{fmt(stt['confidence'], '.2f')} | {stt['n_ok']}/{stt['n']} | "
                             f"{band_range(ds.sel(oil=o).isel({dim: i}), 'whirl_frequency_ratio')} |")
        c = band_counts(tstats)
        per_table.append((t["id"], c))
        all_stats += tstats
        lines += ["", f"{t['id']}: the paper's class is the majority in **{c['agrees']} of {c['evaluated']}** cells "
                      f"(+{c['tied']} tied), occurs in **{c['occurs']} of {c['evaluated']}**.", ""]
        if "mean_cage_slip_ratio" in ds:
            lines += [f"Cage slip ratio [%] (time mean after the transient): nominal sample and the range over the "
                      f"band -- compare {t.get('slip_figure', 'the paper')}:", "",
                      f"| {t.get('axis_label', dim)} | " + " | ".join(study.oils) + " |",
                      "|" + "---|" * (1 + len(study.oils))]
            labels = list(ds["sample_label"].values)
            for i in range(ds.sizes[dim]):
                row = [value_label(ds, dim, i)]
                for o in study.oils:
                    cell = ds.sel(oil=o).isel({dim: i})
                    v = np.asarray(cell["mean_cage_slip_ratio"].values, float) * 100
                    v = np.where(np.asarray(cell["status"].values) == sweeps.STATUS_OK, v, np.nan)
                    nom = v[labels.index("nominal")] if "nominal" in labels else float("nan")
                    fin = v[np.isfinite(v)]
                    row.append(f"{fmt(nom, '.2f')} [{fmt(fin.min(), '.2f')}, {fmt(fin.max(), '.2f')}]"
                               if fin.size else "-")
                lines.append("| " + " | ".join(row) + " |")
            png = plot_slip_band(ds, t, study.oils, figdir / f"slip_bands_{t['id']}.png")
            if png:
                lines += ["", f"![cage slip ratio over the band, {t['id']}]({FIGURES}/{png.name})"]
            lines.append("")
        drift: list[str] = []
        png = plot_gallery(study, t, ds, out, figdir / f"cells_bands_{t['id']}.png", drift)
        if png:
            lines += ["Every cell (one sample each: the nominal one when it is in the majority class):", "",
                      f"![every cell of {t['id']} over the band]({FIGURES}/{png.name})", ""]
        lines += _drift_lines(drift)
    # -- counts
    tot = band_counts(all_stats)
    lines += ["## Agreement over the band", "",
              "| table | cells | cells with a completed sample | majority agrees | tied majority incl. paper | "
              "occurs | majority undetermined |", "|" + "---|" * 7]
    for tid, c in per_table + [("**all**", tot)]:
        lines.append(f"| {tid} | {c['cells']} | {c['evaluated']} | {c['agrees']} | {c['tied']} | {c['occurs']} | "
                     f"{c['undetermined']} |")
    lines += ["", f"**Majority agreement: {tot['agrees']} of {tot['evaluated']} cells; occurrence: {tot['occurs']} "
                  f"of {tot['evaluated']}.** Superseded table: {SUPERSEDED.get(study.name, 'none')}.", "",
              "### What changed from the superseded table, and why", "",
              "> **[LEAD: to be filled from the results]** -- the cage-physics fixes since the superseded table "
              "(land-film sign, guide lands from the geometry, oil laws; docs/validation/cage_whirl.md), the "
              "classifier's sub-labels (still cage / synchronous whirl under \"1 period\"), and what the band "
              "changes: cells whose class depends on the unknown clearances.", ""]
    lines += table6_lines(study, datasets)
    failed, n_missing = [], 0
    for tid, pt in _not_ok_points(datasets):
        if pt["status"].item() == STATUS_MISSING:
            n_missing += 1
        else:
            failed.append(_failed_line(tid, pt))
    if n_missing:
        lines += [f"> **Partial report:** {n_missing} table cells x samples have no archive yet (report only); "
                  "they are left out of the fractions.", ""]
    if failed:
        lines += ["## Points that did not complete", ""] + failed + [""]
    path = out / f"report{BANDS_SUFFIX}.md"
    with atomic_write(path) as tmp:
        tmp.write_text("\n".join(lines))
    return path


def _nominal_wall_line(out: Path, banded_wall: float, name: str) -> str:
    """The nominal study's wall time as its ``report.md`` in the same directory states it, and the sum."""
    import re

    rep = out / "report.md"
    m = re.search(r"wall time of the whole study \(this invocation\): ([0-9.]+) s", rep.read_text()) if rep.exists() else None
    if not m:
        return (f"- wall time of the nominal study: no `report.md` of `hsbearing study {name}` in this directory "
                "(the nominal points were computed here)")
    nom = float(m.group(1))
    return (f"- wall time of the nominal study (its `report.md`, last invocation): {nom:.1f} s; **whole study = nominal "
            f"+ banded invocations: {nom + banded_wall:.1f} s** (a resumed invocation counts only what it computed)")


def _drift_lines(drift: list[str]) -> list[str]:
    if not drift:
        return []
    return (["Cells drawn above whose cage is still drifting at the end of the run (`orbit_drift`: the mean whirl "
             "radius changes monotonically over the analysed span by more than 10 % and 1 % of the guide "
             "clearance, \"DRIFT\" in the panel): their section is an open arc of the transient, so their class "
             "(often \"quasi-periodic\") is not that of an attractor; a longer run would settle them:", ""]
            + [f"- {d}" for d in drift] + [""])


def table6_lines(study: Study, datasets: dict[str, xr.Dataset]) -> list[str]:
    paper = study.spec.get("table6", {})
    if not paper:
        return []
    d = derive_table6(study, datasets)
    tids = [t["id"] for t in study.tables if t["id"] in datasets]
    heads = {t["id"]: t.get("table6_column", t["id"]) for t in study.tables}
    lines = ["## Table 6: recommended working condition per oil, the paper's and ours", "",
             f"Rule (ours): {TABLE6_RULE}", "",
             "| oil | " + " | ".join(f"{heads[k]}: paper | {heads[k]}: ours" for k in tids) + " |",
             "|" + "---|" * (1 + 2 * len(tids))]
    for o in study.oils:
        row = [o]
        for k in tids:
            row += [str(paper.get(o, {}).get(k, "-")), d["table"][o].get(k, "-")]
        lines.append("| " + " | ".join(row) + " |")
    lines += ["", "The most stable oil at every condition (ours; the basis of the table above):", ""]
    for k in tids:
        for value, winners, detail in d["best"][k]:
            lines.append(f"- {k}, {value}: **{', '.join(winners) or '-'}** ({detail})")
    return lines + [""]


def _version() -> str:
    from hsbearing._version import __version__

    return __version__


def _host() -> str:
    import platform

    return platform.node() or "?"


# ----------------------------------------------------------------------------- shared by both reports


def _figure_dir(out: Path) -> Path:
    figdir = out / FIGURES
    figdir.mkdir(parents=True, exist_ok=True)
    return figdir


def _preamble(study: Study, info: dict, title: str, *, bands: bool) -> list[str]:
    """Title, source and generating command, and the warning of a stand-in point function."""
    st = study.spec["study"]
    flag = " --bands" if bands else ""
    lines = [f"# {title}", "",
             f"Source: {st.get('source', '')}. Study definition: `hsbearing/studies/{study.name}.toml`"
             + (" (`[bands]`)" if bands else "") + f"; generated by `hsbearing study {study.name}{flag}` "
             f"(hsbearing {_version()}) on {time.strftime('%Y-%m-%d %H:%M UTC', time.gmtime())}.", ""]
    if info.get("point_fn"):
        lines += [f"> **Not the dynamic model.** The points of this report were computed by the point function "
                  f"`{info['point_fn']}` (a stand-in used to test the study machinery); its classifications "
                  "say nothing about the bearing.", ""]
    return lines


def _duration_line(info: dict, stop_note: str) -> str:
    """The simulated time per point, and the stop rule when it is ``converged`` (``stop_note`` in brackets)."""
    dur = info.get("duration")
    return (f"- simulated time per point: {fmt(dur * 1e3 if dur else float('nan'), '.4g')} ms"
            + ("" if dur else " (the case's `[simulation] duration`)")
            + (f" at most: stop rule `converged` ({stop_note})" if info.get("stop") == "converged" else ""))


def _extension_line(info: dict, datasets: dict) -> str:
    """The extension of undetermined runs, and how many cells were extended (each archive says how far and why it
    stopped: ``extensions``, ``extension_stop_reason``)."""
    text = info.get("extension", "none")
    if text == "none":
        return "- extension of undetermined runs: none"
    n = sum(int((np.nan_to_num(np.asarray(ds["extension_count"].values, float)) > 0).sum())
            for ds in datasets.values() if "extension_count" in ds)
    return f"- extension: {text}; {n} table cell(s) extended (archives: `extensions`, `extension_stop_reason`)"


def _execution_line(info: dict, cores) -> str:
    return f"- execution: {info['backend']} on {cores} core(s) of `{_host()}`"


def _wall_line(info: dict, what: str) -> str:
    """The wall time of this invocation (``what``: "the whole study", "the banded study")."""
    if info["backend"].startswith("report only"):
        return f"- wall time of this invocation (report only: nothing computed): {info['wall_time']:.1f} s"
    return f"- **wall time of {what} (this invocation): {info['wall_time']:.1f} s**"


def _not_ok_points(datasets: dict[str, xr.Dataset]):
    """(table id, point) of every point of the tables whose status is not ok, in table and index order."""
    for tid, ds in datasets.items():
        for idx in np.ndindex(*ds["status"].shape):
            pt = ds.isel(dict(zip(ds["status"].dims, idx)))
            if pt["status"].item() != sweeps.STATUS_OK:
                yield tid, pt


def _failed_line(tid: str, pt: xr.Dataset) -> str:
    where = ", ".join(f"{str(c)[:-6]}={pt[c].item()}" for c in pt.coords if str(c).endswith("_label"))
    return f"- {tid}: {where}: {pt['status'].item()}: {pt['error'].item()}"
