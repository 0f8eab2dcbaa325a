"""State-vector layout of the bearing dynamic model: the ONE place the order is documented.

The state vector ``y`` of :mod:`hsbearing.systems.angular_contact.dynamics` (``N = 9 Z + 12 + 10``
floats, SI units, no scaling) is stored **state-major**: each ball quantity
occupies a contiguous block of ``Z`` entries (one per ball), so that
``y[k*Z:(k+1)*Z]`` is the array of quantity ``k`` over all balls.  This makes
the per-ball loops of the compiled right-hand side and the "perturb the same
state of every ball at once" Jacobian trivial.

Order (index ranges for Z balls):

===========  ==========================  =========================================  ========
block        slice                       quantity                                   unit
===========  ==========================  =========================================  ========
ball 0       ``[0, Z)``                  x_b: ball centre axial position (X)        m
ball 1       ``[Z, 2Z)``                 u_b: radial displacement of the ball       m
                                         centre from the pitch circle,
                                         r_b = d_m/2 + u_b
ball 2       ``[2Z, 3Z)``                theta_rel_b: orbital angle of ball j       rad
                                         relative to its pocket's nominal line,
                                         theta_b = phi_c + 2 pi j / Z + theta_rel_b
ball 3       ``[3Z, 4Z)``                dx_b/dt                                    m/s
ball 4       ``[4Z, 5Z)``                udot_b = du_b/dt = dr_b/dt                 m/s
ball 5       ``[5Z, 6Z)``                dtheta_b/dt: absolute orbital speed        rad/s
                                         (d theta_rel_b/dt = dtheta_b/dt - dphi_c/dt)
ball 6       ``[6Z, 7Z)``                omega_x: ball angular velocity, axial      rad/s
ball 7       ``[7Z, 8Z)``                omega_y: idem, radial (ball frame)         rad/s
ball 8       ``[8Z, 9Z)``                omega_z: idem, circumferential             rad/s
cage         ``9Z + 0 .. 5``             x_c, y_c, z_c [m], phi_c (rotation about   m, rad
                                         X) [rad], tilt_y_c, tilt_z_c [rad]
cage rates   ``9Z + 6 .. 11``            their time derivatives                     m/s, rad/s
ring         ``9Z + 12 .. 16``           x_i, y_i, z_i [m], tilt_y_i, tilt_z_i      m, rad
                                         [rad]
ring rates   ``9Z + 17 .. 21``           their time derivatives                     m/s, rad/s
===========  ==========================  =========================================  ========

The ball angular velocity (omega_x, omega_y, omega_z) is the *absolute*
angular velocity of the ball expressed in the ball frame of Zhang et al. 2016, Fig. 2
(x axial, y radial outward, z circumferential in the direction of increasing
theta_b); the frame turns with the orbit, which gives the gyroscopic terms
I_b omega theta_dot of Eqs. (9)-(10).  The inner-ring spin about X is
prescribed by the case (``operating.inner_speed``) and is not a state; the
outer ring is fixed (its speed ``operating.outer_speed`` enters the contact
kinematics only).

Why u_b and theta_rel_b rather than r_b and theta_b: CVODE weighs the error of
state i by 1/(rtol |y_i| + atol_i).  With r_b ~ d_m/2 the relative part
(rtol r_b ~ 0.2 um at rtol 1e-5) would allow errors of several percent of the
contact deflections (~ 4 um); with an absolute orbit angle that grows
without bound the allowed error would grow with time (at 0.1 s, 6e-4 rad, a
quarter of the pocket clearance).  The displacement from the pitch circle and
the angle relative to the pocket are small numbers, controlled by atol, and
the ball/pocket geometry uses theta_rel_b directly.

Absolute tolerances: :meth:`StateLayout.atol` returns a per-state array,
``atol * scale`` with the scales of :data:`ATOL_SCALE` (the case ``atol`` is
for states of order one; lengths are of order 1e-5..1e-2 m, so the length
scale is 1e-3, giving 1e-11 m for the default atol 1e-8).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

__all__ = ["StateLayout", "BALL_STATES", "CAGE_STATES", "RING_STATES", "ATOL_SCALE"]

#: Per-ball quantities in block order.
BALL_STATES = ("x_b", "u_b", "theta_rel_b", "xdot_b", "udot_b", "thetadot_b", "omega_x", "omega_y", "omega_z")
#: Cage states in order.
CAGE_STATES = ("x_c", "y_c", "z_c", "phi_c", "tilt_y_c", "tilt_z_c",
               "xdot_c", "ydot_c", "zdot_c", "phidot_c", "tiltdot_y_c", "tiltdot_z_c")
#: Inner-ring states in order.
RING_STATES = ("x_i", "y_i", "z_i", "tilt_y_i", "tilt_z_i", "xdot_i", "ydot_i", "zdot_i", "tiltdot_y_i", "tiltdot_z_i")

#: atol multiplier per kind of state (see module docstring).
ATOL_SCALE = {
    "length": 1e-3,  # m   -> 1e-11 m for atol = 1e-8
    "angle": 1e-1,  # rad (tilts; the orbit/cage angles grow, rtol governs them)
    "velocity": 1e1,  # m/s  -> 1e-7 m/s
    "angular_velocity": 1e3,  # rad/s -> 1e-5 rad/s
    "tilt_rate": 1e1,  # rad/s
}

_BALL_KIND = ("length", "length", "angle", "velocity", "velocity", "angular_velocity",
              "angular_velocity", "angular_velocity", "angular_velocity")
_CAGE_KIND = ("length", "length", "length", "angle", "angle", "angle",
              "velocity", "velocity", "velocity", "angular_velocity", "tilt_rate", "tilt_rate")
_RING_KIND = ("length", "length", "length", "angle", "angle",
              "velocity", "velocity", "velocity", "tilt_rate", "tilt_rate")


@dataclass(frozen=True)
class StateLayout:
    """Named slices of the state vector for ``Z`` balls (see the module docstring for the order)."""

    Z: int

    @property
    def n_ball(self) -> int:
        return 9 * self.Z

    @property
    def cage0(self) -> int:
        """Index of the first cage state."""
        return 9 * self.Z

    @property
    def ring0(self) -> int:
        """Index of the first inner-ring state."""
        return 9 * self.Z + 12

    @property
    def size(self) -> int:
        return 9 * self.Z + 22

    def ball(self, name: str) -> slice:
        """Slice of ball quantity ``name`` (one of :data:`BALL_STATES`) over all balls."""
        k = BALL_STATES.index(name)
        return slice(k * self.Z, (k + 1) * self.Z)

    def cage(self, name: str) -> int:
        return self.cage0 + CAGE_STATES.index(name)

    def ring(self, name: str) -> int:
        return self.ring0 + RING_STATES.index(name)

    @property
    def state_names(self) -> list[str]:
        names = [f"{q}[{j}]" for q in BALL_STATES for j in range(self.Z)]
        names += list(CAGE_STATES) + list(RING_STATES)
        return names

    def pack(self, ball: dict, cage: dict, ring: dict) -> np.ndarray:
        """Build ``y`` from ``{name: array (Z,)}``, ``{name: float}``, ``{name: float}``; missing = 0."""
        y = np.zeros(self.size)
        for name, val in ball.items():
            y[self.ball(name)] = val
        for name, val in cage.items():
            y[self.cage(name)] = val
        for name, val in ring.items():
            y[self.ring(name)] = val
        return y

    def unpack(self, y: np.ndarray) -> dict:
        """``y`` of shape (..., N) -> dict of arrays; ball quantities get a trailing ``ball`` axis."""
        y = np.asarray(y)
        out = {name: y[..., self.ball(name)] for name in BALL_STATES}
        for name in CAGE_STATES:
            out[name] = y[..., self.cage(name)]
        for name in RING_STATES:
            out[name] = y[..., self.ring(name)]
        return out

    def ball_radius(self, y, dm: float):
        """r_b = d_m/2 + u_b over all balls (..., Z) [m]."""
        return 0.5 * dm + np.asarray(y)[..., self.ball("u_b")]

    def ball_azimuth(self, y):
        """theta_b = phi_c + 2 pi j/Z + theta_rel_b (..., Z) [rad]."""
        y = np.asarray(y)
        return y[..., self.cage("phi_c"), None] + 2.0 * np.pi * np.arange(self.Z) / self.Z + y[..., self.ball("theta_rel_b")]

    def atol(self, atol: float) -> np.ndarray:
        """Per-state absolute tolerance ``atol * scale`` (:data:`ATOL_SCALE`)."""
        kinds = [k for k in _BALL_KIND for _ in range(self.Z)] + list(_CAGE_KIND) + list(_RING_KIND)
        return atol * np.array([ATOL_SCALE[k] for k in kinds])
