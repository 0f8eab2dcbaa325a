"""``hsbearing run --extend``: an undetermined run is continued until its label is determined or the budget is spent
(hsbearing.systems.angular_contact.extend).  The continuation is a synthetic one here (a whirl whose radius grows
logistically and saturates, re-generated over the longer span and annotated like a real run), so the loop, the
steps and what the archive records are tested without the dynamic model; bad input of the CLI exits 2.
"""

from __future__ import annotations

import json
import math
import subprocess
import sys

import numpy as np
import pytest
import xarray as xr

from hsbearing.analysis import annotate
from hsbearing.systems.angular_contact.extend import MIN_STEP_FRACTION, extend_until_determined, next_step

W = 2 * math.pi * 96.0
DT = 50e-6


def _orbit(t_end, radius):
    t = np.arange(int(round(t_end / DT)) + 1) * DT
    r = radius(t)
    th = 0.97 * W * t
    dr = np.gradient(r, t)
    ds = xr.Dataset({"cage_speed": ("time", np.full_like(t, W)), "cage_angle": ("time", W * t),
                     "cage_center_y": ("time", r * np.cos(th)), "cage_center_z": ("time", r * np.sin(th)),
                     "cage_velocity_y": ("time", dr * np.cos(th) - r * 0.97 * W * np.sin(th)),
                     "cage_velocity_z": ("time", dr * np.sin(th) + r * 0.97 * W * np.cos(th))},
                    coords={"time": t}, attrs={"guide_clearance": 200e-6})
    return annotate(ds)


def logistic(t, sigma=8.0, r0=2e-6, rsat=100e-6):
    return rsat / (1 + (rsat / r0 - 1) * np.exp(-sigma * t))


def _continuation(radius, calls):
    def cont(ds, duration):
        calls.append(duration)
        return _orbit(float(ds["time"].values[-1]) + duration, radius)
    return cont


def test_growing_whirl_is_extended_until_it_saturates():
    ds = _orbit(0.3, logistic)
    assert ds.attrs["classification"] == "undetermined" and "growing" in ds.attrs["classification_reason"]
    step, why = next_step(ds)
    assert "growing" in why and step >= MIN_STEP_FRACTION * 0.3
    calls = []
    out = extend_until_determined(ds, 3.0, continue_fn=_continuation(logistic, calls))
    assert out.attrs["classification"] == "1 period", out.attrs["classification_reason"]
    assert out.attrs["extension_stop_reason"].startswith("determined: 1 period")
    ext = json.loads(out.attrs["extensions"])
    assert len(ext) == len(calls) >= 1
    assert ext[0]["label_before"] == "undetermined" and ext[0]["growth_rate"] > 0  # the growth rate is reported
    assert ext[-1]["label_after"] == "1 period"
    assert float(out["time"].values[-1]) <= 3.0 + 1e-9
    # the saturated orbit: the whirl amplitude is the saturation radius (read on the saturated part only)
    assert float(out["whirl_amplitude"]) == pytest.approx(100e-6, rel=0.015)
    assert out.attrs["transient_rule"].startswith("a whirl that grew from the start")


def test_budget_ends_a_whirl_that_keeps_growing():
    grow = lambda t: 1e-6 * np.exp(5.0 * t)  # noqa: E731 - e-folding 0.2 s, never saturates
    ds = _orbit(0.3, grow)
    calls = []
    out = extend_until_determined(ds, 1.0, continue_fn=_continuation(grow, calls))
    assert out.attrs["classification"] == "undetermined"
    assert out.attrs["extension_stop_reason"].startswith("budget: 1 s")
    assert float(out["time"].values[-1]) == pytest.approx(1.0, abs=DT)
    assert sum(calls) == pytest.approx(0.7, abs=DT)


def test_a_determined_run_is_not_extended():
    ds = _orbit(0.3, lambda t: np.full_like(t, 80e-6))
    out = extend_until_determined(ds, 3.0, continue_fn=lambda d, s: pytest.fail("extended a determined run"))
    assert out.attrs["extension_stop_reason"] == "determined: 1 period (no extension needed)"
    assert json.loads(out.attrs["extensions"]) == []


