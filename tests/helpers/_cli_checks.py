"""Shared check of the CLI's bad-input contract: one stderr line, the expected exit code, no traceback."""

from __future__ import annotations

import re


def one_error_line(capsys_or_err, rc, *needles, code=2):
    """Assert exit code ``code``, exactly one non-empty stderr line, no traceback, and each regex of ``needles`` in
    that line; return the line.  ``capsys_or_err``: pytest's capsys fixture or the stderr text itself."""
    err = capsys_or_err if isinstance(capsys_or_err, str) else capsys_or_err.readouterr().err
    lines = [ln for ln in err.splitlines() if ln.strip()]
    assert rc == code, err
    assert len(lines) == 1, err
    assert "Traceback" not in err
    for n in needles:
        assert re.search(n, lines[0]), (n, lines[0])
    return lines[0]
