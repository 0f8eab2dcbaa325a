"""Compiled right-hand side and arrowhead Jacobian of the bearing dynamic model (Zhang et al. 2016, Eqs. 5-21).

Everything here is numba-compiled and allocation-free per call.  The physics
lives in the named functions of :mod:`hsbearing.models.ball_bearing.ball`,
:mod:`~hsbearing.models.ball_bearing.cage`, :mod:`~hsbearing.models.ball_bearing.ring`,
:mod:`~hsbearing.models.ball_bearing.drag` and the traction law of
:mod:`hsbearing.models.traction.zhang2016`; this module only assembles them
over the balls.  State layout: :mod:`hsbearing.models.ball_bearing.state`.  Parameter
record and output columns: :mod:`hsbearing.models.ball_bearing.kernel_io` (declared once, by name, with units), filled by
:func:`hsbearing.systems.angular_contact.dynamics.build_model`.

Structure (used by the Jacobian): :func:`ball_loop` computes, for each ball
j, the derivatives of its 9 states (they depend only on ball j, the cage and
the ring) and its *contribution* to the generalised forces on the inner ring
and on the cage (array ``contrib[j, :]``, columns ``C_*``); :func:`global_rows`
sums the contributions, adds the ring loads and the guide-land film, and
writes the 22 ring/cage rows.
"""

from __future__ import annotations

import math
from collections import namedtuple

import numpy as np
from numba import njit

from hsbearing.compile_cache import check_compile_cache
from hsbearing.models.ball_bearing.ball import (
    ball_equations_of_motion,
    ehl_rolling_force,
    groove_contact,
    hertz_normal_load,
    inlet_heating_factor,
    inlet_heating_rolling_factor,
)
from hsbearing.models.ball_bearing.cage import (
    cage_equations_of_motion,
    cage_generalised_moments,
    cage_orientation,
    guide_land_forces,
    guide_land_power,
    guide_land_torque,
    pocket_friction_factor,
    smooth_eccentricity,
)
from hsbearing.models.ball_bearing.drag import ball_drag_force
from hsbearing.models.ball_bearing.kernel_io import (  # noqa: F401  (AUX_INDEX, GAUX_INDEX, N_AUX, N_GAUX: re-exported)
    AUX,
    AUX_INDEX,
    GAUX,
    GAUX_INDEX,
    GUIDE_INNER_RING,
    N_AUX,
    N_GAUX,
)
from hsbearing.models.ball_bearing.pocket import PocketKinematics, PocketParams, PocketWrench, pocket_wrench
from hsbearing.models.ball_bearing.power import couple_power, elastic_energy_hertz, normal_damping_power, sliding_power
from hsbearing.models.ball_bearing.ring import (
    inner_groove_centre,
    ring_equations_of_motion,
    tilt_generalised_moments,
    tilt_rotation,
)
from hsbearing.models.traction._kernels import race_traction_coefficients_nb, traction_mu_nb

# Parameters: the record P (one-element structured array, P[0] read as ``p.<group>.<name>``) and the
# output columns AUX / GAUX are declared, with units, in hsbearing.models.ball_bearing.kernel_io.

# contribution columns: forces/moments on the inner ring (inertial X, Y, Z; moments about its centre)
# and on the cage (inertial; moments about the cage centre)
C_RFX, C_RFY, C_RFZ, C_RMY, C_RMZ, C_RMX, C_CFX, C_CFY, C_CFZ, C_CMX, C_CMY, C_CMZ = range(12)
N_CONTRIB = 12

# ---------------- named arguments and result of one race contact (:func:`_race_contact`)
# Plain named tuples: numba compiles them as tuples (a field read is a register), the fields are read by name.
#: the ball's state in its own frame (x, r, t): centre position, velocity and angular velocity
BallMotion = namedtuple("BallMotion", [
    "x", "r",  # axial position and radius of the ball centre [m]
    "vx", "vr", "thd",  # axial and radial velocity [m/s], orbital angular velocity [rad/s]
    "wx", "wy", "wz",  # ball angular velocity, ball frame [rad/s]
])
#: normal load and unit normal (ball centre -> groove centre, ball frame) of one contact
ContactLoad = namedtuple("ContactLoad", ["Q", "nx", "nr", "nt"])
#: motion of the race, ball frame: velocity of its centre [m/s], position of its centre [m], angular velocity [rad/s]
RaceMotion = namedtuple("RaceMotion", ["vx", "vr", "vt", "ox", "orr", "ot", "Wx", "Wr", "Wt"])
#: constants of one race contact: equivalent radius along rolling [m], ellipticity [-], semi-major axis
#: coefficient a = acoef Q^(1/3) [m/N^(1/3)]
ContactShape = namedtuple("ContactShape", ["Rx", "ke", "acoef"])
#: the inlet oil of one race's contacts, at that race's contact inlet temperature: inlet viscosity [Pa s],
#: pressure-viscosity coefficient [1/Pa], -d ln(eta)/dT [1/K], temperature of the traction law [K], and the physical
#: traction model's tau0 [Pa], Lambda [-], G [Pa] (kernel_io: the inner race's lubricant/traction fields, the outer's
#: outer_oil fields)
ContactOil = namedtuple("ContactOil", ["eta_in", "alpha", "beta_T", "T_K", "tau0", "Lambda", "G"])
#: what one race contact puts on the ball (ball frame) and its by-products
RaceContact = namedtuple("RaceContact", [
    "fx", "fr", "ft",  # traction force on the ball [N]
    "mx", "mr", "mt",  # moment about the ball centre: traction (spin couple) + EHL rolling couple [N m]
    "T_roll", "T_trans",  # traction components, rolling and transverse [N]
    "S0",  # slide-roll ratio at the contact centre [-]
    "U",  # rolling speed [m/s]
    "F_R",  # EHL rolling force [N]
    "spin_roll",  # spin-to-roll ratio [-]
    "P_trac", "P_ehl",  # powers dissipated by the traction and by the EHL couple [W]
])


@njit(cache=True, inline="always")
def _cross(ax, ay, az, bx, by, bz):
    return ay * bz - az * by, az * bx - ax * bz, ax * by - ay * bx


#: |x| up to which :func:`_cos_sin_small` sums the Taylor series instead of calling libm
_SMALL_ANGLE = 0.5


@njit(cache=True, inline="always")
def _cos_sin_small(x):
    """(cos x, sin x) by their Taylor series through x^18 / x^17 for |x| <= 0.5, libm beyond (no call for the
    contact-ellipse node angles, |x| <= a/R_b ~ 0.3).

    Both series alternate with decreasing terms for |x| <= 0.5, so the truncation error is below the first
    omitted term: |x|^20/20! <= 4e-25 (cos), |x|^19/19! <= 1.6e-23 |x|/0.5 (sin), i.e. < 1e-22 relative (cos >= 0.87,
    sin x >= 0.95 x there); what remains is the rounding of Horner's scheme in x^2 (<= 2 ulp).
    Checked against libm by tests/models/test_kernel_cost.py::test_cos_sin_small_against_libm.
    """
    if abs(x) > _SMALL_ANGLE:
        return math.cos(x), math.sin(x)
    x2 = x * x
    c = 1.0 - x2 * (1.0 / 2.0 - x2 * (1.0 / 24.0 - x2 * (1.0 / 720.0 - x2 * (1.0 / 40320.0 - x2 * (
        1.0 / 3628800.0 - x2 * (1.0 / 479001600.0 - x2 * (1.0 / 87178291200.0 - x2 * (
            1.0 / 20922789888000.0 - x2 * (1.0 / 6402373705728000.0)))))))))
    sn = x * (1.0 - x2 * (1.0 / 6.0 - x2 * (1.0 / 120.0 - x2 * (1.0 / 5040.0 - x2 * (1.0 / 362880.0 - x2 * (
        1.0 / 39916800.0 - x2 * (1.0 / 6227020800.0 - x2 * (1.0 / 1307674368000.0 - x2 * (
            1.0 / 355687428096000.0)))))))))
    return c, sn