@pytest.mark.parametrize("extra,what", [(["--max-duration", "1s"], "only with --extend"),
                                        (["--extend", "--max-duration", "0.01s"], "at least the run's duration")])
def test_cli_extend_bad_input(tmp_path, extra, what):
    r = subprocess.run([sys.executable, "-m", "hsbearing.cli", "run", "zhang2016", "--duration", "0.05s",
                        "-o", str(tmp_path / "r.nc"), *extra], capture_output=True, text=True, timeout=300)
    assert r.returncode == 2 and what in r.stderr, r.stderr
    assert not list(tmp_path.iterdir())


# ----------------------------------------------------------------------------- maps, sweeps and studies
# Every point extended in its worker before its archive is reduced (keep="answer"), with a synthetic continuation
# (tests/helpers/extendable_runs.py: a steady circle, a whirl that saturates, one that keeps growing).

from extendable_runs import growing_whirl_run  # noqa: E402 - the helpers folder is on the path (conftest)

from hsbearing.results import open_run  # noqa: E402
from hsbearing.systems.angular_contact.extend import extension_wanted  # noqa: E402
from hsbearing.workflows import sweeps  # noqa: E402
from hsbearing.workflows.maps import run_map  # noqa: E402

LOADS = "500,1000,2000N"


def _map(out, **kw):
    kw.setdefault("jobs", 1)
    return run_map("zhang2016", ("operating.axial_load", LOADS), ("lubricant.oil", "4109"), out_dir=out,
                   duration="0.3 s", point_fn=growing_whirl_run, progress=False, figure=False, **kw)


def test_map_points_are_extended_in_the_worker_before_the_archive_is_reduced(tmp_path):
    ds = _map(tmp_path / "m")
    reasons = [str(r) for r in ds["extension_stop_reason"].values.ravel()]
    counts = ds["extension_count"].values.ravel()
    labels = [str(v) for v in ds["classification"].values.ravel()]
    # 500 N: determined at 0.3 s, left alone
    assert counts[0] == 0 and reasons[0] == "determined: 1 period (no extension needed)" and labels[0] == "1 period"
    assert float(ds["simulated_time"].values.ravel()[0]) == pytest.approx(0.3, abs=DT)
    # 1000 N: extended until its whirl saturated, classified on the saturated orbit (the saturation radius)
    assert counts[1] >= 1 and reasons[1].startswith("determined: 1 period after") and labels[1] == "1 period"
    assert float(ds["whirl_amplitude"].values.ravel()[1]) == pytest.approx(100e-6, rel=0.03)
    assert ds["extension_growth_rate"].values.ravel()[1] > 0
    # 2000 N: still growing when the default budget (6 x 0.3 s) is spent; its growth rate is reported
    assert labels[2] == "undetermined" and reasons[2].startswith("budget: 1.8 s")
    assert float(ds["simulated_time"].values.ravel()[2]) == pytest.approx(1.8, abs=DT)
    assert ds["extension_growth_rate"].values.ravel()[2] == pytest.approx(5.0, rel=0.2)
    assert ds["extension_growth_rate"].attrs["units"] == "1/s"
    assert "1.8 s simulated time" in ds.attrs["sweep_extension"]
    # the kept archive: the whole extended orbit, the extensions and why they stopped, the saturated orbit
    a = open_run(tmp_path / "m" / str(ds["archive"].values.ravel()[1]))
    assert a.attrs["keep"] == "answer" and "time_decimated" in a.dims
    ext = json.loads(a.attrs["extensions"])
    assert len(ext) == counts[1] and ext[0]["label_before"] == "undetermined" and ext[0]["growth_rate"] > 0
    assert float(a["time"].values[-1]) == pytest.approx(ext[-1]["to"], abs=DT)
    assert a.attrs["extension_saturated_orbit"].startswith("saturated orbit over ")
    assert a.attrs["extension_max_duration"] == pytest.approx(1.8)


