"""A user's oil is named by its own name everywhere, with where its data come from (docs/traction.md,
"Lubricant files"): the VG 32 data-sheet file of tests/data/lubricants (32 and 5.4 mm^2/s at 40/100 degC,
0.86 g/cm^3, alpha unknown, traction borrowed from 4106) in the headers of ``friction``, ``life`` and ``thermal``,
the run summary and the archives' attributes; one notice line each for the borrowed traction and the estimated
alpha; ``hsbearing oils --template`` writes a commented file that loads; ``hsbearing oils --help`` points to the
format."""

from __future__ import annotations

import tomllib

import pytest
import xarray as xr
from conftest import DATA

from hsbearing import cli, lubricant
from hsbearing.case import load_case

VG32 = str(DATA / "lubricants" / "vg32_data_sheet.toml")
NAME = "VG 32 data sheet"


def _check_named(text: str) -> None:
    assert NAME in text
    assert "oil 4106" not in text.split("notice:")[0].replace("borrowed from oil 4106", "")  # never named as 4106
    notices = [line for line in text.splitlines() if line.startswith("notice:")]
    assert any("borrowed from oil 4106" in n for n in notices), text
    assert any("alpha" in n and "estimated" in n for n in notices), text


def test_friction_names_the_users_oil_and_says_the_traction_is_borrowed(tmp_path, capsys):
    out = tmp_path / "fr.nc"
    assert cli.main(["friction", "zhang2016", "--set", f"oil={VG32}", "-o", str(out)]) == 0
    text = capsys.readouterr().out
    first = text.splitlines()[0]
    assert NAME in first and "4106" not in first and "4109" not in first, first
    _check_named(text)
    attrs = xr.open_dataset(out).attrs
    assert attrs["lubricant_name"] == NAME
    assert "traction borrowed from oil 4106" in attrs["lubricant_provenance"]
    assert "estimated" in attrs["lubricant_notices"]


@pytest.mark.parametrize("command", ["life", "thermal"])
def test_life_and_thermal_name_the_oil(command, tmp_path, capsys):
    out = tmp_path / f"{command}.nc"
    assert cli.main([command, "zhang2016", "--set", f"lubricant.file={VG32}", "-o", str(out)]) == 0
    _check_named(capsys.readouterr().out)
    assert xr.open_dataset(out).attrs["lubricant_name"] == NAME


def test_built_in_oil_keeps_its_number_and_gets_no_notice():
    case = load_case("zhang2016")
    assert lubricant.oil_label(case.lubricant) == "oil 4109"
    assert lubricant.notices(case.lubricant) == []
    assert lubricant.identity_attrs(case)["lubricant_notices"] == "none"
    ns = lubricant.notices(load_case("zhang2016", oil="4050").lubricant)  # 4050's traction is 4106's fit form
    assert len(ns) == 1 and "fit form of oil 4106" in ns[0]


def test_figure_titles_read_the_oils_name_from_the_archived_case():
    from hsbearing.plotting.common import case_labels
    from hsbearing.results import standard_attrs

    case = load_case("zhang2016", **{"lubricant.file": VG32})
    assert case_labels(xr.Dataset(attrs=standard_attrs(case)))["oil"] == NAME
    assert case_labels(xr.Dataset(attrs=standard_attrs(load_case("zhang2016"))))["oil"] == "oil 4109"


def test_run_summary_prints_the_oil_from_the_archive(capsys):
    from hsbearing.cli.common import print_summary
    from hsbearing.results import standard_attrs

    case = load_case("zhang2016", **{"lubricant.file": VG32})
    print_summary(xr.Dataset(attrs=standard_attrs(case, "ok")))
    _check_named(capsys.readouterr().out)


def test_oils_template_writes_a_commented_file_that_loads(tmp_path, capsys):
    path = tmp_path / "my_oil.toml"
    assert cli.main(["oils", "--template", str(path)]) == 0
    assert "docs/traction.md" in capsys.readouterr().out
    text = path.read_text()
    assert text.count("\n#") >= 10  # commented
    d = lubricant.load_lubricant(path)
    assert d.name == tomllib.loads(text)["name"]
    assert d.alpha_estimated and d.traction_oil == "4106"
    assert cli.main(["oils", str(path)]) == 0
    assert "notice: the traction of" in capsys.readouterr().out


def test_oils_help_points_to_the_format(capsys):
    with pytest.raises(SystemExit):
        cli.main(["oils", "--help"])
    text = capsys.readouterr().out
    assert "docs/traction.md" in text and "--template" in text and "Lubricant files" in text
