"""Churning losses of the bearing cavity beyond the drag of a ball in a mixture at rest (quasi-static power loss).

Three laws, each a bound or an estimate whose range is reported (docs/power_loss.md, "Drag band, jet-oil
acceleration, cage windage"):

* :func:`couette_mixture_angular_velocity`, :func:`couette_corotation_fraction`: how fast the air-oil mixture of
  the cavity could be carried round, from the circular Couette flow between the two raceways ([1]); the upper end
  of the co-rotation band.
* :func:`ball_drag_power`: the drag of a ball moving at v through a mixture moving at u (same direction) and the
  power it costs, split into the wake's share and the mixture's share ([2]).
* :func:`jet_oil_acceleration_power`: the power to bring the supplied oil from its inlet tangential speed to the
  speed it leaves with (momentum conservation, derived below).
* :func:`rotating_annulus_windage_moment`: the moment of a thin annulus (the cage side faces) turning in a fluid
  at rest (von Karman's rotating disc, [3]); a labelled estimate of the cage windage.
* :func:`taylor_couette_gap_moment`, :func:`taylor_couette_wall_moment`, :func:`stationary_wall_moment`,
  :func:`free_disc_pumped_flow`, :func:`mixture_momentum_balance`: the steady angular-momentum balance of the cavity
  mixture (balls' drag, rotating and stationary ring walls, the cage's surfaces, side openings, throughflow entering
  without swirl), solved for the mixture's swirl speed u at the pitch circle ([4]-[9]).

References
----------
[1] Circular Couette flow: the steady azimuthal Navier-Stokes solution between coaxial cylinders,
    omega(r) = A + B / r^2, with no slip on both walls (e.g. Landau & Lifshitz, *Fluid Mechanics*, 2nd ed.,
    Sec. 18, Eq. (18.4); Batchelor, *An Introduction to Fluid Dynamics*, Sec. 4.5).  Used here only as the
    estimate of an upper bound of the mixture's co-rotation: it ignores the stationary side walls of the
    housing, the cage bars, and the axial throughflow of air and oil that enter without swirl.
[2] Drag by its definition F = 1/2 C_D rho (pi D^2 / 4) w |w| with w the velocity of the body relative to the
    fluid far from it (Clift, Grace & Weber 1978, Ch. 5; models/ball_bearing/drag.py [4]).  The power the
    moving ball spends is F . v (force on the ball times the ball's velocity in the frame of the stationary
    ring), not F . w: the part F . u is work done on the mixture (driving it round), which the mixture
    dissipates on the stationary walls or carries out of the bearing; the part F . w is dissipated in the
    ball's wake.  Both are losses of the shaft.
[3] von Karman T., Z. angew. Math. Mech. 1 (1921) 233; Cochran W. G., Proc. Camb. Phil. Soc. 30 (1934) 365
    (laminar similarity solution, G'(0) = -0.6159); Schlichting H., Gersten K., *Boundary-Layer Theory*,
    8th ed. (2000), the free rotating disc: moment of both faces of a disc of radius R,
    c_M = 2 M / (1/2 rho omega^2 R^5) = 3.87 Re^-1/2 (laminar) and 0.146 Re^-1/5 (turbulent, von Karman's 1/7
    power-law estimate), Re = omega R^2 / nu.  The coefficients are those of the secondary literature as
    recalled, NOT read here in the book; the laminar one is checked against our own solution of the von
    Karman equations (tests/models/test_churning.py).  The local wall shear behind each law is
    tau ~ r (laminar) and tau ~ r^1.6 (turbulent), so an annulus r1..r2 takes the R^4 resp. R^4.6 difference.
[4] Torque of the flow between coaxial cylinders, inner r1 turning at omega relative to the outer r2 = r1 + s:
    laminar, the circular Couette moment M = 4 pi mu L r1^2 r2^2 omega / (r2^2 - r1^2) ([1]); turbulent, Bilgen E.,
    Boulos R., "Functional dependence of torque coefficient of coaxial cylinders on gap width and Reynolds
    numbers", ASME J. Fluids Eng. 95 (1973) 122: C_M = 2 M / (pi rho omega^2 r1^4 L) = f(s / r1, Re), Re =
    omega r1 s / nu, four regimes.  READ here: the abstract only (four regimes in Re and s / r1).  RECALLED, not
    read (as quoted in the electrical-machine windage literature, e.g. Saari 1998, who writes C_f = C_M / 2):
    C_M = 10 (s/r1)^0.3 / Re (Re < 64), 2 (s/r1)^0.3 Re^-0.6 (64 .. 500), 1.03 (s/r1)^0.3 Re^-0.5 (500 .. 1e4),
    0.065 (s/r1)^0.3 Re^-0.2 (> 1e4).  Used here: the larger of the exact Couette moment and the recalled
    turbulent correlation (Re >= 64), the same upper-leaning max as [3].
[5] Flow pumped by a free rotating disc (the inner ring's side faces drawing air into the cavity): laminar,
    von Karman / Cochran, Q = -H(inf) pi R^2 (nu omega)^1/2 per face with H(inf) = -0.8845 (checked against our own
    solution of the von Karman equations, tests/models/test_churning.py); turbulent (1/7 power law),
    Q = 0.219 nu R Re^0.8 per face, Re = omega R^2 / nu (Owen J. M., Rogers R. H., *Flow and Heat Transfer in
    Rotating-Disc Systems*, Vol. 1 (1989), the free disc; RECALLED, not read).  The larger of the two.
[6] The mixture's angular-momentum balance (derived here; control volume: the annulus between the rings' lands
    over the bearing width, the mixture lumped into one swirl speed u at the pitch radius r_m, i.e. a core in
    solid-body rotation between wall layers as in turbulent Taylor-Couette flow): in steady state
    Z r_m F_b(v - u) + M_in - M_out + M_cage - M_side - (m_oil + m_air) u r_m = 0, with F_b the ball drag of [2]
    (force on the mixture), M_in the moment of the inner ring's surface on the core across its wall layer, M_out that
    of the core on the outer ring's surface ([7], each with its own relative speed and sign), M_cage the cage's
    surfaces ([8]), M_side the two side openings taken as stationary walls under the rotating core ([9], a band: 0
    or both) and the throughflow entering without swirl and leaving with u.  Every term is monotone in u, so the
    root is unique.  In the laminar limit without balls, throughflow, cage or side walls the two Couette moments
    across r_i .. r_m and r_m .. r_o balance at exactly the Couette angular velocity at r_m ([1]): the Couette
    solution restricted to r_i .. r_m is the Couette flow between those radii.
[7] The wall moments of a gap with a core (derived here): Bilgen & Boulos's C_M ([4]) is the moment G of a WHOLE
    gap r1 .. r2 whose walls differ by d_omega; at high Reynolds number the gap is a core in (near) solid-body
    rotation between two wall layers (Batchelor's inviscid core with boundary layers, the picture of [4]'s
    supercritical data), and in steady state both layers transmit the same G (d/dr (r^2 tau) = 0).  A layer's shear
    follows the correlation's own wall law: G ~ Re^-0.2 d_omega^2 gives tau ~ rho^0.8 mu^0.2 (r d)^1.8 s^-0.2 with
    d the layer's jump, so 2 pi r^2 L tau = G at both walls makes d ~ r^-(19/9): d_1 / d_2 = (r2 / r1)^(19/9), and
    d_1 + d_2 = d_omega.  Hence the moment of the wall at r_w on a core d slower than it (r_o the other wall) is
    G_BB at the full-gap jump d (1 + (r_w / r_o)^(19/9)); the two layers in series reproduce G_BB(d_omega) exactly.
    (The former use of [4] across each HALF gap with the layer's own jump gave ~1/3.5 of this, 2^1.8 x 2^0.1.)
    Checked against our own finite-difference solution of the turbulent Couette flow with a mixing length
    (Nikuradse's distribution, van Driest's damping) across the gap (tests/models/test_churning.py).
[8] The cage in the annulus (derived here): the cage turns at omega_c with its bore facing the inner ring's land and
    its outside surface facing the outer ring's land over the cage's width; each such pair is a gap with the
    mixture's core between two wall layers ([7]), the core at the common swirl u / r_m; beside the cage the two
    rings face each other ([7]); the side faces are the free disc ([3]) at the cage's speed relative to the core
    (a disc in a co-rotating fluid; the free-disc law at the relative speed is an estimate, not a solved flow).  The
    guided surface is a thin oil film (the guide-land loss), not a wall layer of the mixture: left out.
[9] Boedewadt U. T., "Die Drehstroemung ueber festem Grunde", Z. angew. Math. Mech. 20 (1940) 241: a fluid rotating
    as a body over a stationary wall, similarity solution u = r omega F, v = r omega G, w = (nu omega)^1/2 H with
    F'' = F^2 - G^2 + H F' + 1, G'' = 2 F G + H G', H' = -2 F, F = G = H = 0 at the wall, F -> 0, G -> 1 far
    from it; G'(0) = 0.7729, F'(0) = -0.9420 (values as tabulated by Rogers M. H., Lance G. N., J. Fluid Mech. 7
    (1960) 617, RECALLED, not read; checked against our own solution of the equations, tests/models/test_churning.py).
"""

