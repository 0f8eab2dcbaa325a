"""The bundled seed 004 study (Tables 3-5): definition vs the transcribed tables, and the study
machinery end to end with a synthetic point function (the dynamic model is tested elsewhere)."""

from __future__ import annotations

import csv
import math
from pathlib import Path

import numpy as np
import pytest
import xarray as xr

from hsbearing import study
from hsbearing.case import CaseError
from hsbearing.results import open_run, standard_attrs

DATA = Path(__file__).resolve().parent / "data"

#: the synthetic "model": one fixed label per oil, so the expected agreement is countable from the CSV
FAKE_LABEL = {"4109": "quasi-periodic", "4106": "1 period", "4050": "4 periods"}


def fake_dynamics(case, duration):
    """A synthetic dynamic run: the cage centre on a circle (radius by oil), constant cage speed,
    scalar summaries and the classification already set (so the test does not depend on the classifier)."""
    n = 600
    dur = duration or 0.01
    t = np.linspace(0.0, dur, n)
    wc = 6000.0  # rad/s: ~10 cage revolutions in 10 ms, so the Poincare panels have points
    r = {"4109": 30e-6, "4106": 20e-6, "4050": 10e-6}[case.lubricant.oil]
    Z = case.bearing.ball_count
    q = case.operating.axial_load / (Z * math.sin(case.bearing.contact_angle))
    slip = 0.01 + 1e-5 * (case.lubricant.temperature - 273.15) + 2e-6 * case.operating.axial_load \
        + 1e-7 * case.operating.radial_load + {"4109": 0.0, "4106": 0.002, "4050": 0.004}[case.lubricant.oil]
    ds = xr.Dataset(
        {
            "cage_speed": ("time", np.full(n, wc)),
            "cage_center_y": ("time", r * np.cos(wc * t)),
            "cage_center_z": ("time", r * np.sin(wc * t)),
            "inner_contact_load": (("time", "ball"), np.full((n, Z), q)),
            "outer_contact_load": (("time", "ball"), np.full((n, Z), 1.1 * q)),
            "mean_cage_slip_ratio": ((), slip),
            "whirl_amplitude": ((), r),
        },
        coords={"time": t, "ball": np.arange(Z)},
        attrs=standard_attrs(case, status="ok", classification=FAKE_LABEL[case.lubricant.oil],
                             classification_confidence=0.9),
    )
    return ds


def _csv_rows():
    with open(DATA / "seed004_periods.csv") as fh:
        return list(csv.DictReader(line for line in fh if not line.startswith("#")))


def test_study_definition_matches_seed_tables():
    s = study.load_study("zhang2016")
    rows = _csv_rows()
    assert len(rows) == 39
    key_col = {"lubricant.temperature": ("temperature_degC", " degC"), "operating.axial_load": ("axial_force_N", " N"),
               "operating.radial_load": ("radial_force_N", " N")}
    n = 0
    for t in s.tables:
        col, unit = key_col[t["vary"]]
        for row in (r for r in rows if f"table{r['table']}" == t["id"]):
            i = t["values"].index(row[col] + unit)
            assert study.normalise_label(t["paper"][row["oil"]][i]) == study.normalise_label(row["response"]), (t["id"], row)
            n += 1
        # the fixed conditions of the table are those of the CSV rows
        for k, v in t["set"].items():
            colk = {"operating.axial_load": "axial_force_N", "operating.radial_load": "radial_force_N",
                    "lubricant.temperature": "temperature_degC"}[k]
            assert {r[colk] for r in rows if f"table{r['table']}" == t["id"]} == {v.split()[0]}
    assert n == 39


@pytest.mark.parametrize("paper, ours", [("Quasi-periodicity", "quasi-periodic"), ("Chaos", "chaos"),
                                         ("1 period", "1 period"), ("4 periods", "4 periods"), ("3 Periods", "3 periods")])
def test_normalise_label(paper, ours):
    assert study.normalise_label(paper) == ours


