"""Output a user reads (issue 13 items 3, 4, 11-13): figures per archive kind, printed units, help texts,
archive attributes, the first-run compile notice.

Figures are checked on the matplotlib Figure objects the CLI draws (captured at save time), not on pixels.
"""

from __future__ import annotations

import math
import os
import subprocess
import sys
import textwrap
from pathlib import Path

import numpy as np
import pytest
from synthetic_runs import cage_run  # tests/helpers (conftest.py)

import hsbearing
from hsbearing import cli, plotting, systems
from hsbearing.analysis import annotate
from hsbearing.results import ATTR_UNITS, make_dataset, open_run, standard_attrs, write_netcdf

_RPM = 60 / (2 * math.pi)


@pytest.fixture
def figures(monkeypatch):
    """The Figure objects the code saves (plotting.save_figure, which every figure module calls as
    hsbearing.plotting.common.save_figure), in order."""
    got = []
    real = plotting.save_figure

    def capture(fig, path, *a, **k):
        got.append(fig)
        return real(fig, path, *a, **k)

    monkeypatch.setattr(plotting, "save_figure", capture)
    monkeypatch.setattr(plotting.common, "save_figure", capture)
    return got


def _texts(fig) -> str:
    """Every text of a figure: suptitle, axes titles, labels, legend entries, annotations."""
    out = [fig._suptitle.get_text() if fig._suptitle else ""]
    for ax in fig.axes:
        out += [ax.get_title(), ax.get_xlabel(), ax.get_ylabel()]
        leg = ax.get_legend()
        if leg:
            out += [t.get_text() for t in leg.get_texts()]
        out += [t.get_text() for t in ax.texts]
    return "\n".join(out)


def _run_cli(argv, capsys):
    rc = cli.main(argv)
    cap = capsys.readouterr()
    return rc, cap.out, cap.err


# ----------------------------------------------------------------------------- item 3: plot dispatch


def test_plot_of_a_friction_archive_draws_the_torques(tmp_path, capsys, figures):
    nc = tmp_path / "f.nc"
    rc, out, err = _run_cli(["friction", "dgbb_6206", "--speeds", "500,5000,15000rpm", "-o", str(nc)], capsys)
    assert rc == 0, err
    rc, out, err = _run_cli(["plot", str(nc)], capsys)
    assert rc == 0 and err == "" and (tmp_path / "f.png").exists()
    fig = figures[-1]
    text = _texts(fig)
    assert "quasi-static" not in text and "oil 4109" not in text  # the old, wrong figure
    assert "friction torque: dgbb_6206" in text and "Fa = 500 N" in text
    ds = open_run(nc)
    ax = fig.axes[0]
    lines = {ln.get_label(): ln for ln in ax.get_lines()}
    msl = lines["$M_{sl}$ sliding (dgbb_prl method)"]
    assert np.allclose(msl.get_xdata(), ds["speed"].values * _RPM)
    assert np.allclose(msl.get_ydata(), ds["sliding_torque"].values * 1e3)  # N mm
    assert np.allclose(lines["SKF 2004 total $M$"].get_ydata(), ds["skf_total_torque"].values * 1e3)
    assert ax.get_xscale() == "log" and ax.get_ylabel() == "torque [N mm]"
    assert len(fig.axes[1].patches) == ds.sizes["ball"]  # one bar per ball


def test_plot_of_a_preload_archive_draws_torque_and_pressure_with_the_iso_limit(tmp_path, capsys, figures):
    nc = tmp_path / "p.nc"
    rc, out, err = _run_cli(["preload", "shan2010_wire_race", "--preload", "10,40,160um", "-o", str(nc)], capsys)
    assert rc == 0
    rc, _, err = _run_cli(["plot", str(nc)], capsys)
    assert rc == 0 and err == ""
    fig = figures[-1]
    ds = open_run(nc)
    torque = {ln.get_label(): ln for ln in fig.axes[0].get_lines()}
    assert np.allclose(torque["$M_s = M_{sc} + M_u$ (Eq. 11)"].get_ydata(), ds["torque"].values)
    assert np.allclose(torque["$M_s = M_{sc} + M_u$ (Eq. 11)"].get_xdata(), [10, 40, 160])
    press = {ln.get_label(): ln for ln in fig.axes[1].get_lines()}
    iso = [ln for lab, ln in press.items() if lab.startswith("ISO 76")]
    assert len(iso) == 1 and np.allclose(iso[0].get_ydata(), 4.2)
    assert np.allclose(press["contact 1: $P_{01}$"].get_ydata(), ds["p_max1"].values * 1e-9)
    assert "above the limit from 40 \u00b5m" in _texts(fig)  # 10 um: 2.9 GPa, 40 um: > 4.2 GPa