from __future__ import annotations

import math

from hsbearing.models.ball_bearing.drag import ball_drag_coefficient

__all__ = ["couette_mixture_angular_velocity", "couette_corotation_fraction", "ball_drag_power",
           "jet_oil_acceleration_power", "rotating_annulus_windage_moment", "DISC_LAMINAR_CM", "DISC_TURBULENT_CM",
           "drag_band", "taylor_couette_gap_moment", "free_disc_pumped_flow", "mixture_momentum_balance",
           "VON_KARMAN_H_INF", "FREE_DISC_TURBULENT_CW", "taylor_couette_wall_moment",
           "WALL_SPLIT_EXPONENT", "stationary_wall_moment", "BOEDEWADT_G0"]

#: c_M Re^1/2 of a free disc, both faces, laminar ([3]: wall shear 0.6159 rho nu^1/2 omega^3/2 r per face, so
#: M = 2 x 2 pi 0.6159 rho nu^1/2 omega^3/2 R^4 / 4 = 1.935 rho nu^1/2 omega^3/2 R^4 = 3.87 Re^-1/2 (1/2 rho omega^2 R^5))
DISC_LAMINAR_CM = 3.87
#: c_M Re^1/5 of a free disc, both faces, turbulent (von Karman 1/7 power law) ([3]; recalled, not read)
DISC_TURBULENT_CM = 0.146
#: -H(inf) of von Karman's free disc: axial inflow per face Q = VON_KARMAN_H_INF pi R^2 (nu omega)^1/2 ([5]; Cochran 1934)
VON_KARMAN_H_INF = 0.8845
#: C_w Re^-0.8 of the turbulent free disc, Q = C_w nu R per face ([5]; recalled, not read)
FREE_DISC_TURBULENT_CW = 0.219
#: Bilgen & Boulos regimes ([4], recalled): (upper Re of the regime, coefficient, Re exponent)
_BB_REGIMES = ((64.0, 10.0, -1.0), (500.0, 2.0, -0.6), (1.0e4, 1.03, -0.5), (math.inf, 0.065, -0.2))
#: G'(0) of Boedewadt's flow (a fluid in solid-body rotation over a stationary wall): wall shear
#: tau = G'(0) rho nu^1/2 omega^3/2 r ([9]; 0.7729 recalled, checked against our own solution, 0.77289)
BOEDEWADT_G0 = 0.7729
#: the exponent p of the split of a turbulent gap's jump between its two wall layers, d_in / d_out = (r_o / r_i)^p
#: ([7]: equal moments 2 pi r^2 L tau and tau ~ rho^0.8 mu^0.2 (r d)^1.8 s^-0.2, the wall law of the Re^-0.2 regime)
WALL_SPLIT_EXPONENT = 19.0 / 9.0


