"""Ball/pocket film (hsbearing.models.ball_bearing.pocket) against closed forms and an independent 2-D Reynolds solution.

Validation, not regression: the reference is tests/helpers/pocket_reynolds_fd.py, a finite-volume solution
of the 2-D Reynolds equation on the pocket wall with the exact sphere-in-cylinder gap, exact surface
velocities, exact pocket edges and p >= 0 complementarity -- it shares none of the model's
approximations (line contact per station, gap to first order, station quadrature).
Geometry: Zhang et al. 2016 (ball 9.525 mm, pocket radius 4.8125 mm, cage bore/outside 44.4/52 mm,
pitch 46 mm); oil 4109 at 130 degC (3.6 mPa s); ball spin relative to the cage from the default
case's initial state (-3250, 1210, 0) rad/s in the pocket frame (x, r, t).
"""

from __future__ import annotations

import math

import numpy as np
import pytest
from pocket_reynolds_fd import solve_pocket_film

from hsbearing.models.ball_bearing import kernel_io as kio
from hsbearing.models.ball_bearing.pocket import (
    PocketKinematics,
    PocketParams,
    pocket_elastic_force,
    pocket_film_gap,
    pocket_film_wrench,
    pocket_wrench,
    station_film,
)

Rb, Rp, R_BORE, R_OUT, HDM, ETA = 4.7625e-3, 4.8125e-3, 22.2e-3, 26e-3, 23e-3, 3.6e-3
C = Rp - Rb
W0 = np.array([-3250.0, 1210.0, 0.0])
N_ST = 16  # stations used by the kernel (hsbearing.systems.angular_contact.dynamics MODEL_DEFAULTS["pocket_stations"])


# ----------------------------------------------------------------------------- closed forms
def test_station_martin_rigid_cylinder():
    """Rigid isoviscous cylinder on a plane with the Reynolds exit condition: W' = 4.896 eta u_m R / h0,
    film rupture at x = 0.475 sqrt(2 R h0) (Martin 1916; Hamrock, Schmid & Jacobson 2004, Ch. 17)."""
    a, U = 20e-6, 16.0
    L = math.sqrt(2 * Rb * a)
    W, Wx, x1, x2 = station_film(a, U, 0.0, -2000 * L, 2000 * L, Rb, ETA)
    assert W / (ETA * 0.5 * U * Rb / a) == pytest.approx(4.896, rel=2e-3)
    assert x2 / L == pytest.approx(0.4751, abs=2e-3)
    # reversed entrainment: mirror image (force unchanged, pressure centroid and rupture mirrored)
    Wm, Wxm, x1m, x2m = station_film(a, -U, 0.0, -2000 * L, 2000 * L, Rb, ETA)
    assert Wm == pytest.approx(W, rel=1e-12) and Wxm == pytest.approx(-Wx, rel=1e-12) and x1m == pytest.approx(-x2)


def test_station_squeeze_cylinder():
    """Long cylinder approaching a plane at v: W' = 3 sqrt(2) pi eta v (R/h0)^(3/2) (classic squeeze film,
    Hamrock, Schmid & Jacobson 2004, Ch. 15); separating: the film cavitates, W' = 0."""
    a, v = 10e-6, 0.02
    L = math.sqrt(2 * Rb * a)
    W, *_ = station_film(a, 0.0, -12 * ETA * v, -2000 * L, 2000 * L, Rb, ETA)
    assert W == pytest.approx(3 * math.sqrt(2) * math.pi * ETA * v * (Rb / a) ** 1.5, rel=2e-3)
    assert station_film(a, 0.0, 12 * ETA * v, -2000 * L, 2000 * L, Rb, ETA)[0] == 0.0


