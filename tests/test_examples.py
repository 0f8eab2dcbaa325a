"""Every gallery script in examples/ runs to the end (slow tier: together a few minutes; docs/testing.md).

The docs build renders the gallery without executing it; this test is what proves the scripts run.  Each script
is run as ``__main__`` in its own process (a sweep with workers re-imports its script) with the non-interactive
matplotlib backend, from a temporary working directory.
"""

from __future__ import annotations

import os
import subprocess
import sys
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[1]
EXAMPLES = sorted((ROOT / "examples").glob("plot_*.py"))


def test_the_gallery_has_the_examples_the_docs_promise():
    names = {p.stem for p in EXAMPLES}
    assert {"plot_default_run", "plot_axial_load_sweep", "plot_compare_oils", "plot_thermal_sweep",
            "plot_stability_map", "plot_classify_orbit", "plot_gyro", "plot_deep_groove"} <= names


@pytest.mark.slow
@pytest.mark.parametrize("script", EXAMPLES, ids=[p.stem for p in EXAMPLES])
def test_example_runs(script, tmp_path):
    env = dict(os.environ, MPLBACKEND="Agg", PYTHONPATH=os.pathsep.join([str(ROOT), os.environ.get("PYTHONPATH", "")]))
    proc = subprocess.run([sys.executable, str(script)], cwd=tmp_path, env=env, capture_output=True, text=True,
                          timeout=900)
    assert proc.returncode == 0, f"{script.name} failed:\n{proc.stdout[-2000:]}\n{proc.stderr[-4000:]}"
    assert proc.stdout.strip(), f"{script.name} printed nothing"
