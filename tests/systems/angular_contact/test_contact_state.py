"""Contact state over time and the warnings (item 5): hsbearing.systems.angular_contact.contact_state.

The run's contact state is derived from the stored trajectory (loads, angles, entrainment speeds, the kernel's
spin-to-roll); the quasi-static dataset computes the same quantities by its own code (exact Hertz per ball, its
race-control kinematics, its entrainment speeds).  At the dynamic model's initial state (= the quasi-static
equilibrium) both must agree: an independent cross-check over both rotation senses and a radial load.
"""

import math

import numpy as np
import pytest
import xarray as xr

from hsbearing import load_case
from hsbearing.models import limits
from hsbearing.models.geometry import derive
from hsbearing.systems.angular_contact.contact_state import contact_state_variables, format_warnings, warnings_for
from hsbearing.systems.angular_contact.dynamics import build_model, to_dataset

NAMES = ["inner_contact_pressure", "outer_contact_pressure", "inner_contact_semimajor", "outer_contact_semimajor",
         "inner_film_thickness_central", "outer_film_thickness_central", "inner_spin_to_roll", "outer_spin_to_roll"]


def _start(case):
    m = build_model(case)
    ds = to_dataset(m, np.array([0.0, 1e-6]), np.vstack([m.y0, m.y0]), {}, annotate=False)
    return ds, m.info["quasistatic"]


CASES = [
    {},
    {"operating.inner_speed": "-14000 rpm"},
    {"operating.radial_load": "800 N", "operating.axial_load": "1500 N"},
    {"simulation.kinematics": "inner_race_control"},
    {"simulation.kinematics": "inner_race_control", "operating.inner_speed": "-14000 rpm"},
]
IDS = ["default", "reversed", "combined_load", "inner_control", "inner_control_reversed"]


@pytest.mark.parametrize("overrides", CASES, ids=IDS)
def test_contact_state_functions_match_quasistatic(overrides):
    """Same loads, angles and entrainment speeds -> the run's Hertz/EHL functions give the quasi-static
    dataset's p_max, semi-major axis and h_c (exact Hertz per ball there, tabulated a_1(alpha) here):
    measured agreement 1e-6."""
    case = load_case("zhang2016", **overrides)
    from hsbearing import quasi_static

    qs = quasi_static(case)
    wi, wo = case.operating.inner_speed, case.operating.outer_speed
    wm, rb = qs["ball_orbit_speed"].values, qs["ball_center_radial"].values
    ai, ao = qs["inner_contact_angle"].values, qs["outer_contact_angle"].values
    ui = np.abs(wi - wm) * (rb - 0.5 * derive(case).D * np.cos(ai))  # entrainment speeds as the quasi-static solver
    uo = np.abs(wo - wm) * (rb + 0.5 * derive(case).D * np.cos(ao))
    out = contact_state_variables(case, qs["inner_contact_load"].values, qs["outer_contact_load"].values, ai, ao, ui, uo)
    for n in NAMES[:6]:
        assert np.allclose(out[n], qs[n].values, rtol=1e-4, atol=0), n


@pytest.mark.parametrize("overrides", [c for c, i in zip(CASES, IDS) if i != "combined_load"],
                         ids=[i for i in IDS if i != "combined_load"])
def test_run_spin_to_roll_matches_quasistatic_at_the_start(overrides):
    """The run's spin-to-roll (kernel ratio converted to the roll rate relative to the race, sign of the rolling
    sense restored) equals the quasi-static dataset's at the start state, both senses, outer and inner race
    control (measured 1e-8).  Not under a combined load: the dynamic start puts every ball at the cage speed
    (dynamics.initial_state) while the quasi-static balls orbit at their own speeds (1.7 % apart there)."""
    ds, qs = _start(load_case("zhang2016", **overrides))
    for n in ("inner_spin_to_roll", "outer_spin_to_roll"):
        assert np.allclose(ds[n].isel(time=0).values, qs[n].values, rtol=1e-5, atol=1e-7), n


