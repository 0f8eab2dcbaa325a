"""Independent review of the steady thermal network (docs/thermal.md, "Review"): reference solutions that do not
use hsbearing.systems.angular_contact.thermal's element formulas, and the energy balance / fixed point over every case the network is used on.

    PYTHONPATH=. python tools/investigations/thermal_review.py disk          # von Karman rotating disk (momentum + energy BVP), Pr of the oils
    PYTHONPATH=. python tools/investigations/thermal_review.py conduction    # finite-volume half space (constriction) and ring section
    PYTHONPATH=. python tools/investigations/thermal_review.py fin           # finite-difference shaft fin, shaft Reynolds numbers
    PYTHONPATH=. python tools/investigations/thermal_review.py sweep OUT.json  # energy balance, convergence, uniqueness over all cases
    PYTHONPATH=. python tools/investigations/thermal_review.py blok          # Blok's heat partition at the contacts visited

Each section prints its numbers; docs/thermal.md quotes them.  The small solvers here are also in
tests/validation/test_thermal_reference.py (there with coarser grids so the default test tier stays fast).
"""

from __future__ import annotations

import json
import math
import sys

import numpy as np

sys.path.insert(0, "tests/helpers")


# ----------------------------------------------------------------------------- the cases
def cases():
    """(label, case) of every case the network is used on (docs/thermal.md, "Review")."""
    import tp2275_power_loss as tp
    import tp2275_speed_exponents as se

    from hsbearing.case import load_case

    out = []
    z = load_case("zhang2016")
    out.append(("zhang2016 amb 130C", z))
    out.append(("zhang2016 amb 20C", z.with_overrides(**{"thermal.ambient_temperature": "20 degC"})))
    for n in sorted(tp.MEASURED):
        c = tp.case_for("").with_overrides(**{"operating.inner_speed": f"{n} rpm"})
        out.append((f"TP-2275 {n} amb 394K", c.with_overrides(**{"thermal.ambient_temperature": "394 K"})))
        out.append((f"TP-2275 {n} amb 20C", c.with_overrides(**{"thermal.ambient_temperature": "20 degC"})))
    for dm, flow, rpms in ((53.5, 1.0, (20000, 45000, 72000)), (150.0, 2.0, (8000, 16000, 25000))):
        base = se.scaled_case(dm, flow)
        for n in rpms:
            c = base.with_overrides(**{"operating.inner_speed": f"{n} rpm"})
            out.append((f"similar dm{dm:g} {n}", c))
            out.append((f"similar dm{dm:g} {n} amb 20C", c.with_overrides(**{"thermal.ambient_temperature": "20 degC"})))
    return out


def node_balance(ds):
    """Largest |heat in - net outflow| of a node over the heat generated (each node's own balance)."""
    nodes = [str(n) for n in ds.node.values]
    net = dict(zip(nodes, ds.node_heat_input.values.astype(float)))
    for a, b, q in zip(ds.link_from.values, ds.link_to.values, ds.link_heat_flow.values):
        if str(a) in net:
            net[str(a)] -= float(q)
        if str(b) in net:
            net[str(b)] += float(q)
    return max(abs(v) for v in net.values()) / float(ds.heat_generated)


