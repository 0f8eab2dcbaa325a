"""Sub-labels of "1 period" (still cage / synchronous whirl / harmonic whirl / synchronous orbit) and the
cage-instability index, on synthetic cage-centre signals with known answers.

Zhang et al. 2016 (Zhang et al. 2016, Sec. 4, Fig. 5a) pairs "1 period" with a single-circle whirl synchronous with the
cage-revolution section.  A cage centre at rest also gives one section point; the sub-label must tell them apart.
Every signal goes through the full path (``hsbearing.analysis.annotate``: section, classifier, sub-label), so a
wrong section, class or sub-label fails here.
"""

from __future__ import annotations

import numpy as np
import pytest
import xarray as xr
from scipy.interpolate import CubicSpline

from hsbearing.analysis import annotate
from hsbearing.analysis.whirl import DETAILS, cage_instability_index, classification_detail

C = 0.25e-3  # guide clearance [m]
W = 2 * np.pi * 100.0  # cage speed [rad/s] (100 rev/s)
N_REV = 200
SPR = 64  # samples per cage revolution


def _run(y, z, t, w=W):
    ds = xr.Dataset(
        {"cage_speed": ("time", np.full_like(t, w)), "cage_center_y": ("time", y), "cage_center_z": ("time", z)},
        coords={"time": t},
        attrs={"guide_clearance": C},
    )
    return annotate(ds, transient=0.3)


def _t():
    return np.arange(N_REV * SPR + 1) / (SPR * W / (2 * np.pi))


def test_synchronous_circle_is_one_period_synchronous_whirl():
    t = _t()
    R = 0.6 * C
    ds = _run(R * np.cos(W * t + 0.3), R * np.sin(W * t + 0.3), t)
    assert ds.attrs["classification"] == "1 period"
    assert ds.attrs["classification_detail"] == "synchronous whirl"
    assert float(ds["cage_instability_index"]) < 1e-6  # constant radius about the bearing axis


def test_backward_synchronous_circle_is_also_synchronous():
    t = _t()
    R = 0.4 * C
    ds = _run(R * np.cos(-W * t), R * np.sin(-W * t), t)
    assert ds.attrs["classification"] == "1 period"
    assert ds.attrs["classification_detail"] == "synchronous whirl"


@pytest.mark.parametrize("offset", [0.0, 0.5 * C])
def test_still_cage_is_one_period_still_cage(offset):
    t = _t()
    rng = np.random.default_rng(1)
    noise = 1e-4 * C  # numerical jitter far below the clearance
    ds = _run(offset + noise * rng.standard_normal(t.size), noise * rng.standard_normal(t.size), t)
    assert ds.attrs["classification"] == "1 period"
    assert ds.attrs["classification_detail"] == "still cage"
    assert float(ds["cage_instability_index"]) < 0.01


def test_harmonic_and_non_circular_synchronous_orbits():
    t = _t()
    R = 0.5 * C
    two = _run(R * np.cos(2 * W * t), R * np.sin(2 * W * t), t)  # two whirl turns per cage revolution
    assert two.attrs["classification"] == "1 period"
    assert two.attrs["classification_detail"] == "harmonic whirl"
    ell = _run(R * np.cos(W * t), 0.3 * R * np.sin(W * t), t)  # synchronous ellipse: one point, not a circle
    assert ell.attrs["classification"] == "1 period"
    assert ell.attrs["classification_detail"] == "synchronous orbit"


def test_quasi_periodic_torus_has_no_one_period_sublabel():
    t = _t()
    R = 0.5 * C
    g = (np.sqrt(5) - 1) / 2  # whirl / cage speed irrational: the section points fill a closed curve
    ds = _run(R * np.cos(g * W * t) + 0.1 * R * np.cos(W * t), R * np.sin(g * W * t), t)
    assert ds.attrs["classification"] == "quasi-periodic"
    assert ds.attrs["classification_detail"] == ""


def test_chaotic_signal_is_chaos_with_large_instability_index():
    t = _t()
    x = np.empty(N_REV + 1)
    x[0] = 0.3141
    for k in range(N_REV):  # logistic map at r = 4: Lyapunov exponent ln 2 per revolution
        x[k + 1] = 4.0 * x[k] * (1.0 - x[k])
    rk = C * (0.1 + 0.8 * x)  # whirl radius at each revolution
    r = CubicSpline(np.arange(N_REV + 1) * 2 * np.pi / W, rk)(t)
    ds = _run(r * np.cos(W * t), r * np.sin(W * t), t)
    assert ds.attrs["classification"] == "chaos"
    assert ds.attrs["classification_detail"] == ""
    # radius spread of a uniform-ish distribution on [0.1, 0.9] C: sd/mean ~ 0.5 (>> 0 of a steady whirl)
    assert float(ds["cage_instability_index"]) > 0.3


def test_detail_vocabulary_and_non_period_labels():
    t = _t()[:200]
    for label in ("k periods", "quasi-periodic", "chaos", "undetermined"):
        assert classification_detail(label, t, np.cos(W * t), np.sin(W * t), W, C)[0] == ""
    d, info = classification_detail("1 period", t, 1e-3 * C * np.cos(W * t), 1e-3 * C * np.sin(W * t), W, C)
    assert d in DETAILS and d == "still cage"
    assert info["orbit_rms_radius"] == pytest.approx(1e-3 * C, rel=1e-2)


def test_instability_index_closed_forms():
    """sd(r)/mean(r) against closed forms: an eccentric circle and the floor near the axis."""
    th = np.linspace(0, 2 * np.pi, 200001)[:-1]
    R, e = 1.0, 0.2
    y, z = e + R * np.cos(th), R * np.sin(th)  # circle of radius R about (e, 0)
    r = np.hypot(y, z)  # r^2 = R^2 + e^2 + 2 e R cos th
    # independent: quadrature of the moments of r over th (trapezoid on a finer grid)
    thf = np.linspace(0, 2 * np.pi, 400001)
    rf = np.sqrt(R**2 + e**2 + 2 * e * R * np.cos(thf))
    m1 = np.trapezoid(rf, thf) / (2 * np.pi)
    m2 = np.trapezoid(rf**2, thf) / (2 * np.pi)  # = R^2 + e^2 exactly
    assert m2 == pytest.approx(R**2 + e**2, rel=1e-9)
    assert cage_instability_index(y, z) == pytest.approx(np.sqrt(m2 - m1**2) / m1, rel=1e-6)
    assert np.std(r) / np.mean(r) == pytest.approx(cage_instability_index(y, z), rel=1e-12)
    # floor: a jitter of 1e-6 m about the axis with clearance 1e-4 m -> sd / (0.05 * 1e-4), not sd / mean
    rng = np.random.default_rng(0)
    jy, jz = 1e-6 * rng.standard_normal(5000), 1e-6 * rng.standard_normal(5000)
    rj = np.hypot(jy, jz)
    assert cage_instability_index(jy, jz, 1e-4) == pytest.approx(np.std(rj) / 5e-6, rel=1e-12)
    assert cage_instability_index(jy, jz) == pytest.approx(np.std(rj) / np.mean(rj), rel=1e-12)
