"""The sanity envelope warns and never refuses (docs/quasistatic.md, "Sanity envelope"):
speed against a limiting n d_m (the case's bearing.limiting_speed, else the typical value of the lubrication
method, case.checks.TYPICAL_NDM), the oil temperature against the oil's stated service range (built-in oils and a
lubricant file's service_temperature), the contact pressure against bearing.permissible_contact_pressure (else
ISO 76's 4.2 GPa); one line each, printed and in the archive's ``warnings`` attribute."""

from __future__ import annotations

import math

import numpy as np
import pytest
import xarray as xr

from hsbearing import cli
from hsbearing.case import envelope_warnings, load_case
from hsbearing.case.checks import TYPICAL_NDM, speed_factor
from hsbearing.results import standard_attrs


def test_speed_factor_is_n_times_pitch_diameter():
    case = load_case("zhang2016", inner_speed="140000 rpm")
    assert speed_factor(case) == pytest.approx(140000 * case.bearing.pitch_diameter * 1e3, rel=1e-12)


def test_a_tenfold_speed_typo_is_warned_the_case_speed_is_not():
    assert envelope_warnings(load_case("zhang2016")) == []  # 14000 r/min x 46 mm = 0.64e6: quiet
    ws = envelope_warnings(load_case("zhang2016", inner_speed="140000 rpm"))
    assert len(ws) == 1 and "n d_m = 6.44e+06" in ws[0] and f"{TYPICAL_NDM['oil_jet']:.3g}" in ws[0]
    assert "typical for oil_jet" in ws[0]


def test_the_cases_limiting_speed_replaces_the_typical_value():
    case = load_case("zhang2016", **{"bearing.limiting_speed": "12000 rpm"})
    ws = envelope_warnings(case)
    assert len(ws) == 1 and "bearing.limiting_speed 12000 r/min" in ws[0]
    assert envelope_warnings(load_case("zhang2016", **{"bearing.limiting_speed": "15000 rpm"})) == []


@pytest.mark.parametrize("lub,limit", sorted(TYPICAL_NDM.items()))
def test_each_lubrication_method_has_its_limit(lub, limit):
    dm_mm = 46.0
    n_over = 1.01 * limit / dm_mm
    n_under = 0.99 * limit / dm_mm
    over = load_case("zhang2016", inner_speed=f"{n_over} rpm", lubrication=lub)
    under = load_case("zhang2016", inner_speed=f"{n_under} rpm", lubrication=lub)
    assert any("n d_m" in w for w in envelope_warnings(over))
    assert not any("n d_m" in w for w in envelope_warnings(under))


def test_warnings_reach_the_archive_and_the_output(tmp_path, capsys):
    out = tmp_path / "qs.nc"
    rc = cli.main(["quasistatic", "zhang2016", "--set", "inner_speed=140000 rpm", "--set", "temperature=300 degC",
                   "-o", str(out)])
    assert rc == 0  # warned, not refused
    err = capsys.readouterr().err
    assert "n d_m" in err and "service range of oil 4109" in err
    w = xr.open_dataset(out).attrs["warnings"]
    assert "n d_m" in w and "service range of oil 4109" in w
    attrs = standard_attrs(load_case("zhang2016", inner_speed="140000 rpm"), warnings="none")
    assert "n d_m" in attrs["warnings"]


def test_lubricant_file_service_range(tmp_path):
    from conftest import DATA

    text = (DATA / "lubricants" / "vg32_data_sheet.toml").read_text()
    p = tmp_path / "vg32_range.toml"
    p.write_text(text.replace("[traction]", 'service_temperature = ["-10 degC", "100 degC"]\n\n[traction]'))
    ws = envelope_warnings(load_case("zhang2016", **{"lubricant.file": str(p)}))
    assert len(ws) == 1 and "service range of VG 32 data sheet (-10..100 degC" in ws[0]
    assert envelope_warnings(load_case("zhang2016", **{"lubricant.file": str(p), "temperature": "80 degC"})) == []


def test_contact_pressure_beyond_the_materials_rating():
    from hsbearing.systems.angular_contact.contact_state import warnings_for

    ds = xr.Dataset({"inner_contact_pressure": ("ball", np.array([1.9e9, 2.1e9])),
                     "outer_contact_pressure": ("ball", np.array([1.5e9, 1.6e9]))})
    assert not any("pressure" in w for w in warnings_for(ds, load_case("zhang2016")))  # below ISO 76's 4.2 GPa
    rated = load_case("zhang2016", **{"bearing.permissible_contact_pressure": "2 GPa"})
    ws = [w for w in warnings_for(ds, rated) if "pressure" in w]
    assert len(ws) == 1 and "2.1 GPa exceeds the 2 GPa" in ws[0]
    assert math.isclose(rated.bearing.permissible_contact_pressure, 2e9)
