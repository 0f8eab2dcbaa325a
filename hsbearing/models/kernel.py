"""Compiled right-hand side and arrowhead Jacobian of the bearing dynamic model (seed 004, Eqs. 5-21).

Everything here is numba-compiled and allocation-free per call.  The physics
lives in the named functions of :mod:`hsbearing.models.ball`,
:mod:`~hsbearing.models.cage`, :mod:`~hsbearing.models.ring`,
:mod:`~hsbearing.models.drag` and the traction law of
:mod:`hsbearing.models.traction.zhang2016`; this module only assembles them
over the balls.  State layout: :mod:`hsbearing.solvers.state`.  Parameter
vector: the ``P_*`` indices below, filled by :func:`hsbearing.dynamics.build_model`.

Structure (used by the Jacobian): :func:`ball_loop` computes, for each ball
j, the derivatives of its 9 states (they depend only on ball j, the cage and
the ring) and its *contribution* to the generalised forces on the inner ring
and on the cage (array ``contrib[j, :]``, columns ``C_*``); :func:`global_rows`
sums the contributions, adds the ring loads and the guide-land film, and
writes the 22 ring/cage rows.
"""

from __future__ import annotations

import math

import numpy as np
from numba import njit

from hsbearing.models.ball import ball_equations_of_motion, ehl_rolling_force, groove_contact, hertz_normal_load
from hsbearing.models.cage import (cage_equations_of_motion, guide_land_forces, guide_land_torque,
                                   pocket_friction_factor, pocket_normal_force, smooth_eccentricity)
from hsbearing.models.drag import ball_drag_force
from hsbearing.models.ring import inner_groove_centre, ring_equations_of_motion
from hsbearing.models.traction.zhang2016 import coefficients_nb, mu_nb

# ---------------------------------------------------------------------------- parameter indices
_names = """Z D m_b I_b rho_i g_i off_i rho_o g_o off_o K_i K_o cd_i cd_o acoef_i acoef_o
omega_i omega_o Ep Rx_i Rx_o k_i k_o eta_in alpha T_K law_id U_eps s_eps friction damping dm
c_p K_c eta_film Rsq_c h_min mu_c v0_c rho_e C_D v0_D m_c Ip_c Id_c R_land L_land c_land eps_max
K_land m_i Ip_i Id_i F_x F_y F_z M_y M_z ehl drag e_eps grav""".split()
P_INDEX = {n: i for i, n in enumerate(_names)}
N_PARAMS = len(_names)
(P_Z, P_D, P_MB, P_IB, P_RHOI, P_GI, P_OFFI, P_RHOO, P_GO, P_OFFO, P_KI, P_KO, P_CDI, P_CDO, P_ACI, P_ACO,
 P_WI, P_WO, P_EP, P_RXI, P_RXO, P_KEI, P_KEO, P_ETAIN, P_ALPHA, P_TK, P_LAW, P_UEPS, P_SEPS, P_FRIC, P_DAMP, P_DM,
 P_CP, P_KC, P_ETAF, P_RSQC, P_HMIN, P_MUC, P_V0C, P_RHOE, P_CDRAG, P_V0D, P_MC, P_IPC, P_IDC, P_RLAND, P_LLAND,
 P_CLAND, P_EPSMAX, P_KLAND, P_MI, P_IPI, P_IDI, P_FX, P_FY, P_FZ, P_MY, P_MZ, P_EHL, P_DRAG, P_EEPS,
 P_GRAV) = range(N_PARAMS)

# contribution columns: forces/moments on the inner ring (inertial X, Y, Z; moments about its centre)
# and on the cage (inertial; moments about the cage centre)
C_RFX, C_RFY, C_RFZ, C_RMY, C_RMZ, C_RMX, C_CFX, C_CFY, C_CFZ, C_CMX, C_CMY, C_CMZ = range(12)
N_CONTRIB = 12

# per-ball auxiliary outputs (written only when want_aux)
_aux = """Q_i Q_o alpha_i alpha_o T_roll_i T_trans_i T_roll_o T_trans_o S_i S_o U_i U_o Q_c P_S F_R_i F_R_o F_D
spin_roll_i spin_roll_o""".split()
AUX_INDEX = {n: i for i, n in enumerate(_aux)}
N_AUX = len(_aux)
# global auxiliary outputs
_gaux = "F_cy F_cz M_cx ring_torque".split()
GAUX_INDEX = {n: i for i, n in enumerate(_gaux)}
N_GAUX = len(_gaux)


