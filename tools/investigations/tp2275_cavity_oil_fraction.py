"""Issue 29 (independent review): is Parker's cavity oil "fraction" X = 1e5 W^0.37 / (n d_m^1.7) a fraction or a
percentage?  Physical evidence from the committed model (docs/power_loss.md, "The cavity oil fraction: fraction or
percent, decided").

(a) identifiability: the share of the computed heat that the oil carries through the drag, and the change of the
    total when Parker's constant 1e5 is multiplied by 2 (or 1/2), under each reading, for the reconstructed 35-mm
    bearing of NASA TP-2275 (tools/investigations/tp2275_power_loss.py; provenance there), against the +-3 % digitisation scatter
    of the heat data the constant was fitted to;
(b) mass balance X V_free = Q tau: the oil's mean residence time and transit speed, cage revolutions and ball passes
    during it, under each reading, with a low and a high estimate of the free volume;
(b') momentum: the power the drag spends on the oil (drag x oil share of rho_e) against m_dot v^2, the least power
    that accelerates the supplied oil once to the ball orbital speed;
(d) the same numbers for zhang2016 at 1 L/min (Parker X = 0.137) and the residence in cage revolutions over speed.

Usage: PYTHONPATH=. python tools/investigations/tp2275_cavity_oil_fraction.py
"""

from __future__ import annotations

import math

import tp2275_power_loss as tp  # same directory (sys.path[0] when run as a script)

from hsbearing.case import load_case, loads_case
from hsbearing.models.ball_bearing.drag import AIR_DENSITY, parker_cavity_oil_fraction
from hsbearing.systems.angular_contact.dynamics import build_model
from hsbearing.systems.angular_contact.rating import quasi_static_power_loss

#: largest plausible jet speed [m/s]: Bernoulli sqrt(2 dp / rho) at 0.5 MPa supply pressure and 920 kg/m^3
JET_SPEED_MAX = math.sqrt(2 * 0.5e6 / 920.0)


def free_volume(case) -> tuple[float, float]:
    """(low, high) estimate of the free volume of the bearing [m^3].

    low: the annulus between the inner-ring land (OD) and the outer-ring land (bore) over the ring width, minus the
    balls and the cage (its annulus minus the pockets, each a cylinder of the pocket diameter through the cage wall);
    the groove volumes outside that annulus are left out.  high: the annulus between the groove bottoms
    (d_m - D, d_m + D) over the ring width, nothing subtracted."""
    b, c = case.bearing, case.cage
    D, dm, B, Z = b.ball_diameter, b.pitch_diameter, b.width, b.ball_count
    ann = math.pi / 4 * (b.outer_land_diameter**2 - b.inner_land_diameter**2) * B
    balls = Z * math.pi / 6 * D**3
    t = 0.5 * (c.outside_diameter - c.bore_diameter)
    cage = math.pi / 4 * (c.outside_diameter**2 - c.bore_diameter**2) * c.width - Z * math.pi / 4 * c.pocket_diameter**2 * t
    return ann - balls - cage, math.pi * dm * D * B


def kinematics(case):
    """(ball orbital speed [m/s], cage speed [rev/s], inner-ring land surface speed [m/s]) at the quasi-static state."""
    m = build_model(case)
    wc = float(m.y0[m.layout.cage("phidot_c")])
    return m.info["drag_orbital_speed"], wc / (2 * math.pi), 0.5 * case.bearing.inner_land_diameter * abs(case.operating.inner_speed)


def residence(case, X, Q):
    """Mass balance X V = Q tau for both free-volume estimates: dict of tau [s], axial transit speed B / tau [m/s]."""
    Vl, Vh = free_volume(case)
    B = case.bearing.width
    return {"V_low": Vl, "V_high": Vh, "tau_low": X * Vl / Q, "tau_high": X * Vh / Q,
            "u_fast": B / (X * Vl / Q), "u_slow": 0.5 * B / (X * Vh / Q)}


