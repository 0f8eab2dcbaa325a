"""Sliding friction torque of deep-groove ball bearings with pure rolling lines (dgbb_prl).

M_sl = M_s + M_r + M_d                                         ([S], Eq. 1)

spinning (M_s), differential sliding due to ball rotation (M_r) and due to
the orbital motion (M_d), from the contact loads, contact angles and contact
ellipses of a (quasi-)static solution.

What the seed transcript lost and how it is rebuilt here
--------------------------------------------------------
The transcript of dgbb_prl keeps Eq. 1, Eq. 7 (2-PRL spinning moment) and a
fragment of Eq. 10 (2-PRL friction force); the kinematic relations (Eqs. 3-4,
11), the rotation moment (Eq. 13), the orbital slip distances (Eqs. 16-19),
the equilibrium (Eqs. 20-23, 29) and the c-value updates (Eqs. 24-28) are
missing.  They are rebuilt from the sources the seed cites:

* Strip theory of the contact ([H], Ch. "Friction in rolling bearings";
  [Ho]; [TH]): the load per unit length across the contact is
  q(x) = (3 Q / 4 a) (1 - (x/a)^2) and each strip carries the rolling-direction
  friction mu q(x) sign(v_y(x)); the slip v_y(x) changes sign on the pure
  rolling lines x = c a.  With 2 PRLs c2 < c1 inside the contact the net force
  and spinning moment are (closed forms of :func:`strip_force_2prl`,
  :func:`strip_spin_moment_2prl`):
      F  = mu Q [1 - 3/2 ((c1 - c2) - (c1^3 - c2^3)/3)]            ([S], Eq. 10)
      m_s = 3/8 mu Q a [2 (c2^2 - c1^2) - (c2^4 - c1^4)]            ([S], Eq. 7)
  and with one PRL c inside (1-PRL case, [S] Eqs. 6, 9)
      F  = 3/2 mu Q (c - c^3/3),  m_s = 3/8 mu Q a (1 - c^2)^2
  (:func:`strip_force_1prl`, :func:`strip_spin_moment_1prl`).  The numerical
  solution integrates the same strip integrals exactly on a line across the
  contact, each cell split at the PRL (:func:`_signed_line_weights`).
* Slip kinematics ([H], Ch. "Ball motions and sliding friction"; [J]):
  in the frame turning with the ball set, the ball turns with omega_B about
  its centre and race k with (omega_k - omega_m) about the bearing axis; the
  deformed contact surface is a circular arc of radius
  R_k = 2 r_k D / (2 r_k + D) across the contact ([H], "radius of the
  deformed surface"; [S] "Hertzian radius").  The slip at a point P of the
  contact is v = omega_B x P - Omega_k x (P - A0); it is a quadratic in x
  whose two roots are the PRLs c1, c2 ([S], Eq. 11: c1 + c2 fixed by the
  spin-to-roll ratio and R_k).
* Ball equilibrium ([S], Eqs. 20-22, 29; [H]): the unknown ball rotation
  (two components) and orbital speed are found such that the friction moments
  on the ball balance about x' and z' and the rolling-direction friction
  forces of the inner and outer contacts cancel ("input torque = output
  torque" of each ball, no cage force).  Instead of Harris' / the seed's
  fixed-point update of the c-values, the three equations are solved by
  Newton iteration on the (smoothly regularised) strip integrals; at the
  solution the c-values are those of the updated c-value method.  Gyroscopic
  moments and centrifugal forces are neglected (the seed: "may be neglected
  in DGBBs"; its Tables 2-4 give the same torque at 5000 and 15000 r/min).
* Torque from power: the inner-ring friction torque is the dissipated power
  over the inner-ring speed.  The power of each contact is split exactly into
  spinning (m_s omega_s, [S] Eq. 8), differential sliding due to the ball
  rotation (the ball-surface velocity across the curved contact, plus the
  rigid slip at the contact centre) and due to the orbital motion (the race
  surface velocity across the curved groove, [S] Eqs. 16-19, Kakuta [K]).

References
----------
[S] dgbb_prl (``/work/shared/seeds/003_*.txt``): estimation of the sliding
    friction torque of deep-groove ball bearings with pure rolling lines and
    an updated c-value method; Tables 2-4.
[H] Harris T. A., Kotzalas M. N., *Rolling Bearing Analysis*, 5th ed., Vol. 2,
    Ch. 2 (ball motions and sliding friction, rolling-direction strip theory)
    and Ch. 6 (friction in rolling bearings).
[J] Jones A. B., "Ball motion and sliding friction in ball bearings",
    J. Basic Eng. 81 (1959) 1-12.
[Ho] Houpert L., "Ball bearing and tapered roller bearing torque: analytical,
    numerical and experimental results", Tribol. Trans. 45 (2002) 345-353.
[TH] Tong V.-C., Hong S.-W., "Improved formulation for running torque in
    angular contact ball bearings", Int. J. Precis. Eng. Manuf. 19 (2018) 47-56.
[K] Kakuta K., "The effects of bearing dimensions and clearance on the
    running torque of ball bearings", J. JSLE (1960s) -- differential slip on
    a curved groove.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np
from numpy.polynomial.legendre import leggauss
from scipy.optimize import fsolve

from hsbearing.errors import SolverError

__all__ = [
    "deformed_radius",
    "strip_force_2prl",
    "strip_force_1prl",
    "strip_spin_moment_2prl",
    "strip_spin_moment_1prl",
    "spinning_moment_pure_spin",
    "jones_prl_symmetric",
    "heathcote_integral",
    "heathcote_slip_power",
    "ContactState",
    "BallFriction",
    "solve_ball",
    "static_load_distribution",
]


# --------------------------------------------------------------------------- closed forms (strip theory)


def deformed_radius(r_groove, D):
    """Radius of the deformed contact surface across the contact R_k [m] = 2 r D / (2 r + D).

    [H], Vol. 2, Ch. 2 (radius of the pressure surface of a ball in a groove of
    radius r = f D); the seed's "Hertzian contact radius" R_k ([S], Eq. 11).
    """
    return 2.0 * r_groove * D / (2.0 * r_groove + D)  # [H]


def _G(c):
    """Primitive of (1 - xi^2): xi - xi^3/3."""
    return c - c**3 / 3.0


def strip_force_2prl(c1, c2):
    """Net rolling-direction friction force of a contact with 2 PRLs, per mu Q [-].

    F / (mu Q) = 1 - 3/2 [(c1 - c2) - (c1^3 - c2^3)/3]  for -1 <= c2 <= c1 <= 1,
    slip of one sign outside [c2, c1] and the other inside ([S], Eq. 10 as
    rebuilt by strip theory, [H], [Ho]).  Positive = direction of the slip
    outside the PRLs.
    """
    c1 = np.asarray(c1, dtype=float)
    c2 = np.asarray(c2, dtype=float)
    return 1.0 - 1.5 * (_G(c1) - _G(c2))  # [S], Eq. 10


def strip_force_1prl(c):
    """Net rolling-direction friction force with one PRL at xi = c inside, per mu Q [-].

    Slip of one sign on (-1, c), the other on (c, 1):
    F / (mu Q) = 3/4 [(G(c) - G(-1)) - (G(1) - G(c))] = 3/2 G(c) = 3/2 (c - c^3/3)
    ([S], Eq. 9 as rebuilt by strip theory).
    """
    c = np.asarray(c, dtype=float)
    return 1.5 * _G(c)  # [S], Eq. 9


def strip_spin_moment_2prl(c1, c2, a):
    """Spinning moment of a contact with 2 PRLs, per mu Q [m].

    m_s / (mu Q) = 3/8 a [2 (c2^2 - c1^2) - (c2^4 - c1^4)]   ([S], Eq. 7; [Ho])
    (sign: moment of the strip forces about the contact centre, positive
    strips outside [c2, c1]).
    """
    c1 = np.asarray(c1, dtype=float)
    c2 = np.asarray(c2, dtype=float)
    return 0.375 * a * (2.0 * (c2**2 - c1**2) - (c2**4 - c1**4))  # [S], Eq. 7


def strip_spin_moment_1prl(c, a):
    """Spinning moment with one PRL at xi = c, per mu Q [m] (strips negative on (-1, c), positive on (c, 1)).

    m_s / (mu Q) = 3/4 a [ (H(1) - H(c)) - (H(c) - H(-1)) ] = 3/8 a (1 - c^2)^2 ... written
    as 3/8 a [1 - 2 c^2 + c^4], H(xi) = xi^2/2 - xi^4/4   ([S], Eq. 6 as rebuilt).
    """
    c = np.asarray(c, dtype=float)
    return 0.375 * a * (1.0 - 2.0 * c**2 + c**4)  # [S], Eq. 6


def spinning_moment_pure_spin(mu, Q, a, E2):
    """Spinning moment of pure spin m_s [N m] = 3/8 mu Q a xi(e) ([S], Eq. 5; [H]; [J]).

    E2 : complete elliptic integral of the second kind of modulus (1 - b^2/a^2)^0.5.
    """
    return 0.375 * mu * Q * a * E2  # [S], Eq. 5


def jones_prl_symmetric():
    """Symmetric PRL location c* [-] (|x| = c* a) of a contact with zero net rolling-direction force.

    Strip theory with the Hertz line load and a slip quadratic in x: 2-PRL force (Eq. 10 with
    c2 = -c1) zero <=> 3 c - c^3 = 1, c* = 0.34730 ([J]; [H], Ch. 2, "0.347 a").
    """
    # root of c^3 - 3c + 1 = 0 in (0, 1): c = 2 cos(4 pi / 9)
    return 2.0 * math.cos(4.0 * math.pi / 9.0)  # [J]


def heathcote_integral(c):
    """I(c) = int_-1^1 3/4 (1 - xi^2) |xi^2 - c^2| dxi = 1/5 - c^2 + 2 c^3 - 2 c^5 / 5  [-].

    Hertz strip load times the magnitude of a quadratic (Heathcote) slip with PRLs at +-c a;
    minimal at c = c* (:func:`jones_prl_symmetric`), I(c*) = 0.16114.
    """
    c = np.asarray(c, dtype=float)
    return 0.2 - c**2 + 2.0 * c**3 - 0.4 * c**5  # [H], Ch. 2 (strip theory)


def heathcote_slip_power(Q, a, R, omega_rel, mu=1.0):
    """Differential-slip (Heathcote) power of one contact at zero contact angle [W].

    P = mu Q a^2 omega_rel / (2 R) I(c*): rolling-direction slip v = omega_rel (x^2 - c*^2 a^2) / (2 R)
    across a contact whose deformed surface has radius R ([H], Ch. 2; [J]; [S] Eqs. 16-19 in
    substance).  omega_rel [rad/s] is |omega_B + Omega_k| at the inner and |omega_B - Omega_k| at
    the outer race (cage frame: ball rotation and race speed relative to the cage); Q [N], a, R [m].
    Used as the independent check of the numerical solution under pure radial load.
    """
    return mu * Q * a**2 * omega_rel / (2.0 * R) * heathcote_integral(jones_prl_symmetric())  # [H], Ch. 2


# --------------------------------------------------------------------------- contact states


@dataclass(frozen=True)
class ContactState:
    """Loads and geometry of one ball's two contacts (SI).  Index 0 = inner, 1 = outer."""

    Q: tuple[float, float]  #: normal loads [N]
    alpha: tuple[float, float]  #: contact angles [rad]
    a: tuple[float, float]  #: semi-major (transverse) axes [m]
    b: tuple[float, float]  #: semi-minor (rolling-direction) axes [m]
    R: tuple[float, float]  #: deformed-surface radii across the contact [m]