@njit(cache=True, inline="always")
def _surface_velocities(px_, pr_, pt_, x, r, vx, vr, thd, wx, wy, wz, rvx, rvr, rvt, ox, orr, ot, Wx, Wr, Wt):
    """Ball-surface and race-surface velocities at the point rho = (px_, pr_, pt_) from the ball centre.

    Ball frame (x, r, t): the ball centre moves at (vx, vr, r thd) and spins at (wx, wy, wz); the race
    centre is at (ox, orr, ot), moves at (rvx, rvr, rvt) and turns at (Wx, Wr, Wt).  Rigid-body
    kinematics v = v_centre + omega x rho (Harris & Kotzalas Vol. 2, Ch. 1).
    """
    bx, br, bt = _cross(wx, wy, wz, px_, pr_, pt_)
    gx, gr, gt = _cross(Wx, Wr, Wt, x + px_ - ox, r + pr_ - orr, pt_ - ot)
    return bx + vx, br + vr, bt + r * thd, gx + rvx, gr + rvr, gt + rvt


@njit(cache=True, error_model="numpy")  # no ZeroDivisionError branch per division (cost only)
def _race_contact(p, qu, qw, load, ball, race, shape, oil):
    """Traction and EHL rolling force of one ball/race contact, in the ball frame (x, r, t).

    ``load`` (:data:`ContactLoad`): normal load Q and unit normal n = (nx, nr, nt) from the ball centre towards
    the groove centre; ``ball`` (:data:`BallMotion`); ``race`` (:data:`RaceMotion`): race translational velocity,
    race centre position, race angular velocity -- all in the ball frame; ``shape`` (:data:`ContactShape`);
    ``oil`` (:data:`ContactOil`): the inlet oil of this race's contacts (its own contact inlet temperature).
    Returns a :data:`RaceContact`: the force on the ball (fx, fr, ft), the moment about the ball
    centre (mx, mr, mt) -- the traction distribution's spin couple and the
    EHL rolling-resistance couple included --, traction components (rolling,
    transverse), centre slide-roll ratio, rolling speed U, F_R, the
    spin-to-roll ratio, and the dissipated powers [W] of the traction (sum
    over the nodes of force x local slip, :func:`models.power.sliding_power`)
    and of the EHL couple (couple x relative angular velocity,
    :func:`models.power.couple_power`).  The race carries the exact opposite
    force system (:func:`reaction_moment`).
    """
    Q, nx, nr, nt = load.Q, load.nx, load.nr, load.nt
    x, r, vx, vr, thd, wx, wy, wz = ball.x, ball.r, ball.vx, ball.vr, ball.thd, ball.wx, ball.wy, ball.wz
    rvx, rvr, rvt, ox, orr, ot = race.vx, race.vr, race.vt, race.ox, race.orr, race.ot
    Wx, Wr, Wt = race.Wx, race.Wr, race.Wt
    Rx, ke, acoef = shape.Rx, shape.ke, shape.acoef
    D2 = 0.5 * p.ball.D
    fx = fr = ft = 0.0
    mx = mr = mt = 0.0
    T1 = T2 = 0.0
    S0 = 0.0
    U = 0.0
    FR = 0.0
    spin_roll = 0.0
    PT = PE = 0.0
    if Q <= 0.0:
        return RaceContact(fx, fr, ft, mx, mr, mt, T1, T2, S0, U, FR, spin_roll, PT, PE)
    # tangent basis: t2 = n x e_t / |.| (transverse, in the axial-radial plane), t1 = t2 x n (rolling, ~ e_t)
    hn = math.sqrt(nx * nx + nr * nr)
    t2x, t2r = nr / hn, -nx / hn
    t1x, t1r, t1t = -nx * nt / hn, -nr * nt / hn, hn
    # contact centre on the ball: rho0 = -(D/2) n
    r0x, r0r, r0t = -D2 * nx, -D2 * nr, -D2 * nt
    # rolling speed: mean surface speed along t1 relative to the moving contact
    vbx, vbr, vbt, vrx, vrr, vrt = _surface_velocities(r0x, r0r, r0t, x, r, vx, vr, thd, wx, wy, wz,
                                                        rvx, rvr, rvt, ox, orr, ot, Wx, Wr, Wt)
    vcx, vcr, vct = vx, vr, (r + r0r) * thd
    Ut = 0.5 * ((vbx + vrx) * t1x + (vbr + vrr) * t1r + (vbt + vrt) * t1t) - (vcx * t1x + vcr * t1r + vct * t1t)
    ueps = p.traction.U_eps
    U = math.sqrt(Ut * Ut + ueps * ueps)
    # spin-to-roll ratio (relative angular velocity along the normal / rolling speed)
    spin_roll = -((wx - Wx) * nx + (wy - Wr) * nr + (wz - Wt) * nt) * D2 / U
    if p.switches.friction:
        a = acoef * np.cbrt(Q)  # semi-major axis, constant ellipticity
        phi_film = 1.0
        if p.switches.inlet_heating:  # the physical traction law's film sees the inlet factor (slip 0, like the
            # reported films: the centre slip is an output of this traction)
            phi_film = inlet_heating_factor(oil.eta_in, oil.beta_T, p.lubricant.K_oil, U,
                                            1.5 * Q * ke / (math.pi * a * a), p.race.Ep, 0.0)
        # per-contact coefficients (traction/_kernels) with this race's inlet oil
        tc = race_traction_coefficients_nb(p, Q, U, Rx, ke, a, phi_film, oil.T_K, oil.eta_in, oil.alpha, oil.tau0,
                                           oil.Lambda, oil.G)
        iU = 1.0 / U
        seps = p.traction.s_eps
        # symmetric nodes (qu[n-1-k] = -qu[k], Gauss-Legendre): phi of the mirror node is exactly -phi, so its
        # cos is the same and its sin changes sign -- half the cos/sin calls; the nodes are visited
        # in the order 0, n-1, 1, n-2, ... (the sums change by round-off only)
        n = qu.size
        sym = True
        for k in range(n // 2):
            if qu[n - 1 - k] != -qu[k]:
                sym = False
        nk = (n + 1) // 2 if sym else n
        for kk in range(nk):
            phi0 = a * qu[kk] / D2
            c0, s0 = _cos_sin_small(phi0)
            for side in range(2 if sym else 1):
                k = kk if side == 0 else n - 1 - kk
                if side == 1 and k == kk:
                    break
                cp = c0
                sp = s0 if side == 0 else -s0
                # node on the ball surface, and the local transverse tangent
                rx_ = D2 * (-cp * nx + sp * t2x)
                rr_ = D2 * (-cp * nr + sp * t2r)
                rt_ = D2 * (-cp * nt)
                ux, ur, ut = sp * nx + cp * t2x, sp * nr + cp * t2r, sp * nt
                # ball and race surface velocities at the node
                bx, br, bt, gx, gr, gt = _surface_velocities(rx_, rr_, rt_, x, r, vx, vr, thd, wx, wy, wz,
                                                             rvx, rvr, rvt, ox, orr, ot, Wx, Wr, Wt)
                dvx, dvr, dvt = bx - gx, br - gr, bt - gt
                s1 = dvx * t1x + dvr * t1r + dvt * t1t
                s2 = dvx * ux + dvr * ur + dvt * ut
                sreg = math.sqrt(s1 * s1 + s2 * s2 + seps * seps)  # regularised slip speed [m/s]
                mu = traction_mu_nb(p.traction.law_id, tc, sreg * iU, qu[k])  # S = sreg / U, strip at y = a u_k
                q = Q * qw[k]
                f = -q * mu / sreg  # traction opposes the local slip  [5] of models.ball
                f1 = f * s1
                f2 = f * s2
                Fx_ = f1 * t1x + f2 * ux
                Fr_ = f1 * t1r + f2 * ur
                Ft_ = f1 * t1t + f2 * ut
                fx += Fx_
                fr += Fr_
                ft += Ft_
                cx, cr, ct = _cross(rx_, rr_, rt_, Fx_, Fr_, Ft_)
                mx += cx
                mr += cr
                mt += ct
                T1 += f1
                T2 += f2
                PT += sliding_power(Fx_, Fr_, Ft_, dvx, dvr, dvt)
                if k == qu.size // 2:
                    S0 = s1 / U
    if p.switches.ehl_rolling:
        FR = ehl_rolling_force(U, Q, Rx, ke, p.race.Ep, oil.eta_in, oil.alpha)
        if p.switches.inlet_heating:  # one inlet factor per contact from its own speed, pressure and slip
            a_h = acoef * np.cbrt(Q)
            p_h = 1.5 * Q * ke / (math.pi * a_h * a_h)  # p_max = 3 Q / (2 pi a b), b = a / k
            FR *= inlet_heating_rolling_factor(inlet_heating_factor(oil.eta_in, oil.beta_T,
                                                                    p.lubricant.K_oil, U, p_h, p.race.Ep, S0))
        sg = Ut / U
        # F_R at the contact against the rolling sense, F_H = F_R through the ball centre:
        # a pure couple on the ball (seed Eq. 7 signs; docs/dynamics.md)
        cx, cr, ct = _cross(r0x, r0r, r0t, -FR * sg * t1x, -FR * sg * t1r, -FR * sg * t1t)
        mx += cx
        mr += cr
        mt += ct
        # the race carries the opposite couple: dissipation = couple x relative angular velocity
        PE = couple_power(cx, cr, ct, wx - Wx, wy - Wr, wz - Wt)
    return RaceContact(fx, fr, ft, mx, mr, mt, T1, T2, S0, U, FR, spin_roll, PT, PE)


@njit(cache=True, inline="always")
def _sum_wrenches(a, b, c, d, e):
    """Component sums a + b + c + d + e (left to right) of five wrenches (fx, fr, ft, mx, mr, mt)."""
    return (a[0] + b[0] + c[0] + d[0] + e[0], a[1] + b[1] + c[1] + d[1] + e[1], a[2] + b[2] + c[2] + d[2] + e[2],
            a[3] + b[3] + c[3] + d[3] + e[3], a[4] + b[4] + c[4] + d[4] + e[4], a[5] + b[5] + c[5] + d[5] + e[5])


@njit(cache=True, inline="always")
def _sum4_wrenches(a, b, c, d):
    """Component sums a + b + c + d (left to right) of four wrenches (fx, fy, fz, mx, my, mz)."""
    return (a[0] + b[0] + c[0] + d[0], a[1] + b[1] + c[1] + d[1], a[2] + b[2] + c[2] + d[2],
            a[3] + b[3] + c[3] + d[3], a[4] + b[4] + c[4] + d[4], a[5] + b[5] + c[5] + d[5])


@njit(cache=True, inline="always")
def reaction_moment(ax, ay, az, fx, fy, fz, mx, my, mz):
    """Moment about a body's reference point O of the reaction to a force system on the ball [N m].

    The contact puts on the ball the force F (fx, fy, fz) [N] and the moment M (mx, my, mz) [N m]
    about the ball centre B (the traction distribution over the ellipse with its spin couple, the
    EHL rolling couple); the other body carries -F and -M (Newton's third law for every node of the
    distribution), whose moment about O is -(B - O) x F - M, with a = B - O (ax, ay, az) [m].
    """
    cx, cy, cz = _cross(ax, ay, az, fx, fy, fz)
    return -cx - mx, -cy - my, -cz - mz


@njit(cache=True)
def ball_loop(y, P, qu, qw, ydot, contrib, aux, want_aux):
    """Ball rows of ydot and per-ball contributions to the ring and cage loads (see module doc)."""
    ball_loop_cached(y, P, qu, qw, ydot, contrib, aux, want_aux, 0, contrib, 0, contrib)  # modes 0: caches unused


@njit(cache=True, error_model="numpy")  # no ZeroDivisionError branch per division (cost only)
def ball_loop_cached(y, P, qu, qw, ydot, contrib, aux, want_aux, pmode, pcache, rmode, rcache):
    """:func:`ball_loop` with the pocket wrench of each ball stored (``pmode`` 1) or reused (``pmode`` 2)
    in ``pcache`` (Z x 11): for Jacobian columns of states the pocket wrench does not depend on (the ring
    states); ``pmode`` 0 computes it as :func:`ball_loop`.  Likewise ``rmode``/``rcache`` (Z x 18) for the
    two race contacts (columns 0-5 the inner wrench on the ball, 6-11 its ring contribution, 12-17 the outer
    wrench), which depend on ball and ring states and on the cage angle only: reused for the other 11 cage
    columns (reuse needs ``want_aux`` False).  Cost only: the arithmetic is unchanged.  Both couplings are
    checked by tests/models/test_kernel_io.py::test_jacobian_reuse_couplings_hold."""
    p = P[0]
    Z = p.ball.Z
    D2 = 0.5 * p.ball.D
    m, I = p.ball.m_b, p.ball.I_b
    cg = 9 * Z
    xc, yc, zc, phc, psy, psz = y[cg], y[cg + 1], y[cg + 2], y[cg + 3], y[cg + 4], y[cg + 5]
    vxc, vyc, vzc, phd, psyd, pszd = y[cg + 6], y[cg + 7], y[cg + 8], y[cg + 9], y[cg + 10], y[cg + 11]
    rg = cg + 12
    xi, yi, zi, by, bz = y[rg], y[rg + 1], y[rg + 2], y[rg + 3], y[rg + 4]
    vxi, vyi, vzi, byd, bzd = y[rg + 5], y[rg + 6], y[rg + 7], y[rg + 8], y[rg + 9]
    Rc, (wcx, wcy, wcz), Jc = cage_orientation(phc, psy, psz, phd, psyd, pszd)
    Rm, Jm = tilt_rotation(by, bz)
    wtx = Jm[1] * byd + Jm[2] * bzd  # tilting angular velocity J beta'
    wty = Jm[4] * byd + Jm[5] * bzd
    wtz = Jm[7] * byd + Jm[8] * bzd
    wi, wo = p.race.omega_i, p.race.omega_o
    fric = 1.0 if p.switches.friction else 0.0  # multiplies the friction coefficients
    damp = 1.0 if p.switches.damping else 0.0  # multiplies the damping coefficients and film viscosity
    hdm = 0.5 * p.ball.dm
    pocket_prm = PocketParams(eta=p.lubricant.eta_film * p.lubricant.pocket_film_factor * damp, Rb=D2, Rp=D2 + p.pocket.c_p, R_bore=p.pocket.R_bore_c,
                              R_out=p.pocket.R_out_c, hdm=hdm, n_st=p.pocket.n_pocket, h_c=p.pocket.h_min,
                              K=p.pocket.K_c, mu=p.pocket.mu_c * fric, v0=p.pocket.v0_c)
    for j in range(Z):
        # state: u_b (radial displacement from the pitch circle), psi_b (angle from the pocket line)
        x, r, th = y[j], hdm + y[Z + j], phc + 2.0 * math.pi * j / Z + y[2 * Z + j]
        vx, vr, thd = y[3 * Z + j], y[4 * Z + j], y[5 * Z + j]
        wx, wy, wz = y[6 * Z + j], y[7 * Z + j], y[8 * Z + j]
        c, s = math.cos(th), math.sin(th)
        ball = BallMotion(x, r, vx, vr, thd, wx, wy, wz)
        # Each action on the ball is a named wrench (force, moment about the ball centre) in the ball frame
        # (x, r, t): gravity, inner, outer, pocket, drag; the balance below sums them (Eqs. 5-10).
        # ---------------- gravity along -Y (horizontal shaft): (0, -g, 0) in the ball frame is (0, -g cos th, g sin th)
        gravity = (0.0, -m * p.env.grav * c, m * p.env.grav * s, 0.0, 0.0, 0.0)
        if rmode == 2 and not want_aux:
            # reuse: the race contacts depend on ball and ring states and on the cage angle only
            inner = (rcache[j, 0], rcache[j, 1], rcache[j, 2], rcache[j, 3], rcache[j, 4], rcache[j, 5])
            outer = (rcache[j, 12], rcache[j, 13], rcache[j, 14], rcache[j, 15], rcache[j, 16], rcache[j, 17])
            contrib[j, C_RFX], contrib[j, C_RFY], contrib[j, C_RFZ] = rcache[j, 6], rcache[j, 7], rcache[j, 8]
            contrib[j, C_RMY], contrib[j, C_RMZ], contrib[j, C_RMX] = rcache[j, 9], rcache[j, 10], rcache[j, 11]
            Qi = Qo = dlt = dltd = dlt_o = dltd_o = nxi = nri = nxo = nro = 0.0  # (auxiliary outputs only)
            Ti1 = Ti2 = To1 = To2 = Si = So = Ui = Uo = FRi = FRo = sri = sro = 0.0
            PTi = PTo = PEi = PEo = tau_o = 0.0
        else:
            # ---------------- inner race contact (Eqs. 5-10, Q_i, T_i, F_R,i)
            dX, dR, dT, vcX, vcR, vcT = inner_groove_centre(x, r, th, p.race.rho_i, p.race.g_i, xi, yi, zi, Rm,
                                                            vxi, vyi, vzi, wtx, wty, wtz)
            dlt, nxi, nri, nti = groove_contact(dX, dR, dT, p.race.off_i)
            dltd = nxi * (vcX - vx) + nri * (vcR - vr) + nti * (vcT - r * thd)
            Qi = hertz_normal_load(dlt, dltd, p.race.K_i, p.race.cd_i * damp)
            # inner ring kinematics in the ball frame
            rvx, rvr, rvt = vxi, vyi * c + vzi * s, -vyi * s + vzi * c
            ox, orr, ot = xi, yi * c + zi * s, -yi * s + zi * c
            # ring angular velocity: spin about its own (tilted) axis R e_x plus the tilting rate
            Wsx, Wsy, Wsz = wi * Rm[0] + wtx, wi * Rm[3] + wty, wi * Rm[6] + wtz
            Wx, Wr, Wt = Wsx, Wsy * c + Wsz * s, -Wsy * s + Wsz * c
            ci = _race_contact(p, qu, qw, ContactLoad(Qi, nxi, nri, nti), ball,
                               RaceMotion(rvx, rvr, rvt, ox, orr, ot, Wx, Wr, Wt),
                               ContactShape(p.race.Rx_i, p.race.k_i, p.race.acoef_i),
                               ContactOil(p.lubricant.eta_in, p.lubricant.alpha, p.lubricant.beta_T, p.traction.T_K,
                                          p.traction.tau0, p.traction.Lambda, p.traction.G))
            tfx, tfr, tft, tmx, tmr, tmt = ci.fx, ci.fr, ci.ft, ci.mx, ci.mr, ci.mt
            Ti1, Ti2, Si, Ui, FRi, sri, PTi, PEi = ci.T_roll, ci.T_trans, ci.S0, ci.U, ci.F_R, ci.spin_roll, ci.P_trac, ci.P_ehl
            fbx = Qi * nxi + tfx  # force of the inner race on the ball (ball frame)
            fbr = Qi * nri + tfr
            fbt = Qi * nti + tft
            inner = (fbx, fbr, fbt, tmx, tmr, tmt)  # normal load + traction, spin and EHL rolling couples
            # reaction on the inner ring: the opposite of the whole force system on the ball (normal load,
            # traction with its spin couple, EHL rolling couple), inertial frame, moment about the ring centre
            gx, gy, gz = -fbx, -(fbr * c - fbt * s), -(fbr * s + fbt * c)
            mrx, mry, mrz = reaction_moment(x - xi, r * c - yi, r * s - zi, -gx, -gy, -gz,
                                            tmx, tmr * c - tmt * s, tmr * s + tmt * c)
            contrib[j, C_RFX] = gx
            contrib[j, C_RFY] = gy
            contrib[j, C_RFZ] = gz
            contrib[j, C_RMY] = mry
            contrib[j, C_RMZ] = mrz
            contrib[j, C_RMX] = mrx
            # ---------------- outer race contact (fixed outer ring, speed wo about X)
            dlt_o, nxo, nro, nto = groove_contact(p.race.g_o - x, p.race.rho_o - r, 0.0, p.race.off_o)
            dltd_o = -nxo * vx - nro * vr
            Qo = hertz_normal_load(dlt_o, dltd_o, p.race.K_o, p.race.cd_o * damp)
            co = _race_contact(p, qu, qw, ContactLoad(Qo, nxo, nro, nto), ball,
                               RaceMotion(0.0, 0.0, 0.0, 0.0, 0.0, 0.0, wo, 0.0, 0.0),  # fixed ring, speed wo about X
                               ContactShape(p.race.Rx_o, p.race.k_o, p.race.acoef_o),
                               ContactOil(p.outer_oil.eta_in_o, p.outer_oil.alpha_o, p.outer_oil.beta_T_o,
                                          p.outer_oil.T_K_o, p.outer_oil.tau0_o, p.outer_oil.Lambda_o, p.outer_oil.G_o))
            tfx, tfr, tft, tmx, tmr, tmt = co.fx, co.fr, co.ft, co.mx, co.mr, co.mt
            To1, To2, So, Uo, FRo, sro, PTo, PEo = co.T_roll, co.T_trans, co.S0, co.U, co.F_R, co.spin_roll, co.P_trac, co.P_ehl
            outer = (Qo * nxo + tfx, Qo * nro + tfr, tft, tmx, tmr, tmt)  # (the outer normal has no t component)
            # moment about X through the origin of the outer-race actions on the ball: (b x F)_X = r F_t, plus M_x
            tau_o = r * tft + tmx
            if rmode == 1:
                for k in range(6):
                    rcache[j, k] = inner[k]
                    rcache[j, 12 + k] = outer[k]
                rcache[j, 6], rcache[j, 7], rcache[j, 8] = contrib[j, C_RFX], contrib[j, C_RFY], contrib[j, C_RFZ]
                rcache[j, 9], rcache[j, 10], rcache[j, 11] = contrib[j, C_RMY], contrib[j, C_RMZ], contrib[j, C_RMX]
        # ---------------- cage pocket (Q_c, P_S), inertial vectors; pocket axes turn and tilt with the cage
        phj = 2.0 * math.pi * j / Z
        cph, sph = math.cos(phj), math.sin(phj)
        ex_x, ex_y, ex_z = Rc[0], Rc[3], Rc[6]  # cage axis
        er_x = Rc[1] * cph + Rc[2] * sph  # pocket axis (radial)
        er_y = Rc[4] * cph + Rc[5] * sph
        er_z = Rc[7] * cph + Rc[8] * sph
        et_x = -Rc[1] * sph + Rc[2] * cph  # pocket circumferential direction
        et_y = -Rc[4] * sph + Rc[5] * cph
        et_z = -Rc[7] * sph + Rc[8] * cph
        bx_, by_, bz_ = x, r * c, r * s  # ball centre
        vbx_, vby_, vbz_ = vx, vr * c - r * thd * s, vr * s + r * thd * c
        dvx_, dvy_, dvz_ = bx_ - xc - hdm * er_x, by_ - yc - hdm * er_y, bz_ - zc - hdm * er_z  # b - P
        # rate of b - P: v_b - V_c - omega_c x (hdm e_r)
        ox_, oy_, oz_ = _cross(wcx, wcy, wcz, hdm * er_x, hdm * er_y, hdm * er_z)
        rdx, rdy, rdz = vbx_ - vxc - ox_, vby_ - vyc - oy_, vbz_ - vzc - oz_
        dxp = dvx_ * ex_x + dvy_ * ex_y + dvz_ * ex_z
        dtp = dvx_ * et_x + dvy_ * et_y + dvz_ * et_z
        # d/dt (d . e) = d' . e + d . (omega x e)
        wex = _cross(wcx, wcy, wcz, ex_x, ex_y, ex_z)
        wet = _cross(wcx, wcy, wcz, et_x, et_y, et_z)
        ddx = rdx * ex_x + rdy * ex_y + rdz * ex_z + dvx_ * wex[0] + dvy_ * wex[1] + dvz_ * wex[2]
        ddt = rdx * et_x + rdy * et_y + rdz * et_z + dvx_ * wet[0] + dvy_ * wet[1] + dvz_ * wet[2]
        drp = dvx_ * er_x + dvy_ * er_y + dvz_ * er_z  # offset along the pocket axis (s_0)
        wer = _cross(wcx, wcy, wcz, er_x, er_y, er_z)
        ddr = rdx * er_x + rdy * er_y + rdz * er_z + dvx_ * wer[0] + dvy_ * wer[1] + dvz_ * wer[2]
        # ball angular velocity relative to the cage, pocket axes
        wbx, wby, wbz = wx, wy * c - wz * s, wy * s + wz * c  # ball angular velocity (inertial)
        wrx_, wry_, wrz_ = wbx - wcx, wby - wcy, wbz - wcz
        wpx = wrx_ * ex_x + wry_ * ex_y + wrz_ * ex_z
        wpr = wrx_ * er_x + wry_ * er_y + wrz_ * er_z
        wpt = wrx_ * et_x + wry_ * et_y + wrz_ * et_z
        # film (rigid isoviscous, floored at h_min) + Hertz + boundary friction P_S: models/ball_bearing/pocket.py
        if pmode == 2:  # reuse: the pocket wrench depends on ball and cage states only
            pw = PocketWrench(pcache[j, 0], pcache[j, 1], pcache[j, 2], pcache[j, 3], pcache[j, 4], pcache[j, 5],
                              pcache[j, 6], pcache[j, 7], pcache[j, 8], pcache[j, 9], pcache[j, 10])
        else:
            pw = pocket_wrench(PocketKinematics(ex=dxp, et=dtp, s0=drp, vx=ddx, vr=ddr, vt=ddt, wx=wpx, wr=wpr, wt=wpt),
                               pocket_prm)
            if pmode == 1:
                for k in range(11):
                    pcache[j, k] = pw[k]
        pFx, pFr, pFt, pMx, pMr, pMt = pw.Fx, pw.Fr, pw.Ft, pw.Mx, pw.Mr, pw.Mt
        Qf, Qs, Ppf, Ppb, PS = pw.Q_film, pw.Q_solid, pw.P_film, pw.P_boundary, pw.P_S
        # to inertial axes: force and moment (about the ball centre) on the ball
        gx_ = pFx * ex_x + pFr * er_x + pFt * et_x
        gy_ = pFx * ex_y + pFr * er_y + pFt * et_y
        gz_ = pFx * ex_z + pFr * er_z + pFt * et_z
        mbx = pMx * ex_x + pMr * er_x + pMt * et_x
        mby = pMx * ex_y + pMr * er_y + pMt * et_y
        mbz = pMx * ex_z + pMr * er_z + pMt * et_z
        Qc = math.sqrt(pFx * pFx + pFt * pFt)  # pocket force on the ball in the pocket plane
        # to the ball frame
        pocket = (gx_, gy_ * c + gz_ * s, -gy_ * s + gz_ * c, mbx, mby * c + mbz * s, -mby * s + mbz * c)
        # reaction on the cage: the opposite wrench on the same line of action (through the ball
        # centre b), moment about the cage centre -(M + (b - c) x F): force and moment closed exactly
        Xx, Xy, Xz = bx_ - xc, by_ - yc, bz_ - zc
        mcx, mcy, mcz = _cross(Xx, Xy, Xz, gx_, gy_, gz_)
        contrib[j, C_CFX] = -gx_
        contrib[j, C_CFY] = -gy_
        contrib[j, C_CFZ] = -gz_
        contrib[j, C_CMX] = -(mbx + mcx)
        contrib[j, C_CMY] = -(mby + mcy)
        contrib[j, C_CMZ] = -(mbz + mcz)
        # ---------------- drag in the air-oil mixture (F_D, Eq. 7)
        FD = 0.0
        if p.switches.drag:
            FD = ball_drag_force(r * thd, p.ball.D, p.drag.rho_e, p.drag.C_D, p.drag.v0_D)
        drag = (0.0, 0.0, FD, 0.0, 0.0, 0.0)  # circumferential, through the ball centre
        if want_aux:
            # ---------------- dissipated power by source (models.power) and stored elastic energy
            Kdi = p.race.K_i * dlt * math.sqrt(dlt) if dlt > 0.0 else 0.0
            Kdo = p.race.K_o * dlt_o * math.sqrt(dlt_o) if dlt_o > 0.0 else 0.0
            aux[j, AUX.P_trac_i] = PTi
            aux[j, AUX.P_trac_o] = PTo
            aux[j, AUX.P_ehl_i] = PEi
            aux[j, AUX.P_ehl_o] = PEo
            aux[j, AUX.P_damp_i] = normal_damping_power(Qi, Kdi, dltd)
            aux[j, AUX.P_damp_o] = normal_damping_power(Qo, Kdo, dltd_o)
            aux[j, AUX.P_pocket_film] = Ppf  # pocket film: entraining shear + squeeze (models.pocket.pocket_film_power)
            aux[j, AUX.P_pocket_boundary] = Ppb  # pocket boundary friction P_S x sliding speed
            aux[j, AUX.P_drag] = sliding_power(0.0, 0.0, FD, 0.0, 0.0, r * thd)  # mixture at rest
            aux[j, AUX.U_el] = (elastic_energy_hertz(p.race.K_i, dlt) + elastic_energy_hertz(p.race.K_o, dlt_o)
                          + (0.4 * Qs * (Qs / p.pocket.K_c) ** (2.0 / 3.0) if Qs > 0.0 else 0.0))  # pocket Hertz part
            aux[j, AUX.tau_o] = tau_o
        # ---------------- ball balance (Eqs. 5-10): forces (Eqs. 5-7) and moments about the ball centre (Eqs. 8-10)
        # F = gravity + Q_i n_i + T_i + Q_o n_o + T_o + pocket (Q_c, P_S) + F_D;  M = race couples (traction spin,
        # EHL rolling F_R) + pocket moment.  The sum is taken left to right in this order.
        Fx, Fr, Ft, Mx, Mr, Mt = _sum_wrenches(gravity, inner, outer, pocket, drag)
        xdd, rdd, thdd, wxd, wyd, wzd = ball_equations_of_motion(Fx, Fr, Ft, Mx, Mr, Mt, r, vr, thd, wy, wz, m, I)
        ydot[j] = vx
        ydot[Z + j] = vr
        ydot[2 * Z + j] = thd - phd
        ydot[3 * Z + j] = xdd
        ydot[4 * Z + j] = rdd
        ydot[5 * Z + j] = thdd
        ydot[6 * Z + j] = wxd
        ydot[7 * Z + j] = wyd
        ydot[8 * Z + j] = wzd
        if want_aux:
            aux[j, AUX.Q_i] = Qi
            aux[j, AUX.Q_o] = Qo
            aux[j, AUX.alpha_i] = math.atan2(nxi, nri)
            aux[j, AUX.alpha_o] = math.atan2(-nxo, -nro)
            aux[j, AUX.T_roll_i] = Ti1
            aux[j, AUX.T_trans_i] = Ti2
            aux[j, AUX.T_roll_o] = To1
            aux[j, AUX.T_trans_o] = To2
            aux[j, AUX.S_i] = Si
            aux[j, AUX.S_o] = So
            aux[j, AUX.U_i] = Ui
            aux[j, AUX.U_o] = Uo
            aux[j, AUX.Q_c] = Qc
            aux[j, AUX.P_S] = PS
            aux[j, AUX.F_R_i] = FRi
            aux[j, AUX.F_R_o] = FRo
            aux[j, AUX.F_D] = FD
            aux[j, AUX.spin_roll_i] = sri
            aux[j, AUX.spin_roll_o] = sro
            aux[j, AUX.Q_film] = Qf
            aux[j, AUX.Q_solid] = Qs


@njit(cache=True)
def guide_land_loads(y, P, Rc, wcx, wcy, wcz):
    """Loads of the guide lands on the cage: one short-width film per land + elastic rub beyond the clearance.

    Land k sits at a_k = +a_land (and -a_land for two lands) along the cage axis e = R_c e_x; its film sees
    the offset of that axis point from the land centre (outer ring: the origin; inner ring: the ring
    centre) and its velocity v_c + omega_c x (a_k e) -- so tilting the cage loads the two lands
    differently and the films resist the tilt.  Forces and Petroff torques add over the lands
    (:func:`~hsbearing.models.ball_bearing.cage.guide_land_forces`, :func:`~hsbearing.models.ball_bearing.cage.guide_land_torque`);
    the film pressure acts through the cage axis, so its moment about the cage centre is a_k e x F_k.

    Returns (F_y, F_z [N], M_x along the cage axis [N m], (M_x, M_y, M_z) of the axial offsets [N m],
    reaction moment about X on the land's ring [N m] (inner guidance, else 0), dissipated power [W],
    elastic energy of the rub [J]).
    """
    p = P[0]
    Z = p.ball.Z
    cg = 9 * Z
    rg = cg + 12
    nl = p.land.n_land
    Fly = Flz = Mlx = Mtx = Mty = Mtz = Mring = Pland = Uland = 0.0
    if nl <= 0:
        return Fly, Flz, Mlx, Mtx, Mty, Mtz, Mring, Pland, Uland
    yc, zc, vyc, vzc, phd = y[cg + 1], y[cg + 2], y[cg + 7], y[cg + 8], y[cg + 9]
    if p.land.guide == GUIDE_INNER_RING:  # inner ring: land centre = ring centre, land speed = ring speed
        yr, zr, vyr, vzr, wl = y[rg + 1], y[rg + 2], y[rg + 6], y[rg + 7], p.race.omega_i
    else:
        yr, zr, vyr, vzr, wl = 0.0, 0.0, 0.0, 0.0, p.race.omega_o
    cl = p.land.c_land
    R = p.land.R_land
    eta_land = p.lubricant.eta_film * p.lubricant.land_film_factor  # exactly eta_film at factor 1 (isothermal)
    Kl = p.land.K_land / nl  # the rub stiffness is shared by the lands (unchanged for an untilted cage)
    ex, ey, ez = Rc[0], Rc[3], Rc[6]
    ew = ex * wcx + ey * wcy + ez * wcz  # cage angular velocity along its axis
    for k in range(nl):
        a = p.land.a_land if k == 0 else -p.land.a_land
        py = yc + a * ey - yr
        pz = zc + a * ez - zr
        vy = vyc + a * (wcz * ex - wcx * ez) - vyr
        vz = vzc + a * (wcx * ey - wcy * ex) - vzr
        e = math.sqrt(py * py + pz * pz + p.land.offset_eps ** 2)
        uy, uz = py / e, pz / e
        ed = (py * vy + pz * vz) / e
        whirl = (py * vz - pz * vy) / (e * e)
        eps = smooth_eccentricity(e / cl, p.land.eps_max)
        fy = fz = mx = 0.0
        if p.switches.damping:
            Fr, Ft = guide_land_forces(eps, ed / cl, phd + wl, whirl, eta_land, R, p.land.L_land, cl)
            fy = Fr * uy - Ft * uz
            fz = Fr * uz + Ft * uy
        else:
            Fr = Ft = 0.0
        if p.switches.friction:
            mx = guide_land_torque(eps, phd - wl, eta_land, R, p.land.L_land, cl)
        # film dissipation: the Petroff moment acts along the cage axis e, so its power uses e.omega_c on
        # the cage and e_x omega_land on the land (exact for a tilted cage, as the cage equations use it)
        Pland += guide_land_power(Fr, Ft, e, ed, whirl, 0.0, 0.0, wl) - mx * (ew - wl * ex)
        Mring += -mx - e * Ft  # the film's moment on the land (massless film)
        if e > cl:
            # elastic rub of the cage on the land (Hertz-like penalty), with regularised Coulomb friction
            pen = e - cl
            Fe = Kl * pen * math.sqrt(pen)
            Uland += 0.4 * Kl * pen * pen * math.sqrt(pen)  # elastic energy 2/5 K pen^2.5
            fy -= Fe * uy
            fz -= Fe * uz
            if p.switches.friction:
                # sliding speed of the cage surface on the land: tangential speed of the axis point relative to
                # the land material there (omega_land e), plus the cage's spin relative to the land times R
                # The contact is on the +u side of the cage (outer-ring guidance: its outside diameter on the ring
                # land) or on its -u side (inner-ring guidance: the cage bore on the ring land), sgn = +1 / -1
                sgn = -1.0 if p.land.guide == GUIDE_INNER_RING else 1.0
                vt = -vy * uz + vz * uy - wl * e + sgn * (ew - wl * ex) * R
                ff = -Fe * pocket_friction_factor(vt, p.pocket.mu_c, p.pocket.v0_c) * vt
                fy += -ff * uz
                fz += ff * uy
                mx += sgn * ff * R
                Pland -= ff * vt
                Mring -= sgn * ff * R + e * ff  # reaction -ff t at the contact, (e - sgn R) u from the land centre
        Fly += fy
        Flz += fz
        Mlx += mx
        # moment of the land force (through the axis point a e) about the cage centre: a e x (0, fy, fz)
        Mtx += a * (ey * fz - ez * fy)
        Mty += -a * ex * fz
        Mtz += a * ex * fy
    if p.land.guide != GUIDE_INNER_RING:
        Mring = 0.0
    return Fly, Flz, Mlx, Mtx, Mty, Mtz, Mring, Pland, Uland


@njit(cache=True)
def global_rows(y, P, csum, ydot, gaux):
    """Cage and inner-ring rows of ydot from the summed ball contributions ``csum`` (Eqs. 11-21)."""
    p = P[0]
    Z = p.ball.Z
    cg = 9 * Z
    rg = cg + 12
    yc, zc = y[cg + 1], y[cg + 2]
    phd, psyd, pszd = y[cg + 9], y[cg + 10], y[cg + 11]
    Rc, (wcx, wcy, wcz), Jc = cage_orientation(y[cg + 3], y[cg + 4], y[cg + 5], phd, psyd, pszd)
    Fly, Flz, Mlx, Mtx, Mty, Mtz, Mring, Pland, Uland = guide_land_loads(y, P, Rc, wcx, wcy, wcz)
    inner_guided = p.land.guide == GUIDE_INNER_RING
    gaux[GAUX.F_cy] = Fly
    gaux[GAUX.F_cz] = Flz
    gaux[GAUX.M_cx] = Mlx
    gaux[GAUX.ring_torque] = csum[C_RMX] + Mring
    # land dissipation (film + rub friction, models.cage.guide_land_power), elastic rub energy, and the moment
    # about X (through the origin) of the land actions on the cage: c x F + the lands' offsets + Petroff torque
    gaux[GAUX.P_guide_land] = Pland
    gaux[GAUX.U_land] = Uland
    gaux[GAUX.land_torque_x] = yc * Flz - zc * Fly + Mtx + Mlx * Rc[0]
    # ---------------- cage balance (Eqs. 11-16): named wrenches, inertial axes, moments about the cage centre
    pockets = (csum[C_CFX], csum[C_CFY], csum[C_CFZ], csum[C_CMX], csum[C_CMY], csum[C_CMZ])  # reactions of the balls
    land = (0.0, Fly, Flz, Mlx * Rc[0], Mlx * Rc[3], Mlx * Rc[6])  # land films + rub; axial moment along the cage axis
    land_offset = (0.0, 0.0, 0.0, Mtx, Mty, Mtz)  # moment of the land forces applied at the lands' axial offsets
    gravity_c = (0.0, -p.cage.m_c * p.env.grav, 0.0, 0.0, 0.0, 0.0)
    Fcx, Fcy, Fcz, Mcx, Mcy, Mcz = _sum4_wrenches(pockets, land, land_offset, gravity_c)
    Qph, Qpy, Qpz = cage_generalised_moments(Mcx, Mcy, Mcz, Rc, Jc)
    a = cage_equations_of_motion(Fcx, Fcy, Fcz, Qph, Qpy, Qpz, phd, psyd, pszd, p.cage.m_c, p.cage.Ip_c, p.cage.Id_c)
    for k in range(6):
        ydot[cg + k] = y[cg + 6 + k]
        ydot[cg + 6 + k] = a[k]
    Rm, Jm = tilt_rotation(y[rg + 3], y[rg + 4])
    # drive: the moment along the ring's own axis e = R e_x that holds the prescribed spin against the
    # ball actions and the external moment; its power at the ring's angular velocity omega_i e + J beta'
    ex, ey, ez = Rm[0], Rm[3], Rm[6]
    Td = -((csum[C_RMX] + Mring) * ex + (p.ring.M_y + csum[C_RMY]) * ey + (p.ring.M_z + csum[C_RMZ]) * ez)
    byd, bzd = y[rg + 8], y[rg + 9]
    we = p.race.omega_i + ex * (Jm[1] * byd + Jm[2] * bzd) + ey * (Jm[4] * byd + Jm[5] * bzd) + ez * (Jm[7] * byd + Jm[8] * bzd)
    gaux[GAUX.drive_torque] = Td
    gaux[GAUX.P_drive] = Td * we
    # ---------------- inner-ring balance (Eqs. 17-21): named wrenches, inertial axes, moments about the ring centre
    Rly = Rlz = 0.0
    if inner_guided:  # the land film's reaction on the inner ring (its moment about the ring centre is neglected)
        Rly, Rlz = -Fly, -Flz
    loads = (p.ring.F_x, p.ring.F_y, p.ring.F_z, 0.0, p.ring.M_y, p.ring.M_z)  # external loads and moments
    balls = (csum[C_RFX], csum[C_RFY], csum[C_RFZ], csum[C_RMX], csum[C_RMY], csum[C_RMZ])  # inner-race reactions
    land_reaction = (0.0, Rly, Rlz, 0.0, 0.0, 0.0)
    gravity_i = (0.0, -p.ring.m_i * p.env.grav, 0.0, 0.0, 0.0, 0.0)
    Fix, Fiy, Fiz, Mix, Miy, Miz = _sum4_wrenches(loads, balls, land_reaction, gravity_i)
    Qy, Qz = tilt_generalised_moments(Mix, Miy, Miz, Rm, Jm)
    b = ring_equations_of_motion(Fix, Fiy, Fiz, Qy, Qz, p.race.omega_i, y[rg + 8], y[rg + 9], p.ring.m_i, p.ring.Ip_i,
                                 p.ring.Id_i)
    for k in range(5):
        ydot[rg + k] = y[rg + 5 + k]
        ydot[rg + 5 + k] = b[k]


@njit(cache=True)
def summed_global_rows(y, P, contrib, csum, ydot, gaux):
    """Sum the balls' contributions to the cage and ring loads over the balls (``csum``, one entry per
    ``C_*`` column of ``contrib``) and evaluate the cage and ring rows of ``ydot`` (:func:`global_rows`)."""
    p = P[0]
    Z = p.ball.Z
    for k in range(N_CONTRIB):
        acc = 0.0
        for j in range(Z):
            acc += contrib[j, k]
        csum[k] = acc
    global_rows(y, P, csum, ydot, gaux)


@njit(cache=True)
def rhs_kernel(y, P, qu, qw, ydot, contrib, aux, want_aux, csum, gaux):
    """Full right-hand side: ``ydot = f(y)`` (time does not appear explicitly)."""
    ball_loop(y, P, qu, qw, ydot, contrib, aux, want_aux)
    summed_global_rows(y, P, contrib, csum, ydot, gaux)


@njit(cache=True)
def jac_kernel(y, P, qu, qw, J, hscale, work):
    """Dense Jacobian d f / d y by the arrowhead-structured finite differences.

    Ball quantity k (k = 0..8) is perturbed for all Z balls at once: ball j's
    rows depend only on ball j's states (plus cage and ring), so one
    evaluation of :func:`ball_loop` gives the Z columns of that quantity, and
    the change of ball j's contribution to the ring and cage loads gives
    those rows (the ring/cage accelerations are linear in the summed
    contributions).  The 22 cage/ring states are perturbed one by one (an
    evaluation each; the 10 ring columns reuse the pocket wrenches of the unperturbed
    evaluation, which do not depend on ring states, and the cage columns but the cage
    angle reuse gravity and the race contacts, which do not depend on cage states
    other than the angle: bit-identical to the full evaluation).  31 evaluations
    instead of 9 Z + 22.

    hscale : per-state typical magnitudes (the perturbation is
    sqrt(eps) max(|y|, hscale)); work : scratch array of length >= 4 N.
    """
    p = P[0]
    Z = p.ball.Z
    N = y.size
    nb = 9 * Z
    f0 = work[0:N]
    f1 = work[N:2 * N]
    yp = work[2 * N:3 * N]
    h = work[3 * N:4 * N]
    c0 = np.empty((Z, N_CONTRIB))
    c1 = np.empty((Z, N_CONTRIB))
    aux = np.empty((1, 1))
    csum = np.empty(N_CONTRIB)
    gaux = np.empty(N_GAUX)
    for i in range(N):
        for k in range(N):
            J[i, k] = 0.0
    sq = 1.4901161193847656e-08
    for i in range(N):
        h[i] = sq * max(abs(y[i]), hscale[i])
    pc = np.empty((Z, 11))  # pocket wrench at y, reused for the ring columns (it does not depend on them)
    rc = np.empty((Z, 18))  # race contacts at y (inner wrench, ring contribution, outer wrench), reused for the
    # cage columns but the cage angle
    ball_loop_cached(y, P, qu, qw, f0, c0, aux, False, 1, pc, 1, rc)
    summed_global_rows(y, P, c0, csum, f0, gaux)
    cg = nb
    rg = nb + 12
    inv_c = (1.0 / p.cage.m_c, 1.0 / p.cage.m_c, 1.0 / p.cage.m_c, 1.0 / p.cage.Ip_c, 1.0 / p.cage.Id_c, 1.0 / p.cage.Id_c)
    inv_r = (1.0 / p.ring.m_i, 1.0 / p.ring.m_i, 1.0 / p.ring.m_i, 1.0 / p.ring.Id_i, 1.0 / p.ring.Id_i)
    ccols = (C_CFX, C_CFY, C_CFZ, C_CMX, C_CMY, C_CMZ)
    rcols = (C_RFX, C_RFY, C_RFZ, C_RMY, C_RMZ)
    Rm, Jm = tilt_rotation(y[rg + 3], y[rg + 4])
    Rc, _w, Jc = cage_orientation(y[cg + 3], y[cg + 4], y[cg + 5], y[cg + 9], y[cg + 10], y[cg + 11])
    for q in range(9):
        for i in range(N):
            yp[i] = y[i]
        for j in range(Z):
            yp[q * Z + j] += h[q * Z + j]
        ball_loop(yp, P, qu, qw, f1, c1, aux, False)
        for j in range(Z):
            col = q * Z + j
            hj = yp[col] - y[col]
            for m in range(9):
                J[m * Z + j, col] = (f1[m * Z + j] - f0[m * Z + j]) / hj
            for k in range(3):
                J[cg + 6 + k, col] = (c1[j, ccols[k]] - c0[j, ccols[k]]) * inv_c[k] / hj
            qa, qb, qc = cage_generalised_moments((c1[j, C_CMX] - c0[j, C_CMX]) / hj, (c1[j, C_CMY] - c0[j, C_CMY]) / hj,
                                                  (c1[j, C_CMZ] - c0[j, C_CMZ]) / hj, Rc, Jc)
            J[cg + 9, col] = qa * inv_c[3]
            J[cg + 10, col] = qb * inv_c[4]
            J[cg + 11, col] = qc * inv_c[5]
            for k in range(3):
                J[rg + 5 + k, col] = (c1[j, rcols[k]] - c0[j, rcols[k]]) * inv_r[k] / hj
            dmx = (c1[j, C_RMX] - c0[j, C_RMX]) / hj
            dmy = (c1[j, C_RMY] - c0[j, C_RMY]) / hj
            dmz = (c1[j, C_RMZ] - c0[j, C_RMZ]) / hj
            qy, qz = tilt_generalised_moments(dmx, dmy, dmz, Rm, Jm)  # linear in M
            J[rg + 8, col] = qy * inv_r[3]
            J[rg + 9, col] = qz * inv_r[4]
    for col in range(nb, N):
        for i in range(N):
            yp[i] = y[i]
        yp[col] += h[col]
        hj = yp[col] - y[col]
        rmode = 2 if (col < rg and col != cg + 3) else 0  # cage columns except the angle phi_c
        ball_loop_cached(yp, P, qu, qw, f1, c1, aux, False, 2 if col >= rg else 0, pc, rmode, rc)
        summed_global_rows(yp, P, c1, csum, f1, gaux)
        for i in range(N):
            J[i, col] = (f1[i] - f0[i]) / hj


# numba bakes callees and captured constants into its cache: key the cache on them (compile_cache.py)
check_compile_cache(globals())