def test_run_pressure_at_the_start_follows_its_loads():
    """The run's p_max at the start is the quasi-static one scaled by (Q_run / Q_qs)^(1/3) (the dynamic start's
    loads differ from the quasi-static ones by up to ~3 % under a combined load)."""
    ds, qs = _start(load_case("zhang2016", **CASES[2]))
    for side in ("inner", "outer"):
        Qr = ds[f"{side}_contact_load"].isel(time=0).values.astype(float)
        Qq = qs[f"{side}_contact_load"].values
        pr = ds[f"{side}_contact_pressure"].isel(time=0).values.astype(float)
        assert np.allclose(pr, qs[f"{side}_contact_pressure"].values * (Qr / Qq) ** (1 / 3), rtol=2e-3)


def test_film_parameter_and_unloaded_contacts():
    case = load_case("zhang2016", **{"materials.ball.surface_roughness": "0.03 um", "materials.races.surface_roughness": "0.04 um"})
    Q = np.array([[500.0, 0.0]])
    al = np.full((1, 2), math.radians(25))
    U = np.array([[10.0, 10.0]])
    out = contact_state_variables(case, Q, Q, al, al, U, U)
    assert out["inner_film_parameter"][0, 0] == pytest.approx(out["inner_film_thickness_minimum"][0, 0] / 0.05e-6, rel=1e-12)
    assert out["inner_contact_pressure"][0, 1] == 0.0 and np.isnan(out["inner_film_parameter"][0, 1])


def _ds(case, **arrays):
    return xr.Dataset({k: (("time", "ball")[: np.ndim(v)], np.asarray(v)) for k, v in arrays.items()})


def test_pressure_and_lambda_warnings():
    case = load_case("zhang2016")
    al = np.full((1, 1), math.radians(25))
    ok = contact_state_variables(case, np.array([[300.0]]), np.array([[300.0]]), al, al, np.array([[10.0]]), np.array([[10.0]]))
    assert warnings_for(_ds(case, **ok), case) == []
    hot = contact_state_variables(case, np.array([[20000.0]]), np.array([[300.0]]), al, al, np.array([[10.0]]), np.array([[10.0]]))
    assert hot["inner_contact_pressure"].max() > 4.2e9
    w = warnings_for(_ds(case, **hot), case)
    assert any("ISO 76" in x for x in w)
    slow = contact_state_variables(case, np.array([[300.0]]), np.array([[300.0]]), al, al, np.array([[0.05]]), np.array([[0.05]]))
    assert slow["inner_film_parameter"].min() < 1
    assert any("lambda" in x for x in warnings_for(_ds(case, **slow), case))


def test_shoulder_truncation_warning_hand_computed():
    """Inner shoulder of zhang2016 (land 38.5 mm): groove bottom d_i = 36.430 mm, r_i = 0.52 * 9.525 = 4.953 mm,
    cos t_s = (18.215 + 4.953 - 19.25) / 4.953 = 0.7911 -> t_s = 37.71 deg (hand-computed).  An ellipse of
    a = 0.8 mm at 25 deg ends at 25 + 0.8/4.953 rad = 34.25 deg (no warning); at 30 deg, 39.25 deg (warning)."""
    case = load_case("zhang2016")
    g = derive(case)
    assert math.degrees(limits.shoulder_angle_inner(g.di, g.ri, 38.5e-3)) == pytest.approx(37.71, abs=0.02)
    for angle, expect in ((25.0, False), (30.0, True)):
        ds = _ds(case, inner_contact_angle=np.full((1, 1), math.radians(angle)), inner_contact_semimajor=np.full((1, 1), 0.8e-3))
        assert any("truncated" in x for x in warnings_for(ds, case)) is expect


def test_cage_orbit_warning():
    case = load_case("zhang2016")
    c = derive(case).guide_clearance
    far = xr.Dataset({"cage_center_y": ("time", [0.0, 0.97 * c]), "cage_center_z": ("time", [0.0, 0.0])})
    near = xr.Dataset({"cage_center_y": ("time", [0.0, 0.5 * c]), "cage_center_z": ("time", [0.0, 0.1 * c])})
    assert any("guide clearance" in x for x in warnings_for(far, case))
    assert warnings_for(near, case) == []
    assert format_warnings([]) == "none" and format_warnings(["a", "b"]) == "a | b"


def test_run_archive_carries_the_warnings_attribute():
    ds, _ = _start(load_case("zhang2016"))
    assert "warnings" in ds.attrs and ("truncated" in ds.attrs["warnings"])  # default case: inner shoulder (see above)
