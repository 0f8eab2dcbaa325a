"""The comparison page: ``compare.nc``, ``compare.md``, ``index.html`` and its figures (PNG files next to it, linked by
relative paths: the page opens offline; no network resource, no script).

Every file is written atomically (temporary file, then rename); ``index.html`` last, so a page that exists refers
to figures and numbers that exist.
"""

from __future__ import annotations

import html
import math
from pathlib import Path

import numpy as np
import xarray as xr

#: file names inside the output directory (the fourth-round contract: index.html, compare.md, a netCDF over ``oil``)
NC_NAME, MD_NAME, HTML_NAME = "compare.nc", "compare.md", "index.html"


def write_dataset(ds: xr.Dataset, out: Path) -> Path:
    from hsbearing.results import write_netcdf

    return write_netcdf(ds, Path(out) / NC_NAME)

#: the rows of the numbers table, in order (each shown when compare.nc carries it); power_loss_<source> rows are
#: inserted after ``power_loss`` / ``dynamic_power_loss`` for the sources that are not zero for every oil
ROWS = (
    ("cage", ("classification", "classification_confidence", "mean_cage_slip_ratio", "whirl_amplitude",
              "whirl_frequency_ratio", "cage_slip_ratio", "cage_speed")),
    ("power (quasi-static)", ("power_loss", "drag_band_power_loss_low", "drag_band_power_loss_high", "drive_torque")),
    ("power (dynamic run)", ("dynamic_power_loss", "dynamic_drive_torque")),
    ("thermal equilibrium", ("inner_ring_temperature", "outer_ring_temperature", "ball_temperature", "cage_temperature",
                             "oil_outlet_temperature", "lubricant_temperature", "heat_generated", "heat_removed_by_oil",
                             "heat_removed_by_conduction")),
    ("film and pressure", ("min_film_thickness", "min_film_parameter", "max_contact_pressure")),
    ("rating life", ("viscosity_ratio", "life_modification_factor", "basic_rating_life", "modified_rating_life",
                     "reference_rating_life", "modified_reference_rating_life")),
)
#: labels users read (the variable name is kept in the page's tooltip and in compare.md)
LABELS = {
    "classification": "cage-motion class", "classification_confidence": "class confidence",
    "mean_cage_slip_ratio": "cage slip ratio (dynamic mean)", "whirl_amplitude": "cage whirl radius (RMS)",
    "whirl_frequency_ratio": "whirl frequency / cage speed", "cage_slip_ratio": "cage slip ratio (quasi-static)",
    "cage_speed": "cage speed (quasi-static)", "power_loss": "power loss (quasi-static)",
    "drag_band_power_loss_low": "  at the drag band's low end", "drag_band_power_loss_high": "  at the drag band's high end",
    "drive_torque": "drive torque (quasi-static)", "dynamic_power_loss": "power loss (dynamic run)",
    "dynamic_drive_torque": "drive torque (dynamic run)", "min_film_thickness": "smallest h_min",
    "min_film_parameter": "smallest lambda", "max_contact_pressure": "largest p_max",
    "viscosity_ratio": "kappa (ISO 281)", "life_modification_factor": "a_ISO", "basic_rating_life": "L_10",
    "modified_rating_life": "L_10m", "reference_rating_life": "L_10r (ISO/TS 16281)",
    "modified_reference_rating_life": "a_ISO L_10r",
}
#: criteria read from the dynamic run (their ranking is flagged when a run's class is undetermined)
_DYNAMIC = ("dynamic_power_loss", "mean_cage_slip_ratio", "whirl_amplitude")
_LIVES = ("basic_rating_life", "modified_rating_life", "reference_rating_life", "modified_reference_rating_life")


def fmt(value, units: str, name: str = "", *, difference: bool = False) -> str:
    """One number as users read it (hsbearing.display), '' for a missing value."""
    from hsbearing.display import format_life, format_quantity

    if isinstance(value, (str, bytes)) or (isinstance(value, np.ndarray) and value.dtype == object):
        return str(value)
    try:
        v = float(value)
    except (TypeError, ValueError):
        return str(value)
    if not math.isfinite(v):
        return "n/a"
    if difference and units == "K":  # a temperature difference, not a temperature
        return f"{v:.3g} K"
    if name.removeprefix("dynamic_") in _LIVES or units == "1e6 rev":
        return format_life(v)
    return format_quantity(v, units, name)