@njit(cache=True, inline="always")
def _cross(ax, ay, az, bx, by, bz):
    return ay * bz - az * by, az * bx - ax * bz, ax * by - ay * bx


@njit(cache=True)
def _race_contact(P, qu, qw, Q, nx, nr, x, r, vx, vr, thd, wx, wy, wz,
                  rvx, rvr, rvt, ox, orr, ot, Wx, Wr, Wt, Rx, ke, acoef):
    """Traction and EHL rolling force of one ball/race contact, in the ball frame (x, r, t).

    (rvx, rvr, rvt): race translational velocity; (ox, orr, ot): race centre
    position; (Wx, Wr, Wt): race angular velocity -- all in the ball frame.
    Returns the force on the ball (fx, fr, ft), the moment about the ball
    centre (mx, mr, mt), traction components (rolling, transverse), centre
    slide-roll ratio, rolling speed U, F_R and the spin-to-roll ratio.
    """
    D2 = 0.5 * P[P_D]
    fx = fr = ft = 0.0
    mx = mr = mt = 0.0
    T1 = T2 = 0.0
    S0 = 0.0
    U = 0.0
    FR = 0.0
    spin_roll = 0.0
    if Q <= 0.0:
        return fx, fr, ft, mx, mr, mt, T1, T2, S0, U, FR, spin_roll
    # contact centre on the ball: rho0 = -(D/2) n
    r0x, r0r = -D2 * nx, -D2 * nr
    # rolling speed: mean surface speed along t relative to the moving contact
    vbx, vbr, vbt = _cross(wx, wy, wz, r0x, r0r, 0.0)
    vbt += r * thd
    px, pr, pt = x + r0x - ox, r + r0r - orr, 0.0 - ot
    vrx, vrr, vrt = _cross(Wx, Wr, Wt, px, pr, pt)
    vrt += rvt
    vct = (r + r0r) * thd
    Ut = 0.5 * (vbt + vrt) - vct
    U = math.sqrt(Ut * Ut + P[P_UEPS] ** 2)
    # spin-to-roll ratio (relative angular velocity along the normal / rolling speed)
    spin_roll = ((wx - Wx) * (-nx) + (wy - Wr) * (-nr)) * D2 / U
    fric = P[P_FRIC]
    if fric > 0.0:
        A, B, C, Dd = coefficients_nb(int(P[P_LAW]), Q, U, P[P_TK], P[P_EP], Rx)
        a = acoef * Q ** (1.0 / 3.0)  # semi-major axis, constant ellipticity
        seps = P[P_SEPS]
        for k in range(qu.size):
            phi = a * qu[k] / D2
            cp, sp = math.cos(phi), math.sin(phi)
            rx_ = D2 * (-cp * nx + sp * nr)
            rr_ = D2 * (-cp * nr - sp * nx)
            t2x, t2r = sp * nx + cp * nr, sp * nr - cp * nx
            # ball surface velocity
            bx, br, bt = _cross(wx, wy, wz, rx_, rr_, 0.0)
            bx += vx
            br += vr
            bt += r * thd
            # race surface velocity at the same point
            px, pr, pt = x + rx_ - ox, r + rr_ - orr, -ot
            gx, gr, gt = _cross(Wx, Wr, Wt, px, pr, pt)
            gx += rvx
            gr += rvr
            gt += rvt
            dvx, dvr, dvt = bx - gx, br - gr, bt - gt
            s1 = dvt
            s2 = dvx * t2x + dvr * t2r
            Sreg = math.sqrt(s1 * s1 + s2 * s2 + seps * seps) / U
            mu = mu_nb(A, B, C, Dd, Sreg)
            q = Q * qw[k]
            f = -q * mu / (Sreg * U)  # traction opposes the local slip  [5] of models.ball
            f1 = f * s1
            f2 = f * s2
            Fx_, Fr_, Ft_ = f2 * t2x, f2 * t2r, f1
            fx += Fx_
            fr += Fr_
            ft += Ft_
            cx, cr, ct = _cross(rx_, rr_, 0.0, Fx_, Fr_, Ft_)
            mx += cx
            mr += cr
            mt += ct
            T1 += f1
            T2 += f2
            if k == qu.size // 2:
                S0 = s1 / U
    if P[P_EHL] > 0.0:
        FR = ehl_rolling_force(U, Q, Rx, ke, P[P_EP], P[P_ETAIN], P[P_ALPHA])
        sg = Ut / U
        # F_R at the contact against the rolling sense, F_H = F_R through the ball centre:
        # a pure couple on the ball (seed Eq. 7 signs; docs/dynamics.md)
        cx, cr, ct = _cross(r0x, r0r, 0.0, 0.0, 0.0, -FR * sg)
        mx += cx
        mr += cr
        mt += ct
    return fx, fr, ft, mx, mr, mt, T1, T2, S0, U, FR, spin_roll


