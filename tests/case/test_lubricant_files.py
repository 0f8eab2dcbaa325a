"""Lubricant files: format, bundled library, case integration, one-line errors through the CLI.

Literature: ASTM D341 (Walther) through the file's points; So & Klaus 1980 (ASLE Trans. 23, 409-421) for an
estimated pressure-viscosity coefficient; Zhang et al. 2016 Table 1 for the seed oils' alpha and K
(tests/data/zhang2016_oils.csv).  The bundled seed-oil files must reproduce the built-in oils exactly.
"""

from __future__ import annotations

import math
import textwrap

import numpy as np
import pytest

from hsbearing import lubricant
from hsbearing.case import load_case, loads_case
from hsbearing.cli import main
from hsbearing.models import ehl, viscosity

GOOD = """\
name = "my oil"
class = "ester from a data sheet"
density = "1003 kg/m^3"
density_temperature = "15 degC"
density_temperature_coefficient = "7e-4 1/K"
viscosity = [["40 degC", "27.6 mm^2/s"], ["100 degC", "5.1 mm^2/s"]]
pressure_viscosity_coefficient = "so_klaus_1980"
[traction]
oil = "4106"
law = "default"
"""


@pytest.fixture
def oil_file(tmp_path):
    p = tmp_path / "my_oil.toml"
    p.write_text(GOOD)
    return p


def _cli(argv, capsys):
    rc = main(argv)
    out = capsys.readouterr()
    return rc, out.out, out.err


# ----------------------------------------------------------------------------- the format


def test_walther_through_the_points_and_density_law(oil_file):
    d = lubricant.load_lubricant(oil_file)
    np.testing.assert_allclose(d.kinematic_viscosity(np.array([313.15, 373.15])) * 1e6, [27.6, 5.1], rtol=1e-12)
    assert d.density(288.15) == pytest.approx(1003.0)
    assert d.density(403.15) == pytest.approx(1003.0 * (1.0 - 7e-4 * 115.0), rel=1e-12)
    assert d.alpha_estimated and d.traction_oil == "4106"
    # the same Walther line as the built-in oils' (models.viscosity)
    A, B = viscosity.walther_coefficients(313.15, 27.6e-6, 373.15, 5.1e-6)
    assert d.walther() == pytest.approx((A, B), rel=1e-12)


def test_three_points_least_squares_and_dynamic_points(tmp_path):
    """Three kinematic points on one Walther line are reproduced; dynamic points are converted with the density."""
    A, B = viscosity.walther_coefficients(313.15, 27.6e-6, 373.15, 5.1e-6)
    T = np.array([313.15, 343.15, 373.15])
    nu = viscosity.walther_kinematic_viscosity(T, A, B) * 1e6
    pts = ", ".join(f'["{t - 273.15:.2f} degC", "{v:.12g} mm^2/s"]' for t, v in zip(T, nu))
    text = GOOD.replace('viscosity = [["40 degC", "27.6 mm^2/s"], ["100 degC", "5.1 mm^2/s"]]', f"viscosity = [{pts}]")
    d = lubricant.loads_lubricant(text, "three.toml")
    assert d.walther() == pytest.approx((A, B), rel=1e-9)
    eta = [viscosity.walther_kinematic_viscosity(t, A, B) * 900.0 for t in T]
    pts = ", ".join(f'["{t - 273.15:.2f} degC", "{e * 1e3:.12g} mPa*s"]' for t, e in zip(T, eta))
    text = textwrap.dedent(f"""\
        name = "dyn"
        viscosity = [{pts}]
        pressure_viscosity_coefficient = [["30 degC", "27e-9 1/Pa"], ["100 degC", "17.5e-9 1/Pa"]]
        [traction]
        oil = "4106"
        """)
    d = lubricant.loads_lubricant(text, "dyn.toml")
    assert d.viscosity_kind == "dynamic"
    assert d.dynamic_viscosity(353.15, 900.0) == pytest.approx(float(viscosity.walther_kinematic_viscosity(353.15, A, B)) * 900.0, rel=1e-9)
    # alpha: linear between the points, held outside
    assert d.alpha(338.15) == pytest.approx(22.25e-9, rel=1e-12) and d.alpha(450.0) == pytest.approx(17.5e-9)


