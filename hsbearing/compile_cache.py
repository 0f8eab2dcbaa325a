"""Keep numba's on-disk cache of the package's compiled functions in step with what they bake in.

numba keys the cache of a ``@njit(cache=True)`` function on the source of the one file that defines it.
Compiled code also bakes in (a) the functions it calls from other modules (inlined or linked into the
same machine code) and (b) the *values* of the global constants it reads (arrays, scalars, tuples:
numba freezes a global at compile time).  An edit of a callee's module, or of a constant table such as
the traction-law constants of :mod:`hsbearing.models.traction.zhang2016`, therefore leaves numba loading
stale machine code.

This module keys the package's numba caches on both:

- **sources** -- the SHA-256 of every package file in the import closure of the modules that define a
  ``cache=True`` function.  The modules are found by parsing the package (any call with the keyword
  ``cache=True`` in a module that imports numba), the closure by following their ``import`` /
  ``from ... import`` statements (anywhere in the module) transitively within the package;
- **values** -- for each cached function, the SHA-256 of the global names its bytecode reads
  (including ``module.NAME`` attributes) whose values are arrays, numbers, strings or tuples of them.

Every module that defines a cached function calls :func:`check_compile_cache` with its ``globals()``
before any of its compiled functions can run (at its end, or before an import-time call).  The first
call in a process compares the source fingerprint with the stamp file kept next to the caches; each call
compares the value digests of the module's cached functions.  Any difference deletes *all* numba cache
files (``*.nbi``, ``*.nbc``) of *all* package directories that hold a cached module, in the cache
location numba uses in this process (``NUMBA_CACHE_DIR``, the in-tree ``__pycache__`` or the user-wide
cache), and rewrites the stamp (atomically; the directory is created when missing, so that a run with
``PYTHONDONTWRITEBYTECODE=1`` keeps its caches).  numba then recompiles once.

Values are hashed for a function the first time a check sees it in a process, so a global defined after
an early check (one placed before an import-time call) is covered by the source fingerprint only.
"""

from __future__ import annotations

import ast
import hashlib
import json
import os
import re
import sys
import tempfile
from pathlib import Path

__all__ = ["cached_modules", "import_closure", "source_fingerprint", "value_digest", "check_compile_cache",
           "cache_dirs", "STAMP_NAME"]

PACKAGE = "hsbearing"
ROOT = Path(__file__).resolve().parent
#: File name of the fingerprint stamp, in the cache directory numba uses for the package root.
STAMP_NAME = "hsbearing_numba_fingerprint.json"
_FORMAT = 1

_source_fp: dict[Path, str] = {}
_cached_mods: dict[Path, list[str]] = {}
_seen: dict[str, dict[str, str]] = {}  # stamp path -> {function: value digest} checked in this process


# ------------------------------------------------------------------------------------------ import graph
def _module_path(name: str, root: Path = ROOT) -> Path | None:
    """File of package module ``name`` (``hsbearing.a.b`` -> a/b.py or a/b/__init__.py), None if not one."""
    parts = name.split(".")
    if parts[0] != PACKAGE:
        return None
    base = root.joinpath(*parts[1:])
    for p in (base.with_suffix(".py") if len(parts) > 1 else None, base / "__init__.py"):
        if p is not None and p.is_file():
            return p
    return None


def _module_name(path: Path, root: Path = ROOT) -> str:
    rel = path.relative_to(root).with_suffix("")
    parts = [PACKAGE, *rel.parts]
    if parts[-1] == "__init__":
        parts.pop()
    return ".".join(parts)


def _parse(path: Path) -> ast.Module:
    return ast.parse(path.read_bytes(), filename=str(path))


def _defines_cached_function(tree: ast.Module) -> bool:
    imports_numba = any(
        (isinstance(n, ast.Import) and any(a.name.split(".")[0] == "numba" for a in n.names))
        or (isinstance(n, ast.ImportFrom) and (n.module or "").split(".")[0] == "numba")
        for n in ast.walk(tree))
    if not imports_numba:
        return False
    return any(isinstance(n, ast.Call) and any(
        k.arg == "cache" and isinstance(k.value, ast.Constant) and k.value.value is True for k in n.keywords)
        for n in ast.walk(tree))