def couette_mixture_angular_velocity(omega_i: float, omega_o: float, r_i: float, r_o: float, r: float) -> float:
    """Angular velocity [rad/s] at radius r of the circular Couette flow between a cylinder r_i turning at omega_i
    and a cylinder r_o turning at omega_o ([1]).

    omega(r) = A + B / r^2 with A = (omega_o r_o^2 - omega_i r_i^2) / (r_o^2 - r_i^2),
    B = (omega_i - omega_o) r_i^2 r_o^2 / (r_o^2 - r_i^2): the solution of d/dr (r^3 d omega / dr) = 0 (no
    azimuthal shear stress divergence) with no slip at both walls.
    """
    if not 0.0 < r_i < r_o:
        raise ValueError("need 0 < r_i < r_o")
    d = r_o * r_o - r_i * r_i
    A = (omega_o * r_o * r_o - omega_i * r_i * r_i) / d
    B = (omega_i - omega_o) * r_i * r_i * r_o * r_o / d
    return A + B / (r * r)


def couette_corotation_fraction(gamma: float, omega_i: float = 1.0, omega_o: float = 0.0) -> float:
    """Upper estimate k_C of the mixture's co-rotation: the Couette angular velocity at the pitch radius over the
    cage's pure-rolling angular velocity [-] ([1]).

    The walls are the raceways at their contact radii r_i = r_m (1 - gamma), r_o = r_m (1 + gamma)
    (gamma = D cos(alpha) / d_m); the cage (ball centre) turns at omega_c = (omega_i (1 - gamma) + omega_o
    (1 + gamma)) / 2 (rolling without slip at both contacts).  For the inner ring turning alone this reduces
    to k_C = 1 - gamma / 2 - gamma^2 / 2 (0.92 for gamma = 0.14): in a laminar Couette flow the mixture at the
    pitch radius would move almost with the balls.  Returns nan when the cage does not turn.
    """
    if not 0.0 < gamma < 1.0:
        raise ValueError("gamma = D cos(alpha) / d_m must be within (0, 1)")
    w_c = 0.5 * (omega_i * (1.0 - gamma) + omega_o * (1.0 + gamma))
    if w_c == 0.0:
        return float("nan")
    return couette_mixture_angular_velocity(omega_i, omega_o, 1.0 - gamma, 1.0 + gamma, 1.0) / w_c


