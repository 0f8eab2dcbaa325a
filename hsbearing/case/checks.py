"""Checks across keys: values that are each in range but impossible together, the bearing envelope, output sizes and the oil's service range (warnings)."""

from __future__ import annotations

import difflib
import math
import re

from hsbearing.case.schema import MAX_CONFORMITY
from hsbearing.errors import CaseError  # defined in errors (below models/); case.CaseError is the same class


def check_physical(case, source: str) -> None:
    """Cross-key checks: conformities, balls on the pitch circle, pocket vs ball, oil."""
    b, c = case.bearing, case.cage
    for key in ("inner_conformity", "outer_conformity"):
        f = getattr(b, key)
        if f is not None and f <= 0.5:
            raise CaseError(source, f"bearing.{key}", f"conformity must be > 0.5 (groove radius larger than the ball radius), got {f}")
        if f is not None and f >= MAX_CONFORMITY:
            raise CaseError(source, f"bearing.{key}", f"conformity {f:g} means a groove radius of {f:g} ball diameters: "
                                                      f"not a ball-bearing groove (must be below {MAX_CONFORMITY:g}; "
                                                      "real bearings 0.505-0.58)")
    D, dm, Z = b.ball_diameter, b.pitch_diameter, b.ball_count
    if D >= dm:
        raise CaseError(source, "bearing.ball_diameter", f"ball diameter {D*1e3:g} mm is not smaller than the pitch diameter {dm*1e3:g} mm")
    chord = dm * math.sin(math.pi / Z)  # centre-to-centre distance of neighbouring balls
    if Z > 1 and chord <= D:
        raise CaseError(
            source, "bearing.ball_count",
            f"{Z} balls of {D*1e3:g} mm do not fit the pitch circle of {dm*1e3:g} mm (neighbour spacing {chord*1e3:.3f} mm)",
        )
    if c.pocket_diameter is not None and c.pocket_diameter <= D:
        raise CaseError(source, "cage.pocket_diameter", f"cage pocket {c.pocket_diameter*1e3:g} mm is not larger than the ball {D*1e3:g} mm")
    if b.bore_diameter is not None and b.outside_diameter is not None and b.bore_diameter >= b.outside_diameter:
        raise CaseError(source, "bearing.bore_diameter", "bore diameter must be smaller than the outside diameter")
    if b.width is not None and b.width < D:  # before the guide lands (a narrow ring leaves no land either)
        raise CaseError(source, "bearing.width", f"ring width {b.width * 1e3:g} mm is narrower than the ball {D * 1e3:g} mm")
    check_guide_lands(case, source)
    if case.system in ("angular_contact", "deep_groove", "gyro_ribbon_cage"):
        from hsbearing.models import traction

        oil = case.lubricant.oil
        if oil not in traction.OILS:
            close = difflib.get_close_matches(oil, list(traction.OILS), n=1)
            hint = f"; did you mean {close[0]!r}?" if close else ""
            from hsbearing.lubricant import bundled_lubricants

            raise CaseError(source, "lubricant.oil", f"unknown oil {oil!r}{hint} (known: {', '.join(traction.OILS)}; "
                            f"bundled lubricants: {', '.join(bundled_lubricants())}; or a lubricant file path ending in .toml)")
        law = case.lubricant.traction_law
        d = case.lubricant.definition
        if law == traction.USER_LAW:
            if d is None or d.coefficients is None:
                raise CaseError(source, "lubricant.traction_law", "law 'user' needs a lubricant file with traction.model = "
                                "\"coefficients\" or \"table\" (docs/traction.md, \"Lubricant files\")")
        elif law not in traction.KNOWN_LAWS[oil]:
            raise CaseError(source, "lubricant.traction_law",
                            f"unknown traction law {law!r} for oil {oil} (known: {', '.join(traction.KNOWN_LAWS[oil])})")
        elif law == traction.PHYSICAL_LAW:
            raise CaseError(source, "lubricant.traction_law", "law 'physical' (thermal) is evaluated at one contact by "
                            "hsbearing.traction_coefficient; the dynamic and quasi-static models do not run it yet "
                            "(use 'eyring', its isothermal form)")
        if case.system == "angular_contact" and case.lubricant.temperature <= 273.15 and traction.is_seed_law(law):
            raise CaseError(source, "lubricant.temperature",
                            "the Zhang et al. 2016 traction laws are fitted in degC and undefined at or below 0 degC")


