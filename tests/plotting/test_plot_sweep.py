"""The sweep / study summary figure (``hsbearing.plotting.plot_sweep``, ``hsbearing plot DIR/sweep.nc``).

Summary Datasets are built with the real layout: ``hsbearing.workflows.sweeps.plan_sweep`` + ``assemble`` with
synthetic point records (nothing is computed), so the dims, coordinates, ``<key>_label`` and attrs are
those of ``DIR/sweep.nc``.  One end-to-end check runs a 2-point quasi-static sweep through the CLI.
The numbers in the records are made up: these tests check what the figure shows, not the physics.
"""

from __future__ import annotations

import numpy as np
import pytest
import xarray as xr
from PIL import Image

from hsbearing import plotting, systems
from hsbearing.case import CaseError
from hsbearing.cli import main
from hsbearing.results import open_run, write_netcdf
from hsbearing.workflows import sweeps


def _summary(vary, summaries, *, kind="run", case="zhang2016", statuses=None, zip=False, attrs=None):
    """A sweep Dataset as assembled by hsbearing.workflows.sweeps from the given per-point summaries (point order = product order)."""
    plan = sweeps.plan_sweep(case, vary, kind=kind, duration=0.1 if kind == "run" else None, zip=zip)
    assert len(plan.points) == len(summaries)
    recs = []
    for i, summ in enumerate(summaries):
        st = statuses[i] if statuses else "ok"
        recs.append({"status": st, "error": "" if st == "ok" else f"SolverError: synthetic failure {i}",
                     "summary": dict(summ) if st in ("ok", "failed") else {}, "wall_time": 0.1,
                     "archive": f"p{i}.nc" if st != "invalid" else ""})
    return sweeps.assemble(plan, recs, attrs=attrs)


def _dyn(i, label="1 period"):
    return {"classification": label, "classification_confidence": 0.8, "mean_cage_slip_ratio": 0.01 * (i + 1),
            "whirl_amplitude": 20e-6 + 1e-6 * i, "whirl_frequency_ratio": 0.5 + 0.01 * i,
            "mean_inner_contact_load": 100.0 + 50 * i, "max_inner_contact_load": 120.0 + 50 * i,
            "mean_outer_contact_load": 110.0 + 50 * i, "max_outer_contact_load": 130.0 + 50 * i}


def _png_text(path) -> dict:
    with Image.open(path) as im:
        return dict(im.text)


def _check_png(path):
    assert path.exists() and path.stat().st_size > 10_000
    with Image.open(path) as im:
        assert im.format == "PNG" and im.size[0] > 600 and im.size[1] > 400
        px = np.asarray(im.convert("L"), dtype=float)
    assert px.std() > 10  # not a blank canvas


def test_one_key_dynamic_with_a_failed_point(tmp_path):
    labels = ["1 period", "4 periods", "quasi-periodic", "chaos", "undetermined"]
    summ = [_dyn(i, lab) for i, lab in enumerate(labels)]
    st = ["ok", "ok", "failed", "ok", "ok"]
    ds = _summary({"axial_load": "100,500,1000,2000,3000N"}, summ, statuses=st)
    lay = plotting.sweep_layout(ds)
    assert lay["x_dim"] == "axial_load" and lay["series_dims"] == [] and lay["n_series"] == 1
    assert lay["x"] == [100.0, 500.0, 1000.0, 2000.0, 3000.0] and lay["x_title"] == "operating.axial_load [N]"
    assert lay["panels"] == ["mean cage slip ratio", "cage whirl radius", "whirl frequency / cage speed",
                             "inner race contact load $Q_i$", "outer race contact load $Q_o$"]
    assert not lay["map"]  # one varied key: the classes are the marker styles, no map
    # the failed point is counted and named, and its (partial) class is not counted with the good ones
    assert lay["not_ok"] == 1 and lay["not_ok_points"] == ["1000 N: failed"]
    assert lay["classes"] == {"1 period": 1, "k periods": 1, "chaos": 1, "undetermined": 1}
    png = plotting.plot_sweep(ds, tmp_path / "sweep.png")
    _check_png(png)
    text = _png_text(png)
    assert "points=5 not_ok=1" in text["Description"]
    assert text["Comment"] == "not ok: 1000 N: failed"
    assert "4 of 5 points ok" in text["Title"]


