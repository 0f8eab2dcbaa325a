"""The package's layers, read from its imports (ast, every ``import`` including those inside functions):

- the layers, lowest first (``LAYERS``): foundations (errors, jit, compile_cache, _version) < physics (models,
  solvers) < inputs and outputs (units, lubricant, case, results, display) < analysis and shared figures (analysis,
  plotting) < systems < workflows < front ends (cli and the package API); a module imports only from its own layer
  or below;
- peers do not import each other: models and solvers, and one system package and another (the registry
  ``hsbearing.systems`` and ``systems.base`` excepted);

- ``hsbearing.models`` is pure physics: it imports only ``hsbearing.models``, ``hsbearing.errors``,
  ``hsbearing.jit`` and ``hsbearing.compile_cache`` (which imports no package module; nothing above it: no cli, plotting, sweeps, study, maps, systems, dynamics, solvers,
  case or results);
- ``hsbearing.solvers`` is numerics that knows nothing of bearings: it imports only ``hsbearing.solvers``,
  ``hsbearing.errors`` and ``hsbearing.jit``;
- no module imports one that (directly or through others) imports it back: no import circles.

``ALLOWED`` lists the exceptions that must stay for now, each with its reason: a test that an exception is still
needed fails once it is not, so the list only shrinks.
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

#: the layers, lowest first; a module belongs to the first prefix it matches (``hsbearing`` alone: the package API)
LAYERS = (
    ("foundations", ("hsbearing._version", "hsbearing._moved", "hsbearing._interrupt", "hsbearing.errors", "hsbearing.jit",
                     "hsbearing.compile_cache")),
    ("physics", ("hsbearing.models", "hsbearing.solvers")),
    ("inputs and outputs", ("hsbearing.units", "hsbearing.lubricant", "hsbearing.case", "hsbearing.results",
                            "hsbearing.display")),
    ("analysis and shared figures", ("hsbearing.analysis", "hsbearing.plotting")),
    ("systems", ("hsbearing.systems",)),
    ("workflows", ("hsbearing.workflows",)),
    ("front ends", ("hsbearing.cli", "hsbearing")),
)
#: packages whose direct sub-packages are peers that must not import each other
PEER_PARENTS = ("hsbearing.systems",)
#: modules of a peer parent that are shared by its peers (the registry and the interface)
PEER_SHARED = ("hsbearing.systems", "hsbearing.systems.base")

# (importer, imported) -> reason.  Each must be a real edge today (test_exceptions_still_needed).
ALLOWED: dict[tuple[str, str], str] = {
    ("hsbearing.systems.deep_groove", "hsbearing.systems.angular_contact"):
        "a deep-groove bearing runs the ball-bearing engine of the angular-contact system (Zhang et al. 2016 model "
        "at any contact angle): its System takes simulate/build_model/summaries from there",
    ("hsbearing.systems.deep_groove.friction", "hsbearing.systems.angular_contact.quasistatic"):
        "the dgbb_prl sliding method needs the contact loads of the ball-bearing quasi-static solver",
}


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


def layer_of(mod: str) -> int:
    for i, (_, prefixes) in enumerate(LAYERS):
        if any(mod == p or (p != "hsbearing" and mod.startswith(p + ".")) for p in prefixes):
            return i
    raise AssertionError(f"{mod} is in no layer: add it to LAYERS")


def _upward_imports() -> list[tuple[str, str]]:
    return sorted((m, d) for m, deps in GRAPH.items() for d in deps if layer_of(d) > layer_of(m))


def _peer_of(mod: str) -> str | None:
    for parent in PEER_PARENTS:
        if mod.startswith(parent + ".") and mod not in PEER_SHARED:
            return ".".join(mod.split(".")[: parent.count(".") + 2])
    return None


def _peer_imports() -> list[tuple[str, str]]:
    bad = []
    for m, deps in GRAPH.items():
        for d in deps:
            pm, pd = _peer_of(m), _peer_of(d)
            if pm and pd and pm != pd:
                bad.append((m, d))
    bad += [(m, d) for m, deps in GRAPH.items() for d in deps
            if (m.startswith("hsbearing.models") and d.startswith("hsbearing.solvers"))
            or (m.startswith("hsbearing.solvers") and d.startswith("hsbearing.models"))]
    return sorted(bad)


def test_every_module_has_a_layer():
    for m in MODULES:
        layer_of(m)


def test_no_module_imports_a_higher_layer():
    bad = [e for e in _upward_imports() if e not in ALLOWED]
    assert not bad, "imports of a higher layer (importer -> imported):\n" + "\n".join(
        f"  {a} ({LAYERS[layer_of(a)][0]}) -> {b} ({LAYERS[layer_of(b)][0]})" for a, b in bad)


def test_peers_do_not_import_each_other():
    bad = [e for e in _peer_imports() if e not in ALLOWED]
    assert not bad, "imports between peers:\n" + "\n".join(f"  {a} -> {b}" for a, b in bad)


def test_layer_rules_are_live():
    """The checks see a violation when there is one (a broken reader or rule would pass everything)."""
    assert layer_of("hsbearing.models.hertz") < layer_of("hsbearing.case") < layer_of("hsbearing.systems.gyro.model")
    assert layer_of("hsbearing.workflows.sweeps") < layer_of("hsbearing.cli") == layer_of("hsbearing")
    assert _peer_of("hsbearing.systems.gyro.model") == "hsbearing.systems.gyro"
    assert _peer_of("hsbearing.systems.base") is None


def test_top_level_is_small():
    """The top of the package keeps the API and the foundations: at most 12 modules."""
    top = sorted(p.name for p in PKG.glob("*.py"))
    assert len(top) <= 12, top


def test_graph_is_read():
    """The parser sees the imports (a broken reader would pass every rule)."""
    assert "hsbearing.models.hertz" in GRAPH["hsbearing.models.ball_bearing.quasistatic"]
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