def check_guide_lands(case, source: str) -> None:
    """Guide-land keys: land inside the cage, lands wider than the ring/cage, no land left by the groove."""
    if case.system not in ("angular_contact", "deep_groove") or case.cage is None:
        return
    from hsbearing.models.geometry import GuideLandError, guide_lands

    c = case.cage
    if c.guide_land_count == 0 and c.guidance != "ball":
        raise CaseError(source, "cage.guide_land_count", f"guidance = {c.guidance} needs at least one land (0 only for guidance = ball)")
    try:
        guide_lands(case)
    except GuideLandError as exc:
        raise CaseError(source, exc.key, exc.message) from None

#: Most output samples one run may store (duration / output_interval + 1); about 3 kB each for an
#: 11-ball bearing, so the limit keeps a run's arrays near 1.5 GB.
MAX_OUTPUT_SAMPLES = 500_000

#: A case name becomes a file name (``runs/<name>-<hash>.nc``): letters, digits, ``_ - . +``, no path.
_NAME = re.compile(r"^[A-Za-z0-9][A-Za-z0-9_.+-]{0,99}$")


def check_output_samples(case, duration: float | None = None, *, source: str | None = None,
                         key: str = "simulation.output_interval") -> int:
    """Number of output samples of a run of ``duration`` [s] (None: the case's); CaseError above the limit."""
    sim = case.simulation
    T = sim.duration if duration is None else float(duration)
    dt = min(sim.output_interval, T) if T > 0 else sim.output_interval
    n = T / dt + 1.0 if dt > 0 else math.inf
    if not n <= MAX_OUTPUT_SAMPLES:
        raise CaseError(source or case.source, key,
                        f"duration {T:g} s / output_interval {sim.output_interval:g} s gives {n:.3g} output samples "
                        f"(at most {MAX_OUTPUT_SAMPLES}): raise simulation.output_interval or shorten the duration")
    return int(n)


