"""Figures of the ball-bearing dynamic model (:mod:`hsbearing.systems.angular_contact.dynamics`: angular-contact and deep-groove runs)
and of the quasi-static equilibrium (:mod:`hsbearing.systems.angular_contact.quasistatic`).

- :func:`plot_dynamic`: (a) cage whirl orbit D_Y-D_Z with the guide clearance circle, (b) Poincare map (D_Y, V_Y)
  -- the same section points as the stored classification (:mod:`hsbearing.analysis.poincare`), (c) cage speed
  against time with the pure-rolling speed, (d) cage slip ratio;
- :func:`plot_quasistatic`: per-ball contact loads and angles.
"""

from __future__ import annotations

from pathlib import Path

import numpy as np

from hsbearing.plotting import common  # common.save_figure: one place to capture every figure
from hsbearing.plotting.common import (
    RPM,
    _figure,
    _wrap,
    case_labels,
    length_scale,
    per_ball_axes,
    shade,
    title_lines,
    vals,
    velocity_scale,
)

__all__ = ['plot_dynamic', 'plot_quasistatic', 'plot_friction_angular_contact']


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
        lf, lu = length_scale(r_ext)
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
        _draw_section_line(ax, ds, lf, view)
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
        pts = poincare.poincare_points(ds)
    except Exception:
        pts = np.zeros((0, 2))
    vy = poincare.cage_velocity(ds, "y") if "cage_center_y" in ds else np.zeros(0)
    yy = np.asarray(ds["cage_center_y"].values, float) if "cage_center_y" in ds else np.zeros(0)
    ext_y = float(np.nanmax(np.abs(yy[mask]))) if mask.any() and yy.size else float("nan")
    ext_v = float(np.nanmax(np.abs(vy[mask]))) if mask.any() and vy.size else float("nan")
    if len(pts):
        ext_y = max(ext_y, float(np.nanmax(np.abs(pts[:, 0])))) if np.isfinite(ext_y) else float(np.nanmax(np.abs(pts[:, 0])))
        ext_v = max(ext_v, float(np.nanmax(np.abs(pts[:, 1])))) if np.isfinite(ext_v) else float(np.nanmax(np.abs(pts[:, 1])))
    lf, lu = length_scale(ext_y)
    vf, vu = velocity_scale(ext_v)
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
    kind = ds.attrs.get("poincare_section_kind", "cage_revolution")
    ttl = f"(b) Poincar\u00e9 map, {len(pts)} points (one per cage revolution)"
    if kind == "plane":
        ttl = f"(b) Poincar\u00e9 map, {len(pts)} points (plane D_Z = mean, upward)"
    elif kind == "transverse":
        ttl = (f"(b) Poincar\u00e9 map, {len(pts)} points\n(transverse: D_Z = mean, D_Y > mean, in the whirl's sense;"
               " red line in (a))")
    ax.set_title(ttl, fontsize=10)
    if lab:
        txt = lab if lab == "undetermined" or conf is None else f"{lab} (confidence {float(conf):.2f})"
        reason = ds.attrs.get("classification_reason", "")
        alt = ds.attrs.get("classification_alternative")
        if alt:
            txt += f"  [{ds.attrs.get('classification_alternative_section', 'other')} section: {alt}]"
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
        w = np.asarray(ds["cage_speed"].values, float) * RPM
        ax.plot(t_ms, w, color="C0", lw=0.8, label="cage speed")
        if "theoretical_cage_speed" in ds:
            wth = float(ds["theoretical_cage_speed"]) * RPM
            ax.axhline(wth, color="k", ls="--", lw=0.9, label=f"pure rolling at \u03b1$_0$: {wth:.0f} r/min")
        if "raceway_control_cage_speed" in ds and np.isfinite(float(ds["raceway_control_cage_speed"])):
            wrc = float(ds["raceway_control_cage_speed"]) * RPM
            ax.axhline(wrc, color="C2", ls=":", lw=1.1,
                       label=f"outer-raceway control at loaded \u03b1: {wrc:.0f} r/min")
        shade(ax, t_tr * 1e3)
        ax.legend(fontsize=8, loc="best")
    ax.set_xlabel("time [ms]")
    ax.set_ylabel("cage speed [r/min]")
    ax.set_title("(c) cage speed", fontsize=10)
    ax.grid(alpha=0.3)

    # (d) slip ratio
    ax = axs[1, 1]
    if "cage_slip_ratio" in ds:
        s = np.asarray(ds["cage_slip_ratio"].values, float) * 100
        ts = ds["cage_slip_ratio"].dims[0] if ds["cage_slip_ratio"].dims else "time"
        t_s = t_ms if ts == "time" else (np.asarray(ds[ts].values, float) - t[0]) * 1e3  # a kept (decimated) history
        ax.plot(t_s, s, color="C3", lw=0.8, label="cage slip ratio")
        if "mean_cage_slip_ratio" in ds and np.isfinite(float(ds["mean_cage_slip_ratio"])):
            ms = 100 * float(ds["mean_cage_slip_ratio"])
            ax.axhline(ms, color="k", ls=":", lw=0.9, label=f"mean after transient {ms:.2f} %")
        if "mean_cage_slip_ratio_raceway_control" in ds and np.isfinite(float(ds["mean_cage_slip_ratio_raceway_control"])):
            rc = 100 * float(ds["mean_cage_slip_ratio_raceway_control"])
            ax.plot([], [], " ", label=f"against outer-raceway control at loaded \u03b1: {rc:.2f} %")
        shade(ax, t_tr * 1e3)
        ax.legend(fontsize=8, loc="best")
    else:
        ax.text(0.5, 0.5, "no cage slip ratio (case unknown)", ha="center", va="center", transform=ax.transAxes)
    ax.set_xlabel("time [ms]")
    ax.set_ylabel("cage slip ratio $(\\omega_{c,th}-\\omega_c)/\\omega_{c,th}$ [%]")
    ax.set_title("(d) cage slip ratio", fontsize=10)
    ax.grid(alpha=0.3)
    return common.save_figure(fig, path)




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
            x = np.arange(nb)  # balls 0..Z-1, as in the archive and the printed table
            off = -0.2 if "inner" in name else 0.2
            ax1.bar(x + off, q, width=0.4, color=c, label=lab)
    per_ball_axes(ax1, nb, "contact load [N]", "contact loads per ball", grid_axis="y")
    for name, lab, c in (("inner_contact_angle", "inner race $\\alpha_i$", "C0"), ("outer_contact_angle", "outer race $\\alpha_o$", "C1")):
        if name in ds:
            a = np.degrees(np.atleast_1d(np.asarray(ds[name].values, float)))
            ax2.plot(np.arange(len(a)), a, "o-", color=c, label=lab)
    per_ball_axes(ax2, nb, "contact angle [\N{DEGREE SIGN}]", "contact angles per ball", grid_axis="both")
    return common.save_figure(fig, path)




