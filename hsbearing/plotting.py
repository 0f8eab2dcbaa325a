"""The run and sweep figures (``hsbearing run`` / ``hsbearing plot OUT.nc`` / ``DIR/sweep.png``).

:func:`plot_run` dispatches on the Dataset:

the kind of archive (:func:`archive_kind`, from its attributes and dimensions) selects the figure:

- ``"sweep"``: a sweep or study summary (:func:`is_sweep_summary`: ``attrs["title"] == "hsbearing sweep"``
  or ``sweep_vary`` in the attrs, as written by :func:`hsbearing.sweeps.assemble`) -> :func:`plot_sweep`:
  the summary variables against the varied keys;
- ``"gyro"``: a gyro-bearing run (``attrs["model"] == "gyro_ribbon_cage"``) -> :func:`plot_gyro`
  (through :func:`hsbearing.models.friction.gyro.plot_run`): speeds, M_C, the friction-moment sources;
- ``"friction"``: ``hsbearing friction`` (dim ``speed``, ``sliding_torque``) -> :func:`plot_friction`;
- ``"preload"``: ``hsbearing preload`` (dim ``preload``) -> :func:`plot_preload`;
- ``"quasistatic"``: no ``time`` dimension, per-ball contact loads -> per-ball contact loads and angles;
- ``"run"``: the dynamic-run figure: (a) cage whirl orbit D_Y-D_Z with the
  guide clearance circle, (b) Poincare map (D_Y, V_Y) -- the same section
  points as the stored classification (:mod:`hsbearing.analysis.poincare`),
  (c) cage speed against time with the pure-rolling speed, (d) cage slip ratio.

Matplotlib is used through its object API with the Agg canvas (no pyplot, no
global backend change), and the PNG is written atomically (temporary file in
the target directory, then rename).
"""

from __future__ import annotations

import math
import tomllib
from pathlib import Path

import numpy as np

__all__ = ["archive_kind", "is_sweep_summary", "plot_run", "plot_sweep", "plot_friction", "plot_preload", "plot_gyro",
           "save_figure", "sweep_figure", "sweep_layout", "title_lines", "ISO76_BALL_PRESSURE"]

from hsbearing.display import ISO76_BALL_PRESSURE  # noqa: E402  (ISO 76 static limit of ball bearings [Pa])

_RPM = 60.0 / (2.0 * math.pi)


def save_figure(fig, path, dpi: int = 110, metadata: dict | None = None) -> Path:
    """Save a matplotlib figure atomically (temporary file, then rename) and return its path.

    ``metadata``: text chunks of the PNG (matplotlib ``savefig(metadata=...)``), e.g. the point counts
    of a sweep figure.
    """
    from matplotlib.backends.backend_agg import FigureCanvasAgg

    from hsbearing.results import atomic_write

    path = Path(path)
    FigureCanvasAgg(fig)
    with atomic_write(path, suffix=path.suffix or ".png") as tmp:
        fig.savefig(tmp, dpi=dpi, format=(path.suffix.lstrip(".") or "png"), metadata=metadata)
    return path


_save = save_figure


def _case_labels(ds) -> dict[str, str]:
    """Readable operating-condition labels from the ``case_toml`` attr (empty dict if absent)."""
    from hsbearing.case import parse_quantity

    text = ds.attrs.get("case_toml")
    if not text:
        return {}
    try:
        raw = tomllib.loads(text)
    except tomllib.TOMLDecodeError:
        return {}
    out = {}
    lub, op = raw.get("lubricant", {}), raw.get("operating", {})

    def q(table, key, kind):
        try:
            return parse_quantity(table[key], kind) if key in table else None
        except Exception:
            return None

    if "oil" in lub:
        out["oil"] = f"oil {lub['oil']}"
    T = q(lub, "temperature", "temperature")
    if T is not None:
        out["temperature"] = f"T = {T - 273.15:.0f} \N{DEGREE SIGN}C"
    n = q(op, "inner_speed", "angular_speed")
    if n is not None:
        out["speed"] = f"n = {n * _RPM:.0f} r/min"
    Fa = q(op, "axial_load", "force")
    if Fa is not None:
        out["axial_load"] = f"Fa = {Fa:.0f} N"
    Fr = q(op, "radial_load", "force")
    if Fr:
        out["radial_load"] = f"Fr = {Fr:.0f} N"
    return out


def title_lines(ds) -> list[str]:
    """Figure title: case name and operating conditions; classification, slip and status."""
    name = ds.attrs.get("case_name", "hsbearing run")
    lab = _case_labels(ds)
    first = ", ".join([name] + [lab[k] for k in ("oil", "speed", "axial_load", "radial_load", "temperature") if k in lab])
    parts = []
    if "classification" in ds.attrs:
        conf = ds.attrs.get("classification_confidence")
        c = f"cage motion: {ds.attrs['classification']}"
        if conf is not None and ds.attrs["classification"] != "undetermined":
            c += f" (confidence {float(conf):.2f})"
        parts.append(c)
    if "mean_cage_slip_ratio" in ds and np.isfinite(float(ds["mean_cage_slip_ratio"])):
        parts.append(f"mean cage slip ratio {100 * float(ds['mean_cage_slip_ratio']):.2f} %")
    status = ds.attrs.get("status", "")
    if status and status != "ok":
        parts.append(f"status: {status}")
    return [first, "; ".join(parts)] if parts else [first]