def test_two_keys_with_classes_draw_the_class_map_and_lines_per_oil(tmp_path):
    vary = {"oil": "4109,4106", "temperature": "27,80,130degC"}
    labels = ["quasi-periodic", "3 periods", "chaos", "1 period", "1 period", "undetermined"]
    ds = _summary(vary, [_dyn(i, lab) for i, lab in enumerate(labels)])
    # the study tables carry the paper's label of every cell
    ds["paper_classification"] = (ds["status"].dims, np.array([["1 period", "3 periods", "quasi-periodic"],
                                                                ["1 period", "1 period", "1 period"]], dtype=object))
    lay = plotting.sweep_layout(ds)
    # x = the numeric key (temperature, in the unit it was written in), one line per oil
    assert lay["x_dim"] == "temperature" and lay["series_dims"] == ["oil"] and lay["n_series"] == 2
    assert lay["x"] == [27.0, 80.0, 130.0] and lay["x_title"] == "lubricant.temperature [\N{DEGREE SIGN}C]"
    assert lay["x_labels"] == ["27 \N{DEGREE SIGN}C", "80 \N{DEGREE SIGN}C", "130 \N{DEGREE SIGN}C"]
    assert lay["map"]
    png = plotting.plot_sweep(ds, tmp_path / "t.png")
    _check_png(png)
    # classified cells (not "undetermined"): 5; same label as the paper: 3 periods and 1 period, 1 period -> 3
    assert "paper_agreement=3/5" in _png_text(png)["Description"]


def test_quasistatic_two_keys_no_classification(tmp_path):
    vary = {"axial_load": "250,500,1000N", "inner_speed": "6000,14000rpm"}
    summ = []
    for fa in (250.0, 500.0, 1000.0):
        for n in (6000.0, 14000.0):
            q = fa / 11 / np.sin(0.44)
            summ.append({"mean_inner_contact_load": q, "max_inner_contact_load": q, "mean_outer_contact_load": 1.1 * q,
                         "max_outer_contact_load": 1.1 * q, "cage_speed": 0.41 * n * 2 * np.pi / 60,
                         "inner_ring_axial_displacement": 1e-6 * fa ** (2 / 3)})
    ds = _summary(vary, summ, kind="quasistatic")
    lay = plotting.sweep_layout(ds)
    assert lay["x_dim"] == "axial_load" and lay["series_dims"] == ["inner_speed"]
    assert not lay["map"] and lay["classes"] == {}
    assert lay["panels"] == ["inner race contact load $Q_i$", "outer race contact load $Q_o$", "cage speed",
                             "inner ring axial displacement"]
    _check_png(plotting.plot_sweep(ds, tmp_path / "q.png"))


def test_gyro_summary_draws_the_friction_moments_first(tmp_path):
    summ = [{"sfmc": 7.3e-6, "sfmo": 6.0e-6, "sfmo_stderr": 0.4e-6, "rfmc": 2.7e-6},
            {"sfmc": 9.8e-6, "sfmo": float("nan"), "sfmo_stderr": float("nan"), "rfmc": 2.7e-6}]
    ds = _summary({"cage.thickness": "0.15,0.30mm"}, summ, case="jiang2014_gyro")
    lay = plotting.sweep_layout(ds)
    assert lay["panels"] == ["friction moments (Jiang et al. 2014)"]  # no dynamics fields in a gyro summary: nothing else
    assert lay["x"] == [0.15, 0.30] and lay["x_title"] == "cage.thickness [mm]"
    png = plotting.plot_sweep(ds, tmp_path / "g.png")
    _check_png(png)
    # the SI values would be 1.5e-4 m: the axis is in the unit of the labels
    assert "panels=1" in _png_text(png)["Description"]


