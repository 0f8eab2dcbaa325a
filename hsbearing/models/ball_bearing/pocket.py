"""Ball / cylindrical-pocket lubricating film: hydrodynamic force and moment (P_R of Zhang et al. 2016, Eqs. 5-16).

The pocket of Zhang et al. 2016 is a cylinder of radius R_p (4.8125 mm) drilled radially through the cage ring
(bore R_bore, outside R_out); the ball (radius R_b, 4.7625 mm) sits inside with a radial play
c = R_p - R_b (50 um).  Pocket frame, right-handed (x, r, t): x along the cage axis, r along the
pocket axis (bearing radial direction), t circumferential.  The wall point at polar angle theta
around the pocket axis has the outward normal n = cos(theta) e_x + sin(theta) e_t and the tangent
theta_hat = -sin(theta) e_x + cos(theta) e_t; its coordinate along the pocket axis is u.

Film model (all functions below, docs/pocket.md):

* gap: h = a(theta) + x^2 / (2 R_b), a = c - e . n, x = u - s_0 (s_0: ball centre along the pocket
  axis) -- sphere in a cylinder, first order in e/R_b and x/R_b ([3], Ch. 3 gap of conformal
  surfaces);
* Reynolds equation of a thin isoviscous film between the wall (at rest in the cage frame) and
  the ball surface ([3], Ch. 7, general form with translation and squeeze):
  div(h^3 grad p / (12 eta)) = div(h U / 2) + dh/dt, U = ball surface velocity relative to the wall;
* the gap varies along the pocket axis over L = sqrt(2 R_b a) (0.14-0.7 mm) and around it over
  R_p sqrt(2 a / e) (>= 1.4 mm): each station theta is a line contact (Martin's rigid-isoviscous
  cylinder, [1], [3] Ch. 17) with its own entraining speed along the pocket axis, the
  circumferential (journal) wedge and the squeeze as a uniform source, and the pocket edges as
  p = 0 inlets (flooded pocket).  The 1-D problem is solved in closed form with the Reynolds
  (Swift-Stieber) cavitation condition p = dp/dx = 0 at the film rupture, i.e. the p >= 0
  complementarity solution ([3], Ch. 8; [4]);
* stations are summed around the pocket with a periodic trapezoidal rule on a conformal map
  that concentrates the nodes near the thinnest film (:func:`station_angle`);
* shear: Couette -eta dU/h over the whole wetted wall (flooded pocket) + Poiseuille -(h/2) dp/dx;
  pressure acts along the ball normal (through the ball centre), shear at the ball surface.

The wrench on the ball is returned; the kernel applies the opposite wrench to the cage on the
same line of action, so force and moment are closed exactly, and the dissipated power is
-(F . v_rel + M . omega_rel) (:func:`pocket_film_power`).

References
----------
[1] Martin H. M., "Lubrication of gear teeth", Engineering 102 (1916) 119-121 (rigid cylinder on a
    plane, isoviscous, Reynolds exit condition: W' = 4.9 eta u_mean R / h_0).
[2] Brewe D. E., Hamrock B. J., Taylor C. M., "Effect of geometry on hydrodynamic film thickness",
    J. Lubr. Technol. 101 (1979) 231-239 (rigid-isoviscous ball/ellipsoid conjunctions).
[3] Hamrock B. J., Schmid S. R., Jacobson B. O., *Fundamentals of Fluid Film Lubrication*, 2nd ed.,
    Dekker 2004: Ch. 7 (Reynolds equation: physical wedge, stretch, translation, squeeze terms),
    Ch. 8 (cavitation: half-Sommerfeld, Reynolds/Swift-Stieber condition), Ch. 17 (rigid cylinder
    near a plane), Ch. 18-21 (rigid-isoviscous / elastic regimes of the four-regime map).
[4] Christopherson D. G., "A new mathematical method for the solution of film lubrication
    problems", Proc. IMechE 146 (1941) 126-135 (p >= 0 complementarity = Reynolds condition).
[5] Gupta P. K., *Advanced Dynamics of Rolling Elements*, Springer 1984: ball/cage interaction
    (hydrodynamic pocket force in the rigid-isoviscous regime, elastic contact when the film
    collapses, boundary friction).
[6] Harris T. A., Kotzalas M. N., *Rolling Bearing Analysis*, 5th ed., Vol. 1, Ch. 6 (Hertz point
    contact, Q = K delta^1.5).
"""

from __future__ import annotations

import math
from collections import namedtuple

import numpy as np
from numba import njit

from hsbearing.compile_cache import check_compile_cache

__all__ = ["station_film", "station_angle", "pocket_edges", "pocket_film_wrench", "pocket_film_gap",
           "pocket_elastic_force", "pocket_boundary_friction", "pocket_film_power", "pocket_wrench",
           "PocketKinematics", "PocketParams", "PocketWrench"]

# ---------------------------------------------------------------- named arguments and result of pocket_wrench
# Plain named tuples (numba compiles them as tuples: a field read is a register, no cost); the fields are read
# by name, so two same-typed quantities cannot be swapped silently.
#: the ball's offset and motion relative to its pocket, pocket frame (x: cage axis, r: pocket axis, t: circumferential)
PocketKinematics = namedtuple("PocketKinematics", [
    "ex",  # ball-centre offset from the pocket axis along x [m]
    "et",  # ... along t [m]
    "s0",  # ball-centre offset along the pocket axis from the pocket centre (pitch radius) [m]
    "vx", "vr", "vt",  # ball-centre velocity relative to the pocket (cage frame) [m/s]
    "wx", "wr", "wt",  # ball angular velocity relative to the cage [rad/s]
])
#: pocket geometry, film and contact constants
PocketParams = namedtuple("PocketParams", [
    "eta",  # film viscosity [Pa s] (0: no film)
    "Rb",  # ball radius [m]
    "Rp",  # pocket radius [m]
    "R_bore",  # cage bore radius [m]
    "R_out",  # cage outside radius [m]
    "hdm",  # pocket-centre radius d_m/2 [m]
    "n_st",  # stations around the pocket wall (int, even)
    "h_c",  # film floor [m]
    "K",  # Hertz constant ball/pocket [N/m^1.5]
    "mu",  # boundary friction coefficient [-] (0: none)
    "v0",  # Coulomb regularisation speed [m/s]
])
#: the pocket wrench on the ball (pocket frame) and its by-products
PocketWrench = namedtuple("PocketWrench", [
    "Fx", "Fr", "Ft",  # force on the ball [N]
    "Mx", "Mr", "Mt",  # moment on the ball about its centre [N m]
    "Q_film",  # film normal load [N]
    "Q_solid",  # Hertz load [N]
    "P_film",  # power dissipated by the film [W]
    "P_boundary",  # power dissipated by boundary friction [W]
    "P_S",  # boundary friction force magnitude [N]
])


# ---------------------------------------------------------------- 1-D line-contact integrals
@njit(cache=True, fastmath=True, inline="always")
def _kk(xi, at):
    """int_0^xi dxi/H^2, int_0^xi dxi/H^3, an antiderivative of xi/H^3 (H = 1 + xi^2, at = atan(xi)) and 1/H.

    One division (divisions are a large part of a station's cost)."""
    iH = 1.0 / (1.0 + xi * xi)
    xh = xi * iH
    return 0.5 * (xh + at), xh * (0.25 * iH + 0.375) + 0.375 * at, -0.25 * (iH * iH), iH


