"""Regenerate docs/figures/traction.png and the evidence tables of docs/traction.md.

Usage (from the repository root)::

    .venv/bin/python docs/figures/make_traction_figure.py            # figure
    .venv/bin/python docs/figures/make_traction_figure.py --tables   # markdown tables to stdout

The contact is the inner ball/race contact of the bundled default case
``zhang2016`` (seed 004): D = 9.525 mm, d_m = 46 mm, f_i = 0.52, alpha = 25 deg,
GCr15 (E = 208 GPa, nu = 0.3), inner ring 14000 r/min, pure-rolling
entrainment velocity U = omega_i d_m (1 - gamma^2) / 4.
"""

from __future__ import annotations

import itertools
import sys
from pathlib import Path

import numpy as np

from hsbearing.case import load_case
from hsbearing.models import traction
from hsbearing.models.geometry import curvature_radii
from hsbearing.models.hertz import reduced_modulus
from hsbearing.models.traction import zhang2016

HERE = Path(__file__).resolve().parent


def inner_contact():
    """(Rx, Ry, E', U) of the default case's inner contact [m, m, Pa, m/s]."""
    c = load_case("zhang2016")
    b, m = c.bearing, c.materials
    Rx, Ry, _, _ = curvature_radii(b.ball_diameter, b.pitch_diameter, b.contact_angle, b.inner_conformity, b.outer_conformity)
    Ep = float(reduced_modulus(m.ball.elastic_modulus, m.ball.poisson_ratio, m.races.elastic_modulus, m.races.poisson_ratio))
    gamma = b.ball_diameter * np.cos(b.contact_angle) / b.pitch_diameter
    U = c.operating.inner_speed * b.pitch_diameter * (1.0 - gamma**2) / 4.0
    return float(Rx), float(Ry), Ep, float(U)


def make_figure(path=HERE / "traction.png"):
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    Rx, Ry, Ep, U = inner_contact()
    S = np.linspace(0.0, 0.2, 401)
    temps = (27.0, 130.0, 180.0)
    colors = {"4109": "tab:blue", "4106": "tab:orange", "4050": "tab:green"}
    fig, axes = plt.subplots(1, 3, figsize=(13, 4.4), sharey=True)
    for ax, Tc in zip(axes, temps):
        T = Tc + 273.15
        for oil in traction.OILS:
            for W, ls in ((1000.0, "-"), (50.0, "--")):
                mu = traction.get(oil)(S, W, U, T, Ep, Rx)
                label = f"{oil} ({traction.law_name(oil)}), W = {W:g} N"
                ax.plot(S, mu, ls, color=colors[oil], lw=1.8, label=label)
        for W, ls in ((1000.0, ":"), (50.0, "-.")):
            mu = traction.get("4050", "printed")(S, W, U, T, Ep, Rx)
            ax.plot(S, mu, ls, color="0.45", lw=1.2, label=f"4050 Eq. 4 as printed, W = {W:g} N")
        ax.set_title(f"T = {Tc:g} degC, U = {U:.1f} m/s")
        ax.set_xlabel("slide-roll ratio S [-]")
        ax.set_xlim(0, 0.2)
        ax.set_ylim(0, 0.06)
        ax.grid(alpha=0.3)
    axes[0].set_ylabel("traction coefficient mu [-]")
    handles, labels = axes[0].get_legend_handles_labels()
    fig.legend(handles, labels, loc="lower center", ncol=4, fontsize=8, frameon=False)
    fig.suptitle("Seed 004 traction laws, default-case inner contact (Rx = %.2f mm, E' = %.1f GPa)" % (Rx * 1e3, Ep / 1e9))
    fig.tight_layout(rect=(0, 0.14, 1, 1))
    fig.savefig(path, dpi=110)
    plt.close(fig)
    return path


# ----------------------------------------------------------------------------
# evidence: conventions tested

OPS = [(W, U, T) for W in (50.0, 200.0, 1000.0, 3000.0) for U in (8.0, 15.0, 25.0) for T in (27.0, 80.0, 130.0, 180.0)]
S_GRID = np.concatenate([np.linspace(0.0, 0.3, 601), [0.5, 1.0]])