def ball_drag_power(v: float, u: float, D: float, rho_e: float, C_D: float) -> tuple[float, float, float, float]:
    """Drag of one ball moving at v [m/s] through the mixture moving at u [m/s] (both along the orbit, signed), and
    its power: (F, P_total, P_wake, P_mixture) in [N], [W] ([2]).

    F = -1/2 C_D rho_e (pi D^2 / 4) w |w|, w = v - u (the force on the ball, opposite to its motion relative to
    the mixture); P_total = -F v (what the ball's driver spends), P_wake = -F w >= 0 (dissipated in the ball's
    wake), P_mixture = -F u (work done on the mixture; dissipated at the walls or carried out).
    P_total = P_wake + P_mixture.  With u = k v, 0 <= k <= 1: P_total = 1/2 C_D rho_e A (1 - k)^2 |v|^3 >= 0 in
    both orbit directions.
    """
    w = v - u
    F = -0.5 * C_D * rho_e * 0.25 * math.pi * D * D * w * abs(w)  # [2]
    return F, -F * v, -F * w, -F * u


def jet_oil_acceleration_power(mass_flow: float, v_out: float, v_in: float = 0.0) -> tuple[float, float]:
    """Power [W] to accelerate the supplied oil tangentially from v_in to v_out, and the part dissipated: (P, P_diss).

    Derivation (momentum conservation, steady flow through a control volume round the rotating parts): the oil
    enters with tangential velocity v_in and leaves with v_out, so the rotating surfaces exert on it the
    tangential force m_dot (v_out - v_in); these surfaces move at v_out where the oil leaves them, so they spend
    P = m_dot (v_out - v_in) v_out.  The oil carries out the kinetic energy 1/2 m_dot (v_out^2 - v_in^2); the
    rest, P_diss = 1/2 m_dot (v_out - v_in)^2, is dissipated in the acceleration (an inelastic pick-up).  For oil
    supplied without swirl, P = m_dot v^2 (the term named in NASA-era bearing heat balances as the oil's
    "acceleration" or "churning"; the form is the momentum argument above, not a read equation).  Both the
    kinetic energy carried out and the dissipation are lost by the shaft.
    """
    if mass_flow < 0.0:
        raise ValueError("mass flow must not be negative")
    P = mass_flow * (v_out - v_in) * v_out
    return P, 0.5 * mass_flow * (v_out - v_in) ** 2


def _free_disc_turbulent_moment(rho: float, nu: float, w: float, r1: float, r2: float) -> float:
    """|M| [N m] of the two faces of an annulus r1..r2 turning at |omega| = w in a fluid at rest, von Karman's
    turbulent 1/7-power law: DISC_TURBULENT_CM / 2 rho nu^1/5 w^9/5 (r2^4.6 - r1^4.6) ([3])."""
    return 0.5 * DISC_TURBULENT_CM * rho * nu**0.2 * w**1.8 * (r2**4.6 - r1**4.6)