def test_invalid_and_all_failed_points_are_shown_not_dropped(tmp_path):
    ds = _summary({"axial_load": "500,1000N"}, [_dyn(0), _dyn(1)], statuses=["invalid", "crashed"])
    lay = plotting.sweep_layout(ds)
    assert lay["not_ok"] == 2 and lay["panels"] == [] and lay["classes"] == {}
    png = plotting.plot_sweep(ds, tmp_path / "bad.png")
    assert png.stat().st_size > 10_000
    assert _png_text(png)["Comment"] == "not ok: 500 N: invalid; 1000 N: crashed"


def test_summary_failed_point_is_marked(tmp_path):
    ds = _summary({"axial_load": "500,1000,2000N"}, [_dyn(0), _dyn(1), _dyn(2)])
    ds["error"][1] = "summary failed: ValueError: synthetic"
    lay = plotting.sweep_layout(ds)
    assert lay["not_ok"] == 0 and lay["no_summary"] == 1 and lay["not_ok_points"] == ["1000 N: summary failed"]
    plotting.plot_sweep(ds, tmp_path / "s.png")


def test_three_keys_lines_per_combination_or_a_clear_refusal(tmp_path):
    vary = {"oil": "4109,4106", "temperature": "27,130degC", "axial_load": "500,1000,2000N"}
    ds = _summary(vary, [_dyn(i % 5) for i in range(12)])
    lay = plotting.sweep_layout(ds)
    # x = the numeric key with the most values; every combination of the others is one line (2 x 2 = 4)
    assert lay["x_dim"] == "axial_load" and lay["series_dims"] == ["oil", "temperature"] and lay["n_series"] == 4
    assert lay["map"]
    _check_png(plotting.plot_sweep(ds, tmp_path / "three.png"))
    # more lines than MAX_SERIES: one-line CaseError, from the library and from the CLI (exit 2, no figure)
    big = _summary({"oil": "4109,4106,4050", "temperature": "27,80,130,180degC", "axial_load": "500,1000,2000,3000,6000N"},
                   [_dyn(i % 5) for i in range(60)])
    with pytest.raises(CaseError, match="12 lines per panel over oil, temperature are too many"):
        plotting.plot_sweep(big, tmp_path / "big.png")
    assert not (tmp_path / "big.png").exists()
    write_netcdf(big, tmp_path / "big" / "sweep.nc")
    rc = main(["plot", str(tmp_path / "big" / "sweep.nc")])
    assert rc == 2
    assert not (tmp_path / "big" / "sweep.png").exists()


def test_three_keys_cli_message_names_the_file(tmp_path, capsys):
    big = _summary({"oil": "4109,4106,4050", "temperature": "27,80,130,180degC", "axial_load": "500,1000,2000,3000N"},
                   [_dyn(0) for _ in range(48)])
    path = tmp_path / "sweep.nc"
    write_netcdf(big, path)
    assert main(["plot", str(path)]) == 2
    err = capsys.readouterr().err.strip().splitlines()
    assert len(err) == 1 and err[0].startswith(f"hsbearing: error: {path}: ") and "too many" in err[0]


