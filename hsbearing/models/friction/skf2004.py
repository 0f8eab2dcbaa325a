"""SKF (2004) frictional-moment model for deep-groove ball bearings.

M = M_rr + M_sl + M_seal + M_drag                                   ([1], Eq. 1)

The catalogue formulas are written in the catalogue's own units (d_m in mm,
loads in N, n in r/min, nu in mm^2/s, moments in N mm); the functions below
keep those units (stated in [brackets]) and :func:`skf_moments` converts the
result to SI (N m) at the boundary.

References
----------
[1] SKF, *General Catalogue* 6000 EN (2005/2008), section "Friction" --
    "The new SKF model for calculation of the frictional moment", pp. 88-103:
    Eq. (1) total moment; rolling moment M_rr = G_rr (nu n)^0.6; sliding
    moment M_sl = G_sl mu_sl; Table 2a (G_rr, G_sl for deep-groove ball
    bearings, alpha_F); Table 1 geometry constants R1, R2, S1, S2; mu_sl =
    phi_bl mu_bl + (1 - phi_bl) mu_EHL with phi_bl = 1/e^(2.6e-8 (n nu)^1.4 d_m);
    inlet-shear heating factor phi_ish; kinematic replenishment factor
    phi_rs (K_rs, K_Z); drag losses M_drag = V_M K_ball d_m^5 n^2.
    The same text is the SKF brochure "The SKF model for calculating the
    frictional moment" (SKF 2004/2014).
[2] SKF *General Catalogue* 6000 EN, deep-groove ball bearing tables:
    basic static load ratings C_0 (6206: 11.2 kN, 6207: 15.3 kN, 6208: 19 kN).
[3] dgbb_prl (DGBB sliding friction torque with pure rolling lines), Sec. 3
    and Tables 2-4: the "SKF" column lists the sliding moment M_sl only.
[4] SKF *General Catalogue* 6000 EN, "Friction", Table 2a, angular contact
    ball bearings: G_rr = R1 d_m^1.97 (F_r + F_g + R2 F_a)^0.54 with
    F_g = R3 d_m^4 n^2; G_sl = S1 d_m^0.26 ((F_r + F_g)^(4/3) + S2 F_a^(4/3))
    with F_g = S3 d_m^4 n^2 (formulas checked against a public copy of the
    catalogue text: yumpu "SKF - Rolling Bearings", p. 106, Table 2a
    "Geometric and load dependent variables for rolling and sliding frictional
    moments - radial bearings"; p. 105 gives mu_bl ~ 0.15, mu_EHL = 0.05 /
    0.04 / 0.1 and phi_bl = 1/e^(2.6e-8 (n nu)^1.4 d_m)).

    The series geometry constants R1, R2, R3, S1, S2, S3 of single-row
    angular contact ball bearings come from SKF's geometry-constants table
    for rolling and sliding frictional moments (table number not confirmed
    from a copy; p. 106 is Table 2a).  No copy of that table was reachable
    (skf-check, docs/life.md).  The rows used here are those of a public
    per-series transcription of the published SKF tables [5]:

    ==============  ========  ====  ========  ========  ====  ========
    row             R1        R2    R3        S1        S2    S3
    ==============  ========  ====  ========  ========  ====  ========
    72 B(E) 40 deg  4.33e-7   2.02  2.44e-12  1.82e-2   0.71  2.44e-12
    73 B(E) 40 deg  4.54e-7   2.02  1.84e-12  1.64e-2   0.71  1.84e-12
    72 AC 25 deg    3.58e-7   3.64  3.55e-12  1.14e-2   1.55  3.55e-12
    73 AC 25 deg    3.48e-7   3.64  1.66e-12  9.85e-3   1.55  1.66e-12
    other           5.03e-7   1.97  1.90e-12  1.30e-2   0.68  1.91e-12
    ==============  ========  ====  ========  ========  ====  ========

    K_Z = 4.4.  The "other single-row" row is also used, with K_Z = 4.4, by a
    second independent open-source implementation.  Before skf-check the
    ``life`` helper had typed the "other" row from memory as "72 B(E)" and an
    unsupported "73 B(E)" row (R1 4.97e-7, R2 1.68, R3 1.41e-12, S1 1.12e-2,
    S2 0.68, S3 1.18e-12) that matches no source: both replaced.  All rows
    remain secondary (not read from an SKF copy): :data:`ACBB_CONSTANTS_STATUS`.
[5] Public transcription of the SKF friction-model constants tables (an
    open-source Python bearing tool, module of "SKF friction-model constants
    transcribed from the published SKF tables"; its deep-groove 62 row equals
    DGBB_SERIES (S1, S2 also reproduce dgbb_prl), its other deep-groove rows
    agree with two other public transcriptions, and its K_rs and mu_EHL
    values with [1]).  Not an SKF document: secondary.
"""