def rotating_annulus_windage_moment(omega: float, r1: float, r2: float, rho: float, mu: float) -> float:
    """Moment [N m] resisting a thin annulus r1..r2, both faces wetted, turning at omega in a fluid at rest ([3]).

    Laminar (von Karman / Cochran): M = DISC_LAMINAR_CM / 2 rho nu^1/2 |omega|^3/2 (r2^4 - r1^4);
    turbulent (von Karman 1/7 law): M = DISC_TURBULENT_CM / 2 rho nu^1/5 |omega|^9/5 (r2^4.6 - r1^4.6);
    the larger of the two is taken (the turbulent law exceeds the laminar one above Re ~ 5.5e4, below the
    observed transition Re ~ 3e5: the max is a labelled, upper-leaning choice).  Signed opposite to omega.
    A disc-friction estimate of the cage side faces, not a cage windage law read from a bearing source.
    """
    if not 0.0 <= r1 < r2:
        raise ValueError("need 0 <= r1 < r2")
    if omega == 0.0 or rho == 0.0:
        return 0.0
    nu = mu / rho
    w = abs(omega)
    m_lam = 0.5 * DISC_LAMINAR_CM * rho * math.sqrt(nu) * w**1.5 * (r2**4 - r1**4)
    m_turb = _free_disc_turbulent_moment(rho, nu, w, r1, r2)
    return -math.copysign(max(m_lam, m_turb), omega)


def drag_band(Z: int, v: float, D: float, rho_e: float, mu_e: float, k_max: float) -> dict:
    """The ball drag of Z balls at orbital speed v over the unsettled choices: the co-rotation fraction k in
    {0, k_max} and C_D of the free sphere held subcritical (:func:`~hsbearing.models.ball_bearing.drag.ball_drag_coefficient`)
    or the standard curve with its crisis (the cavity's turbulence moves the crisis to the ball's Reynolds
    number; models/ball_bearing/drag.py [4]), each at the Reynolds number of the relative velocity.

    Returns {(k, "subcritical"|"crisis"): P_total [W]} and "low", "high".
    """
    from hsbearing.models.ball_bearing.drag import RE_FLOOR, sphere_drag_coefficient

    out = {}
    for k in (0.0, k_max):
        w = (1.0 - k) * v
        C_sub, Re = ball_drag_coefficient(rho_e, mu_e, w, D)
        C_cr = sphere_drag_coefficient(max(Re, RE_FLOOR))
        for label, C in (("subcritical", C_sub), ("crisis", C_cr)):
            out[(k, label)] = Z * ball_drag_power(v, k * v, D, rho_e, C)[1]
    vals = list(out.values())
    out["low"], out["high"] = min(vals), max(vals)
    return out


def taylor_couette_gap_moment(d_omega: float, r1: float, r2: float, length: float, rho: float, mu: float,
                              turbulent: bool = True) -> float:
    """Moment [N m] transmitted across the gap between coaxial cylinders r1 < r2 of axial length ``length`` whose
    angular velocities differ by d_omega = omega(r1) - omega(r2) [rad/s]; signed like d_omega (the moment the inner
    surface exerts on the outer) ([4]).

    Laminar: the circular Couette moment 4 pi mu L r1^2 r2^2 d_omega / (r2^2 - r1^2) (exact; [1]).  ``turbulent``:
    the larger of that and Bilgen & Boulos's correlation M = 1/2 C_M pi rho d_omega^2 r1^4 L at Re = |d_omega| r1 s /
    nu >= 64 (recalled constants; [4]).
    """
    if not 0.0 < r1 < r2:
        raise ValueError("need 0 < r1 < r2")
    if d_omega == 0.0:
        return 0.0
    w = abs(d_omega)
    m = 4.0 * math.pi * mu * length * r1 * r1 * r2 * r2 * w / (r2 * r2 - r1 * r1)  # [1]
    if turbulent and rho > 0.0:
        m = max(m, _bilgen_boulos_moment(w, r1, r2, length, rho, mu))
    return math.copysign(m, d_omega)


