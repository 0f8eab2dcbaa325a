"""Exceptions shared by the library and the CLI (exit codes: CaseError -> 2, SolverError -> 1)."""

from __future__ import annotations

from hsbearing.case import CaseError

__all__ = ["CaseError", "SolverError"]


class SolverError(RuntimeError):
    """A numerical failure.  ``partial`` holds whatever was computed (an xarray Dataset or None)."""

    def __init__(self, message: str, partial=None):
        super().__init__(message)
        self.partial = partial