def test_zipped_sweep_and_mixed_units(tmp_path):
    ds = _summary({"axial_load": ["500 N", "1 kN"], "inner_speed": ["6000 rpm", "10000 rpm"]},
                  [_dyn(0), _dyn(1)], zip=True)
    lay = plotting.sweep_layout(ds)
    assert lay["x_dim"] == "point" and lay["x_labels"] == ["500 N, 6000 r/min", "1 kN, 10000 r/min"]
    _check_png(plotting.plot_sweep(ds, tmp_path / "z.png"))
    # mixed units in the labels ("500 N", "1 kN"): the SI coordinate in the display unit of its kind
    ds = _summary({"axial_load": ["500 N", "1 kN"]}, [_dyn(0), _dyn(1)])
    lay = plotting.sweep_layout(ds)
    assert lay["x"] == [500.0, 1000.0] and lay["x_title"] == "operating.axial_load [N]"
    ds = _summary({"inner_speed": ["6000 rpm", "1000 rad/s"]}, [_dyn(0), _dyn(1)])
    assert plotting.sweep_layout(ds)["x"] == pytest.approx([6000.0, 1000.0 * 60 / (2 * np.pi)])
    lay = plotting.sweep_layout(_summary({"temperature": ["27 degC", "400 K"]}, [_dyn(0), _dyn(1)]))
    assert lay["x"] == pytest.approx([27.0, 400 - 273.15]) and lay["x_title"] == "lubricant.temperature [\N{DEGREE SIGN}C]"
    # a plain number (no unit): the value itself, the key as the axis title
    lay = plotting.sweep_layout(_summary({"inner_conformity": [0.51, 0.52, 0.54]}, [_dyn(i) for i in range(3)]))
    assert lay["x"] == [0.51, 0.52, 0.54] and lay["x_title"] == "bearing.inner_conformity"


def test_plot_run_dispatches_a_summary(tmp_path):
    ds = _summary({"axial_load": "500,1000N"}, [_dyn(0), _dyn(1)])
    assert plotting.is_sweep_summary(ds)
    png = systems.plot_run(ds, tmp_path / "r.png")
    assert "hsbearing sweep figure" in _png_text(png)["Description"]
    # a summary whose attrs were lost (e.g. a slice saved with plain xarray) is still recognised by its shape
    bare = ds.copy()
    bare.attrs = {}
    assert plotting.is_sweep_summary(bare)
    # ... and a single result is not (quasi-static dataset: per-ball variables, no status variable)
    qs = xr.Dataset({"inner_contact_load": ("ball", np.ones(11))}, attrs={"status": "ok"})
    assert not plotting.is_sweep_summary(qs)


def test_quasistatic_sweep_cli_end_to_end(tmp_path, capsys):
    out = tmp_path / "sw"
    rc = main(["sweep", "zhang2016", "--kind", "quasistatic", "--vary", "operating.axial_load=500,1000N",
               "-o", str(out), "-j", "1"])
    printed = capsys.readouterr().out
    assert rc == 0
    assert f"figure: {out / 'sweep.png'}" in printed  # written next to sweep.nc by default
    _check_png(out / "sweep.png")
    lay = plotting.sweep_layout(open_run(out / "sweep.nc"))
    assert lay["x"] == [500.0, 1000.0] and lay["not_ok"] == 0
    assert "cage speed" in lay["panels"] and "inner race contact load $Q_i$" in lay["panels"]
    (out / "sweep.png").unlink()
    assert main(["plot", str(out / "sweep.nc"), "-o", str(tmp_path / "fig.png")]) == 0
    assert capsys.readouterr().out.strip() == f"figure: {tmp_path / 'fig.png'}"
    _check_png(tmp_path / "fig.png")
    # --no-figure: the resumed sweep draws nothing
    assert main(["sweep", "zhang2016", "--kind", "quasistatic", "--vary", "operating.axial_load=500,1000N",
                 "-o", str(out), "-j", "1", "--no-figure"]) == 0
    assert not (out / "sweep.png").exists()


def test_study_cli_writes_one_figure_per_table(tmp_path, monkeypatch, capsys):
    from hsbearing.workflows import study

    real = study.run_study

    def one_table(name, out_dir, **kw):  # the CLI with a synthetic model and one table (seconds, not minutes)
        from study_fakes import fake_dynamics  # tests/helpers (conftest.py)

        kw.update(point_fn=fake_dynamics, tables=["table3"], duration="5 ms", progress=False)
        return real(name, out_dir, **kw)

    monkeypatch.setattr(study, "run_study", one_table)
    assert main(["study", "zhang2016", "-o", str(tmp_path), "-j", "1"]) == 0
    assert f"figure: {tmp_path / 'table3.png'}" in capsys.readouterr().out
    _check_png(tmp_path / "table3.png")
    assert not (tmp_path / "table4.png").exists()  # table4 was not run
    text = _png_text(tmp_path / "table3.png")["Description"]
    assert "map=1" in text and "paper_agreement=" in text