@dataclass(frozen=True)
class BallFriction:
    """Friction result of one ball at unit friction coefficient and unit inner-ring speed.

    Powers are per (mu omega_i) [N m], i.e. torque contributions per unit mu.
    """

    spin_power: float  #: spinning (both contacts) [N m per mu]
    rotation_power: float  #: differential sliding due to ball rotation (+ centre slip) [N m per mu]
    orbital_power: float  #: differential sliding due to orbital motion [N m per mu]
    omega_ball: np.ndarray  #: ball angular velocity per omega_i, cage frame (x', y', z') [-]
    omega_m: float  #: orbital speed per omega_i [-]
    spin_moment: tuple[float, float]  #: m_s,k per mu [N m] (inner, outer)
    spin_speed: tuple[float, float]  #: omega_s,k per omega_i [-]
    friction_force: tuple[float, float]  #: rolling-direction friction forces on the ball per mu [N]
    prl: tuple[tuple[float, float], tuple[float, float]]  #: (c1, c2) per contact, nan if outside
    inner_ring_torque: float  #: torque of the friction on the inner ring about the axis per mu [N m]
    residual: float  #: max |equilibrium residual| / (Q D/2) at the solution
    contact_powers: tuple = ((0.0, 0.0, 0.0), (0.0, 0.0, 0.0))  #: (spin, rotation, orbital) per contact (inner, outer) [N m per mu]

    @property
    def total(self) -> float:
        return self.spin_power + self.rotation_power + self.orbital_power