# ---------------------------------------------------------------- rupture: tabulated start for the Newton solve
# The free boundary xi_2 of :func:`_station_dimless` (when it lies inside the wall) depends only on the
# source sign change xs = -beta/(2A) and the inlet edge lo (not on hi).  A bilinear table of
# g = (xi_2 - xs)/(xs - lo) > 0 (1/2 for a vanishing inlet) over the mapped plane
# (z / sqrt(_RUP_C^2 + z^2) for z = xs, lo)
# gives the Newton iteration a start within ~1e-3 of the root, so it stops after ~2 iterations instead of
# ~4 from Martin's infinite-inlet start.  The table only moves the start: the iteration and
# its stopping rule are unchanged, the returned root is the same exact root (docs/pocket.md "Cost").
_RUP_N = 96  # nodes per axis (cell-centred on (-1, 1))
_RUP_C = 4.0  # [-] half-width of the mapped range: resolution ~0.1 near the film minimum


@njit(cache=True, fastmath=True)
def _rupture_exact(xs, lo):
    """Root xi_2 > xs of the free-boundary residual for A = 1, beta = -2 xs, no far edge.

    Bracketing + Newton to 1e-14 (table construction only)."""
    b = -2.0 * xs
    k2l, k3l, m3l, _ = _kk(lo, math.atan(lo))
    a_ = xs
    b_ = xs + 0.5 + math.sqrt(1.0 + xs * xs)
    for _ in range(200):  # bracket: G < 0 at b_
        k2x, k3x, m3x, _ = _kk(b_, math.atan(b_))
        if (k2x - k2l) + b * (m3x - m3l) - ((1.0 + b_ * b_) + b * b_) * (k3x - k3l) < 0.0:
            break
        a_ = b_
        b_ = xs + 2.0 * (b_ - xs)
    x = 0.5 * (a_ + b_)
    for _ in range(200):
        k2x, k3x, m3x, _ = _kk(x, math.atan(x))
        dk3 = k3x - k3l
        G = (k2x - k2l) + b * (m3x - m3l) - ((1.0 + x * x) + b * x) * dk3
        if G > 0.0:
            a_ = x
        else:
            b_ = x
        dG = -(2.0 * x + b) * dk3
        xn = x - G / dG if dG < 0.0 else 0.5 * (a_ + b_)
        if not (a_ < xn < b_):
            xn = 0.5 * (a_ + b_)
        if abs(xn - x) <= 1e-14 * (1.0 + abs(x)) or b_ - a_ <= 1e-14 * (1.0 + abs(x)):
            return xn
        x = xn
    return x


@njit(cache=True)
def _rupture_table(n, cmap):
    """Table of g = (xi_2 - xs)/(xs - lo) on the cell-centred grid of the mapped (xs, lo) plane (1/2 where lo >= xs)."""
    T = np.empty((n, n))
    for i in range(n):
        ps = -1.0 + (i + 0.5) * 2.0 / n
        xs = cmap * ps / math.sqrt(1.0 - ps * ps)
        for j in range(n):
            pl = -1.0 + (j + 0.5) * 2.0 / n
            lo = cmap * pl / math.sqrt(1.0 - pl * pl)
            if lo >= xs or (xs - lo) < 1e-6 * (1.0 + abs(xs)):
                T[i, j] = 0.5  # the limit for a vanishing inlet (local symmetric bump)
            else:
                T[i, j] = (_rupture_exact(xs, lo) - xs) / (xs - lo)
    return T


check_compile_cache(globals())  # before the import-time call below; again at the end
_RUP_TABLE = _rupture_table(_RUP_N, _RUP_C)


@njit(cache=True, fastmath=True, inline="always")
def _rupture_guess(xs, lo):
    """Start for the rupture Newton solve: xs + g (xs - lo), g bilinear in :data:`_RUP_TABLE` (a guess only)."""
    n = _RUP_N
    us = (xs / math.sqrt(_RUP_C * _RUP_C + xs * xs) + 1.0) * (0.5 * n) - 0.5
    ul = (lo / math.sqrt(_RUP_C * _RUP_C + lo * lo) + 1.0) * (0.5 * n) - 0.5
    us = min(max(us, 0.0), n - 1.000001)
    ul = min(max(ul, 0.0), n - 1.000001)
    i = int(us)
    j = int(ul)
    # integer clamp as well: whatever the float path gave (the caller passes finite arguments only),
    # the table is never read outside its bounds
    i = min(max(i, 0), n - 2)
    j = min(max(j, 0), n - 2)
    fs = us - i
    fl = ul - j
    g = ((1.0 - fs) * ((1.0 - fl) * _RUP_TABLE[i, j] + fl * _RUP_TABLE[i, j + 1])
         + fs * ((1.0 - fl) * _RUP_TABLE[i + 1, j] + fl * _RUP_TABLE[i + 1, j + 1]))
    return xs + g * (xs - lo)


@njit(cache=True, fastmath=True, inline="always")
def _atan_diff(x, lo):
    """atan(x) - atan(lo) with one libm call: atan((x - lo)/(1 + x lo)), shifted by +-pi where 1 + x lo < 0.

    Exact identity (the difference lies in (-pi, pi)); it is also free of the cancellation of two nearly equal
    atans when x is close to lo.  All station integrals use only such differences (docs/pocket.md).
    """
    num = x - lo
    den = 1.0 + x * lo
    if den > 0.0:
        return math.atan(num / den)
    if den < 0.0:
        return math.atan(num / den) + (math.pi if num > 0.0 else -math.pi)
    return math.copysign(0.5 * math.pi, num)


@njit(cache=True, fastmath=True, inline="always")
def _atan_near(x, xp, atp, lo):
    """atan(x) - atan(lo) from atp = atan(xp) - atan(lo) for a nearby xp (the previous Newton iterate), no libm call.

    atan(x) = atan(xp) + atan(u), u = (x - xp)/(1 + x xp) (valid for x xp > -1); for |u| < 0.02 the odd
    series of atan(u) to u^9 is exact to |u|^11/11 < 2e-20; otherwise (or if x xp <= -1) :func:`_atan_diff`.
    """
    den = 1.0 + x * xp
    if den > 0.0:
        u = (x - xp) / den
        if abs(u) < 0.02:
            u2 = u * u
            return atp + u * (1.0 - u2 * (1.0 / 3.0 - u2 * (0.2 - u2 * (1.0 / 7.0 - u2 * (1.0 / 9.0)))))
    return _atan_diff(x, lo)


# short pressurised interval (the source sign change xs within _SHORT sqrt(1 + lo^2) of the inlet edge lo): the
# closed form's integrals are differences of O(1) antiderivatives for a result of order (xs - lo)^4, so they lose
# all digits there (docs/pocket.md "Short pressurised interval"); Gauss-Legendre quadrature of the factored
# integrands is used instead (5 nodes on an interval of at most 1.6 _SHORT local widths: relative error < 1e-13)
_SHORT = 0.05
_GL5_X = np.array([-0.9061798459386640, -0.5384693101056831, 0.0, 0.5384693101056831, 0.9061798459386640])
_GL5_W = np.array([0.2369268850561891, 0.4786286704993665, 0.5688888888888889, 0.4786286704993665,
                   0.2369268850561891])