def test_extended_map_resumes_and_equals_two_processes(tmp_path):
    one = _map(tmp_path / "m")
    again = _map(tmp_path / "m")
    assert again.attrs["sweep_points_resumed"] == 3 and again.attrs["map_points_computed"] == 0
    two = _map(tmp_path / "j2", jobs=2)
    for v in ("classification", "extension_count", "extension_stop_reason", "simulated_time", "whirl_amplitude",
              "archive"):
        xr.testing.assert_identical(one[v].reset_coords(drop=True), two[v].reset_coords(drop=True))


def test_extended_map_on_dask_equals_local(tmp_path):
    import distributed  # a locked dependency: a missing one fails here, never skips

    local = _map(tmp_path / "local")
    with distributed.LocalCluster(n_workers=1, threads_per_worker=1, processes=True, host="127.0.0.1",
                                  dashboard_address=None) as cluster:
        remote = _map(tmp_path / "dask", scheduler=cluster.scheduler_address, jobs=None)
    assert remote.attrs["sweep_backend"].startswith("dask tcp://127.0.0.1")
    for v in ("classification", "extension_count", "extension_stop_reason", "simulated_time", "archive"):
        xr.testing.assert_identical(local[v].reset_coords(drop=True), remote[v].reset_coords(drop=True))


def test_the_budget_is_part_of_the_point_hash(tmp_path):
    """Extended, differently extended and unextended points never share an archive (resume cannot mix them)."""
    names = {}
    for ext in ("default", "1.5 s", None):
        plan = sweeps.plan_sweep("zhang2016", {"axial_load": "1000N"}, duration="0.3 s", point_fn=growing_whirl_run,
                                 extend=ext)
        names[ext] = plan.points[0].archive
        want = {"default": 1.8, "1.5 s": 1.5}.get(ext) if ext else None
        assert plan.points[0].extend == (pytest.approx(want) if want else None)
    assert len(set(names.values())) == 3
    # a stand-in point function without a continuation is never extended (and keeps its hash)
    from study_fakes import fake_dynamics

    a = sweeps.plan_sweep("zhang2016", {"axial_load": "1000N"}, duration="0.3 s", point_fn=fake_dynamics,
                          extend="default").points[0]
    b = sweeps.plan_sweep("zhang2016", {"axial_load": "1000N"}, duration="0.3 s", point_fn=fake_dynamics).points[0]
    assert a.extend is None and a.archive == b.archive


def test_a_budget_below_the_duration_is_an_input_error(tmp_path):
    from hsbearing.case import CaseError

    with pytest.raises(CaseError, match="max_duration.*at least the run's duration"):
        _map(tmp_path / "bad", extend="0.1 s")
    assert not (tmp_path / "bad").exists()


def test_what_asks_for_an_extension():
    grow = _orbit(0.3, lambda t: 1e-6 * np.exp(5.0 * t))
    assert extension_wanted(grow)[0]
    stopped = grow.copy()
    stopped.attrs["stopped_at"] = 0.3  # the stop rule ended it as converged: not extended
    assert not extension_wanted(stopped)[0]
    irregular = grow.copy()
    irregular.attrs.update(classification_details=json.dumps({"kind": "irregular"}),
                           classification_reason="aperiodic irregular section, the chaos indicators do not agree")
    ok, why = extension_wanted(irregular)
    assert not ok and "without an estimate" in why
    irregular.attrs["classification_reason"] += "; run longer"
    assert extension_wanted(irregular)[0]
    out = extend_until_determined(stopped, 3.0, continue_fn=lambda d, s: pytest.fail("extended a converged run"))
    assert out.attrs["extension_stop_reason"].startswith("not extended: the stop rule")