def _coefs_reading(oil, W, U, T_C, *, E, R, w_scale=1.0, u_scale=1.0, e_scale=1.0, r_scale=1.0, t_kelvin=False,
                   eta_scale=1.0, tbar=None):
    """Eqs. 2-4 evaluated under one reading of the units (the package kernel generalised)."""
    lid = traction.law_id(oil, "printed")
    p = zhang2016.PARAMS[lid]
    eta0, beta, K = p[0] * eta_scale, p[1], p[2]
    W, U, E, R = W * w_scale, U * u_scale, E * e_scale, R * r_scale
    T = T_C + (273.15 if t_kelvin else 0.0)
    Wb, Ub = W / (E * R * R), eta0 * U / (E * R)
    kind = p[3] if tbar is None else tbar
    Tb = T * np.sqrt(K * eta0 * beta) / (E * R) if kind == 0 else T * K / (eta0 * U * U)
    f = abs((p[5] * Tb * Tb + p[6] * Tb + p[7]) / Wb - 1.0) if p[4] else 1.0
    return [p[9 + 4 * j] * Wb ** p[10 + 4 * j] * f * Ub ** p[11 + 4 * j] * Tb ** p[12 + 4 * j] for j in range(4)]


def _physical(A, B, C, D, s_scale):
    with np.errstate(all="ignore"):
        mu = (A + B * S_GRID * s_scale) * np.exp(-C * S_GRID * s_scale) + D
    sel = S_GRID <= 0.2
    mx = np.nanmax(np.abs(mu[sel]))
    j = int(np.argmax(np.abs(mu[sel]) >= 0.63 * mx)) if mx > 0 else 0
    ok = (np.isfinite(mx) and abs(mu[0]) < 0.01 and 0.005 <= mx <= 0.12 and abs(mu[-1]) <= 1.2 * mx
          and 0.001 <= S_GRID[j] <= 0.1)
    return ok, mu


READINGS = {
    "SI, T in degC, E = E', R = Rx, S fraction (adopted)": {},
    "T in K": dict(t_kelvin=True),
    "E = E'/2 (Johnson's E*)": dict(e_scale=0.5),
    "E = Young's modulus E": dict(e_scale=0.91),
    "R = reduced radius R'": dict(r_red=True),
    "S in percent": dict(s_pct=True),
    "E in GPa, R in mm": dict(e_scale=1e-9, r_scale=1e3),
    "E in MPa, R in mm, W in N": dict(e_scale=1e-6, r_scale=1e3),
    "U in mm/s, eta0 in mPa s": dict(u_scale=1e3, eta_scale=1e3),
    "W in kN": dict(w_scale=1e-3),
    "Eq. 4 with Tbar of Eqs. 2-3": dict(tbar=0),
}


def convention_table():
    Rx, Ry, Ep, Ucase = inner_contact()
    Rred = 1.0 / (1.0 / Rx + 1.0 / Ry)
    rows = ["| reading | oil | A_L | B_L | C_L | D_L | mu(0.05) | mu(1) | physical at (of 48) |",
            "|---|---|---|---|---|---|---|---|---|"]
    for name, kw in READINGS.items():
        kw = dict(kw)
        R = Rred if kw.pop("r_red", False) else Rx
        s_scale = 100.0 if kw.pop("s_pct", False) else 1.0
        for oil in traction.OILS:
            if "tbar" in kw and oil != "4050":
                continue
            n_ok = 0
            for W, U, T in OPS:
                ok, _ = _physical(*_coefs_reading(oil, W, U, T, E=Ep, R=R, **kw), s_scale)
                n_ok += ok
            A, B, C, D = _coefs_reading(oil, 1000.0, 15.0, 130.0, E=Ep, R=R, **kw)
            with np.errstate(all="ignore"):
                mu = lambda s: (A + B * s * s_scale) * np.exp(-C * s * s_scale) + D  # noqa: E731
                rows.append(f"| {name} | {oil} | {A:.3g} | {B:.3g} | {C:.3g} | {D:.3g} | {mu(0.05):.4g} | {mu(1.0):.4g} | {n_ok} |")
    return "\n".join(rows)


