"""``hsbearing oils``: the bundled lubricant library and one oil's derived values at a case.

:func:`library_rows` lists the bundled lubricants (``hsbearing/lubricants/*.toml``) with their key
properties; :func:`at_case` evaluates one lubricant (bundled name or file) at a case's temperature and
at the contacts of the case's quasi-static solution (viscosity, alpha, central / minimum film thickness
and film parameter at the inner and outer contacts); :func:`plot_traction` draws mu(S) of the oil's
traction law at those contacts (PNG, atomic write).  The definitions: :mod:`hsbearing.lubricant`.
"""

from __future__ import annotations

from pathlib import Path

import numpy as np

from hsbearing import lubricant as lubmod
from hsbearing.errors import CaseError

__all__ = ["library_rows", "format_library", "at_case", "format_at_case", "plot_traction", "write_template"]


def write_template(path) -> Path:
    """Write :data:`hsbearing.lubricant.TEMPLATE` to ``path`` (atomic; the caller checks the path first)."""
    from hsbearing.results import atomic_write

    path = Path(path)
    with atomic_write(path) as tmp:
        tmp.write_text(lubmod.TEMPLATE, encoding="utf-8")
    return path

T40, T100 = 313.15, 373.15


def _fmt(x, spec=".3g", none="-"):
    return none if x is None or not np.isfinite(x) else format(x, spec)


def library_rows() -> list[dict]:
    """One dict per bundled lubricant: name, file, class, nu40, nu100 [mm^2/s], VI, rho15 [kg/m^3],
    alpha40 [GPa^-1] (or the correlation's name), traction law."""
    rows = []
    for stem, path in lubmod.bundled_lubricants().items():
        d = lubmod.load_lubricant(path)
        rho_known = d.density_ref is not None
        kin = d.viscosity_kind == "kinematic"
        nu40 = nu100 = None
        if kin or rho_known:
            fb = None if rho_known else 900.0  # kinematic points: nu does not depend on the density
            nu40 = float(d.kinematic_viscosity(T40, fb)) * 1e6
            nu100 = float(d.kinematic_viscosity(T100, fb)) * 1e6
        if d.alpha_estimate is not None:
            alpha = f"est. ({d.alpha_estimate})"
        else:
            alpha = _fmt(d.alpha(T40) * 1e9)
        rows.append({
            "name": stem, "title": d.name, "class": d.oil_class, "nu40": nu40, "nu100": nu100,
            "eta40": None if (kin or rho_known) else d.dynamic_viscosity(T40, 870.0) * 1e3,
            "vi": d.viscosity_index, "rho15": d.density(288.15) if rho_known else None, "alpha40": alpha,
            "traction": f"{d.traction_oil}/{d.traction_law}" if d.traction_model == "zhang2016" else d.traction_model,
        })
    return rows


def format_library(rows) -> list[str]:
    head = f"{'name':22s} {'nu40':>7s} {'nu100':>6s} {'VI':>4s} {'rho15':>6s} {'alpha40':>22s}  {'traction':14s} class"
    unit = f"{'':22s} {'mm^2/s':>7s} {'mm^2/s':>6s} {'':>4s} {'kg/m^3':>6s} {'GPa^-1':>22s}  {'oil/law':14s}"
    out = [head, unit]
    for r in rows:
        nu40 = _fmt(r["nu40"], ".4g") if r["nu40"] is not None else "-"
        out.append(f"{r['name']:22s} {nu40:>7s} {_fmt(r['nu100'], '.3g'):>6s} {_fmt(r['vi'], '.0f'):>4s} "
                   f"{_fmt(r['rho15'], '.0f'):>6s} {r['alpha40']:>22s}  {r['traction']:14s} {r['class']}")
    out.append("nu: Walther (ASTM D341) through the file's points; '-' = not in the source (density: the case's "
               "lubricant.density is used; VI: only as the source states it); alpha at 40 degC.")
    dyn = [r for r in rows if r["eta40"] is not None]
    for r in dyn:
        out.append(f"  {r['name']}: dynamic viscosity data without density (eta(40 degC) = {r['eta40']:.3g} mPa s at "
                   "870 kg/m^3; nu depends on the density the case gives)")
    return out


def at_case(spec: str, case_name, sets: dict | None = None):
    """(case with the lubricant, quasi-static Dataset, derived dict) for lubricant ``spec`` at a case."""
    from hsbearing.case import load_case
    from hsbearing.models import ehl
    from hsbearing.systems.angular_contact import contact_state, quasistatic

    overrides = dict(sets or {})
    overrides["lubricant.file"] = spec
    case = load_case(case_name, **overrides)
    if case.system not in ("angular_contact", "deep_groove"):
        raise CaseError(case.source, "case.system", f"hsbearing oils --at needs a ball-bearing case with a quasi-static "
                                                    f"solution (angular_contact, deep_groove), got {case.system}")
    qs = quasistatic.solve_case(case)
    cs = contact_state.quasi_static_contact_state(case, qs)
    lp = ehl.lubricant_parameters(case)
    out = {"T": lp["T"], "eta": lp["eta"], "nu": lp["eta"] / case.lubricant.density, "rho": case.lubricant.density,
           "alpha": lp["alpha"], "alpha_estimated": case.lubricant.definition.alpha_estimated}
    for side in ("inner", "outer"):
        Q = qs[f"{side}_contact_load"].values
        i = int(np.nanargmax(Q))
        out[side] = {"ball": i, "Q": float(Q[i]), "p": float(cs[f"{side}_contact_pressure"][i]),
                     "hc": float(cs[f"{side}_film_thickness_central"][i]), "hmin": float(cs[f"{side}_film_thickness_minimum"][i]),
                     "lam_min": float(np.nanmin(cs[f"{side}_film_parameter"])),
                     "lam": float(cs[f"{side}_film_parameter"][i])}
    return case, qs, out


