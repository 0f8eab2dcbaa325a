"""The thermal physical traction law "physical" (hsbearing.models.traction.thermal): each piece against its exact answer,
the law's symmetries and shape, the registry, and the public hsbearing.traction_coefficient.

The whole law against an independent finite-volume solution of the energy equation:
tests/validation/test_traction_thermal_reference.py.
"""

import math

import numpy as np
import pytest
from scipy.integrate import quad
from scipy.special import k0e

import hsbearing
from hsbearing.models import hertz, traction
from hsbearing.models.traction import thermal as th

EP = 228.6e9
RX, RY = 3.87e-3, 0.124  # the default case's inner contact
ARGS = ("182 N", "16.3 m/s", "130 degC", "3.87 mm", "124 mm", "228.6 GPa")


@pytest.mark.parametrize("u", [0.3, 5.0, 60.0, -16.0])
def test_band_source_matches_a_quadrature_of_jaegers_line_source(u):
    k, kap = th.STEEL_CONDUCTIVITY, th.STEEL_DIFFUSIVITY
    edges = np.array([-1e-4, -2e-5, 1e-4])
    xc = np.array([-3e-4, -5e-5, 0.0, 9e-5, 4e-4])
    M = th.band_source_influence(edges, xc, u, k, kap)
    for i, x in enumerate(xc):
        for j in range(2):
            def f(xi):
                X = u * (x - xi) / (2.0 * kap)
                return (k0e(X) if X > 0 else math.exp(-2.0 * abs(X)) * k0e(abs(X))) / (math.pi * k) if X != 0 else 0.0
            lo, hi = edges[j], edges[j + 1]
            ref = quad(f, lo, hi, points=[x] if lo < x < hi else None, limit=400, epsabs=0.0, epsrel=1e-11)[0]
            # far upstream the entry is ~1e-10 of the largest: the difference of two antiderivatives near -1 there
            assert M[i, j] == pytest.approx(ref, rel=1e-6, abs=1e-9 * M.max())


def test_band_source_high_peclet_limit_is_the_one_dimensional_transient():
    """Trailing edge of a uniform band source of width 2l at Pe = u l / (2 kappa) ~ 400: 2 q sqrt(kappa t / pi) / k,
    t = 2 l / u (Carslaw & Jaeger, semi-infinite solid under constant flux), 2 %."""
    k, kap, u, l = th.STEEL_CONDUCTIVITY, th.STEEL_DIFFUSIVITY, 100.0, 1e-4
    M = th.band_source_influence(np.array([-l, l]), np.array([l * (1 - 1e-9)]), u, k, kap)[0, 0]
    assert M == pytest.approx(2.0 * math.sqrt(kap * (2 * l / u) / math.pi) / k, rel=0.02)


def test_roelands_reduces_to_the_inlet_viscosity_and_its_slopes():
    eta_in, alpha, beta, T_in = 2e-3, 1.3e-8, 0.012, 403.15
    z, S0 = th.roelands_indices(eta_in, alpha, beta, T_in)
    assert th.roelands_viscosity(0.0, T_in, eta_in, T_in, z, S0) == pytest.approx(eta_in, rel=1e-12)
    dp = 1e3
    slope_p = math.log(th.roelands_viscosity(dp, T_in, eta_in, T_in, z, S0) / eta_in) / dp
    assert slope_p == pytest.approx(alpha, rel=1e-5)
    dT = 1e-3
    slope_T = -math.log(th.roelands_viscosity(0.0, T_in + dT, eta_in, T_in, z, S0)
                        / th.roelands_viscosity(0.0, T_in - dT, eta_in, T_in, z, S0)) / (2 * dT)
    assert slope_T == pytest.approx(beta, rel=1e-5)
    # at 1.2 GPa Roelands lies far below Barus (the point of the change)
    assert th.roelands_viscosity(1.2e9, T_in, eta_in, T_in, z, S0) < 0.05 * eta_in * math.exp(alpha * 1.2e9)


def test_heat_partition_and_film_temperatures():
    w1, w2 = th.heat_partition(16.0, 9.0)
    assert w1 + w2 == pytest.approx(1.0) and w1 / w2 == pytest.approx(4.0 / 3.0)
    assert th.heat_partition(0.0, 0.0) == (0.5, 0.5)
    assert th.film_mean_temperature_rise(1e7, 1.0, 1e-7, 0.1) == pytest.approx(
        2.0 / 3.0 * th.midfilm_temperature_rise(1e7, 1.0, 1e-7, 0.1))