from __future__ import annotations

import math
import re
from dataclasses import dataclass

import numpy as np

from hsbearing.errors import CaseError

#: output variables of the SKF 2004 moments over ``speed`` (name, dims, units, long_name): a table the systems that
#: report them register (``hsbearing friction`` of deep-groove and angular-contact cases)
OUTPUTS = (
    ("skf_sliding_torque", ("speed",), "N*m", "SKF 2004 sliding frictional moment M_sl = G_sl mu_sl"),
    ("skf_rolling_torque", ("speed",), "N*m", "SKF 2004 rolling frictional moment M_rr"),
    ("skf_drag_torque", ("speed",), "N*m", "SKF 2004 drag-loss moment M_drag (oil bath)"),
    ("skf_total_torque", ("speed",), "N*m", "SKF 2004 total frictional moment M_rr + M_sl + M_drag (open bearing, no seal)"),
    ("skf_sliding_coefficient", ("speed",), "1", "SKF 2004 sliding coefficient mu_sl = phi_bl mu_bl + (1 - phi_bl) mu_EHL"),
)

__all__ = [
    "OUTPUTS",
    "SeriesConstants",
    "DGBB_SERIES",
    "series_of",
    "contact_angle_alpha_F",
    "rolling_variable_G_rr",
    "sliding_variable_G_sl",
    "boundary_weighting_phi_bl",
    "sliding_coefficient_mu_sl",
    "inlet_shear_factor_phi_ish",
    "replenishment_factor_phi_rs",
    "rolling_moment",
    "sliding_moment",
    "drag_moment",
    "skf_moments",
    "ACBB_SERIES",
    "ACBB_CONSTANTS_STATUS",
    "angular_contact_series_of",
    "angular_contact_row_of",
    "rolling_variable_G_rr_angular_contact",
    "sliding_variable_G_sl_angular_contact",
    "skf_moments_angular_contact",
]


@dataclass(frozen=True)
class SeriesConstants:
    """Geometry constants of [1] Table 1 for one deep-groove ball bearing series."""

    R1: float
    R2: float
    S1: float
    S2: float


#: [1], Table 1 "Geometry constants for rolling and sliding frictional moments",
#: deep-groove ball bearings, series 62 / 622.  S1, S2 are checked: they reproduce
#: dgbb_prl Table 2 (SKF column) to 5 significant digits (tests/systems/deep_groove/test_friction_dgbb.py);
#: R1, R2 are not checked by any seed table.  Other series (60, 63, ...) are left
#: out on purpose until their row is verified against the catalogue.
DGBB_SERIES: dict[str, SeriesConstants] = {
    "62": SeriesConstants(R1=3.9e-7, R2=1.7, S1=3.23e-3, S2=36.5),  # 62, 622
}

#: [1] "Inlet shear heating" / "kinematic replenishment": K_Z = 3.1 for deep-groove ball bearings.
K_Z_DGBB = 3.1
#: [1] K_rs = 3e-8 for low-level oil bath and oil jet, 6e-8 for grease and oil-air.
K_RS = {"oil_jet": 3e-8, "oil_bath": 3e-8, "oil_air": 6e-8, "grease": 6e-8, "dry": 6e-8}


@dataclass(frozen=True)
class AngularContactConstants:
    """Geometry constants of [4] (geometry-constants table) for one single-row angular contact ball bearing series."""

    R1: float
    R2: float
    R3: float
    S1: float
    S2: float
    S3: float


