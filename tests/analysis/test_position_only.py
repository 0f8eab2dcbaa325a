"""Position-only input (a measured orbit, an archive without cage velocities): the velocity estimate and the
classifier's benchmark on positions alone (hsbearing.analysis.derivative, hsbearing.analysis.benchmark).

"chaos" requires on positions what it requires on stored velocities (the classifier is the same; only the
velocity fed to the section changes), and no motion of the benchmark that is not chaotic is ever read "chaos",
on any input.
"""

from __future__ import annotations

import math

import numpy as np
import pytest
import xarray as xr

from hsbearing.analysis import annotate
from hsbearing.analysis import benchmark as B
from hsbearing.analysis.derivative import noise_gain, smoothed_velocity, velocity_window
from hsbearing.analysis.whirl import classify_motion

W = B.CAGE_SPEED


# ----------------------------------------------------------------------------- the estimator


def test_noise_gain_measured_on_white_noise():
    """White position noise s -> velocity noise G s with G = sqrt(sum c_k^2), measured; and G is far below the
    central differences' 1/(sqrt 2 dt) at the benchmark sampling."""
    rng = np.random.default_rng(11)
    dt, n = B.DT, 200_000
    t = np.arange(n) * dt
    # a slow whirl fixes the window (dominant frequency 93 Hz), noise on top
    s = 1e-6
    y = 100e-6 * np.cos(0.97 * W * t) + s * rng.standard_normal(n)
    z = 100e-6 * np.sin(0.97 * W * t) + s * rng.standard_normal(n)
    vy, vz, info = smoothed_velocity(t, y, z)
    inner = slice(1000, -1000)
    err = vy[inner] + 100e-6 * 0.97 * W * np.sin(0.97 * W * t[inner])
    G = noise_gain(info["window"], dt)
    assert info["window"] == velocity_window(dt, 0.97 * W / (2 * math.pi), n) == 117
    assert np.std(err) == pytest.approx(G * s, rel=0.03)
    cd = np.gradient(y, t)[inner] + 100e-6 * 0.97 * W * np.sin(0.97 * W * t[inner])
    assert np.std(cd) == pytest.approx(s / (math.sqrt(2) * dt), rel=0.03)
    assert G < (1 / (math.sqrt(2) * dt)) / 55  # 59 x less noise than central differences


@pytest.mark.parametrize("harmonic,tol", [(1.0, 1e-3), (2.0, 0.025)])
def test_bias_on_a_sinusoid(harmonic, tol):
    """No noise: the derivative of a sinusoid at the dominant frequency is exact to 0.1 %, its second harmonic
    loses at most 2.5 % (the filter's response 0.98)."""
    dt = B.DT
    t = np.arange(40_000) * dt
    f0 = 93.0
    y = 100e-6 * np.cos(2 * np.pi * f0 * t) + 10e-6 * np.cos(2 * np.pi * harmonic * f0 * t + 0.4)
    z = 100e-6 * np.sin(2 * np.pi * f0 * t)
    vy, _, info = smoothed_velocity(t, y, z)
    exact = -100e-6 * 2 * np.pi * f0 * np.sin(2 * np.pi * f0 * t) \
        - 10e-6 * 2 * np.pi * harmonic * f0 * np.sin(2 * np.pi * harmonic * f0 * t + 0.4)
    inner = slice(500, -500)
    rel = np.max(np.abs(vy[inner] - exact[inner])) / (10e-6 * 2 * np.pi * harmonic * f0)
    if harmonic == 1.0:
        rel = np.max(np.abs(vy[inner] - exact[inner])) / (110e-6 * 2 * np.pi * f0)
    assert rel < tol, (rel, info)


def test_nonuniform_sampling():
    rng = np.random.default_rng(3)
    t = np.sort(rng.uniform(0, 0.2, 4000))
    y, z = 100e-6 * np.cos(600 * t), 100e-6 * np.sin(600 * t)
    vy, vz, info = smoothed_velocity(t, y, z)
    inner = slice(200, -200)
    assert np.max(np.abs(vy[inner] + 0.06 * np.sin(600 * t[inner]))) < 0.02 * 0.06


# ----------------------------------------------------------------------------- the benchmark on positions


def _check(m, positions_only):
    vy, vz = (None, None) if positions_only else (m.vy, m.vz)
    label, conf, det = classify_motion(m.t, m.y, m.z, vy, vz, m.phi, clearance=B.CLEARANCE)
    ok = m.accepts(label) and (not m.kind or label != "undetermined" or det["kind"] == m.kind)
    if m.kind == "still":
        ok = ok and det["kind"] == "still"
    return ok, label, det


def _misses(length, noise, positions_only=True):
    out = []
    for m in B.cases(length, noise):
        ok, label, det = _check(m, positions_only)
        if not ok:
            out.append((m.name, m.expected, label, det.get("kind"), det.get("reason")))
    return out


