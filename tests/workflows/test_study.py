"""The bundled Zhang et al. 2016 study (Tables 3-5): definition vs the transcribed tables, and the study
machinery end to end with a synthetic point function (the dynamic model is tested elsewhere)."""

from __future__ import annotations

import csv
import math
import re
from pathlib import Path

import numpy as np
import pytest
import xarray as xr

from hsbearing.case import CaseError
from hsbearing.results import open_run
from hsbearing.workflows import study

DATA = Path(__file__).resolve().parents[1] / "data"

#: the synthetic "model": one fixed label per oil, so the expected agreement is countable from the CSV
from study_fakes import FAKE_LABEL, fake_dynamics  # noqa: E402,F401 - helpers (conftest puts them on sys.path)


def _csv_rows():
    with open(DATA / "zhang2016_periods.csv") as fh:
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


@pytest.mark.slow  # long: default tier kept under ~10 min (docs/testing.md)
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
    assert "Not the dynamic model" in text and "study_fakes.fake_dynamics" in text
    # agreement count, computed independently from the CSV
    agree = sum(study.normalise_label(r["response"]) == FAKE_LABEL[r["oil"]] for r in _csv_rows())
    assert f"**{agree} of 39** cells that completed and were classified; 0 completed cells are *undetermined*" in text
    assert "0 of 39 cells did not complete" in text
    for t in ("Table 3", "Table 4", "Table 5"):
        assert t in text
    assert "| 27 degC | 1 period | quasi-periodic (x) | 1 period | 1 period (=) | 4 periods | 4 periods (=) |" in text
    assert "wall time of the whole study" in text
    figs = sorted(p.name for p in (tmp_path / "figures").glob("*.png"))
    assert figs == sorted([f"fig{i:02d}.png" for i in range(5, 13)] + ["slip_table3.png", "slip_table4.png", "slip_table5.png"]
                          + ["cells_table3.png", "cells_table4.png", "cells_table5.png"])  # every cell, per table
    assert "## Table 6: recommended working condition per oil" in text
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


# ----------------------------------------------------------------------------- bands

#: REGRESSION (not validation): the band samples of the bundled study as first drawn (seed 16).  The banded
#: study's point archives are named by these values; if this changes, a banded study on disk is no longer
#: reused -- change it only on purpose.
ZHANG_BAND_LHS1 = {"bearing.outer_land_diameter": "52.3094 mm", "cage.guide_land_width": "1.1495 mm",
                   "cage.pocket_diameter": "9.8057 mm"}


def test_band_samples_deterministic_in_range_and_nominal_first():
    s = study.load_study("zhang2016")
    a, b = study.band_samples(s), study.band_samples(s)
    assert a == b  # fixed seed: the same samples every time
    bands = s.bands
    assert bands["method"] == "lhs" and bands["include_nominal"] is True
    assert len(a) == bands["samples"] + 1
    nom = a[0]
    assert nom.label == "nominal" and nom.overrides == {}  # the nominal case exactly: its archives are reused
    base = study.load_case("zhang2016")
    assert nom.values["bearing.outer_land_diameter"] == base.bearing.outer_land_diameter
    assert nom.values["cage.pocket_diameter"] == base.cage.pocket_diameter
    assert nom.values["cage.guide_land_width"] == pytest.approx(1.827e-3, abs=1e-6)  # the geometric default
    lhs = a[1:]
    n = len(lhs)
    for key, (lo_s, hi_s) in bands["keys"].items():
        lo, hi = (study.parse_quantity(v, "length") for v in (lo_s, hi_s))
        vals = np.array([smp.values[key] for smp in lhs])
        assert ((vals >= lo) & (vals <= hi)).all(), key
        # Latin hypercube: exactly one sample in each of the n equal strata of the range
        strata = np.floor((vals - lo) / (hi - lo) * n).astype(int)
        assert sorted(strata) == list(range(n)), (key, strata)
        # the override string is the value (0.1 um resolution)
        for smp in lhs:
            assert study.parse_quantity(smp.overrides[key], "length") == pytest.approx(smp.values[key], abs=1e-12)
    assert lhs[0].overrides == ZHANG_BAND_LHS1
    # every sample is a valid case for every table (lands fit beside the groove): run_study checks it first
    for t in s.tables:
        for smp in a:
            study.load_case("zhang2016", **t.get("set", {}), **smp.overrides)