@njit(cache=True, fastmath=True)
def _station_short(A, beta, lo, xs):
    """:func:`_station_dimless` for a short pressurised interval (A > 0, 0 < xs - lo <= _SHORT sqrt(1 + lo^2)).

    With gamma = -(A H2 + beta x2) the pressure gradient factors as P'(t) = (t - x2)(A (t + x2) + beta)/H(t)^3,
    so the rupture residual G(x2) = P(x2) = int_lo^x2 (t - x2)(A (t + x2) + beta)/H^3 dt, its derivative
    -(2 A x2 + beta) int dt/H^3, IP = int P dt = -int (x2 - t)^2 (A (t + x2) + beta)/H^3 dt and
    IPxi = int P t dt = int (x2^2 - t^2)/2 P'(t) dt are integrals of smooth, cancellation-free integrands over
    [lo, x2]: 5-point Gauss-Legendre, Newton from the short-interval limit x2 = lo + 1.5 (xs - lo) (G ~ A X^2
    (S - 2 X/3)/H^3 with X = x2 - lo, S = xs - lo).  Returns (xi_2, IP, IPxi); the far edge is beyond 2 S.
    """
    X = 1.5 * (xs - lo)
    for _ in range(30):
        x = lo + X
        G = 0.0
        I3 = 0.0
        for i in range(5):
            t = lo + 0.5 * X * (1.0 + _GL5_X[i])
            iH = 1.0 / (1.0 + t * t)
            w3 = _GL5_W[i] * iH * iH * iH
            G += w3 * (t - x) * (A * (t + x) + beta)
            I3 += w3
        G *= 0.5 * X
        dG = -(2.0 * A * x + beta) * 0.5 * X * I3
        if not dG < 0.0:
            break
        dX = -G / dG
        X += dX
        if abs(dX) <= 1e-14 * X:
            break
    x2 = lo + X
    IP = 0.0
    IPxi = 0.0
    for i in range(5):
        t = lo + 0.5 * X * (1.0 + _GL5_X[i])
        iH = 1.0 / (1.0 + t * t)
        q = _GL5_W[i] * iH * iH * iH * (x2 - t) * (A * (t + x2) + beta)  # -(t - x2)(...)/H^3 w
        IP -= q * (x2 - t)
        IPxi -= q * 0.5 * (x2 + t) * (x2 - t)
    return x2, 0.5 * X * IP, 0.5 * X * IPxi


@njit(cache=True, fastmath=True)
def _station_dimless(A, beta, lo, hi, dat_hi, tabulated=True):
    """Dimensionless line contact with A >= 0: returns (xi_2, IP, IPxi).

    dP/dxi = A / H^2 + beta xi / H^3 + gamma / H^3, H = 1 + xi^2, P(lo) = P(xi_2) = 0, P > 0
    inside, p >= 0 complementarity (Reynolds exit condition P = P' = 0 at a free xi_2 < hi).
    IP = int P dxi, IPxi = int P xi dxi over [lo, xi_2]; dat_hi = atan(hi) - atan(lo) (:func:`_atan_diff`).
    Every atan enters as a difference from atan(lo), so atan(lo) is taken as the origin (at_lo = 0).
    ``tabulated``: start the rupture Newton solve from :func:`_rupture_guess` (default) instead of
    Martin's infinite-inlet exit and take atan of the later iterates from the previous one
    (:func:`_atan_near`, exact to round-off); ``False`` is the reference (kept for the tests); both
    converge to the same root with the same stopping rule.
    """
    if not hi > lo:  # no wall left at this station (the pocket edges meet): no film
        return lo, 0.0, 0.0
    at_lo = 0.0  # atans relative to atan(lo)
    at_hi = dat_hi
    if A <= 0.0:
        if beta >= 0.0:
            return lo, 0.0, 0.0
        x2 = hi  # pure approach: the whole wall is pressurised
        at2 = at_hi
    else:
        xs = -beta / (2.0 * A)  # source 2 A xi + beta < 0 for xi < xs: pressure builds there
        if xs <= lo:
            return lo, 0.0, 0.0
        S = xs - lo
        if S * S <= (_SHORT * _SHORT) * (1.0 + lo * lo) and hi - lo >= 2.0 * S:
            return _station_short(A, beta, lo, xs)  # cancellation-free form for a short interval
        k2l, k3l, m3l, _ = _kk(lo, at_lo)
        # free boundary G(x2) = P(x2) with gamma = -(A H2 + beta x2); G > 0 on (lo, xs], concave, decreasing after
        k2h, k3h, m3h, _ = _kk(hi, at_hi)
        Ghi = A * (k2h - k2l) + beta * (m3h - m3l) - (A * (1.0 + hi * hi) + beta * hi) * (k3h - k3l)
        if Ghi >= 0.0:
            x2 = hi
            at2 = at_hi
        else:
            # Newton inside the bracket (xs, hi)
            a_ = xs
            b_ = hi
            # start: Martin's exit 0.475 (infinite inlet, no source) scaled by the local width sqrt(1 + xs^2)
            if tabulated and abs(xs) < 1e300 and lo > -1e300:  # (A vanishing: xs overflows; Martin's start)
                x = _rupture_guess(xs, lo)
                if x <= a_:
                    x = xs + 0.475 * math.sqrt(1.0 + xs * xs)
            else:
                x = xs + 0.475 * math.sqrt(1.0 + xs * xs)
            if x >= b_:
                x = b_
            at2 = at_hi
            xp = x
            atp = 0.0
            for it in range(60):
                if tabulated and it > 0:
                    at2 = _atan_near(x, xp, atp, lo)
                else:
                    at2 = _atan_diff(x, lo)
                xp = x
                atp = at2
                k2x, k3x, m3x, iHx = _kk(x, at2)
                dk3 = k3x - k3l
                G = A * (k2x - k2l) + beta * (m3x - m3l) - (A * (1.0 + x * x) + beta * x) * dk3
                if G > 0.0:
                    a_ = x
                else:
                    b_ = x
                dG = -(2.0 * A * x + beta) * dk3
                xn = x - G / dG if dG < 0.0 else b_
                if not (a_ <= xn <= b_):
                    # G is concave and decreasing beyond xs: from a point left of the root the Newton step
                    # overshoots; from the right bracket point (G < 0) Newton converges monotonically
                    xn = b_ if G > 0.0 else 0.5 * (a_ + b_)
                elif abs(xn - x) <= 1e-6 * (1.0 + abs(x)):
                    # quadratic convergence: xn is exact to ~1e-12; atan(xn) to first order (error ~ step^2)
                    at2 += (xn - x) * iHx
                    x = xn
                    break
                x = xn
            x2 = x
    k2l, k3l, m3l, iHl = _kk(lo, at_lo)
    k2x, k3x, m3x, iH2 = _kk(x2, at2)
    H2 = 1.0 + x2 * x2
    dk2 = k2x - k2l
    dk3 = k3x - k3l
    dm3 = m3x - m3l
    if x2 < hi:
        gamma = -(A * H2 + beta * x2)
    else:  # full film to the far edge: P(hi) = 0
        gamma = -(A * dk2 + beta * dm3) / dk3
    d1 = 0.5 * (iHl - iH2)  # [int xi/H^2]
    d2 = dm3  # [int xi/H^3] = [-1/(4 H^2)]
    dat = at2 - at_lo
    # int P = -int xi P' ; int P xi = -(1/2) int xi^2 P'   (P = 0 at both ends)
    IP = -(A * d1 + beta * (dk2 - dk3) + gamma * d2)
    IPxi = -0.5 * (A * (dat - dk2) + beta * (d1 - d2) + gamma * (dk2 - dk3))  # int xi^3/H^3 = [int xi/H^2] - [int xi/H^3]
    return x2, IP, IPxi