def test_a_failed_continuation_keeps_the_run_in_a_map_point():
    from hsbearing.errors import SolverError

    ds = _orbit(0.3, lambda t: 1e-6 * np.exp(5.0 * t))

    def fails(d, s):
        raise SolverError("CVODE: too much work", partial=None)

    with pytest.raises(SolverError):
        extend_until_determined(ds, 1.0, continue_fn=fails)
    out = extend_until_determined(ds, 1.0, continue_fn=fails, keep_on_failure=True)
    assert out.attrs["extension_stop_reason"].startswith("failed: the extension 0.3 -> ")
    assert float(out["time"].values[-1]) == pytest.approx(0.3)


def test_study_points_are_extended(tmp_path):
    from hsbearing.workflows.study import run_study

    res = run_study("zhang2016", tmp_path / "s", jobs=1, duration="0.3 s", point_fn=growing_whirl_run,
                    progress=False, tables=["table3"])
    ds = res["tables"]["table3"]
    assert "extension_stop_reason" in ds and "1.8 s of simulated time" in res["extension"]
    assert "- extension: " in res["report"].read_text()


@pytest.mark.parametrize("extra,what", [(["--no-extend", "--max-duration", "3s"], "not with --no-extend"),
                                        (["--max-duration", "0.01s"], "at least the run's duration")])
def test_map_cli_extension_bad_input(tmp_path, extra, what):
    r = subprocess.run([sys.executable, "-m", "hsbearing.cli", "map", "zhang2016", "--x", "axial_load=1,2kN",
                        "--y", "inner_speed=1000,2000rpm", "--duration", "0.05s", "-o", str(tmp_path / "m"), *extra],
                       capture_output=True, text=True, timeout=300)
    assert r.returncode == 2 and what in r.stderr, r.stderr
    assert not (tmp_path / "m").exists()


@pytest.mark.parametrize("extra,what", [(["--max-duration", "3s"], "only with --extend"),
                                        (["--extend", "--max-duration", "0.01s"], "at least the run's duration"),
                                        (["--extend", "--kind", "quasistatic"], "only with --kind run")])
def test_sweep_cli_extension_bad_input(tmp_path, extra, what):
    r = subprocess.run([sys.executable, "-m", "hsbearing.cli", "sweep", "zhang2016", "--vary", "axial_load=1,2kN",
                        "--duration", "0.05s", "-o", str(tmp_path / "s"), *extra],
                       capture_output=True, text=True, timeout=300)
    assert r.returncode == 2 and what in r.stderr, r.stderr
    assert len(r.stderr.strip().splitlines()) == 1
    assert not (tmp_path / "s").exists()


def test_sweep_cli_extension_of_another_system_is_an_input_error(tmp_path):
    r = subprocess.run([sys.executable, "-m", "hsbearing.cli", "sweep", "dgbb_6206", "--vary", "radial_load=1,2kN",
                        "--extend", "-o", str(tmp_path / "s")], capture_output=True, text=True, timeout=300)
    assert r.returncode == 2 and "cannot be extended" in r.stderr, r.stderr
    assert not (tmp_path / "s").exists()


@pytest.mark.parametrize("extra,expected", [([], None), (["--extend"], "default"),
                                            (["--extend", "--max-duration", "2s"], "2s")])
def test_sweep_cli_passes_the_extension_to_the_sweep(tmp_path, monkeypatch, extra, expected):
    """``hsbearing sweep --extend [--max-duration T]`` (opt-in, as ``run --extend``) reaches run_sweep's ``extend=``."""
    from hsbearing.cli.parser import build_parser
    from hsbearing.workflows.sweeps import cli as sweep_cli

    seen = {}

    def fake_run_sweep(case, vary, **kw):
        seen.update(kw)
        raise SystemExit(0)

    monkeypatch.setattr(sweep_cli, "run_sweep", fake_run_sweep)
    args = build_parser().parse_args(["sweep", "zhang2016", "--vary", "axial_load=1,2kN", "-o", str(tmp_path / "s"),
                                      *extra])
    with pytest.raises(SystemExit):
        sweep_cli.cli_main(args)
    assert seen["extend"] == expected
