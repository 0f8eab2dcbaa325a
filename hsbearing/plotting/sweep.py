"""The sweep / study summary figure (``DIR/sweep.png``, ``DIR/<table>.png``, ``hsbearing plot SUMMARY.nc``): the
summary variables against the varied keys, for every system."""

from __future__ import annotations

import math
import tomllib
from pathlib import Path

import numpy as np

from hsbearing.plotting import common  # common.save_figure: one place to capture every figure
from hsbearing.plotting.common import RPM, case_labels

# ----------------------------------------------------------------------------- sweep / study summary figure
#
# A sweep Dataset (hsbearing.workflows.sweeps.assemble) has one dimension per varied key (``point`` for --zip),
# an SI coordinate per key with ``units`` / ``case_key`` attrs and ``<dim>_label`` (the values as
# written), a ``status`` per point and the per-point summary variables.  The figure draws those
# summaries against the varied key with the most numeric values (x axis); every other varied key
# gives one line per value (or per combination of values).  With a cage-motion classification and
# more than one varied key, a categorical map of the classes (the layout of Zhang et al. 2016 Tables 3-5)
# is drawn on top, with the paper's label of every cell when the summary carries
# ``paper_classification`` (study tables).

#: Marker and colour of each cage-motion class (:data:`hsbearing.analysis.periods.LABELS`;
#: ``"k periods"`` stands for every k >= 2, the cell text of the map keeps the k).
CLASS_STYLE = {
    "1 period": ("o", "#2ca02c"),
    "k periods": ("s", "#1f77b4"),
    "quasi-periodic": ("D", "#ff7f0e"),
    "chaos": ("^", "#9467bd"),
    "undetermined": ("o", "#8c8c8c"),
}
#: Marker and colour of a point whose status is not ``ok`` (drawn at the bottom of every panel).
NOT_OK_STYLE = ("x", "#d62728")
#: Most lines (series) in one panel; more is refused with a CaseError (plot a slice of the Dataset).
MAX_SERIES = 10
#: Same, when the lines are the values of one numeric key (ordered colours and a colour bar instead of a legend).
MAX_ORDERED_SERIES = 30

# (panel title, y label with its unit, factor SI -> unit or (factor, offset), ((variable, legend label, line style), ...)), in
# drawing order (friction moments first for a gyro sweep); a panel is drawn only if one of its variables is
# present with a finite value at an ok point.
_SWEEP_PANELS = (
    # the slip against the nominal contact angle reads as an overspeed at light load (-10.6 % at 100 N); the
    # raceway-control slip (epicyclic speed at the running contact angles, as `run` prints) is drawn beside it
    ("mean cage slip ratio", "slip ratio [%]", 100.0, (("mean_cage_slip_ratio", "vs nominal contact angle", "-"),
                                                       ("mean_cage_slip_ratio_raceway_control",
                                                        "vs raceway control (running angles)", "--"),
                                                       ("cage_slip_ratio", "quasi-static state", "-"))),
    ("cage whirl radius", "whirl radius [\u00b5m]", 1e6, (("whirl_amplitude", "RMS (whirl amplitude)", "-"),
                                                           ("whirl_radius_max", "max", ":"))),
    ("whirl frequency / cage speed", "frequency ratio [-]", 1.0, (("whirl_frequency_ratio", None, "-"),)),
    ("inner race contact load $Q_i$", "$Q_i$ [N]", 1.0, (("mean_inner_contact_load", "mean over balls", "-"),
                                                       ("max_inner_contact_load", "max over balls", "--"))),
    ("outer race contact load $Q_o$", "$Q_o$ [N]", 1.0, (("mean_outer_contact_load", "mean over balls", "-"),
                                                       ("max_outer_contact_load", "max over balls", "--"))),
    ("cage speed", "cage speed [r/min]", RPM, (("cage_speed", None, "-"),)),
    ("inner ring axial displacement", "displacement [\u00b5m]", 1e6, (("inner_ring_axial_displacement", None, "-"),)),
    # what users compare (run: mean after the transient; quasi-static: at the state): power, torque, film, pressure
    ("power loss", "power [W]", 1.0, (("power_loss", None, "-"),)),
    ("power loss by source", "power [W]", 1.0,
     (("power_loss_race_traction", "race traction", "-"), ("power_loss_ehl_rolling", "EHL rolling", "--"),
      ("power_loss_contact_damping", "contact damping", ":"), ("power_loss_pocket_film", "pocket film", "-."),
      ("power_loss_pocket_boundary", "pocket boundary", "-"), ("power_loss_guide_land", "guide land", "--"),
      ("power_loss_drag", "ball drag", ":"))),
    ("drive torque", "torque [N mm]", 1e3, (("drive_torque", None, "-"),)),
    ("smallest minimum film thickness $h_{min}$", "$h_{min}$ [nm]", 1e9, (("min_film_thickness", None, "-"),)),
    ("smallest film parameter \u03bb", "\u03bb [-]", 1.0, (("min_film_parameter", None, "-"),)),
    ("largest contact pressure $p_{max}$", "$p_{max}$ [GPa]", 1e-9, (("max_contact_pressure", None, "-"),)),
    # thermal sweeps (kind = "thermal"): temperatures in degC (factor, offset), heats in W
    ("component temperatures", "temperature [\N{DEGREE SIGN}C]", (1.0, -273.15),
     (("inner_ring_temperature", "inner ring", "-"), ("outer_ring_temperature", "outer ring", "--"),
      ("ball_temperature", "balls", ":"), ("oil_outlet_temperature", "oil outlet", "-."),
      ("cage_temperature", "cage", "-"), ("housing_temperature", "housing", "--"), ("shaft_temperature", "shaft", ":"))),
    ("lubricant temperature at equilibrium", "temperature [\N{DEGREE SIGN}C]", (1.0, -273.15),
     (("lubricant_temperature", None, "-"),)),
    ("heat generated and where it goes", "heat [W]", 1.0,
     (("heat_generated", "generated", "-"), ("heat_removed_by_oil", "removed by the oil", "--"),
      ("heat_removed_by_conduction", "conducted to the air", ":"))),
    ("heat by path", "heat [W]", 1.0,
     (("heat_flow_balls_to_inner_ring", "balls \u2192 inner ring", "-"),
      ("heat_flow_balls_to_outer_ring", "balls \u2192 outer ring", "--"),
      ("heat_flow_inner_ring_to_oil", "inner ring \u2192 oil", ":"), ("heat_flow_outer_ring_to_oil", "outer ring \u2192 oil", "-."),
      ("heat_flow_balls_to_oil", "balls \u2192 oil", "-"), ("heat_flow_cage_to_oil", "cage \u2192 oil", "--"),
      ("heat_flow_inner_ring_to_shaft", "inner ring \u2192 shaft", ":"),
      ("heat_flow_outer_ring_to_housing", "outer ring \u2192 housing", "-."),
      ("heat_flow_oil_to_oil_inlet", "carried off by the oil", "-"))),
    ("friction moments (Jiang et al. 2014)", "moment [\u00b5N m]", 1e6,
     (("sfmc", "SFMC", "-"), ("sfmc_ensemble_mean", "SFMC, start ensemble mean", "-."), ("sfmo", "SFMO", "--"),
      ("rfmc", "RFMC", ":"))),
)

