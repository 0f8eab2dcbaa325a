"""Synthetic signals and cage runs whose answer is known (logistic map, forced Duffing oscillator, a cage whirling on a
prescribed orbit: one period, k loops, a torus, chaos, noise), shared by the analysis, plotting and CLI tests."""

from __future__ import annotations

import math

import numpy as np
from scipy.integrate import solve_ivp

import hsbearing
from hsbearing.analysis import theoretical_cage_speed
from hsbearing.models.geometry import derive
from hsbearing.results import make_dataset, standard_attrs


def logistic_points(r, n=400, x0=0.3, skip=200):
    x = np.empty(n + skip + 1)
    x[0] = x0
    for i in range(n + skip):
        x[i + 1] = r * x[i] * (1 - x[i])
    x = x[skip:]
    return np.column_stack([x[:-1], x[1:]])


def duffing(g, n_periods=260, spp=64, skip=60):
    """Forced Duffing oscillator (Jordan & Smith Ch. 13 parameters), sampled spp times per forcing period."""
    d, w = 0.3, 1.2
    T = 2 * np.pi / w
    t = np.arange(0, (n_periods + skip) * spp + 1) * (T / spp)
    sol = solve_ivp(lambda t, y: [y[1], -d * y[1] + y[0] - y[0] ** 3 + g * np.cos(w * t)], (0, t[-1]), [1.0, 0.0],
                    t_eval=t, rtol=1e-9, atol=1e-11, method="DOP853")
    return sol.t, sol.y, T, spp, skip


def cage_run(kind, case=None, n_rev=90, spr=200, R=20e-6, r2=6e-6, slip=0.03, k=4, noise=0.0,
             with_angle=True, with_velocity=True, seed=0, transient=True):
    """A synthetic dynamic-run Dataset: cage at constant speed, cage centre on a prescribed orbit.

    kind: "period" (synchronous circular whirl), "k" (whirl + sub-harmonic at 1/k of the cage rate),
    "quasi" (whirl + incommensurate component, rotation number (sqrt 5 - 1)/2), "chaos" (cage centre
    driven by the chaotic Duffing solution, one forcing period per cage revolution).
    """
    case = case or hsbearing.load_case("zhang2016")
    g = derive(case)
    wth = theoretical_cage_speed(g, case.operating.inner_speed, case.operating.outer_speed)
    wc = (1 - slip) * wth
    Tc = 2 * np.pi / wc
    t = np.arange(n_rev * spr + 1) * (Tc / spr)
    ph = wc * t + 0.3
    if kind == "period":
        y, z = R * np.cos(ph), R * np.sin(ph)
        vy, vz = -R * wc * np.sin(ph), R * wc * np.cos(ph)
    elif kind in ("k", "quasi"):
        rho = 1.0 / k if kind == "k" else (math.sqrt(5) - 1) / 2
        y = R * np.cos(ph) + r2 * np.cos(rho * wc * t + 0.5)
        z = R * np.sin(ph) + r2 * np.sin(rho * wc * t + 0.5)
        vy = -R * wc * np.sin(ph) - r2 * rho * wc * np.sin(rho * wc * t + 0.5)
        vz = R * wc * np.cos(ph) + r2 * rho * wc * np.cos(rho * wc * t + 0.5)
    elif kind == "chaos":
        td, yd, T, spp, skip = duffing(0.5, n_periods=n_rev, spp=spr, skip=40)
        x, v = yd[0, skip * spp:], yd[1, skip * spp:]
        x, v = x[: t.size], v[: t.size]
        # forcing phase 1.2 t_d = cage angle: t_d = cage angle / 1.2
        s = R / 1.5
        y, z = s * x, s * v
        vy, vz = s * v * (wc / 1.2), s * (-0.3 * v + x - x**3 + 0.5 * np.cos(1.2 * td[skip * spp:][: t.size])) * (wc / 1.2)
        ph = wc * t  # the Duffing forcing phase is 0 at t = 0
    else:
        raise ValueError(kind)
    if transient:  # a decaying start-up transient (over the first ~20 % of the run)
        env = 8e-6 * np.exp(-t / (0.04 * t[-1]))
        y = y + env * np.cos(3.7 * wc * t)
        vy = vy + env * (-3.7 * wc * np.sin(3.7 * wc * t) - np.cos(3.7 * wc * t) / (0.04 * t[-1]))
    if noise:
        rng = np.random.default_rng(seed)
        y = y + noise * R * rng.standard_normal(t.size)
        z = z + noise * R * rng.standard_normal(t.size)
        vy = vy + noise * R * wc * rng.standard_normal(t.size)
    data = {"cage_speed": np.full(t.size, wc), "cage_center_y": y, "cage_center_z": z}
    ds = make_dataset(data, coords={"time": t}, attrs=standard_attrs(case, model="synthetic"))
    extra = {}
    if with_velocity:
        extra["cage_velocity_y"] = ("time", vy, {"units": "m/s"})
        extra["cage_velocity_z"] = ("time", vz, {"units": "m/s"})
    if with_angle:
        extra["cage_angle"] = ("time", ph - ph[0], {"units": "rad"})
    return ds.assign(extra)


# ----------------------------------------------------------------------------- slip ratio