def tp2275():
    rows = []
    print("(a) identifiability, TP-2275 35-mm reconstruction (oil 760 cm^3/min, 394 K); totals from quasi_static_power_loss")
    print(" reading    n [r/min]   X          total [W]  drag [W]  drag/total  oil part of drag/total   total(2K)/total-1  "
          "total(K/2)/total-1   measured")
    for n in sorted(tp.MEASURED):
        w = n * math.pi / 30
        Xf = parker_cavity_oil_fraction(tp.FLOW, w, 0.0465)
        for label, X in (("fraction", Xf), ("percent", Xf / 100)):
            def at(x, w=w):
                return quasi_static_power_loss(tp.case_for(f"oil_volume_fraction = {min(x, 1.0):.8g}").with_overrides(
                    **{"friction.cavity_losses": "off"}), w)  # drag only, as tabled in docs/power_loss.md
            r, r2, rh = at(X), at(2 * X), at(0.5 * X)
            rho_oil = 920.0
            share = X * rho_oil / (X * rho_oil + (1 - X) * AIR_DENSITY)
            d2, dh = r2["power_loss"] / r["power_loss"] - 1, rh["power_loss"] / r["power_loss"] - 1
            print(f" {label:9s} {n:9d} {X:10.4g} {r['power_loss']:10.1f} {r['drag']:9.1f} {r['drag'] / r['power_loss']:10.3f}"
                  f" {share * r['drag'] / r['power_loss']:22.4f} {d2:19.4f} {dh:19.4f} {tp.MEASURED[n]:10.0f}")
            rows.append(dict(reading=label, n=n, X=X, total=r["power_loss"], drag=r["drag"], share=share, d2=d2, dh=dh))
    print("\n(b) mass balance and (b') momentum, TP-2275: Q = 760 cm^3/min, B = 13 mm; jet speed at most "
          f"{JET_SPEED_MAX:.0f} m/s (0.5 MPa)")
    Q = tp.FLOW
    mdot = 920.0 * Q
    print(" reading    n [r/min]  tau [ms] (V low..high)  cage revs in tau  ball passes  axial speed [m/s] (B/tau_low .. B/2/tau_high)"
          "  v_orbit [m/s]  inner land [m/s]  P_oil [W]  mdot v^2 [W]  P_oil/(mdot v^2)")
    for r in rows:
        case = tp.case_for("").with_overrides(**{"operating.inner_speed": f"{r['n']} rpm"})
        v, fc, ui = kinematics(case)
        res = residence(case, r["X"], Q)
        Poil = r["share"] * r["drag"]
        print(f" {r['reading']:9s} {r['n']:9d}  {res['tau_low'] * 1e3:8.3g} .. {res['tau_high'] * 1e3:<8.3g}"
              f"  {res['tau_low'] * fc:6.3g} .. {res['tau_high'] * fc:<6.3g}  {res['tau_low'] * fc * 16:6.3g} .. {res['tau_high'] * fc * 16:<6.3g}"
              f"  {res['u_fast']:8.3g} .. {res['u_slow']:<8.3g}  {v:8.1f}  {ui:8.1f}  {Poil:9.1f}  {mdot * v * v:9.1f}  {Poil / (mdot * v * v):8.3g}")
        r.update(res, v=v, fc=fc, Poil=Poil, mdotv2=mdot * v * v)
    Vl, Vh = free_volume(tp.case_for(""))
    print(f" free volume: low {Vl * 1e6:.2f} cm^3, high {Vh * 1e6:.2f} cm^3")
    return rows


def zhang():
    print("\n(d) zhang2016 (7206-size, d_m 46 mm), oil jet 1 L/min, Parker X without the 0.05 override")
    base = load_case("zhang2016")
    text = base.raw_text_base.replace("oil_volume_fraction = 0.05", "# oil_volume_fraction: Parker")
    out = []
    for n in (6000, 14000, 30000):
        case = loads_case(text, **{"operating.inner_speed": f"{n} rpm"})
        Q = case.lubricant.oil_flow_rate
        Xf = parker_cavity_oil_fraction(Q, n * math.pi / 30, case.bearing.pitch_diameter)
        v, fc, ui = kinematics(case)
        for label, X in (("fraction", Xf), ("percent", Xf / 100)):
            res = residence(case, X, Q)
            print(f"  {label:9s} {n:6d} r/min: X {X:.4g}; V_free {res['V_low'] * 1e6:.2f}..{res['V_high'] * 1e6:.2f} cm^3; "
                  f"tau {res['tau_low'] * 1e3:.3g}..{res['tau_high'] * 1e3:.3g} ms = {res['tau_low'] * fc:.3g}..{res['tau_high'] * fc:.3g} "
                  f"cage revolutions; axial speed {res['u_fast']:.3g}..{res['u_slow']:.3g} m/s; v_orbit {v:.1f} m/s")
            out.append(dict(reading=label, n=n, X=X, v=v, fc=fc, **res))
    return out


if __name__ == "__main__":
    tp2275()
    zhang()


def drag_law_changes():
    """Old law (v^1.95, volume-weighted viscosity) against the committed one (v^2, droplet-in-air viscosity) at
    the quasi-static orbital speed: Re, C_D and the drag ratio new / old, for zhang2016 (X = 0.05), the TP-2275
    reconstruction (Parker X, fraction) and the 120-mm 7206-similar bearing (Parker X, 2 L/min)."""
    import issue29_speed_exponents as se

    from hsbearing.models.ball_bearing.drag import ball_drag_coefficient, mixture_viscosity

    cases = [("zhang2016", 14000, load_case("zhang2016"))]
    cases += [("TP-2275 35-mm", n, tp.case_for("")) for n in (28000, 72000)]
    cases += [("120-mm similar", n, se.scaled_case(150.0, 2.0)) for n in (8000, 25000)]
    print("\n(ii) drag law: old (v^1.95, mu_e = X mu_oil + (1 - X) mu_air) -> committed (v^2, droplets in air)")
    print("  case              n [r/min]   X       v [m/s]  mu_oil [Pa s]  mu_e old  mu_e new   Re old    Re new   C_D old  C_D new"
          "  v^0.05  drag new/old")
    rows = []
    for label, n, case in cases:
        m = build_model(case.with_overrides(**{"operating.inner_speed": f"{n} rpm"}))
        i = m.info
        X, v, eta, rho = i["cavity_oil_fraction"], i["drag_orbital_speed"], i["oil_viscosity"], i["drag_density"]
        D = case.bearing.ball_diameter
        mu_old = X * eta + (1 - X) * 2.1e-5
        mu_new = mixture_viscosity(eta, X)
        cd_old, re_old = ball_drag_coefficient(rho, mu_old, v, D)
        cd_new, re_new = ball_drag_coefficient(rho, mu_new, v, D)
        ratio = cd_new / cd_old * v**0.05
        print(f"  {label:17s} {n:9d} {X:7.4f} {v:8.2f} {eta:12.4g} {mu_old:9.3g} {mu_new:9.3g} {re_old:9.3g} {re_new:9.3g}"
              f" {cd_old:8.3f} {cd_new:8.3f} {v**0.05:7.3f} {ratio:10.3f}")
        rows.append((label, n, X, v, re_old, re_new, cd_old, cd_new, ratio))
    return rows


if __name__ == "__main__":
    drag_law_changes()
