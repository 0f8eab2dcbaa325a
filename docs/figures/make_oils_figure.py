"""docs/figures/oils_viscosity_film.png and the table of docs/traction.md, "4050 as an oil of its own" (issue 26).

The three oils of Zhang et al. 2016 (built-in definitions, default case zhang2016: 14000 r/min, Fa = 1 kN,
lubricant.density 960 kg/m^3) at 27/80/130/180 degC: ambient-pressure viscosity (models.viscosity, Walther
through each oil's points), alpha (Table 1), and the Hamrock-Dowson central / minimum film thickness at the
inner and outer contacts of the most loaded ball of the quasi-static solution (contact_state).

Run: PYTHONPATH=. .venv/bin/python docs/figures/make_oils_figure.py   (about 15 s)
"""

from __future__ import annotations

from pathlib import Path

import numpy as np

from hsbearing.case import load_case
from hsbearing.models import ehl, viscosity
from hsbearing.systems.angular_contact import contact_state, quasistatic

OILS = ("4109", "4106", "4050")
TEMPS = (27.0, 80.0, 130.0, 180.0)
OUT = Path(__file__).with_name("oils_viscosity_film.png")


def compute():
    rows = []
    for oil in OILS:
        for T in TEMPS:
            case = load_case("zhang2016", oil=oil, **{"lubricant.temperature": f"{T} degC"})
            lp = ehl.lubricant_parameters(case)
            qs = quasistatic.solve_case(case)
            cs = contact_state.quasi_static_contact_state(case, qs)
            r = {"oil": oil, "T": T, "eta": lp["eta"], "alpha": lp["alpha"]}
            for side in ("inner", "outer"):
                i = int(np.nanargmax(qs[f"{side}_contact_load"].values))
                r[f"{side}_hc"] = float(cs[f"{side}_film_thickness_central"][i])
                r[f"{side}_hmin"] = float(cs[f"{side}_film_thickness_minimum"][i])
                r[f"{side}_lam"] = float(cs[f"{side}_film_parameter"][i])
            rows.append(r)
    return rows


def table(rows) -> str:
    lines = ["| oil | T [°C] | η [mPa s] | α [GPa⁻¹] | h_c,i [nm] | h_min,i [nm] | λ_i | h_c,o [nm] | h_min,o [nm] | λ_o |",
             "|---|---|---|---|---|---|---|---|---|---|"]
    for r in rows:
        lines.append(f"| {r['oil']} | {r['T']:.0f} | {r['eta'] * 1e3:.3f} | {r['alpha'] * 1e9:.2f} | {r['inner_hc'] * 1e9:.0f} | "
                     f"{r['inner_hmin'] * 1e9:.0f} | {r['inner_lam']:.2f} | {r['outer_hc'] * 1e9:.0f} | "
                     f"{r['outer_hmin'] * 1e9:.0f} | {r['outer_lam']:.2f} |")
    return "\n".join(lines)


def figure(rows) -> Path:
    import matplotlib

    matplotlib.use("Agg")
    from matplotlib.figure import Figure

    from hsbearing.plotting.common import save_figure

    colors = {"4109": "tab:blue", "4106": "tab:orange", "4050": "tab:green"}
    fig = Figure(figsize=(10.5, 4.2))
    ax1, ax2 = fig.add_subplot(121), fig.add_subplot(122)
    Tc = np.linspace(20.0, 190.0, 200)
    for oil in OILS:
        eta = viscosity.dynamic_viscosity(oil, Tc + 273.15, "walther", density=960.0) * 1e3
        ax1.semilogy(Tc, eta, color=colors[oil], label=f"{oil}: {viscosity.OIL_SPEC[oil].oil_class}")
        rr = [r for r in rows if r["oil"] == oil]
        ax1.semilogy([r["T"] for r in rr], [r["eta"] * 1e3 for r in rr], "o", color=colors[oil])
        ax2.plot([r["T"] for r in rr], [r["inner_hmin"] * 1e9 for r in rr], "o-", color=colors[oil], label=f"{oil} inner")
        ax2.plot([r["T"] for r in rr], [r["outer_hmin"] * 1e9 for r in rr], "s--", color=colors[oil], label=f"{oil} outer")
    eta_old = viscosity.dynamic_viscosity("4106", Tc + 273.15, "walther", density=960.0) * 1e3
    ax1.semilogy(Tc, eta_old, ":", color="tab:green", lw=1.0, label="4050 before issue 26 (= 4106's class curve)")
    ax1.set_xlabel("temperature [°C]")
    ax1.set_ylabel("η at ambient pressure [mPa s] (ρ = 960 kg/m³)")
    ax1.set_title("viscosity (Walther through each oil's points)", fontsize=9)
    ax1.legend(fontsize=6.5)
    ax1.grid(True, which="both", alpha=0.3)
    ax2.set_yscale("log")
    ax2.set_xlabel("oil temperature [°C]")
    ax2.set_ylabel("h_min, most loaded ball [nm]")
    ax2.set_title("Hamrock-Dowson h_min, zhang2016 (14000 r/min, 1 kN), quasi-static", fontsize=8)
    ax2.legend(fontsize=6.5, ncol=2)
    ax2.grid(True, which="both", alpha=0.3)
    fig.tight_layout()
    return save_figure(fig, OUT)


if __name__ == "__main__":
    rows = compute()
    print(table(rows))
    print(figure(rows))
