"""Viscosity-temperature laws of the oils 4109, 4106, 4050 (hsbearing.models.viscosity; docs/traction.md, "Viscosity").

Literature: the specification-class points of hsbearing.models.viscosity.OIL_SPEC -- MIL-PRF-7808 grade 3
(11.5 mm^2/s at 40 degC, 3.0 mm^2/s at 100 degC) for 4109; MIL-PRF-23699 (Mobil Jet Oil II typical
27.6 and 5.1 mm^2/s) for 4106; for 4050 those 4106 points times Table 1's 4050/4106 viscosity
ratio at 40 and 100 degC -- and Zhang et al. 2016's Table 1 (tests/data/zhang2016_oils.csv).
"""

import math

import numpy as np
import pytest

from hsbearing.case import CaseError, load_case
from hsbearing.models import ehl, traction, viscosity


def _table1_ratio_independent(T_degC):
    """eta_4050 / eta_4106 of Table 1's exponential law, from the CSV transcription (not from the package)."""
    import csv
    from pathlib import Path

    rows = {}
    with open(Path(__file__).resolve().parents[1] / "data" / "zhang2016_oils.csv") as fh:
        for r in csv.DictReader(line for line in fh if not line.startswith("#")):
            rows[r["oil"]] = (float(r["eta0_Pa_s"]), float(r["beta_per_degC"]))
    (e1, b1), (e2, b2) = rows["4050"], rows["4106"]
    return e1 / e2 * math.exp(-(b1 - b2) * (T_degC - 27.0))


CLASS_POINTS = {  # oil: (nu40, nu100) [mm^2/s], the published class values quoted in the module docstring
    "4109": (11.5, 3.0),
    "4106": (27.6, 5.1),
    # 4050: 4106's class points x Table 1's eta(4050)/eta(4106) at 40 and 100 degC
    "4050": (27.6 * _table1_ratio_independent(40.0), 5.1 * _table1_ratio_independent(100.0)),
}


def test_4050_is_an_oil_of_its_own():
    """Issue 26: 4050 no longer shares 4106's class curve.  Its points are 28.78 and 4.319 mm^2/s (Table 1 ratios
    1.0428 at 40 degC, 0.8469 at 100 degC): thicker than 4106 cold, thinner hot (2.40 vs 2.94 mPa s at 130 degC
    at 960 kg/m^3)."""
    assert CLASS_POINTS["4050"] == pytest.approx((28.781, 4.3190), rel=1e-4)
    eta = {o: float(viscosity.dynamic_viscosity(o, 403.15, "walther", density=960.0)) for o in ("4106", "4050")}
    assert eta["4050"] == pytest.approx(2.401e-3, rel=2e-3) and eta["4106"] == pytest.approx(2.936e-3, rel=2e-3)
    c6 = ehl.lubricant_parameters(load_case("zhang2016", oil="4106"))
    c5 = ehl.lubricant_parameters(load_case("zhang2016", oil="4050"))
    assert c5["eta"] < 0.85 * c6["eta"] and c5["alpha"] == 2.02e-8 and c6["alpha"] == 1.85e-8


@pytest.mark.parametrize("oil", ["4109", "4106", "4050"])
def test_walther_passes_through_the_cited_class_data_consistency(oil):
    """CONSISTENCY, not validation: the Walther coefficients are fitted through these two class points, so the
    law reproduces them exactly by construction (asserted 1e-12, measured 4e-15); this checks that the fit is
    the one the package uses, for kinematic viscosity through the density of the dynamic one."""
    nu40, nu100 = CLASS_POINTS[oil]
    rho = 960.0
    eta = viscosity.dynamic_viscosity(oil, np.array([313.15, 373.15]), "walther", density=rho)
    np.testing.assert_allclose(eta / rho * 1e6, [nu40, nu100], rtol=1e-12)


