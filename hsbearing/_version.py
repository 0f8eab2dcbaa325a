"""The installed package version, in a module of its own so that modules below the package's API
(results, cli) can read it without importing ``hsbearing/__init__`` (no import circles)."""

from __future__ import annotations

from importlib.metadata import PackageNotFoundError
from importlib.metadata import version as _version

try:
    __version__ = _version("hsbearing")
except PackageNotFoundError:  # pragma: no cover - running from a source tree
    __version__ = "0.0.0+unknown"
