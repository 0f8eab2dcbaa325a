"""numba's on-disk cache never serves stale compiled physics (hsbearing/compile_cache.py, docs/dynamics.md).

numba keys a cached function on the source of its own file only.  The package keys all its numba caches
on the import closure of the cached modules and on the constants their functions capture.  The
end-to-end tests run on a *copy* of the package in a tmp directory (a cold cache of its own), each run in
a fresh subprocess, and evaluate the traction kernel ``coefficients_nb`` -- the cached function that
captured the traction constants of ``traction/zhang2016.py`` as a global and served them stale.
"""

from __future__ import annotations

import ast
import json
import os
import shutil
import subprocess
import sys
import textwrap
import types
from pathlib import Path

import numpy as np
import pytest

import hsbearing
from hsbearing import compile_cache as cc

PKG = Path(hsbearing.__file__).resolve().parent

# Evaluate the numba traction kernel and its numpy twin at one contact; report numba's cache statistics.
_PROBE = textwrap.dedent("""
    import json
    import hsbearing
    import hsbearing.models.ball_bearing.kernel  # imports every cached module of the kernel: all checks run
    from hsbearing.models.ball_bearing import pocket
    from hsbearing.models.traction import _kernels, zhang2016
    from hsbearing.models.traction import law_id
    from hsbearing import jit
    cold = jit.cache_is_cold([_kernels.coefficients_nb])
    lid = law_id("4109", "percent")
    args = (lid, 800.0, 20.0, 373.15, 2.3e11, 3.5e-3)
    nb = _kernels.coefficients_nb(*args)
    py = [float(v) for v in zhang2016.coefficients(*args)]
    def stats(d):
        s = d.stats
        return {"hits": sum(s.cache_hits.values()), "misses": sum(s.cache_misses.values())}
    print(json.dumps({"nb": list(nb), "py": py, "cold": cold, "file": hsbearing.__file__,
                      "coefficients_nb": stats(_kernels.coefficients_nb),
                      "rupture_table": stats(pocket._rupture_table)}))
""")


def _copy_package(tmp_path: Path) -> Path:
    dst = tmp_path / "pkg"
    shutil.copytree(PKG, dst / "hsbearing", ignore=shutil.ignore_patterns("__pycache__", "*.nbi", "*.nbc"))
    return dst


def _run(root: Path, **env_extra) -> dict:
    env = {k: v for k, v in os.environ.items() if k not in ("NUMBA_CACHE_DIR", "PYTHONDONTWRITEBYTECODE")}
    env["PYTHONPATH"] = str(root)
    env.update(env_extra)
    out = subprocess.run([sys.executable, "-c", _PROBE], cwd=root, env=env, capture_output=True, text=True,
                         timeout=600)
    assert out.returncode == 0, out.stderr[-3000:]
    res = json.loads(out.stdout.strip().splitlines()[-1])
    assert Path(res["file"]).resolve().parent == (root / "hsbearing").resolve()  # the copy, not the worktree
    return res


def test_cached_modules_and_closure_come_from_the_import_graph():
    mods = cc.cached_modules()
    for m in ("hsbearing.models.ball_bearing.kernel", "hsbearing.models.traction._kernels", "hsbearing.models.ball_bearing.pocket",
              "hsbearing.models.ball_bearing.cage", "hsbearing.models.friction.gyro"):
        assert m in mods
    names = {str(p.relative_to(cc.ROOT)) for p in cc.import_closure(mods)}
    # the constants' module and what it imports, reached only through imports, never listed by hand
    assert {"models/traction/zhang2016.py", "models/traction/eyring_limit.py", "models/hertz.py"} <= names
    assert "cli.py" not in names and not any(n.startswith("study") for n in names)


def test_every_cached_module_checks_its_cache():
    """A module with cache=True functions must call check_compile_cache(globals()) at module level, after its
    last cached function (and before any import-time call of one)."""
    for m in cc.cached_modules():
        tree = ast.parse(cc._module_path(m).read_text())
        calls = [i for i, n in enumerate(tree.body) if isinstance(n, ast.Expr) and isinstance(n.value, ast.Call)
                 and getattr(n.value.func, "id", None) == "check_compile_cache"]
        defs = [i for i, n in enumerate(tree.body) if isinstance(n, ast.FunctionDef) and n.decorator_list]
        assert calls, f"{m} defines cached numba functions but never calls check_compile_cache(globals())"
        assert max(calls) > max(defs), f"{m}: check_compile_cache must follow the last cached function"


def test_value_digest_follows_captured_constants():
    """The digest of a function changes with the value of a global array it reads (directly or as
    module.NAME), and not with a global it does not read."""
    mod = types.ModuleType("consts")
    mod.TABLE = np.array([1.0, 2.0])
    g = {"A": np.array([1.0, 2.0]), "S": 3.0, "consts": mod, "UNUSED": np.zeros(2)}
    exec("def f(i):\n    return A[i] * S + consts.TABLE[i]\n", g)
    d = types.SimpleNamespace(py_func=g["f"])
    base = cc.value_digest(d)
    g["UNUSED"] = np.ones(2)
    assert cc.value_digest(d) == base
    g["A"] = np.array([1.0, 4.0])
    assert cc.value_digest(d) != base
    g["A"] = np.array([1.0, 2.0])
    mod.TABLE = np.array([1.0, 3.0])
    assert cc.value_digest(d) != base
    mod.TABLE = np.array([1.0, 2.0])
    g["S"] = 3.5
    assert cc.value_digest(d) != base


