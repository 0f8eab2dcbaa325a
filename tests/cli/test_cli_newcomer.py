"""Issue 27, items 10 (what a new user trips over) and 11 (the plotting <-> systems import circle)."""

from __future__ import annotations

import ast
import re
from pathlib import Path

import numpy as np
import xarray as xr

from hsbearing import cli

PKG = Path(__file__).resolve().parents[2] / "hsbearing"


def _err_lines(capsys):
    return [ln for ln in capsys.readouterr().err.splitlines() if ln.strip()]


def test_bare_command_one_line(capsys):
    assert cli.main([]) == 2
    lines = _err_lines(capsys)
    assert len(lines) == 1 and lines[0].startswith("hsbearing: error: no command given"), lines


def test_argparse_errors_one_line(capsys):
    for argv in (["bogus"], ["run", "--bogus"], ["sweep", "zhang2016"], ["run", "--duration"]):
        try:
            rc = cli.main(argv)
        except SystemExit as exc:  # argparse exits through SystemExit(2)
            rc = exc.code
        lines = _err_lines(capsys)
        assert rc == 2 and len(lines) == 1 and lines[0].startswith("hsbearing: error: "), (argv, lines)
        assert "usage:" not in lines[0]


def test_duration_without_unit_says_so(capsys):
    assert cli.main(["run", "--duration", "0.01", "-o", "x.nc"]) == 2
    lines = _err_lines(capsys)
    assert len(lines) == 1 and "'0.01' has no unit: write e.g. \"0.01 s\" (no unit is assumed)" in lines[0], lines


def test_quasistatic_prints_the_shoulder_warning_and_a_clean_solver_line(capsys):
    assert cli.main(["quasistatic", "--set", "axial_load=4000 N"]) == 0
    out = capsys.readouterr().out
    assert re.search(r"^warning: inner contact ellipse truncated by the groove shoulder", out, re.M), out
    solver = next(ln for ln in out.splitlines() if ln.startswith("solver: "))
    assert "_units" not in solver, solver


def test_sweep_leaves_no_lock_file(tmp_path, capsys):
    out = tmp_path / "sw"
    rc = cli.main(["sweep", "--kind", "quasistatic", "--vary", "axial_load=100,200N", "-j", "1", "--no-figure",
                   "-o", str(out)])
    assert rc == 0, capsys.readouterr().err
    assert not (out / ".hsbearing-sweep.lock").exists()
    assert sorted(p.name for p in out.iterdir() if p.name.startswith(".")) == []


def test_sweep_table_shows_raceway_control_slip(capsys):
    from hsbearing.workflows.sweeps import print_table

    ds = xr.Dataset({"status": ("axial_load", np.array(["ok"], dtype=object)),
                     "error": ("axial_load", np.array([""], dtype=object)),
                     "mean_cage_slip_ratio": ("axial_load", [-0.106], {"units": "1"}),
                     "mean_cage_slip_ratio_raceway_control": ("axial_load", [0.0123], {"units": "1"})},
                    coords={"axial_load_label": ("axial_load", np.array(["100 N"], dtype=object))})
    print_table(ds)
    line = capsys.readouterr().out
    assert "mean_cage_slip_ratio=-10.6 %" in line and "mean_cage_slip_ratio_raceway_control=1.23 %" in line, line


def test_plot_of_an_angular_contact_friction_archive(tmp_path, capsys):
    nc, png = tmp_path / "fr.nc", tmp_path / "fr.png"
    assert cli.main(["friction", "zhang2016", "--speeds", "5000,14000rpm", "-o", str(nc)]) == 0
    capsys.readouterr()
    assert cli.main(["plot", str(nc), "-o", str(png)]) == 0, capsys.readouterr().err
    assert png.read_bytes()[:8] == b"\x89PNG\r\n\x1a\n" and png.stat().st_size > 10_000


def test_plotting_imports_no_system_figures_by_name():
    """Item 11: hsbearing/plotting dispatches through the systems registry; it names no systems.<x>.figures module
    (those import hsbearing.plotting: the circle)."""
    for p in (PKG / "plotting").glob("*.py"):
        for node in ast.walk(ast.parse(p.read_text())):
            mods = [node.module or ""] if isinstance(node, ast.ImportFrom) else \
                [a.name for a in node.names] if isinstance(node, ast.Import) else []
            for m in mods:
                assert not re.match(r"hsbearing\.systems\.\w+(\.figures|\.power_figure)?$", m), (p.name, m)
    from hsbearing import plotting

    for old in ("plot_gyro", "plot_friction", "plot_preload", "plot_run", "archive_kind"):  # dispatch: hsbearing.systems
        assert not hasattr(plotting, old), old


def _capture(monkeypatch, module, attr="save_figure"):
    figs = []

    def keep(fig, path, *a, **k):
        figs.append(fig)
        return Path(path)

    monkeypatch.setattr(module, attr, keep)
    return figs


def test_quasistatic_figure_numbers_balls_from_zero(monkeypatch, tmp_path):
    """Balls are 0..Z-1 in the archive and the printed table; the figure numbered them 1..Z."""
    import hsbearing
    from hsbearing import systems
    from hsbearing.plotting import common

    figs = _capture(monkeypatch, common)
    ds = hsbearing.quasi_static(hsbearing.load_case("zhang2016"))
    systems.plot_run(ds, tmp_path / "q.png")
    ax1 = figs[0].axes[0]
    assert list(ax1.get_xticks()) == list(range(ds.sizes["ball"])) == list(ds["ball"].values)


def test_power_figure_legend_leaves_the_drive_line_free(monkeypatch, tmp_path):
    import hsbearing
    from hsbearing import plotting
    from hsbearing.systems.angular_contact import power_figure

    ds = hsbearing.simulate(hsbearing.load_case("zhang2016"), duration=0.004)
    figs = _capture(monkeypatch, plotting)
    power_figure.plot_power(ds, tmp_path / "p.png")
    ax = figs[0].axes[0]
    drive = max(line.get_ydata().max() for line in ax.get_lines())
    stacked = max(c.get_paths()[0].vertices[:, 1].max() for c in ax.collections)
    y0, y1 = ax.get_ylim()
    assert y1 >= max(drive, stacked) + 0.5 * (max(drive, stacked) - y0)  # the upper third is the legend's


def test_preload_window_line_carries_the_pressure_caveat(capsys):
    assert cli.main(["preload", "shan2010_wire_race", "--preload", "10..160um", "--target-torque", "90..100N*m"]) == 0
    out = capsys.readouterr().out
    line = next(ln for ln in out.splitlines() if ln.startswith("preload window for"))
    m = re.search(r"caveat: maximum contact pressure there ([0-9.]+)-([0-9.]+) GPa, above the 4.2 GPa of ISO 76", line)
    assert m and 10 < float(m.group(1)) <= float(m.group(2)) < 12, line