@pytest.mark.parametrize("noise", B.NOISE_LEVELS)
def test_benchmark_positions_only_short(noise):
    """Every benchmark motion, positions only (velocities estimated), 80 cage revolutions: its known label."""
    assert _misses("short", noise) == []


@pytest.mark.slow  # long: default tier kept under ~10 min (docs/testing.md)
def test_benchmark_positions_only_long_noisy():
    assert _misses("long", 0.01) == []


@pytest.mark.slow
@pytest.mark.parametrize("length,noise", [("short", 0.0), ("long", 0.0), ("long", 0.002)])
def test_benchmark_positions_only_remaining(length, noise):
    assert _misses(length, noise) == []


def _only_undetermined(misses):
    assert {m[0].split(",")[0] for m in misses} <= {"epicycle period 3", "torus (golden)"}, misses
    assert all(m[2] == "undetermined" for m in misses), misses


def test_probe_noise_two_percent_short():
    """At the 2 % probe noise (above the benchmark's levels), positions only, every motion gets its label but the
    3-loop epicycle, read "undetermined" -- as it is with its stored velocities at 2 % -- and nothing is read
    wrong; on 400 revolutions (slow test) the torus too."""
    _only_undetermined(_misses("short", B.PROBE_NOISE))


@pytest.mark.slow
def test_probe_noise_two_percent_long():
    _only_undetermined(_misses("long", B.PROBE_NOISE))


@pytest.mark.parametrize("positions_only", [False, True])
@pytest.mark.parametrize("noise", (0.0,) + B.NOISE_LEVELS + (B.PROBE_NOISE,))
def test_no_false_chaos_on_any_input(noise, positions_only):
    """No motion of the benchmark that is not chaotic is read "chaos": stored velocities or positions only, at every
    noise level (and the 2 % probe level), short runs (long runs: the slow test below)."""
    false = []
    for m in B.cases("short", noise):
        if m.expected == "chaos":
            continue
        ok, label, det = _check(m, positions_only)
        if label == "chaos":
            false.append((m.name, det.get("reason")))
    assert false == []


@pytest.mark.slow
@pytest.mark.parametrize("positions_only", [False, True])
@pytest.mark.parametrize("noise", (0.0,) + B.NOISE_LEVELS + (B.PROBE_NOISE,))
def test_no_false_chaos_on_any_input_long(noise, positions_only):
    false = [m.name for m in B.cases("long", noise) if m.expected != "chaos"
             and _check(m, positions_only)[1] == "chaos"]
    assert false == []


def test_chaos_still_read_on_positions():
    """The Rössler flow stays "chaos" on positions alone (0.2 % noise, 400 revolutions): the estimate does not
    smooth away what chaos requires."""
    m = B.with_noise(B.rossler(400), 0.002)
    ok, label, det = _check(m, True)
    assert label == "chaos", det.get("reason")


# ----------------------------------------------------------------------------- the two reported cases, via annotate


def _probe_ds(m):
    """What a proximity-probe record gives: time and the two displacements (plus the cage speed), no velocities."""
    return xr.Dataset({"cage_speed": ("time", np.full_like(m.t, W)), "cage_center_y": ("time", m.y),
                       "cage_center_z": ("time", m.z)}, coords={"time": m.t}, attrs={"guide_clearance": B.CLEARANCE})


def test_three_loop_epicycle_probe_noise_is_three_periods():
    """A 3-loop epicycle of 190 um outer radius with 0.2 um probe noise, positions only: "3 periods" (central
    differences read it "chaos")."""
    m = B.epicycle(3, a=0.9, revs=80)
    scale = 190e-6 / float(np.max(np.hypot(m.y, m.z)))
    rng = np.random.default_rng(1)
    y = scale * m.y + 0.2e-6 * rng.standard_normal(m.t.size)
    z = scale * m.z + 0.2e-6 * rng.standard_normal(m.t.size)
    ds = _probe_ds(B.replace(m, y=y, z=z))
    out = annotate(ds, transient=0.0)
    assert out.attrs["classification"] == "3 periods", out.attrs["classification_reason"]
    assert out.attrs["cage_velocity_source"].startswith("estimated from the positions")
    label_cd = classify_motion(m.t, y, z, np.gradient(y, m.t), np.gradient(z, m.t), None, clearance=B.CLEARANCE)[0]
    assert label_cd != "3 periods"  # what central differences gave: the defect this estimator removes


def test_circle_with_two_percent_noise_is_one_period():
    m = B.with_noise(B.circle(0.97), B.PROBE_NOISE, seed=2)
    out = annotate(_probe_ds(m), transient=0.0)
    assert out.attrs["classification"] == "1 period", out.attrs["classification_reason"]


def test_stored_velocities_are_used_when_present():
    m = B.circle(0.97)
    ds = _probe_ds(m).assign(cage_velocity_y=("time", m.vy), cage_velocity_z=("time", m.vz))
    assert annotate(ds, transient=0.0).attrs["cage_velocity_source"] == "stored"
