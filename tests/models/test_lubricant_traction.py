"""Traction models in lubricant files: the physical model, user coefficients, a measured table.

Ground truths: the file's values reach the kernel parameters unchanged (tau0, Lambda, G; c_A .. c_D); the
table fit reproduces a table generated from known coefficients; bad traction tables give one-line errors
naming the file and the key (exit 2) through the CLI; a sweep over the seed oils and a user oil runs.
"""

from __future__ import annotations

import numpy as np
import pytest
from _cli_checks import one_error_line

from hsbearing import lubricant
from hsbearing.case import load_case
from hsbearing.cli import main
from hsbearing.models import traction
from hsbearing.models.ball_bearing import kernel_io as kio
from hsbearing.models.traction import zhang2016

HEAD = """\
name = "data-sheet ester"
class = "5 cSt polyol ester"
density = "1004 kg/m^3"
density_temperature = "15 degC"
viscosity = [["40 degC", "25.3 mm^2/s"], ["100 degC", "5.0 mm^2/s"]]
pressure_viscosity_coefficient = "1.5e-8 1/Pa"
"""
EYRING = HEAD + """
[traction]
model = "eyring"
limiting_shear_coefficient = 0.05
shear_modulus = "0.4 GPa"
"""
COEFS = HEAD + """
[traction]
model = "coefficients"
coefficients = [-0.04, 1.5, 60.0, 0.04]
temperature = "80 degC"
"""
TABLE = HEAD + """
[traction]
model = "table"
temperature = "120 degC"
load = "200 N"
speed = "10 m/s"
slide_roll_ratio = [0.001, 0.003, 0.01, 0.03, 0.1]
mu = [0.012, 0.027, 0.038, 0.040, 0.036]
"""


def _write(tmp_path, text, name="oil.toml"):
    p = tmp_path / name
    p.write_text(text)
    return p


def _cli(argv, capsys):
    rc = main(argv)
    out = capsys.readouterr()
    return rc, out.out, out.err


def test_eyring_file_reaches_the_kernel(tmp_path):
    from hsbearing.models import ehl
    from hsbearing.systems.angular_contact.dynamics import traction_values

    p = _write(tmp_path, EYRING)
    case = load_case("zhang2016", **{"lubricant.file": str(p)})
    assert case.lubricant.traction_law == "eyring"
    assert traction.law_id(case.lubricant.oil, case.lubricant.traction_law) == traction.EYRING_LAW_ID
    alpha = ehl.lubricant_parameters(case)["alpha"]
    tv = traction_values(case, alpha)
    assert tv["Lambda"] == 0.05 and tv["G"] == 0.4e9
    assert tv["tau0"] == pytest.approx(2 * 0.05 / 1.5e-8)  # default tau0 = 2 Lambda / alpha


def test_built_in_oils_take_the_physical_model_by_name():
    from hsbearing.models import ehl
    from hsbearing.systems.angular_contact.dynamics import traction_values

    for oil in traction.OILS:
        case = load_case("zhang2016", **{"lubricant.oil": oil, "lubricant.traction_law": "eyring"})
        alpha = ehl.lubricant_parameters(case)["alpha"]
        assert alpha == traction.OILS[oil].alpha  # the oil's own Table 1 alpha feeds the model
        assert traction_values(case, alpha)["tau0"] == pytest.approx(2 * 0.047 / alpha)


def test_coefficients_file_reaches_the_kernel(tmp_path):
    from hsbearing.systems.angular_contact.dynamics import build_model

    p = _write(tmp_path, COEFS)
    case = load_case("zhang2016", **{"lubricant.file": str(p)})
    assert case.lubricant.traction_law == "user"
    m = build_model(case)
    assert kio.get(m.P, "law_id") == traction.COEFFICIENTS_LAW_ID
    assert [kio.get(m.P, k) for k in ("c_A", "c_B", "c_C", "c_D")] == [-0.04, 1.5, 60.0, 0.04]


def test_table_fit_recovers_known_coefficients():
    """A table sampled from mu = (A + B S) e^(-C S) + D with A = -D is fitted back to those coefficients."""
    A, B, C, D = -0.035, 2.0, 150.0, 0.035
    S = np.array([5e-4, 1e-3, 3e-3, 1e-2, 3e-2, 0.1])
    mu = zhang2016.traction_coefficient(A, B, C, D, S)
    (fA, fB, fC, fD), dev = lubricant.fit_seed_form(S, mu)
    assert dev < 1e-8
    np.testing.assert_allclose([fA, fB, fC, fD], [A, B, C, D], rtol=1e-5)


def test_table_file_fitted_within_tolerance(tmp_path):
    d = lubricant.load_lubricant(_write(tmp_path, TABLE))
    S, mu = (np.array(x) for x in d.traction_table)
    fit = zhang2016.traction_coefficient(*d.coefficients, S)
    assert np.max(np.abs(fit - mu)) == pytest.approx(d.table_fit_deviation)
    assert d.table_fit_deviation <= max(lubricant.TABLE_FIT_ABS, lubricant.TABLE_FIT_REL * mu.max())
    assert d.traction_conditions == {"T": pytest.approx(393.15), "W": 200.0, "U": 10.0}


def test_check_warns_outside_the_stated_temperature(tmp_path, capsys):
    p = _write(tmp_path, TABLE.replace('temperature = "120 degC"', 'temperature = "60 degC"'))
    rc, out, err = _cli(["check", "--set", f"lubricant.file={p}"], capsys)
    assert rc == 0, err
    assert "fitted to a measured table" in out
    assert "stated at 60 degC and are used as given at 130 degC" in out
    assert "stated at 200 N, 10 m/s" in out
    p2 = _write(tmp_path, EYRING, "ey.toml")
    rc, out, err = _cli(["check", "--set", f"lubricant.file={p2}"], capsys)
    assert rc == 0 and "physical model (eyring): Lambda = 0.05" in out and "used as given" not in out


