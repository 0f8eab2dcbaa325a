"""annotate() classifies a run under two Poincare sections (the chosen one and the other, kept side by side);
the growth and whirl-cage lock tests do not depend on the section, so the second classification takes those of
the first instead of computing them again.  The annotated run must be exactly what it was when both were
computed twice: compared here against annotate() with the reuse switched off."""

from __future__ import annotations

import importlib
import json

import numpy as np
import pytest
from synthetic_runs import cage_run  # tests/helpers (conftest.py)

import hsbearing
from hsbearing.analysis import annotate

# the modules (the package re-exports annotate from orbit)
_cl = importlib.import_module("hsbearing.analysis.whirl")
_orbit = importlib.import_module("hsbearing.analysis.orbit")


@pytest.fixture(scope="module")
def case():
    return hsbearing.load_case("zhang2016")


def _growing(case):
    """A whirl whose radius grows through the window (the classifier answers at its growth test)."""
    ds = cage_run("period", case, n_rev=60, transient=False)
    t = ds["time"].values
    g = np.exp(2.0 * t / t[-1])
    return ds.assign(cage_center_y=ds["cage_center_y"] * g, cage_center_z=ds["cage_center_z"] * g,
                     cage_velocity_y=ds["cage_velocity_y"] * g, cage_velocity_z=ds["cage_velocity_z"] * g)


RUNS = {
    "period": lambda c: cage_run("period", c, n_rev=60),
    "quasi": lambda c: cage_run("quasi", c, n_rev=60),
    "k": lambda c: cage_run("k", c, k=3, n_rev=60),
    "still": lambda c: cage_run("period", c, n_rev=60, R=1e-10, transient=False),  # answered by the still test
    "growing": _growing,
    "no angle": lambda c: cage_run("quasi", c, n_rev=60, with_angle=False),
}


def _text(ds) -> str:
    """Every attribute and variable of an annotated run, as one comparable text (NaN-safe)."""
    return json.dumps({"attrs": {k: str(v) for k, v in ds.attrs.items()},
                       "vars": {k: np.asarray(v.values).tolist() for k, v in ds.variables.items()}},
                      sort_keys=True, default=str)


@pytest.mark.parametrize("section", ["transverse", "cage_revolution"])
@pytest.mark.parametrize("run", list(RUNS))
def test_second_section_reuses_growth_and_lock_with_identical_results(case, run, section, monkeypatch):
    ds = RUNS[run](case)
    real = _cl.classify_motion

    # reference: every classification computes its own growth and lock (as before the reuse)
    def fresh(*a, growth=None, lock=None, **kw):
        return real(*a, **kw)

    monkeypatch.setattr(_orbit, "_motion", fresh)
    before = annotate(ds, case, section=section)
    monkeypatch.setattr(_orbit, "_motion", real)

    calls = {"growth": 0, "lock": 0}
    g0, l0 = _cl.whirl_growth, _cl.whirl_lock

    def growth(*a, **kw):
        calls["growth"] += 1
        return g0(*a, **kw)

    def lock(*a, **kw):
        calls["lock"] += 1
        return l0(*a, **kw)

    monkeypatch.setattr(_cl, "whirl_growth", growth)
    monkeypatch.setattr(_cl, "whirl_lock", lock)
    after = annotate(ds, case, section=section)
    assert calls["growth"] == 1  # once for both sections (it was twice)
    assert calls["lock"] == 1
    assert after.attrs["classification_alternative_section"] != section
    assert _text(after) == _text(before)
    if run == "growing":  # the case is what it claims to be: both sections answer at the growth test
        assert after.attrs["classification_kind"] == "growing"
        assert after.attrs["classification_alternative"] == "undetermined"
    if run == "still":
        assert after.attrs["classification_kind"] == "still"