def test_latin_hypercube_strata_and_seed():
    u = study.latin_hypercube(7, 3, seed=1)
    assert u.shape == (7, 3) and ((u >= 0) & (u < 1)).all()
    for j in range(3):
        assert sorted(np.floor(u[:, j] * 7).astype(int)) == list(range(7))
    np.testing.assert_array_equal(u, study.latin_hypercube(7, 3, seed=1))
    assert not np.array_equal(u, study.latin_hypercube(7, 3, seed=2))


def test_band_cell_stats_fractions_majority_occurrence():
    ok, bad = "ok", "failed"
    st = study.band_cell_stats(["1 period", "Chaos", "1 period", "quasi-periodic", "1 period", "chaos"],
                               [ok, ok, ok, ok, ok, bad], [0.8, 0.5, 0.6, 0.9, 0.7, 0.1],
                               ["still cage", "", "synchronous whirl", "", "still cage", ""], paper="1 period")
    assert st["n"] == 6 and st["n_ok"] == 5 and st["n_failed"] == 1  # the failed sample is left out
    assert st["fractions"] == {"1 period": pytest.approx(0.6), "chaos": pytest.approx(0.2),
                               "quasi-periodic": pytest.approx(0.2)}
    assert st["subfractions"]["1 period"] == {"still cage": pytest.approx(0.4), "synchronous whirl": pytest.approx(0.2)}
    assert st["majority"] == "1 period" and not st["tie"]
    assert st["agrees"] and st["occurs"] and not st["agrees_tied"]
    assert st["confidence"] == pytest.approx(0.7)  # mean over the three "1 period" samples
    # the paper's class occurs but is not the majority
    st = study.band_cell_stats(["chaos", "chaos", "4 periods"], [ok] * 3, paper="4 periods")
    assert st["majority"] == "chaos" and not st["agrees"] and st["occurs"]
    # a tie: not counted as agreement, reported as tied
    st = study.band_cell_stats(["chaos", "4 periods"], [ok] * 2, [0.4, 0.6], paper="Chaos")
    assert st["majority"] == "4 periods / chaos" and st["tie"] and not st["agrees"] and st["agrees_tied"]
    assert st["confidence"] == pytest.approx(0.5)
    # "undetermined" is an outcome: it can be the majority, then the cell does not agree
    st = study.band_cell_stats(["undetermined", "undetermined", "1 period"], [ok] * 3, paper="1 period")
    assert st["majority"] == "undetermined" and not st["agrees"] and st["occurs"]
    # the paper's class never appears; nothing completed
    st = study.band_cell_stats(["chaos"], [ok], paper="1 period")
    assert not st["occurs"] and not st["agrees"]
    st = study.band_cell_stats(["", ""], [bad, bad], paper="1 period")
    assert st["n_ok"] == 0 and st["majority"] == "-" and st["fractions"] == {} and not st["occurs"]


def banded_fake_dynamics(case, duration):
    """The synthetic run of :func:`fake_dynamics`, but chaotic when the guide clearance exceeds 0.2 mm, so
    the class depends on the band sample (the counts below are computed from that rule)."""
    ds = fake_dynamics(case, duration)
    if case.bearing.outer_land_diameter > 52.4e-3 + 1e-9:
        ds.attrs["classification"] = "chaos"
        ds.attrs["classification_confidence"] = 0.4
    return ds


def _mini_study(tmp_path, samples=2, include_nominal=True, extra=""):
    p = tmp_path / "mini.toml"
    p.write_text(f"""
[study]
name = "mini"
case = "zhang2016"
oils = ["4109", "4106"]
duration = "3 ms"

[bands]
method = "lhs"
seed = 3
samples = {samples}
include_nominal = {'true' if include_nominal else 'false'}
{extra}
[bands.keys]
"bearing.outer_land_diameter" = ["52.2 mm", "52.6 mm"]
"cage.guide_land_width" = ["1.0 mm", "1.7 mm"]
"cage.pocket_diameter" = ["9.575 mm", "9.825 mm"]

[[table]]
id = "t5"
title = "Table 5 (two cells)"
set = {{ "lubricant.temperature" = "130 degC", "operating.axial_load" = "1000 N" }}
vary = "operating.radial_load"
values = ["100 N"]

[table.paper]
"4109" = ["quasi-periodic"]
"4106" = ["chaos"]
""")
    return p


