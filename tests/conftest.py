"""Shared test setup: the helper modules (independent reference solutions, CLI checks) are importable by name
from every test folder, and the paths tests read from are named once."""

from __future__ import annotations

import sys
from pathlib import Path

TESTS = Path(__file__).resolve().parent
ROOT = TESTS.parent
DATA = TESTS / "data"
sys.path.insert(0, str(TESTS / "helpers"))