@njit(cache=True, fastmath=True, inline="always")
def _station(a, U_e, F0, lo, hi, dat, L, eta, tabulated=True):
    """:func:`station_film` on the dimensionless edges (lo, hi) = x/L, dat = atan(hi) - atan(lo): (W, Wx, x1, x2) / L."""
    A = 6.0 * eta * U_e
    ia = 1.0 / a
    beta = F0 * L * ia
    if A >= 0.0:
        x2, IP, IPxi = _station_dimless(A, beta, lo, hi, dat, tabulated)
        x1 = lo
    else:  # mirror xi -> -xi: (A, beta, gamma) -> (-A, beta, -gamma)
        x2m, IP, IPxi = _station_dimless(-A, beta, -hi, -lo, dat, tabulated)  # atan(-lo) - atan(-hi) = dat
        x1, x2 = -x2m, hi
        IPxi = -IPxi
    s = L * L * ia * ia
    return s * IP, (s * L) * IPxi, x1, x2  # p = (L/a^2) P, dx = L dxi


@njit(cache=True)
def station_film(a, U_e, F0, x_lo, x_hi, R, eta):
    """Rigid-isoviscous line contact at one pocket station: pressure integrals per unit wall length.

    Solves (h^3 p')' = 6 eta U_e h' + F0 on x in [x_lo, x_hi] with h = a + x^2/(2R), p = 0 at the
    edges, p >= 0 (Reynolds exit condition p = p' = 0 at the film rupture) in closed form
    ([3], Ch. 7-8 and 17; [1] for F0 = 0 and infinite edges: W' = 4.9 eta (U_e/2) R / a).

    Parameters
    ----------
    a : minimum gap at the station [m]; U_e : entraining speed of the ball surface along the pocket
    axis relative to the gap shape [m/s]; F0 : uniform source 6 eta U_s dh/ds - 12 eta v_n
    (circumferential wedge and squeeze) [Pa m]; x_lo, x_hi : pocket edges relative
    to the ball centre along the pocket axis [m]; R : ball radius [m]; eta : viscosity [Pa s].

    Returns
    -------
    W : int p dx [N/m]; Wx : int p x dx [N]; x1, x2 : pressurised interval [m].
    """
    L = math.sqrt(2.0 * R * a)
    lo, hi = x_lo / L, x_hi / L
    W, Wx, x1, x2 = _station(a, U_e, F0, lo, hi, _atan_diff(hi, lo), L, eta)
    return W, Wx, x1 * L, x2 * L


_TQ_N = 16  # the kernel's station count (MODEL_DEFAULTS pocket_stations)
# tan(tau_i / 2) of the station nodes tau_i = -pi + (i + 1/2) 2 pi / n for n = _TQ_N, tabulated once (it
# saves the per-station division of the rotation recurrence in :func:`pocket_film_wrench`; other n use it)
_TQ_TABLE = np.tan(0.5 * (-np.pi + (np.arange(_TQ_N) + 0.5) * 2.0 * np.pi / _TQ_N))


@njit(cache=True, inline="always")
def station_angle(tau, k):
    """Conformal map theta(tau) = 2 atan(k tan(tau/2)) and d theta / d tau [-].

    With k = sqrt((c - e)/(c + e)) it would turn d theta / (c - e cos theta) into d tau / sqrt(c^2 - e^2);
    :func:`pocket_film_wrench` uses k = ((c - e)/(c + e))^(1/4), half as strong, which also keeps
    stations on the thick side where the entraining speed changes sign (measured: 16 stations give
    the force to 0.3 % of the film load for e/c <= 0.995; tests/models/test_pocket.py).  Periodic and
    analytic: the trapezoidal rule keeps its accuracy.
    """
    half = 0.5 * tau
    ch, sh = math.cos(half), math.sin(half)
    th = 2.0 * math.atan2(k * sh, ch)
    dth = k / (ch * ch + k * k * sh * sh)
    return th, dth


@njit(cache=True, inline="always")
def pocket_edges(sin_theta, Rp, R_bore, R_out, hdm):
    """Pocket wall extent along the pocket axis at polar angle theta, from the pocket centre [m].

    The wall point at theta is R_p sin(theta) off the pocket axis circumferentially; the cage bore
    and outside cylinders (about the cage axis) cut the wall at sqrt(R^2 - (R_p sin theta)^2) - d_m/2.
    """
    t2 = (Rp * sin_theta) ** 2
    return math.sqrt(R_bore * R_bore - t2) - hdm, math.sqrt(R_out * R_out - t2) - hdm


@njit(cache=True, inline="always")
def _station_kinematics(tq, k, cte, ste, e, c, vx, vr, vt, wx, wr, wt, eta, Rb, Rp, R_bore, R_out, hdm, s0):
    """One station of :func:`pocket_film_wrench` at tan(tau/2) = ``tq``: wall geometry and film inputs.

    :func:`station_angle` in rational form (T = k tan(tau/2), cos = (1 - T^2)/(1 + T^2), sin = 2 T/(1 + T^2)),
    the gap a = c - e . n, the ball's surface velocity relative to the wall along the pocket axis and around
    it, the entraining speed U_e, the source F0 (circumferential wedge + squeeze) and the edges in units of
    the local contact width L = sqrt(2 R_b a) (module docstring; [3] Ch. 7).  Returns
    (d theta/d tau, n_x, n_t, q_x, q_t, a, dU_u, dU_s, U_e, F0, L, lo, hi).
    """
    T = k * tq
    den = 1.0 / (1.0 + T * T)
    cp, sp = (1.0 - T * T) * den, 2.0 * T * den
    dph = k * (1.0 + tq * tq) * den
    # station angle in the pocket plane: measured from the offset direction
    cth = cte * cp - ste * sp
    sth = ste * cp + cte * sp
    a = c - e * cp  # a = c - e . n
    nx, nt = cth, sth  # wall normal n
    qx, qt = -sth, cth  # tangent theta_hat
    # relative surface velocity of the ball at the equator point R_b n (wall at rest)
    wq = wx * qx + wt * qt  # omega . theta_hat
    dUu = vr + Rb * wq  # along e_r (pocket axis): v_r + R_b omega . theta_hat   (n x e_r = theta_hat)
    dUs = vx * qx + vt * qt - Rb * wr  # along theta_hat                          (n x theta_hat = -e_r)
    vn = vx * nx + vt * nt
    Ue = dUu - 2.0 * vr  # entraining speed relative to the moving gap shape (Galilean form)
    hs = e * sp / Rp  # dh/ds = -(e . theta_hat)/R_p
    F0 = 6.0 * eta * dUs * hs - 12.0 * eta * vn
    xlo, xhi = pocket_edges(sth, Rp, R_bore, R_out, hdm)
    L = math.sqrt(2.0 * Rb * a)
    iL = 1.0 / L
    return dph, nx, nt, qx, qt, a, dUu, dUs, Ue, F0, L, (xlo - s0) * iL, (xhi - s0) * iL