def test_banded_study_reuses_nominal_resumes_and_aggregates(tmp_path):
    src = _mini_study(tmp_path)
    out = tmp_path / "out"
    nominal = study.run_study(src, out, jobs=1, point_fn=banded_fake_dynamics, progress=False)
    assert nominal["n_computed"] == 2
    res = study.run_study(src, out, jobs=1, point_fn=banded_fake_dynamics, progress=False, bands=True)
    # 2 cells x (nominal + 2 samples) = 6 points; the 2 nominal ones come from the nominal study's archives
    assert res["n_unique_points"] == 6 and res["n_computed"] == 4
    assert len(list((out / "runs").glob("*.nc"))) == 6
    ds = res["tables"]["t5"]
    assert ds["status"].dims == ("sample", "oil", "radial_load") and ds.sizes["sample"] == 3
    assert list(ds["sample_label"].values) == ["nominal", "lhs1", "lhs2"]
    assert (ds["archive"].isel(sample=0).values == nominal["tables"]["t5"]["archive"].values).all()
    samples = res["samples"]
    np.testing.assert_allclose(ds["band_outer_land_diameter"].values,
                               [smp.values["bearing.outer_land_diameter"] for smp in samples])
    on_disk = open_run(out / "t5_bands.nc")
    assert on_disk["classification"].dims == ("sample", "oil", "radial_load")
    assert (out / "report.md").exists() and (out / "t5.nc").exists()  # the nominal outputs are kept

    # expected aggregation, from the rule of banded_fake_dynamics and the samples' land diameters
    n_chaos = sum(smp.values["bearing.outer_land_diameter"] > 52.4e-3 + 1e-9 for smp in samples)
    assert 0 < n_chaos < 3  # the band straddles the rule (else this test would not test the fractions)
    text = (out / "report_bands.md").read_text()
    assert "Not the dynamic model" in text
    f_chaos = n_chaos / 3
    maj = {"4109": "chaos" if n_chaos > 1.5 else "quasi-periodic", "4106": "chaos" if n_chaos > 1.5 else "1 period"}
    other = {"4109": "quasi-periodic", "4106": "1 period"}
    for oil, paper in (("4109", "quasi-periodic"), ("4106", "chaos")):
        st = study.cell_stats(ds, "radial_load", oil, 0)
        assert st["fractions"]["chaos"] == pytest.approx(f_chaos)
        assert st["fractions"][other[oil]] == pytest.approx(1 - f_chaos)
        assert st["majority"] == maj[oil] and st["occurs"]
        assert st["agrees"] == (maj[oil] == paper)
    n_agree = sum(maj[o] == p for o, p in (("4109", "quasi-periodic"), ("4106", "chaos")))
    assert f"**Majority agreement: {n_agree} of 2 cells; occurrence: 2 of 2.**" in text
    assert "| 100 N | 4106 | chaos | " in text
    assert "wall time of the banded study" in text and "4000-run map on a 16-core cluster" in text
    nominal_wall = float(re.search(r"wall time of the whole study \(this invocation\): ([0-9.]+) s",
                                   (out / "report.md").read_text()).group(1))
    whole = float(re.search(r"whole study = nominal \+ banded invocations: ([0-9.]+) s", text).group(1))
    banded_wall = float(re.search(r"wall time of the banded study \(this invocation\): ([0-9.]+) s", text).group(1))
    assert whole == pytest.approx(nominal_wall + banded_wall, abs=0.11)  # printed to 0.1 s
    walls = np.unique(ds["wall_time"].values.ravel())
    mean_w = float(re.search(r"mean per point ([0-9.e+-]+) s", text).group(1))
    assert mean_w == pytest.approx(np.mean(ds["wall_time"].values), rel=0.01)  # 6 distinct points, 3 sig. digits
    assert len(walls) == 6
    assert "[LEAD: to be filled from the results]" in text
    for png in ("cells_bands_t5.png", "slip_bands_t5.png"):
        assert (out / "figures" / png).stat().st_size > 1000 and f"figures/{png}" in text

    # resumption: nothing is recomputed, the same table is written
    again = study.run_study(src, out, jobs=1, point_fn=banded_fake_dynamics, progress=False, bands=True)
    assert again["n_computed"] == 0
    xr.testing.assert_equal(again["tables"]["t5"]["classification"], ds["classification"])


