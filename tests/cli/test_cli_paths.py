"""Command-line paths a user takes that no other test walked (issue 20, "untested"): `hsbearing run` of the
default angular-contact case end to end, `run` ending in a numerical failure (exit 1, partial archive kept),
and `sweep --zip` from the command line.  Contract: docs/design.md "CLI" (exit 0 / 1 / 2, default output
runs/<case>-<hash>.nc + PNG + summary)."""

from __future__ import annotations

import re
import subprocess
import sys
from pathlib import Path

import numpy as np
import pytest

import hsbearing
from hsbearing import cli
from hsbearing.results import open_run


def _hsbearing_cmd():
    exe = Path(sys.executable).with_name("hsbearing")  # the console script of the installed package
    return [str(exe)] if exe.exists() else [sys.executable, "-m", "hsbearing.cli"]


def test_run_default_case_end_to_end(tmp_path):
    """`hsbearing run --duration 0.01s` in an empty directory: exit 0, runs/zhang2016-<hash>.nc and .png, the
    summary lines, an archive that carries the contract names and the status, no temporary file left."""
    r = subprocess.run(_hsbearing_cmd() + ["run", "--duration", "0.01s", "-q"], cwd=tmp_path, capture_output=True,
                       text=True, timeout=600)
    assert r.returncode == 0, r.stderr[-2000:]
    assert "Traceback" not in r.stderr
    out = r.stdout
    m = re.search(r"^archive: (runs/zhang2016-[0-9a-f]{10}\.nc)$", out, re.M)
    assert m, out
    nc = tmp_path / m.group(1)
    png = nc.with_suffix(".png")
    assert re.search(rf"^figure: {re.escape(str(png.relative_to(tmp_path)))}$", out, re.M), out
    for line in ("status: ok", "mean_cage_slip_ratio:", "mean_cage_speed:", "whirl_amplitude:", "classification:",
                 "solver: "):
        assert re.search(rf"^{re.escape(line)}", out, re.M), (line, out)
    power_png = png.with_name(png.stem + "_power.png")  # second figure: power loss by source, drive torque
    assert re.search(rf"^figure: {re.escape(str(power_png.relative_to(tmp_path)))}$", out, re.M), out
    lock_png = png.with_name(png.stem + "_lock.png")  # third figure: whirl-cage lock/drift and the clock section
    assert re.search(rf"^figure: {re.escape(str(lock_png.relative_to(tmp_path)))}$", out, re.M), out
    assert sorted(p.name for p in (tmp_path / "runs").iterdir()) == sorted([nc.name, png.name, power_png.name,
                                                                          lock_png.name])  # nothing else
    assert png.stat().st_size > 10_000 and png.read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"
    ds = open_run(nc)
    assert ds.attrs["status"] == "ok" and ds.attrs["solver_steps"] > 0
    assert float(ds.time[-1]) == pytest.approx(0.01)
    case = hsbearing.load_case("zhang2016")
    assert ds.sizes["ball"] == case.bearing.ball_count
    for name in ("inner_contact_load", "outer_contact_load", "inner_contact_angle", "outer_contact_angle",
                 "cage_speed", "cage_slip_ratio", "cage_center_y", "cage_center_z", "ball_orbit_speed",
                 "ball_spin_speed", "inner_ring_axial_displacement"):
        assert name in ds and ds[name].attrs["units"], name
    # the default case is the Zhang et al. 2016 bearing under 1 kN axial load: the inner contacts carry it
    Qi, ai = ds.inner_contact_load.values[-1], ds.inner_contact_angle.values[-1]
    assert (Qi * np.sin(ai)).sum() == pytest.approx(1000.0, rel=0.05)


def test_run_numerical_failure_exit_1_keeps_partial_archive(tmp_path, monkeypatch, capsys):
    """A run that stops numerically: exit 1, one 'numerical failure' line on stderr naming the archive, the partial
    Dataset written with status 'failed at t = ...'.  The case schema has no step limit and no tolerance makes
    CVODE fail quickly (rtol = 1e-30 is clamped and succeeds; atol = 1e-300 runs for > 10 min), so the failure is
    CVODE's own stop at a wall-time limit of 1 us, passed through the real simulate()."""
    real = hsbearing.simulate

    def limited(case, duration=None, progress=False, **kw):
        return real(case, duration=duration, progress=progress, wall_limit=1e-6, **kw)

    monkeypatch.setattr(hsbearing, "simulate", limited)
    out = tmp_path / "fail.nc"
    rc = cli.main(["run", "zhang2016", "--duration", "0.01s", "-q", "--no-plot", "-o", str(out)])
    assert rc == 1
    err = capsys.readouterr().err.strip().splitlines()
    assert len(err) == 1 and "numerical failure" in err[0] and str(out) in err[0], err
    ds = open_run(out)
    assert ds.attrs["status"].startswith("failed at t = ")
    assert ds.sizes["time"] >= 1 and float(ds.time[-1]) < 0.01
    assert not [p for p in tmp_path.iterdir() if p.name != out.name]  # no temporary file left


def test_sweep_zip_from_the_cli(tmp_path, capsys):
    """`hsbearing sweep ... --zip`: the lists are paired (3 points, not 9), one `point` dimension, each point's
    archive holds its pair, and its numbers are the direct quasi-static solution of that pair."""
    d = tmp_path / "zip"
    rc = cli.main(["sweep", "zhang2016", "--vary", "axial_load=100,500,1000N", "--vary", "radial_load=0,50,200N",
                   "--zip", "--kind", "quasistatic", "-j", "1", "-o", str(d), "--no-figure"])
    assert rc == 0, capsys.readouterr().err
    sw = open_run(d / "sweep.nc")
    assert sw.attrs["sweep_mode"] == "zip" and sw["status"].dims == ("point",) and sw.sizes["point"] == 3
    assert list(sw["axial_load"].values) == [100.0, 500.0, 1000.0]
    assert list(sw["radial_load"].values) == [0.0, 50.0, 200.0]
    assert (sw["status"] == "ok").all()
    assert len(list(d.glob("zhang2016-*.nc"))) == 3
    direct = hsbearing.quasi_static(hsbearing.load_case("zhang2016", **{"operating.axial_load": "500 N",
                                                                        "operating.radial_load": "50 N"}))
    assert float(sw["max_inner_contact_load"].values[1]) == pytest.approx(float(direct.inner_contact_load.max()),
                                                                          rel=1e-9)
    arch = open_run(d / str(sw["archive"].values[2]))
    case = hsbearing.case.loads_case(arch.attrs["case_toml"], "archive")
    assert case.operating.axial_load == 1000.0 and case.operating.radial_load == 200.0
