"""Steady thermal network (issue 29 items 4-5): analytical limit cases, energy balance, CLI + archive + figure."""

import math

import numpy as np
import pytest

from hsbearing import cli
from hsbearing.systems.angular_contact.thermal import (
    Network,
    constriction_resistance,
    cylinder_resistance,
    fin_conductance,
    harris_oil_h,
    rotating_cylinder_h,
    solve_network,
)


def test_one_conduction_path_to_a_convective_sink():
    """T = T_inf + Q (R_cond + 1/(hA)): a heated ring conducting through a cylindrical wall to a surface cooled by air."""
    Q, T_inf, h, A = 25.0, 300.0, 40.0, 0.02
    R_cond = cylinder_resistance(0.02, 0.05, 0.03, 45.0)
    assert R_cond == pytest.approx(math.log(2.5) / (2 * math.pi * 45.0 * 0.03))
    net = Network(nodes=["ring", "surface"], fixed={"air": T_inf},
                  links=[("ring", "surface", 1.0 / R_cond, "conduction"), ("surface", "air", h * A, "convection")],
                  sources={"ring": Q})
    T, R = solve_network(net)
    assert T["ring"] == pytest.approx(T_inf + Q * (R_cond + 1.0 / (h * A)), rel=1e-10)
    assert T["surface"] == pytest.approx(T_inf + Q / (h * A), rel=1e-10)
    assert np.max(np.abs(R)) < 1e-8


def test_advection_and_nonlinear_link():
    """Oil node heated by Q, carried away by m c_p: T = T_in + Q / (m c_p); a temperature-dependent link still closes."""
    net = Network(nodes=["oil"], fixed={"in": 350.0}, advection=[("oil", "in", 20.0)], sources={"oil": 10.0})
    T, _ = solve_network(net)
    assert T["oil"] == pytest.approx(350.5, rel=1e-12)
    # G(T) = 0.1 (T - 290)^0.5 from a body to air: solve Q = G(T) (T - 300), check the balance
    net = Network(nodes=["b"], fixed={"air": 300.0}, links=[("b", "air", lambda T: 0.1 * (T["b"] - 290.0) ** 0.5, "c")],
                  sources={"b": 50.0})
    T, R = solve_network(net)
    assert 0.1 * (T["b"] - 290.0) ** 0.5 * (T["b"] - 300.0) == pytest.approx(50.0, rel=1e-9)


def test_elements():
    assert constriction_resistance(1e-3, 40.0) == pytest.approx(1.0 / 0.16)
    assert constriction_resistance(1e-3, 40.0, 1e-3) == pytest.approx(1.0 / 0.16)
    # a thin ellipse: K(m) -> ln(4 a / b) (Abramowitz & Stegun 17.3.26), R -> ln(4 a/b) / (2 pi k a)
    assert constriction_resistance(1e-3, 40.0, 1e-6) == pytest.approx(math.log(4e3) / (2 * math.pi * 40.0 * 1e-3), rel=1e-5)
    # long fin: sqrt(h P k A)
    d, h, k = 0.02, 50.0, 40.0
    assert fin_conductance(h, d, k, 100.0) == pytest.approx(math.sqrt(h * math.pi * d * k * math.pi * d * d / 4))
    # short fin: ~ h P L (all the surface at the base temperature)
    assert fin_conductance(h, d, k, 1e-4) == pytest.approx(h * math.pi * d * 1e-4, rel=1e-3)
    # Nu = 0.133 Re^(2/3) Pr^(1/3), Re = omega d^2 / nu
    Re = 1000.0 * 0.03**2 / 1.8e-5
    assert rotating_cylinder_h(1000.0, 0.03) == pytest.approx(0.133 * Re ** (2 / 3) * 0.71 ** (1 / 3) * 0.028 / 0.03)
    # n in r/min: 1000 rad/s = 9549.3 r/min (the reading is checked against the rotating disk in test_thermal_reference)
    assert harris_oil_h(1000.0, 1e-5, 0.14, 50.0, 1.0) == pytest.approx(0.0986 * 0.14 * 50 ** (1 / 3) * math.sqrt(9549.2966 / 1e-5))


@pytest.fixture(scope="module")
def zhang_archive(tmp_path_factory):
    out = tmp_path_factory.mktemp("thermal") / "t.nc"
    rc = cli.main(["thermal", "zhang2016", "-o", str(out)])
    return rc, out


