"""Sweep summaries carry what users compare (docs/sweeps.md, "What a sweep reports").

Checked: a quasi-static sweep over oil (a bundled oil and a user's data-sheet lubricant file) reports per point the
power loss, its sources and the drive torque, each equal to the independent
:func:`hsbearing.systems.angular_contact.rating.quasi_static_power_loss` of the point's case (the number `hsbearing
friction` prints), the smallest film and lambda and the largest contact pressure equal to the extremes of the
point's own contact state, and the oil by its own name; every variable and coordinate of ``sweep.nc`` has units and
long_name; the printed table and the figure show them (no empty cell, the oils drawn as categories, no line
joining them).  :func:`contact_power_summary` is checked on a synthetic run against numpy reductions written here;
a thermal point carries every node temperature and the heat along every path of the network.
"""

from __future__ import annotations

import io

import numpy as np
import pytest
import xarray as xr
from conftest import DATA

import hsbearing
from hsbearing.analysis.orbit import contact_power_summary
from hsbearing.case import load_case
from hsbearing.results import open_run
from hsbearing.systems.angular_contact.balances import SOURCES

VG32 = str(DATA / "lubricants" / "vg32_data_sheet.toml")


@pytest.fixture(scope="module")
def qs_sweep(tmp_path_factory):
    out = tmp_path_factory.mktemp("qs_oils")
    ds = hsbearing.sweep("zhang2016", {"oil": ["4109", VG32]}, out_dir=out, kind="quasistatic", jobs=1, progress=False)
    return out, ds


def test_power_and_torque_per_point_equal_the_direct_quasi_static_power_loss(qs_sweep):
    from hsbearing.systems.angular_contact.rating import CAVITY_SOURCES, quasi_static_power_loss

    out, ds = qs_sweep
    assert (ds["status"].values == "ok").all()
    for i, oil in enumerate(("4109", VG32)):
        ref = quasi_static_power_loss(load_case("zhang2016", oil=oil))
        pt = ds.isel(oil=i)
        assert pt["power_loss"].item() == pytest.approx(ref["power_loss"], rel=1e-12)
        assert pt["drive_torque"].item() == pytest.approx(ref["drive_torque"], rel=1e-12)
        for s in tuple(SOURCES) + CAVITY_SOURCES:  # the kernel's sources and the quasi-static churning terms
            assert pt[f"power_loss_{s}"].item() == pytest.approx(ref[s], rel=1e-12, abs=1e-15), s
        total = sum(pt[f"power_loss_{s}"].item() for s in tuple(SOURCES) + CAVITY_SOURCES)
        assert pt["power_loss"].item() == pytest.approx(total, rel=1e-12)
    # the two oils differ (viscosity, film): the sweep answers the question it is asked
    assert ds["power_loss"].values[0] != ds["power_loss"].values[1]


def test_film_and_pressure_are_the_extremes_of_the_points_own_contact_state(qs_sweep):
    from hsbearing.systems.angular_contact import contact_state

    out, ds = qs_sweep
    for i, oil in enumerate(("4109", VG32)):
        case = load_case("zhang2016", oil=oil)
        arch = open_run(out / str(ds["archive"].values[i]))
        st = contact_state.quasi_static_contact_state(case, arch)
        h = np.concatenate([st["inner_film_thickness_minimum"], st["outer_film_thickness_minimum"]])
        lam = np.concatenate([st["inner_film_parameter"], st["outer_film_parameter"]])
        p = np.concatenate([arch["inner_contact_pressure"].values, arch["outer_contact_pressure"].values])
        pt = ds.isel(oil=i)
        assert pt["min_film_thickness"].item() == pytest.approx(np.nanmin(h), rel=1e-12)
        assert pt["min_film_parameter"].item() == pytest.approx(np.nanmin(lam), rel=1e-12)
        assert pt["max_contact_pressure"].item() == pytest.approx(np.max(p), rel=1e-12)


def test_sweep_nc_every_variable_has_units_and_long_name_and_names_the_oil(qs_sweep):
    out, ds = qs_sweep
    disk = xr.open_dataset(out / "sweep.nc")
    missing = [str(v) for v in disk.variables if "units" not in disk[v].attrs or "long_name" not in disk[v].attrs]
    assert missing == []
    assert disk["power_loss"].attrs["units"] == "W" and disk["drive_torque"].attrs["units"] == "N*m"
    assert "quasi-static state" in disk["power_loss"].attrs["long_name"]
    assert list(disk["lubricant_name"].values) == ["4109", "VG 32 data sheet"]
    assert "borrowed from oil 4106" in str(disk["lubricant_provenance"].values[1])