def plot_run(ds, path) -> Path:
    """Draw the figure of a result Dataset to ``path`` (PNG) and return the path.

    See the module docstring for the dispatch.  A dynamic run that was not
    annotated is annotated first (:func:`hsbearing.analysis.annotate`, with the
    case re-read from ``attrs["case_toml"]``) so the figure shows the slip
    ratio, the Poincare map and the classification.
    """
    path = Path(path)
    kind = archive_kind(ds)
    if kind == "sweep":
        return plot_sweep(ds, path)
    if kind == "gyro":
        from hsbearing.models.friction import gyro

        return gyro.plot_run(ds, path)
    if kind == "friction":
        return plot_friction(ds, path)
    if kind == "preload":
        return plot_preload(ds, path)
    if kind == "quasistatic":
        return _plot_static(ds, path)
    return _plot_dynamic(ds, path)


def archive_kind(ds) -> str:
    """What an hsbearing Dataset holds: ``"sweep"``, ``"gyro"``, ``"friction"``, ``"preload"``,
    ``"quasistatic"`` or ``"run"`` (see the module docstring).

    Decided from the attributes every archive carries (``title``, ``model``, ``case_system``) and
    the dimensions / variables, so archives written before this function existed are recognised too.
    Raises :class:`hsbearing.case.CaseError` for a Dataset that is none of these.
    """
    from hsbearing.case import CaseError

    if is_sweep_summary(ds):
        return "sweep"
    system = ds.attrs.get("case_system", "")
    if ds.attrs.get("model") == "gyro_ribbon_cage" or (system == "gyro_ribbon_cage" and "time" in ds.dims):
        return "gyro"
    if "speed" in ds.dims and "sliding_torque" in ds:
        return "friction"
    if "preload" in ds.dims or system == "wire_race":
        return "preload"
    if "time" in ds.dims:
        return "run"
    if "inner_contact_load" in ds or "outer_contact_load" in ds:
        return "quasistatic"
    source = str(ds.encoding.get("source", "dataset"))
    raise CaseError(source, None, "not an hsbearing result this command can draw (no run, quasi-static, friction, "
                                  "preload, gyro or sweep variables)")


def _figure(figsize):
    from matplotlib.figure import Figure

    return Figure(figsize=figsize, layout="constrained")