# markers of the quantities of one panel when no class is drawn (mean / max, SFMC / SFMO / RFMC)
_ITEM_MARKERS = ("o", "s", "^", "D", "v", "P", "X", "*", "h")
# error bars: quantity -> (its spread in the summary, what the legend calls it)
_YERR = {"sfmo": ("sfmo_stderr", "standard error"), "sfmc_ensemble_mean": ("sfmc_ensemble_sd", "sd")}

# unit as written in a label -> as printed on an axis
_PRETTY_UNIT = {"rpm": "r/min", "degC": "\N{DEGREE SIGN}C", "deg": "\N{DEGREE SIGN}", "um": "\u00b5m",
                "N*m": "N m", "mm^2/s": "mm\u00b2/s", "kg/m^3": "kg/m\u00b3"}
# SI unit of a coordinate -> (factor, offset, unit) for display, when the labels do not share one unit
_SI_DISPLAY = {"rad/s": (RPM, 0.0, "r/min"), "K": (1.0, -273.15, "\N{DEGREE SIGN}C"),
               "rad": (180.0 / math.pi, 0.0, "\N{DEGREE SIGN}"), "N*m": (1.0, 0.0, "N m"),
               "m**2/s": (1e6, 0.0, "mm\u00b2/s"), "kg/m**3": (1.0, 0.0, "kg/m\u00b3")}
_LABEL_KEYS = {"lubricant.oil": "oil", "operating.inner_speed": "speed", "operating.axial_load": "axial_load",
               "operating.radial_load": "radial_load", "lubricant.temperature": "temperature"}


def is_sweep_summary(ds) -> bool:
    """True for a sweep or study summary Dataset.

    The attrs written by :func:`hsbearing.workflows.sweeps.assemble` (``title = "hsbearing sweep"``, ``sweep_vary``),
    or, for a summary whose attrs were lost, its shape: no ``time`` dimension and a text ``status``
    variable over at least one dimension (no result Dataset of a single run has one).
    """
    if ds.attrs.get("title") == "hsbearing sweep" or "sweep_vary" in ds.attrs:
        return True
    st = ds.variables.get("status") if hasattr(ds, "variables") else None
    return "time" not in ds.dims and st is not None and st.ndim >= 1 and st.dtype.kind in "OUS"


def class_family(label) -> str | None:
    """Key of :data:`CLASS_STYLE` for a classification label (``"4 periods"`` -> ``"k periods"``); None if empty."""
    label = str(label).strip()
    if not label or label == "nan":
        return None
    if label in CLASS_STYLE:
        return label
    head, _, tail = label.partition(" ")
    if head.isdigit() and tail in ("period", "periods"):
        return "1 period" if head == "1" else "k periods"
    return "undetermined"


def sweep_dims(ds) -> tuple[str, ...]:
    """The varied dimensions of a sweep summary: those of ``status`` (else every dim of the Dataset)."""
    if "status" in ds:
        return tuple(ds["status"].dims)
    return tuple(d for d in ds.dims)


def _is_text(values) -> bool:
    return np.asarray(values).dtype.kind in "OUS"


def _split_label(text: str):
    import re

    m = re.match(r"^\s*([-+]?(?:\d+\.?\d*|\.\d+)(?:[eE][-+]?\d+)?)\s*(.*?)\s*$", str(text))
    return (float(m.group(1)), m.group(2), m.group(1)) if m else None