@pytest.mark.parametrize("cache_dir", [False, pytest.param(True, marks=pytest.mark.slow)], ids=["in_tree", "NUMBA_CACHE_DIR"])
def test_traction_constant_edit_is_compiled_without_manual_cache_clear(tmp_path, cache_dir):
    """Doubling the A_L coefficient column of the traction constants in the copy's zhang2016.py changes what
    the cached numba kernel returns in the next process: no stale machine code, no manual clearing."""
    root = _copy_package(tmp_path)
    env = {"NUMBA_CACHE_DIR": str(tmp_path / "numba_cache")} if cache_dir else {}
    first = _run(root, **env)
    assert first["cold"] and first["coefficients_nb"]["misses"] >= 1
    np.testing.assert_allclose(first["nb"], first["py"], rtol=1e-12)

    again = _run(root, **env)  # unchanged sources: served from the cache
    assert not again["cold"] and again["coefficients_nb"] == {"hits": 1, "misses": 0}
    assert again["nb"] == first["nb"]

    src = root / "hsbearing" / "models" / "traction" / "zhang2016.py"
    text = src.read_text()
    anchor = "PARAMS = np.array(_rows, dtype=float)\n"
    assert anchor in text
    src.write_text(text.replace(anchor, anchor + "PARAMS[:, 9] *= 2.0  # A_L coefficient doubled\n"))

    edited = _run(root, **env)
    np.testing.assert_allclose(edited["nb"], edited["py"], rtol=1e-12)  # the numba kernel uses the new constant
    assert edited["nb"][0] == pytest.approx(2.0 * first["nb"][0], rel=1e-12)  # A_L doubled
    assert edited["nb"][1:] == pytest.approx(first["nb"][1:], rel=1e-12)


def test_no_recompile_without_bytecode(tmp_path):
    """With PYTHONDONTWRITEBYTECODE=1 (no __pycache__ written by Python), the second run loads every compiled
    function from the cache: the fingerprint stamp is written even when __pycache__ did not exist."""
    root = _copy_package(tmp_path)
    first = _run(root, PYTHONDONTWRITEBYTECODE="1")
    assert first["rupture_table"]["misses"] >= 1 and first["coefficients_nb"]["misses"] >= 1
    stamp = root / "hsbearing" / "__pycache__" / cc.STAMP_NAME
    assert stamp.is_file()
    assert not list((root / "hsbearing").rglob("*.pyc"))  # Python wrote no bytecode: only numba used __pycache__
    second = _run(root, PYTHONDONTWRITEBYTECODE="1")
    assert not second["cold"]
    assert second["rupture_table"] == {"hits": 1, "misses": 0}
    assert second["coefficients_nb"] == {"hits": 1, "misses": 0}


_MODEL_PROBE = textwrap.dedent("""
    import json
    import hsbearing
    from hsbearing.systems.angular_contact.dynamics import build_model
    from hsbearing.models.ball_bearing import kernel as K
    m = build_model(hsbearing.load_case("zhang2016"))
    aux, gaux = m.outputs(m.y0)
    print(json.dumps({"file": hsbearing.__file__, "T_roll_i": aux[:, K.AUX_INDEX["T_roll_i"]].tolist(),
                      "drive_torque": float(gaux[K.GAUX_INDEX["drive_torque"]]),
                      "hits": sum(K.rhs_kernel.stats.cache_hits.values())}))
""")


@pytest.mark.slow
def test_traction_constant_edit_reaches_the_compiled_kernel(tmp_path):
    """The full kernel (which compiles the traction kernel into its own machine code) after the same edit:
    the warm-cache run of the edited copy gives exactly what a cold compile of the edited copy gives, and not
    what the original gave.  Three full kernel compiles (~2 min each)."""
    root = _copy_package(tmp_path)

    def run(**env):
        env_ = {k: v for k, v in os.environ.items() if k != "NUMBA_CACHE_DIR"}
        env_.update(PYTHONPATH=str(root), **env)
        out = subprocess.run([sys.executable, "-c", _MODEL_PROBE], cwd=root, env=env_, capture_output=True,
                             text=True, timeout=1800)
        assert out.returncode == 0, out.stderr[-3000:]
        return json.loads(out.stdout.strip().splitlines()[-1])

    before = run()
    src = root / "hsbearing" / "models" / "traction" / "zhang2016.py"
    anchor = "PARAMS = np.array(_rows, dtype=float)\n"
    src.write_text(src.read_text().replace(anchor, anchor + "PARAMS[:, 9] *= 2.0  # A_L coefficient doubled\n"))
    after = run()  # the in-tree cache of the first run is still there
    cold = run(NUMBA_CACHE_DIR=str(tmp_path / "fresh_cache"))  # a cache that never saw the old constants
    assert cold["hits"] == 0
    assert after["T_roll_i"] == cold["T_roll_i"] and after["drive_torque"] == cold["drive_torque"]
    assert after["drive_torque"] != pytest.approx(before["drive_torque"], rel=1e-6)
