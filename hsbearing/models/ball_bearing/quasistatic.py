"""Physics of the high-speed quasi-static ball bearing model (Jones 1960, Harris & Kotzalas).

Pure, vectorised functions (arrays over balls) used by
:mod:`hsbearing.systems.angular_contact.quasistatic`: the groove curvature-centre geometry of a
loaded ball, Hertz loads, ball centrifugal force and gyroscopic moment,
race-control kinematics, the ball equilibrium residual and the reaction of the
balls on the inner ring.

Frames (Zhang et al. 2016, Fig. 2): X is the bearing axis, Y/Z radial.  Ball j sits at
azimuth psi_j measured from +Y towards +Z.  In the ball's azimuthal plane we
use the right-handed triad (e_X, e_r, e_t): axial, radial outward,
circumferential (e_X x e_r = e_t); these are the ball frame axes x, y, z of
Zhang et al. 2016.  Two-component vectors ``(axial, radial)`` live in the (e_X, e_r)
plane.

Sign conventions (documented in docs/quasistatic.md):

* The axial load F_x > 0 pushes the inner ring towards +X; the unloaded
  contact line runs from the inner contact to the outer contact along
  n0 = (sin alpha_0, cos alpha_0), so alpha > 0 for a loaded ball.
* X1, X2 = axial and radial position of the ball centre relative to the outer
  groove curvature centre ([1] Fig. 3.3 "X1j, X2j").  A1, A2 = axial and
  radial position of the inner groove curvature centre relative to the outer
  one ([1] Eqs. 3.6-3.7).
* The inner contact force on the ball is Q_i e_i with e_i = (A1-X1, A2-X2)/L_i
  (pointing from the inner contact through the ball centre), the outer
  contact force is -Q_o e_o with e_o = (X1, X2)/L_o.

References
----------
[1] Harris T. A., Kotzalas M. N., *Rolling Bearing Analysis*, 5th ed., Vol. 2
    (Advanced Concepts of Bearing Technology), Ch. 3 "Distribution of internal
    loading in high speed ball bearings": Eqs. 3.1-3.2 (centrifugal force,
    gyroscopic moment), 3.6-3.7 (A1, A2 with ring displacements and tilt),
    3.8-3.9 (contact angles from X1, X2), 3.10-3.11 (compatibility),
    3.14-3.15 (ball equilibrium with lambda_i, lambda_o), 3.20-3.24 (ring
    equilibrium).
[2] Jones A. B., "A general theory for elastically constrained ball and
    radial roller bearings under arbitrary load and speed conditions",
    J. Basic Eng. 82 (1960) 309-320 (race control, ball equilibrium).
[3] Harris T. A., Kotzalas M. N., *Rolling Bearing Analysis*, 5th ed., Vol. 1
    (Essential Concepts), Ch. 8 "Ball and roller bearing kinematics":
    Eq. 8.21 (cage speed), 8.40-8.45 (pitch angle beta under outer/inner
    raceway control, spin-to-roll ratio).
[4] Harris & Kotzalas Vol. 1, Ch. 7, Eq. 7.13 ff. (static axial load
    Fa = Z K (B D)^1.5 sin a (cos a0/cos a - 1)^1.5).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
from numpy.polynomial import chebyshev as _cheb

from hsbearing.models import hertz

__all__ = [
    "LAMBDA_SPLIT",
    "ContactStiffness",
    "groove_centre_layout",
    "groove_centre_separation",
    "contact_geometry",
    "hertz_load",
    "centrifugal_force",
    "unloaded_force_scale",
    "gyroscopic_moment",
    "gyroscopic_friction",
    "race_control_kinematics",
    "race_control_criterion",
    "race_control_ratio",
    "gyroscopic_split",
    "contact_spin_roll",
    "ball_equilibrium_residual",
    "inner_ring_reaction",
    "axial_static_single_ball",
]

#: (lambda_i, lambda_o): share of the gyroscopic moment resisted at the inner
#: and the outer contact ([1] Eqs. 3.14-3.15: "lambda_i = 0, lambda_o = 2 for
#: outer raceway control, otherwise lambda_i = lambda_o = 1").
LAMBDA_SPLIT = {
    "outer_race_control": (0.0, 2.0),
    "inner_race_control": (1.0, 1.0),
}


# ----------------------------------------------------------------------------- Hertz constant K(alpha)


@dataclass(frozen=True)
class ContactStiffness:
    """Hertz load-deflection constants K_i(alpha), K_o(alpha) [N/m^1.5] of one bearing.

    K depends on the contact angle only through gamma = D cos(alpha)/d_m
    (the rolling-direction radii, [4] Eqs. 2.27-2.31).  The exact constants of
    :func:`hsbearing.models.hertz.point_contact` (elliptic integrals) are
    sampled once on Chebyshev nodes in c = cos(alpha) in [0, 1] and evaluated
    by the Chebyshev series (degree 16: relative interpolation error < 1e-13
    for D/d_m up to 0.4, checked in tests/systems/angular_contact/test_quasistatic.py), so the
    equilibrium iterations never re-solve the ellipticity equation.
    """

    D: float
    dm: float
    fi: float
    fo: float
    Ep: float  #: reduced modulus E' [Pa]
    coef_i: np.ndarray
    coef_o: np.ndarray

    @classmethod
    def build(cls, D, dm, fi, fo, E1, nu1, E2, nu2, degree: int = 16) -> "ContactStiffness":
        from hsbearing.models.geometry import curvature_radii

        # Chebyshev-Gauss-Lobatto nodes on c in [0, 1]
        t = np.cos(np.pi * np.arange(degree + 1) / degree)
        c = 0.5 * (t + 1.0)
        alpha = np.arccos(np.clip(c, -1.0, 1.0))
        Rxi, Ryi, Rxo, Ryo = curvature_radii(D, dm, alpha, fi, fo)
        Ki = hertz.point_contact(Rxi, Ryi, 1.0, E1, nu1, E2, nu2).K
        Ko = hertz.point_contact(Rxo, Ryo, 1.0, E1, nu1, E2, nu2).K
        ci = _cheb.chebfit(t, np.log(Ki), degree)
        co = _cheb.chebfit(t, np.log(Ko), degree)
        return cls(D=D, dm=dm, fi=fi, fo=fo, Ep=float(hertz.reduced_modulus(E1, nu1, E2, nu2)), coef_i=ci, coef_o=co)

    def K(self, cos_alpha_i, cos_alpha_o):
        """(K_i, K_o) [N/m^1.5] at the inner and outer contact angles (given by their cosines)."""
        ci, co = np.broadcast_arrays(np.asarray(cos_alpha_i, dtype=float), np.asarray(cos_alpha_o, dtype=float))
        t = 2.0 * np.abs(np.stack([ci, co])) - 1.0
        coef = np.stack([self.coef_i, self.coef_o], axis=1).reshape((-1, 2) + (1,) * ci.ndim)
        lnK = _cheb.chebval(t, coef, tensor=False)  # one Clenshaw pass for both contacts
        return np.exp(lnK[0]), np.exp(lnK[1])


# ----------------------------------------------------------------------------- geometry


def groove_centre_layout(D, dm, fi, fo, alpha0, aligned=False):
    """Unloaded positions of the groove curvature centres (all [m]).

    Returns ``(x_i0, R_i, x_o0, R_o)``: axial position (from the bearing
    mid-plane) and radius (from the bearing axis) of the locus of the inner
    and of the outer groove curvature centres.

    * angular contact (``aligned=False``): the rings are set so that the
      unloaded contact angle is alpha_0 and the ball centres lie on the pitch
      circle in the mid-plane; [1] Eq. 3.5:
      R_i = d_m/2 + (f_i - 0.5) D cos(alpha_0),
      R_o = d_m/2 - (f_o - 0.5) D cos(alpha_0), the groove centres offset
      axially by +/-(f - 0.5) D sin(alpha_0).
    * deep groove (``aligned=True``): both grooves in the mid-plane, the
      diametral clearance P_d = 2 (f_i + f_o - 1) D (1 - cos alpha_0) split
      evenly ([4] Eqs. 2.8-2.10: raceway diameters d_m -/+ (D + P_d/2)).

    In both layouts (A1, A2) at zero displacement differ only in A1
    (A sin alpha_0 or 0), and A2 = A cos alpha_0.
    """
    if aligned:
        Pd = 2.0 * (fi + fo - 1.0) * D * (1.0 - np.cos(alpha0))
        return 0.0, 0.5 * dm + (fi - 0.5) * D - 0.25 * Pd, 0.0, 0.5 * dm - (fo - 0.5) * D + 0.25 * Pd
    x_i0 = (fi - 0.5) * D * np.sin(alpha0)
    R_i = 0.5 * dm + (fi - 0.5) * D * np.cos(alpha0)  # [1], Eq. 3.5
    x_o0 = -(fo - 0.5) * D * np.sin(alpha0)
    R_o = 0.5 * dm - (fo - 0.5) * D * np.cos(alpha0)
    return x_i0, R_i, x_o0, R_o


def groove_centre_separation(q, psi, D, dm, fi, fo, alpha0, aligned=False):
    """A1, A2 [m]: inner groove curvature centre relative to the outer one, per ball.

    Parameters
    ----------
    q : inner-ring displacement ``(delta_x, delta_y, delta_z, theta_y, theta_z)``
        [m, m, m, rad, rad] about the bearing centre (small rotations).
    psi : ball azimuths [rad], from +Y towards +Z.
    aligned : deep-groove layout (see :func:`groove_centre_layout`).

    Notes
    -----
    [1] Eqs. 3.6-3.7 generalised to two radial displacements and two tilts:
    the inner groove centre at (x_i0, R_i e_r) moves by u + theta x r (linear
    kinematics, rotation about the bearing centre).  At q = 0,
    (A1, A2) = (f_i + f_o - 1) D (sin alpha_0, cos alpha_0).
    """
    dx, dy, dz, ty, tz = q
    x_i0, R_i, x_o0, R_o = groove_centre_layout(D, dm, fi, fo, alpha0, aligned)
    c, s = np.cos(psi), np.sin(psi)
    A1 = x_i0 - x_o0 + dx + R_i * (ty * s - tz * c)  # [1], Eq. 3.6 (theta x r, axial component)
    A2 = R_i - R_o + (dy + tz * x_i0) * c + (dz - ty * x_i0) * s  # [1], Eq. 3.7 (radial component)
    return A1, A2


def contact_geometry(X1, X2, A1, A2, D, fi, fo):
    """Contact deflections and angles of balls whose centres are at (X1, X2).

    Returns ``(delta_i, delta_o, sin_ai, cos_ai, sin_ao, cos_ao, L_i, L_o)``:
    normal approaches [m] (negative = gap), contact-angle sines/cosines and
    the centre distances L_i = |groove centre i - ball centre|,
    L_o = |ball centre - groove centre o| [m].

    [1] Eqs. 3.8-3.11: cos a_o = X2/L_o, sin a_o = X1/L_o,
    cos a_i = (A2 - X2)/L_i, sin a_i = (A1 - X1)/L_i,
    delta_o = L_o - (f_o - 0.5) D, delta_i = L_i - (f_i - 0.5) D.
    """
    ui, vi = A1 - X1, A2 - X2
    L_i = np.hypot(ui, vi)
    L_o = np.hypot(X1, X2)
    delta_i = L_i - (fi - 0.5) * D  # [1], Eq. 3.10
    delta_o = L_o - (fo - 0.5) * D  # [1], Eq. 3.11
    return delta_i, delta_o, ui / L_i, vi / L_i, X1 / L_o, X2 / L_o, L_i, L_o


def hertz_load(K, delta):
    """Hertz normal load Q = K max(delta, 0)^1.5 [N] ([4] Eq. 6.39); zero when the contact opens."""
    d = np.maximum(delta, 0.0)
    return K * d * np.sqrt(d)


def centrifugal_force(m, R_b, omega_m):
    """Ball centrifugal force F_c = m R_b omega_m^2 [N] ([1] Eq. 3.1, with R_b = d_m/2 there).

    m : ball mass [kg]; R_b : radius of the ball-centre orbit [m];
    omega_m : ball orbital speed [rad/s].
    """
    return m * R_b * np.square(omega_m)  # [1], Eq. 3.1


#: Standard gravity [m/s^2] (the ball weight of :func:`unloaded_force_scale`).
STANDARD_GRAVITY = 9.80665


def unloaded_force_scale(Z, m, D, dm, alpha0, omega_i, omega_o, centrifugal=True):
    """Force scale [N] of a bearing carrying no applied load: Z (m g + F_c), the weight of the balls plus
    their centrifugal force at the pure-rolling cage speed.

    The quasi-static equations neglect the ball weight, so a ring residual far below Z m g says nothing
    about the bearing; and the round-off of the ball force balances, which carry F_c at the outer contact
    whatever the applied load, sets the smallest ring residual the solver can reach.  It is therefore the
    absolute floor of the residual tolerance (a load below ``tol`` times it is answered by the unloaded
    limit).  F_c = m (d_m/2) omega_m^2 ([1] Eq. 3.1) with the cage (orbital) speed of pure rolling
    omega_m = [omega_i (1 - gamma) + omega_o (1 + gamma)]/2, gamma = D cos(alpha_0)/d_m ([3] Eq. 8.21 with
    beta = 0 and the free contact angle).
    """
    gamma = D * np.cos(alpha0) / dm
    omega_m = 0.5 * (omega_i * (1.0 - gamma) + omega_o * (1.0 + gamma))  # [3], Eq. 8.21
    Fc = centrifugal_force(m, 0.5 * dm, omega_m) if centrifugal else 0.0  # [1], Eq. 3.1
    return float(Z * (m * STANDARD_GRAVITY + Fc))


def gyroscopic_moment(J, omega_m, omega_y):
    """Gyroscopic moment M_g = J omega_m omega_y [N m] about the circumferential axis e_t.

    J : ball moment of inertia about a diameter [kg m^2]; omega_m : orbital
    speed [rad/s]; omega_y : radial component of the ball angular velocity
    [rad/s].  With omega_y = -omega_R sin(beta) this is [1] Eq. 3.2
    (M_g = J omega_R omega_m sin beta) with the sign of the present frame:
    it is the rate of change dH/dt of the ball's angular momentum carried
    round the bearing axis, which the contact friction forces must supply.
    """
    return J * omega_m * omega_y  # [1], Eq. 3.2


def gyroscopic_friction(Mg, D, lam_i, lam_o):
    """Friction forces (F_i, F_o) [N] at the contacts that supply the gyroscopic moment.

    F_i acts on the ball along t_i = (cos a_i, -sin a_i), F_o along
    t_o = (cos a_o, -sin a_o).  Their moment about the ball centre is
    (D/2)(F_i - F_o) e_t = M_g e_t when lam_i + lam_o = 2 ([1] Eqs. 3.14-3.15:
    lambda_i M_g / D and lambda_o M_g / D).
    """
    return lam_i * Mg / D, -lam_o * Mg / D  # [1], Eqs. 3.14-3.15


def race_control_kinematics(omega_i, omega_o, R_b, D, sin_ai, cos_ai, sin_ao, cos_ao, control="outer_race_control"):
    """Ball kinematics by raceway control (Jones [2]; [3] Ch. 8).

    Unknowns per ball: the orbital speed omega_m and the ball angular
    velocity relative to the cage (omega_x, omega_y) in (e_X, e_r) (no yaw).
    Three linear conditions: no rolling-direction slip at the centre of the
    inner and of the outer contact, and no spin at the controlling contact.

    Parameters
    ----------
    omega_i, omega_o : ring speeds about X [rad/s].
    R_b : radius of the ball-centre orbit [m].
    control : ``"outer_race_control"``, ``"inner_race_control"`` or a boolean
        array (True = outer control) per ball.

    Returns
    -------
    omega_m, omega_x, omega_y [rad/s] (arrays over balls).

    Notes
    -----
    The contact point of the outer race is at R_b + (D/2) cos a_o from the
    axis, the inner one at R_b - (D/2) cos a_i.  Rolling condition at a
    contact r (relative to the ball centre) with a race turning at Omega
    relative to the cage: (omega_b x r) . e_t = Omega rho.  Spin at a contact:
    (omega_b - Omega e_X) . n.  For R_b = d_m/2 and outer control this
    reproduces [3] Eq. 8.40: tan beta = sin a_o / (cos a_o + D/d_m), with
    omega = omega_R (cos beta, -sin beta) and the cage speed of [3] Eq. 8.21
    when the contact angles are equal.
    """
    h = 0.5 * D
    rho_o = R_b + h * cos_ao
    rho_i = R_b - h * cos_ai
    n = np.shape(R_b * sin_ai)
    M = np.zeros(n + (3, 3))
    rhs = np.zeros(n + (3,))
    # unknown vector u = (omega_x, omega_y, omega_m)
    # outer rolling: h (wx cos_ao - wy sin_ao) - (omega_o - omega_m) rho_o = 0
    M[..., 0, 0] = h * cos_ao
    M[..., 0, 1] = -h * sin_ao
    M[..., 0, 2] = rho_o
    rhs[..., 0] = omega_o * rho_o
    # inner rolling: -h (wx cos_ai - wy sin_ai) - (omega_i - omega_m) rho_i = 0
    M[..., 1, 0] = -h * cos_ai
    M[..., 1, 1] = h * sin_ai
    M[..., 1, 2] = rho_i
    rhs[..., 1] = omega_i * rho_i
    if isinstance(control, str):
        if control not in ("outer_race_control", "inner_race_control"):
            raise ValueError(f"unknown race control {control!r} (outer_race_control, inner_race_control)")
        outer = np.full(n, control == "outer_race_control")
    else:
        outer = np.broadcast_to(np.asarray(control, dtype=bool), n)
    # no spin at the controlling contact, e.g. outer: wx sin_ao + wy cos_ao - (omega_o - omega_m) sin_ao = 0
    s_c = np.where(outer, sin_ao, sin_ai)
    c_c = np.where(outer, cos_ao, cos_ai)
    M[..., 2, 0] = s_c
    M[..., 2, 1] = c_c
    M[..., 2, 2] = s_c
    rhs[..., 2] = np.where(outer, omega_o, omega_i) * s_c
    u = np.linalg.solve(M, rhs[..., None])[..., 0]
    return u[..., 2], u[..., 0], u[..., 1]


def gyroscopic_split(outer_control):
    """(lambda_i, lambda_o) per ball from the controlling race ([1] Eqs. 3.14-3.15, :data:`LAMBDA_SPLIT`)."""
    oc = np.asarray(outer_control, dtype=bool)
    (li_o, lo_o), (li_i, lo_i) = LAMBDA_SPLIT["outer_race_control"], LAMBDA_SPLIT["inner_race_control"]
    return np.where(oc, li_o, li_i), np.where(oc, lo_o, lo_i)


def race_control_criterion(Qi, a_i, E_i, Qo, a_o, E_o, alpha_i, alpha_o):
    """Jones' raceway-control criterion: True where the outer raceway controls the ball.

    Outer control when Q_o a_o E(e_o) cos(alpha_i - alpha_o) > Q_i a_i E(e_i)
    ([2]; [3] Ch. 8, "raceway control").  Q a E is proportional to the largest
    spinning friction moment a contact can transmit (3/8 mu Q a E for a
    uniform friction coefficient): the race that can resist more spin
    imposes pure rolling, the ball spins on the other.  a = semi-major axis
    [m], E = complete elliptic integral of the second kind [-].
    """
    return race_control_ratio(Qi, a_i, E_i, Qo, a_o, E_o, alpha_i, alpha_o) > 1.0


def race_control_ratio(Qi, a_i, E_i, Qo, a_o, E_o, alpha_i, alpha_o):
    """Margin of Jones' raceway-control criterion [-]: Q_o a_o E(e_o) cos(a_i - a_o) / (Q_i a_i E(e_i)).

    Parameters
    ----------
    Qi, Qo : normal contact loads [N].
    a_i, a_o : contact-ellipse semi-major axes [m].
    E_i, E_o : complete elliptic integrals of the second kind of the contacts [-].
    alpha_i, alpha_o : contact angles [rad].

    Returns
    -------
    ratio [-]: > 1 the outer raceway controls the ball, < 1 the inner one
    ([2]; [3] Ch. 8); inf where only the outer contact is loaded, 0 where
    the outer one (or both) is unloaded.  The ratio shows how close a
    solution is to the switch of the controlling raceway, where race-control
    theory jumps (docs/quasistatic.md, "Comparison with independent codes").
    """
    num = Qo * a_o * E_o * np.cos(alpha_i - alpha_o)
    den = Qi * a_i * E_i
    with np.errstate(divide="ignore", invalid="ignore"):
        return np.where(den > 0, num / np.where(den > 0, den, 1.0), np.where(num > 0, np.inf, 0.0))


def contact_spin_roll(omega_x, omega_y, omega_m, omega_i, omega_o, sin_ai, cos_ai, sin_ao, cos_ao):
    """Spin and roll angular speeds of the ball relative to each race [rad/s].

    Returns ``(spin_i, roll_i, spin_o, roll_o)``: components of the ball
    angular velocity relative to the race (both seen from the cage frame)
    along the contact normal (spin) and along the in-plane tangent (roll).
    The spin-to-roll ratio of [3] Eqs. 8.44-8.45 is spin/roll.
    """
    wi_x = omega_x - (omega_i - omega_m)
    wo_x = omega_x - (omega_o - omega_m)
    spin_i = wi_x * sin_ai + omega_y * cos_ai
    roll_i = wi_x * cos_ai - omega_y * sin_ai
    spin_o = wo_x * sin_ao + omega_y * cos_ao
    roll_o = wo_x * cos_ao - omega_y * sin_ao
    return spin_i, roll_i, spin_o, roll_o


def ball_equilibrium_residual(Qi, Qo, sin_ai, cos_ai, sin_ao, cos_ao, Fc, Fi, Fo):
    """Axial and radial force balance of each ball [N] ([1] Eqs. 3.14-3.15).

    Sum of the forces on the ball in (e_X, e_r):
    Q_i e_i - Q_o e_o + F_i t_i + F_o t_o + F_c e_r = 0, with
    t = (cos a, -sin a).  Returns ``(r_axial, r_radial)``.
    """
    r_ax = Qi * sin_ai - Qo * sin_ao + Fi * cos_ai + Fo * cos_ao  # [1], Eq. 3.14
    r_rad = Qi * cos_ai - Qo * cos_ao - Fi * sin_ai - Fo * sin_ao + Fc  # [1], Eq. 3.15
    return r_ax, r_rad


def inner_ring_reaction(Qi, Fi, sin_ai, cos_ai, psi, x_i0, R_i, r_i):
    """Force and moment of each ball on the inner ring, shape (5, Z) ([1] Eqs. 3.20-3.24).

    Parameters
    ----------
    Qi, Fi : inner normal load and gyroscopic friction force [N] per ball
        (the ring receives -(Q_i e_i + F_i t_i)).
    sin_ai, cos_ai : inner contact angle.  psi : ball azimuths [rad].
    x_i0, R_i : axial position and radius of the inner groove curvature
        centre of the unloaded ring [m] (:func:`groove_centre_layout`).
    r_i : inner groove radius f_i D [m].

    Returns
    -------
    rows (F_x, F_y, F_z, M_y, M_z) [N, N m] per ball.  Equilibrium of the
    ring: applied load + sum over balls = 0.

    Notes
    -----
    Moments are taken about the bearing centre with the arms of the
    undisplaced ring, as in [1] Eqs. 3.23-3.24 (arm R_i of the groove-centre
    locus): the normal force acts along a line through the inner groove
    curvature centre, the friction force at the contact point
    (groove centre - r_i e_i).  This is the statics that is work-conjugate to
    the linearised ring kinematics of :func:`groove_centre_separation`, so the
    static stiffness matrix is exactly symmetric.
    """
    f_ax = -(Qi * sin_ai + Fi * cos_ai)
    f_rad = -(Qi * cos_ai - Fi * sin_ai)
    c, s = np.cos(psi), np.sin(psi)
    fx, fy, fz = f_ax, f_rad * c, f_rad * s
    px = x_i0 - r_i * sin_ai  # contact point, axial
    pr = R_i - r_i * cos_ai  # contact point, radius
    py, pz = pr * c, pr * s
    My = pz * fx - px * fz  # [1], Eq. 3.23 (r x F, Y component)
    Mz = px * fy - py * fx  # [1], Eq. 3.24 (r x F, Z component)
    return np.stack([fx, fy, fz, My, Mz])


def axial_static_single_ball(Fa, Z, D, dm, fi, fo, alpha0, stiffness: ContactStiffness, tol=1e-15):
    """Closed-form static pure-axial solution: contact angle alpha [rad] and ball load Q [N].

    Solves [4] Eq. 7.13 (Harris): Fa / Z = Q sin(alpha) with
    Q = K_n (B D)^1.5 (cos a0 / cos a - 1)^1.5, where the total approach of
    one ball is delta_n = B D (cos a0/cos a - 1) and 1/K_n^(2/3) =
    1/K_i^(2/3) + 1/K_o^(2/3) (both K at the loaded angle alpha) -- by
    bisection on alpha in (alpha0, 90 deg).
    """
    A = (fi + fo - 1.0) * D
    if Fa <= 0:
        return alpha0, 0.0

    def load(a):
        Ki, Ko = stiffness.K(np.cos(a), np.cos(a))
        Kn = (Ki ** (-2.0 / 3.0) + Ko ** (-2.0 / 3.0)) ** -1.5
        dn = A * (np.cos(alpha0) / np.cos(a) - 1.0)
        return Z * Kn * max(dn, 0.0) ** 1.5 * np.sin(a)  # [4], Eq. 7.13

    lo, hi = alpha0, 0.5 * np.pi - 1e-9
    for _ in range(200):
        mid = 0.5 * (lo + hi)
        if load(mid) < Fa:
            lo = mid
        else:
            hi = mid
        if hi - lo < tol:
            break
    a = 0.5 * (lo + hi)
    return a, Fa / (Z * np.sin(a))
