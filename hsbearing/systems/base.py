"""The interface every bearing system declares (:class:`System`); the registry is :mod:`hsbearing.systems`."""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import Callable

__all__ = ["System"]


def _none(*_args, **_kw):
    return None


def _no_lines(_ds) -> list[str]:
    return []


@dataclass(frozen=True)
class System:
    """The interface of one bearing system (see the module docstring)."""

    name: str
    description: str
    friction: Callable
    simulate: Callable | None = None
    build_model: Callable | None = None
    summary_lines: Callable = _no_lines
    run_summary: Callable | None = None
    extend: Callable | None = None  #: ``extend(ds, max_duration, **kw) -> ds``: continue an undetermined run
    archive_kind: Callable = _none
    figures: dict = field(default_factory=dict)
    register_outputs: Callable = _none
    friction_archive: bool = True  #: ``hsbearing friction -o OUT.nc`` writes an archive
    fallback: bool = False  #: its archive kinds are generic (asked after every other system's)