def format_at_case(case, d) -> list[str]:
    lub = case.lubricant
    dfn = lub.definition
    lines = [f"{dfn.name} ({dfn.oil_class or 'class not given'}) at case {case.name}, {d['T'] - 273.15:.4g} degC "
             f"(quasi-static solution):",
             f"  eta = {d['eta'] * 1e3:.4g} mPa s, nu = {d['nu'] * 1e6:.4g} mm^2/s, rho = {d['rho']:.4g} kg/m^3"
             + ("" if dfn.density_ref is not None else " (the case's lubricant.density)"),
             f"  alpha = {d['alpha'] * 1e9:.4g} GPa^-1" + (f"  (ESTIMATED, {dfn.alpha_estimate})" if d["alpha_estimated"] else ""),
             f"  traction: {lubmod.traction_summary(dfn)}"]
    for side in ("inner", "outer"):
        s = d[side]
        lines.append(f"  {side} contact (most loaded ball {s['ball']}): Q = {s['Q']:.4g} N, p_max = {s['p'] * 1e-9:.3g} GPa, "
                     f"h_c = {s['hc'] * 1e9:.4g} nm, h_min = {s['hmin'] * 1e9:.4g} nm, lambda = {s['lam']:.3g} "
                     f"(lowest over the balls {s['lam_min']:.3g})")
    return lines


def contact_conditions(case, qs, side):
    """(Q [N], U [m/s], Rx [m], Ry [m]) of the most loaded ball's ``side`` ("inner"/"outer") contact of the
    quasi-static solution ``qs`` (rolling speed of the ball centre's orbit against the race, no spin)."""
    from hsbearing.models.geometry import derive

    g = derive(case)
    D = g.D
    wm, rb = qs["ball_orbit_speed"].values, qs["ball_center_radial"].values
    Qs = qs[f"{side}_contact_load"].values
    i = int(np.nanargmax(Qs))
    a = float(qs[f"{side}_contact_angle"].values[i])
    if side == "inner":
        U = abs(case.operating.inner_speed - wm[i]) * (rb[i] - 0.5 * D * np.cos(a))
        Rx = 0.5 * D * (1.0 - D * np.cos(a) / g.dm)
        f = g.fi
    else:
        U = abs(case.operating.outer_speed - wm[i]) * (rb[i] + 0.5 * D * np.cos(a))
        Rx = 0.5 * D * (1.0 + D * np.cos(a) / g.dm)
        f = g.fo
    Ry = f * D / (2.0 * f - 1.0)  # ball against the groove of radius f D
    return float(Qs[i]), float(U), float(Rx), float(Ry)


def contact_traction(case, S, Q, U, Rx, Ry):
    """mu(S) of the case's traction law at one ball/race contact (load Q [N], rolling speed U [m/s], radii
    Rx, Ry [m]): the registered seed laws, the physical model (with the contact's Hertz ellipse, the oil's
    eta and alpha at the case temperature and the case's rheological constants) or the user coefficients."""
    from hsbearing.models import ehl, hertz, traction
    from hsbearing.systems.angular_contact.dynamics import traction_values

    lub = case.lubricant
    mb, mr = case.materials.ball, case.materials.races
    Ep = float(hertz.reduced_modulus(mb.elastic_modulus, mb.poisson_ratio, mr.elastic_modulus, mr.poisson_ratio))
    lp = ehl.lubricant_parameters(case)
    tv = traction_values(case, lp["alpha"])
    pc = hertz.point_contact(Rx, Ry, Q, mb.elastic_modulus, mb.poisson_ratio, mr.elastic_modulus, mr.poisson_ratio)
    return traction.contact_mu(lub.oil, S, Q, U, lub.temperature, Ep, Rx, Ry, law=lub.traction_law,
                               k=float(pc.ellipticity), a=float(pc.a), eta=lp["eta"], alpha=lp["alpha"],
                               eyring=(tv["tau0"], tv["Lambda"], tv["G"]),
                               coefficients=(tv["c_A"], tv["c_B"], tv["c_C"], tv["c_D"]))


def plot_traction(case, qs, path) -> Path:
    """mu(S) of the case's traction law at the inner and outer contacts of the most loaded ball (PNG)."""
    import matplotlib

    matplotlib.use("Agg", force=False)
    from matplotlib.figure import Figure

    from hsbearing.models import traction
    from hsbearing.plotting.common import save_figure

    lub = case.lubricant
    S = np.logspace(-5, np.log10(0.2), 400)
    fig = Figure(figsize=(6.4, 4.2))
    ax = fig.add_subplot(111)
    for side, color in (("inner", "tab:blue"), ("outer", "tab:red")):
        Q, U, Rx, Ry = contact_conditions(case, qs, side)
        mu = contact_traction(case, S, Q, U, Rx, Ry)
        ax.semilogx(S * 100.0, mu, color=color, label=f"{side}: Q = {Q:.0f} N, U = {U:.1f} m/s")
    ax.set_xlabel("slide-roll ratio S [%]")
    ax.set_ylabel("traction coefficient mu [-]")
    name = lub.definition.name if lub.definition is not None else lub.oil
    lawtxt = (f"law {traction.law_name(lub.oil, lub.traction_law)} of oil {lub.oil}" if traction.is_seed_law(lub.traction_law)
              else f"law {lub.traction_law}")
    ax.set_title(f"{name}: {lawtxt}, "
                 f"{lub.temperature - 273.15:.0f} degC, case {case.name}", fontsize=9)
    ax.grid(True, alpha=0.3)
    ax.legend(fontsize=8)
    fig.tight_layout()
    return save_figure(fig, path)