def vary_points(ds: xr.Dataset) -> list[tuple[dict, str]]:
    """The points of the varied keys (besides the oil): (isel dict, label) -- one point ``({}, "")`` without."""
    dims = [d for d in ds["quasistatic_status"].dims if d != "oil"]
    if not dims:
        return [({}, "")]
    out = []
    for idx in np.ndindex(*(ds.sizes[d] for d in dims)):
        sel = dict(zip(dims, idx))
        label = ", ".join(f"{d} = {ds[f'{d}_label'].values[i] if f'{d}_label' in ds else ds[d].values[i]}"
                          for d, i in sel.items())
        out.append((sel, label))
    return out


def _sources(ds, prefix: str) -> list[str]:
    names = [str(v) for v in ds.data_vars if str(v).startswith(prefix) and not str(v).startswith(prefix + "band")]
    keep = []
    for n in names:
        rest = n[len(prefix):]
        if prefix == "power_loss_" and rest.startswith(("low", "high")):
            continue
        a = np.asarray(ds[n].values, dtype=float)
        if np.any(np.isfinite(a) & (np.abs(a) > 1e-12)):
            keep.append(n)
    return keep


def row_names(ds) -> list[tuple[str, list[str]]]:
    out = []
    for group, names in ROWS:
        rows = []
        for n in names:
            if n not in ds:
                continue
            rows.append(n)
            if n == "power_loss":
                rows += _sources(ds, "power_loss_")
            if n == "dynamic_power_loss":
                rows += _sources(ds, "dynamic_power_loss_")
        if rows:
            out.append((group, rows))
    return out


def label_of(name: str) -> str:
    if name in LABELS:
        return LABELS[name].strip()
    for prefix, what in (("dynamic_power_loss_", "  dynamic: "), ("power_loss_", "  ")):
        if name.startswith(prefix):
            return (what + name[len(prefix):].replace("_", " ")).strip()
    return name.replace("_", " ")


def numbers_table(ds, sel: dict) -> tuple[list[str], list[list[str]]]:
    """(header, rows) of the numbers table at one point of the varied keys: one column per oil."""
    names = [str(n) for n in ds["oil_name"].values]
    header = ["quantity"] + names
    rows = []
    for group, rnames in row_names(ds):
        rows.append([f"**{group}**"] + [""] * len(names))
        for n in rnames:
            v = ds[n].isel(sel) if sel else ds[n]
            units = v.attrs.get("units", "")
            rows.append([label_of(n)] + [fmt(v.isel(oil=i).values.item() if v.dtype != object else v.isel(oil=i).values.item(),
                                             units, n) for i in range(len(names))])
    return header, rows