def test_sweep_cli_with_an_invalid_point_still_draws_the_figure(tmp_path, capsys):
    out = tmp_path / "kg"
    rc = main(["sweep", "zhang2016", "--kind", "quasistatic", "--vary", "inner_conformity=0.52,0.49", "--keep-going",
               "-o", str(out), "-j", "1"])
    assert rc == 1  # a point is not ok
    assert f"figure: {out / 'sweep.png'}" in capsys.readouterr().out
    text = _png_text(out / "sweep.png")
    assert "points=2 not_ok=1" in text["Description"]
    assert text["Comment"] == "not ok: 0.49: invalid"


def test_dense_two_key_grid_uses_a_colour_bar_and_a_compact_class_map(tmp_path):
    # 14 loads x 13 speeds: the lines are the values of one numeric key -> ordered colours and a colour bar
    loads = ",".join(str(100 * (i + 1)) for i in range(14)) + "N"
    speeds = ",".join(str(1000 * (i + 2)) for i in range(13)) + "rpm"
    labels = ["1 period", "3 periods", "quasi-periodic", "chaos", "undetermined"]
    ds = _summary({"axial_load": loads, "inner_speed": speeds}, [_dyn(i % 7, labels[i % 5]) for i in range(14 * 13)],
                  statuses=["failed" if i == 20 else "ok" for i in range(14 * 13)])
    lay = plotting.sweep_layout(ds)
    assert lay["x_dim"] == "axial_load" and lay["n_series"] == 13 and lay["colorbar"] and lay["map"]
    assert lay["not_ok_points"] == ["200 N, 9000 r/min: failed"]  # point 20 in product order: load 2, speed 8
    png = plotting.plot_sweep(ds, tmp_path / "dense.png")
    _check_png(png)
    assert "points=182 not_ok=1" in _png_text(png)["Description"]
    # beyond MAX_ORDERED_SERIES lines even ordered colours are refused
    n = plotting.MAX_ORDERED_SERIES + 1  # (the sweep layout built by hand: planning ~1000 cases is slow)
    big = xr.Dataset({"status": (("axial_load", "inner_speed"), np.full((n + 1, n), "ok", dtype=object)),
                      "mean_cage_slip_ratio": (("axial_load", "inner_speed"), np.zeros((n + 1, n)))},
                     coords={"axial_load": np.arange(1.0, n + 2), "inner_speed": np.arange(1.0, n + 1)},
                     attrs={"title": "hsbearing sweep"})
    with pytest.raises(CaseError, match=f"{n} lines per panel over inner_speed are too many"):
        plotting.sweep_layout(big)
    plotting.sweep_layout(big.isel(inner_speed=slice(0, n - 1)))  # at the limit: drawn


def _red_crosses(ax):
    """x data of the not-ok markers drawn in a panel (red 'x' scatter collections)."""
    from matplotlib.colors import to_rgba

    red = to_rgba(plotting.NOT_OK_STYLE[1])
    xs = []
    for c in ax.collections:
        fc = c.get_facecolor()
        if len(fc) and np.allclose(fc[0], red) and len(c.get_offsets()):
            xs.extend(np.asarray(c.get_offsets())[:, 0].tolist())
    return sorted(xs)