_NX, _NY = 96, 12
_XI, _WX = leggauss(_NX)
_ETA, _WY = leggauss(_NY)


def _contact_grid(n, t, R, a, b, D):
    """Quadrature points on the deformed contact surface and weights of p dA per Q.

    Returns P (N,3) points relative to the ball centre, normals (N,3), w (N,)
    with sum(w) = 1 (Hertz pressure), and xi (N,) transverse coordinate / a.
    """
    X, E = np.meshgrid(_XI, _ETA, indexing="ij")
    W = np.outer(_WX, _WY)
    x = a * X
    s = np.sqrt(np.clip(1.0 - X**2, 0.0, None))
    y = b * s * E
    # Hertz pressure p = 3Q/(2 pi a b) sqrt(1 - xi^2 - (y/b)^2); dA = a b s dxi deta
    p_over_Q = 1.5 / (math.pi * a * b) * s * np.sqrt(np.clip(1.0 - E**2, 0.0, None))
    w = (p_over_Q * a * b * s * W).ravel()
    c = 0.5 * D * n
    O = c - R * n
    th = (x / R).ravel()
    normals = np.cos(th)[:, None] * n[None, :] + np.sin(th)[:, None] * t[None, :]
    P = O[None, :] + R * normals + y.ravel()[:, None] * np.array([0.0, 1.0, 0.0])[None, :]
    return P, normals, w / w.sum(), X.ravel()