plot_dynamic = _plot_dynamic
plot_quasistatic = _plot_static


def _draw_section_line(ax, ds, lf: float, view: float) -> None:
    """The transverse section's half-plane D_Z = z̄, D_Y > ȳ as a red half-line on the orbit panel."""
    import json

    if ds.attrs.get("poincare_section_kind") != "transverse":
        return
    try:
        d = json.loads(ds.attrs.get("poincare_section_definition", "{}"))
        yc, zc, sense = float(d["centre_y"]) * lf, float(d["centre_z"]) * lf, int(d["sense"])
    except (KeyError, TypeError, ValueError):
        return
    if not (np.isfinite(yc) and np.isfinite(zc)):
        return
    ax.plot([yc, view], [zc, zc], color="r", lw=1.2, zorder=4,
            label="section: D_Z = mean, D_Y > mean, " + ("V_Z > 0" if sense >= 0 else "V_Z < 0"))
    ax.plot([yc], [zc], "rx", ms=6, zorder=4)


def plot_friction_angular_contact(ds, path) -> Path:
    """Figure of ``hsbearing friction`` of an angular-contact case (dim ``speed``, ``qs_power_loss``):
    (a) the quasi-static power loss by source against the inner-ring speed [W]; (b) its friction torque
    P / omega next to the SKF 2004 moments M_rr, M_sl and M [N mm]."""
    from hsbearing.systems.angular_contact.balances import SOURCES

    path = Path(path)
    fig = _figure((11, 4.6))
    ax1, ax2 = fig.subplots(1, 2)
    rpm = vals(ds, "speed", RPM)
    lab = case_labels(ds)
    head = ", ".join([ds.attrs.get("case_name", "friction")] + [lab[k] for k in ("oil", "axial_load", "radial_load",
                                                                                "temperature") if k in lab])
    fig.suptitle(f"quasi-static power loss and friction torque: {head}", fontsize=11)
    marker = "o" if len(rpm) <= 12 else None
    for k, s in enumerate(tuple(SOURCES) + ("jet_oil_acceleration", "cage_windage")):  # + rating.CAVITY_SOURCES
        name = f"qs_power_loss_{s}"
        if name in ds and np.any(np.abs(vals(ds, name)) > 1e-9):
            ax1.plot(rpm, vals(ds, name), marker=marker, ms=4, lw=1.2, color=f"C{k % 10}", label=s.replace("_", " "))
    if "qs_drag_band_low" in ds and np.any(vals(ds, "qs_drag_band_high") > 0):
        ax1.fill_between(rpm, vals(ds, "qs_drag_band_low"), vals(ds, "qs_drag_band_high"), color="0.6", alpha=0.25,
                         lw=0, label="drag band (co-rotation, C_D)")
    ax1.plot(rpm, vals(ds, "qs_power_loss"), marker=marker, ms=4, lw=2.0, color="k", label="total")
    ax1.set_xlabel("inner-ring speed n [r/min]")
    ax1.set_ylabel("power loss [W]")
    ax1.set_title("(a) power loss by source (quasi-static state)", fontsize=10)
    ax1.grid(alpha=0.3)
    ax1.legend(fontsize=7.5, loc="best")
    rows = (("qs_friction_torque", "quasi-static P / \u03c9", "k", "-", 2.0),
            ("skf_rolling_torque", "SKF 2004 $M_{rr}$", "C4", "--", 1.2),
            ("skf_sliding_torque", "SKF 2004 $M_{sl}$", "C1", "--", 1.2),
            ("skf_total_torque", "SKF 2004 total $M$", "C3", "--", 1.6))
    for name, label, col, ls, lw in rows:
        if name in ds:
            ax2.plot(rpm, vals(ds, name, 1e3), ls=ls, color=col, lw=lw, marker=marker, ms=4, label=label)
    ax2.set_xlabel("inner-ring speed n [r/min]")
    ax2.set_ylabel("torque [N mm]")
    ax2.set_title("(b) friction torque", fontsize=10)
    ax2.grid(alpha=0.3)
    ax2.legend(fontsize=7.5, loc="best")
    return common.save_figure(fig, path)
