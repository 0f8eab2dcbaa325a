"""Independent reference for the pocket film: 2-D finite-volume Reynolds solution on the pocket wall.

Test helper only (not part of the package).  Solves, on the cylindrical wall of the pocket
(polar angle theta around the pocket axis, coordinate u along it),

    div(h^3 grad p / (12 eta)) = div(h U / 2) + dh/dt,      p >= 0   (complementarity)

with the *exact* sphere-in-cylinder gap h(theta, u) (first intersection of the wall's inward
normal line with the ball), the exact ball-surface velocity v + omega x rho at the ball point
facing each wall point (tangential part; dh/dt from the ball-centre velocity by differencing the
exact gap), the exact pocket edges (cage bore / outside cylinders cut the wall), and both
Poiseuille directions.  Finite volumes on a uniform theta grid (periodic) and a sinh-clustered
u grid; the edges enter with their exact distance (Shortley-Weller) along u.  The linear
complementarity problem (p >= 0, w = M p + b >= 0, p w = 0 -- Christopherson's p >= 0 = the
Reynolds exit condition) is solved by a primal-dual active-set iteration with sparse direct solves.

The force and moment on the ball: pressure along the exact ball normal, shear
-eta U_t / h - (h/2) grad p on the ball surface (flooded, full-film Couette, the same assumption
as the model), moment rho x shear.
"""

from __future__ import annotations

import numpy as np
import scipy.sparse as sp
import scipy.sparse.linalg as spla


def _gap(theta, u, b, Rb, Rp):
    """Exact gap along the wall's inward normal, wall point (Rp cos th, u, Rp sin th) in (x, r, t)."""
    cx, ct = np.cos(theta), np.sin(theta)
    dx = Rp * cx - b[0]
    dr = u - b[1]
    dt = Rp * ct - b[2]
    dn = dx * cx + dt * ct
    d2 = dx * dx + dr * dr + dt * dt
    disc = dn * dn - d2 + Rb * Rb
    return dn - np.sqrt(np.maximum(disc, 0.0))


def _surface(theta, u, b, v, w, Rb, Rp):
    """Gap, tangential relative surface velocity (U_theta, U_u), dh/dt and rho at wall points."""
    h = _gap(theta, u, b, Rb, Rp)
    cx, ct = np.cos(theta), np.sin(theta)
    # ball point facing the wall point
    px = Rp * cx - h * cx - b[0]
    pr = u - b[1]
    pt = Rp * ct - h * ct - b[2]
    # v + omega x rho   (x, r, t) components
    Vx = v[0] + w[1] * pt - w[2] * pr
    Vr = v[1] + w[2] * px - w[0] * pt
    Vt = v[2] + w[0] * pr - w[1] * px
    Us = -Vx * ct + Vt * cx  # along theta_hat = (-sin, 0, cos)
    Uu = Vr
    # dh/dt = grad_b h . v  (central differences of the exact gap)
    db = 1e-9
    ht = 0.0
    for k in range(3):
        bp = np.array(b, dtype=float)
        bm = np.array(b, dtype=float)
        bp[k] += db
        bm[k] -= db
        ht = ht + (_gap(theta, u, bp, Rb, Rp) - _gap(theta, u, bm, Rb, Rp)) / (2 * db) * v[k]
    return h, Us, Uu, ht, (px, pr, pt)