def best_table(ds, sel: dict) -> tuple[list[str], list[list[str]]]:
    """(header, rows) of 'which oil is best, by how much' at one point of the varied keys."""
    header = ["criterion", "best", "value", "runner-up", "by", "relative", "uncertainty"]
    rows = []
    if "criterion" not in ds.dims:
        return header, rows
    for i in range(ds.sizes["criterion"]):
        pt = {**sel, "criterion": i}
        units = str(ds["criterion_units"].values[i])
        var = str(ds["criterion_variable"].values[i])
        best = str(ds["best_oil"].isel(pt).values.item())
        if not best:
            continue
        rel = float(ds["best_relative_margin"].isel(pt).values)
        rel_txt = ("-" if units == "K" else "n/a") if not math.isfinite(rel) else (f"{rel * 100:.3g} %" + (" (no difference)" if rel < 1e-3 else ""))
        unc = ""
        if "best_oil_band_low" in ds and str(ds["best_oil_band_low"].isel(pt).values.item()):
            lo, hi = (str(ds[f"best_oil_band_{e}"].isel(pt).values.item()) for e in ("low", "high"))
            mlo, mhi = (float(ds[f"best_margin_band_{e}"].isel(pt).values) for e in ("low", "high"))
            same = lo == hi == best
            unc = (f"drag band: best at both ends, by {fmt(mlo, units, var, difference=True)} .. "
                   f"{fmt(mhi, units, var, difference=True)}" if same else
                   f"drag band: best is {lo} at the low end, {hi} at the high end: the ranking is not settled")
        if var in _DYNAMIC and "classification" in ds:  # a run whose class is undetermined has no final answer yet
            names = [str(n) for n in ds["oil_name"].values]
            cls = ds["classification"].isel(sel) if sel else ds["classification"]
            open_ = [n for k, n in enumerate(names) if n in (best, str(ds["runner_up_oil"].isel(pt).values.item()))
                     and str(cls.isel(oil=k).values.item()).startswith("undetermined")]
            if open_:
                unc = (unc + "; " if unc else "") + f"class undetermined for {', '.join(open_)}: not a final answer"
        rows.append([str(ds["criterion_description"].values[i]), best,
                     fmt(float(ds["best_value"].isel(pt).values), units, var),
                     str(ds["runner_up_oil"].isel(pt).values.item()) or "-",
                     fmt(float(ds["best_margin"].isel(pt).values), units, var, difference=True) if str(ds["runner_up_oil"].isel(pt).values.item()) else "-",
                     rel_txt, unc])
    return header, rows


def oils_table(ds) -> tuple[list[str], list[list[str]]]:
    header = ["oil", "given as", "where its data come from", "notices"]
    rows = []
    for i, o in enumerate(ds["oil"].values):
        prov = _first_text(ds, "lubricant_provenance", i)
        notes = _first_text(ds, "lubricant_notices", i) or "none"
        rows.append([str(ds["oil_name"].values[i]), str(o), prov, notes])
    return header, rows


def _first_text(ds, name, i) -> str:
    if name not in ds:
        return ""
    vals = np.asarray(ds[name].isel(oil=i).values, dtype=object).ravel()
    return next((str(v) for v in vals if str(v)), "")


# ----------------------------------------------------------------------------- figures


def _grouped_bars(ax, ds, sel_list, oils, get, *, stacked=None, err=None):
    """Bars per oil, grouped by point of the varied keys; ``get(sel, i)`` the value; ``stacked``: list of
    (label, get) drawn stacked instead; ``err(sel, i) -> (low, high)`` an error bar."""
    import matplotlib

    n_o, n_g = len(oils), len(sel_list)
    width = 0.8 / n_o
    colours = matplotlib.colormaps["tab10"]
    for j, (sel, _) in enumerate(sel_list):
        for i in range(n_o):
            x = j + (i - (n_o - 1) / 2) * width
            if stacked:
                bottom = 0.0
                for k, (lab, g) in enumerate(stacked):
                    v = g(sel, i)
                    if math.isfinite(v) and v != 0:
                        ax.bar(x, v, width * 0.9, bottom=bottom, color=colours(k % 10),
                               label=lab if (i == 0 and j == 0) else None)
                        bottom += v
            else:
                v = get(sel, i)
                if math.isfinite(v):
                    ax.bar(x, v, width * 0.9, color=colours(i % 10), label=oils[i] if j == 0 else None)
            if err is not None:
                lo, hi = err(sel, i)
                if math.isfinite(lo) and math.isfinite(hi):
                    ax.plot([x, x], [lo, hi], color="k", lw=1.2)
                    ax.plot([x - width * 0.2, x + width * 0.2], [lo, lo], color="k", lw=1.2)
                    ax.plot([x - width * 0.2, x + width * 0.2], [hi, hi], color="k", lw=1.2)
    if n_g == 1:
        ax.set_xticks([(i - (n_o - 1) / 2) * width for i in range(n_o)], oils, rotation=20, ha="right", fontsize=8)
    else:
        ax.set_xticks(range(n_g), [lab for _, lab in sel_list], rotation=20, ha="right", fontsize=8)


def _val(ds, name, sel, i, scale=1.0, offset=0.0):
    if name not in ds:
        return math.nan
    v = ds[name].isel(sel) if sel else ds[name]
    try:
        return float(v.isel(oil=i).values) * scale + offset
    except (TypeError, ValueError):
        return math.nan