def _bilgen_boulos_moment(w: float, r1: float, r2: float, length: float, rho: float, mu: float) -> float:
    """|M| of Bilgen & Boulos's correlation for the whole gap r1 .. r2 at the jump w >= 0 ([4]); 0 below Re = 64."""
    s = r2 - r1
    Re = rho * w * r1 * s / mu
    if Re < 64.0:
        return 0.0
    for re_max, c, e in _BB_REGIMES:
        if Re < re_max:
            C_M = c * (s / r1) ** 0.3 * Re**e  # [4]
            break
    return 0.5 * C_M * math.pi * rho * w * w * r1**4 * length


def taylor_couette_wall_moment(d_omega: float, r_wall: float, r_other: float, r_core: float, length: float,
                               rho: float, mu: float, turbulent: bool = True) -> float:
    """Moment [N m] that ONE wall of a gap exerts on the gap's core in solid-body rotation, the wall at radius r_wall
    turning d_omega = omega_wall - omega_core [rad/s] faster than the core, the gap closed by a wall at r_other; signed
    like d_omega ([7]).

    Turbulent: the full-gap moment of Bilgen & Boulos (:func:`taylor_couette_gap_moment` between min and max of
    r_wall, r_other) at the full-gap jump d_omega (1 + (r_wall / r_other)^(19/9)) -- the jump the whole gap would need
    for this wall's layer to carry d_omega, when both layers transmit the same moment and each follows the
    correlation's wall law tau ~ (r d_omega)^1.8 ([7]).  Laminar: the exact circular Couette moment across
    r_wall .. r_core (the wall to the core's radius, [1]).  ``turbulent``: the larger of the two, else the laminar.
    """
    if not (r_wall > 0.0 and r_other > 0.0 and r_wall != r_other):
        raise ValueError("need r_wall > 0, r_other > 0 and r_wall != r_other")
    if not min(r_wall, r_other) < r_core < max(r_wall, r_other):
        raise ValueError("the core radius must lie between the walls")
    if d_omega == 0.0:
        return 0.0
    r1, r2 = min(r_wall, r_core), max(r_wall, r_core)
    m = abs(taylor_couette_gap_moment(d_omega, r1, r2, length, rho, mu, turbulent=False))  # [1]
    if turbulent and rho > 0.0:
        full = abs(d_omega) * (1.0 + (r_wall / r_other) ** WALL_SPLIT_EXPONENT)  # [7]
        m = max(m, _bilgen_boulos_moment(full, min(r_wall, r_other), max(r_wall, r_other), length, rho, mu))
    return math.copysign(m, d_omega)


def stationary_wall_moment(omega_f: float, r1: float, r2: float, rho: float, mu: float) -> float:
    """Moment [N m] that two stationary annular walls r1..r2 (the side openings, one face each) exert on a fluid
    above them turning as a body at omega_f; signed opposite to omega_f ([9]).

    Laminar: Boedewadt's flow, wall shear tau = BOEDEWADT_G0 rho nu^1/2 |omega_f|^3/2 r, so
    M = pi BOEDEWADT_G0 rho nu^1/2 |omega_f|^3/2 (r2^4 - r1^4) for the two faces (25.5 % above the free disc's
    0.6159); turbulent: the free disc's 1/7-power law of :func:`rotating_annulus_windage_moment` at the relative
    speed (no turbulent Boedewadt law was read); the larger of the two.
    """
    if not 0.0 <= r1 < r2:
        raise ValueError("need 0 <= r1 < r2")
    if omega_f == 0.0 or rho == 0.0:
        return 0.0
    nu = mu / rho
    w = abs(omega_f)
    m_lam = math.pi * BOEDEWADT_G0 * rho * math.sqrt(nu) * w**1.5 * (r2**4 - r1**4)  # [9]
    m_turb = _free_disc_turbulent_moment(rho, nu, w, r1, r2)  # [3]
    return -math.copysign(max(m_lam, m_turb), omega_f)


def free_disc_pumped_flow(omega: float, R: float, nu: float) -> float:
    """Volume flow [m^3/s] drawn axially towards and pumped radially out by ONE face of a disc of radius R turning
    at omega in a fluid at rest ([5]): the larger of von Karman's laminar 0.8845 pi R^2 (nu |omega|)^1/2 and the
    turbulent 0.219 nu R (|omega| R^2 / nu)^0.8."""
    if R <= 0.0 or nu <= 0.0:
        raise ValueError("need R > 0 and nu > 0")
    w = abs(omega)
    if w == 0.0:
        return 0.0
    q_lam = VON_KARMAN_H_INF * math.pi * R * R * math.sqrt(nu * w)
    q_turb = FREE_DISC_TURBULENT_CW * nu * R * (w * R * R / nu) ** 0.8
    return max(q_lam, q_turb)


