"""The dynamic kernel's guide-land and pocket films at their thermal factors (``run --thermal``; docs/power_loss.md
"Thermal cage films").

``build_model(case, cage_film_factors=(f_land, f_pocket))`` multiplies the kernel's isothermal film viscosity eta_film
by f_land in the guide-land film and by f_pocket in the pocket films.  Both films are linear in the viscosity
(Reynolds films: pressure and shear stress proportional to eta at a given geometry and kinematics), so proven here
against the isothermal kernel evaluated independently at the same state:

* factors (1, 1) are the default build, bit for bit (every regression archive is a default build);
* with factors, the land film force, moment and power equal the isothermal ones times f_land, the pocket film load
  and power times f_pocket, to 1e-9, and everything else (race contacts, drag) is unchanged exactly -- at the
  quasi-static state and at perturbed states with the cage whirling either way, balls off-centre in their pockets
  on either side (no solid contact: the film alone), for both rotation senses;
* ``run --thermal``: the model gets the factors that ``friction --thermal`` applies at the same case and walls, and
  the run's first sample (the quasi-static state) dissipates in the land and pocket films what ``friction
  --thermal`` reports for them; the archive records the factors; ``friction.thermal_films = off``: factors 1.
"""

from __future__ import annotations

import numpy as np
import pytest

from hsbearing.case import load_case
from hsbearing.models.ball_bearing import kernel_io as kio
from hsbearing.models.ball_bearing.kernel_io import AUX_INDEX as A
from hsbearing.models.ball_bearing.kernel_io import GAUX_INDEX as G
from hsbearing.systems.angular_contact.balances import power_variables
from hsbearing.systems.angular_contact.dynamics import build_model

F_LAND, F_POCKET = 0.63, 0.41  # two different factors, so a mix-up of the films shows

LAND = [G[k] for k in ("F_cy", "F_cz", "M_cx", "P_guide_land")]
POCKET = [A[k] for k in ("Q_film", "P_pocket_film")]


def _whirling_states(m):
    """The quasi-static state, and states with the cage off-centre (0.2-0.6 of the land clearance) whirling either
    way, squeezing, spinning 3 % faster or slower, and the balls off-centre in their pockets on either side with radial
    and axial velocities of both signs: the cage offset (up to 120 um, land clearance 200 um) moves the pockets past
    their 50 um clearance, so some balls touch their pocket wall (film and Hertz contact together), and the last
    state (cage 10 um off) has the pocket films alone."""
    L = m.layout
    Z = L.Z
    c_land, c_p, rm = kio.get(m.P, "c_land"), kio.get(m.P, "c_p"), 0.5 * kio.get(m.P, "dm")
    out = [m.y0.copy()]
    j = np.arange(Z)
    for sgn, r, a in ((1.0, 0.6, 0.4), (-1.0, 0.2, 2.5), (1.0, 0.45, -1.9), (-1.0, 0.05, 0.9)):
        y = m.y0.copy()
        y[L.cage("y_c")], y[L.cage("z_c")] = r * c_land * np.cos(a), r * c_land * np.sin(a)
        wc = float(m.y0[L.cage("phidot_c")])
        v = sgn * 0.3 * r * c_land * wc  # whirl at 0.3 x the cage speed, either way, plus a squeeze
        y[L.cage("ydot_c")] = -v * np.sin(a) + 0.05 * v * np.cos(a)
        y[L.cage("zdot_c")] = v * np.cos(a) + 0.05 * v * np.sin(a)
        y[L.cage("phidot_c")] *= 1.0 + 0.03 * sgn
        y[L.ball("theta_rel_b")] = min(0.6, r) * c_p / rm * np.sin(1.3 * j + a)
        y[L.ball("udot_b")] = 2e-3 * sgn * np.cos(0.7 * j)
        y[L.ball("xdot_b")] = -1e-3 * sgn * np.sin(0.9 * j)
        out.append(y)
    return out


@pytest.fixture(scope="module", params=["forward", "reversed"])
def models(request):
    speed = "30000 rpm" if request.param == "forward" else "-30000 rpm"
    case = load_case("zhang2016").with_overrides(**{"operating.inner_speed": speed})
    iso = build_model(case)
    return case, iso, build_model(case, cage_film_factors=(F_LAND, F_POCKET))