def _slip_basis(P, normals, race_speed, A0):
    """Tangential slip at P as s = s0 + S @ u, u = (w_Bx, w_Bz, w_m) (per omega_i)."""
    ex = np.array([1.0, 0.0, 0.0])
    ez = np.array([0.0, 0.0, 1.0])
    ball_x = np.cross(ex, P)  # omega_B = w_Bx e_x + w_Bz e_z
    ball_z = np.cross(ez, P)
    race = np.cross(ex, P - A0)  # race velocity = (race_speed - w_m) e_x x (P - A0)
    s0 = -race_speed * race
    cols = [ball_x, ball_z, race]

    def tang(v):
        return v - np.sum(v * normals, axis=1)[:, None] * normals

    return tang(s0), [tang(cvec) for cvec in cols]


_NLINE = 1601


def _trapezoid_weights(x):
    """Trapezoid weights on the nodes x."""
    h = np.diff(x)
    w = np.zeros_like(x)
    w[:-1] += 0.5 * h
    w[1:] += 0.5 * h
    return w


def _signed_line_weights(v, x):
    """Weights W with sum(W f) = integral of sign(v(x)) f(x) dx, exact for piecewise-linear v and f.

    Each cell whose end values of v differ in sign is split at the linear root
    (the pure rolling line); each part is integrated by the trapezoid rule.
    """
    h = np.diff(x)
    sg = np.where(v >= 0.0, 1.0, -1.0)
    s0, s1 = sg[:-1], sg[1:]
    v0, v1 = v[:-1], v[1:]
    cross = s0 != s1
    with np.errstate(invalid="ignore", divide="ignore"):
        th = np.where(cross, v0 / (v0 - v1), 1.0)
    th = np.clip(th, 0.0, 1.0)
    # part 1 on [x_k, x_r] with sign s0, part 2 on [x_r, x_k+1] with sign s1; f_r = (1-th) f_k + th f_k+1
    c0 = s0 * th * h / 2 * (2.0 - th) + s1 * (1.0 - th) * h / 2 * (1.0 - th)
    c1 = s0 * th * h / 2 * th + s1 * (1.0 - th) * h / 2 * (1.0 + th)
    W = np.zeros_like(x)
    W[:-1] += c0
    W[1:] += c1
    return W