def check_possible(case, source: str) -> None:
    """Values that are each in range but impossible for a bearing, or unsafe as file names."""
    b, c, info = case.bearing, case.cage, case.info
    if not _NAME.match(info.name):
        raise CaseError(source, "case.name", f"{info.name!r} is not a plain file name (letters, digits, _ - . +; "
                                             "no path, no spaces; at most 100 characters): it names the output files")
    if b.contact_angle is not None and not b.contact_angle < 0.5 * math.pi:
        raise CaseError(source, "bearing.contact_angle",
                        f"must be below 90 deg (a radial or angular-contact bearing), got {math.degrees(b.contact_angle):g} deg")
    if case.lubricant.temperature is not None and not case.lubricant.temperature > 0:
        raise CaseError(source, "lubricant.temperature",
                        f"{case.lubricant.temperature:g} K is at or below absolute zero")
    D, dm = b.ball_diameter, b.pitch_diameter
    mm = lambda x: f"{x * 1e3:g} mm"  # noqa: E731
    if b.bore_diameter is not None and b.bore_diameter >= dm - D:
        raise CaseError(source, "bearing.bore_diameter", f"bore {mm(b.bore_diameter)} does not leave room for the "
                        f"inner raceway (pitch diameter {mm(dm)} - ball diameter {mm(D)} = {mm(dm - D)})")
    if b.outside_diameter is not None and b.outside_diameter <= dm + D:
        raise CaseError(source, "bearing.outside_diameter", f"outside diameter {mm(b.outside_diameter)} does not "
                        f"enclose the outer raceway (pitch diameter + ball diameter = {mm(dm + D)})")
    if b.inner_land_diameter is not None and not (b.bore_diameter or 0.0) < b.inner_land_diameter < dm:
        raise CaseError(source, "bearing.inner_land_diameter", f"{mm(b.inner_land_diameter)} must lie between the bore "
                        f"and the pitch diameter {mm(dm)}")
    if b.outer_land_diameter is not None and not dm < b.outer_land_diameter < (b.outside_diameter or math.inf):
        raise CaseError(source, "bearing.outer_land_diameter", f"{mm(b.outer_land_diameter)} must lie between the "
                        f"pitch diameter {mm(dm)} and the outside diameter")
    if c.outside_diameter is not None:
        if c.outside_diameter <= dm:
            raise CaseError(source, "cage.outside_diameter", f"cage outside diameter {mm(c.outside_diameter)} must be "
                            f"larger than the pitch diameter {mm(dm)} (the pockets straddle the pitch circle)")
        if b.outside_diameter is not None and c.outside_diameter >= b.outside_diameter:
            raise CaseError(source, "cage.outside_diameter", f"cage {mm(c.outside_diameter)} is larger than the "
                            f"bearing (outside diameter {mm(b.outside_diameter)})")
        if c.guidance == "outer_ring" and b.outer_land_diameter is not None and c.outside_diameter >= b.outer_land_diameter:
            raise CaseError(source, "bearing.outer_land_diameter", f"guide land {mm(b.outer_land_diameter)} is not "
                            f"larger than the outer-ring guided cage (cage.outside_diameter {mm(c.outside_diameter)})")
    if c.bore_diameter is not None:
        if c.bore_diameter >= dm:
            raise CaseError(source, "cage.bore_diameter", f"cage bore {mm(c.bore_diameter)} must be smaller than the "
                            f"pitch diameter {mm(dm)} (the pockets straddle the pitch circle)")
        if c.outside_diameter is not None and c.bore_diameter >= c.outside_diameter:
            raise CaseError(source, "cage.bore_diameter", "cage bore must be smaller than the cage outside diameter")
        if b.bore_diameter is not None and c.bore_diameter <= b.bore_diameter:
            raise CaseError(source, "cage.bore_diameter", f"cage bore {mm(c.bore_diameter)} is inside the bearing bore "
                            f"{mm(b.bore_diameter)}")
        if c.guidance == "inner_ring" and b.inner_land_diameter is not None and c.bore_diameter <= b.inner_land_diameter:
            raise CaseError(source, "bearing.inner_land_diameter", f"guide land {mm(b.inner_land_diameter)} is not "
                            f"smaller than the inner-ring guided cage bore (cage.bore_diameter {mm(c.bore_diameter)})")
    check_envelope(case, source)
    check_output_samples(case, source=source)


#: Temperature envelope of the bundled oils [degC]: (pour point, lowest service temperature, highest service
#: temperature) of the specification class each oil is read as (hsbearing.models.viscosity.OIL_SPEC):
#: MIL-PRF-7808 (4109) and MIL-PRF-23699 (4106, 4050) turbine oils, pour points -60 / -54 degC (spec maxima),
#: service ranges -51..204 and -40..204 degC (the specs' qualification ranges).  Beyond the service range the
#: oil data (40/100 degC viscosities, the traction fits) are extrapolated: a warning.  Below the pour point
#: the oil does not flow, above OIL_DECOMPOSITION_C ester base stocks decompose thermally: an error.
OIL_TEMPERATURE_C: dict[str, tuple[float, float, float]] = {
    "4109": (-60.0, -51.0, 204.0),
    "4106": (-54.0, -40.0, 204.0),
    "4050": (-54.0, -40.0, 204.0),
}
#: Above this [degC] no lubricating oil of the bundled classes is a liquid film (thermal decomposition of the
#: ester base stock; flash points of the classes 210-270 degC): refused.
OIL_DECOMPOSITION_C = 350.0


def _free_contact_angle(b) -> float | None:
    """Free contact angle [rad] implied by the diametral clearance (None if no clearance is given)."""
    if b.diametral_clearance is None or b.inner_conformity is None or b.outer_conformity is None:
        return None
    A = (b.inner_conformity + b.outer_conformity - 1.0) * b.ball_diameter
    c = 1.0 - b.diametral_clearance / (2.0 * A)
    return math.acos(max(-1.0, min(1.0, c))) if c > -1.0 else math.pi