def _gyro_dataset(n=400):
    case = hsbearing.load_case("jiang2014_gyro")
    t = np.linspace(0.0, 0.2, n)
    mc = np.where((t > 0.08) & (t < 0.09), 4e-6, 0.0) - np.where((t > 0.15) & (t < 0.16), 3e-6, 0.0)
    src = {"friction_moment_viscous": 0.05e-6, "friction_moment_hysteresis": 0.858e-6,
           "friction_moment_differential": 0.893e-6, "friction_moment_pivoting": 0.970e-6}
    from hsbearing.systems.gyro import model as gyro  # noqa: F401  (registers the gyro variables)

    data = {k: np.full(n, v) for k, v in src.items()}
    data["friction_moment_cage"] = mc
    data["friction_moment_total"] = sum(src.values()) + np.maximum(mc, 0.0)
    data["cage_speed"] = np.full(n, 0.25)
    data["outer_race_speed"] = np.full(n, 5 / _RPM)
    data["sfmc"] = float(data["friction_moment_total"].max())
    data["rfmc"] = sum(src.values())
    ds = make_dataset(data, coords={"time": t}, attrs=standard_attrs(case, model="gyro_ribbon_cage"))
    return ds, src


def test_plot_of_a_gyro_archive_separates_the_sources(tmp_path, capsys, figures):
    ds, src = _gyro_dataset()
    nc = write_netcdf(ds, tmp_path / "g.nc")
    rc, _, err = _run_cli(["plot", str(nc)], capsys)
    assert rc == 0 and err == ""
    fig = figures[-1]
    text = _texts(fig)
    assert "uN m" not in text and "\u00b5N m" in text  # one spelling of the unit
    assert "speed [r/min]" in text
    ax = fig.axes[2]
    bands = ax.collections  # stackplot: one filled band per source, stacked
    assert len(bands) == 5
    # the bands do not overlap: each band's top is the next band's bottom, the last top is M
    tops = []
    for b in bands:
        v = b.get_paths()[0].vertices
        tops.append(v[:, 1].max())
    assert np.all(np.diff(tops) > 0)  # strictly increasing tops: no two sources drawn on top of each other
    total = [ln for ln in ax.get_lines() if ln.get_label().startswith("$M$ total")][0]
    assert np.isclose(tops[-1], total.get_ydata().max(), rtol=1e-9)
    labels = [t.get_text() for t in ax.get_legend().get_texts()]
    assert any("$M_E$" in lab and "0.858 \u00b5N m" in lab for lab in labels)
    assert any("$M_S$" in lab and "0.97 \u00b5N m" in lab for lab in labels)


def test_plot_of_a_quasistatic_archive_and_of_an_unknown_dataset(tmp_path, capsys, figures):
    nc = tmp_path / "q.nc"
    rc, _, _ = _run_cli(["quasistatic", "zhang2016", "-o", str(nc)], capsys)
    assert rc == 0
    rc, _, err = _run_cli(["plot", str(nc)], capsys)
    assert rc == 0 and figures[-1]._suptitle.get_text().startswith("quasi-static equilibrium: zhang2016")
    other = write_netcdf(make_dataset({}, attrs={"title": "something else"}), tmp_path / "x.nc")
    rc, out, err = _run_cli(["plot", str(other)], capsys)
    assert rc == 2 and len(err.strip().splitlines()) == 1 and "Traceback" not in err
    assert str(other) in err and not (tmp_path / "x.png").exists()


def test_archive_kind_of_each_result():
    case = hsbearing.load_case("zhang2016")
    assert systems.archive_kind(_gyro_dataset(20)[0]) == "gyro"
    assert systems.archive_kind(cage_run("period", case, n_rev=2)) == "run"


# ----------------------------------------------------------------------------- item 11: figures of a run


def _whirl_dataset(case, kind="k", gc=200e-6, R=150e-6, n_rev=60):
    ds = cage_run(kind, case, n_rev=n_rev, spr=60, R=R, r2=0.2 * R)
    ds.attrs["guide_clearance"] = gc
    return annotate(ds, case)


