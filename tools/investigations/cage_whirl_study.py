"""What drives the cage whirl of the Zhang et al. 2016 (zhang2016) dynamic model: term switches and sensitivity.

Produces the numbers and figures of docs/validation/cage_whirl.md.

    .venv/bin/python tools/investigations/cage_whirl_study.py [-j 2] [--only NAME ...] [--figures-only]

Each run is ``hsbearing.simulate`` of the bundled ``zhang2016`` case (oil 4109, 14000 r/min,
Fx = 1 kN, 130 degC) with ONE change.  Per run the script records (docs/validation/cage_whirl.md
explains each quantity):

- ``summary`` of :func:`hsbearing.analysis.orbit.summary` (whirl amplitude, whirl frequency ratio,
  mean cage slip ratio, classification);
- ``sigma``: exponential growth rate [1/s] of the cage-centre radius r(t) while it spirals out,
  ln(0.7/0.25) / (t(r = 0.7 c) - t(r = 0.25 c)), c = guide clearance (NaN if r never reaches 0.7 c);
- ``t_land``: first time r > 0.9 c [s];
- ``W_land``, ``W_pocket``: work [J] done on the cage's translation (y, z) by the guide-land film and
  by everything else except gravity (pocket normal + friction forces, obtained as m a - F_land - m g)
  from t = 0 to t(r = 0.9 c): which force pumps energy into the whirl;
- the instantaneous whirl ratio (phase rate of y + i z / cage speed) after the cage reached the land.

Analytic reference (no simulation): the linearised free cage on the short-bearing film
(:func:`free_cage_eigenvalue`).  Results go to runs/cage_whirl/results.json (git-ignored), the
figures to docs/validation/cage_whirl_figures/.
"""

from __future__ import annotations

import argparse
import json
import math
import os
import sys
import time
from concurrent.futures import ProcessPoolExecutor
from pathlib import Path

import numpy as np

from hsbearing.models.ball_bearing import kernel_io as kio
from hsbearing.systems.angular_contact.dynamics import simulate as ac_simulate

ROOT = Path(__file__).resolve().parents[2]
OUT = ROOT / "runs" / "cage_whirl"
FIG = ROOT / "docs" / "validation" / "cage_whirl_figures"

SHORT = 0.3  # s, mechanism runs (growth phase + a few whirl turns)
LONG = 0.6  # s, sensitivity runs (~40 Poincare points after the transient, as the seed-004 study)

#: name -> (group, description, case overrides, build_model options, duration [s])
RUNS = {
    # --- 1. mechanism: switch one term off at a time (0.3 s)
    "default": ("mechanism", "all terms (reference)", {}, {}, LONG),
    "no_gravity": ("mechanism", "gravity = 0", {}, {"gravity": 0.0}, SHORT),
    "no_pocket_friction": ("mechanism", "pocket friction mu_c = 0", {"friction.cage_coefficient": 0.0}, {}, SHORT),
    "no_drag": ("mechanism", "air-oil drag F_D off", {}, {"drag": False}, SHORT),
    "no_ehl_rolling": ("mechanism", "EHL rolling force F_R off", {}, {"ehl_rolling": False}, SHORT),
    "no_film": ("mechanism", "damping=False: no guide-land film, no pocket squeeze film, no contact damping",
                {}, {"damping": False}, SHORT),
    "no_traction": ("mechanism", "friction=False: no race traction, no pocket/land friction (balls not tied to the races)",
                    {}, {"friction": False}, SHORT),
    "no_traction_no_gravity": ("mechanism", "friction=False and gravity = 0 (clean linear growth)",
                               {}, {"friction": False, "gravity": 0.0}, SHORT),
    "pocket_film_min_x4": ("mechanism", "pocket squeeze-film floor h_min 0.5 -> 2 um (weaker pocket film damping)",
                           {}, {"pocket_film_min": 2e-6}, SHORT),
    "pocket_film_min_x0.25": ("mechanism", "pocket squeeze-film floor h_min 0.5 -> 0.125 um (stronger pocket film damping)",
                              {}, {"pocket_film_min": 0.125e-6}, SHORT),
    "tilt_frozen": ("mechanism", "cage diametral inertia x100 (1.13e-4 kg m^2): cage tilt practically frozen",
                    {"cage.diametral_inertia": "1.1331598802612628e-4 kg*m^2"}, {}, SHORT),
    "tilt_frozen_no_gravity": ("mechanism", "tilt frozen (I_d x100) and gravity = 0",
                               {"cage.diametral_inertia": "1.1331598802612628e-4 kg*m^2"}, {"gravity": 0.0}, SHORT),
    "contact_damping_0.02": ("mechanism", "ball/race contact damping ratio 0.1 -> 0.02", {}, {"contact_damping_ratio": 0.02}, SHORT),
    "land_eps_max_0.8": ("mechanism", "film saturation eps_max 0.95 -> 0.8", {}, {"land_eps_max": 0.8}, SHORT),
    # --- 2. sensitivity to the inputs the paper does not give (0.6 s)
    "guide_c0.1": ("guide clearance", "outer_land_diameter 52.2 mm (c = 0.1 mm)",
                   {"bearing.outer_land_diameter": "52.2 mm"}, {}, LONG),
    "guide_c0.4": ("guide clearance", "outer_land_diameter 52.8 mm (c = 0.4 mm)",
                   {"bearing.outer_land_diameter": "52.8 mm"}, {}, LONG),
    "guide_c0.125": ("guide clearance", "outer_land_diameter 52.25 mm (c = 0.125 mm)",
                     {"bearing.outer_land_diameter": "52.25 mm"}, {}, LONG),
    "guide_c0.15": ("guide clearance", "outer_land_diameter 52.3 mm (c = 0.15 mm)",
                    {"bearing.outer_land_diameter": "52.3 mm"}, {}, LONG),
    "guide_c0.1_no_gravity": ("guide clearance", "c = 0.1 mm and gravity = 0 (is the weight what holds it?)",
                              {"bearing.outer_land_diameter": "52.2 mm"}, {"gravity": 0.0}, LONG),
    "guide_c0.4_no_gravity": ("guide clearance", "c = 0.4 mm and gravity = 0 (clean linear growth for the theory check)",
                              {"bearing.outer_land_diameter": "52.8 mm"}, {"gravity": 0.0}, SHORT),
    "land_L5.5_no_gravity": ("land width", "land 5.5 mm and gravity = 0 (clean linear growth for the theory check)",
                             {}, {"land_length": 5.5e-3, "gravity": 0.0}, SHORT),
    "pocket_c0.025": ("pocket clearance", "pocket_diameter 9.575 mm (c_p = 0.025 mm)",
                      {"cage.pocket_diameter": "9.575 mm"}, {}, LONG),
    "pocket_c0.1": ("pocket clearance", "pocket_diameter 9.725 mm (c_p = 0.1 mm)",
                    {"cage.pocket_diameter": "9.725 mm"}, {}, LONG),
    "pocket_c0.25": ("pocket clearance", "pocket_diameter 10.025 mm (c_p = 0.25 mm > c)",
                     {"cage.pocket_diameter": "10.025 mm"}, {}, LONG),
    "mass_x0.5": ("cage mass", "cage density 570 kg/m^3 (m_c x 0.5)", {"materials.cage.density": "570 kg/m^3"}, {}, LONG),
    "mass_x2": ("cage mass", "cage density 2280 kg/m^3 (m_c x 2)", {"materials.cage.density": "2280 kg/m^3"}, {}, LONG),
    "land_L5.5": ("land width", "guide-land film length 5.5 mm (half the cage width)", {}, {"land_length": 5.5e-3}, LONG),
    "land_L3": ("land width", "guide-land film length 3 mm", {}, {"land_length": 3e-3}, LONG),
    "T80": ("oil temperature", "80 degC (higher viscosity)", {"lubricant.temperature": "80 degC"}, {}, LONG),
    "T180": ("oil temperature", "180 degC (lower viscosity)", {"lubricant.temperature": "180 degC"}, {}, LONG),
    "mu_c0.2": ("pocket friction", "mu_c = 0.2", {"friction.cage_coefficient": 0.2}, {}, LONG),
}


