"""docs/figures/oils_traction.png and the tables of docs/traction.md, "Physical model".

The three oils of Zhang et al. 2016 (built-in definitions) at the default case (zhang2016: 14000 r/min,
Fa = 1 kN) at 27/80/130/180 degC, at the inner contact of the most loaded ball of the quasi-static solution:

* top row, one panel per temperature: mu(S) of each oil's default (seed) law (solid) and of the physical
  model "eyring" with the oil's own viscosity and alpha and the default rheological constants (dashed);
* bottom row: ambient-pressure viscosity, Hamrock-Dowson central film at that contact, and mu at S = 1 %
  of both models against temperature.

Printed: the table of mu at S = 0.01, 0.05, 0.2, 1, 5 % for each oil, temperature and model, and the ratio
eyring / seed (the consistency check of docs/traction.md).

Run (from the repository root): PYTHONPATH=. .venv/bin/python tools/generators/oils_traction_figure.py [--no-figure]
(about 20 s after the numba compile).
"""

from __future__ import annotations

import argparse
from pathlib import Path

import numpy as np

from hsbearing.case import load_case
from hsbearing.cli.oils import contact_conditions, contact_traction
from hsbearing.models import ehl, hertz
from hsbearing.systems.angular_contact import quasistatic

OILS = ("4109", "4106", "4050")
TEMPS = (27.0, 80.0, 130.0, 180.0)
S_TABLE = (0.0001, 0.0005, 0.002, 0.01, 0.05)
OUT = Path(__file__).resolve().parents[2] / "docs" / "figures" / "oils_traction.png"
COLORS = {"4109": "tab:blue", "4106": "tab:red", "4050": "tab:green"}


def compute():
    S = np.logspace(-4, np.log10(0.2), 200)
    rows = []
    for oil in OILS:
        for T in TEMPS:
            over = {"lubricant.oil": oil, "lubricant.temperature": f"{T} degC"}
            seed = load_case("zhang2016", **over)
            ey = load_case("zhang2016", **over, **{"lubricant.traction_law": "eyring"})
            qs = quasistatic.solve_case(seed)
            Q, U, Rx, Ry = contact_conditions(seed, qs, "inner")
            lp = ehl.lubricant_parameters(seed)
            mb, mr = seed.materials.ball, seed.materials.races
            Ep = float(hertz.reduced_modulus(mb.elastic_modulus, mb.poisson_ratio, mr.elastic_modulus, mr.poisson_ratio))
            pc = hertz.point_contact(Rx, Ry, Q, mb.elastic_modulus, mb.poisson_ratio, mr.elastic_modulus, mr.poisson_ratio)
            hc, _ = ehl.film_thickness(Q, U, Rx, Ry, Ep, lp["eta"], lp["alpha"], k=float(pc.ellipticity))
            rows.append({
                "oil": oil, "T": T, "Q": Q, "U": U, "eta": lp["eta"], "alpha": lp["alpha"], "hc": float(hc),
                "p0": float(pc.p_max), "S": S,
                "mu_seed": contact_traction(seed, S, Q, U, Rx, Ry), "mu_eyring": contact_traction(ey, S, Q, U, Rx, Ry),
                "tab_seed": contact_traction(seed, np.array(S_TABLE), Q, U, Rx, Ry),
                "tab_eyring": contact_traction(ey, np.array(S_TABLE), Q, U, Rx, Ry),
            })
    return rows


def table(rows):
    head = "| oil | T [°C] | Q [N] | U [m/s] | p0 [GPa] | h_c [nm] | model | " + " | ".join(
        f"μ({100 * s:g} %)" for s in S_TABLE) + " |"
    out = [head, "|" + "---|" * (7 + len(S_TABLE))]
    for r in rows:
        for m in ("seed", "eyring"):
            out.append(f"| {r['oil']} | {r['T']:g} | {r['Q']:.0f} | {r['U']:.1f} | {r['p0'] / 1e9:.2f} | {r['hc'] * 1e9:.0f} | "
                       f"{'default' if m == 'seed' else 'eyring'} | " + " | ".join(f"{x:.4f}" for x in r[f"tab_{m}"]) + " |")
        ratio = r["tab_eyring"] / r["tab_seed"]
        out.append("| | | | | | | eyring/default | " + " | ".join(f"{x:.2f}" for x in ratio) + " |")
    return out


def figure(rows, path):
    import matplotlib

    matplotlib.use("Agg")
    from matplotlib.figure import Figure

    from hsbearing.plotting.common import save_figure

    fig = Figure(figsize=(15, 7.5))
    axs = fig.subplots(2, 4)
    for j, T in enumerate(TEMPS):
        ax = axs[0, j]
        for r in rows:
            if r["T"] != T:
                continue
            c = COLORS[r["oil"]]
            ax.semilogx(r["S"] * 100, r["mu_seed"], color=c, label=f"{r['oil']} default law")
            ax.semilogx(r["S"] * 100, r["mu_eyring"], color=c, ls="--", label=f"{r['oil']} eyring")
        ax.set_title(f"{T:g} degC, inner contact, most loaded ball", fontsize=9)
        ax.set_xlabel("slide-roll ratio S [%]")
        ax.grid(True, alpha=0.3)
        if j == 0:
            ax.set_ylabel("traction coefficient mu [-]")
            ax.legend(fontsize=7)
    for oil in OILS:
        rr = [r for r in rows if r["oil"] == oil]
        T = [r["T"] for r in rr]
        c = COLORS[oil]
        axs[1, 0].semilogy(T, [r["eta"] * 1e3 for r in rr], "o-", color=c, label=oil)
        axs[1, 1].plot(T, [r["hc"] * 1e9 for r in rr], "o-", color=c, label=oil)
        i1 = S_TABLE.index(0.01)
        axs[1, 2].plot(T, [r["tab_seed"][i1] for r in rr], "o-", color=c, label=f"{oil} default")
        axs[1, 2].plot(T, [r["tab_eyring"][i1] for r in rr], "s--", color=c, label=f"{oil} eyring")
        i5 = S_TABLE.index(0.05)
        axs[1, 3].plot(T, [r["tab_seed"][i5] for r in rr], "o-", color=c, label=f"{oil} default")
        axs[1, 3].plot(T, [r["tab_eyring"][i5] for r in rr], "s--", color=c, label=f"{oil} eyring")
    for ax, yl in zip(axs[1], ("viscosity eta [mPa s]", "central film h_c (inner) [nm]", "mu at S = 1 %",
                               "mu at S = 5 %")):
        ax.set_xlabel("oil temperature [degC]")
        ax.set_ylabel(yl)
        ax.grid(True, alpha=0.3)
        ax.legend(fontsize=7)
    fig.suptitle("Oils 4109 / 4106 / 4050 at the default case (zhang2016): seed laws (solid) and the physical "
                 "model (dashed, default Lambda = 0.047, tau0 = 2 Lambda/alpha, G = 0.3 GPa)", fontsize=10)
    fig.tight_layout()
    return save_figure(fig, path)


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--no-figure", action="store_true")
    ap.add_argument("-o", "--output", default=str(OUT))
    args = ap.parse_args()
    rows = compute()
    print("\n".join(table(rows)))
    if not args.no_figure:
        print("figure:", figure(rows, args.output))


if __name__ == "__main__":
    main()