def _pretty_label(text) -> str:
    """A value as written (``"6000 rpm"``) with its unit spelled for print (``"6000 r/min"``)."""
    p = _split_label(text)
    return f"{p[2]} {_PRETTY_UNIT.get(p[1], p[1])}".strip() if p else str(text)


def _fmt_num(v: float) -> str:
    return f"{v:.6g}"


class _SweepAxis:
    """Positions and text of one varied dimension: ``x`` (floats), ``labels`` (one per value), ``title``."""

    def __init__(self, ds, dim: str):
        self.dim = dim
        n = ds.sizes[dim]
        self.categorical = False
        coord = ds[dim] if dim in ds.coords else None
        if dim == "point":  # --zip: the keys vary together; the x axis is the point index
            keys = [str(c)[:-6] for c in ds.coords if str(c).endswith("_label") and ds[c].dims == ("point",)]
            self.labels = [", ".join(_pretty_label(ds[f"{k}_label"].values[i]) for k in keys) for i in range(n)] \
                if keys else [str(i) for i in range(n)]
            self.x = np.arange(n, dtype=float)
            self.categorical = True
            self.title = " + ".join(ds[k].attrs.get("case_key", k) for k in keys if k in ds.coords) or "point"
            return
        key = coord.attrs.get("case_key", dim) if coord is not None else dim
        lab = f"{dim}_label"
        given = [str(v) for v in ds[lab].values] if lab in ds.coords and ds[lab].dims == (dim,) else None
        if coord is None or _is_text(coord.values):
            vals = [str(v) for v in (coord.values if coord is not None else range(n))]
            self.labels = given or vals
            if key in ("lubricant.oil", "lubricant.file") and "lubricant_name" in ds:  # each oil by its own name
                names = ds["lubricant_name"].transpose(dim, ...).values.reshape(n, -1)
                self.labels = [next((str(x) for x in row if str(x) not in ("", "nan")), lab)
                               for row, lab in zip(names, self.labels)]
            # a lubricant file without its name in the summary (older sweeps): the file name, not its whole path
            self.labels = [Path(lab).name if lab.endswith(".toml") else lab for lab in self.labels]
            self.x = np.arange(n, dtype=float)
            self.categorical = True
            self.title = key
            return
        si = np.asarray(coord.values, dtype=float)
        parsed = [_split_label(g) for g in given] if given else None
        if parsed and all(p is not None for p in parsed) and len({p[1] for p in parsed}) == 1:
            # the values as the user wrote them ("6000 rpm", "27 degC", "0.15 mm"): their number and unit
            self.x = np.array([p[0] for p in parsed])
            unit = _PRETTY_UNIT.get(parsed[0][1], parsed[0][1])
        else:  # mixed units ("500 N, 1 kN") or no labels: the SI coordinate in a readable unit
            u = coord.attrs.get("units", "")
            f, off, unit = _SI_DISPLAY.get(u, (1.0, 0.0, "" if u in ("", "1") else u))
            if u == "m":
                f, unit = (1e3, "mm") if np.nanmax(np.abs(si)) >= 1e-4 else (1e6, "\u00b5m")
            elif u == "Pa":
                f, unit = (1e-9, "GPa") if np.nanmax(np.abs(si)) >= 1e8 else (1e-6, "MPa")
            self.x = si * f + off
        self.unit = unit
        if parsed and all(p is not None for p in parsed):  # as written, with the unit spelled for print
            self.labels = [_pretty_label(g) for g in given]
        else:
            self.labels = given or [_fmt_num(v) + (f" {unit}" if unit else "") for v in self.x]
        self.title = f"{key} [{unit}]" if unit else key


def _series_label(axes, idx) -> str:
    parts = []
    for ax, i in zip(axes, idx):
        lab = ax.labels[i]
        parts.append(f"{ax.dim} = {lab}" if ax.dim != "oil" else f"oil {lab}" if lab.isdigit() else lab)
    return ", ".join(parts)


def _grid_of(ds, name, order, shape, dtype=float):
    """Values of ``name`` as an array (series, x) in the order ``order`` of the sweep dims."""
    v = ds[name]
    missing = [d for d in order if d not in v.dims]
    if missing:  # a variable that does not vary along every sweep dim: broadcast
        v = v.expand_dims({d: ds.sizes[d] for d in missing})
    arr = np.asarray(v.transpose(*order).values)
    if dtype is float:
        try:
            arr = arr.astype(float)
        except (TypeError, ValueError):
            return None
    else:
        arr = arr.astype(str)
    return arr.reshape(shape)


def sweep_layout(ds) -> dict:
    """What :func:`plot_sweep` draws for a sweep summary, without drawing (also used by the tests).

    Returns a dict: ``x_dim``, ``series_dims``, ``n_series``, ``panels`` (titles),
    ``map`` (bool: classification map drawn), ``points``, ``not_ok`` (count), ``not_ok_points``
    (list of "label: status"), ``no_summary`` (ok points whose summary failed), ``classes``
    (count per class family).  Raises :class:`hsbearing.case.CaseError` for a Dataset that is not a
    summary it can draw (no varied dimension, too many series).
    """
    return _prepare_sweep(ds)["layout"]


