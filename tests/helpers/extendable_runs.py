"""A synthetic dynamic run that can be continued, for the tests of the extension of undetermined map, sweep and
study points (hsbearing.systems.angular_contact.extend through hsbearing.workflows.sweeps.points.extend_point).

The cage centre whirls at 0.97 x the cage speed on a radius r(t) chosen by the axial load:

- 500 N: a steady circle (80 um): "1 period" at once, never extended;
- 1000 N: a logistic growth 2 -> 100 um at 12/s (saturates by ~0.35 s): "undetermined (growing)" at 0.3 s,
  "1 period" on its saturated orbit once extended;
- 2000 N: an exponential growth at 5/s that never saturates: still growing when the budget is spent.

``growing_whirl_run(case, duration)`` is the point function; its ``continue_fn(ds, duration)`` re-generates the run
over the longer span from the case stored in the archive (a synthetic continuation: exact, so the extended run is
the longer run) and annotates it like a real one.  Module-level, so spawned and dask workers import it by name.
"""

from __future__ import annotations

import math

import numpy as np
import xarray as xr

from hsbearing.analysis import annotate
from hsbearing.case import loads_case
from hsbearing.results import standard_attrs

W = 2 * math.pi * 96.0
DT = 100e-6
#: the radius law of each axial load [N]
RADIUS = {
    500.0: lambda t: np.full_like(t, 80e-6),
    1000.0: lambda t: 100e-6 / (1 + (100e-6 / 2e-6 - 1) * np.exp(-12.0 * t)),
    2000.0: lambda t: 1e-6 * np.exp(5.0 * t),
}


def _run(case, t_end: float) -> xr.Dataset:
    t = np.arange(int(round(t_end / DT)) + 1) * DT
    r = RADIUS[float(case.operating.axial_load)](t)
    th = 0.97 * W * t
    dr = np.gradient(r, t)
    Z = case.bearing.ball_count
    q = 200.0 + 5.0 * np.sin(11 * W * t)[:, None] + np.zeros((t.size, Z))
    ds = xr.Dataset(
        {"cage_center_y": ("time", r * np.cos(th)), "cage_center_z": ("time", r * np.sin(th)),
         "cage_velocity_y": ("time", dr * np.cos(th) - r * 0.97 * W * np.sin(th)),
         "cage_velocity_z": ("time", dr * np.sin(th) + r * 0.97 * W * np.cos(th)),
         "cage_angle": ("time", W * t), "cage_speed": ("time", np.full_like(t, W)),
         "inner_contact_load": (("time", "ball"), q), "outer_contact_load": (("time", "ball"), 1.1 * q),
         "final_state": ("state", np.r_[r[-1], th[-1], np.zeros(8)])},
        coords={"time": t, "ball": np.arange(Z), "state": [f"s{i}" for i in range(10)]},
        attrs=standard_attrs(case, status="ok"))
    ds.attrs["case_toml"] = case.to_toml()
    ds.attrs["guide_clearance"] = 200e-6
    return annotate(ds, case)


def growing_whirl_run(case, duration):
    """The point function: the run up to ``duration`` (s)."""
    return _run(case, float(duration))


def continue_growing_whirl(ds, duration):
    """The continuation: the same run ``duration`` s longer (re-generated; the case comes from the archive)."""
    case = loads_case(ds.attrs["case_toml"], "continuation")
    return _run(case, float(ds["time"].values[-1]) + float(duration))


growing_whirl_run.continue_fn = continue_growing_whirl


# ---------------------------------------------------------------------------------------------------------------
# A whirl with a known limit cycle whose continuation starts from the stored state (so that a fast-forward, which
# scales the cage-centre deviation of final_state, changes what follows): the Hopf normal form (Stuart-Landau
# equation) of the cage centre w = y + i z,
#     w' = (SL_SIGMA + i SL_W) w - (SL_SIGMA + i SL_BETA) |w|^2 w / SL_A^2
# grows at SL_SIGMA about the centre (linear regime) and saturates on the circle |w| = SL_A, run at the angular
# frequency SL_W - SL_BETA (exact).  Integrated with classical RK4; the stored velocities are w'.

SL_W = 0.97 * W            # linear whirl angular frequency [rad/s] (0.97 x the cage speed W)
SL_BETA = 0.02 * SL_W      # non-linear frequency shift [rad/s]: the limit cycle runs at 0.9506 x W
SL_A = 100e-6              # limit-cycle radius [m]
SL_SIGMA = 5.0             # linear growth rate [1/s]
SL_R0 = 5e-8               # initial radius [m]
SL_DT = 100e-6
SL_STATES = ["y_c", "z_c", "ydot_c", "zdot_c"]


def _sl_rhs(w):
    return (SL_SIGMA + 1j * SL_W) * w - (SL_SIGMA + 1j * SL_BETA) * (abs(w) ** 2 / SL_A ** 2) * w


def sl_integrate(w0: complex, n: int) -> np.ndarray:
    """``n`` RK4 steps of SL_DT from the complex position ``w0``; the n + 1 positions."""
    out = np.empty(n + 1, complex)
    out[0] = w = complex(w0)
    h = SL_DT
    for i in range(n):
        k1 = _sl_rhs(w)
        k2 = _sl_rhs(w + 0.5 * h * k1)
        k3 = _sl_rhs(w + 0.5 * h * k2)
        k4 = _sl_rhs(w + h * k3)
        out[i + 1] = w = w + h / 6.0 * (k1 + 2 * k2 + 2 * k3 + k4)
    return out


def _sl_dataset(case, t, w) -> xr.Dataset:
    Z = case.bearing.ball_count
    v = _sl_rhs(w)
    q = 200.0 + 5.0 * np.sin(11 * W * t)[:, None] + np.zeros((t.size, Z))
    ds = xr.Dataset(
        {"cage_center_y": ("time", w.real), "cage_center_z": ("time", w.imag),
         "cage_velocity_y": ("time", v.real), "cage_velocity_z": ("time", v.imag),
         "cage_angle": ("time", W * t), "cage_speed": ("time", np.full_like(t, W)),
         "inner_contact_load": (("time", "ball"), q), "outer_contact_load": (("time", "ball"), 1.1 * q),
         "final_state": ("state", np.array([w[-1].real, w[-1].imag, v[-1].real, v[-1].imag]))},
        coords={"time": t, "ball": np.arange(Z), "state": SL_STATES},
        attrs=standard_attrs(case, status="ok"))
    ds.attrs["case_toml"] = case.to_toml()
    ds.attrs["guide_clearance"] = 200e-6
    return ds


def hopf_whirl_run(case, duration):
    """The point function: the Stuart-Landau whirl from the radius SL_R0, ``duration`` s, annotated."""
    n = int(round(float(duration) / SL_DT))
    return annotate(_sl_dataset(case, np.arange(n + 1) * SL_DT, sl_integrate(SL_R0, n)), case)


def continue_hopf_whirl(ds, duration):
    """The continuation from the stored ``final_state`` (position; old samples kept, new ones appended), annotated."""
    case = loads_case(ds.attrs["case_toml"], "continuation")
    n = int(round(float(duration) / SL_DT))
    t_last = float(ds["time"].values[-1])
    f = ds["final_state"].values
    w_new = sl_integrate(complex(f[0], f[1]), n)[1:]
    t = np.r_[ds["time"].values, t_last + np.arange(1, n + 1) * SL_DT]
    w = np.r_[ds["cage_center_y"].values + 1j * ds["cage_center_z"].values, w_new]
    return annotate(_sl_dataset(case, t, w), case)


hopf_whirl_run.continue_fn = continue_hopf_whirl
