"""Exceptions shared by the library and the CLI (exit codes: CaseError -> 2, SolverError -> 1)."""

from __future__ import annotations

__all__ = ["CaseError", "SolverError", "Interrupted"]


class CaseError(ValueError):
    """Bad input in a case file: carries the file and the key for a one-line message."""

    def __init__(self, source: str, key: str | None, message: str):
        self.source = str(source)
        self.key = key
        self.message = message
        where = f"{self.source}: {key}: " if key else f"{self.source}: "
        super().__init__(where + message)


class SolverError(RuntimeError):
    """A numerical failure.  ``partial`` holds whatever was computed (an xarray Dataset or None)."""

    def __init__(self, message: str, partial=None):
        super().__init__(message)
        self.partial = partial


class Interrupted(KeyboardInterrupt):
    """Ctrl-C during an integration.  ``partial`` holds the run up to the last output (or None).

    A KeyboardInterrupt, so code that records failures (``except Exception``: sweeps) lets it through;
    the CLI writes ``partial`` (status ``interrupted at t = ...``) and exits with 130.
    """

    def __init__(self, message: str = "interrupted", partial=None):
        super().__init__(message)
        self.partial = partial