#: [4], [5]: single-row angular contact ball bearings, keyed by series and variant (B = 40 deg, AC = 25 deg);
#: "other" = any other single-row angular contact ball bearing (e.g. 72/73 with 15 or 30 deg).
ACBB_SERIES: dict[str, AngularContactConstants] = {
    "72 B": AngularContactConstants(R1=4.33e-7, R2=2.02, R3=2.44e-12, S1=1.82e-2, S2=0.71, S3=2.44e-12),
    "73 B": AngularContactConstants(R1=4.54e-7, R2=2.02, R3=1.84e-12, S1=1.64e-2, S2=0.71, S3=1.84e-12),
    "72 AC": AngularContactConstants(R1=3.58e-7, R2=3.64, R3=3.55e-12, S1=1.14e-2, S2=1.55, S3=3.55e-12),
    "73 AC": AngularContactConstants(R1=3.48e-7, R2=3.64, R3=1.66e-12, S1=9.85e-3, S2=1.55, S3=1.66e-12),
    "other": AngularContactConstants(R1=5.03e-7, R2=1.97, R3=1.90e-12, S1=1.30e-2, S2=0.68, S3=1.91e-12),
}
_SECONDARY = "not checked against an SKF copy; from one public transcription of the SKF tables [5]"
#: Verification status of each :data:`ACBB_SERIES` row (module note [4], docs/life.md "SKF constants").
ACBB_CONSTANTS_STATUS: dict[str, str] = {
    "72 B": _SECONDARY, "73 B": _SECONDARY, "72 AC": _SECONDARY, "73 AC": _SECONDARY,
    "other": _SECONDARY + " and a second independent implementation",
}
#: [4], [5] K_Z = 4.4 for single-row angular contact ball bearings (secondary transcriptions).
K_Z_ACBB = 4.4


def angular_contact_row_of(designation: str, contact_angle=None, source: str = "<case>") -> str:
    """Row key of :data:`ACBB_SERIES` for a single-row angular-contact designation ([4], [5]).

    The series is read from the designation (``72xx``, ``73xx``); the variant from its suffix
    (``B``/``BE``... -> 40 deg, ``AC``... -> 25 deg), else from the nominal contact angle [rad]
    (40 +- 2.5 deg -> B, 25 +- 2.5 deg -> AC); any other variant (15, 30 deg, unknown) -> ``"other"``.
    """
    m = re.match(r"^\s*(7[23])\d{2}\s*-?\s*([A-Z]*)", (designation or "").upper())
    if not m:
        raise CaseError(
            source, "bearing.designation",
            f"SKF model needs a single-row angular-contact designation of series 72 or 73 like 7206 BE or 7206 AC, got {designation!r}",
        )
    series, suffix = m.group(1), m.group(2)
    if suffix.startswith("AC"):
        variant = "AC"
    elif suffix.startswith("B"):
        variant = "B"
    elif contact_angle is not None and abs(math.degrees(contact_angle) - 40.0) <= 2.5:
        variant = "B"
    elif contact_angle is not None and abs(math.degrees(contact_angle) - 25.0) <= 2.5:
        variant = "AC"
    else:
        return "other"
    return f"{series} {variant}"


def angular_contact_series_of(designation: str, source: str = "<case>", contact_angle=None) -> AngularContactConstants:
    """Constants of a single-row angular-contact designation such as ``"7206 BE"`` ([4], [5]; see
    :func:`angular_contact_row_of` and ``ACBB_CONSTANTS_STATUS``)."""
    return ACBB_SERIES[angular_contact_row_of(designation, contact_angle, source)]


def rolling_variable_G_rr_angular_contact(Fr, Fa, dm_mm, n_rpm, consts: AngularContactConstants):
    """Rolling frictional variable G_rr [-] of an angular contact ball bearing ([4] Table 2a).

    G_rr = R1 d_m^1.97 (F_r + F_g + R2 F_a)^0.54,  F_g = R3 d_m^4 n^2  (N, mm, r/min).
    """
    n = np.abs(np.asarray(n_rpm, dtype=float))
    Fg = consts.R3 * dm_mm**4 * n**2  # [4] Table 2a
    return consts.R1 * dm_mm**1.97 * (abs(Fr) + Fg + consts.R2 * abs(Fa)) ** 0.54  # [4] Table 2a