def power_figure(ds, path: Path) -> Path | None:
    """Power loss by source per oil (quasi-static, with the drag band as an error bar; the dynamic run beside)."""
    from hsbearing.plotting.common import _figure, save_figure

    oils = [str(n) for n in ds["oil_name"].values]
    pts = vary_points(ds)
    panels = [("quasi-static power loss by source [W]", "power_loss_", "drag_band_power_loss")]
    if "dynamic_power_loss" in ds:
        panels.append(("dynamic run: power loss by source [W] (time mean)", "dynamic_power_loss_", None))
    fig = _figure((5.2 * len(panels) + 1.5, 4.4))
    for k, (title, prefix, band) in enumerate(panels):
        ax = fig.add_subplot(1, len(panels), k + 1)
        srcs = _sources(ds, prefix)
        stacked = [(s[len(prefix):].replace("_", " "), (lambda sel, i, s=s: _val(ds, s, sel, i))) for s in srcs]
        err = None
        if band and f"{band}_low" in ds:
            err = (lambda sel, i, b=band: (_val(ds, f"{b}_low", sel, i), _val(ds, f"{b}_high", sel, i)))
        _grouped_bars(ax, ds, pts, oils, None, stacked=stacked, err=err)
        ax.set_title(title + ("\n(bar: the drag band)" if err else ""), fontsize=9)
        ax.grid(axis="y", alpha=0.3)
        if k == len(panels) - 1:
            ax.legend(fontsize=7, loc="upper left", bbox_to_anchor=(1.0, 1.0))
    fig.suptitle("Power loss by source, " + ", ".join(oils), fontsize=10)
    return save_figure(fig, path)


#: the panels of the per-criterion figure: (variable, title, scale, offset)
CRITERIA_PANELS = (
    ("power_loss", "power loss, quasi-static [W]", 1.0, 0.0),
    ("dynamic_power_loss", "power loss, dynamic run [W]", 1.0, 0.0),
    ("mean_cage_slip_ratio", "cage slip ratio, dynamic [%]", 100.0, 0.0),
    ("whirl_amplitude", "cage whirl radius (RMS) [um]", 1e6, 0.0),
    ("min_film_parameter", "smallest lambda [-]", 1.0, 0.0),
    ("min_film_thickness", "smallest h_min [nm]", 1e9, 0.0),
    ("max_contact_pressure", "largest p_max [GPa]", 1e-9, 0.0),
    ("modified_rating_life", "L_10m [million rev]", 1.0, 0.0),
    ("inner_ring_temperature", "inner ring at equilibrium [degC]", 1.0, -273.15),
    ("oil_outlet_temperature", "oil outlet at equilibrium [degC]", 1.0, -273.15),
)


def criteria_figure(ds, path: Path) -> Path | None:
    """One small panel per criterion the comparison carries: bars per oil (grouped by point of the varied keys)."""
    from hsbearing.plotting.common import _figure, save_figure

    oils = [str(n) for n in ds["oil_name"].values]
    pts = vary_points(ds)
    panels = [p for p in CRITERIA_PANELS if p[0] in ds and np.any(np.isfinite(np.asarray(ds[p[0]].values, float)))]
    if not panels:
        return None
    ncol = min(3, len(panels))
    nrow = math.ceil(len(panels) / ncol)
    fig = _figure((4.0 * ncol, 3.0 * nrow + 0.6))
    for k, (name, title, scale, offset) in enumerate(panels):
        ax = fig.add_subplot(nrow, ncol, k + 1)
        _grouped_bars(ax, ds, pts, oils, lambda sel, i, n=name, s=scale, o=offset: _val(ds, n, sel, i, s, o))
        ax.set_title(title, fontsize=9)
        ax.grid(axis="y", alpha=0.3)
        if name.endswith("temperature"):
            lo = min(_val(ds, name, sel, i, scale, offset) for sel, _ in pts for i in range(len(oils)))
            if math.isfinite(lo):
                ax.set_ylim(bottom=lo - 10.0)
    fig.suptitle("Oils at the same conditions: " + ", ".join(oils), fontsize=10)
    return save_figure(fig, path)