def _prl_roots(vy_line, xi_line):
    """Roots of the rolling-direction slip along the major axis -> (c1 >= c2), nan if absent."""
    roots = []
    for k in range(len(xi_line) - 1):
        f0, f1 = vy_line[k], vy_line[k + 1]
        if f0 == 0.0:
            roots.append(xi_line[k])
        elif f0 * f1 < 0.0:
            roots.append(xi_line[k] - f0 * (xi_line[k + 1] - xi_line[k]) / (f1 - f0))
    roots = sorted(roots, reverse=True)[:2]
    while len(roots) < 2:
        roots.append(float("nan"))
    return float(roots[0]), float(roots[1])


def solve_ball(state: ContactState, D: float, dm: float, outer_speed_ratio: float = 0.0,
               traction: str = "strip", eps: float = 1e-6) -> BallFriction:
    """Friction kinematics and power of one ball (per unit mu and unit inner-ring speed).

    Parameters
    ----------
    state : loads, contact angles, ellipses and deformed radii of the ball's contacts.
    D, dm : ball and pitch diameter [m].
    outer_speed_ratio : outer-ring speed / inner-ring speed [-] (0: outer ring fixed).
    traction : ``"strip"`` -- rolling-direction strip theory of [S], [H] (the
        slip's rolling component sets the sign of each strip's friction);
        ``"full"`` -- Coulomb traction along the full 2-D slip direction ([S], Eq. 2).
    eps : regularisation of sign(v) as v / sqrt(v^2 + (eps omega_i d_m/2)^2).

    Returns
    -------
    BallFriction.  Unknowns (ball rotation in the x'-z' plane, orbital speed)
    solve the x'/z' moment balance and the rolling-direction force balance
    ([S], Eqs. 20-22, 29).
    """
    if traction not in ("strip", "full"):
        raise ValueError(f"unknown traction model {traction!r} (strip, full)")
    ey = np.array([0.0, 1.0, 0.0])
    A0 = np.array([0.0, 0.0, -0.5 * dm])
    race_speeds = (1.0, outer_speed_ratio)
    vref_box = [eps * 0.5 * dm]
    contacts = []
    for k in range(2):
        Q = state.Q[k]
        if Q <= 0.0 or state.a[k] <= 0.0:
            contacts.append(None)
            continue
        al = state.alpha[k]
        n = np.array([math.sin(al), 0.0, math.cos(al)]) * (1.0 if k == 1 else -1.0)
        t = np.cross(ey, n)
        t /= np.linalg.norm(t)
        # line along the major axis (y = 0): PRLs, and the whole strip-theory integral
        xl = np.linspace(-1.0, 1.0, _NLINE)
        th = xl * state.a[k] / state.R[k]
        nl = np.cos(th)[:, None] * n + np.sin(th)[:, None] * t
        Pl = (0.5 * D * n - state.R[k] * n) + state.R[k] * nl
        s0l, colsl = _slip_basis(Pl, nl, race_speeds[k], A0)
        if traction == "strip":
            # strip theory: traction along e_y with the sign of v_y, and v_y does not depend on y,
            # so the contact integral is the line integral of q(xi) = 3/4 (1 - xi^2) ([S], [H])
            P, normals, s0, cols = Pl, nl, s0l, colsl
            w = _trapezoid_weights(xl) * 0.75 * (1.0 - xl**2)
        else:
            P, normals, w, xi = _contact_grid(n, t, state.R[k], state.a[k], state.b[k], D)
            s0, cols = _slip_basis(P, normals, race_speeds[k], A0)
        contacts.append(dict(Q=Q, n=n, cpt=0.5 * D * n, t=t, P=P, normals=normals, w=w, s0=s0, cols=cols,
                             s0l=s0l, colsl=colsl, xl=xl, race_speed=race_speeds[k], a=state.a[k]))
    live = [c for c in contacts if c is not None]
    if len(live) < 2:
        # unloaded ball (or pressed on the outer race by its centrifugal force only): it is carried
        # by the cage and transmits no friction torque to the inner ring in this model
        zero2 = (0.0, 0.0)
        return BallFriction(0.0, 0.0, 0.0, np.zeros(3), float("nan"), zero2, zero2, zero2,
                            ((float("nan"),) * 2,) * 2, 0.0, 0.0)

    def traction_on_ball(c, u):
        vref = vref_box[0]
        s = c["s0"] + sum(ui * col for ui, col in zip(u, c["cols"]))
        if traction == "strip":
            vy = s[:, 1]
            if vref > 0.0:
                g = c["w"] * vy / np.sqrt(vy * vy + vref * vref)
            else:  # exact sign integration, split at the pure rolling lines
                g = _signed_line_weights(vy, c["xl"]) * 0.75 * (1.0 - c["xl"] ** 2)
            tau = -(c["Q"] * g)[:, None] * ey[None, :]
        else:
            mag = np.sqrt(np.sum(s * s, axis=1) + vref * vref)
            tau = -(c["Q"] * c["w"] / mag)[:, None] * s
        return s, tau

    Qs = 0.5 * D * max(c["Q"] for c in live)

    def residual(u, jac=False):
        M = np.zeros(3)
        Fy = 0.0
        J = np.zeros((3, 3))
        vref = vref_box[0]
        for c in live:
            s, tau = traction_on_ball(c, u)
            M += np.cross(c["P"], tau).sum(axis=0)
            Fy += tau[:, 1].sum()
            if jac:
                for i, col in enumerate(c["cols"]):
                    if traction == "strip":
                        vy = s[:, 1]
                        dg = vref * vref / (vy * vy + vref * vref) ** 1.5
                        dtau = -(c["Q"] * c["w"] * dg * col[:, 1])[:, None] * ey[None, :]
                    else:
                        m = np.sqrt(np.sum(s * s, axis=1) + vref * vref)
                        sd = np.sum(s * col, axis=1)
                        dtau = -(c["Q"] * c["w"])[:, None] * (col / m[:, None] - s * (sd / m**3)[:, None])
                    dM = np.cross(c["P"], dtau).sum(axis=0)
                    J[:, i] += [dM[0], dM[2], dtau[:, 1].sum() * 0.5 * D]
        r = np.array([M[0], M[2], Fy * 0.5 * D]) / Qs
        return (r, J / Qs) if jac else r

    def newton(u, tol=1e-11, maxit=100):
        r, J = residual(u, jac=True)
        nr = np.max(np.abs(r))
        for _ in range(maxit):
            if nr < tol:
                break
            try:
                du = np.linalg.solve(J, -r)
            except np.linalg.LinAlgError:
                du = np.linalg.lstsq(J, -r, rcond=None)[0]
            lam = 1.0
            while lam > 1e-6:
                un = u + lam * du
                rn = residual(un)
                if np.max(np.abs(rn)) < (1.0 - 1e-4 * lam) * nr:
                    break
                lam *= 0.5
            u = un
            r, J = residual(u, jac=True)
            nr = np.max(np.abs(r))
        return u, nr

    # continuation in the regularisation: smooth first, then sharpen to eps
    u = _initial_guess(live, A0)
    msg = ""
    for e in sorted({1e-1, 3e-2, 1e-2, 3e-3, 1e-3, 3e-4, 1e-4, 3e-5, 1e-5, eps}, reverse=True):
        if e < eps:
            continue
        vref_box[0] = e * 0.5 * dm
        u, nr = newton(u)
        if nr > 1e-8:  # fall back to MINPACK at this level
            u2, info, ier, msg = fsolve(residual, u, full_output=True, xtol=1e-13)
            if np.max(np.abs(residual(u2))) < nr:
                u = u2
    if traction == "strip":
        # polish with the exact (unregularised) sign integration: piecewise smooth residual
        vref_box[0] = 0.0
        u2, info, ier, msg = fsolve(residual, u, full_output=True, xtol=1e-13)
        if np.max(np.abs(residual(u2))) <= np.max(np.abs(residual(u))):
            u = u2
    res = float(np.max(np.abs(residual(u))))
    if res > 1e-6:
        raise SolverError(f"ball friction equilibrium did not converge (residual {res:.2e} {msg.strip()})")
    omega_B = np.array([u[0], 0.0, u[1]])
    P_spin = P_rot = P_orb = 0.0
    m_s, w_s, F_y, prl = [0.0, 0.0], [0.0, 0.0], [0.0, 0.0], [(float("nan"),) * 2] * 2
    T_inner = 0.0
    cpow = [(0.0, 0.0, 0.0), (0.0, 0.0, 0.0)]
    for k, c in enumerate(contacts):
        if c is None:
            continue
        s, tau = traction_on_ball(c, u)
        n, P = c["n"], c["P"]
        Omega = (c["race_speed"] - u[2]) * np.array([1.0, 0.0, 0.0])
        cpt = 0.5 * D * n
        r = P - cpt
        # exact split of the slip: v = v(c) + w_s n x r + w_Bt x r - Omega_t x r
        ws = float(np.dot(omega_B - Omega, n))
        wBt = omega_B - np.dot(omega_B, n) * n
        Omt = Omega - np.dot(Omega, n) * n
        tang = lambda v: v - np.sum(v * c["normals"], axis=1)[:, None] * c["normals"]  # noqa: B023 - used in this iteration
        v_c = np.cross(omega_B, cpt) - np.cross(Omega, cpt - A0)
        v_spin = tang(ws * np.cross(n, r))  # spinning about the contact normal
        v_rot = tang(np.broadcast_to(v_c, r.shape))  # rigid slip of the ball at the contact centre
        v_orb = tang(np.cross(wBt - Omt, r))  # differential slip across the curved contact
        cp = (-float(np.sum(tau * v_spin)), -float(np.sum(tau * v_rot)), -float(np.sum(tau * v_orb)))
        cpow[k] = cp
        P_spin += cp[0]
        P_rot += cp[1]
        P_orb += cp[2]
        m_s[k] = float(np.dot(np.cross(r, tau).sum(axis=0), n))
        w_s[k] = ws
        F_y[k] = float(tau[:, 1].sum())
        if k == 0:  # torque on the inner ring about the bearing axis (reaction of the ball traction)
            T_inner = float(np.dot(np.cross(P - A0, -tau).sum(axis=0), np.array([1.0, 0.0, 0.0])))
        sl = c["s0l"] + sum(ui * col for ui, col in zip(u, c["colsl"]))
        prl[k] = _prl_roots(sl[:, 1], c["xl"])
    return BallFriction(
        spin_power=P_spin, rotation_power=P_rot, orbital_power=P_orb,
        omega_ball=omega_B, omega_m=float(u[2]), spin_moment=tuple(m_s), spin_speed=tuple(w_s),
        friction_force=tuple(F_y), prl=tuple(prl), inner_ring_torque=T_inner, residual=res,
        contact_powers=tuple(cpow),
    )