def _prepare_sweep(ds) -> dict:
    from hsbearing.case import CaseError

    source = str(ds.encoding.get("source", "sweep summary"))
    dims = sweep_dims(ds)
    if not dims:
        raise CaseError(source, None, "a sweep summary without a varied dimension has nothing to plot")
    axes = {d: _SweepAxis(ds, d) for d in dims}
    numeric = [d for d in dims if not axes[d].categorical]
    # x: a numeric key with more than one value; else the categorical key (oils) with the most values
    pool = [d for d in numeric if ds.sizes[d] > 1] or [d for d in dims if ds.sizes[d] > 1] or numeric or list(dims)
    x_dim = max(pool, key=lambda d: (ds.sizes[d], -dims.index(d)))
    series_dims = [d for d in dims if d != x_dim]
    n_x = ds.sizes[x_dim]
    n_series = int(np.prod([ds.sizes[d] for d in series_dims])) if series_dims else 1
    ordered = len(series_dims) == 1 and not axes[series_dims[0]].categorical
    limit = MAX_ORDERED_SERIES if ordered else MAX_SERIES
    if n_series > limit:
        raise CaseError(source, None, f"{n_series} lines per panel over {', '.join(series_dims)} are too many for one "
                                      f"figure (at most {limit}); plot a slice, e.g. "
                                      f"hsbearing.plotting.plot_sweep(ds.isel({series_dims[0]}=[0, 1]), 'fig.png')")
    order = series_dims + [x_dim]
    shape = (n_series, n_x)
    series_idx = list(np.ndindex(*[ds.sizes[d] for d in series_dims])) if series_dims else [()]
    status = _grid_of(ds, "status", order, shape, str) if "status" in ds else np.full(shape, "ok")
    error = _grid_of(ds, "error", order, shape, str) if "error" in ds else np.full(shape, "")
    ok = status == "ok"
    no_summary = ok & np.char.startswith(error, "summary failed")
    good = ok & ~no_summary
    cls = None
    if "classification" in ds:
        raw = _grid_of(ds, "classification", order, shape, str)
        fam = np.vectorize(class_family, otypes=[object])(raw)
        if any(f is not None for f in fam[good]):
            cls = (raw, fam)
    paper = _grid_of(ds, "paper_classification", order, shape, str) if "paper_classification" in ds else None
    panels = []
    spec = _SWEEP_PANELS
    if ds.attrs.get("case_system") == "gyro_ribbon_cage":  # the friction moments are the result of interest
        spec = spec[-1:] + spec[:-1]
    yerr = {}  # error bars (gyro summaries): SFMO +/- its standard error, start-ensemble SFMC +/- its sd
    for name, (err, _) in _YERR.items():
        if name in ds and err in ds and ds[err].dtype.kind in "fiu":
            yerr[name] = _grid_of(ds, err, order, shape)
    for title, unit, factor, items in spec:
        factor, offset = factor if isinstance(factor, tuple) else (factor, 0.0)  # display = SI x factor + offset
        got = []
        for name, lab, ls in items:
            if name in yerr:
                yerr[name] = yerr[name] * factor
            if name in ds and ds[name].dtype.kind in "fiu":
                y = _grid_of(ds, name, order, shape)
                if y is not None and np.isfinite(y[good]).any():
                    if (len(items) > 1 and name.startswith(("power_loss_", "heat_flow_"))
                            and not (np.abs(np.nan_to_num(y[good])) > 1e-9).any()):
                        continue  # a source or path that is zero at every point (e.g. no pocket contact): no line
                    got.append((name, lab, ls, y * factor + offset))
        if (len(got) == 2 and got[0][0].startswith("mean_") and got[1][0].startswith("max_")
                and np.allclose(got[0][3][good], got[1][3][good], rtol=1e-9, equal_nan=True)):
            # mean = max over the balls (e.g. pure axial load): one line, and the legend says so
            got = [(got[0][0], "mean = max over balls", got[0][2], got[0][3])]
        if got:
            panels.append((title, unit, got))
    refs = {}  # horizontal reference lines: the cage guide clearance, when the same at every ok point
    if "whirl_radius_max" in ds and "guide_clearance_used" in ds:
        with np.errstate(divide="ignore", invalid="ignore"):
            gc = (_grid_of(ds, "whirl_radius_max", order, shape) / _grid_of(ds, "guide_clearance_used", order, shape))[good]
        gc = gc[np.isfinite(gc) & (gc > 0)]
        if gc.size and np.ptp(gc) <= 1e-3 * np.mean(gc):
            refs["cage whirl radius"] = [(float(np.mean(gc)) * 1e6, f"guide clearance {np.mean(gc) * 1e6:.0f} \u00b5m")]
    xa = axes[x_dim]
    bad_pts = []
    for s, idx in enumerate(series_idx):
        for j in range(n_x):
            if not good[s, j]:
                where = ", ".join([xa.labels[j]] + [axes[d].labels[i] for d, i in zip(series_dims, idx)])
                bad_pts.append(f"{where}: {'summary failed' if ok[s, j] else status[s, j]}")
    classes = {}
    if cls is not None:
        for f in cls[1][good]:
            if f is not None:
                classes[f] = classes.get(f, 0) + 1
    layout = {
        "x_dim": x_dim,
        "x_title": xa.title,
        "x": [float(v) for v in xa.x],
        "x_labels": list(xa.labels),
        "series_dims": series_dims,
        "n_series": n_series,
        "panels": [p[0] for p in panels],
        "map": cls is not None and (len(dims) > 1 or paper is not None),
        "colorbar": bool(ordered and n_series > 6),  # many ordered lines: a colour bar, not legend entries
        "points": int(status.size),
        "not_ok": int((~ok).sum()),
        "no_summary": int(no_summary.sum()),
        "not_ok_points": bad_pts,
        "classes": classes,
    }
    return {"layout": layout, "yerr": yerr, "refs": refs, "error": error, "axes": axes, "x_dim": x_dim,
            "series_dims": series_dims, "series_idx": series_idx, "status": status, "ok": ok, "good": good,
            "cls": cls, "paper": paper, "panels": panels, "source": source}


