"""Exceptions shared by the library and the CLI (exit codes: CaseError -> 2, SolverError -> 1)."""

from __future__ import annotations

__all__ = ["CaseError", "SolverError", "Interrupted", "OutputWriteError", "ClusterLost"]


class CaseError(ValueError):
    """Bad input in a case file: carries the file and the key for a one-line message."""

    def __init__(self, source: str, key: str | None, message: str):
        self.source = _one_line(str(source))
        self.key = None if key is None else _one_line(str(key))
        self.message = _one_line(str(message))
        where = f"{self.source}: {self.key}: " if self.key else f"{self.source}: "
        super().__init__(where + self.message)


def _one_line(text: str) -> str:
    """``text`` with every control character (CR, LF, tab, ...) written as its escape: an error stays one line
    whatever the user's input contained (a quoted value is echoed back in the message)."""
    if text.isprintable():
        return text
    return "".join(c if c.isprintable() else c.encode("unicode_escape").decode("ascii") for c in text)


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


class OutputWriteError(OSError):
    """The final write of a computed result failed (disk full, file too large, read-only directory ...).

    ``path``: where it should have gone; ``reason``: why it failed; ``saved_to``: the fallback file the
    result was written to instead (None if no fallback place took it either).  The CLI prints one line
    and exits 1: the computation succeeded, the result is kept where ``saved_to`` says.
    """

    def __init__(self, path, reason: str, saved_to=None, note: str | None = None):
        self.path = str(path)
        self.reason = reason
        self.saved_to = None if saved_to is None else str(saved_to)
        if note is None:
            note = (f"the result was saved to {self.saved_to} instead" if self.saved_to else
                    "no fallback place could take the result either (nothing written)")
        super().__init__(f"cannot write {self.path}: {reason}; {note}")


class ClusterLost(RuntimeError):
    """The dask scheduler of a sweep went away (killed, its machine lost): the points computed so far are kept
    and the same command resumes from them.  The CLI prints one line and exits 1."""