def check_envelope(case, source: str) -> None:
    """Impossible bearings: whatever does not fit in the bearing's envelope."""
    b, c = case.bearing, case.cage
    D, dm, Z = b.ball_diameter, b.pitch_diameter, b.ball_count
    mm = lambda x: f"{x * 1e3:g} mm"  # noqa: E731
    if case.system in ("angular_contact", "deep_groove") and b.diametral_clearance is not None:
        A = (b.inner_conformity + b.outer_conformity - 1.0) * D
        alpha = _free_contact_angle(b)
        if alpha is not None and not alpha < 0.5 * math.pi:
            raise CaseError(source, "bearing.diametral_clearance",
                            f"{b.diametral_clearance * 1e6:g} um gives a free contact angle of "
                            f"{math.degrees(alpha):.4g} deg (>= 90 deg: the balls would not be held between the "
                            f"rings); it must be below 2 (f_i + f_o - 1) D = {2 * A * 1e6:.4g} um")
    if c is not None:
        if c.width is not None and b.width is not None and c.width > b.width:
            raise CaseError(source, "cage.width", f"cage width {mm(c.width)} is wider than the bearing "
                                                  f"(bearing.width {mm(b.width)})")
        dp = c.pocket_diameter if c.pocket_diameter is not None else (
            D + 2.0 * c.pocket_clearance if c.pocket_clearance is not None else None)
        if dp is not None and Z > 1:
            chord = dm * math.sin(math.pi / Z)  # centre distance of neighbouring pockets
            if dp >= chord:
                key = "cage.pocket_diameter" if c.pocket_diameter is not None else "cage.pocket_clearance"
                raise CaseError(source, key, f"{Z} pockets of {mm(dp)} overlap on the pitch circle of {mm(dm)} "
                                             f"(neighbour spacing {chord * 1e3:.4g} mm): no cage bar is left between them")
        if (case.system in ("angular_contact", "deep_groove") and dp is not None and c.width is not None
                and c.width <= dp):
            raise CaseError(source, "cage.width", f"cage width {mm(c.width)} is not wider than its pockets ({mm(dp)}): "
                                                  "the pockets cut the cage ring through")
        if c.pocket_depth is not None and c.pocket_depth <= 0.5 * D:
            raise CaseError(source, "cage.pocket_depth", f"pocket depth {mm(c.pocket_depth)} is not deeper than the ball "
                                                         f"radius {mm(0.5 * D)}: the ball does not fit the pocket")
        if c.mass is None and c.outside_diameter and c.bore_diameter and c.width and dp is not None:
            vol = math.pi / 4 * (c.outside_diameter**2 - c.bore_diameter**2) * c.width \
                - Z * math.pi / 4 * dp**2 * (c.outside_diameter - c.bore_diameter) / 2
            if not vol > 0:
                raise CaseError(source, "cage.pocket_diameter", f"the {Z} pockets of {mm(dp)} remove the whole cage "
                                                                "(computed cage mass 0 g): give smaller pockets or cage.mass")
    if case.system == "angular_contact" and case.operating.axial_load < 0:
        raise CaseError(source, "operating.axial_load",
                        f"{case.operating.axial_load:g} N: a single angular-contact bearing carries axial load in one "
                        "direction only (positive: the inner ring pushed along +X into its contacts); a negative load "
                        "lifts the balls off the contact angle -- mount the bearing the other way round (give the "
                        "load as positive)")
    oil, T = case.lubricant.oil, case.lubricant.temperature
    if T is not None:
        t_c = T - 273.15
        if t_c > OIL_DECOMPOSITION_C:  # any system: no lubricating oil film there
            raise CaseError(source, "lubricant.temperature", f"{t_c:g} degC: no oil film at this temperature (the "
                                                             f"turbine-oil classes decompose above ~{OIL_DECOMPOSITION_C:g} degC)")
        if _oil_data_used(case):  # the oil's own data: below its pour point it does not flow
            pour, _, _ = OIL_TEMPERATURE_C[oil]
            if t_c < pour:
                raise CaseError(source, "lubricant.temperature", f"{t_c:g} degC is below the pour point of oil {oil} "
                                                                 f"({pour:g} degC): the oil does not flow")