# Linear-regime fast-forward of a growing whirl (extend.plan_fast_forward), proven on the Hopf normal form
# (tests/helpers/extendable_runs.py: the Stuart-Landau whirl, limit cycle of radius SL_A at SL_W - SL_BETA, exact;
# its continuation starts from the stored final_state, so the scaled state is what is continued).

from extendable_runs import SL_A, SL_BETA, SL_R0, SL_SIGMA, SL_W, continue_hopf_whirl, hopf_whirl_run, sl_integrate  # noqa: E402

from hsbearing.case import load_case  # noqa: E402
from hsbearing.systems.angular_contact.extend import (  # noqa: E402
    FAST_FORWARD_FRACTION,
    FAST_FORWARD_TWIN_TIME,
    apply_fast_forward,
    plan_fast_forward,
)


def _hopf(duration=0.3):
    return hopf_whirl_run(load_case("zhang2016"), duration)


def _first_crossing(t, r, level):
    i = int(np.argmax(r >= level))
    assert r[i] >= level
    return t[i - 1] + (level - r[i - 1]) / (r[i] - r[i - 1]) * (t[i] - t[i - 1])


def test_fast_forward_reaches_the_limit_cycle_of_the_full_run():
    ds = _hopf(0.3)
    assert ds.attrs["classification"] == "undetermined"
    ff = extend_until_determined(ds, 6.0, continue_fn=continue_hopf_whirl, fast_forward=True)
    full = extend_until_determined(ds, 6.0, continue_fn=continue_hopf_whirl)
    plan = json.loads(ff.attrs["fast_forward"])
    # the rule: the run and its kicked twin continued FAST_FORWARD_TWIN_TIME, then moved along their difference to
    # FAST_FORWARD_FRACTION of the 200 um clearance; k = target / amplitude at that time
    t1 = 0.3 + FAST_FORWARD_TWIN_TIME
    r1 = SL_R0 * math.exp(SL_SIGMA * t1)
    assert plan["at"] == pytest.approx(t1) and plan["amplitude_after"] == pytest.approx(FAST_FORWARD_FRACTION * 200e-6)
    assert plan["amplitude_before"] == pytest.approx(r1, rel=0.06)  # RMS over the last tau/2: 5 % below the end
    # one mode: exactly aligned; the end radius is e^(sigma tau/4) = 2.5 % above the RMS over the last tau/2
    assert plan["radius_after"] == pytest.approx(plan["amplitude_after"] * math.exp(SL_SIGMA * FAST_FORWARD_TWIN_TIME / 4), rel=0.005)
    assert plan["sigma"] == pytest.approx(SL_SIGMA, rel=0.01)
    assert plan["equivalent_time"] == pytest.approx(math.log(plan["factor"]) / plan["sigma"])
    # same answer as the full run and as the exact limit cycle: label, radius (1 %), frequency (1 %)
    f_exact = (SL_W - SL_BETA) / W
    for run in (ff, full):
        assert run.attrs["classification"] == "1 period"
        assert float(run["whirl_amplitude"]) == pytest.approx(SL_A, rel=0.01)
        assert float(run["whirl_frequency_ratio"]) == pytest.approx(f_exact, rel=0.01)
    # at less simulated time
    assert ff["time"].values[-1] < 0.7 * full["time"].values[-1]
    # the time shift: the scaled run reaches half the limit cycle ln(k)/sigma earlier than the unscaled motion
    # (exact Stuart-Landau solution r(t) = a / sqrt(1 + (a^2/r0^2 - 1) exp(-2 sigma t)); within 5 % of ln(k)/sigma)
    t_exact = math.log((SL_A ** 2 / SL_R0 ** 2 - 1) / 3.0) / (2 * SL_SIGMA)
    after = ff["time"].values > plan["at"]
    r = np.hypot(ff["cage_center_y"].values, ff["cage_center_z"].values)
    t_ff = _first_crossing(ff["time"].values[after], r[after], 0.5 * SL_A)
    assert t_exact - t_ff == pytest.approx(plan["equivalent_time"], rel=0.05)
    # the independent integration agrees with the exact solution (the reference is right)
    n = int(round(2.0 / 1e-4))
    w = sl_integrate(SL_R0, n)
    assert _first_crossing(np.arange(n + 1) * 1e-4, abs(w), 0.5 * SL_A) == pytest.approx(t_exact, abs=2e-4)
    # recorded: where the jump was, the classification over the part after it only
    ext = json.loads(ff.attrs["extensions"])
    assert "fast_forward" in ext[0] and ext[0]["why"].startswith("growing whirl after the fast-forward")
    assert float(ff.attrs["transient_discarded"]) > plan["at"]
    assert ff.attrs["extension_saturated_orbit"].startswith("saturated orbit over ")
    assert "fast_forward" not in full.attrs  # only on request