def brute_force_search():
    """Count, per oil, the unit readings (of 2304) under which the printed law is physical at all 48 points,
    and the best reading's count: 3 moduli (E', E'/2, E) x Pa/MPa/GPa x (Rx, R') x m/mm x U m/s, mm/s x W N, kN
    x T degC, K x eta0 Pa s, mPa s x S fraction, percent x (Tbar of Eqs. 2-3, Tbar of Eq. 4)."""
    Rx, Ry, Ep, Ucase = inner_contact()
    Rred = 1.0 / (1.0 / Rx + 1.0 / Ry)
    moduli = {"E'": Ep, "E'/2": Ep / 2, "E": 208e9}
    out = ["| oil | readings tested | physical at all 48 points | best reading: points passed |", "|---|---|---|---|"]
    for oil in traction.OILS:
        n_read, n_full, best = 0, 0, (-1, None)
        for (en, E), es, (rn, R), rs, us, ws, tk, hs, ss, tb in itertools.product(
                moduli.items(), (1.0, 1e-6, 1e-9), (("Rx", Rx), ("R'", Rred)), (1.0, 1e3), (1.0, 1e3), (1.0, 1e-3),
                (False, True), (1.0, 1e3), (1.0, 100.0), (0, 1)):
            n_read += 1
            n_ok = 0
            for W, U, T in OPS:
                ok, _ = _physical(*_coefs_reading(oil, W, U, T, E=E, R=R, e_scale=es, r_scale=rs, u_scale=us,
                                                  w_scale=ws, t_kelvin=tk, eta_scale=hs, tbar=tb), ss)
                n_ok += ok
            n_full += n_ok == len(OPS)
            if n_ok > best[0]:
                best = (n_ok, (en, es, rn, rs, us, ws, "K" if tk else "degC", hs, ss, "sqrt" if tb == 0 else "brinkman"))
        out.append(f"| {oil} | {n_read} | {n_full} | {best[0]} {best[1]} |")
    return "\n".join(out)


def critical_load_table():
    """Critical load W_c = Wbar_c E' Rx^2 [N] of Eqs. 2-3 with T in degC and in K."""
    Rx, Ry, Ep, U = inner_contact()
    rows = ["| oil | T [degC] | W_c, T in degC [N] | W_c, T in K [N] |", "|---|---|---|---|"]
    for oil in ("4109", "4106"):
        p = zhang2016.PARAMS[traction.law_id(oil, "printed")]
        for Tc in (27.0, 80.0, 130.0, 180.0):
            out = []
            for T in (Tc, Tc + 273.15):
                Tb = T * np.sqrt(p[2] * p[0] * p[1]) / (Ep * Rx)
                out.append((p[5] * Tb * Tb + p[6] * Tb + p[7]) * Ep * Rx * Rx)
            rows.append(f"| {oil} | {Tc:g} | {out[0]:.1f} | {out[1]:.1f} |")
    return "\n".join(rows)


def eq4_required_groups():
    """Values of (Wbar, Ubar, Tbar) at which Eq. 4 would give a typical EHL curve."""
    M = np.array([[0.3403, 0.4748, 0.2488], [0.3831, 2.9404, 1.6113], [-0.1372, 0.2116, 0.1766]])
    rows = ["| target D_L | target C_L | target peak B/(C e) | Wbar | Ubar | Tbar |", "|---|---|---|---|---|---|"]
    for Dt, Ct, peak in ((0.02, 30.0, 0.05), (0.03, 20.0, 0.06), (0.04, 100.0, 0.08)):
        rhs = np.log([Dt / 16.7177, Ct / 61.4605, peak * Ct * np.e / 7.2804])
        x = np.exp(np.linalg.solve(M, rhs))
        rows.append(f"| {Dt} | {Ct:g} | {peak} | {x[0]:.2g} | {x[1]:.2g} | {x[2]:.2g} |")
    return "\n".join(rows)


def oil_comparison_table():
    Rx, Ry, Ep, U = inner_contact()
    rows = ["| T [degC] | W [N] | 4109 | 4106 | 4050 (analogue_4106) | 4050 printed | slope dmu/dS(0): 4106 / 4050 printed |",
            "|---|---|---|---|---|---|---|"]
    for Tc, W in itertools.product((27.0, 130.0, 180.0), (50.0, 1000.0)):
        T = Tc + 273.15
        vals = [float(traction.get(o)(0.1, W, U, T, Ep, Rx)) for o in ("4109", "4106", "4050")]
        pr = float(traction.get("4050", "printed")(0.1, W, U, T, Ep, Rx))
        A, B, C, D = zhang2016.coefficients(traction.law_id("4106"), W, U, T, Ep, Rx)
        A4, B4, C4, D4 = zhang2016.coefficients(traction.law_id("4050", "printed"), W, U, T, Ep, Rx)
        rows.append(f"| {Tc:g} | {W:g} | {vals[0]:.4f} | {vals[1]:.4f} | {vals[2]:.4f} | {pr:.4f} | "
                    f"{float(B - A * C):.3f} / {float(B4 - A4 * C4):.3f} |")
    return f"mu at S = 0.1, U = {U:.2f} m/s (default-case inner contact)\n\n" + "\n".join(rows)


if __name__ == "__main__":
    if "--tables" in sys.argv:
        print(convention_table(), end="\n\n")
        print(critical_load_table(), end="\n\n")
        print(eq4_required_groups(), end="\n\n")
        print(oil_comparison_table(), end="\n\n")
        print(brute_force_search())
    else:
        print(make_figure())