def cached_modules(root: Path = ROOT) -> list[str]:
    """Names of the package modules that define a numba function with ``cache=True`` (parsed, not imported)."""
    root = Path(root).resolve()
    if root not in _cached_mods:
        _cached_mods[root] = _find_cached_modules(root)
    return list(_cached_mods[root])


def _find_cached_modules(root: Path) -> list[str]:
    out = []
    for path in sorted(root.rglob("*.py")):
        if "__pycache__" in path.parts:
            continue
        try:
            text = path.read_bytes()
            if b"numba" not in text or not re.search(rb"\bcache\s*=\s*True", text):  # cheap pre-filter
                continue
            tree = ast.parse(text, filename=str(path))
        except (SyntaxError, OSError):
            continue
        if _defines_cached_function(tree):
            out.append(_module_name(path, root))
    return out


def _imports(path: Path, name: str, root: Path) -> set[str]:
    """Package modules imported anywhere in the module ``name`` (file ``path``)."""
    is_pkg = path.name == "__init__.py"
    pkg = name if is_pkg else name.rpartition(".")[0]
    found: set[str] = set()
    for n in ast.walk(_parse(path)):
        if isinstance(n, ast.Import):
            for a in n.names:
                parts = a.name.split(".")
                for i in range(1, len(parts) + 1):  # "import a.b.c" binds a and executes a, a.b, a.b.c
                    found.add(".".join(parts[:i]))
        elif isinstance(n, ast.ImportFrom):
            if n.level:
                base_parts = pkg.split(".")
                if n.level > 1:
                    base_parts = base_parts[: len(base_parts) - (n.level - 1)]
                base = ".".join(base_parts + ([n.module] if n.module else []))
            else:
                base = n.module or ""
            found.add(base)
            for a in n.names:  # "from a import b": b may be a submodule
                found.add(f"{base}.{a.name}")
    return {m for m in found if _module_path(m, root) is not None}


def import_closure(modules, root: Path = ROOT) -> list[Path]:
    """Files of ``modules`` and of every package module they import, transitively (sorted)."""
    todo = list(modules)
    files: dict[str, Path] = {}
    while todo:
        m = todo.pop()
        if m in files:
            continue
        p = _module_path(m, root)
        if p is None:
            continue
        files[m] = p
        todo.extend(_imports(p, m, root) - files.keys())
    return sorted(files.values())


def source_fingerprint(root: Path = ROOT) -> str:
    """SHA-256 over the relative paths and bytes of :func:`import_closure` of :func:`cached_modules`."""
    root = Path(root).resolve()
    if root not in _source_fp:
        h = hashlib.sha256(f"format {_FORMAT}\n".encode())
        for p in import_closure(cached_modules(root), root):
            h.update(str(p.relative_to(root)).encode() + b"\0" + p.read_bytes() + b"\0")
        _source_fp[root] = h.hexdigest()
    return _source_fp[root]


# ------------------------------------------------------------------------------------------ captured values
def _feed(h, value, depth: int = 0) -> bool:
    """Add a constant ``value`` to hash ``h``; False (nothing added) for code, modules, classes and the like."""
    import numpy as np

    if isinstance(value, np.ndarray):
        h.update(f"ndarray {value.dtype.str} {value.shape}".encode())
        h.update(np.ascontiguousarray(value).tobytes())
        return True
    if value is None or isinstance(value, (bool, int, float, complex, str, bytes, np.generic)):
        h.update(f"{type(value).__name__} {value!r}".encode())
        return True
    if isinstance(value, (tuple, list)) and depth < 4:
        h.update(f"{type(value).__name__} {len(value)}".encode())
        for v in value:
            if not _feed(h, v, depth + 1):
                h.update(b"?")
        return True
    return False


def _names(code) -> set[str]:
    names = set(code.co_names)
    for c in code.co_consts:
        if hasattr(c, "co_names"):
            names |= _names(c)
    return names