# ----------------------------------------------------------------------------- 2-D Reynolds reference
# States the simulation visits: offsets 0..0.96 c toward the circumferential walls (+-t, where the
# ball drives the cage) and the axial wall (x), ball spin in both senses, approach and separation at
# 0.05 m/s (the largest ball-in-pocket rates of the default run are ~0.02 m/s), the ball moving
# along the pocket axis, off the pocket mid-plane by +-0.15 mm (cage eccentricity up to 0.2 mm).
STATES = {
    "centred": (0.0, 0.0, 0.0, (0, 0, 0), W0),
    "e0.5_t": (0.0, 0.5 * C, 0.0, (0, 0, 0), W0),
    "e0.8_t": (0.0, 0.8 * C, 0.0, (0, 0, 0), W0),
    "e0.96_t": (0.0, 0.96 * C, 0.0, (0, 0, 0), W0),
    "e0.96_minus_t": (0.0, -0.96 * C, 0.0, (0, 0, 0), W0),
    "e0.8_x": (0.8 * C, 0.0, 0.0, (0, 0, 0), W0),
    "e0.8_diag_reverse_spin": (0.57 * C, -0.57 * C, 0.0, (0, 0, 0), -W0),
    "approach": (0.0, 0.8 * C, 0.0, (0, 0, 0.05), W0),
    "separation": (0.0, 0.8 * C, 0.0, (0, 0, -0.05), W0),
    "squeeze_only": (0.0, 0.9 * C, 0.0, (0, 0, 0.05), 0 * W0),
    "separation_no_spin": (0.0, 0.9 * C, 0.0, (0, 0, -0.05), 0 * W0),
    "axial_slide": (0.0, 0.8 * C, 0.0, (0.0, 0.05, 0.0), W0),
    "s0_plus": (0.0, 0.8 * C, 0.15e-3, (0, 0, 0), W0),
    "s0_minus": (0.0, -0.8 * C, -0.15e-3, (0, 0, 0), W0),
    "whirl_slide": (0.0, 0.8 * C, 0.0, (0.05, 0.0, 0.0), W0),
}
FAST = ["centred", "e0.8_t", "e0.96_minus_t", "approach", "separation", "squeeze_only"]
# tolerance: force error <= 5 % of the film's total pressure load W = int p dA, moment error <= 5 % of
# |M| + M_FLOOR (1 % of the spin-driven pocket moment of the default case, 2.4e-4 N m); power within 5 %.
# Measured worst case over STATES: docs/pocket.md.
TOL = 0.05
M_FLOOR = 2.4e-6


def _compare(name, n_theta, n_u):
    ex, et, s0, v, w = STATES[name]
    ref = solve_pocket_film(ex, et, s0, v, w, ETA, Rb, Rp, R_BORE, R_OUT, HDM, n_theta=n_theta, n_u=n_u)
    m = pocket_film_wrench(ex, et, s0, *v, *w, ETA, Rb, Rp, R_BORE, R_OUT, HDM, N_ST)
    F, M, Wn = np.array(m[:3]), np.array(m[3:6]), m[6]
    eF = np.linalg.norm(F - ref["F"]) / ref["W"] if ref["W"] > 0 else np.linalg.norm(F - ref["F"])
    # moment: TOL of |M| plus an absolute M_FLOOR (translation-only states carry moments ~1e-7 N m)
    eM = np.linalg.norm(M - ref["M"]) / (np.linalg.norm(ref["M"]) + M_FLOOR / TOL)
    P = -(F @ np.asarray(v, float) + M @ np.asarray(w, float))
    eP = abs(P - ref["D"]) / ref["D"]
    return ref, F, M, Wn, eF, eM, eP


@pytest.mark.parametrize("name", FAST)
def test_film_against_2d_reynolds(name):
    ref, F, M, Wn, eF, eM, eP = _compare(name, 180, 60)
    assert eF < TOL, (name, F, ref["F"], ref["W"])
    assert eM < TOL, (name, M, ref["M"])
    assert eP < TOL, (name, ref["D"])
    if ref["W"] > 0:
        assert Wn == pytest.approx(ref["W"], rel=TOL)


@pytest.mark.slow
@pytest.mark.parametrize("name", sorted(set(STATES) - set(FAST)))
def test_film_against_2d_reynolds_all_states(name):
    ref, F, M, Wn, eF, eM, eP = _compare(name, 360, 120)
    assert eF < TOL, (name, F, ref["F"], ref["W"])
    assert eM < TOL, (name, M, ref["M"])
    assert eP < TOL, (name, ref["D"])


def test_film_dissipates():
    """The film only dissipates: -(F . v + M . omega) >= 0 for random states in the visited range."""
    rng = np.random.default_rng(4)
    for _ in range(300):
        e = C * rng.uniform(0, 0.99)
        ang = rng.uniform(0, 2 * np.pi)
        v = rng.normal(0, 0.03, 3)
        w = rng.normal(0, 2000, 3)
        m = pocket_film_wrench(e * math.cos(ang), e * math.sin(ang), rng.uniform(-2e-4, 2e-4), *v, *w,
                               ETA, Rb, Rp, R_BORE, R_OUT, HDM, N_ST)
        P = -(np.dot(m[:3], v) + np.dot(m[3:6], w))
        assert P >= 0.0