BAD = [
    ("unknown model", EYRING.replace('"eyring"', '"eyrin"'), "traction.model", "did you mean 'eyring'"),
    ("key of another model", EYRING + "coefficients = [1, 2, 3, 4]\n", "traction.coefficients", "a key of model coefficients"),
    ("Lambda absurd", EYRING.replace("0.05", "0.5"), "traction.limiting_shear_coefficient", "outside 0.01-0.15"),
    ("G no unit", EYRING.replace('"0.4 GPa"', "0.4"), "traction.shear_modulus", ""),
    ("tau0 absurd", EYRING + 'eyring_stress = "500 MPa"\n', "traction.eyring_stress", "outside 0.1-100 MPa"),
    ("k_tau0 without tau0", EYRING + 'eyring_stress_temperature_coefficient = "1e-3 1/K"\n',
     "traction.eyring_stress_temperature_coefficient", "needs traction.eyring_stress"),
    ("three coefficients", COEFS.replace("[-0.04, 1.5, 60.0, 0.04]", "[-0.04, 1.5, 60.0]"), "traction.coefficients", "four numbers"),
    ("C negative", COEFS.replace("60.0", "-60.0"), "traction.coefficients", "C must be positive"),
    ("not a traction curve", COEFS.replace("1.5, 60.0", "150.0, 1.0"), "traction.coefficients", "not a traction curve"),
    ("no temperature", COEFS.replace('temperature = "80 degC"\n', ""), "traction.temperature", "missing required key"),
    ("table lengths", TABLE.replace("0.040, 0.036]", "0.040]"), "traction.mu", "expected a list of 5"),
    ("table in percent", TABLE.replace("0.03, 0.1]", "3.0, 10.0]"), "traction.slide_roll_ratio", "fractions, not percent"),
    ("table not the form", TABLE.replace("0.040, 0.036]", "0.010, 0.045]"), "traction.mu", "follows this table only within"),
    ("zhang2016 without oil", HEAD + '[traction]\nlaw = "default"\n', "traction.oil", "missing required key"),
]


@pytest.mark.parametrize("label,text,key,words", BAD, ids=[b[0] for b in BAD])
def test_bad_traction_table_one_line_error(label, text, key, words, tmp_path, capsys):
    p = _write(tmp_path, text, "bad_oil.toml")
    rc = main(["check", "--set", f"lubricant.file={p}"])
    line = one_error_line(capsys, rc)
    assert line.startswith(f"hsbearing: error: {p}: {key}: "), line
    assert words in line


def test_user_law_needs_a_file(capsys):
    rc = main(["check", "--set", "lubricant.traction_law=user"])
    one_error_line(capsys, rc, r"lubricant\.traction_law: law 'user' needs a lubricant file")


def test_sweep_plan_over_seed_oils_and_user_oils(tmp_path):
    from hsbearing.workflows import sweeps

    pe, pc = _write(tmp_path, EYRING, "ey.toml"), _write(tmp_path, COEFS, "co.toml")
    plan = sweeps.plan_sweep(load_case("zhang2016"), {"oil": f"4109,4106,4050,{pe},{pc}"}, kind="run")
    assert all(pt.case is not None for pt in plan.points), [pt.error for pt in plan.points]
    assert [pt.case.lubricant.traction_law for pt in plan.points][-2:] == ["eyring", "user"]
    assert len({pt.hash for pt in plan.points}) == 5


@pytest.mark.slow
def test_dynamic_sweep_over_seed_oils_and_a_user_oil_runs(tmp_path, capsys):
    """Done-when of issue 26: `hsbearing sweep --vary oil=4109,4106,4050,<user oil>` runs (2 ms per point)."""
    pe = _write(tmp_path, EYRING, "ey.toml")
    rc = main(["sweep", "zhang2016", "--vary", f"oil=4109,4106,4050,{pe}", "--duration", "2ms", "-j", "1",
               "-o", str(tmp_path / "sw")])
    out = capsys.readouterr().out
    assert rc == 0, out
    assert "4 of 4 points ok" in out


@pytest.mark.slow
def test_short_dynamic_run_with_the_physical_model(tmp_path, capsys):
    p = _write(tmp_path, EYRING)
    rc, stdout, err = _cli(["run", "--set", f"lubricant.file={p}", "--duration", "2ms", "--no-figure", "-q",
                            "-o", str(tmp_path / "run.nc")], capsys)
    assert rc == 0, err
    assert "status: ok" in stdout


def test_oils_at_a_case_draws_the_physical_model(tmp_path, capsys):
    from hsbearing.cli import oils
    from hsbearing.systems.angular_contact import quasistatic

    p = _write(tmp_path, EYRING)
    png = tmp_path / "mu.png"
    rc, out, err = _cli(["oils", str(p), "--at", "zhang2016", "-o", str(png)], capsys)
    assert rc == 0, err
    assert "physical model (eyring): Lambda = 0.05" in out and png.read_bytes()[:4] == b"\x89PNG"
    # the drawn curve is the physical model at that contact: it tends to the file's Lambda at large slip
    case = load_case("zhang2016", **{"lubricant.file": str(p)})
    qs = quasistatic.solve_case(case)
    Q, U, Rx, Ry = oils.contact_conditions(case, qs, "inner")
    mu = oils.contact_traction(case, np.array([1e-3, 0.05, 1e3]), Q, U, Rx, Ry)
    assert np.all(np.diff(mu) > 0) and mu[-1] == pytest.approx(0.05, rel=0.01)