# ----------------------------------------------------------------------------------------------
# analytic reference: the free (unsupported) cage on a short-bearing guide-land film
# ----------------------------------------------------------------------------------------------
def film_coefficients(eta, R, L, c, omega):
    """Linearised short-bearing (Ocvirk, pi-film) coefficients at the centred position [N/m, N s/m].

    From the film forces of :func:`hsbearing.models.ball_bearing.cage.guide_land_forces` (San Andres, Modern
    Lubrication Theory, Notes 4-5, dynamic short-length bearing) at eps -> 0:
    F_r = -C e' (direct damping), F_t = +K_xy e - C e phi' with
    C = pi eta R L^3 / (2 c^3) and K_xy = C omega / 2 (cross-coupled stiffness);
    no direct stiffness (F_r ~ eps^2).  omega = cage + land speed [rad/s].
    """
    C = math.pi * eta * R * L**3 / (2.0 * c**3)
    return C, 0.5 * C * omega


def free_cage_eigenvalue(m, C, omega):
    """Unstable root s = sigma + i nu [1/s] of m s^2 + C s - i C omega / 2 = 0 (z = y + i z ~ e^{s t}).

    The linearised free cage (mass m [kg]) on the film of :func:`film_coefficients`: always one
    root with sigma > 0 (forward whirl); for m omega << C, sigma ~ m omega^2 / (4 C) and
    nu ~ omega / 2 (half-frequency whirl).
    """
    s = (-C + np.sqrt(C * C + 2j * m * C * omega)) / (2.0 * m)
    return complex(s)


def free_cage_spiral(m, eta, R, L, c, omega, eps_max=0.95, gravity=9.81, r0_over_c=0.1, t_end=3.0):
    """Nonlinear free cage on the kernel's film (no balls): growth rate [1/s] by the simulation's metric.

    Integrates m r'' = F_film(r, r') - m g e_y with :func:`hsbearing.models.ball_bearing.cage.guide_land_forces`
    and :func:`~hsbearing.models.ball_bearing.cage.smooth_eccentricity` (as in hsbearing.models.ball_bearing.kernel.global_rows,
    without the elastic rub) from r = r0 at rest; returns (sigma, whirl ratio at r = 0.7 c), sigma =
    ln(0.7/0.25) / (t(0.7 c) - t(0.25 c)) as for the full runs.
    """
    from scipy.integrate import solve_ivp

    from hsbearing.models.ball_bearing.cage import guide_land_forces, smooth_eccentricity

    def rhs(t, u):
        y, z, vy, vz = u
        e = math.hypot(y, z) + 1e-12 * c
        uy, uz = y / e, z / e
        eps = smooth_eccentricity(e / c, eps_max)
        Fr, Ft = guide_land_forces(eps, (y * vy + z * vz) / e / c, omega, (y * vz - z * vy) / e**2, eta, R, L, c)
        return [vy, vz, (Fr * uy - Ft * uz) / m - gravity, (Fr * uz + Ft * uy) / m]

    def hit(level):
        ev = lambda t, u: math.hypot(u[0], u[1]) - level * c  # noqa: E731
        ev.terminal = level > 0.5
        ev.direction = 1
        return ev

    sol = solve_ivp(rhs, (0.0, t_end), [r0_over_c * c, 0.0, 0.0, 0.0], method="LSODA", rtol=1e-8,
                    atol=1e-12 * c, events=[hit(0.25), hit(0.7)])
    t25, t70 = sol.t_events
    if len(t70) == 0 or len(t25) == 0:
        return float("nan"), float("nan")
    y, z, vy, vz = sol.y_events[1][0]
    whirl = (y * vz - z * vy) / (y * y + z * z)
    return math.log(0.7 / 0.25) / (t70[0] - t25[-1]), whirl / omega


