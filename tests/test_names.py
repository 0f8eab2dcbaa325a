"""Names in physics and papers, not history: no issue, session or seed numbers in the package (code, bundled
cases, lubricants, studies) or in the names of test, tool and benchmark files; old module paths still import,
with a DeprecationWarning, for one release."""

from __future__ import annotations

import importlib
import re
import subprocess
import sys
import warnings

import pytest
from conftest import ROOT

HISTORY = re.compile(r"\b(issue|session)\s*#?\d+|\bseed\s*_?0\d\d\b|\bseed0\d\d\b", re.IGNORECASE)


#: lines that must keep an old word, with the reason: (file, text the line contains)
EXEMPT = {
    ("hsbearing/case/load.py", "CHOICE_ALIASES"): "the old spelling of a case value, accepted for one release",
}


def _tracked(*dirs: str) -> list[str]:
    out = subprocess.run(["git", "ls-files", *dirs], cwd=ROOT, capture_output=True, text=True)
    if out.returncode != 0:  # not a git checkout (an sdist): every file on disk
        return [str(p.relative_to(ROOT)) for d in dirs for p in (ROOT / d).rglob("*") if p.is_file()]
    return out.stdout.split()


def test_history_pattern_is_live():
    for text in ("issue 27", "Session 4", "seed 004", "seed003", "(issue #12)"):
        assert HISTORY.search(text), text
    for text in ("Zhang et al. 2016", "zhang2016", "random seed 7", "issues a warning", "seed=0"):
        assert not HISTORY.search(text), text


def test_no_history_words_in_the_package():
    bad = []
    for f in _tracked("hsbearing"):
        path = ROOT / f
        if path.suffix not in (".py", ".toml", ".md", ".txt"):
            continue
        for i, line in enumerate(path.read_text(encoding="utf-8").splitlines(), 1):
            if HISTORY.search(line) and not any(f == ef and et in line for ef, et in EXEMPT):
                bad.append(f"{f}:{i}: {line.strip()[:100]}")
    assert not bad, "history words in the package:\n" + "\n".join(bad)


def test_no_history_words_in_file_names():
    bad = [f for f in _tracked("tests", "tools", "benchmarks") if re.search(r"issue\d|session\d|seed\d", f, re.I)]
    assert not bad, bad


def test_old_module_paths_warn_and_give_the_new_module():
    import hsbearing  # noqa: F401 - installs the old paths
    from hsbearing._moved import MOVED

    old = "hsbearing.sweeps"
    sys.modules.pop(old, None)
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        mod = importlib.import_module(old)
    assert mod is importlib.import_module(MOVED[old])
    assert any(issubclass(w.category, DeprecationWarning) and MOVED[old] in str(w.message) for w in caught)


@pytest.mark.parametrize("old", ["hsbearing.dynamics", "hsbearing.models.kernel", "hsbearing.study"])
def test_each_old_path_resolves(old):
    from hsbearing._moved import MOVED

    with warnings.catch_warnings():
        warnings.simplefilter("ignore", DeprecationWarning)
        assert importlib.import_module(old) is importlib.import_module(MOVED[old])