def test_station_count_converged():
    """The station quadrature (conformal map) is converged at the kernel's count to 1 % of the load."""
    for frac in (0.0, 0.5, 0.9, 0.98):
        ref = np.array(pocket_film_wrench(0, frac * C, 0, 0, 0, 0.02, *W0, ETA, Rb, Rp, R_BORE, R_OUT, HDM, 512))
        m = np.array(pocket_film_wrench(0, frac * C, 0, 0, 0, 0.02, *W0, ETA, Rb, Rp, R_BORE, R_OUT, HDM, N_ST))
        assert np.linalg.norm(m[:3] - ref[:3]) < 0.01 * ref[6], frac


# ----------------------------------------------------------------------------- blend into Hertz
def _normal_force(e, h_c=0.5e-6, K=1.35e9):
    kin = PocketKinematics(ex=0.0, et=e, s0=0.0, vx=0.0, vr=0.0, vt=0.0, wx=W0[0], wr=W0[1], wt=W0[2])
    prm = PocketParams(eta=ETA, Rb=Rb, Rp=Rp, R_bore=R_BORE, R_out=R_OUT, hdm=HDM, n_st=N_ST, h_c=h_c, K=K, mu=0.1, v0=0.01)
    return -pocket_wrench(kin, prm).Ft  # push back along -t


def test_blend_limits():
    """Thick film: the rigid film itself (floor inactive); deep contact: Hertz K delta^1.5 + the floored film."""
    h_c, K = 0.5e-6, 1.35e9
    for frac in (0.0, 0.5, 0.9):
        ef, hf = pocket_film_gap(frac * C, C, h_c)
        assert ef == pytest.approx(frac * C, abs=2e-4 * h_c)
    rigid = -pocket_film_wrench(0, 0.9 * C, 0, 0, 0, 0, *W0, ETA, Rb, Rp, R_BORE, R_OUT, HDM, N_ST)[2]
    assert _normal_force(0.9 * C) == pytest.approx(rigid, rel=1e-4)  # floor correction ~exp(-9) at 10 h_c
    d = 5e-6
    film_at_floor = -pocket_film_wrench(0, C - h_c, 0, 0, 0, 0, *W0, ETA, Rb, Rp, R_BORE, R_OUT, HDM, N_ST)[2]
    for dd in (d, 2 * d):  # in contact: Hertz on top of the film held at its floor h_c
        assert _normal_force(C + dd) - K * dd**1.5 == pytest.approx(film_at_floor, rel=1e-3)


def test_blend_smooth():
    """Force and its derivative are continuous through the film-to-contact transition (e from c - 5 um to c + 3 um).

    The film floor is C-infinity; Hertz K delta^1.5 starts with zero force and zero slope at delta = 0
    (its curvature is infinite there, so the slope is checked by one-sided quotients, not by jumps)."""
    e = C + np.linspace(-5e-6, 3e-6, 801)
    Q = np.array([_normal_force(x) for x in e])
    dQ = np.diff(Q) / np.diff(e)
    assert np.all(np.isfinite(Q)) and np.all(dQ > 0)  # monotone: the pocket always pushes harder when closer
    # away from the Hertz onset no jump in the slope (a kink or a step would show as one large jump)
    away = np.abs(e[1:-1] - C) > 0.3e-6
    assert np.max((np.abs(np.diff(dQ)) / dQ[1:])[away]) < 0.02
    # at the onset: left and right slopes agree
    h = 1e-11
    left = (_normal_force(C) - _normal_force(C - h)) / h
    right = (_normal_force(C + h) - _normal_force(C)) / h
    assert right == pytest.approx(left, rel=0.01)
    assert pocket_elastic_force(C, C, 1e9) == 0.0 and pocket_elastic_force(C + 1e-12, C, 1e9) < 1e-8