def _plot_dynamic(ds, path: Path) -> Path:
    from hsbearing.analysis import orbit, poincare

    if "classification" not in ds.attrs and all(v in ds.variables for v in orbit.REQUIRED):
        try:
            ds = orbit.annotate(ds)
        except Exception as exc:  # the figure still shows the raw signals
            ds = ds.copy()
            ds.attrs["classification"] = "undetermined"
            ds.attrs["classification_reason"] = f"analysis failed: {exc}"
    t = np.asarray(ds["time"].values, float)
    try:
        mask, t_tr = poincare.after_transient(ds)
    except Exception:
        mask, t_tr = poincare.steady_mask(t, poincare.DEFAULT_TRANSIENT_FRACTION)
    t_ms = (t - t[0]) * 1e3 if t.size else t

    fig = _figure((12.5, 9.5))
    axs = fig.subplots(2, 2)
    fig.suptitle("\n".join(title_lines(ds)), fontsize=11)

    # (a) whirl orbit
    ax = axs[0, 0]
    if "cage_center_y" in ds and "cage_center_z" in ds:
        y_m = np.asarray(ds["cage_center_y"].values, float)
        z_m = np.asarray(ds["cage_center_z"].values, float)
        r_m = np.hypot(y_m, z_m)
        r_ext = float(np.nanmax(r_m)) if r_m.size and np.any(np.isfinite(r_m)) else float("nan")
        lf, lu = _length_scale(r_ext)
        y, z = y_m * lf, z_m * lf
        ax.plot(y[~mask], z[~mask], color="0.75", lw=0.6, label=f"transient (first {t_tr * 1e3:.3g} ms)")
        ax.plot(y[mask], z[mask], color="C0", lw=0.8, label="after transient")
        rmax = float(np.nanmax(np.hypot(y, z))) if y.size and np.any(np.isfinite(y)) else 0.0
        gc = ds.attrs.get("guide_clearance")
        view = max(rmax, 1e-3) * 1.15
        if gc is not None and np.isfinite(gc) and gc > 0:
            gcu = float(gc) * lf
            th = np.linspace(0, 2 * np.pi, 361)
            if rmax > 0.25 * gcu:
                view = max(view, 1.08 * gcu)
                ax.plot(gcu * np.cos(th), gcu * np.sin(th), "r--", lw=1.0,
                        label=f"guide clearance {float(gc) * 1e6:.0f} \u00b5m")
                if rmax > gcu:  # the rub contact is compliant: the cage centre passes the nominal clearance
                    ax.plot([], [], " ", label=f"cage centre up to {rmax:.1f} {lu}: {rmax - gcu:.2g} {lu}\n"
                                               "elastic penetration of the cage-land rub contact")
            else:
                used = 100 * rmax / gcu
                ax.plot([], [], "r--", lw=1.0, label=f"guide clearance {float(gc) * 1e6:.0f} \u00b5m (off view: orbit "
                        + (f"uses {used:.1f} %)" if used >= 0.1 else "uses < 0.1 %)"))
        ax.plot([0], [0], "k+", ms=8)
        ax.set_xlim(-view, view)
        ax.set_ylim(-view, view)
        ax.set_aspect("equal", adjustable="box")
        ax.set_xlabel(f"cage centre $D_Y$ [{lu}]")
        ax.set_ylabel(f"cage centre $D_Z$ [{lu}]")
        amp = float(ds["whirl_amplitude"]) * lf if "whirl_amplitude" in ds else float("nan")
        ratio = float(ds["whirl_frequency_ratio"]) if "whirl_frequency_ratio" in ds else float("nan")
        ttl = "(a) cage centre orbit"
        if np.isfinite(amp):
            ttl += f": RMS radius {amp:.3g} {lu}"
        note = None
        try:
            from hsbearing.analysis.orbit import whirl_ratio_note

            note = whirl_ratio_note(ds)
        except Exception:  # noqa: BLE001 - an old or partial archive: the ratio is shown as stored
            note = None
        if note:
            ttl += ", no whirl (cage parked)"
        elif np.isfinite(ratio):
            ttl += f", whirl/cage speed {ratio:.3g}"
        ax.set_title(ttl, fontsize=10)
        ax.legend(fontsize=8, loc="upper center", bbox_to_anchor=(0.5, -0.12), ncol=2, frameon=False)
        ax.grid(alpha=0.3)

    # (b) Poincare map
    ax = axs[0, 1]
    try:
        pts = poincare.poincare_points(ds, ds.attrs.get("poincare_section_kind", "cage_revolution"))
    except Exception:
        pts = np.zeros((0, 2))
    vy = poincare.cage_velocity(ds, "y") if "cage_center_y" in ds else np.zeros(0)
    yy = np.asarray(ds["cage_center_y"].values, float) if "cage_center_y" in ds else np.zeros(0)
    ext_y = float(np.nanmax(np.abs(yy[mask]))) if mask.any() and yy.size else float("nan")
    ext_v = float(np.nanmax(np.abs(vy[mask]))) if mask.any() and vy.size else float("nan")
    if len(pts):
        ext_y = max(ext_y, float(np.nanmax(np.abs(pts[:, 0])))) if np.isfinite(ext_y) else float(np.nanmax(np.abs(pts[:, 0])))
        ext_v = max(ext_v, float(np.nanmax(np.abs(pts[:, 1])))) if np.isfinite(ext_v) else float(np.nanmax(np.abs(pts[:, 1])))
    lf, lu = _length_scale(ext_y)
    vf, vu = _velocity_scale(ext_v)
    if len(pts):
        sc = ax.scatter(pts[:, 0] * lf, pts[:, 1] * vf, c=np.arange(len(pts)), cmap="viridis", s=14, zorder=3)
        cb = fig.colorbar(sc, ax=ax, pad=0.01)
        cb.set_label("section index (time \u2192)")
        from matplotlib.ticker import MaxNLocator

        cb.locator = MaxNLocator(integer=True)
        cb.update_ticks()
        # orbit in the same plane, faint, to show where the section lies
        if yy.size:
            ax.plot(yy[mask] * lf, vy[mask] * vf, color="0.85", lw=0.4, zorder=1)
    else:
        ax.text(0.5, 0.5, "no Poincare section point\n(run shorter than one cage revolution after the transient)",
                ha="center", va="center", transform=ax.transAxes)
    ax.set_xlabel(f"cage centre $D_Y$ [{lu}]")
    ax.set_ylabel(f"cage centre velocity $V_Y$ [{vu}]")
    lab = ds.attrs.get("classification", "")
    conf = ds.attrs.get("classification_confidence")
    ttl = f"(b) Poincar\u00e9 map, {len(pts)} points (one per cage revolution)"
    if ds.attrs.get("poincare_section_kind") == "plane":
        ttl = f"(b) Poincar\u00e9 map, {len(pts)} points (plane D_Z = mean, upward)"
    ax.set_title(ttl, fontsize=10)
    if lab:
        txt = lab if lab == "undetermined" or conf is None else f"{lab} (confidence {float(conf):.2f})"
        reason = ds.attrs.get("classification_reason", "")
        if reason:
            short = reason.split("; 0-1 test")[0]
            short = short if len(short) <= 300 else short[:297] + "..."
            txt += "\n" + _wrap(short, 70)
        # below the panel (under the axis label), never over the section points
        ax.annotate(txt, xy=(0.5, 0.0), xycoords=ax.xaxis.label, xytext=(0, -4), textcoords="offset points",
                    ha="center", va="top", fontsize=7.5, annotation_clip=False,
                    bbox=dict(boxstyle="round", fc="white", ec="0.6", alpha=0.9))
    ax.grid(alpha=0.3)

    # (c) cage speed
    ax = axs[1, 0]
    if "cage_speed" in ds:
        w = np.asarray(ds["cage_speed"].values, float) * _RPM
        ax.plot(t_ms, w, color="C0", lw=0.8, label="cage speed")
        if "theoretical_cage_speed" in ds:
            wth = float(ds["theoretical_cage_speed"]) * _RPM
            ax.axhline(wth, color="k", ls="--", lw=0.9, label=f"pure rolling at \u03b1$_0$: {wth:.0f} r/min")
        if "raceway_control_cage_speed" in ds and np.isfinite(float(ds["raceway_control_cage_speed"])):
            wrc = float(ds["raceway_control_cage_speed"]) * _RPM
            ax.axhline(wrc, color="C2", ls=":", lw=1.1,
                       label=f"outer-raceway control at loaded \u03b1: {wrc:.0f} r/min")
        _shade(ax, t_tr * 1e3)
        ax.legend(fontsize=8, loc="best")
    ax.set_xlabel("time [ms]")
    ax.set_ylabel("cage speed [r/min]")
    ax.set_title("(c) cage speed", fontsize=10)
    ax.grid(alpha=0.3)

    # (d) slip ratio
    ax = axs[1, 1]
    if "cage_slip_ratio" in ds:
        s = np.asarray(ds["cage_slip_ratio"].values, float) * 100
        ax.plot(t_ms, s, color="C3", lw=0.8, label="cage slip ratio")
        if "mean_cage_slip_ratio" in ds and np.isfinite(float(ds["mean_cage_slip_ratio"])):
            ms = 100 * float(ds["mean_cage_slip_ratio"])
            ax.axhline(ms, color="k", ls=":", lw=0.9, label=f"mean after transient {ms:.2f} %")
        if "mean_cage_slip_ratio_raceway_control" in ds and np.isfinite(float(ds["mean_cage_slip_ratio_raceway_control"])):
            rc = 100 * float(ds["mean_cage_slip_ratio_raceway_control"])
            ax.plot([], [], " ", label=f"against outer-raceway control at loaded \u03b1: {rc:.2f} %")
        _shade(ax, t_tr * 1e3)
        ax.legend(fontsize=8, loc="best")
    else:
        ax.text(0.5, 0.5, "no cage slip ratio (case unknown)", ha="center", va="center", transform=ax.transAxes)
    ax.set_xlabel("time [ms]")
    ax.set_ylabel("cage slip ratio $(\\omega_{c,th}-\\omega_c)/\\omega_{c,th}$ [%]")
    ax.set_title("(d) cage slip ratio", fontsize=10)
    ax.grid(alpha=0.3)
    return _save(fig, path)