def test_so_klaus_against_the_formula_written_out():
    """The correlation as written in the module docstring, evaluated independently at one point
    (nu 3.058 mm^2/s, rho 922 kg/m^3, b = 3.0): alpha = 1e-8 (1.216 + 4.143 L^3.0627 + 2.848e-4 b^5.1903 L^1.5976
    - 3.999 L^3.0975 rho^0.1162).  Plausibility (not validation): 10-25 GPa^-1 for ester and mineral oils."""
    L = math.log10(3.058)
    want = 1e-8 * (1.216 + 4.143 * L**3.0627 + 2.848e-4 * 3.0**5.1903 * L**1.5976 - 3.999 * L**3.0975 * 0.922**0.1162)
    assert lubricant.so_klaus_alpha(3.058e-6, 922.0, 3.0) == pytest.approx(want, rel=1e-12)
    d = lubricant.load_lubricant(lubricant.bundled_path("mobil_jet_oil_ii"))
    for T, lo, hi in ((313.15, 15e-9, 25e-9), (403.15, 10e-9, 16e-9)):
        assert lo < d.alpha(T, 960.0) < hi
    with pytest.raises(ValueError):
        lubricant.so_klaus_alpha(0.9e-6, 900.0, 3.0)


# ----------------------------------------------------------------------------- the bundled library


def test_bundled_library_loads_and_is_shipped():
    names = set(lubricant.bundled_lubricants())
    assert {"4109", "4106", "4050", "mobil_jet_oil_ii", "mil_prf_7808_grade3"} <= names
    for n in names:
        d = lubricant.load_lubricant(lubricant.bundled_path(n))
        assert d.text.lstrip().startswith("#"), f"{n}: the file must open with its sources as comments"
    import tomllib
    from pathlib import Path

    pp = tomllib.loads((Path(__file__).resolve().parents[2] / "pyproject.toml").read_text())
    assert "lubricants/*.toml" in pp["tool"]["setuptools"]["package-data"]["hsbearing"]


@pytest.mark.parametrize("oil", ["4109", "4106", "4050"])
def test_bundled_seed_oils_reproduce_the_built_in_ones(oil):
    """`lubricant.file = "4109"` and `oil = "4109"` give the same viscosity, alpha, density and traction law."""
    for T in ("27 degC", "80 degC", "130 degC", "180 degC"):
        a = load_case("zhang2016", oil=oil, **{"lubricant.temperature": T})
        b = load_case("zhang2016", **{"lubricant.file": oil, "lubricant.temperature": T})
        pa, pb = ehl.lubricant_parameters(a), ehl.lubricant_parameters(b)
        assert pb["eta"] == pytest.approx(pa["eta"], rel=1e-12) and pb["alpha"] == pa["alpha"]
        assert (b.lubricant.oil, b.lubricant.traction_law, b.lubricant.density) == (a.lubricant.oil, a.lubricant.traction_law, a.lubricant.density)
    sp = viscosity.OIL_SPEC[oil]
    d = lubricant.load_lubricant(lubricant.bundled_path(oil))
    np.testing.assert_allclose(d.kinematic_viscosity(np.array([313.15, 373.15])), [sp.nu40, sp.nu100], rtol=1e-11)


# ----------------------------------------------------------------------------- the case


def test_case_takes_the_file_values_at_its_temperature(oil_file):
    c = load_case("zhang2016", **{"lubricant.file": str(oil_file)})
    d = c.lubricant.definition
    T = c.lubricant.temperature
    assert c.lubricant.oil == "4106" and c.lubricant.density == pytest.approx(d.density(T))  # file density beats the case's 960
    p = ehl.lubricant_parameters(c)
    assert p["eta"] == pytest.approx(float(d.kinematic_viscosity(T)) * d.density(T), rel=1e-12)
    assert p["alpha"] == pytest.approx(d.alpha(T, d.density(T)), rel=1e-12)
    # an override beside the file wins
    c2 = load_case("zhang2016", **{"lubricant.file": str(oil_file), "lubricant.pressure_viscosity_coefficient": "2e-8 1/Pa"})
    assert ehl.lubricant_parameters(c2)["alpha"] == 2e-8
    # oil = a bundled lubricant name or a .toml path works like lubricant.file
    c3 = load_case("zhang2016", oil="mobil_jet_oil_ii")
    assert c3.lubricant.definition.name == "Mobil Jet Oil II" and c3.lubricant.oil == "4106"
    c4 = load_case("zhang2016", oil=str(oil_file))
    assert ehl.lubricant_parameters(c4)["eta"] == pytest.approx(p["eta"], rel=1e-12)


