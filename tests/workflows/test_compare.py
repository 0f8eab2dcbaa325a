"""``hsbearing compare``: every number on the page and in compare.nc is the single run it summarises.

One comparison (oil 4109 and a data-sheet-only lubricant file, quasi-static, thermal equilibrium, lives) is run once
through the CLI in this process (``-j 1 --no-dynamics``); each number is then recomputed by the single-run function a
user would call (``quasi_static_power_loss``, ``quasi_static_contact_state``, ``rating.life``,
``thermal_equilibrium``) and compared.  A 5 ms dynamic comparison checks the dynamic columns against
``simulate`` + the sweep summary of the same case.  The page's files, names and bad input are checked too.
The browser rendering of the page is the slow-tier test_compare_browser.py.
"""

from __future__ import annotations

import math
import re
from pathlib import Path

import numpy as np
import pytest
import xarray as xr

from hsbearing.case import load_case
from hsbearing.cli import main

DATA_SHEET = """\
name = "VG 32 sheet"
viscosity = [["40 degC", "32 mm^2/s"], ["100 degC", "5.4 mm^2/s"]]
density = "0.86 g/cm^3"
"""

RTOL = 1e-10  # the same functions on the same case: equal but for the netCDF round trip (float64: exact)


@pytest.fixture(scope="module")
def compared(tmp_path_factory):
    d = tmp_path_factory.mktemp("compare")
    oil = d / "vg32.toml"
    oil.write_text(DATA_SHEET)
    out = d / "page"
    rc = main(["compare", "zhang2016", "--oils", f"4109,{oil}", "--no-dynamics", "-j", "1", "-q", "-o", str(out)])
    assert rc == 0
    ds = xr.load_dataset(out / "compare.nc")
    return {"dir": out, "ds": ds, "oils": ["4109", str(oil)]}


def _case(oil):
    return load_case("zhang2016", **{"lubricant.oil": oil})


def test_files_and_dimension(compared):
    out, ds = compared["dir"], compared["ds"]
    for name in ("index.html", "compare.md", "compare.nc", "criteria.png", "power_by_source.png"):
        assert (out / name).is_file() and (out / name).stat().st_size > 0, name
    assert "oil" in ds.dims and ds.sizes["oil"] == 2
    assert list(ds["oil"].values) == compared["oils"]
    assert list(ds["oil_name"].values) == ["4109", "VG 32 sheet"]
    for name in ("power_loss", "drive_torque", "power_loss_race_traction", "power_loss_drag", "min_film_thickness",
                 "min_film_parameter", "max_contact_pressure", "modified_rating_life", "basic_rating_life",
                 "inner_ring_temperature", "oil_outlet_temperature", "drag_band_power_loss_low",
                 "drag_band_power_loss_high", "lubricant_name", "lubricant_provenance", "lubricant_notices",
                 "quasistatic_status", "thermal_status", "best_oil", "best_margin"):
        assert name in ds, name
    assert "dynamic_status" not in ds and "classification" not in ds  # --no-dynamics
    for name, v in list(ds.data_vars.items()) + list(ds.coords.items()):
        assert "units" in v.attrs and v.attrs.get("long_name"), name


def test_quasistatic_power_film_pressure_equal_the_single_runs(compared):
    from hsbearing.systems.angular_contact import contact_state
    from hsbearing.systems.angular_contact.quasistatic import solve_case
    from hsbearing.systems.angular_contact.rating import quasi_static_power_loss

    ds = compared["ds"]
    for i, oil in enumerate(compared["oils"]):
        case = _case(oil)
        p = quasi_static_power_loss(case)
        pt = ds.isel(oil=i)
        assert float(pt["power_loss"]) == pytest.approx(p["power_loss"], rel=RTOL)
        assert float(pt["drive_torque"]) == pytest.approx(p["drive_torque"], rel=RTOL)
        for src in ("race_traction", "ehl_rolling", "pocket_film", "guide_land", "drag", "jet_oil_acceleration",
                    "cage_windage"):
            assert float(pt[f"power_loss_{src}"]) == pytest.approx(p[src], rel=RTOL, abs=1e-12), src
        rest = p["power_loss"] - p["drag"]
        assert float(pt["drag_band_power_loss_low"]) == pytest.approx(rest + p["drag_band_low"], rel=RTOL)
        assert float(pt["drag_band_power_loss_high"]) == pytest.approx(rest + p["drag_band_high"], rel=RTOL)
        st = contact_state.quasi_static_contact_state(case, solve_case(case))
        h = min(np.min(st["inner_film_thickness_minimum"]), np.min(st["outer_film_thickness_minimum"]))
        lam = min(np.min(st["inner_film_parameter"]), np.min(st["outer_film_parameter"]))
        pmax = max(np.max(st["inner_contact_pressure"]), np.max(st["outer_contact_pressure"]))
        assert float(pt["min_film_thickness"]) == pytest.approx(h, rel=RTOL)
        assert float(pt["min_film_parameter"]) == pytest.approx(lam, rel=RTOL)
        assert float(pt["max_contact_pressure"]) == pytest.approx(pmax, rel=RTOL)
    # the oils differ where they should: another viscosity and traction law -> another power and film
    assert float(ds["power_loss"][0]) != pytest.approx(float(ds["power_loss"][1]), rel=1e-3)
    assert float(ds["min_film_thickness"][0]) != pytest.approx(float(ds["min_film_thickness"][1]), rel=1e-3)


