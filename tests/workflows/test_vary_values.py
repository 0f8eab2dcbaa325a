"""``--vary`` values are read by the case's own rules (hsbearing.case.read_override, as ``--set`` and a case
file): whatever a case accepts for a key, a value list accepts, with the same SI value; what a case refuses,
a value list refuses with the case's message (one line naming the source and the key)."""

from __future__ import annotations

import pytest

import hsbearing
from hsbearing.case import CaseError
from hsbearing.units import split_number
from hsbearing.workflows import sweeps


def _case_value(key: str, value: str) -> float:
    """The SI value load_case gives ``key = value`` (the independent path: the case loader)."""
    case = hsbearing.load_case("zhang2016", **{key: value})
    table, _, leaf = key.rpartition(".")
    obj = case
    for part in table.split("."):
        obj = getattr(obj, part)
    return getattr(obj, leaf)


@pytest.mark.parametrize("key, spec, expected_values", [
    ("operating.axial_load", "1,2.5kN", ["1 kN", "2.5 kN"]),
    ("operating.axial_load", "100,200 lbf", ["100 lbf", "200 lbf"]),
    ("operating.axial_load", "0,1kN", ["0 kN", "1 kN"]),
    ("operating.inner_speed", "10000,14000 r/min", ["10000 r/min", "14000 r/min"]),
    ("operating.inner_speed", "100,200 Hz", ["100 Hz", "200 Hz"]),  # Hz of a speed: revolutions per second
    ("operating.inner_speed", "12000,14000 1/min", ["12000 1/min", "14000 1/min"]),
    ("lubricant.temperature", "5,120degC", ["5 degC", "120 degC"]),
    ("lubricant.temperature", "300,400 K", ["300 K", "400 K"]),
    ("lubricant.temperature", "-5,20degC", None),  # read as a value list; the case refuses it below 0 degC
    ("bearing.contact_angle", "0.3,0.4363rad", ["0.3 rad", "0.4363 rad"]),
    ("bearing.contact_angle", "15 deg,25deg", ["15 deg", "25 deg"]),
    ("operating.radial_load", ".5,1e2 N", [".5 N", "1e2 N"]),
    ("cage.pocket_diameter", "9.6 mm,0.38 inch", ["9.6 mm", "0.38 inch"]),
])
def test_every_unit_a_case_accepts_gives_the_case_value(key, spec, expected_values):
    values, coords = sweeps.parse_values(key, spec)
    if expected_values is None:
        assert values == ["-5 degC", "20 degC"] and coords == pytest.approx([268.15, 293.15], rel=1e-15)
        return
    assert values == expected_values  # the override text (hence the archive hash) as before: "<number> <unit>"
    for v, c in zip(values, coords):
        assert c == pytest.approx(_case_value(key, v), rel=1e-15), (key, v)


def test_a_bare_zero_is_a_value_as_in_a_case_file():
    values, coords = sweeps.parse_values("operating.radial_load", "0")
    assert coords == [0.0]
    assert _case_value("operating.radial_load", values[0]) == 0.0


@pytest.mark.parametrize("key, item, hint", [
    ("operating.axial_load", "100", '"100 N"'),
    ("lubricant.temperature", "27", '"27 degC"'),
    ("bearing.contact_angle", "15", '"15 deg"'),  # the hint table was sweeps' own before and suggested rad
    ("operating.inner_speed", "14000", '"14000 rpm"'),
])
def test_a_bare_number_needs_a_unit_with_the_case_hint(key, item, hint):
    with pytest.raises(CaseError) as exc:
        sweeps.parse_values(key, f"{item},{item}5")
    msg = str(exc.value)
    assert "\n" not in msg and msg.startswith(f"--vary: {key}: ") and "needs a unit" in msg and hint in msg
    with pytest.raises(CaseError) as ref:  # the same words as --set
        hsbearing.load_case("zhang2016", **{key: item})
    assert ref.value.message == exc.value.message


@pytest.mark.parametrize("key, item", [
    ("bearing.inner_conformity", "inf"),  # was accepted by the value list, refused only by the case
    ("bearing.inner_conformity", ".52"),  # not a TOML number: --set refuses it as well
    ("bearing.ball_count", "12.0"),
    ("operating.axial_load", "12 mm"),
])
def test_what_a_case_refuses_a_value_list_refuses_with_the_case_message(key, item):
    with pytest.raises(CaseError) as exc:
        sweeps.parse_values(key, [item], source="study.toml")
    assert str(exc.value).startswith(f"study.toml: {key}: ") and "\n" not in str(exc.value)
    with pytest.raises(CaseError) as ref:
        hsbearing.load_case("zhang2016", **{key: item})
    assert ref.value.message == exc.value.message


def test_a_value_out_of_range_is_left_to_the_point_case():
    """Range checks are the case's: 0.49 < 0.5 is read, and its point is planned invalid (``--keep-going``)."""
    values, coords = sweeps.parse_values("bearing.inner_conformity", "0.49,0.52")
    assert coords == [0.49, 0.52]
    plan = sweeps.plan_sweep("zhang2016", {"bearing.inner_conformity": "0.49,0.52"}, kind="quasistatic")
    assert [pt.case is None for pt in plan.points] == [True, False]
    assert "inner_conformity" in plan.points[0].error


@pytest.mark.parametrize("text, parts", [
    ("2.5kN", ("2.5", "kN")), ("1000", ("1000", "")), (" 1e3 N ", ("1e3", "N")), ("-5degC", ("-5", "degC")),
    (".5 mm", (".5", "mm")), ("14000 r/min", ("14000", "r/min")), ("1000 1/min", ("1000", "1/min")),
    ("4109", ("4109", "")), ("kN", ("", "kN")), ("inf N", ("", "inf N")), ("nanometre", ("", "nanometre")),
    ("1eV", ("1", "eV")), ("", ("", "")),
])
def test_split_number(text, parts):
    assert split_number(text) == parts