# ----------------------------------------------------------------------------- kernel: momentum closure
def test_kernel_pocket_wrench_closed():
    """The pocket puts equal and opposite force AND moment on ball and cage (about any point).

    The pocket's share of each ball's acceleration is isolated by evaluating the kernel with and
    without the pocket (film, Hertz and friction off); the cage's contribution must be the
    opposite force and the opposite moment transported to the cage centre."""
    import hsbearing
    from hsbearing.models.ball_bearing import kernel as K
    from hsbearing.systems.angular_contact.dynamics import build_model

    model = build_model(hsbearing.load_case("zhang2016"), gravity=0.0)
    P = model.P.copy()
    Z = model.layout.Z
    y = model.y0.copy()
    cg = 9 * Z
    hdm = 0.5 * kio.get(P, "dm")
    y[2 * Z:3 * Z] = np.linspace(-1.25, 1.25, Z) * kio.get(P, "c_p") / hdm  # from contact with one wall, through the film, to the other
    y[:Z] = np.linspace(20e-6, -20e-6, Z)  # axial offsets
    y[3 * Z:4 * Z] = 0.01  # axial and radial ball velocities: squeeze and sliding along the pocket axis
    y[4 * Z:5 * Z] = -0.01
    y[cg + 1], y[cg + 2], y[cg + 4], y[cg + 5] = 5e-6, -3e-6, 2e-5, -1e-5  # cage off-centre and tilted
    y[cg + 7], y[cg + 8], y[cg + 10], y[cg + 11] = 0.02, -0.01, 0.5, 0.3

    def run(p):
        ydot = np.zeros_like(y)
        contrib = np.zeros((Z, K.N_CONTRIB))
        aux = np.zeros((Z, K.N_AUX))
        K.ball_loop(y, p, model.qu, model.qw, ydot, contrib, aux, True)
        return ydot, contrib, aux

    yd1, c1, aux = run(P)
    P0 = P.copy()
    for name in ("eta_film", "K_c", "mu_c"):
        kio.set_value(P0, name, 0.0)
    yd0, c0, _ = run(P0)
    assert np.all(np.abs(c0[:, K.C_CFX:]) == 0.0)  # nothing else touches the cage in ball_loop
    assert aux[:, K.AUX_INDEX["Q_solid"]].max() > 0.0 and aux[:, K.AUX_INDEX["Q_film"]].min() > 0.0  # both regimes present
    m, I = kio.get(P, "m_b"), kio.get(P, "I_b")
    phc = y[cg + 3]
    for j in range(Z):
        r = hdm + y[Z + j]
        th = phc + 2 * np.pi * j / Z + y[2 * Z + j]
        c, s = np.cos(th), np.sin(th)
        d = yd1 - yd0
        fx, fr, ft = m * d[3 * Z + j], m * d[4 * Z + j], m * r * d[5 * Z + j]  # ball frame (x, r, t)
        mx, mr, mt = I * d[6 * Z + j], I * d[7 * Z + j], I * d[8 * Z + j]
        F = np.array([fx, fr * c - ft * s, fr * s + ft * c])  # inertial
        M = np.array([mx, mr * c - mt * s, mr * s + mt * c])
        b = np.array([y[j], r * c, r * s]) - y[cg:cg + 3]  # ball centre relative to the cage centre
        Fc = c1[j, K.C_CFX:K.C_CFX + 3]
        Mc = c1[j, K.C_CMX:K.C_CMX + 3]
        scaleF = np.linalg.norm(F) + 1e-12
        assert np.linalg.norm(Fc + F) < 1e-9 * scaleF + 1e-12, j
        assert np.linalg.norm(Mc + M + np.cross(b, F)) < 1e-9 * (np.linalg.norm(M) + 0.03 * scaleF) + 1e-15, j


# ----------------------------------------------------------------------------- tabulated rupture start
def _random_pocket_states(rng, n):
    """The state space the simulation visits (docs/pocket.md): e/c up to 0.995 in any direction, spin in
    both senses, squeeze both signs, sliding, ball off the pocket mid-plane by up to +-0.2 mm."""
    out = []
    for _ in range(n):
        ec = rng.uniform(0.9, 0.995) if rng.random() < 0.4 else rng.uniform(0.0, 0.995)
        ang = rng.uniform(0, 2 * np.pi)
        v = rng.normal(0, 0.05, 3)
        w = np.array([rng.choice([-1, 1]) * rng.uniform(300, 4000), rng.uniform(-2500, 2500), rng.uniform(-800, 800)])
        out.append((C * ec * math.cos(ang), C * ec * math.sin(ang), rng.uniform(-2e-4, 2e-4), v, w))
    return out


