"""impossible bearings are refused at load time (``case.check_possible``), so ``check``,
``quasistatic``, ``run`` and ``life`` agree: exit 2, one line naming the key, nothing computed or written.
Oil temperatures: an error beyond what is physical (below the pour point, above ~350 degC), a warning beyond
the oil's service range (its data are extrapolated)."""

from __future__ import annotations

import re

import pytest

import hsbearing
from hsbearing import cli

IMPOSSIBLE = {
    # name: (case, --set items, key, message regex)
    "clearance_180deg": ("zhang2016", ["diametral_clearance=2 mm"], "bearing.diametral_clearance", r"free contact angle of 180 deg"),
    "clearance_just_90deg": ("zhang2016", ["diametral_clearance=0.96 mm"], "bearing.diametral_clearance", r">= 90 deg"),
    "overlapping_pockets": ("zhang2016", ["pocket_diameter=13 mm"], "cage.pocket_diameter", r"11 pockets of 13 mm overlap"),
    "ring_narrower_than_ball": ("zhang2016", ["bearing.width=5 mm"], "bearing.width", r"narrower than the ball 9.525 mm"),
    "cage_wider_than_bearing": ("zhang2016", ["cage.width=20 mm"], "cage.width", r"wider than the bearing"),
    "pocket_shallower_than_ball_radius": ("jiang2014_gyro", ["pocket_depth=0.6 mm"], "cage.pocket_depth",
                                          r"not deeper than the ball radius 0.65 mm"),
    "negative_axial_load_angular_contact": ("zhang2016", ["axial_load=-100 N"], "operating.axial_load",
                                            r"one direction only"),
    "oil_500C": ("zhang2016", ["temperature=500 degC"], "lubricant.temperature", r"no oil film"),
    "oil_500C_gyro": ("jiang2014_gyro", ["temperature=500 degC"], "lubricant.temperature", r"no oil film"),
}


@pytest.fixture
def work(tmp_path, monkeypatch):
    monkeypatch.chdir(tmp_path)

    def boom(*a, **k):
        raise AssertionError("computation started on an impossible bearing")

    monkeypatch.setattr(hsbearing, "simulate", boom)
    monkeypatch.setattr(hsbearing, "quasi_static", boom)
    return tmp_path


def _sets(items):
    return [x for it in items for x in ("--set", it)]


@pytest.mark.parametrize("name", sorted(IMPOSSIBLE))
@pytest.mark.parametrize("command", ["check", "quasistatic", "run", "life"])
def test_impossible_bearing_refused(name, command, work, capsys):
    case, items, key, msg = IMPOSSIBLE[name]
    if command == "life" and case == "jiang2014_gyro":
        pytest.skip("life is for radial ball bearings")
    extra = {"check": [], "quasistatic": ["-o", "o.nc"], "run": ["-q", "-o", "o.nc"], "life": []}[command]
    rc = cli.main([command, case, *_sets(items), *extra])
    err = capsys.readouterr().err
    lines = [ln for ln in err.splitlines() if ln.strip()]
    assert rc == 2 and len(lines) == 1 and "Traceback" not in err, err
    if key:
        assert f": {key}: " in lines[0], lines[0]
    assert re.search(msg, lines[0]), lines[0]
    assert list(work.iterdir()) == []


def test_pockets_cutting_the_cage_refused(work, capsys):
    """`check` used to print "cage mass 0 g" for pockets that eat the cage while `run` refused: a cage no wider than
    its pockets is cut through, refused by both (key cage.width)."""
    for command in (["check"], ["quasistatic", "-o", "o.nc"]):
        rc = cli.main([*command, "--set", "cage.width=9 mm"])
        err = capsys.readouterr().err
        assert rc == 2 and len(err.strip().splitlines()) == 1, err
        assert re.search(r"cage.width: cage width 9 mm is not wider than its pockets \(9.625 mm\)", err), err


def test_oil_beyond_service_range_warns(capsys):
    assert cli.main(["check", "--set", "temperature=250 degC"]) == 0
    err = capsys.readouterr().err.strip().splitlines()
    assert len(err) == 1 and re.search(r"warning: .*lubricant.temperature: 250 degC is outside the service range "
                                       r"of oil 4109 \(-51..204 degC\)", err[0]), err
    assert cli.main(["check"]) == 0  # the default 130 degC: no warning
    assert capsys.readouterr().err == ""


def test_below_pour_point_refused_where_the_oil_data_are_used(capsys):
    """The angular-contact model reads the oil's data; 4106 pours down to -54 degC (the 0 degC traction-law limit
    of that system is met first, so the pour point is shown on a case at -60 with the limit's message)."""
    rc = cli.main(["check", "--set", "oil=4106", "--set", "temperature=-60 degC"])
    err = capsys.readouterr().err
    assert rc == 2 and "lubricant.temperature" in err and len(err.strip().splitlines()) == 1