def test_unit_factors_are_the_default_build(models):
    case, iso, _ = models
    one = build_model(case, cage_film_factors=(1.0, 1.0))
    for y in _whirling_states(iso):
        assert np.array_equal(one.f(y), iso.f(y))
        a1, g1 = one.outputs(y)
        a0, g0 = iso.outputs(y)
        assert np.array_equal(a1, a0) and np.array_equal(g1, g0)


def test_films_scale_with_their_factors_at_the_same_state(models):
    _, iso, th = models
    solid = []
    for k, y in enumerate(_whirling_states(iso)):
        a0, g0 = iso.outputs(y)
        a1, g1 = th.outputs(y)
        solid.append(bool(np.any(a0[:, A["Q_solid"]] > 0)))
        assert np.array_equal(a1[:, A["Q_solid"]], a0[:, A["Q_solid"]])  # the Hertz contact is not a film
        if k:  # off-centre: the films carry load
            assert np.all(np.abs(a0[:, A["Q_film"]]) > 0) and abs(g0[G["F_cy"]]) + abs(g0[G["F_cz"]]) > 0
        assert g0[G["P_guide_land"]] > 0 and np.all(a0[:, A["P_pocket_film"]] > 0)
        np.testing.assert_allclose(g1[LAND], F_LAND * g0[LAND], rtol=1e-9, atol=0)
        np.testing.assert_allclose(a1[:, POCKET], F_POCKET * a0[:, POCKET], rtol=1e-9, atol=0)
        # the race contacts and the drag do not see the cage films at a given state
        rest = [A[c] for c in ("Q_i", "Q_o", "T_roll_i", "T_trans_i", "T_roll_o", "T_trans_o", "F_R_i", "F_R_o",
                               "F_D", "P_trac_i", "P_trac_o", "P_ehl_i", "P_ehl_o")]
        assert np.array_equal(a1[:, rest], a0[:, rest])
        p0 = power_variables(a0[None], g0[None])
        p1 = power_variables(a1[None], g1[None])
        assert float(p1["power_loss_guide_land"][0]) == pytest.approx(F_LAND * float(p0["power_loss_guide_land"][0]),
                                                                      rel=1e-9)
        assert float(p1["power_loss_pocket_film"][0]) == pytest.approx(F_POCKET * float(p0["power_loss_pocket_film"][0]),
                                                                       rel=1e-9)
    assert any(solid) and not solid[-1]  # states with a ball on its pocket wall, and the films alone


def test_bad_factors_are_refused():
    case = load_case("zhang2016")
    for bad in ((0.0, 1.0), (1.0, float("nan")), (-1.0, 1.0)):
        with pytest.raises(ValueError, match="cage_film_factors"):
            build_model(case, cage_film_factors=bad)


def test_run_thermal_films_are_friction_thermals_at_the_quasi_static_state():
    """The model of ``run --thermal`` dissipates at its first sample (the quasi-static state) in the land and pocket
    films what ``friction --thermal`` reports for them at that speed (same factors, same walls)."""
    from hsbearing import _thermal_start  # what run --thermal hands the model: case at T_lub, race inlets, walls
    from hsbearing.systems.angular_contact import rating

    case = load_case("zhang2016")
    ct, races, films = _thermal_start(case)
    f = (films["land"]["factor"], films["pocket"]["factor"])
    assert 0.3 < f[0] < 1.0 and 0.3 < f[1] < 1.0  # the films are hotter than the oil: thinner
    m = build_model(ct, race_temperatures=races, cage_film_factors=f)
    aux, gaux = m.outputs(m.y0)
    pv = power_variables(aux[None], gaux[None])
    fr = rating._thermal_row(case, case.operating.inner_speed)
    assert fr["land_film_factor"] == f[0] and fr["pocket_film_factor"] == f[1]
    assert float(pv["power_loss_guide_land"][0]) == pytest.approx(fr["guide_land"], rel=1e-12)
    assert float(pv["power_loss_pocket_film"][0]) == pytest.approx(fr["pocket_film"], rel=1e-12)
    from hsbearing.systems.angular_contact.dynamics import thermal_cage_film_factors

    walls = {k: fr["thermal"][k] for k in ("inner_ring", "outer_ring", "balls", "cage")}
    assert thermal_cage_film_factors(ct, walls, races)["land"]["factor"] == f[0]  # the walls friction --thermal used
    off = thermal_cage_film_factors(ct.with_overrides(**{"friction.thermal_films": "off"}), walls, races)
    assert off["land"]["factor"] == 1.0 and off["pocket"]["factor"] == 1.0


