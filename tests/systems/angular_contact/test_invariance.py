"""Invariances of the full dynamic model (Zhang et al. 2016, hsbearing.systems.angular_contact.dynamics).

Three symmetries a correct model must have, whatever its force laws:

* **ball renumbering** -- the balls are identical: shifting every ball's states by s pockets and turning the
  cage back by 2 pi s / Z describes the same physical state, so the right-hand side must be the same,
  shifted;
* **mirror symmetry** -- the reflection Z -> -Z (a plane through the axis and the load/gravity direction Y)
  maps a motion with inner-ring speed +omega_i onto one with -omega_i; polar vectors keep their X and Y
  components and flip Z, pseudo-vectors (angular velocities, tilts) flip X and Y and keep Z, and ball j
  goes to ball (Z - j) mod Z;
* **outer-ring drive** -- under a pure axial load the bearing is axisymmetric, so (inner omega, outer 0) seen
  from the inner ring is (inner 0, outer -omega): at low speed, where the centrifugal and gyroscopic terms
  that distinguish the two frames are negligible, the loads and angles agree and every absolute speed
  differs by omega.

The rhs-level checks evaluate the compiled kernel at a generic, deliberately asymmetric state (every ball
different, cage off-centre and moving, ring displaced and tilted), so every force term is exercised; the
trajectory checks integrate a few milliseconds (short enough that the chaotic cage has not amplified
round-off) through the quasi-static start, CVODE and the Dataset.
"""

from __future__ import annotations

import dataclasses
import math

import numpy as np
import pytest

import hsbearing
from hsbearing.systems.angular_contact import dynamics as dy

RPM = math.pi / 30.0

# ball-state signs under Z -> -Z, in hsbearing.models.ball_bearing.state.BALL_STATES order:
# x_b, u_b, theta_rel_b, xdot_b, udot_b, thetadot_b, omega_x, omega_y, omega_z (ball frame: x axial, y radial,
# z along increasing theta -- a reflected ball's z axis is the reflection of -z, so omega_z keeps its sign)
_BALL_MIRROR = (1, 1, -1, 1, 1, -1, -1, -1, 1)
# cage: x_c, y_c, z_c, phi_c, tilt_y_c, tilt_z_c and their rates
_CAGE_MIRROR = (1, 1, -1, -1, -1, 1) * 2
# ring: x_i, y_i, z_i, tilt_y_i, tilt_z_i and their rates
_RING_MIRROR = (1, 1, -1, -1, 1) * 2


def _case(**kw):
    return hsbearing.load_case("zhang2016", **{"operating.radial_load": "500 N", **kw})


def _generic_state(m, seed=1):
    """The model's initial state made asymmetric: every ball, the cage and the ring perturbed."""
    Z, cg, rg = m.layout.Z, m.layout.cage0, m.layout.ring0
    rng = np.random.default_rng(seed)
    y = m.y0.copy()
    y[:Z] += 1e-7 * rng.standard_normal(Z)  # axial position
    y[Z:2 * Z] += 1e-7 * rng.standard_normal(Z)  # radial
    y[2 * Z:3 * Z] += 1e-3 * rng.standard_normal(Z)  # position in the pocket
    y[3 * Z:6 * Z] += 1e-3 * rng.standard_normal(3 * Z)  # velocities
    y[6 * Z:9 * Z] += 10.0 * rng.standard_normal(3 * Z)  # angular velocities
    y[cg + 1] += 2e-5
    y[cg + 2] -= 1e-5
    y[cg + 4] += 1e-4
    y[cg + 5] -= 1e-4
    y[cg + 7] += 1e-3
    y[cg + 8] -= 2e-3
    y[rg + 2] += 1e-6
    y[rg + 3] += 1e-5
    return y


def _rhs(m, y):
    yd = np.zeros_like(y)
    m.rhs(0.0, y, yd)
    return yd


def _shift(m, y, s):
    """Renumber the balls: ball j's states move to slot j + s, the cage turns back by 2 pi s / Z."""
    Z, cg = m.layout.Z, m.layout.cage0
    out = y.copy()
    for k in range(9):
        out[k * Z:(k + 1) * Z] = np.roll(y[k * Z:(k + 1) * Z], s)
    out[cg + 3] = y[cg + 3] - 2.0 * math.pi * s / Z
    return out


