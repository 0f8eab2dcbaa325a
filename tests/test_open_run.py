"""``hsbearing.open_run`` refuses, with one CaseError naming the file, anything that is not an hsbearing archive;
``hsbearing plot`` keeps its own message for such a file, and says so when an archive is ours but has no figure."""

from __future__ import annotations

import netCDF4
import numpy as np
import pytest
import xarray as xr

from hsbearing import cli, load_case, open_run
from hsbearing.case import CaseError
from hsbearing.results import make_dataset, standard_attrs, write_netcdf


def _ours(path, **attrs):
    case = load_case()
    ds = make_dataset({"cage_speed": np.array([600.0, 601.0])}, coords={"time": np.array([0.0, 1e-3])},
                      attrs=standard_attrs(case, status="ok", **attrs))
    write_netcdf(ds, path)
    return path


def _not_ours(tmp_path):
    """Files that are not hsbearing archives: an empty netCDF-3 header, a netCDF-4 file of another program,
    a netCDF with our title but no variables, a text file, a directory."""
    empty3 = tmp_path / "empty3.nc"
    netCDF4.Dataset(empty3, "w", format="NETCDF3_CLASSIC").close()
    other = tmp_path / "other.nc"
    xr.Dataset({"t2m": ("x", np.arange(3.0))}, attrs={"title": "ERA5 2 m temperature"}).to_netcdf(other)
    hollow = tmp_path / "hollow.nc"
    xr.Dataset(attrs=standard_attrs(None)).to_netcdf(hollow)
    text = tmp_path / "notes.nc"
    text.write_text("not a netCDF file\n")
    folder = tmp_path / "dir.nc"
    folder.mkdir()
    return [empty3, other, hollow, text, folder, tmp_path / "missing.nc"]


def test_open_run_refuses_what_is_not_an_hsbearing_archive(tmp_path):
    for path in _not_ours(tmp_path):
        with pytest.raises(CaseError) as err:
            open_run(path)
        msg = str(err.value)
        assert str(path) in msg and "\n" not in msg, msg  # one line naming the file
    assert "not an hsbearing archive" in _msg(tmp_path / "empty3.nc")
    assert "not an hsbearing archive" in _msg(tmp_path / "other.nc")
    assert "no variables" in _msg(tmp_path / "hollow.nc")
    assert "not a readable netCDF" in _msg(tmp_path / "notes.nc")


def _msg(path):
    with pytest.raises(CaseError) as err:
        open_run(path)
    return str(err.value)


def test_open_run_reads_our_archives(tmp_path):
    ds = open_run(_ours(tmp_path / "run.nc"))
    assert ds.attrs["hsbearing_version"] and float(ds["cage_speed"][1]) == 601.0


def test_plot_keeps_its_message_for_a_file_that_is_not_ours(tmp_path, capsys):
    empty3 = _not_ours(tmp_path)[0]
    assert cli.main(["plot", str(empty3)]) == 2
    err = capsys.readouterr().err.strip().splitlines()
    assert len(err) == 1 and str(empty3) in err[0] and "not an hsbearing result this command can draw" in err[0]
    assert not empty3.with_suffix(".png").exists()


def test_plot_of_our_archive_without_a_figure_says_so(tmp_path, capsys):
    life = tmp_path / "life.nc"
    assert cli.main(["life", "zhang2016", "-o", str(life)]) == 0
    capsys.readouterr()
    assert cli.main(["plot", str(life)]) == 2
    err = capsys.readouterr().err.strip().splitlines()
    assert len(err) == 1, err
    assert "an hsbearing archive (hsbearing rating life" in err[0] and "has no figure" in err[0]
    assert "hsbearing.open_run" in err[0]  # what to use instead
    assert "not an hsbearing result" not in err[0]
