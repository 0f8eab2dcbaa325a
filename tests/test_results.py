"""Output registry and atomic netCDF archives."""

import os

import numpy as np
import pytest
import xarray as xr

from hsbearing import load_case, open_run
from hsbearing.results import make_dataset, register, solver_attrs, standard_attrs, write_netcdf


def _dataset():
    case = load_case()
    t = np.linspace(0, 1e-3, 11)
    rng = np.random.default_rng(1)
    data = {
        "inner_contact_load": rng.random((11, 11)) * 500,
        "cage_speed": rng.random(11) * 600,
        "cage_center_y": rng.random(11) * 1e-5,
    }
    attrs = standard_attrs(case, status="ok", model="test") | solver_attrs({"steps": 12, "rhs_evals": 40, "wall_time": 0.5})
    return make_dataset(data, coords={"time": t, "ball": np.arange(11)}, attrs=attrs)


def test_attrs_from_registry():
    ds = _dataset()
    assert ds["inner_contact_load"].dims == ("time", "ball")
    assert ds["inner_contact_load"].attrs["units"] == "N"
    assert ds["time"].attrs["units"] == "s"
    assert ds.attrs["hsbearing_version"]
    assert "[bearing]" in ds.attrs["case_toml"]
    assert ds.attrs["solver_steps"] == 12


def test_quasi_static_shape_drops_time():
    ds = make_dataset({"inner_contact_load": np.ones(11)}, coords={"ball": np.arange(11)})
    assert ds["inner_contact_load"].dims == ("ball",)


def test_unregistered_and_conflicting():
    with pytest.raises(KeyError):
        make_dataset({"not_a_variable": np.ones(3)})
    register("test_only_var", ("time",), "m", "a test variable")
    register("test_only_var", ("time",), "m", "a test variable")  # identical: fine
    with pytest.raises(ValueError):
        register("test_only_var", ("time",), "s", "a test variable")


def test_round_trip_exact(tmp_path):
    ds = _dataset()
    path = write_netcdf(ds, tmp_path / "sub" / "run.nc")
    back = open_run(path)
    xr.testing.assert_identical(ds, back)
    assert [p.name for p in path.parent.iterdir()] == ["run.nc"]
    umask = os.umask(0)
    os.umask(umask)
    assert os.stat(path).st_mode & 0o777 == 0o666 & ~umask


def test_atomic_write_leaves_no_partial_file(tmp_path, monkeypatch):
    ds = _dataset()
    target = tmp_path / "run.nc"

    def boom(self, *a, **k):
        raise RuntimeError("disk full")

    monkeypatch.setattr(xr.Dataset, "to_netcdf", boom)
    from hsbearing.errors import OutputWriteError

    with pytest.raises(OutputWriteError, match="disk full"):  # issue 27: the failed write is reported as such
        write_netcdf(ds, target, fallback=False)
    assert list(tmp_path.iterdir()) == []


def test_existing_archive_replaced_atomically(tmp_path):
    ds = _dataset()
    target = tmp_path / "run.nc"
    write_netcdf(ds, target)
    ino = os.stat(target).st_ino
    ds2 = ds.assign(cage_speed=ds.cage_speed * 2)
    write_netcdf(ds2, target)
    assert os.stat(target).st_ino != ino  # a new file renamed over the old one
    np.testing.assert_array_equal(open_run(target).cage_speed.values, ds2.cage_speed.values)