def _initial_guess(live, A0):
    """Zero centre slip (rolling direction) at both contacts + no spin on the outer race (Jones)."""
    rows, rhs = [], []
    ex = np.array([1.0, 0.0, 0.0])
    for c in live:
        # y-slip at the contact centre: (w_B x cpt)_y - (race - w_m)(e_x x (cpt - A0))_y = 0
        cpt = c["cpt"]
        bx = np.cross(ex, cpt)[1]
        bz = np.cross(np.array([0.0, 0.0, 1.0]), cpt)[1]
        rc = np.cross(ex, cpt - A0)[1]
        rows.append([bx, bz, rc])
        rhs.append(c["race_speed"] * rc)
    outer = live[-1]
    n = outer["n"]
    # spin on the outer race zero: (w_B - (race - w_m) e_x) . n = 0
    rows.append([n[0], n[2], n[0]])
    rhs.append(outer["race_speed"] * n[0])
    A = np.array(rows)
    try:
        return np.linalg.solve(A, np.array(rhs))
    except np.linalg.LinAlgError:
        return np.linalg.lstsq(A, np.array(rhs), rcond=None)[0]


# --------------------------------------------------------------------------- static load distribution


def static_load_distribution(Z, D, dm, fi, fo, Pd, E_ball, nu_ball, E_race, nu_race, Fa, Fr, M=0.0, tilt=True):
    """Rigid-ring static load distribution of a radial ball bearing (no centrifugal force).

    Harris & Kotzalas Vol. 1, Ch. 7 ([H], combined radial, axial and moment
    loading): the inner ring is displaced by (delta_a, delta_r) and tilted by
    theta about the axis normal to the radial load; the groove curvature
    centres of ball j at psi_j = 2 pi j / Z are separated by
    (delta_a + theta Rc_i cos psi_j, A - P_d/2 + delta_r cos psi_j) with
    Rc_i = d_m/2 + (f_i - 1/2) D cos(alpha_0) the locus of the inner groove
    curvature centres; contact angle alpha_j = atan2 of that vector,
    Q_j = K_j (s_j - A)^1.5 (K_j: inner and outer Hertz constants in series).
    Equilibrium: sum Q sin(alpha) = F_a, sum Q cos(alpha) cos(psi) = F_r and,
    with ``tilt=True``, sum Q sin(alpha) Rc_i cos(psi) = M (the seed's 5-DOF
    loading with the given moment, 0 by default); ``tilt=False`` holds the ring
    square (theta = 0, moment reacted elsewhere).

    Returns psi, Q, alpha (arrays over balls).
    """
    from hsbearing.models.geometry import curvature_radii
    from hsbearing.models.hertz import point_contact

    A = (fi + fo - 1.0) * D
    h0 = A - 0.5 * Pd
    alpha0 = math.acos(max(-1.0, min(1.0, h0 / A)))
    Rc = 0.5 * dm + (fi - 0.5) * D * math.cos(alpha0)
    psi = 2.0 * math.pi * np.arange(Z) / Z
    cpsi = np.cos(psi)

    def K_of(alpha):
        Rxi, Ryi, Rxo, Ryo = curvature_radii(D, dm, alpha, fi, fo)
        Ki = point_contact(Rxi, Ryi, 1.0, E_ball, nu_ball, E_race, nu_race).K
        Ko = point_contact(Rxo, Ryo, 1.0, E_ball, nu_ball, E_race, nu_race).K
        return (Ki ** (-2.0 / 3.0) + Ko ** (-2.0 / 3.0)) ** -1.5

    def loads(x):
        da, dr, th = x[0], x[1], (x[2] if tilt else 0.0)
        xa = da + th * Rc * cpsi
        zc = h0 + dr * cpsi
        s = np.hypot(xa, zc)
        al = np.arctan2(xa, zc)
        d = np.clip(s - A, 0.0, None)
        return K_of(al) * d**1.5, al

    def eqs(x):
        Q, al = loads(x)
        scale = max(Fa, Fr, abs(M) / Rc, 1.0)
        out = [(np.sum(Q * np.sin(al)) - Fa) / scale, (np.sum(Q * np.cos(al) * cpsi) - Fr) / scale]
        if tilt:
            out.append((np.sum(Q * np.sin(al) * Rc * cpsi) - M) / (scale * Rc))
        return out

    # initial guesses: rigid axial / radial estimates, then a few scalings
    K0 = float(np.mean(K_of(np.zeros(1))))
    Qa = max(Fa, 1e-9) / Z
    da0 = math.sqrt(max((A + (Qa / K0) ** (2 / 3)) ** 2 - h0**2, 0.0)) if Fa > 0 else 0.0
    dr0 = (5.0 * max(Fr, 1e-9) / Z / K0) ** (2 / 3) + 0.5 * Pd if Fr > 0 else 0.0
    best = None
    for scale in (1.0, 0.5, 2.0, 1.5, 0.8):
        x0 = [da0 * scale, dr0 * scale] + ([0.0] if tilt else [])
        sol, info, ier, msg = fsolve(eqs, x0, full_output=True, xtol=1e-13)
        r = np.max(np.abs(eqs(sol)))
        if best is None or r < best[1]:
            best = (sol, r)
        if r < 1e-9:
            break
    sol, r = best
    if r > 1e-6:
        raise SolverError(f"static load distribution did not converge (residual {r:.2e})")
    Q, al = loads(sol)
    return psi, Q, al