def test_banded_study_bad_input(tmp_path):
    with pytest.raises(CaseError, match="bands.seed"):
        study.load_study(_write(tmp_path, _mini_study(tmp_path).read_text().replace("seed = 3\n", "")))
    with pytest.raises(CaseError, match="not below high"):
        study.load_study(_write(tmp_path, _mini_study(tmp_path).read_text().replace('["52.2 mm", "52.6 mm"]',
                                                                                    '["52.6 mm", "52.2 mm"]')))
    with pytest.raises(CaseError, match="bands.method"):
        study.load_study(_write(tmp_path, _mini_study(tmp_path).read_text().replace('"lhs"', '"grid"')))
    # a sample whose land is wider than the groove leaves: bad input before anything is computed
    wide = _write(tmp_path, _mini_study(tmp_path).read_text().replace('["1.0 mm", "1.7 mm"]', '["1.9 mm", "2.5 mm"]'))
    with pytest.raises(CaseError, match="bands.*sample lhs"):
        study.run_study(wide, tmp_path / "o", jobs=1, point_fn=banded_fake_dynamics, progress=False, bands=True)
    assert not (tmp_path / "o" / "runs").exists() or not list((tmp_path / "o" / "runs").glob("*.nc"))
    with pytest.raises(CaseError, match="no \\[bands\\] table"):
        study.run_study(_write(tmp_path, _mini_study(tmp_path).read_text().split("[bands]")[0]
                               + "[[table]]" + _mini_study(tmp_path).read_text().split("[[table]]")[1]),
                        tmp_path / "o2", jobs=1, point_fn=banded_fake_dynamics, progress=False, bands=True)


def _write(tmp_path, text, name="variant.toml"):
    p = tmp_path / name
    p.write_text(text)
    return p


def test_study_cli_bands_flag(tmp_path, capsys):
    from hsbearing import cli

    parser = cli.build_parser()
    assert parser.parse_args(["study", "zhang2016", "-o", "x"]).bands is False  # default: nominal only
    assert parser.parse_args(["study", "zhang2016", "-o", "x", "--bands"]).bands is True
    assert parser.parse_args(["study", "zhang2016", "-o", "x", "--no-bands"]).bands is False
    assert parser.parse_args(["study", "zhang2016", "-o", "x", "--table", "table3", "--table", "table5"]).tables == [
        "table3", "table5"]
    with pytest.raises(SystemExit) as exc:
        parser.parse_args(["study", "zhang2016", "-o", "x", "--bands", "--no-bands"])
    assert exc.value.code == 2
    # --bands on a study without [bands]: exit 2, nothing computed or written
    src = _mini_study(tmp_path).read_text()
    plain = _write(tmp_path, src.split("[bands]")[0] + "[[table]]" + src.split("[[table]]")[1], "plain.toml")
    assert cli.main(["study", str(plain), "-o", str(tmp_path / "o"), "--bands", "-j", "1"]) == 2
    assert "no [bands] table" in capsys.readouterr().err
    assert not list((tmp_path / "o").glob("**/*.nc"))


def test_study_cli_bands_runs_the_banded_study(tmp_path, monkeypatch, capsys):
    """``hsbearing study zhang2016 --bands``: the CLI passes the flag through (synthetic model, Table 5 only)."""
    from hsbearing import cli

    real = study.run_study

    def table5(name, out_dir, **kw):
        kw.update(point_fn=banded_fake_dynamics, tables=["table5"], duration="3 ms", progress=False)
        return real(name, out_dir, **kw)

    monkeypatch.setattr(study, "run_study", table5)
    assert cli.main(["study", "zhang2016", "-o", str(tmp_path), "-j", "1", "--bands"]) == 0
    out = capsys.readouterr().out
    assert "(bands)" in out and f"table: {tmp_path / 'table5_bands.nc'}" in out
    assert "45 distinct points" in out  # 9 cells x (nominal + 4 LHS samples)
    ds = open_run(tmp_path / "table5_bands.nc")
    assert ds.sizes == {"sample": 5, "oil": 3, "radial_load": 3}
    assert "**Majority agreement:" in (tmp_path / "report_bands.md").read_text()
    assert not (tmp_path / "report.md").exists()


