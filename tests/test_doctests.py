"""The Examples sections of the public API's docstrings run as doctests (default tier; < 10 s together).

Examples that simulate (``simulate``, ``quasi_static``, ``sweep``) are marked ``+SKIP`` in their docstrings: they
are shown in the API reference, and the gallery scripts run the same calls in the slow tier.
"""

from __future__ import annotations

import doctest
import importlib

import pytest

MODULES = [
    "hsbearing",
    "hsbearing.case.load",
    "hsbearing.models.hertz",
    "hsbearing.models.traction",
    "hsbearing.analysis.slip",
    "hsbearing.display",
]


@pytest.mark.parametrize("name", MODULES)
def test_docstring_examples(name):
    module = importlib.import_module(name)
    finder = doctest.DocTestFinder(exclude_empty=True)
    runner = doctest.DocTestRunner(optionflags=doctest.ELLIPSIS | doctest.NORMALIZE_WHITESPACE)
    tests = [t for t in finder.find(module, name) if t.examples]
    assert tests, f"{name}: no docstring examples found"
    for t in tests:
        runner.run(t)
    result = runner.summarize(verbose=False)
    assert result.failed == 0, f"{name}: {result.failed} of {result.attempted} docstring examples failed"