@njit(cache=True, inline="always")
def _station_wrench(W, Wx, I1, I1x, eta, dUu, dUs, Rb, ds, nx, nt, qx, qt):
    """Force and moment on the ball of one station of wall arc length ``ds`` (:func:`pocket_film_wrench`).

    Pressure (W = int p dx, Wx = int p x dx) along the ball normal (R_b n + x e_r)/R_b, pushing the ball off
    the wall; shear at the ball surface: Couette -eta dU/h over the wetted wall (I1 = int dx/h, I1x = int x dx/h)
    + Poiseuille -(h/2) dp/dx ([3] Ch. 7).  Moment about the ball centre (R_b n + x e_r) x (T_u e_r + T_s
    theta_hat) = R_b T_u theta_hat - R_b T_s e_r + (int x T_s) n.  Returns the increments
    (Fx, Fr, Ft, Mx, Mr, Mt, W_n) in the pocket frame.
    """
    Tu = -eta * dUu * I1 + 0.5 * Wx / Rb  # shear on the ball along e_r: Couette + Poiseuille
    Ts = -eta * dUs * I1  # along theta_hat
    Tsx = -eta * dUs * I1x
    fn = -W
    fr = -Wx / Rb + Tu
    return (ds * (fn * nx + Ts * qx), ds * fr, ds * (fn * nt + Ts * qt),
            ds * (Rb * Tu * qx + Tsx * nx), ds * (-Rb * Ts), ds * (Rb * Tu * qt + Tsx * nt), ds * W)


@njit(cache=True, inline="always")
def _offset_frame(ex, et, Rb, Rp):
    """Radial clearance c = Rp - Rb [m], offset e = |(ex, et)| [m], its direction (cos, sin) in the pocket's
    (x, t) plane (x for a centred ball), and k = ((c - e)/(c + e))^(1/4), the conformal-map factor of
    :func:`station_angle` with half the exponent that would make the map exact (docstring there)."""
    c = Rp - Rb
    e = math.sqrt(ex * ex + et * et)
    if e > 0.0:
        cte, ste = ex / e, et / e
    else:
        cte, ste = 1.0, 0.0
    k = math.sqrt(math.sqrt((c - e) / (c + e)))
    return c, e, cte, ste, k


@njit(cache=True, fastmath=True)
def _pocket_film_wrench_reference(ex, et, s0, vx, vr, vt, wx, wr, wt, eta, Rb, Rp, R_bore, R_out, hdm, n_st):
    """:func:`pocket_film_wrench` station by station with the reference rupture start (``tabulated=False``).

    The scalar form, one station at a time, kept as the reference of the batched form (tests/models/test_pocket.py).
    """
    c, e, cte, ste, k = _offset_frame(ex, et, Rb, Rp)
    Fx = Fr = Ft = 0.0
    Mx = Mr = Mt = 0.0
    Wn = 0.0
    dtau = 2.0 * math.pi / n_st
    # half-angles tau/2 = -pi/2 + (i + 1/2) dtau/2 by a rotation recurrence (no tan per station)
    ch, sh = math.sin(0.25 * dtau), -math.cos(0.25 * dtau)
    cd, sd = math.cos(0.5 * dtau), math.sin(0.5 * dtau)
    tab = n_st == _TQ_N
    for _i in range(n_st):
        if tab:
            tq = _TQ_TABLE[_i]
        else:
            tq = sh / ch
            ch, sh = ch * cd - sh * sd, sh * cd + ch * sd
        dph, nx, nt, qx, qt, a, dUu, dUs, Ue, F0, L, lo, hi = _station_kinematics(
            tq, k, cte, ste, e, c, vx, vr, vt, wx, wr, wt, eta, Rb, Rp, R_bore, R_out, hdm, s0)
        dat = _atan_diff(hi, lo)  # atan(hi) - atan(lo): one libm atan per station
        W, Wx, x1, x2 = _station(a, Ue, F0, lo, hi, dat, L, eta, False)
        I1 = L * dat / a
        I1x = Rb * math.log((1.0 + hi * hi) / (1.0 + lo * lo))
        f = _station_wrench(W, Wx, I1, I1x, eta, dUu, dUs, Rb, Rp * dph * dtau, nx, nt, qx, qt)
        Fx += f[0]
        Fr += f[1]
        Ft += f[2]
        Mx += f[3]
        Mr += f[4]
        Mt += f[5]
        Wn += f[6]
    return Fx, Fr, Ft, Mx, Mr, Mt, Wn


# ---------------------------------------------------------------- batched stations
# The stations of a pocket are independent: they are solved _LANES at a time, each pass over the lanes a loop
# without data-dependent control flow (selects only), which LLVM compiles to SIMD instructions (measured: the
# 16 stations' rupture Newton sweep in ~30 ns instead of ~16 x 8 ns).  No libm call may sit in those loops
# (numba has no vector maths library here: llvmlite is not SVML-patched), hence :func:`_atan_poly`.
_LANES = 16  # lanes per batch (stations), the row stride of the work array
# rows of the work array (row r of lane i at r * _LANES + i)
(_R_LO, _R_HI, _R_DAT, _R_A, _R_L, _R_AM, _R_BETA, _R_LOM, _R_HIM, _R_MIR, _R_ST, _R_X, _R_AA, _R_BB, _R_AT,
 _R_K2L, _R_K3L, _R_M3L, _R_NX, _R_NT, _R_DUU, _R_DUS, _R_DPH, _R_W, _R_WX, _R_TQ) = range(26)
_NROWS = 26
# lane status (row _R_ST)
_ST_NONE, _ST_FULL, _ST_NEWTON, _ST_DONE, _ST_SHORT = 0.0, 1.0, 2.0, 3.0, 4.0

#: atan(w) = w + w s P(s), s = w^2, |w| <= tan(pi/8): coefficients of P (ascending powers of s), Chebyshev
#: interpolant of (atan(sqrt s)/sqrt s - 1)/s on [0, tan^2(pi/8)] (200 nodes, degree 11; tools/generators/make_atan_poly.py)
_ATAN_P = (-0.3333333333333333, 0.1999999999999646, -0.14285714285177972, 0.11111111070489664,
           -0.09090907322824225, 0.07692259804866149, -0.06665821580002596, 0.0587240345196698,
           -0.05184542582264705, 0.043494961312255, -0.02952046932450224, 0.010821815583843321)
_TAN_PI8 = 0.41421356237309503  # tan(pi/8)
_TAN_3PI8 = 2.414213562373095  # tan(3 pi/8)