def _contact(oil="4109", W=182.0, U=16.3, T=403.15, prm=None):
    eta, alpha, beta, K, _ = hsbearing._oil_at(oil, T)
    c = hertz.point_contact(RX, RY, W, EP, 0.0, EP, 0.0)
    return dict(W=W, U=U, Ep=EP, Rx=RX, k=float(c.ellipticity), a=float(c.a), T_in=T, eta_in=eta, alpha=alpha,
                beta_in=beta, K=K, prm=prm)


def test_thermal_off_is_the_isothermal_march():
    """thermal = False: the strip's mu is the Maxwell-Eyring march at the inlet temperature summed over the cells."""
    c = _contact(prm=th.PhysicalParameters(thermal=False))
    prm = c["prm"]
    b, p0, h, Ge, tau0 = th.contact_parameters(c["W"], c["U"], EP, RX, c["k"], c["a"], c["eta_in"], c["alpha"], prm,
                                               c["T_in"])
    oil = dict(eta_in=c["eta_in"], alpha=c["alpha"], beta_in=c["beta_in"], K=c["K"])
    S = 0.002
    mu = th.strip_mu(S, c["U"], p0, b, h, c["T_in"], oil, prm, Ge=Ge, tau0_in=tau0)
    edges, xc = th._strip_grid(b, th.N_CELLS)
    p = p0 * np.sqrt(1 - (xc / b) ** 2)
    z, S0 = th.roelands_indices(c["eta_in"], c["alpha"], c["beta_in"], c["T_in"])
    tau = th.maxwell_eyring_march(xc, p, th.roelands_viscosity(p, c["T_in"], c["eta_in"], c["T_in"], z, S0), tau0,
                                  prm.Lambda * p, Ge, S * c["U"] / h, c["U"], -b)
    assert mu == pytest.approx(float(np.sum(tau * np.diff(edges)) / np.sum(p * np.diff(edges))), rel=1e-13)


