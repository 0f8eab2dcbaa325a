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
"""

from __future__ import annotations

import math

from hsbearing.models.ball_bearing.drag import ball_drag_coefficient

__all__ = ["couette_mixture_angular_velocity", "couette_corotation_fraction", "ball_drag_power",
           "jet_oil_acceleration_power", "rotating_annulus_windage_moment", "DISC_LAMINAR_CM", "DISC_TURBULENT_CM",
           "drag_band"]

#: c_M Re^1/2 of a free disc, both faces, laminar ([3]: wall shear 0.6159 rho nu^1/2 omega^3/2 r per face, so
#: M = 2 x 2 pi 0.6159 rho nu^1/2 omega^3/2 R^4 / 4 = 1.935 rho nu^1/2 omega^3/2 R^4 = 3.87 Re^-1/2 (1/2 rho omega^2 R^5))
DISC_LAMINAR_CM = 3.87
#: c_M Re^1/5 of a free disc, both faces, turbulent (von Karman 1/7 power law) ([3]; recalled, not read)
DISC_TURBULENT_CM = 0.146


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
    m_turb = 0.5 * DISC_TURBULENT_CM * rho * nu**0.2 * w**1.8 * (r2**4.6 - r1**4.6)
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
