"""The angular-contact ball bearing (Zhang et al. 2016): the 6-DOF dynamic model with cage
(:mod:`hsbearing.systems.angular_contact.dynamics`, wrapped here), its quasi-static start (:mod:`hsbearing.systems.angular_contact.quasistatic`), the
quasi-static power loss by source with the SKF 2004 cross-check (``hsbearing friction``) and the run
figures (:mod:`hsbearing.systems.angular_contact.figures`); the cage films at their film temperature
(:mod:`hsbearing.systems.angular_contact.cage_films`) and the oil's properties at any temperature
(:mod:`hsbearing.systems.angular_contact.oil_properties`), shared by the loss, the thermal network and the model."""

from __future__ import annotations

import math
import sys

import numpy as np

from hsbearing.systems.base import System

__all__ = ["SYSTEM", "simulate", "build_model", "extend", "summary_lines", "run_summary", "friction_command",
           "archive_kind"]


def simulate(case, duration=None, progress: bool = False, **kwargs):
    """The dynamic run (:func:`hsbearing.systems.angular_contact.dynamics.simulate`)."""
    from hsbearing.systems.angular_contact import dynamics

    return dynamics.simulate(case, duration=duration, progress=progress, **kwargs)


def build_model(case, **kwargs):
    """The dynamic model object (:func:`hsbearing.systems.angular_contact.dynamics.build_model`)."""
    from hsbearing.systems.angular_contact import dynamics

    return dynamics.build_model(case, **kwargs)


def extend(ds, max_duration, **kwargs):
    """Continue an undetermined run until determined (:func:`hsbearing.systems.angular_contact.extend.extend_until_determined`)."""
    from hsbearing.systems.angular_contact.extend import extend_until_determined

    return extend_until_determined(ds, max_duration, **kwargs)


def summary_lines(ds) -> list[str]:
    """Drive torque and power loss by source of a dynamic run (:func:`hsbearing.systems.angular_contact.balances.power_summary_lines`)."""
    if "drive_torque" not in ds:
        return []
    from hsbearing.systems.angular_contact.balances import power_summary_lines

    return list(power_summary_lines(ds))


def run_summary(ds) -> dict:
    """Scalars of a dynamic run for a sweep table (:func:`hsbearing.analysis.summary`, without ``status``)."""
    from hsbearing import analysis
    from hsbearing.systems.angular_contact.extend import extension_summary

    out = {k: v for k, v in dict(analysis.summary(ds)).items() if k != "status"}
    out.update(extension_summary(ds))  # a run extended until determined (maps, studies): how far and why it stopped
    return out