def sliding_variable_G_sl_angular_contact(Fr, Fa, dm_mm, n_rpm, consts: AngularContactConstants):
    """Sliding frictional variable G_sl [-] of an angular contact ball bearing ([4] Table 2a).

    G_sl = S1 d_m^0.26 ((F_r + F_g)^(4/3) + S2 F_a^(4/3)),  F_g = S3 d_m^4 n^2  (N, mm, r/min).
    """
    n = np.abs(np.asarray(n_rpm, dtype=float))
    Fg = consts.S3 * dm_mm**4 * n**2  # [4] Table 2a
    return consts.S1 * dm_mm**0.26 * ((abs(Fr) + Fg) ** (4.0 / 3.0) + consts.S2 * abs(Fa) ** (4.0 / 3.0))  # [4] Table 2a


def series_of(designation: str, source: str = "<case>") -> SeriesConstants:
    """Series constants from a catalogue designation such as ``"6206"`` ([1] Table 1)."""
    m = re.match(r"^\s*(6\d)\d{2}", designation or "")
    if not m or m.group(1) not in DGBB_SERIES:
        raise CaseError(
            source, "bearing.designation",
            f"SKF model needs a deep-groove series designation like 6206 (known series: {', '.join(DGBB_SERIES)}), got {designation!r}",
        )
    return DGBB_SERIES[m.group(1)]


def contact_angle_alpha_F(Fa, C0):
    """Load-dependent contact angle alpha_F [rad] of the SKF model.

    alpha_F = 24.6 (F_a / C_0)^0.24 degrees  ([1], Table 2a, deep-groove ball bearings).

    Parameters
    ----------
    Fa : axial load [N].  C0 : basic static load rating [N].
    """
    return np.radians(24.6 * (np.asarray(Fa, dtype=float) / C0) ** 0.24)  # [1], Table 2a


def rolling_variable_G_rr(Fr, Fa, dm_mm, C0, consts: SeriesConstants):
    """Rolling frictional variable G_rr [-] (catalogue units; M_rr in N mm).

    F_a = 0: G_rr = R1 d_m^1.96 F_r^0.54;
    F_a > 0: G_rr = R1 d_m^1.96 (F_r + R2/sin(alpha_F) F_a)^0.54   ([1], Table 2a).

    Parameters
    ----------
    Fr, Fa : radial and axial load [N].  dm_mm : pitch diameter [mm].  C0 [N].
    """
    Fr = float(Fr)
    Fa = float(Fa)
    if Fa <= 0.0:
        return consts.R1 * dm_mm**1.96 * Fr**0.54  # [1], Table 2a (F_a = 0)
    aF = contact_angle_alpha_F(Fa, C0)
    return consts.R1 * dm_mm**1.96 * (Fr + consts.R2 / np.sin(aF) * Fa) ** 0.54  # [1], Table 2a (F_a > 0)