@pytest.mark.parametrize("edges", [(R_BORE, R_OUT), (22.9e-3, 24.0e-3)], ids=["seed004", "narrow_cage"])
def test_tabulated_rupture_start_same_wrench(edges):
    """The tabulated Newton start (default) returns the reference closed form's wrench (Martin's start,
    ``tabulated=False``) to round-off over random visited states, for the seed's cage edges and for a
    narrow cage whose edges cut the film on both sides.  Measured worst: ~2e-12 of the film load."""
    rng = np.random.default_rng(18)
    worst_f = worst_m = 0.0
    for ex, et, s0, v, w in _random_pocket_states(rng, 400):
        args = (ex, et, s0, *v, *w, ETA, Rb, Rp, edges[0], edges[1], HDM, N_ST)
        ref = np.array(pocket_film_wrench(*args, False))
        new = np.array(pocket_film_wrench(*args))
        W = max(ref[6], 1e-12)
        worst_f = max(worst_f, np.abs(new[:3] - ref[:3]).max() / W)
        worst_m = max(worst_m, np.abs(new[3:6] - ref[3:6]).max() / (np.abs(ref[3:6]).max() + 1e-12))
    assert worst_f < 1e-9 and worst_m < 1e-9, (worst_f, worst_m)


def test_tabulated_rupture_start_station_level():
    """Station level, beyond the visited range: entrainment of both signs, any source (wedge/squeeze) of either
    sign, gaps 0.2-50 um, edges 0.1-20 contact widths on both sides.  The rupture position and the pressure
    integrals equal the reference start's to the closed form's own round-off: scale W_M = Martin's load
    4.896 eta (|U|/2) R_b L / a (Hamrock et al. Ch. 17); measured worst 1.5e-8 W_M (W), 1.8e-5 W_M L (Wx,
    whose lever arm reaches 20 L), 5e-7 (1 + |x|/L) L (rupture).  (The closed form's cancellation when the
    source sign change sits within ~1e-3 L of an edge is handled by the short-interval form since issue 18
    session 5: test_station_closed_form_against_quadrature.)"""
    from hsbearing.models.ball_bearing.pocket import _station

    rng = np.random.default_rng(7)
    worst = np.zeros(3)
    for _ in range(20000):
        a = 10 ** rng.uniform(-6.7, -4.3)
        L = math.sqrt(2 * Rb * a)
        lo, hi = -10 ** rng.uniform(-1, 1.3), 10 ** rng.uniform(-1, 1.3)
        U = rng.choice([-1, 1]) * 10 ** rng.uniform(-3, 1.5)
        F0 = rng.choice([-1, 1]) * 10 ** rng.uniform(-3, 3) * 6 * ETA * abs(U) * L / a
        args = (a, U, F0, lo, hi, math.atan(hi) - math.atan(lo), L, ETA)
        r = np.array(_station(*args, False))
        t = np.array(_station(*args, True))
        WM = max(4.896 * ETA * 0.5 * abs(U) * Rb * L / a, abs(r[0]))
        d = np.abs(t - r)
        worst = np.maximum(worst, [d[0] / WM, d[1] / (WM * L), max(d[2] / (1 + abs(r[2])), d[3] / (1 + abs(r[3])))])
    assert worst[0] < 1e-7 and worst[1] < 1e-4 and worst[2] < 1e-5, worst


def test_rupture_guess_extreme_arguments():
    """Extreme finite arguments stay inside the table (a read outside it would be undefined memory in
    compiled code); a vanishing entrainment (xs = -beta/(2A) overflowing) falls back to the reference start
    and gives the reference result."""
    from hsbearing.models.ball_bearing.pocket import _rupture_guess, _station

    for xs, lo in [(1e308, -1e308), (-1e308, -1e308), (1e300, 1e300), (0.5, 0.5), (0.0, -1e-300), (-1e-300, 0.0)]:
        assert math.isfinite(_rupture_guess(xs, lo)) or abs(xs) > 1e300 or abs(lo) > 1e300
    a, L = 5e-6, math.sqrt(2 * Rb * 5e-6)
    for U in (5e-320, -5e-320, 1e-300, 1e-30):
        args = (a, U, -0.3, -4.0, 6.0, math.atan(6.0) - math.atan(-4.0), L, ETA)
        r, t = _station(*args, False), _station(*args, True)
        assert np.allclose(r, t, rtol=1e-9, atol=0, equal_nan=True), (U, r, t)