def test_table6_transcription_matches_seed():
    s = study.load_study("zhang2016")
    with open(DATA / "zhang2016_table6.csv") as fh:
        rows = list(csv.DictReader(line for line in fh if not line.startswith("#")))
    col = {"table3": "temperature", "table4": "axial_load", "table5": "radial_load"}
    assert {r["oil"] for r in rows} == set(s.spec["table6"]) == set(s.oils)
    for r in rows:
        for tid, c in col.items():
            assert s.spec["table6"][r["oil"]][tid] == r[c].lower(), (r["oil"], tid)


@pytest.mark.parametrize("label, rank", [("1 period", 1), ("4 periods", 4), ("3 Periods", 3), ("Quasi-periodicity", 10),
                                         ("chaos", 11)])
def test_stability_rank_follows_the_papers_criterion(label, rank):
    assert study.stability_rank(label) == rank
    assert math.isnan(study.stability_rank("undetermined")) and math.isnan(study.stability_rank("(failed)"))


def test_derive_table6_by_the_stated_rule():
    spec = {"study": {"oils": ["a", "b", "c"], "case": "zhang2016"},
            "table": [{"id": "t", "vary": "operating.radial_load", "values": ["1 N", "2 N", "3 N"]}],
            "table6": {"a": {"t": "light load"}}}
    st = study.Study("syn", "syn.toml", spec)
    cls = [["1 period", "chaos", "2 periods"], ["1 period", "quasi-periodic", "4 periods"],
           ["chaos", "chaos", "undetermined"]]
    idx = [[0.20, 0.9, 0.5], [0.05, 0.2, 0.1], [0.3, 0.3, 0.0]]
    slip = [[0.01, 0.02, 0.03]] * 3
    dims = ("oil", "radial_load")
    ds = xr.Dataset({"classification": (dims, np.array(cls, dtype=object)),
                     "status": (dims, np.full((3, 3), "ok", dtype=object)),
                     "cage_instability_index": (dims, np.array(idx)),
                     "mean_cage_slip_ratio": (dims, np.array(slip))},
                    coords={"oil": ["a", "b", "c"], "radial_load": [1.0, 2.0, 3.0],
                            "radial_load_label": ("radial_load", np.array(["1 N", "2 N", "3 N"], dtype=object))})
    d = study.derive_table6(st, {"t": ds})
    # 1 N: a and b both "1 period" -> the lower instability index (b); 2 N: quasi-periodic (10) beats chaos (11);
    # 3 N: 2 periods beats 4 periods, undetermined is not ranked
    assert [w for _, w, _ in d["best"]["t"]] == [["b"], ["b"], ["a"]]
    assert d["table"] == {"a": {"t": "heavy load (3 N)"}, "b": {"t": "light load (1 N); medium load (2 N)"},
                          "c": {"t": "-"}}
    # index differences below TABLE6_INDEX_TOL do not count: then the slip ratio decides, then all tied win
    ds["cage_instability_index"][0, 0] = 0.05 + 0.04
    assert study.derive_table6(st, {"t": ds})["best"]["t"][0][1] == ["a", "b"]  # same slip: both recommended
    ds["mean_cage_slip_ratio"][1, 0] = -0.005  # |slip| 0.5 % < 1 %: b
    assert study.derive_table6(st, {"t": ds})["best"]["t"][0][1] == ["b"]
    lines = study.table6_lines(st, {"t": ds})
    assert "| a | light load | heavy load (3 N) |" in lines


def test_band_samples_limit_runs_a_prefix_and_the_rest_resumes(tmp_path):
    src = _mini_study(tmp_path, samples=3)
    out = tmp_path / "out"
    part = study.run_study(src, out, jobs=1, point_fn=banded_fake_dynamics, progress=False, bands=True,
                           band_samples_limit=2)
    assert part["n_computed"] == 4 and part["tables"]["t5"].sizes["sample"] == 2
    assert "Only the first 2 of the 4 band samples were run" in (out / "report_bands.md").read_text()
    full = study.run_study(src, out, jobs=1, point_fn=banded_fake_dynamics, progress=False, bands=True)
    assert full["n_computed"] == 4 and full["n_unique_points"] == 8  # the first two samples were resumed
    assert "Only the first" not in (out / "report_bands.md").read_text()
    with pytest.raises(CaseError, match="--band-samples"):
        study.run_study(src, out, jobs=1, point_fn=banded_fake_dynamics, progress=False, bands=True,
                        band_samples_limit=0)
    from hsbearing import cli

    assert cli.main(["study", str(src), "-o", str(tmp_path / "o3"), "--band-samples", "2"]) == 2  # needs --bands
    assert cli.main(["study", str(src), "-o", str(tmp_path / "o4"), "--table", "t9"]) == 2  # unknown table
    assert not list((tmp_path / "o4").glob("**/*.nc"))


