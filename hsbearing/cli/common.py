"""What the commands share: the case of a command line, default output names, the printed run summary in readable units, the reason of a NaN."""

from __future__ import annotations

import hashlib
import sys
from pathlib import Path

from hsbearing.case import DEFAULT_CASE, load_case, parse_sets


class UsageError(Exception):
    pass




def case_from_args(args) -> "object":
    sets = parse_sets(getattr(args, "set", None))
    case = load_case(args.case or DEFAULT_CASE, **sets)
    # --stop RULE / --section NAME are --set simulation.stop / simulation.section, set only when they change the
    # case (a default left out of the TOML keeps the archive hashes)
    extra = {}
    stop, section = getattr(args, "stop", None), getattr(args, "section", None)
    if stop and stop != case.simulation.stop:
        extra["simulation.stop"] = stop
    if section and section != case.simulation.section:
        extra["simulation.section"] = section
    if extra:
        case = load_case(args.case or DEFAULT_CASE, **sets, **extra)
    print_envelope_warnings(case)
    return case


def print_envelope_warnings(case) -> None:
    """Values that are possible but outside the data behind the model (e.g. an oil beyond its service range)."""
    from hsbearing.case import envelope_warnings

    for w in envelope_warnings(case):
        print(f"hsbearing: warning: {case.source}: {w}", file=sys.stderr)


def default_output(case, suffix: str, extra: str = "") -> Path:
    h = hashlib.sha1((case.to_toml() + extra).encode()).hexdigest()[:10]
    return Path("runs") / f"{case.name}-{h}{suffix}"


def print_summary(ds, out: Path | None = None) -> None:
    """The scalars of a run in the units users read (hsbearing.display), with the reasons behind values
    that are not defined (parked cage, undetermined classification) and the whirl radius explained."""
    import numpy as np

    from hsbearing.display import format_solver_stats, format_value

    print(f"status: {ds.attrs.get('status', '?')}")
    from hsbearing.lubricant import header_lines_of_archive

    for line in header_lines_of_archive(ds.attrs):  # the oil by its own name, and where its data come from
        print(line)
    note = None
    if "whirl_frequency_ratio" in ds:
        try:
            from hsbearing.analysis.orbit import whirl_ratio_note

            note = whirl_ratio_note(ds)
        except Exception:  # noqa: BLE001 - the value is printed as stored
            note = None
    gc = ds.attrs.get("guide_clearance")
    for name, var in ds.data_vars.items():
        if var.ndim != 0:
            continue
        text = format_value(var, name)
        if name == "whirl_frequency_ratio" and note:
            text = f"not defined ({note})"
        elif is_nan_variable(var):  # never a bare "nan" with exit 0: say why the value is not defined
            text = f"n/a ({nan_reason(name, ds)})"
        elif name in ("whirl_amplitude", "whirl_radius_max"):
            text += " (RMS radius of the cage mass-centre orbit)" if name == "whirl_amplitude" else ""
            r = float(var.values)
            if name == "whirl_radius_max" and gc is not None and np.isfinite(r) and r > float(gc):
                text += (f" (cage centre {(r - float(gc)) * 1e6:.2g} \u00b5m beyond the {float(gc) * 1e6:.0f} \u00b5m "
                         "guide clearance: elastic penetration of the cage-land rub contact)")
        print(f"{name}: {text}")
    from hsbearing.systems import for_archive

    system = for_archive(ds)  # the system's own lines: gyro start ensemble; drive torque and power loss by source
    for line in (system.summary_lines(ds) if system is not None else []):
        print(line)
    if ds.attrs.get("warnings", "none") != "none":  # contact/film/cage limits (hsbearing.systems.angular_contact.contact_state)
        for w in str(ds.attrs["warnings"]).split(" | "):
            print(f"warning: {w}")
    if "classification" in ds.attrs:
        cls = ds.attrs["classification"]
        reason = ds.attrs.get("classification_reason", "")
        kind = ds.attrs.get("poincare_section_kind", "")
        if cls == "undetermined":
            print(f"classification: undetermined ({reason})" if reason else "classification: undetermined")
        else:
            conf = ds.attrs.get("classification_confidence")
            det = ds.attrs.get("classification_detail", "")
            print(f"classification: {cls}" + (f", {det}" if det else "")
                  + (f" (confidence {float(conf):.2f})" if conf is not None else ""))
        if ds.attrs.get("poincare_section"):
            print(f"section: {kind + ' -- ' if kind else ''}{ds.attrs['poincare_section']}")
        alt = ds.attrs.get("classification_alternative")
        if alt:
            print(f"classification on the {ds.attrs.get('classification_alternative_section', 'other')} section: {alt}")
        if ds.attrs.get("whirl_cage_lock"):
            print(f"whirl-cage lock: {ds.attrs['whirl_cage_lock']}")
        try:
            import json as _json

            det = _json.loads(ds.attrs.get("classification_details", "{}"))
        except ValueError:
            det = {}
        if det.get("modulation_y") is not None and det.get("modulation_vy") is not None:
            print(f"section spread (modulation amplitude the label does not resolve): D_Y "
                  f"{det['modulation_y'] * 1e6:.3g} \u00b5m, V_Y {det['modulation_vy'] * 1e3:.3g} mm/s")
    stats = {k[len("solver_"):]: v for k, v in ds.attrs.items()
             if k.startswith("solver_") and not k.endswith("_units")}  # the NAME_units companions are not stats
    if stats:
        print("solver: " + format_solver_stats(stats))
    if out is not None:
        print(f"archive: {out}")


def is_nan_variable(var) -> bool:
    import numpy as np

    try:
        return var.dtype.kind == "f" and bool(np.isnan(var.values))
    except (TypeError, ValueError):
        return False


def nan_reason(name: str, ds) -> str:
    """Why a summary scalar of a run is not defined (printed instead of "nan")."""
    if name == "sfmo" or name.startswith("sfmo_"):
        import tomllib

        try:
            mode = tomllib.loads(str(ds.attrs.get("case_toml", ""))).get("operating", {}).get("mode", "constant")
        except tomllib.TOMLDecodeError:
            mode = "?"
        if mode != "oscillation":
            return "SFMO is the starting moment under oscillation: operating.mode = oscillation"
        return "SFMO needs at least two reversal windows: simulate longer than two oscillation periods"
    if name.startswith("whirl_") or name == "mean_cage_speed":
        n = int(ds.sizes.get("time", 0))
        return (f"fewer than 16 cage-centre samples after the transient ({n} samples in the run): simulate longer "
                "or sample more often")
    if name.startswith("sfmc") or name == "rfmc":
        return "no complete starting window in the run: simulate longer"
    return "not defined for this run"