def test_jacobian_reuses_pocket_wrench_for_ring_columns_exactly():
    """jac_kernel reuses each ball's pocket wrench for the ring-state columns (the pocket depends on ball and
    cage states only): those columns equal the plain finite difference of the full rhs bit for bit, at a
    state with film, Hertz contact and friction all active."""
    import hsbearing
    from hsbearing.models.ball_bearing import kernel as K
    from hsbearing.systems.angular_contact.dynamics import build_model

    model = build_model(hsbearing.load_case("zhang2016"))
    P = model.P
    Z = model.layout.Z
    y = model.y0.copy()
    y[2 * Z:3 * Z] = np.linspace(-1.25, 1.25, Z) * kio.get(P, "c_p") / (0.5 * kio.get(P, "dm"))  # wall contact to wall contact
    y[3 * Z:4 * Z] = 0.01
    N = y.size
    J = np.zeros((N, N))
    K.jac_kernel(y, P, model.qu, model.qw, J, model.hscale, np.empty(4 * N))

    def f(yy):
        out = np.empty(N)
        K.rhs_kernel(yy, P, model.qu, model.qw, out, np.empty((Z, K.N_CONTRIB)), np.empty((1, 1)), False,
                     np.empty(K.N_CONTRIB), np.empty(K.N_GAUX))
        return out

    f0 = f(y)
    rg = 9 * Z + 12
    for col in range(rg, N):
        h = 1.4901161193847656e-08 * max(abs(y[col]), model.hscale[col])
        yp = y.copy()
        yp[col] += h
        assert np.array_equal(J[:, col], (f(yp) - f0) / (yp[col] - y[col])), col


# ----------------------------------------------------------------------------- station closed form vs quadrature
def _station_reference(A, beta, lo, hi, n=2000):
    """:func:`_station_trapezoid` on n and 2n intervals, Richardson-extrapolated (error O(h^4), ~1e-10 relative)."""
    r1 = np.array(_station_trapezoid(A, beta, lo, hi, n))
    r2 = np.array(_station_trapezoid(A, beta, lo, hi, 2 * n))
    return tuple((4.0 * r2 - r1) / 3.0)


def _station_trapezoid(A, beta, lo, hi, n):
    """Independent reference for one dimensionless station (A > 0): the rupture x2 by bisection on P(x2) = 0 and
    IP = int P, IPxi = int P xi, with P accumulated by the trapezoidal rule on n intervals in long double from
    P' = A/H^2 + beta xi/H^3 + gamma/H^3, gamma = -(A H2 + beta x2) (Reynolds exit condition), H = 1 + xi^2, on a
    grid uniform in atan(xi).  No closed form, no cancellation-prone antiderivative."""
    ld = np.longdouble
    A, beta, lo = ld(A), ld(beta), ld(lo)

    def integrals(x2):
        # uniform in th = atan(xi) (dxi = H dth): fine where the film is thin, coarse far out
        th = np.linspace(np.arctan(lo), np.arctan(x2), n + 1)
        t = np.tan(th)
        t[0], t[-1] = lo, x2
        H = 1 + t * t
        gamma = -(A * (1 + x2 * x2) + beta * x2)
        dp = (A * H + beta * t + gamma) / H**2  # dP/dth
        h = th[1] - th[0]
        P = np.concatenate([[ld(0)], np.cumsum((dp[1:] + dp[:-1]) * h / 2)])
        f, g = P * H, P * H * t
        return P[-1], np.sum((f[1:] + f[:-1]) * h / 2), np.sum((g[1:] + g[:-1]) * h / 2)

    xs = -beta / (2 * A)
    a_, b_ = xs, ld(hi)
    for _ in range(64):
        x2 = (a_ + b_) / 2
        if integrals(x2)[0] > 0:
            a_ = x2
        else:
            b_ = x2
    _, IP, IPxi = integrals(x2)
    return float(x2), float(IP), float(IPxi)


