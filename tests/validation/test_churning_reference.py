"""The churning terms against independent references and the measured heat of NASA TP-2275 (35-mm bearing).

* cage windage (laminar branch): the moment from the von Karman disc solved by tests/helpers/thermal_reference.py (no
  hsbearing import), and Cochran's G'(0) = -0.6159 (Cochran 1934, the literature value, tolerance 2e-4);
* jet-oil acceleration: m_dot v^2 from the case's inputs and the quasi-static cage speed, by hand;
* the TP-2275 35-mm comparison (third-party digitisation, +-3 % reading, +-10-15 % as an oil-enthalpy measurement;
  docs/power_loss.md): VALIDATION only, nothing calibrated on it.  Recorded outcome: the measured heat lies inside
  the band of the total over the drag choices at 28 000 and 72 000 r/min, and the default (mixture at rest, C_D
  subcritical) is the band's upper end.  Tolerances set before looking: the band must contain the measurement
  +-15 %.
"""

import math
import sys
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[2]
sys.path.insert(0, str(ROOT / "tests" / "helpers"))
sys.path.insert(0, str(ROOT / "tools" / "investigations"))
import thermal_reference as ref  # noqa: E402

from hsbearing.models.ball_bearing import churning  # noqa: E402


def test_windage_laminar_against_the_reference_disc():
    G0 = ref.rotating_disk([1.0])["G0p"]
    assert G0 == pytest.approx(-0.6159, abs=2e-4)  # Cochran (1934)
    rho, mu, w, r1, r2 = 850.0, 0.2, 30.0, 0.0453 / 2, 0.051 / 2  # Re = w r2^2 / nu ~ 0.08: laminar
    nu = mu / rho
    M_ref = 2 * 2 * math.pi * (-G0) * rho * math.sqrt(nu) * w**1.5 * (r2**4 - r1**4) / 4  # both faces
    assert -churning.rotating_annulus_windage_moment(w, r1, r2, rho, mu) == pytest.approx(M_ref, rel=1e-3)


@pytest.fixture(scope="module")
def tp2275():
    import numpy as np
    from tp2275_power_loss import MEASURED, case_for

    from hsbearing.systems.angular_contact.rating import quasi_static_power_loss

    rpm = [28000, 72000]
    case = case_for("")  # no bearing designation: the SKF side of hsbearing friction is not available, the loss is
    rows = [quasi_static_power_loss(case, n * math.pi / 30) for n in rpm]
    return case, rpm, [MEASURED[n] for n in rpm], {k: np.array([r[k] for r in rows]) for k in rows[0]}


def test_tp2275_jet_term_by_hand(tp2275):
    case, rpm, _, ds = tp2275
    m_dot = 920.0 * 760e-6 / 60.0
    # the cage speed of the quasi-static state: the orbit speed behind the ball Reynolds number (Re = rho_e v D / mu_e)
    from hsbearing.models.ball_bearing.drag import mixture_density, mixture_viscosity

    for i in range(len(rpm)):
        X = float(ds['cavity_oil_fraction'][i])
        rho_e = mixture_density(920.0, X)
        from hsbearing.systems.angular_contact.dynamics import build_model

        m = build_model(case.with_overrides(**{"operating.inner_speed": f"{rpm[i]} rpm"}))
        v = float(ds['drag_reynolds_number'][i]) * mixture_viscosity(m.info["oil_viscosity"], X) / (rho_e * 7.14e-3)
        assert float(ds['jet_oil_acceleration'][i]) == pytest.approx(m_dot * v * v, rel=1e-9)
        # nominal pure-rolling orbit speed at 24 deg as a sanity bound: the quasi-static one is 0-15 % above it
        # (centrifugal loads turn the contact angles)
        v_nom = rpm[i] * math.pi / 30 / 2 * (1 - 7.14 * math.cos(math.radians(24)) / 46.5) * 0.02325
        assert 1.0 <= v / v_nom <= 1.15


def test_tp2275_measured_heat_inside_the_band(tp2275):
    _, rpm, meas, ds = tp2275
    rest = ds["power_loss"] - ds["drag"]
    lo, hi = rest + ds["drag_band_low"], rest + ds["drag_band_high"]
    for i, H in enumerate(meas):
        assert lo[i] <= 1.15 * H and 0.85 * H <= hi[i], (rpm[i], lo[i], hi[i], H)
        assert float(ds["power_loss"][i]) == pytest.approx(hi[i], rel=1e-12)  # default = upper end


def test_tp2275_mixture_balance_recorded_outcome(tp2275):
    """The mixture's momentum balance on the TP-2275 35-mm bearing (VALIDATION, nothing calibrated; the bounds below
    were set AFTER the first look, they record the outcome of docs/power_loss.md, "The mixture's momentum balance"):
    the co-rotation is ~0.83 and flat in speed (the oil throughflow's hold scales like the balls' drive: rho_e ~ 1/n,
    v ~ n), the churning falls ~20x below the k = 0 drag and the total to ~0.3-0.55 of the measured heat, so the
    balance does NOT bring the speed exponent to the measured 1.44 (it stays ~2, the contacts')."""
    import numpy as np

    from hsbearing.systems.angular_contact.rating import quasi_static_power_loss

    case, rpm, meas, ds = tp2275
    bal = case.with_overrides(**{"friction.mixture_corotation_law": "balance"})
    rows = [quasi_static_power_loss(bal, n * math.pi / 30) for n in rpm]
    k = [r["mixture_corotation"] for r in rows]
    assert all(0.75 < x < 0.9 for x in k) and abs(k[1] - k[0]) < 0.02
    for r, H, d0 in zip(rows, meas, ds["drag"]):
        assert r["mixture_corotation_balance_low"] <= r["mixture_corotation"] <= r["mixture_corotation_balance_high"]
        assert r["drag"] < 0.1 * d0
        assert 0.2 < r["power_loss"] / H < 0.7
    e = float(np.polyfit(np.log(rpm), np.log([r["power_loss"] for r in rows]), 1)[0])
    assert e > 1.8  # measured 1.44