def friction_command(case, args) -> int:
    """``hsbearing friction CASE``: quasi-static power loss by source and the SKF 2004 angular-contact model."""
    from hsbearing.lubricant import header_lines, oil_label
    from hsbearing.results import write_netcdf
    from hsbearing.systems.angular_contact.rating import NOTE_QS, NOTE_SKF, friction_angular_contact, rpm
    from hsbearing.units import parse_speeds

    out = getattr(args, "output", None)
    speeds = parse_speeds(args.speeds) if args.speeds else np.array([abs(case.operating.inner_speed)])
    ds = friction_angular_contact(case, speeds, thermal=bool(getattr(args, "thermal", False)))
    print(f"case {case.name}: Fa = {abs(case.operating.axial_load):g} N, Fr = {math.hypot(case.operating.radial_load, case.operating.radial_load_z):g} N, "
          f"{oil_label(case.lubricant)} at {case.lubricant.temperature - 273.15:.4g} degC")
    for line in header_lines(case):  # where the oil's data come from; traction borrowed / alpha estimated
        print(line)
    from hsbearing.systems.angular_contact.balances import SOURCES
    from hsbearing.systems.angular_contact.rating import CAVITY_SOURCES

    srcs = [s for s in tuple(SOURCES) + CAVITY_SOURCES if np.any(np.abs(ds[f"qs_power_loss_{s}"].values) > 1e-9)]
    head = ["n [r/min]"] + [f"{s} [W]" for s in srcs] + ["total [W]", "M [N mm]", "SKF M_rr [N mm]", "SKF M_sl [N mm]", "SKF M [N mm]", "SKF P [W]"]
    print("quasi-static power loss by source | SKF 2004 (72xx angular contact)")
    print("  ".join(f"{h:>16s}" for h in head))
    for i, wi in enumerate(ds["speed"].values):
        row = [f"{rpm(wi):16.0f}"] + [f"{ds[f'qs_power_loss_{s}'].values[i]:16.4g}" for s in srcs]
        M = ds.qs_friction_torque.values[i]
        row += [f"{ds.qs_power_loss.values[i]:16.4g}", f"{M * 1e3:16.4g}" if np.isfinite(M) else f"{'n/a (0 r/min)':>16s}",
                f"{ds.skf_rolling_torque.values[i] * 1e3:16.4g}", f"{ds.skf_sliding_torque.values[i] * 1e3:16.4g}",
                f"{ds.skf_total_torque.values[i] * 1e3:16.4g}", f"{ds.skf_total_torque.values[i] * abs(wi):16.4g}"]
        print("  ".join(row))
    print("split of both totals into the SKF terms [W] (ours: rolling = ehl_rolling + contact_damping; sliding = "
          "race_traction + pocket_film + pocket_boundary + guide_land; drag = ball drag + jet_oil_acceleration + cage_windage; seals: none modelled)")
    print("  ".join(f"{h:>14s}" for h in ["n [r/min]", "model", "rolling", "sliding", "drag", "seal", "total"]))
    for i, wi in enumerate(ds["speed"].values):
        for label, pre, tot in (("ours", "qs_power_as_skf_", ds.qs_power_loss.values[i]),
                                ("SKF 2004", "skf_power_", ds.skf_total_torque.values[i] * abs(wi))):
            print("  ".join([f"{rpm(wi):14.0f}", f"{label:>14s}"] + [f"{ds[pre + t].values[i]:14.4g}" for t in
                                                                      ("rolling", "sliding", "drag", "seal")] + [f"{tot:14.4g}"]))
    X, Re, CD = ds["cavity_oil_fraction"].values, ds["drag_reynolds_number"].values, ds["drag_coefficient"].values
    print(f"drag: cavity oil fraction {', '.join(f'{x:.4g}' for x in X)} ({ds.attrs.get('cavity_oil_fraction_source', '')}); "
          f"ball Reynolds number {', '.join(f'{r:.3g}' for r in Re)}; C_D {', '.join(f'{c:.3g}' for c in CD)} (smooth "
          "sphere, standard drag curve of Clift, Grace & Weber 1978, Table 5.2)")
    k = ds["mixture_corotation"].values
    kc = ", ".join(f"{x:.3g}" if np.isfinite(x) else "n/a (cage at rest)" for x in ds["mixture_corotation_couette"].values)
    print(f"drag band [W] (mixture co-rotation 0 .. Couette estimate {kc}"
          f" of the cage speed; C_D held subcritical or with the sphere's crisis): "
          + ", ".join(f"{lo:.4g}..{hi:.4g}" for lo, hi in zip(ds.qs_drag_band_low.values, ds.qs_drag_band_high.values))
          + f"; drag above at co-rotation {', '.join(f'{x:.3g}' for x in k)} (friction.mixture_corotation)")
    if "mixture_corotation_balance" in ds and np.any(np.isfinite(ds["mixture_corotation_balance"].values)):
        kb = zip(ds.mixture_corotation_balance.values, ds.mixture_corotation_balance_low.values,
                 ds.mixture_corotation_balance_high.values)
        print("mixture momentum balance (friction.mixture_corotation_law = "
              f"{case.friction.mixture_corotation_law}): co-rotation "
              + ", ".join(f"{x:.3g} ({lo:.3g}..{hi:.3g})" for x, lo, hi in kb)
              + "; churning band [W] (balls + ring surface) "
              + ", ".join(f"{lo:.4g}..{hi:.4g}" for lo, hi in zip(ds.qs_drag_balance_band_low.values,
                                                                  ds.qs_drag_balance_band_high.values))
              + (f"; {ds.attrs['mixture_balance_cage']}" if ds.attrs.get("mixture_balance_cage") else ""))
    for key, what in (("land", "guide-land film"), ("pocket", "pocket films")):
        Tm = ds[f"{key}_film_temperature"].values
        if np.any(np.isfinite(Tm)):
            print(f"{what}: film temperature {', '.join(f'{t - 273.15:.4g}' for t in Tm)} degC (walls "
                  + ", ".join(f"{a - 273.15:.4g}/{b - 273.15:.4g}" for a, b in zip(ds[f"{key}_film_wall_temperature_a"].values,
                                                                               ds[f"{key}_film_wall_temperature_b"].values))
                  + f" degC), viscosity x {', '.join(f'{f:.3g}' for f in ds[f'{key}_film_viscosity_factor'].values)} "
                  "(friction.thermal_films)")
    print("EHL rolling starvation band [W] (race inlets fed only by the cavity mixture .. flooded): "
          + ", ".join(f"{lo:.4g}..{hi:.4g}" for lo, hi in zip(ds.qs_ehl_rolling_band_low.values, ds.qs_ehl_rolling_band_high.values))
          + "; starved/flooded central film at the low end, thinnest inner/outer contact: "
          + ", ".join(f"{a:.3g}/{b:.3g}" for a, b in zip(ds.inner_starved_film_ratio_low.values, ds.outer_starved_film_ratio_low.values)))
    print("total band [W] (drag band; land and pocket films part-filled at the cavity oil fraction; race contacts "
          "starved .. flooded): "
          + ", ".join(f"{lo:.4g}..{hi:.4g}" for lo, hi in zip(ds.qs_total_band_low.values, ds.qs_total_band_high.values)))
    if "contact_inlet_temperature" in ds:
        if "inner_contact_inlet_temperature" in ds:  # each race's contacts at their own inlet temperature
            head = ("--thermal: contact inlet temperature inner/outer race " + ", ".join(
                f"{a - 273.15:.4g}/{b - 273.15:.4g}" for a, b in zip(ds.inner_contact_inlet_temperature.values,
                                                                    ds.outer_contact_inlet_temperature.values))
                    + " degC ((T_ring + T_ball)/2 of each race; mean " + ", ".join(
                        f"{t - 273.15:.4g}" for t in ds.contact_inlet_temperature.values) + " degC)")
        else:
            head = "--thermal: contact inlet temperature " + ", ".join(
                f"{t - 273.15:.4g}" for t in ds.contact_inlet_temperature.values) + " degC"
        print(head + "; rings " + ", ".join(f"{a - 273.15:.4g}/{b - 273.15:.4g}" for a, b in zip(
                  ds.thermal_inner_ring_temperature.values, ds.thermal_outer_ring_temperature.values))
              + " degC; balls " + ", ".join(f"{t - 273.15:.4g}" for t in ds.thermal_ball_temperature.values)
              + " degC; cage " + ", ".join(f"{t - 273.15:.4g}" for t in ds.thermal_cage_temperature.values)
              + " degC; oil out " + ", ".join(f"{t - 273.15:.4g}" for t in ds.thermal_oil_outlet_temperature.values) + " degC")
    print("note: " + NOTE_QS)
    print("note: " + NOTE_SKF)
    if case.friction.law == "coulomb":
        print("note: friction.law = coulomb selects the dgbb_prl deep-groove sliding method with a dry constant mu; it is not "
              "used for angular-contact bearings (the traction law of the oil is)")
    if not np.all(np.isfinite(ds.qs_friction_torque.values)):
        print("note: M = P / omega is not defined at 0 r/min (no rotation, no power): n/a")
    print("the dynamic run (hsbearing run) lets the balls find their own spin axes (not race control) and the cage whirl: "
          "more race traction and guide-land loss (zhang2016: 58.1 W against 45.8 W of the same sources; 'Quasi-static, "
          "dynamic and SKF' in docs/power_loss.md); power_loss_<source> in its archive")
    if ds.attrs.get("warnings", "none") != "none":
        for x in str(ds.attrs["warnings"]).split(" | "):
            print(f"warning: {x}")
    if out:
        write_netcdf(ds, out)
        print(f"archive: {out}")
    sys.stdout.flush()
    return 0