def _length_scale(extent_m: float) -> tuple[float, str]:
    """Display factor and unit for a length of the given extent [m]: um, or nm below 1 um."""
    return (1e9, "nm") if np.isfinite(extent_m) and extent_m < 1e-6 else (1e6, "\u00b5m")


def _velocity_scale(extent: float) -> tuple[float, str]:
    """Display factor and unit for a velocity extent [m/s]: mm/s, or um/s below 1 mm/s."""
    return (1e6, "\u00b5m/s") if np.isfinite(extent) and extent < 1e-3 else (1e3, "mm/s")


def _shade(ax, t_end_ms):
    if t_end_ms > 0:
        ax.axvspan(0.0, t_end_ms, color="0.9", zorder=0, label="transient (discarded)")


def _wrap(text: str, width: int) -> str:
    import textwrap

    return "\n".join(textwrap.wrap(text, width))


def _per_ball_axes(ax, nb, ylabel: str, title: str, grid_axis: str) -> None:
    """Labels, ball ticks 1..nb, legend and grid of a per-ball panel."""
    ax.set_xlabel("ball")
    ax.set_ylabel(ylabel)
    ax.set_title(title, fontsize=10)
    if nb:
        ax.set_xticks(np.arange(1, nb + 1))
        ax.legend(fontsize=8)
    ax.grid(alpha=0.3, axis=grid_axis)