def _mirror(m, y):
    Z, cg, rg = m.layout.Z, m.layout.cage0, m.layout.ring0
    j = (-np.arange(Z)) % Z
    out = y.copy()
    for k in range(9):
        out[k * Z:(k + 1) * Z] = _BALL_MIRROR[k] * y[k * Z:(k + 1) * Z][j]
    out[cg:cg + 12] = np.asarray(_CAGE_MIRROR) * y[cg:cg + 12]
    out[rg:rg + 10] = np.asarray(_RING_MIRROR) * y[rg:rg + 10]
    return out


def _assert_blocks_close(m, got, want, rtol):
    """Per ball quantity / per global state: |got - want| <= rtol * (largest |want| of that block)."""
    Z, cg = m.layout.Z, m.layout.cage0
    names = m.layout.state_names
    for k in range(9):
        blk = slice(k * Z, (k + 1) * Z)
        scale = np.abs(want[blk]).max()
        assert np.abs(got[blk] - want[blk]).max() <= rtol * scale, (names[k * Z], got[blk], want[blk])
    for i in range(cg, got.size):
        assert abs(got[i] - want[i]) <= rtol * max(abs(want[i]), 1e-9 * np.abs(want[cg:]).max()), (
            names[i], got[i], want[i])


# ----------------------------------------------------------------------------- ball renumbering


@pytest.fixture(scope="module")
def model():
    return dy.build_model(_case())


@pytest.mark.parametrize("s", [1, 4])
def test_ball_renumbering_rhs(model, s):
    """Shifting the ball numbering by s pockets (cage turned back by 2 pi s / Z) gives the shifted rhs: measured
    agreement 1e-11 (ball blocks) and 4e-11 of the largest cage/ring rate -- round-off of the summation order."""
    m = model
    y = _generic_state(m)
    want = _shift(m, _rhs(m, y), s)
    want[m.layout.cage0 + 3] = _rhs(m, y)[m.layout.cage0 + 3]  # d(phi_c)/dt is not shifted
    _assert_blocks_close(m, _rhs(m, _shift(m, y, s)), want, rtol=1e-8)


def test_ball_renumbering_trajectory(model):
    """3 ms of the radially loaded bearing started from the renumbered quasi-static state: every ball's loads and
    speeds are those of the original run, renumbered; the cage and ring follow the same path (measured: loads
    5e-5, cage centre 6e-4 of their ranges -- the cage is sensitive to round-off, the tolerance is 20x that)."""
    m = model
    c = m.case
    a = dy.simulate(c, duration=0.003, model=m, annotate=False)
    b = dy.simulate(c, duration=0.003, model=dataclasses.replace(m, y0=_shift(m, m.y0, 3)), annotate=False)
    for v in ("inner_contact_load", "outer_contact_load", "ball_orbit_speed", "inner_contact_angle"):
        x, y = a[v].values, np.roll(b[v].values, -3, axis=1)
        assert np.abs(x - y).max() <= 1e-3 * np.abs(x).max(), v
    for v in ("cage_center_y", "cage_center_z", "cage_speed", "inner_ring_radial_displacement_y",
              "inner_ring_axial_displacement"):
        x, y = a[v].values, b[v].values
        assert np.abs(x - y).max() <= 1e-2 * np.abs(x).max(), v


# ----------------------------------------------------------------------------- mirror symmetry

# Before issue 14's land film (merged), these two tests were strict xfails for this reason; the Guembel film
# is mirror symmetric and both pass now (kept as the record of what they caught):
_LAND_FILM_ASYMMETRY = (
    "guide-land film (models.cage.guide_land_forces, Ocvirk short bearing) is not mirror symmetric: its radial "
    "force -k w eps^2/(1-eps^2)^2 changes sign with w = omega_cage + omega_land - 2 whirl, so a cage turning "
    "the other way is pushed instead of pulled; measured at the generic state: d(v_y,c)/dt 9.41 vs mirrored "
    "-2.88 m/s^2, d(v_z,c)/dt -50.1 vs -60.0 (issue 14: the land film is being rewritten)")


@pytest.fixture(scope="module")
def mirrored_model():
    return dy.build_model(_case(**{"operating.inner_speed": "-14000 rpm"}))


def test_mirror_initial_state(model, mirrored_model):
    """The quasi-static start of -omega_i is the mirror image of that of +omega_i."""
    m, mm = model, mirrored_model
    want = _mirror(m, m.y0)
    assert np.allclose(mm.y0, want, rtol=1e-9, atol=1e-15)