def test_life_and_thermal_equal_the_single_runs(compared):
    from hsbearing.systems.angular_contact.rating import life
    from hsbearing.systems.angular_contact.thermal import thermal_equilibrium

    ds = compared["ds"]
    for i, oil in enumerate(compared["oils"]):
        case = _case(oil)
        pt = ds.isel(oil=i)
        lf = life(case)
        for name in ("basic_rating_life", "modified_rating_life", "reference_rating_life",
                     "modified_reference_rating_life", "viscosity_ratio", "life_modification_factor"):
            assert float(pt[name]) == pytest.approx(float(lf[name]), rel=RTOL), name
        th = thermal_equilibrium(case)
        for name in ("inner_ring_temperature", "outer_ring_temperature", "ball_temperature", "cage_temperature",
                     "oil_outlet_temperature", "heat_generated", "heat_removed_by_oil"):
            assert float(pt[name]) == pytest.approx(float(th[name]), rel=RTOL), name
        assert str(pt["thermal_status"].values) == "ok"


def test_best_oil_per_criterion_is_the_ranking_of_the_numbers(compared):
    ds = compared["ds"]
    names = list(ds["oil_name"].values)
    for i, crit in enumerate(ds["criterion"].values):
        var, better = str(ds["criterion_variable"].values[i]), str(ds["criterion_better"].values[i])
        v = np.asarray(ds[var].values, dtype=float)
        score = v if better == "lower" else -v if better == "higher" else np.abs(v)
        k = int(np.argmin(score))
        assert str(ds["best_oil"].values[i]) == names[k], crit
        assert float(ds["best_value"].values[i]) == v[k]
        assert float(ds["best_margin"].values[i]) == pytest.approx(abs(v[1 - k] - v[k]), rel=1e-12)
        assert str(ds["runner_up_oil"].values[i]) == names[1 - k]
    # the drag band: every oil at the same end of it, the ranking read at both ends
    j = list(ds["criterion"].values).index("power_loss")
    lo = np.asarray(ds["drag_band_power_loss_low"].values, float)
    assert str(ds["best_oil_band_low"].values[j]) == names[int(np.argmin(lo))]
    assert float(ds["best_margin_band_low"].values[j]) == pytest.approx(abs(lo[1] - lo[0]), rel=1e-12)


def test_best_of_handles_missing_values_and_signs():
    from hsbearing.workflows.compare import best_of

    r = best_of([3.0, float("nan"), 1.0], ["a", "b", "c"], "lower")
    assert (r["best"], r["runner_up"], r["margin"]) == ("c", "a", 2.0)
    r = best_of([-0.02, 0.01, 0.03], ["a", "b", "c"], "abs_lower")  # cage slip: closest to zero wins
    assert (r["best"], r["runner_up"]) == ("b", "a") and r["margin"] == pytest.approx(0.01)
    r = best_of([1.0, 5.0], ["a", "b"], "higher")
    assert (r["best"], r["margin"], r["relative_margin"]) == ("b", 4.0, 0.8)
    r = best_of([float("nan"), 2.0], ["a", "b"], "lower")
    assert r["best"] == "b" and r["runner_up"] == "" and math.isnan(r["margin"])


def test_page_names_each_oil_its_provenance_and_numbers(compared):
    from hsbearing.display import format_quantity

    out, ds = compared["dir"], compared["ds"]
    md = (out / "compare.md").read_text()
    page = (out / "index.html").read_text()
    for text in (md, page):
        assert "VG 32 sheet" in text and "4109" in text
        assert "no [traction] table" in text  # the data-sheet file's notice
        assert "recommended law" in text  # its provenance
        assert "Zhang et al. 2016 Table 1" in text  # the built-in oil's
        for i in range(2):  # the numbers as printed equal the archive's
            assert format_quantity(float(ds["power_loss"][i]), "W", "power_loss") in text
            assert format_quantity(float(ds["min_film_parameter"][i]), "1", "min_film_parameter") in text
    assert "Best oil per criterion" in md and "| power loss at the quasi-static state |" in md