def sweep(out_path, starts=True):
    from hsbearing.systems.angular_contact.thermal import NODES, thermal_equilibrium

    rows = []
    for label, case in cases():
        try:
            ds = thermal_equilibrium(case)
        except Exception as exc:  # noqa: BLE001
            print(f"{label}: FAILED {type(exc).__name__}: {exc}", flush=True)
            rows.append({"label": label, "error": f"{type(exc).__name__}: {exc}"})
            continue
        T = {n: float(v) for n, v in zip(NODES, ds.node_temperature.values)}
        r = {"label": label, "T": T, "T_lub": float(ds.lubricant_temperature), "P": float(ds.heat_generated),
             "q_oil": float(ds.heat_removed_by_oil), "q_air": float(ds.heat_removed_by_conduction),
             "balance": float(ds.heat_balance_error), "node_balance": node_balance(ds),
             "iterations": int(ds.fixed_point_iterations), "converged": int(ds.attrs["converged"]),
             "T_in": float(ds.oil_inlet_temperature), "T_amb": float(ds.ambient_temperature),
             "h_shaft": float(ds.attrs["network_h_shaft"])}
        if starts:  # uniqueness: other starting lubricant and node temperatures
            alt = []
            for dT in (-60.0, +40.0):
                try:
                    d2 = thermal_equilibrium(case, T_start=r["T_in"] + dT, x0_nodes=[r["T_in"] + dT] * len(NODES))
                except Exception as exc:  # noqa: BLE001
                    alt.append({"dT_start": dT, "error": f"{type(exc).__name__}: {exc}", "iterations": -1,
                                "max_dT_nodes": float("nan")})
                    continue
                alt.append({"dT_start": dT, "T_lub": float(d2.lubricant_temperature),
                            "iterations": int(d2.fixed_point_iterations), "converged": int(d2.attrs["converged"]),
                            "max_dT_nodes": float(np.max(np.abs(d2.node_temperature.values - ds.node_temperature.values)))})
            r["starts"] = alt
        rows.append(r)
        print(f"{label:28s} it {r['iterations']:2d} conv {r['converged']} P {r['P']:8.2f} W  oil {r['q_oil']:8.2f} "
              f"air {r['q_air']:8.2f}  bal {r['balance']:+.1e} node {r['node_balance']:.1e}  T_lub {r['T_lub'] - 273.15:7.2f}C "
              + " ".join(f"{n[:5]} {T[n] - 273.15:7.2f}" for n in NODES)
              + ("  starts " + ", ".join(f"{a['dT_start']:+.0f}K: it {a['iterations']} dT {a['max_dT_nodes']:.1e}"
                                         for a in r.get("starts", [])) if starts else ""), flush=True)
    with open(out_path + ".tmp", "w") as f:
        json.dump(rows, f, indent=1)
    import os

    os.replace(out_path + ".tmp", out_path)
    return rows


# ----------------------------------------------------------------------------- 1. ring / ball / cage to oil
def disk():
    """Pr of the oils over 40-220 degC (the project's viscosity model, c_p 2000 J/(kg K), k of Table 1), the rotating
    disk's -theta'(0) at those Pr, and the ratio of harris_oil_h to it for n read in r/min, rad/s, rev/s."""
    import thermal_reference as ref

    from hsbearing.case import load_case
    from hsbearing.models.traction import OILS
    from hsbearing.systems.angular_contact.thermal import _viscosity, harris_oil_h

    z = load_case("zhang2016")
    prs = []
    print("Prandtl numbers (walther viscosity x zhang2016 density 960 kg/m^3, c_p 2000 J/(kg K), k Table 1):")
    for oil in ("4109", "4106", "4050"):
        c = z.with_overrides(**{"lubricant.oil": oil})
        row = []
        for TC in (40, 70, 100, 130, 160, 190, 220):
            eta = _viscosity(c, TC + 273.15)
            Pr = eta * 2000.0 / OILS[oil].K
            prs.append(Pr)
            row.append(f"{TC} C {Pr:5.0f}")
        print(f"  {oil}: " + ", ".join(row))
    grid = np.array([min(prs), 20, 30, 60, 100, 200, 400, max(prs)])
    r = ref.rotating_disk(grid)
    print(f"von Karman: F'(0) {r['F0p']:.5f}, G'(0) {r['G0p']:.5f}, H(inf) {r['Hinf']:.5f}; large-Pr limit "
          f"{(r['F0p'] / 3) ** (1 / 3) / math.gamma(4 / 3):.5f} Pr^(1/3)")
    nu, k, omega, gamma = 2e-6, 0.0966, 1466.0, 0.1877
    print("  Pr      -theta'(0)  BVP - quadrature   C/Pr^(1/3) | harris / disk at the relative speed (inner ring), n in:"
          "  r/min   rad/s   rev/s")
    for Pr, c, q in zip(grid, r["nu_bvp"], r["nu_quad"]):
        h_disk = c * k * math.sqrt(0.5 * omega * (1 + gamma) / nu)
        rpm = harris_oil_h(omega, nu, k, Pr, 1 + gamma) / h_disk
        rads = harris_oil_h(omega * math.pi / 30, nu, k, Pr, 1 + gamma) / h_disk
        revs = harris_oil_h(omega / 60, nu, k, Pr, 1 + gamma) / h_disk
        print(f"  {Pr:6.1f}  {c:9.5f}  {c - q:+.1e}          {c / Pr ** (1 / 3):.4f}   |"
              f"                                              {rpm:.3f}   {rads:.3f}   {revs:.3f}")