@njit(cache=True, inline="always")
def _atan_poly(t):
    """atan(t) [rad] for any real t without a libm call (vectorisable); relative error <= 4 ulp (2^-53).

    Reduction by the exact identities atan(z) = pi/4 + atan((z - 1)/(z + 1)) for tan(pi/8) < z <= tan(3 pi/8)
    and atan(z) = pi/2 - atan(1/z) beyond, z = |t| (one division), to |w| <= tan(pi/8); there atan(w) =
    w + w s P(s) with the degree-11 polynomial :data:`_ATAN_P`, whose relative error over the reduced range is
    1.1 ulp measured on 200001 points against long-double atan (the interpolant's own error is below 1e-18:
    Chebyshev coefficients of an analytic function with its nearest singularity at s = -1 decay like 25^-n).
    The reduction adds <= 2.5 ulp (rounded w, pi/4 and pi/2, one addition).  Checked against long-double
    atan over 1e-300 <= |t| <= 1e300 by tests/models/test_pocket.py::test_atan_poly_error_bound.  atan(+-inf) = +-pi/2.
    """
    z = abs(t)
    big = z > _TAN_3PI8
    mid = z > _TAN_PI8
    num = -1.0 if big else (z - 1.0 if mid else z)
    den = z if big else (z + 1.0 if mid else 1.0)
    w = num / den
    base = 0.5 * math.pi if big else (0.25 * math.pi if mid else 0.0)
    s = w * w
    p = _ATAN_P[11]
    p = p * s + _ATAN_P[10]
    p = p * s + _ATAN_P[9]
    p = p * s + _ATAN_P[8]
    p = p * s + _ATAN_P[7]
    p = p * s + _ATAN_P[6]
    p = p * s + _ATAN_P[5]
    p = p * s + _ATAN_P[4]
    p = p * s + _ATAN_P[3]
    p = p * s + _ATAN_P[2]
    p = p * s + _ATAN_P[1]
    p = p * s + _ATAN_P[0]
    r = base + (w + w * (s * p))
    return r if t >= 0.0 else -r


@njit(cache=True, inline="always")
def _atan_diff_poly(x, lo):
    """atan(x) - atan(lo) as :func:`_atan_diff` (same identity, same branches as selects) with :func:`_atan_poly`."""
    num = x - lo
    den = 1.0 + x * lo
    r = _atan_poly(num / den)  # den = 0: num/den = +-inf, atan = +-pi/2 (num != 0 there: x lo = -1, x != lo)
    sh = math.pi if num > 0.0 else -math.pi
    return r + sh if den < 0.0 else r


@njit(cache=True, inline="always")
def _kk_b(xi, at):
    """:func:`_kk` without its fastmath flags (inlined into the batched passes, which set their own)."""
    iH = 1.0 / (1.0 + xi * xi)
    xh = xi * iH
    return 0.5 * (xh + at), xh * (0.25 * iH + 0.375) + 0.375 * at, -0.25 * (iH * iH), iH


# fast-math flags of the batched passes: no nnan/ninf (lanes that are masked out may carry inf/nan); reassoc
# and contract move round-off only (the rhs stays within 1e-12 of the scalar form: tests/models/test_kernel_cost.py)
_FM = {"nsz", "arcp", "contract", "reassoc"}


@njit(cache=True, error_model="numpy", fastmath=_FM)
def _batch_setup(w, nl, k, cte, ste, e, c, vx, vr, vt, wx, wr, wt, eta, Rb, Rp, R_bore, R_out, hdm, s0):
    """Pass 1 over ``nl`` lanes: station kinematics (:func:`_station_kinematics`) and the line-contact problem
    in :func:`_station_dimless`'s form (A = |6 eta U_e|, beta, edges; mirrored for U_e < 0, as :func:`_station`)."""
    for i in range(nl):
        tq = w[_R_TQ * _LANES + i]
        dph, nx, nt, qx, qt, a, dUu, dUs, Ue, F0, L, lo, hi = _station_kinematics(
            tq, k, cte, ste, e, c, vx, vr, vt, wx, wr, wt, eta, Rb, Rp, R_bore, R_out, hdm, s0)
        dat = _atan_diff_poly(hi, lo)
        A = 6.0 * eta * Ue
        beta = F0 * L / a
        mir = A < 0.0
        Am = -A if mir else A
        lom = -hi if mir else lo
        him = -lo if mir else hi
        w[_R_LO * _LANES + i] = lo
        w[_R_HI * _LANES + i] = hi
        w[_R_DAT * _LANES + i] = dat
        w[_R_A * _LANES + i] = a
        w[_R_L * _LANES + i] = L
        w[_R_AM * _LANES + i] = Am
        w[_R_BETA * _LANES + i] = beta
        w[_R_LOM * _LANES + i] = lom
        w[_R_HIM * _LANES + i] = him
        w[_R_MIR * _LANES + i] = -1.0 if mir else 1.0
        w[_R_NX * _LANES + i] = nx
        w[_R_NT * _LANES + i] = nt
        w[_R_DUU * _LANES + i] = dUu
        w[_R_DUS * _LANES + i] = dUs
        w[_R_DPH * _LANES + i] = dph


@njit(cache=True, error_model="numpy", fastmath=_FM)
def _batch_classify(w, nl):
    """The case of every lane's line contact -- no film / full film / rupture Newton / short interval -- and the
    Newton start (:func:`_rupture_guess`) and bracket: the branches of :func:`_station_dimless`, as selects."""
    for i in range(nl):
        dat = w[_R_DAT * _LANES + i]
        Am = w[_R_AM * _LANES + i]
        beta = w[_R_BETA * _LANES + i]
        lom = w[_R_LOM * _LANES + i]
        him = w[_R_HIM * _LANES + i]
        # A > 0: rupture problem
        xs = -beta / (2.0 * Am)
        S = xs - lom
        short = (S * S <= (_SHORT * _SHORT) * (1.0 + lom * lom)) and (him - lom >= 2.0 * S)
        k2l, k3l, m3l, _ = _kk_b(lom, 0.0)
        k2h, k3h, m3h, _ = _kk_b(him, dat)
        Ghi = Am * (k2h - k2l) + beta * (m3h - m3l) - (Am * (1.0 + him * him) + beta * him) * (k3h - k3l)
        xsf = xs if abs(xs) < 1e300 else 0.0  # (a vanishing A: Martin's start below; keep the table read finite)
        x0 = _rupture_guess(xsf, lom)
        martin = xs + 0.475 * math.sqrt(1.0 + xs * xs)
        x0 = x0 if (abs(xs) < 1e300 and x0 > xs) else martin
        x0 = him if x0 >= him else x0
        if not him > lom:
            st = _ST_NONE
        elif not Am > 0.0:
            st = _ST_NONE if beta >= 0.0 else _ST_FULL
        elif xs <= lom:
            st = _ST_NONE
        elif short:
            st = _ST_SHORT
        elif Ghi >= 0.0:
            st = _ST_FULL
        else:
            st = _ST_NEWTON
        w[_R_ST * _LANES + i] = st
        w[_R_X * _LANES + i] = x0 if st == _ST_NEWTON else him
        w[_R_AA * _LANES + i] = xs
        w[_R_BB * _LANES + i] = him
        w[_R_AT * _LANES + i] = dat
        w[_R_K2L * _LANES + i] = k2l
        w[_R_K3L * _LANES + i] = k3l
        w[_R_M3L * _LANES + i] = m3l


