"""docs/nomenclature.md lists every case key and every registered output variable (one nomenclature)."""

import importlib.util
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]


def test_nomenclature_is_current():
    spec = importlib.util.spec_from_file_location("make_nomenclature", ROOT / "tools" / "generators" / "make_nomenclature.py")
    mod = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(mod)
    doc = (ROOT / "docs" / "nomenclature.md").read_text()
    assert mod.render(doc) == doc, "docs/nomenclature.md is stale: run .venv/bin/python tools/generators/make_nomenclature.py"