# ----------------------------------------------------------------------------- 2. conduction
def conduction():
    import thermal_reference as ref

    from hsbearing.case import load_case
    from hsbearing.systems.angular_contact.thermal import (
        _geometry,
        constriction_resistance,
        cylinder_resistance,
        heat_by_body,
    )

    print("half-space disk, finite volumes (R k a; exact 1/4 isothermal, 8/(3 pi^2) = 0.27019 isoflux):")
    for mode, exact in (("isothermal", 0.25), ("isoflux", 8 / (3 * math.pi**2))):
        for n in (20, 40, 80):
            R = ref.halfspace_disk_fv(mode, n)
            print(f"  {mode:10s} n {n:3d}: {R:.5f} ({R / exact - 1:+.2%})")
    print("elliptic contact, boundary elements (R k a) vs K(m)/(2 pi) and the circle of equal area 1/(4 sqrt(b/a)):")
    for ratio in (1.0, 3.0, 5.8, 9.2):
        a, b = 1.0, 1.0 / ratio
        Rs = [ref.ellipse_bem(a, b, n) for n in ((80, 160) if ratio > 5 else (40, 80) if ratio > 1 else (30, 60))]
        Rx = 2 * Rs[1] - Rs[0]
        ex, circ = constriction_resistance(a, 1.0, b), 1 / (4 * math.sqrt(a * b))
        print(f"  a/b {ratio:4.1f}: BEM {Rs[0]:.4f}, {Rs[1]:.4f} -> {Rx:.4f}; K(m)/(2 pi a) {ex:.4f} ({ex / Rx - 1:+.1%}); "
              f"circle {circ:.4f} ({circ / Rx - 1:+.1%})")
    case = load_case("zhang2016")
    g = _geometry(case)
    src, heat, qs = heat_by_body(case)
    ks = case.thermal.steel_thermal_conductivity
    for side, (r1, r2), at in (("inner", (g["d"] / 2, (g["dm"] - g["D"]) / 2), "outer"),
                               ("outer", ((g["dm"] + g["D"]) / 2, g["Do"] / 2), "inner")):
        a = float(qs[f"{side}_contact_semimajor"][0])
        b = float(qs[f"{side}_contact_semiminor"][0])
        h = float(qs[f"{side}_film_thickness_central"][0])
        Rln = cylinder_resistance(r1, r2, g["B"], ks)
        Ru = ref.ring_fv(r1, r2, g["B"], 1.0001 * g["B"], ks, 20, 80, at)[0]
        Rb = [ref.ring_fv(r1, r2, g["B"], 2 * a, ks, 20 * m, 80 * m, at)[0] for m in (1, 2, 4)]
        print(f"zhang2016 {side} ring: ln(r2/r1)/(2 pi k B) {Rln:.5f} K/W, FV uniform race {Ru:.5f} ({Ru / Rln - 1:+.1e}); "
              f"race band 2a = {2 * a * 1e3:.2f} mm: band mean {', '.join(f'{x:.4f}' for x in Rb)} K/W (grids x1, x2, x4)")
        Rc_old = 2 * constriction_resistance(math.sqrt(a * b), ks)
        Rc_new = 2 * constriction_resistance(a, ks, b)
        Rf = h / (case.thermal.oil_thermal_conductivity or 0.0966) / (math.pi * a * b)
        print(f"  contact a {a * 1e3:.3f} mm b {b * 1e3:.4f} mm (a/b {a / b:.1f}), h_c {h * 1e9:.0f} nm: constriction "
              f"(2 bodies) circle {Rc_old:.2f} K/W -> ellipse {Rc_new:.2f} K/W; film {Rf:.2f} K/W; per contact "
              f"{1 / (Rc_old + Rf):.4f} -> {1 / (Rc_new + Rf):.4f} W/K")