def test_poincare_note_does_not_hide_section_points(tmp_path, figures):
    case = hsbearing.load_case("zhang2016")
    ds = cage_run("quasi", case, n_rev=60, spr=60, R=20e-6)
    systems.plot_run(ds, tmp_path / "r.png")
    fig = figures[-1]
    ax = fig.axes[1]  # (b) Poincare map
    assert ax.get_title().startswith("(b) Poincar")
    fig.canvas.draw()  # layout at the figure's own dpi, then measure in display coordinates
    r = fig.canvas.get_renderer()
    notes = [c for c in ax.get_children() if type(c).__name__ == "Annotation"]
    assert notes, "the classification note is drawn"
    box = notes[0].get_window_extent(r)
    pts = ax.collections[0].get_offsets()
    disp = ax.transData.transform(np.asarray(pts))
    assert len(disp) >= 10
    inside = (disp[:, 0] >= box.x0) & (disp[:, 0] <= box.x1) & (disp[:, 1] >= box.y0) & (disp[:, 1] <= box.y1)
    assert not inside.any()
    assert box.y1 <= ax.get_window_extent(r).y0  # below the plotting area


def test_whirl_radius_beyond_the_clearance_is_labelled(tmp_path, figures):
    case = hsbearing.load_case("zhang2016")
    ds = _whirl_dataset(case, gc=140e-6, R=130e-6)  # RMS ~ 130 um, peak ~ 156 um > 140 um clearance
    assert float(ds["whirl_radius_max"]) > 140e-6
    systems.plot_run(ds, tmp_path / "r.png")
    text = _texts(figures[-1])
    assert "elastic penetration of the cage-land rub contact" in text
    # a run inside its clearance has no such label
    ds2 = _whirl_dataset(case, gc=400e-6, R=130e-6)
    systems.plot_run(ds2, tmp_path / "r2.png")
    assert "penetration" not in _texts(figures[-1])


def test_sweep_of_a_numeric_key_uses_a_numeric_axis_and_prints_units(tmp_path, capsys, figures):
    rc, out, err = _run_cli(["sweep", "zhang2016", "--kind", "quasistatic", "--vary", "axial_load=100,500,1000N",
                             "-j", "1", "-o", str(tmp_path / "sw")], capsys)
    assert rc == 0, err
    rows = [ln for ln in out.splitlines() if ln.startswith("axial_load=")]
    assert len(rows) == 3
    assert all(" r/min" in ln for ln in rows)  # cage_speed in r/min, not rad/s
    fig = figures[-1]
    for ax in fig.axes:
        if not ax.get_lines():
            continue
        assert ax.get_xlabel().startswith("operating.axial_load [N]")
        xs = ax.get_lines()[0].get_xdata()
        assert np.allclose(xs, [100, 500, 1000])  # positions are the values: not evenly spaced
        lo, hi = ax.get_xlim()
        assert lo < 100 and hi > 1000


# ----------------------------------------------------------------------------- item 11: printed output


def _parked_dataset(case, gc=200e-6, Z=11):
    """Cage resting 170 um off the axis with a 3 um jitter at the ball-pass frequency Z x cage speed."""
    from hsbearing.analysis.slip import theoretical_cage_speed
    from hsbearing.models.geometry import derive

    wc = theoretical_cage_speed(derive(case), case.operating.inner_speed, case.operating.outer_speed)
    t = np.linspace(0.0, 0.1, 4001)
    y = 170e-6 * math.cos(2.0) + 3e-6 * np.cos(Z * wc * t)
    z = 170e-6 * math.sin(2.0) + 3e-6 * np.sin(Z * wc * t)
    data = {"cage_speed": np.full(t.size, wc), "cage_center_y": y, "cage_center_z": z,
            "inner_contact_load": np.full((t.size, Z), 100.0)}
    ds = make_dataset(data, coords={"time": t, "ball": np.arange(Z)}, attrs=standard_attrs(case, model="synthetic"))
    ds.attrs["guide_clearance"] = gc
    return annotate(ds, case)