def test_report_only_computes_nothing_and_marks_missing_points(tmp_path):
    src = _mini_study(tmp_path)
    out = tmp_path / "out"
    study.run_study(src, out, jobs=1, point_fn=banded_fake_dynamics, progress=False, bands=True, band_samples_limit=2)
    before = sorted(p.name for p in (out / "runs").iterdir())
    res = study.run_study(src, out, jobs=1, point_fn=banded_fake_dynamics, progress=False, bands=True,
                          report_only=True)
    assert sorted(p.name for p in (out / "runs").iterdir()) == before  # nothing computed or written there
    assert res["n_computed"] == 0 and res["backend"].startswith("report only")
    ds = res["tables"]["t5"]
    assert list(ds["status"].isel(sample=2).values.ravel()) == ["missing", "missing"]
    assert (ds["status"].isel(sample=slice(0, 2)) == "ok").all()
    st = study.cell_stats(ds, "radial_load", "4109", 0)
    assert st["n_ok"] == 2 and st["n"] == 3
    text = (out / "report_bands.md").read_text()
    assert "**Partial report:** 2 table cells x samples have no archive yet" in text
    assert "## Points that did not complete" not in text
    assert "report only: nothing computed" in text and "wall time of the banded study" not in text


def test_orbit_drift_flags_a_spiral_not_a_steady_whirl_or_a_still_cage():
    t = np.linspace(0.0, 1.0, 4001)
    w = 2 * np.pi * 50
    c = 200e-6  # guide clearance
    # a spiral still growing (r from 50 to 150 um over the analysed span): drifting
    r = 50e-6 + 100e-6 * t
    d = study.orbit_drift(t, r * np.cos(w * t), r * np.sin(w * t), 0.0, c)
    assert d["drifting"] and d["change"] == pytest.approx(75e-6, rel=0.05)  # quarter means 62.5 ... 137.5 um
    # a steady whirl on the land with a little noise: not drifting
    rng = np.random.default_rng(0)
    r = 190e-6 + 2e-6 * rng.standard_normal(t.size)
    assert not study.orbit_drift(t, r * np.cos(w * t), r * np.sin(w * t), 0.0, c)["drifting"]
    # a still cage creeping by 1 um (< 1 % of the clearance): not flagged
    y = -2e-6 + 1e-6 * t
    assert not study.orbit_drift(t, y, np.zeros_like(t), 0.0, c)["drifting"]
    # only the analysed span counts: a spiral that settles before t_start is steady
    r = np.where(t < 0.5, 50e-6 + 280e-6 * t, 190e-6)
    assert not study.orbit_drift(t, r * np.cos(w * t), r * np.sin(w * t), 0.5, c)["drifting"]
    # over the whole run it rises, then stays: the last quarters are equal, not a monotone drift
    assert study.orbit_drift(t, r * np.cos(w * t), r * np.sin(w * t), 0.0, c)["drifting"] is False


@pytest.mark.parametrize("extra,progress", [([], True), (["-q"], False)])
def test_study_cli_quiet_turns_the_progress_bar_off(tmp_path, monkeypatch, extra, progress):
    """``hsbearing study ... -q`` (as ``hsbearing map -q``): no progress bar; the run itself is stubbed."""
    from hsbearing.cli.parser import build_parser
    from hsbearing.workflows.study import cli as study_cli

    seen = {}

    def stub(name, out_dir, **kw):
        seen.update(kw)
        raise SystemExit(0)

    args = build_parser().parse_args(["study", "zhang2016", "-o", str(tmp_path / "o"), *extra])
    with pytest.raises(SystemExit):
        study_cli.cli_main(args, run_study=stub)
    assert seen["progress"] is progress