def _sweep_title(ds, prep) -> str:
    name = ds.attrs.get("case_name", "hsbearing")
    kind = ds.attrs.get("sweep_kind", "")
    dur = ds.attrs.get("sweep_duration", "")
    try:
        dur_txt = f", {float(dur):.3g} s simulated per point" if kind == "run" and str(dur) != "" else ""
    except (TypeError, ValueError):
        dur_txt = ""
    lay = prep["layout"]
    n, bad = lay["points"], lay["not_ok"]
    head = f"study {ds.attrs['study']}, {ds.attrs.get('study_table', '')}" if "study" in ds.attrs else "sweep"
    what = {"run": "dynamic runs", "quasistatic": "quasi-static equilibria",
            "thermal": "thermal equilibria"}.get(kind, kind or "points")
    line1 = f"{head} of case {name}: {what}{dur_txt}; {n - bad} of {n} points ok"
    if lay["no_summary"]:
        line1 += f" ({lay['no_summary']} without summary)"
    varied = [prep["axes"][d].title.split(" [")[0] for d in sweep_dims(ds)]
    keys = set()
    for d in sweep_dims(ds):
        c = ds[d] if d in ds.coords else None
        keys.add(c.attrs.get("case_key", d) if c is not None else d)
    for c in ds.coords:
        if str(c).endswith("_label") and ds[c].dims == ("point",):
            keys.add(ds[str(c)[:-6]].attrs.get("case_key", str(c)[:-6]) if str(c)[:-6] in ds.coords else str(c)[:-6])
    lab = case_labels(ds)
    if ds.attrs.get("case_system", "angular_contact") != "angular_contact":
        lab.pop("oil", None)  # the other systems carry the oil name as a placeholder: their models do not use it
    if lab.get("speed") == "n = 0 r/min":  # outer ring rotating (gyro bearings): show the outer-ring speed
        lab.pop("speed")
        if "operating.outer_speed" in keys or "outer_speed" in keys:  # varied: not a fixed condition
            n_o_varied = True
        else:
            n_o_varied = False
        from hsbearing.case import CaseError, parse_quantity

        try:
            n_o = parse_quantity(tomllib.loads(ds.attrs["case_toml"])["operating"]["outer_speed"], "angular_speed")
        except (KeyError, tomllib.TOMLDecodeError, CaseError):  # no case text or no outer speed: nothing to add
            n_o = 0.0
        if n_o and not n_o_varied:
            lab["speed"] = f"outer ring n$_o$ = {n_o * RPM:.3g} r/min"
    fixed = [lab[v] for k, v in _LABEL_KEYS.items() if v in lab and k not in keys and v not in keys]
    line2 = "varied: " + ", ".join(varied) + ("; fixed: " + ", ".join(fixed) if fixed else "")
    import textwrap

    return "\n".join(textwrap.wrap(line1, 110) + textwrap.wrap(line2, 110))  # long titles wrap, never clip


def _series_colours(prep):
    from matplotlib import colormaps

    n = prep["layout"]["n_series"]
    sd = prep["series_dims"]
    if n == 1:
        return ["0.25"]
    if len(sd) == 1 and not prep["axes"][sd[0]].categorical and n >= 3:  # ordered values: a sequential map
        cmap = colormaps["viridis"]
        return [cmap(0.85 * i / (n - 1)) for i in range(n)]
    return [f"C{i % 10}" for i in range(n)]


