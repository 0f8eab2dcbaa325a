"""What a new user trips over: one -o suffix rule for every command that writes an archive, and unit
spellings of the trade answered with a suggestion."""

from __future__ import annotations

import pytest

from hsbearing import cli
from hsbearing.case import CaseError
from hsbearing.units import parse_quantity


@pytest.mark.parametrize("argv", [
    ["quasistatic", "zhang2016"],
    ["run", "zhang2016", "--duration", "1 ms"],
    ["thermal", "zhang2016"],
    ["life", "zhang2016"],
    ["friction", "zhang2016", "--speeds", "5000rpm"],
])
@pytest.mark.parametrize("name", ["result.csv", "result"])
def test_every_command_refuses_a_non_nc_archive_name(tmp_path, capsys, argv, name):
    out = tmp_path / name
    assert cli.main([*argv, "-o", str(out)]) == 2
    err = [ln for ln in capsys.readouterr().err.splitlines() if ln.strip()]
    assert len(err) == 1 and err[0].startswith("hsbearing: error: -o") and "must be a .nc file" in err[0], err
    assert not out.exists() and list(tmp_path.iterdir()) == []  # nothing written


@pytest.mark.parametrize("text, kind, suggestion", [
    ("0.86 g/cm3", "density", "0.86 g/cm^3"),
    ("20 mm2/s", "kinematic_viscosity", "20 mm^2/s"),
    ("20 cst", "kinematic_viscosity", "20 mm^2/s"),
    ("20 CST", "kinematic_viscosity", "20 mm^2/s"),
    ("10 KGF", "force", "10 kgf"),
    ("10 kp", "force", "10 kgf"),
    ("7.83 g/cc3", "density", None),
])
def test_unit_spelling_suggestions(text, kind, suggestion):
    with pytest.raises(CaseError) as err:
        parse_quantity(text, kind, source="case.toml", key="k")
    msg = str(err.value)
    if suggestion is None:
        assert "did you mean" not in msg
    else:
        assert f"did you mean {suggestion!r}?" in msg, msg
        assert parse_quantity(suggestion, kind) > 0  # the suggestion itself is read


def test_density_spelling_in_a_case_file(tmp_path, capsys):
    assert cli.main(["check", "zhang2016", "--set", "materials.ball.density=0.86 g/cm3"]) == 2
    err = capsys.readouterr().err
    assert "did you mean '0.86 g/cm^3'?" in err and "materials.ball.density" in err, err
