"""The deep-groove ball bearing (dgbb_prl): friction torque by the sliding method with pure rolling lines
and the SKF 2004 model over speeds (:mod:`hsbearing.systems.deep_groove.friction`, ``hsbearing friction``),
its figures (:mod:`hsbearing.systems.deep_groove.figures`); a deep-groove case with a cage also runs the
6-DOF dynamic model (:mod:`hsbearing.systems.angular_contact.dynamics`, as the angular-contact system)."""

from __future__ import annotations

from hsbearing.systems import angular_contact
from hsbearing.systems.base import System

__all__ = ["SYSTEM", "friction_command", "archive_kind"]


def friction_command(case, args) -> int:
    """``hsbearing friction CASE`` of a deep-groove case: dgbb_prl sliding method + SKF 2004."""
    from hsbearing.systems.deep_groove.friction import friction_command as run

    rc = run(case, args)
    print("note: dgbb_prl sliding method = spinning + differential sliding of the balls with the [friction] law "
          "(no EHL rolling, no drag); SKF 2004 = catalogue model M_rr + M_sl (+ M_drag)")
    return rc


def archive_kind(ds) -> str | None:
    """``"friction"``: an ``hsbearing friction`` archive of the sliding method (dim ``speed``, ``sliding_torque``)."""
    return "friction" if "speed" in ds.dims and "sliding_torque" in ds else None


def _plot_friction(ds, path):
    from hsbearing.systems.deep_groove.figures import plot_friction

    return plot_friction(ds, path)


SYSTEM = System(
    name="deep_groove",
    description="deep-groove ball bearing: sliding friction torque with pure rolling lines vs SKF 2004 (dgbb_prl)",
    friction=friction_command, simulate=angular_contact.simulate, build_model=angular_contact.build_model,
    summary_lines=angular_contact.summary_lines, run_summary=angular_contact.run_summary,
    archive_kind=archive_kind, figures={"friction": _plot_friction},
    register_outputs=angular_contact.SYSTEM.register_outputs,
)
