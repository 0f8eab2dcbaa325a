"""The ball-drag law checked against independent physics (issue 29, independent review).

- the force is the sphere drag that defines C_D, 1/2 C_D rho v^2 A, hence independent of the unit system
  (Harris's v^1.95 form, read in SI with C_D from the sphere curve, is not);
- the effective viscosity of oil droplets dispersed in air reduces to Einstein's dilute-suspension result,
  lies within 3 % of Batchelor & Green's second-order result for phi <= 0.1, and within the Voigt
  (arithmetic) and Reuss (harmonic) means;
- the drag power that ``hsbearing friction`` reports is Z F_D v with F_D computed by hand from the model's
  own mixture density, C_D and orbital speed.
"""

import math

import numpy as np
import pytest

from hsbearing.case import load_case
from hsbearing.models.ball_bearing import drag


def test_drag_force_is_unit_system_independent():
    """Same physical state in SI and in cgs (cm, g, s -> dyn): the force must agree after the unit conversion.
    A v^1.95 law would differ by 100^0.05 = 1.26 between the two systems."""
    v, D, rho, C = 37.0, 7.14e-3, 23.0, 0.48  # m/s, m, kg/m^3
    f_si = drag.ball_drag_force(v, D, rho, C, 0.0)  # N
    f_cgs = drag.ball_drag_force(v * 100.0, D * 100.0, rho * 1e-3, C, 0.0)  # dyn
    assert f_cgs * 1e-5 == pytest.approx(f_si, rel=1e-12)
    # and it is the sphere drag: 1/2 C_D rho v^2 (pi D^2 / 4), independent of the regularisation far from v = 0
    assert f_si == pytest.approx(-0.5 * C * rho * v * v * math.pi * D * D / 4.0, rel=1e-12)
    assert drag.ball_drag_force(2 * v, D, rho, C, 0.0) == pytest.approx(4.0 * f_si, rel=1e-12)
    # both directions of the orbit: opposite to the motion, odd in v (also through the regularised v = 0)
    for u in (-v, -1e-3, 1e-3, v):
        f = drag.ball_drag_force(u, D, rho, C, 0.01)
        assert f * u < 0.0 and f == pytest.approx(-drag.ball_drag_force(-u, D, rho, C, 0.01), rel=1e-15)
    assert drag.ball_drag_force(0.0, D, rho, C, 0.01) == 0.0


def test_mixture_viscosity_einstein_limit():
    """Dilute rigid spheres (oil 1e6 x more viscous than air): d mu / d phi -> 5/2 mu_air (Einstein 1906/1911)."""
    mu_a = drag.AIR_VISCOSITY
    for phi in (1e-6, 1e-4):
        mu = drag.mixture_viscosity(1e6 * mu_a, phi)
        assert (mu / mu_a - 1.0) / phi == pytest.approx(2.5, rel=1e-3)


def test_mixture_viscosity_batchelor_green():
    """Rigid spheres at finite phi: Batchelor & Green, J. Fluid Mech. 56 (1972) 401, mu / mu_c = 1 + 2.5 phi
    + 5.2 phi^2 (pure straining).  The implemented lower bound agrees within 3 % up to phi = 0.1."""
    mu_a = drag.AIR_VISCOSITY
    for phi in (0.01, 0.03, 0.05, 0.1):
        ref = 1.0 + 2.5 * phi + 5.2 * phi * phi
        assert drag.mixture_viscosity(1e6 * mu_a, phi) / mu_a == pytest.approx(ref, rel=0.03)


def test_mixture_viscosity_taylor_drops():
    """Oil drops in air (viscosity ratio ~90, e.g. 1.9e-3 / 2.1e-5): Taylor, Proc. R. Soc. A 138 (1932) 41,
    mu = mu_c (1 + phi (1 + 5/2 lambda) / (1 + lambda)).  Agreement of the first-order coefficient within 3 %
    (the bound treats the drops as viscous inclusions without interfacial slip; Taylor's drops circulate)."""
    mu_a, mu_o = drag.AIR_VISCOSITY, 1.9e-3
    lam = mu_o / mu_a
    phi = 1e-5
    coef = (drag.mixture_viscosity(mu_o, phi) / mu_a - 1.0) / phi
    assert coef == pytest.approx((1.0 + 2.5 * lam) / (1.0 + lam), rel=0.03)


def test_mixture_viscosity_bounds_and_limits():
    mu_a, mu_o = drag.AIR_VISCOSITY, 1.9e-3
    assert drag.mixture_viscosity(mu_o, 0.0) == mu_a
    assert drag.mixture_viscosity(mu_o, 1.0) == pytest.approx(mu_o, rel=1e-12)
    x = np.linspace(0.0, 1.0, 101)
    mu = np.array([drag.mixture_viscosity(mu_o, xi) for xi in x])
    voigt = x * mu_o + (1 - x) * mu_a
    reuss = 1.0 / (x / mu_o + (1 - x) / mu_a)
    assert np.all(mu <= voigt * (1 + 1e-12)) and np.all(mu >= reuss * (1 - 1e-12))
    assert np.all(np.diff(mu) > 0)
    with pytest.raises(ValueError):
        drag.mixture_viscosity(mu_o, 1.5)
    with pytest.raises(ValueError):
        drag.mixture_viscosity(1e-6, 0.1)


def test_friction_drag_power_is_z_fd_v():
    """``hsbearing friction``'s drag (the compiled kernel at the quasi-static state) = Z x F_D x v with
    F_D = 1/2 C_D rho_e (pi D^2/4) v^2 computed here from the mixture of the case (rho_e = X rho_oil +
    (1 - X) rho_air by hand) and the model's orbital speed and C_D."""
    from hsbearing.systems.angular_contact.dynamics import build_model
    from hsbearing.systems.angular_contact.rating import quasi_static_power_loss

    case = load_case("zhang2016")
    r = quasi_static_power_loss(case)
    m = build_model(case)
    info = m.info
    X = case.lubricant.oil_volume_fraction
    rho_e = X * case.lubricant.density + (1 - X) * 1.1
    D = case.bearing.ball_diameter
    # orbital speed of each ball centre at the state: r_b thetadot_b (r_b = d_m/2 + u_b)
    v = m.layout.ball_radius(m.y0, case.bearing.pitch_diameter) * m.y0[m.layout.ball("thetadot_b")]
    assert info["drag_orbital_speed"] == pytest.approx(float(v.mean()), rel=1e-3)  # d_m/2 x cage speed
    P = float(np.sum(0.5 * info["drag_coefficient"] * rho_e * math.pi * D * D / 4.0 * v**3))
    assert info["drag_density"] == pytest.approx(rho_e, rel=1e-12)
    assert r["drag"] == pytest.approx(P, rel=1e-6)  # v0 = 0.01 m/s regularisation: ~1e-7 relative