def test_the_twin_kick_scales_only_the_cage_centre_about_its_orbit_centre():
    ds = _hopf(0.3)
    plan, why = plan_fast_forward(ds)
    assert why == "planned"
    out = apply_fast_forward(ds, plan)
    names = [str(n) for n in ds["state"].values]
    before, after = ds["final_state"].values, out["final_state"].values
    refs = {"y_c": plan["orbit_centre"][0], "z_c": plan["orbit_centre"][1],
            "ydot_c": plan["mean_velocity"][0], "zdot_c": plan["mean_velocity"][1]}
    for n, ref in refs.items():
        i = names.index(n)
        assert after[i] - ref == pytest.approx(plan["factor"] * (before[i] - ref), rel=1e-12)
    assert ds["final_state"].values[0] == before[0]  # the input is not modified


@pytest.mark.parametrize("what", ["determined", "near target", "not growing", "no cage state"])
def test_no_fast_forward_outside_the_linear_regime(what):
    if what == "determined":
        ds = _orbit(0.3, lambda t: np.full_like(t, 80e-6))
        want = "determined"
    elif what == "near target":  # 0.3 s: 0.45 x 20 um, within the factor 2 of the target
        ds = hopf_whirl_run(load_case("zhang2016"), 0.3)
        ds = ds.assign(cage_center_y=ds["cage_center_y"] * 60, cage_center_z=ds["cage_center_z"] * 60)
        want = "within a factor 2"
    elif what == "not growing":
        ds = _orbit(0.3, lambda t: 50e-6 * np.exp(-5.0 * t))
        want = "not a growing whirl"
    else:  # a run without the cage centre in its state (extendable_runs.growing_whirl_run)
        ds = growing_whirl_run(load_case("zhang2016", **{"operating.axial_load": "2000 N"}), 0.3)
        want = "no cage centre"
    plan, why = plan_fast_forward(ds)
    assert plan is None and want in why


def test_a_failed_continuation_after_a_fast_forward_keeps_the_unscaled_state():
    from hsbearing.errors import SolverError

    ds = _hopf(0.3)

    def fails(d, s):
        raise SolverError("CVODE: too much work", partial=None)

    out = extend_until_determined(ds, 3.0, continue_fn=fails, keep_on_failure=True, fast_forward=True)
    assert out.attrs["extension_stop_reason"].startswith("failed: ")
    np.testing.assert_array_equal(out["final_state"].values, ds["final_state"].values)
    assert "not_done" in json.loads(out.attrs.get("fast_forward", '{"not_done": ""}'))


def test_map_points_are_fast_forwarded(tmp_path):
    ds = run_map("zhang2016", ("operating.axial_load", "1000N"), ("lubricant.oil", "4109"), out_dir=tmp_path / "m",
                 duration="0.3 s", point_fn=hopf_whirl_run, progress=False, figure=False, jobs=1, extend="3 s")
    assert str(ds["classification"].values.ravel()[0]) == "1 period"
    a = open_run(tmp_path / "m" / str(ds["archive"].values.ravel()[0]))
    plan = json.loads(a.attrs["fast_forward"])
    assert plan["factor"] > 10 and plan["at"] == pytest.approx(0.3 + FAST_FORWARD_TWIN_TIME)
    assert float(a["whirl_amplitude"]) == pytest.approx(SL_A, rel=0.01)


