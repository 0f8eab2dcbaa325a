"""Case files: unit conversion to SI, overrides, validation errors (issue 2, items 2-3)."""

import math
import pickle

import pytest

from hsbearing import load_case
from hsbearing.case import SCHEMA, CaseError, loads_case, parse_quantity, resolve_key


def test_default_case_in_si():
    c = load_case()
    assert c.name == "zhang2016" and c.system == "angular_contact"
    assert c.bearing.ball_diameter == pytest.approx(9.525e-3)
    assert c.operating.inner_speed == pytest.approx(14000 * 2 * math.pi / 60)
    assert c.lubricant.temperature == pytest.approx(403.15)
    assert c.operating.axial_load == pytest.approx(1000.0)
    assert c.bearing.contact_angle == pytest.approx(math.radians(25))
    assert c.materials.ball.elastic_modulus == pytest.approx(208e9)
    assert c.cage.pocket_diameter == pytest.approx(9.625e-3)


@pytest.mark.parametrize(
    "text,kind,si",
    [("9.525 mm", "length", 9.525e-3), ("1 kN", "force", 1000.0), ("130 degC", "temperature", 403.15),
     ("14000 rpm", "angular_speed", 14000 * math.pi / 30), ("25 deg", "angle", math.radians(25)),
     ("14.8 mm^2/s", "kinematic_viscosity", 14.8e-6), ("2 GPa", "pressure", 2e9), ("20 us", "time", 2e-5),
     ("10 uN*m", "moment", 1e-5), ("300 K", "temperature", 300.0)],
)
def test_parse_quantity(text, kind, si):
    assert parse_quantity(text, kind) == pytest.approx(si, rel=1e-12)


def test_overrides_full_and_bare_keys_and_pickle():
    c = load_case("zhang2016", **{"operating.axial_load": "2 kN", "oil": "4106", "temperature": "27 degC"})
    assert c.operating.axial_load == 2000.0
    assert c.lubricant.oil == "4106"
    assert c.lubricant.temperature == pytest.approx(300.15)
    assert "overrides" in c.text
    c2 = pickle.loads(pickle.dumps(c))
    assert c2 == c
    # to_toml round-trips through the loader
    c3 = loads_case(c.to_toml())
    assert c3.operating.axial_load == 2000.0 and c3.lubricant.oil == "4106"
    # numbers given on the command line are parsed as TOML values
    c4 = load_case("zhang2016", **{"bearing.ball_count": "10"})
    assert c4.bearing.ball_count == 10


def test_resolve_key_ambiguous_and_unknown():
    with pytest.raises(CaseError, match="ambiguous"):
        resolve_key("outside_diameter")
    with pytest.raises(CaseError, match="did you mean 'axial_load'"):
        resolve_key("axial_lod")
    assert resolve_key("operating.axial_load") == ("operating", "axial_load")


def test_schema_fields_documented():
    for table, fields in SCHEMA.items():
        for key, fld in fields.items():
            assert fld.doc, f"{table}.{key} has no description"


def test_with_overrides_accumulates():
    c = load_case("zhang2016", axial_load="500 N").with_overrides(radial_load="1 N")
    assert c.operating.axial_load == 500.0 and c.operating.radial_load == 1.0
    c2 = c.with_overrides(**{"operating.axial_load": "2 kN"})
    assert c2.operating.axial_load == 2000.0 and c2.operating.radial_load == 1.0