def test_whirl_ratio_note_parked_and_whirling():
    from hsbearing.analysis.orbit import whirl_ratio_note

    case = hsbearing.load_case("zhang2016")
    parked = _parked_dataset(case)
    assert abs(float(parked["whirl_frequency_ratio"]) - 11) < 0.1  # what the FFT finds: the ball pass
    note = whirl_ratio_note(parked)
    assert note and note.startswith("cage parked") and "ball pass, Z = 11" in note
    assert whirl_ratio_note(_whirl_dataset(case)) is None  # a real whirl keeps its ratio


def test_run_summary_is_printed_in_readable_units(tmp_path, capsys, monkeypatch):
    case = hsbearing.load_case("zhang2016")
    ds = _whirl_dataset(case, gc=140e-6, R=130e-6)
    ds.attrs.update({"solver_wall_time": 38.14458563199997, "solver_steps": 1234, "solver_atol": 1.0000000000000001e-11,
                     "classification": "undetermined", "classification_reason": "only 3 Poincare section points (need >= 6); simulate longer"})
    monkeypatch.setattr(hsbearing, "simulate", lambda *a, **k: ds)
    rc, out, err = _run_cli(["run", "-o", str(tmp_path / "r.nc"), "--no-figure", "-q"], capsys)
    assert rc == 0
    lines = dict(ln.split(": ", 1) for ln in out.splitlines() if ": " in ln)
    amp = float(ds["whirl_amplitude"]) * 1e6
    assert lines["whirl_amplitude"].startswith(f"{amp:.4g} \u00b5m")
    assert lines["mean_cage_speed"] == f"{float(ds['mean_cage_speed']) * _RPM:.4g} r/min"
    assert lines["mean_cage_slip_ratio"] == f"{100 * float(ds['mean_cage_slip_ratio']):.4g} %"
    assert lines["whirl_frequency_ratio"] == f"{float(ds['whirl_frequency_ratio']):.4g}"  # no unit "1"
    assert not any(v.endswith(" 1") for v in lines.values())
    assert "guide clearance: elastic penetration" in lines["whirl_radius_max"]
    assert lines["classification"] == "undetermined (only 3 Poincare section points (need >= 6); simulate longer)"
    assert "wall_time=38.1 s" in lines["solver"] and "steps=1234" in lines["solver"] and "atol=1e-11" in lines["solver"]


def test_parked_cage_summary_says_ratio_not_defined(tmp_path, capsys, monkeypatch):
    ds = _parked_dataset(hsbearing.load_case("zhang2016"))
    monkeypatch.setattr(hsbearing, "simulate", lambda *a, **k: ds)
    rc, out, _ = _run_cli(["run", "-o", str(tmp_path / "r.nc"), "--no-plot", "-q"], capsys)
    assert rc == 0
    line = [ln for ln in out.splitlines() if ln.startswith("whirl_frequency_ratio:")][0]
    assert line.startswith("whirl_frequency_ratio: not defined (cage parked")
    assert "11" not in line.split("(")[0]


def test_format_quantity_units():
    from hsbearing.display import format_quantity, format_seconds

    assert format_quantity(2.00321e-4, "m") == "200.3 \u00b5m"
    assert format_quantity(600.796, "rad/s") == f"{600.796 * _RPM:.4g} r/min"
    assert format_quantity(-0.00893961, "1", "mean_cage_slip_ratio") == "-0.894 %"
    assert format_quantity(0.508835, "1") == "0.5088"
    assert format_quantity(6.96e-6, "N m") == "6.96 \u00b5N m"
    assert format_quantity(float("nan"), "m") == "nan"
    assert format_seconds(38.14458563199997) == "38.1 s" and format_seconds(3725) == "1 h 02 min"


# ----------------------------------------------------------------------------- item 12: help and wording


def test_help_names_papers_not_seed_numbers(capsys):
    for argv in (["--help"], ["run", "--help"], ["friction", "--help"], ["preload", "--help"], ["study", "--help"]):
        with pytest.raises(SystemExit) as exc:
            cli.main(argv)
        assert exc.value.code == 0
        text = capsys.readouterr().out
        assert "seed 00" not in text.lower(), argv
    rc, out, _ = _run_cli(["cases"], capsys)
    assert rc == 0 and "seed" not in out.lower()
    assert "Zhang et al. 2016" in out and "Shan et al. 2010" in out and "Jiang et al. 2014" in out and "6206" in out