def _draw_sweep_panel(ax, prep, title, unit, items, colours, annotate_bad: bool) -> None:
    xa = prep["axes"][prep["x_dim"]]
    x = xa.x
    good, ok, status, cls = prep["good"], prep["ok"], prep["status"], prep["cls"]
    one = prep["layout"]["n_series"] == 1
    n_ser = prep["layout"]["n_series"]
    x0 = x
    for s in range(n_ser):
        col = colours[s]
        for k, (name, _lab, ls, y) in enumerate(items):
            if xa.categorical:  # categories (oils, zipped points): markers side by side in each category, no lines
                n_pos = n_ser * len(items)
                x = x0 + (s * len(items) + k - 0.5 * (n_pos - 1)) * min(0.7 / n_pos, 0.15)
            ys = np.where(good[s], y[s], np.nan)
            fin = np.isfinite(ys)
            if not xa.categorical:  # numbers: a line; NaN (not-ok or missing points) breaks it
                ax.plot(x, ys, ls=ls, color=col, lw=1.1, zorder=2)
            if name in prep["yerr"]:
                e = prep["yerr"][name][s]
                fe = fin & np.isfinite(e)
                ax.errorbar(x[fe], ys[fe], yerr=e[fe], fmt="none", ecolor=col, elinewidth=1.0, capsize=3, zorder=2)
            size = (34 if k == 0 else 20) if len(x) <= 12 and prep["layout"]["n_series"] <= 6 else (16 if k == 0 else 9)
            if cls is None or (xa.categorical and len(items) > 1):
                # no classes, or categories (no line style to tell them apart): the marker tells the quantities of
                # a panel apart (e.g. SFMC on top of RFMC, mean and max)
                ax.scatter(x[fin], ys[fin], marker=_ITEM_MARKERS[k % len(_ITEM_MARKERS)], s=size, color=col, zorder=3)
                continue
            fam = cls[1][s]
            for f, (mk, ccol) in CLASS_STYLE.items():
                m = fin & np.array([g == f for g in fam])
                if not m.any():
                    continue
                c = ccol if one else col
                if f == "undetermined":
                    ax.scatter(x[m], ys[m], marker=mk, s=size, facecolors="none", edgecolors=c, linewidths=1.2, zorder=3)
                else:
                    ax.scatter(x[m], ys[m], marker=mk, s=size, color=c, edgecolors="k" if one else c,
                               linewidths=0.4, zorder=3)
            m = fin & np.array([g is None for g in fam])
            if m.any():
                ax.scatter(x[m], ys[m], marker=".", s=size, color=col, zorder=3)
        bad = ~good[s]
        if bad.any():  # not silently dropped: a red x at the bottom of the panel (x in data, y in axes units)
            yb = np.full(int(bad.sum()), 0.04 + 0.045 * (s % 4))
            ax.scatter(x[bad], yb, marker=NOT_OK_STYLE[0], s=46, color=NOT_OK_STYLE[1], linewidths=1.6,
                       transform=ax.get_xaxis_transform(), clip_on=False, zorder=5)
            if annotate_bad:
                for xx, yy, st, o in zip(x[bad], yb, status[s][bad], ok[s][bad]):
                    ax.annotate("summary failed" if o else st, (xx, yy), xycoords=ax.get_xaxis_transform(),
                                xytext=(5, 0), textcoords="offset points", fontsize=7, color=NOT_OK_STYLE[1],
                                va="center")
    x = x0
    ax.set_title(title, fontsize=10)
    ax.set_ylabel(unit)
    ax.set_xlabel(xa.title)
    ax.grid(alpha=0.3)
    if not prep["good"].any():
        ax.set_yticks([])
    if xa.categorical:
        ax.set_xticks(x)
        ax.set_xticklabels(xa.labels, rotation=30 if max(len(t) for t in xa.labels) > 8 else 0,
                           ha="right" if max(len(t) for t in xa.labels) > 8 else "center", fontsize=8)
        ax.set_xlim(x[0] - 0.5, x[-1] + 0.5)
    else:  # every varied value in view, also those of not-ok points (no line reaches them)
        span = float(np.ptp(x)) if len(x) > 1 else 0.0
        pad = 0.06 * span if span > 0 else max(0.05 * abs(float(x[0])), 1e-12) if len(x) else 1.0
        ax.set_xlim(float(np.min(x)) - pad, float(np.max(x)) + pad)
    if not xa.categorical and len(x) <= 10:
        span = float(np.ptp(x)) if len(x) > 1 else 0.0
        gaps = np.diff(np.sort(x))
        if span > 0 and gaps.min() >= 0.1 * span:
            ax.set_xticks(x)
            ax.set_xticklabels([_fmt_num(v) for v in x], fontsize=8)
    lo, hi = ax.get_ylim()
    if (~prep["good"]).any():  # room at the bottom for the red marks (up to 4 levels, one per line)
        levels = min(int((~prep["good"]).any(axis=1).sum()), 4) if prep["layout"]["n_series"] > 1 else 1
        ax.set_ylim(lo - (0.08 + 0.05 * levels) * (hi - lo), hi)
    refs = prep["refs"].get(title, [])
    for val, _ in refs:
        ax.axhline(val, color="r", ls="--", lw=1.0, zorder=1)
    if any(lab for _, lab, _, _ in items) or refs:
        from matplotlib.lines import Line2D

        named = [(k, name, lab, ls) for k, (name, lab, ls, _) in enumerate(items) if lab]
        cat = xa.categorical  # categories: markers only (no lines drawn)
        handles = [Line2D([], [], color="0.3", ls="" if cat else ls, ms=5,
                          marker=_ITEM_MARKERS[k % len(_ITEM_MARKERS)]
                          if prep["cls"] is None or (cat and len(items) > 1) else None)
                   for k, _, _, ls in named]
        texts = [lab + (f" \u00b1 {_YERR[name][1]}" if name in prep["yerr"] else "") for _, name, lab, _ in named]
        ax.legend(handles + [Line2D([], [], color="r", ls="--") for _ in refs], texts + [lab for _, lab in refs],
                  fontsize=7.5, loc="best")


