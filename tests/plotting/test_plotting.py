"""The run figure: dispatch, content of the title, atomic write, `hsbearing plot`."""

from __future__ import annotations

import numpy as np
import pytest
from synthetic_runs import cage_run  # tests/helpers (conftest.py)

import hsbearing
from hsbearing import plotting, systems
from hsbearing.analysis import annotate
from hsbearing.results import make_dataset, standard_attrs, write_netcdf


@pytest.fixture(scope="module")
def case():
    return hsbearing.load_case("zhang2016")


def _png_ok(path):
    import matplotlib.image as mpimg

    img = mpimg.imread(path)
    assert img.ndim == 3 and img.shape[0] > 400 and img.shape[1] > 800
    # not a blank canvas
    assert np.std(img[..., :3]) > 0.05
    return img


def _no_temp_left(directory):
    return not [p for p in directory.iterdir() if p.name.startswith(".")]


def test_dynamic_figure(case, tmp_path):
    ds = annotate(cage_run("k", case, n_rev=40), case)
    out = systems.plot_run(ds, tmp_path / "run.png")
    assert out == tmp_path / "run.png" and out.exists()
    _png_ok(out)
    assert _no_temp_left(tmp_path)


def test_title_names_case_conditions_and_classification(case):
    ds = annotate(cage_run("k", case, n_rev=40), case)
    lines = plotting.title_lines(ds)
    assert "zhang2016" in lines[0] and "oil 4109" in lines[0] and "14000 r/min" in lines[0]
    assert "Fa = 1000 N" in lines[0] and "130 \N{DEGREE SIGN}C" in lines[0]
    assert "4 periods" in lines[1] and "3.00 %" in lines[1]
    over = case.with_overrides(**{"operating.radial_load": "500 N", "lubricant.oil": "4050"})
    ds2 = cage_run("period", over, n_rev=10)
    l2 = plotting.title_lines(annotate(ds2, over))[0]
    assert "Fr = 500 N" in l2 and "oil 4050" in l2


def test_unannotated_run_is_annotated_for_the_figure(case, tmp_path):
    ds = cage_run("quasi", case, n_rev=30)
    assert "classification" not in ds.attrs
    out = systems.plot_run(ds, tmp_path / "a.png")
    _png_ok(out)
    assert "classification" not in ds.attrs  # input untouched


def test_run_without_case_and_failed_status(case, tmp_path):
    ds = cage_run("period", case, n_rev=12)
    ds.attrs = {"status": "failed at t = 0.012 s"}
    assert "status: failed at t = 0.012 s" in " ".join(plotting.title_lines(annotate(ds)))
    _png_ok(systems.plot_run(ds, tmp_path / "b.png"))


def test_too_short_run_still_draws(case, tmp_path):
    ds = cage_run("period", case, n_rev=1, spr=50)
    _png_ok(systems.plot_run(ds, tmp_path / "c.png"))


def test_quasi_static_figure(case, tmp_path):
    ds = make_dataset({"inner_contact_load": np.linspace(300, 350, 11), "outer_contact_load": np.linspace(380, 420, 11),
                       "inner_contact_angle": np.radians(np.full(11, 27.0)), "outer_contact_angle": np.radians(np.full(11, 22.0))},
                      attrs=standard_attrs(case))
    _png_ok(systems.plot_run(ds, tmp_path / "qs.png"))


def test_gyro_dispatch(monkeypatch, tmp_path):
    """A gyro archive is drawn by the gyro system's figure (hsbearing.systems.gyro.figures.plot_gyro)."""
    import hsbearing.systems.gyro.figures as gyro_figures

    calls = []
    monkeypatch.setattr(gyro_figures, "plot_gyro", lambda ds, path: calls.append(path) or path)
    ds = make_dataset({}, attrs={"model": "gyro_ribbon_cage"})
    assert systems.plot_run(ds, tmp_path / "g.png") == tmp_path / "g.png"
    assert calls == [tmp_path / "g.png"]


def test_failed_write_leaves_nothing(case, tmp_path, monkeypatch):
    from matplotlib.figure import Figure

    def boom(self, *a, **k):
        raise OSError("disk full")

    monkeypatch.setattr(Figure, "savefig", boom)
    with pytest.raises(OSError):
        systems.plot_run(annotate(cage_run("period", case, n_rev=10), case), tmp_path / "x.png")
    assert list(tmp_path.iterdir()) == []


def test_cli_plot_redraws_from_archive(case, tmp_path, capsys):
    from hsbearing.cli import main

    nc = write_netcdf(annotate(cage_run("quasi", case, n_rev=30), case), tmp_path / "run.nc")
    assert main(["plot", str(nc)]) == 0
    assert (tmp_path / "run.png").exists()
    _png_ok(tmp_path / "run.png")
    assert main(["plot", str(nc), "-o", str(tmp_path / "other.png")]) == 0
    assert (tmp_path / "other.png").exists()
    # bad input: exit 2, one line, nothing written
    assert main(["plot", str(tmp_path / "missing.nc")]) == 2
    bad = tmp_path / "bad.nc"
    bad.write_text("not netcdf")
    assert main(["plot", str(bad)]) == 2
    assert not (tmp_path / "bad.png").exists()
    err = capsys.readouterr().err.strip().splitlines()
    assert len(err) == 2 and all(line.startswith("hsbearing: error:") for line in err)


# ----------------------------------------------------------------------------- the power figure

def _power_run(case):
    """A synthetic run carrying the power accounting variables (levels chosen, not computed)."""
    from hsbearing.systems.angular_contact.balances import SOURCES

    ds = cage_run("k", case, n_rev=20)
    t = ds["time"].values
    rng = np.random.default_rng(3)
    total = np.zeros(t.size)
    for i, s in enumerate(SOURCES):
        p = (i + 1.0) * (1.0 + 0.2 * np.sin(2e3 * t)) + 0.05 * rng.standard_normal(t.size)
        ds[f"power_loss_{s}"] = ("time", p)
        total += p
    ds["power_loss"] = ("time", total)
    ds["drive_power"] = ("time", total + 0.1)
    ds["drive_torque"] = ("time", (total + 0.1) / 1466.0)
    return ds


def test_power_figure(case, tmp_path):
    from hsbearing.systems.angular_contact import power_figure as plotting_power

    ds = _power_run(case)
    assert plotting_power.has_power(ds) and not plotting_power.has_power(cage_run("k", case, n_rev=5))
    path = plotting_power.power_figure_path(tmp_path / "run.png")
    assert path.name == "run_power.png"
    out = plotting_power.plot_power(ds, path)
    assert out == path
    _png_ok(out)
    assert _no_temp_left(tmp_path)


def test_power_figure_moving_mean_against_convolution():
    """The smoothing of panels (a)-(b): a centred moving mean, checked against numpy's convolution inside."""
    from hsbearing.systems.angular_contact.power_figure import _moving_mean

    t = np.arange(200) * 1e-5
    y = np.random.default_rng(0).standard_normal(200)
    m = _moving_mean(t, y, 10e-5)  # 10 samples
    ref = np.convolve(y, np.ones(10) / 10, mode="valid")  # window [i-5, i+5)
    assert np.allclose(m[5:196], ref[:191])
    assert np.isclose(m[0], y[:5].mean())  # shrinking edge
