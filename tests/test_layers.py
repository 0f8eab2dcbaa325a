"""The package's layers, read from its imports (ast, every ``import`` including those inside functions;
issue 19 item 2):

- ``hsbearing.models`` is pure physics: it imports only ``hsbearing.models``, ``hsbearing.errors``,
  ``hsbearing.jit`` and ``hsbearing.compile_cache`` (which imports no package module; nothing above it: no cli, plotting, sweeps, study, maps, systems, dynamics, solvers,
  case or results);
- ``hsbearing.solvers`` is numerics that knows nothing of bearings: it imports only ``hsbearing.solvers``,
  ``hsbearing.errors`` and ``hsbearing.jit``;
- no module imports one that (directly or through others) imports it back: no import circles.

``ALLOWED`` lists the exceptions that must stay for now, each with its reason and issue: a test that
an exception is still needed fails once it is not, so the list only shrinks.
"""

from __future__ import annotations

import ast
from pathlib import Path

import pytest

PKG = Path(__file__).resolve().parents[1] / "hsbearing"

LAYER_RULES = {
    "hsbearing.models": ("hsbearing.models", "hsbearing.errors", "hsbearing.jit", "hsbearing.compile_cache"),
    "hsbearing.solvers": ("hsbearing.solvers", "hsbearing.errors", "hsbearing.jit", "hsbearing.compile_cache"),
    # below everything: the numba compile-cache keying imports no package module at all
    "hsbearing.compile_cache": (),
}

# (importer, imported) -> reason.  Each must be a real edge today (test_exceptions_still_needed).
ALLOWED: dict[tuple[str, str], str] = {}  # issue 19: zero exceptions (the last four removed in session 4)


def _modules() -> dict[str, Path]:
    out = {}
    for f in sorted(PKG.rglob("*.py")):
        parts = list(f.relative_to(PKG.parent).with_suffix("").parts)
        if parts[-1] == "__init__":
            parts = parts[:-1]
        out[".".join(parts)] = f
    return out


MODULES = _modules()


def _resolve(name: str) -> str:
    """The module an imported dotted name refers to (``pkg.mod.attr`` -> ``pkg.mod``)."""
    while name and name not in MODULES:
        name = name.rpartition(".")[0]
    return name


def imports_of(mod: str) -> set[str]:
    path = MODULES[mod]
    is_pkg = path.name == "__init__.py"
    out: set[str] = set()
    for node in ast.walk(ast.parse(path.read_text(encoding="utf-8"))):
        if isinstance(node, ast.Import):
            out |= {_resolve(a.name) for a in node.names if a.name.startswith("hsbearing")}
        elif isinstance(node, ast.ImportFrom):
            if node.level:
                base = mod.split(".") if is_pkg else mod.split(".")[:-1]
                base = base[: len(base) - (node.level - 1)]
                target = ".".join(base + ([node.module] if node.module else []))
            else:
                target = node.module or ""
            if not target.startswith("hsbearing"):
                continue
            for a in node.names:  # ``from pkg import submodule`` imports the submodule
                sub = f"{target}.{a.name}"
                out.add(sub if sub in MODULES else _resolve(target))
    out.discard(mod)
    out.discard("")
    return out


GRAPH = {m: imports_of(m) for m in MODULES}


def _layer_violations() -> list[tuple[str, str]]:
    bad = []
    for mod, deps in GRAPH.items():
        for layer, allowed in LAYER_RULES.items():
            if mod == layer or mod.startswith(layer + "."):
                for d in deps:
                    if not any(d == a or d.startswith(a + ".") for a in allowed):
                        bad.append((mod, d))
    return sorted(bad)


def _cycles() -> list[list[str]]:
    """Strongly connected components of more than one module (Tarjan), each sorted; the ``ALLOWED`` edges
    are left out (each is an import circle on its own, listed with its reason)."""
    graph = {m: {d for d in deps if (m, d) not in ALLOWED} for m, deps in GRAPH.items()}
    index, low, on, stack, out = {}, {}, set(), [], []
    counter = [0]

    def visit(v):
        index[v] = low[v] = counter[0]
        counter[0] += 1
        stack.append(v)
        on.add(v)
        for w in graph.get(v, ()):
            if w not in graph:
                continue
            if w not in index:
                visit(w)
                low[v] = min(low[v], low[w])
            elif w in on:
                low[v] = min(low[v], index[w])
        if low[v] == index[v]:
            comp = []
            while True:
                w = stack.pop()
                on.discard(w)
                comp.append(w)
                if w == v:
                    break
            if len(comp) > 1:
                out.append(sorted(comp))

    for v in sorted(graph):
        if v not in index:
            visit(v)
    return out


def test_graph_is_read():
    """The parser sees the imports (a broken reader would pass every rule)."""
    assert "hsbearing.models.hertz" in GRAPH["hsbearing.models.quasistatic_physics"]
    assert "hsbearing.case" in GRAPH["hsbearing.cli"]
    assert len(MODULES) > 40


def test_models_and_solvers_import_nothing_above_them():
    bad = [e for e in _layer_violations() if e not in ALLOWED]
    assert not bad, "layer violations (importer -> imported):\n" + "\n".join(f"  {a} -> {b}" for a, b in bad)


def test_no_import_cycles():
    cycles = _cycles()
    assert not cycles, "import circles:\n" + "\n".join("  " + " <-> ".join(c) for c in cycles)


@pytest.mark.parametrize("edge", sorted(ALLOWED))
def test_exceptions_still_needed(edge):
    a, b = edge
    assert b in GRAPH.get(a, set()), f"{a} no longer imports {b}: remove the exception from ALLOWED"
