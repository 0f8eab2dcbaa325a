"""The ``hsbearing`` command: a thin layer over the library (the same functions, the same names).

Exit codes: 0 success; 2 bad input (one line naming the file and the key,
nothing written); 1 numerical failure (partial result kept, status says why).

By concern: ``common`` (the case of a command line, default output names, the printed run summary),
``commands`` (one ``cmd_*`` per subcommand), ``parser`` (the argparse tree), ``oils`` (``hsbearing oils``)
and :func:`main` here (exit codes).
"""

from __future__ import annotations

import sys

from hsbearing.case import CaseError
from hsbearing.cli.commands import cmd_thermal
from hsbearing.cli.common import case_from_args
from hsbearing.cli.parser import build_parser
from hsbearing.errors import ClusterLost, OutputWriteError, SolverError

__all__ = ["main", "build_parser", "case_from_args", "cmd_thermal"]


def main(argv: list[str] | None = None) -> int:
    """The hsbearing command: its exit status (0, 1, 2, 130 on Ctrl-C at any moment)."""
    from hsbearing import _interrupt

    program = argv is None and _interrupt.is_command()
    if program:
        _interrupt.take_over()
    try:
        try:
            rc = _main(argv)
        finally:
            if program:  # the status is decided: a Ctrl-C from here to the interpreter's exit changes nothing
                _interrupt.ignore_after_exit()
    except KeyboardInterrupt as exc:  # one that arrived outside the command's own handler (e.g. in a message)
        if program:
            _interrupt.ignore_after_exit()
        rc = _interrupted(exc)
    if program:  # every KeyboardInterrupt is handled: python -m must not re-raise the signal at exit
        _interrupt.forget_handled_interrupt()
    return rc


def _interrupted(exc: KeyboardInterrupt) -> int:
    what = str(exc) if type(exc) is not KeyboardInterrupt and str(exc) not in ("", "interrupted") else ""
    try:
        print(f"hsbearing: interrupted{': ' + what if what else ''}", file=sys.stderr)
    except (KeyboardInterrupt, OSError, ValueError):
        pass
    return 130


def _main(argv: list[str] | None) -> int:
    parser = build_parser()
    args = parser.parse_args(argv)
    if not getattr(args, "func", None):  # bare `hsbearing`: say what is missing, on one line
        print("hsbearing: error: no command given (commands: cases, check, run, quasistatic, sweep, compare, map, study, "
              "friction, life, preload, plot; see 'hsbearing --help')", file=sys.stderr)
        return 2
    try:
        rc = int(args.func(args) or 0)
        sys.stdout.flush()  # a closed pipe shows here (BrokenPipeError below), not in the interpreter's exit
        return rc
    except CaseError as exc:
        print(f"hsbearing: error: {exc}", file=sys.stderr)
        return 2
    except ClusterLost as exc:  # the dask scheduler went away: what is kept and how to go on, exit 1
        print(f"hsbearing: error: {exc}", file=sys.stderr)
        return 1
    except OutputWriteError as exc:  # computed, but the final write failed: where the result went, exit 1
        print(f"hsbearing: error: {exc}", file=sys.stderr)
        return 1
    except SolverError as exc:
        print(f"hsbearing: numerical failure: {exc}", file=sys.stderr)
        return 1
    except KeyboardInterrupt as exc:
        return _interrupted(exc)
    except (ArithmeticError, _linalg_error()) as exc:  # a singular matrix / overflow deep in a model: one line, exit 1
        print(f"hsbearing: numerical failure: {type(exc).__name__}: {str(exc).splitlines()[0] if str(exc) else ''} "
              "(the inputs are valid but the model cannot solve them; check the geometry and loads)", file=sys.stderr)
        return 1
    except BrokenPipeError:
        # the reader of stdout went away (``hsbearing check ... | head -1``): not an error of ours.
        # Point stdout at /dev/null so that the interpreter's final flush does not complain.
        _silence_stdout()
        return 0


def _linalg_error() -> type:
    import numpy as np

    return np.linalg.LinAlgError


def _silence_stdout() -> None:
    import os

    try:
        devnull = os.open(os.devnull, os.O_WRONLY)
        os.dup2(devnull, sys.stdout.fileno())
        os.close(devnull)
    except (OSError, ValueError, AttributeError):  # no real stdout (in-process use): nothing to silence
        pass


if __name__ == "__main__":  # pragma: no cover
    sys.exit(main())