# ----------------------------------------------------------------------------- 3. shaft fin
def fin():
    import thermal_reference as ref

    from hsbearing.systems.angular_contact.thermal import AIR_NU, fin_conductance, rotating_cylinder_h

    for h, L in ((194.0, 0.08), (40.0, 0.3), (900.0, 0.05)):
        G, Gfd = fin_conductance(h, 0.03, 42.0, L), ref.fin_fd(h, 0.03, 42.0, L, 400)
        print(f"fin h {h} d 30 mm L {L} m: tanh form {G:.6f} W/K, FD {Gfd:.6f} ({G / Gfd - 1:+.1e})")
    print("shaft Reynolds numbers omega d^2 / nu_air (correlation valid Re < 4.3e5), Biot h d / (4 k):")
    for label, case in cases():
        if "amb 20C" in label:
            continue
        d, w = case.bearing.bore_diameter, case.operating.inner_speed
        Re = w * d * d / AIR_NU
        h = rotating_cylinder_h(w, d)
        print(f"  {label:24s} d {d * 1e3:6.1f} mm  n {w * 30 / math.pi:7.0f} r/min  Re {Re:9.3g} "
              f"{'OUT OF RANGE' if Re > 4.3e5 else 'in range':12s} h {h:6.0f} W/(m^2 K)  Bi {h * d / 4 / 42:.3f}")


# ----------------------------------------------------------------------------- 5. heat partition
def blok(sweep_json="/tmp/thermrev/new_sweep.json"):
    """Blok's partition of each race contact's heat between ring and ball, at the equilibrium lubricant temperature
    of each case (from a sweep's JSON if given, else the inlet), and the network temperatures with it.

    Two bodies of the same steel under a moving source at high Peclet number (Pe = U b / (2 kappa) >> 1): equal mean
    flash temperatures give the fraction to body 1 sqrt(u_1) / (sqrt(u_1) + sqrt(u_2)), u the surfaces' speeds past
    the contact, U (1 +- S/2) with S the slide-roll ratio at the contact centre (Blok 1937; Jaeger 1942).  The
    spin adds a sliding speed omega_s y across the contact, at most (spin/roll) 2 a / D of U at its edge."""
    from hsbearing.models.ball_bearing.kernel import AUX_INDEX
    from hsbearing.systems.angular_contact.dynamics import build_model
    from hsbearing.systems.angular_contact.thermal import NODES, bearing_network, heat_by_body, solve_network

    try:
        eq = {r["label"]: r for r in json.load(open(sweep_json)) if "T_lub" in r}
    except OSError:
        eq = {}
    kappa = 42.0 / (7800.0 * 460.0)  # AISI 52100 diffusivity [m^2/s]
    for label, case in cases():
        if "amb 20C" in label:
            continue
        T = eq.get(label, {}).get("T_lub")
        c = case if T is None else case.with_overrides(**{"lubricant.temperature": f"{T} K"})
        try:
            m = build_model(c)
        except Exception as exc:  # noqa: BLE001
            print(f"{label}: {type(exc).__name__}: {exc}")
            continue
        aux, _ = m.outputs(m.y0)
        src, heat, qs = heat_by_body(c)
        D = c.bearing.ball_diameter
        line = [f"{label:24s}"]
        frac = {}
        for side, sfx in (("inner", "i"), ("outer", "o")):
            U = aux[:, AUX_INDEX[f"U_{sfx}"]]
            S = aux[:, AUX_INDEX[f"S_{sfx}"]]
            b = qs[f"{side}_contact_semiminor"].values
            a = qs[f"{side}_contact_semimajor"].values
            sr = np.abs(aux[:, AUX_INDEX[f"spin_roll_{sfx}"]]) * 2 * a / D
            Pe = np.abs(U) * b / (2 * kappa)
            s_max = float(np.max(np.abs(S)))
            f_hi = math.sqrt(1 + s_max / 2) / (math.sqrt(1 + s_max / 2) + math.sqrt(1 - s_max / 2))
            frac[side] = f_hi
            line.append(f"{side}: Pe {float(np.min(Pe)):6.0f}-{float(np.max(Pe)):6.0f} |S| <= {s_max:.4f} spin slip <= "
                        f"{float(np.max(sr)):.3f}  ring fraction {1 - f_hi:.4f}-{f_hi:.4f}")
        # the temperatures with the most uneven split either way
        P_in = src["race_traction_inner"] + src["ehl_rolling_inner"] + src["contact_damping_inner"]
        P_out = src["race_traction_outer"] + src["ehl_rolling_outer"] + src["contact_damping_outer"]
        T_in = case.thermal.oil_inlet_temperature or case.lubricant.temperature
        net0, _ = bearing_network(c, heat, qs, T_in)
        T0, _ = solve_network(net0)
        worst = 0.0
        for sign in (+1, -1):
            h2 = dict(heat)
            for side, P, node in (("inner", P_in, "inner_ring"), ("outer", P_out, "outer_ring")):
                df = sign * (frac[side] - 0.5) * P
                h2[node] += df
                h2["balls"] -= df
            net2, _ = bearing_network(c, h2, qs, T_in)
            T2, _ = solve_network(net2)
            worst = max(worst, max(abs(T2[n] - T0[n]) for n in NODES))
        line.append(f"largest node temperature change {worst:.3f} K")
        print("  ".join(line), flush=True)


