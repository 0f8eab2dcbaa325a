"""Bad input through the CLI: exit code 2, one line naming the file and the key, no output file.

Issue 2, item 3: missing required key, unknown key (closest suggestion), wrong dimension,
negative/zero sizes and counts, conformity <= 0.5, balls that do not fit the pitch circle, a
cage pocket smaller than the ball, unknown oil (known ones listed), malformed TOML (line number).
"""

import re
import subprocess
import sys

import pytest

from hsbearing.case import case_path

BASE = case_path("zhang2016").read_text()


def _edit(text: str, old: str, new: str) -> str:
    assert old in text, old
    return text.replace(old, new, 1)


CASES = {
    "missing_required": (lambda t: _edit(t, 'ball_diameter = "9.525 mm"', ""), "bearing.ball_diameter", "missing required key"),
    "unknown_key": (lambda t: _edit(t, 'axial_load = "1000 N"', 'axial_lod = "1000 N"'), "operating.axial_lod", "did you mean 'operating.axial_load'"),
    "unknown_table": (lambda t: t + '\n[operatng]\nx = 1\n', "operatng", r"did you mean \[operating\]"),
    "wrong_dimension": (lambda t: _edit(t, 'ball_diameter = "9.525 mm"', 'ball_diameter = "9.525 kg"'), "bearing.ball_diameter", "is not a length"),
    "bare_number": (lambda t: _edit(t, 'ball_diameter = "9.525 mm"', "ball_diameter = 9.525"), "bearing.ball_diameter", "with units"),
    "negative_size": (lambda t: _edit(t, 'ball_diameter = "9.525 mm"', 'ball_diameter = "-9.525 mm"'), "bearing.ball_diameter", "must be positive"),
    "zero_count": (lambda t: _edit(t, "ball_count = 11", "ball_count = 0"), "bearing.ball_count", "must be positive"),
    "conformity": (lambda t: _edit(t, "inner_conformity = 0.52", "inner_conformity = 0.5"), "bearing.inner_conformity", "must be > 0.5"),
    "balls_do_not_fit": (lambda t: _edit(t, "ball_count = 11", "ball_count = 16"), "bearing.ball_count", "do not fit the pitch circle"),
    "pocket_too_small": (lambda t: _edit(t, 'pocket_diameter = "9.625 mm"', 'pocket_diameter = "9.5 mm"'), "cage.pocket_diameter", "not larger than the ball"),
    "unknown_oil": (lambda t: _edit(t, 'oil = "4109"', 'oil = "4108"'), "lubricant.oil", "known: 4109, 4106, 4050"),
    "bad_choice": (lambda t: _edit(t, 'guidance = "outer_ring"', 'guidance = "outer"'), "cage.guidance", "allowed: outer_ring"),
    "malformed_toml": (lambda t: _edit(t, 'ball_count = 11', 'ball_count = = 11'), None, r"malformed TOML: .*line \d+"),
    "zero_start_positions": (lambda t: _edit(t, "[simulation]", "[simulation]\nstart_positions = 0"), "simulation.start_positions", "must be positive"),
}


def _run(args, cwd):
    return subprocess.run([sys.executable, "-m", "hsbearing.cli", *args], capture_output=True, text=True, cwd=cwd, timeout=120)


@pytest.mark.parametrize("name", sorted(CASES))
def test_bad_case_file_exit_2(name, tmp_path):
    mutate, key, msg = CASES[name]
    bad = tmp_path / f"{name}.toml"
    bad.write_text(mutate(BASE))
    out = tmp_path / "out.nc"
    for cmd in (["check", str(bad)], ["run", str(bad), "-o", str(out), "--no-plot", "-q"], ["quasistatic", str(bad), "-o", str(out)]):
        res = _run(cmd, tmp_path)
        assert res.returncode == 2, (cmd, res.stdout, res.stderr)
        lines = [ln for ln in res.stderr.strip().splitlines() if ln.strip()]
        assert len(lines) == 1, res.stderr  # one line, no traceback
        line = lines[0]
        assert str(bad) in line
        if key:
            assert key in line
        assert re.search(msg, line), line
        assert not out.exists()
        assert not any(p.name.endswith(".tmp") for p in tmp_path.iterdir())


def test_bad_override_and_bad_duration(tmp_path):
    res = _run(["check", "zhang2016", "--set", "operating.axial_load=2 kg"], tmp_path)
    assert res.returncode == 2 and "operating.axial_load" in res.stderr and "is not a force" in res.stderr
    res = _run(["check", "zhang2016", "--set", "operating.axial_load"], tmp_path)
    assert res.returncode == 2 and "expected key=value" in res.stderr
    res = _run(["run", "zhang2016", "--duration", "3 mm", "-o", str(tmp_path / "x.nc")], tmp_path)
    assert res.returncode == 2 and "--duration" in res.stderr
    assert not (tmp_path / "x.nc").exists()


def test_unknown_case_name(tmp_path):
    res = _run(["check", "zhang2061"], tmp_path)
    assert res.returncode == 2 and "did you mean 'zhang2016'" in res.stderr


def test_check_prints_geometry(tmp_path):
    res = _run(["check"], tmp_path)
    assert res.returncode == 0
    assert "free contact angle alpha_0 = 25 deg" in res.stdout


def test_bad_override_value_names_the_override(tmp_path):
    """The case file is fine; the --set value is not (review finding 5)."""
    res = _run(["check", "zhang2016", "--set", "axial_load=abc"], tmp_path)
    assert res.returncode == 2 and "(override): operating.axial_load: cannot parse quantity" in res.stderr
    res = _run(["check", "zhang2016", "--set", "inner_conformity=0.5"], tmp_path)
    assert res.returncode == 2 and "(override): bearing.inner_conformity" in res.stderr


# Issue 13, items 5-7, through a real process (the in-process versions of every item are in
# tests/cli/test_cli_robustness.py): one stderr line, exit 2, no traceback, nothing left in the directory.
SUBPROCESS_BAD = {
    "case_is_a_directory": (["check", "adir"], r"adir: is a directory"),
    "power_tower_does_not_hang": (["check", "--set", "ball_diameter=10**10**10 mm"], r"bearing.ball_diameter: cannot parse"),
    "scheduler_not_a_url": (["sweep", "--vary", "axial_load=1,2N", "--scheduler", "not a url", "-o", "sw"], r"--scheduler"),
    "output_is_a_directory": (["run", "-q", "-o", "adir"], r"-o adir: is a directory"),
    "impossible_contact_angle": (["check", "--set", "contact_angle=400 deg"], r"bearing.contact_angle: must be below 90 deg"),
}


@pytest.mark.parametrize("name", sorted(SUBPROCESS_BAD))
def test_bad_inputs_in_a_real_process(name, tmp_path):
    argv, msg = SUBPROCESS_BAD[name]
    (tmp_path / "adir").mkdir()
    res = _run(argv, tmp_path)
    lines = [ln for ln in res.stderr.splitlines() if ln.strip()]
    assert res.returncode == 2 and len(lines) == 1 and "Traceback" not in res.stderr, res.stderr
    assert re.search(msg, lines[0]), lines[0]
    assert sorted(p.name for p in tmp_path.iterdir()) == ["adir"] and not any((tmp_path / "adir").iterdir())
