"""Names in physics and papers, not history: no issue, session or seed numbers in the package (code, bundled
cases, lubricants, studies), in the names of test, tool and benchmark files, or in the docs pages listed in
CLEAN_DOCS; old module paths still import, with a DeprecationWarning, for one release."""

from __future__ import annotations

import importlib
import re
import subprocess
import sys
import warnings

import pytest
from conftest import ROOT

HISTORY = re.compile(r"\b(issue|session)\s*#?\d+|\bseed\s*_?0\d\d\b|\bseed0\d\d\b", re.IGNORECASE)


#: history labels in prose: the package's words plus "round N" and hyphenated forms ("issue-14", "seed-004")
DOC_HISTORY = re.compile(r"\b(issue|session|round)[\s-]*#?\d+|\bseed[\s_-]*0\d\d\b", re.IGNORECASE)

#: explanation pages that name papers and changes by their physics (zhang2016, "the guide-land film correction"),
#: never by issue, session, round or seed number; add a page here once it is clean
CLEAN_DOCS = (
    "docs/dynamics.md",
    "docs/analysis.md",
    "docs/kernel.md",
    "docs/life.md",
    "docs/pocket.md",
    "docs/quasistatic.md",
    "docs/output.md",
    "docs/nomenclature.md",
    "docs/numerics.md",
    "docs/validation/cage_whirl.md",
    "docs/validation/dgbb_friction.md",
    "docs/validation/gyro.md",
    "docs/validation/quasistatic.md",
    "docs/validation/wire_race.md",
    "docs/validation/nasa_heat_generation.md",
    "docs/traction.md",
    "docs/power_loss.md",
    "docs/thermal.md",
    "docs/testing.md",
    "docs/validation/summary.md",
    "docs/validation/index.md",
    "docs/guide/case_files.md",
    "docs/guide/getting_started.md",
    "docs/guide/lubricants.md",
    "docs/guide/python_api.md",
)

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


def test_doc_history_pattern_is_live():
    for text in ("issue 14", "(issue 28, item 4)", "Session 5", "session-4", "round 3", "seed 004", "seed-004",
                 "the issue-14 land correction"):
        assert DOC_HISTORY.search(text), text
    for text in ("zhang2016 Table 3", "the dgbb_prl paper", "around 0.5", "rounded to 0.01", "round-off",
                 "gravity only seeds the start-up", "`seed_cubes`", "issues a warning"):
        assert not DOC_HISTORY.search(text), text


@pytest.mark.parametrize("page", CLEAN_DOCS)
def test_no_history_words_in_clean_docs(page):
    if not (ROOT / "docs").is_dir():  # an sdist ships no docs
        pytest.skip("no docs/ in this checkout")
    path = ROOT / page
    assert path.is_file(), f"{page} is listed in CLEAN_DOCS but does not exist (renamed? update the list)"
    bad = [f"{page}:{i}: {line.strip()[:100]}" for i, line in enumerate(path.read_text(encoding="utf-8").splitlines(), 1)
           if DOC_HISTORY.search(line)]
    assert not bad, "history labels in a cleaned docs page (name the paper or the physics):\n" + "\n".join(bad)