@pytest.mark.parametrize("lo", [-46.0, -5.0, -1.2, 2.0])
def test_station_closed_form_against_quadrature(lo):
    """_station_dimless (closed form, and its Gauss form for a short pressurised interval) against the independent
    long-double quadrature: the rupture, int P and int P xi for sources of both signs and for the source sign change
    xs from 3 local widths down to 1e-6 of a width from the inlet edge (the old closed form's cancellation corner,
    where it returned up to 1e-4 A for a station that carries ~1e-30 A).  Scale: A (Martin's IP is 0.16 A)."""
    from hsbearing.models.ball_bearing.pocket import _station_dimless

    A = 1.0
    w = math.sqrt(1.0 + lo * lo)  # local width
    hi = lo + 60.0 * w
    worst = np.zeros(3)
    for f in (3.0, 1.0, 0.3, 0.1, 0.06, 0.05, 0.045, 0.03, 0.01, 1e-3, 1e-6):
        xs = lo + f * w
        beta = -2.0 * A * xs
        x2r, IPr, IPxr = _station_reference(A, beta, lo, hi)
        x2, IP, IPxi = _station_dimless(A, beta, lo, hi, math.atan(hi) - math.atan(lo))
        # x2: 1e-9 of the interval; IP, IPxi: 1e-6 relative (the reference's trapezoid) or 1e-13 A absolute
        e = [abs(x2 - x2r) / (x2r - lo), abs(IP - IPr) / (1e-6 * abs(IPr) + 1e-13 * A),
             abs(IPxi - IPxr) / (1e-6 * abs(IPxr) + 1e-13 * A * w)]
        worst = np.maximum(worst, e)
        assert e[0] < 1e-6 and e[1] < 1 and e[2] < 1, (f, x2, x2r, IP, IPr, IPxi, IPxr)
        # short-interval limit: IP -> 0.140625 A S^4 / H_lo^3 (S = xs - lo): no jolt
        if f <= 1e-3:
            assert abs(IP / (0.140625 * A * (f * w) ** 4 / w**6) - 1.0) < 1e-2, (f, IP)


def test_station_first_moment_with_source():
    """int P xi with a source (beta != 0): the closed form's beta term is int xi^3/H^3 = [int xi/H^2] -
    [int xi/H^3] (it had a sign error, (d1 + d2), until issue 18's review: int P xi wrong by up to 20x, e.g.
    lo = -3, xs = -1: +0.229 instead of -0.018).  Independent reference: long-double quadrature."""
    from hsbearing.models.ball_bearing.pocket import _station_dimless

    for lo, xs in ((-3.0, 1.0), (-3.0, -1.0), (-10.0, 0.5), (-1.0, -0.5), (-3.0, 0.0)):
        A, beta, hi = 1.0, -2.0 * xs, 40.0
        x2r, IPr, IPxr = _station_reference(A, beta, lo, hi)
        x2, IP, IPxi = _station_dimless(A, beta, lo, hi, math.atan(hi) - math.atan(lo))
        assert abs(IP - IPr) < 1e-6 * abs(IPr) and abs(IPxi - IPxr) < 1e-6 * abs(IPxr) + 1e-12, (lo, xs, IPxi, IPxr)


# ----------------------------------------------------------------------------- batched stations
def test_atan_poly_error_bound():
    """The libm-free atan of the batched station passes is within its documented 4 ulp (relative 4 * 2^-53) of
    long-double atan over 1e-300 <= |t| <= 1e300 (log-uniform, both signs) and at the reduction boundaries (measured
    2.2 ulp); and
    atan(hi) - atan(lo) from it equals the libm form (``_atan_diff``) to 1e-15 rad, the +-pi branch included."""
    from hsbearing.models.ball_bearing.pocket import _TAN_3PI8, _TAN_PI8, _atan_diff, _atan_diff_poly, _atan_poly

    rng = np.random.default_rng(28)
    t = np.concatenate([rng.choice([-1.0, 1.0], 20000) * 10.0 ** rng.uniform(-300, 300, 20000),
                        rng.uniform(-4.0, 4.0, 20000),
                        np.array([0.0, 1.0, -1.0, _TAN_PI8, np.nextafter(_TAN_PI8, 1), _TAN_3PI8,
                                  np.nextafter(_TAN_3PI8, 0), 1e-320])])
    ref = np.arctan(t.astype(np.longdouble))
    got = np.array([_atan_poly(x) for x in t], dtype=np.longdouble)
    rel = np.abs(got - ref) / np.maximum(np.abs(ref), np.longdouble(1e-300))
    assert float(rel.max()) <= 4 * 2.0 ** -53, float(rel.max())
    assert _atan_poly(np.inf) == 0.5 * math.pi and _atan_poly(-np.inf) == -0.5 * math.pi
    worst = 0.0
    for _ in range(20000):
        x, lo = rng.choice([-1, 1]) * 10 ** rng.uniform(-3, 2), rng.choice([-1, 1]) * 10 ** rng.uniform(-3, 2)
        worst = max(worst, abs(_atan_diff_poly(x, lo) - _atan_diff(x, lo)))
    assert worst < 1e-15, worst


