"""angular speeds and angles cannot be misread.

pint reads ``Hz`` and ``1/min`` as 1/s and a ratio (``%``) or a quoted bare number as radians, so
``inner_speed = "233.33 Hz"`` used to be taken as 233.33 rad/s (a 2 pi error: cage 908 r/min instead of 5758)
and ``contact_angle = "0.5"`` as 0.5 rad.  Now a speed without an angle unit counts revolutions (docs/output.md,
docs/nomenclature.md) and an angle needs an angle unit.
"""

from __future__ import annotations

import math
import re

import pytest

from hsbearing import cli, load_case
from hsbearing.case import CaseError, case_path, loads_case, parse_quantity

RPM = 2.0 * math.pi / 60.0


@pytest.mark.parametrize("text, rpm", [
    ("14000 rpm", 14000.0), ("14000 r/min", 14000.0), ("14000 rev/min", 14000.0), ("14000 1/min", 14000.0),
    ("233.333 Hz", 13999.98), ("233.333 rev/s", 13999.98), ("233.333 rps", 13999.98), ("233.333 1/s", 13999.98),
    ("0.233333 kHz", 13999.98), ("1466.0766 rad/s", 14000.0), ("84000 deg/s", 14000.0), ("233.333 turn/s", 13999.98),
])
def test_angular_speed_units(text, rpm):
    assert parse_quantity(text, "angular_speed") == pytest.approx(rpm * RPM, rel=1e-6)


def test_hz_is_revolutions_per_second_not_radians():
    """The example of the issue: 233.33 Hz = 2 pi 233.33 rad/s."""
    assert parse_quantity("233.33 Hz", "angular_speed") == pytest.approx(2 * math.pi * 233.33, rel=1e-12)
    case = load_case("zhang2016", **{"operating.inner_speed": "233.33 Hz"})
    assert case.operating.inner_speed == pytest.approx(2 * math.pi * 233.33)


@pytest.mark.parametrize("text", ["0.5", "25 %", "0.5 dimensionless", "25 deg*m", "2 ppm"])
def test_unitless_angle_refused_with_key(text, capsys):
    rc = cli.main(["check", "--set", f"contact_angle={text}"])
    err = capsys.readouterr().err.strip().splitlines()
    assert rc == 2 and len(err) == 1, err
    assert re.search(r"bearing\.contact_angle: .*(is not an angle: give an angle unit|with units like .* got bare number)", err[0]), err


def test_quoted_bare_angle_in_a_case_file_refused():
    text = case_path("zhang2016").read_text()
    text = re.sub(r'(?m)^contact_angle\s*=.*$', 'contact_angle = "0.5"', text, count=1)
    with pytest.raises(CaseError, match=r"bearing\.contact_angle: '0\.5' is not an angle"):
        loads_case(text, source="x.toml")
    text0 = re.sub(r'(?m)^contact_angle\s*=.*$', "contact_angle = 0", text, count=1)
    assert loads_case(text0, source="x.toml").bearing.contact_angle == 0.0  # zero needs no unit


def test_frequency_in_cycles():
    assert parse_quantity("5 Hz", "frequency") == 5.0
    assert parse_quantity("60 rpm", "frequency") == pytest.approx(1.0)


def test_cage_speed_same_for_hz_and_rpm(capsys):
    """Through the CLI: the quasi-static cage speed of 233.333 Hz equals that of 14000 r/min (5758 r/min, not 908)."""
    def cage(speed):
        assert cli.main(["quasistatic", "--set", f"inner_speed={speed}"]) == 0
        out = capsys.readouterr().out
        return float(re.search(r"^cage speed: ([0-9.]+) r/min", out, re.M).group(1))

    ref = cage("14000 rpm")
    assert ref == pytest.approx(5758, rel=2e-3)
    assert cage("233.3333 Hz") == pytest.approx(ref, rel=1e-5)
    assert cage("14000 1/min") == pytest.approx(ref, rel=1e-9)
    assert cage("14000 r/min") == pytest.approx(ref, rel=1e-9)


@pytest.mark.parametrize("text", ["1 000 N", "2 500.5 N", "1 -5 N"])
def test_digits_separated_by_a_space_are_refused(text):
    """pint multiplies juxtaposed numbers ("1 000" -> 1 x 000 = 0): a thousands separator silently gave 0 N."""
    with pytest.raises(CaseError, match="digits separated by a space"):
        parse_quantity(text, "force", source="case.toml", key="load.axial")


def test_ordinary_quantities_still_parse():
    assert parse_quantity("1000 N", "force") == 1000.0
    assert parse_quantity("1.5 kN", "force") == 1500.0
    assert parse_quantity("1e3 N", "force") == 1000.0