def _plot_static(ds, path: Path) -> Path:
    fig = _figure((11, 4.8))
    ax1, ax2 = fig.subplots(1, 2)
    lines = title_lines(ds)
    lines[0] = "quasi-static equilibrium: " + lines[0]
    fig.suptitle("\n".join(lines), fontsize=11)
    nb = None
    for name, lab, c in (("inner_contact_load", "inner race $Q_i$", "C0"), ("outer_contact_load", "outer race $Q_o$", "C1")):
        if name in ds:
            q = np.atleast_1d(np.asarray(ds[name].values, float))
            nb = len(q)
            x = np.arange(1, nb + 1)
            off = -0.2 if "inner" in name else 0.2
            ax1.bar(x + off, q, width=0.4, color=c, label=lab)
    _per_ball_axes(ax1, nb, "contact load [N]", "contact loads per ball", grid_axis="y")
    for name, lab, c in (("inner_contact_angle", "inner race $\\alpha_i$", "C0"), ("outer_contact_angle", "outer race $\\alpha_o$", "C1")):
        if name in ds:
            a = np.degrees(np.atleast_1d(np.asarray(ds[name].values, float)))
            ax2.plot(np.arange(1, len(a) + 1), a, "o-", color=c, label=lab)
    _per_ball_axes(ax2, nb, "contact angle [\N{DEGREE SIGN}]", "contact angles per ball", grid_axis="both")
    return _save(fig, path)


# ----------------------------------------------------------------------------- friction, preload, gyro figures


def _vals(ds, name, factor=1.0):
    return np.asarray(ds[name].values, dtype=float) * factor


def plot_friction(ds, path) -> Path:
    """Figure of ``hsbearing friction`` (seed 003 sliding method and SKF 2004 model) to ``path`` (PNG).

    (a) torques against the inner-ring speed [N mm]: the sliding components M_s (spinning), M_r (ball
    rotation), M_d (orbital) and their sum M_sl by the seed 003 method (solid), the SKF 2004 M_sl,
    M_rr, M_drag and total M (dashed / dotted); (b) contact load and angle of each ball at the first
    speed (the archive's ``note``).
    """
    path = Path(path)
    fig = _figure((12, 4.9))
    ax1, ax2 = fig.subplots(1, 2, width_ratios=[1.4, 1.0])
    rpm = _vals(ds, "speed", _RPM)
    lab = _case_labels(ds)
    head = ", ".join([ds.attrs.get("case_name", "friction torque")]
                     + [lab[k] for k in ("axial_load", "radial_load") if k in lab])
    extra = [f"law {ds.attrs['friction_law']}" if "friction_law" in ds.attrs else "",
             f"\u03bd = {float(ds.attrs['kinematic_viscosity_mm2_s']):g} mm\u00b2/s" if "kinematic_viscosity_mm2_s" in ds.attrs else ""]
    fig.suptitle("friction torque: " + ", ".join([head] + [e for e in extra if e]), fontsize=11)
    rows = (("sliding_torque", "$M_{sl}$ sliding (seed 003 method)", "k", "-", 2.0),
            ("spinning_torque", "$M_s$ spinning", "C0", "-", 1.2),
            ("orbital_sliding_torque", "$M_d$ orbital (differential) sliding", "C2", "-", 1.2),
            ("rotation_sliding_torque", "$M_r$ ball-rotation sliding", "C1", "-", 1.2),
            ("skf_sliding_torque", "SKF 2004 $M_{sl}$", "k", "--", 1.4),
            ("skf_rolling_torque", "SKF 2004 $M_{rr}$ rolling", "C4", "--", 1.2),
            ("skf_drag_torque", "SKF 2004 $M_{drag}$", "C5", ":", 1.2),
            ("skf_total_torque", "SKF 2004 total $M$", "C3", "--", 1.6))
    for name, label, col, ls, lw in rows:
        if name in ds:
            ax1.plot(rpm, _vals(ds, name, 1e3), ls=ls, color=col, lw=lw, marker="o" if len(rpm) <= 12 else None,
                     ms=4, label=label)
    if len(rpm) > 1 and np.all(rpm > 0) and rpm.max() / rpm.min() >= 10:
        ax1.set_xscale("log")
    ax1.set_xlabel("inner-ring speed n [r/min]")
    ax1.set_ylabel("torque [N mm]")
    ax1.set_title("(a) friction torques", fontsize=10)
    ax1.grid(alpha=0.3, which="both")
    ax1.legend(fontsize=7.5, loc="best")
    nb = None
    if "ball_contact_load" in ds:
        q = np.atleast_1d(_vals(ds, "ball_contact_load"))
        nb = q.size
        x = np.arange(1, nb + 1)
        ax2.bar(x, q, width=0.6, color="C0", label="contact load Q")
        ax2.set_xticks(x)
        ax2.set_ylabel("contact load Q [N]")
        if "ball_contact_angle" in ds:
            a2 = ax2.twinx()
            a2.plot(x, np.degrees(np.atleast_1d(_vals(ds, "ball_contact_angle"))), "o-", color="C3", label="contact angle")
            a2.set_ylabel("contact angle [\N{DEGREE SIGN}]", color="C3")
    ax2.set_xlabel("ball")
    sp = f" at n = {rpm[0]:.0f} r/min" if len(rpm) else ""
    ax2.set_title(f"(b) ball contacts{sp}", fontsize=10)
    ax2.grid(alpha=0.3, axis="y")
    return _save(fig, path)