@pytest.mark.parametrize("command", ["friction", "preload"])
def test_required_case_shows_no_default(command, capsys):
    with pytest.raises(SystemExit):
        cli.main([command, "--help"])
    assert "(default: zhang2016)" not in capsys.readouterr().out
    with pytest.raises(SystemExit) as exc:  # and it is indeed required
        cli.main([command])
    assert exc.value.code == 2


def test_study_help_lists_studies_runtime_and_backends(capsys):
    with pytest.raises(SystemExit):
        cli.main(["study", "--help"])
    text = capsys.readouterr().out
    assert "zhang2016:" in text and "runtime: ~10 min with -j 2" in text
    assert "dask.distributed" in text and "worker processes" in text
    with pytest.raises(SystemExit):
        cli.main(["sweep", "--help"])
    text = capsys.readouterr().out
    assert "dask.distributed" in text and "worker processes" in text


def test_no_figure_and_no_plot_are_one_flag():
    p = cli.build_parser()
    for flag in ("--no-figure", "--no-plot"):
        assert p.parse_args(["run", flag]).no_plot is True
        assert p.parse_args(["sweep", "--vary", "oil=4109", "-o", "d", flag]).no_figure is True
        assert p.parse_args(["study", "zhang2016", "-o", "d", flag]).no_figure is True


def test_quantity_errors_use_the_right_article(capsys):
    rc, _, err = _run_cli(["check", "--set", "operating.inner_speed=5 N"], capsys)
    assert rc == 2 and "is not an angular speed" in err and "a angular" not in err
    rc, _, err = _run_cli(["check", "--set", "bearing.ball_diameter=5 s"], capsys)
    assert rc == 2 and "is not a length" in err


def test_contact_pressure_warning_iso76(tmp_path, capsys):
    rc, out, err = _run_cli(["preload", "shan2010_wire_race", "--preload", "10,160um"], capsys)
    assert rc == 0
    warn = [ln for ln in err.splitlines() if "warning" in ln]
    assert len(warn) == 1 and "ISO 76" in warn[0] and "11.4 GPa" in warn[0] and "160 \u00b5m" in warn[0]
    rc, out, err = _run_cli(["preload", "shan2010_wire_race", "--preload", "10,15um"], capsys)
    assert rc == 0 and "warning" not in err  # 2.9-3.4 GPa: below 4.2 GPa
    rc, out, err = _run_cli(["quasistatic", "zhang2016"], capsys)
    assert rc == 0 and "warning" not in err
    rc, out, err = _run_cli(["quasistatic", "zhang2016", "--set", "operating.axial_load=60 kN"], capsys)
    assert rc == 0 and "ISO 76" in err


# ----------------------------------------------------------------------------- item 13: archive details


def test_quasistatic_archive_coordinates_and_attribute_units(tmp_path, capsys, monkeypatch):
    case_file = tmp_path / "mycase.toml"
    case_file.write_text(Path(hsbearing.case.case_path("zhang2016")).read_text())
    monkeypatch.chdir(tmp_path)
    rc, _, err = _run_cli(["quasistatic", "mycase.toml", "-o", "q.nc"], capsys)
    assert rc == 0, err
    ds = open_run(tmp_path / "q.nc")
    assert ds["dof"].attrs["long_name"] and ds["dof2"].attrs["long_name"]
    assert ds.attrs["case_source"] == str(case_file.resolve())
    assert ds.attrs["inner_speed_units"] == "rad/s"