def test_march_converges_to_the_linear_maxwell_closed_form():
    """Constant viscosity, linear flow (tau0 large), no cap: the Maxwell equation U/G dtau/dx = gdot - tau/eta has
    tau = eta gdot (1 - exp(-G (x - x_in) / (eta U))).  Relaxation length half the path: backward Euler is first
    order (error halves with the step) and within 1e-3 on 400 steps.  Relaxation length 1e-3 of the path (steps
    2.5-10 x longer, the stiff case of a hot film): no overshoot, the viscous
    level reached to 1e-9 from a quarter of the path on."""
    eta, G, gdot, U, L = 20.0, 1e9, 1e3, 10.0, 2e-4
    errs = []
    e = 500.0 * eta  # relaxation length e U / G = 1e-4 m = L / 2
    for n in (100, 200, 400):
        x = np.linspace(0.0, L, n + 1)[1:]
        tau = th.maxwell_eyring_march(x, np.ones(n), e, 1e15, 1e15, G, gdot, U, 0.0)
        exact = e * gdot * -np.expm1(-G * x / (e * U))
        errs.append(float(np.max(np.abs(tau - exact)) / (e * gdot)))
    assert errs[2] < 1e-3 and 1.8 < errs[0] / errs[1] < 2.2 and 1.8 < errs[1] / errs[2] < 2.2, errs
    for n in (100, 200, 400):
        x = np.linspace(0.0, L, n + 1)[1:]
        tau = th.maxwell_eyring_march(x, np.ones(n), eta, 1e15, 1e15, G, gdot, U, 0.0)
        assert np.all(tau <= eta * gdot * (1 + 1e-12)) and np.all(np.diff(tau) >= -1e-12 * eta * gdot)
        assert np.allclose(tau[n // 4:], eta * gdot, rtol=1e-9, atol=0)


def test_march_is_bounded_by_the_elastic_line_and_the_flow_curve():
    """The marched stress never exceeds the elastic stress G gdot (x - x_in) / U nor the cap tau_L, and rises
    monotonically where the viscosity and the cap do not fall (a uniform film)."""
    x = np.linspace(0.0, 1e-4, 60)[1:]
    G, gdot, U, tauL = 5e8, 3e4, 16.0, 4e7
    tau = th.maxwell_eyring_march(x, np.ones_like(x), 1e3, 5e6, tauL, G, gdot, U, 0.0)
    assert np.all(tau <= G * gdot * x / U * (1 + 1e-12)) and np.all(tau < tauL)
    assert np.all(np.diff(tau) >= 0.0)


def test_closed_form_buildup_is_kept_as_an_option():
    """buildup = "closed": the strip's mu is the closed-form local stress summed over the cells (exact)."""
    c = _contact(prm=th.PhysicalParameters(thermal=False, buildup="closed"))
    prm = c["prm"]
    b, p0, h, Ge, tau0 = th.contact_parameters(c["W"], c["U"], EP, RX, c["k"], c["a"], c["eta_in"], c["alpha"], prm,
                                               c["T_in"])
    oil = dict(eta_in=c["eta_in"], alpha=c["alpha"], beta_in=c["beta_in"], K=c["K"])
    S = 0.02
    mu = th.strip_mu(S, c["U"], p0, b, h, c["T_in"], oil, prm, Ge=Ge, tau0_in=tau0)
    edges, xc = th._strip_grid(b, th.N_CELLS)
    p = p0 * np.sqrt(1 - (xc / b) ** 2)
    z, S0 = th.roelands_indices(c["eta_in"], c["alpha"], c["beta_in"], c["T_in"])
    tau = th.local_stress(p, th.roelands_viscosity(p, c["T_in"], c["eta_in"], c["T_in"], z, S0), S * c["U"] / h, tau0,
                          prm.Lambda * p, Ge * S * (xc + b) / h)
    assert mu == pytest.approx(float(np.sum(tau * np.diff(edges)) / np.sum(p * np.diff(edges))), rel=1e-13)


def test_odd_in_slip_even_in_rolling_direction_and_heating_lowers_traction():
    c = _contact()
    S = np.array([-0.3, -0.05, -1e-3, 1e-3, 0.05, 0.3])
    mu = th.contact_mu(S, **c)
    assert np.allclose(mu[::-1], -mu, rtol=0, atol=1e-15)
    c2 = dict(c, U=-c["U"])
    assert np.allclose(th.contact_mu(S, **c2), mu, rtol=0, atol=1e-15)
    iso = th.contact_mu(S, **dict(c, prm=th.PhysicalParameters(thermal=False)))
    assert np.all(np.abs(mu) <= np.abs(iso) + 1e-15)
    assert abs(mu[-1]) < 0.9 * abs(iso[-1])  # at S = 0.3 the heat matters


def test_traction_falls_beyond_its_maximum_at_large_slip():
    """The shape the issue asks for: mu has an interior maximum in slip and falls beyond it (heating)."""
    c = _contact()
    S = np.geomspace(1e-4, 1.5, 40)
    mu = th.contact_mu(S, **c)
    i = int(np.argmax(mu))
    assert 0 < i < len(S) - 1
    assert mu[-1] < 0.95 * mu[i]


def test_registry_gives_physical_to_every_oil_and_not_to_the_kernel():
    for oil in traction.OILS:
        assert traction.PHYSICAL_LAW in traction.KNOWN_LAWS[oil]
        assert traction.law_name(oil, "physical") == "physical"
        with pytest.raises(ValueError, match="not compiled"):
            traction.law_id(oil, "physical")
    assert not traction.is_seed_law("physical")
    assert traction.RECOMMENDED_LAW in (traction.EYRING_LAW, traction.PHYSICAL_LAW)


def test_case_with_physical_law_is_refused_with_one_line():
    case = hsbearing.load_case("zhang2016")
    with pytest.raises(hsbearing.CaseError, match="traction_law"):
        from hsbearing.case.checks import check_possible  # noqa: F401

        case.with_overrides(**{"lubricant.traction_law": "physical"})


# ----------------------------------------------------------------------------
# the public API


def test_traction_coefficient_default_is_the_registered_law():
    mu = hsbearing.traction_coefficient("4109", 0.05, *ARGS)
    ref = float(traction.get("4109")(0.05, 182.0, 16.3, 403.15, 228.6e9, 3.87e-3))
    assert mu == pytest.approx(ref, rel=1e-12)


def test_traction_coefficient_units_quantities_and_si_agree():
    import pint

    ureg = pint.UnitRegistry()
    a = hsbearing.traction_coefficient("4106", [0.01, -0.05], *ARGS, law="physical")
    b = hsbearing.traction_coefficient("4106", [0.01, -0.05], 182.0, 16.3, 403.15, 3.87e-3, 0.124, 228.6e9,
                                       law="physical")
    c = hsbearing.traction_coefficient("4106", [0.01, -0.05], 182 * ureg.N, 16.3 * ureg("m/s"),
                                       ureg.Quantity(130.0, ureg.degC), 3.87 * ureg.mm, 124 * ureg.mm,
                                       228.6 * ureg.GPa, law="physical")
    assert np.allclose(a, b, rtol=1e-12) and np.allclose(a, c, rtol=1e-12)
    assert a.shape == (2,) and a[0] > 0 > a[1]


def test_traction_coefficient_eyring_equals_the_registry():
    mu = hsbearing.traction_coefficient("4106", 0.01, *ARGS, law="eyring")
    eta, alpha, *_ = hsbearing._oil_at("4106", 403.15)
    c = hertz.point_contact(RX, RY, 182.0, EP, 0.0, EP, 0.0)
    ref = traction.contact_mu("4106", 0.01, 182.0, 16.3, 403.15, EP, RX, RY, "eyring", k=float(c.ellipticity),
                              a=float(c.a), eta=eta, alpha=alpha)
    assert mu == pytest.approx(float(ref), rel=1e-12)


def test_traction_coefficient_of_a_lubricant_file():
    mu = hsbearing.traction_coefficient("heavy_machine_oil", 0.05, *ARGS, law="physical")
    assert 0.0 < mu < 0.1
    assert hsbearing.traction_coefficient("heavy_machine_oil", 0.05, *ARGS) == pytest.approx(
        hsbearing.traction_coefficient("4106", 0.05, *ARGS), rel=1e-12)  # its [traction] table: the 4106 law


@pytest.mark.parametrize("args,key", [
    (("4109", 0.05, "-1 N", *ARGS[1:]), "load"),
    (("4109", 0.05, "182 N", "16.3 m", *ARGS[2:]), "rolling_speed"),
    (("4109", 0.05, *ARGS[:4], "1 mm", ARGS[5]), "Ry"),
    (("no_such_oil", 0.05, *ARGS), "oil"),
    (("4109", "fast", *ARGS), "S"),
])
def test_traction_coefficient_bad_input_names_the_argument(args, key):
    with pytest.raises(hsbearing.CaseError) as e:
        hsbearing.traction_coefficient(*args)
    assert key in str(e.value)


def test_traction_coefficient_unknown_law():
    with pytest.raises(hsbearing.CaseError, match="law"):
        hsbearing.traction_coefficient("4109", 0.05, *ARGS, law="magic")


def test_nahme_film_matches_a_finite_volume_film():
    """The closed-form film (thermal.nahme_film) against the reference's finite-volume film (tests/helpers): a
    Newtonian film with viscosity eta0 exp(-beta dT) between walls at one temperature; F = tau h / (eta0 dU) and
    the mean rise phi_mean / beta, 1e-3 (the grid's error)."""
    import sys
    from pathlib import Path

    sys.path.insert(0, str(Path(__file__).resolve().parents[1] / "helpers"))
    import thermal_traction_fv as fv

    eta0, beta, K, h = 0.01, 0.03, 0.1, 1e-6
    for dU in (5.0, 30.0, 80.0):
        tau, dT = fv.couette_film(dU, h, K, lambda T: eta0 * np.exp(-beta * (T - 300.0)), n_film=400)
        F, phi_max, phi_mean = th.nahme_film(beta * tau * dU * h / (8.0 * K))
        assert float(F) == pytest.approx(tau * h / (eta0 * dU), rel=1e-3)
        assert float(phi_max) / beta == pytest.approx(dT.max(), rel=1e-3)
        assert float(phi_mean) / beta == pytest.approx(dT.mean(), rel=1e-3)
    F, _, pm = th.nahme_film(np.array([1e-6]))
    assert F[0] == pytest.approx(1.0 - 2e-6 / 3.0, rel=1e-9) and pm[0] == pytest.approx(2e-6 / 3.0, rel=1e-3)