def plot_preload(ds, path) -> Path:
    """Figure of ``hsbearing preload`` (wire-race bearing, seed 001) to ``path`` (PNG).

    (a) starting torque against the preload: rolling-resistance torque M_sc (Eq. 4) and M_s = M_sc + M_u
    (Eq. 11), with the target-torque band and the preload window when the archive has them;
    (b) maximum contact pressure of the four ball/wire contacts, with the ISO 76 limit
    (:data:`ISO76_BALL_PRESSURE`) drawn and the preloads beyond it shaded.
    """
    path = Path(path)
    fig = _figure((12, 4.9))
    ax1, ax2 = fig.subplots(1, 2)
    um = _vals(ds, "preload", 1e6)
    fig.suptitle(f"{ds.attrs.get('case_name', 'wire race')}: starting torque and contact pressure against the preload "
                 "(seed 001 model)", fontsize=11)
    ax1.plot(um, _vals(ds, "rolling_torque"), "-", color="C0", label="$M_{sc}$ rolling resistance (Eq. 4)")
    ax1.plot(um, _vals(ds, "torque"), "--", color="C1", label="$M_s = M_{sc} + M_u$ (Eq. 11)")
    tt, win = ds.attrs.get("target_torque"), ds.attrs.get("preload_window")
    if tt is not None and np.size(tt) == 2:
        ax1.axhspan(float(np.ravel(tt)[0]), float(np.ravel(tt)[1]), color="0.85", zorder=0,
                    label=f"target {float(np.ravel(tt)[0]):g}-{float(np.ravel(tt)[1]):g} N m")
    if win is not None and np.size(win) == 2:
        w = np.ravel(win) * 1e6
        ax1.axvspan(w[0], w[1], color="C0", alpha=0.12, zorder=0, label=f"preload window {w[0]:.1f}-{w[1]:.1f} \u00b5m")
    ax1.set_xlabel("preload \u03b4 [\u00b5m]")
    ax1.set_ylabel("starting torque [N m]")
    ax1.set_title("(a) starting torque", fontsize=10)
    ax1.grid(alpha=0.3)
    ax1.legend(fontsize=8, loc="upper left")
    pmax = np.zeros_like(um)
    for j in range(1, 5):
        name = f"p_max{j}"
        if name in ds:
            p = _vals(ds, name, 1e-9)
            pmax = np.maximum(pmax, p)
            ax2.plot(um, p, lw=1.1, ls=("-", "--", "-.", ":")[j - 1], label=f"contact {j}: $P_{{0{j}}}$")
    lim = ISO76_BALL_PRESSURE * 1e-9
    ax2.axhline(lim, color="r", lw=1.2, label=f"ISO 76 static limit for ball bearings, {lim:g} GPa")
    over = pmax > lim
    if over.any():
        ax2.axvspan(um[over].min(), um.max(), color="r", alpha=0.08, zorder=0,
                    label=f"above the limit from {um[over].min():.3g} \u00b5m")
    ax2.set_xlabel("preload \u03b4 [\u00b5m]")
    ax2.set_ylabel("maximum contact pressure [GPa]")
    ax2.set_title("(b) maximum contact pressure", fontsize=10)
    ax2.grid(alpha=0.3)
    ax2.legend(fontsize=8, loc="upper left")
    return _save(fig, path)


#: The five friction-moment sources of the gyro model ([J] Eq. 1), in stacking order: name, label, colour.
GYRO_SOURCES = (("friction_moment_viscous", "$M_L$ viscous", "#17becf"),
                ("friction_moment_hysteresis", "$M_E$ elastic hysteresis", "#2ca02c"),
                ("friction_moment_differential", "$M_D$ differential sliding", "#ff7f0e"),
                ("friction_moment_pivoting", "$M_S$ pivoting", "#8c564b"),
                ("friction_moment_cage", "$M_C$ ball/cage (driving part)", "#e377c2"))