def test_every_dimensional_global_attribute_has_units(tmp_path, capsys):
    """Each numeric global attr of the archives is either declared in results.ATTR_UNITS (and then has its
    companion NAME_units) or is a count / flag / dimensionless number listed here."""
    dimensionless = {"friction", "damping", "ring_tilt_free", "lambda_inner", "lambda_outer", "centrifugal",
                     "gyroscopic", "unloaded_balls", "ball_count", "classification_confidence",
                     "classification_alternative_confidence",
                     "solver_steps", "solver_rhs_evals", "solver_jac_evals"}  # counts
    rc, _, _ = _run_cli(["quasistatic", "zhang2016", "-o", str(tmp_path / "q.nc")], capsys)
    rc2, _, _ = _run_cli(["friction", "dgbb_6206", "-o", str(tmp_path / "f.nc")], capsys)
    rc3, _, _ = _run_cli(["preload", "shan2010_wire_race", "--preload", "10,20um", "--target-torque", "20..22N*m",
                          "-o", str(tmp_path / "p.nc")], capsys)
    rc4, _, _ = _run_cli(["run", "jiang2014_gyro", "--duration", "0.01s", "-q", "--no-figure", "-o", str(tmp_path / "g.nc")],
                         capsys)
    assert rc == rc2 == rc3 == rc4 == 0
    case = hsbearing.load_case("zhang2016")
    run = cage_run("period", case, n_rev=20, spr=60)
    run.attrs.update(guide_clearance=2e-4, pocket_clearance=5e-5, solver_wall_time=1.5, solver_steps=10)
    write_netcdf(annotate(run, case), tmp_path / "r.nc")
    for f in ("q", "f", "p", "r", "g"):
        ds = open_run(tmp_path / f"{f}.nc")
        for name, v in ds.attrs.items():
            if name.endswith("_units") or name.startswith("solver_") and name not in ATTR_UNITS:
                continue
            if isinstance(v, (str, bytes)):  # texts (names, JSON, status)
                continue
            if name in ATTR_UNITS:
                assert ds.attrs[f"{name}_units"] == ATTR_UNITS[name], (f, name)
            else:
                assert name in dimensionless, f"{f}.nc: global attribute {name}={v!r} has no declared units"


# ----------------------------------------------------------------------------- item 4: first-run compile


def test_cache_is_cold_follows_numbas_on_disk_cache(tmp_path):
    mod = tmp_path / "tinyjit.py"
    mod.write_text(textwrap.dedent("""
        from numba import njit

        @njit(cache=True)
        def f(x):
            return 2.0 * x
    """))
    code = ("import sys; sys.path.insert(0, {d!r}); import tinyjit; from hsbearing.jit import cache_is_cold; "
            "cold = cache_is_cold([tinyjit.f]); tinyjit.f(1.0); print(cold, cache_is_cold([tinyjit.f]))").format(d=str(tmp_path))
    env = dict(os.environ, NUMBA_CACHE_DIR=str(tmp_path / "cache"))
    first = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, env=env, timeout=300)
    second = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, env=env, timeout=300)
    assert first.stdout.split() == ["True", "False"], first.stderr  # cold, then compiled in the process
    assert second.stdout.split() == ["False", "False"], second.stderr  # warm from the disk cache


def test_compile_notice_comes_before_the_bar_and_compilation_before_integration(tmp_path, capsys, monkeypatch):
    from hsbearing import jit
    from hsbearing.solvers import cvode

    events = []
    real_warm, real_integrate = jit.warm_up, cvode.integrate
    monkeypatch.setattr(jit, "cache_is_cold", lambda d: True)  # as on a fresh install
    monkeypatch.setattr(jit, "warm_up", lambda *a, **k: events.append("warm") or real_warm(*a, **k))
    monkeypatch.setattr(cvode, "integrate", lambda *a, **k: events.append("integrate") or real_integrate(*a, **k))
    rc, out, err = _run_cli(["run", "--duration", "0.002s", "-o", str(tmp_path / "r.nc"), "--no-figure"], capsys)
    assert rc == 0
    assert events == ["warm", "integrate"]
    i = err.index("compiling the model (first run only, ~40 s)")
    assert "%|" in err and i < err.index("%|")
    # the bar and the solver wall time count integration only: the warm-up call compiled every kernel
    # signature CVODE uses (state passed read-only) before the bar started
    from hsbearing.models.ball_bearing import kernel as K

    assert any(not sig[0].mutable for sig in K.rhs_kernel.signatures)
    assert any(not sig[0].mutable for sig in K.jac_kernel.signatures)


def test_start_ensemble_bars_say_which_start(monkeypatch):
    """A 5-start gyro run shows five progress bars: each is labelled "start k/5" (they were identical)."""
    from hsbearing.systems.gyro import model as gyro

    descs = []

    def fake(case, duration=None, progress=False, *, progress_desc="gyro", **kw):
        descs.append(progress_desc)
        return {"sfmc": 1.0}

    monkeypatch.setattr(gyro, "_simulate_one", fake)
    case = hsbearing.load_case("jiang2014_gyro")
    vals = list(gyro._ensemble_sfmc(case, gyro.start_offsets(5), progress=True))
    assert vals == [1.0] * 5
    assert [d.split(" (")[0] for d in descs] == [f"gyro start {k}/5" for k in range(1, 6)]
    assert len(set(descs)) == 5
