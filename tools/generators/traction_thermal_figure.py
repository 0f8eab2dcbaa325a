"""docs/figures/traction_thermal.png: traction curves of the seed laws, "eyring" and "physical", and the film temperature.

The default case's inner contact (182 N, 16.3 m/s, Rx 3.87 mm, Ry 124 mm, E' 228.6 GPa), oils 4109/4106/4050 at 27 and
130 degC, slide-roll ratio 1e-5 ... 1 (log).  Left: mu of the three laws; right: the largest film mean temperature rise
of the central strip of "physical".  Run: PYTHONPATH=. .venv/bin/python tools/generators/traction_thermal_figure.py
"""

from pathlib import Path

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

import hsbearing  # noqa: E402
from hsbearing.models import hertz, traction  # noqa: E402
from hsbearing.models.traction import thermal as th  # noqa: E402
from hsbearing.plotting.common import save_figure  # noqa: E402

EP, RX, RY, W, U = 228.6e9, 3.87e-3, 0.124, 182.0, 16.3
OUT = Path(__file__).resolve().parents[2] / "docs" / "figures" / "traction_thermal.png"


def main():
    S = np.geomspace(1e-5, 1.0, 36)
    fig, (ax, axT) = plt.subplots(1, 2, figsize=(11, 4.2))
    colors = {"4109": "C0", "4106": "C1", "4050": "C2"}
    c = hertz.point_contact(RX, RY, W, EP, 0.0, EP, 0.0)
    for oil in traction.OILS:
        for T_C, ls in ((27.0, "-"), (130.0, "--")):
            T = T_C + 273.15
            args = (W, U, T, RX, RY, EP)
            seed = traction.get(oil)(S, W, U, T, EP, RX)
            ey = hsbearing.traction_coefficient(oil, S, *args, law="eyring")
            ph = hsbearing.traction_coefficient(oil, S, *args, law="physical")
            ax.plot(S, seed, ls, color=colors[oil], lw=0.8, alpha=0.6)
            ax.plot(S, ey, ls, color=colors[oil], lw=0.8, marker=".", ms=3, alpha=0.6)
            ax.plot(S, ph, ls, color=colors[oil], lw=2.0, label=f"{oil} {T_C:.0f} °C")
            eta, alpha, beta, K, _ = hsbearing._oil_at(oil, T)
            prm = th.PhysicalParameters()
            b, p0, h, Ge, tau0 = th.contact_parameters(W, U, EP, RX, float(c.ellipticity), float(c.a), eta, alpha,
                                                       prm, T)
            oil_d = dict(eta_in=eta, alpha=alpha, beta_in=beta, K=K)
            dT = [float(np.max(th.strip_mu(s, U, p0, b, h, T, oil_d, prm, Ge=Ge, tau0_in=tau0,
                                           return_fields=True)[1]["T"]) - T) for s in S]
            axT.plot(S, dT, ls, color=colors[oil], label=f"{oil} {T_C:.0f} °C")
    ax.set_xscale("log")
    ax.set_xlabel("slide-roll ratio S")
    ax.set_ylabel("traction coefficient μ")
    ax.set_title("thick: physical (thermal); dots: eyring; thin: seed law (default)", fontsize=9)
    ax.legend(fontsize=7, ncol=2)
    axT.set_xscale("log")
    axT.set_yscale("log")
    axT.set_xlabel("slide-roll ratio S")
    axT.set_ylabel("largest film temperature rise, central strip [K]")
    axT.legend(fontsize=7, ncol=2)
    fig.suptitle("default case inner contact: 182 N, 16.3 m/s, p0 1.28 GPa", fontsize=10)
    fig.tight_layout()
    save_figure(fig, OUT)
    print(OUT)


if __name__ == "__main__":
    main()