def test_batched_station_solve_equals_the_reference_station_by_station():
    """The batched solve (16 lanes per pass, selects instead of branches) gives every lane the reference
    station's pressure integrals (``_station(..., tabulated=False)``: scalar, Martin's start, libm atan) over
    random line-contact problems of both entrainment signs, any source, gaps 0.2-50 um, edges 0.1-20 widths,
    including short pressurised intervals (source sign change within 0.05 widths of the inlet) and lanes
    without film.  Tolerance as the tabulated start's station test (the same root, the closed form's own
    round-off): measured worst 9.9e-9 W_M (W), 2.2e-8 W_M L (Wx).  Every case of _station_dimless must occur
    (none, full film, Newton, short)."""
    from hsbearing.models.ball_bearing import pocket as pk

    rng = np.random.default_rng(281)
    seen = set()
    worst = np.zeros(2)
    for _ in range(400):
        w = np.zeros(pk._NROWS * pk._LANES)
        nl = int(rng.integers(1, pk._LANES + 1))
        refs = []
        for i in range(nl):
            a = 10 ** rng.uniform(-6.7, -4.3)
            L = math.sqrt(2 * Rb * a)
            lo, hi = -10 ** rng.uniform(-1, 1.3), 10 ** rng.uniform(-1, 1.3)
            if rng.random() < 0.05:
                lo, hi = hi, lo  # no wall: no film
            U = rng.choice([-1, 1]) * 10 ** rng.uniform(-3, 1.5)
            A = 6 * ETA * U
            if rng.random() < 0.2:  # short pressurised interval: xs = -beta/(2|A|) just past the inlet edge
                lom = -hi if A < 0 else lo
                beta = -2 * abs(A) * (lom + rng.uniform(1e-4, 0.04) * math.sqrt(1 + lom * lom))
            else:
                beta = rng.choice([-1, 1]) * 10 ** rng.uniform(-3, 3) * abs(A)
            F0 = beta * a / L
            dat = math.atan(hi) - math.atan(lo)
            refs.append((np.array(pk._station(a, U, F0, lo, hi, dat, L, ETA, False)[:2]),
                         max(4.896 * ETA * 0.5 * abs(U) * Rb * L / a, 1e-300), L))
            mir = A < 0
            for row, v in ((pk._R_A, a), (pk._R_L, L), (pk._R_AM, abs(A)), (pk._R_BETA, beta),
                           (pk._R_LOM, -hi if mir else lo), (pk._R_HIM, -lo if mir else hi),
                           (pk._R_MIR, -1.0 if mir else 1.0), (pk._R_DAT, dat)):
                w[row * pk._LANES + i] = v
        pk._batch_solve(w, nl)
        for i, (ref, WM, L) in enumerate(refs):
            seen.add(w[pk._R_ST * pk._LANES + i])
            got = np.array([w[pk._R_W * pk._LANES + i], w[pk._R_WX * pk._LANES + i]])
            WM = max(WM, abs(ref[0]))
            worst = np.maximum(worst, np.abs(got - ref) / [WM, WM * L])
    assert seen == {pk._ST_NONE, pk._ST_FULL, pk._ST_DONE, pk._ST_SHORT}, seen
    assert worst[0] < 1e-7 and worst[1] < 1e-4, worst


@pytest.mark.parametrize("n_st", [16, 24, 40, 512])
def test_batched_pocket_film_wrench_equals_reference(n_st):
    """The batched pocket film (lanes of 16, a partial last batch for 24 and 40 stations, 32 batches for 512)
    returns the scalar reference's wrench over random visited states: force within 1e-9 of the film load,
    moment within 1e-9 of its largest component (measured <= 8.2e-13 and 3.1e-13: the reference starts from
    Martin's exit, so its Newton root differs in the last digits)."""
    rng = np.random.default_rng(n_st)
    worst_f = worst_m = 0.0
    for ex, et, s0, v, w in _random_pocket_states(rng, 60):
        args = (ex, et, s0, *v, *w, ETA, Rb, Rp, R_BORE, R_OUT, HDM, n_st)
        ref = np.array(pocket_film_wrench(*args, False))
        new = np.array(pocket_film_wrench(*args))
        worst_f = max(worst_f, np.abs(new[:3] - ref[:3]).max() / max(ref[6], 1e-12))
        worst_m = max(worst_m, np.abs(new[3:6] - ref[3:6]).max() / (np.abs(ref[3:6]).max() + 1e-12))
    assert worst_f < 1e-9 and worst_m < 1e-9, (worst_f, worst_m)
