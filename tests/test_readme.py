"""The README stays short and opens with what the package does; every local link in it resolves."""

from __future__ import annotations

import re
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
README = (ROOT / "README.md").read_text(encoding="utf-8")


def test_readme_is_short_and_opens_with_what_it_does():
    lines = README.splitlines()
    assert len(lines) <= 150, f"README.md has {len(lines)} lines (at most 150: long tables belong in docs/)"
    first_paragraph = README.split("\n\n")[1]
    assert "simulates the dynamics and friction of rolling ball bearings" in first_paragraph
    assert not re.search(r"\b(seed 0\d\d|issue \d+|session \d+)\b", README)


def test_readme_local_links_resolve():
    for target in re.findall(r"\]\(([^)#]+)(?:#[^)]*)?\)", README):
        if "://" in target:
            continue
        assert (ROOT / target).exists(), f"README links to {target}, which does not exist"