def sliding_variable_G_sl(Fr, Fa, dm_mm, C0, consts: SeriesConstants, reading: str = "catalogue"):
    """Sliding frictional variable G_sl [-] (catalogue units; M_sl = G_sl mu_sl in N mm).

    ``reading="catalogue"`` ([1], Table 2a):
      F_a = 0: G_sl = S1 d_m^-0.26 F_r^(5/3);
      F_a > 0: G_sl = S1 d_m^-0.145 (F_r^5 + S2 d_m^1.5 / sin(alpha_F) F_a^4)^(1/3).

    ``reading="dgbb_prl"``: the reading that reproduces the SKF column of seed
    003 Tables 2-4 to 4-5 digits: the axial (F_a > 0) term and *half* the
    pure-radial term added,
      G_sl = S1 d_m^-0.145 (S2 d_m^1.5 / sin(alpha_F) F_a^4)^(1/3) + 0.5 S1 d_m^-0.26 F_r^(5/3).
    It is not the catalogue formula; see docs/validation/dgbb_friction.md.

    Parameters
    ----------
    Fr, Fa : radial and axial load [N].  dm_mm : pitch diameter [mm].  C0 [N].
    """
    Fr = float(Fr)
    Fa = float(Fa)
    radial_only = consts.S1 * dm_mm ** (-0.26) * Fr ** (5.0 / 3.0)  # [1], Table 2a (F_a = 0)
    if reading == "dgbb_prl":
        axial = 0.0
        if Fa > 0.0:
            aF = contact_angle_alpha_F(Fa, C0)
            axial = consts.S1 * dm_mm ** (-0.145) * (consts.S2 * dm_mm**1.5 / np.sin(aF) * Fa**4) ** (1.0 / 3.0)
        return axial + 0.5 * radial_only  # dgbb_prl Tables 2-4 (reverse-engineered, see docs)
    if reading != "catalogue":
        raise ValueError(f"unknown G_sl reading {reading!r}")
    if Fa <= 0.0:
        return radial_only
    aF = contact_angle_alpha_F(Fa, C0)
    return consts.S1 * dm_mm ** (-0.145) * (Fr**5 + consts.S2 * dm_mm**1.5 / np.sin(aF) * Fa**4) ** (1.0 / 3.0)  # [1], Table 2a


def boundary_weighting_phi_bl(n_rpm, nu_mm2s, dm_mm):
    """Weighting factor phi_bl [-] between boundary and full-film sliding friction.

    phi_bl = 1 / e^(2.6e-8 (n nu)^1.4 d_m)   ([1], "Sliding frictional moment").

    Parameters
    ----------
    n_rpm : rotational speed [r/min].  nu_mm2s : operating kinematic viscosity [mm^2/s].
    dm_mm : pitch diameter [mm].
    """
    n = np.abs(np.asarray(n_rpm, dtype=float))
    return np.exp(-2.6e-8 * (n * nu_mm2s) ** 1.4 * dm_mm)  # [1]


def sliding_coefficient_mu_sl(n_rpm, nu_mm2s, dm_mm, mu_bl=0.15, mu_ehl=0.05):
    """Sliding friction coefficient mu_sl [-] = phi_bl mu_bl + (1 - phi_bl) mu_EHL ([1]).

    SKF defaults: mu_bl = 0.15; mu_EHL = 0.05 for mineral oils (0.04 synthetic,
    0.1 transmission fluids).  This is the "Stribeck-type" coefficient of dgbb_prl.
    """
    phi = boundary_weighting_phi_bl(n_rpm, nu_mm2s, dm_mm)
    return phi * mu_bl + (1.0 - phi) * mu_ehl  # [1]


def inlet_shear_factor_phi_ish(n_rpm, nu_mm2s, dm_mm):
    """Inlet shear heating reduction factor phi_ish [-] = 1 / (1 + 1.84e-9 (n d_m)^1.28 nu^0.64) ([1])."""
    n = np.abs(np.asarray(n_rpm, dtype=float))
    return 1.0 / (1.0 + 1.84e-9 * (n * dm_mm) ** 1.28 * nu_mm2s**0.64)  # [1]


def replenishment_factor_phi_rs(n_rpm, nu_mm2s, d_mm, D_mm, K_rs=3e-8, K_Z=K_Z_DGBB):
    """Kinematic replenishment/starvation reduction factor phi_rs [-] ([1]).

    phi_rs = 1 / e^(K_rs nu n (d + D) sqrt(K_Z / (2 (D - d))))

    Parameters
    ----------
    d_mm, D_mm : bore and outside diameter [mm].  K_rs : replenishment constant
    (3e-8 oil jet / low-level oil bath, 6e-8 grease / oil-air).  K_Z : bearing
    type constant (3.1 deep-groove ball bearings).
    """
    n = np.abs(np.asarray(n_rpm, dtype=float))
    return np.exp(-K_rs * nu_mm2s * n * (d_mm + D_mm) * np.sqrt(K_Z / (2.0 * (D_mm - d_mm))))  # [1]


def rolling_moment(n_rpm, nu_mm2s, G_rr, phi_ish=1.0, phi_rs=1.0):
    """Rolling frictional moment M_rr [N mm] = phi_ish phi_rs G_rr (nu n)^0.6 ([1])."""
    n = np.abs(np.asarray(n_rpm, dtype=float))
    return phi_ish * phi_rs * G_rr * (nu_mm2s * n) ** 0.6  # [1]