@njit(cache=True)
def ball_loop(y, P, qu, qw, ydot, contrib, aux, want_aux):
    """Ball rows of ydot and per-ball contributions to the ring and cage loads (see module doc)."""
    Z = int(P[P_Z])
    D2 = 0.5 * P[P_D]
    m, I = P[P_MB], P[P_IB]
    cg = 9 * Z
    xc, yc, zc, phc, psy, psz = y[cg], y[cg + 1], y[cg + 2], y[cg + 3], y[cg + 4], y[cg + 5]
    vxc, vyc, vzc, phd, psyd, pszd = y[cg + 6], y[cg + 7], y[cg + 8], y[cg + 9], y[cg + 10], y[cg + 11]
    rg = cg + 12
    xi, yi, zi, by, bz = y[rg], y[rg + 1], y[rg + 2], y[rg + 3], y[rg + 4]
    vxi, vyi, vzi, byd, bzd = y[rg + 5], y[rg + 6], y[rg + 7], y[rg + 8], y[rg + 9]
    wi, wo = P[P_WI], P[P_WO]
    fric, damp = P[P_FRIC], P[P_DAMP]
    hdm = 0.5 * P[P_DM]
    for j in range(Z):
        # state: u_b (radial displacement from the pitch circle), psi_b (angle from the pocket line)
        x, r, th = y[j], hdm + y[Z + j], phc + 2.0 * math.pi * j / Z + y[2 * Z + j]
        vx, vr, thd = y[3 * Z + j], y[4 * Z + j], y[5 * Z + j]
        wx, wy, wz = y[6 * Z + j], y[7 * Z + j], y[8 * Z + j]
        c, s = math.cos(th), math.sin(th)
        # gravity along -Y (horizontal shaft): (0, -g, 0) in the ball frame is (0, -g cos th, g sin th)
        Fx = 0.0
        Fr = -m * P[P_GRAV] * c
        Ft = m * P[P_GRAV] * s
        Mx = Mr = Mt = 0.0
        # ---------------- inner race contact (Eqs. 5-10, Q_i, T_i, F_R,i)
        cx, cr, cxd, crd = inner_groove_centre(th, P[P_RHOI], P[P_GI], xi, yi, zi, by, bz, vxi, vyi, vzi, byd, bzd, thd)
        dlt, nxi, nri = groove_contact(cx - x, cr - r, P[P_OFFI])
        dltd = nxi * (cxd - vx) + nri * (crd - vr)
        Qi = hertz_normal_load(dlt, dltd, P[P_KI], P[P_CDI] * damp)
        # inner ring kinematics in the ball frame
        rvx, rvr, rvt = vxi, vyi * c + vzi * s, -vyi * s + vzi * c
        ox, orr, ot = xi, yi * c + zi * s, -yi * s + zi * c
        Wx, Wr, Wt = wi, byd * c + bzd * s, -byd * s + bzd * c
        (tfx, tfr, tft, tmx, tmr, tmt, Ti1, Ti2, Si, Ui, FRi, sri) = _race_contact(
            P, qu, qw, Qi, nxi, nri, x, r, vx, vr, thd, wx, wy, wz,
            rvx, rvr, rvt, ox, orr, ot, Wx, Wr, Wt, P[P_RXI], P[P_KEI], P[P_ACI])
        fbx = Qi * nxi + tfx  # force of the inner race on the ball (ball frame)
        fbr = Qi * nri + tfr
        fbt = tft
        Fx += fbx
        Fr += fbr
        Ft += fbt
        Mx += tmx
        Mr += tmr
        Mt += tmt
        # reaction on the inner ring at the contact centre (inertial frame), moment about its centre
        gx, gy, gz = -fbx, -(fbr * c - fbt * s), -(fbr * s + fbt * c)
        rc = r - D2 * nri
        ax_, ay_, az_ = x - D2 * nxi - xi, rc * c - yi, rc * s - zi
        mrx, mry, mrz = _cross(ax_, ay_, az_, gx, gy, gz)
        contrib[j, C_RFX] = gx
        contrib[j, C_RFY] = gy
        contrib[j, C_RFZ] = gz
        contrib[j, C_RMY] = mry
        contrib[j, C_RMZ] = mrz
        contrib[j, C_RMX] = mrx
        # ---------------- outer race contact (fixed outer ring, speed wo about X)
        dlt_o, nxo, nro = groove_contact(P[P_GO] - x, P[P_RHOO] - r, P[P_OFFO])
        dltd_o = -nxo * vx - nro * vr
        Qo = hertz_normal_load(dlt_o, dltd_o, P[P_KO], P[P_CDO] * damp)
        (tfx, tfr, tft, tmx, tmr, tmt, To1, To2, So, Uo, FRo, sro) = _race_contact(
            P, qu, qw, Qo, nxo, nro, x, r, vx, vr, thd, wx, wy, wz,
            0.0, 0.0, 0.0, 0.0, 0.0, 0.0, wo, 0.0, 0.0, P[P_RXO], P[P_KEO], P[P_ACO])
        Fx += Qo * nxo + tfx
        Fr += Qo * nro + tfr
        Ft += tft
        Mx += tmx
        Mr += tmr
        Mt += tmt
        # ---------------- cage pocket (Q_c, P_S), computed in the pocket frame (e_x, e_rp, e_tp)
        phj = phc + 2.0 * math.pi * j / Z
        cph, sph = math.cos(phj), math.sin(phj)
        dl = th - phj
        cdl, sdl = math.cos(dl), math.sin(dl)
        Px = xc + hdm * (psy * sph - psz * cph)
        Pr = yc * cph + zc * sph + hdm
        Pt = -yc * sph + zc * cph
        dx_ = x - Px
        dr_ = r * cdl - Pr
        dt_ = r * sdl - Pt
        # absolute velocities in the pocket frame
        vbx_, vbr_, vbt_ = vx, vr * cdl - r * thd * sdl, vr * sdl + r * thd * cdl
        Vcx = vxc
        Vcr = vyc * cph + vzc * sph
        Vct = -vyc * sph + vzc * cph
        dPx = vxc + hdm * (psyd * sph - pszd * cph + (psy * cph + psz * sph) * phd)
        ddx = vbx_ - dPx
        ddt = vbt_ - (Vct + phd * hdm) - phd * dr_
        e = math.sqrt(dx_ * dx_ + dt_ * dt_ + P[P_EEPS] ** 2)
        npx, npt = dx_ / e, dt_ / e
        ed = npx * ddx + npt * ddt
        Qc = pocket_normal_force(e, ed, P[P_CP], P[P_KC], P[P_ETAF] * damp, P[P_RSQC], P[P_HMIN])
        fpx, fpr, fpt = -Qc * npx, 0.0, -Qc * npt  # on the ball, pocket frame
        PS = 0.0
        mpx = mpr = mpt = 0.0
        if fric > 0.0 and Qc > 0.0:
            # contact point on the ball: b + (D/2) n ; ball angular velocity in the pocket frame
            wpx, wpr, wpt = wx, wy * cdl - wz * sdl, wy * sdl + wz * cdl
            kx, kr, kt = D2 * npx, 0.0, D2 * npt
            sbx, sbr, sbt = _cross(wpx, wpr, wpt, kx, kr, kt)
            sbx += vbx_
            sbr += vbr_
            sbt += vbt_
            # cage point velocity: V_c + Omega_c x (X - C), X - C = (Px - xc + kx, Pr' + ...)
            Xx, Xr, Xt = dx_ + kx + (Px - xc), dr_ + Pr - (yc * cph + zc * sph), dt_ + kt + Pt - (-yc * sph + zc * cph)
            Wcx, Wcr, Wct = phd, psyd * cph + pszd * sph, -psyd * sph + pszd * cph
            scx, scr, sct = _cross(Wcx, Wcr, Wct, Xx, Xr, Xt)
            scx += Vcx
            scr += Vcr
            sct += Vct
            dvx, dvr, dvt = sbx - scx, sbr - scr, sbt - sct
            dvn = dvx * npx + dvt * npt
            dvx -= dvn * npx
            dvt -= dvn * npt
            vs = math.sqrt(dvx * dvx + dvr * dvr + dvt * dvt)
            ff = -Qc * pocket_friction_factor(vs, P[P_MUC], P[P_V0C])
            ffx, ffr, fft = ff * dvx, ff * dvr, ff * dvt
            PS = abs(ff) * vs
            fpx += ffx
            fpr += ffr
            fpt += fft
            mpx, mpr, mpt = _cross(kx, kr, kt, ffx, ffr, fft)
        # to the ball frame (e_r = cdl e_rp + sdl e_tp, e_t = -sdl e_rp + cdl e_tp)
        Fx += fpx
        Fr += fpr * cdl + fpt * sdl
        Ft += -fpr * sdl + fpt * cdl
        Mx += mpx
        Mr += mpr * cdl + mpt * sdl
        Mt += -mpr * sdl + mpt * cdl
        # reaction on the cage (inertial), moment about the cage centre
        gcx, gcr, gct = -fpx, -fpr, -fpt
        Xx, Xr, Xt = Px - xc + dx_ + D2 * npx, hdm + dr_, dt_ + D2 * npt  # contact point minus cage centre (pocket frame)
        mcx, mcr, mct = _cross(Xx, Xr, Xt, gcx, gcr, gct)
        contrib[j, C_CFX] = gcx
        contrib[j, C_CFY] = gcr * cph - gct * sph
        contrib[j, C_CFZ] = gcr * sph + gct * cph
        contrib[j, C_CMX] = mcx
        contrib[j, C_CMY] = mcr * cph - mct * sph
        contrib[j, C_CMZ] = mcr * sph + mct * cph
        # ---------------- drag in the air-oil mixture (F_D, Eq. 7)
        FD = 0.0
        if P[P_DRAG] > 0.0:
            FD = ball_drag_force(r * thd, P[P_D], P[P_RHOE], P[P_CDRAG], P[P_V0D])
            Ft += FD
        # ---------------- equations of motion (Eqs. 5-10)
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
            aux[j, 0] = Qi
            aux[j, 1] = Qo
            aux[j, 2] = math.atan2(nxi, nri)
            aux[j, 3] = math.atan2(-nxo, -nro)
            aux[j, 4] = Ti1
            aux[j, 5] = Ti2
            aux[j, 6] = To1
            aux[j, 7] = To2
            aux[j, 8] = Si
            aux[j, 9] = So
            aux[j, 10] = Ui
            aux[j, 11] = Uo
            aux[j, 12] = Qc
            aux[j, 13] = PS
            aux[j, 14] = FRi
            aux[j, 15] = FRo
            aux[j, 16] = FD
            aux[j, 17] = sri
            aux[j, 18] = sro