def test_zhang2016_converges_and_balances(zhang_archive, capsys):
    from hsbearing import open_run

    rc, out = zhang_archive
    assert rc == 0
    ds = open_run(out)
    assert ds.attrs["converged"] == 1
    P = float(ds.heat_generated)
    removed = float(ds.heat_removed_by_oil) + float(ds.heat_removed_by_conduction)
    assert abs(P - removed) / P < 1e-3  # issue: < 0.1 %
    assert abs(float(ds.heat_balance_error)) < 1e-9  # measured ~3e-15
    # the heat generated is the sum of the sources at equilibrium
    srcs = [v for k, v in ds.data_vars.items() if k.startswith("thermal_power_loss_")]
    assert sum(float(v) for v in srcs) == pytest.approx(P, rel=1e-12)
    assert float(ds.node_heat_input.sum()) == pytest.approx(P, rel=1e-12)
    # temperatures in kelvin, above the inlet: the bearing heats on its own heat
    for name in [k for k in ds.data_vars if "temperature" in k]:
        assert ds[name].attrs["units"] == "K"
    assert float(ds.oil_outlet_temperature) > float(ds.oil_inlet_temperature)
    assert (ds.node_temperature.values > 273.15).all()
    # the fixed point: the last lubricant temperature reproduces the network's contact temperature
    T = dict(zip([str(n) for n in ds.node.values], ds.node_temperature.values))
    Tc = 0.25 * (T["inner_ring"] + T["outer_ring"] + 2 * T["balls"])
    assert abs(Tc - float(ds.lubricant_temperature)) < 0.01
    # each node's own balance: heat generated = net outflow along its links
    net = dict(zip([str(n) for n in ds.node.values], ds.node_heat_input.values.astype(float)))
    for a, b, q in zip(ds.link_from.values, ds.link_to.values, ds.link_heat_flow.values):
        net[str(a)] = net.get(str(a), 0.0) - float(q)
        net[str(b)] = net.get(str(b), 0.0) + float(q)
    assert max(abs(net[n]) for n in T if n in net and n not in ("oil_inlet", "ambient")) < 1e-9 * P


def test_zhang2016_archive_plots(zhang_archive, tmp_path):
    from hsbearing import systems
    from hsbearing.results import open_run

    rc, out = zhang_archive
    assert systems.archive_kind(open_run(out)) == "thermal"
    png = tmp_path / "t.png"
    assert cli.main(["plot", str(out), "-o", str(png)]) == 0
    assert png.stat().st_size > 10_000


def test_thermal_needs_a_flow():
    from hsbearing.case import CaseError, load_case
    from hsbearing.systems.angular_contact.thermal import thermal_equilibrium

    case = load_case("zhang2016", **{"lubricant.oil_flow_rate": "0 L/min"})
    with pytest.raises(CaseError, match="oil_flow_rate"):
        thermal_equilibrium(case)


def test_run_thermal_starts_at_the_equilibrium_temperature(monkeypatch, capsys, tmp_path):
    """hsbearing run --thermal hands the dynamics the case at the thermal equilibrium's lubricant temperature and
    each race's contact inlet temperature (T_ring + T_ball)/2."""
    import hsbearing
    from hsbearing import systems
    from hsbearing.case import load_case
    from hsbearing.systems.angular_contact.thermal import thermal_equilibrium

    seen = {}

    class Stop(Exception):
        pass

    def fake_simulate(case, **kw):
        seen["T"] = case.lubricant.temperature
        seen["races"] = kw.get("race_temperatures")
        raise Stop

    monkeypatch.setattr(hsbearing, "simulate", fake_simulate)
    monkeypatch.setattr(systems, "simulate", fake_simulate)
    with pytest.raises(Stop):
        cli.main(["run", "zhang2016", "--thermal", "--duration", "1ms", "-o", str(tmp_path / "r.nc"), "-q", "--no-figure"])
    out = capsys.readouterr().out
    assert "thermal equilibrium: lubricant temperature" in out
    assert seen["T"] - 273.15 == pytest.approx(131.81, abs=0.05)  # docs/thermal.md (regression of our own network)
    assert "contact inlet temperatures: inner race" in out
    th = thermal_equilibrium(load_case("zhang2016"))
    Tb = float(th.ball_temperature)
    assert seen["races"] == pytest.approx((0.5 * (float(th.inner_ring_temperature) + Tb),
                                           0.5 * (float(th.outer_ring_temperature) + Tb)), rel=1e-12)


def test_oil_convection_follows_the_oil_temperature_for_a_lubricant_file():
    """A lubricant file sets lubricant.kinematic_viscosity at the case temperature; the oil-side convection takes
    the viscosity at the oil node's temperature from the file (it took the case's value at every temperature)."""
    from hsbearing.case import load_case
    from hsbearing.systems.angular_contact.thermal import _viscosity

    case = load_case("zhang2016", **{"lubricant.oil": "mobil_jet_oil_ii", "lubricant.temperature": "121 degC"})
    d, rho = case.lubricant.definition, case.lubricant.density
    assert _viscosity(case, 394.15) == pytest.approx(case.lubricant.kinematic_viscosity * rho, rel=1e-9)
    for T in (360.0, 450.0):
        assert _viscosity(case, T) == pytest.approx(float(d.kinematic_viscosity(T, rho)) * rho, rel=1e-12)
    assert _viscosity(case, 450.0) < 0.6 * _viscosity(case, 394.15)
    # a viscosity given in the case stays the user's value
    fixed = load_case("zhang2016", **{"lubricant.kinematic_viscosity": "3 mm^2/s"})
    assert _viscosity(fixed, 450.0) == pytest.approx(3e-6 * fixed.lubricant.density)