# ----------------------------------------------------------------------------------------------
def _metrics(name, ds, case, model):
    from hsbearing.analysis.orbit import summary
    from hsbearing.models.geometry import derive

    g = derive(case)
    c = g.guide_clearance
    t = ds["time"].values
    y, z = ds["cage_center_y"].values, ds["cage_center_z"].values
    vy, vz = ds["cage_velocity_y"].values, ds["cage_velocity_z"].values
    r = np.hypot(y, z)
    w = ds["cage_speed"].values
    out = {"name": name, "summary": summary(ds, case), "guide_clearance": c, "pocket_clearance": g.pocket_clearance,
           "cage_mass": g.cage_mass, "oil_viscosity": float(model.info["oil_viscosity"])}

    def first(level):
        k = np.nonzero(r > level * c)[0]
        return float(t[k[0]]) if k.size else float("nan")

    t25, t70, t90 = first(0.25), first(0.7), first(0.9)
    # growth from the last crossing of 0.25 c before t70 (the start-up transient may exceed 0.25 c briefly)
    if np.isfinite(t70):
        k70 = np.searchsorted(t, t70)
        below = np.nonzero(r[:k70] < 0.25 * c)[0]
        t25 = float(t[below[-1]]) if below.size else t25
        out["sigma"] = math.log(0.7 / 0.25) / (t70 - t25) if t70 > t25 else float("nan")
    else:
        out["sigma"] = float("nan")
    out["t_land"] = t90
    out["r_final_over_c"] = float(np.sqrt(np.mean(r[t > t[-1] - 0.05] ** 2)) / c)
    # energy budget of the cage translation up to reaching the land
    m = g.cage_mass
    grav = float(model.info["options"]["gravity"])
    Fly = ds["cage_land_force_y"].values
    Flz = ds["cage_land_force_z"].values
    ay, az = np.gradient(vy, t), np.gradient(vz, t)
    Fpy = m * ay - Fly + m * grav  # the rest (pocket contacts and friction): m a = F_land + F_pocket - m g e_y
    Fpz = m * az - Flz
    tend = t90 if np.isfinite(t90) else t[-1]
    sel = t <= tend
    _tr = getattr(np, "trapezoid", None) or np.trapz
    out["W_land"] = float(_tr((Fly * vy + Flz * vz)[sel], t[sel]))
    out["W_pocket"] = float(_tr((Fpy * vy + Fpz * vz)[sel], t[sel]))
    out["W_gravity"] = float(_tr((-m * grav * vy)[sel], t[sel]))
    out["KE_end"] = float(0.5 * m * (vy[sel][-1] ** 2 + vz[sel][-1] ** 2))
    # instantaneous whirl ratio after the land was reached (phase rate / cage speed)
    if np.isfinite(t90):
        late = t > max(t90 + 0.02, t[-1] - 0.15)
        ph = np.unwrap(np.arctan2(z[late], y[late]))
        if late.sum() > 10:
            rate = np.polyfit(t[late], ph, 1)[0]
            out["whirl_ratio_on_land"] = float(rate / np.mean(w[late]))
        else:
            out["whirl_ratio_on_land"] = float("nan")
    else:
        out["whirl_ratio_on_land"] = float("nan")
    # ball/pocket and land forces after the land was reached
    late = t > t[-1] - 0.1
    Qc = ds["ball_cage_force"].values
    out["pocket_force_mean"] = float(np.mean(Qc[late]))
    out["pocket_force_max"] = float(np.max(Qc[late]))
    out["land_force_mean"] = float(np.mean(np.hypot(Fly, Flz)[late]))
    # decimated trace for the figures
    step = max(1, len(t) // 3000)
    np.savez_compressed(OUT / f"{name}.npz", t=t[::step], y=y[::step], z=z[::step], w=w[::step],
                        py=ds["poincare_y"].values if "poincare_y" in ds else np.array([]),
                        pvy=ds["poincare_vy"].values if "poincare_vy" in ds else np.array([]))
    return out


def run_one(name):
    import hsbearing
    from hsbearing.systems.angular_contact.dynamics import build_model

    group, desc, over, opts, dur = RUNS[name]
    case = hsbearing.load_case("zhang2016", **over)
    t0 = time.time()
    model = build_model(case, **opts)
    try:
        ds = ac_simulate(case, duration=dur, model=model)  # the engine: takes a prebuilt model
        status = "ok"
    except Exception as exc:  # SolverError: keep the partial trajectory
        ds = getattr(exc, "partial", None)
        status = f"failed: {exc}"
        if ds is None:
            return {"name": name, "group": group, "description": desc, "status": status}
    wall = time.time() - t0
    out = _metrics(name, ds, case, model)
    out.update(group=group, description=desc, status=status, wall=wall, duration=dur)
    print(f"{name}: {wall:.1f} s wall, sigma {out['sigma']:.1f} 1/s, r/c {out['r_final_over_c']:.3f}, "
          f"{out['summary']['classification']}", flush=True)
    return out


def model_defaults():
    from hsbearing.systems.angular_contact.dynamics import MODEL_DEFAULTS

    return dict(MODEL_DEFAULTS)


def analytic_table(results):
    """Free-cage film model of each run: predicted sigma and whirl ratio."""
    import hsbearing
    from hsbearing.systems.angular_contact.dynamics import build_model

    rows = {}
    for name, res in results.items():
        if "summary" not in res:
            continue
        group, desc, over, opts, dur = RUNS[name]
        if not opts.get("damping", True):
            continue
        case = hsbearing.load_case("zhang2016", **over)
        P = build_model(case, **opts).P
        eta, R, L, c, m = (kio.get(P, n) for n in ("eta_film", "R_land", "L_land", "c_land", "m_c"))
        omega = res["summary"]["mean_cage_speed"]
        C, Kxy = film_coefficients(eta, R, L, c, omega)
        s = free_cage_eigenvalue(m, C, omega)
        opt = dict(model_defaults(), **{k: v for k, v in opts.items() if k in model_defaults()})
        sig_nl, wr_nl = free_cage_spiral(m, eta, R, L, c, omega, opt["land_eps_max"], opt["gravity"])
        rows[name] = {"C": C, "K_xy": Kxy, "sigma_free": s.real, "whirl_ratio_free": s.imag / omega,
                      "sigma_free_nonlinear": sig_nl, "whirl_ratio_free_nonlinear": wr_nl}
    return rows


def growth_phase(name, res, lo=0.1, hi=0.5):
    """Whirl ratio and growth rate while the cage spirals from r = lo c to hi c (last such passage).

    From the decimated trace: phase rate of y + i z over the mean cage speed, and the slope of ln r.
    With the linearised film damping C_f (eps -> 0, :func:`film_coefficients`) and a ball-set
    'rotating damper' c_b turning with the cage (docs/validation/cage_whirl.md), the whirl turns at
    rho omega = (C_f omega/2 + c_b omega)/(C_f + c_b), so c_b = C_f (rho - 1/2)/(1 - rho).
    """
    f = OUT / f"{name}.npz"
    out = {"growth_whirl_ratio": float("nan"), "growth_sigma_early": float("nan"), "c_b_estimate": float("nan")}
    if not f.exists() or "guide_clearance" not in res:
        return out
    d = np.load(f)
    t, y, z, w = d["t"], d["y"], d["z"], d["w"]
    c = res["guide_clearance"]
    r = np.hypot(y, z)
    k_hi = np.nonzero(r > hi * c)[0]
    if not k_hi.size:
        return out
    k1 = k_hi[0]
    below = np.nonzero(r[:k1] < lo * c)[0]
    k0 = below[-1] if below.size else 0
    if k1 - k0 < 20:
        return out
    sl = slice(k0, k1 + 1)
    ph = np.unwrap(np.arctan2(z[sl], y[sl]))
    rho = np.polyfit(t[sl], ph, 1)[0] / np.mean(w[sl])
    out["growth_whirl_ratio"] = float(rho)
    out["growth_sigma_early"] = float(np.polyfit(t[sl], np.log(r[sl]), 1)[0])
    Cf = res.get("analytic", {}).get("C")
    if Cf is not None and 0.5 < rho < 1.0:
        out["c_b_estimate"] = float(Cf * (rho - 0.5) / (1.0 - rho))
    return out


def two_damper_fit(sigma, rho, omega, C_f):
    """Effective whirling mass M [kg] and ball-set rotating damping c_b [N s/m] from a measured growth.

    Model: M z'' = -C_f (z' - i (omega/2) z) - c_b (z' - i omega z) (complex z = y + i z): the film is a
    damper turning at omega/2 (its cross-coupled stiffness), the balls a damper turning with the cage.
    Its root s = sigma + i rho omega gives, exactly, A = nu (nu^2 + sigma^2)/(nu^2 - sigma^2) (nu = rho
    omega), c_b = C_f (omega/2 - A)/(A - omega), M = (C_f + c_b) sigma / (nu^2 - sigma^2).
    """
    nu = rho * omega
    A = nu * (nu * nu + sigma * sigma) / (nu * nu - sigma * sigma)
    c_b = C_f * (0.5 * omega - A) / (A - omega)
    return (C_f + c_b) * sigma / (nu * nu - sigma * sigma), c_b


def figures(results):
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    FIG.mkdir(parents=True, exist_ok=True)
    # 1. r(t)/c of the mechanism runs
    fig, ax = plt.subplots(figsize=(7, 4))
    for name, res in results.items():
        if res.get("group") != "mechanism" or not (OUT / f"{name}.npz").exists():
            continue
        d = np.load(OUT / f"{name}.npz")
        ax.plot(d["t"], np.hypot(d["y"], d["z"]) / res["guide_clearance"], lw=1, label=name)
    ax.set_xlim(0, SHORT)
    ax.set_xlabel("time [s]")
    ax.set_ylabel("cage-centre radius / guide clearance")
    ax.set_yscale("log")
    ax.set_ylim(1e-2, 1.5)
    ax.legend(fontsize=7, loc="lower right")
    ax.set_title("zhang2016 default: cage spiral-out with one term switched off")
    fig.tight_layout()
    fig.savefig(FIG / "mechanism_radius.png", dpi=90)
    plt.close(fig)
    # 2. sensitivity: r(t)/c per group, and the orbits
    groups = []
    for res in results.values():
        g = res.get("group")
        if g and g != "mechanism" and g not in groups:
            groups.append(g)
    fig, axs = plt.subplots(2, len(groups), figsize=(2.6 * len(groups), 5.2), squeeze=False)
    for j, g in enumerate(groups):
        names = ["default"] + [n for n, r in results.items() if r.get("group") == g]
        for n in names:
            if not (OUT / f"{n}.npz").exists():
                continue
            d = np.load(OUT / f"{n}.npz")
            c = results[n]["guide_clearance"]
            lab = "default" if n == "default" else n.split("_", 1)[-1]
            axs[0, j].plot(d["t"], np.hypot(d["y"], d["z"]) / c, lw=0.8, label=lab)
            k = d["t"] > d["t"][-1] - 0.2
            axs[1, j].plot(d["y"][k] * 1e3, d["z"][k] * 1e3, lw=0.5, label=lab)
        axs[0, j].set_title(g, fontsize=9)
        axs[0, j].set_ylim(0, 1.1)
        axs[0, j].set_xlabel("time [s]", fontsize=8)
        axs[0, j].legend(fontsize=6)
        axs[1, j].set_aspect("equal")
        axs[1, j].set_xlabel("D_Y [mm]", fontsize=8)
        axs[1, j].tick_params(labelsize=6)
        axs[0, j].tick_params(labelsize=6)
    axs[0, 0].set_ylabel("r / c", fontsize=8)
    axs[1, 0].set_ylabel("D_Z [mm] (last 0.2 s)", fontsize=8)
    fig.tight_layout()
    fig.savefig(FIG / "sensitivity.png", dpi=80)
    plt.close(fig)


def linear_modes(t_settle=0.04, n_snap=3, **opts):
    """Eigenvalues of the full model's Jacobian at the centred steady state (gravity off).

    Integrates the default case for ``t_settle`` with gravity = 0 (the cage stays centred to round-off),
    then evaluates the compiled Jacobian (``DynamicModel.jac``) at ``n_snap`` instants 1/(3 Z f_c)
    apart (the ball set rotates, so the linearisation is only approximately autonomous) and returns,
    per instant, the unstable eigenvalues (real part > 1 1/s) with their whirl ratio Im/omega_c and the
    share of the eigenvector (scaled by :attr:`DynamicModel.hscale`) in each state group.
    """
    import hsbearing
    from hsbearing.models.ball_bearing.state import BALL_STATES, CAGE_STATES
    from hsbearing.solvers.cvode import integrate
    from hsbearing.systems.angular_contact.dynamics import build_model

    case = hsbearing.load_case("zhang2016")
    model = build_model(case, gravity=0.0, **opts)
    L = model.layout
    Z = L.Z
    wc = float(model.y0[L.cage("phidot_c")])
    dt_snap = 2 * math.pi / wc / (3 * Z)
    t_eval = np.concatenate([[0.0, t_settle], t_settle + dt_snap * np.arange(1, n_snap)])
    res = integrate(model.rhs, model.y0, t_eval, rtol=1e-7, atol=1e-10, jacfn=model.jac)
    out = []
    names = [f"ball {n}" for n in BALL_STATES] + [f"cage {n}" for n in CAGE_STATES] + ["inner ring"]
    for k in range(1, len(res.t)):
        y = res.y[k]
        J = np.zeros((L.size, L.size))
        model.jac(res.t[k], y, np.zeros(L.size), J)
        lam, V = np.linalg.eig(J)
        wcage = float(y[L.cage("phidot_c")])
        rows = []
        for i in np.nonzero((lam.real > 1.0) & (lam.imag >= 0))[0]:
            v = np.abs(V[:, i]) / model.hscale  # back to physical units relative to typical scales
            v = np.abs(V[:, i]) * 0 + np.abs(V[:, i]) / np.maximum(model.hscale, 1e-30)
            share = {}
            for j, n in enumerate(BALL_STATES):
                share[f"ball {n}"] = float(np.sum(v[j * Z:(j + 1) * Z] ** 2))
            for j, n in enumerate(CAGE_STATES):
                share[f"cage {n}"] = float(v[L.cage0 + j] ** 2)
            share["inner ring"] = float(np.sum(v[L.ring0:] ** 2))
            tot = sum(share.values())
            share = {n: share[n] / tot for n in names if share[n] / tot > 0.02}
            rows.append({"sigma": float(lam[i].real), "whirl_ratio": float(lam[i].imag / wcage), "share": share})
        out.append({"t": float(res.t[k]), "cage_radius": float(math.hypot(y[L.cage("y_c")], y[L.cage("z_c")])),
                    "omega_c": wcage, "unstable": rows})
    return out


def coupled_cage_root(C_f, omega, m_c, m_b, Z, c_t):
    """Unstable root s = sigma + i nu [1/s] of the linear cage + film + dragged-ball model.

    z = D_Y + i D_Z ~ e^{st}.  The film is a damper turning at omega/2 (:func:`film_coefficients`); each
    ball stays on its pocket wall (preloaded by the land drag torque), so its position relative to the
    ball set (turning at omega) follows the cage, and it reacts with its inertia m_b and the race
    traction c_t [N s/m per ball] resisting its velocity relative to the ball set; summed over the
    ball set (the tangential projection averages to Z/2):

        m_c s^2 + C_f (s - i omega/2) + (Z/2) [m_b (s - i omega)^2 + c_t (s - i omega)] = 0.
    """
    a = m_c + 0.5 * Z * m_b
    b = C_f + 0.5 * Z * c_t - 1j * Z * m_b * omega
    cc = -0.5j * C_f * omega - 0.5 * Z * m_b * omega**2 - 0.5j * Z * c_t * omega
    r = np.roots([a, b, cc])
    return complex(r[np.argmax(r.real)])


def ball_force_regression(ds, c, dm, lo=0.02, hi=0.3, t_min=0.05):
    """Per-ball force modulations regressed on the ball's position s, velocity s' and acceleration s''
    relative to the ball set (s = r_p (theta_b - mean_j theta_b), its time mean removed), over the
    samples with lo c < r < hi c.  Returns {variable: (k [N/m], c [N s/m], m [kg], R^2)}."""
    t = ds["time"].values
    r = np.hypot(ds["cage_center_y"].values, ds["cage_center_z"].values)
    k = (r > lo * c) & (r < hi * c) & (t > t_min)
    th = ds["ball_orbit_angle"].values
    d = th - th.mean(1, keepdims=True)
    sp = 0.5 * dm * (d - d[k].mean(0))
    sd = np.gradient(sp, t, axis=0)
    sdd = np.gradient(sd, t, axis=0)
    A = np.column_stack([sp[k].ravel(), sd[k].ravel(), sdd[k].ravel()])
    out = {}
    for n in ("ball_cage_force", "ball_cage_friction", "inner_traction_rolling", "outer_traction_rolling",
              "ball_drag_force", "inner_rolling_force", "outer_rolling_force"):
        if n not in ds:
            continue
        X = ds[n].values
        X = (X - X.mean(1, keepdims=True))[k].ravel()
        coef = np.linalg.lstsq(A, X, rcond=None)[0]
        r2 = 1 - np.sum((X - A @ coef) ** 2) / max(np.sum((X - X.mean()) ** 2), 1e-300)
        out[n] = (float(coef[0]), float(coef[1]), float(coef[2]), float(r2))
    return out


def force_decomposition(duration=0.26, t_min=0.05, bands=((0.01, 0.05), (0.05, 0.2), (0.2, 0.5)), **opts):
    """Forces on the cage in the whirl frame during the clean linear growth (default case, gravity off).

    Runs the default case without gravity (the cage leaves the centre from round-off, a clean
    exponential) and, for r in [0.01, 0.05], [0.05, 0.2], [0.2, 0.5] c, returns the medians of the
    pocket force (m a - F_land) and of the land-film force per unit eccentricity, split into the radial
    (outward +) and tangential (forward +) components, with the whirl ratio and growth rate, and the
    rms ball-in-pocket offset r_p (theta_b - phi_c) against the rms cage eccentricity.
    """
    import hsbearing
    from hsbearing.models.geometry import derive

    case = hsbearing.load_case("zhang2016")
    g = derive(case)
    m, c = g.cage_mass, g.guide_clearance
    opts = dict({"gravity": 0.0}, **opts)
    grav = opts["gravity"]
    ds = ac_simulate(case, duration=duration, **opts)  # the engine: takes the model options
    t = ds["time"].values
    y, z = ds["cage_center_y"].values, ds["cage_center_z"].values
    vy, vz = ds["cage_velocity_y"].values, ds["cage_velocity_z"].values
    Fly, Flz = ds["cage_land_force_y"].values, ds["cage_land_force_z"].values
    Fpy, Fpz = m * np.gradient(vy, t) - Fly + m * grav, m * np.gradient(vz, t) - Flz
    r = np.hypot(y, z)
    r = np.where(r > 0, r, np.nan)
    uy, uz = y / r, z / r

    def rad(fy, fz):
        return fy * uy + fz * uz

    def tan(fy, fz):
        return -fy * uz + fz * uy

    w = ds["cage_speed"].values
    rows = []
    if opts["gravity"] == 0.0:
        reg = ball_force_regression(ds, c, g.dm)
        print("per-ball force modulation vs ball position s, velocity s', acceleration s'' relative to the ball set:")
        for n, (ks, cs, ms, r2) in reg.items():
            print(f"  {n:26s} {ks:8.1f} N/m  {cs:8.3f} N s/m  {ms * 1e3:7.3f} g   R^2 {r2:.3f}")
        c_t = -(reg["inner_traction_rolling"][1] + reg["outer_traction_rolling"][1])
        rows_theory = {}
        for lab, Cf in (("c 0.1 mm", 196.0), ("c 0.125 mm", 100.0), ("c 0.15 mm", 58.0), ("c 0.2 mm (default)", 24.5),
                        ("c 0.4 mm / L 5.5 mm", 3.06), ("L 3 mm", 0.497), ("no film", 0.0)):
            sr = coupled_cage_root(Cf, float(np.median(w)), m, g.ball_mass, g.Z, c_t)
            rows_theory[lab] = (Cf, sr.real, sr.imag / float(np.median(w)))
        (OUT / "ball_traction.json").write_text(json.dumps({"c_t": c_t, "omega_c": float(np.median(w)), "regression": reg}, indent=1))
        print(f"coupled linear theory with c_t = {c_t:.3f} N s/m per ball (race traction, regressed above):")
        for lab, (Cf, sg, rho) in rows_theory.items():
            print(f"  {lab:22s} C_f {Cf:7.2f} N s/m -> sigma {sg:6.1f} 1/s, whirl ratio {rho:.3f}")
    for lo, hi in bands:
        k = (r > lo * c) & (r < hi * c) & (t > t_min)
        if k.sum() < 20:
            continue
        nu = float(np.median(tan(vy, vz)[k] / r[k]))
        sig = float(np.median(rad(vy, vz)[k] / r[k]))
        th = ds["ball_orbit_angle"].values[k] - ds["cage_angle"].values[k][:, None]
        th = th - th.mean(0)
        rows.append(dict(
            r_lo=lo, r_hi=hi, whirl_ratio=nu / float(np.median(w[k])), sigma=sig, omega_c=float(np.median(w[k])),
            pocket_radial=float(np.median(rad(Fpy, Fpz)[k] / r[k])), pocket_tangential=float(np.median(tan(Fpy, Fpz)[k] / r[k])),
            land_radial=float(np.median(rad(Fly, Flz)[k] / r[k])), land_tangential=float(np.median(tan(Fly, Flz)[k] / r[k])),
            cage_inertia_radial=m * (sig**2 - nu**2), cage_inertia_tangential=m * 2 * sig * nu,
            ball_offset_rms=float(np.sqrt(np.mean(th**2))) * 0.5 * g.dm, cage_e_rms=float(np.sqrt(np.mean(r[k] ** 2))),
            pocket_force_mean=float(ds["ball_cage_force"].values[k].mean()),
            pocket_force_min=float(ds["ball_cage_force"].values[k].min())))
    return rows


def clean_growth_labels():
    return {"no_gravity": "c 0.2 mm, g = 0", "guide_c0.1_no_gravity": "c 0.1 mm, g = 0",
            "guide_c0.4_no_gravity": "c 0.4 mm, g = 0", "land_L5.5_no_gravity": "L 5.5 mm, g = 0"}


def clean_growth(name, results):
    """(sigma [1/s], whirl ratio, C_f [N s/m]) of the exponential growth of a gravity-free run, or None."""
    f = OUT / f"{name}.npz"
    if not f.exists() or name not in results or "analytic" not in results[name]:
        return None
    q = np.load(f)
    t, y, z, w = q["t"], q["y"], q["z"], q["w"]
    c = results[name]["guide_clearance"]
    r = np.hypot(y, z)
    k = (t > 0.2) if name == "guide_c0.1_no_gravity" else ((r > 0.01 * c) & (r < 0.3 * c) & (t > 0.02))
    if k.sum() < 20:
        return None
    sg = np.polyfit(t[k], np.log(r[k]), 1)[0]
    rho = np.polyfit(t[k], np.unwrap(np.arctan2(z[k], y[k])), 1)[0] / np.mean(w[k])
    return float(sg), float(rho), float(results[name]["analytic"]["C"])


def theory_figure(results):
    """Growth rate and whirl ratio vs film damping C_f: coupled linear theory and the simulated runs."""
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    import hsbearing
    from hsbearing.models.geometry import derive

    f = OUT / "ball_traction.json"
    if not f.exists():
        return
    bt = json.loads(f.read_text())
    g = derive(hsbearing.load_case("zhang2016"))
    w = bt["omega_c"]
    Cf = np.logspace(-1, 2.6, 200)
    roots = [coupled_cage_root(x, w, g.cage_mass, g.ball_mass, g.Z, bt["c_t"]) for x in Cf]
    free = [free_cage_eigenvalue(g.cage_mass, x, w) for x in Cf]
    fig, ax = plt.subplots(1, 2, figsize=(9, 3.6))
    ax[0].loglog(Cf, [r.real for r in roots], "k-", label="cage + film + dragged balls (theory)")
    ax[0].loglog(Cf, [r.real for r in free], "k:", label="cage on the film alone")
    ax[1].semilogx(Cf, [r.imag / w for r in roots], "k-")
    ax[1].semilogx(Cf, [r.imag / w for r in free], "k:")
    sims = {"default": "default", "guide_c0.15": "c 0.15 mm", "guide_c0.4": "c 0.4 mm",
            "mass_x0.5": "m_c x0.5", "mass_x2": "m_c x2", "pocket_c0.25": "c_p 0.25 mm"}
    for n, lab in sims.items():
        r = results.get(n)
        if not r or not np.isfinite(r.get("growth_whirl_ratio", np.nan)):
            continue
        C = r["analytic"]["C"]
        ax[0].loglog(C, r["growth_sigma_early"], "o", label=lab)
        ax[1].semilogx(C, r["growth_whirl_ratio"], "o")
    # clean exponentials without gravity (0.01-0.3 c; c = 0.1 mm: 0.2-0.6 s, it stays below 0.01 c)
    for n, lab in clean_growth_labels().items():
        q = clean_growth(n, results)
        if q is None:
            continue
        ax[0].loglog(q[2], q[0], "s", mfc="none", ms=8, label=lab)
        ax[1].semilogx(q[2], q[1], "s", mfc="none", ms=8)
    ax[0].set_xlabel("guide-land film damping C_f [N s/m]")
    ax[0].set_ylabel("growth rate sigma [1/s]")
    ax[1].set_xlabel("guide-land film damping C_f [N s/m]")
    ax[1].set_ylabel("whirl ratio nu / omega_c (growth phase)")
    ax[1].set_ylim(0.4, 1.0)
    ax[0].legend(fontsize=6)
    fig.suptitle(f"linear theory (c_t = {bt['c_t']:.2f} N s/m per ball from the traction regression) vs simulations", fontsize=8)
    fig.tight_layout()
    fig.savefig(FIG / "linear_theory.png", dpi=90)
    plt.close(fig)


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("-j", "--jobs", type=int, default=2)
    ap.add_argument("--only", nargs="*", help="run only these names (others are reused from results.json)")
    ap.add_argument("--figures-only", action="store_true")
    ap.add_argument("--decompose", action="store_true", help="force decomposition in the whirl frame (one 0.26 s run)")
    a = ap.parse_args(argv)
    OUT.mkdir(parents=True, exist_ok=True)
    store = OUT / "results.json"
    if a.decompose:
        variants = {"default, gravity 0": dict(),
                    "default (with gravity)": dict(gravity=9.81, t_min=0.01, bands=((0.25, 0.6),), duration=0.08),
                    "friction=False (with gravity)": dict(gravity=9.81, t_min=0.01, bands=((0.25, 0.6),), duration=0.09,
                                                          friction=False)}
        allrows = []
        for lab, kw in variants.items():
            for q in force_decomposition(**kw):
                q["variant"] = lab
                allrows.append(q)
        (OUT / "decomposition.json").write_text(json.dumps(allrows, indent=1))
        rows = allrows
        print("| run | r/c | whirl ratio | sigma [1/s] | pocket F_r/e, F_t/e [N/m] | land F_r/e, F_t/e [N/m] "
              "| m(sigma^2-nu^2), 2 m sigma nu [N/m] | ball-in-pocket offset / e (rms) | pocket force mean, min [N] "
              "| ball inertia (Z/2) m_b [(w-nu)^2-sigma^2], (Z/2) m_b 2 sigma (w-nu) [N/m] |")
        print("|---|---|---|---|---|---|---|---|---|---|")
        import hsbearing as _h
        from hsbearing.models.geometry import derive as _derive
        _g = _derive(_h.load_case("zhang2016"))
        mZ = 0.5 * _g.Z * _g.ball_mass
        for q in rows:
            nu, w, sg = q["whirl_ratio"] * q["omega_c"], q["omega_c"], q["sigma"]
            print(f"| {q['variant']} | {q['r_lo']}-{q['r_hi']} | {q['whirl_ratio']:.3f} | {q['sigma']:.1f} | {q['pocket_radial']:.0f}, "
                  f"{q['pocket_tangential']:.0f} | {q['land_radial']:.0f}, {q['land_tangential']:.0f} | "
                  f"{q['cage_inertia_radial']:.0f}, {q['cage_inertia_tangential']:.0f} | "
                  f"{q['ball_offset_rms'] / q['cage_e_rms']:.2f} | {q['pocket_force_mean']:.3f}, {q['pocket_force_min']:.3f} "
                  f"| {mZ * ((w - nu) ** 2 - sg**2):.0f}, {mZ * 2 * sg * (w - nu):.0f} |")
        return
    results = json.loads(store.read_text()) if store.exists() else {}
    if not a.figures_only:
        todo = a.only if a.only else [n for n in RUNS if n not in results]
        t0 = time.time()
        with ProcessPoolExecutor(max_workers=a.jobs) as ex:
            for res in ex.map(run_one, todo):
                results[res["name"]] = res
                store.write_text(json.dumps(results, indent=1, default=float))
        print(f"study wall {time.time() - t0:.0f} s", file=sys.stderr)
    an = analytic_table(results)
    for n, v in an.items():
        results[n]["analytic"] = v
    for n, r in results.items():
        r.update(growth_phase(n, r))
        Cf = r.get("analytic", {}).get("C")
        if Cf and np.isfinite(r.get("growth_whirl_ratio", np.nan)) and 0.5 < r["growth_whirl_ratio"] < 1:
            M, cb = two_damper_fit(r["growth_sigma_early"], r["growth_whirl_ratio"], r["summary"]["mean_cage_speed"], Cf)
            r["two_damper_M"], r["two_damper_c_b"] = M, cb
            print(f"two-damper fit {n}: M_eff = {M * 1e3:.2f} g (cage {r['cage_mass'] * 1e3:.2f} g), c_b = {cb:.2f} N s/m, "
                  f"C_f = {Cf:.3g} N s/m")
    store.write_text(json.dumps(results, indent=1, default=float))
    figures(results)
    theory_figure(results)
    # table
    print("| run | r/c (last 50 ms) | whirl ratio (FFT / on land) | sigma sim [1/s] | sigma free cage [1/s] | t(r>0.9c) [s] "
          "| sigma free cage, nonlinear [1/s] | W_land / W_pocket [uJ] | mean slip | class (conf.) "
          "| growth phase 0.1-0.5 c: whirl ratio, sigma [1/s] | C_f [N s/m] | c_b est. [N s/m] |")
    print("|---|---|---|---|---|---|---|---|---|---|---|---|---|")
    for n, r in results.items():
        if "summary" not in r:
            print(f"| {n} | {r.get('status')} |")
            continue
        s = r["summary"]
        sf = r.get("analytic", {}).get("sigma_free", float("nan"))
        snl = r.get("analytic", {}).get("sigma_free_nonlinear", float("nan"))
        print(f"| {n} | {r['r_final_over_c']:.3f} | {s['whirl_frequency_ratio']:.3f} / {r['whirl_ratio_on_land']:.3f} "
              f"| {r['sigma']:.1f} | {sf:.1f} | {r['t_land']:.3f} | {snl:.1f} | {r['W_land']*1e6:.2f} / {r['W_pocket']*1e6:.2f} "
              f"| {s['mean_cage_slip_ratio']:.4f} | {s['classification']} ({s['classification_confidence']:.2f}) "
              f"| {r['growth_whirl_ratio']:.3f}, {r['growth_sigma_early']:.1f} | {r.get('analytic', {}).get('C', float('nan')):.3g} "
              f"| {r['c_b_estimate']:.3g} |")


if __name__ == "__main__":
    os.environ.setdefault("OMP_NUM_THREADS", "1")
    main()
