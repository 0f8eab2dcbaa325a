"""The gyroscope mini bearing with a ribbon cage (Jiang et al. 2014): ``[case] system =
"gyro_ribbon_cage"``.  Model, simulation and start ensemble: :mod:`hsbearing.systems.gyro.model`; studies
and validation figures: :mod:`hsbearing.workflows.study.gyro`; the run figure:
:mod:`hsbearing.systems.gyro.figures`; the physics: :mod:`hsbearing.models.friction.gyro`."""

from __future__ import annotations

import math

from hsbearing.systems.base import System

__all__ = ["SYSTEM", "simulate", "build_model", "summary_lines", "run_summary", "friction_command", "archive_kind"]


def simulate(case, duration=None, progress: bool = False, **kwargs):
    """The gyro run (:func:`hsbearing.systems.gyro.model.simulate`)."""
    from hsbearing.systems.gyro import model

    return model.simulate(case, duration=duration, progress=progress, **kwargs)


def build_model(case, **kwargs):
    from hsbearing.systems.gyro import model

    return model.build_model(case, **kwargs)


def summary_lines(ds) -> list[str]:
    """The start ensemble (``simulation.start_positions`` > 1): mean +/- sd and each start."""
    if "sfmc_ensemble" not in ds:
        return []
    from hsbearing.systems.gyro import model

    return list(model.ensemble_lines(ds))


def run_summary(ds) -> dict:
    """SFMC/SFMO/RFMC and their statistics (:func:`hsbearing.systems.gyro.model.summary`)."""
    from hsbearing.systems.gyro import model

    return model.summary(ds)


def friction_command(case, args) -> int:
    """``hsbearing friction CASE``: the five friction moments of Jiang et al. 2014 at the case thrust load (static part)."""
    from hsbearing.errors import CaseError

    if getattr(args, "output", None):
        raise CaseError("-o", None, "the gyro friction summary writes no archive; use hsbearing run -o")
    from hsbearing.models.friction import gyro

    sf = gyro.static_friction(case)
    print(f"case {case.name}: gyro bearing, Fa = {case.operating.axial_load:g} N, contact angle {math.degrees(sf.beta):.3g} deg")
    print(f"  friction moments of the ball-race contacts (Jiang et al. 2014 Eqs. 1-2), N mm: M_E (hysteresis) = {sf.M_E * 1e3:.4g}, "
          f"M_D (differential sliding) = {sf.M_D * 1e3:.4g}, M_S (spin) = {sf.M_S * 1e3:.4g}, M_L (viscous) = {sf.M_L * 1e3:.4g}, "
          f"sum = {(sf.M_E + sf.M_D + sf.M_S + sf.M_L) * 1e3:.4g}")
    print("note: cage moment M_C and the start/oscillation moments (SFMC, SFMO, RFMC) need the cage dynamics: hsbearing run "
          f"{case.name}")
    return 0


def archive_kind(ds) -> str | None:
    """``"gyro"``: a gyro run (``attrs["model"]``, or a time series of a gyro case)."""
    if ds.attrs.get("model") == "gyro_ribbon_cage" or (ds.attrs.get("case_system") == SYSTEM.name and "time" in ds.dims):
        return "gyro"
    return None


def _plot_gyro(ds, path):
    from pathlib import Path

    from hsbearing.systems.gyro.figures import plot_gyro

    return plot_gyro(ds, Path(path))


def _register_outputs():
    import hsbearing.systems.gyro.model  # noqa: F401 - declares the gyro variables


SYSTEM = System(
    name="gyro_ribbon_cage",
    description="gyroscope mini bearing with a ribbon cage under ultra-low-speed oscillation (Jiang et al. 2014)",
    friction=friction_command, simulate=simulate, build_model=build_model, summary_lines=summary_lines,
    run_summary=run_summary, archive_kind=archive_kind, figures={"gyro": _plot_gyro}, friction_archive=False,
    register_outputs=_register_outputs,
)