def test_fixed_point_is_the_same_from_a_cold_and_a_hot_start(zhang_archive):
    """Uniqueness (docs/thermal.md, "Review"): started 60 K below the inlet (lubricant and every node) the fixed
    point reaches the temperatures of the default start within the fixed-point tolerance."""
    from hsbearing import open_run
    from hsbearing.case import load_case
    from hsbearing.systems.angular_contact.thermal import NODES, thermal_equilibrium

    ref = open_run(zhang_archive[1])
    case = load_case("zhang2016")
    ds = thermal_equilibrium(case, T_start=case.lubricant.temperature - 60.0,
                             x0_nodes=[case.lubricant.temperature - 60.0] * len(NODES))
    assert ds.attrs["converged"] == 1
    np.testing.assert_allclose(ds.node_temperature.values, ref.node_temperature.values, atol=0.01)


def test_no_equilibrium_is_a_result_with_its_status(capsys, tmp_path):
    """An oil flow far too small: the fixed point climbs past the oil's range (thermal runaway at this flow). That is
    an answer, not bad input: the last network solved is archived with status no_equilibrium and the reason, the
    CLI says so on one stderr line naming lubricant.oil_flow_rate and exits 1; ``run --thermal`` has no steady state
    to start from and refuses on one line (exit 2) before any dynamics."""
    from hsbearing import open_run

    bad = ["--set", "lubricant.oil_flow_rate=0.01 L/min", "--set", "operating.inner_speed=40000 rpm"]
    rc = cli.main(["thermal", "zhang2016", *bad, "-o", str(tmp_path / "t.nc")])  # 720+ W, 0.3 W/K of oil
    err = capsys.readouterr().err.strip().splitlines()
    assert rc == 1 and len(err) == 1
    assert "lubricant.oil_flow_rate" in err[0] and "no thermal equilibrium" in err[0]
    ds = open_run(tmp_path / "t.nc")
    assert ds.attrs["status"] == "no_equilibrium" and "no thermal equilibrium" in ds.attrs["error"]
    assert int(ds.fixed_point_iterations) == ds.sizes["iteration"] >= 1
    assert abs(float(ds.heat_balance_error)) < 1e-9  # the last network solved is a balanced network
    assert np.all(np.diff(ds.iteration_lubricant_temperature.values) > 0)  # it was climbing
    rc = cli.main(["run", "zhang2016", "--thermal", *bad, "--duration", "1ms", "-o", str(tmp_path / "r.nc")])
    err = capsys.readouterr().err.strip().splitlines()
    assert rc == 2 and len(err) == 1 and "no thermal equilibrium" in err[0]
    assert not (tmp_path / "r.nc").exists()


def test_no_equilibrium_point_of_a_thermal_sweep(tmp_path):
    """In a sweep over the oil flow the runaway point keeps its archive and its status; the others are ok."""
    import hsbearing

    ds = hsbearing.sweep(hsbearing.load_case("zhang2016", inner_speed="40000 rpm"), {"oil_flow_rate": "0.01,1L/min"},
                         out_dir=tmp_path, kind="thermal", jobs=1, progress=False)
    assert list(ds["status"].values) == ["no_equilibrium", "ok"]
    assert "no thermal equilibrium" in str(ds["error"].values[0])
    assert (tmp_path / str(ds["archive"].values[0])).exists()


def test_summary_notes_a_shaft_beyond_the_correlation_range(zhang_archive):
    """The rotating-cylinder correlation holds for Re < 4.3e5 (Incropera & DeWitt); zhang2016's shaft is at 7.3e4
    (no note), TP-2275's at 72 000 r/min at 5.1e5 (docs/thermal.md "Review", 3): the summary says so."""
    from hsbearing import open_run
    from hsbearing.systems.angular_contact.thermal import thermal_lines

    ds = open_run(zhang_archive[1])
    assert float(ds.attrs["network_Re_shaft"]) == pytest.approx(1466.08 * 0.03**2 / 1.8e-5, rel=1e-3)
    assert not any("correlation's range" in line for line in thermal_lines(ds))
    ds.attrs["network_Re_shaft"] = 5.1e5
    assert any("beyond the rotating-cylinder correlation's range" in line for line in thermal_lines(ds))
