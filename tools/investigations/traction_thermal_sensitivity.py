"""Sensitivity of the physical traction plateau to each rheological choice, and the curve's shape against the seed laws.

Conditions: the default case's inner contact (zhang2016: Q = 182 N, U = 16.3 m/s, Rx = 3.87 mm, Ry = 124 mm,
E' = 228.6 GPa, p0 = 1.28 GPa), 130 degC, the three oils.  Prints (markdown):

1. mu at S = 0.05 (the plateau) for: the seed law (default), "eyring" (isothermal, Barus), "physical" (thermal,
   Roelands) and "physical" with one choice changed at a time -- Barus instead of Roelands; alpha(T) falling as the
   measured mineral-oil alpha of Stachowiak & Batchelor Table 2.3 (heavy machine oil, alpha(100 degC)/alpha(30 degC)
   = 17.5/27.0, applied to Table 1's alpha; ILLUSTRATIVE: no ester alpha(T) could be read); tau0 constant in T;
   tau0 = 2.5 MPa (the lower part of the 2-20 MPa range quoted for EHL oils); Lambda(T) falling 0.2 %/K from 40 degC
   (ILLUSTRATIVE: no measured Lambda(T) of these oils was read); Lambda = 0.035 (lower end of the ester bracket);
   thermal off; the closed-form Maxwell build-up tau_f (1 - exp(-tel / tau_f)) the law had before it marched the
   Maxwell-Eyring equation.
2. the shape: slide-roll ratio of the maximum, mu(0.3)/mu_max and mu(1)/mu_max for the seed laws and "physical".

Run: PYTHONPATH=. .venv/bin/python tools/investigations/traction_thermal_sensitivity.py  (about a minute)
Nothing is fitted: every constant is the model's default or the named alternative.
"""

from __future__ import annotations

import numpy as np

import hsbearing
from hsbearing.models import hertz, traction
from hsbearing.models.traction import thermal as th

EP, RX, RY, W, U = 228.6e9, 3.87e-3, 0.124, 182.0, 16.3
ALPHA_T_RATIO = 17.5 / 27.0  # Stachowiak & Batchelor Table 2.3, heavy machine oil, alpha(100 degC)/alpha(30 degC)


def physical(oil, S, T, prm=None, alpha_scale=1.0):
    eta, alpha, beta, K, _ = hsbearing._oil_at(oil, T)
    c = hertz.point_contact(RX, RY, W, EP, 0.0, EP, 0.0)
    return th.contact_mu(S, W, U, EP, RX, float(c.ellipticity), float(c.a), T, eta, alpha * alpha_scale, beta, K, prm)


def seed(oil, S, T):
    return traction.get(oil)(np.asarray(S), W, U, T, EP, RX)


def eyring(oil, S, T):
    return hsbearing.traction_coefficient(oil, S, W, U, T, RX, RY, EP, law="eyring")


def main():
    T = 403.15
    P = th.PhysicalParameters()
    variants = [
        ("seed law (default)", lambda o: seed(o, 0.05, T)),
        ("eyring (isothermal, Barus, tau0 const)", lambda o: eyring(o, 0.05, T)),
        ("physical (thermal, Roelands, tau0 ~ T)", lambda o: physical(o, 0.05, T, P)),
        ("  Barus instead of Roelands", lambda o: physical(o, 0.05, T, P.with_(pressure_viscosity="barus"))),
        ("  alpha(T): x 0.648 (mineral-oil trend, illustrative)", lambda o: physical(o, 0.05, T, P, ALPHA_T_RATIO)),
        ("  tau0 constant in T", lambda o: physical(o, 0.05, T, P.with_(eyring_temperature="constant"))),
        ("  tau0 = 2.5 MPa", lambda o: physical(o, 0.05, T, P.with_(tau0=2.5e6))),
        ("  Lambda(T) -0.2 %/K from 40 degC (illustrative)", lambda o: physical(o, 0.05, T, P.with_(k_Lambda=-0.002))),
        ("  Lambda = 0.035", lambda o: physical(o, 0.05, T, P.with_(Lambda=0.035))),
        ("  thermal off", lambda o: physical(o, 0.05, T, P.with_(thermal=False))),
        ("  closed-form Maxwell build-up (the law before the march)", lambda o: physical(o, 0.05, T,
                                                                                   P.with_(buildup="closed"))),
    ]
    oils = list(traction.OILS)
    print("mu at S = 0.05, 130 degC, 182 N, 16.3 m/s (p0 1.28 GPa)\n")
    print("| choice | " + " | ".join(oils) + " | physical / seed |")
    print("|---|" + "---|" * (len(oils) + 1))
    base = {o: float(physical(o, 0.05, T, P)) for o in oils}
    sd = {o: float(seed(o, 0.05, T)) for o in oils}
    for name, f in variants:
        vals = [float(f(o)) for o in oils]
        ratio = " / ".join(f"{v / sd[o]:.2f}" for v, o in zip(vals, oils))
        print(f"| {name} | " + " | ".join(f"{v:.4f}" for v in vals) + f" | {ratio} |")
    print("\nshape: S of the maximum, mu(0.3)/mu_max, mu(1.0)/mu_max (S on 60 log points 1e-5 ... 1)\n")
    print("| oil | T [degC] | law | S at max | mu_max | mu(0.3)/mu_max | mu(1)/mu_max |")
    print("|---|---|---|---|---|---|---|")
    S = np.geomspace(1e-5, 1.0, 60)
    for o in oils:
        for Tc in (27.0, 130.0, 180.0):
            Tk = Tc + 273.15
            for name, mu in (("seed (default)", seed(o, S, Tk)), ("physical", physical(o, S, Tk, P))):
                mu = np.asarray(mu)
                i = int(np.argmax(mu))
                m03 = float(np.interp(np.log(0.3), np.log(S), mu))
                print(f"| {o} | {Tc:.0f} | {name} | {S[i]:.2g} | {mu[i]:.4f} | {m03 / mu[i]:.3f} | {mu[-1] / mu[i]:.3f} |")
    _ = base


if __name__ == "__main__":
    main()
