"""Exceptions shared by the library and the CLI (exit codes: CaseError -> 2, SolverError -> 1)."""

from __future__ import annotations

from hsbearing.case import CaseError

__all__ = ["CaseError", "SolverError", "Interrupted"]


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