def solve_pocket_film(e_x, e_t, s0, v, w, eta, Rb, Rp, R_bore, R_out, hdm, n_theta=720, n_u=220):
    """2-D Reynolds solution with p >= 0; returns dict(F=(Fx,Fr,Ft), M=(Mx,Mr,Mt), W=int p dA, p, theta, u, iters).

    Positions in the pocket frame (x: cage axis, r: pocket axis, t: circumferential), relative to the
    pocket centre; v, w: ball velocity and angular velocity relative to the cage, (x, r, t) [SI].
    """
    b = np.array([e_x, s0, e_t], dtype=float)
    v = np.asarray(v, dtype=float)
    w = np.asarray(w, dtype=float)
    c = Rp - Rb
    e = np.hypot(e_x, e_t)
    Lmin = np.sqrt(2 * Rb * (c - e))
    th = (np.arange(n_theta) + 0.5) * 2 * np.pi / n_theta
    dth = 2 * np.pi / n_theta
    ds = Rp * dth
    st = np.sin(th)
    ulo = np.sqrt(R_bore**2 - (Rp * st) ** 2) - hdm
    uhi = np.sqrt(R_out**2 - (Rp * st) ** 2) - hdm
    A = 0.5 * Lmin
    z = np.linspace(np.arcsinh((ulo.min() - s0) / A), np.arcsinh((uhi.max() - s0) / A), n_u)
    ug = s0 + A * np.sinh(z)
    TH, U = np.meshgrid(th, ug, indexing="ij")
    inside = (U > ulo[:, None]) & (U < uhi[:, None])
    N = n_theta * n_u
    idx = np.arange(N).reshape(n_theta, n_u)
    # neighbour positions along u (grid node or the exact edge)
    inside_dn = np.zeros_like(inside)
    inside_dn[:, 1:] = inside[:, :-1]
    inside_up = np.zeros_like(inside)
    inside_up[:, :-1] = inside[:, 1:]
    u_dn = np.where(inside_dn, np.roll(U, 1, axis=1), ulo[:, None])
    u_up = np.where(inside_up, np.roll(U, -1, axis=1), uhi[:, None])
    f_dn = 0.5 * (U + u_dn)
    f_up = 0.5 * (U + u_up)
    du = f_up - f_dn
    # face quantities
    h_dn, Us_dn, Uu_dn, _, _ = _surface(TH, f_dn, b, v, w, Rb, Rp)
    h_up, Us_up, Uu_up, _, _ = _surface(TH, f_up, b, v, w, Rb, Rp)
    h_w, Us_w, Uu_w, _, _ = _surface(TH - 0.5 * dth, U, b, v, w, Rb, Rp)
    h_e, Us_e, Uu_e, _, _ = _surface(TH + 0.5 * dth, U, b, v, w, Rb, Rp)
    h_c, Us_c, Uu_c, ht_c, rho = _surface(TH, U, b, v, w, Rb, Rp)
    with np.errstate(divide="ignore", invalid="ignore"):  # outside nodes: masked below
        C_dn = h_dn**3 / (12 * eta) / (U - u_dn) * ds
        C_up = h_up**3 / (12 * eta) / (u_up - U) * ds
    C_w = h_w**3 / (12 * eta) / ds * du
    C_e = h_e**3 / (12 * eta) / ds * du
    # Couette outflow + storage
    rhs = (0.5 * h_up * Uu_up - 0.5 * h_dn * Uu_dn) * ds + (0.5 * h_e * Us_e - 0.5 * h_w * Us_w) * du + ht_c * ds * du
    rows, cols, vals = [], [], []
    diag = C_dn + C_up + C_w + C_e
    I = idx[inside]
    rows.append(I)
    cols.append(I)
    vals.append(diag[inside])
    # off-diagonals (only to inside neighbours; outside neighbours are p = 0)
    for Cn, nb_idx, nb_in in ((C_dn, np.roll(idx, 1, axis=1), inside_dn), (C_up, np.roll(idx, -1, axis=1), inside_up),
                              (C_w, np.roll(idx, 1, axis=0), np.roll(inside, 1, axis=0)),
                              (C_e, np.roll(idx, -1, axis=0), np.roll(inside, -1, axis=0))):
        m = inside & nb_in
        rows.append(idx[m])
        cols.append(nb_idx[m])
        vals.append(-Cn[m])
    M = sp.csr_matrix((np.concatenate(vals), (np.concatenate(rows), np.concatenate(cols))), shape=(N, N))
    Mi = M[I][:, I].tocsc()
    bi = rhs[inside]
    # primal-dual active set for p >= 0, w = M p + b >= 0, p w = 0
    free = np.ones(I.size, dtype=bool)
    p = np.zeros(I.size)
    for it in range(200):
        p[:] = 0.0
        if free.any():
            p[free] = spla.spsolve(Mi[free][:, free].tocsc(), -bi[free])
        wv = Mi @ p + bi
        new_free = np.where(free, p > 0.0, wv < 0.0)
        if np.array_equal(new_free, free):
            break
        free = new_free
    P = np.zeros((n_theta, n_u))
    P[inside] = np.maximum(p, 0.0)
    # forces on the ball: pressure along the exact ball normal rho / |rho|, shear on the ball surface
    px, pr, pt = rho
    rn = np.sqrt(px**2 + pr**2 + pt**2)
    dA = np.where(inside, ds * du, 0.0)
    Fx = -np.sum(P * px / rn * dA)
    Fr = -np.sum(P * pr / rn * dA)
    Ft = -np.sum(P * pt / rn * dA)
    # pressure gradient (central differences; p = 0 at edges / outside)
    Pdn = np.where(inside_dn, np.roll(P, 1, axis=1), 0.0)
    Pup = np.where(inside_up, np.roll(P, -1, axis=1), 0.0)
    dpdu = (Pup - Pdn) / (u_up - u_dn)
    dpds = (np.roll(P, -1, axis=0) - np.roll(P, 1, axis=0)) / (2 * ds)
    tau_s = -eta * Us_c / h_c - 0.5 * h_c * dpds
    tau_u = -eta * Uu_c / h_c - 0.5 * h_c * dpdu
    cx, ct = np.cos(TH), np.sin(TH)
    Tx = tau_s * (-ct)
    Tt = tau_s * cx
    Tr = tau_u
    Fx += np.sum(Tx * dA)
    Fr += np.sum(Tr * dA)
    Ft += np.sum(Tt * dA)
    Mx = np.sum((pr * Tt - pt * Tr) * dA)
    Mr = np.sum((pt * Tx - px * Tt) * dA)
    Mt = np.sum((px * Tr - pr * Tx) * dA)
    # viscous dissipation (Couette over the flooded wall + Poiseuille where p > 0)
    D = np.sum((eta * (Us_c**2 + Uu_c**2) / h_c + h_c**3 * (dpds**2 + dpdu**2) / (12 * eta) * (P > 0)) * dA)
    return dict(F=np.array([Fx, Fr, Ft]), M=np.array([Mx, Mr, Mt]), W=float(np.sum(P * dA)), D=float(D), p=P,
                theta=th, u=ug, iters=it + 1)