def _draw_class_map(ax, prep) -> None:
    """The cage-motion class of every point as a coloured cell (rows: series, columns: x values)."""
    from matplotlib.patches import Rectangle

    xa = prep["axes"][prep["x_dim"]]
    raw, fam = prep["cls"]
    paper = prep["paper"]
    conf = prep.get("conf")
    n_s, n_x = raw.shape
    agree = n_cmp = 0
    compact = n_s > 12 or n_x > 12  # colours only (class legend in the map); the text would not fit
    for s in range(n_s):
        for j in range(n_x):
            r = n_s - 1 - s  # first series on top
            if not prep["good"][s, j]:
                st = "summary failed" if prep["ok"][s, j] else prep["status"][s, j]
                ax.add_patch(Rectangle((j, r), 1, 1, facecolor="#fbe3e3", edgecolor="white", hatch="xx", lw=2))
                txt, col = f"not ok: {st}", NOT_OK_STYLE[1]
            else:
                f = fam[s, j]
                fc = CLASS_STYLE[f][1] if f else "white"
                ax.add_patch(Rectangle((j, r), 1, 1, facecolor=fc, alpha=0.35 if f != "undetermined" else 0.18,
                                       edgecolor="white", lw=2))
                txt, col = (raw[s, j] if f else "-"), "k"
                if conf is not None and f not in (None, "undetermined") and np.isfinite(conf[s, j]):
                    txt += f" ({conf[s, j]:.2f})"
            if paper is not None and paper[s, j] not in ("", "nan"):
                mine = raw[s, j] if prep["good"][s, j] else ""
                counted = class_family(mine) not in (None, "undetermined")
                same = counted and mine == paper[s, j]
                n_cmp += counted
                agree += same
                txt += f"\npaper: {paper[s, j]}" + (" \u2713" if same else "")
            if not compact:
                ax.text(j + 0.5, r + 0.5, txt, ha="center", va="center", fontsize=7.5 if paper is not None else 8,
                        color=col)
    ax.set_xlim(0, n_x)
    ax.set_ylim(0, n_s)
    ax.set_xticks(np.arange(n_x) + 0.5)
    crowded = sum(len(t) for t in xa.labels) > 110
    ax.set_xticklabels(xa.labels, fontsize=8 if n_x <= 12 else 7, rotation=90 if crowded else 0)
    ax.set_xlabel(xa.title.split(" [")[0])
    labels = [_series_label([prep["axes"][d] for d in prep["series_dims"]], idx) for idx in prep["series_idx"]]
    ax.set_yticks(np.arange(n_s) + 0.5)
    ax.set_yticklabels(labels[::-1] if labels[0] else [""] * n_s, fontsize=8 if n_s <= 12 else 6.5)
    if compact:
        from matplotlib.patches import Patch

        present = [f for f in CLASS_STYLE if (fam[prep["good"]] == f).any()]
        hs = [Patch(facecolor=CLASS_STYLE[f][1], alpha=0.35 if f != "undetermined" else 0.18) for f in present]
        if (~prep["good"]).any():
            hs.append(Patch(facecolor="#fbe3e3", hatch="xx", edgecolor="white"))
            present.append("not ok")
        ax.legend(hs, present, fontsize=7.5, loc="upper left", bbox_to_anchor=(1.01, 1.0), frameon=False)
    ax.tick_params(length=0)
    for sp in ax.spines.values():
        sp.set_visible(False)
    ttl = "cage motion (classification of the Poincar\u00e9 section"
    ttl += ", confidence in brackets)" if conf is not None and not compact else ")"
    if paper is not None:
        ttl += f"; same label as the paper in {agree} of {n_cmp} classified cells (\u2713)"
    ax.set_title(ttl, fontsize=10)
    prep["layout"]["paper_agreement"] = (agree, n_cmp) if paper is not None else None


def plot_sweep(ds, path) -> Path:
    """Draw the figure of a sweep or study summary (:func:`hsbearing.workflows.sweeps.assemble`) to ``path`` (PNG).

    Panels (each only if its variables are present with a finite value at an ok point): mean cage slip
    ratio [%], whirl amplitude (RMS radius) [um], whirl frequency / cage speed [-], inner and outer
    contact loads (mean and max over the balls) [N], cage speed [r/min] and inner-ring axial
    displacement [um] (quasi-static sweeps), SFMC / SFMO / RFMC [uN m] (gyro sweeps); x axis: the
    varied key with the most numeric values, in the unit the values were written in
    (``<key>_label``); one line per value of the other varied keys (at most :data:`MAX_SERIES`).
    Marker shape (and, with one line, colour) = cage-motion class; with two or more varied keys and a
    classification, a map of the classes over the keys is drawn on top, with the paper's label when
    the summary has ``paper_classification``.  Points whose status is not ``ok`` (or whose summary
    failed) are red crosses at the bottom of every panel and hatched cells in the map; their partial
    values are not drawn.  The counts are in the title and in the PNG text chunk ``Description``.

    Raises :class:`hsbearing.case.CaseError` when the summary has no varied dimension or needs more
    than :data:`MAX_SERIES` (:data:`MAX_ORDERED_SERIES` for the values of one numeric key) lines per
    panel.
    """
    fig, meta = sweep_figure(ds)
    return common.save_figure(fig, Path(path), metadata=meta)