def value_digest(dispatcher) -> str:
    """SHA-256 of the global constants (and ``module.CONSTANT`` attributes) read by ``dispatcher.py_func``."""
    import types

    f = dispatcher.py_func
    g = f.__globals__
    names = _names(f.__code__)
    h = hashlib.sha256()
    for n in sorted(names):
        if n not in g:
            continue
        v = g[n]
        if isinstance(v, types.ModuleType):
            for a in sorted(names):
                if hasattr(v, a) and _feed(hashlib.sha256(), getattr(v, a)):
                    h.update(f"{n}.{a}=".encode())
                    _feed(h, getattr(v, a))
        else:
            h.update(f"{n}=".encode())
            if not _feed(h, v):
                h.update(b"-")
    return h.hexdigest()


def _cached_dispatchers(namespace: dict) -> list:
    out = []
    for v in list(namespace.values()):
        cache = getattr(v, "_cache", None)
        py_func = getattr(v, "py_func", None)
        if py_func is None or cache is None or not hasattr(cache, "_impl"):  # NullCache: not cached
            continue
        if py_func.__module__ == namespace.get("__name__"):
            out.append(v)
    return out


# ------------------------------------------------------------------------------------------ cache files
def cache_dirs(dispatcher, root: Path = ROOT) -> tuple[Path, list[Path]]:
    """(stamp file, cache directories of every package directory holding a cached module) in the cache
    location numba chose for ``dispatcher`` (same locator class, applied to the other directories)."""
    loc = dispatcher._cache._impl.locator
    cls = type(loc)
    dirs = sorted({_module_path(m, root).parent for m in cached_modules(root)})
    try:
        stamp_dir = Path(cls(dispatcher.py_func, str(root / "__init__.py")).get_cache_path())
        cdirs = [Path(cls(dispatcher.py_func, str(d / "__init__.py")).get_cache_path()) for d in dirs]
    except Exception:  # noqa: BLE001 - a locator that is not per directory (zip, IPython): its own dir only
        stamp_dir = Path(loc.get_cache_path())
        cdirs = [stamp_dir]
    return stamp_dir / STAMP_NAME, cdirs


def _wipe(dirs) -> None:
    for d in dirs:
        if not d.is_dir():
            continue
        for f in list(d.glob("*.nbi")) + list(d.glob("*.nbc")):
            try:
                f.unlink()
            except OSError:  # a concurrent process removed it, or read-only
                pass


def _read(stamp: Path) -> dict:
    try:
        data = json.loads(stamp.read_text())
        return data if isinstance(data, dict) else {}
    except (OSError, ValueError):
        return {}


def _write(stamp: Path, data: dict) -> None:
    try:
        stamp.parent.mkdir(parents=True, exist_ok=True)
        fd, tmp = tempfile.mkstemp(dir=stamp.parent, prefix=".fingerprint-", suffix=".tmp")
        with os.fdopen(fd, "w") as fh:
            json.dump(data, fh, indent=0, sort_keys=True)
        os.replace(tmp, stamp)
    except OSError:  # read-only location: numba cannot write there either
        pass


def check_compile_cache(namespace: dict, root: Path = ROOT) -> bool:
    """Delete every numba cache file of the package when its sources or the constants captured by the
    cached functions of the module whose ``globals()`` is ``namespace`` differ from the stamp.

    Returns True when caches were deleted.  Call before any compiled function of the module can run.
    """
    disp = _cached_dispatchers(namespace)
    if not disp:
        return False
    root = Path(root).resolve()
    stamp, dirs = cache_dirs(disp[0], root)
    key = str(stamp)
    seen = _seen.setdefault(key, {})
    fp = source_fingerprint(root)
    data = _read(stamp)
    wiped = False
    if data.get("format") != _FORMAT or data.get("sources") != fp or not isinstance(data.get("values"), dict):
        _wipe(dirs)
        wiped = True
        data = {"format": _FORMAT, "sources": fp, "values": dict(seen)}
    values = data["values"]
    changed = wiped
    for d in disp:
        name = f"{d.py_func.__module__}.{d.py_func.__qualname__}"
        if name in seen:
            continue
        seen[name] = value_digest(d)
        old = values.get(name)
        if old != seen[name]:
            if old is not None and not wiped:
                _wipe(dirs)
                wiped = True
                values.clear()
                values.update(seen)
            values[name] = seen[name]
            changed = True
    if changed:
        _write(stamp, data)
    if wiped and os.environ.get("HSBEARING_CACHE_DEBUG"):
        print(f"hsbearing: numba caches invalidated ({namespace.get('__name__')})", file=sys.stderr)
    return wiped
