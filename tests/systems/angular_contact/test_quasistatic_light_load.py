"""Near-zero and zero loads in the quasi-static solver: answered at once, the unloaded limit a valid answer.

A relative tolerance on a vanishing load has no answer (``hsbearing quasistatic dgbb_6207 --set
operating.axial_load="5e-07 N"`` took 28 s and failed); the residual tolerance now has an absolute floor, the
bearing's own force scale, 1e-3 Z (m g + F_c) (:func:`hsbearing.models.ball_bearing.quasistatic.unloaded_force_scale`).
Deep groove: both signs of the axial load; angular contact: F_x >= 0 (a negative one is refused by the case
checks).
"""

from __future__ import annotations

import math
import resource

import numpy as np
import pytest

from hsbearing.case import load_case
from hsbearing.systems.angular_contact import quasistatic as qs

TOL = 1e-10  # qs.solve's default ring tolerance (relative to the load scale)


def _cpu() -> float:
    r = resource.getrusage(resource.RUSAGE_SELF)
    return r.ru_utime + r.ru_stime


def _floor(P) -> float:
    """1e-3 Z (m g + F_c) by hand from the problem's geometry (the force floor the solver is held to)."""
    wm = 0.5 * (P.omega_i * (1 - P.D * math.cos(P.alpha0) / P.dm) + P.omega_o * (1 + P.D * math.cos(P.alpha0) / P.dm))
    return 1e-3 * P.Z * P.ball_mass * (9.80665 + 0.5 * P.dm * wm**2)


def _solve(name: str, load: float):
    P = qs.build_problem(load_case(name, **{"operating.axial_load": f"{load!r} N"}))
    t = _cpu()
    sol = qs.solve(P)
    return P, sol, _cpu() - t


def test_force_floor_is_ball_weight_plus_centrifugal_force():
    """The floor by hand for the 6207 at 5000 r/min: m = rho pi D^3/6, omega_m of pure rolling (Harris Vol. 1
    Eq. 8.21), F_c = m (d_m/2) omega_m^2 (Harris Vol. 2 Eq. 3.1)."""
    P = qs.build_problem(load_case("dgbb_6207"))
    D, dm, Pd = 11.12e-3, 53.5e-3, 13e-6
    m = 7830 * math.pi * D**3 / 6
    cos_a0 = 1 - Pd / (2 * (0.52 + 0.52 - 1) * D)  # free contact angle of the clearance (Harris Vol. 1 Eq. 2.21)
    wm = 0.5 * (5000 * 2 * math.pi / 60) * (1 - D * cos_a0 / dm)  # outer ring still
    expected = 9 * (m * 9.80665 + m * 0.5 * dm * wm**2)
    assert P.force_floor == pytest.approx(1e-3 * expected, rel=1e-12)
    assert 0.05 < P.force_floor < 0.07  # ~6.6 N of centrifugal force per ball: the floor is set by the speed here


@pytest.mark.parametrize("name, loads", [
    ("dgbb_6207", [0.0, 1e-12, 1e-9, 5e-7, -1e-12, -1e-9, -5e-7]),
    ("zhang2016", [0.0, 1e-12, 1e-9, 5e-7]),
])
def test_near_zero_axial_load_is_answered_at_once(name, loads):
    qx = {}
    for F in loads:
        P, sol, cpu = _solve(name, F)
        assert cpu < 10.0, (name, F, cpu)  # was 28 s wall and a failure at 5e-7 N (dgbb_6207)
        # the ring equilibrium holds to the absolute floor: |R| <= tol x 1e-3 Z (m g + F_c)
        assert np.max(np.abs(sol.residual[:3])) <= TOL * _floor(P), (name, F, sol.residual)
        # the inner contacts carry the load and no more: sum Q_i sin(alpha_i) = |F| within the same floor
        st = sol.state
        axial = float(np.sum(st["Qi"] * np.abs(st["si"])))
        assert abs(axial - abs(F)) <= TOL * _floor(P) + 1e-12 * abs(F), (name, F, axial)
        qx[F] = sol.q[0]
    if name == "dgbb_6207":
        # the ring goes to the end of its axial play in the load direction: the sign follows the load, the two
        # ends are mirror images (the grooves are symmetric), and 0 N leaves the ring centred
        assert qx[0.0] == 0.0
        for F in (1e-12, 1e-9, 5e-7):
            assert qx[F] > 1e-5 and qx[-F] < -1e-5
            assert qx[F] == pytest.approx(-qx[-F], abs=1e-12)
    # the unloaded limit: the vanishing loads leave the ring where the largest of them does, within the Hertz
    # approach of 5e-7 N ((Q/K)^(2/3) ~ 1e-11 m per contact): one answer, continuous down to the limit
    positive = [F for F in loads if F > 0]
    assert max(qx[F] for F in positive) - min(qx[F] for F in positive) < 1e-9