def mixture_momentum_balance(*, Z: int, D: float, r_m: float, r_i: float, r_o: float, length: float,
                             omega_i: float, omega_o: float, omega_c: float, rho_e: float, mu_e: float,
                             drag_coefficient, mass_flow: float, side_walls: bool = False,
                             turbulent: bool = True, balls: bool = True, wall_law: str = "full_gap",
                             cage: dict | None = None) -> dict:
    """Steady swirl of the cavity mixture from its angular-momentum balance ([6]).

    Walls: the inner ring's surface at r_i turning at omega_i, the outer ring's at r_o turning at omega_o (both of
    axial length ``length``), each coupled to the mixture's core through :func:`taylor_couette_wall_moment` (the
    full gap r_i .. r_o, [7]; ``wall_law = "half_gap"``: the former :func:`taylor_couette_gap_moment` across r_i .. r_m
    and r_m .. r_o with each layer's own jump, kept for comparison only);
    with ``side_walls`` the two side openings r_i .. r_o as stationary walls (:func:`stationary_wall_moment`, [9],
    at the core's angular velocity).  Balls: Z balls on the pitch circle at the cage speed v = omega_c r_m, drag
    1/2 C_D rho_e (pi D^2/4) (v - u)|v - u| on the mixture ([2]), C_D = ``drag_coefficient(|v - u|)`` (the drag law's
    C_D at the relative speed).  Throughflow: ``mass_flow`` [kg/s] entering without swirl and leaving at u.

    ``cage`` (dict r_bore, r_outside, width [m], guidance "outer_ring" | "inner_ring" | "ball"; r_i < r_bore < r_m <
    r_outside < r_o): the cage turning at omega_c inside the annulus ([8]).  Over the cage's width the inner ring faces
    the cage's bore across r_i .. r_bore and the outer ring faces the cage's outside surface across r_outside .. r_o
    (each pair a gap of :func:`taylor_couette_wall_moment`); beside the cage (length - width) the rings face each other
    across r_i .. r_o; the cage's two side faces (when width < length) exchange the free-disc moment
    (:func:`rotating_annulus_windage_moment`) at the cage's speed relative to the core.  A guide land is a film, not a
    wall layer of the mixture: an outer-ring-guided cage's outside surface and the outer land over the cage's width
    (an inner-ring-guided cage's bore and the inner land) are left out of the balance (their loss is the guide land's).

    Returns dict: u [m/s], k = u / v (nan if the cage stands still), omega_f = u / r_m, the moments on the mixture
    (``M_balls``, ``M_inner``, ``M_outer``, ``M_cage``, ``M_side``, ``M_flow``; they sum to ~0), the ball force on
    the mixture per ball ``F_ball`` (= - the drag on the ball), C_D, and the powers: ``P_balls`` = Z F_ball v (what
    the balls' drivers spend), ``P_wake`` = Z F_ball (v - u), ``P_inner`` = M_inner omega_i (the inner ring's
    surface), ``P_outer`` = -M_outer omega_o, ``P_cage`` = M_cage omega_c (the cage's surfaces), the dissipation in
    the wall layers ``P_walls``, the outflow's kinetic energy ``P_outflow_ke`` = 1/2 m u^2 and the pick-up
    dissipation ``P_mixing`` = 1/2 m u^2.
    """
    from scipy.optimize import brentq

    if mass_flow < 0.0:
        raise ValueError("mass flow must not be negative")
    if not 0.0 < r_i < r_m < r_o:
        raise ValueError("need 0 < r_i < r_m < r_o")
    if wall_law not in ("full_gap", "half_gap"):
        raise ValueError("wall_law must be 'full_gap' or 'half_gap'")
    if cage is not None:
        r_cb, r_co, w_cage, guide = cage["r_bore"], cage["r_outside"], cage["width"], cage["guidance"]
        if not r_i < r_cb < r_m < r_co < r_o or w_cage <= 0.0:
            raise ValueError("need r_i < cage bore radius < r_m < cage outside radius < r_o and a cage width > 0")
        if guide not in ("outer_ring", "inner_ring", "ball"):
            raise ValueError("cage guidance must be outer_ring, inner_ring or ball")
        w_in = min(w_cage, length)  # over the cage's width
        L_free = length - w_in  # beside the cage: ring faces ring
    else:
        L_free = length
    A = 0.25 * math.pi * D * D
    v = omega_c * r_m

    def wall(d, r_w, r_x, L):  # moment of the wall r_w on the core of the gap r_w .. r_x over the length L
        if L <= 0.0:
            return 0.0
        return taylor_couette_wall_moment(d, r_w, r_x, 0.5 * (r_w + r_x) if not min(r_w, r_x) < r_m < max(r_w, r_x)
                                          else r_m, L, rho_e, mu_e, turbulent)

    def parts(u):
        w_f = u / r_m
        w = v - u
        C = drag_coefficient(abs(w)) if (balls and w != 0.0) else 0.0
        F = 0.5 * C * rho_e * A * w * abs(w) if balls else 0.0  # [2], on the mixture
        if wall_law == "half_gap":
            M_in = taylor_couette_gap_moment(omega_i - w_f, r_i, r_m, L_free, rho_e, mu_e, turbulent)
            M_out = taylor_couette_gap_moment(w_f - omega_o, r_m, r_o, L_free, rho_e, mu_e, turbulent)
        else:  # [7]: M_out is the moment of the core on the outer ring's surface
            M_in = wall(omega_i - w_f, r_i, r_o, L_free)
            M_out = -wall(omega_o - w_f, r_o, r_i, L_free)
        M_cage = 0.0
        if cage is not None:  # [8]
            if guide != "inner_ring":  # the inner land and the cage's bore face each other across the mixture
                M_in += wall(omega_i - w_f, r_i, r_cb, w_in)
                M_cage += wall(omega_c - w_f, r_cb, r_i, w_in)
            if guide != "outer_ring":
                M_out -= wall(omega_o - w_f, r_o, r_co, w_in)
                M_cage += wall(omega_c - w_f, r_co, r_o, w_in)
            if L_free > 0.0:  # the side faces inside the control volume
                M_cage -= rotating_annulus_windage_moment(omega_c - w_f, r_cb, r_co, rho_e, mu_e)
        M_side = (-stationary_wall_moment(w_f, r_i, r_o, rho_e, mu_e)) if side_walls else 0.0
        M_flow = mass_flow * u * r_m
        return F, C, M_in, M_out, M_cage, M_side, M_flow

    def f(u):
        F, _, M_in, M_out, M_cage, M_side, M_flow = parts(u)
        return Z * F * r_m + M_in - M_out + M_cage - M_side - M_flow

    speeds = (0.0, v, omega_i * r_m, omega_o * r_m)
    lo, hi = min(speeds), max(speeds)
    if hi == lo:
        u = lo
    else:
        f_lo, f_hi = f(lo), f(hi)
        if f_lo <= 0.0:
            u = lo
        elif f_hi >= 0.0:
            u = hi
        else:
            u = brentq(f, lo, hi, xtol=1e-13 * (hi - lo), rtol=1e-15, maxiter=200)
    F, C, M_in, M_out, M_cage, M_side, M_flow = parts(u)
    w_f = u / r_m
    P_inner, P_outer = M_in * omega_i, -M_out * omega_o
    P_walls = M_in * (omega_i - w_f) + M_out * (w_f - omega_o) + M_cage * (omega_c - w_f) + M_side * w_f
    return {"u": u, "k": u / v if v != 0.0 else float("nan"), "omega_f": w_f, "v": v, "C_D": C,
            "F_ball": F, "M_balls": Z * F * r_m, "M_inner": M_in, "M_outer": -M_out, "M_cage": M_cage,
            "M_side": -M_side, "M_flow": -M_flow, "P_balls": Z * F * v, "P_wake": Z * F * (v - u),
            "P_inner": P_inner, "P_outer": P_outer, "P_cage": M_cage * omega_c, "P_walls": P_walls,
            "P_outflow_ke": 0.5 * mass_flow * u * u, "P_mixing": 0.5 * mass_flow * u * u}
