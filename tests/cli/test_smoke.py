"""Smoke tests of the package skeleton (import, version, CLI entry)."""

import subprocess
import sys

import hsbearing


def test_version_string():
    assert hsbearing.__version__.count(".") >= 2


def test_cli_version_and_cases():
    out = subprocess.run([sys.executable, "-m", "hsbearing.cli", "--version"], capture_output=True, text=True)
    assert out.returncode == 0 and "hsbearing" in out.stdout
    out = subprocess.run([sys.executable, "-m", "hsbearing.cli", "cases"], capture_output=True, text=True)
    assert out.returncode == 0 and "zhang2016" in out.stdout