def plot_gyro(ds, path) -> Path:
    """Figure of a gyro-bearing run (like [J] Figs. 7-9) to ``path`` (PNG).

    (a) outer-race, cage and ball-1 orbital speeds [r/min]; (b) ball/cage friction moment M_C [uN m];
    (c) the sources stacked as bands, M_L + M_E + M_D + M_S + max(M_C, 0) = M ([J] Eq. 1), so that
    sources of nearly equal size stay distinguishable (their time means are in the legend), and M on top.
    """
    path = Path(path)
    u = 1e6
    t = _vals(ds, "time")
    fig = _figure((10, 9))
    ax = fig.subplots(3, 1, sharex=True)
    if "outer_race_speed" in ds:
        ax[0].plot(t, _vals(ds, "outer_race_speed", _RPM), color="0.5", lw=1.0, ls="--", label="outer race")
    if "ball_orbit_speed" in ds:
        ax[0].plot(t, _vals(ds.isel(ball=0), "ball_orbit_speed", _RPM), "k-", lw=1, label="ball 1 orbit")
    if "cage_speed" in ds:
        ax[0].plot(t, _vals(ds, "cage_speed", _RPM), "r-", lw=0.8, label="cage")
    ax[0].set_ylabel("angular speed [r/min]")
    ax[0].set_title("(a) speeds", fontsize=10)
    ax[0].legend(loc="best", fontsize=8)
    if "friction_moment_cage" in ds:
        ax[1].plot(t, _vals(ds, "friction_moment_cage", u), "-", color=GYRO_SOURCES[-1][2], lw=0.8)
    ax[1].set_ylabel("$M_C$ [\u00b5N m]")
    ax[1].set_title("(b) ball/cage friction moment $M_C$ (signed; peak of each output interval)", fontsize=10)
    bands, labels, colours = [], [], []
    for name, lab, col in GYRO_SOURCES:
        if name in ds:
            v = _vals(ds, name, u)
            v = np.maximum(v, 0.0) if name == "friction_moment_cage" else v
            bands.append(v)
            labels.append(f"{lab}: mean {np.nanmean(v):.3g} \u00b5N m")
            colours.append(col)
    if bands:
        ax[2].stackplot(t, *bands, labels=labels, colors=colours, alpha=0.85, lw=0)
    if "friction_moment_total" in ds:
        ax[2].plot(t, _vals(ds, "friction_moment_total", u), color="b", lw=1.1, label="$M$ total (Eq. 1)")
    ax[2].set_ylabel("friction moment [\u00b5N m]")
    ax[2].set_xlabel("time [s]")
    ax[2].set_title("(c) friction-moment sources, stacked: $M_L + M_E + M_D + M_S + \\max(M_C, 0) = M$", fontsize=10)
    ax[2].legend(loc="upper left", bbox_to_anchor=(1.01, 1.0), fontsize=8, frameon=False)
    for a in ax:
        a.grid(alpha=0.3)
    title = f"{ds.attrs.get('case_name', '')}: " + ", ".join(
        f"{v.upper()} = {float(ds[v]) * u:.3g} \u00b5N m" for v in ("sfmc", "sfmo", "rfmc") if v in ds and np.isfinite(float(ds[v])))
    if ds.attrs.get("status", "ok") != "ok":
        title += f" [{ds.attrs['status']}]"
    fig.suptitle(title, fontsize=10)
    return _save(fig, path)


# ----------------------------------------------------------------------------- sweep / study summary figure
#
# A sweep Dataset (hsbearing.sweeps.assemble) has one dimension per varied key (``point`` for --zip),
# an SI coordinate per key with ``units`` / ``case_key`` attrs and ``<dim>_label`` (the values as
# written), a ``status`` per point and the per-point summary variables.  The figure draws those
# summaries against the varied key with the most numeric values (x axis); every other varied key
# gives one line per value (or per combination of values).  With a cage-motion classification and
# more than one varied key, a categorical map of the classes (the layout of seed 004 Tables 3-5)
# is drawn on top, with the paper's label of every cell when the summary carries
# ``paper_classification`` (study tables).

#: Marker and colour of each cage-motion class (:data:`hsbearing.analysis.classify.LABELS`;
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

# (panel title, y label with its unit, factor SI -> unit, ((variable, legend label, line style), ...)), in
# drawing order (friction moments first for a gyro sweep); a panel is drawn only if one of its variables is
# present with a finite value at an ok point.
_SWEEP_PANELS = (
    ("mean cage slip ratio", "slip ratio [%]", 100.0, (("mean_cage_slip_ratio", None, "-"),)),
    ("cage whirl radius", "whirl radius [\u00b5m]", 1e6, (("whirl_amplitude", "RMS (whirl amplitude)", "-"),
                                                           ("whirl_radius_max", "max", ":"))),
    ("whirl frequency / cage speed", "frequency ratio [-]", 1.0, (("whirl_frequency_ratio", None, "-"),)),
    ("inner race contact load $Q_i$", "$Q_i$ [N]", 1.0, (("mean_inner_contact_load", "mean over balls", "-"),
                                                       ("max_inner_contact_load", "max over balls", "--"))),
    ("outer race contact load $Q_o$", "$Q_o$ [N]", 1.0, (("mean_outer_contact_load", "mean over balls", "-"),
                                                       ("max_outer_contact_load", "max over balls", "--"))),
    ("cage speed", "cage speed [r/min]", _RPM, (("cage_speed", None, "-"),)),
    ("inner ring axial displacement", "displacement [\u00b5m]", 1e6, (("inner_ring_axial_displacement", None, "-"),)),
    ("friction moments (seed 000)", "moment [\u00b5N m]", 1e6,
     (("sfmc", "SFMC", "-"), ("sfmc_ensemble_mean", "SFMC, start ensemble mean", "-."), ("sfmo", "SFMO", "--"),
      ("rfmc", "RFMC", ":"))),
)

