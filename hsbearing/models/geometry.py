"""Internal geometry, masses and inertias of a ball bearing, derived from a case.

References
----------
[1] Harris T. A., Kotzalas M. N., *Rolling Bearing Analysis*, 5th ed., Vol. 1
    (Essential Concepts), Ch. 2: Eq. 2.2 (pitch diameter), 2.5-2.6 (groove
    curvature radii, conformity), 2.9 (distance between groove curvature
    centres A = B D, total curvature B = f_i + f_o - 1), 2.10 (free contact
    angle cos alpha_0 = 1 - P_d / (2 A)); Ch. 2.4 curvature sums
    (Eqs. 2.27-2.31).

[2] Hamrock B. J., Dowson D., *Ball Bearing Lubrication*, Wiley 1981, Ch. 2-3.

All results SI.  gamma = D cos(alpha) / d_m.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

__all__ = ["Geometry", "derive", "curvature_radii", "describe", "GuideLands", "GuideLandError", "guide_lands", "groove_width_at"]


@dataclass(frozen=True)
class Geometry:
    """Derived geometry of a ball bearing (SI)."""

    Z: int  #: ball count
    D: float  #: ball diameter [m]
    dm: float  #: pitch diameter [m]
    fi: float  #: inner conformity r_i / D
    fo: float  #: outer conformity r_o / D
    ri: float  #: inner groove radius [m]  ([1] Eq. 2.5)
    ro: float  #: outer groove radius [m]
    B: float  #: total curvature f_i + f_o - 1  ([1] Eq. 2.9)
    A: float  #: distance between groove curvature centres at zero load, B D [m]
    alpha0: float  #: free contact angle [rad]  ([1] Eq. 2.10)
    Pd: float  #: diametral clearance [m]
    Pe: float  #: free end play 2 A sin(alpha0) [m]  ([1] Eq. 2.13)
    di: float  #: inner raceway (groove bottom) diameter [m]
    do: float  #: outer raceway (groove bottom) diameter [m]
    ball_mass: float  #: [kg]
    ball_inertia: float  #: about a diameter, m D^2 / 10 [kg m^2]
    cage_mass: float  #: [kg]
    cage_axial_inertia: float  #: [kg m^2]
    cage_diametral_inertia: float  #: [kg m^2]
    inner_ring_mass: float  #: [kg]
    inner_ring_axial_inertia: float  #: [kg m^2]
    inner_ring_diametral_inertia: float  #: [kg m^2]
    pocket_clearance: float  #: radial clearance between ball and pocket (d_p - D)/2 [m]
    guide_clearance: float  #: radial clearance cage / guiding land [m] (nan if not given)


def curvature_radii(D, dm, alpha, fi, fo):
    """Effective radii (Rx_i, Ry_i, Rx_o, Ry_o) [m] of the ball/race contacts at contact angle alpha.

    [1] Eqs. 2.27-2.31 with gamma = D cos(alpha)/d_m:
    Rx_i = D (1 - gamma)/2, Ry_i = f_i D / (2 f_i - 1),
    Rx_o = D (1 + gamma)/2, Ry_o = f_o D / (2 f_o - 1).
    """
    gamma = D * np.cos(alpha) / dm
    Rx_i = 0.5 * D * (1.0 - gamma)
    Rx_o = 0.5 * D * (1.0 + gamma)
    Ry_i = fi * D / (2.0 * fi - 1.0)
    Ry_o = fo * D / (2.0 * fo - 1.0)
    return Rx_i, np.broadcast_to(Ry_i, np.shape(Rx_i)), Rx_o, np.broadcast_to(Ry_o, np.shape(Rx_o))


def derive(case) -> Geometry:
    """Derive the bearing geometry, masses and inertias from a :class:`~hsbearing.case.Case`."""
    b, c = case.bearing, case.cage
    Z, D, dm = b.ball_count, b.ball_diameter, b.pitch_diameter
    fi = b.inner_conformity if b.inner_conformity is not None else 0.52
    fo = b.outer_conformity if b.outer_conformity is not None else 0.52
    Bc = fi + fo - 1.0
    A = Bc * D
    if b.diametral_clearance is not None:
        Pd = b.diametral_clearance
        alpha0 = math.acos(max(-1.0, min(1.0, 1.0 - Pd / (2.0 * A))))  # [1] Eq. 2.10
    else:
        alpha0 = b.contact_angle or 0.0
        Pd = 2.0 * A * (1.0 - math.cos(alpha0))  # [1] Eq. 2.10 inverted
    Pe = 2.0 * A * math.sin(alpha0)  # [1] Eq. 2.13
    ri, ro = fi * D, fo * D
    # groove-bottom diameters: ball centre on d_m, groove centres at +/- (r - D/2) offset along the contact line
    di = dm - D - Pd / 2.0
    do = dm + D + Pd / 2.0
    rho_b = case.materials.ball.density
    ball_mass = rho_b * math.pi * D**3 / 6.0
    ball_inertia = ball_mass * D**2 / 10.0
    # cage: annulus minus Z cylindrical pockets (radial through-holes) unless given
    if c.outside_diameter and c.bore_diameter and c.width:
        Do_c, Di_c, w = c.outside_diameter, c.bore_diameter, c.width
        dp = c.pocket_diameter or (D + 2 * (c.pocket_clearance or 0.0))
        vol = math.pi / 4 * (Do_c**2 - Di_c**2) * w - Z * math.pi / 4 * dp**2 * (Do_c - Di_c) / 2
        m_c = case.materials.cage.density * max(vol, 0.0)
        J_cx = m_c * (Do_c**2 + Di_c**2) / 8.0
        J_cy = m_c * ((Do_c**2 + Di_c**2) / 16.0 + w**2 / 12.0)
    else:
        m_c = J_cx = J_cy = float("nan")
    cage_mass = c.mass if c.mass is not None else m_c
    cage_ax = c.axial_inertia if c.axial_inertia is not None else J_cx
    cage_di = c.diametral_inertia if c.diametral_inertia is not None else J_cy
    # inner ring: annulus from the bore to the raceway shoulder, full width (an estimate unless given)
    if b.bore_diameter and b.width:
        d_out = b.inner_land_diameter or (dm - 0.5 * D)
        vol_i = math.pi / 4 * (d_out**2 - b.bore_diameter**2) * b.width
        m_i = case.materials.races.density * vol_i
        J_ix = m_i * (d_out**2 + b.bore_diameter**2) / 8.0
        J_iy = m_i * ((d_out**2 + b.bore_diameter**2) / 16.0 + b.width**2 / 12.0)
    else:
        m_i = J_ix = J_iy = float("nan")
    if c.pocket_diameter is not None:
        pc = 0.5 * (c.pocket_diameter - D)
    elif c.pocket_clearance is not None:
        pc = c.pocket_clearance
    else:
        pc = float("nan")
    if c.guidance == "outer_ring" and b.outer_land_diameter and c.outside_diameter:
        gc = 0.5 * (b.outer_land_diameter - c.outside_diameter)
    elif c.guidance == "inner_ring" and b.inner_land_diameter and c.bore_diameter:
        gc = 0.5 * (c.bore_diameter - b.inner_land_diameter)
    else:
        gc = float("nan")
    return Geometry(
        Z=Z, D=D, dm=dm, fi=fi, fo=fo, ri=ri, ro=ro, B=Bc, A=A, alpha0=alpha0, Pd=Pd, Pe=Pe, di=di, do=do,
        ball_mass=ball_mass, ball_inertia=ball_inertia,
        cage_mass=cage_mass, cage_axial_inertia=cage_ax, cage_diametral_inertia=cage_di,
        inner_ring_mass=b.inner_ring_mass if b.inner_ring_mass is not None else m_i,
        inner_ring_axial_inertia=b.inner_ring_axial_inertia if b.inner_ring_axial_inertia is not None else J_ix,
        inner_ring_diametral_inertia=b.inner_ring_diametral_inertia if b.inner_ring_diametral_inertia is not None else J_iy,
        pocket_clearance=pc, guide_clearance=gc,
    )


class GuideLandError(ValueError):
    """A bad combination of guide-land keys; ``key`` names the case key (``table.key``)."""

    def __init__(self, key: str, message: str):
        super().__init__(f"{key}: {message}")
        self.key, self.message = key, message


@dataclass(frozen=True)
class GuideLands:
    """The cage guide lands of a case (SI).  ``count`` 0 for a ball-piloted cage (no land film)."""

    guidance: str  #: outer_ring, inner_ring or ball
    count: int  #: number of lands (separate films, forces add)
    width: float  #: axial width of one land film [m]
    diameter: float  #: land diameter [m] (nan for ball guidance)
    radius: float  #: film radius = cage guide-surface radius [m]
    clearance: float  #: radial guide clearance [m]
    offsets: tuple  #: axial positions of the land centres from the cage mid-plane [m]
    groove_width: float  #: raceway-groove width at the land diameter [m] (nan if not computable)
    notes: tuple  #: where each value comes from (``hsbearing check``)


def groove_width_at(diameter, groove_radius, groove_centre_radius):
    """Axial width [m] of a circular groove (radius r, centre at radius rho) at the diameter d: 2 sqrt(r^2 - (d/2 - rho)^2).

    nan when the groove does not reach that diameter.  The groove is the circle of the
    groove cross-section (Harris & Kotzalas, 5th ed., Vol. 1, Ch. 2, Fig. 2.6).
    """
    q = groove_radius**2 - (0.5 * diameter - groove_centre_radius) ** 2
    return 2.0 * math.sqrt(q) if q > 0 else float("nan")


def guide_lands(case) -> GuideLands:
    """Guide lands of the cage from the case: guidance, count, width, diameter, clearance, axial positions.

    Defaults (each overridable in ``[cage]``):

    * ``guide_land_count``: 2 for ring guidance -- one land on each side of the raceway groove;
    * ``guide_land_width``: the axial overlap of the cage guide surface with the land on one side,
      min(ring width, cage width)/2 - (groove width at the land diameter)/2, the groove (radius
      f D, centre at d_o/2 - f D for the outer ring, d_i/2 + f D for the inner ring; raceway
      diameters of :func:`derive`) taken symmetric about the cage mid-plane; the ring width is the
      bearing ``width`` (the cage width if absent);
    * land positions: each land film reaches the cage face, centres at +-(cage width - land width)/2
      (one land: on the +X side).

    Raises :class:`GuideLandError` naming the key for a land inside the cage, lands wider than the
    ring or the cage, or a groove that leaves no land under the cage.
    """
    b, c = case.bearing, case.cage
    nan = float("nan")
    guidance = c.guidance
    if guidance == "ball":
        if c.guide_land_count not in (None, 0):
            raise GuideLandError("cage.guide_land_count", "a ball-piloted cage (guidance = \"ball\") has no guide land")
        return GuideLands("ball", 0, 0.0, nan, nan, nan, (), nan, ("ball-piloted: no land film",))
    g = derive(case)
    notes = []
    if guidance == "outer_ring":
        dkey, d_land, surf, _surf_key = "bearing.outer_land_diameter", b.outer_land_diameter, c.outside_diameter, "cage.outside_diameter"
        if d_land is not None and surf is not None and d_land <= surf:
            raise GuideLandError(dkey, f"outer-ring land diameter {d_land*1e3:g} mm is not larger than the cage outside "
                                       f"diameter {surf*1e3:g} mm (land inside the cage)")
        if d_land is not None and d_land >= g.do:
            raise GuideLandError(dkey, f"outer-ring land diameter {d_land*1e3:g} mm is not smaller than the outer raceway "
                                       f"diameter {g.do*1e3:.4g} mm")
        rho, r_g = 0.5 * g.do - g.ro, g.ro
    else:
        dkey, d_land, surf, _surf_key = "bearing.inner_land_diameter", b.inner_land_diameter, c.bore_diameter, "cage.bore_diameter"
        if d_land is not None and surf is not None and d_land >= surf:
            raise GuideLandError(dkey, f"inner-ring land diameter {d_land*1e3:g} mm is not smaller than the cage bore "
                                       f"{surf*1e3:g} mm (land inside the cage)")
        if d_land is not None and d_land <= g.di:
            raise GuideLandError(dkey, f"inner-ring land diameter {d_land*1e3:g} mm is not larger than the inner raceway "
                                       f"diameter {g.di*1e3:.4g} mm")
        rho, r_g = 0.5 * g.di + g.ri, g.ri
    clearance = abs(0.5 * (d_land - surf)) if (d_land is not None and surf is not None) else nan
    radius = 0.5 * surf if surf is not None else nan
    gw = groove_width_at(d_land, r_g, rho) if d_land is not None else nan
    w_cage = c.width
    w_ring = b.width if b.width is not None else w_cage
    span = min(w for w in (w_cage, w_ring) if w is not None) if (w_cage or w_ring) else nan
    count = c.guide_land_count if c.guide_land_count is not None else 2
    notes.append(f"{count} land(s)" + (" (default: one each side of the groove)" if c.guide_land_count is None else " (case)"))
    if c.guide_land_width is not None:
        width = c.guide_land_width
        notes.append(f"land width {width*1e3:.4g} mm (case)")
    else:
        width = 0.5 * (span - gw) if math.isfinite(gw) and math.isfinite(span) else nan
        if math.isfinite(width) and width <= 0:
            raise GuideLandError("cage.guide_land_width",
                                 f"the groove ({gw*1e3:.4g} mm wide at the land diameter {d_land*1e3:g} mm) covers the whole "
                                 f"{span*1e3:g} mm of cage/ring overlap: no land under the cage; give the land width")
        if math.isfinite(width):
            ring_txt = f"{w_ring*1e3:g}" if w_ring is not None else "not given"  # either width may be absent
            cage_txt = f"{w_cage*1e3:g} mm" if w_cage is not None else "not given"
            notes.append(f"land width {width*1e3:.4g} mm (default: (min(ring width {ring_txt}, cage width "
                         f"{cage_txt}) - groove width {gw*1e3:.4g} mm at the land diameter) / 2)")
    if math.isfinite(width) and math.isfinite(span) and math.isfinite(gw) and width > 0.5 * (span - gw) * (1 + 1e-9):
        raise GuideLandError("cage.guide_land_width",
                             f"a land of {width*1e3:g} mm does not fit beside the {gw*1e3:.4g} mm groove (at the land diameter) in "
                             f"the {span*1e3:g} mm the cage overlaps the ring: at most {0.5*(span-gw)*1e3:.4g} mm per land "
                             f"(guide_land_width is now the width of ONE land; before guide_land_count it was the whole film length)")
    if math.isfinite(width) and math.isfinite(span) and count * width > span * (1 + 1e-12):
        raise GuideLandError("cage.guide_land_width",
                             f"{count} land(s) of {width*1e3:g} mm are wider than the {span*1e3:g} mm the cage overlaps the ring "
                             f"(guide_land_width is the width of ONE land; it was the whole film length before "
                             f"guide_land_count existed: give guide_land_count = 1 for a single film)")
    if math.isfinite(width) and w_cage is not None:
        a = 0.5 * (w_cage - width)
        offsets = (-a, a) if count == 2 else (a,)
    else:
        offsets = (0.0,) * count
    return GuideLands(guidance, count, width, d_land if d_land is not None else nan, radius, clearance, offsets, gw,
                      tuple(notes))


def describe(case) -> list[str]:
    """Human-readable lines of the derived geometry (``hsbearing check``)."""
    mm, deg = 1e3, 180 / math.pi
    if case.system == "wire_race":
        b = case.bearing
        lines = [
            f"balls: Z = {b.ball_count}, D = {b.ball_diameter*mm:.4g} mm on pitch diameter d_m = {b.pitch_diameter*mm:.5g} mm",
            f"four ball/wire contacts at alpha = {(b.contact_angle or 0.0)*deg:.4g} deg",
        ]
        if b.wire_diameter is not None:
            lines.append(f"wire diameter d_w = {b.wire_diameter*mm:.4g} mm")
        if case.operating.preload is not None:
            lines.append(f"preload delta = {case.operating.preload*1e6:.4g} um")
        return lines
    g = derive(case)
    lines = [
        f"balls: Z = {g.Z}, D = {g.D*mm:.4g} mm, pitch diameter d_m = {g.dm*mm:.4g} mm, gamma0 = {g.D*math.cos(g.alpha0)/g.dm:.4f}",
        f"conformity f_i = {g.fi:.4g}, f_o = {g.fo:.4g}; groove radii r_i = {g.ri*mm:.4g} mm, r_o = {g.ro*mm:.4g} mm",
        f"total curvature B = {g.B:.4g}, A = B D = {g.A*mm:.4g} mm",
        f"free contact angle alpha_0 = {g.alpha0*deg:.4g} deg, diametral clearance P_d = {g.Pd*1e6:.4g} um, free end play P_e = {g.Pe*1e6:.4g} um",
        f"raceway diameters d_i = {g.di*mm:.5g} mm, d_o = {g.do*mm:.5g} mm",
        f"ball mass {g.ball_mass*1e3:.4g} g, inertia {g.ball_inertia:.4g} kg m^2",
    ]
    if math.isfinite(g.cage_mass):
        lines.append(f"cage mass {g.cage_mass*1e3:.4g} g, inertia axial {g.cage_axial_inertia:.4g} / diametral {g.cage_diametral_inertia:.4g} kg m^2")
    if math.isfinite(g.inner_ring_mass):
        lines.append(f"inner ring mass {g.inner_ring_mass*1e3:.4g} g, inertia axial {g.inner_ring_axial_inertia:.4g} kg m^2")
    if math.isfinite(g.pocket_clearance):
        lines.append(f"pocket clearance {g.pocket_clearance*1e6:.4g} um (radial)")
    if math.isfinite(g.guide_clearance):
        lines.append(f"cage guide clearance {g.guide_clearance*1e6:.4g} um (radial, {case.cage.guidance})")
    if case.cage is not None and case.system in ("angular_contact", "deep_groove"):
        try:
            gl = guide_lands(case)
        except GuideLandError:
            gl = None
        if gl is not None and gl.count and not math.isfinite(gl.diameter):  # no land geometry in the case
            key = "bearing.outer_land_diameter" if gl.guidance == "outer_ring" else "bearing.inner_land_diameter"
            lines.append(f"guide lands ({gl.guidance}): not described (no {key}; the dynamic model needs it)")
        elif gl is not None and gl.count:
            pos = ", ".join(f"{x*mm:+.4g}" for x in gl.offsets)
            lines.append(f"guide lands ({gl.guidance}): {gl.count} x {gl.width*mm:.4g} mm on diameter {gl.diameter*mm:.4g} mm, "
                         f"centres at {pos} mm from the cage mid-plane; groove width there {gl.groove_width*mm:.4g} mm")
            lines.append("  from: " + "; ".join(gl.notes))
        elif gl is not None:
            lines.append("guide lands: none (ball-piloted cage)")
    return lines