@njit(cache=True)
def global_rows(y, P, csum, ydot, gaux):
    """Cage and inner-ring rows of ydot from the summed ball contributions ``csum`` (Eqs. 11-21)."""
    Z = int(P[P_Z])
    cg = 9 * Z
    rg = cg + 12
    yc, zc = y[cg + 1], y[cg + 2]
    vyc, vzc, phd, psyd, pszd = y[cg + 7], y[cg + 8], y[cg + 9], y[cg + 10], y[cg + 11]
    # guide land (outer ring): short journal bearing film + elastic rub
    cl = P[P_CLAND]
    e = math.sqrt(yc * yc + zc * zc + (P[P_EEPS] * 1e-2) ** 2)
    uy, uz = yc / e, zc / e
    Fly = Flz = Mlx = 0.0
    if P[P_DAMP] > 0.0:
        eps = smooth_eccentricity(e / cl, P[P_EPSMAX])
        ed = (yc * vyc + zc * vzc) / e
        whirl = (yc * vzc - zc * vyc) / (e * e)
        Fr, Ft = guide_land_forces(eps, ed / cl, phd + P[P_WO], whirl, P[P_ETAF], P[P_RLAND], P[P_LLAND], cl)
        Fly += Fr * uy - Ft * uz
        Flz += Fr * uz + Ft * uy
    if P[P_FRIC] > 0.0:
        eps = smooth_eccentricity(e / cl, P[P_EPSMAX])
        Mlx = guide_land_torque(eps, phd - P[P_WO], P[P_ETAF], P[P_RLAND], P[P_LLAND], cl)
    if e > cl:
        # elastic rub of the cage on the land (Hertz-like penalty), with regularised Coulomb friction
        pen = e - cl
        Fe = P[P_KLAND] * pen * math.sqrt(pen)
        Fly -= Fe * uy
        Flz -= Fe * uz
        if P[P_FRIC] > 0.0:
            R = P[P_RLAND]
            vt = -vyc * uz + vzc * uy + (phd - P[P_WO]) * R  # sliding speed of the cage surface on the land
            ff = -Fe * pocket_friction_factor(vt, P[P_MUC], P[P_V0C]) * vt
            Fly += -ff * uz
            Flz += ff * uy
            Mlx += ff * R
    gaux[0] = Fly
    gaux[1] = Flz
    gaux[2] = Mlx
    gaux[3] = csum[C_RMX]
    a = cage_equations_of_motion(csum[C_CFX], csum[C_CFY] + Fly - P[P_MC] * P[P_GRAV], csum[C_CFZ] + Flz, csum[C_CMX] + Mlx,
                                 csum[C_CMY], csum[C_CMZ], phd, psyd, pszd, P[P_MC], P[P_IPC], P[P_IDC])
    for k in range(6):
        ydot[cg + k] = y[cg + 6 + k]
        ydot[cg + 6 + k] = a[k]
    b = ring_equations_of_motion(P[P_FX] + csum[C_RFX], P[P_FY] + csum[C_RFY] - P[P_MI] * P[P_GRAV], P[P_FZ] + csum[C_RFZ],
                                 P[P_MY] + csum[C_RMY], P[P_MZ] + csum[C_RMZ], P[P_WI], y[rg + 8], y[rg + 9],
                                 P[P_MI], P[P_IPI], P[P_IDI])
    for k in range(5):
        ydot[rg + k] = y[rg + 5 + k]
        ydot[rg + 5 + k] = b[k]


