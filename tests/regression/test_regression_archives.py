"""REGRESSION (not validation): every bundled case, run with the short settings of
``tools/generators/make_regression_archives.py``, gives the archive stored in ``tests/data/regression/``.

The stored archives are our own earlier outputs: they show that a refactoring changed no behaviour, not that
the behaviour is right.  Data variables, coordinates, their attrs and the global attrs are compared, except
the attrs that record when/where/which version (``IGNORED_ATTRS``).  Closed forms, quasi-static solves and
tables must agree to ``NON_ODE_RTOL`` (1e-10 of the largest magnitude among the variables of the same unit: a numba kernel compiled afresh, or for another CPU model,
and one loaded from the on-disk cache can differ in the last bit); the two ODE runs (``ODE_ARCHIVES``) are compared to ``ODE_RTOL`` of each
variable's scale (their solver statistics are not compared), because a change of floating-point evaluation
order in the integrator moves a trajectory within its integration tolerance.

After an intended change of behaviour: ``.venv/bin/python tools/generators/make_regression_archives.py [NAME ...]``
and commit the archives with a message that says why.
"""

from __future__ import annotations

import importlib.util
from pathlib import Path

import numpy as np
import pytest
import xarray as xr

_TOOL = Path(__file__).resolve().parents[2] / "tools" / "generators" / "make_regression_archives.py"
_spec = importlib.util.spec_from_file_location("make_regression_archives", _TOOL)
reg = importlib.util.module_from_spec(_spec)
_spec.loader.exec_module(reg)


def _open(path: Path) -> xr.Dataset:
    with xr.open_dataset(path) as ds:
        return ds.load()


@pytest.mark.parametrize("name", sorted(reg.RUNS))
def test_regression_archive_unchanged(name, tmp_path):
    stored = reg.ARCHIVE_DIR / f"{name}.nc"
    assert stored.is_file(), f"missing {stored}: run tools/generators/make_regression_archives.py {name}"
    new = _open(reg.produce(name, tmp_path / f"{name}.nc"))
    diffs = reg.compare(_open(stored), new, name)
    assert not diffs, f"{name} differs from its regression archive:\n  " + "\n  ".join(diffs[:20])


def test_every_bundled_case_has_an_archive():
    from hsbearing.case import list_cases

    covered = {args[1] for args in reg.RUNS.values()}
    assert set(list_cases()) <= covered, f"bundled cases without a regression archive: {set(list_cases()) - covered}"


def test_compare_sees_a_change():
    """The comparison can fail: a perturbed value, a dropped variable and a changed attr are all reported."""
    a = xr.Dataset({"x": ("t", np.array([1.0, 2.0, np.nan])), "y": ((), 3.0)}, attrs={"status": "ok", "created": "now"})
    b = a.copy(deep=True)
    b.attrs["created"] = "later"  # ignored: when it was written
    assert reg.compare(a, b, "zhang2016_friction") == []
    b["x"].values[0] = np.nextafter(1.0, 2.0)  # a last-bit difference (cold vs cached numba kernel) is not a change
    assert reg.compare(a, b, "zhang2016_friction") == []
    b["x"].values[0] = 1.0 + 10 * reg.NON_ODE_RTOL * 2.0
    assert any("x: values differ" in d for d in reg.compare(a, b, "zhang2016_friction"))
    assert reg.compare(a, b, "zhang2016_run") == []  # within the ODE tolerance
    b["x"].values[0] = 1.0 + 3 * reg.ODE_RTOL * 3.0  # RMS of the difference beyond ODE_RTOL of the unit's scale (3)
    assert any("x: values differ" in d for d in reg.compare(a, b, "zhang2016_run"))
    c = a.drop_vars("y")
    c.attrs["status"] = "failed"
    d = reg.compare(a, c, "zhang2016_life")
    assert any("only stored ['y']" in x for x in d) and any("attrs[status]" in x for x in d)


def test_json_attrs_of_an_ode_run_compare_their_numbers_within_the_ode_tolerance():
    """The classifier's details of an ODE run are JSON whose numbers move with the trajectory (a fresh numba compile
    against a cached one moved a growth radius by 5e-7 relative): compared number by number within ODE_RTOL; a
    changed label, key or a number beyond the tolerance is still a difference; exact for non-ODE archives."""
    d1 = '{"kind": "too-few-points", "growth": {"radii": [5.0928456751814645e-06, 1.0], "direction": ""}, "n": 0}'
    d2 = '{"kind": "too-few-points", "growth": {"radii": [5.092848355345589e-06, 1.0], "direction": ""}, "n": 0}'
    a = xr.Dataset({"x": ("t", np.array([1.0, 2.0]))}, attrs={"classification_details": d1})
    b = a.copy(deep=True)
    b.attrs["classification_details"] = d2
    assert reg.compare(a, b, "zhang2016_run") == []
    assert reg.compare(a, b, "zhang2016_friction") != []  # non-ODE: exact text
    for changed in (d2.replace("too-few-points", "1 period"), d2.replace('"n": 0', '"m": 0'),
                    d2.replace("1.0]", f"{1.0 + 2 * reg.ODE_RTOL}]")):
        b.attrs["classification_details"] = changed
        assert reg.compare(a, b, "zhang2016_run") != [], changed