@njit(cache=True, error_model="numpy", fastmath=_FM)
def _batch_newton_sweep(w, nl):
    """One Newton step of the rupture solve of :func:`_station_dimless` on every lane still iterating.

    The step, its bracket and its stopping rule are those of :func:`_station_dimless` (with the atan of the
    iterate from :func:`_atan_diff_poly`); a lane that meets the stopping rule is frozen.  Returns the
    number of lanes still iterating."""
    nact = 0
    for i in range(nl):
        A = w[_R_AM * _LANES + i]
        beta = w[_R_BETA * _LANES + i]
        lo = w[_R_LOM * _LANES + i]
        x = w[_R_X * _LANES + i]
        a_ = w[_R_AA * _LANES + i]
        b_ = w[_R_BB * _LANES + i]
        at_old = w[_R_AT * _LANES + i]
        st = w[_R_ST * _LANES + i]
        at2 = _atan_diff_poly(x, lo)
        k2x, k3x, m3x, iHx = _kk_b(x, at2)
        dk3 = k3x - w[_R_K3L * _LANES + i]
        G = A * (k2x - w[_R_K2L * _LANES + i]) + beta * (m3x - w[_R_M3L * _LANES + i]) - (A * (1.0 + x * x) + beta * x) * dk3
        gp = G > 0.0
        a_ = x if gp else a_
        b_ = b_ if gp else x
        dG = -(2.0 * A * x + beta) * dk3
        q = G / dG
        xn = x - q if dG < 0.0 else b_
        inside = (a_ <= xn) and (xn <= b_)
        d = xn - x
        conv = inside and (abs(d) <= 1e-6 * (1.0 + abs(x)))
        xn = xn if inside else (b_ if gp else 0.5 * (a_ + b_))
        act = st == _ST_NEWTON
        w[_R_X * _LANES + i] = xn if act else x
        w[_R_AA * _LANES + i] = a_ if act else w[_R_AA * _LANES + i]
        w[_R_BB * _LANES + i] = b_ if act else w[_R_BB * _LANES + i]
        # converged: atan(xn) to first order from atan(x) (error ~ step^2), as the scalar form
        w[_R_AT * _LANES + i] = (at2 + d * iHx if conv else at2) if act else at_old
        w[_R_ST * _LANES + i] = _ST_DONE if (act and conv) else st
        nact += 1 if (act and not conv) else 0
    return nact


@njit(cache=True, error_model="numpy", fastmath=_FM)
def _batch_finish(w, nl):
    """Pressure integrals of every lane from its pressurised interval [lo, x_2] (:func:`_station_dimless`'s
    closed form, :func:`_station`'s scaling): rows _R_W = int p dx [N/m], _R_WX = int p x dx [N]."""
    for i in range(nl):
        st = w[_R_ST * _LANES + i]
        A = w[_R_AM * _LANES + i]
        beta = w[_R_BETA * _LANES + i]
        lo = w[_R_LOM * _LANES + i]
        hi = w[_R_HIM * _LANES + i]
        x2 = w[_R_X * _LANES + i]
        at2 = w[_R_AT * _LANES + i]
        k2l, k3l, m3l, iHl = _kk_b(lo, 0.0)
        k2x, k3x, m3x, iH2 = _kk_b(x2, at2)
        H2 = 1.0 + x2 * x2
        dk2 = k2x - k2l
        dk3 = k3x - k3l
        dm3 = m3x - m3l
        gamma = -(A * H2 + beta * x2) if x2 < hi else -(A * dk2 + beta * dm3) / dk3
        d1 = 0.5 * (iHl - iH2)
        d2 = dm3
        IP = -(A * d1 + beta * (dk2 - dk3) + gamma * d2)
        IPxi = -0.5 * (A * (at2 - dk2) + beta * (d1 - d2) + gamma * (dk2 - dk3))
        film = st != _ST_NONE
        a = w[_R_A * _LANES + i]
        L = w[_R_L * _LANES + i]
        ia = 1.0 / a
        s = L * L * ia * ia
        w[_R_W * _LANES + i] = s * IP if film else 0.0
        w[_R_WX * _LANES + i] = (s * L) * (IPxi * w[_R_MIR * _LANES + i]) if film else 0.0


@njit(cache=True, fastmath=True)
def _batch_solve(w, nl):
    """Rows _R_W, _R_WX (int p dx [N/m], int p x dx [N]) of ``nl`` lanes from their line-contact problems (rows
    _R_A, _R_L, _R_AM, _R_BETA, _R_LOM, _R_HIM, _R_MIR, _R_DAT): :func:`_station` of each lane, batched."""
    _batch_classify(w, nl)
    for _it in range(60):
        if _batch_newton_sweep(w, nl) == 0:
            break
    for i in range(nl):  # lanes left iterating after 60 sweeps: the atan of their last iterate
        if w[_R_ST * _LANES + i] == _ST_NEWTON:
            w[_R_AT * _LANES + i] = _atan_diff(w[_R_X * _LANES + i], w[_R_LOM * _LANES + i])
    _batch_finish(w, nl)
    for i in range(nl):
        if w[_R_ST * _LANES + i] == _ST_SHORT:  # cancellation-free form for a short interval (rare)
            A = w[_R_AM * _LANES + i]
            beta = w[_R_BETA * _LANES + i]
            x2, IP, IPxi = _station_short(A, beta, w[_R_LOM * _LANES + i], -beta / (2.0 * A))
            L = w[_R_L * _LANES + i]
            a = w[_R_A * _LANES + i]
            s = L * L / (a * a)
            w[_R_W * _LANES + i] = s * IP
            w[_R_WX * _LANES + i] = (s * L) * (IPxi * w[_R_MIR * _LANES + i])


@njit(cache=True, fastmath=True, error_model="numpy")
def pocket_film_wrench(ex, et, s0, vx, vr, vt, wx, wr, wt, eta, Rb, Rp, R_bore, R_out, hdm, n_st, tabulated=True):
    """Film force and moment on the ball from a rigid isoviscous film in its cylindrical pocket.

    Parameters
    ----------
    ex, et : ball-centre offset from the pocket axis in the pocket plane (x: cage axis,
        t: circumferential) [m]; must satisfy |e| < c = R_p - R_b;
    s0 : ball-centre offset along the pocket axis from the pocket centre (pitch radius) [m];
    vx, vr, vt : ball-centre velocity relative to the pocket (cage frame) [m/s];
    wx, wr, wt : ball angular velocity relative to the cage [rad/s];
    eta : oil viscosity [Pa s]; Rb, Rp : ball and pocket radii [m]; R_bore, R_out : cage bore and
    outside radii [m]; hdm : pocket-centre radius d_m/2 [m]; n_st : number of stations (even);
    tabulated : the batched form with the tabulated rupture start (default); False = the scalar reference
        (:func:`_pocket_film_wrench_reference`, Martin's start), the same roots to round-off.

    Returns
    -------
    (Fx, Fr, Ft) : force on the ball [N]; (Mx, Mr, Mt) : moment on the ball about its centre [N m];
    Wn : sum of the station pressure forces |int p dA| [N] (the film's normal load).
    All in the pocket frame (x, r, t).  Sources: module docstring, [1]-[5].

    Stations are solved :data:`_LANES` at a time (``_batch_*``: SIMD passes, docs/pocket.md "Cost"); a station
    whose pressurised interval is short (:func:`_station_short`) is solved alone.
    """
    if not tabulated:
        return _pocket_film_wrench_reference(ex, et, s0, vx, vr, vt, wx, wr, wt, eta, Rb, Rp, R_bore, R_out, hdm, n_st)
    c, e, cte, ste, k = _offset_frame(ex, et, Rb, Rp)
    Fx = Fr = Ft = 0.0
    Mx = Mr = Mt = 0.0
    Wn = 0.0
    dtau = 2.0 * math.pi / n_st
    w = np.empty(_NROWS * _LANES)
    for c0 in range(0, n_st, _LANES):
        nl = min(_LANES, n_st - c0)
        for i in range(nl):  # tan(tau/2) of the station nodes tau = -pi + (i + 1/2) dtau
            w[_R_TQ * _LANES + i] = _TQ_TABLE[i] if n_st == _TQ_N else math.tan(0.5 * (-math.pi + (c0 + i + 0.5) * dtau))
        _batch_setup(w, nl, k, cte, ste, e, c, vx, vr, vt, wx, wr, wt, eta, Rb, Rp, R_bore, R_out, hdm, s0)
        _batch_solve(w, nl)
        for i in range(nl):
            lo = w[_R_LO * _LANES + i]
            hi = w[_R_HI * _LANES + i]
            a = w[_R_A * _LANES + i]
            # Couette integrals over the wetted wall: int dx/h, int x dx/h
            I1 = w[_R_L * _LANES + i] * w[_R_DAT * _LANES + i] / a
            I1x = Rb * math.log((1.0 + hi * hi) / (1.0 + lo * lo))
            nx = w[_R_NX * _LANES + i]
            nt = w[_R_NT * _LANES + i]
            f = _station_wrench(w[_R_W * _LANES + i], w[_R_WX * _LANES + i], I1, I1x, eta, w[_R_DUU * _LANES + i],
                                w[_R_DUS * _LANES + i], Rb, Rp * w[_R_DPH * _LANES + i] * dtau, nx, nt, -nt, nx)
            Fx += f[0]
            Fr += f[1]
            Ft += f[2]
            Mx += f[3]
            Mr += f[4]
            Mt += f[5]
            Wn += f[6]
    return Fx, Fr, Ft, Mx, Mr, Mt, Wn

