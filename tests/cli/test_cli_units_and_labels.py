"""What the commands print, on every bundled case: no internal label ("seed", "issue", "session") and every number
with its unit, by the one rule of docs/output.md (torques: N mm / µN m in a line, the column's unit in a table
header; powers in W; lives in million revolutions).

The commands run in-process (``hsbearing.cli.main``) with short settings; the dynamic run is covered by the
run-summary lines, built here from a synthetic run (the full run is in the slow tier and the regression archives).
"""

from __future__ import annotations

import re

import numpy as np
import pytest
import xarray as xr

from hsbearing import cli
from hsbearing.display import format_grouped, format_life, format_quantity

LABEL = re.compile(r"\b(seed|issue|session)s?\b\s*#?\d*", re.IGNORECASE)


def _run(capsys, *argv) -> str:
    rc = cli.main(list(argv))
    out = capsys.readouterr()
    assert rc == 0, f"hsbearing {' '.join(argv)} exited {rc}: {out.err[-2000:]}"
    return out.out + out.err


def _no_labels(text: str, what: str) -> None:
    hits = [m.group(0) for m in LABEL.finditer(text)]
    assert not hits, f"{what}: internal labels in the output: {hits}"


@pytest.mark.parametrize("case", ["zhang2016", "dgbb_6206", "jiang2014_gyro", "shan2010_wire_race"])
def test_check_prints_no_internal_label(capsys, case):
    _no_labels(_run(capsys, "check", case), f"check {case}")


def test_cases_and_oils_print_no_internal_label(capsys):
    _no_labels(_run(capsys, "cases"), "cases")
    out = _run(capsys, "oils")
    _no_labels(out, "oils")
    assert "mm^2/s" in out and "GPa^-1" in out  # the columns' units (second header line)


def test_quasistatic_output(capsys, tmp_path):
    out = _run(capsys, "quasistatic", "zhang2016", "-o", str(tmp_path / "qs.nc"))
    _no_labels(out, "quasistatic")
    assert "cage speed:" in out and "r/min" in out and "Q_i/N" in out


def test_friction_tables_state_every_torque_unit(capsys, tmp_path):
    out = _run(capsys, "friction", "zhang2016", "-o", str(tmp_path / "fr.nc"))
    _no_labels(out, "friction zhang2016")
    header = next(line for line in out.splitlines() if "n [r/min]" in line and "SKF" in line)
    for col in ("M [N mm]", "SKF M_rr [N mm]", "SKF M_sl [N mm]", "SKF M [N mm]", "SKF P [W]", "total [W]"):
        assert col in header, f"friction table column {col!r} missing from {header!r}"
    out = _run(capsys, "friction", "dgbb_6206", "--speeds", "500rpm", "-o", str(tmp_path / "frd.nc"))
    _no_labels(out, "friction dgbb_6206")
    header = next(line for line in out.splitlines() if "n [r/min]" in line)
    cols = re.findall(r"(\S+(?: \S+)?) \[([^\]]+)\]", header)
    assert len(cols) == 10 and all(u in ("r/min", "-", "N mm") for _, u in cols), header


def test_life_prints_million_revolutions(capsys, tmp_path):
    out = _run(capsys, "life", "zhang2016", "-o", str(tmp_path / "life.nc"))
    _no_labels(out, "life")
    assert "10^6 rev" not in out
    l10 = next(line for line in out.splitlines() if line.strip().startswith("L_10 "))
    assert re.search(r"L_10  = [\d ]+(\.\d+)? million rev = [\d ]+(\.\d+)? h", l10), l10


def test_thermal_and_preload_print_no_internal_label(capsys, tmp_path):
    _no_labels(_run(capsys, "thermal", "zhang2016", "-o", str(tmp_path / "th.nc")), "thermal")
    out = _run(capsys, "preload", "shan2010_wire_race", "--preload", "10..30um")
    _no_labels(out, "preload")
    assert "[N m]" in out and "[µm]" in out


def test_run_summary_drive_torque_in_n_mm():
    """The run summary's torque line follows the N m rule (40.27 N mm, not 0.04027 N m)."""
    from hsbearing.systems.angular_contact.balances import SOURCES, power_summary_lines

    t = np.linspace(0.0, 0.01, 11)
    data = {"drive_torque": ("time", np.full(t.size, 0.04027)), "drive_power": ("time", np.full(t.size, 59.03)),
            "power_loss": ("time", np.full(t.size, 59.03))}
    data.update({f"power_loss_{s}": ("time", np.full(t.size, 1.0)) for s in SOURCES})
    lines = power_summary_lines(xr.Dataset(data, coords={"time": t}))
    torque = next(line for line in lines if "drive_torque" in line)
    assert "40.27 N mm" in torque, torque
    assert all(line.rstrip().endswith(("W", "W, by source:", "ms:")) for line in lines if "torque" not in line), lines


def test_format_life_and_torque_rule():
    assert format_life(13630.4) == "13 630 million rev"
    assert format_life(0.5432) == "0.5432 million rev"
    assert format_life(1.363e12) == "1.363 x 10^12 million rev"
    assert format_life(float("nan")) == "nan"
    assert format_grouped(16234.7, "h") == "16 230 h"
    assert format_grouped(999.96, "h") == "1 000 h"
    assert format_quantity(0.04027, "N m") == "40.27 N mm"
    assert format_quantity(4.27e-6, "N m") == "4.27 µN m"
    assert format_quantity(17.3, "N m") == "17.3 N m"