def sliding_moment(G_sl, mu_sl):
    """Sliding frictional moment M_sl [N mm] = G_sl mu_sl ([1])."""
    return G_sl * mu_sl  # [1]


def drag_moment(n_rpm, dm_mm, d_mm, D_mm, V_M, irw=1, K_Z=K_Z_DGBB):
    """Drag-loss moment in an oil bath M_drag [N mm] = V_M K_ball d_m^5 n^2 ([1], "Drag losses").

    K_ball = i_rw K_Z (d + D) / (D - d) 1e-12.  V_M is read from the
    catalogue diagram as a function of the oil level H / d_m (it is an input
    here, ``[friction] skf_drag_variable``; not digitised).
    """
    n = np.asarray(n_rpm, dtype=float)
    K_ball = irw * K_Z * (d_mm + D_mm) / (D_mm - d_mm) * 1e-12  # [1]
    return V_M * K_ball * dm_mm**5 * n**2  # [1]


def skf_moments(case, speeds, reading: str | None = None) -> dict[str, np.ndarray]:
    """SKF-model moments of a deep-groove ball bearing case at inner-ring speeds.

    Parameters
    ----------
    case : a :class:`hsbearing.case.Case` (``system = "deep_groove"``); uses
        ``bearing.designation`` (series constants), ``pitch_diameter``,
        ``bore_diameter``, ``outside_diameter``, ``operating.axial_load``,
        ``radial_load``, ``lubricant.kinematic_viscosity``, ``lubrication``,
        ``friction.static_load_rating``, ``boundary_coefficient``,
        ``ehl_coefficient``, ``skf_reading``, ``skf_drag_variable``.
    speeds : inner-ring speeds [rad/s] (array).
    reading : G_sl reading (``"catalogue"``, ``"dgbb_prl"``); None = ``[friction] skf_reading``.

    Returns
    -------
    dict with ``skf_rolling_torque``, ``skf_sliding_torque``,
    ``skf_drag_torque``, ``skf_total_torque`` [N m] and
    ``skf_sliding_coefficient`` [-], each shaped like ``speeds``.
    """
    src = case.source
    b, lub, fr, op = case.bearing, case.lubricant, case.friction, case.operating
    if case.system == "angular_contact":
        return skf_moments_angular_contact(case, speeds)
    consts = series_of(b.designation, src)
    for key, val in (("friction.static_load_rating", fr.static_load_rating),
                     ("lubricant.kinematic_viscosity", lub.kinematic_viscosity),
                     ("bearing.bore_diameter", b.bore_diameter),
                     ("bearing.outside_diameter", b.outside_diameter)):
        if val is None:
            raise CaseError(src, key, "required by the SKF frictional-moment model")
    dm = b.pitch_diameter * 1e3
    d, D = b.bore_diameter * 1e3, b.outside_diameter * 1e3
    C0 = fr.static_load_rating
    nu = lub.kinematic_viscosity * 1e6  # m^2/s -> mm^2/s
    Fa, Fr = abs(op.axial_load), math.hypot(op.radial_load, op.radial_load_z)
    w = np.asarray(speeds, dtype=float)
    n = np.abs(w) * 60.0 / (2.0 * math.pi)  # rad/s -> r/min
    G_rr = rolling_variable_G_rr(Fr, Fa, dm, C0, consts)
    G_sl = sliding_variable_G_sl(Fr, Fa, dm, C0, consts, reading=reading or fr.skf_reading)
    mu_sl = sliding_coefficient_mu_sl(n, nu, dm, fr.boundary_coefficient, fr.ehl_coefficient)
    phi_ish = inlet_shear_factor_phi_ish(n, nu, dm)
    phi_rs = replenishment_factor_phi_rs(n, nu, d, D, K_rs=K_RS[lub.lubrication])
    M_rr = rolling_moment(n, nu, G_rr, phi_ish, phi_rs)
    M_sl = sliding_moment(G_sl, mu_sl)
    if lub.lubrication == "oil_bath":
        if fr.skf_drag_variable is None:
            raise CaseError(src, "friction.skf_drag_variable",
                            "oil-bath drag needs V_M from the SKF catalogue diagram (function of oil level H/d_m)")
        M_drag = drag_moment(n, dm, d, D, fr.skf_drag_variable)
    else:  # [1]: drag losses are those of an oil bath; none for oil jet / oil-air / grease here
        M_drag = np.zeros_like(n)
    to_Nm = 1e-3
    return {
        "skf_rolling_torque": M_rr * to_Nm,
        "skf_sliding_torque": np.broadcast_to(M_sl, n.shape) * to_Nm,
        "skf_drag_torque": M_drag * to_Nm,
        "skf_total_torque": (M_rr + M_sl + M_drag) * to_Nm,
        "skf_sliding_coefficient": mu_sl,
    }