def test_the_figure_draws_the_failed_point_and_breaks_its_line():
    summ = [_dyn(i) for i in range(4)]
    ds = _summary({"axial_load": "500,1000,2000,3000N"}, summ, statuses=["ok", "failed", "ok", "ok"])
    fig, meta = plotting.sweep_figure(ds)
    panels = [ax for ax in fig.axes if ax.get_title() in plotting.sweep_layout(ds)["panels"]]
    assert len(panels) == 5
    for ax in panels:
        assert _red_crosses(ax) == [1000.0]  # the failed point, at its x, in every panel
        assert ax.get_xlim()[0] < 500 and ax.get_xlim()[1] > 3000
    slip = next(ax for ax in panels if ax.get_title() == "mean cage slip ratio")
    (line,) = slip.get_lines()
    y = np.asarray(line.get_ydata(), float)
    # the failed point's (partial) value is not drawn and the line is broken there, not bridged
    assert np.isnan(y[1]) and y[[0, 2, 3]] == pytest.approx([1.0, 3.0, 4.0])
    assert slip.get_ylabel() == "slip ratio [%]"
    # the status is written next to the cross in the first panel
    assert "failed" in [t.get_text() for t in slip.texts]
    assert "not_ok=1" in meta["Description"]


def test_the_class_map_cells_and_the_paper_check_marks():
    vary = {"oil": "4109,4106", "axial_load": "500,1000N"}
    ds = _summary(vary, [_dyn(0, "1 period"), _dyn(1, "chaos"), _dyn(2, "quasi-periodic"), _dyn(3)],
                  statuses=["ok", "ok", "ok", "crashed"])
    ds["paper_classification"] = (ds["status"].dims, np.array([["1 period", "quasi-periodic"],
                                                                ["quasi-periodic", "1 period"]], dtype=object))
    fig, meta = plotting.sweep_figure(ds)
    cmap = next(ax for ax in fig.axes if ax.get_title().startswith("cage motion"))
    texts = sorted(t.get_text() for t in cmap.texts)
    assert texts == sorted(["1 period (0.80)\npaper: 1 period \u2713", "chaos (0.80)\npaper: quasi-periodic",
                            "quasi-periodic (0.80)\npaper: quasi-periodic \u2713", "not ok: crashed\npaper: 1 period"])
    assert "same label as the paper in 2 of 3 classified cells" in cmap.get_title()
    assert "paper_agreement=2/3" in meta["Description"]
    assert [t.get_text() for t in cmap.get_yticklabels()] == ["oil 4106", "oil 4109"]  # first oil on top


def test_slip_panel_shows_raceway_control_beside_nominal():
    """Issue 27: the sweep figure showed the slip against the nominal contact angle only (-10.6 % at 100 N reads
    as an overspeed); the raceway-control slip is drawn beside it, as `run` prints it."""
    summ = [dict(_dyn(i), mean_cage_slip_ratio=-0.106 + 0.05 * i, mean_cage_slip_ratio_raceway_control=0.01 * i)
            for i in range(3)]
    ds = _summary({"axial_load": "100,500,1000N"}, summ)
    prep = plotting.sweep._prepare_sweep(ds)
    title, unit, items = prep["panels"][0]
    assert title == "mean cage slip ratio"
    assert [it[0] for it in items] == ["mean_cage_slip_ratio", "mean_cage_slip_ratio_raceway_control"]
    np.testing.assert_allclose(items[0][3].ravel(), [-10.6, -5.6, -0.6])


def test_gyro_sweep_title_names_no_varied_key_as_fixed_and_no_unused_oil():
    """Issue 27: the gyro sweep title named the varied outer-ring speed as fixed and an oil the model does not use,
    and was clipped (now wrapped)."""
    summ = [{"sfmc": 2e-6 + 1e-7 * i, "rfmc": 1e-6} for i in range(2)]
    ds = _summary({"operating.outer_speed": "2,5rpm"}, summ, case="jiang2014_gyro")
    prep = plotting.sweep._prepare_sweep(ds)
    from hsbearing.plotting.sweep import _sweep_title

    title = _sweep_title(ds, prep)
    fixed = title.split("fixed: ", 1)[1] if "fixed: " in title else ""
    assert "outer ring" not in fixed and "oil" not in title.lower(), title
    assert all(len(line) <= 110 for line in title.splitlines()), title
