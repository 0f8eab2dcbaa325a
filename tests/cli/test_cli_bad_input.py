"""inputs that gave a traceback, a hang, or NaN with exit 0.

Through the command line (``hsbearing.cli.main`` in-process): a traceback becomes exit 2 (bad input) with one
line naming the file and the key; a hang becomes an immediate refusal; a NaN printed with exit 0 becomes a
value with its reason or ``n/a (reason)``.
"""

from __future__ import annotations

import os
import re
import time

import pytest
from _cli_checks import one_error_line as _one_line

import hsbearing
from hsbearing import cli
from hsbearing.case import case_path

BASE = case_path("zhang2016").read_text()


@pytest.fixture
def work(tmp_path, monkeypatch):
    monkeypatch.chdir(tmp_path)
    return tmp_path


# ----------------------------------------------------------------------------- class 6: tracebacks


def test_integer_beyond_float_range(work, capsys):
    for key, line in (("bearing.ball_count", "ball_count = "), ("simulation.rtol", "rtol = ")):
        text = re.sub(rf"(?m)^{line}.*$", line + "1" + "0" * 400, BASE, count=1)
        (work / "big.toml").write_text(text)
        rc = cli.main(["check", "big.toml"])
        _one_line(capsys, rc, rf"big.toml: {re.escape(key)}: integer with 401 digits")
    rc = cli.main(["check", "--set", "friction.coefficient=" + "9" * 400])
    _one_line(capsys, rc, r"friction.coefficient: integer with 400 digits")


@pytest.mark.parametrize("nest", ["[" * 3000 + "]" * 3000, "{a=" * 3000 + "1" + "}" * 3000])
def test_deeply_nested_toml(nest, work, capsys):
    (work / "deep.toml").write_text(BASE + f"\n[extra]\nx = {nest}\n")
    rc = cli.main(["check", "deep.toml"])
    _one_line(capsys, rc, r"deep.toml: malformed TOML: .*nested deeper than 20")
    rc = cli.main(["check", "--set", "rtol=" + "[" * 3000])  # an override too: refused, no RecursionError
    _one_line(capsys, rc, r"simulation.rtol")


@pytest.mark.parametrize("addr, msg", [("ucx://h:1", r"ucx:// protocol needs ucx-py"),
                                       ("tls://h:8786", r"TLS schedulers need a security configuration"),
                                       ("inproc://h/1/2", r"inproc:// scheduler exists only inside the process")])
def test_scheduler_of_other_protocols(addr, msg, work, capsys):
    t0 = time.perf_counter()
    rc = cli.main(["sweep", "--vary", "axial_load=100,200N", "--scheduler", addr, "-o", "sw"])
    assert time.perf_counter() - t0 < 10  # no 30 s connect timeout
    _one_line(capsys, rc, r"--scheduler: ", msg)
    assert list(work.iterdir()) == []


def test_absurd_conformity(work, capsys):
    for f in ("1e300", "5"):
        rc = cli.main(["quasistatic", "--set", f"inner_conformity={f}", "-o", "q.nc"])
        _one_line(capsys, rc, r"bearing.inner_conformity: conformity .* not a ball-bearing groove")
    assert list(work.iterdir()) == []


def test_model_arithmetic_error_is_one_line(work, capsys, monkeypatch):
    """Any singular matrix / overflow deep in a model (valid inputs the model cannot solve) is one line, exit 1."""
    import numpy as np

    def singular(*a, **k):
        raise np.linalg.LinAlgError("Singular matrix")

    monkeypatch.setattr(hsbearing, "quasi_static", singular)
    rc = cli.main(["quasistatic"])
    _one_line(capsys, rc, r"numerical failure: LinAlgError: Singular matrix", code=1)


# ----------------------------------------------------------------------------- class 8: hangs


def test_check_refuses_fifo_and_devices_at_once(work, capsys):
    os.mkfifo(work / "case.toml")
    for arg in ("case.toml", "/dev/zero", "/dev/null"):
        t0 = time.perf_counter()
        rc = cli.main(["check", arg])
        assert time.perf_counter() - t0 < 5
        _one_line(capsys, rc, re.escape(arg) + r": is a (FIFO|character device).*not a case file")


def test_start_positions_bounded(work, capsys):
    rc = cli.main(["check", "jiang2014_gyro", "--set", "start_positions=1000000000"])
    _one_line(capsys, rc, r"simulation.start_positions: must be <= 64")


def test_directory_named_like_a_bundled_case_does_not_hide_it(work, capsys):
    (work / "zhang2016").mkdir()
    assert cli.main(["check", "zhang2016"]) == 0
    assert "hsbearing/cases/zhang2016.toml" in capsys.readouterr().out


# ----------------------------------------------------------------------------- class 9: NaN with exit 0


def test_zero_speed_film_thickness_and_life(work, capsys):
    assert cli.main(["quasistatic", "--set", "inner_speed=0 rpm"]) == 0
    out, err = capsys.readouterr()
    assert "nan" not in out.lower() and "All-NaN" not in err
    assert "central film thickness: inner n/a (no rolling speed: no EHL film)" in out
    assert cli.main(["life", "zhang2016", "--set", "inner_speed=0 rpm"]) == 0
    out = capsys.readouterr().out
    assert "nan" not in out.lower()
    assert re.search(r"kappa = n/a \(no rotation", out) and "a_ISO = n/a" in out


def test_zero_speed_friction_torque(work, capsys):
    assert cli.main(["friction", "zhang2016", "--set", "inner_speed=0 rpm"]) == 0
    out = capsys.readouterr().out
    assert "nan" not in out.lower() and "n/a (0 r/min)" in out


def test_ball_guided_cage_power_loss_is_a_number(work, capsys):
    """The pocket film of a ball-piloted cage used the land radius (NaN: no land): total power loss was nan."""
    assert cli.main(["friction", "zhang2016", "--set", "guidance=ball"]) == 0
    out = capsys.readouterr().out
    assert "nan" not in out.lower(), out
    from hsbearing.systems.angular_contact.rating import quasi_static_power_loss

    r = quasi_static_power_loss(hsbearing.load_case("zhang2016", **{"cage.guidance": "ball"}))
    assert all(map(lambda v: v == v, r.values())) and r["power_loss"] > 0


@pytest.mark.slow  # long: default tier kept under ~10 min (docs/testing.md)
def test_sfmo_and_whirl_frequency_reasons(work, capsys):
    """A short oscillation run of the gyro bearing (no complete reversal window) and a short angular-contact
    run (< 16 orbit samples): the summary says why instead of printing nan."""
    assert cli.main(["run", "jiang2014_gyro", "--set", "mode=oscillation", "--duration", "0.3s", "-q", "--no-plot",
                     "-o", "g.nc"]) == 0
    out = capsys.readouterr().out
    assert re.search(r"^sfmo: n/a \(SFMO needs at least two reversal windows", out, re.M), out
    assert not re.search(r":\s*nan\b", out)
    assert cli.main(["run", "--duration", "0.0004s", "-q", "--no-plot", "-o", "a.nc"]) == 0
    out = capsys.readouterr().out
    assert re.search(r"^whirl_frequency: n/a \(fewer than 16 cage-centre samples", out, re.M), out
    assert not re.search(r":\s*nan\b", out)
