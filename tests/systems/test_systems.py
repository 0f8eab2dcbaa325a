"""The system registry: one package per ``[case] system`` with the same interface, and the
front ends (CLI, API, sweeps, plot) dispatching through it rather than by comparing system names."""

from __future__ import annotations

import re
from pathlib import Path

import pytest

from hsbearing import case as case_mod
from hsbearing import systems
from hsbearing.case import CaseError, load_case

PKG = Path(__file__).resolve().parents[2] / "hsbearing"


def test_every_case_system_has_a_package():
    assert set(systems.SYSTEMS) == set(case_mod.SYSTEMS)
    for name, s in systems.SYSTEMS.items():
        assert s.name == name and callable(s.friction) and s.figures, name
        assert all(callable(f) for f in s.figures.values())


@pytest.mark.parametrize("name", sorted(case_mod.list_cases()))
def test_bundled_case_finds_its_system(name):
    c = load_case(name)
    assert systems.get(c).name == c.system


def test_unknown_system_is_a_case_error():
    with pytest.raises(CaseError, match="unknown system 'roller'"):
        systems.get("roller")


def test_no_system_without_dynamics_is_simulated():
    with pytest.raises(CaseError, match="no dynamic model"):
        systems.simulate(load_case("shan2010_wire_race"))


def test_each_archive_kind_has_one_figure():
    kinds = systems.figure_functions()
    assert {"run", "quasistatic", "friction", "preload", "gyro"} <= set(kinds)


FRONT_ENDS = {  # the generic front ends (hsbearing oils is an angular-contact/deep-groove command of its own)
    "api": ["__init__.py"],
    "cli": ["cli/__init__.py", "cli/commands.py", "cli/common.py", "cli/parser.py"],
    "sweeps": sorted(str(p.relative_to(PKG)) for p in (PKG / "workflows" / "sweeps").glob("*.py")),
    "plotting": ["plotting/__init__.py"],
}


@pytest.mark.parametrize("front", sorted(FRONT_ENDS))
def test_front_ends_do_not_switch_on_the_system_name(front):
    text = "\n".join((PKG / f).read_text(encoding="utf-8") for f in FRONT_ENDS[front])
    hits = re.findall(r"\.(?:system|name)\s*(?:==|!=|in\b|not in\b)|case_system\"?\)?\s*==", text)
    assert not hits, f"{front} compares system names ({hits}); dispatch through hsbearing.systems"