# markers of the quantities of one panel when no class is drawn (mean / max, SFMC / SFMO / RFMC)
_ITEM_MARKERS = ("o", "s", "^", "D")
# error bars: quantity -> (its spread in the summary, what the legend calls it)
_YERR = {"sfmo": ("sfmo_stderr", "standard error"), "sfmc_ensemble_mean": ("sfmc_ensemble_sd", "sd")}

# unit as written in a label -> as printed on an axis
_PRETTY_UNIT = {"rpm": "r/min", "degC": "\N{DEGREE SIGN}C", "deg": "\N{DEGREE SIGN}", "um": "\u00b5m",
                "N*m": "N m", "mm^2/s": "mm\u00b2/s", "kg/m^3": "kg/m\u00b3"}
# SI unit of a coordinate -> (factor, offset, unit) for display, when the labels do not share one unit
_SI_DISPLAY = {"rad/s": (_RPM, 0.0, "r/min"), "K": (1.0, -273.15, "\N{DEGREE SIGN}C"),
               "rad": (180.0 / math.pi, 0.0, "\N{DEGREE SIGN}"), "N*m": (1.0, 0.0, "N m"),
               "m**2/s": (1e6, 0.0, "mm\u00b2/s"), "kg/m**3": (1.0, 0.0, "kg/m\u00b3")}
_LABEL_KEYS = {"lubricant.oil": "oil", "operating.inner_speed": "speed", "operating.axial_load": "axial_load",
               "operating.radial_load": "radial_load", "lubricant.temperature": "temperature"}


def is_sweep_summary(ds) -> bool:
    """True for a sweep or study summary Dataset.

    The attrs written by :func:`hsbearing.sweeps.assemble` (``title = "hsbearing sweep"``, ``sweep_vary``),
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
        parts.append(f"{ax.dim} = {ax.labels[i]}" if ax.dim != "oil" else f"oil {ax.labels[i]}")
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
    pool = numeric or list(dims)
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
        got = []
        for name, lab, ls in items:
            if name in yerr:
                yerr[name] = yerr[name] * factor
            if name in ds and ds[name].dtype.kind in "fiu":
                y = _grid_of(ds, name, order, shape)
                if y is not None and np.isfinite(y[good]).any():
                    got.append((name, lab, ls, y * factor))
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
    what = {"run": "dynamic runs", "quasistatic": "quasi-static equilibria"}.get(kind, kind or "points")
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
    lab = _case_labels(ds)
    if lab.get("speed") == "n = 0 r/min":  # outer ring rotating (gyro bearings): show the outer-ring speed
        lab.pop("speed")
        from hsbearing.case import CaseError, parse_quantity

        try:
            n_o = parse_quantity(tomllib.loads(ds.attrs["case_toml"])["operating"]["outer_speed"], "angular_speed")
        except (KeyError, tomllib.TOMLDecodeError, CaseError):  # no case text or no outer speed: nothing to add
            n_o = 0.0
        if n_o:
            lab["speed"] = f"outer ring n$_o$ = {n_o * _RPM:.3g} r/min"
    fixed = [lab[v] for k, v in _LABEL_KEYS.items() if v in lab and k not in keys and v not in keys]
    line2 = "varied: " + ", ".join(varied) + ("; fixed: " + ", ".join(fixed) if fixed else "")
    return line1 + "\n" + line2


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
    for s in range(prep["layout"]["n_series"]):
        col = colours[s]
        for k, (name, lab, ls, y) in enumerate(items):
            ys = np.where(good[s], y[s], np.nan)
            fin = np.isfinite(ys)
            ax.plot(x, ys, ls=ls, color=col, lw=1.1, zorder=2)  # NaN (not-ok or missing points) breaks the line
            if name in prep["yerr"]:
                e = prep["yerr"][name][s]
                fe = fin & np.isfinite(e)
                ax.errorbar(x[fe], ys[fe], yerr=e[fe], fmt="none", ecolor=col, elinewidth=1.0, capsize=3, zorder=2)
            size = (34 if k == 0 else 20) if len(x) <= 12 and prep["layout"]["n_series"] <= 6 else (16 if k == 0 else 9)
            if cls is None:
                # no classes: the marker tells the quantities of a panel apart (e.g. SFMC on top of RFMC)
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
        handles = [Line2D([], [], color="0.3", ls=ls, ms=5,
                          marker=_ITEM_MARKERS[k % len(_ITEM_MARKERS)] if prep["cls"] is None else None)
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
    """Draw the figure of a sweep or study summary (:func:`hsbearing.sweeps.assemble`) to ``path`` (PNG).

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
    return save_figure(fig, Path(path), metadata=meta)


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
    axs = np.atleast_1d(bottom.subplots(nrows, ncols, squeeze=False)).ravel()
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