def archive_kind(ds) -> str | None:
    """``"thermal"`` (a thermal network), ``"friction_angular_contact"`` (``hsbearing friction`` of an
    angular-contact case: dim ``speed``, ``qs_power_loss``), ``"run"`` (a time series) or ``"quasistatic"``
    (per-ball contact loads): the fallback kinds, asked last."""
    if ds.attrs.get("archive_kind") == "thermal" or "node_temperature" in ds:
        return "thermal"
    if "speed" in ds.dims and "qs_power_loss" in ds and "sliding_torque" not in ds:
        return "friction_angular_contact"
    if "time" in ds.dims:
        return "run"
    if "inner_contact_load" in ds or "outer_contact_load" in ds:
        return "quasistatic"
    return None


def _plot_dynamic(ds, path):
    from hsbearing.systems.angular_contact.figures import plot_dynamic

    return plot_dynamic(ds, path)


def _plot_friction(ds, path):
    from hsbearing.systems.angular_contact.figures import plot_friction_angular_contact

    return plot_friction_angular_contact(ds, path)


def _plot_quasistatic(ds, path):
    from hsbearing.systems.angular_contact.figures import plot_quasistatic

    return plot_quasistatic(ds, path)


def _plot_thermal(ds, path):
    from hsbearing.systems.angular_contact.thermal_figure import plot_thermal

    return plot_thermal(ds, path)


def _register_outputs():
    import hsbearing.analysis.orbit  # noqa: F401 - the run summary variables
    import hsbearing.systems.angular_contact.balances  # noqa: F401 - power_loss, power_loss_<source>, drive_torque
    import hsbearing.systems.angular_contact.extend  # noqa: F401 - what a sweep table carries of an extension
    import hsbearing.systems.angular_contact.rating  # noqa: F401 - the quasi-static sources and the lives
    import hsbearing.systems.angular_contact.thermal  # noqa: F401 - the thermal network variables


SYSTEM = System(
    name="angular_contact",
    description="angular-contact ball bearing: 6-DOF dynamics with cage (Zhang et al. 2016), quasi-static equilibrium",
    friction=friction_command, simulate=simulate, build_model=build_model, summary_lines=summary_lines,
    run_summary=run_summary, extend=extend, archive_kind=archive_kind, fallback=True,
    figures={"run": _plot_dynamic, "quasistatic": _plot_quasistatic, "thermal": _plot_thermal,
             "friction_angular_contact": _plot_friction},
    register_outputs=_register_outputs,
)
