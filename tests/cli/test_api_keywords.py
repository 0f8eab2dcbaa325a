"""``hsbearing.simulate``, ``hsbearing.sweep`` and ``hsbearing.quasi_static`` take explicit keywords (the options the
CLI has for the same command), each documented in the numpydoc Parameters section; quantities as unit strings, pint
Quantities or SI floats; an unknown keyword is a TypeError naming the function, the closest keyword and, for a case
key, where case values go (``overrides=``)."""

from __future__ import annotations

import inspect
import math
import re

import pytest

import hsbearing
from hsbearing.case import CaseError
from hsbearing.units import _ureg

FUNCTIONS = ("simulate", "sweep", "quasi_static")


def _documented(fn) -> set[str]:
    doc = inspect.getdoc(fn)
    part = doc.split("Parameters\n----------\n", 1)[1].split("\nReturns\n", 1)[0]
    names = set()
    for line in part.splitlines():
        if line and not line.startswith(" "):
            for n in line.split(":")[0].split(","):
                names.add(n.strip())
    return names


@pytest.mark.parametrize("name", FUNCTIONS)
def test_no_hidden_keywords_and_every_keyword_documented(name):
    fn = getattr(hsbearing, name)
    params = inspect.signature(fn).parameters
    assert not [p for p in params.values() if p.kind in (p.VAR_KEYWORD, p.VAR_POSITIONAL)], name
    missing = set(params) - _documented(fn)
    assert not missing, f"{name}: keywords without a docstring entry: {sorted(missing)}"


@pytest.mark.parametrize("name", FUNCTIONS)
def test_unknown_keyword_is_a_clear_type_error(name):
    fn = getattr(hsbearing, name)
    with pytest.raises(TypeError, match=rf"hsbearing\.{name}\(\) got an unknown keyword 'overides'; did you mean "
                                        r"'overrides'\?"):
        fn("zhang2016", {} if name == "sweep" else None, overides={})
    with pytest.raises(TypeError, match=r"'axial_load' is a case value: overrides=\{'operating.axial_load': \.\.\.\}"):
        fn("zhang2016", axial_load="2 kN")
    with pytest.raises(TypeError, match=r"keywords: case, .*overrides"):
        fn("zhang2016", foo_bar_baz=1)


def test_quasi_static_speed_as_string_quantity_or_si_float_and_overrides():
    si = hsbearing.quasi_static("zhang2016", inner_speed=10000 * math.pi / 30)
    for v in ("10000 rpm", _ureg().Quantity(10000, "rpm")):
        got = hsbearing.quasi_static("zhang2016", inner_speed=v)
        assert float(got.cage_speed) == pytest.approx(float(si.cage_speed), rel=1e-12)
    a = hsbearing.quasi_static("zhang2016", overrides={"axial_load": _ureg().Quantity(2, "kN")})
    b = hsbearing.quasi_static(hsbearing.load_case("zhang2016", axial_load="2 kN"))
    assert a.inner_contact_load.values == pytest.approx(b.inner_contact_load.values, rel=1e-12)
    assert float(a.inner_contact_load[0]) > float(si.inner_contact_load[0]) * 1.5  # the override did act
    with pytest.raises(CaseError, match="inner_speed"):
        hsbearing.quasi_static("zhang2016", inner_speed="3 kN")


def test_simulate_passes_every_option_to_the_engine(monkeypatch):
    """Plumbing (no integration): what the engine receives for each keyword."""
    from hsbearing import systems

    seen = {}

    def fake(case, duration=None, progress=False, **kw):
        seen.update(case=case, duration=duration, progress=progress, kw=kw)
        return "ds"

    monkeypatch.setattr(systems, "simulate", fake)
    for d in ("2 ms", _ureg().Quantity(2, "ms"), 2e-3):
        assert hsbearing.simulate("zhang2016", d) == "ds"
        assert seen["duration"] == pytest.approx(2e-3, rel=1e-12) and seen["kw"] == {}
    hsbearing.simulate("zhang2016", overrides={"axial_load": 2000.0}, stop="converged", section="cage_revolution",
                       rtol=1e-6, atol=1e-9, progress=True, cvode_settings={})
    c = seen["case"]
    assert (c.operating.axial_load, c.simulation.stop, c.simulation.section) == (2000.0, "converged", "cage_revolution")
    assert (c.simulation.rtol, c.simulation.atol, seen["progress"], seen["kw"]) == (1e-6, 1e-9, True,
                                                                                     {"cvode_settings": {}})
    with pytest.raises(CaseError, match="only with extend=True"):
        hsbearing.simulate("zhang2016", max_duration="1 s")
    with pytest.raises(CaseError, match="duration"):
        hsbearing.simulate("zhang2016", duration="-1 s")
    with pytest.raises(CaseError, match="stop"):
        hsbearing.simulate("zhang2016", stop="never")
    with pytest.raises(CaseError, match="angular-contact"):
        hsbearing.simulate("jiang2014_gyro", extend=True)


def test_sweep_passes_every_option_to_the_engine(monkeypatch, tmp_path):
    from hsbearing.workflows import sweeps

    seen = {}

    def fake(case, vary, **kw):
        seen.update(case=case, vary=vary, kw=kw)
        return "ds"

    monkeypatch.setattr(sweeps, "run_sweep", fake)
    hsbearing.sweep("zhang2016", {"oil": "4109,4106"}, out_dir=tmp_path, kind="quasistatic", zip=True,
                    duration=_ureg().Quantity(5, "ms"), jobs=1, keep="full", retry_failed=True, progress=False,
                    overrides={"axial_load": "2 kN"}, stop="converged")
    kw = seen["kw"]
    assert kw["duration"] == pytest.approx(5e-3, rel=1e-12)
    assert (kw["zip"], kw["jobs"], kw["keep"], kw["retry_failed"], kw["progress"], kw["kind"]) == (
        True, 1, "full", True, False, "quasistatic")
    assert seen["case"].operating.axial_load == 2000.0 and seen["case"].simulation.stop == "converged"
    hsbearing.sweep("zhang2016", {"oil": "4109"}, out_dir=tmp_path, stop="duration")  # the case's own rule:
    # the case is not rewritten, so the point archives (hashes) stay those of the CLI
    assert seen["case"].to_toml() == hsbearing.load_case("zhang2016").to_toml()
    with pytest.raises(TypeError, match=re.escape("hsbearing.sweep() got an unknown keyword 'job'; did you mean")):
        hsbearing.sweep("zhang2016", {"oil": "4109"}, out_dir=tmp_path, job=2)
