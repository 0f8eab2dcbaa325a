"""Dissipated power of a contact action, by source (the force set of Zhang et al. 2016).

Every contact of the dynamic model acts on two bodies with equal and opposite
force systems (action on the ball, reaction on the ring, the cage or the
ground).  The power that such a pair of actions takes out of the mechanical
system is the work rate of the action on body A and of the reaction on body
B, which depends only on the *relative* motion at the point of application
(Goldstein, *Classical Mechanics*, 3rd ed., Sec. 1.2; Greenwood, *Principles
of Dynamics*, 2nd ed., Sec. 2.4: the work of internal forces between two rigid
bodies):

    D = -(F . (v_A(P) - v_B(P)) + M_P . (omega_A - omega_B))

with F the force on A applied at P and M_P its moment about P.  Each source of
loss is evaluated by one of the functions below, with the force (or moment)
and the relative sliding (or angular) velocity at its own contact, so that a
source added by another model plugs in through one call.  They are pure,
numba-compiled and callable from Python.  The sum over sources, together with
the rate of the mechanical energy, closes the power balance of the bearing
(tests/systems/angular_contact/test_balances.py; docs/power_loss.md).
"""

from __future__ import annotations

from numba import njit

from hsbearing.compile_cache import check_compile_cache

__all__ = ["sliding_power", "couple_power", "normal_damping_power", "elastic_energy_hertz"]


@njit(cache=True, inline="always")
def sliding_power(fx, fy, fz, dvx, dvy, dvz):
    """Power dissipated by a contact force that opposes sliding [W].

    D = -F . dv, with F the force [N] that the contact puts on body A at the
    point P, and dv = v_A(P) - v_B(P) [m/s] the velocity of A's material point
    relative to B's material point at P (B carries the reaction -F at P).
    Positive when the force opposes the slip (traction, Coulomb friction, drag
    against a medium at rest).  Any frame: only the relative velocity enters.
    """
    return -(fx * dvx + fy * dvy + fz * dvz)


@njit(cache=True, inline="always")
def couple_power(mx, my, mz, dwx, dwy, dwz):
    """Power dissipated by a pure couple between two bodies [W].

    D = -M . (omega_A - omega_B), M [N m] the couple on body A (B carries -M),
    dw = omega_A - omega_B [rad/s] the relative angular velocity.  Used for
    the EHL rolling-resistance couple of a race contact and for the viscous
    friction moment of the guide-land film.
    """
    return -(mx * dwx + my * dwy + mz * dwz)


@njit(cache=True, inline="always")
def normal_damping_power(Q, Q_elastic, approach_rate):
    """Power dissipated by the non-elastic part of a normal contact force [W].

    The normal pair (load Q [N] pushing the bodies apart along the normal,
    approach delta with rate delta' [m/s]) does the work rate -Q delta'.  Its
    elastic part Q_elastic(delta) is conservative (-d/dt of the stored
    energy, :func:`elastic_energy_hertz`); the rest, (Q - Q_elastic) delta',
    is dissipated: contact damping (Hunt & Crossley 1975), squeeze films
    (Hamrock, Schmid & Jacobson 2004, Ch. 15).  When Q is clipped at zero
    while the elastic part is positive (fast separation) the difference is
    negative and delta' < 0, so D >= 0 still.
    """
    return (Q - Q_elastic) * approach_rate


@njit(cache=True, inline="always")
def elastic_energy_hertz(K, delta):
    """Elastic energy of a Hertz point contact Q = K delta^1.5: U = (2/5) K delta^2.5 [J] (0 for delta <= 0).

    Harris & Kotzalas, *Rolling Bearing Analysis* 5th ed., Vol. 1, Eq. 6.40 integrated over delta.
    """
    if delta <= 0.0:
        return 0.0
    return 0.4 * K * delta * delta * delta ** 0.5


# numba bakes callees and captured constants into its cache: key the cache on them (compile_cache.py)
check_compile_cache(globals())