def test_study_end_to_end_with_synthetic_runs(tmp_path):
    res = study.run_study("zhang2016", tmp_path, jobs=2, duration="10 ms", point_fn=fake_dynamics, progress=False)
    # 39 cells, 36 distinct cases: (130 degC, 1000 N, Fy = 0) is in Tables 3 and 4 for each oil
    assert res["n_unique_points"] == 36 and res["n_computed"] == 36
    assert len(list((tmp_path / "runs").glob("*.nc"))) == 36
    t3, t4, t5 = (res["tables"][k] for k in ("table3", "table4", "table5"))
    assert t3["status"].dims == ("oil", "temperature") and t3.sizes == {"oil": 3, "temperature": 4}
    assert t4.sizes == {"oil": 3, "axial_load": 6} and t5.sizes == {"oil": 3, "radial_load": 3}
    np.testing.assert_allclose(t3["temperature"].values - 273.15, [27, 80, 130, 180])
    assert t3["archive"].sel(oil="4109", temperature=403.15).item() == t4["archive"].sel(oil="4109", axial_load=1000.0).item()
    # the summary went through hsbearing.analysis.summary: slip ratio from the runs, labels from attrs
    expect = 0.01 + 1e-5 * 130 + 2e-6 * 3000 + 0.002
    assert t4["mean_cage_slip_ratio"].sel(oil="4106", axial_load=3000.0).item() == pytest.approx(expect, rel=1e-12)
    assert list(t5["classification"].sel(oil="4050").values) == ["4 periods"] * 3
    assert t5["paper_classification"].sel(oil="4106").values.tolist() == ["1 period", "quasi-periodic", "chaos"]
    disk = open_run(tmp_path / "table4.nc")
    assert disk.attrs["study_table"] == "table4" and disk["archive"].values[0, 0].startswith("runs/")

    text = (tmp_path / "report.md").read_text()
    assert "Not the dynamic model" in text and "test_study.fake_dynamics" in text
    # agreement count, computed independently from the CSV
    agree = sum(study.normalise_label(r["response"]) == FAKE_LABEL[r["oil"]] for r in _csv_rows())
    assert f"**{agree} of 39** cells that completed and were classified; 0 completed cells are *undetermined*" in text
    assert "0 of 39 cells did not complete" in text
    for t in ("Table 3", "Table 4", "Table 5"):
        assert t in text
    assert "| 27 degC | 1 period | quasi-periodic (x) | 1 period | 1 period (=) | 4 periods | 4 periods (=) |" in text
    assert "wall time of the whole study" in text
    figs = sorted(p.name for p in (tmp_path / "figures").glob("*.png"))
    assert figs == sorted([f"fig{i:02d}.png" for i in range(5, 13)] + ["slip_table3.png", "slip_table4.png", "slip_table5.png"])
    for name in figs:
        assert f"figures/{name}" in text

    # resume: a second invocation computes nothing and writes the same tables
    again = study.run_study("zhang2016", tmp_path, jobs=1, duration="10 ms", point_fn=fake_dynamics, progress=False,
                            tables=["table5"])
    assert again["n_computed"] == 0
    xr.testing.assert_equal(again["tables"]["table5"]["mean_cage_slip_ratio"], t5["mean_cage_slip_ratio"])


def test_study_subset_and_failure_reporting(tmp_path):
    res = study.run_study("zhang2016", tmp_path, jobs=1, duration="5 ms", point_fn=failing_dynamics,
                          progress=False, tables=["table5"])
    assert list(res["tables"]) == ["table5"]
    t5 = res["tables"]["table5"]
    assert (t5["status"].sel(radial_load=1000.0) == "failed").all()
    text = (tmp_path / "report.md").read_text()
    assert "## Points that did not complete" in text and "did not converge" in text
    assert "(failed)" in text
    assert "**6 of 6**" not in text  # failed cells are not counted as agreement


def failing_dynamics(case, duration):
    from hsbearing.errors import SolverError

    ds = fake_dynamics(case, duration)
    if case.operating.radial_load >= 1000.0:
        raise SolverError("did not converge (test)", partial=ds.isel(time=slice(0, 50)))
    return ds


def test_study_bad_input(tmp_path):
    from hsbearing import cli

    assert cli.main(["study", "nosuch", "-o", str(tmp_path / "x")]) == 2
    bad = tmp_path / "bad.toml"
    bad.write_text('[study]\ncase = "zhang2016"\noils = ["4109"]\n[[table]]\nid = "t"\nvary = "axial_load"\n'
                   'values = ["1 kN", "2 kN"]\n[table.paper]\n"4109" = ["chaos"]\n')
    with pytest.raises(CaseError, match="1 labels for 2 values"):
        study.load_study(bad)
    with pytest.raises(CaseError, match="no table selected"):
        study.run_study("zhang2016", tmp_path, tables=["table9"], progress=False)


@pytest.mark.slow
def test_study_on_dask_equals_local(tmp_path):
    import distributed  # a hard dependency (dask[distributed]): missing is an error, not a skip
    local = study.run_study("zhang2016", tmp_path / "local", jobs=1, duration="10 ms", point_fn=fake_dynamics,
                            progress=False, tables=["table5"])
    with distributed.LocalCluster(n_workers=1, threads_per_worker=1, processes=True, host="127.0.0.1",
                                  dashboard_address=None) as cluster:
        remote = study.run_study("zhang2016", tmp_path / "dask", scheduler=cluster.scheduler_address, duration="10 ms",
                                 point_fn=fake_dynamics, progress=False, tables=["table5"])
    a, b = local["tables"]["table5"], remote["tables"]["table5"]
    for v in ("mean_cage_slip_ratio", "classification", "status", "archive", "paper_classification"):
        xr.testing.assert_identical(a[v], b[v])
    assert "execution: dask tcp://127.0.0.1" in (tmp_path / "dask" / "report.md").read_text()
