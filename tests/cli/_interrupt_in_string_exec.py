"""Run as ``python -m _interrupt_in_string_exec`` by tests/cli/test_ctrl_c_anytime.py: the hsbearing command's main()
whose Ctrl-C surfaces inside code that Python runs from a string (as dataclasses, namedtuple and numba build
functions: a Ctrl-C during an import or a compilation lands there).  Deterministic: the KeyboardInterrupt is raised
by that code itself.  main() catches it and returns 130; the process must then exit 130, not die by SIGINT."""

import sys

import hsbearing.cli as cli


def _parser_interrupted():
    exec("raise KeyboardInterrupt")  # a KeyboardInterrupt out of string-exec'd code, as a Ctrl-C would give


cli.build_parser = _parser_interrupted
sys.argv[0] = "hsbearing"  # the command's process (hsbearing._interrupt.is_command)
sys.exit(cli.main())