def test_mirror_rhs_without_land_film(model):
    """Every force except the guide-land film (damping=False switches off the contact damping, the EHL rolling
    force and the land film): the rhs at the mirrored state is the mirrored rhs (measured 1e-11)."""
    c = model.case
    m = dy.build_model(c, damping=False)
    mm = dy.build_model(_case(**{"operating.inner_speed": "-14000 rpm"}), damping=False)
    y = _generic_state(m)
    _assert_blocks_close(mm, _rhs(mm, _mirror(m, y)), _mirror(m, _rhs(m, y)), rtol=1e-8)


def test_mirror_rhs_full_model(model, mirrored_model):
    """-omega_i: the rhs at the mirrored generic state is the mirrored rhs, every force on (friction, damping, EHL
    rolling force, drag, guide-land film, gravity along -Y, radial load along Y)."""
    m, mm = model, mirrored_model
    y = _generic_state(m)
    _assert_blocks_close(mm, _rhs(mm, _mirror(m, y)), _mirror(m, _rhs(m, y)), rtol=1e-8)


def test_mirror_trajectory(model, mirrored_model):
    """3 ms from the quasi-static start: the -omega_i run is the mirror image of the +omega_i run (ball j <->
    ball (Z - j) mod Z; Z components, speeds about X and tilts about Y change sign)."""
    a = dy.simulate(model.case, duration=0.003, model=model, annotate=False)
    b = dy.simulate(mirrored_model.case, duration=0.003, model=mirrored_model, annotate=False)
    j = (-np.arange(model.layout.Z)) % model.layout.Z
    signs = {"inner_contact_load": 1, "outer_contact_load": 1, "inner_contact_angle": 1, "outer_contact_angle": 1,
             "ball_orbit_speed": -1, "ball_center_radial": 1, "ball_angular_velocity_x": -1,
             "ball_angular_velocity_y": -1, "ball_spin_speed": 1, "cage_center_y": 1, "cage_center_z": -1,
             "cage_speed": -1, "inner_ring_axial_displacement": 1, "inner_ring_radial_displacement_y": 1,
             "inner_ring_tilt_z": 1}
    for v, sg in signs.items():
        x, y = a[v].values, b[v].values
        if x.ndim == 2:
            y = y[:, j]
        assert np.abs(x - sg * y).max() <= 1e-2 * np.abs(x).max(), v


# ----------------------------------------------------------------------------- outer-ring drive


def test_outer_ring_drive_same_relative_kinematics():
    """Pure axial load, no gravity, 2000 r/min: (inner +omega, outer 0) and (inner 0, outer -omega) have the same
    contact loads and angles (within 1 %; measured 0.03-0.26 %) and every absolute speed differs by omega: cage,
    ball orbit and ball omega_x within 0.2 % of omega (measured <= 0.05 %), omega_y, omega_z within 1 % of omega
    (measured 0.05 %, 0.7 %).  The residue is the centrifugal / gyroscopic difference of the two frames: at
    14000 r/min it grows to 9 % on Q_o (measured), which is why a low speed is used."""
    w = 2000.0
    W = w * RPM
    a = dy.simulate(hsbearing.load_case("zhang2016", **{"operating.inner_speed": f"{w} rpm"}), duration=0.005,
                    annotate=False, gravity=0.0)
    b = dy.simulate(hsbearing.load_case("zhang2016", **{"operating.inner_speed": "0 rpm",
                                                          "operating.outer_speed": f"{-w} rpm"}),
                    duration=0.005, annotate=False, gravity=0.0)
    late_a, late_b = a.time > 0.0025, b.time > 0.0025
    for v in ("inner_contact_load", "outer_contact_load", "inner_contact_angle", "outer_contact_angle"):
        assert float(b[v][late_b].mean()) == pytest.approx(float(a[v][late_a].mean()), rel=0.01), v
    for v, shift, tol in (("cage_speed", W, 2e-3), ("ball_orbit_speed", W, 2e-3), ("ball_angular_velocity_x", W, 2e-3),
                          ("ball_angular_velocity_y", 0.0, 1e-2), ("ball_angular_velocity_z", 0.0, 1e-2)):
        assert float(b[v][late_b].mean()) == pytest.approx(float(a[v][late_a].mean()) - shift, abs=tol * W), v
    # the cage turns with the outer ring, at about (1 + gamma)/2 of its speed (epicyclic)
    assert float(b.cage_speed[late_b].mean()) / -W == pytest.approx(0.59, abs=0.02)
