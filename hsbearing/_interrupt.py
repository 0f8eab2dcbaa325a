"""Ctrl-C over the whole life of the ``hsbearing`` command: exit status 130, never death by the signal.

Python ends a program whose KeyboardInterrupt nobody caught by killing itself with SIGINT (exit status -2 to
the shell).  :func:`hsbearing.cli.main` catches it while it runs; this module covers the two moments it cannot:
the imports before it is called (:func:`guard_command_start`, at the top of ``hsbearing/__init__``) and the
interpreter's shutdown after it returned (:func:`ignore_after_exit`).  Either way nothing half-written is left:
archives are written atomically (:func:`hsbearing.results.atomic_write`).

One more way to die by the signal although main() caught the KeyboardInterrupt and returned 130
(:func:`forget_handled_interrupt`): under ``python -m hsbearing.cli``, a KeyboardInterrupt that left code run from
a *string* by ``exec``/``eval`` (dataclasses and namedtuple build their methods that way, numba its wrappers; a
Ctrl-C during an import or a compilation lands there often) sets CPython's "unhandled KeyboardInterrupt" flag
(``run_eval_code_obj`` in Python/pythonrun.c), whoever catches it later; after the module returns, ``Py_RunMain``
sees the flag and kills the process with SIGINT (``exit_sigint`` in Modules/main.c): the handled line, then -2.
The console script (a script file) does not check the flag.  The flag is cleared at the start of every string
evaluation, so one ``eval`` of a constant once the status is decided clears it.

Before the first statement of ``hsbearing/__init__`` runs (the interpreter's own start: ``site``, the import
machinery locating the package), Ctrl-C is the Python runtime's: a traceback and exit 1 or -2, nothing computed
and nothing written.  No code of a package can run earlier.
"""

from __future__ import annotations

import os
import signal
import sys
import threading

__all__ = ["is_command", "guard_command_start", "take_over", "ignore_after_exit", "forget_handled_interrupt"]


def is_command() -> bool:
    """True in the process of the ``hsbearing`` command (console script or ``python -m hsbearing.cli``)."""
    argv0 = sys.argv[0] if sys.argv else ""
    if os.path.basename(argv0) == "hsbearing" or argv0 == "-m":  # "-m": runpy is importing hsbearing.cli's parents
        return True
    main = sys.modules.get("__main__")
    spec = getattr(main, "__spec__", None)
    return getattr(spec, "name", "") in ("hsbearing.cli", "hsbearing.cli.__main__")


def _exit_130(signum, frame):  # pragma: no cover - ends the process
    try:
        os.write(2, b"hsbearing: interrupted (nothing computed yet, nothing written)\n")
    except OSError:
        pass
    os._exit(130)


def guard_command_start() -> None:
    """In the hsbearing command, until :func:`take_over`: Ctrl-C exits at once with 130 (nothing was computed)."""
    if is_command() and threading.current_thread() is threading.main_thread() and \
            signal.getsignal(signal.SIGINT) is signal.default_int_handler:
        signal.signal(signal.SIGINT, _exit_130)


def take_over() -> None:
    """The command's main() runs: Ctrl-C is a KeyboardInterrupt again (runs keep their partial result)."""
    if threading.current_thread() is threading.main_thread() and signal.getsignal(signal.SIGINT) is _exit_130:
        signal.signal(signal.SIGINT, signal.default_int_handler)


def ignore_after_exit() -> None:
    """The command's main() has its exit status: a Ctrl-C during the interpreter's shutdown changes nothing."""
    if threading.current_thread() is threading.main_thread():
        signal.signal(signal.SIGINT, signal.SIG_IGN)


def forget_handled_interrupt() -> None:
    """The command has handled every KeyboardInterrupt and holds Ctrl-C off (:func:`ignore_after_exit`): clear
    CPython's "unhandled KeyboardInterrupt" flag, which a KeyboardInterrupt raised inside string-``exec``'d code
    leaves set even when caught, and which makes ``python -m`` end by killing itself with SIGINT (module docstring).
    Clearing it: ``run_eval_code_obj`` resets the flag at the start of every string evaluation."""
    eval("None")  # a string evaluation: resets the flag; nothing else