def draw_figures(ds, sweeps, out: Path) -> tuple[list[tuple[str, str]], list[str]]:
    """Draw every figure into ``out``; returns ([(file name, caption)], [notes on figures not drawn])."""
    from hsbearing.case import CaseError
    from hsbearing.plotting import plot_sweep

    figs, notes = [], []
    for fn, name, cap in ((criteria_figure, "criteria.png", "Each criterion per oil."),
                          (power_figure, "power_by_source.png", "Power loss by source per oil: quasi-static (error bar: "
                                                                "the total at the two ends of the drag band) and, when "
                                                                "run, the dynamic run's time mean.")):
        try:
            if fn(ds, out / name) is not None:
                figs.append((name, cap))
        except (ValueError, KeyError, TypeError) as exc:
            notes.append(f"{name} not drawn: {type(exc).__name__}: {exc}")
    for kind, name, cap in (("quasistatic", "quasistatic.png", "The quasi-static sweep over the oils (hsbearing sweep's figure)."),
                            ("run", "dynamic.png", "The dynamic runs over the oils: cage slip, whirl, class (hsbearing sweep's figure)."),
                            ("thermal", "thermal.png", "The thermal equilibria over the oils (hsbearing sweep's figure).")):
        if kind not in sweeps:
            continue
        try:
            plot_sweep(sweeps[kind], out / name)
            figs.append((name, cap))
        except (CaseError, ValueError, KeyError, TypeError) as exc:
            notes.append(f"{name} not drawn: {exc}")
    return figs, notes


# ----------------------------------------------------------------------------- markdown and HTML


def _md_table(header, rows) -> str:
    def cell(x):
        return str(x).replace("|", "\\|").replace("\n", " ")

    lines = ["| " + " | ".join(cell(h) for h in header) + " |", "|" + "---|" * len(header)]
    lines += ["| " + " | ".join(cell(c) for c in r) + " |" for r in rows]
    return "\n".join(lines)


def _html_table(header, rows) -> str:
    def cell(x, tag):
        x = str(x)
        if x.startswith("**") and x.endswith("**"):
            return f"<{tag} class='group'>{html.escape(x[2:-2])}</{tag}>"
        return f"<{tag}>{html.escape(x)}</{tag}>"

    out = ["<table>", "<thead><tr>" + "".join(cell(h, "th") for h in header) + "</tr></thead>", "<tbody>"]
    out += ["<tr>" + "".join(cell(c, "td") for c in r) + "</tr>" for r in rows]
    out.append("</tbody></table>")
    return "\n".join(out)


def _conditions(ds) -> list[str]:
    a = ds.attrs
    lines = [f"case: {a.get('case_name', '')}", f"dynamics: {a.get('compare_dynamics', '')}",
             f"thermal: {a.get('compare_thermal', '')}"]
    try:
        import tomllib

        c = tomllib.loads(a.get("case_toml", ""))
        op, lub = c.get("operating", {}), c.get("lubricant", {})
        lines.insert(1, "conditions: " + ", ".join(f"{k} = {op[k]}" for k in ("inner_speed", "outer_speed", "axial_load",
                                                                              "radial_load") if k in op)
                     + (f", oil temperature = {lub['temperature']}" if "temperature" in lub else "")
                     + (f", oil flow = {lub['oil_flow_rate']}" if "oil_flow_rate" in lub else ""))
    except (ValueError, TypeError):
        pass
    vary = a.get("compare_vary", "{}")
    if vary not in ("{}", ""):
        lines.append(f"varied besides the oil: {vary}")
    lines.append(f"status: {a.get('status', '')}")
    return lines


READING = ("The three power losses are different models: the quasi-static value (the dynamic model's contact laws at the "
           "quasi-static state, plus jet-oil acceleration and cage windage) and the dynamic run's time mean (cage "
           "whirl and pocket contacts included) are compared in docs/power_loss.md. Race traction of an oil whose "
           "traction is borrowed from another oil is that oil's, not a result (see the notices). A relative difference "
           "below 0.1 % is marked 'no difference'.")


