"""Independent plain-Python reference of the assembled equations of motion (Zhang et al. 2016, Eqs. 5-21).

This module re-assembles the ball, cage and inner-ring equations of motion of docs/dynamics.md from the
package's stand-alone *leaf* laws only, with frame rotations written here, in inertial vectors (numpy), so
that the compiled kernel (``hsbearing/models/ball_bearing/kernel.py``, which works in ball-frame components) can be
checked term by term by ``tests/validation/test_assembly_reference.py``.

Leaf laws used (each validated by its own tests): Hertz load ``ball.hertz_normal_load``, EHL rolling force
``ball.ehl_rolling_force``, the traction law ``traction.zhang2016.coefficients`` / ``traction_coefficient``
(the plain numpy law, not the numba twin the kernel calls), the pocket line-contact film
``pocket.station_film`` with ``pocket.station_angle`` / ``pocket.pocket_edges`` /
``pocket.pocket_film_gap`` / ``pocket.pocket_elastic_force`` / ``pocket.pocket_boundary_friction``, the
guide-land film ``cage.guide_land_forces`` / ``cage.guide_land_torque`` / ``cage.smooth_eccentricity``
and the drag ``drag.ball_drag_force``.  NOT used: anything of ``kernel.py`` (the parameters filled by ``dynamics.build_model``
are read by name through ``kernel_io.as_dict``, a numba-free declaration), ``ball.groove_contact``,
``ball.ball_equations_of_motion``, ``ring.*``, ``cage.cage_orientation`` / ``cage_generalised_moments`` /
``cage_equations_of_motion``, ``pocket.pocket_film_wrench`` / ``pocket_wrench`` (the station sum around the
pocket and the pocket frame are assembled here).

Conventions (docs/dynamics.md, "Coordinates and state"; hsbearing/models/ball_bearing/state.py): inertial X axial, Y, Z;
ball frame (x axial, r radial outward, t circumferential) at the orbit angle theta; gravity along -Y.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from hsbearing.models.ball_bearing.ball import ehl_rolling_force, hertz_normal_load
from hsbearing.models.ball_bearing.cage import guide_land_forces, guide_land_torque, smooth_eccentricity
from hsbearing.models.ball_bearing.drag import ball_drag_force
from hsbearing.models.ball_bearing.pocket import (
    pocket_boundary_friction,
    pocket_edges,
    pocket_elastic_force,
    pocket_film_gap,
    station_angle,
    station_film,
)
from hsbearing.models.traction.zhang2016 import coefficients, traction_coefficient

EX = np.array([1.0, 0.0, 0.0])


# ----------------------------------------------------------------------------- frames (written here)
def skew(v):
    return np.array([[0.0, -v[2], v[1]], [v[2], 0.0, -v[0]], [-v[1], v[0], 0.0]])


def exp_map(beta):
    """Rotation matrix R = exp([beta x]) and left Jacobian J (omega = J beta') of a rotation vector beta.

    Rodrigues' formula; docs/dynamics.md "Nearest groove-centre point, exact tilts": ring and cage tilts are
    rotation vectors (0, beta_y, beta_z) mapped by the exponential map.  Evaluated with numpy here.
    """
    beta = np.asarray(beta, dtype=float)
    t = float(np.linalg.norm(beta))
    K = skew(beta)
    if t < 1e-8:
        a, b, c = 1.0 - t * t / 6.0, 0.5 - t * t / 24.0, 1.0 / 6.0 - t * t / 120.0
    else:
        a, b, c = math.sin(t) / t, (1.0 - math.cos(t)) / t**2, (t - math.sin(t)) / t**3
    R = np.eye(3) + a * K + b * K @ K
    J = np.eye(3) + b * K + c * K @ K
    return R, J


def rot_x(phi):
    c, s = math.cos(phi), math.sin(phi)
    return np.array([[1.0, 0.0, 0.0], [0.0, c, -s], [0.0, s, c]])


def ball_basis(theta):
    """Unit vectors (e_x, e_r, e_t) of the ball frame at orbit angle theta (seed Fig. 2)."""
    c, s = math.cos(theta), math.sin(theta)
    return EX.copy(), np.array([0.0, c, s]), np.array([0.0, -s, c])


# ----------------------------------------------------------------------------- parameters
@dataclass
class Prm:
    """The model constants, read by name from ``DynamicModel.P`` (filled by ``dynamics.build_model``)."""

    v: dict
    R_out_cage: float  # cage outside radius [m] of the pocket edges (docs/pocket.md), see params_of
    R_bore_cage: float  # cage bore radius [m], from the case
    orbit_radial: bool  # contact-centre velocity: the full orbital rotation (True) or its e_t part only

    def __getattr__(self, name):
        try:
            return self.__dict__["v"][name]
        except KeyError:
            raise AttributeError(name) from None


#: The places where the kernel's formulation differs from the one written here from the docs; the
#: reference follows the docs by default, ``KERNEL_CONVENTIONS`` reproduces the kernel's choice:
#: * ``pocket_outer_radius``: the pocket wall ends at the cage outside cylinder (docs/pocket.md: "pocket edges
#:   from the cage bore/outside diameters") -- "case", what the kernel does; "land" reproduces the kernel
#:   before its fix (it passed the guide-land film radius R_land, equal to the cage outside radius for
#:   outer-ring guidance only: no pocket film with inner-ring guidance, NaN with a ball-piloted cage);
#: * ``orbit_radial``: the contact centre moves with the ball frame, v_c = v_b + theta' e_x x (s0 - b) (True);
#:   the kernel keeps the circumferential part (r + rho_r) theta' e_t only (False; a 1e-7 effect on U).
DOC_CONVENTIONS = {"pocket_outer_radius": "case", "orbit_radial": True}
KERNEL_CONVENTIONS = {"pocket_outer_radius": "case", "orbit_radial": False}


def params_of(model, conventions=None) -> Prm:
    from hsbearing.models.ball_bearing.kernel_io import as_dict  # the parameter record read by name only

    conv = dict(DOC_CONVENTIONS, **(conventions or {}))
    v = as_dict(model.P)  # switches are bools, counts and the guidance ints
    cg = model.case.cage
    r_out = 0.5 * cg.outside_diameter if conv["pocket_outer_radius"] == "case" else v["R_land"]
    return Prm(v=v, R_out_cage=r_out, R_bore_cage=0.5 * cg.bore_diameter, orbit_radial=bool(conv["orbit_radial"]))


def strip_nodes(n):
    """Gauss-Legendre nodes u_k along the major axis and the load fractions (3/4) g_k (1 - u_k^2)
    (docs/dynamics.md, "Traction over the contact ellipse")."""
    u, g = np.polynomial.legendre.leggauss(int(n))
    w = 0.75 * g * (1.0 - u * u)
    return u, w / w.sum()


# ----------------------------------------------------------------------------- state unpacking
@dataclass
class Bodies:
    Z: int
    balls: list  # per ball: dict(b, vb, wb, theta, thd, r, vr, basis, w_frame)
    cage: dict
    ring: dict


def unpack(y, prm: Prm) -> Bodies:
    """State vector -> inertial positions/velocities (hsbearing/models/ball_bearing/state.py layout)."""
    Z = int(prm.Z)
    cg, rg = 9 * Z, 9 * Z + 12
    c = y[cg:cg + 12]
    Rt, Jt = exp_map([0.0, c[4], c[5]])
    Rc = Rt @ rot_x(c[3])  # docs/dynamics.md: R_c = R_tilt(psi) R_x(phi)
    wc = Jt @ np.array([0.0, c[10], c[11]]) + c[9] * (Rc @ EX)
    cage = dict(pos=np.array(c[0:3]), vel=np.array(c[6:9]), phi=c[3], phd=c[9], R=Rc, J=Jt, w=wc,
                psid=np.array([c[10], c[11]]))
    ri = y[rg:rg + 10]
    Rm, Jm = exp_map([0.0, ri[3], ri[4]])
    wt = Jm @ np.array([0.0, ri[8], ri[9]])
    ring = dict(pos=np.array(ri[0:3]), vel=np.array(ri[5:8]), R=Rm, J=Jm, wt=wt, betad=np.array([ri[8], ri[9]]),
                w=prm.omega_i * (Rm @ EX) + wt)
    balls = []
    for j in range(Z):
        x, u, thr, vx, vr, thd, wx, wy, wz = (y[k * Z + j] for k in range(9))
        r = 0.5 * prm.dm + u
        theta = c[3] + 2.0 * math.pi * j / Z + thr
        ex_, er, et = ball_basis(theta)
        b = x * ex_ + r * er
        vb = vx * ex_ + vr * er + r * thd * et
        wb = wx * ex_ + wy * er + wz * et
        balls.append(dict(b=b, vb=vb, wb=wb, theta=theta, thd=thd, r=r, vr=vr, x=x, vx=vx,
                          basis=(ex_, er, et), wf=np.array([wx, wy, wz])))
    return Bodies(Z, balls, cage, ring)


# ----------------------------------------------------------------------------- ball / race contact
def race_contact(prm: Prm, side, ball, C, vC, Oc, vO, Om, u_nodes, w_nodes):
    """Force and moment (about the ball centre) of one raceway on the ball, inertial [N, N m].

    C, vC: groove curvature centre the ball touches and its velocity (docs/dynamics.md, "Nearest groove-centre
    point"); Oc, vO, Om: a point of the race body, its velocity and the race angular velocity (rigid race
    v(s) = vO + Om x (s - Oc)).  Normal load Q = K delta^1.5 + damping (H&K Vol. 1 Eq. 6.40, Hunt-Crossley),
    traction mu(S) over the contact ellipse at the Gauss nodes (seed Eqs. 1-4; Gupta 1984 Ch. 3-4), the EHL
    rolling force as a couple (D/2) F_R (docs/dynamics.md, "F_H = F_R through the ball centre").
    """
    K, cd, off, Rx, ke, acoef = ((prm.K_i, prm.cd_i, prm.off_i, prm.Rx_i, prm.k_i, prm.acoef_i) if side == "i" else
                                 (prm.K_o, prm.cd_o, prm.off_o, prm.Rx_o, prm.k_o, prm.acoef_o))
    b, vb, wb = ball["b"], ball["vb"], ball["wb"]
    d = C - b
    L = float(np.linalg.norm(d))
    n = d / L
    delta = L - off
    delta_dot = float(n @ (vC - vb))  # envelope theorem: the nearest point's own motion along the circle is ⟂ n
    Q = float(hertz_normal_load(delta, delta_dot, K, cd * prm.damping))
    out = dict(Q=Q, n=n, F=Q * n, M=np.zeros(3), T1=0.0, T2=0.0, S0=0.0, U=0.0, FR=0.0)
    if Q <= 0.0:
        return out
    D2 = 0.5 * prm.D
    et = ball["basis"][2]
    t1 = et - (et @ n) * n
    t1 /= np.linalg.norm(t1)  # rolling direction: e_t in the tangent plane
    t2 = np.cross(n, t1)  # transverse (major axis) direction
    s0 = b - D2 * n  # contact centre

    def v_ball(s):
        return vb + np.cross(wb, s - b)

    def v_race(s):
        return vO + np.cross(Om, s - Oc)

    # the contact centre moves with the orbiting ball frame: ball-centre translation + orbit rotation about X
    # (the kernel keeps only the circumferential part of the rotation: KERNEL_CONVENTIONS)
    v_c = vb + ball["thd"] * np.cross(EX, s0 - b)
    if not prm.orbit_radial:
        v_c = vb + ball["thd"] * float(np.cross(EX, s0 - b) @ et) * et
    Ut = 0.5 * float((v_ball(s0) + v_race(s0)) @ t1) - float(v_c @ t1)
    U = math.sqrt(Ut * Ut + prm.U_eps**2)
    out["U"] = U
    F = np.zeros(3)
    M = np.zeros(3)
    if prm.friction > 0.0:
        A, B, Cc, Dd = (float(np.asarray(q)) for q in coefficients(int(prm.law_id), Q, U, prm.T_K, prm.Ep, Rx))
        a = acoef * Q ** (1.0 / 3.0)  # semi-major axis at constant ellipticity
        for k, (uk, wk) in enumerate(zip(u_nodes, w_nodes)):
            ph = a * uk / D2
            rho = D2 * (-math.cos(ph) * n + math.sin(ph) * t2)  # node on the ball surface
            ut = math.sin(ph) * n + math.cos(ph) * t2  # local transverse tangent (d rho / d ph)
            s = b + rho
            slip = v_ball(s) - v_race(s)
            s1, s2 = float(slip @ t1), float(slip @ ut)
            sreg = math.sqrt(s1 * s1 + s2 * s2 + prm.s_eps**2)
            S = sreg / U  # slide-roll ratio (fraction) -- seed Eq. 1
            mu = float(traction_coefficient(A, B, Cc, Dd, S))
            f = -Q * wk * mu / sreg  # traction opposes the local slip
            Fk = f * (s1 * t1 + s2 * ut)
            F += Fk
            M += np.cross(rho, Fk)
            out["T1"] += f * s1
            out["T2"] += f * s2
            if k == len(u_nodes) // 2:
                out["S0"] = s1 / U
    if prm.ehl_rolling:
        FR = float(ehl_rolling_force(U, Q, Rx, ke, prm.Ep, prm.eta_in, prm.alpha))
        out["FR"] = FR
        M += np.cross(s0 - b, -FR * (Ut / U) * t1)  # seed Eq. 7: F_R against rolling, F_H through the centre
    out["F"] = Q * n + F
    out["M"] = M
    return out


def inner_contact(prm, ball, ring, u_nodes, w_nodes):
    """Inner race on the ball: groove-centre circle (radius rho_i, axial offset g_i in the ring frame) of the
    displaced, tilted ring; the point nearest to the ball centre (H&K Vol. 1 Ch. 2, Vol. 2 Ch. 1)."""
    o, R = ring["pos"], ring["R"]
    q = R.T @ (ball["b"] - o)
    psi = math.atan2(q[2], q[1])
    cr = np.array([prm.g_i, prm.rho_i * math.cos(psi), prm.rho_i * math.sin(psi)])
    C = o + R @ cr
    vC = ring["vel"] + np.cross(ring["wt"], R @ cr)  # at fixed ring azimuth (spin moves it along the circle)
    return race_contact(prm, "i", ball, C, vC, o, ring["vel"], ring["w"], u_nodes, w_nodes)


def outer_contact(prm, ball, u_nodes, w_nodes):
    """Outer race (centre fixed at the origin, turning at omega_o about X) on the ball."""
    ex_, er, _ = ball["basis"]
    C = prm.g_o * ex_ + prm.rho_o * er
    return race_contact(prm, "o", ball, C, np.zeros(3), np.zeros(3), np.zeros(3), prm.omega_o * EX, u_nodes, w_nodes)


# ----------------------------------------------------------------------------- ball / pocket
def pocket_film(ex, et, s0, v, w, eta, Rb, Rp, R_bore, R_out, hdm, n_st):
    """Film wrench on the ball in its cylindrical pocket, pocket frame (x, r, t) (docs/pocket.md).

    Sum over n_st stations around the pocket wall (periodic trapezoidal rule in tau with the conformal map
    theta(tau) of ``pocket.station_angle``, k = ((c - e)/(c + e))^(1/4)); each station a rigid-isoviscous line
    contact (``pocket.station_film``) with entraining speed U_e = R_b omega.theta_hat - v_r (docs/pocket.md),
    circumferential wedge 6 eta U_s dh/ds and squeeze -12 eta v.n as the source F0; shear Couette
    -eta dU/h over the wetted wall plus Poiseuille -(h/2) dp/dx (int by parts: W_x/(2 R_b)).
    """
    vx, vr, vt = v
    wx, wr, wt = w
    c = Rp - Rb
    e = math.hypot(ex, et)
    th_e = math.atan2(et, ex) if e > 0.0 else 0.0
    k = ((c - e) / (c + e)) ** 0.25
    F = np.zeros(3)  # (x, r, t)
    M = np.zeros(3)
    Wn = 0.0
    dtau = 2.0 * math.pi / n_st
    for i in range(n_st):
        tau = -math.pi + (i + 0.5) * dtau
        thp, dth = station_angle(tau, k)
        th = th_e + thp
        nx, nt = math.cos(th), math.sin(th)  # wall normal
        qx, qt = -math.sin(th), math.cos(th)  # tangent theta_hat
        a = c - e * math.cos(thp)
        dUu = vr + Rb * (wx * qx + wt * qt)  # ball surface along e_r
        dUs = vx * qx + vt * qt - Rb * wr  # along theta_hat
        vn = vx * nx + vt * nt
        Ue = Rb * (wx * qx + wt * qt) - vr  # docs/pocket.md: U_e = R_b omega.theta_hat - v_r
        hs = e * math.sin(thp) / Rp
        F0 = 6.0 * eta * dUs * hs - 12.0 * eta * vn
        xlo, xhi = pocket_edges(math.sin(th), Rp, R_bore, R_out, hdm)
        lo, hi = xlo - s0, xhi - s0
        W, Wx, _x1, _x2 = station_film(a, Ue, F0, lo, hi, Rb, eta)
        Lh = math.sqrt(2.0 * Rb * a)
        I1 = Lh / a * (math.atan(hi / Lh) - math.atan(lo / Lh))  # int dx / h
        I1x = Rb * math.log((1.0 + (hi / Lh) ** 2) / (1.0 + (lo / Lh) ** 2))  # int x dx / h
        Tu = -eta * dUu * I1 + 0.5 * Wx / Rb
        Ts = -eta * dUs * I1
        Tsx = -eta * dUs * I1x
        ds = Rp * dth * dtau
        F += ds * np.array([-W * nx + Ts * qx, -Wx / Rb + Tu, -W * nt + Ts * qt])
        M += ds * np.array([Rb * Tu * qx + Tsx * nx, -Rb * Ts, Rb * Tu * qt + Tsx * nt])
        Wn += ds * W
    return F, M, Wn


def pocket_contact(prm: Prm, j, ball, cage):
    """Pocket wrench on ball j, inertial, moment about the ball centre (seed P_R, Q_c, P_S; docs/pocket.md).

    Pocket j's axis e_r = R_c (0, cos phi_j, sin phi_j), phi_j = 2 pi j / Z, centre at c + (d_m/2) e_r;
    the ball's offset and velocity relative to the (turning, tilting) pocket frame.
    """
    Z = int(prm.Z)
    Rc, wc = cage["R"], cage["w"]
    pj = 2.0 * math.pi * j / Z
    e_x = Rc @ EX
    e_r = Rc @ np.array([0.0, math.cos(pj), math.sin(pj)])
    e_t = Rc @ np.array([0.0, -math.sin(pj), math.cos(pj)])
    hdm = 0.5 * prm.dm
    d = ball["b"] - cage["pos"] - hdm * e_r
    dd = ball["vb"] - cage["vel"] - np.cross(wc, hdm * e_r)  # inertial rate of d
    E = np.array([e_x, e_r, e_t])  # rows: pocket axes
    loc = E @ d
    vloc = E @ dd + np.array([d @ np.cross(wc, e) for e in (e_x, e_r, e_t)])  # d/dt (d . e)
    wrel = E @ (ball["wb"] - wc)
    Rb, Rp = 0.5 * prm.D, 0.5 * prm.D + prm.c_p
    c = Rp - Rb
    ex, s0, et = loc
    e = math.hypot(ex, et)
    eta = prm.eta_film * prm.pocket_film_factor * prm.damping
    F = np.zeros(3)
    M = np.zeros(3)
    Qf = 0.0
    if eta > 0.0:
        ef, _hf = pocket_film_gap(e, c, prm.h_min)  # film floor h_c (mixed lubrication)
        sc = ef / e if e > 0.0 else 0.0
        F, M, Qf = pocket_film(ex * sc, et * sc, s0, vloc, wrel, eta, Rb, Rp, prm.R_bore_cage, prm.R_out_cage, hdm,
                               int(prm.n_pocket))
    Qs = float(pocket_elastic_force(e, c, prm.K_c))
    PS = 0.0
    if Qs > 0.0:
        nrm = np.array([ex / e, 0.0, et / e])
        F = F - Qs * nrm
        mu = prm.mu_c * prm.friction
        if mu > 0.0:
            p = Rb * nrm
            sl = vloc + np.cross(wrel, p)
            sl = sl - (sl @ nrm) * nrm
            vs = float(np.linalg.norm(sl))
            if vs > 0.0:
                PS = float(pocket_boundary_friction(vs, Qs, mu, prm.v0_c))
                ff = -PS * sl / vs
                F = F + ff
                M = M + np.cross(p, ff)
    # pocket (x, r, t) -> inertial
    return dict(F=E.T @ F, M=E.T @ M, Q_film=Qf, Q_solid=Qs, Q_c=math.hypot(F[0], F[2]), P_S=PS)


# ----------------------------------------------------------------------------- guide lands
def guide_lands(prm: Prm, bodies: Bodies):
    """Guide-land films (+ rub) on the cage: force (inertial), moment about the cage centre, Petroff moment.

    docs/dynamics.md "Guide-land film": one short-width film per land at its station a_k e on the cage axis,
    the offset of that point from the land centre (outer ring: the bearing axis; inner ring: the ring centre),
    whirl and squeeze from its velocity; omega_sum = cage + land speed; the Petroff moment
    -2 pi eta R^3 L (omega_c - omega_land)/(c sqrt(1 - eps^2)) along the cage axis; the rub (K_land/n)(e - c)^1.5
    with regularised Coulomb friction mu_c beyond the clearance.
    """
    nl = int(prm.n_land)
    F = np.zeros(3)
    M = np.zeros(3)
    Mpet = 0.0
    if nl <= 0:
        return dict(F=F, M=M, Mx_axis=0.0, ring_F=np.zeros(3))
    cage, ring = bodies.cage, bodies.ring
    inner = prm.guide == 2  # kernel_io.GUIDE_INNER_RING
    if inner:
        oc, vo, wl = ring["pos"], ring["vel"], prm.omega_i
    else:
        oc, vo, wl = np.zeros(3), np.zeros(3), prm.omega_o
    e_ax = cage["R"] @ EX
    ew = float(e_ax @ cage["w"])
    cl, R, L = prm.c_land, prm.R_land, prm.L_land
    for k in range(nl):
        a = prm.a_land if k == 0 else -prm.a_land
        pnt = cage["pos"] + a * e_ax
        vp = cage["vel"] + np.cross(cage["w"], a * e_ax)
        p = (pnt - oc)[1:]
        v = (vp - vo)[1:]
        e = math.sqrt(p @ p + prm.offset_eps ** 2)  # regularised offset (the kernel's choice)
        u = p / e
        ed = float(p @ v) / e
        whirl = float(p[0] * v[1] - p[1] * v[0]) / e**2
        eps = float(smooth_eccentricity(e / cl, prm.eps_max))
        f = np.zeros(2)
        mx = 0.0
        if prm.damping > 0.0:
            Fr, Ft = guide_land_forces(eps, ed / cl, cage["phd"] + wl, whirl, prm.eta_film * prm.land_film_factor, R, L, cl)
            f += Fr * u + Ft * np.array([-u[1], u[0]])
        if prm.friction > 0.0:
            mx = float(guide_land_torque(eps, cage["phd"] - wl, prm.eta_film * prm.land_film_factor, R, L, cl))
        if e > cl:
            pen = e - cl
            Fe = prm.K_land / nl * pen**1.5
            f -= Fe * u
            if prm.friction > 0.0:
                sgn = -1.0 if inner else 1.0  # contact on the cage's outside (outer guidance) or bore (inner)
                vt = float(-v[0] * u[1] + v[1] * u[0]) - wl * e + sgn * (ew - wl * e_ax[0]) * R
                ff = -Fe * prm.mu_c * vt / math.sqrt(vt * vt + prm.v0_c**2)
                f += ff * np.array([-u[1], u[0]])
                mx += sgn * ff * R
        f3 = np.array([0.0, f[0], f[1]])
        F += f3
        M += mx * e_ax + np.cross(a * e_ax, f3)
        Mpet += mx
    return dict(F=F, M=M, Mx_axis=Mpet, ring_F=-F if inner else np.zeros(3))


# ----------------------------------------------------------------------------- assembly
def ball_terms(prm: Prm, bodies: Bodies, j, u_nodes, w_nodes):
    """Forces (inertial) and moments (about the ball centre, inertial) on ball j by source (seed Eqs. 5-10)."""
    ball = bodies.balls[j]
    m = prm.m_b
    ci = inner_contact(prm, ball, bodies.ring, u_nodes, w_nodes)
    co = outer_contact(prm, ball, u_nodes, w_nodes)
    pk = pocket_contact(prm, j, ball, bodies.cage)
    FD = float(ball_drag_force(ball["r"] * ball["thd"], prm.D, prm.rho_e, prm.C_D, prm.v0_D)) if prm.drag else 0.0
    grav = np.array([0.0, -m * prm.grav, 0.0])
    return dict(inner=ci, outer=co, pocket=pk, drag=FD * ball["basis"][2], FD=FD, gravity=grav)


def ball_rates(prm: Prm, ball, F, M, phd):
    """Ball rows of ydot from the resultant (inertial) force and moment (seed Eqs. 5-10, docs/dynamics.md):
    m x'' = F_x; m (r'' - r theta'^2) = F_r; m (r theta'' + 2 r' theta') = F_t;
    I w_x' = M_x, I w_y' = M_y + I theta' w_z, I w_z' = M_z - I theta' w_y (frame turning at theta')."""
    m, Ib = prm.m_b, prm.I_b
    B = np.array(ball["basis"])
    Fx, Fr, Ft = B @ F
    Mx, Mr, Mt = B @ M
    r, vr, thd = ball["r"], ball["vr"], ball["thd"]
    wx, wy, wz = ball["wf"]
    return np.array([ball["vx"], vr, thd - phd, Fx / m, Fr / m + r * thd * thd, (Ft / m - 2.0 * vr * thd) / r,
                     Mx / Ib, Mr / Ib + thd * wz, Mt / Ib - thd * wy])  # seed Eqs. 5-7, 8-10


def evaluate(model, y, conventions=None, u_nodes=None, w_nodes=None):
    """Reference ydot and every term, at state y (``conventions``: see DOC_CONVENTIONS).  Returns (ydot, terms)."""
    prm = params_of(model, conventions)
    if u_nodes is None:
        u_nodes, w_nodes = strip_nodes(model.info["options"]["quadrature_points"])
    bodies = unpack(np.asarray(y, dtype=float), prm)
    Z = bodies.Z
    ydot = np.zeros_like(np.asarray(y, dtype=float))
    cage, ring = bodies.cage, bodies.ring
    Fc = np.zeros(3)
    Mc = np.zeros(3)  # about the cage centre
    Fr_ = np.zeros(3)
    Mr_ = np.zeros(3)  # about the ring centre
    per_ball = []
    for j in range(Z):
        t = ball_terms(prm, bodies, j, u_nodes, w_nodes)
        ball = bodies.balls[j]
        F = t["inner"]["F"] + t["outer"]["F"] + t["pocket"]["F"] + t["drag"] + t["gravity"]
        M = t["inner"]["M"] + t["outer"]["M"] + t["pocket"]["M"]
        rates = ball_rates(prm, ball, F, M, cage["phd"])
        for k in range(9):
            ydot[k * Z + j] = rates[k]
        # reactions (Newton's third law on the same lines of action)
        Fc -= t["pocket"]["F"]
        Mc -= t["pocket"]["M"] + np.cross(ball["b"] - cage["pos"], t["pocket"]["F"])
        Fr_ -= t["inner"]["F"]
        Mr_ -= t["inner"]["M"] + np.cross(ball["b"] - ring["pos"], t["inner"]["F"])
        t["ring_F"] = -t["inner"]["F"]
        t["ring_M"] = -(t["inner"]["M"] + np.cross(ball["b"] - ring["pos"], t["inner"]["F"]))
        t["cage_F"] = -t["pocket"]["F"]
        t["cage_M"] = -(t["pocket"]["M"] + np.cross(ball["b"] - cage["pos"], t["pocket"]["F"]))
        t["F_total"], t["M_total"] = F, M
        per_ball.append(t)
    land = guide_lands(prm, bodies)
    # cage, seed Eqs. 11-16: m x'' = F; Q_phi = e.M, Q_psi = J^T M (y, z); Euler terms of an axisymmetric cage
    Fcage = Fc + land["F"] + np.array([0.0, -prm.m_c * prm.grav, 0.0])
    Mcage = Mc + land["M"]
    e_c = cage["R"] @ EX
    Qphi = float(e_c @ Mcage)
    Qpsi = cage["J"].T @ Mcage
    psyd, pszd = cage["psid"]
    cg = 9 * Z
    ydot[cg:cg + 6] = model_rates_slice(np.asarray(y), cg)
    ydot[cg + 6:cg + 9] = Fcage / prm.m_c
    ydot[cg + 9] = Qphi / prm.Ip_c
    ydot[cg + 10] = (Qpsi[1] - prm.Ip_c * cage["phd"] * pszd) / prm.Id_c
    ydot[cg + 11] = (Qpsi[2] + prm.Ip_c * cage["phd"] * psyd) / prm.Id_c
    # inner ring, seed Eqs. 17-21: external loads, weight, contact reactions, land reaction (inner guidance)
    rg = cg + 12
    Fring = Fr_ + np.array([prm.F_x, prm.F_y - prm.m_i * prm.grav, prm.F_z]) + land["ring_F"]
    Mring = Mr_ + np.array([0.0, prm.M_y, prm.M_z])
    e_r = ring["R"] @ EX
    Mperp = Mring - (Mring @ e_r) * e_r  # the axial part is taken by the spin drive
    Q = ring["J"].T @ Mperp
    byd, bzd = ring["betad"]
    ydot[rg:rg + 5] = model_rates_slice(np.asarray(y), rg, n=5)
    ydot[rg + 5:rg + 8] = Fring / prm.m_i
    ydot[rg + 8] = (Q[1] - prm.Ip_i * prm.omega_i * bzd) / prm.Id_i  # seed Eq. 20
    ydot[rg + 9] = (Q[2] + prm.Ip_i * prm.omega_i * byd) / prm.Id_i  # seed Eq. 21
    terms = dict(balls=per_ball, land=land, cage_F=Fcage, cage_M=Mcage, ring_F=Fring, ring_M=Mring,
                 pocket_sum_F=Fc, pocket_sum_M=Mc, contact_sum_F=Fr_, contact_sum_M=Mr_, bodies=bodies)
    return ydot, terms


def model_rates_slice(y, start, n=6):
    """Position rows of a rigid body: d(q)/dt = q' (the rates are states)."""
    return y[start + n:start + 2 * n]