def test_saved_case_reloads_to_the_same_oil_and_carries_the_file(oil_file, tmp_path):
    c = load_case("zhang2016", **{"lubricant.file": str(oil_file), "lubricant.density": "900 kg/m^3"})
    text = c.to_toml()
    assert "file_text" in text
    again = loads_case(text, str(tmp_path / "saved.toml"))
    assert again.lubricant == c.lubricant and again.lubricant.density == 900.0
    oil_file.unlink()  # the archived copy is used when the file is gone
    gone = loads_case(text, str(tmp_path / "saved.toml"))
    assert ehl.lubricant_parameters(gone) == ehl.lubricant_parameters(c)
    # the file's content is part of the case text, so of the archive hash
    other = tmp_path / "other.toml"
    other.write_text(GOOD.replace("27.6 mm^2/s", "30 mm^2/s"))
    c5 = load_case("zhang2016", **{"lubricant.file": str(other)})
    assert c5.to_toml() != text


def test_path_relative_to_the_case_file(tmp_path):
    (tmp_path / "oils").mkdir()
    (tmp_path / "oils" / "x.toml").write_text(GOOD)
    from hsbearing.case import read_case_text

    case_text = read_case_text(load_case("zhang2016").source).replace('oil = "4109"', 'file = "oils/x.toml"')
    p = tmp_path / "case.toml"
    p.write_text(case_text)
    c = load_case(str(p))
    assert c.lubricant.definition.name == "my oil"


def test_sweep_accepts_oil_names_bundled_names_and_files(oil_file):
    from hsbearing.workflows import sweeps

    base = load_case("zhang2016")
    plan = sweeps.plan_sweep(base, {"oil": f"4109,4106,4050,mobil_jet_oil_ii,{oil_file}"}, kind="quasistatic")
    cases = [pt.case for pt in plan.points]
    assert all(c is not None for c in cases), [pt.error for pt in plan.points]
    etas = [ehl.lubricant_parameters(c)["eta"] for c in cases]
    assert len({round(e, 12) for e in etas}) == 4  # 4106 and Mobil Jet Oil II share the class points
    assert etas[2] < 0.85 * etas[1]  # 4050 is not 4106 inside the model
    plan = sweeps.plan_sweep(base, {"lubricant.file": f"4109,4050,{oil_file}"}, kind="quasistatic")
    assert all(pt.case is not None for pt in plan.points)
    assert len({pt.hash for pt in plan.points}) == 3


# ----------------------------------------------------------------------------- the CLI


def test_check_prints_the_oil_and_warns_when_alpha_is_estimated(oil_file, capsys):
    rc, out, err = _cli(["check", "--set", f"lubricant.file={oil_file}"], capsys)
    assert rc == 0, err
    assert "lubricant: my oil" in out and "warning: alpha of my oil is ESTIMATED (so_klaus_1980" in out
    rc, out, _ = _cli(["check"], capsys)
    assert "lubricant: oil 4109 (built-in)" in out and "ESTIMATED" not in out


BAD = [
    ("no viscosity", GOOD.replace('viscosity = [["40 degC", "27.6 mm^2/s"], ["100 degC", "5.1 mm^2/s"]]\n', ""),
     "viscosity", "missing required key"),
    ("one point", GOOD.replace(', ["100 degC", "5.1 mm^2/s"]', ""), "viscosity", "two or more"),
    ("rising", GOOD.replace("5.1 mm^2/s", "51 mm^2/s"), "viscosity", "must fall"),
    ("no unit", GOOD.replace('"27.6 mm^2/s"', "27.6"), "viscosity[0]", "is not"),
    ("wrong dimension", GOOD.replace("27.6 mm^2/s", "27.6 mm"), "viscosity[0]", "is not"),
    ("mixed kinds", GOOD.replace("5.1 mm^2/s", "5 mPa*s"), "viscosity", "mixes"),
    ("unknown key", 'viscosty_index = 1\n' + GOOD, "viscosty_index", "did you mean 'viscosity_index'"),
    ("unknown correlation", GOOD.replace('"so_klaus_1980"', '"gold_2001"'), "pressure_viscosity_coefficient", "unknown correlation"),
    ("absurd alpha", GOOD.replace('"so_klaus_1980"', '"1.8e-6 1/Pa"'), "pressure_viscosity_coefficient", "outside"),
    ("unknown traction oil", GOOD.replace('oil = "4106"', 'oil = "4107"'), "traction.oil", "unknown registered oil"),
    ("unknown law", GOOD.replace('law = "default"', 'law = "eyring"'), "traction.law", "unknown traction law"),
    ("bad traction model", GOOD.replace('oil = "4106"', 'model = "eyrin"'), "traction.model", "did you mean 'eyring'"),
    ("bad density", GOOD.replace("1003 kg/m^3", "10 kg/m^3"), "density", "not the density of a lubricant"),
    ("malformed", GOOD.replace("[traction]", "[traction"), None, "malformed TOML"),
]