def test_printed_table_shows_power_torque_film_pressure_and_the_oils_name(qs_sweep):
    from hsbearing.workflows.sweeps import print_table

    _, ds = qs_sweep
    buf = io.StringIO()
    print_table(ds, file=buf)
    text = buf.getvalue()
    for key in ("power_loss=", "drive_torque=", "min_film_thickness=", "min_film_parameter=", "max_contact_pressure=",
                "power_loss_race_traction=", "power_loss_drag=", "lubricant_name=VG 32 data sheet"):
        assert key in text, key
    assert " W" in text and " N mm" in text and " GPa" in text


def test_figure_draws_the_oils_as_categories_without_empty_cells(qs_sweep):
    from hsbearing.plotting.sweep import sweep_figure, sweep_layout

    _, ds = qs_sweep
    lay = sweep_layout(ds)
    for panel in ("power loss", "power loss by source", "drive torque", "largest contact pressure $p_{max}$"):
        assert panel in lay["panels"], panel
    assert lay["x_labels"] == ["4109", "VG 32 data sheet"]  # each oil by its own name, not the file path
    fig, _ = sweep_figure(ds)
    axes = [a for a in fig.get_axes() if a.get_title()]
    assert len(axes) == len(lay["panels"])  # every axes drawn holds a panel: no empty cell
    for ax in axes:  # categories: markers only, no line joins one oil to the next
        assert not [line for line in ax.get_lines() if len(np.atleast_1d(line.get_xdata())) >= 2
                    and line.get_linestyle() not in ("None", "", " ") and line.get_xydata().shape[0] >= 2
                    and np.isfinite(line.get_xydata()).all()], ax.get_title()


def test_contact_power_summary_of_a_run_against_numpy():
    rng = np.random.default_rng(3)
    nt, nb = 40, 5
    t = np.linspace(0.0, 0.04, nt)
    data = {"power_loss": ("time", rng.uniform(40, 60, nt)), "drive_torque": ("time", rng.uniform(0.002, 0.004, nt)),
            "power_loss_drag": ("time", rng.uniform(20, 25, nt))}
    for side in ("inner", "outer"):
        data[f"{side}_film_thickness_minimum"] = (("time", "ball"), rng.uniform(1e-7, 3e-7, (nt, nb)))
        data[f"{side}_film_parameter"] = (("time", "ball"), rng.uniform(1, 3, (nt, nb)))
        data[f"{side}_contact_pressure"] = (("time", "ball"), rng.uniform(1e9, 2e9, (nt, nb)))
    data["inner_film_parameter"][1][3, 2] = np.nan  # an unloaded contact has no film: ignored
    ds = xr.Dataset(data, coords={"time": t})
    keep = np.arange(nt) >= 12  # after the transient
    out = contact_power_summary(ds, {"time": np.nonzero(keep)[0]})
    assert out["power_loss"] == pytest.approx(np.mean(data["power_loss"][1][keep]), rel=1e-14)
    assert out["drive_torque"] == pytest.approx(np.mean(data["drive_torque"][1][keep]), rel=1e-14)
    assert out["power_loss_drag"] == pytest.approx(np.mean(data["power_loss_drag"][1][keep]), rel=1e-14)
    h = np.concatenate([data["inner_film_thickness_minimum"][1][keep], data["outer_film_thickness_minimum"][1][keep]])
    lam = np.concatenate([data["inner_film_parameter"][1][keep], data["outer_film_parameter"][1][keep]])
    p = np.concatenate([data["inner_contact_pressure"][1][keep], data["outer_contact_pressure"][1][keep]])
    assert out["min_film_thickness"] == np.min(h)
    assert out["min_film_parameter"] == np.nanmin(lam)
    assert out["max_contact_pressure"] == np.max(p)
    assert "power_loss_guide_land" not in out  # a quantity the result does not carry is left out, not NaN


def test_thermal_point_carries_every_node_temperature_and_heat_by_path():
    from hsbearing.systems.angular_contact.thermal import HEAT_PATHS, heat_path_name, thermal_equilibrium
    from hsbearing.workflows.sweeps import thermal_summary

    th = thermal_equilibrium(load_case("zhang2016"))
    s = thermal_summary(th)
    for node in th["node"].values:
        name = "ball_temperature" if node == "balls" else f"{node}_temperature" if node != "oil" else "oil_outlet_temperature"
        assert s[name] == pytest.approx(float(th["node_temperature"].sel(node=node)), abs=1e-9), node
    for (a, b, _), q in zip(HEAT_PATHS, th["link_heat_flow"].values):
        assert s[heat_path_name(a, b)] == float(q)
    # heat by path closes the balance: what the oil carries off + what leaves to the air = the heat generated
    out = s[heat_path_name("oil", "oil_inlet")] + s[heat_path_name("housing", "ambient")] + s[heat_path_name("shaft", "ambient")]
    assert out == pytest.approx(s["heat_generated"], rel=1e-6)