@pytest.mark.slow
def test_run_thermal_continue_reproduces_the_uninterrupted_run(monkeypatch, tmp_path, capsys):
    """``run --thermal`` records the two film factors; ``--continue`` of it rebuilds the kernel with them, and 0.2 +
    0.2 ms continued equals 0.4 ms uninterrupted to the integration tolerance."""
    from hsbearing import cli
    from hsbearing.results import open_run
    from hsbearing.systems.angular_contact import dynamics

    seen = []
    real = dynamics.build_model

    def spy(case, **kw):
        seen.append(kw.get("cage_film_factors"))
        return real(case, **kw)

    monkeypatch.setattr(dynamics, "build_model", spy)
    full, half, cont = tmp_path / "full.nc", tmp_path / "half.nc", tmp_path / "cont.nc"
    common = ["-q", "--no-figure"]
    assert cli.main(["run", "zhang2016", "--thermal", "--duration", "0.4ms", "-o", str(full), *common]) == 0
    assert "cage films: guide land x" in capsys.readouterr().out
    assert cli.main(["run", "zhang2016", "--thermal", "--duration", "0.2ms", "-o", str(half), *common]) == 0
    a, h = open_run(full), open_run(half)
    want = (h.attrs["thermal_guide_land_film_factor"], h.attrs["thermal_pocket_film_factor"])
    assert want[0] < 1.0 and want[1] < 1.0 and seen[-1] == want
    assert "frozen at that state" in h.attrs["thermal_cage_film_rule"]
    assert "thermal_cage_film_rule" in h.attrs["contact_temperatures"]
    seen.clear()
    assert cli.main(["run", "--continue", str(half), "--duration", "0.2ms", "-o", str(cont), *common]) == 0
    assert seen == [want]  # the continuation's one model, with the recorded factors
    c = open_run(cont)
    assert (c.attrs["thermal_guide_land_film_factor"], c.attrs["thermal_pocket_film_factor"]) == want
    case = load_case("zhang2016")
    assert float(a.time[-1]) == pytest.approx(float(c.time[-1]), rel=1e-12)
    err = _weighted_error(a["final_state"].values, c["final_state"].values, case, real(case))
    # an isothermal 0.2 + 0.2 ms continuation: 90 % quantile 30, median 2.2 (test below); the start-up transient
    assert np.quantile(err, 0.9) < 100.0 and np.median(err) < 10.0, (np.quantile(err, 0.9), np.median(err))


def _weighted_error(ya, yc, case, m):
    """|ya - yc| in units of the solver's local error weight rtol |y| + atol (per component)."""
    w = float(case.simulation.rtol) * np.abs(ya) + m.layout.atol(float(case.simulation.atol))
    return np.abs(ya - yc) / w


def test_continue_with_the_factors_is_as_close_as_an_isothermal_continuation():
    """0.2 ms + 0.2 ms continued vs 0.4 ms uninterrupted (the start-up transient: CVODE restarts, so the two differ by
    the integration's global error, measured 2.2 median, 30 at the 90 % quantile, 620 at most in units of the local
    error weight for the isothermal model): with the factors (0.9, 0.8) recorded, the continuation is as close as the
    isothermal one (measured median 1.2, 90 % 21, max 265); continued without them it is far off (median 4.0, 90 %
    1800, max 7500): the continuation rebuilds the model the run used."""
    from hsbearing.systems.angular_contact import dynamics as dy

    case = load_case("zhang2016")
    stats = {}
    for fac in (None, (0.9, 0.8)):
        m = build_model(case, cage_film_factors=fac)
        full = dy.simulate(case, duration=4e-4, model=m, annotate=False)
        half = dy.simulate(case, duration=2e-4, model=m, annotate=False)
        runs = {"isothermal": half} if fac is None else {"dropped": half.copy(), "thermal": half}
        half.attrs.update({} if fac is None else dict(thermal_guide_land_film_factor=fac[0],
                                                      thermal_pocket_film_factor=fac[1]))
        for name, start in runs.items():
            c = dy.continue_run(start, 2e-4)
            err = _weighted_error(full.final_state.values, c.final_state.values, case, m)
            stats[name] = (np.median(err), np.quantile(err, 0.9), np.max(err))
    iso, th, drop = stats["isothermal"], stats["thermal"], stats["dropped"]
    assert all(t < 3.0 * i for t, i in zip(th, iso)), stats
    assert drop[1] > 10.0 * iso[1] and drop[2] > 5.0 * iso[2], stats