@njit(cache=True)
def rhs_kernel(y, P, qu, qw, ydot, contrib, aux, want_aux, csum, gaux):
    """Full right-hand side: ``ydot = f(y)`` (time does not appear explicitly)."""
    ball_loop(y, P, qu, qw, ydot, contrib, aux, want_aux)
    Z = int(P[P_Z])
    for k in range(N_CONTRIB):
        acc = 0.0
        for j in range(Z):
            acc += contrib[j, k]
        csum[k] = acc
    global_rows(y, P, csum, ydot, gaux)


@njit(cache=True)
def jac_kernel(y, P, qu, qw, J, hscale, work):
    """Dense Jacobian d f / d y by the arrowhead-structured finite differences.

    Ball quantity k (k = 0..8) is perturbed for all Z balls at once: ball j's
    rows depend only on ball j's states (plus cage and ring), so one
    evaluation of :func:`ball_loop` gives the Z columns of that quantity, and
    the change of ball j's contribution to the ring and cage loads gives
    those rows (the ring/cage accelerations are linear in the summed
    contributions).  The 22 cage/ring states are perturbed one by one (a full
    evaluation each).  31 evaluations instead of 9 Z + 22.

    hscale : per-state typical magnitudes (the perturbation is
    sqrt(eps) max(|y|, hscale)); work : scratch array of length >= 4 N.
    """
    Z = int(P[P_Z])
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
    ball_loop(y, P, qu, qw, f0, c0, aux, False)
    for k in range(N_CONTRIB):
        acc = 0.0
        for j in range(Z):
            acc += c0[j, k]
        csum[k] = acc
    global_rows(y, P, csum, f0, gaux)
    cg = nb
    rg = nb + 12
    inv_c = (1.0 / P[P_MC], 1.0 / P[P_MC], 1.0 / P[P_MC], 1.0 / P[P_IPC], 1.0 / P[P_IDC], 1.0 / P[P_IDC])
    inv_r = (1.0 / P[P_MI], 1.0 / P[P_MI], 1.0 / P[P_MI], 1.0 / P[P_IDI], 1.0 / P[P_IDI])
    ccols = (C_CFX, C_CFY, C_CFZ, C_CMX, C_CMY, C_CMZ)
    rcols = (C_RFX, C_RFY, C_RFZ, C_RMY, C_RMZ)
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
            for k in range(6):
                J[cg + 6 + k, col] = (c1[j, ccols[k]] - c0[j, ccols[k]]) * inv_c[k] / hj
            for k in range(5):
                J[rg + 5 + k, col] = (c1[j, rcols[k]] - c0[j, rcols[k]]) * inv_r[k] / hj
    for col in range(nb, N):
        for i in range(N):
            yp[i] = y[i]
        yp[col] += h[col]
        hj = yp[col] - y[col]
        ball_loop(yp, P, qu, qw, f1, c1, aux, False)
        for k in range(N_CONTRIB):
            acc = 0.0
            for j in range(Z):
                acc += c1[j, k]
            csum[k] = acc
        global_rows(yp, P, csum, f1, gaux)
        for i in range(N):
            J[i, col] = (f1[i] - f0[i]) / hj