def _oil_data_used(case) -> bool:
    """The model reads the named oil's data (viscosity, traction): the angular-contact model with a bundled oil
    (the other systems carry the oil name as a placeholder and use their own viscosity)."""
    return (case.system == "angular_contact" and case.lubricant.oil in OIL_TEMPERATURE_C
            and getattr(case.lubricant, "file", None) is None)


#: Typical upper speed factor n d_m [mm r/min] of single-row angular-contact ball bearings by lubrication method,
#: used for the speed warning when the case gives no ``bearing.limiting_speed``.  Order values of the bearing
#: makers' lubrication guides (FAG publication WL 81 115/4 EA "Rolling Bearing Lubrication", section 2.5 "Selection
#: of the lubrication system": speed parameter n d_m by method; Harris & Kotzalas, "Essential Concepts of Bearing
#: Technology", 5th ed. 2007, ch. 1 and 12: aero-engine main-shaft ball bearings under jet lubrication at 2-3 million
#: DN).  The numbers were not re-read from those tables here: they are typical values, stated as such in the
#: warning, and a case with the catalogue's limiting speed replaces them.
TYPICAL_NDM = {"oil_jet": 2.5e6, "oil_air": 2.0e6, "oil_bath": 0.5e6, "grease": 1.0e6, "dry": 0.1e6}


def speed_factor(case) -> float:
    """n d_m [mm r/min]: the relative ring speed |n_i - n_o| [r/min] times the pitch diameter [mm]."""
    n_rpm = abs(case.operating.inner_speed - case.operating.outer_speed) * 30.0 / math.pi
    return n_rpm * case.bearing.pitch_diameter * 1e3


def speed_limit(case) -> tuple[float, str]:
    """The n d_m limit [mm r/min] of the speed warning and where it comes from (the case, else the typical value)."""
    b = case.bearing
    if getattr(b, "limiting_speed", None):
        n = b.limiting_speed * 30.0 / math.pi
        return n * b.pitch_diameter * 1e3, f"bearing.limiting_speed {n:.6g} r/min x d_m {b.pitch_diameter * 1e3:.4g} mm"
    lub = case.lubricant.lubrication
    return TYPICAL_NDM.get(lub, TYPICAL_NDM["oil_jet"]), (
        f"typical for {lub} lubrication of angular-contact ball bearings (FAG WL 81 115, Harris & Kotzalas; not the "
        "bearing's own rating: give bearing.limiting_speed from its catalogue)")


def envelope_warnings(case) -> list[str]:
    """Values inside what is possible but outside the data behind the model (printed as warnings by the CLI and
    stored in the archives' ``warnings``): the oil beyond its stated service range, the speed beyond a limiting
    n d_m.  One line each; nothing is refused."""
    out = []
    oil, T = case.lubricant.oil, case.lubricant.temperature
    if T is not None and _oil_data_used(case):
        _, lo, hi = OIL_TEMPERATURE_C[oil]
        t_c = T - 273.15
        if not lo <= t_c <= hi:
            out.append(f"lubricant.temperature: {t_c:g} degC is outside the service range of oil {oil} "
                       f"({lo:g}..{hi:g} degC): its viscosity and traction data are extrapolated")
    d = getattr(case.lubricant, "definition", None)
    if T is not None and d is not None and d.service_range is not None:
        lo, hi = (x - 273.15 for x in d.service_range)
        t_c = T - 273.15
        if not lo <= t_c <= hi:
            out.append(f"lubricant.temperature: {t_c:g} degC is outside the service range of {d.name} "
                       f"({lo:g}..{hi:g} degC, its lubricant file): its viscosity data are extrapolated")
    if case.system in ("angular_contact", "deep_groove") and case.bearing.pitch_diameter:
        ndm = speed_factor(case)
        lim, why = speed_limit(case)
        if ndm > lim:
            out.append(f"operating.inner_speed: n d_m = {ndm:.3g} mm r/min is above {lim:.3g} mm r/min ({why}): "
                       "check the speed (a typing error?); the results are computed but the bearing would not run there")
    return out