@pytest.mark.parametrize("label,text,key,words", BAD, ids=[b[0] for b in BAD])
def test_bad_lubricant_file_one_line_error(label, text, key, words, tmp_path, capsys):
    p = tmp_path / "bad_oil.toml"
    p.write_text(text)
    rc, out, err = _cli(["check", "--set", f"lubricant.file={p}"], capsys)
    assert rc == 2 and out == ""
    lines = err.strip().splitlines()
    assert len(lines) == 1, err
    prefix = f"hsbearing: error: {p}: " + (f"{key}: " if key else "")
    assert lines[0].startswith(prefix), lines[0]
    assert words in lines[0]


def test_missing_lubricant_file_and_unknown_oil_one_line(capsys):
    rc, _, err = _cli(["check", "--set", "lubricant.file=nowhere/oil.toml"], capsys)
    assert rc == 2 and len(err.strip().splitlines()) == 1
    assert "lubricant.file: no such lubricant file or bundled lubricant 'nowhere/oil.toml'" in err
    rc, _, err = _cli(["check", "--set", "oil=mobil_jet_2"], capsys)
    assert rc == 2 and len(err.strip().splitlines()) == 1
    assert "unknown oil 'mobil_jet_2'" in err and "mobil_jet_oil_ii" in err


def test_oils_lists_the_library(capsys):
    rc, out, err = _cli(["oils"], capsys)
    assert rc == 0, err
    for name in ("4109", "4106", "4050", "mobil_jet_oil_ii", "mil_prf_7808_grade3"):
        assert any(line.startswith(name + " ") for line in out.splitlines()), name
    assert "est. (so_klaus_1980)" in out


def test_oils_at_a_case_prints_the_contacts_and_draws_mu(oil_file, tmp_path, capsys):
    png = tmp_path / "mu.png"
    rc, out, err = _cli(["oils", str(oil_file), "--at", "zhang2016", "-o", str(png)], capsys)
    assert rc == 0, err
    assert "inner contact" in out and "outer contact" in out and "lambda" in out and "ESTIMATED" in out
    assert png.is_file() and png.read_bytes()[:4] == b"\x89PNG"


@pytest.mark.slow
def test_short_dynamic_run_with_a_user_oil_file(oil_file, tmp_path, capsys):
    """Done-when of issue 26: `hsbearing run --set lubricant.file=my_oil.toml` (1 ms; slow: numba compile when the
    cache is cold).  Run by hand this session: status ok, 386 CVODE steps."""
    out = tmp_path / "run.nc"
    rc, stdout, err = _cli(["run", "--set", f"lubricant.file={oil_file}", "--duration", "1ms", "--no-figure", "-q",
                            "-o", str(out)], capsys)
    assert rc == 0, err
    assert "status: ok" in stdout and out.is_file()


# ----------------------------------------------------------------------------- data-sheet values only

DATA_SHEET_ONLY = """\
name = "VG 32 sheet"
viscosity = [["40 degC", "32 mm^2/s"], ["100 degC", "5.4 mm^2/s"]]
density = "0.86 g/cm^3"
"""


def test_data_sheet_only_file_gets_the_recommended_law_and_notices(tmp_path, capsys):
    """No [traction] table and no alpha (what a data sheet gives): accepted with models.traction.RECOMMENDED_LAW
    (its default constants), alpha estimated, and a one-line notice for each."""
    from hsbearing.models import traction

    p = tmp_path / "vg32.toml"
    p.write_text(DATA_SHEET_ONLY)
    d = lubricant.load_lubricant(p)
    assert d.traction_recommended and d.traction_model == traction.RECOMMENDED_LAW
    assert d.alpha_estimate == lubricant.ALPHA_ESTIMATES[0]
    case = load_case("zhang2016", **{"lubricant.file": str(p)})
    assert case.lubricant.traction_law == traction.RECOMMENDED_LAW
    ns = lubricant.notices(case.lubricant)
    assert any("no [traction] table" in n and traction.RECOMMENDED_LAW in n for n in ns), ns
    assert any("alpha" in n and "estimated" in n for n in ns), ns
    assert all("\n" not in n for n in ns)
    assert "recommended law" in lubricant.provenance(case.lubricant)
    # the same law as a file that asks for it explicitly (with its default constants)
    q = tmp_path / "explicit.toml"
    q.write_text(DATA_SHEET_ONLY + 'pressure_viscosity_coefficient = "so_klaus_1980"\n[traction]\nmodel = "'
                 + traction.RECOMMENDED_LAW + '"\n')
    e = lubricant.load_lubricant(q)
    assert e.eyring == d.eyring and not e.traction_recommended
    rc, out, err = _cli(["check", "--set", f"lubricant.file={p}"], capsys)
    assert rc == 0, err
    assert "recommended law" in out