def markdown(ds, figs, notes) -> str:
    parts = ["# Lubricant comparison", ""] + [f"- {x}" for x in _conditions(ds)] + ["", READING, "",
                                                                                    "## Oils and where their data come from", "",
                                                                                    _md_table(*oils_table(ds)), ""]
    for sel, label in vary_points(ds):
        suffix = f" ({label})" if label else ""
        parts += [f"## Best oil per criterion{suffix}", "", _md_table(*best_table(ds, sel)), "",
                  f"## Numbers per oil{suffix}", "", _md_table(*numbers_table(ds, sel)), ""]
    parts += ["## Figures", ""]
    for name, cap in figs:
        parts += [f"![{cap}]({name})", "", f"*{cap}*", ""]
    parts += [f"- {n}" for n in notes]
    parts += ["", f"Numbers: `{NC_NAME}` (dimension `oil`); point archives: `points/`.", ""]
    return "\n".join(parts)


CSS = ("body{font-family:sans-serif;max-width:1200px;margin:1em auto;padding:0 1em;color:#222}"
       "table{border-collapse:collapse;margin:0.5em 0 1.5em}td,th{border:1px solid #bbb;padding:3px 8px;"
       "font-size:0.9em;text-align:left;vertical-align:top}th{background:#eee}td.group{background:#f6f6f6;"
       "font-weight:bold}img{max-width:100%;border:1px solid #ddd}figure{margin:1em 0}"
       "figcaption{font-size:0.9em;color:#555}")


def html_page(ds, figs, notes) -> str:
    e = html.escape
    parts = ["<!DOCTYPE html>", "<html lang='en'><head><meta charset='utf-8'>",
             "<title>hsbearing: lubricant comparison</title>", f"<style>{CSS}</style></head><body>",
             "<h1>Lubricant comparison</h1>", "<ul>"]
    parts += [f"<li>{e(x)}</li>" for x in _conditions(ds)] + ["</ul>", f"<p>{e(READING)}</p>",
                                                              "<h2>Oils and where their data come from</h2>",
                                                              _html_table(*oils_table(ds))]
    for sel, label in vary_points(ds):
        suffix = f" ({label})" if label else ""
        parts += [f"<h2>Best oil per criterion{e(suffix)}</h2>", _html_table(*best_table(ds, sel)),
                  f"<h2>Numbers per oil{e(suffix)}</h2>", _html_table(*numbers_table(ds, sel))]
    parts.append("<h2>Figures</h2>")
    for name, cap in figs:
        parts.append(f"<figure><img src='{e(name)}' alt='{e(cap)}'><figcaption>{e(cap)}</figcaption></figure>")
    parts += [f"<p>{e(n)}</p>" for n in notes]
    parts.append(f"<p>Numbers: <a href='{NC_NAME}'>{NC_NAME}</a> (dimension <code>oil</code>); "
                 f"<a href='{MD_NAME}'>{MD_NAME}</a>; point archives in <code>points/</code>. "
                 f"hsbearing {e(str(ds.attrs.get('hsbearing_version', '')))}, {e(str(ds.attrs.get('created', '')))}.</p>")
    parts.append("</body></html>")
    return "\n".join(parts) + "\n"


def _write_text(path: Path, text: str) -> None:
    from hsbearing.errors import OutputWriteError
    from hsbearing.results import atomic_write

    try:
        with atomic_write(path, suffix=path.suffix) as tmp:
            tmp.write_text(text, encoding="utf-8")
    except OSError as exc:
        raise OutputWriteError(path, exc.strerror or str(exc), note="not written") from None


def write_all(ds, sweeps, out: Path, *, figures: bool = True) -> dict:
    """compare.nc, the figures, compare.md and (last) index.html into ``out``; returns their paths."""
    out = Path(out)
    paths = {"netcdf": write_dataset(ds, out)}
    figs, notes = draw_figures(ds, sweeps, out) if figures else ([], ["figures not drawn (--no-figure)"])
    _write_text(out / MD_NAME, markdown(ds, figs, notes))
    _write_text(out / HTML_NAME, html_page(ds, figs, notes))
    paths.update(markdown=out / MD_NAME, html=out / HTML_NAME, figures=[out / n for n, _ in figs])
    return paths
