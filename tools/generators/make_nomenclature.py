"""Regenerate the generated part of docs/nomenclature.md from the case SCHEMA and the output registry.

Run: .venv/bin/python tools/generators/make_nomenclature.py   (tests/test_nomenclature.py checks it is current)
"""

from __future__ import annotations

import importlib
import pkgutil
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]
DOC = ROOT / "docs" / "nomenclature.md"
BEGIN = "<!-- BEGIN GENERATED -->"
END = "<!-- END GENERATED -->"


def import_all() -> None:
    import hsbearing

    for mod in pkgutil.walk_packages(hsbearing.__path__, "hsbearing."):
        if mod.name.endswith("__main__") or ".cases" in mod.name:
            continue
        try:
            importlib.import_module(mod.name)
        except Exception as exc:  # a module that cannot import is reported, not hidden
            print(f"warning: cannot import {mod.name}: {exc}", file=sys.stderr)


def generated() -> str:
    import_all()
    from hsbearing.case import DIMENSIONS, SCHEMA
    from hsbearing.results import VARIABLES

    out = ["## Case-file keys (`hsbearing/case.py` SCHEMA)", "", "| key | SI unit | meaning |", "|---|---|---|"]
    for table, fields in SCHEMA.items():
        for key, fld in fields.items():
            unit = DIMENSIONS.get(fld.kind, {"number": "1", "int": "count", "str": "text", "choice": "one of: " + ", ".join(fld.choices), "bool": "true/false"}.get(fld.kind, ""))
            out.append(f"| `{table}.{key}` | {unit} | {fld.doc} |")
    out += ["", "## Output variables (`hsbearing.results.VARIABLES`)", "", "| name | dims | units | meaning |", "|---|---|---|---|"]
    for name in sorted(VARIABLES):
        v = VARIABLES[name]
        if name.startswith("test_only"):
            continue
        out.append(f"| `{name}` | {', '.join(v.dims) or 'scalar'} | {v.units} | {v.long_name} |")
    from hsbearing.results import ATTR_UNITS

    out += ["", "## Global attributes with units (`hsbearing.results.ATTR_UNITS`)", "",
            "An archive stores next to each of these attributes a companion `NAME_units` (docs/output.md).", "",
            "| attribute | units |", "|---|---|"]
    for name in sorted(ATTR_UNITS):
        out.append(f"| `{name}` | {ATTR_UNITS[name]} |")
    return "\n".join(out) + "\n"


def render(existing: str) -> str:
    gen = generated()
    if BEGIN in existing and END in existing:
        head, _, rest = existing.partition(BEGIN)
        _, _, tail = rest.partition(END)
        return f"{head}{BEGIN}\n{gen}{END}{tail}"
    return existing.rstrip() + f"\n\n{BEGIN}\n{gen}{END}\n"


if __name__ == "__main__":
    DOC.write_text(render(DOC.read_text() if DOC.exists() else "# Nomenclature\n"))
    print(f"wrote {DOC}")
