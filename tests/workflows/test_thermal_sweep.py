"""``hsbearing sweep --kind thermal``: every point is the thermal equilibrium of ``hsbearing thermal`` (docs/sweeps.md).

Checked: each point of the sweep equals the direct ``thermal_equilibrium`` of its case (same temperatures, heat and
power by source); the heat balance closes at every point; temperatures and heat rise with speed at a fixed oil flow
and the outer ring runs cooler with more oil (what the network must do, not numbers of our own); a second run
resumes every point; the summary figure draws the thermal panels; a case that cannot give a network is refused
before anything is computed (one-line error naming the key, exit 2).
"""

from __future__ import annotations

import numpy as np
import pytest

import hsbearing
from hsbearing.case import CaseError, load_case
from hsbearing.results import open_run
from hsbearing.systems.angular_contact.thermal import thermal_equilibrium
from hsbearing.workflows import sweeps


@pytest.fixture(scope="module")
def swept(tmp_path_factory):
    out = tmp_path_factory.mktemp("thermal_sweep")
    vary = {"inner_speed": "8000,14000rpm", "oil_flow_rate": "0.5,2L/min"}
    ds = hsbearing.sweep("zhang2016", vary, out_dir=out, kind="thermal", jobs=1, progress=False)
    return out, ds


def test_each_point_is_the_direct_thermal_equilibrium(swept):
    out, ds = swept
    assert ds.attrs["sweep_kind"] == "thermal"
    assert (ds["status"].values == "ok").all()
    for n in ("8000 rpm", "14000 rpm"):
        for q in ("0.5 L/min", "2 L/min"):
            ref = thermal_equilibrium(load_case("zhang2016", inner_speed=n, oil_flow_rate=q))
            pt = ds.isel(inner_speed=0 if n.startswith("8") else 1, oil_flow_rate=0 if q.startswith("0.5") else 1)
            for name in sweeps.THERMAL_SUMMARY:
                assert pt[name].item() == pytest.approx(float(ref[name]), rel=1e-12, abs=1e-12), name
            for name in (str(v) for v in ref.data_vars if str(v).startswith("thermal_power_loss_")):
                assert pt[name].item() == pytest.approx(float(ref[name]), rel=1e-12, abs=1e-12), name
            arch = open_run(out / pt["archive"].item())  # the point archive is the full network
            np.testing.assert_allclose(arch["node_temperature"].values, ref["node_temperature"].values, rtol=1e-12)


def test_balance_and_physical_trends(swept):
    _, ds = swept
    assert np.abs(ds["heat_balance_error"].values).max() < 1e-3  # issue 29: the balance closes within 0.1 %
    gen = ds["heat_generated"].values
    removed = ds["heat_removed_by_oil"].values + ds["heat_removed_by_conduction"].values
    np.testing.assert_allclose(removed, gen, rtol=1e-3)
    for name in ("heat_generated", "outer_ring_temperature", "ball_temperature", "lubricant_temperature"):
        v = ds[name].values  # dims (inner_speed, oil_flow_rate)
        assert (v[1] > v[0]).all(), f"{name} must rise with speed at a fixed oil flow"
    # more oil at the same inlet temperature carries the heat away with a smaller rise: cooler outer ring
    T_or = ds["outer_ring_temperature"].values
    assert (T_or[:, 1] < T_or[:, 0]).all()


def test_resume_and_figure(swept, tmp_path):
    out, _ = swept
    again = hsbearing.sweep("zhang2016", {"inner_speed": "8000,14000rpm", "oil_flow_rate": "0.5,2L/min"},
                            out_dir=out, kind="thermal", jobs=1, progress=False)
    assert (again["resumed"].values == 1).all()
    from hsbearing.plotting.sweep import sweep_layout

    panels = sweep_layout(again)["panels"]
    for p in ("component temperatures", "lubricant temperature at equilibrium", "heat generated and where it goes"):
        assert p in panels
    png = hsbearing.plotting.plot_sweep(again, tmp_path / "t.png")
    assert png.stat().st_size > 10_000


def test_a_case_without_oil_flow_is_refused_before_compute(tmp_path, capsys):
    text = (hsbearing.case.case_path("zhang2016")).read_text()
    text = "\n".join(line for line in text.splitlines() if not line.startswith("oil_flow_rate"))
    path = tmp_path / "noflow.toml"
    path.write_text(text)
    plan = sweeps.plan_sweep(load_case(path), {"axial_load": "500,1000N"}, kind="thermal")
    assert all(pt.case is None and "lubricant.oil_flow_rate" in pt.error for pt in plan.points)  # recorded invalid
    from hsbearing import cli

    rc = cli.main(["sweep", str(path), "--kind", "thermal", "--vary", "axial_load=500,1000N", "-o", str(tmp_path / "o")])
    err = capsys.readouterr().err.strip().splitlines()
    assert rc == 2 and len(err) == 1 and "lubricant.oil_flow_rate" in err[0] and "noflow.toml" in err[0]
    assert not (tmp_path / "o").exists()


def test_kind_is_checked():
    with pytest.raises(CaseError, match="allowed: run, quasistatic, thermal"):
        sweeps.plan_sweep(load_case("zhang2016"), {"axial_load": "500N"}, kind="heat")
