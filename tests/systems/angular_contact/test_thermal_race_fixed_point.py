"""The thermal network's fixed point with each race's contact losses at that race's own inlet temperature
(docs/thermal.md, "Each race at its own inlet temperature inside the fixed point").

Checked against ground truth:
- with equal race temperatures the per-race iteration is the former one bit for bit (the offset forced to zero: the
  kernel gets (T_lub, T_lub), which is bit-identical to the single-temperature kernel, test_race_temperatures.py);
- the fixed point against an independent solve of the same per-race network (scipy's MINPACK hybrd on the seven
  node temperatures, every source evaluated at the temperatures of the current nodes, from a start 15 K away);
- energy balance of the network, and the heat it balanced per race source equal to the losses that
  ``hsbearing friction --thermal`` reports at the converged temperatures, to the fixed point's tolerance.
"""

import numpy as np
import pytest

from hsbearing.case import load_case
from hsbearing.errors import CaseError
from hsbearing.systems.angular_contact import thermal
from hsbearing.systems.angular_contact.rating import _thermal_row, race_inlet_temperatures
from hsbearing.systems.angular_contact.thermal import (
    NODES,
    bearing_network,
    contact_temperature,
    heat_by_body,
    thermal_equilibrium,
)

RACE = ("race_traction_inner", "race_traction_outer", "ehl_rolling_inner", "ehl_rolling_outer",
        "contact_damping_inner", "contact_damping_outer")


#: the bundled case (nearly isothermal: rings within 0.06 K) and the same bearing in a 20 degC room, where the shaft
#: cools the inner ring 16 K below the outer (docs/thermal.md): the race inlets then differ by 7.8 K
CASES = {"bundled": {}, "room": {"thermal.ambient_temperature": "20 degC"}}


@pytest.fixture(scope="module", params=list(CASES))
def case(request):
    return load_case("zhang2016", **CASES[request.param])


@pytest.fixture(scope="module")
def per_race(case):
    return thermal_equilibrium(case)


@pytest.fixture(scope="module")
def former(case):
    return thermal_equilibrium(case, race_rule="lubricant")


def _nodes(ds) -> dict:
    return dict(zip(ds.node.values, (float(v) for v in ds.node_temperature.values)))


def test_equal_race_temperatures_give_the_former_iteration_bit_for_bit(case, former, monkeypatch):
    """Offset forced to zero (both races at the lubricant temperature through the per-race path): every variable
    of the Dataset equals the former rule's (race_rule="lubricant", which passes no race temperatures to the kernel:
    the former code path) exactly -- same iterations, temperatures, heat."""
    ref = former
    monkeypatch.setattr(thermal, "race_inlet_offset", lambda T: 0.0)
    eq = thermal_equilibrium(case, race_rule="per_race")
    for v in ref.data_vars:
        assert np.array_equal(ref[v].values, eq[v].values), v
    assert int(eq.fixed_point_iterations) == int(ref.fixed_point_iterations)
    assert ref.attrs["race_temperature_rule"].startswith("lubricant")


def test_converged_state_is_consistent_and_balanced(case, per_race, former):
    """Energy balance of the network; the race inlet temperatures the last iteration used are (T_ring + T_b)/2 of the
    converged network within the tolerance; the heat the network balanced, source by source and per race, equals
    the losses evaluated at the converged temperatures (what friction --thermal reports) to the tolerance's effect."""
    ds, tol = per_race, case.thermal.tolerance
    assert ds.attrs["status"] == "ok" and ds.attrs["converged"] == 1
    assert ds.attrs["race_temperature_rule"].startswith("per_race")
    assert abs(float(ds.heat_balance_error)) < 1e-12
    assert float(ds.attrs["network_residual_W"]) < 1e-9 * float(ds.heat_generated)
    assert float(np.sum(ds.node_heat_input.values)) == pytest.approx(float(ds.heat_generated), rel=1e-14)
    T = _nodes(ds)
    Ti, To = race_inlet_temperatures(T["inner_ring"], T["outer_ring"], T["balls"])
    assert abs(float(ds.inner_race_inlet_temperature) - Ti) < tol
    assert abs(float(ds.outer_race_inlet_temperature) - To) < tol
    assert abs(float(ds.lubricant_temperature) - contact_temperature(T)) < tol
    # the losses at the converged temperatures, per race and source (the kernel's columns, as heat_by_body splits them)
    c = case.with_overrides(**{"lubricant.temperature": f"{float(ds.lubricant_temperature)!r} K"})
    src, heat, _ = heat_by_body(c, walls=T, race_temperatures=(Ti, To))
    for s in RACE + ("pocket_film", "guide_land", "drag"):
        # a race source moves ~0.1 W/K at most here (docs/power_loss.md); 2 tolerances of temperature -> 2e-3 W
        assert float(ds[f"thermal_power_loss_{s}"]) == pytest.approx(src[s], abs=2e-3, rel=0), s
    np.testing.assert_allclose(ds.node_heat_input.values, [heat[n] for n in NODES], atol=2e-3, rtol=0)
    # what hsbearing friction --thermal reports (its own thermal equilibrium, the same function)
    row = _thermal_row(case, case.operating.inner_speed)
    assert row["thermal"]["inner_contact"] == pytest.approx(Ti, abs=1e-12)
    assert row["race_traction"] == pytest.approx(src["race_traction_inner"] + src["race_traction_outer"], rel=1e-12)
    assert row["ehl_rolling"] == pytest.approx(src["ehl_rolling_inner"] + src["ehl_rolling_outer"], rel=1e-12)
    net_race = sum(float(ds[f"thermal_power_loss_{s}"]) for s in RACE)
    assert row["race_traction"] + row["ehl_rolling"] + row["contact_damping"] == pytest.approx(net_race, abs=2e-3, rel=0)
    if abs(Ti - To) > 1.0:  # the former rule balanced other heat than it reported (0.26 W at the room's inner EHL rolling)
        T0 = _nodes(former)
        c0 = case.with_overrides(**{"lubricant.temperature": f"{float(former.lubricant_temperature)!r} K"})
        src0, _, _ = heat_by_body(c0, walls=T0, race_temperatures=race_inlet_temperatures(
            T0["inner_ring"], T0["outer_ring"], T0["balls"]))
        assert max(abs(float(former[f"thermal_power_loss_{s}"]) - src0[s]) for s in RACE) > 0.1