def test_walther_coefficients_against_an_independent_solution():
    """ASTM D341 through two points solved independently (2x2 linear system in (A, B)) and the
    relation checked to be monotone and log-log linear in between."""
    T = np.array([313.15, 373.15])
    z = np.log10(np.log10(np.array([27.6, 5.1]) + 0.7))
    A, B = np.linalg.solve(np.array([[1.0, -math.log10(T[0])], [1.0, -math.log10(T[1])]]), z)
    got = viscosity.walther_coefficients(313.15, 27.6e-6, 373.15, 5.1e-6)
    assert got == pytest.approx((A, B), rel=1e-12)
    Ts = np.linspace(300.0, 453.15, 50)
    nu = viscosity.walther_kinematic_viscosity(Ts, A, B) * 1e6
    assert np.all(np.diff(nu) < 0)
    zz = np.log10(np.log10(nu + 0.7))
    np.testing.assert_allclose(np.diff(zz) / np.diff(np.log10(Ts)), -B, rtol=1e-9)


def test_table1_law_contradicts_the_class_data():
    """The reason for the walther default: over 27-180 degC Table 1's exponential law is 1.9-2.5 times the
    MIL-PRF-7808 grade-3 class for 4109 at 27-130 degC, 3.6 times below the MIL-PRF-23699 class for 4106 at
    180 degC (4.5 times below 4050's own curve, issue 26), and ranks 4109 above 4106 at 130 degC (3.60 vs 2.14 mPa s) where the classes
    rank 4106 (5 cSt) above 4109 (3 cSt)."""
    rho = 960.0
    T = np.array([27.0, 40.0, 100.0, 130.0, 180.0]) + 273.15
    w = {o: viscosity.dynamic_viscosity(o, T, "walther", density=rho) for o in traction.OILS}
    t = {o: viscosity.dynamic_viscosity(o, T, "table1") for o in traction.OILS}
    r4109 = t["4109"] / w["4109"]
    assert np.all(r4109[:4] > 1.8) and np.all(r4109[:4] < 2.6)
    assert t["4106"][-1] < w["4106"][-1] / 3.0 and t["4050"][-1] < w["4050"][-1] / 4.0
    assert t["4109"][3] > t["4106"][3] and w["4109"][3] < w["4106"][3]
    assert float(t["4109"][3]) == pytest.approx(3.604e-3, rel=1e-3) and float(t["4106"][3]) == pytest.approx(2.138e-3, rel=1e-3)
    # Table 1 misses the class data by far more than the round-off the walther law is held to
    assert abs(float(t["4109"][1]) / rho * 1e6 / 11.5 - 1.0) > 0.5


def test_table1_law_is_the_seed_exponential():
    o = traction.OILS["4106"]
    eta = viscosity.dynamic_viscosity("4106", 403.15, "table1")
    assert float(eta) == pytest.approx(o.eta0 * math.exp(-o.beta * 103.0), rel=1e-12)
    assert float(ehl.viscosity_at_temperature(o.eta0, o.beta, 403.15)) == pytest.approx(float(eta), rel=1e-12)


def test_lubricant_parameters_use_the_selected_law():
    c = load_case("zhang2016")
    assert c.lubricant.viscosity_law == "walther"
    p = ehl.lubricant_parameters(c)
    assert p["eta"] == pytest.approx(float(viscosity.dynamic_viscosity("4109", 403.15, "walther", density=960.0)), rel=1e-12)
    assert 1.8e-3 < p["eta"] < 2.0e-3 and p["alpha"] == 1.28e-8  # alpha stays Table 1's
    c = load_case("zhang2016", **{"lubricant.viscosity_law": "table1"})
    assert ehl.lubricant_parameters(c)["eta"] == pytest.approx(0.033 * math.exp(-0.0215 * 103.0), rel=1e-12)
    # explicit overrides keep their precedence over the law
    c = load_case("zhang2016", **{"lubricant.kinematic_viscosity": "5 mm^2/s"})
    assert ehl.lubricant_parameters(c)["eta"] == pytest.approx(5e-6 * 960.0)


def test_unknown_viscosity_law_is_a_case_error():
    with pytest.raises(CaseError) as e:
        load_case("zhang2016", **{"lubricant.viscosity_law": "vogel"})
    assert e.value.key == "lubricant.viscosity_law" and "walther" in str(e.value)
    with pytest.raises(ValueError, match="known"):
        viscosity.dynamic_viscosity("4109", 400.0, "vogel", density=960.0)
    with pytest.raises(ValueError, match="density"):
        viscosity.dynamic_viscosity("4109", 400.0, "walther")