def sweep_figure(ds):
    """The figure of :func:`plot_sweep`, not saved: ``(matplotlib Figure, PNG metadata dict)``."""
    from matplotlib.figure import Figure
    from matplotlib.lines import Line2D

    prep = _prepare_sweep(ds)
    lay = prep["layout"]
    if "classification_confidence" in ds and prep["cls"] is not None:
        order = prep["series_dims"] + [prep["x_dim"]]
        prep["conf"] = _grid_of(ds, "classification_confidence", order, prep["good"].shape)
    panels = prep["panels"]
    n_p = max(len(panels), 1)
    ncols = 1 if n_p == 1 else 2 if n_p in (2, 4) else 3
    nrows = math.ceil(n_p / ncols)
    n_s = lay["n_series"]
    map_h = ((0.55 if n_s <= 12 else 0.22) * n_s + 1.3) if lay["map"] else 0.0
    fig = Figure(figsize=(4.6 * ncols if ncols > 1 else 7.0, 3.2 * nrows + map_h + 1.5), layout="constrained")
    fig_title = _sweep_title(ds, prep)
    fig.suptitle(fig_title, fontsize=11)
    if lay["map"]:
        top, bottom = fig.subfigures(2, 1, height_ratios=[map_h, 3.2 * nrows + 0.6])
        _draw_class_map(top.subplots(1, 1), prep)
    else:
        bottom = fig
    # no empty cell: a last row with fewer panels is centred (a grid of half-width columns)
    gs = bottom.add_gridspec(nrows, 2 * ncols)
    axs = []
    for k in range(n_p):
        r, c = divmod(k, ncols)
        in_row = min(ncols, n_p - r * ncols)
        c0 = (ncols - in_row) + 2 * c
        axs.append(bottom.add_subplot(gs[r, c0:c0 + 2]))
    axs = np.array(axs, dtype=object)
    colours = _series_colours(prep)
    if not panels:  # nothing to draw: say why, point by point (status and error message)
        lines = ["no summary variable with a finite value at an ok point", ""]
        errs = prep["error"][~prep["good"]]
        for k, (pt, err) in enumerate(zip(lay["not_ok_points"], errs)):
            if k == 12:
                lines.append(f"... and {len(errs) - 12} more (see the status and error variables)")
                break
            err = str(err)
            lines.append(pt + (": " + (err if len(err) <= 90 else err[:87] + "...") if err else ""))
        axs[0].text(0.5, 0.5, "\n".join(lines), ha="center", va="center", transform=axs[0].transAxes, fontsize=9)
        axs[0].set_axis_off()
    for k, (title, unit, items) in enumerate(panels):
        _draw_sweep_panel(axs[k], prep, title, unit, items, colours, annotate_bad=(k == 0 and n_s == 1))
    for ax in axs[len(panels):] if panels else axs[1:]:
        ax.set_axis_off()
    # one legend for the figure: classes (marker), series (colour), not-ok points
    handles, labels = [], []
    if prep["cls"] is not None:
        for f, (mk, col) in CLASS_STYLE.items():
            if f in lay["classes"]:
                c = col if n_s == 1 else "0.2"
                handles.append(Line2D([], [], ls="", marker=mk, ms=7, markerfacecolor="none" if f == "undetermined" else c,
                                      markeredgecolor=c))
                labels.append(f"{f} ({lay['classes'][f]})")
    if lay["colorbar"]:  # the lines are the values of one numeric key: a colour bar, ticks = the values
        from matplotlib.cm import ScalarMappable
        from matplotlib.colors import ListedColormap, Normalize

        sa = prep["axes"][prep["series_dims"][0]]
        sm = ScalarMappable(norm=Normalize(-0.5, n_s - 0.5), cmap=ListedColormap(colours))
        cb = bottom.colorbar(sm, ax=[a for a in axs if a.axison] or list(axs), pad=0.01, aspect=40)
        step = max(1, math.ceil(n_s / 15))
        cb.set_ticks(np.arange(0, n_s, step))
        cb.set_ticklabels([sa.labels[i] for i in range(0, n_s, step)], fontsize=7.5)
        cb.set_label(sa.title.split(" [")[0] + " (line colour)")
    elif n_s > 1:
        for s, idx in enumerate(prep["series_idx"]):
            handles.append(Line2D([], [], color=colours[s], lw=2))
            labels.append(_series_label([prep["axes"][d] for d in prep["series_dims"]], idx))
    if lay["not_ok"] or lay["no_summary"]:
        counts = {}
        for st, o in zip(prep["status"][~prep["good"]], prep["ok"][~prep["good"]]):
            key = "summary failed" if o else str(st)
            counts[key] = counts.get(key, 0) + 1
        handles.append(Line2D([], [], ls="", marker=NOT_OK_STYLE[0], ms=7, color=NOT_OK_STYLE[1], mew=1.6))
        labels.append("not ok, values not drawn: " + ", ".join(f"{v} {k}" for k, v in counts.items()))
    if handles:
        ncol = len(handles) if len(handles) <= 7 else math.ceil(len(handles) / 2)
        fig.legend(handles, labels, loc="outside lower center", ncol=ncol, fontsize=8, frameon=False)
    meta = {"Title": fig_title.replace("\n", "; "),
            "Description": (f"hsbearing sweep figure: points={lay['points']} not_ok={lay['not_ok']} "
                            f"no_summary={lay['no_summary']} x={lay['x_dim']} series={'+'.join(lay['series_dims'])} "
                            f"panels={len(panels)} map={int(lay['map'])}"
                            + (f" paper_agreement={lay['paper_agreement'][0]}/{lay['paper_agreement'][1]}"
                               if lay.get("paper_agreement") else "")),
            "Software": "hsbearing"}
    if lay["not_ok_points"]:
        meta["Comment"] = "not ok: " + "; ".join(lay["not_ok_points"])
    return fig, meta