@njit(cache=True, inline="always")
def pocket_film_gap(e, c, h_c):
    """Offset e_f = c - h_f at which the rigid film is evaluated, and the film gap h_f [m].

    h_f = h_c + h_c softplus((g - h_c)/h_c), g = c - e the rigid gap: h_f = g (to within
    h_c exp(-(g - h_c)/h_c)) while the rigid gap is thicker than the film floor h_c (composite
    roughness of ball and pocket), and h_f -> h_c once the surfaces meet, where the elastic contact
    (:func:`pocket_elastic_force`) carries the rest (mixed-lubrication load sharing; C-infinity,
    docs/pocket.md).  Returns (e_f, h_f).
    """
    g = c - e
    z = (g - h_c) / h_c
    if z > 0.0:
        hf = h_c * (1.0 + z + math.log1p(math.exp(-z)))
    else:
        hf = h_c * (1.0 + math.log1p(math.exp(z)))
    ef = c - hf
    if ef < 0.0:
        ef = 0.0
    return ef, hf


@njit(cache=True, inline="always")
def pocket_elastic_force(e, c, K):
    """Hertz load of the ball pressed into the pocket wall Q = K delta^1.5, delta = e - c > 0 [N] ([6], Eq. 6.40).

    C1 at delta = 0 (force and its derivative vanish there).
    """
    d = e - c
    if d <= 0.0:
        return 0.0
    return K * d * math.sqrt(d)


@njit(cache=True, inline="always")
def pocket_boundary_friction(v_slide, Q_solid, mu, v0):
    """Boundary (asperity) friction force magnitude P_S on the solid part of the load [N] ([5]; Zhang et al. 2016 P_S).

    P_S = mu Q_solid v / sqrt(v^2 + v0^2): Coulomb with the documented regularisation of sign(v)
    (v0 = 0.01 m/s, docs/dynamics.md).
    """
    return mu * Q_solid * v_slide / math.sqrt(v_slide * v_slide + v0 * v0)


@njit(cache=True, inline="always")
def pocket_film_power(Fx, Fr, Ft, Mx, Mr, Mt, vx, vr, vt, wx, wr, wt):
    """Power dissipated by a pocket wrench: -(F . v_rel + M . omega_rel) [W] (source ``pocket_film``/``pocket_boundary``).

    The ball receives (F, M about its centre), the cage the opposite wrench on the same line of
    action; their summed rate of work is F . v_rel + M . omega_rel with the ball's velocity and
    angular velocity relative to the cage.
    """
    return -(Fx * vx + Fr * vr + Ft * vt + Mx * wx + Mr * wr + Mt * wt)


@njit(cache=True, error_model="numpy")
def pocket_wrench(kin, prm):
    """Total pocket wrench on the ball: film (rigid isoviscous, floored at h_c) + Hertz + boundary friction.

    ``kin`` : :data:`PocketKinematics` (offset and motion of the ball relative to its pocket); ``prm`` :
    :data:`PocketParams`.  Returns a :data:`PocketWrench` in the pocket frame: force [N] and moment about the
    ball centre [N m] on the ball, the film normal load, the Hertz load, the powers dissipated by the film
    and by boundary friction [W] (sources ``pocket_film`` and ``pocket_boundary``) and the boundary friction
    force magnitude P_S [N].
    """
    ex, et, s0, vx, vr, vt, wx, wr, wt = kin.ex, kin.et, kin.s0, kin.vx, kin.vr, kin.vt, kin.wx, kin.wr, kin.wt
    eta, Rb, Rp, R_bore, R_out, hdm = prm.eta, prm.Rb, prm.Rp, prm.R_bore, prm.R_out, prm.hdm
    n_st, h_c, K, mu, v0 = prm.n_st, prm.h_c, prm.K, prm.mu, prm.v0
    c = Rp - Rb
    e = math.sqrt(ex * ex + et * et)
    Fx = Fr = Ft = Mx = Mr = Mt = 0.0
    Qf = 0.0
    Pf = 0.0
    if eta > 0.0:
        ef, hf = pocket_film_gap(e, c, h_c)
        s = ef / e if e > 0.0 else 0.0
        Fx, Fr, Ft, Mx, Mr, Mt, Qf = pocket_film_wrench(ex * s, et * s, s0, vx, vr, vt, wx, wr, wt, eta, Rb, Rp,
                                                         R_bore, R_out, hdm, n_st)
        Pf = pocket_film_power(Fx, Fr, Ft, Mx, Mr, Mt, vx, vr, vt, wx, wr, wt)
    Qs = pocket_elastic_force(e, c, K)
    Pb = 0.0
    fb = 0.0
    if Qs > 0.0:
        nx, nt = ex / e, et / e
        Fx -= Qs * nx
        Ft -= Qs * nt
        if mu > 0.0:
            # sliding velocity of the ball surface at the contact point R_b n, tangential part
            px, pr, pt = Rb * nx, 0.0, Rb * nt
            sx = vx + wr * pt - wt * pr
            sr = vr + wt * px - wx * pt
            st = vt + wx * pr - wr * px
            sn = sx * nx + st * nt
            sx -= sn * nx
            st -= sn * nt
            vs = math.sqrt(sx * sx + sr * sr + st * st)
            if vs > 0.0:
                fb = pocket_boundary_friction(vs, Qs, mu, v0)
                gx, gr, gt = -fb * sx / vs, -fb * sr / vs, -fb * st / vs
                Fx += gx
                Fr += gr
                Ft += gt
                Mx += pr * gt - pt * gr
                Mr += pt * gx - px * gt
                Mt += px * gr - pr * gx
                Pb = fb * vs
    return PocketWrench(Fx, Fr, Ft, Mx, Mr, Mt, Qf, Qs, Pf, Pb, fb)


# numba bakes callees and captured constants into its cache: key the cache on them (compile_cache.py)
check_compile_cache(globals())