@pytest.mark.parametrize("start", [15.0, pytest.param(-20.0, marks=pytest.mark.slow)])
def test_fixed_point_against_an_independent_solve(case, per_race, former, start):
    """The per-race network as one system of seven equations (the heat balance of every node, every source
    evaluated at the lubricant, race-inlet and wall temperatures of the current nodes) solved by MINPACK's hybrd
    (scipy.optimize.fsolve; not the package's damped Newton nor its relaxed fixed point) from every node 15 K
    above or 20 K below the converged state: the node temperatures agree within the fixed point's tolerance
    (measured 2.2e-5 K in both cases).  In the room the former rule's fixed point is 0.030 K away from this
    solution: the check tells the two apart."""
    from scipy.optimize import fsolve

    T_in = case.lubricant.temperature
    calls = []

    def residual(x):
        T = dict(zip(NODES, (float(v) for v in x)))
        T_lub = contact_temperature(T)
        races = race_inlet_temperatures(T["inner_ring"], T["outer_ring"], T["balls"])
        c = case.with_overrides(**{"lubricant.temperature": f"{T_lub!r} K"})
        _, heat, qs = heat_by_body(c, walls=T, race_temperatures=races)
        net, _ = bearing_network(c, heat, qs, T_in)
        calls.append(1)
        return net.residual(x) / max(sum(heat.values()), 1e-3)

    x_ref = per_race.node_temperature.values
    x, info, ier, msg = fsolve(residual, x_ref + start, full_output=True, xtol=1e-10)
    assert ier == 1, msg
    assert np.max(np.abs(residual(x))) < 1e-9
    np.testing.assert_allclose(x, x_ref, atol=case.thermal.tolerance, rtol=0)
    if case.thermal.ambient_temperature < 300.0:
        assert np.max(np.abs(x - former.node_temperature.values)) > 2.0 * case.thermal.tolerance


def test_a_non_converging_case_keeps_its_status_and_message():
    """thermal.max_iterations too small: status not_converged (not an error), friction --thermal refuses with its
    one message naming the keys, as before."""
    case = load_case("zhang2016")
    c = case.with_overrides(**{"thermal.max_iterations": "1"})
    ds = thermal_equilibrium(c)
    assert ds.attrs["status"] == "not_converged" and ds.attrs["converged"] == 0
    assert int(ds.fixed_point_iterations) == 1 and ds.sizes["iteration"] == 1
    with pytest.raises(CaseError, match="thermal.max_iterations, thermal.tolerance"):
        _thermal_row(c, c.operating.inner_speed)
    with pytest.raises(ValueError, match="race_rule"):
        thermal_equilibrium(case, race_rule="mean")


def test_a_race_inlet_beyond_the_oil_range_is_no_equilibrium(monkeypatch):
    """A race inlet temperature that leaves the oil's range while the lubricant temperature is still inside it is
    the same answer as the lubricant leaving it (thermal runaway at this oil flow), not an exception: status
    no_equilibrium, the last network solved kept, the message names the race inlet and the oil flow."""
    monkeypatch.setattr(thermal, "race_inlet_offset", lambda T: 300.0)  # an inner inlet 300 K above T_lub
    ds = thermal_equilibrium(load_case("zhang2016"))
    assert ds.attrs["status"] == "no_equilibrium" and ds.attrs["converged"] == 0
    assert "inner race inlet temperature" in ds.attrs["error"] and "lubricant.oil_flow_rate" in ds.attrs["error"]
    assert int(ds.fixed_point_iterations) == ds.sizes["iteration"] == 1
    assert abs(float(ds.heat_balance_error)) < 1e-12