def test_page_is_self_contained(compared):
    """Every image of index.html is a PNG file beside it (relative path); no network resource, no script."""
    out = compared["dir"]
    page = (out / "index.html").read_text()
    srcs = re.findall(r"<img[^>]*\ssrc='([^']+)'", page)
    assert len(srcs) >= 3
    for s in srcs:
        assert "/" not in s and (out / s).read_bytes()[:8] == b"\x89PNG\r\n\x1a\n", s
    assert "://" not in page and "<script" not in page.lower() and "<link" not in page.lower()


def test_bad_input_exit_2_nothing_written(tmp_path, capsys):
    cases = [
        (["--oils", "4109,nosuch"], "not a valid case"),
        (["--oils", "4109,4109"], "given twice"),
        (["--oils", "4109,4106", "--vary", "oil=4050"], "--oils"),
        (["--oils", "4109,4106", "--no-dynamics", "--duration", "5ms"], "--no-dynamics"),
        (["--oils", "4109,missing_oil.toml"], "missing_oil.toml"),
    ]
    for i, (argv, words) in enumerate(cases):
        out = tmp_path / f"out{i}"
        rc = main(["compare", "zhang2016", *argv, "-q", "-o", str(out)])
        err = capsys.readouterr().err.strip().splitlines()
        assert rc == 2, argv
        assert len(err) == 1 and err[0].startswith("hsbearing: error:") and words in err[0], (argv, err)
        assert not out.exists(), argv


def test_dynamic_columns_equal_the_single_run(tmp_path):
    """A 5 ms dynamic comparison: the class, slip, whirl and power of each oil equal ``simulate`` of the same case
    (stop rule on, as compare runs it) summarised by the sweep's own summary."""
    import hsbearing
    from hsbearing.workflows.sweeps.points import dynamic_summary

    ds = hsbearing.compare("zhang2016", ["4109", "4050"], out_dir=tmp_path / "dyn", duration="5 ms", jobs=1,
                           figures=False)
    assert ds.attrs["status"] == "ok", ds.attrs["status"]
    for i, oil in enumerate(["4109", "4050"]):
        case = load_case("zhang2016", **{"lubricant.oil": oil, "simulation.stop": "converged"})
        s = dynamic_summary(hsbearing.simulate(case, duration=0.005))
        pt = ds.isel(oil=i)
        assert str(pt["classification"].values) == s["classification"]
        for ours, theirs in (("mean_cage_slip_ratio", "mean_cage_slip_ratio"), ("whirl_amplitude", "whirl_amplitude"),
                             ("dynamic_power_loss", "power_loss"), ("dynamic_drive_torque", "drive_torque")):
            assert float(pt[ours]) == pytest.approx(s[theirs], rel=1e-9, abs=1e-15), ours
        assert str(pt["dynamic_status"].values) == "ok"
    assert "dynamic run of at most 0.005 s" in ds.attrs["compare_dynamics"]
    assert not (Path(tmp_path / "dyn") / "criteria.png").exists()  # figures=False
    assert (Path(tmp_path / "dyn") / "index.html").is_file()


def test_vary_and_thermal_skipped_without_oil_flow(tmp_path):
    """Every oil at each value of a varied key; a case without an oil flow skips the thermal equilibrium and says why."""
    import hsbearing
    from hsbearing.systems.angular_contact.rating import quasi_static_power_loss

    text = (Path(hsbearing.__file__).parent / "cases" / "zhang2016.toml").read_text()
    text = "\n".join(line for line in text.splitlines() if not line.startswith("oil_flow_rate"))
    case_file = tmp_path / "no_flow.toml"
    case_file.write_text(text)
    out = tmp_path / "vary"
    ds = hsbearing.compare(str(case_file), "4109,4106", vary={"axial_load": "500,1000N"}, out_dir=out,
                           dynamics=False, jobs=1)
    assert dict(ds["power_loss"].sizes) == {"oil": 2, "axial_load": 2}
    assert "lubricant.oil_flow_rate" in ds.attrs["thermal_skipped"]
    assert "thermal_status" not in ds and "inner_ring_temperature" not in ds
    assert ds["best_oil"].dims == ("criterion", "axial_load")
    case = load_case(str(case_file), **{"lubricant.oil": "4106", "operating.axial_load": "500 N"})
    assert float(ds["power_loss"].sel(oil="4106", axial_load=500.0)) == pytest.approx(
        quasi_static_power_loss(case)["power_loss"], rel=RTOL)
    md = (out / "compare.md").read_text()
    assert md.count("## Best oil per criterion (axial_load = ") == 2
    assert "thermal equilibrium skipped" in md and "lubricant.oil_flow_rate" in md
    for name in ("criteria.png", "power_by_source.png", "quasistatic.png"):
        assert (out / name).is_file(), name
    assert not (out / "thermal.png").exists()