@pytest.mark.parametrize("sigma", [3.0, 8.0, 20.0])
def test_a_grown_whirl_is_read_on_its_saturated_part_only(sigma):
    """annotate_saturated against the known logistic radius r(t) = a / (1 + (a/r0 - 1) exp(-sigma t)): the growth
    is cut where r enters the drift test's band (within 5 % of a here, at most 2 revolutions after r = 0.98 a), whatever fraction of the run
    it takes (no 60 % cap), and the amplitude read is a within 1.5 %; with fewer than SATURATED_REVOLUTIONS
    revolutions after it, or an amplitude still changing, the label is not accepted yet."""
    from hsbearing.systems.angular_contact.extend import SATURATED_REVOLUTIONS, annotate_saturated

    a, r0 = 100e-6, 2e-6
    def t_at(x):  # r(t_at(x)) = x a
        return math.log((a / r0 - 1) / (1 / x - 1)) / sigma

    t98 = t_at(0.98)
    rev = 2 * math.pi / W
    # the drift test's reference, the last 25 % of the revolutions, must lie on the saturated orbit
    T = max(t98 + (SATURATED_REVOLUTIONS + 10) * rev, t98 / 0.72)
    out = annotate_saturated(_orbit(T, lambda t: logistic(t, sigma=sigma, r0=r0, rsat=a)), 0.0)
    assert out.attrs["classification"] == "1 period", out.attrs["classification_reason"]
    # cut where r enters the drift test's band (2 % of the reference's median plus half its range below the
    # reference, the last 25 % of the revolutions: here within 5 % of a), not after r is within 2 % of a
    cut = float(out.attrs["transient_discarded"])
    assert t_at(0.95) <= cut <= t98 + 2 * rev
    if t98 / T > 0.65:
        assert cut / T > 0.6  # no 60 % cap: the growth takes most of the run
    # the part read may start up to 5 % below a (above) and its halves agree to 2 %: the amplitude within 1.5 %
    assert float(out["whirl_amplitude"]) == pytest.approx(a, rel=0.015)
    # too few revolutions after the growth: not yet (the time the missing ones take is the next step)
    short = annotate_saturated(_orbit(t98 + 20 * rev, lambda t: logistic(t, sigma=sigma, r0=r0, rsat=a)), 0.0)
    det = json.loads(short.attrs["classification_details"])
    assert short.attrs["classification"] == "undetermined"
    if det["kind"] == "too-few-points":
        assert det["provisional_label"] == "1 period"
        assert 0 < det["run_longer_s"] <= SATURATED_REVOLUTIONS * rev  # the missing revolutions
        assert next_step(short)[0] >= det["run_longer_s"]
    else:  # the classifier itself saw the growth's tail
        assert det["kind"] == "growing"


def test_a_whirl_still_approaching_saturation_is_not_read_as_saturated():
    """A run whose amplitude still changes after the drift test's end of growth (a slow approach: the reference
    band of the drift test is itself still growing) is not labelled: the two halves of the part read differ by
    more than the stop rule's amplitude tolerance."""
    from hsbearing.systems.angular_contact.extend import annotate_saturated

    grow = lambda t: 100e-6 * (1 - 0.3 * np.exp(-0.8 * t))  # noqa: E731 - 30 % below saturation, e-folding 1.25 s
    out = annotate_saturated(_orbit(1.5, grow), 0.0)
    det = json.loads(out.attrs["classification_details"])
    assert out.attrs["classification"] == "undetermined"
    assert det["kind"] == "growing" and "still changes" in det["reason"], det["reason"]
    assert det["run_longer_s"] > 0 and next_step(out)[0] >= det["run_longer_s"]