def skf_moments_angular_contact(case, speeds) -> dict[str, np.ndarray]:
    """SKF-model moments of a single-row angular contact ball bearing at inner-ring speeds ([4]).

    M = phi_ish phi_rs G_rr (nu n)^0.6 + G_sl mu_sl (+ drag in an oil bath), with the
    angular-contact G_rr, G_sl of [4] Table 2a (speed-dependent through F_g), the row of
    :data:`ACBB_SERIES` chosen by :func:`angular_contact_row_of` from ``bearing.designation`` and
    ``bearing.contact_angle`` ([5], secondary), and K_Z = 4.4.  The operating viscosity nu is ``lubricant.kinematic_viscosity`` or
    eta(T)/density of the oil.  Same return dict as :func:`skf_moments`.
    """
    from hsbearing.models import ehl

    src = case.source
    b, lub, fr, op = case.bearing, case.lubricant, case.friction, case.operating
    consts = angular_contact_series_of(b.designation, src, contact_angle=b.contact_angle)
    for key, val in (("bearing.bore_diameter", b.bore_diameter), ("bearing.outside_diameter", b.outside_diameter)):
        if val is None:
            raise CaseError(src, key, "required by the SKF frictional-moment model")
    dm = b.pitch_diameter * 1e3
    d, D = b.bore_diameter * 1e3, b.outside_diameter * 1e3
    nu_si = lub.kinematic_viscosity if lub.kinematic_viscosity is not None else ehl.lubricant_parameters(case)["eta"] / lub.density
    nu = nu_si * 1e6
    Fa, Fr = abs(op.axial_load), math.hypot(op.radial_load, op.radial_load_z)
    w = np.asarray(speeds, dtype=float)
    n = np.abs(w) * 60.0 / (2.0 * math.pi)
    G_rr = rolling_variable_G_rr_angular_contact(Fr, Fa, dm, n, consts)
    G_sl = sliding_variable_G_sl_angular_contact(Fr, Fa, dm, n, consts)
    mu_sl = sliding_coefficient_mu_sl(n, nu, dm, fr.boundary_coefficient, fr.ehl_coefficient)
    phi_ish = inlet_shear_factor_phi_ish(n, nu, dm)
    phi_rs = replenishment_factor_phi_rs(n, nu, d, D, K_rs=K_RS[lub.lubrication], K_Z=K_Z_ACBB)
    M_rr = rolling_moment(n, nu, G_rr, phi_ish, phi_rs)
    M_sl = sliding_moment(G_sl, mu_sl)
    if lub.lubrication == "oil_bath":
        if fr.skf_drag_variable is None:
            raise CaseError(src, "friction.skf_drag_variable",
                            "oil-bath drag needs V_M from the SKF catalogue diagram (function of oil level H/d_m)")
        M_drag = drag_moment(n, dm, d, D, fr.skf_drag_variable, K_Z=K_Z_ACBB)
    else:
        M_drag = np.zeros_like(n)
    to_Nm = 1e-3
    return {
        "skf_rolling_torque": M_rr * to_Nm,
        "skf_sliding_torque": M_sl * to_Nm,
        "skf_drag_torque": M_drag * to_Nm,
        "skf_total_torque": (M_rr + M_sl + M_drag) * to_Nm,
        "skf_sliding_coefficient": mu_sl,
    }