# ----------------------------------------------------------------------------- effect of each change
def stages():
    """The effect of each change of the review, applied one after the other from the former network (the former
    laws restored by patching hsbearing.systems.angular_contact.thermal): zhang2016 and the TP-2275 reconstruction (ambient 394 K)."""
    import tp2275_power_loss as tp

    import hsbearing.systems.angular_contact.thermal as th

    new_h, new_c, new_v, new_step = th.harris_oil_h, th.constriction_resistance, th._viscosity, th.MAX_FIXED_POINT_STEP

    def old_viscosity(case, T):
        lub = case.lubricant
        if lub.kinematic_viscosity is not None:
            return lub.kinematic_viscosity * lub.density
        return new_v(case, T)

    def patched(case, rpm, signs, balls, ellipse, visc, step):
        g = th._geometry(case)
        gm = g["gamma"]
        fb = 2.0 * th.body_oil_speeds(1.0, gm, g["dm"], g["D"])["balls"]
        remap = {}
        if not signs:
            remap.update({1.0 + gm: 1.0 - gm, 1.0 - gm: 1.0 + gm})
        if not balls:
            remap[fb] = 1.0

        def h(omega, nu, k, Pr, factor=1.0):
            f = remap.get(factor, factor)
            return new_h(omega if rpm else omega * math.pi / 30.0, nu, k, Pr, f)

        th.harris_oil_h = h
        th.constriction_resistance = new_c if ellipse else (lambda a, k, b=None: 1.0 / (4.0 * k * math.sqrt(a * (b or a))))
        th._viscosity = new_v if visc else old_viscosity
        th.MAX_FIXED_POINT_STEP = new_step if step else 1e9

    flags = ["rpm", "signs", "balls", "ellipse", "visc", "step"]
    names = ["former network", "+ n in r/min", "+ (1 +- gamma) to the relative speeds", "+ balls at their rolling speed",
             "+ elliptic constriction", "+ lubricant-file viscosity at T_oil", "+ bounded fixed-point step (= this review)"]
    tp_cases = [(n, tp.case_for("").with_overrides(**{"operating.inner_speed": f"{n} rpm",
                                                        "thermal.ambient_temperature": "394 K"})) for n in sorted(tp.MEASURED)]
    from hsbearing.case import load_case

    z = load_case("zhang2016")
    try:
        for i, name in enumerate(names):
            on = dict.fromkeys(flags, False)
            on.update({f: True for f in flags[:i]})
            patched(z, **on)
            ds = th.thermal_equilibrium(z)
            T = {n: float(v) - 273.15 for n, v in zip(th.NODES, ds.node_temperature.values)}
            out = []
            for _n, c in tp_cases:
                patched(c, **on)
                d2 = th.thermal_equilibrium(c)
                out.append(f"{float(d2.outer_ring_temperature):.1f}")
            print(f"{name:44s} zhang2016: it {int(ds.fixed_point_iterations)} P {float(ds.heat_generated):.2f} W "
                  f"T_lub {float(ds.lubricant_temperature) - 273.15:.2f} C; "
                  + " ".join(f"{n[:5]} {v:.2f}" for n, v in T.items())
                  + f" | TP-2275 outer ring [K] 28/48/64/72 krpm: {' '.join(out)}", flush=True)
    finally:
        th.harris_oil_h, th.constriction_resistance, th._viscosity, th.MAX_FIXED_POINT_STEP = new_h, new_c, new_v, new_step


if __name__ == "__main__":
    what = sys.argv[1] if len(sys.argv) > 1 else "disk"
    if what == "sweep":
        sweep(sys.argv[2], starts="--no-starts" not in sys.argv)
    else:
        globals()[what]()
