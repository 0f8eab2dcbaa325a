"""First-run compilation of the numba kernels: say so before it happens, and do it before the progress bar.

numba compiles a ``@njit(cache=True)`` function at its first call for each argument-type signature and
keeps the machine code on disk (``__pycache__`` next to the source, or ``NUMBA_CACHE_DIR``), so only
the first run after an install (or after an edit of a compiled source or of a constant it captures:
:mod:`hsbearing.compile_cache` keys the caches on them) pays the ~40 s (measured 2026-11-26: 54 s first make run, 15.6 s the next).  Two things
follow for the progress bar of a simulation:

- :func:`compile_notice` prints "compiling the model (first run only, ~40 s)" when the on-disk cache
  of the kernels has nothing usable (a cold cache), before anything is compiled;
- :func:`warm_up` calls the right-hand side (and Jacobian) once with the argument types the integrator
  will use -- CVODE hands the state over as a *read-only* array, which numba compiles as a signature of
  its own -- so the compilation is over before the bar starts and its ETA counts integration only.

Nothing here knows about bearings.
"""

from __future__ import annotations

import sys
import time
from typing import Callable, Iterable

import numpy as np

__all__ = ["cache_is_cold", "compile_notice", "warm_up", "NOTICE"]

#: The line printed (on stderr) before a cold-cache compilation; ``{what}`` and ``{seconds}`` are filled in.
NOTICE = "compiling {what} (first run only, ~{seconds} s) ..."


def cache_is_cold(dispatchers: Iterable) -> bool:
    """True when one of the numba ``dispatchers`` has neither code compiled in this process nor a usable
    on-disk cache index (missing, written by another numba version, or stale after a source edit).

    Objects that are not cached numba dispatchers are ignored (False for them).
    """
    for d in dispatchers:
        if getattr(d, "signatures", None):  # already compiled (or loaded) in this process
            continue
        cache = getattr(d, "_cache", None)
        cache_file = getattr(cache, "_cache_file", None)
        if cache_file is None:
            continue
        try:
            index = cache_file._load_index()  # numba's own freshness rule: {} if absent, foreign or stale
        except Exception:  # noqa: BLE001 - an unreadable index is a cold cache for numba as well
            return True
        if not index:
            return True
    return False


def compile_notice(dispatchers: Iterable, what: str = "the model", seconds: int = 40, stream=None) -> bool:
    """Print :data:`NOTICE` to ``stream`` (stderr) if :func:`cache_is_cold`; return whether it did."""
    if not cache_is_cold(list(dispatchers)):
        return False
    print(NOTICE.format(what=what, seconds=seconds), file=stream or sys.stderr, flush=True)
    return True


def warm_up(rhs: Callable, y0, jac: Callable | None = None, extra: Callable | None = None) -> float:
    """Call ``rhs(0, y, ydot)`` (and ``jac(0, y, ydot, J)``, then ``extra()``) once so that every kernel
    signature the integration needs is compiled now; returns the wall time it took [s].

    ``y`` is a read-only copy of ``y0`` (the array type CVODE passes); the outputs are discarded.
    """
    t0 = time.perf_counter()
    y = np.array(y0, dtype=float)
    y.flags.writeable = False
    ydot = np.empty(y.size)
    rhs(0.0, y, ydot)
    if jac is not None:
        jac(0.0, y, ydot, np.zeros((y.size, y.size)))
    if extra is not None:
        extra()
    return time.perf_counter() - t0
